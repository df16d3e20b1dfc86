// The worker threads of a parallel tick. A job opens with one atomic store; workers awake
// see it within a spin (a sleeping thread takes tens of µs to start, the time of ~10,000
// plain updates); the calling thread waits for the last worker's piece the same way (at most
// one piece of work: the job hands out small pieces).
#include "tick_pool.hpp"

#include "internal/compiler.hpp"

namespace grape::detail {

namespace {
inline void relax() noexcept { cpu_relax(); }
}  // namespace

TickPool::TickPool(int workers, std::chrono::nanoseconds awake) : awake_(awake) {
    threads_.reserve(static_cast<std::size_t>(workers));
    try {
        for (int k = 0; k < workers; ++k) threads_.emplace_back([this] { work(); });
    } catch (...) {
        stop_and_join();
        throw;
    }
}

TickPool::~TickPool() { stop_and_join(); }

void TickPool::stop_and_join() noexcept {
    stop_.store(true);
    {
        const std::lock_guard lock(mutex_);  // a worker between its test and its sleep finishes both
    }
    start_.notify_all();
    for (std::thread& t : threads_) t.join();
}

void TickPool::run(Job job, void* context) noexcept {
    const auto now = std::chrono::steady_clock::now();
    if (awake_.count() > 0 && now - last_closed_ > awake_) {
        // A job after a gap (a frame's first tick): expect the next one after as long again,
        // when that is frame-like (up to 250 ms, a 4 Hz frame). Not when workers are not to
        // wait awake at all: a timed wake would then only wake them to sleep again.
        const auto period = now - last_gap_open_;
        const bool regular = last_gap_open_.time_since_epoch().count() != 0 && period <= std::chrono::milliseconds(250);
        due_.store(regular ? (now + period).time_since_epoch().count() : 0, std::memory_order_relaxed);
        last_gap_open_ = now;
    }
    job_ = job;
    context_ = context;
    const std::uint64_t open = state_.load(std::memory_order_relaxed) + 1;
    state_.store(open);
    if (sleepers_.load() > 0) {
        // A worker that counted itself a sleeper before this load tests state_ under the
        // mutex: it either sees the open job or is waiting when the notify comes.
        { const std::lock_guard lock(mutex_); }
        start_.notify_all();
    }
    job(context);
    state_.store(open + 1);  // closed: a worker that counts itself from now on sees it and leaves
    for (int spins = 0; active_.load() != 0; ++spins) {
        if (spins < 4096) relax();
        else std::this_thread::yield();  // the worker was descheduled mid-piece
    }
    last_closed_ = std::chrono::steady_clock::now();
}

template <class Ready>
bool TickPool::spin_until(Ready&& ready, std::chrono::steady_clock::time_point until) noexcept {
    for (int spins = 1;; ++spins) {
        if (ready()) return true;
        relax();
        if (spins % 64 == 0 && std::chrono::steady_clock::now() >= until) return ready();
    }
}

bool TickPool::wait_for_job(std::uint64_t seen) noexcept {
    // seq_cst: after a sleeper counts itself, this test and run()'s store and load of
    // sleepers_ are in one order, so either the test sees the job or run() notifies.
    auto ready = [&] { return stop_.load() || state_.load() != seen; };
    using Clock = std::chrono::steady_clock;
    if (spin_until(ready, Clock::now() + awake_)) return !stop_.load();
    std::unique_lock lock(mutex_);
    const Clock::time_point due{Clock::duration{due_.load(std::memory_order_relaxed)}};
    if (due - awake_ > Clock::now()) {
        // Asleep until `awake` before the job after a gap is due, then awake until `awake`
        // after it (a timed wake is late by the timer's slack, ~50 µs on Linux).
        sleepers_.fetch_add(1);
        const bool woken = start_.wait_until(lock, due - awake_, ready);
        sleepers_.fetch_sub(1);
        if (woken) return !stop_.load();
        lock.unlock();
        if (spin_until(ready, due + awake_)) return !stop_.load();
        lock.lock();
    }
    sleepers_.fetch_add(1);
    start_.wait(lock, ready);
    sleepers_.fetch_sub(1);
    return !stop_.load();
}

void TickPool::work() noexcept {
    std::uint64_t seen = 0;
    while (wait_for_job(seen)) {
        seen = state_.load();
        if (!(seen & 1)) continue;  // opened and closed already: wait for the next
        active_.fetch_add(1);
        if (state_.load() == seen) job_(context_);  // still open: run() waits for this call
        active_.fetch_sub(1);
        ++seen;  // this job's closed state: wait for the next one, not for this one to close
    }
}

}  // namespace grape::detail
