// What Layout::shared promises in every family (core/patch_options.hpp; docs/api.md, "A slot is not always a
// position"): one vertex per pattern slot. Uniform slots are distinct positions; CP keeps the coincident
// slots of its transitional states apart so that the index buffer is fixed within a token triple (§2.10,
// §2.11); D3D11 keeps the reference's own coincident points (fractional partitioning), bit for bit.
#include <ctess/cp/line.hpp>
#include <ctess/cp/pattern.hpp>
#include <ctess/d3d11/tessellator.hpp>
#include <ctess/runtime/uniform/patch.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

namespace {

template <class P>
std::size_t distinct_positions(const std::vector<P>& points, std::size_t count) {
    std::set<std::pair<std::uint32_t, std::uint32_t>> keys;
    for (std::size_t i = 0; i < count; ++i) keys.insert({points[i].u, points[i].v});
    return keys.size();
}

ctess::cp::PatternOptions cp_shared() {
    ctess::cp::PatternOptions opt;
    opt.layout = ctess::Layout::shared;
    return opt;
}

} // namespace

TEST_CASE("uniform shared layout: one vertex per distinct position for every stored pattern (N = 16)",
          "[core][layout][uniform]") {
    const auto& tables = ctess::rt::uniform_tables_16;
    const ctess::PatchOptions opt{ctess::Layout::shared, ctess::default_winding};
    std::vector<ctess::uniform::Point> points(1024);
    std::vector<std::uint32_t> indices(6144);
    for (std::uint32_t a = 1; a <= 16; ++a)
        for (std::uint32_t b = 1; b <= 16; ++b)
            for (std::uint32_t c = 1; c <= 16; ++c) {
                const ctess::rt::UniformPatch patch(tables, {a, b, c}, opt);
                const auto n = patch.counts();
                REQUIRE(n.vertices <= points.size());
                REQUIRE(patch.emit(points, indices));
                INFO(a << "," << b << "," << c);
                REQUIRE(distinct_positions(points, n.vertices) == n.vertices);
            }
}

TEST_CASE("D3D11 integer and pow2 patterns: one vertex per distinct position (tri and quad)",
          "[core][layout][d3d11]") {
    using namespace ctess::d3d11;
    std::mt19937 rng(20261124);
    std::uniform_real_distribution<float> factor(0.5f, 40.0f);
    std::vector<Point> points(max_quad_counts.vertices);
    std::vector<std::uint32_t> indices(max_quad_counts.index_count());
    for (const Partitioning p : {Partitioning::integer, Partitioning::pow2}) {
        const TessOptions opt{p, ctess::default_winding};
        for (int trial = 0; trial < 300; ++trial) {
            const std::array<float, 4> tri{factor(rng), factor(rng), factor(rng), factor(rng)};
            const auto n = tessellate_tri(points, indices, tri, opt);
            REQUIRE(n.index_count() <= indices.size());
            INFO("tri " << tri[0] << "," << tri[1] << "," << tri[2] << "," << tri[3]);
            REQUIRE(distinct_positions(points, n.vertices) == n.vertices);
            const std::array<float, 6> quad{factor(rng), factor(rng), factor(rng),
                                            factor(rng), factor(rng), factor(rng)};
            const auto m = tessellate_quad(points, indices, quad, opt);
            REQUIRE(m.index_count() <= indices.size());
            REQUIRE(distinct_positions(points, m.vertices) == m.vertices);
        }
    }
}

