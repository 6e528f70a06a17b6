// A consumer of ctess that splits above the table (docs/algorithm.md §3.5), built as a user's project with
// the flags that once made UniformSplit's counts() and emit() disagree (-ffast-math, -ffp-contract=fast; see
// docs/api.md, "Crack-free evaluation"). An icosahedron and its once-subdivided mesh get per-edge factors
// 17..256 (integers, hundredths and halves, so neighbouring patches differ); every patch sizes exact buffers
// from counts() and emits in both layouts. Checked without a sanitizer: guard zones around each span stay
// untouched, every slot of each span is written, every index is below counts().vertices, the shared layout
// has no position twice, both layouts put the same points on each edge, and the two patches of every mesh
// edge put the same exact edge parameters on it. The same for N = 11 (factors 12..121). Exit 0 when all hold.
#include <ctess/runtime/uniform.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <map>
#include <set>
#include <span>
#include <utility>
#include <vector>

namespace {

using ctess::Layout;
using ctess::PatchOptions;
using ctess::Winding;
using ctess::rt::UniformSplit;
using ctess::rt::UniformTableSet;
using Point = UniformSplit::point_type;

constexpr std::uint64_t one = ctess::rt::uniform_split_fixed_one;

struct Mesh {
    std::uint32_t vertex_count = 0;
    std::vector<std::array<std::uint32_t, 3>> faces; // counter-clockwise
};

Mesh icosahedron() {
    return {12, {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}}};
}

// Each face split in four at its edges' midpoints (one new vertex per edge).
Mesh subdivided(const Mesh& m) {
    Mesh out{m.vertex_count, {}};
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
        const std::pair<std::uint32_t, std::uint32_t> key{a < b ? a : b, a < b ? b : a};
        return mid.emplace(key, mid.size() + m.vertex_count).first->second;
    };
    for (const auto& f : m.faces) {
        const std::uint32_t ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
        out.faces.push_back({f[0], ab, ca});
        out.faces.push_back({f[1], bc, ab});
        out.faces.push_back({f[2], ca, bc});
        out.faces.push_back({ab, bc, ca});
    }
    out.vertex_count = m.vertex_count + static_cast<std::uint32_t>(mid.size());
    return out;
}

// A mesh edge's factor in [lo, hi] from its endpoints in index order (both faces get the same float): an
// integer, a multiple of 1/100 or a half (the rounding boundary), by `round`.
float edge_factor(std::uint32_t a, std::uint32_t b, std::uint32_t round, std::uint32_t lo, std::uint32_t hi) {
    std::uint32_t h = (a < b ? a : b) * 2654435761u ^ (a < b ? b : a) * 40503u ^ round * 2246822519u;
    h ^= h >> 15, h *= 2246822519u, h ^= h >> 13;
    const std::uint32_t span = hi - lo;
    switch (round % 3) {
    case 0:
        return static_cast<float>(lo + h % (span + 1));
    case 1:
        return static_cast<float>(lo) + static_cast<float>(h % (100 * span + 1)) / 100.0f;
    default:
        return static_cast<float>(lo + h % span) + 0.5f;
    }
}

// An exact-size span inside a buffer with guard zones on both sides, every slot preset to a sentinel.
template <class T>
struct Guarded {
    std::vector<T> storage;
    std::size_t guard, size;
    T sentinel;
    Guarded(std::size_t n, T s) : storage(n + 2 * (n + 4096), s), guard(n + 4096), size(n), sentinel(s) {}
    std::span<T> span() { return {storage.data() + guard, size}; }
    // Whether the guards are untouched and every slot of the span was written.
    bool exact() const {
        for (std::size_t i = 0; i < storage.size(); ++i) {
            const bool inside = i >= guard && i < guard + size;
            if ((storage[i] == sentinel) == inside) return false;
        }
        return true;
    }
};

// The points of the patch on its edge k (from corner k to corner k + 1), as parameters from that corner in
// units of `one`.
std::set<std::uint64_t> edge_points(std::span<const Point> points, int k) {
    std::set<std::uint64_t> out;
    for (const Point& p : points) {
        const std::uint64_t u = p.u, v = p.v;
        if (k == 0 && v == 0) out.insert(u);
        if (k == 1 && u + v == one) out.insert(v);
        if (k == 2 && u == 0) out.insert(one - v);
    }
    return out;
}

