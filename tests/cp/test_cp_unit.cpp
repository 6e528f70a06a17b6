// Unit tests of the CP triangle pattern's pieces: column counts, gap merge, Type-1 point P, counts against
// the independent prototype's count tables, provoking layout, quads, orientation, bad input, constant
// evaluation. (The exhaustive coverage/pop/triforce suite is tests/cp/test_cp_pattern_*.cpp.)
#include <ctess/analysis/signed_area.hpp>
#include <ctess/cp/orientation.hpp>
#include <ctess/cp/pattern.hpp>
#include <ctess/cp/quad.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <span>
#include <vector>

#include <catch2/catch.hpp>

using ctess::Counts;
using ctess::DomainPoint;
using ctess::Layout;
using ctess::Winding;
using namespace ctess::cp;

namespace {

constexpr std::int64_t one = fixed_one;

struct Mesh {
    Counts counts;
    std::vector<DomainPoint> vertices;
    std::vector<std::uint32_t> indices;
};

Mesh build(LineState s0, LineState s1, LineState s2, const PatternOptions& opt) {
    Mesh m;
    m.counts = tessellate({}, {}, s0, s1, s2, opt);
    m.vertices.resize(m.counts.vertices);
    m.indices.resize(3 * std::size_t{m.counts.triangles});
    const Counts filled = tessellate(m.vertices, m.indices, s0, s1, s2, opt);
    REQUIRE(filled == m.counts);
    return m;
}

Mesh build(float f0, float f1, float f2, const PatternOptions& opt) {
    const unsigned mf = pattern_max_factor(opt.max_factor);
    return build(line_state(f0, mf), line_state(f1, mf), line_state(f2, mf), opt);
}

using ctess::analysis::int128;
using ctess::analysis::signed_area2;

struct Validity {
    int128 area2 = 0; // sum of 2*area in units of 2^-48: fixed_one^2 for the whole domain
    unsigned inverted = 0;
    unsigned degenerate = 0;
};

Validity validity(const Mesh& m) {
    Validity v;
    for (std::size_t t = 0; t < m.counts.triangles; ++t) {
        const int128 c = signed_area2(m.vertices[m.indices[3 * t]], m.vertices[m.indices[3 * t + 1]],
                                      m.vertices[m.indices[3 * t + 2]]);
        v.area2 += c;
        if (c < 0) ++v.inverted;
        if (c == 0) ++v.degenerate;
    }
    return v;
}

PatternOptions options(unsigned max_factor, ColumnRule rule = ColumnRule::minimal, bool collapse = true,
                       bool provoking = false) {
    PatternOptions o;
    o.max_factor = max_factor;
    o.column_rule = rule;
    o.collapse_t0 = collapse;
    o.layout = provoking ? Layout::provoking : Layout::shared;
    return o;
}

struct Tracks {
    std::array<PointTrack, max_segments + 1> t{};
    unsigned n = 0; // segments
};
Tracks tracks_of(unsigned token) {
    Tracks r;
    r.n = token_points(token == 0 ? 1 : token, r.t.data()) - 1;
    return r;
}

} // namespace

// --- counts: the independent prototype's tables, equal and unequal factors (docs/algorithm.md §2.14) -------

TEST_CASE("equal factors: counts of both rules, max 64 and 256 (docs/algorithm.md §2.14)", "[cp][counts]") {
    struct Row {
        float f;
        Counts b;
        unsigned degenerate_b;
        Counts a;
        unsigned degenerate_a;
    };
    const Row rows[] = {
        {1.0f, {3, 1}, 0, {3, 1}, 0},
        {1.5f, {10, 9}, 0, {10, 9}, 0},
        {2.0f, {10, 9}, 5, {10, 9}, 5},
        {4.0f, {15, 16}, 0, {15, 16}, 0},
        {8.0f, {45, 64}, 0, {45, 64}, 0},
        {16.0f, {153, 256}, 0, {153, 256}, 0},
        {32.0f, {561, 1024}, 0, {561, 1024}, 0},
        {64.0f, {2145, 4096}, 0, {2145, 4096}, 0},
        {5.0f, {25, 30}, 0, {28, 36}, 6},
        {10.3f, {86, 134}, 0, {91, 144}, 10},
        {24.0f, {316, 558}, 0, {325, 576}, 18},
        {48.0f, {1208, 2270}, 0, {1225, 2304}, 34},
    };
    for (unsigned max_factor : {64u, 256u}) {
        for (const Row& r : rows) {
            CAPTURE(max_factor, r.f);
            const Mesh b = build(r.f, r.f, r.f, options(max_factor, ColumnRule::minimal));
            const Mesh a = build(r.f, r.f, r.f, options(max_factor, ColumnRule::staircase));
            CHECK(b.counts == r.b);
            CHECK(a.counts == r.a);
            const Validity vb = validity(b), va = validity(a);
            CHECK(vb.degenerate == r.degenerate_b);
            CHECK(va.degenerate == r.degenerate_a);
            CHECK(vb.area2 == one * one);
            CHECK(va.area2 == one * one);
            CHECK(vb.inverted + va.inverted == 0);
        }
    }
    for (std::uint32_t n : {128u, 256u}) {
        const Mesh m = build(float(n), float(n), float(n), options(256));
        CHECK(m.counts == Counts{(n + 1) * (n + 2) / 2, n * n});
        CHECK(validity(m).degenerate == 0);
    }
}

