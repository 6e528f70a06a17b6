// UniformSplit at factors up to uniform_split_max_factor = 32768 (docs/algorithm.md §3.5, "Deeper splits"):
// a closed octahedron of split patches, emitted whole, welds into a closed surface; at 32768 the patches of
// every shared edge put the same points on it (edge_points, without emitting a billion triangles each);
// counts() is what emit() writes at every depth; the emitted root-edge points are edge_points(); the
// conversion to the pipeline's 2^-24 base weights is exact round-to-nearest and keeps edge e1 closed.
#include <ctess/analysis/signed_area.hpp>
#include <ctess/runtime/uniform/pipeline_words.hpp>
#include <ctess/runtime/uniform/split.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

#include <catch2/catch.hpp>

#include "support/emit_all.hpp"

namespace {

using ctess::Layout;
using ctess::PatchOptions;
using ctess::Winding;
using ctess::analysis::int128;
using ctess::rt::UniformSplit;
using ctess::uniform::SplitPoint;
constexpr std::uint64_t one = ctess::rt::uniform_split_fixed_one;

std::vector<SplitPoint> edge_points(const UniformSplit& s, std::uint32_t k) {
    std::vector<SplitPoint> out(s.edge_point_count(k));
    REQUIRE(s.edge_points(k, out));
    return out;
}

// --- A closed octahedron of split patches: corners are the unit axes, so every point is exact in 3D. ---
using P3 = std::array<std::int64_t, 3>;
struct Face {
    std::array<int, 3> corner; // octahedron vertex ids, counter-clockwise seen from outside
};
P3 axis(int id) { // 0: +x, 1: -x, 2: +y, 3: -y, 4: +z, 5: -z
    P3 p{0, 0, 0};
    p[static_cast<std::size_t>(id / 2)] = id % 2 == 0 ? 1 : -1;
    return p;
}
std::array<Face, 8> octahedron() {
    std::array<Face, 8> faces{};
    int k = 0;
    for (int x : {0, 1})
        for (int y : {2, 3})
            for (int z : {4, 5}) {
                const bool positive = ((x % 2) + (y % 2) + (z % 2)) % 2 == 0; // sign product +1
                faces[static_cast<std::size_t>(k++)] = positive ? Face{{x, y, z}} : Face{{x, z, y}};
            }
    return faces;
}
// The point (u, v) of a face in 3D, in units of 65534^2: w A + u B + v C, exact.
P3 in_space(const Face& f, SplitPoint p) {
    const std::int64_t w = std::int64_t(one) - p.u - p.v;
    const P3 a = axis(f.corner[0]), b = axis(f.corner[1]), c = axis(f.corner[2]);
    return {w * a[0] + p.u * b[0] + p.v * c[0], w * a[1] + p.u * b[1] + p.v * c[1],
            w * a[2] + p.u * b[2] + p.v * c[2]};
}
// Face edge k's octahedron vertices in the edge's own order (e0: v0 -> v1, e1: v1 -> v2, e2: v0 -> v2).
std::array<int, 2> face_edge(const Face& f, std::uint32_t k) {
    return k == 0   ? std::array<int, 2>{f.corner[0], f.corner[1]}
           : k == 1 ? std::array<int, 2>{f.corner[1], f.corner[2]}
                    : std::array<int, 2>{f.corner[0], f.corner[2]};
}
// A factor per octahedron edge, from the edge alone (its unordered vertex pair): what a mesh would do.
using EdgeFactor = float (*)(int lo, int hi);
std::array<float, 3> face_factors(const Face& f, EdgeFactor factor) {
    std::array<float, 3> r{};
    for (std::uint32_t k = 0; k < 3; ++k) {
        const auto e = face_edge(f, k);
        r[k] = factor(std::min(e[0], e[1]), std::max(e[0], e[1]));
    }
    return r;
}
std::array<UniformSplit, 8> split_faces(const ctess::rt::UniformTableSet& set, EdgeFactor factor,
                                        Layout layout, double tolerance) {
    const auto faces = octahedron();
    auto make = [&](std::size_t i) {
        const auto f = face_factors(faces[i], factor);
        return UniformSplit(set, f[0], f[1], f[2], PatchOptions{layout, Winding::ccw}, tolerance);
    };
    return {make(0), make(1), make(2), make(3), make(4), make(5), make(6), make(7)};
}

// Every octahedron edge's points from both of its faces, in 3D, in the order from its lower vertex.
void check_shared_edges(const std::array<UniformSplit, 8>& splits) {
    const auto faces = octahedron();
    std::map<std::array<int, 2>, std::vector<std::vector<P3>>> seen;
    for (std::size_t i = 0; i < faces.size(); ++i)
        for (std::uint32_t k = 0; k < 3; ++k) {
            const auto e = face_edge(faces[i], k);
            std::vector<P3> points;
            for (const SplitPoint& p : edge_points(splits[i], k)) points.push_back(in_space(faces[i], p));
            if (e[0] > e[1]) std::reverse(points.begin(), points.end());
            seen[{std::min(e[0], e[1]), std::max(e[0], e[1])}].push_back(points);
        }
    REQUIRE(seen.size() == 12);
    for (const auto& [edge, sides] : seen) {
        INFO("octahedron edge " << edge[0] << "-" << edge[1]);
        REQUIRE(sides.size() == 2);
        CHECK(sides[0].size() > 1);
        CHECK(sides[0] == sides[1]); // bit for bit
        const P3 start = axis(edge[0]);
        CHECK(sides[0].front() ==
              P3{start[0] * std::int64_t(one), start[1] * std::int64_t(one), start[2] * std::int64_t(one)});
    }
}

} // namespace

