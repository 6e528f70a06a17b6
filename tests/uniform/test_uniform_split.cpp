// Uniform-density splitting above the table (docs/algorithm.md §3.5): exact coverage without inverted or
// zero-area triangles, bounded depth, counts equal to what emit writes, crack-free neighbours at any depth
// (shared-edge positions equal bit for bit), the patch itself below N, and bad input clamped.
#include <ctess/analysis/signed_area.hpp>
#include <ctess/runtime/uniform/split.hpp>
#include <ctess/uniform/metric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <vector>

#include <catch2/catch.hpp>

#include "support/emit_all.hpp"

using ctess::rt::UniformSplit;
using ctess::uniform::SplitPoint;

namespace {

using ctess::analysis::int128;

using ctess::test::emit_all;

// The default interior dice tolerance (1.433 N) and the strict one (N), §3.5: the same invariants hold.
constexpr std::array<double, 2> tolerances{ctess::rt::uniform_split_interior_tolerance,
                                           ctess::rt::uniform_split_strict_tolerance};

void check_coverage(const ctess::rt::UniformTableSet& set, double tolerance);

// Two patches on common integer corners (A = P0 P1 P2, B on P1, P2 and Q): a split patch's point d (units of
// uniform_split_fixed_one) as an exact position, so points on a shared edge compare bit for bit.
using Pos = std::array<int128, 2>;
constexpr Pos P0{0, 0}, P1{1000003, 17}, P2{-31, 999983}, Q{1200000, 1100000};
Pos position(SplitPoint d, const Pos& c0, const Pos& c1, const Pos& c2) {
    const int128 one = ctess::rt::uniform_split_fixed_one;
    const int128 w = one - d.u - d.v;
    return Pos{w * c0[0] + d.u * c1[0] + d.v * c2[0], w * c0[1] + d.u * c1[1] + d.v * c2[1]};
}

// The given triples, then `count` seeded random ones with factors in [low, low + range).
std::vector<std::array<float, 3>> with_random(std::vector<std::array<float, 3>> cases, std::uint32_t state,
                                              int count, unsigned low, unsigned range) {
    for (int k = 0; k < count; ++k) {
        std::array<float, 3> f{};
        for (float& x : f) x = static_cast<float>(low + (state = state * 1664525u + 1013904223u) % range);
        cases.push_back(f);
    }
    return cases;
}

} // namespace

TEST_CASE("uniform split: exact coverage, positive triangles, bounded depth", "[uniform][split]") {
    for (const auto* tables : {&ctess::rt::uniform_tables_11, &ctess::rt::uniform_tables_16})
        for (const double tolerance : tolerances) check_coverage(*tables, tolerance);
}