TEST_CASE("equal tokens: rule (b) emits N^2 - d_T, rule (a) N^2 (docs/algorithm.md §2.4, §2.14)",
          "[cp][counts]") {
    // d_T for T2..T24 from the table of §7.3 (0 for the octave-final tokens).
    const unsigned d[25] = {0,  0,  0,  6, 0,  6,  10,  18, 0,  10,  18,  34, 0,
                            18, 34, 66, 0, 34, 66, 130, 0,  66, 130, 258, 0};
    for (unsigned max_factor : {64u, 256u}) {
        for (unsigned tok = 2; tok < token_count(max_factor); ++tok) {
            const std::uint32_t n = token_info(tok).segments;
            const LineState s{tok, 12345};
            CAPTURE(max_factor, tok);
            CHECK(tessellate({}, {}, s, s, s, options(max_factor, ColumnRule::minimal)).triangles ==
                  n * n - d[tok]);
            CHECK(tessellate({}, {}, s, s, s, options(max_factor, ColumnRule::staircase)) ==
                  Counts{(n + 1) * (n + 2) / 2, n * n});
        }
    }
}

TEST_CASE("unequal factors: counts (docs/algorithm.md §2.14)", "[cp][counts]") {
    struct Row {
        float f0, f1, f2;
        PatternType type;
        Counts counts;
        unsigned nondegenerate;
    };
    const auto T2 = PatternType::parallelogram, T1 = PatternType::fan;
    const Row rows[] = {
        {16, 8, 4, T2, {49, 68}, 68},         {4, 8, 16, T2, {40, 50}, 50},
        {8, 16, 4, T2, {37, 44}, 44},         {32, 32, 8, T2, {177, 280}, 280},
        {8, 32, 32, T2, {156, 238}, 238},     {5, 9, 3, T2, {26, 30}, 26},
        {3, 9, 5, T2, {24, 26}, 22},          {64, 1, 1, T2, {66, 64}, 64},
        {1, 64, 1, T1, {66, 64}, 64},         {1, 1, 64, T2, {66, 64}, 64},
        {1.5f, 1, 1, T1, {6, 5}, 5},          {1, 1.5f, 1, T1, {5, 3}, 3},
        {1.5f, 20, 1.2f, T1, {27, 26}, 26},   {2.5f, 1.2f, 40, T2, {75, 101}, 57},
        {40, 1.2f, 2.5f, T2, {104, 159}, 97}, {64, 64, 2, T2, {162, 191}, 190},
        {2, 64, 64, T2, {194, 255}, 128},
    };
    for (unsigned max_factor : {64u, 256u}) {
        for (const Row& r : rows) {
            CAPTURE(max_factor, r.f0, r.f1, r.f2);
            const PatternOptions opt = options(max_factor);
            CHECK(pattern_type(line_state(r.f0, max_factor), line_state(r.f1, max_factor),
                               line_state(r.f2, max_factor)) == r.type);
            const Mesh m = build(r.f0, r.f1, r.f2, opt);
            CHECK(m.counts == r.counts);
            const Validity v = validity(m);
            CHECK(m.counts.triangles - v.degenerate == r.nondegenerate);
            CHECK(v.area2 == one * one);
            CHECK(v.inverted == 0);
            CHECK(pattern_counts(r.f0, r.f1, r.f2, opt) == r.counts);
        }
    }
    // docs/algorithm.md §2.9: without the collapse, (64, 1, 1) emits 130 triangles and (1, 1, 64) 194.
    CHECK(pattern_counts(64, 1, 1, options(64, ColumnRule::minimal, false)).triangles == 130);
    CHECK(pattern_counts(1, 1, 64, options(64, ColumnRule::minimal, false)).triangles == 194);
}

TEST_CASE("Type 2 counts follow the closed form of docs/algorithm.md §2.14 without the collapse",
          "[cp][counts]") {
    std::mt19937 rng(42);
    for (unsigned max_factor : {64u, 256u}) {
        const unsigned tokens = token_count(max_factor);
        for (int it = 0; it < 300; ++it) {
            const auto draw = [&](unsigned lo) {
                return LineState{lo + static_cast<unsigned>(rng() % (tokens - lo)),
                                 static_cast<std::uint32_t>(rng() % (lerp_one + 1))};
            };
            const LineState s0 = draw(0), s1 = draw(0), s2 = draw(2);
            for (ColumnRule rule : {ColumnRule::minimal, ColumnRule::staircase}) {
                ColumnCounts r{};
                const unsigned n0 = column_counts(s0.token, s2.token, rule, r.data());
                const unsigned n1 = tracks_of(s1.token).n;
                std::uint32_t vertices = n1 + 1, triangles = n0 + n1 - 1;
                for (unsigned i = 0; i < n0; ++i) vertices += r[i];
                for (unsigned i = 0; i + 1 < n0; ++i) triangles += r[i] + r[i + 1] - 2u;
                CAPTURE(s0.token, s1.token, s2.token);
                CHECK(tessellate({}, {}, s0, s1, s2, options(max_factor, rule, false)) ==
                      Counts{vertices, triangles});
                // Provoking layout: one copy of each non-top point of columns 1..n0-2 (interior doubled up).
                std::uint32_t copies = 0;
                for (unsigned i = 1; i + 2 <= n0; ++i) copies += r[i] - 1u;
                CHECK(tessellate({}, {}, s0, s1, s2, options(max_factor, rule, false, true)) ==
                      Counts{vertices + copies, triangles});
            }
        }
    }
}

