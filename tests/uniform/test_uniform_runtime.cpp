// ctess::rt::UniformPatch against the constexpr patterns (docs/algorithm.md §3.4): for every sorted triple of
// both table sets and every order of its factors, the patch is the stored pattern with its corners mapped so
// that output edge i has f_i segments, counter-clockwise (or clockwise on request); the provoking layout is
// the shared one plus the fewest copies, with every first index unique; neighbouring patches weld bit for
// bit; bad input gets the documented clamp.
#include <ctess/runtime/uniform/patch.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <vector>

#include <catch2/catch.hpp>

#include "support/emit_all.hpp"
#include "support/mesh_checks.hpp"

namespace uf = ctess::uniform;
using ctess::rt::UniformPatch;
using ctess::rt::UniformTableSet;
using ctess::uniform::Point;

namespace {

using Factors = std::array<std::uint32_t, 3>;
using Keyed = std::array<std::uint64_t, 3>;

// The corner permutations: perm[c] = output corner of canonical corner c.
constexpr std::array<std::array<int, 3>, 6> permutations = {
    {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}};

// Edge (a, b) of corners -> edge index: {0,1} e0, {1,2} e1, {0,2} e2.
int edge_of(int a, int b) {
    const int lo = std::min(a, b), hi = std::max(a, b);
    return lo == 0 ? (hi == 1 ? 0 : 2) : 1;
}

Point map_point(Point c, const std::array<int, 3>& perm) {
    const std::uint32_t weight[3] = {uf::fixed_one - c.u - c.v, c.u, c.v};
    std::uint32_t out[3] = {};
    for (int k = 0; k < 3; ++k) out[perm[k]] = weight[k];
    return {out[1], out[2]};
}

// The triangles of a mesh as rotated position keys, sorted (winding kept).
std::vector<Keyed> keyed(const std::vector<Point>& v, const std::vector<std::uint32_t>& idx) {
    std::vector<Keyed> out;
    for (std::size_t t = 0; t < idx.size(); t += 3) {
        const auto r = ctess::test::canonical_rotation({ctess::test::check_point(v[idx[t]]),
                                                        ctess::test::check_point(v[idx[t + 1]]),
                                                        ctess::test::check_point(v[idx[t + 2]])});
        out.push_back({ctess::test::position_key(r[0]), ctess::test::position_key(r[1]),
                       ctess::test::position_key(r[2])});
    }
    std::sort(out.begin(), out.end());
    return out;
}

using ctess::test::emit_all;
using Emitted = ctess::test::BasicEmitted<Point>;

// The stored pattern mapped by every corner permutation that carries canonical edge factors onto the output
// edges; the patch must equal one of them.
bool matches_some_mapping(const Emitted& e, const Factors& f, bool cw) {
    std::array<std::uint32_t, 3> s = f;
    std::sort(s.begin(), s.end(), std::greater<>());
    const uf::Pattern p = uf::pattern(s[0], s[1], s[2]);
    const auto got = keyed(e.vertices, e.indices);
    for (const auto& perm : permutations) {
        // canonical e0 = (0,1), e1 = (1,2), e2 = (0,2)
        if (f[edge_of(perm[0], perm[1])] != s[0] || f[edge_of(perm[1], perm[2])] != s[1] ||
            f[edge_of(perm[0], perm[2])] != s[2])
            continue;
        std::vector<Point> v;
        for (unsigned k = 0; k < p.vertex_count(); ++k) v.push_back(map_point(p.vertex(k), perm));
        std::vector<std::uint32_t> idx;
        for (unsigned t = 0; t < p.triangle_count(); ++t) {
            auto tri = p.triangle(t);
            // orient counter-clockwise in the output plane (or clockwise on request)
            const bool ccw = ctess::test::signed_area2(v[tri[0]], v[tri[1]], v[tri[2]]) > 0;
            if (ccw == cw) std::swap(tri[1], tri[2]);
            idx.insert(idx.end(), tri.begin(), tri.end());
        }
        if (keyed(v, idx) == got) return true;
    }
    return false;
}

// Calls visit(factors, sorted) for every sorted triple of [1, n] in each of the six orders of its factors.
template <class Visit>
void for_each_ordered_triple(unsigned n, Visit&& visit) {
    for (unsigned a = 1; a <= n; ++a)
        for (unsigned b = 1; b <= a; ++b)
            for (unsigned c = 1; c <= b; ++c)
                for (const auto& order : permutations) {
                    const Factors sorted{a, b, c};
                    visit(Factors{sorted[order[0]], sorted[order[1]], sorted[order[2]]}, sorted);
                }
}

std::vector<std::uint32_t> parameters(unsigned f) {
    std::vector<std::uint32_t> out;
    for (unsigned i = 0; i <= f; ++i) out.push_back(uf::edge_parameter(i, f));
    return out;
}

} // namespace