namespace {
float factor_near_1000(int lo, int hi) {
    return float(600 + ((lo * 7 + hi * 13) % 11) * 31);
}
float factor_near_300(int lo, int hi) {
    return float(150.4 + ((lo * 5 + hi * 3) % 7) * 23);
}
float factor_near_32768(int lo, int hi) {
    constexpr float f[] = {32768, 32767, 31000.5f, 30000, 28673, 29999.4f, 32768, 32000, 30517, 31999, 28000};
    return f[(lo * 3 + hi * 5) % 11];
}
} // namespace

TEST_CASE("uniform split deep (§3.5): a closed octahedron at factors near 1,000 welds closed",
          "[uniform][split][deep]") {
    struct Config {
        const ctess::rt::UniformTableSet* set;
        double tolerance;
        EdgeFactor factor;
    };
    for (const Config& c : {Config{&ctess::rt::uniform_tables_16, ctess::rt::uniform_split_interior_tolerance,
                                   factor_near_1000},
                            Config{&ctess::rt::uniform_tables_11, ctess::rt::uniform_split_strict_tolerance,
                                   factor_near_300}}) {
        INFO("N " << c.set->max_factor << " tolerance " << c.tolerance);
        const auto faces = octahedron();
        const auto splits = split_faces(*c.set, c.factor, Layout::shared, c.tolerance);
        check_shared_edges(splits);
        // Each face emitted whole: inside it every edge is used once in each direction; the edges used once
        // are its boundary, and every one of them is used once the other way by the neighbouring face.
        std::map<std::array<P3, 2>, int> boundary; // directed boundary edges in 3D
        std::uint64_t triangles = 0, deeper = 0;
        for (std::size_t i = 0; i < faces.size(); ++i) {
            const UniformSplit& s = splits[i];
            deeper += s.depth() >= 2;
            const auto e = ctess::test::emit_all(s);
            triangles += s.counts().triangles;
            std::vector<std::uint64_t> half;
            half.reserve(e.indices.size());
            for (std::size_t t = 0; t < e.indices.size(); t += 3)
                for (int k = 0; k < 3; ++k)
                    half.push_back(std::uint64_t{e.indices[t + k]} << 32 | e.indices[t + (k + 1) % 3]);
            std::sort(half.begin(), half.end());
            REQUIRE(std::adjacent_find(half.begin(), half.end()) == half.end()); // no half-edge twice
            std::uint64_t own = 0;
            for (const std::uint64_t h : half) {
                const std::uint64_t twin = (h << 32) | (h >> 32);
                if (std::binary_search(half.begin(), half.end(), twin)) continue;
                ++own;
                const P3 a = in_space(faces[i], e.vertices[h >> 32]),
                         b = in_space(faces[i], e.vertices[h & 0xFFFFFFFFu]);
                REQUIRE(++boundary[{a, b}] == 1);
            }
            std::uint64_t segments = 0;
            for (std::uint32_t k = 0; k < 3; ++k) segments += s.edge_point_count(k) - 1;
            CHECK(own == segments); // the boundary is exactly the three root edges' segments
        }
        CHECK(deeper > 0); // depth 2 at least (the limit is 3)
        CHECK(triangles > 20000);
        for (const auto& [edge, count] : boundary) REQUIRE(boundary.count({edge[1], edge[0]}) == 1);
    }
}