TEST_CASE("max_pattern_counts bounds every token triple and every option", "[cp][counts]") {
    for (unsigned max_factor : {8u, 16u, 64u, 256u}) {
        const unsigned tokens = token_count(max_factor);
        const Counts bound = max_pattern_counts(max_factor);
        Counts seen{};
        for (unsigned a = 0; a < tokens; ++a) {
            for (unsigned b = 0; b < tokens; ++b) {
                // Counts depend on tokens only; at 256, e1 only adds gap triangles and points, so its
                // smallest (T0, T1, T2) and largest tokens cover the cases.
                if (max_factor == 256 && b > 2 && b + 1 < tokens) continue;
                for (unsigned c = 0; c < tokens; ++c) {
                    for (int o = 0; o < 8; ++o) {
                        const PatternOptions opt =
                            options(max_factor, (o & 1) ? ColumnRule::staircase : ColumnRule::minimal,
                                    (o & 2) != 0, (o & 4) != 0);
                        const Counts k =
                            tessellate({}, {}, LineState{a, 7}, LineState{b, 7}, LineState{c, 7}, opt);
                        seen.vertices = std::max(seen.vertices, k.vertices);
                        seen.triangles = std::max(seen.triangles, k.triangles);
                    }
                }
            }
        }
        CAPTURE(max_factor);
        CHECK(seen == bound); // tight: reached by the triforce
    }
}

// --- column counts: docs/algorithm.md §2.4 -----------------------------------------------------------------

TEST_CASE("column counts: closed forms of 4.3 against the definition", "[cp][columns]") {
    for (unsigned max_factor : {64u, 256u}) {
        const unsigned tokens = token_count(max_factor);
        for (unsigned t0 = 0; t0 < tokens; ++t0) {
            for (unsigned t2 = 0; t2 < tokens; ++t2) {
                if (t0 <= 1 && t2 <= 1) continue; // Type 1: no columns
                ColumnCounts r{};
                const unsigned n0 = column_counts(t0, t2, ColumnRule::minimal, r.data());
                const Tracks e0 = tracks_of(t0), e2 = tracks_of(t2);
                CAPTURE(t0, t2);
                REQUIRE(n0 == e0.n);
                REQUIRE(r[0] == e2.n);
                for (unsigned i = 1; i < n0; ++i) {
                    unsigned expected = 0;
                    if (t0 <= 1) {
                        expected = i == 1 ? e2.n : 1;
                    } else if (t2 <= 1) {
                        expected = e0.t[i].final < 128 ? 2 : 1;
                    } else if (t0 == t2) {
                        continue; // no closed form; see the reach test
                    } else {
                        const auto& S0 = e0.t;
                        const unsigned n2 = e2.n, m0 = e0.n - 1;
                        for (unsigned k = 0; k < n2; ++k) {
                            const auto& P = e2.t[k];
                            int lhs = 0;
                            if (t0 < t2) {
                                lhs = std::min(P.start, P.final) + std::min(S0[i].start + 256 - S0[m0].start,
                                                                            S0[i].final + 256 - S0[m0].final);
                            } else {
                                const auto& L = e2.t[n2 - 1];
                                lhs = std::min(P.start + 256 - L.start, P.final + 256 - L.final) +
                                      std::min(S0[i].start, S0[i].final);
                            }
                            if (lhs >= 256) {
                                expected = k + 1;
                                break;
                            }
                        }
                    }
                    CAPTURE(i);
                    CHECK(r[i] == expected);
                }
            }
        }
    }
}

TEST_CASE("column counts: properties of 4.3 for both rules", "[cp][columns]") {
    for (unsigned max_factor : {64u, 256u}) {
        const unsigned tokens = token_count(max_factor);
        for (unsigned t0 = 0; t0 < tokens; ++t0) {
            for (unsigned t2 = 0; t2 < tokens; ++t2) {
                if (t0 <= 1 && t2 <= 1) continue;
                ColumnCounts b{}, a{};
                const unsigned n0 = column_counts(t0, t2, ColumnRule::minimal, b.data());
                column_counts(t0, t2, ColumnRule::staircase, a.data());
                CAPTURE(t0, t2);
                CHECK(b[n0 - 1] == 1); // no corner fan at v1
                CHECK(a[n0 - 1] == 1);
                for (unsigned i = 1; i < n0; ++i) {
                    CHECK(b[i] <= b[i - 1]); // non-increasing, R_1 <= n2
                    CHECK(a[i] <= a[i - 1]);
                    CHECK(a[i] >= b[i]); // the staircase is valid wherever the minimum is
                }
                if (t0 == t2 && t0 >= 2 && ctess::is_pow2(token_info(t0).segments)) {
                    for (unsigned i = 0; i < n0; ++i) CHECK(b[i] == n0 - i); // triforce at powers of two
                }
            }
        }
    }
}

TEST_CASE("column counts reach the clamp line at every lerp and rule (b) is the fewest", "[cp][columns]") {
    // Independent of the corner formula: rebuild the actual positions on a lerp grid and look at the column.
    // T0 shares T1's table (a T0 edge is processed as T1 at t = 0), so the lerp range is T1's.
    const std::uint32_t lerps[] = {0, 16384, 32768, 49152, 65536};
    for (unsigned t0 = 1; t0 < token_count(64); ++t0) {
        for (unsigned t2 = 1; t2 < token_count(64); ++t2) {
            if (t0 <= 1 && t2 <= 1) continue;
            ColumnCounts b{}, a{}, b0{};
            column_counts(t0 == 1 ? 0 : t0, t2 == 1 ? 0 : t2, ColumnRule::minimal, b0.data());
            const unsigned n0 = column_counts(t0, t2, ColumnRule::minimal, b.data());
            column_counts(t0, t2, ColumnRule::staircase, a.data());
            std::array<bool, max_segments> tight{}; // rule (b): one row less misses the clamp at some lerp
            for (std::uint32_t l0 : lerps) {
                for (std::uint32_t l2 : lerps) {
                    const EdgeLine e0 = make_edge_line({t0, l0});
                    const EdgeLine e2 = make_edge_line({t2, l2});
                    const std::uint32_t k = clamp_line(e0, e2);
                    for (unsigned i = 1; i < n0; ++i) {
                        const std::uint32_t c = column_clamp(k, e0.pos[i]);
                        CAPTURE(t0, t2, l0, l2, i);
                        CHECK(e2.pos[b[i] - 1] >= c);
                        CHECK(e2.pos[a[i] - 1] >= c);
                        if (b[i] >= 2 && e2.pos[b[i] - 2] < c) tight[i] = true;
                    }
                }
            }
            for (unsigned i = 1; i < n0; ++i) {
                CAPTURE(t0, t2, i);
                CHECK((b[i] == 1 || tight[i]));
                CHECK(b0[i] == b[i]);
            }
        }
    }
}