namespace {
// The pieces an edge of factor t ends in (docs/algorithm.md §3.5), with exact spans.
double final_pieces(double t, double n) {
    if (t < n + 0.5) return 1.0;
    const double k = std::min(std::ceil(std::floor(t + 0.5) / n), n);
    return k * final_pieces(t / k, n);
}
void check_coverage(const ctess::rt::UniformTableSet& set, double tolerance) {
    const double n = set.max_factor;
    const std::array<std::array<float, 3>, 9> cases = {{{40, 30, 20},
                                                        {17, 1, 16},
                                                        {100, 3, 99},
                                                        {256, 256, 256},
                                                        {255.4f, 17, 200},
                                                        {33, 64, 31},
                                                        {16, 16, 17},
                                                        {250, 9, 250},
                                                        {1e9f, 5, 200}}};
    for (const auto& f : cases) {
        INFO("N " << n << " tolerance " << tolerance << " factors " << f[0] << "," << f[1] << "," << f[2]);
        const UniformSplit s(set, f[0], f[1], f[2], {}, tolerance);
        REQUIRE(s.depth() <= s.depth_limit());
        REQUIRE(s.depth_limit() <= ctess::rt::uniform_split_depth_bound(set.max_factor));
        const auto e = emit_all(s);
        int128 sum = 0;
        for (std::size_t t = 0; t < e.indices.size(); t += 3) {
            const int128 a = ctess::analysis::signed_area2(
                e.vertices[e.indices[t]], e.vertices[e.indices[t + 1]], e.vertices[e.indices[t + 2]]);
            REQUIRE(a > 0);
            sum += a;
        }
        const int128 one = ctess::rt::uniform_split_fixed_one;
        REQUIRE(sum == one * one);
        // A split edge with factor T gets S = min(ceil(T / N), N) sub-edges of factor T * span, split again
        // the same way until they are at most N (+ 0.5); only those final P pieces round, each on its own,
        // so the edge carries T segments within P / 2 (the spans' quantisation adds far less than 0.5).
        std::set<std::uint32_t> on_e0, on_e1, on_e2;
        for (const SplitPoint& p : e.vertices) {
            if (p.v == 0) on_e0.insert(p.u);
            if (std::uint64_t{p.u} + p.v == ctess::rt::uniform_split_fixed_one) on_e1.insert(p.v);
            if (p.u == 0) on_e2.insert(p.v);
        }
        const auto r = s.factors();
        const std::size_t counts[3] = {on_e0.size() - 1, on_e1.size() - 1, on_e2.size() - 1};
        for (int i = 0; i < 3; ++i) {
            const double sub_edges = final_pieces(r[i], n);
            INFO("edge " << i << ": " << counts[i] << " segments for factor " << r[i]);
            CHECK(std::fabs(double(counts[i]) - r[i]) <= (r[i] <= n ? 0.0 : sub_edges / 2));
        }
    }
}
} // namespace

TEST_CASE("uniform split: no T-junction inside the patch, whichever subpatches dice and which split",
          "[uniform][split]") {
    // A subpatch that dices and its neighbour that splits must put the same points on their shared edge:
    // every edge inside the root patch is used once in each direction (exact positions). The first four
    // triples cracked when a split patch subdivided an edge that its diced neighbour kept whole (found by
    // fuzz_uniform).
    const auto cases =
        with_random({{193, 160, 254}, {222, 193, 192}, {93, 231, 142}, {256, 256, 210}}, 2026, 60, 1, 256);
    constexpr std::uint64_t one = ctess::rt::uniform_split_fixed_one;
    auto on_root_edge = [](SplitPoint a, SplitPoint b) {
        return (a.v == 0 && b.v == 0) || (a.u == 0 && b.u == 0) ||
               (std::uint64_t{a.u} + a.v == one && std::uint64_t{b.u} + b.v == one);
    };
    for (const auto* set : {&ctess::rt::uniform_tables_11, &ctess::rt::uniform_tables_16})
        for (const double tolerance : tolerances)
            for (const auto& f : cases) {
                INFO("N " << set->max_factor << " tolerance " << tolerance << " factors " << f[0] << ","
                          << f[1] << "," << f[2]);
                const auto e = emit_all(UniformSplit(*set, f[0], f[1], f[2], {}, tolerance));
                std::map<std::pair<std::uint64_t, std::uint64_t>, int>
                    net; // (lower, higher) position: up minus down
                auto key = [](SplitPoint p) { return (std::uint64_t{p.u} << 32) | p.v; };
                for (std::size_t t = 0; t < e.indices.size(); t += 3)
                    for (unsigned j = 0; j < 3; ++j) {
                        const std::uint64_t a = key(e.vertices[e.indices[t + j]]),
                                            b = key(e.vertices[e.indices[t + (j + 1) % 3]]);
                        net[{a < b ? a : b, a < b ? b : a}] += a < b ? 1 : -1;
                    }
                std::size_t inside_open = 0;
                for (const auto& [edge, n] : net) {
                    const SplitPoint a{std::uint32_t(edge.first >> 32), std::uint32_t(edge.first)};
                    const SplitPoint b{std::uint32_t(edge.second >> 32), std::uint32_t(edge.second)};
                    inside_open += n != 0 && !on_root_edge(a, b);
                }
                CHECK(inside_open == 0);
            }
}