TEST_CASE("uniform runtime: every triple in every order is the stored pattern with edge i at f_i",
          "[uniform][runtime]") {
    for (const UniformTableSet* set : {&ctess::rt::uniform_tables_11, &ctess::rt::uniform_tables_16}) {
        const unsigned n = set->max_factor;
        std::size_t checked = 0;
        for_each_ordered_triple(n, [&](const Factors& f, const Factors& sorted) {
            INFO("max " << n << " factors " << f[0] << "," << f[1] << "," << f[2]);
            for (bool cw : {false, true}) {
                const ctess::PatchOptions opt{ctess::Layout::shared,
                                              cw ? ctess::Winding::cw : ctess::Winding::ccw};
                const UniformPatch patch(*set, float(f[0]), float(f[1]), float(f[2]), opt);
                const Emitted e = emit_all(patch);
                REQUIRE(patch.counts().triangles ==
                        uf::pattern(sorted[0], sorted[1], sorted[2]).triangle_count());
                REQUIRE(matches_some_mapping(e, f, cw));
                // random access equals the bulk emit
                for (std::uint32_t t = 0; t < patch.counts().triangles; ++t) {
                    const auto tri = patch.triangle(t);
                    REQUIRE((tri[0] == e.indices[3 * t] && tri[1] == e.indices[3 * t + 1] &&
                             tri[2] == e.indices[3 * t + 2]));
                }
                if (!cw) { // edge i carries exactly f_i segments
                    const auto loop = ctess::test::boundary_loop_edges(parameters(f[0]), parameters(f[1]),
                                                                       parameters(f[2]), uf::fixed_one);
                    const std::vector<ctess::DomainPoint> carried = ctess::test::check_points(e.vertices);
                    const auto topo = ctess::test::surface_topology({carried, e.indices}, loop);
                    REQUIRE(topo.boundary_matches);
                    REQUIRE(topo.edges_unique);
                }
            }
            ++checked;
        });
        REQUIRE(checked == 6 * uf::pattern_count(n));
    }
}

