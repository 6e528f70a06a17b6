// The workloads every generator is timed on, so that one run prints comparable figures: the factor sets,
// the random index lists of the random-access runs, and the counters.
#pragma once
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

namespace ctess::bench {

// Bulk emission: one equal-factor set per octave and one mixed set, plus an equal and a
// mixed set at the uniform-density table's N = 16 (bench_uniform.cpp).
inline constexpr std::int64_t bulk_factors[][3] = {{8, 8, 8},    {32, 32, 32}, {64, 64, 64},
                                                   {32, 12, 20}, {16, 16, 16}, {16, 9, 11}};

inline void bulk_factor_sets(benchmark::internal::Benchmark* b) {
    b->ArgNames({"f0", "f1", "f2"});
    for (const auto& f : bulk_factors) b->Args({f[0], f[1], f[2]});
}

// Large factors, for the generators that take them (UniformSplit up to 32,768, OpenSubdiv): one patch of
// 65,536 and one of 16.8 M triangles (at 4,096 one iteration writes about 330 MB, so few iterations run).
inline constexpr std::int64_t large_factors[][3] = {{256, 256, 256}, {4096, 4096, 4096}};

inline void large_factor_sets(benchmark::internal::Benchmark* b) {
    b->ArgNames({"f0", "f1", "f2"});
    for (const auto& f : large_factors) b->Args({f[0], f[1], f[2]});
}

// Random access: the bulk sets plus one with a T0 edge (f1 = 1), which takes the collapse path.
inline void random_factor_sets(benchmark::internal::Benchmark* b) {
    bulk_factor_sets(b);
    b->Args({32, 1, 20});
}

inline float factor(const benchmark::State& state, int k) {
    return static_cast<float>(state.range(k));
}

// A fixed pseudo-random list of indices in [0, count); its length is a power of two, so that a run walks it
// with a mask.
inline constexpr std::size_t random_list_length = 4096;

inline std::vector<std::uint32_t> random_indices(std::uint32_t count, std::uint32_t seed = 4) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<std::uint32_t> pick(0, count - 1);
    std::vector<std::uint32_t> list(random_list_length);
    for (auto& i : list) i = pick(rng);
    return list;
}

// Triangles per second over the whole run (printed as e.g. 520M/s), and the patch's triangle count.
inline void count_triangles(benchmark::State& state, std::uint64_t triangles_per_iteration) {
    state.counters["tri/s"] = benchmark::Counter(static_cast<double>(triangles_per_iteration) *
                                                     static_cast<double>(state.iterations()),
                                                 benchmark::Counter::kIsRate);
    state.counters["tris"] = static_cast<double>(triangles_per_iteration);
}

// Seconds per random-access call (printed as e.g. 5.1ns): one call per iteration.
inline void count_calls(benchmark::State& state) {
    state.counters["per_call"] = benchmark::Counter(
        static_cast<double>(state.iterations()), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// Random access for a generator that has none: every query builds the whole patch into the buffers that
// `indices` points into (generate()) and reads one triangle of it.
template <class Index, class Generate>
void regenerate_per_query(benchmark::State& state, std::uint32_t triangles, const Index* indices,
                          Generate&& generate) {
    const std::vector<std::uint32_t> list = random_indices(triangles);
    const std::size_t mask = list.size() - 1;
    std::size_t k = 0;
    std::uint32_t carry = 0;
    for (auto _ : state) {
        generate();
        benchmark::ClobberMemory();
        const std::size_t p = list[k++ & mask];
        carry += static_cast<std::uint32_t>(indices[3 * p] ^ indices[3 * p + 1] ^ indices[3 * p + 2]);
    }
    benchmark::DoNotOptimize(carry);
    count_calls(state);
}

} // namespace ctess::bench