TEST_CASE("uniform split deep (§3.5): at 32768 every shared edge agrees, counts within the closed form",
          "[uniform][split][deep]") {
    const auto& set = ctess::rt::uniform_tables_16;
    const auto faces = octahedron();
    const auto splits =
        split_faces(set, factor_near_32768, Layout::provoking, ctess::rt::uniform_split_interior_tolerance);
    check_shared_edges(splits);
    // Triangles per unit of intrinsic area A (Heron on the factors): the regular grid of unit edges has
    // 4 / sqrt(3) = 2.309. Upper bound: no table pattern is denser than the grid of its largest factor, and
    // the leaves here have factors near 8 (32768 / 16^3), whose rounding by at most 0.5 scales a leaf's
    // area by at most (8.5 / 8)^2 = 1.13; 1.2 x 2.309 = 2.77. Lower bound: every output edge is at most
    // 2.2 in the root's metric (§3.5 measures 2.10 at N^2), so every triangle's area is at most
    // sqrt(3) / 4 x 2.2^2 = 2.10 and there are at least A / 2.10 = 0.476 A triangles.
    for (std::size_t i = 0; i < faces.size(); ++i) {
        const auto r = splits[i].factors();
        const double p = (r[0] + r[1] + r[2]) / 2, area = std::sqrt(p * (p - r[0]) * (p - r[1]) * (p - r[2]));
        const double t = splits[i].counts().triangles;
        INFO("face " << i << " factors " << r[0] << "," << r[1] << "," << r[2] << " triangles " << t);
        CHECK(splits[i].depth() == 3);
        CHECK(t >= 0.476 * area);
        CHECK(t <= 2.77 * area);
        CHECK(splits[i].counts().vertices >= t); // provoking: at least one first vertex per triangle
    }
    // The regular case in closed form: 32768 = 16 x 16 x 16 x 8 at N = 16, regular grids of regular grids.
    const UniformSplit grid(set, 32768, 32768, 32768);
    CHECK(grid.counts().triangles == 32768u * 32768u);
    CHECK(grid.depth() == 3);
    CHECK(grid.subpatch_count() == 256u * 256 * 64); // 16, 16, 8 pieces per edge, then 16-grids
}

TEST_CASE("uniform split deep (§3.5): neighbours with different depth limits agree on their edge",
          "[uniform][split][deep]") {
    // A patch's depth limit comes from its largest factor; an edge of factor T is whole from depth
    // levels(T) on, which both limits reach: the same points whatever the other factors.
    for (const auto* set : {&ctess::rt::uniform_tables_11, &ctess::rt::uniform_tables_16}) {
        const std::uint32_t n = set->max_factor;
        for (const float shared : {1.0f, 16.0f, 17.0f, 121.0f, 122.0f, 256.0f, 257.0f, 1331.0f, 1332.0f,
                                   2000.5f, 4096.0f, 4097.0f, 14641.0f, 14642.0f, 32767.0f, 32768.0f}) {
            const UniformSplit low(*set, shared, 3, shared); // its own limit
            const UniformSplit high(*set, 32768, shared, 1); // the deepest limit (thin: cheap to count)
            INFO("N " << n << " shared " << shared << " limits " << low.depth_limit() << " "
                      << high.depth_limit());
            CHECK(high.depth_limit() == ctess::rt::uniform_split_depth_bound(n));
            // low's e0 (v0 -> v1) glued to high's e1 (v1 -> v2) either way round: the parameters along
            // the edge agree from either end (low's u against high's v, or reversed, high's u).
            const auto a = edge_points(low, 0), b = edge_points(high, 1);
            REQUIRE(a.size() == b.size());
            for (std::size_t i = 0; i < a.size(); ++i) {
                const SplitPoint r = b[b.size() - 1 - i];
                REQUIRE(a[i].v == 0);
                REQUIRE(std::uint64_t{b[i].u} + b[i].v == one); // on e1 exactly
                REQUIRE(a[i].u == b[i].v);
                REQUIRE(a[i].u == r.u);
            }
        }
    }
}

