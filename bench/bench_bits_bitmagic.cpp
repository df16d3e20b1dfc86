// See bench_bits_bitmagic.hpp.
#include "bench_bits_bitmagic.hpp"

#include <bm.h>

#include <benchmark/benchmark.h>

#include <memory>

namespace bitmagic_peer {
namespace {

using BV = bm::bvector<>;

std::unique_ptr<BV> g_sparse, g_dense_a, g_dense_b;

std::unique_ptr<BV> build(std::size_t bits, const std::vector<std::uint32_t>& set) {
    auto bv = std::make_unique<BV>(static_cast<bm::id_t>(bits));
    for (const std::uint32_t i : set) bv->set_bit(i);
    bv->optimize();
    return bv;
}

}  // namespace

void register_rows(const Patterns& p) {
    g_sparse = build(p.bits, p.sparse);
    g_dense_a = build(p.bits, p.dense_a);
    g_dense_b = build(p.bits, p.dense_b);
    auto reg = [](const char* name, void (*fn)(benchmark::State&)) {
        benchmark::RegisterBenchmark(name, fn)->MinTime(0.1)->Repetitions(5)->ReportAggregatesOnly(true);
    };
    reg("sparse count/BitMagic bvector", [](benchmark::State& s) {
        for (auto _ : s) benchmark::DoNotOptimize(g_sparse->count());
    });
    reg("sparse iterate/BitMagic bvector", [](benchmark::State& s) {
        for (auto _ : s) {
            std::size_t sum = 0;
            for (BV::enumerator en = g_sparse->first(); en.valid(); ++en) sum += *en;
            benchmark::DoNotOptimize(sum);
        }
    });
    reg("dense &=/BitMagic bvector", [](benchmark::State& s) {
        BV a(*g_dense_a);
        for (auto _ : s) {
            a &= *g_dense_b;
            benchmark::ClobberMemory();
        }
    });
    reg("dense &= + count/BitMagic bvector", [](benchmark::State& s) {
        BV a(*g_dense_a);
        for (auto _ : s) {
            a &= *g_dense_b;
            benchmark::DoNotOptimize(a.count());
        }
    });
}

std::size_t sparse_memory_bytes() {
    BV::statistics st;
    g_sparse->calc_stat(&st);
    return st.memory_used;
}

}  // namespace bitmagic_peer