TEST_CASE("D3D11 fractional patterns: the reference's coincident slots, as documented",
          "[core][layout][d3d11]") {
    // docs/api.md: bit-exact with the reference, fractional_odd's picture frame at the inside minimum (1 +
    // 2^-16) puts its inner ring's three points at one position, and a fractional factor just above an
    // integer rounds its short segments to zero length in 16-bit fixed point.
    using namespace ctess::d3d11;
    std::vector<Point> points(max_tri_counts.vertices);
    std::vector<std::uint32_t> indices(max_tri_counts.index_count());
    const auto odd = tessellate_tri(points, indices, {22.2974f, 27.6708f, 17.2456f, 0.6f},
                                    {Partitioning::fractional_odd, ctess::default_winding});
    CHECK(odd.vertices - distinct_positions(points, odd.vertices) == 3);
    const auto odd_whole = tessellate_tri(points, indices, {22.2974f, 27.6708f, 17.2456f, 3.5f},
                                          {Partitioning::fractional_odd, ctess::default_winding});
    CHECK(distinct_positions(points, odd_whole.vertices) == odd_whole.vertices);
    const auto even = tessellate_tri(points, indices, {14.1388f, 1.43721f, 21.4726f, 28.0001f},
                                     {Partitioning::fractional_even, ctess::default_winding});
    CHECK(distinct_positions(points, even.vertices) < even.vertices);
    const auto even_clear = tessellate_tri(points, indices, {14.1388f, 1.43721f, 21.4726f, 28.5f},
                                           {Partitioning::fractional_even, ctess::default_winding});
    CHECK(distinct_positions(points, even_clear.vertices) == even_clear.vertices);
}

TEST_CASE("CP shared layout: coincident slots stay apart, the documented example", "[core][layout][cp]") {
    // docs/api.md: at 2, 2, 2 the shared layout has 10 vertices at 6 positions, 5 of 9 triangles zero-area.
    std::vector<ctess::DomainPoint> points(64);
    std::vector<std::uint32_t> indices(64 * 3);
    const auto n = ctess::cp::tessellate(points, indices, 2.0f, 2.0f, 2.0f, cp_shared());
    REQUIRE(n.vertices == 10);
    REQUIRE(n.triangles == 9);
    REQUIRE(distinct_positions(points, n.vertices) == 6);
    int zero_area = 0;
    for (std::uint32_t t = 0; t < n.triangles; ++t) {
        const auto& a = points[indices[3 * t]];
        const auto& b = points[indices[3 * t + 1]];
        const auto& c = points[indices[3 * t + 2]];
        const std::int64_t area2 = (std::int64_t{b.u} - a.u) * (std::int64_t{c.v} - a.v) -
                                   (std::int64_t{b.v} - a.v) * (std::int64_t{c.u} - a.u);
        zero_area += area2 == 0;
    }
    REQUIRE(zero_area == 5);
}

TEST_CASE("CP shared layout: the index buffer is fixed within a token triple (why slots stay apart)",
          "[core][layout][cp]") {
    // Two line states with the same token and different lerps must give the same counts and the same indices;
    // only the positions move. Over random token triples at max 64, lerps drawn anywhere in (0, 1].
    const unsigned max_factor = 64;
    const unsigned tokens = ctess::cp::token_count(max_factor);
    std::mt19937 rng(7);
    std::uniform_int_distribution<unsigned> token(1, tokens - 1);
    std::uniform_int_distribution<std::uint32_t> lerp(1, 65536);
    const auto cap = ctess::cp::max_pattern_counts(max_factor);
    std::vector<ctess::DomainPoint> pa(cap.vertices), pb(cap.vertices);
    std::vector<std::uint32_t> ia(cap.index_count()), ib(cap.index_count());
    int moved = 0;
    for (int trial = 0; trial < 400; ++trial) {
        std::array<ctess::cp::LineState, 3> s, t;
        for (int k = 0; k < 3; ++k) {
            const unsigned tk = token(rng);
            s[k] = {tk, lerp(rng)};
            t[k] = {tk, lerp(rng)};
        }
        const auto na = ctess::cp::tessellate(pa, ia, s[0], s[1], s[2], cp_shared());
        const auto nb = ctess::cp::tessellate(pb, ib, t[0], t[1], t[2], cp_shared());
        REQUIRE(na == nb);
        REQUIRE(std::equal(ia.begin(), ia.begin() + na.index_count(), ib.begin()));
        moved += !std::equal(pa.begin(), pa.begin() + na.vertices, pb.begin());
    }
    REQUIRE(moved > 0); // the positions do move: the test compares two different states
}