TEST_CASE("uniform split: neighbours sharing an edge weld bit for bit at any depth", "[uniform][split]") {
    // Patch A (P0, P1, P2) and patch B (P2, P1, Q) share A's e1 as B's e0; integer corners, exact positions.
    const auto& set = ctess::rt::uniform_tables_16;
    std::size_t checked = 0;
    for (float shared : {1.0f, 7.0f, 16.0f, 17.0f, 31.0f, 32.0f, 33.0f, 97.0f, 200.0f, 256.0f})
        for (float other : {1.0f, 12.0f, 40.0f, 150.0f, 256.0f}) {
            const UniformSplit a(set, other, shared, 256.0f - other / 2);
            const UniformSplit b(set, shared, other / 3 + 1, 200.0f);
            const auto ea = emit_all(a), eb = emit_all(b);
            std::set<Pos> on_a, on_b;
            for (const SplitPoint& d : ea.vertices)
                if (std::uint64_t{d.u} + d.v == ctess::rt::uniform_split_fixed_one)
                    on_a.insert(position(d, P0, P1, P2));
            for (const SplitPoint& d : eb.vertices)
                if (d.v == 0) on_b.insert(position(d, P2, P1, Q));
            INFO("shared " << shared << " other " << other);
            REQUIRE(on_a.size() >= 2);
            REQUIRE(on_a == on_b);
            ++checked;
        }
    REQUIRE(checked == 50);
}

TEST_CASE("uniform split: the provoking layout gives every triangle its own first vertex",
          "[uniform][split][provoking]") {
    // Each subpatch keeps its own vertices and copies: the triangles are the shared layout's as positions,
    // in the same order, and no two triangles of the whole output share a first index.
    for (const auto* set : {&ctess::rt::uniform_tables_11, &ctess::rt::uniform_tables_16})
        for (const auto& f : std::array<std::array<float, 3>, 5>{
                 {{40, 30, 20}, {17, 1, 16}, {256, 256, 256}, {100, 3, 99}, {12, 9, 5}}}) {
            INFO("max " << set->max_factor << " factors " << f[0] << "," << f[1] << "," << f[2]);
            const UniformSplit shared(*set, f[0], f[1], f[2], {ctess::Layout::shared, ctess::Winding::ccw});
            const UniformSplit provoking(*set, f[0], f[1], f[2],
                                         {ctess::Layout::provoking, ctess::Winding::ccw});
            REQUIRE(provoking.counts().triangles == shared.counts().triangles);
            REQUIRE(provoking.counts().vertices >= shared.counts().vertices);
            REQUIRE(provoking.counts().vertices >= provoking.counts().triangles);
            const auto s = emit_all(shared), e = emit_all(provoking);
            std::vector<int> provokes(e.vertices.size(), 0);
            for (std::size_t t = 0; t < e.indices.size(); ++t) {
                REQUIRE(e.vertices[e.indices[t]] == s.vertices[s.indices[t]]);
                if (t % 3 == 0) REQUIRE(++provokes[e.indices[t]] == 1);
            }
        }
}

