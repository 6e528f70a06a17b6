// The procedural CP generator (cp::tessellate, constexpr/ctess/cp/pattern.hpp), the reference the runtime
// reproduces bit for bit: bulk emission, and random access by rebuilding the patch per query (it has no
// other way to reach one triangle).
#include <ctess/core/config.hpp>
#include <ctess/core/domain_point.hpp>
#include <ctess/cp/pattern.hpp>

#include <cstdint>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench_workloads.hpp"

namespace {

using ctess::DomainPoint;
namespace bench = ctess::bench;
namespace cp = ctess::cp;

struct ProceduralPatch {
    cp::PatternOptions options;
    ctess::Counts counts;
    std::vector<DomainPoint> vertices;
    std::vector<std::uint32_t> indices;

    explicit ProceduralPatch(const benchmark::State& state) {
        options.max_factor = ctess::max_tess_factor;
        counts = cp::pattern_counts(bench::factor(state, 0), bench::factor(state, 1), bench::factor(state, 2),
                                    options);
        vertices.resize(counts.vertices);
        indices.resize(3 * std::size_t{counts.triangles});
    }
    void generate(const benchmark::State& state) {
        float f0 = bench::factor(state, 0);
        benchmark::DoNotOptimize(f0);
        // The fill alone (the buffers were sized from the counts above): the generator's own cost, without
        // the counting pass the span overload adds.
        cp::detail::tessellate_into(vertices.data(), indices.data(), f0, bench::factor(state, 1),
                                    bench::factor(state, 2), options);
    }
};

void cp_procedural_emit(benchmark::State& state) {
    ProceduralPatch patch(state);
    for (auto _ : state) {
        patch.generate(state);
        benchmark::ClobberMemory();
    }
    bench::count_triangles(state, patch.counts.triangles);
}

void cp_procedural_triangle(benchmark::State& state) {
    ProceduralPatch patch(state);
    bench::regenerate_per_query(state, patch.counts.triangles, patch.indices.data(),
                                [&] { patch.generate(state); });
}

} // namespace

BENCHMARK(cp_procedural_emit)->Name("cp_procedural/emit")->Apply(bench::bulk_factor_sets);
BENCHMARK(cp_procedural_triangle)->Name("cp_procedural/triangle")->Apply(bench::random_factor_sets);