// --- gap zipper: docs/algorithm.md §2.6 --------------------------------------------------------------------

TEST_CASE("gap merge: equal tokens give M(a) = a (triforce), T1 conventions of 4.6", "[cp][gap]") {
    std::array<std::uint16_t, max_segments + 1> lambda{}, sigma{}, merge{};
    for (unsigned tok = 2; tok < token_count(256); ++tok) {
        const EdgeLine e = make_edge_line({tok, 30000});
        const unsigned nl = gap_lhs_coords(e, lambda.data());
        const unsigned n1 = gap_rhs_coords(e, sigma.data());
        REQUIRE(nl == n1);
        gap_merge(lambda.data(), nl, sigma.data(), n1, merge.data());
        for (unsigned a = 0; a <= nl; ++a) CHECK(merge[a] == a);
    }
    const EdgeLine t1 = make_edge_line({1, 1000});
    const EdgeLine t0 = make_edge_line({0, 0});
    for (const EdgeLine* e1 : {&t0, &t1}) {
        // e0 and e1 in T1: B0 covers [v1, R_1], A0's column reaches B1, column 0 fans B1 -> v2.
        unsigned nl = gap_lhs_coords(t1, lambda.data());
        unsigned n1 = gap_rhs_coords(*e1, sigma.data());
        gap_merge(lambda.data(), nl, sigma.data(), n1, merge.data());
        CHECK(std::vector<unsigned>(merge.begin(), merge.begin() + 4) == std::vector<unsigned>{0, 1, 2, 3});
        // e0 in T2+, e1 in T1: the first lhs point fans v1 -> A1 -> B1; every later one attaches to B1.
        const EdgeLine big = make_edge_line({9, 5000});
        nl = gap_lhs_coords(big, lambda.data());
        n1 = gap_rhs_coords(*e1, sigma.data());
        gap_merge(lambda.data(), nl, sigma.data(), n1, merge.data());
        CHECK(merge[0] == 0);
        for (unsigned a = 1; a < nl; ++a) CHECK(merge[a] == 2);
        CHECK(merge[nl] == 3);
    }
    // e0 in T1, e1 in T2+: B0 covers only [v1, R_1].
    const EdgeLine big = make_edge_line({9, 5000});
    const unsigned nl = gap_lhs_coords(t1, lambda.data());
    const unsigned n1 = gap_rhs_coords(big, sigma.data());
    gap_merge(lambda.data(), nl, sigma.data(), n1, merge.data());
    CHECK(merge[1] == 1);
    unsigned count = 0;
    for_each_gap_triangle(merge.data(), nl, [&](GapCorner, GapCorner, GapCorner) { ++count; });
    CHECK(count == nl + n1 - 1);
}

// --- Type 1: the point P, docs/algorithm.md §2.8 -----------------------------------------------------------

TEST_CASE("Type 1 point P: exact values at the joins", "[cp][type1]") {
    CHECK(type1_center(0, 0) == DomainPoint{0, 0}); // v0: the Type 0 limit
    for (std::uint32_t t = 0; t <= lerp_one; ++t) {
        // t0 = 1: the midpoint of e0.
        CHECK(type1_center(lerp_one, t) == DomainPoint{fixed_one / 2, 0});
        // t2 = 1: (t0/2, (1 - t0)/2), where A0's column meets u + v = 1/2.
        CHECK(type1_center(t, lerp_one) == DomainPoint{128 * t, 128 * (lerp_one - t)});
        // t0 = 0: at A2's height.
        CHECK(type1_center(0, t).v == 128 * t);
    }
    // The real-valued formula of §3.2 at interior points: the fixed-point P is within half a unit of it.
    const std::uint32_t samples[] = {1, 255, 4096, 32768, 40000, 65535};
    for (std::uint32_t a : samples) {
        for (std::uint32_t c : samples) {
            const double t0 = a / 65536.0, t2 = c / 65536.0;
            const double x = (t0 + (1 - t0) * t2 * (1 - t2)) / 2 * fixed_one;
            const double y = (1 - t0) * (t0 + t2 - t0 * t2) / 2 * fixed_one;
            const DomainPoint p = type1_center(a, c);
            CAPTURE(a, c);
            CHECK(std::abs(p.u - x) <= 0.5 + 1e-6);
            CHECK(std::abs(p.v - y) <= 0.5 + 1e-6);
        }
    }
}

TEST_CASE("Type 1 patterns are valid on a lerp grid, including T0 edges", "[cp][type1]") {
    const std::uint32_t lerps[] = {0, 1, 9000, 32768, 65535, 65536};
    for (unsigned tok0 : {0u, 1u}) {
        for (unsigned tok2 : {0u, 1u}) {
            for (unsigned tok1 : {0u, 1u, 2u, 7u, 16u}) {
                if (tok0 + tok1 + tok2 == 0) continue;
                for (std::uint32_t l0 : lerps) {
                    for (std::uint32_t l2 : lerps) {
                        for (bool collapse : {false, true}) {
                            const LineState s0{tok0, l0}, s1{tok1, 20000}, s2{tok2, l2};
                            REQUIRE(pattern_type(s0, s1, s2) == PatternType::fan);
                            const Mesh m = build(s0, s1, s2, options(64, ColumnRule::minimal, collapse));
                            const Validity v = validity(m);
                            CAPTURE(tok0, tok1, tok2, l0, l2, collapse);
                            CHECK(v.area2 == one * one);
                            CHECK(v.inverted == 0);
                            if (!collapse) CHECK(m.counts.triangles == tracks_of(tok1).n + 6);
                        }
                    }
                }
            }
        }
    }
}