TEST_CASE(
    "uniform split provoking and leaves: each leaf's block is its own pattern, whether leaves repeat or "
    "alternate",
    "[uniform][split][provoking]") {
    // emit() (provoking) and emit_leaves() (shared: the mesh pipeline's unwelded layout, §7.5) reuse the last
    // leaf's points and indices when a leaf rounds alike (§3.5, "Leaf reuse"). Checked against each leaf's
    // UniformPatch through random access (vertex(i), triangle(p): no bulk emit, no reuse): leaf k's indices
    // are its triangles plus the vertices of the leaves before it, and its points its pattern's points on its
    // corners, exact at depth 0 and 1, within half a unit (the rounding) below. The shared leaves' triangles
    // are the welded emit()'s, position for position.
    std::size_t repeated = 0, changed = 0;
    for (const auto* set : {&ctess::rt::uniform_tables_11, &ctess::rt::uniform_tables_16})
        for (const ctess::Layout layout : {ctess::Layout::provoking, ctess::Layout::shared})
            for (const ctess::Winding winding : {ctess::Winding::ccw, ctess::Winding::cw})
                for (const auto& f : std::array<std::array<float, 3>, 5>{
                         {{32, 32, 32}, {64, 40, 25}, {100, 3, 99}, {300, 280, 260}, {33, 17, 33}}}) {
                    INFO("max " << set->max_factor << " factors " << f[0] << "," << f[1] << "," << f[2]
                                << (layout == ctess::Layout::shared ? " leaves" : " provoking"));
                    const UniformSplit split(*set, f[0], f[1], f[2], {layout, winding});
                    ctess::test::BasicEmitted<SplitPoint> e;
                    if (layout == ctess::Layout::shared) {
                        e.vertices.resize(split.leaf_counts().vertices);
                        e.indices.resize(split.leaf_counts().index_count());
                        REQUIRE(split.emit_leaves(e.vertices, e.indices));
                        REQUIRE_FALSE(
                            split.emit_leaves(std::span(e.vertices).first(e.vertices.size() - 1), e.indices));
                        const auto welded = emit_all(split);
                        REQUIRE(welded.indices.size() == e.indices.size());
                        std::size_t moved = 0;
                        for (std::size_t t = 0; t < e.indices.size(); ++t)
                            moved += welded.vertices[welded.indices[t]] != e.vertices[e.indices[t]];
                        CHECK(moved == 0);
                        CHECK(split.leaf_counts().vertices > split.counts().vertices);
                    } else {
                        e = emit_all(split);
                        CHECK(split.leaf_counts() == split.counts());
                    }
                    std::uint32_t base = 0, first = 0;
                    std::size_t wrong_indices = 0, wrong_points = 0, outside = 0;
                    std::array<std::uint32_t, 3> previous{};
                    split.for_each_leaf([&](const UniformSplit::Leaf& leaf) {
                        const ctess::Counts n = leaf.patch.counts();
                        const auto sorted = leaf.patch.sorted_factors();
                        (sorted == previous ? repeated : changed) += 1;
                        previous = sorted;
                        if (std::size_t{base} + n.vertices > e.vertices.size() ||
                            std::size_t{first} + n.index_count() > e.indices.size()) {
                            ++outside;
                            return;
                        }
                        for (std::uint32_t p = 0; p < n.triangles; ++p) {
                            const auto t = leaf.patch.triangle(p);
                            for (std::uint32_t c = 0; c < 3; ++c)
                                wrong_indices += e.indices[first + 3 * p + c] != base + t[c];
                        }
                        constexpr std::int64_t one = ctess::uniform::fixed_one;
                        for (std::uint32_t i = 0; i < n.vertices; ++i) {
                            const auto d = leaf.patch.vertex(i);
                            const std::int64_t w = one - d.u - d.v;
                            for (int k = 0; k < 2; ++k) {
                                const std::int64_t sum = w * leaf.corners[0][k] +
                                                         std::int64_t{d.u} * leaf.corners[1][k] +
                                                         std::int64_t{d.v} * leaf.corners[2][k];
                                const std::int64_t got =
                                    k == 0 ? e.vertices[base + i].u : e.vertices[base + i].v;
                                wrong_points += leaf.depth <= 1
                                                    ? sum % one != 0 || got != sum / one
                                                    : got * one - sum > one / 2 || sum - got * one > one / 2;
                            }
                        }
                        base += n.vertices, first += n.index_count();
                    });
                    CHECK(outside == 0);
                    CHECK(wrong_indices == 0);
                    CHECK(wrong_points == 0);
                    CHECK(base == e.vertices.size());
                    CHECK(first == e.indices.size());
                }
    // Both paths ran: leaves that repeat the last one's pattern and leaves that change it.
    CHECK(repeated > 500);
    CHECK(changed > 100);
}

