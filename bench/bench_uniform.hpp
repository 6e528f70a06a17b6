// Uniform density's whole-patch emission with construction (bench_uniform.cpp, bench_uniform_split.cpp),
// timed as cp_runtime/emit and opensubdiv/emit are, on the bulk factor sets, from the N = 16 table.
#pragma once
#include <ctess/core/domain_point.hpp>
#include <ctess/core/patch_options.hpp>
#include <ctess/runtime/uniform/table_set.hpp>

#include <cstdint>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench_workloads.hpp"

namespace ctess::bench {

inline constexpr std::int64_t uniform_max_factor = 16;

inline const rt::UniformTableSet& uniform_tables() {
    return rt::uniform_tables_16;
}

// Construction plus emit, per iteration.
template <class Patch, Layout layout>
void uniform_emit(benchmark::State& state) {
    const PatchOptions options{layout, Winding::ccw};
    const Patch probe(uniform_tables(), factor(state, 0), factor(state, 1), factor(state, 2), options);
    const Counts n = probe.counts();
    std::vector<typename Patch::point_type> vertices(n.vertices);
    std::vector<std::uint32_t> indices(n.index_count());
    for (auto _ : state) {
        float f0 = factor(state, 0), f1 = factor(state, 1), f2 = factor(state, 2);
        benchmark::DoNotOptimize(f0); // keeps the construction inside the loop
        const Patch patch(uniform_tables(), f0, f1, f2, options);
        benchmark::DoNotOptimize(patch.emit(vertices, indices));
        benchmark::ClobberMemory();
    }
    count_triangles(state, n.triangles);
    state.counters["verts"] = static_cast<double>(n.vertices);
}

// The bulk factor sets whose factors are all within the table (within = true), or not.
template <bool within>
void uniform_factor_sets(benchmark::internal::Benchmark* b) {
    b->ArgNames({"f0", "f1", "f2"});
    for (const auto& f : bulk_factors)
        if ((f[0] <= uniform_max_factor && f[1] <= uniform_max_factor && f[2] <= uniform_max_factor) ==
            within)
            b->Args({f[0], f[1], f[2]});
}

} // namespace ctess::bench
