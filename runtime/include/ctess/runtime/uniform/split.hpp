// Uniform-density splitting above the table (docs/algorithm.md §3.5; Karis 2026, docs/references.md): a patch
// whose factors exceed the table's maximum N is split with the table's own pattern for the split factors, and
// each subpatch is diced (or split once more) with the table.
//
// * Factors: NaN, -inf, zero and negatives give 1; each factor is rounded to the nearest integer (halves up)
//   and clamped to [1, uniform_split_max_factor = 32768] (+inf and huge values give 32768; NVIDIA's
//   vk_tessellated_clusters splits up to the same factor).
// * SplitFactor S = min(ceil(T / N), N) per edge (Karis 2026: min(TessFactor / MaxDiceFactor,
// MaxSplitFactor),
//   rounded up so that each sub-edge's factor T / S is at most N).
// * A subpatch edge's factor is the intrinsic length of that edge in the metric of its parent (the parent's
//   factors as side lengths): on a parent edge that is T_i times the edge's parameter span, i.e. a function
//   of that edge's own factor and position only; inside the parent it is computed from the edge's endpoints
//   in either direction with the same result. Neighbours therefore agree bit for bit at any depth: no cracks.
//   Every factor is kept as its exact square in fixed point (uniform/split_factor.hpp, §3.5 "Exact
//   factors"), so every decision below compares integers, as the shaders' split passes do.
// * How many pieces a split gives an edge is a function of that edge's own factor and depth: an edge within
//   the dice limit (N on the root's boundary at every depth, from its corners; inside the root tolerance x N)
//   stays whole, whole edges keep their factor exactly, and a subpatch is diced when all three of its
//   edges stay whole. So a patch that splits and its neighbour that dices put the same points on their shared
//   edge. The interior tolerance is a constructor argument in [1, 1.433]: 1.433 (the default, the table's own
//   longest edge, §3.1) dices more interior edges whole (fewer subpatches, longer final edges); 1 (strict)
//   dices no interior edge above N. Everything that decides an edge's pieces reads the same value, so both
//   walks (counts, emit) and both sides of an edge agree.
// * Depth: a patch splits down to its depth limit, uniform_split_depth_limit(N, largest root factor): one
//   level more than its largest root edge needs (the smallest d with N^(d+1) >= T; interior edges are up to
//   1.433 times longer), at least 2 (the depth of every patch up to N^2, whose output is unchanged) and at
//   most the table's bound uniform_split_depth_bound(N) (N = 16: 3, N = 11: 4). At the limit factors clamp
//   to N (only an interior edge can still be longer). A root edge of factor T is whole from depth
//   levels(T) <= limit on, in every patch that holds it, so neighbours with other limits still agree.
// * Output: positions in units of fixed_one = 65534^2 on the root patch: exact at depth 0 and 1, rounded
//   below from an exact integer sum of the edge's own endpoints, which is the same on both sides of a shared
//   edge; ties round to even on the root's edges (a neighbour whose coordinate runs the other way gets the
//   same point, and e1 keeps u + v = 65534^2), half up inside (outputs up to N^2 unchanged).
//   to_base_weights() converts them to the mesh pipeline's 2^-24 base weights (round to nearest; no ties
//   exist), so that both sides of a shared edge still agree (truncating does not).
// * edge_points(k, out): the points the patch puts on root edge k, from that edge's data alone, by the same
//   decisions as emit(): what two patches of a shared edge compare without emitting their interiors.
// * Counts: 3T indices and V must fit 32 bits (below the primitive-restart value 2^32 - 1); a patch beyond
//   that (none at N = 11 or 16, tested at 32768^3) would count {0, 0} and emit nothing.
// * Layout::provoking: every subpatch's own vertices, each subpatch followed by its own copies (UniformPatch,
//   §3.4), so every triangle's first index is unique over the whole output.
// * Layout::shared: welded, one vertex per exact position, without scratch memory (§3.5, "The shared
//   layout"). Every point is numbered by the node that owns it: the root's corners and edge points first,
//   then each split node's interior in walk order: its pattern's interior vertices, the points of its
//   pattern's interior edges (each owned by the half-edge that runs from the lower to the higher pattern
//   vertex), then its subpatches' interiors. Subpatches look up the points on their edges from the edge's
//   own data (factor, depth), so both sides of an edge agree. counts().vertices = 1 + (T + B) / 2 (Euler on
//   a disk, B the root's boundary segments). Below N it is UniformPatch's own numbering.
//
// Embedded style: no heap, no exceptions; counts() is computed by one traversal in the constructor, which
// also lists up to 16 leaves; emit() writes a listed patch from that list (the provoking layout, and
// emit_leaves() in both) and otherwise traverses again (docs/algorithm.md §3.5, "Leaf list"). It returns
// false (writing nothing) when a span is shorter than counts(); during its walk it checks every leaf and
// every welded vertex number against the spans too, and returns false rather than write past one. Every
// decision (factor sanitising, the dice limit and an edge's pieces, rounding, child factors, segments, the
// walks, longest_edge) is out of line in runtime/src/uniform/split.cpp, compiled with -ffp-contract=off
// -fno-fast-math (ctess::uniform_core): in header code the constructor's count and emit()'s walk were
// compiled with the caller's flags in different inlining contexts, and under -ffast-math they could decide an
// edge differently (§3.5; docs/api.md, "Crack-free evaluation"). Every walk keeps its split pattern's points
// on the stack per split level (at most uniform_split_max_depth levels) and one leaf-sized buffer; the shared
// layout's emit() also keeps one pattern-sized set of arrays per level: the stack is bounded by depth x the
// largest stored pattern, whatever the factors (measured in docs/algorithm.md §3.5). A leaf that rounds like
// the last one reuses that leaf's pattern output (§3.5, "Leaf reuse"); that state lives in the walk of one
// call, so a UniformSplit (all its methods const) may be used from several threads at once, as before.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <type_traits>

