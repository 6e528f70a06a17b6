// Uniform density (docs/algorithm.md §3) from the N = 16 table: whole-patch emission with construction, as
// cp_runtime/emit and opensubdiv/emit time it, on the bulk factor sets. UniformPatch where every factor is at
// most 16, both layouts; the same patch emitted element by element through vertex(i) and triangle(p) (what
// emit() did before its bulk path); UniformSplit (§3.5) on the sets above 16.
#include <ctess/domain_point.hpp>
#include <ctess/runtime/uniform_patch.hpp>
#include <ctess/runtime/uniform_split.hpp>

#include <cstdint>
#include <span>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench_workloads.hpp"

namespace {

using ctess::DomainPoint;
namespace bench = ctess::bench;

const ctess::rt::UniformTableSet& tables() {
    return ctess::rt::uniform_tables_16;
}

// UniformPatch emitted through random access, one call per element.
struct ByElement : ctess::rt::UniformPatch {
    using UniformPatch::UniformPatch;
    bool emit(std::span<DomainPoint> vertices, std::span<std::uint32_t> indices) const noexcept {
        const ctess::Counts n = counts();
        if (vertices.size() < n.vertices || indices.size() < n.index_count()) return false;
        for (std::uint32_t i = 0; i < n.vertices; ++i) vertices[i] = vertex(i);
        for (std::uint32_t p = 0; p < n.triangles; ++p) {
            const ctess::rt::UniformTriangle t = triangle(p);
            indices[3 * p] = t[0], indices[3 * p + 1] = t[1], indices[3 * p + 2] = t[2];
        }
        return true;
    }
};

// Construction plus emit, per iteration (as cp_runtime/emit).
template <class Patch, ctess::Layout layout>
void uniform_emit(benchmark::State& state) {
    const ctess::PatchOptions options{layout, ctess::Winding::ccw};
    const Patch probe(tables(), bench::factor(state, 0), bench::factor(state, 1), bench::factor(state, 2),
                      options);
    const ctess::Counts n = probe.counts();
    std::vector<DomainPoint> vertices(n.vertices);
    std::vector<std::uint32_t> indices(n.index_count());
    for (auto _ : state) {
        float f0 = bench::factor(state, 0), f1 = bench::factor(state, 1), f2 = bench::factor(state, 2);
        benchmark::DoNotOptimize(f0); // keeps the construction inside the loop
        const Patch patch(tables(), f0, f1, f2, options);
        benchmark::DoNotOptimize(patch.emit(vertices, indices));
        benchmark::ClobberMemory();
    }
    bench::count_triangles(state, n.triangles);
    state.counters["verts"] = static_cast<double>(n.vertices);
}

// The bulk factor sets whose factors are all within the table (within = true) or not.
template <bool within>
void factor_sets(benchmark::internal::Benchmark* b) {
    b->ArgNames({"f0", "f1", "f2"});
    for (const auto& f : bench::bulk_factors)
        if ((f[0] <= 16 && f[1] <= 16 && f[2] <= 16) == within) b->Args({f[0], f[1], f[2]});
}

using ctess::Layout;
using ctess::rt::UniformPatch;
using ctess::rt::UniformSplit;

} // namespace

BENCHMARK(uniform_emit<UniformPatch, Layout::provoking>)->Name("uniform/emit")->Apply(factor_sets<true>);
BENCHMARK(uniform_emit<UniformPatch, Layout::shared>)->Name("uniform/emit_shared")->Apply(factor_sets<true>);
BENCHMARK(uniform_emit<ByElement, Layout::provoking>)
    ->Name("uniform/emit_by_element")
    ->Apply(factor_sets<true>);
BENCHMARK(uniform_emit<ByElement, Layout::shared>)
    ->Name("uniform/emit_by_element_shared")
    ->Apply(factor_sets<true>);
BENCHMARK(uniform_emit<UniformSplit, Layout::provoking>)
    ->Name("uniform/split_emit")
    ->Apply(factor_sets<false>);
BENCHMARK(uniform_emit<UniformSplit, Layout::shared>)
    ->Name("uniform/split_emit_shared")
    ->Apply(factor_sets<false>);