TEST_CASE("uniform runtime: the provoking layout is the shared one with a unique first vertex per triangle",
          "[uniform][runtime][provoking]") {
    using ctess::Layout;
    for (const UniformTableSet* set : {&ctess::rt::uniform_tables_11, &ctess::rt::uniform_tables_16}) {
        const unsigned n = set->max_factor;
        std::size_t copies_total = 0, checked = 0;
        for (unsigned a = 1; a <= n; ++a)
            for (unsigned b = 1; b <= a; ++b)
                for (unsigned c = 1; c <= b; ++c) {
                    const uf::Pattern pattern = uf::pattern(a, b, c);
                    const std::uint32_t v = pattern.vertex_count(), t = pattern.triangle_count();
                    // every triangle needs a first vertex of its own: at least max(T - V, 0) copies
                    const std::uint32_t fewest = t > v ? t - v : 0u;
                    copies_total += fewest;
                    for (const auto& order : permutations)
                        for (const ctess::Winding winding : {ctess::Winding::ccw, ctess::Winding::cw}) {
                            const Factors sorted{a, b, c};
                            const Factors f{sorted[order[0]], sorted[order[1]], sorted[order[2]]};
                            INFO("max " << n << " factors " << f[0] << "," << f[1] << "," << f[2] << " cw "
                                        << (winding == ctess::Winding::cw));
                            const UniformPatch shared(*set, f, {Layout::shared, winding});
                            const UniformPatch provoking(*set, f, {Layout::provoking, winding});
                            REQUIRE(shared.counts() == ctess::Counts{v, t});
                            REQUIRE(provoking.counts() == ctess::Counts{v + fewest, t});
                            REQUIRE(provoking.distinct_vertices() == v);
                            const Emitted s = emit_all(shared), e = emit_all(provoking);
                            // positions [0, V) are the shared layout's
                            REQUIRE(std::equal(s.vertices.begin(), s.vertices.end(), e.vertices.begin()));
                            std::set<std::uint64_t> distinct;
                            for (const Point d : s.vertices) distinct.insert(ctess::test::position_key(d));
                            std::vector<int> provokes(v + fewest, 0);
                            for (std::uint32_t p = 0; p < t; ++p) {
                                const std::uint32_t* si = &s.indices[3 * p];
                                const std::uint32_t* pi = &e.indices[3 * p];
                                // the same triangle as positions, same order and winding
                                for (int k = 0; k < 3; ++k) REQUIRE(e.vertices[pi[k]] == s.vertices[si[k]]);
                                // only the first index may differ, and then it names a copy
                                REQUIRE((pi[1] == si[1] && pi[2] == si[2]));
                                REQUIRE((pi[0] == si[0] || pi[0] >= v));
                                ++provokes[pi[0]];
                                const auto tri = provoking.triangle(p);
                                REQUIRE((tri[0] == pi[0] && tri[1] == pi[1] && tri[2] == pi[2]));
                            }
                            // every first index is unique, and every copy provokes exactly one triangle
                            for (std::uint32_t i = 0; i < v + fewest; ++i) {
                                REQUIRE(provokes[i] <= 1);
                                if (i >= v) {
                                    REQUIRE(provokes[i] == 1);
                                    REQUIRE(distinct.count(ctess::test::position_key(e.vertices[i])) == 1);
                                }
                                REQUIRE(provoking.vertex(i) == e.vertices[i]);
                            }
                            // short spans: false, nothing written
                            std::vector<Point> sv(v + fewest - 1, Point{7, 7});
                            std::vector<std::uint32_t> si(3 * t, 7u);
                            REQUIRE_FALSE(provoking.emit(sv, si));
                            REQUIRE(
                                std::all_of(si.begin(), si.end(), [](std::uint32_t x) { return x == 7u; }));
                            sv.assign(v + fewest, Point{7, 7});
                            si.resize(3 * t - 1);
                            REQUIRE_FALSE(provoking.emit(sv, si));
                            REQUIRE(std::all_of(sv.begin(), sv.end(), [](Point d) {
                                return d == Point{7, 7};
                            }));
                            ++checked;
                        }
                }
        REQUIRE(checked == 12 * uf::pattern_count(n));
        // the regular n^2 grid has more triangles than vertices: one vertex per triangle
        const UniformPatch grid(*set, Factors{n, n, n}, {Layout::provoking, ctess::Winding::ccw});
        CHECK(grid.counts() == ctess::Counts{n * n, n * n});
        WARN("copies at N = " << n << ": " << copies_total);
    }
}

TEST_CASE("uniform runtime: two patches sharing an edge weld bit for bit", "[uniform][runtime]") {
    // Patch A on corners (P0, P1, P2); patch B on (P2, P1, Q) shares A's e1 (P1 -> P2) as its e0 (P2 -> P1).
    // Positions are exact integer interpolations of integer corners.
    using Pos = std::array<std::int64_t, 2>;
    const Pos P0{0, 0}, P1{1000003, 17}, P2{-31, 999983}, Q{1200000, 1100000};
    auto position = [](Point d, const Pos& c0, const Pos& c1, const Pos& c2) {
        const std::int64_t w = uf::fixed_one - d.u - d.v;
        return Pos{w * c0[0] + d.u * c1[0] + d.v * c2[0], w * c0[1] + d.u * c1[1] + d.v * c2[1]};
    };
    const UniformTableSet& set = ctess::rt::uniform_tables_16;
    for (std::uint32_t shared = 1; shared <= 16; ++shared)
        for (std::uint32_t a0 = 1; a0 <= 16; ++a0)
            for (std::uint32_t a2 = 1; a2 <= 16; ++a2)
                for (std::uint32_t b1 = 1; b1 <= 16; b1 += 3) {
                    const UniformPatch a(set, float(a0), float(shared), float(a2));
                    const UniformPatch b(set, float(shared), float(b1), float(a2 == 1 ? 16 : a2 - 1));
                    std::set<Pos> on_a, on_b;
                    for (std::uint32_t i = 0; i < a.counts().vertices; ++i) {
                        const Point d = a.vertex(i);
                        if (d.u + d.v == uf::fixed_one) on_a.insert(position(d, P0, P1, P2));
                    }
                    for (std::uint32_t i = 0; i < b.counts().vertices; ++i) {
                        const Point d = b.vertex(i);
                        if (d.v == 0) on_b.insert(position(d, P2, P1, Q));
                    }
                    INFO("shared " << shared << " a " << a0 << "," << a2 << " b " << b1);
                    REQUIRE(on_a.size() == shared + 1);
                    REQUIRE(on_a == on_b);
                }
}