#include <ctess/core/counts.hpp>
#include <ctess/core/domain_point.hpp>
#include <ctess/core/patch_concept.hpp>
#include <ctess/core/patch_options.hpp>
#include <ctess/uniform/metric.hpp>
#include <ctess/uniform/pattern.hpp>
#include <ctess/uniform/split_factor.hpp>

#include "patch.hpp"

namespace ctess::rt {

// The largest factor UniformSplit takes (inputs above clamp to it), as NVIDIA's vk_tessellated_clusters.
inline constexpr std::uint32_t uniform_split_max_factor = 32768;

// The split levels a root edge of factor t needs with table maximum n >= 2: the smallest d with
// n^(d+1) >= t (each level divides an edge into at most n pieces, the last pieces dice at most n).
constexpr std::uint32_t uniform_split_levels(std::uint32_t n, std::uint32_t t) noexcept {
    std::uint64_t reach = n < 2 ? 2 : n;
    std::uint32_t d = 0;
    for (; reach < t; ++d) reach *= n < 2 ? 2 : n;
    return d;
}
// The deepest split of table maximum n: the levels of uniform_split_max_factor.
constexpr std::uint32_t uniform_split_depth_bound(std::uint32_t n) noexcept {
    return uniform_split_levels(n, uniform_split_max_factor);
}
// A patch's depth limit from its largest rounded root factor: one level more than its edges need (for the
// longer interior edges), at least 2, at most the bound (§3.5).
constexpr std::uint32_t uniform_split_depth_limit(std::uint32_t n, std::uint32_t largest) noexcept {
    const std::uint32_t wanted = uniform_split_levels(n, largest) + 1, bound = uniform_split_depth_bound(n);
    const std::uint32_t limit = wanted < bound ? wanted : bound;
    return limit > 2 ? limit : 2;
}
static_assert(uniform_split_depth_bound(16) == 3 && uniform_split_depth_bound(11) == 4);
static_assert(uniform_split_depth_limit(16, 256) == 2 && uniform_split_depth_limit(16, 257) == 3 &&
              uniform_split_depth_limit(16, 32768) == 3 && uniform_split_depth_limit(11, 121) == 2 &&
              uniform_split_depth_limit(11, 122) == 3 && uniform_split_depth_limit(11, 1332) == 4);
// The deepest split of the shipped tables (N = 11): what the stack is sized for.
inline constexpr std::uint32_t uniform_split_max_depth = uniform_split_depth_bound(11);
// Edges inside the root patch dice at N up to this factor / N by default: the table's own longest edge
// (§3.1). The strict tolerance dices no interior edge above N (§3.5, the trade-off table).
inline constexpr double uniform_split_interior_tolerance = 1.433;
inline constexpr double uniform_split_strict_tolerance = 1.0;
inline constexpr std::uint32_t uniform_split_fixed_one = uniform::fixed_one * uniform::fixed_one;

// A split point as the mesh pipeline's base weights (units of 2^-24, docs/algorithm.md §0): each coordinate
// rounded to nearest from the exact c * 2^24 / 65534^2 (coordinates above 65534^2 clamp to it). No
// coordinate lies halfway (65534^2 / 2 is odd, c * 2^24 even), and for u + v = 65534^2 the rounded weights
// sum to 2^24 exactly, so w0 = 2^24 - u - v is never negative and a point on edge e1 stays on it. Points
// of depth 0 and 1 (multiples of 65534) give uniform_weight_to_fixed's weights, as a UniformPatch beside
// the split patch does. Truncating instead moves e1's points off the edge: cracks.
constexpr DomainPoint to_base_weights(uniform::SplitPoint p) noexcept {
    constexpr std::uint64_t one = uniform_split_fixed_one;
    const auto weight = [](std::uint32_t c) {
        const std::uint64_t x = c < one ? c : one;
        return static_cast<std::uint32_t>((x * (std::uint64_t{1} << 24) + one / 2) / one);
    };
    return {weight(p.u), weight(p.v)};
}
static_assert(to_base_weights({uniform_split_fixed_one, 0}) == DomainPoint{1u << 24, 0});

class UniformSplit;
namespace uniform_split_detail {
// emit()'s walk without its up-front comparison of the spans with counts(): every write is still checked
// against the spans, and false comes back on any shortfall (the spans then hold a partial output). For the
// tests of those checks; use emit().
bool emit_checked(const UniformSplit& split, std::span<uniform::SplitPoint> vertices,
                  std::span<std::uint32_t> indices) noexcept;
} // namespace uniform_split_detail

class UniformSplit {
  public:
    using point_type = uniform::SplitPoint; // units of uniform_split_fixed_one = 65534^2
    // interior_tolerance: the dice limit of edges inside the root patch, in units of N; clamped to
    // [uniform_split_strict_tolerance, uniform_split_interior_tolerance] (NaN gives the strict 1).
    UniformSplit(const UniformTableSet& tables, float f0, float f1, float f2, PatchOptions options = {},
                 double interior_tolerance = uniform_split_interior_tolerance) noexcept;

