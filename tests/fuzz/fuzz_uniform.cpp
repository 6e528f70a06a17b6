// libFuzzer target: the uniform-density runtime (ctess::rt::UniformPatch, UniformSplit) through its public
// API. Input: table set (N = 11 or 16), layout and winding, three factors as float bit patterns, then index
// queries and span sizes. Properties of UniformPatch: emit equals vertex(i) / triangle(p); every index is in
// range; every point lies in the domain; every triangle has the requested orientation and a non-zero area,
// and together they cover the domain exactly (integer areas); edge k carries uniform_factor(f_k) segments;
// out-of-range queries give zeros; a short span writes nothing. UniformSplit (any factor, up to 32768):
// bounded depth, indices in range, points in the domain, exact coverage in units of 65534^2; in the shared
// layout (welded, docs/algorithm.md §3.5) no position twice, V = 1 + (T + B) / 2 and the same triangles
// (position triples, in order) as the provoking layout, whose positions are exactly the shared ones, and the
// leaves' own points (emit_leaves, the pipeline's unwelded layout) as well; a short span writes nothing.
#include <cstdio>
#include <cstdlib>
#include <set>
#include <utility>
#include <vector>

#include <ctess/analysis/signed_area.hpp>
#include <ctess/runtime/uniform/split.hpp>

#include "fuzz_input.hpp"

using namespace ctess;

