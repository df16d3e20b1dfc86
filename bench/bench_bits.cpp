// BitVector against std::vector<bool>, boost::dynamic_bitset, std::bitset and plain word
// loops on 10,000,000 bits, with memcpy of the same bytes as the memory-speed reference, all
// in one run. Prints the memory table first and two summaries with ratios last: the
// whole-vector rows, then the rows on parts of the vector (shifts, ranges, rank/select,
// backward search, insert/erase, order, push_back).
//
//   build-bench/bench/bench_bits [--benchmark_filter=...] [--benchmark_enable_random_interleaving=true]
#include <grape/bits.hpp>
#include <grape/sparse_bits.hpp>

#include <benchmark/benchmark.h>
#include <boost/dynamic_bitset.hpp>

#include "bench_bits_boost_popcnt.hpp"

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
#include <type_traits>
#include <vector>

#if GRAPE_BENCH_BITMAGIC
#include "bench_bits_bitmagic.hpp"
#endif
#include "heap_hooks.hpp"

// ---- heap accounting for the memory table: every operator new in this program is counted ----
namespace {
std::size_t g_heap_bytes = 0;
}
void heap_hooks::on_alloc(void*, std::size_t n) noexcept { g_heap_bytes += n; }
void heap_hooks::on_free(void*) noexcept {}

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
// The same boost::dynamic_bitset with count() compiled for popcnt (count only).
struct BoostPopcntOps : BoostOps {
    static constexpr const char* name = "boost -mpopcnt";
    static std::size_t count(const C& c) { return boost_popcnt::count(c); }
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

// Plain word loops over a std::vector<uint64_t>: a plain countr_zero loop and a
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
const char* const columns[] = {GrapeOps::name, GrapeRangeOps::name, BoostOps::name, BoostPopcntOps::name, BitsetOps::name,
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


// ---- the operations that move, count or search a part of the vector ----
// Every contender does the same job on the same 10,000,000 bits; the rows are registered
// contender by contender within each row, and --benchmark_enable_random_interleaving mixes
// the repetitions of all of them.

constexpr std::size_t shift_by = 37;                    // not a whole number of words
constexpr std::size_t range_first = 3, range_last = bits - 5;  // partial words at both ends

// One bit set, at index 0: find_last/find_prev scan the whole vector.
template <class C, class Make, class Set>
std::unique_ptr<C> only_bit_zero(Make make, Set set) {
    auto c = make();
    set(*c, 0);
    return c;
}

struct NewRow {
    const char* name;
    double bytes_touched;  // bytes of one operand read (and written) per iteration; 0: per bit
    std::size_t items;     // bits per iteration for the per-bit rows
};
const NewRow new_rows[] = {
    {"<<= 37", operand_bytes, 0},
    {">>= 37", operand_bytes, 0},
    {"set_range [3, n-5)", operand_bytes, 0},
    {"flip_range [3, n-5)", operand_bytes, 0},
    {"count_range [3, n-5)", operand_bytes, 0},
    {"rank(n-5)", operand_bytes, 0},
    {"select(count/2)", operand_bytes / 2.0, 0},
    {"find_last (only bit 0 set)", operand_bytes, 0},
    {"find_prev(n-1) (only bit 0 set)", operand_bytes, 0},
    {"insert(0) + erase(0)", 2.0 * operand_bytes, 0},
    {"< (equal vectors)", 2.0 * operand_bytes, 0},
    {"push_back n bits", 0, bits},
};
const char* const new_columns[] = {"grape::BitVector", "boost::dynamic_bitset", "std::vector<bool>", "plain uint64_t loop"};

void reg_new(const std::string& row, const char* contender, void (*fn)(benchmark::State&)) {
    benchmark::RegisterBenchmark((row + "/" + contender).c_str(), fn)->MinTime(0.1)->Repetitions(5)->ReportAggregatesOnly(true);
}

// A fresh copy of pattern B for the benchmarks that change the vector.
template <class Ops>
std::unique_ptr<typename Ops::C> copy_b() { return std::make_unique<typename Ops::C>(pattern_b<Ops>()); }

// Plain word loops for the rows without a library peer: what one would write by hand
// (scalar, std::popcount compiled for popcnt, no vector types).
namespace plain {
using W = std::uint64_t;
void shift_up(std::vector<W>& w, std::size_t s) {
    const std::size_t ws = s / 64, bs = s % 64;
    for (std::size_t k = w.size(); k-- > ws + 1;) w[k] = (w[k - ws] << bs) | (w[k - ws - 1] >> (64 - bs));
    w[ws] = w[0] << bs;
    for (std::size_t k = 0; k < ws; ++k) w[k] = 0;
    w.back() &= (W{1} << (bits % 64)) - 1;
}
void shift_down(std::vector<W>& w, std::size_t s) {
    const std::size_t ws = s / 64, bs = s % 64, n = w.size();
    for (std::size_t k = 0; k + ws + 1 < n; ++k) w[k] = (w[k + ws] >> bs) | (w[k + ws + 1] << (64 - bs));
    w[n - ws - 1] = w[n - 1] >> bs;
    for (std::size_t k = n - ws; k < n; ++k) w[k] = 0;
}
W head(std::size_t first) { return ~((W{1} << (first % 64)) - 1); }
W tail(std::size_t last) { return last % 64 == 0 ? ~W{0} : (W{1} << (last % 64)) - 1; }
void set_range(std::vector<W>& w, std::size_t first, std::size_t last) {
    const std::size_t k0 = first / 64, k1 = (last - 1) / 64;
    w[k0] |= head(first);
    for (std::size_t k = k0 + 1; k < k1; ++k) w[k] = ~W{0};
    w[k1] |= tail(last);
}
void flip_range(std::vector<W>& w, std::size_t first, std::size_t last) {
    const std::size_t k0 = first / 64, k1 = (last - 1) / 64;
    w[k0] ^= head(first);
    for (std::size_t k = k0 + 1; k < k1; ++k) w[k] = ~w[k];
    w[k1] ^= tail(last);
}
__attribute__((target("popcnt"))) std::size_t count_range(const std::vector<W>& w, std::size_t first, std::size_t last) {
    const std::size_t k0 = first / 64, k1 = (last - 1) / 64;
    std::size_t c = static_cast<std::size_t>(std::popcount(w[k0] & head(first)));
    for (std::size_t k = k0 + 1; k < k1; ++k) c += static_cast<std::size_t>(std::popcount(w[k]));
    return c + static_cast<std::size_t>(std::popcount(w[k1] & tail(last)));
}
__attribute__((target("popcnt"))) std::size_t rank(const std::vector<W>& w, std::size_t i) {
    std::size_t c = 0;
    for (std::size_t k = 0; k < i / 64; ++k) c += static_cast<std::size_t>(std::popcount(w[k]));
    if (i % 64) c += static_cast<std::size_t>(std::popcount(w[i / 64] & ((W{1} << (i % 64)) - 1)));
    return c;
}
__attribute__((target("popcnt"))) std::size_t select(const std::vector<W>& w, std::size_t r) {
    for (std::size_t k = 0; k < w.size(); ++k) {
        const std::size_t c = static_cast<std::size_t>(std::popcount(w[k]));
        if (r < c) {
            W x = w[k];
            for (; r > 0; --r) x &= x - 1;
            return k * 64 + static_cast<std::size_t>(std::countr_zero(x));
        }
        r -= c;
    }
    return static_cast<std::size_t>(-1);
}
std::size_t find_prev(const std::vector<W>& w, std::size_t i) {  // highest set bit below i
    if (i == 0) return static_cast<std::size_t>(-1);
    std::size_t k = (i - 1) / 64;
    W x = w[k] & tail(i);
    while (x == 0) {
        if (k == 0) return static_cast<std::size_t>(-1);
        x = w[--k];
    }
    return k * 64 + 63 - static_cast<std::size_t>(std::countl_zero(x));
}
}  // namespace plain

std::size_t g_select_rank = 0;  // count(B)/2, set before the runs

template <class C>
void keep(const C& c) {
    benchmark::DoNotOptimize(&c);
    benchmark::ClobberMemory();
}

void register_new_rows() {
    using G = GrapeOps;
    using B = BoostOps;
    using V = VectorBoolOps;
    using P = WordsOps;
    // shifts
    reg_new("<<= 37", G::name, [](benchmark::State& s) { auto a = copy_b<G>(); for (auto _ : s) { *a <<= shift_by; keep(*a); } });
    reg_new("<<= 37", B::name, [](benchmark::State& s) { auto a = copy_b<B>(); for (auto _ : s) { *a <<= shift_by; keep(*a); } });
    reg_new("<<= 37", V::name, [](benchmark::State& s) {
        auto a = copy_b<V>();
        for (auto _ : s) {
            std::copy_backward(a->begin(), a->end() - shift_by, a->end());
            std::fill(a->begin(), a->begin() + shift_by, false);
            keep(*a);
        }
    });
    reg_new("<<= 37", P::name, [](benchmark::State& s) { auto a = copy_b<P>(); for (auto _ : s) { plain::shift_up(a->w, shift_by); keep(*a); } });
    reg_new(">>= 37", G::name, [](benchmark::State& s) { auto a = copy_b<G>(); for (auto _ : s) { *a >>= shift_by; keep(*a); } });
    reg_new(">>= 37", B::name, [](benchmark::State& s) { auto a = copy_b<B>(); for (auto _ : s) { *a >>= shift_by; keep(*a); } });
    reg_new(">>= 37", V::name, [](benchmark::State& s) {
        auto a = copy_b<V>();
        for (auto _ : s) {
            std::copy(a->begin() + shift_by, a->end(), a->begin());
            std::fill(a->end() - shift_by, a->end(), false);
            keep(*a);
        }
    });
    reg_new(">>= 37", P::name, [](benchmark::State& s) { auto a = copy_b<P>(); for (auto _ : s) { plain::shift_down(a->w, shift_by); keep(*a); } });
    // ranges
    reg_new("set_range [3, n-5)", G::name, [](benchmark::State& s) { auto a = copy_b<G>(); for (auto _ : s) { a->set_range(range_first, range_last); keep(*a); } });
    reg_new("set_range [3, n-5)", B::name, [](benchmark::State& s) { auto a = copy_b<B>(); for (auto _ : s) { a->set(range_first, range_last - range_first, true); keep(*a); } });
    reg_new("set_range [3, n-5)", V::name, [](benchmark::State& s) {
        auto a = copy_b<V>();
        for (auto _ : s) { std::fill(a->begin() + range_first, a->begin() + range_last, true); keep(*a); }
    });
    reg_new("set_range [3, n-5)", P::name, [](benchmark::State& s) { auto a = copy_b<P>(); for (auto _ : s) { plain::set_range(a->w, range_first, range_last); keep(*a); } });
    reg_new("flip_range [3, n-5)", G::name, [](benchmark::State& s) { auto a = copy_b<G>(); for (auto _ : s) { a->flip_range(range_first, range_last); keep(*a); } });
    reg_new("flip_range [3, n-5)", B::name, [](benchmark::State& s) { auto a = copy_b<B>(); for (auto _ : s) { a->flip(range_first, range_last - range_first); keep(*a); } });
    reg_new("flip_range [3, n-5)", V::name, [](benchmark::State& s) {
        auto a = copy_b<V>();
        for (auto _ : s) { for (auto it = a->begin() + range_first; it != a->begin() + range_last; ++it) (*it).flip(); keep(*a); }
    });
    reg_new("flip_range [3, n-5)", P::name, [](benchmark::State& s) { auto a = copy_b<P>(); for (auto _ : s) { plain::flip_range(a->w, range_first, range_last); keep(*a); } });
    // counts and searches (boost 1.74 has no range count, rank, select, find_last or find_prev)
    reg_new("count_range [3, n-5)", G::name, [](benchmark::State& s) { const auto& a = pattern_b<G>(); for (auto _ : s) benchmark::DoNotOptimize(a.count_range(range_first, range_last)); });
    reg_new("count_range [3, n-5)", V::name, [](benchmark::State& s) {
        const auto& a = pattern_b<V>();
        for (auto _ : s) benchmark::DoNotOptimize(std::count(a.begin() + range_first, a.begin() + range_last, true));
    });
    reg_new("count_range [3, n-5)", P::name, [](benchmark::State& s) { const auto& a = pattern_b<P>(); for (auto _ : s) benchmark::DoNotOptimize(plain::count_range(a.w, range_first, range_last)); });
    reg_new("rank(n-5)", G::name, [](benchmark::State& s) { const auto& a = pattern_b<G>(); for (auto _ : s) benchmark::DoNotOptimize(a.rank(range_last)); });
    reg_new("rank(n-5)", V::name, [](benchmark::State& s) {
        const auto& a = pattern_b<V>();
        for (auto _ : s) benchmark::DoNotOptimize(std::count(a.begin(), a.begin() + range_last, true));
    });
    reg_new("rank(n-5)", P::name, [](benchmark::State& s) { const auto& a = pattern_b<P>(); for (auto _ : s) benchmark::DoNotOptimize(plain::rank(a.w, range_last)); });
    reg_new("select(count/2)", G::name, [](benchmark::State& s) { const auto& a = pattern_b<G>(); for (auto _ : s) benchmark::DoNotOptimize(a.select(g_select_rank)); });
    reg_new("select(count/2)", V::name, [](benchmark::State& s) {
        const auto& a = pattern_b<V>();
        for (auto _ : s) {
            std::size_t r = g_select_rank, i = 0;
            for (; i < bits; ++i)
                if (a[i] && r-- == 0) break;
            benchmark::DoNotOptimize(i);
        }
    });
    reg_new("select(count/2)", P::name, [](benchmark::State& s) { const auto& a = pattern_b<P>(); for (auto _ : s) benchmark::DoNotOptimize(plain::select(a.w, g_select_rank)); });
    reg_new("find_last (only bit 0 set)", G::name, [](benchmark::State& s) {
        const auto a = only_bit_zero<G::C>(G::make, G::set);
        for (auto _ : s) benchmark::DoNotOptimize(a->find_last());
    });
    reg_new("find_last (only bit 0 set)", V::name, [](benchmark::State& s) {
        const auto a = only_bit_zero<V::C>(V::make, V::set);
        for (auto _ : s) benchmark::DoNotOptimize(std::find(a->rbegin(), a->rend(), true));
    });
    reg_new("find_last (only bit 0 set)", P::name, [](benchmark::State& s) {
        const auto a = only_bit_zero<P::C>(P::make, P::set);
        for (auto _ : s) benchmark::DoNotOptimize(plain::find_prev(a->w, bits));
    });
    reg_new("find_prev(n-1) (only bit 0 set)", G::name, [](benchmark::State& s) {
        const auto a = only_bit_zero<G::C>(G::make, G::set);
        for (auto _ : s) benchmark::DoNotOptimize(a->find_prev(bits - 1));
    });
    reg_new("find_prev(n-1) (only bit 0 set)", V::name, [](benchmark::State& s) {
        const auto a = only_bit_zero<V::C>(V::make, V::set);
        for (auto _ : s) benchmark::DoNotOptimize(std::find(a->rbegin() + 1, a->rend(), true));
    });
    reg_new("find_prev(n-1) (only bit 0 set)", P::name, [](benchmark::State& s) {
        const auto a = only_bit_zero<P::C>(P::make, P::set);
        for (auto _ : s) benchmark::DoNotOptimize(plain::find_prev(a->w, bits - 1));
    });
    // edits (boost 1.74 has no insert or erase)
    reg_new("insert(0) + erase(0)", G::name, [](benchmark::State& s) {
        auto a = copy_b<G>();
        for (auto _ : s) { a->insert(0, true); a->erase(0); keep(*a); }
    });
    reg_new("insert(0) + erase(0)", V::name, [](benchmark::State& s) {
        auto a = copy_b<V>();
        for (auto _ : s) { a->insert(a->begin(), true); a->erase(a->begin()); keep(*a); }
    });
    // comparison of equal vectors: every word is read
    reg_new("< (equal vectors)", G::name, [](benchmark::State& s) { const auto a = copy_b<G>(); const auto& b = pattern_b<G>(); for (auto _ : s) benchmark::DoNotOptimize(*a < b); });
    reg_new("< (equal vectors)", B::name, [](benchmark::State& s) { const auto a = copy_b<B>(); const auto& b = pattern_b<B>(); for (auto _ : s) benchmark::DoNotOptimize(*a < b); });
    reg_new("< (equal vectors)", V::name, [](benchmark::State& s) { const auto a = copy_b<V>(); const auto& b = pattern_b<V>(); for (auto _ : s) benchmark::DoNotOptimize(*a < b); });
    // growth one bit at a time
    reg_new("push_back n bits", G::name, [](benchmark::State& s) {
        for (auto _ : s) { grape::BitVector v; for (std::size_t i = 0; i < bits; ++i) v.push_back(i % 3 == 0); keep(v); }
    });
    reg_new("push_back n bits", B::name, [](benchmark::State& s) {
        for (auto _ : s) { Boost v; for (std::size_t i = 0; i < bits; ++i) v.push_back(i % 3 == 0); keep(v); }
    });
    reg_new("push_back n bits", V::name, [](benchmark::State& s) {
        for (auto _ : s) { std::vector<bool> v; for (std::size_t i = 0; i < bits; ++i) v.push_back(i % 3 == 0); keep(v); }
    });
    // the memory-speed references for the in-place rows
    benchmark::RegisterBenchmark("memmove in place by 8 bytes", [](benchmark::State& s) {
        std::vector<unsigned char> buf(operand_bytes + 8, 0x5a);
        for (auto _ : s) {
            std::memmove(buf.data() + 8, buf.data(), operand_bytes);
            benchmark::ClobberMemory();
        }
    })->MinTime(0.1)->Repetitions(5)->ReportAggregatesOnly(true);
}

void print_new_summary(const SummaryReporter& reporter) {
    auto ns_of = [&](const std::string& key) -> double {
        const auto it = reporter.medians.find(key);
        if (it == reporter.medians.end()) return 0.0;
        return it->second.GetAdjustedCPUTime() * 1e9 / benchmark::GetTimeUnitMultiplier(it->second.time_unit);
    };
    const double memcpy_ns = ns_of("memcpy (same bytes)"), memmove_ns = ns_of("memmove in place by 8 bytes");
    std::printf("\nParts of the vector (median CPU time of 5 repetitions): GB/s of the operand bytes read\n"
                "(higher is better), ns per bit for push_back. References: memcpy %.1f GB/s, memmove in place %.1f GB/s.\n\n",
                memcpy_ns > 0 ? operand_bytes / memcpy_ns : 0.0, memmove_ns > 0 ? operand_bytes / memmove_ns : 0.0);
    std::printf("%-32s", "row");
    for (const char* c : new_columns) std::printf(" | %-14.14s", c);
    std::printf(" | best peer / grape | grape / memcpy | grape / memmove in place\n");
    for (const NewRow& row : new_rows) {
        std::printf("%-32s", row.name);
        double grape = 0.0, best_peer = 0.0;
        const bool per_bit = row.bytes_touched == 0;
        for (const char* c : new_columns) {
            const double ns = ns_of(std::string(row.name) + "/" + c);
            if (ns == 0.0) {
                std::printf(" | %-14s", "-");
                continue;
            }
            const double v = per_bit ? ns / static_cast<double>(row.items) : row.bytes_touched / ns;
            std::printf(" | %8.3f %-5s", v, per_bit ? "ns" : "GB/s");
            double& best = std::string(c) == new_columns[0] ? grape : best_peer;
            if (best == 0.0 || (per_bit ? v < best : v > best)) best = v;
        }
        if (grape == 0.0 || best_peer == 0.0) {
            std::printf(" | -");
        } else {
            std::printf(" | %.2fx", per_bit ? best_peer / grape : grape / best_peer);
        }
        if (!per_bit && grape > 0 && memcpy_ns > 0) std::printf(" | %.2f", grape / (operand_bytes / memcpy_ns));
        if (!per_bit && grape > 0 && memmove_ns > 0) std::printf(" | %.2f", grape / (operand_bytes / memmove_ns));
        std::printf("\n");
    }
}


// ---- SparseBitVector against BitVector and (with -DGRAPE_BITMAGIC_DIR) BitMagic ----

// Random bits at density 1/1000 (10,000 of the 10,000,000), the same in every contender.
const std::vector<std::uint32_t>& sparse_pattern() {
    static const std::vector<std::uint32_t> set = [] {
        std::mt19937_64 rng(1000);
        std::bernoulli_distribution bit(0.001);
        std::vector<std::uint32_t> s;
        for (std::size_t i = 0; i < bits; ++i)
            if (bit(rng)) s.push_back(static_cast<std::uint32_t>(i));
        return s;
    }();
    return set;
}
template <class C>
C& sparse_of() {
    static C c = [] {
        C v(bits);
        for (const std::uint32_t i : sparse_pattern()) v.set(i);
        if constexpr (std::is_same_v<C, grape::SparseBitVector>) v.shrink_to_fit();
        return v;
    }();
    return c;
}
template <class C>
C dense_of(bool b) {
    C v(bits);
    if (b) {
        const auto& p = b_pattern();
        for (std::size_t i = 0; i < bits; ++i)
            if (p[i]) v.set(i);
    } else {
        for (std::size_t i = 0; i < bits; i += 3) v.set(i);
    }
    return v;
}

template <class C>
void register_sparse_rows(const char* name) {
    auto reg = [](const std::string& row, const char* contender, void (*fn)(benchmark::State&)) {
        benchmark::RegisterBenchmark((row + "/" + contender).c_str(), fn)->MinTime(0.1)->Repetitions(5)->ReportAggregatesOnly(true);
    };
    reg("sparse count", name, [](benchmark::State& s) {
        const C& v = sparse_of<C>();
        for (auto _ : s) benchmark::DoNotOptimize(v.count());
    });
    reg("sparse iterate", name, [](benchmark::State& s) {
        const C& v = sparse_of<C>();
        for (auto _ : s) {
            std::size_t sum = 0;
            v.for_each_set([&sum](std::size_t i) { sum += i; });
            benchmark::DoNotOptimize(sum);
        }
    });
    // Fresh work for every contender: one bit toggled (a block of SparseBitVector gains or
    // loses a bit, and its count with it), the count taken, the bit toggled back.
    reg("sparse toggle + count", name, [](benchmark::State& s) {
        C v = sparse_of<C>();  // a copy: the shared vector stays as built for the memory row
        std::size_t i = 0;
        for (auto _ : s) {
            i = (i + 1'000'003) % bits;
            v.set(i, !v.get(i));
            benchmark::DoNotOptimize(v.count());
            v.set(i, !v.get(i));
        }
    });
    reg("dense &=", name, [](benchmark::State& s) {
        C a = dense_of<C>(false);
        const C b = dense_of<C>(true);
        for (auto _ : s) {
            a &= b;
            benchmark::ClobberMemory();
        }
    });
    // The and followed by the count of the result (SparseBitVector counts its bitmap blocks
    // there, not in the and).
    reg("dense &= + count", name, [](benchmark::State& s) {
        C a = dense_of<C>(false);
        const C b = dense_of<C>(true);
        for (auto _ : s) {
            a &= b;
            benchmark::DoNotOptimize(a.count());
        }
    });
}

// The last column is BitMagic's visitor (bm::for_each_bit), beside its enumerator.
const char* const sparse_columns[] = {"grape::SparseBitVector", "grape::BitVector", "BitMagic bvector",
                                      "BitMagic for_each_bit"};

void register_sparse_benchmarks() {
    register_sparse_rows<grape::SparseBitVector>(sparse_columns[0]);
    register_sparse_rows<grape::BitVector>(sparse_columns[1]);
#if GRAPE_BENCH_BITMAGIC
    bitmagic_peer::Patterns p;
    p.bits = bits;
    p.sparse = sparse_pattern();
    for (std::size_t i = 0; i < bits; i += 3) p.dense_a.push_back(static_cast<std::uint32_t>(i));
    const auto& b = b_pattern();
    for (std::size_t i = 0; i < bits; ++i)
        if (b[i]) p.dense_b.push_back(static_cast<std::uint32_t>(i));
    bitmagic_peer::register_rows(p);
#endif
}

void print_sparse_summary(const SummaryReporter& reporter) {
    auto ns_of = [&](const std::string& key) -> double {
        const auto it = reporter.medians.find(key);
        if (it == reporter.medians.end()) return 0.0;
        return it->second.GetAdjustedCPUTime() * 1e9 / benchmark::GetTimeUnitMultiplier(it->second.time_unit);
    };
    const double ones = static_cast<double>(sparse_pattern().size());
    std::printf("\nSparse bits: %zu bits, %zu set (density 1/1000) for count and iterate; dense &= on the\n"
                "density-1/3 and 1/2 patterns (GB/s of one 1.25 MB operand). Median CPU time of 5 repetitions.\n\n",
                bits, sparse_pattern().size());
    std::printf("%-22s", "row");
    for (const char* c : sparse_columns) std::printf(" | %-22s", c);
    std::printf(" | best BitMagic / SparseBitVector\n");
    struct R {
        const char* name;
        const char* unit;
    };
    // "sparse count" on an unchanged vector reads grape's stored block counts (cached) while
    // BitMagic counts afresh; "sparse toggle + count" and "dense &= + count" are fresh work
    // for all.
    for (const R row : {R{"sparse count", "ns/call"}, R{"sparse toggle + count", "ns/call"}, R{"sparse iterate", "ns/bit"},
                        R{"dense &=", "GB/s"}, R{"dense &= + count", "GB/s"}}) {
        std::printf("%-22s", row.name);
        double v[4] = {0, 0, 0, 0};
        for (int k = 0; k < 4; ++k) {
            const double ns = ns_of(std::string(row.name) + "/" + sparse_columns[k]);
            if (ns == 0.0) {
                std::printf(" | %-22s", "-");
                continue;
            }
            v[k] = row.unit[0] == 'G' ? operand_bytes / ns : row.unit[3] == 'b' ? ns / ones : ns;
            std::printf(" | %12.3f %-9s", v[k], row.unit);
        }
        // > 1: SparseBitVector is faster than BitMagic's faster form.
        const bool higher_better = row.unit[0] == 'G';
        double bm = v[2];
        if (v[3] > 0 && (bm == 0 || (higher_better ? v[3] > bm : v[3] < bm))) bm = v[3];
        if (v[0] > 0 && bm > 0) std::printf(" | %.2fx", higher_better ? v[0] / bm : bm / v[0]);
        const double memcpy_ns = ns_of("memcpy (same bytes)");
        if (row.unit[0] == 'G' && v[0] > 0 && memcpy_ns > 0)
            std::printf("  (SparseBitVector = %.2f x memcpy)", v[0] / (operand_bytes / memcpy_ns));
        std::printf("\n");
    }
    std::printf("memory (bytes)         | %12zu %-9s | %12zu %-9s |", sparse_of<grape::SparseBitVector>().memory_bytes(), "",
                sparse_of<grape::BitVector>().memory_bytes(), "");
#if GRAPE_BENCH_BITMAGIC
    const std::size_t bm_bytes = bitmagic_peer::sparse_memory_bytes();
    std::printf(" %12zu %-9s | SparseBitVector / BitMagic: %.2f\n", bm_bytes, "",
                static_cast<double>(sparse_of<grape::SparseBitVector>().memory_bytes()) / static_cast<double>(bm_bytes));
#else
    std::printf(" -\n");
#endif
}

}  // namespace

int main(int argc, char** argv) {
    print_memory_table();
    register_container<GrapeOps>();
    register_container<GrapeRangeOps>(false);
    register_container<BoostOps>();
    benchmark::RegisterBenchmark((std::string("count/") + BoostPopcntOps::name).c_str(), bm_count<BoostPopcntOps>)
        ->MinTime(0.1)
        ->Repetitions(5)
        ->ReportAggregatesOnly(true);
    register_container<BitsetOps>();
    register_container<VectorBoolOps>();
    register_container<WordsOps>();
    benchmark::RegisterBenchmark("memcpy (same bytes)", bm_memcpy)->MinTime(0.1)->Repetitions(5)->ReportAggregatesOnly(true);
    register_new_rows();
    register_sparse_benchmarks();
    g_select_rank = pattern_b<GrapeOps>().count() / 2;
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    SummaryReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    print_summary(reporter);
    print_new_summary(reporter);
    print_sparse_summary(reporter);
    benchmark::Shutdown();
    return 0;
}
