// The table-driven CP runtime: counts only (cp_counts), bulk emission (CpPatchSetup + emit, both layouts; the
// portable build of the fast path, which emit() skips where it has AVX2; and CpPatch + emit, which also
// builds the random-access buckets), and random access to triangle(p) and vertex(i) on a CpPatch, as
// independent calls (throughput) and as a dependent chain (latency: each call's index waits for the previous
// call's result).
#include <ctess/core/config.hpp>
#include <ctess/core/domain_point.hpp>
#include <ctess/runtime/cp/patch.hpp>

#include <cstdint>
#include <span>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench_workloads.hpp"

namespace {

using ctess::DomainPoint;
namespace bench = ctess::bench;

const ctess::rt::CpTableSet& tables() {
    return ctess::max_tess_factor == 256 ? ctess::rt::cp_tables_256 : ctess::rt::cp_tables_64;
}

// Construction plus emit, per iteration: what a renderer pays per patch.
template <class Patch, ctess::Layout layout = ctess::Layout::provoking>
void cp_emit(benchmark::State& state) {
    const ctess::PatchOptions options{layout, ctess::Winding::ccw};
    const Patch probe(tables(), bench::factor(state, 0), bench::factor(state, 1), bench::factor(state, 2),
                      options);
    std::vector<DomainPoint> vertices(probe.vertex_count());
    std::vector<std::uint32_t> indices(3 * std::size_t{probe.triangle_count()});
    for (auto _ : state) {
        float f0 = bench::factor(state, 0), f1 = bench::factor(state, 1), f2 = bench::factor(state, 2);
        benchmark::DoNotOptimize(f0); // keeps the construction inside the loop
        const Patch patch(tables(), f0, f1, f2, options);
        benchmark::DoNotOptimize(patch.emit(vertices, indices));
        benchmark::ClobberMemory();
    }
    bench::count_triangles(state, probe.triangle_count());
    state.counters["verts"] = static_cast<double>(probe.vertex_count());
}

// The portable (16-byte vector) build of emit's fast path, which emit() skips on a machine with AVX2.
struct PortableEmit : ctess::rt::CpPatchSetup {
    using CpPatchSetup::CpPatchSetup;
    bool emit(std::span<DomainPoint> vertices, std::span<std::uint32_t> indices) const noexcept {
        if (vertices.size() < vertex_count() || indices.size() / 3 < triangle_count()) return false;
        emit_baseline(vertices.data(), indices.data());
        return true;
    }
};

// Counts only, per iteration: a GPU's first pass or an allocator. The factors change every call (the
// lerp moves), so nothing is hoisted out of the loop.
void cp_counts(benchmark::State& state) {
    const float f[3] = {bench::factor(state, 0), bench::factor(state, 1), bench::factor(state, 2)};
    std::uint32_t k = 0, sum = 0;
    for (auto _ : state) {
        const float nudge = static_cast<float>(k++ & 15u) * (1.0f / 64.0f);
        const ctess::Counts n = ctess::rt::cp_counts(tables(), f[0] - nudge, f[1] - nudge, f[2] - nudge);
        sum += n.vertices + n.triangles;
    }
    benchmark::DoNotOptimize(sum);
    bench::count_calls(state);
}

// Random triangle(p) on one patch: independent calls (chain = false) or a dependent chain.
template <class Patch, bool chain>
void cp_triangle(benchmark::State& state) {
    const Patch patch(tables(), bench::factor(state, 0), bench::factor(state, 1), bench::factor(state, 2));
    const std::vector<std::uint32_t> list = bench::random_indices(patch.triangle_count());
    const std::size_t mask = list.size() - 1;
    std::size_t k = 0;
    std::uint32_t carry = 0;
    for (auto _ : state) {
        const auto t = patch.triangle(list[k++ & mask] + (chain ? carry : 0u));
        // Chain: indices are < 2^31, so carry is 0, but the next call cannot start before this one ends.
        carry = chain ? t[0] >> 31 : carry + (t[0] ^ t[1] ^ t[2]);
    }
    benchmark::DoNotOptimize(carry);
    bench::count_calls(state);
}

template <class Patch, bool chain>
void cp_vertex(benchmark::State& state) {
    const Patch patch(tables(), bench::factor(state, 0), bench::factor(state, 1), bench::factor(state, 2));
    const std::vector<std::uint32_t> list = bench::random_indices(patch.vertex_count());
    const std::size_t mask = list.size() - 1;
    std::size_t k = 0;
    std::uint32_t carry = 0;
    for (auto _ : state) {
        const DomainPoint p = patch.vertex(list[k++ & mask] + (chain ? carry : 0u));
        carry = chain ? p.u >> 31 : carry + (p.u ^ p.v); // u <= 2^24: see cp_triangle
    }
    benchmark::DoNotOptimize(carry);
    bench::count_calls(state);
}

using Current = ctess::rt::CpPatch;
using Setup = ctess::rt::CpPatchSetup;

} // namespace

BENCHMARK(cp_emit<Setup>)->Name("cp_runtime/emit")->Apply(bench::bulk_factor_sets);
BENCHMARK(cp_emit<Setup, ctess::Layout::shared>)
    ->Name("cp_runtime/emit_shared")
    ->Apply(bench::bulk_factor_sets);
BENCHMARK(cp_emit<Current>)->Name("cp_runtime/patch_emit")->Apply(bench::bulk_factor_sets);
BENCHMARK(cp_emit<PortableEmit>)->Name("cp_runtime/emit_portable")->Apply(bench::bulk_factor_sets);
BENCHMARK(cp_counts)->Name("cp_runtime/counts")->Apply(bench::random_factor_sets);
BENCHMARK(cp_triangle<Current, false>)->Name("cp_runtime/triangle")->Apply(bench::random_factor_sets);
BENCHMARK(cp_triangle<Current, true>)->Name("cp_runtime/triangle_chain")->Apply(bench::random_factor_sets);
BENCHMARK(cp_vertex<Current, false>)->Name("cp_runtime/vertex")->Apply(bench::random_factor_sets);
BENCHMARK(cp_vertex<Current, true>)->Name("cp_runtime/vertex_chain")->Apply(bench::random_factor_sets);