    Counts counts() const noexcept { return counts_; }
    std::uint32_t subpatch_count() const noexcept { return subpatches_; }
    std::uint32_t depth() const noexcept { return depth_; }
    std::array<double, 3> factors() const noexcept { return root_; }
    double interior_tolerance() const noexcept { return tolerance_; }
    // The depth at which this patch dices whatever its factors: uniform_split_depth_limit(N, largest).
    std::uint32_t depth_limit() const noexcept { return depth_limit_; }

    // The points the patch puts on its root edge k (0: v0 -> v1, 1: v1 -> v2, 2: v0 -> v2, §3.1), in that
    // order, both corners included: edge_point_count(k) of them (segments + 1; 0 for k > 2). They come from
    // the edge's own factor by the decisions emit() takes, so a neighbour sharing the edge gives the same
    // points (reversed when its edge runs the other way) without emitting either interior. edge_points()
    // returns false and writes nothing for k > 2 or a span shorter than edge_point_count(k).
    std::uint32_t edge_point_count(std::uint32_t edge) const noexcept;
    bool edge_points(std::uint32_t edge, std::span<point_type> out) const noexcept;
    // The points every UniformSplit with a root edge of factor f (rounded and clamped as the constructor
    // does) puts on that edge, as edge_points(0) of a patch with that edge gives them: from (0, 0) to
    // (uniform_split_fixed_one, 0), both corners included, root_edge_point_count(tables, f) of them. They
    // depend on the edge alone, so the mesh pipeline numbers a shared edge's points without walking a patch
    // (docs/algorithm.md §7.5). root_edge_points returns false and writes nothing when out is too short.
    static std::uint32_t root_edge_point_count(const UniformTableSet& tables, float f) noexcept;
    static bool root_edge_points(const UniformTableSet& tables, float f, std::span<point_type> out) noexcept;