// --- layouts -----------------------------------------------------------------------------------------------

TEST_CASE("vertex order of the unique layout", "[cp][layout]") {
    const PatternOptions opt = options(64, ColumnRule::minimal, false);
    {
        const Mesh m = build(1, 1, 1, opt);
        CHECK(m.vertices == std::vector<DomainPoint>{{0, 0}, {fixed_one, 0}, {0, fixed_one}});
        CHECK(m.indices == std::vector<std::uint32_t>{0, 1, 2});
    }
    {
        // Type 1: v0, A0, B0, e1 from v1 to v2, B2, A2, P.
        const LineState s0{1, 20000}, s1{1, 30000}, s2{1, 40000};
        const Mesh m = build(s0, s1, s2, opt);
        REQUIRE(m.vertices.size() == 10);
        CHECK(m.vertices[0] == DomainPoint{0, 0});
        CHECK(m.vertices[1] == DomainPoint{128 * 20000, 0});
        CHECK(m.vertices[2] == DomainPoint{fixed_one - 128 * 20000, 0});
        CHECK(m.vertices[3] == DomainPoint{fixed_one, 0});
        CHECK(m.vertices[4] == DomainPoint{fixed_one - 128 * 30000, 128 * 30000});
        CHECK(m.vertices[5] == DomainPoint{128 * 30000, fixed_one - 128 * 30000});
        CHECK(m.vertices[6] == DomainPoint{0, fixed_one});
        CHECK(m.vertices[7] == DomainPoint{0, fixed_one - 128 * 40000});
        CHECK(m.vertices[8] == DomainPoint{0, 128 * 40000});
        CHECK(m.vertices[9] == type1_center(20000, 40000));
    }
    {
        // Type 2 triforce N = 8: column i holds 8 - i points at u = i/8, then e1 from v1 to v2.
        const Mesh m = build(8, 8, 8, opt);
        unsigned k = 0;
        for (unsigned i = 0; i < 8; ++i) {
            for (unsigned j = 0; j < 8 - i; ++j)
                CHECK(m.vertices[k++] == DomainPoint{i * fixed_one / 8, j * fixed_one / 8});
        }
        for (unsigned b = 0; b <= 8; ++b)
            CHECK(m.vertices[k++] == DomainPoint{(8 - b) * fixed_one / 8, b * fixed_one / 8});
    }
}

TEST_CASE("provoking layout: unique first index, same triangles, interior doubled, gap once",
          "[cp][layout]") {
    std::mt19937 rng(5);
    for (unsigned max_factor : {64u, 256u}) {
        const unsigned tokens = token_count(max_factor);
        for (int it = 0; it < (max_factor == 64 ? 400 : 60); ++it) {
            LineState s[3];
            for (LineState& x : s) {
                x.token = static_cast<unsigned>(rng() % tokens);
                const auto pick = rng() % 4;
                x.t16 = pick == 0   ? 0u
                        : pick == 1 ? lerp_one
                                    : static_cast<std::uint32_t>(rng() % (lerp_one + 1));
            }
            for (int o = 0; o < 4; ++o) {
                const ColumnRule rule = (o & 1) ? ColumnRule::staircase : ColumnRule::minimal;
                const bool collapse = (o & 2) != 0;
                const Mesh flat = build(s[0], s[1], s[2], options(max_factor, rule, collapse, false));
                const Mesh prov = build(s[0], s[1], s[2], options(max_factor, rule, collapse, true));
                CAPTURE(s[0].token, s[1].token, s[2].token, s[0].t16, s[1].t16, s[2].t16, o);
                REQUIRE(prov.counts.triangles == flat.counts.triangles);
                // The unique vertices come first, unchanged; copies follow.
                REQUIRE(std::equal(flat.vertices.begin(), flat.vertices.end(), prov.vertices.begin()));
                std::set<std::uint32_t> first;
                bool same = true;
                for (std::size_t t = 0; t < 3 * std::size_t{flat.counts.triangles}; ++t) {
                    same = same && prov.vertices[prov.indices[t]] == flat.vertices[flat.indices[t]];
                    if (t % 3 != 0) same = same && prov.indices[t] == flat.indices[t];
                }
                for (std::size_t t = 0; t < flat.counts.triangles; ++t) first.insert(prov.indices[3 * t]);
                CHECK(same);
                CHECK(first.size() == prov.counts.triangles);
                // Each unique vertex gets at most one copy (interior points doubled up), e1's points (gap
                // rhs) none; each copy provokes exactly one triangle.
                std::map<std::uint32_t, unsigned> copies_of;
                for (std::size_t t = 0; t < flat.counts.triangles; ++t) {
                    if (prov.indices[3 * t] != flat.indices[3 * t]) {
                        CHECK(prov.indices[3 * t] >= flat.counts.vertices);
                        ++copies_of[flat.indices[3 * t]];
                    }
                }
                unsigned over = 0, e1_copied = 0, copies = 0;
                for (const auto& [index, n] : copies_of) {
                    const DomainPoint p = flat.vertices[index];
                    over += n > 1;
                    e1_copied += p.u + p.v == fixed_one;
                    copies += n;
                }
                CHECK(over == 0);
                CHECK(e1_copied == 0);
                CHECK(prov.counts.vertices == flat.counts.vertices + copies);
            }
        }
    }
}

// --- winding -----------------------------------------------------------------------------------------------

