// BitVector against std::vector<bool>, boost::dynamic_bitset, std::bitset and plain word
// loops on 10,000,000 bits, with memcpy of the same bytes as the memory-speed reference, all
// in one run. Prints the memory table first and a summary with ratios last.
//
//   build-bench/bench/bench_bits [--benchmark_filter=...]
#include <grape/bits.hpp>

#include <benchmark/benchmark.h>
#include <boost/dynamic_bitset.hpp>

#include <algorithm>
#include <bit>
#include <bitset>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <memory>
#include <new>
#include <random>
#include <string>
#include <vector>

// ---- heap accounting for the memory table: every operator new in this program is counted ----
namespace {
std::size_t g_heap_bytes = 0;
}
void* operator new(std::size_t n) {
    g_heap_bytes += n;
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace {

constexpr std::size_t bits = 10'000'000;
constexpr std::size_t operand_bytes = bits / 8;  // 1.25 MB: one operand of a whole-vector op
using Bitset = std::bitset<bits>;
using Boost = boost::dynamic_bitset<std::uint64_t>;

// The same two patterns in every container: A has every third bit set (density 1/3), B is
// random at density 1/2.
const std::vector<bool>& b_pattern() {
    static const std::vector<bool> b = [] {
        std::mt19937_64 rng(42);
        std::vector<bool> v(bits);
        for (std::size_t i = 0; i < bits; ++i) v[i] = (rng() >> 63) != 0;
        return v;
    }();
    return b;
}

// Adapters: one way to spell each operation per container.
struct GrapeOps {
    using C = grape::BitVector;
    static constexpr const char* name = "grape::BitVector";
    static std::unique_ptr<C> make() { return std::make_unique<C>(bits); }
    static void set(C& c, std::size_t i) { c.set(i); }
    static bool get(const C& c, std::size_t i) { return c.get(i); }
    static void and_assign(C& a, const C& b) { a &= b; }
    static void or_assign(C& a, const C& b) { a |= b; }
    static std::size_t count(const C& c) { return c.count(); }
    static std::size_t sum_set(const C& c) {
        std::size_t s = 0;
        c.for_each_set([&s](std::size_t i) { s += i; });
        return s;
    }
};
struct GrapeRangeOps : GrapeOps {  // the range-for spelling of the same walk
    static constexpr const char* name = "grape::BitVector (range-for)";
    static std::size_t sum_set(const C& c) {
        std::size_t s = 0;
        for (std::size_t i : c.set_bits()) s += i;
        return s;
    }
};
struct BoostOps {
    using C = Boost;
    static constexpr const char* name = "boost::dynamic_bitset";
    static std::unique_ptr<C> make() { return std::make_unique<C>(bits); }
    static void set(C& c, std::size_t i) { c.set(i); }
    static bool get(const C& c, std::size_t i) { return c.test(i); }
    static void and_assign(C& a, const C& b) { a &= b; }
    static void or_assign(C& a, const C& b) { a |= b; }
    static std::size_t count(const C& c) { return c.count(); }
    static std::size_t sum_set(const C& c) {
        std::size_t s = 0;
        for (std::size_t i = c.find_first(); i != C::npos; i = c.find_next(i)) s += i;
        return s;
    }
};
struct VectorBoolOps {
    using C = std::vector<bool>;
    static constexpr const char* name = "std::vector<bool>";
    static std::unique_ptr<C> make() { return std::make_unique<C>(bits); }
    static void set(C& c, std::size_t i) { c[i] = true; }
    static bool get(const C& c, std::size_t i) { return c[i]; }
    static void and_assign(C& a, const C& b) {
        for (std::size_t i = 0; i < bits; ++i) a[i] = a[i] && b[i];
    }
    static void or_assign(C& a, const C& b) {
        for (std::size_t i = 0; i < bits; ++i) a[i] = a[i] || b[i];
    }
    static std::size_t count(const C& c) { return static_cast<std::size_t>(std::count(c.begin(), c.end(), true)); }
    static std::size_t sum_set(const C& c) {
        std::size_t s = 0;
        for (std::size_t i = 0; i < bits; ++i)
            if (c[i]) s += i;
        return s;
    }
};
struct BitsetOps {
    using C = Bitset;
    static constexpr const char* name = "std::bitset";
    static std::unique_ptr<C> make() { return std::make_unique<C>(); }
    static void set(C& c, std::size_t i) { c.set(i); }
    static bool get(const C& c, std::size_t i) { return c[i]; }
    static void and_assign(C& a, const C& b) { a &= b; }
    static void or_assign(C& a, const C& b) { a |= b; }
    static std::size_t count(const C& c) { return c.count(); }
    static std::size_t sum_set(const C& c) {  // libstdc++'s _Find_first/_Find_next
        std::size_t s = 0;
        for (std::size_t i = c._Find_first(); i < bits; i = c._Find_next(i)) s += i;
        return s;
    }
};

// Plain word loops over a std::vector<uint64_t>: the "plain countr_zero loop" and a
// std::popcount loop compiled for the popcnt instruction (what -mpopcnt gives).
struct Words {
    std::vector<std::uint64_t> w = std::vector<std::uint64_t>((bits + 63) / 64);
};
struct WordsOps {
    using C = Words;
    static constexpr const char* name = "plain uint64_t loop";
    static std::unique_ptr<C> make() { return std::make_unique<C>(); }
    static void set(C& c, std::size_t i) { c.w[i / 64] |= std::uint64_t{1} << (i % 64); }
    static bool get(const C& c, std::size_t i) { return (c.w[i / 64] >> (i % 64)) & 1u; }
    static void and_assign(C& a, const C& b) {
        for (std::size_t k = 0; k < a.w.size(); ++k) a.w[k] &= b.w[k];
    }
    static void or_assign(C& a, const C& b) {
        for (std::size_t k = 0; k < a.w.size(); ++k) a.w[k] |= b.w[k];
    }
    __attribute__((target("popcnt"))) static std::size_t count(const C& c) {
        std::size_t s = 0;
        for (std::uint64_t x : c.w) s += static_cast<std::size_t>(std::popcount(x));
        return s;
    }
    static std::size_t sum_set(const C& c) {
        std::size_t s = 0;
        for (std::size_t k = 0; k < c.w.size(); ++k)
            for (std::uint64_t x = c.w[k]; x != 0; x &= x - 1) s += k * 64 + static_cast<std::size_t>(std::countr_zero(x));
        return s;
    }
};

template <class Ops>
const typename Ops::C& pattern_a() {
    static const std::unique_ptr<typename Ops::C> a = [] {
        auto c = Ops::make();
        for (std::size_t i = 0; i < bits; i += 3) Ops::set(*c, i);
        return c;
    }();
    return *a;
}
template <class Ops>
const typename Ops::C& pattern_b() {
    static const std::unique_ptr<typename Ops::C> b = [] {
        auto c = Ops::make();
        const auto& p = b_pattern();
        for (std::size_t i = 0; i < bits; ++i)
            if (p[i]) Ops::set(*c, i);
        return c;
    }();
    return *b;
}

template <class Ops>
void bm_set_third(benchmark::State& state) {
    auto c = Ops::make();
    for (auto _ : state) {
        for (std::size_t i = 0; i < bits; i += 3) Ops::set(*c, i);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>((bits + 2) / 3));
}
template <class Ops>
void bm_test_all(benchmark::State& state) {
    const auto& a = pattern_a<Ops>();
    for (auto _ : state) {
        std::size_t ones = 0;
        for (std::size_t i = 0; i < bits; ++i) ones += Ops::get(a, i);
        benchmark::DoNotOptimize(ones);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(bits));
}
template <class Ops, bool is_and>
void bm_combine(benchmark::State& state) {
    auto a = std::make_unique<typename Ops::C>(pattern_a<Ops>());
    const auto& b = pattern_b<Ops>();
    for (auto _ : state) {
        if constexpr (is_and) Ops::and_assign(*a, b); else Ops::or_assign(*a, b);
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(operand_bytes));
}
template <class Ops>
void bm_count(benchmark::State& state) {
    const auto& b = pattern_b<Ops>();
    for (auto _ : state) benchmark::DoNotOptimize(Ops::count(b));
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(operand_bytes));
}
template <class Ops>
void bm_iterate(benchmark::State& state) {
    const auto& a = pattern_a<Ops>();
    for (auto _ : state) benchmark::DoNotOptimize(Ops::sum_set(a));
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>((bits + 2) / 3));
}
void bm_memcpy(benchmark::State& state) {
    std::vector<unsigned char> src(operand_bytes, 0x5a), dst(operand_bytes);
    for (auto _ : state) {
        std::memcpy(dst.data(), src.data(), operand_bytes);
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(operand_bytes));
}