TEST_CASE("uniform split deep (§3.5): counts() is what emit() writes, and emitted root edges are edge_points",
          "[uniform][split][deep]") {
    std::uint32_t state = 19u;
    auto next = [&](std::uint32_t m) { return ((state = state * 1664525u + 1013904223u) >> 8) % m; };
    std::vector<std::array<float, 3>> cases;
    // A grid over the depth boundaries of both tables, and random triples up to 4096 (kept to thin or
    // small patches: at most about 2^21 triangles are emitted).
    const float grid[] = {1, 11, 12, 16, 17, 121, 122, 256, 257, 1331, 1332, 4096};
    for (float a : grid)
        for (float b : grid)
            for (float c : {1.0f, 2.0f, 15.5f, 300.0f})
                if (a * c < 2e5f && b * c < 2e5f) cases.push_back({a, b, c});
    for (int k = 0; k < 24; ++k) {
        const float big = float(1 + next(4096)), small = float(1 + next(k % 2 == 0 ? 64 : 512));
        const float mid = float(1 + next(static_cast<std::uint32_t>(big)));
        cases.push_back(k % 3 == 0 ? std::array<float, 3>{big, small, mid}
                                   : std::array<float, 3>{mid, big, small});
    }
    std::array<std::uint64_t, 5> by_depth{};
    for (const auto* set : {&ctess::rt::uniform_tables_11, &ctess::rt::uniform_tables_16})
        for (const Layout layout : {Layout::shared, Layout::provoking})
            for (const auto& f : cases) {
                const UniformSplit s(*set, f[0], f[1], f[2], PatchOptions{layout, Winding::ccw});
                if (s.counts().triangles > (1u << 18)) continue;
                INFO("N " << set->max_factor << " factors " << f[0] << "," << f[1] << "," << f[2]
                          << (layout == Layout::shared ? " shared" : " provoking"));
                ++by_depth[s.depth()];
                // Independent of emit(): the leaves' own counts (the provoking layout keeps them all).
                std::uint64_t leaf_triangles = 0, leaf_vertices = 0;
                s.for_each_leaf([&](const UniformSplit::Leaf& leaf) {
                    leaf_triangles += leaf.patch.counts().triangles;
                    leaf_vertices += leaf.patch.counts().vertices;
                    REQUIRE(leaf.depth <= s.depth_limit());
                });
                REQUIRE(leaf_triangles == s.counts().triangles);
                if (layout == Layout::provoking) REQUIRE(leaf_vertices == s.counts().vertices);
                // emit() with spans one longer than counts(): it must write exactly counts(), never more.
                std::vector<SplitPoint> v(s.counts().vertices + 1, SplitPoint{7, 7});
                std::vector<std::uint32_t> idx(s.counts().index_count() + 1, 7u);
                REQUIRE(s.emit(v, idx));
                REQUIRE(v.back() == (SplitPoint{7, 7}));
                REQUIRE(idx.back() == 7u);
                v.pop_back(), idx.pop_back();
                int128 area = 0;
                for (std::size_t t = 0; t < idx.size(); t += 3) {
                    REQUIRE(std::max({idx[t], idx[t + 1], idx[t + 2]}) < v.size());
                    const SplitPoint a = v[idx[t]], b = v[idx[t + 1]], c = v[idx[t + 2]];
                    const int128 cross = int128(std::int64_t(b.u) - a.u) * (std::int64_t(c.v) - a.v) -
                                         int128(std::int64_t(b.v) - a.v) * (std::int64_t(c.u) - a.u);
                    REQUIRE(cross > 0);
                    area += cross;
                }
                REQUIRE(area == int128(one) * int128(one)); // the triangles cover the patch exactly
                // The emitted points on each root edge, in the edge's order, are edge_points().
                std::array<std::vector<SplitPoint>, 3> on{};
                for (const SplitPoint& p : v) {
                    if (p.v == 0) on[0].push_back(p);
                    if (std::uint64_t{p.u} + p.v == one) on[1].push_back(p);
                    if (p.u == 0) on[2].push_back(p);
                }
                auto by = [](bool along_v) {
                    return [along_v](SplitPoint a, SplitPoint b) { return along_v ? a.v < b.v : a.u < b.u; };
                };
                std::sort(on[0].begin(), on[0].end(), by(false));
                std::sort(on[1].begin(), on[1].end(), by(true));
                std::sort(on[2].begin(), on[2].end(), by(true));
                if (layout == Layout::provoking) // subpatches repeat their shared points: one of each
                    for (auto& side : on) side.erase(std::unique(side.begin(), side.end()), side.end());
                for (std::uint32_t k = 0; k < 3; ++k) REQUIRE(on[k] == edge_points(s, k));
            }
    CHECK(by_depth[2] > 0);
    CHECK(by_depth[3] > 0);
    CHECK(by_depth[4] > 0); // N = 11 reaches its bound
}

