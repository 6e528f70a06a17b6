// libFuzzer target: the D3D11 tessellator (constexpr/ctess/d3d11/tessellator.hpp), every domain and
// partitioning, factors as arbitrary float bit patterns. Properties: the count-only call equals the filled
// one and fits max_*_counts; every index names an emitted point; every point lies in the domain (16.16, and
// u + v <= 1 on triangles); counter-clockwise output is the clockwise output with each triangle's last two
// indices swapped.
#include <array>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <vector>

#include <ctess/d3d11/tessellator.hpp>

#include "fuzz_input.hpp"

using namespace ctess;
using namespace ctess::d3d11;

namespace {

constexpr std::uint32_t one = 65536;

// Counts (tri, quad) or IsolineCounts: vertices and index_count() either way.
template <std::size_t N, typename MostCounts, typename Tessellate>
void check_domain(fuzz::Input& in, Partitioning partitioning, MostCounts most, unsigned per_primitive,
                  bool triangle_domain, Tessellate tessellate) {
    std::array<float, N> factors{};
    for (float& f : factors) f = in.float_bits();
    const TessOptions cw{partitioning, Winding::cw}, ccw{partitioning, Winding::ccw};
    const auto counts = tessellate(std::span<Point>{}, std::span<std::uint32_t>{}, factors, cw); // count only
    const std::uint32_t index_count = counts.index_count();
    CTESS_FUZZ_CHECK(counts.vertices <= most.vertices && index_count <= most.index_count());
    CTESS_FUZZ_CHECK(index_count % per_primitive == 0);
    std::vector<Point> points(most.vertices), points_ccw(most.vertices);
    std::vector<std::uint32_t> indices(most.index_count()), indices_ccw(most.index_count());
    CTESS_FUZZ_CHECK(tessellate(points, indices, factors, cw) == counts);
    CTESS_FUZZ_CHECK(tessellate(points_ccw, indices_ccw, factors, ccw) == counts);
    for (std::uint32_t i = 0; i < counts.vertices; ++i) {
        const Point p = points[i];
        CTESS_FUZZ_CHECK(p.u <= one && p.v <= one);
        if (triangle_domain) CTESS_FUZZ_CHECK(p.u + p.v <= one);
        CTESS_FUZZ_CHECK(points_ccw[i] == p);
    }
    for (std::uint32_t k = 0; k < index_count; ++k) CTESS_FUZZ_CHECK(indices[k] < counts.vertices);
    if (per_primitive == 3) {
        for (std::uint32_t k = 0; k < index_count; k += 3) {
            CTESS_FUZZ_CHECK(indices_ccw[k] == indices[k]);
            CTESS_FUZZ_CHECK(indices_ccw[k + 1] == indices[k + 2] && indices_ccw[k + 2] == indices[k + 1]);
        }
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Input in(data, size);
    const std::uint8_t mode = in.byte();
    const auto partitioning = static_cast<Partitioning>(mode % 4);
    switch ((mode / 4) % 3) {
    case 0:
        check_domain<4>(in, partitioning, max_tri_counts, 3, true,
                        [](auto&&... a) { return tessellate_tri(a...); });
        break;
    case 1:
        check_domain<6>(in, partitioning, max_quad_counts, 3, false,
                        [](auto&&... a) { return tessellate_quad(a...); });
        break;
    default:
        check_domain<2>(in, partitioning, max_isoline_counts, 2, false,
                        [](auto&&... a) { return tessellate_isoline(a...); });
        break;
    }
    return 0;
}