TEST_CASE("winding: cw is ccw with the last two indices of each triangle swapped", "[cp][winding]") {
    STATIC_REQUIRE(PatternOptions{}.winding == Winding::ccw);
    // Type 0, Type 1 (with a T0 collapse), the Type 1 / Type 2 join, Type 2 equal and unequal, the maximum.
    const float triples[][3] = {{1, 1, 1},   {1.5f, 20, 1.2f}, {2, 2, 2},  {2.6f, 2.6f, 2.6f},
                                {16, 8, 4},  {5, 2, 2},        {64, 1, 1}, {37.3f, 11.9f, 53.1f},
                                {64, 64, 64}};
    for (const bool provoking : {false, true}) {
        for (const auto& f : triples) {
            CAPTURE(provoking, f[0], f[1], f[2]);
            PatternOptions opt = options(64, ColumnRule::minimal, true, provoking);
            const Mesh ccw = build(f[0], f[1], f[2], opt);
            opt.winding = Winding::cw;
            const Mesh cw = build(f[0], f[1], f[2], opt);
            REQUIRE(cw.counts == ccw.counts);
            REQUIRE(cw.vertices == ccw.vertices);
            std::vector<std::uint32_t> swapped = ccw.indices;
            for (std::size_t k = 0; k + 2 < swapped.size(); k += 3) std::swap(swapped[k + 1], swapped[k + 2]);
            REQUIRE(cw.indices == swapped);
            // The signed areas flip: the domain's doubled area, negated, and no triangle turns positive.
            const Validity v = validity(cw);
            REQUIRE(v.area2 == -one * one);
            REQUIRE(v.inverted + v.degenerate == cw.counts.triangles);
        }
    }
}

// --- bad input ---------------------------------------------------------------------------------------------

TEST_CASE("bad input is clamped to [1, max_factor]", "[cp][input]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (unsigned max_factor : {64u, 256u}) {
        const PatternOptions opt = options(max_factor, ColumnRule::minimal, true, true);
        const float top = float(max_factor);
        const auto same = [&](float a, float b, float c, float ea, float eb, float ec) {
            const Mesh m = build(a, b, c, opt), e = build(ea, eb, ec, opt);
            CHECK(m.vertices == e.vertices);
            CHECK(m.indices == e.indices);
        };
        same(nan, nan, nan, 1, 1, 1);
        same(-inf, 0.0f, -0.0f, 1, 1, 1);
        same(-5, 7, nan, 1, 7, 1);
        same(inf, 3, 1e30f, top, 3, top);
        same(3.5f, std::numeric_limits<float>::max(), 0.5f, 3.5f, top, 1);
        same(std::numeric_limits<float>::denorm_min(), 2, 300, 1, 2, top);
        CHECK(pattern_counts(nan, inf, -inf, opt) == pattern_counts(1, top, 1, opt));
    }
    // Line states: a token past the range is the last token at t = 1; t16 > 1 is 1; T0 has no lerp.
    CHECK(clamp_line_state({99, 5}, 64) == LineState{16, lerp_one});
    CHECK(clamp_line_state({99, 5}, 256) == LineState{24, lerp_one});
    CHECK(clamp_line_state({5, 70000}, 64) == LineState{5, lerp_one});
    CHECK(clamp_line_state({0, 777}, 64) == LineState{0, 0});
    CHECK(tessellate({}, {}, LineState{99, 5}, LineState{0, 777}, LineState{3, 1u << 31}, options(64)) ==
          tessellate({}, {}, LineState{16, lerp_one}, LineState{0, 0}, LineState{3, lerp_one}, options(64)));
    // max_factor: clamped to [8, 256], rounded down to a power of two.
    CHECK(pattern_max_factor(0) == 8);
    CHECK(pattern_max_factor(64) == 64);
    CHECK(pattern_max_factor(100) == 64);
    CHECK(pattern_max_factor(256) == 256);
    CHECK(pattern_max_factor(100000) == 256);
    CHECK(pattern_counts(200, 200, 200, options(0)) == pattern_counts(8, 8, 8, options(64)));
}

// --- quads -------------------------------------------------------------------------------------------------

TEST_CASE("quads: split along q1-q3, diagonal forced to q0q1's factor, watertight", "[cp][quad]") {
    const std::array<float, 4> f = {12.5f, 3.0f, 12.5f, 40.0f};
    const QuadSplit s = split_quad(f);
    CHECK(s.triangles[0].corner == std::array<std::uint8_t, 3>{0, 1, 3});
    CHECK(s.triangles[1].corner == std::array<std::uint8_t, 3>{2, 3, 1});
    CHECK(s.triangles[0].factors == std::array<float, 3>{12.5f, 12.5f, 40.0f});
    CHECK(s.triangles[1].factors == std::array<float, 3>{12.5f, 12.5f, 3.0f});
    CHECK(quad_triangle_corners(s, 1, {10, 11, 12, 13}) == std::array<std::uint32_t, 3>{12, 13, 11});

    std::mt19937 rng(3);
    std::uniform_real_distribution<float> factor(0.5f, 70.0f);
    for (int it = 0; it < 200; ++it) {
        const std::array<float, 4> q = {factor(rng), factor(rng), factor(rng),
                                        it % 3 == 0 ? 1.0f : factor(rng)};
        const QuadSplit split = split_quad(q);
        int128 area2 = 0;
        unsigned inverted = 0;
        std::array<std::set<std::uint32_t>, 2> diagonal; // u of the points on the diagonal u + v = 1
        std::array<std::set<std::uint32_t>, 4> edges;    // parameter of the points on each quad edge
        for (unsigned t = 0; t < 2; ++t) {
            const auto& ft = split.triangles[t].factors;
            const Mesh m = build(ft[0], ft[1], ft[2], options(64));
            for (std::size_t k = 0; k < m.counts.triangles; ++k) {
                const int128 c = signed_area2(quad_point(t, m.vertices[m.indices[3 * k]]),
                                              quad_point(t, m.vertices[m.indices[3 * k + 1]]),
                                              quad_point(t, m.vertices[m.indices[3 * k + 2]]));
                area2 += c;
                inverted += c < 0;
            }
            for (const DomainPoint& p : m.vertices) {
                const DomainPoint w = quad_point(t, p);
                if (w.u + w.v == fixed_one) diagonal[t].insert(w.u);
                if (w.v == 0) edges[0].insert(w.u);
                if (w.u == fixed_one) edges[1].insert(w.v);
                if (w.v == fixed_one) edges[2].insert(fixed_one - w.u);
                if (w.u == 0) edges[3].insert(fixed_one - w.v);
            }
        }
        CAPTURE(q[0], q[1], q[2], q[3]);
        CHECK(area2 == 2 * one * one);
        CHECK(inverted == 0);
        CHECK(diagonal[0] == diagonal[1]); // the two halves share the diagonal's points bit for bit
        for (unsigned e = 0; e < 4; ++e) {
            std::array<std::uint32_t, max_segments + 1> pts{};
            const unsigned n = edge_points(q[e], 64, pts.data());
            CHECK(edges[e] ==
                  std::set<std::uint32_t>(pts.begin(), pts.begin() + n)); // each edge: its own line
        }
    }
}