TEST_CASE("uniform split: below the table it is the plain patch, scaled", "[uniform][split]") {
    const auto& set = ctess::rt::uniform_tables_16;
    const UniformSplit s(set, 11, 9, 6);
    const ctess::rt::UniformPatch p(set, 11, 9, 6);
    REQUIRE(s.subpatch_count() == 1);
    REQUIRE(s.depth() == 0);
    REQUIRE(s.counts() == p.counts());
    const auto e = emit_all(s);
    for (std::uint32_t i = 0; i < p.counts().vertices; ++i) {
        REQUIRE(e.vertices[i] == ctess::exact_convert<ctess::units::split>(p.vertex(i)));
    }
}

TEST_CASE("uniform split bad input: clamps, bounded output, emit refuses small spans",
          "[uniform][split][bad_input]") {
    const auto& set = ctess::rt::uniform_tables_11;
    constexpr float nan_f = std::numeric_limits<float>::quiet_NaN();
    constexpr float inf_f = std::numeric_limits<float>::infinity();
    for (float f : {nan_f, -inf_f, -1.0f, 0.0f, 1.4f}) {
        const UniformSplit s(set, f, f, f);
        CHECK(s.counts() == ctess::Counts{3, 1});
    }
    for (float f : {121.0f, 1331.0f}) {
        const UniformSplit s(set, f, f, f);
        CHECK(s.factors()[0] == double(f));
        CHECK(s.counts().triangles == std::uint32_t(f * f)); // regular grids of regular grids
        CHECK(s.depth() == (f == 121.0f ? 1u : 2u));
    }
    for (float f : {inf_f, 1e30f, 32768.4f}) { // clamped to uniform_split_max_factor (counted, not emitted)
        const UniformSplit s(set, f, 1, 1);
        CHECK(s.factors() == std::array<double, 3>{32768, 1, 1});
        CHECK(s.depth_limit() == 4); // N = 11: 11^5 >= 32768 > 11^4
    }
    const UniformSplit s(set, 50, 40, 30);
    std::vector<SplitPoint> v(s.counts().vertices - 1, SplitPoint{7, 7});
    std::vector<std::uint32_t> idx(s.counts().index_count(), 7u);
    CHECK_FALSE(s.emit(v, idx));
    CHECK(std::all_of(v.begin(), v.end(), [](SplitPoint d) { return d == SplitPoint{7, 7}; }));
}

namespace {

// The largest ratio of squared lengths |d|_f^2 / |d|_r^2 over all directions d (the largest generalized
// eigenvalue of the two metrics' 2 x 2 matrices in (du, dv); docs/algorithm.md §3.1's formula gives
// [[f0^2, h], [h, f2^2]], h = (f0^2 + f2^2 - f1^2) / 2). r must be a real triangle.
double stretch_squared(const std::array<double, 3>& f, const std::array<double, 3>& r) {
    auto gram = [](const std::array<double, 3>& x) {
        return std::array<double, 3>{x[0] * x[0], (x[0] * x[0] + x[2] * x[2] - x[1] * x[1]) / 2, x[2] * x[2]};
    };
    const auto a = gram(f), b = gram(r);
    const double det_a = a[0] * a[2] - a[1] * a[1], det_b = b[0] * b[2] - b[1] * b[1];
    const double t = a[0] * b[2] + a[2] * b[0] - 2 * a[1] * b[1];
    return (t + std::sqrt(std::max(0.0, t * t - 4 * det_a * det_b))) / (2 * det_b);
}

std::array<double, 3> rounded(const std::array<double, 3>& f, double n) {
    std::array<double, 3> r{};
    for (int i = 0; i < 3; ++i) r[i] = std::clamp(std::floor(f[i] + 0.5), 1.0, n);
    return r;
}

} // namespace