struct Checker {
    // A mesh edge (lower, higher vertex) -> its parameters from the lower vertex, as the first face put them.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::set<std::uint64_t>> edges;
    unsigned failures = 0, patches = 0;
    void fail(const char* what, const std::array<float, 3>& f) {
        if (++failures <= 10) std::printf("FAIL: %s (factors %.2f %.2f %.2f)\n", what, f[0], f[1], f[2]);
    }

    // Emits one patch in `layout` into exact guarded spans; false on any bounds failure.
    bool emit(const UniformSplit& split, const std::array<float, 3>& f, Layout layout,
              std::vector<Point>& points, std::vector<std::uint32_t>& indices) {
        const ctess::Counts n = split.counts();
        Guarded<Point> p(n.vertices, Point{0xFFFFFFFFu, 0xFFFFFFFFu});
        Guarded<std::uint32_t> i(n.index_count(), 0xFFFFFFFFu);
        if (!split.emit(p.span(), i.span())) return fail("emit refused spans sized by counts()", f), false;
        if (!p.exact() || !i.exact()) return fail("emit wrote outside its spans or left a slot", f), false;
        points.assign(p.span().begin(), p.span().end());
        indices.assign(i.span().begin(), i.span().end());
        for (const std::uint32_t x : indices)
            if (x >= n.vertices) return fail("an index past counts().vertices", f), false;
        if (layout == Layout::shared) {
            std::vector<std::pair<std::uint32_t, std::uint32_t>> seen;
            for (const Point& q : points) seen.emplace_back(q.u, q.v);
            std::sort(seen.begin(), seen.end());
            if (std::adjacent_find(seen.begin(), seen.end()) != seen.end())
                return fail("a position twice in the shared layout", f), false;
        }
        return true;
    }

    void patch(const UniformTableSet& tables, const std::array<std::uint32_t, 3>& w,
               const std::array<float, 3>& f, double tolerance) {
        ++patches;
        std::array<std::set<std::uint64_t>, 3> by_layout[2];
        int l = 0;
        for (const Layout layout : {Layout::provoking, Layout::shared}) {
            const UniformSplit split(tables, f[0], f[1], f[2], PatchOptions{layout, Winding::ccw}, tolerance);
            std::vector<Point> points;
            std::vector<std::uint32_t> indices;
            if (!emit(split, f, layout, points, indices)) return;
            for (int k = 0; k < 3; ++k) by_layout[l][k] = edge_points(points, k);
            ++l;
        }
        if (by_layout[0] != by_layout[1]) return fail("the two layouts put different points on an edge", f);
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = w[k], b = w[(k + 1) % 3];
            std::set<std::uint64_t> oriented; // parameters from the lower mesh vertex
            for (const std::uint64_t t : by_layout[0][k]) oriented.insert(a < b ? t : one - t);
            const auto [it, first] = edges.emplace(std::make_pair(a < b ? a : b, a < b ? b : a), oriented);
            if (!first && it->second != oriented) fail("two patches put different points on their edge", f);
        }
    }
};

unsigned run(const UniformTableSet& tables, const Mesh& mesh, std::uint32_t rounds, double tolerance) {
    const std::uint32_t n = tables.max_factor;
    unsigned failures = 0;
    for (std::uint32_t round = 0; round < rounds; ++round) {
        Checker c;
        for (const auto& w : mesh.faces) {
            std::array<float, 3> f{};
            for (int k = 0; k < 3; ++k) f[k] = edge_factor(w[k], w[(k + 1) % 3], round, n + 1, n * n);
            c.patch(tables, w, f, tolerance);
        }
        failures += c.failures;
    }
    return failures;
}

} // namespace

int main() {
    const Mesh ico = icosahedron(), fine = subdivided(ico);
    unsigned failures = 0;
    for (const double tolerance :
         {ctess::rt::uniform_split_interior_tolerance, ctess::rt::uniform_split_strict_tolerance}) {
        failures += run(ctess::rt::uniform_tables_16, ico, 24, tolerance);
        failures += run(ctess::rt::uniform_tables_16, fine, 3, tolerance);
        failures += run(ctess::rt::uniform_tables_11, ico, 12, tolerance);
    }
    std::printf("%s: %u failures\n", failures == 0 ? "ok" : "FAILED", failures);
    return failures == 0 ? 0 : 1;
}