// --- orientation -------------------------------------------------------------------------------------------

TEST_CASE("orientation: smallest edge on e2, winding kept, deterministic ties", "[cp][orientation]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::array<float, 3> lengths[] = {{1, 2, 3}, {3, 1, 2}, {2, 3, 1},
                                            {5, 5, 5}, {2, 1, 1}, {nan, 4, 2}};
    const unsigned smallest[] = {0, 1, 2, 0, 1, 2};
    for (unsigned k = 0; k < 6; ++k) {
        const auto& l = lengths[k];
        const Rotation r = smallest_edge_rotation(l[0], l[1], l[2]);
        CAPTURE(k);
        CHECK(rotate_factors(r, l)[2] == l[smallest[k]]);
    }
    CHECK(smallest_edge_rotation(nan, nan, nan) == smallest_edge_rotation(1, 2, 3));
    CHECK(smallest_edge_rotation(nan, nan, 7) == Rotation{0}); // e2 = E2
    for (std::uint8_t shift = 0; shift < 3; ++shift) {
        const Rotation r{shift};
        // Base edge E_k joins w_k and w_{k+1}; pattern edge e0 = v0v1, e1 = v1v2, e2 = v2v0 (as a set).
        const std::array<float, 3> base = {10, 20, 30};
        const std::array<float, 3> f = rotate_factors(r, base);
        for (unsigned e = 0; e < 3; ++e) {
            const unsigned a = base_vertex(r, e), b = base_vertex(r, (e + 1) % 3);
            const unsigned base_edge = (b == (a + 1) % 3) ? a : b;
            CHECK(f[e] == base[base_edge]);
        }
        // Corners map to base corners, and a CCW pattern triangle stays CCW in base coordinates.
        const DomainPoint corners[3] = {{0, 0}, {fixed_one, 0}, {0, fixed_one}};
        for (unsigned k = 0; k < 3; ++k) CHECK(to_base_point(r, corners[k]) == corners[base_vertex(r, k)]);
        const DomainPoint p{1000, 2000}, q{5000, 100}, t{300, 9000};
        REQUIRE(signed_area2(p, q, t) > 0);
        CHECK(signed_area2(to_base_point(r, p), to_base_point(r, q), to_base_point(r, t)) ==
              signed_area2(p, q, t));
    }
}

// --- constant evaluation -----------------------------------------------------------------------------------

namespace {
constexpr Counts constexpr_mesh_area_ok() {
    std::array<DomainPoint, 64> v{};
    std::array<std::uint32_t, 3 * 68> idx{};
    PatternOptions opt;
    opt.max_factor = 64;
    opt.layout = Layout::shared;
    const Counts c = tessellate(v, idx, 16.0f, 8.0f, 4.0f, opt);
    int128 area2 = 0;
    for (std::uint32_t t = 0; t < c.triangles; ++t)
        area2 += signed_area2(v[idx[3 * t]], v[idx[3 * t + 1]], v[idx[3 * t + 2]]);
    return area2 == std::int64_t{fixed_one} * fixed_one ? c : Counts{};
}
constexpr bool constexpr_provoking_unique() {
    std::array<DomainPoint, 66> v{};
    std::array<std::uint32_t, 3 * 64> idx{};
    const Counts c = tessellate(v, idx, 8.0f, 8.0f, 8.0f,
                                PatternOptions{{Layout::provoking}, 64, ColumnRule::minimal, true});
    if (!(c == Counts{66, 64})) return false; // 45 unique + one copy per non-top point of columns 1..6
    for (std::uint32_t a = 0; a < c.triangles; ++a) {
        for (std::uint32_t b = a + 1; b < c.triangles; ++b) {
            if (idx[3 * a] == idx[3 * b]) return false;
        }
    }
    return true;
}
constexpr unsigned constexpr_gap_count() {
    std::array<std::uint16_t, 9> l{}, s{}, m{};
    const EdgeLine e = make_edge_line({4, lerp_one});
    const unsigned nl = gap_lhs_coords(e, l.data());
    const unsigned n1 = gap_rhs_coords(e, s.data());
    gap_merge(l.data(), nl, s.data(), n1, m.data());
    unsigned count = 0;
    for_each_gap_triangle(m.data(), nl, [&](GapCorner, GapCorner, GapCorner) { ++count; });
    return m[3] == 3 ? count : 0;
}
constexpr unsigned constexpr_type1_count() {
    unsigned count = 0;
    for_each_type1_triangle(Type1Slots{3}, [&](unsigned, unsigned, unsigned) { ++count; });
    return count;
}
constexpr unsigned constexpr_column_sum() {
    ColumnCounts r{};
    const unsigned n0 = column_counts(4, 4, ColumnRule::minimal, r.data());
    unsigned sum = 0;
    for (unsigned i = 0; i < n0; ++i) sum += r[i];
    return sum;
}
constexpr std::array<unsigned, 2> constexpr_rows() {
    std::array<PointTrack, 9> t{};
    token_points(4, t.data());
    return {minimal_rows(t.data(), 8, t.data(), 8, 4, 3), staircase_rows(t.data(), t.data(), 8, 3)};
}
} // namespace