// Rows of the summary, in order, and how each is measured.
struct Row {
    const char* name;
    bool bytes;         // throughput in GB/s of one operand; otherwise ns per bit touched
    std::size_t items;  // bits set, tested or visited per iteration
};
constexpr std::size_t thirds = (bits + 2) / 3;
const Row rows[] = {{"set every 3rd bit", false, thirds}, {"test every bit", false, bits}, {"&=", true, 0},
                    {"|=", true, 0}, {"count", true, 0}, {"iterate set bits", false, thirds}};
const char* const columns[] = {GrapeOps::name, GrapeRangeOps::name, BoostOps::name, BitsetOps::name,
                               VectorBoolOps::name, WordsOps::name};

template <class Ops>
void register_container(bool with_mutation = true) {
    auto reg = [](const std::string& row, auto fn) {
        benchmark::RegisterBenchmark((row + "/" + Ops::name).c_str(), fn)->MinTime(0.1)->Repetitions(5)->ReportAggregatesOnly(true);
    };
    if (with_mutation) {
        reg("set every 3rd bit", bm_set_third<Ops>);
        reg("test every bit", bm_test_all<Ops>);
        reg("&=", bm_combine<Ops, true>);
        reg("|=", bm_combine<Ops, false>);
        reg("count", bm_count<Ops>);
    }
    reg("iterate set bits", bm_iterate<Ops>);
}