TEST_CASE("uniform split: final edge lengths against the table's own bound, default and strict tolerance",
          "[uniform][split][tolerance]") {
    // In the root's metric a leaf's edges are the table pattern's for its rounded factors r, measured with
    // its real factors f (§3.5): each is at most sqrt(stretch(f, r)) times the pattern's own longest edge (at
    // most 1.4328, §3.1) when r is a real triangle, and unbounded by the table when it is not. The strict
    // tolerance dices no leaf edge above N (+ 0.5 rounding) except where depth 2 clamps; the default dices up
    // to 1.433 N.
    const auto cases = with_random({{40, 30, 25},
                                    {48, 20, 33},
                                    {70, 197, 186},
                                    {176, 176, 176},
                                    {100, 90, 60},
                                    {17, 16, 16},
                                    {64, 64, 20},
                                    {56, 36, 23}},
                                   77, 40, 12, 245);
    const double one = ctess::rt::uniform_split_fixed_one;
    for (const auto* set : {&ctess::rt::uniform_tables_11, &ctess::rt::uniform_tables_16})
        for (const double tolerance : tolerances) {
            const double n = set->max_factor;
            std::size_t leaves = 0, bounded = 0, above_n = 0, clamped = 0;
            for (const auto& f : cases) {
                const UniformSplit s(*set, f[0], f[1], f[2], {}, tolerance);
                const auto root = s.factors();
                if (!ctess::uniform::is_real_triangle(root)) continue;
                INFO("N " << n << " tolerance " << tolerance << " factors " << f[0] << "," << f[1] << ","
                          << f[2]);
                s.for_each_leaf([&](const UniformSplit::Leaf& leaf) {
                    ++leaves;
                    const double largest = std::max({leaf.factors[0], leaf.factors[1], leaf.factors[2]});
                    above_n += largest >= n + 0.5;
                    clamped += largest >= n + 0.5 && leaf.depth == s.depth_limit();
                    if (tolerance == ctess::rt::uniform_split_strict_tolerance && leaf.depth < 2)
                        REQUIRE(largest < n + 0.5);
                    const auto r = rounded(leaf.factors, n);
                    if (!ctess::uniform::is_real_triangle(r)) return;
                    ++bounded;
                    const double stretch = std::sqrt(stretch_squared(leaf.factors, r));
                    double pattern_longest = 0, root_longest = 0;
                    for (std::uint32_t t = 0; t < leaf.patch.counts().triangles; ++t) {
                        const auto tri = leaf.patch.triangle(t);
                        for (int e = 0; e < 3; ++e) {
                            const ctess::uniform::Point a = leaf.patch.vertex(tri[e]),
                                                        b = leaf.patch.vertex(tri[(e + 1) % 3]);
                            const double du = (double(b.u) - a.u) / ctess::uniform::fixed_one,
                                         dv = (double(b.v) - a.v) / ctess::uniform::fixed_one;
                            pattern_longest =
                                std::max(pattern_longest, ctess::uniform::intrinsic_length(r, du, dv));
                            // The same edge on the root: corners combined exactly, measured with the root's
                            // factors.
                            double root_d[2];
                            for (int k = 0; k < 2; ++k)
                                root_d[k] = (du * double(leaf.corners[1][k] - leaf.corners[0][k]) +
                                             dv * double(leaf.corners[2][k] - leaf.corners[0][k])) /
                                            one;
                            root_longest = std::max(
                                root_longest, ctess::uniform::intrinsic_length(root, root_d[0], root_d[1]));
                        }
                    }
                    CHECK(pattern_longest <= 1.4328);
                    CHECK(root_longest <= stretch * pattern_longest * (1 + 1e-6));
                });
            }
            INFO("N " << n << " tolerance " << tolerance);
            CHECK(bounded * 10 > leaves * 9); // almost every leaf's rounded triple is a real triangle
            if (tolerance == ctess::rt::uniform_split_strict_tolerance)
                CHECK(above_n == clamped); // only the depth-2 clamp dices above N
            else
                CHECK(above_n > clamped); // the default dices interior edges above N at depth 1
        }
}