TEST_CASE("constant evaluation of every public function", "[cp][constexpr]") {
    STATIC_REQUIRE(constexpr_mesh_area_ok() == Counts{49, 68});
    STATIC_REQUIRE(tessellate({}, {}, LineState{4, lerp_one}, LineState{4, lerp_one}, LineState{4, lerp_one},
                              PatternOptions{{Layout::shared}, 64, ColumnRule::minimal, true}) ==
                   Counts{45, 64});
    STATIC_REQUIRE(
        pattern_counts(1.5f, 20.0f, 1.2f, PatternOptions{{Layout::shared}, 64, ColumnRule::minimal, true}) ==
        Counts{27, 26});
    STATIC_REQUIRE(
        pattern_counts(5, 5, 5, PatternOptions{{Layout::shared}, 64, ColumnRule::staircase, true}) ==
        Counts{28, 36});
    STATIC_REQUIRE(pattern_counts(1, 1, 1) == Counts{3, 1});
    STATIC_REQUIRE(max_pattern_counts(64) == Counts{4098, 4096});
    STATIC_REQUIRE(pattern_type(LineState{0, 0}, LineState{9, 0}, LineState{1, 5}) == PatternType::fan);
    STATIC_REQUIRE(constexpr_provoking_unique());
    STATIC_REQUIRE(constexpr_gap_count() == 15);
    STATIC_REQUIRE(constexpr_type1_count() == 9);
    STATIC_REQUIRE(constexpr_column_sum() == 36);
    STATIC_REQUIRE(constexpr_rows() == std::array<unsigned, 2>{5, 5});
    STATIC_REQUIRE(clamp_line(make_edge_line({2, lerp_one}), make_edge_line({2, lerp_one})) ==
                   3 * fixed_one / 4);
    STATIC_REQUIRE(column_clamp(100, 30) == 70);
    STATIC_REQUIRE(column_clamp(30, 100) == 0);
    STATIC_REQUIRE(clamp_line_state({99, 5}, 64) == LineState{16, lerp_one});
    STATIC_REQUIRE(pattern_max_factor(100) == 64);
    STATIC_REQUIRE(type1_center(lerp_one, 123) == DomainPoint{fixed_one / 2, 0});
    STATIC_REQUIRE(split_quad({1, 2, 3, 4}).triangles[1].factors == std::array<float, 3>{3, 1, 2});
    STATIC_REQUIRE(quad_triangle_corners(split_quad({1, 2, 3, 4}), 0, {7, 8, 9, 10}) ==
                   std::array<std::uint32_t, 3>{7, 8, 10});
    STATIC_REQUIRE(quad_point(1, {0, 0}) == DomainPoint{fixed_one, fixed_one});
    STATIC_REQUIRE(smallest_edge_rotation(3, 1, 2) == Rotation{2});
    STATIC_REQUIRE(base_vertex(Rotation{2}, 2) == 1);
    STATIC_REQUIRE(rotate_factors(Rotation{1}, {1, 2, 3}) == std::array<float, 3>{2, 3, 1});
    STATIC_REQUIRE(to_base_point(Rotation{1}, {0, 0}) == DomainPoint{fixed_one, 0});
}

// docs/api.md, "Sized outputs": a fill into a span one entry too short writes nothing and still returns the
// counts; spans of exactly the counts are filled.
TEST_CASE("cp::tessellate and tessellate_quad: a short span gets nothing written, exact spans the pattern",
          "[cp][bad_input]") {
    constexpr DomainPoint sentinel{0xDEADBEEFu, 0xFEEDFACEu};
    auto check = [&](auto&& fill, Counts n) {
        for (int short_side = 0; short_side < 2; ++short_side) {
            std::vector<DomainPoint> v(n.vertices - (short_side == 0 ? 1 : 0), sentinel);
            std::vector<std::uint32_t> i(n.index_count() - (short_side == 1 ? 1 : 0), 0xABCDEF01u);
            CHECK(fill(v, i) == n);
            CHECK(std::all_of(v.begin(), v.end(), [&](DomainPoint p) { return p == sentinel; }));
            CHECK(std::all_of(i.begin(), i.end(), [](std::uint32_t x) { return x == 0xABCDEF01u; }));
        }
        std::vector<DomainPoint> v(n.vertices, sentinel);
        std::vector<std::uint32_t> i(n.index_count(), 0xABCDEF01u);
        CHECK(fill(v, i) == n);
        CHECK(std::none_of(i.begin(), i.end(), [](std::uint32_t x) { return x == 0xABCDEF01u; }));
    };
    for (const Layout layout : {Layout::provoking, Layout::shared}) {
        PatternOptions opt;
        opt.layout = layout;
        check([&](std::span<DomainPoint> v,
                  std::span<std::uint32_t> i) { return tessellate(v, i, 10.3f, 6, 3, opt); },
              pattern_counts(10.3f, 6, 3, opt));
        const std::array<float, 4> quad{12, 5, 12, 30};
        check([&](std::span<DomainPoint> v,
                  std::span<std::uint32_t> i) { return tessellate_quad(v, i, quad, opt); },
              tessellate_quad({}, {}, quad, opt));
    }
}