// Keeps the median of each benchmark for the summary while the console shows everything.
class SummaryReporter : public benchmark::ConsoleReporter {
public:
    std::map<std::string, Run> medians;
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& run : runs)
            if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median") medians[run.run_name.function_name] = run;
        ConsoleReporter::ReportRuns(runs);
    }
};

template <class C>
std::size_t heap_bytes_of(std::function<std::unique_ptr<C>()> make) {
    const std::size_t before = g_heap_bytes;
    auto c = make();
    benchmark::DoNotOptimize(c.get());
    return g_heap_bytes - before;
}

void print_memory_table() {
    std::printf("Memory for %zu booleans (heap bytes allocated while building, plus the object):\n", bits);
    auto line = [](const char* name, std::size_t heap, std::size_t object) {
        std::printf("  %-24s %12zu bytes  (%6.3f bits per boolean)\n", name, heap + object,
                    8.0 * static_cast<double>(heap + object) / static_cast<double>(bits));
    };
    line("bool[]", heap_bytes_of<bool[]>([] { return std::make_unique<bool[]>(bits); }), 0);
    line("std::vector<char>", heap_bytes_of<std::vector<char>>([] { return std::make_unique<std::vector<char>>(bits); }), 0);
    line("std::vector<bool>", heap_bytes_of<std::vector<bool>>([] { return std::make_unique<std::vector<bool>>(bits); }), 0);
    line("std::bitset", heap_bytes_of<Bitset>([] { return std::make_unique<Bitset>(); }), 0);
    line("boost::dynamic_bitset", heap_bytes_of<Boost>([] { return std::make_unique<Boost>(bits); }), 0);
    line("grape::BitVector", heap_bytes_of<grape::BitVector>([] { return std::make_unique<grape::BitVector>(bits); }), 0);
    std::printf("  (each figure includes the container object itself, allocated on the heap here)\n\n");
}

void print_summary(const SummaryReporter& reporter) {
    // From the median CPU time per iteration (CPU time, not wall time: the machine is shared
    // and a descheduled benchmark should not look slow). 0 when the benchmark did not run.
    auto median = [&](const std::string& key, const Row& row) -> double {
        const auto it = reporter.medians.find(key);
        if (it == reporter.medians.end()) return 0.0;
        const double ns = it->second.GetAdjustedCPUTime() * 1e9 / benchmark::GetTimeUnitMultiplier(it->second.time_unit);
        return row.bytes ? static_cast<double>(operand_bytes) / ns : ns / static_cast<double>(row.items);
    };
    const double memcpy_gbs = median("memcpy (same bytes)", rows[2]);
    std::printf("\nSummary (median CPU time of 5 repetitions): GB/s of one %zu-byte operand for whole-vector rows (higher is better),\n"
                "ns per bit set/tested/visited for the others (lower is better). memcpy: %.1f GB/s.\n\n",
                operand_bytes, memcpy_gbs);
    std::printf("%-18s", "row");
    for (const char* c : columns) std::printf(" | %-14.14s", c);
    std::printf(" | best peer / grape\n");
    for (const Row& row : rows) {
        std::printf("%-18s", row.name);
        double grape = 0.0, best_peer = 0.0;
        for (const char* c : columns) {
            const double v = median(std::string(row.name) + "/" + c, row);
            if (v == 0.0) {
                std::printf(" | %-14s", "-");
                continue;
            }
            std::printf(" | %8.3f %-5s", v, row.bytes ? "GB/s" : "ns");
            const bool is_grape = std::string(c).rfind("grape::", 0) == 0;
            if (is_grape) {
                if (grape == 0.0 || (row.bytes ? v > grape : v < grape)) grape = v;
            } else if (best_peer == 0.0 || (row.bytes ? v > best_peer : v < best_peer)) {
                best_peer = v;
            }
        }
        // > 1 means grape is faster than the best peer.
        if (grape == 0.0 || best_peer == 0.0) {  // filtered out
            std::printf(" | -\n");
            continue;
        }
        const double speedup = row.bytes ? grape / best_peer : best_peer / grape;
        std::printf(" | %.2fx", speedup);
        if (row.bytes && memcpy_gbs > 0) std::printf("  (grape = %.2f x memcpy)", grape / memcpy_gbs);
        std::printf("\n");
    }
}

}  // namespace

int main(int argc, char** argv) {
    print_memory_table();
    register_container<GrapeOps>();
    register_container<GrapeRangeOps>(false);
    register_container<BoostOps>();
    register_container<BitsetOps>();
    register_container<VectorBoolOps>();
    register_container<WordsOps>();
    benchmark::RegisterBenchmark("memcpy (same bytes)", bm_memcpy)->MinTime(0.1)->Repetitions(5)->ReportAggregatesOnly(true);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    SummaryReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    print_summary(reporter);
    benchmark::Shutdown();
    return 0;
}
