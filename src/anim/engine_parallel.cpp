// Two-phase ticks: the plain updates first, shared among threads, then everything that may
// run a handler, in record order on the calling thread.
#include "engine_impl.hpp"

#include <grape/error.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "engine_eval.hpp"
#include "engine_lean_table.hpp"
#include "tick_pool.hpp"

namespace grape::detail {

void TickPoolDelete::operator()(TickPool* pool) const noexcept { delete pool; }

namespace {
// A block is the unit a thread takes: large enough that taking one (an atomic add on its
// slice's counter) costs nothing beside its updates, small enough that the thread that
// finishes first leaves little for the other: 256 to 4,096 records (8 KB to 128 KB; ~10 µs of
// updates), about 32 per thread.
constexpr std::size_t min_block = 256;
std::size_t block_size(std::size_t n, int threads) noexcept {
    return std::clamp<std::size_t>(n / (32 * static_cast<std::size_t>(threads)), min_block, 4096);
}
}  // namespace

void EngineImpl::set_parallel(int threads, std::size_t min_records, double awake) {
    if (threads < 1 || threads > max_tick_threads)
        throw Error("Engine::set_parallel: threads must be in [1, " + std::to_string(max_tick_threads) + "] (got " +
                    std::to_string(threads) + ")");
    if (!(awake >= 0.0 && awake <= 1.0))  // also NaN
        throw Error("Engine::set_parallel: awake must be in [0, 1] seconds (got " + number_text(awake) + ")");
    if (ticking_ || depth_ > 0) throw Error("Engine::set_parallel: called from inside one of the engine's own handlers");
    const auto awake_ns = std::chrono::nanoseconds(static_cast<std::int64_t>(awake * 1e9));
    std::unique_ptr<SliceCounter[]> slices(new SliceCounter[static_cast<std::size_t>(threads)]);
    if (!pool_ || pool_->workers() != threads - 1 || pool_->awake() != awake_ns) {
        pool_.reset();
        if (threads > 1) pool_.reset(new TickPool(threads - 1, awake_ns));
    }
    slice_next_ = std::move(slices);
    threads_ = threads;
    parallel_min_ = min_records;
    two_phase_ = true;
}

void EngineImpl::set_serial() {
    if (ticking_ || depth_ > 0) throw Error("Engine::set_serial: called from inside one of the engine's own handlers");
    pool_.reset();
    threads_ = 1;
    two_phase_ = false;
}

// Phase 1: every record of [0, driven_begin_) that plain_step takes, in blocks; the others'
// indices go to slow_, each block's from the block's first index on, in order.
void EngineImpl::plain_phase(double dt) {
    const std::size_t n = driven_begin_;
    const bool parallel = pool_ && n >= parallel_min_ && n > 0;
    block_ = parallel ? block_size(n, threads_) : std::max<std::size_t>(n, 1);
    blocks_ = (n + block_ - 1) / block_;
    // Grown only when the engine has grown past every earlier tick: no allocation per tick.
    if (slow_.size() < n) slow_.resize(std::max(n, 2 * slow_.size()));
    const std::size_t most_blocks = n / min_block + 1;  // whatever the block size: fixed by n
    if (slow_count_.size() < most_blocks) slow_count_.resize(std::max(most_blocks, 2 * slow_count_.size()));
    plain_n_ = n;
    plain_dt_ = dt;
    slices_ = parallel ? threads_ : 1;
    for (int s = 0; s < slices_; ++s) slice_next_[static_cast<std::size_t>(s)].next.store(slice_begin(s), std::memory_order_relaxed);
    arrivals_.store(0, std::memory_order_relaxed);
    if (parallel) pool_->run(&EngineImpl::plain_job, this);  // opening the job publishes the above
    else plain_job(this);
}

void EngineImpl::plain_job(void* self) noexcept {
    EngineImpl& e = *static_cast<EngineImpl*>(self);
    const int first = e.arrivals_.fetch_add(1, std::memory_order_relaxed) % e.slices_;
    for (int k = 0; k < e.slices_; ++k) {  // its own slice first, then the others'
        const int s = (first + k) % e.slices_;
        const std::size_t end_block = e.slice_begin(s + 1);
        for (;;) {
            const std::size_t b = e.slice_next_[static_cast<std::size_t>(s)].next.fetch_add(1, std::memory_order_relaxed);
            if (b >= end_block) break;
            const std::size_t begin = b * e.block_;
            const std::size_t end = std::min(e.plain_n_, begin + e.block_);
            e.slow_count_[b] = static_cast<std::uint32_t>(e.advance_plain(begin, end, e.plain_dt_, e.slow_.data() + begin));
        }
    }
}

GRAPE_FLATTEN std::size_t EngineImpl::advance_plain(std::size_t begin, std::size_t end, double dt, std::uint32_t* slow) noexcept {
    Hot* const hot = hot_.data();
    Cold* const cold = cold_.data();
    const PathFast* const fast = path_fast_.data();
    const LeanTables tables{line_fast_.data(), fast, arc_fast_.data(), cold, wide_lanes()};
    std::size_t k = 0;
    for (std::size_t i = begin; i < end; ++i) {
        if (const LeanRun run = lean_for(hot[i], tables)) {  // formula curves only: no user code
            i = run(hot, tables, i, end, dt);
            if (i == end) break;
        }
        if (!plain_step<true>(hot, cold, fast, i, dt)) slow[k++] = static_cast<std::uint32_t>(i);
    }
    return k;
}

// Phase 2: the records phase 1 left, in record order; their handlers run here. slow_ and the
// counts are not touched by handlers (set_parallel and tick refuse to run inside one).
void EngineImpl::general_phase(double dt) {
    const std::size_t blocks = blocks_, block = block_;
    for (std::size_t b = 0; b < blocks; ++b) {
        const std::uint32_t* const slow = slow_.data() + b * block;
        for (std::uint32_t k = 0, count = slow_count_[b]; k < count; ++k) advance_general(slow[k], dt);
    }
}

}  // namespace grape::detail