// The exact rule in double arithmetic, independent of uniform::round_factor's bit manipulation: every float
// below 2^24 plus 0.5 is exact in double, so floor() rounds halves up exactly.
static std::uint32_t reference_round(float f, std::uint32_t n) {
    if (!(f >= 1.5f)) return 1;
    const double r = std::floor(static_cast<double>(f) + 0.5);
    return r >= n ? n : static_cast<std::uint32_t>(r);
}

TEST_CASE("uniform factor rounding: one rule, exact halves up, for every float in [0, 20) and around every "
          "half in [0.5, 300]",
          "[uniform][runtime][bad_input]") {
    std::uint64_t wrong = 0;
    for (std::uint32_t bits = 0; bits <= std::bit_cast<std::uint32_t>(20.0f); ++bits) {
        const float f = std::bit_cast<float>(bits);
        for (std::uint32_t n : {11u, 16u})
            wrong += ctess::uniform::round_factor(f, n) != reference_round(f, n);
    }
    CHECK(wrong == 0);
    for (std::uint32_t k = 0; k <= 300; ++k) {
        const std::uint32_t half = std::bit_cast<std::uint32_t>(static_cast<float>(k) + 0.5f);
        for (std::uint32_t bits = half - 64; bits <= half + 64; ++bits) {
            const float f = std::bit_cast<float>(bits);
            for (std::uint32_t n : {11u, 16u, 256u}) {
                INFO("f = " << f << ", n = " << n);
                REQUIRE(ctess::uniform::round_factor(f, n) == reference_round(f, n));
                REQUIRE(ctess::uniform::within_table(f, n) == (reference_round(f, n + 1) <= n));
            }
        }
    }
    // The ties that float addition (f + 0.5f) rounds the wrong way: just below k + 0.5 where k + 1 is a power
    // of two, f + 0.5f is exactly halfway between two floats and rounds to the even k + 1.
    CHECK(ctess::uniform::round_factor(std::nextafter(3.5f, 0.0f), 16) == 3);
    CHECK(ctess::uniform::round_factor(std::nextafter(7.5f, 0.0f), 16) == 7);
    CHECK(ctess::uniform::round_factor(std::nextafter(127.5f, 0.0f), 256) == 127);
}

TEST_CASE("uniform runtime bad input: documented rounding and clamps, never UB",
          "[uniform][runtime][bad_input]") {
    const UniformTableSet& set = ctess::rt::uniform_tables_16;
    constexpr float nan_f = std::numeric_limits<float>::quiet_NaN();
    constexpr float inf_f = std::numeric_limits<float>::infinity();
    for (float f :
         {nan_f, -inf_f, -5.0f, -0.0f, 0.0f, std::numeric_limits<float>::denorm_min(), 1.0f, 1.49f}) {
        INFO("f = " << f);
        CHECK(ctess::rt::uniform_factor(f, 16) == 1);
        const UniformPatch p(set, f, f, f);
        CHECK(p.counts() == ctess::Counts{3, 1});
    }
    for (float f : {inf_f, 1e30f, 16.0f, 15.5f, 17.0f, float(std::numeric_limits<std::uint32_t>::max())}) {
        INFO("f = " << f);
        CHECK(ctess::rt::uniform_factor(f, 16) == 16);
        CHECK(UniformPatch(set, f, f, f).counts().triangles == 256);
    }
    CHECK(ctess::rt::uniform_factor(1.5f, 16) == 2);
    CHECK(ctess::rt::uniform_factor(2.49f, 16) == 2);
    CHECK(ctess::rt::uniform_factor(2.5f, 16) == 3);
    CHECK(ctess::rt::uniform_factor(12.0f, 11) == 11);
    CHECK(UniformPatch(ctess::rt::uniform_tables_11, 16.0f, 16.0f, 16.0f).counts().triangles == 121);
    CHECK(UniformPatch(set, Factors{0, 99, 5}).sorted_factors() == Factors{16, 5, 1});

    const UniformPatch p(set, 11.0f, 9.0f, 6.0f);
    const ctess::Counts n = p.counts();
    CHECK(p.vertex(n.vertices) == Point{0, 0});
    CHECK(p.vertex(0xFFFFFFFFu) == Point{0, 0});
    CHECK(p.triangle(n.triangles) == ctess::rt::UniformTriangle{0, 0, 0});
    std::vector<Point> v(n.vertices - 1, Point{7, 7});
    std::vector<std::uint32_t> idx(n.index_count(), 7u);
    CHECK_FALSE(p.emit(v, idx));
    CHECK(std::all_of(v.begin(), v.end(), [](Point d) { return d == Point{7, 7}; }));
    CHECK(std::all_of(idx.begin(), idx.end(), [](std::uint32_t i) { return i == 7u; }));
    v.resize(n.vertices);
    idx.resize(n.index_count() - 1);
    CHECK_FALSE(p.emit(v, idx));
    CHECK(std::all_of(idx.begin(), idx.end(), [](std::uint32_t i) { return i == 7u; }));
    // an index_base whose largest index would reach 2^32 - 1 (the restart value) or wrap: false, nothing
    // written; the largest base that fits puts the last vertex at 2^32 - 2
    idx.resize(n.index_count(), 7u);
    std::fill(v.begin(), v.end(), Point{7, 7});
    const std::uint32_t largest = 0xFFFFFFFFu - n.vertices;
    CHECK_FALSE(p.emit(v, idx, largest + 1));
    CHECK(std::all_of(v.begin(), v.end(), [](Point d) { return d == Point{7, 7}; }));
    CHECK(std::all_of(idx.begin(), idx.end(), [](std::uint32_t i) { return i == 7u; }));
    REQUIRE(p.emit(v, idx, largest));
    CHECK(*std::max_element(idx.begin(), idx.end()) == 0xFFFFFFFEu);
}