TEST_CASE("uniform split: a diced patch beside a split patch welds bit for bit on their shared edge",
          "[uniform][split][tolerance]") {
    // Patch A (P0, P1, P2) stays within N after rounding and dices with UniformPatch; patch B splits because
    // of another edge and shares A's e1 (P1 -> P2) as its e0, walked P2 -> P1 (B = (P2, P1, Q)) or P1 -> P2
    // (B = (P1, P2, Q), the other orientation). The edge's points, as exact positions on common integer
    // corners, must be the same set from both sides.
    std::size_t checked = 0;
    for (const auto* set : {&ctess::rt::uniform_tables_11, &ctess::rt::uniform_tables_16})
        for (const double tolerance : tolerances) {
            const float n = float(set->max_factor);
            for (const float shared : {1.0f, 5.0f, n - 1, n, n + 0.4f})
                for (const std::array<float, 2> other : {std::array<float, 2>{n + 1, 2 * n},
                                                         {3 * n + 0.6f, n * n},
                                                         {n * n, 1},
                                                         {2.5f * n, n + 0.5f}})
                    for (const bool reversed : {true, false}) {
                        INFO("N " << n << " tolerance " << tolerance << " shared " << shared << " other "
                                  << other[0] << "," << other[1] << (reversed ? " reversed" : " forward"));
                        const UniformSplit a(*set, n / 2, shared, n - 2, {}, tolerance);
                        const UniformSplit b(*set, shared, other[0], other[1], {}, tolerance);
                        REQUIRE(a.depth() == 0);
                        REQUIRE(a.subpatch_count() == 1);
                        REQUIRE(b.depth() >= 1);
                        const auto ea = emit_all(a), eb = emit_all(b);
                        std::set<Pos> on_a, on_b;
                        for (const SplitPoint& d : ea.vertices)
                            if (std::uint64_t{d.u} + d.v == ctess::rt::uniform_split_fixed_one)
                                on_a.insert(position(d, P0, P1, P2));
                        for (const SplitPoint& d : eb.vertices)
                            if (d.v == 0)
                                on_b.insert(reversed ? position(d, P2, P1, Q) : position(d, P1, P2, Q));
                        REQUIRE(on_a.size() == std::size_t(std::floor(shared + 0.5f)) + 1);
                        REQUIRE(on_a == on_b);
                        ++checked;
                    }
        }
    REQUIRE(checked == 2 * 2 * 5 * 4 * 2);
}

TEST_CASE("uniform split bad input: the interior tolerance is clamped to [1, 1.433]",
          "[uniform][split][tolerance][bad_input]") {
    const auto& set = ctess::rt::uniform_tables_16;
    constexpr double nan_d = std::numeric_limits<double>::quiet_NaN();
    constexpr double inf_d = std::numeric_limits<double>::infinity();
    for (const double t : {nan_d, -inf_d, -1.0, 0.0, 0.5, 1.0})
        CHECK(UniformSplit(set, 40, 30, 25, {}, t).interior_tolerance() == 1.0);
    for (const double t : {1.433, 2.0, 1e300, inf_d})
        CHECK(UniformSplit(set, 40, 30, 25, {}, t).interior_tolerance() == 1.433);
    CHECK(UniformSplit(set, 40, 30, 25, {}, 1.2).interior_tolerance() == 1.2);
    CHECK(UniformSplit(set, 40, 30, 25).interior_tolerance() == 1.433);
}
