// D3D11 triangle, quad and isoline domains: the count tables and closed forms of docs/algorithm.md §5.5,
// geometric validity (the triangles tile the domain, edges are watertight), winding, pow2 == integer, and bad
// factors (§5.1).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <ctess/analysis/signed_area.hpp>
#include <ctess/cp/pattern.hpp>
#include <ctess/d3d11/tessellator.hpp>

namespace {

using namespace ctess::d3d11;
using ctess::Counts;

constexpr float nan_f = std::numeric_limits<float>::quiet_NaN();
constexpr float inf_f = std::numeric_limits<float>::infinity();
constexpr float denorm_f = std::numeric_limits<float>::denorm_min();

constexpr Partitioning all_modes[] = {Partitioning::integer, Partitioning::pow2, Partitioning::fractional_odd,
                                      Partitioning::fractional_even};

// ---- constant evaluation ----
constexpr TessOptions odd_cw{Partitioning::fractional_odd, Winding::cw};
static_assert(tessellate_tri({}, {}, {2.5f, 3.7f, 5.1f, 4.2f}, odd_cw) == Counts{27, 37});
static_assert(tessellate_tri({}, {}, {64, 64, 64, 64}, {Partitioning::fractional_even, Winding::cw}) ==
              Counts{3169, 6144});
static_assert(tessellate_quad({}, {}, {3, 3, 3, 3, 3, 3}, {Partitioning::integer, Winding::cw}) ==
              Counts{16, 18});
static_assert(tessellate_isoline({}, {}, {4.5f, 2.5f}, {Partitioning::fractional_even, Winding::cw}) ==
              IsolineCounts{5 * 5, 5 * 4});
// The default options are integer partitioning, clockwise (the reference's defaults).
static_assert(tessellate_tri({}, {}, {3, 3, 3, 3}) ==
              tessellate_tri({}, {}, {3, 3, 3, 3}, {Partitioning::integer, Winding::cw}));

// Filled in a constant expression: the minimum triangle, a 2x2 quad, and a small isoline.
constexpr bool tri_minimum_ok = [] {
    std::array<Point, 3> p{};
    std::array<std::uint32_t, 3> i{};
    const Counts c = tessellate_tri(p, i, {1, 1, 1, 1}, {Partitioning::integer, Winding::ccw});
    return c == Counts{3, 1} && p[0] == Point{0, 65536} && p[1] == Point{0, 0} && p[2] == Point{65536, 0} &&
           i == std::array<std::uint32_t, 3>{0, 2, 1};
}();
static_assert(tri_minimum_ok);
constexpr bool quad_2x2_ok = [] {
    std::array<Point, 9> p{};
    std::array<std::uint32_t, 24> i{};
    const Counts c = tessellate_quad(p, i, {2, 2, 2, 2, 2, 2}, {Partitioning::integer, Winding::cw});
    // Outer ring clockwise from (0, 1), then the centre.
    return c == Counts{9, 8} && p[0] == Point{0, 65536} && p[1] == Point{0, 32768} && p[2] == Point{0, 0} &&
           p[4] == Point{65536, 0} && p[8] == Point{32768, 32768};
}();
static_assert(quad_2x2_ok);
constexpr bool isoline_ok = [] {
    std::array<Point, 6> p{};
    std::array<std::uint32_t, 8> i{};
    const IsolineCounts c = tessellate_isoline(p, i, {2, 2}, {Partitioning::integer, Winding::cw});
    return c == IsolineCounts{6, 4} && p[4] == Point{32768, 32768} &&
           i == std::array<std::uint32_t, 8>{0, 1, 1, 2, 3, 4, 4, 5};
}();
static_assert(isoline_ok);

// ---- helpers ----
// CountsT: Counts for triangles, IsolineCounts for segments.
template <class CountsT>
struct MeshOf {
    CountsT counts;
    std::vector<Point> points;
    std::vector<std::uint32_t> indices;
};
using Mesh = MeshOf<Counts>;
using IsoMesh = MeshOf<IsolineCounts>;

template <std::size_t N, class Tessellate>
auto run(Tessellate tessellate, Partitioning mode, Winding winding, const std::array<float, N>& f) {
    const TessOptions options{mode, winding};
    MeshOf<decltype(tessellate({}, {}, f, options))> m;
    m.counts = tessellate({}, {}, f, options);
    m.points.assign(m.counts.vertices + 1, Point{0xdeadbeef, 0xdeadbeef});
    m.indices.assign(m.counts.index_count() + 1, 0xdeadbeef);
    const auto filled = tessellate(m.points, m.indices, f, options);
    REQUIRE(filled == m.counts);
    REQUIRE(m.points.back() == Point{0xdeadbeef, 0xdeadbeef}); // nothing written past the count
    REQUIRE(m.indices.back() == 0xdeadbeef);
    m.points.pop_back();
    m.indices.pop_back();
    return m;
}
Mesh tri(Partitioning mode, std::array<float, 4> f, Winding w = Winding::cw) {
    return run(tessellate_tri, mode, w, f);
}
Mesh quad(Partitioning mode, std::array<float, 6> f, Winding w = Winding::cw) {
    return run(tessellate_quad, mode, w, f);
}
IsoMesh iso(Partitioning mode, std::array<float, 2> f) {
    return run(tessellate_isoline, mode, Winding::cw, f);
}

template <class CountsT>
bool same(const MeshOf<CountsT>& a, const MeshOf<CountsT>& b) {
    return a.counts == b.counts && a.points == b.points && a.indices == b.indices;
}

bool is_integer_mode(Partitioning m) {
    return m == Partitioning::integer || m == Partitioning::pow2;
}

// Independent of the implementation (docs/algorithm.md §5.1, §5.5): clamp, round up for integer modes, 16.16
// with ties to even, then the next segment count of the mode's parity (integer: ceil).
float clamp_to(float f, float lo, float hi) {
    return std::isnan(f) ? lo : std::min(hi, std::max(lo, f));
}
std::uint32_t segments_of(Partitioning mode, float clamped, bool odd_parity) {
    if (is_integer_mode(mode)) clamped = std::ceil(clamped);
    const auto fx = static_cast<std::uint64_t>(std::nearbyint(static_cast<double>(clamped) * 65536.0));
    const auto whole = static_cast<std::uint32_t>((fx + 65535) / 65536);
    if (is_integer_mode(mode)) return whole;
    return odd_parity ? whole + 1 - (whole & 1) : whole + (whole & 1);
}
float lo_of(Partitioning m) {
    return m == Partitioning::fractional_even ? 2.0f : 1.0f;
}
float hi_of(Partitioning m) {
    return m == Partitioning::fractional_odd ? 63.0f : 64.0f;
}
std::uint32_t edge_segments(Partitioning m, float f) {
    return segments_of(m, clamp_to(f, lo_of(m), hi_of(m)), m == Partitioning::fractional_odd);
}
// Inside segments; `frame` says whether fractional_odd raises the lower bound to 1 + 2^-16.
std::uint32_t inside_segments(Partitioning m, float f, bool frame) {
    const float lo = frame ? 1.0f + 1.0f / 65536.0f : lo_of(m);
    return segments_of(m, clamp_to(f, lo, hi_of(m)), m == Partitioning::fractional_odd);
}
bool odd_frame(Partitioning m, std::initializer_list<float> seen) {
    if (m != Partitioning::fractional_odd) return false;
    for (const float f : seen)
        if (f > 1.0f + 1.0f / 131072.0f) return true;
    return false;
}

// Closed forms of docs/algorithm.md §5.5. Returns {points, triangles}.
Counts tri_formula(Partitioning m, const std::array<float, 4>& f) {
    std::uint32_t se[3];
    float clamped[3];
    for (int e = 0; e < 3; ++e) {
        se[e] = edge_segments(m, f[e]);
        clamped[e] = clamp_to(f[e], lo_of(m), hi_of(m));
    }
    std::uint32_t si = inside_segments(m, f[3], odd_frame(m, {clamped[0], clamped[1], clamped[2]}));
    const bool all_one = se[0] == 1 && se[1] == 1 && se[2] == 1 && si == 1;
    if (all_one && m != Partitioning::fractional_even) return {3, 1};
    if (m == Partitioning::fractional_odd) si = std::max(si, 3u);
    if (is_integer_mode(m) && si == 1) si = 2;
    std::uint32_t tris = (3 * (si - 2) * (si - 2)) / 2;
    std::uint32_t points = 0;
    for (const std::uint32_t s : se) {
        tris += s + si - 2;
        points += s;
    }
    const std::uint32_t r = (si + 1) / 2 - 1;
    points += si % 2 == 1 ? 3 * r * r : 3 * r * (r + 1) + 1;
    return {points, tris};
}

Counts quad_formula(Partitioning m, const std::array<float, 6>& f) {
    std::uint32_t se[4];
    float seen[6];
    for (int e = 0; e < 4; ++e) {
        se[e] = edge_segments(m, f[e]);
        seen[e] = clamp_to(f[e], lo_of(m), hi_of(m));
    }
    seen[4] = f[4];
    seen[5] = f[5];
    const bool frame = odd_frame(m, {seen[0], seen[1], seen[2], seen[3], seen[4], seen[5]});
    std::uint32_t su = inside_segments(m, f[4], frame);
    std::uint32_t sv = inside_segments(m, f[5], frame);
    if (se[0] == 1 && se[1] == 1 && se[2] == 1 && se[3] == 1 && su == 1 && sv == 1 &&
        m != Partitioning::fractional_even)
        return {4, 2};
    const std::uint32_t min_inside = m == Partitioning::fractional_odd ? 3 : 2;
    su = std::max(su, min_inside);
    sv = std::max(sv, min_inside);
    const std::uint32_t tris =
        (se[0] + sv - 2) + (se[2] + sv - 2) + (se[1] + su - 2) + (se[3] + su - 2) + 2 * (su - 2) * (sv - 2);
    const std::uint32_t points = se[0] + se[1] + se[2] + se[3] + (su - 1) * (sv - 1);
    return {points, tris};
}

IsolineCounts isoline_formula(Partitioning m, const std::array<float, 2>& f) {
    const auto lines = static_cast<std::uint32_t>(std::ceil(clamp_to(f[0], 1.0f, 64.0f)));
    const std::uint32_t detail = edge_segments(m, f[1]);
    return {lines * (detail + 1), lines * detail}; // {points, segments}
}

// Deterministic factors: mostly in [0.5, 66], some exact integers and integers +- 2^-17 / 2^-16.
struct FactorSource {
    std::uint64_t state = 0x9e3779b97f4a7c15u;
    std::uint32_t next() {
        state = state * 6364136223846793005u + 1442695040888963407u;
        return static_cast<std::uint32_t>(state >> 33);
    }
    float factor() {
        const std::uint32_t kind = next() % 8;
        const float whole = static_cast<float>(1 + next() % 65);
        if (kind == 0) return whole;
        if (kind == 1) return whole + (next() % 2 ? 1.0f : -1.0f) / 131072.0f;
        if (kind == 2) return whole + (next() % 2 ? 1.0f : -1.0f) / 65536.0f;
        if (kind == 3) return 0.5f + static_cast<float>(next() % 4096) / 4096.0f * 4.0f; // small factors
        return 0.5f + static_cast<float>(next() % (1u << 20)) / static_cast<float>(1u << 20) * 65.5f;
    }
};

// The triangles tile the domain: every index is a point, the signed areas sum exactly to the domain's area,
// and no triangle is inverted beyond a sliver. With this area sign TRIANGLE_CW triangles in (u, v) are
// positive (the minimum triangle (0,1), (0,0), (1,0) is). Zero area is allowed at coincident points (R4
// §11.7.14). The reference does emit slightly inverted slivers: its edge points are monotone only up to the
// reciprocal table's rounding
// (<= 16 units, see test_d3d11_line), e.g. even 6 + 2^-16 places 32769, 32768, 32767 around the midpoint. So
// an inverted triangle may have at most 16 units of base times the full height: doubled area >= -16 * 65536.
void require_tiles(const Mesh& m, std::int64_t domain_doubled_area) {
    for (const std::uint32_t i : m.indices) REQUIRE(i < m.counts.vertices);
    ctess::analysis::int128 sum = 0; // doubled areas in (1/65536)^2 (ctess::analysis::signed_area2)
    for (std::size_t k = 0; k + 2 < m.indices.size(); k += 3) {
        const auto a = ctess::analysis::signed_area2(m.points[m.indices[k]], m.points[m.indices[k + 1]],
                                                     m.points[m.indices[k + 2]]);
        sum += a;
        REQUIRE(a >= -16 * 65536);
    }
    REQUIRE(sum == domain_doubled_area);
}

// The outer ring's points (the first `outer` points) on one edge, by parameter. Inner points may coincide
// with the boundary (an inside factor near 1 puts a ring on it) and are not part of the shared edge.
std::vector<std::uint32_t> sorted_edge(const Mesh& m, std::size_t outer, bool (*on_edge)(const Point&),
                                       std::uint32_t (*param)(const Point&)) {
    std::vector<std::uint32_t> out;
    for (std::size_t k = 0; k < outer; ++k)
        if (on_edge(m.points[k])) out.push_back(param(m.points[k]));
    std::sort(out.begin(), out.end());
    return out;
}
std::vector<std::uint32_t> sorted_edge_points(Partitioning mode, float f) {
    std::vector<std::uint32_t> out(max_edge_points);
    out.resize(edge_points(mode, f, out.data()));
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

// ---- count tables (docs/algorithm.md §5.5) ----

TEST_CASE("d3d11 domains: the two done-when numbers", "[d3d11][domains]") {
    const Mesh even64 = tri(Partitioning::fractional_even, {64, 64, 64, 64});
    REQUIRE(even64.counts.vertices == 3169);
    REQUIRE(even64.counts.triangles == 6144);
    REQUIRE(even64.indices.size() == 6144 * 3);
    const Mesh odd = tri(Partitioning::fractional_odd, {2.5f, 3.7f, 5.1f, 4.2f});
    REQUIRE(odd.counts.vertices == 27);
    REQUIRE(odd.counts.triangles == 37);
    REQUIRE(odd.indices.size() == 37 * 3);
}

TEST_CASE("d3d11 domains: uniform triangle counts (docs/algorithm.md §5.5)", "[d3d11][domains]") {
    struct Row {
        Partitioning mode;
        std::array<Counts, 10> expect; // {points, triangles}
    };
    const float factors[10] = {1, 2, 3, 4, 5, 8, 16, 32, 63, 64};
    const Row rows[] = {
        {Partitioning::fractional_even,
         {{{7, 6},
           {7, 6},
           {19, 24},
           {19, 24},
           {37, 54},
           {61, 96},
           {217, 384},
           {817, 1536},
           {3169, 6144},
           {3169, 6144}}}},
        {Partitioning::fractional_odd,
         {{{3, 1},
           {12, 13},
           {12, 13},
           {27, 37},
           {27, 37},
           {75, 121},
           {243, 433},
           {867, 1633},
           {3072, 5953},
           {3072, 5953}}}},
        {Partitioning::integer,
         {{{3, 1},
           {7, 6},
           {12, 13},
           {19, 24},
           {27, 37},
           {61, 96},
           {217, 384},
           {817, 1536},
           {3072, 5953},
           {3169, 6144}}}},
        {Partitioning::pow2, // the hardware treats pow2 as integer
         {{{3, 1},
           {7, 6},
           {12, 13},
           {19, 24},
           {27, 37},
           {61, 96},
           {217, 384},
           {817, 1536},
           {3072, 5953},
           {3169, 6144}}}},
    };
    for (const Row& row : rows) {
        for (int k = 0; k < 10; ++k) {
            const float f = factors[k];
            INFO("mode " << static_cast<int>(row.mode) << " f " << f);
            const Counts c = tessellate_tri({}, {}, {f, f, f, f}, {row.mode, Winding::cw});
            REQUIRE(c.vertices == row.expect[k].vertices);
            REQUIRE(c.triangles == row.expect[k].triangles);
            // Uniform closed forms: tris = floor(3S^2/2); points 3S^2/4 + 3S/2 + 1 (even S), 3S + 3(S-1)^2/4
            // (odd).
            const std::uint32_t s = edge_segments(row.mode, f);
            const std::uint32_t pts =
                s % 2 == 0 ? 3 * s * s / 4 + 3 * s / 2 + 1 : 3 * s + 3 * (s - 1) * (s - 1) / 4;
            if (s > 1) {
                REQUIRE(c.triangles == 3 * s * s / 2);
                REQUIRE(c.vertices == pts);
            }
        }
    }
}

TEST_CASE("d3d11 domains: non-uniform triangle counts (docs/algorithm.md §5.5)", "[d3d11][domains]") {
    const std::array<float, 4> a = {2.5f, 3.7f, 5.1f, 4.2f};
    const std::array<float, 4> b = {7.3f, 1.0f, 20.0f, 9.9f};
    const auto counts = [](Partitioning m, const std::array<float, 4>& f) {
        return tessellate_tri({}, {}, f, {m, Winding::cw});
    };
    REQUIRE(counts(Partitioning::fractional_even, a) == Counts{33, 50});
    REQUIRE(counts(Partitioning::fractional_even, b) == Counts{91, 150});
    REQUIRE(counts(Partitioning::fractional_odd, a) == Counts{27, 37});
    REQUIRE(counts(Partitioning::fractional_odd, b) == Counts{106, 179});
    REQUIRE(counts(Partitioning::integer, a) == Counts{25, 35});
    REQUIRE(counts(Partitioning::integer, b) == Counts{90, 149});
    REQUIRE(counts(Partitioning::pow2, a) == Counts{25, 35});
    REQUIRE(counts(Partitioning::pow2, b) == Counts{90, 149});
}

TEST_CASE("d3d11 domains: closed-form counts over a factor sweep (docs/algorithm.md §5.5)",
          "[d3d11][domains]") {
    FactorSource src;
    for (const Partitioning m : all_modes) {
        for (int n = 0; n < 3000; ++n) {
            const std::array<float, 4> t = {src.factor(), src.factor(), src.factor(), src.factor()};
            const Counts ct = tessellate_tri({}, {}, t, {m, Winding::cw});
            const Counts ft = tri_formula(m, t);
            INFO("tri mode " << static_cast<int>(m) << " " << t[0] << " " << t[1] << " " << t[2] << " "
                             << t[3]);
            REQUIRE(ct.vertices == ft.vertices);
            REQUIRE(ct.triangles == ft.triangles);
            REQUIRE(ct.vertices <= max_tri_counts.vertices);
            REQUIRE(ct.triangles <= max_tri_counts.triangles);

            const std::array<float, 6> q = {src.factor(), src.factor(), src.factor(),
                                            src.factor(), src.factor(), src.factor()};
            const Counts cq = tessellate_quad({}, {}, q, {m, Winding::cw});
            const Counts fq = quad_formula(m, q);
            INFO("quad " << q[0] << " " << q[1] << " " << q[2] << " " << q[3] << " " << q[4] << " " << q[5]);
            REQUIRE(cq.vertices == fq.vertices);
            REQUIRE(cq.triangles == fq.triangles);
            REQUIRE(cq.vertices <= max_quad_counts.vertices);
            REQUIRE(cq.triangles <= max_quad_counts.triangles);

            const std::array<float, 2> l = {src.factor(), src.factor()};
            const IsolineCounts cl = tessellate_isoline({}, {}, l, {m, Winding::cw});
            const IsolineCounts fl = isoline_formula(m, l);
            INFO("isoline " << l[0] << " " << l[1]);
            REQUIRE(cl.vertices == fl.vertices);
            REQUIRE(cl.segments == fl.segments);
            REQUIRE(cl.vertices <= max_isoline_counts.vertices);
            REQUIRE(cl.segments <= max_isoline_counts.segments);
        }
    }
}

TEST_CASE("d3d11 domains: buffer maxima are reached at factor 64", "[d3d11][domains]") {
    for (const Partitioning m : {Partitioning::integer, Partitioning::fractional_even}) {
        REQUIRE(tessellate_tri({}, {}, {64, 64, 64, 64}, {m, Winding::cw}) == max_tri_counts);
        REQUIRE(tessellate_quad({}, {}, {64, 64, 64, 64, 64, 64}, {m, Winding::cw}) == max_quad_counts);
        REQUIRE(tessellate_isoline({}, {}, {64, 64}, {m, Winding::cw}) == max_isoline_counts);
    }
    REQUIRE(max_tri_counts == Counts{3169, 6144});
    REQUIRE(max_tri_counts.index_count() == 18432);
    REQUIRE(max_quad_counts == Counts{4225, 8192});
    REQUIRE(max_quad_counts.index_count() == 24576);
    REQUIRE(max_isoline_counts == IsolineCounts{4160, 4096});
    REQUIRE(max_isoline_counts.index_count() == 8192);
}

// ---- geometry ----

TEST_CASE("d3d11 domains: triangles tile the domain and shared edges are watertight", "[d3d11][domains]") {
    FactorSource src;
    src.state = 12345;
    for (const Partitioning m : all_modes) {
        for (int n = 0; n < 150; ++n) {
            const std::array<float, 4> t = {src.factor(), src.factor(), src.factor(), src.factor()};
            INFO("tri mode " << static_cast<int>(m) << " " << t[0] << " " << t[1] << " " << t[2] << " "
                             << t[3]);
            const Mesh mt = tri(m, t);
            require_tiles(mt, std::int64_t{65536} * 65536);
            std::size_t outer = 0;
            for (int e = 0; e < 3; ++e) outer += edge_points(m, t[e], nullptr) - 1;
            if (mt.counts.vertices == 3) outer = 3; // the minimum triangle
            // Each edge holds exactly the 1-D points of its factor: what a neighbour sharing it places.
            REQUIRE(sorted_edge(
                        mt, outer, [](const Point& p) { return p.u == 0; },
                        [](const Point& p) { return p.v; }) == sorted_edge_points(m, t[0]));
            REQUIRE(sorted_edge(
                        mt, outer, [](const Point& p) { return p.v == 0; },
                        [](const Point& p) { return p.u; }) == sorted_edge_points(m, t[1]));
            REQUIRE(sorted_edge(
                        mt, outer, [](const Point& p) { return p.u + p.v == 65536; },
                        [](const Point& p) { return p.u; }) == sorted_edge_points(m, t[2]));

            const std::array<float, 6> q = {src.factor(), src.factor(), src.factor(),
                                            src.factor(), src.factor(), src.factor()};
            INFO("quad " << q[0] << " " << q[1] << " " << q[2] << " " << q[3] << " " << q[4] << " " << q[5]);
            const Mesh mq = quad(m, q);
            require_tiles(mq, std::int64_t{2} * 65536 * 65536);
            outer = 0;
            for (int e = 0; e < 4; ++e) outer += edge_points(m, q[e], nullptr) - 1;
            REQUIRE(sorted_edge(
                        mq, outer, [](const Point& p) { return p.u == 0; },
                        [](const Point& p) { return p.v; }) == sorted_edge_points(m, q[0]));
            REQUIRE(sorted_edge(
                        mq, outer, [](const Point& p) { return p.v == 0; },
                        [](const Point& p) { return p.u; }) == sorted_edge_points(m, q[1]));
            REQUIRE(sorted_edge(
                        mq, outer, [](const Point& p) { return p.u == 65536; },
                        [](const Point& p) { return p.v; }) == sorted_edge_points(m, q[2]));
            REQUIRE(sorted_edge(
                        mq, outer, [](const Point& p) { return p.v == 65536; },
                        [](const Point& p) { return p.u; }) == sorted_edge_points(m, q[3]));
        }
    }
}

TEST_CASE("d3d11 domains: isoline lines and segments", "[d3d11][domains]") {
    // Density 3.2 -> 4 lines at v = 0, 1/4, 1/2, 3/4 (none at 1); detail even 2.5 -> the §5.2 vector.
    const IsoMesh m = iso(Partitioning::fractional_even, {3.2f, 2.5f});
    REQUIRE(m.counts == IsolineCounts{20, 16});
    const std::uint32_t detail[5] = {0, 28672, 32768, 36864, 65536};
    for (std::uint32_t l = 0; l < 4; ++l) {
        for (std::uint32_t p = 0; p < 5; ++p) {
            REQUIRE(m.points[l * 5 + p].u == detail[p]);
            REQUIRE(m.points[l * 5 + p].v == l * 16384);
        }
        for (std::uint32_t s = 0; s < 4; ++s) {
            REQUIRE(m.indices[(l * 4 + s) * 2] == l * 5 + s);
            REQUIRE(m.indices[(l * 4 + s) * 2 + 1] == l * 5 + s + 1);
        }
    }
    // Density is integer whatever the partitioning: 3.2 rounds up, fractional_odd detail does not.
    REQUIRE(iso(Partitioning::fractional_odd, {3.2f, 1.0f}).counts == IsolineCounts{8, 4});
}

// ---- winding and modes ----

TEST_CASE("d3d11 domains: CCW is CW with the last two indices swapped, pow2 is integer", "[d3d11][domains]") {
    FactorSource src;
    src.state = 777;
    const auto swapped = [](std::vector<std::uint32_t> v) {
        for (std::size_t k = 0; k + 2 < v.size(); k += 3) std::swap(v[k + 1], v[k + 2]);
        return v;
    };
    for (const Partitioning m : all_modes) {
        for (int n = 0; n < 100; ++n) {
            const std::array<float, 4> t = {src.factor(), src.factor(), src.factor(), src.factor()};
            const Mesh cw = tri(m, t);
            const Mesh ccw = tri(m, t, Winding::ccw);
            REQUIRE(ccw.points == cw.points);
            REQUIRE(ccw.indices == swapped(cw.indices));
            const std::array<float, 6> q = {src.factor(), src.factor(), src.factor(),
                                            src.factor(), src.factor(), src.factor()};
            const Mesh qcw = quad(m, q);
            const Mesh qccw = quad(m, q, Winding::ccw);
            REQUIRE(qccw.points == qcw.points);
            REQUIRE(qccw.indices == swapped(qcw.indices));
            if (m == Partitioning::integer) {
                REQUIRE(same(tri(Partitioning::pow2, t), cw));
                REQUIRE(same(quad(Partitioning::pow2, q), qcw));
                const std::array<float, 2> l = {t[0], t[1]};
                REQUIRE(same(iso(Partitioning::pow2, l), iso(Partitioning::integer, l)));
            }
        }
    }
}

// ---- bad input (docs/algorithm.md §5.1) ----

TEST_CASE("d3d11 domains: bad edge factors cull the patch", "[d3d11][domains][bad-input]") {
    const float culling[] = {nan_f, 0.0f, -0.0f, -1.0f, -1e30f, -inf_f, -denorm_f};
    for (const Partitioning m : all_modes) {
        for (const float bad : culling) {
            INFO("mode " << static_cast<int>(m) << " bad " << bad);
            for (int e = 0; e < 3; ++e) {
                std::array<float, 4> t = {5, 6, 7, 8};
                t[e] = bad;
                const Mesh mt = tri(m, t);
                REQUIRE(mt.counts == Counts{0, 0});
            }
            for (int e = 0; e < 4; ++e) {
                std::array<float, 6> q = {5, 6, 7, 8, 9, 10};
                q[e] = bad;
                REQUIRE(quad(m, q).counts == Counts{0, 0});
            }
            REQUIRE(iso(m, {bad, 4}).counts == IsolineCounts{0, 0});
            REQUIRE(iso(m, {4, bad}).counts == IsolineCounts{0, 0});
            // The inside factor never culls.
            REQUIRE(tri(m, {5, 6, 7, bad}).counts.vertices > 0);
            REQUIRE(quad(m, {5, 6, 7, 8, bad, 9}).counts.vertices > 0);
            REQUIRE(quad(m, {5, 6, 7, 8, 9, bad}).counts.vertices > 0);
        }
    }
}

TEST_CASE("d3d11 domains: bad factors that clamp", "[d3d11][domains][bad-input]") {
    for (const Partitioning m : all_modes) {
        INFO("mode " << static_cast<int>(m));
        const float lo = lo_of(m);
        const float hi = hi_of(m);
        // Edges: +inf and huge -> upper bound; denormal and tiny positive -> lower bound.
        for (const float big : {inf_f, 1e30f}) {
            REQUIRE(same(tri(m, {big, 6, 7, 8}), tri(m, {hi, 6, 7, 8})));
            REQUIRE(same(quad(m, {5, big, 7, 8, 9, 10}), quad(m, {5, hi, 7, 8, 9, 10})));
            REQUIRE(same(iso(m, {3, big}), iso(m, {3, hi})));
            REQUIRE(same(iso(m, {big, 3}), iso(m, {64, 3})));
            // Inside: +inf and huge -> upper bound.
            REQUIRE(same(tri(m, {5, 6, 7, big}), tri(m, {5, 6, 7, hi})));
            REQUIRE(same(quad(m, {5, 6, 7, 8, big, big}), quad(m, {5, 6, 7, 8, hi, hi})));
        }
        for (const float tiny : {denorm_f, 1e-30f, 0.5f}) {
            REQUIRE(same(tri(m, {5, tiny, 7, 8}), tri(m, {5, lo, 7, 8})));
            REQUIRE(same(quad(m, {5, 6, tiny, 8, 9, 10}), quad(m, {5, 6, lo, 8, 9, 10})));
            REQUIRE(same(iso(m, {3, tiny}), iso(m, {3, lo})));
            REQUIRE(same(iso(m, {tiny, 3}), iso(m, {1, 3})));
        }
        // Inside NaN, zero, negative, -inf, denormal -> the lower bound. Fractional_odd raises it to 1 +
        // 2^-16 when an edge exceeds 1 (a 3-segment picture frame), and keeps 1 when every edge is 1.
        const float inside_lo = m == Partitioning::fractional_odd ? 1.0f + 1.0f / 65536.0f : lo;
        for (const float bad : {nan_f, 0.0f, -1.0f, -inf_f, denorm_f}) {
            REQUIRE(same(tri(m, {5, 6, 7, bad}), tri(m, {5, 6, 7, inside_lo})));
            REQUIRE(same(quad(m, {5, 6, 7, 8, bad, 9}), quad(m, {5, 6, 7, 8, inside_lo, 9})));
            REQUIRE(same(tri(m, {1, 1, 1, bad}), tri(m, {1, 1, 1, lo})));
        }
    }
    // Exact results, counted by hand from algorithm.md §5.1 and §5.5.
    // Integer, edges 64, inside NaN -> inside 1 (even): 3 x 64 outer points + the centre; 3 x 64 triangles.
    REQUIRE(tri(Partitioning::integer, {64, 64, 64, nan_f}).counts == Counts{193, 192});
    // Odd, all edges 1, inside NaN -> inside 1: the single minimum triangle.
    const Mesh minimum = tri(Partitioning::fractional_odd, {1, 1, 1, nan_f});
    REQUIRE(minimum.counts == Counts{3, 1});
    REQUIRE(minimum.indices == std::vector<std::uint32_t>{0, 1, 2});
    // Odd, edges {2, 1, 1}, inside NaN -> inside 1 + 2^-16, 3 segments: 5 outer + 3 inner points;
    // (3+3-2) + 2 x (1+3-2) + floor(3/2) = 9 triangles.
    REQUIRE(tri(Partitioning::fractional_odd, {2, 1, 1, nan_f}).counts == Counts{8, 9});
    // The minimum quad: corners from (0, 0) counter-clockwise in (u, v), two triangles.
    const Mesh qmin = quad(Partitioning::integer, {1, 1, 1, 1, nan_f, -inf_f});
    REQUIRE(qmin.points == std::vector<Point>{{0, 0}, {65536, 0}, {65536, 65536}, {0, 65536}});
    REQUIRE(qmin.indices == std::vector<std::uint32_t>{0, 1, 3, 1, 2, 3});
    // Odd quad: a raw inside factor above 1 also forces the frame (the triangle has no such rule).
    REQUIRE(quad(Partitioning::fractional_odd, {1, 1, 1, 1, 1, 1}).counts == Counts{4, 2});
    REQUIRE(quad(Partitioning::fractional_odd, {1, 1, 1, 1, 1.5f, nan_f}).counts ==
            quad(Partitioning::fractional_odd, {1, 1, 1, 1, 1.5f, 1.0f + 1.0f / 65536.0f}).counts);
    // Even: the minimum is 6 triangles and 7 points even for all-1 (clamped to 2).
    REQUIRE(tri(Partitioning::fractional_even, {1, 1, 1, nan_f}).counts == Counts{7, 6});
    // Isoline: huge density -> 64 lines; tiny density -> 1 line.
    REQUIRE(iso(Partitioning::integer, {1e30f, 1}).counts == IsolineCounts{128, 64});
    REQUIRE(iso(Partitioning::integer, {denorm_f, 1}).counts == IsolineCounts{2, 1});
}

// docs/api.md, "Sized outputs": a fill into a span one entry too short writes nothing and still returns the
// counts; every family's default winding is counter-clockwise.
TEST_CASE("d3d11 tessellators: a short span gets nothing written, the default winding is ccw",
          "[d3d11][bad_input]") {
    constexpr Point sentinel{0xDEADBEEFu, 0xFEEDFACEu};
    auto check = [&](auto&& fill) {
        const auto n = fill(std::span<Point>{}, std::span<std::uint32_t>{});
        REQUIRE(n.vertices > 0);
        for (int short_side = 0; short_side < 2; ++short_side) {
            std::vector<Point> v(n.vertices - (short_side == 0 ? 1 : 0), sentinel);
            std::vector<std::uint32_t> i(n.index_count() - (short_side == 1 ? 1 : 0), 0xABCDEF01u);
            CHECK(fill(std::span<Point>(v), std::span<std::uint32_t>(i)) == n);
            CHECK(std::all_of(v.begin(), v.end(), [&](Point p) { return p == sentinel; }));
            CHECK(std::all_of(i.begin(), i.end(), [](std::uint32_t x) { return x == 0xABCDEF01u; }));
        }
    };
    const TessOptions odd{Partitioning::fractional_odd};
    check([&](auto v, auto i) { return tessellate_tri(v, i, {2.5f, 3.7f, 5.1f, 4.2f}, odd); });
    check([&](auto v, auto i) { return tessellate_quad(v, i, {3, 4, 5, 6, 4, 5}, odd); });
    check([&](auto v, auto i) { return tessellate_isoline(v, i, {4.5f, 2.5f}, odd); });
    STATIC_REQUIRE(TessOptions{}.winding == ctess::Winding::ccw);
    STATIC_REQUIRE(ctess::cp::PatternOptions{}.winding == TessOptions{}.winding);
}