TEST_CASE("uniform runtime: emit() is vertex(i) and triangle(p) bit for bit, plus index_base",
          "[uniform][runtime][emit]") {
    // The bulk path (docs/algorithm.md §3.4) shares no code with random access past the constructor: its
    // boundary parameters use the reciprocal, its copies a running rank, its winding a swap of bytes.
    constexpr std::uint32_t base = 1000, spare = 5; // spare elements past the counts: never written
    for (const UniformTableSet* set : {&ctess::rt::uniform_tables_11, &ctess::rt::uniform_tables_16}) {
        const unsigned n = set->max_factor;
        std::size_t checked = 0;
        for_each_ordered_triple(n, [&](const Factors& f, const Factors&) {
            for (const ctess::Layout layout : {ctess::Layout::shared, ctess::Layout::provoking})
                for (const ctess::Winding winding : {ctess::Winding::ccw, ctess::Winding::cw}) {
                    INFO("max " << n << " factors " << f[0] << "," << f[1] << "," << f[2] << " provoking "
                                << (layout == ctess::Layout::provoking) << " cw "
                                << (winding == ctess::Winding::cw));
                    const UniformPatch patch(*set, f, {layout, winding});
                    const ctess::Counts counts = patch.counts();
                    std::vector<Point> v(counts.vertices + spare, Point{7, 7});
                    std::vector<std::uint32_t> idx(counts.index_count() + spare, 7u);
                    for (const std::uint32_t b0 : {0u, base}) {
                        REQUIRE(patch.emit(v, idx, b0));
                        for (std::uint32_t i = 0; i < counts.vertices; ++i) REQUIRE(v[i] == patch.vertex(i));
                        for (std::uint32_t p = 0; p < counts.triangles; ++p) {
                            const auto t = patch.triangle(p);
                            REQUIRE((idx[3 * p] == b0 + t[0] && idx[3 * p + 1] == b0 + t[1] &&
                                     idx[3 * p + 2] == b0 + t[2]));
                        }
                        for (std::uint32_t k = 0; k < spare; ++k) {
                            REQUIRE(v[counts.vertices + k] == Point{7, 7});
                            REQUIRE(idx[counts.index_count() + k] == 7u);
                        }
                    }
                    ++checked;
                }
        });
        REQUIRE(checked == 24 * uf::pattern_count(n));
    }
}

TEST_CASE("uniform quantise: the reciprocal edge parameter equals the division up to f = 238",
          "[uniform][runtime][emit]") {
    // Exhaustive over 0 <= i <= f: exact through 238 (the header's static_assert covers 128), and the bound
    // is tight: f = 239 has a point where the multiply and shift is off by one.
    CHECK(uf::edge_reciprocal_exact(238));
    CHECK_FALSE(uf::edge_reciprocal_exact(239));
    // spot values: the midpoint of an even edge is exactly 0.5, the ends are exact
    CHECK(uf::edge_parameter(8, 16, uf::edge_reciprocal(16)) == 32767);
    CHECK(uf::edge_parameter(0, 11, uf::edge_reciprocal(11)) == 0);
    CHECK(uf::edge_parameter(11, 11, uf::edge_reciprocal(11)) == uf::fixed_one);
}
