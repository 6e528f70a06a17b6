// OpenSubdiv's Bfr::Tessellation (3.5) at the same integer rates: a triangle parameterization (Loop), facet
// size 3, the inner rate inferred (floor of the mean). OSD's edge k runs from corner k to corner k + 1, so
// the rates are (f0, f1, f2) in CP's edge order. Per patch: construct the Tessellation, then GetCoords and
// GetFacets into buffers made once (OpenSubdiv's documented usage). Random access rebuilds the patch per
// query.
#include <cstdint>
#include <vector>

#include <benchmark/benchmark.h>
#include <opensubdiv/bfr/parameterization.h>
#include <opensubdiv/bfr/tessellation.h>
#include <opensubdiv/sdc/types.h>

#include "bench_workloads.hpp"

namespace {

namespace bench = ctess::bench;
namespace Bfr = OpenSubdiv::Bfr;

struct OsdPatch {
    Bfr::Parameterization parameterization{OpenSubdiv::Sdc::SCHEME_LOOP, 3};
    Bfr::Tessellation::Options options;
    int rates[3] = {};
    int triangles = 0;
    std::vector<float> coords;
    std::vector<int> facets;

    explicit OsdPatch(const benchmark::State& state) {
        options.SetFacetSize(3);
        for (int k = 0; k < 3; ++k) rates[k] = static_cast<int>(state.range(k));
        const Bfr::Tessellation t(parameterization, 3, rates, options);
        triangles = t.GetNumFacets();
        coords.resize(2 * static_cast<std::size_t>(t.GetNumCoords()));
        facets.resize(3 * static_cast<std::size_t>(triangles));
    }
    void generate() {
        int r[3] = {rates[0], rates[1], rates[2]};
        benchmark::DoNotOptimize(r);
        const Bfr::Tessellation t(parameterization, 3, r, options);
        t.GetCoords(coords.data());
        t.GetFacets(facets.data());
    }
};

void osd_emit(benchmark::State& state) {
    OsdPatch patch(state);
    for (auto _ : state) {
        patch.generate();
        benchmark::ClobberMemory();
    }
    bench::count_triangles(state, static_cast<std::uint64_t>(patch.triangles));
}

void osd_triangle(benchmark::State& state) {
    OsdPatch patch(state);
    bench::regenerate_per_query(state, static_cast<std::uint32_t>(patch.triangles), patch.facets.data(),
                                [&] { patch.generate(); });
}

} // namespace

BENCHMARK(osd_emit)->Name("opensubdiv/emit")->Apply(bench::bulk_factor_sets)->Apply(bench::large_factor_sets);
BENCHMARK(osd_triangle)->Name("opensubdiv/triangle")->Apply(bench::random_factor_sets);