    // One diced subpatch: its pattern (the table's, for its factors rounded and clamped to [1, N]), its
    // factors before rounding (its edges' intrinsic lengths in its parent's metric) as doubles and as the
    // exact squares the decisions read (uniform/split_factor.hpp: f^2 * 2^32), its corners on the root (units
    // of uniform_split_fixed_one; exact at depth 1) and its depth.
    struct Leaf {
        const UniformPatch& patch;
        std::array<double, 3> factors;
        std::array<uniform::SquaredFactor, 3> squared_factors;
        std::array<std::array<std::int64_t, 2>, 3> corners;
        std::uint32_t depth;
    };
    // Calls f(const Leaf&) for every diced subpatch in output order. The walk and its decisions are out of
    // line (split.cpp); only the call to f is in the caller's code.
    using LeafCallback = void (*)(void* context, const Leaf& leaf);
    void for_each_leaf(LeafCallback callback, void* context) const noexcept;
    template <class F>
    void for_each_leaf(F&& f) const noexcept {
        using Fn = std::remove_reference_t<F>;
        for_each_leaf([](void* c, const Leaf& leaf) { (*static_cast<Fn*>(c))(leaf); },
                      const_cast<void*>(static_cast<const void*>(std::addressof(f))));
    }

    // The longest edge of the output's triangles in the root patch's intrinsic metric (§3.1: the rounded
    // root factors as side lengths; negative squares clamp at 0), from the emitted positions.
    double longest_edge() const noexcept;

    // Writes the vertices (units of uniform_split_fixed_one) and triangles, welded in the shared layout.
    // Returns false and writes nothing when either span is shorter than counts(). Every write is checked
    // against the spans as well, never only against counts(): should the walk disagree with counts(), emit()
    // returns false with a partial output inside the spans and nothing past them.
    bool emit(std::span<point_type> vertices, std::span<std::uint32_t> indices) const noexcept;

    // The leaves' own points: every diced subpatch's pattern in the patch's layout, leaf after leaf in walk
    // order, each mapped into the root, so a point on an edge between leaves is written once per leaf that
    // holds it. For the provoking layout this is emit(); for the shared one it is the mesh pipeline's
    // unwelded layout, which the shaders write leaf by leaf (docs/algorithm.md §7.5). leaf_counts() is its
    // counts() ({0, 0} past 32 bits, as counts()); emit_leaves() writes nothing and returns false when a span
    // is shorter, and checks every leaf against the spans as emit() does.
    Counts leaf_counts() const noexcept { return leaf_counts_; }
    bool emit_leaves(std::span<point_type> vertices, std::span<std::uint32_t> indices) const noexcept;

  private:
    struct Impl; // split.cpp
    static Impl impl_of(const UniformTableSet& tables, PatchOptions options, std::array<double, 3> root,
                        double tolerance, std::uint32_t depth_limit) noexcept;
    Impl make_impl() const noexcept;
    static Impl edge_impl(const UniformTableSet& tables,
                          float f) noexcept; // all three root edges of factor f
    friend bool uniform_split_detail::emit_checked(const UniformSplit&, std::span<uniform::SplitPoint>,
                                                   std::span<std::uint32_t>) noexcept;

    const UniformTableSet* tables_;
    PatchOptions options_;
    std::array<double, 3> root_{1, 1, 1};
    double tolerance_ = uniform_split_interior_tolerance;
    Counts counts_, leaf_counts_;
    std::uint32_t subpatches_ = 0, depth_ = 0, depth_limit_ = 2;
    bool overflow_ = false; // counts beyond 32 bits: counts() {0, 0}, emit() false
    // The leaves of a split of up to listed_leaf_capacity leaves, in walk order, as the counting walk met
    // them: their corners on the root (units of 65534^2, which fit 32 bits) and rounded factors. The leaf
    // writer (emit() in the provoking layout or at depth 0, emit_leaves()) reads them without walking the
    // tree again (docs/algorithm.md §3.5, "Leaf list"); listed_leaves_ = 0: walk.
    struct ListedLeaf {
        std::array<std::array<std::uint32_t, 2>, 3> corner;
        std::array<std::uint32_t, 3> factors;
    };
    static constexpr std::uint32_t listed_leaf_capacity = 16;
    std::array<ListedLeaf, listed_leaf_capacity> leaf_list_{};
    std::uint32_t listed_leaves_ = 0;
};

static_assert(TessPatch<UniformSplit>);

} // namespace ctess::rt