TEST_CASE("uniform split deep: edge_points count then fill, bad edges and short spans",
          "[uniform][split][deep][bad_input]") {
    const UniformSplit s(ctess::rt::uniform_tables_16, 5000, 3, 4998);
    CHECK(s.edge_point_count(3) == 0);
    CHECK(s.edge_point_count(1) == 4); // 3 segments
    std::vector<SplitPoint> out(s.edge_point_count(0) - 1, SplitPoint{7, 7});
    CHECK_FALSE(s.edge_points(0, out));
    CHECK(std::all_of(out.begin(), out.end(), [](SplitPoint p) { return p == SplitPoint{7, 7}; }));
    CHECK_FALSE(s.edge_points(7, out));
    const auto e0 = edge_points(s, 0);
    CHECK(e0.front() == (SplitPoint{0, 0}));
    CHECK(e0.back() == (SplitPoint{std::uint32_t(one), 0}));
    CHECK(e0.size() >= 5000 - 16 * 16 / 2); // T segments within P / 2 (P <= 16 x 16 final pieces)
    CHECK(e0.size() <= 5001 + 16 * 16 / 2);
}

TEST_CASE("uniform split deep: to_base_weights rounds to nearest, agrees with UniformPatch, closes e1",
          "[uniform][split][deep]") {
    using ctess::rt::to_base_weights;
    constexpr std::uint64_t base = 1u << 24;
    // Points of depth 0 and 1 (multiples of 65534) convert as a UniformPatch's points do: every weight.
    for (std::uint32_t w = 0; w <= ctess::uniform::fixed_one; ++w) {
        const auto b = to_base_weights({w * ctess::uniform::fixed_one, 0});
        REQUIRE(b.u == ctess::rt::uniform_weight_to_fixed(w));
        REQUIRE(b.v == 0);
    }
    // Nearest (exact rational comparison), and on e1 (u + v = 65534^2) the weights sum to 2^24: w0 = 0.
    std::uint64_t state = 7, truncation_cracks = 0;
    for (int k = 0; k < 200000; ++k) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        const std::uint32_t u = static_cast<std::uint32_t>((state >> 16) % (one + 1)),
                            v = static_cast<std::uint32_t>(one - u);
        const auto b = to_base_weights({u, v});
        const int128 err = int128(b.u) * int128(one) - int128(u) * int128(base);
        REQUIRE(2 * (err < 0 ? -err : err) < int128(one));
        REQUIRE(std::uint64_t{b.u} + b.v == base);
        truncation_cracks += (std::uint64_t{u} * base / one + std::uint64_t{v} * base / one) != base;
    }
    CHECK(truncation_cracks > 100000); // truncating leaves e1's points off the edge almost always
    CHECK(to_base_weights({0xFFFFFFFFu, 0}).u == base); // above 65534^2: clamped
}

namespace {
// The pieces a root edge of factor t ends in with exact spans (§3.5): split into min(ceil(t / N), N) while
// above N + 0.5.
double final_pieces(double t, double n) {
    if (t < n + 0.5) return 1.0;
    const double k = std::min(std::ceil(std::floor(t + 0.5) / n), n);
    return k * final_pieces(t / k, n);
}
} // namespace

