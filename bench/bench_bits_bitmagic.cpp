// See bench_bits_bitmagic.hpp.
#include "bench_bits_bitmagic.hpp"

#include <bm.h>
#include <bmalgo.h>

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

// The visitor bm::for_each_bit calls: bits by blocks of offsets, runs of ones as ranges.
struct SumVisitor {
    using size_type = BV::size_type;
    std::size_t sum = 0;
    int add_bits(size_type offset, const unsigned char* bits, unsigned size) {
        for (unsigned i = 0; i < size; ++i) sum += offset + bits[i];
        return 0;
    }
    int add_range(size_type offset, size_type size) {
        sum += size * offset + size * (size - 1) / 2;
        return 0;
    }
};

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
    reg("sparse iterate/BitMagic for_each_bit", [](benchmark::State& s) {
        for (auto _ : s) {
            SumVisitor sum;
            bm::for_each_bit(*g_sparse, sum);
            benchmark::DoNotOptimize(sum.sum);
        }
    });
    reg("sparse toggle + count/BitMagic bvector", [](benchmark::State& s) {
        BV v(*g_sparse);  // a copy: the shared vector stays as built for the memory row
        bm::id_t i = 0;
        for (auto _ : s) {
            i = (i + 1'000'003) % v.size();
            v.flip(i);
            benchmark::DoNotOptimize(v.count());
            v.flip(i);
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