namespace {

// Indices in range, points in the triangle of side `one`, orientation and exact coverage.
template <class Point>
void check_mesh(const std::vector<Point>& v, const std::vector<std::uint32_t>& idx, std::uint64_t one,
                Winding winding) {
    for (const Point& p : v) CTESS_FUZZ_CHECK(std::uint64_t{p.u} + p.v <= one);
    __int128 total = 0;
    for (std::size_t k = 0; k < idx.size(); k += 3) {
        for (unsigned j = 0; j < 3; ++j) CTESS_FUZZ_CHECK(idx[k + j] < v.size());
        const __int128 a = analysis::signed_area2(v[idx[k]], v[idx[k + 1]], v[idx[k + 2]]);
        CTESS_FUZZ_CHECK(winding == Winding::ccw ? a > 0 : a < 0);
        total += a;
    }
    const __int128 full = __int128(one) * __int128(one);
    CTESS_FUZZ_CHECK(total == (winding == Winding::ccw ? full : -full));
}

// The shared layout of a split patch against the provoking layout of the same factors, welded here.
void check_split_weld(const rt::UniformSplit& split, const std::vector<uniform::SplitPoint>& v,
                      const std::vector<std::uint32_t>& idx, const rt::UniformTableSet& tables,
                      const float* f, Winding winding) {
    using Position = std::pair<std::uint32_t, std::uint32_t>;
    const std::uint64_t one = rt::uniform_split_fixed_one;
    std::set<Position> positions;
    std::uint64_t boundary = 0;
    for (const uniform::SplitPoint& p : v) {
        CTESS_FUZZ_CHECK(positions.insert({p.u, p.v}).second);
        boundary += p.u == 0 || p.v == 0 || std::uint64_t{p.u} + p.v == one;
    }
    CTESS_FUZZ_CHECK(split.counts().vertices == 1 + (split.counts().triangles + boundary) / 2);
    const rt::UniformSplit provoking(tables, f[0], f[1], f[2], PatchOptions{Layout::provoking, winding});
    std::vector<uniform::SplitPoint> pv(provoking.counts().vertices);
    std::vector<std::uint32_t> pi(provoking.counts().index_count());
    CTESS_FUZZ_CHECK(provoking.emit(pv, pi) && pi.size() == idx.size());
    std::set<Position> welded;
    for (std::size_t k = 0; k < pi.size(); ++k) {
        const uniform::SplitPoint a = pv[pi[k]], b = v[idx[k]];
        CTESS_FUZZ_CHECK(a == b);
        welded.insert({a.u, a.v});
    }
    CTESS_FUZZ_CHECK(welded == positions);
    // The leaves' own points: the same triangles, leaf by leaf, at least as many points as the welded patch.
    const Counts leaves = split.leaf_counts();
    CTESS_FUZZ_CHECK(leaves.triangles == split.counts().triangles &&
                     leaves.vertices >= split.counts().vertices);
    std::vector<uniform::SplitPoint> lv(leaves.vertices);
    std::vector<std::uint32_t> li(leaves.index_count());
    CTESS_FUZZ_CHECK(split.emit_leaves(lv, li));
    for (std::size_t k = 0; k < li.size(); ++k) CTESS_FUZZ_CHECK(li[k] < lv.size() && lv[li[k]] == v[idx[k]]);
    lv.pop_back();
    CTESS_FUZZ_CHECK(!split.emit_leaves(lv, li));
    std::vector<uniform::SplitPoint> short_v(v.size() - 1, uniform::SplitPoint{7, 7});
    std::vector<std::uint32_t> short_i(idx.size(), 7u);
    CTESS_FUZZ_CHECK(!split.emit(short_v, short_i));
    for (const uniform::SplitPoint& p : short_v) CTESS_FUZZ_CHECK(p == (uniform::SplitPoint{7, 7}));
    for (const std::uint32_t i : short_i) CTESS_FUZZ_CHECK(i == 7u);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Input in(data, size);
    const std::uint8_t mode = in.byte();
    const rt::UniformTableSet& tables = (mode & 1) ? rt::uniform_tables_16 : rt::uniform_tables_11;
    const PatchOptions options{(mode & 2) ? Layout::provoking : Layout::shared,
                               (mode & 4) ? Winding::cw : Winding::ccw};
    const float f[3] = {in.float_bits(), in.float_bits(), in.float_bits()};

    if (mode & 8) { // split: any factor, rounded and clamped to [1, 32768]
        const rt::UniformSplit split(tables, f[0], f[1], f[2], options);
        CTESS_FUZZ_CHECK(split.depth() <= split.depth_limit());
        CTESS_FUZZ_CHECK(split.depth_limit() <= rt::uniform_split_depth_bound(tables.max_factor));
        const Counts n = split.counts();
        // Up to a billion triangles at 32768: above 2^20 only the root edges' points are checked (their
        // count; docs/algorithm.md §3.5), so that an input stays fast and small.
        if (n.triangles > (1u << 20)) {
            for (std::uint32_t k = 0; k < 3; ++k) {
                std::vector<uniform::SplitPoint> e(split.edge_point_count(k));
                CTESS_FUZZ_CHECK(e.size() >= 2 && split.edge_points(k, e));
            }
            return 0;
        }
        std::vector<uniform::SplitPoint> v(n.vertices);
        std::vector<std::uint32_t> idx(n.index_count());
        CTESS_FUZZ_CHECK(split.emit(v, idx));
        check_mesh(v, idx, rt::uniform_split_fixed_one, options.winding);
        if (options.layout == Layout::shared) check_split_weld(split, v, idx, tables, f, options.winding);
        return 0;
    }

    const rt::UniformPatch patch(tables, f[0], f[1], f[2], options);
    const Counts n = patch.counts();
    std::vector<uniform::Point> v(n.vertices + 1, uniform::Point{7, 7});
    std::vector<std::uint32_t> idx(n.index_count() + 1, 7u);
    CTESS_FUZZ_CHECK(patch.emit(std::span(v.data(), n.vertices), std::span(idx.data(), n.index_count())));
    CTESS_FUZZ_CHECK(v.back() == (uniform::Point{7, 7}) && idx.back() == 7u);
    v.pop_back();
    idx.pop_back();
    for (std::uint32_t i = 0; i < n.vertices; ++i) CTESS_FUZZ_CHECK(patch.vertex(i) == v[i]);
    for (std::uint32_t t = 0; t < n.triangles; ++t) {
        const auto tri = patch.triangle(t);
        for (unsigned k = 0; k < 3; ++k) CTESS_FUZZ_CHECK(tri[k] == idx[3 * t + k]);
    }
    check_mesh(v, idx, uniform::fixed_one, options.winding);

    // Edge k (e0: v = 0, e1: u + v = 1, e2: u = 0) has uniform_factor(f_k) segments: that many + 1 positions.
    std::set<std::pair<std::uint32_t, std::uint32_t>> on_edge[3];
    for (const uniform::Point& p : v) {
        if (p.v == 0) on_edge[0].insert({p.u, p.v});
        if (p.u + p.v == uniform::fixed_one) on_edge[1].insert({p.u, p.v});
        if (p.u == 0) on_edge[2].insert({p.u, p.v});
    }
    for (unsigned k = 0; k < 3; ++k)
        CTESS_FUZZ_CHECK(on_edge[k].size() == rt::uniform_factor(f[k], tables.max_factor) + 1u);

    // Out of range: zeros. A short span: false, nothing written.
    const std::uint32_t far = n.vertices + in.u32() % 1000u;
    CTESS_FUZZ_CHECK(patch.vertex(far) == uniform::Point{});
    const auto none = patch.triangle(n.triangles + in.u32() % 1000u);
    CTESS_FUZZ_CHECK(none[0] == 0 && none[1] == 0 && none[2] == 0);
    std::vector<uniform::Point> short_v(n.vertices - 1, uniform::Point{7, 7});
    std::vector<std::uint32_t> short_i(n.index_count(), 7u);
    CTESS_FUZZ_CHECK(!patch.emit(short_v, short_i));
    for (const uniform::Point& p : short_v) CTESS_FUZZ_CHECK(p == (uniform::Point{7, 7}));
    for (const std::uint32_t i : short_i) CTESS_FUZZ_CHECK(i == 7u);
    return 0;
}