TEST_CASE("uniform split deep (§3.5): a root edge of any factor up to 32768 carries T segments within P / 2",
          "[uniform][split][deep]") {
    // Every final piece rounds on its own (P of them), nothing clamps: a root edge is whole before its
    // patch's depth limit, for every T (sampled every 331, and around each power of N).
    for (const auto* set : {&ctess::rt::uniform_tables_11, &ctess::rt::uniform_tables_16}) {
        const double n = set->max_factor;
        std::vector<std::uint32_t> factors;
        for (std::uint32_t t = 1; t <= 32768; t += 331) factors.push_back(t);
        for (std::uint32_t p = set->max_factor; p <= 32768; p *= set->max_factor)
            for (std::uint32_t t : {p - 1, p, p + 1, 2 * p - 1, 2 * p + 1})
                factors.push_back(std::min(t, 32768u));
        factors.push_back(32768);
        for (const std::uint32_t t : factors) {
            const UniformSplit s(*set, float(t), 1, float(t));
            const double segments = s.edge_point_count(0) - 1.0, p = final_pieces(t, n);
            INFO("N " << n << " T " << t << " segments " << segments << " pieces " << p);
            REQUIRE(std::fabs(segments - t) <= p / 2);
            REQUIRE(s.edge_point_count(2) == s.edge_point_count(0)); // the same factor, the same points
        }
    }
}

// The map of a leaf's points into the root below depth 1 (§3.5; split.hpp, "Output"), written from the rule:
// the exact sum w c0 + u c1 + v c2 over 65534 rounded to nearest, a tie half to even on the root's edges (a
// point lies on root edge j when every corner it weights does) and half up inside. emit() computes it in
// 32-bit pieces with a fallback for ties; this checks every provoking-layout vertex against the rule, on
// patches whose leaves reach depth 2 and 3, where corners are not multiples of 65534 and ties occur.
TEST_CASE(
    "uniform split deep (§3.5): every emitted point below depth 1 is its leaf's point rounded by the rule",
    "[uniform][split][deep]") {
    constexpr std::int64_t unit = ctess::uniform::fixed_one, half = unit / 2;
    auto root_edges = [](const std::array<std::int64_t, 2>& c) {
        return (c[1] == 0 ? 1u : 0u) | (c[0] + c[1] == std::int64_t(one) ? 2u : 0u) | (c[0] == 0 ? 4u : 0u);
    };
    std::uint64_t deep_leaves = 0, ties_on_edges = 0, ties_inside = 0;
    const float cases[][3] = {{300, 300, 300}, {1000, 700, 300}, {5000, 77, 4999}, {257, 3000, 1234.5f}};
    for (const auto& f : cases) {
        for (const Winding winding : {Winding::ccw, Winding::cw}) {
            const UniformSplit s(ctess::rt::uniform_tables_16, f[0], f[1], f[2],
                                 {Layout::provoking, winding});
            REQUIRE(s.depth() >= 2);
            const auto e = ctess::test::emit_all(s);
            std::size_t next = 0;
            s.for_each_leaf([&](const UniformSplit::Leaf& leaf) {
                deep_leaves += leaf.depth >= 2 ? 1u : 0u;
                for (std::uint32_t i = 0; i < leaf.patch.counts().vertices; ++i) {
                    const ctess::uniform::Point d = leaf.patch.vertex(i);
                    const std::int64_t weight[3] = {unit - d.u - d.v, d.u, d.v};
                    std::uint32_t edges = 7;
                    for (int k = 0; k < 3; ++k)
                        if (weight[k] != 0) edges &= root_edges(leaf.corners[static_cast<std::size_t>(k)]);
                    std::int64_t expected[2] = {};
                    for (std::size_t c = 0; c < 2; ++c) {
                        std::int64_t sum = 0;
                        for (std::size_t k = 0; k < 3; ++k) sum += weight[k] * leaf.corners[k][c];
                        const std::int64_t q = sum / unit, r = sum % unit;
                        const bool tie = r == half;
                        ties_on_edges += tie && edges != 0 ? 1u : 0u;
                        ties_inside += tie && edges == 0 ? 1u : 0u;
                        expected[c] = q + (r > half || (tie && (edges == 0 || q % 2 != 0)) ? 1 : 0);
                    }
                    REQUIRE(next < e.vertices.size());
                    INFO("factors " << f[0] << ", " << f[1] << ", " << f[2] << ", vertex " << next);
                    REQUIRE(e.vertices[next].u == static_cast<std::uint32_t>(expected[0]));
                    REQUIRE(e.vertices[next].v == static_cast<std::uint32_t>(expected[1]));
                    ++next;
                }
            });
            REQUIRE(next == e.vertices.size());
        }
    }
    // The cases reach the paths the rule distinguishes: deep leaves, and ties inside and on the root's edges.
    CHECK(deep_leaves > 0);
    CHECK(ties_inside > 0);
    CHECK(ties_on_edges > 0);
}
