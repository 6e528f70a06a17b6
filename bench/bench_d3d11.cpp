// The D3D11 fixed-function tessellator (ctess::d3d11::tessellate_tri) at the same integer rates, with
// integer and fractional_even partitioning. Edges: CP's e0 (v = 0), e1 (u + v = 1) and e2 (u = 0) are D3D's
// Veq0, Weq0 and Ueq0; the inside factor is the mean of the three. Random access rebuilds the patch per
// query (the tessellator has no other way to reach one triangle).
#include <ctess/core/domain_point.hpp>
#include <ctess/d3d11/tessellator.hpp>

#include <array>
#include <cstdint>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench_workloads.hpp"

namespace {

using ctess::d3d11::Point;
namespace bench = ctess::bench;
namespace d3d11 = ctess::d3d11;

struct D3D11Patch {
    d3d11::TessOptions options;
    std::array<float, 4> factors{};
    ctess::Counts counts;
    std::vector<d3d11::Point> points;
    std::vector<std::uint32_t> indices;

    D3D11Patch(const benchmark::State& state, d3d11::Partitioning partitioning) {
        options.partitioning = partitioning;
        const float f0 = bench::factor(state, 0), f1 = bench::factor(state, 1), f2 = bench::factor(state, 2);
        factors = {f2, f0, f1, (f0 + f1 + f2) / 3.0f};
        counts = d3d11::tessellate_tri({}, {}, factors, options);
        points.resize(counts.vertices);
        indices.resize(counts.index_count());
    }
    std::uint32_t triangles() const { return counts.triangles; }
    void generate() {
        std::array<float, 4> f = factors;
        benchmark::DoNotOptimize(f);
        d3d11::detail::tessellate_tri_into(points.data(), indices.data(), f, options); // the fill alone
    }
};

template <d3d11::Partitioning partitioning>
void d3d11_emit(benchmark::State& state) {
    D3D11Patch patch(state, partitioning);
    for (auto _ : state) {
        patch.generate();
        benchmark::ClobberMemory();
    }
    bench::count_triangles(state, patch.triangles());
}

template <d3d11::Partitioning partitioning>
void d3d11_triangle(benchmark::State& state) {
    D3D11Patch patch(state, partitioning);
    bench::regenerate_per_query(state, patch.triangles(), patch.indices.data(), [&] { patch.generate(); });
}

constexpr auto integer = d3d11::Partitioning::integer;
constexpr auto fractional_even = d3d11::Partitioning::fractional_even;

} // namespace

BENCHMARK(d3d11_emit<integer>)->Name("d3d11_integer/emit")->Apply(bench::bulk_factor_sets);
BENCHMARK(d3d11_emit<fractional_even>)->Name("d3d11_fractional_even/emit")->Apply(bench::bulk_factor_sets);
BENCHMARK(d3d11_triangle<integer>)->Name("d3d11_integer/triangle")->Apply(bench::random_factor_sets);
BENCHMARK(d3d11_triangle<fractional_even>)
    ->Name("d3d11_fractional_even/triangle")
    ->Apply(bench::random_factor_sets);
