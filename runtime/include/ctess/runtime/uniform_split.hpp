// Uniform-density splitting above the table (docs/algorithm.md §3.5, seed 001): a patch whose factors exceed
// the table's maximum N is split with the table's own pattern for the split factors, and each subpatch is
// diced (or split once more) with the table.
//
// * Factors: NaN, -inf, zero and negatives give 1; each factor is rounded to the nearest integer (halves up)
//   and clamped to [1, N^2] (+inf and huge values give N^2), which two levels of splitting always reach.
// * SplitFactor S = min(ceil(T / N), N) per edge (seed 001: min(TessFactor / MaxDiceFactor, MaxSplitFactor),
//   rounded up so that each sub-edge's factor T / S is at most N).
// * A subpatch edge's factor is the intrinsic length of that edge in the metric of its parent (the parent's
//   factors as side lengths): on a parent edge that is T_i times the edge's parameter span, i.e. a function
//   of that edge's own factor and position only; inside the parent it is computed from the edge's endpoints
//   in either direction with the same result. Neighbours therefore agree bit for bit at any depth: no cracks.
// * How many pieces a split gives an edge is a function of that edge's own factor and depth: an edge within
//   the dice limit (N at the root; below it 1.433 N, the table's own longest edge, §3.1, which only edges inside
//   the root patch can exceed) stays whole, whole edges keep their factor exactly, and a subpatch is diced when
//   all three of its edges stay whole. So a patch that splits and its neighbour that dices put the same points
//   on their shared edge.
// * Depth is at most 2; at depth 2 factors are clamped to N (an interior edge may then stay longer than one).
// * Output: every subpatch's own vertices (not welded; shared positions are bit-identical), positions in
//   units of fixed_one = 65534^2 on the root patch. In the provoking layout each subpatch is followed by its
//   own copies (UniformPatch, §3.4), so every triangle's first index is unique over the whole output. Depth-2 positions are rounded to that unit from an exact
//   integer sum, which is the same on both sides of a shared edge.
//
// Embedded style: no heap, no exceptions; counts() is computed by one traversal in the constructor, emit()
// traverses again and returns false (writing nothing) when a span is too small.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <span>

#include <ctess/counts.hpp>
#include <ctess/domain_point.hpp>
#include <ctess/patch_options.hpp>

#include "uniform_patch.hpp"

namespace ctess::rt {

inline constexpr std::uint32_t uniform_split_max_depth = 2;
// Edges inside the root patch dice at N up to this factor / N: the table's own longest edge (§3.1).
inline constexpr double uniform_split_interior_tolerance = 1.433;
inline constexpr std::uint32_t uniform_split_fixed_one = uniform::fixed_one * uniform::fixed_one;

class UniformSplit {
  public:
    UniformSplit(const UniformTableSet& tables, float f0, float f1, float f2,
                 PatchOptions options = {}) noexcept
        : tables_(&tables), options_(options) {
        const std::uint32_t n = tables.max_factor;
        const float top = static_cast<float>(n * n);
        for (int i = 0; i < 3; ++i) {
            const float f = i == 0 ? f0 : i == 1 ? f1 : f2;
            root_[i] = !(f >= 1.5f) ? 1.0 : !(f < top - 0.5f) ? double(n * n) : std::floor(double(f) + 0.5);
        }
        Counter c;
        walk(c);
        counts_ = c.counts;
        subpatches_ = c.subpatches;
        depth_ = c.depth;
    }

    Counts counts() const noexcept { return counts_; }
    std::uint32_t subpatch_count() const noexcept { return subpatches_; }
    std::uint32_t depth() const noexcept { return depth_; }
    std::array<double, 3> factors() const noexcept { return root_; }

    // Writes every subpatch's vertices (units of uniform_split_fixed_one) and triangles. Returns false and
    // writes nothing when either span is too small.
    bool emit(std::span<DomainPoint> vertices, std::span<std::uint32_t> indices) const noexcept {
        if (vertices.size() < counts_.vertices || indices.size() < counts_.index_count()) return false;
        Writer w{vertices, indices};
        walk(w);
        return true;
    }

  private:
    using Point = std::array<std::int64_t, 2>; // units of 65534^2
    struct Sub {
        std::array<Point, 3> corner;
        std::array<double, 3> factor;
        std::uint32_t depth;
    };
    struct Counter {
        Counts counts;
        std::uint32_t subpatches = 0, depth = 0;
        void patch(const UniformPatch& p, const Sub& s, const UniformSplit&) {
            counts.vertices += p.counts().vertices;
            counts.triangles += p.counts().triangles;
            ++subpatches;
            depth = s.depth > depth ? s.depth : depth;
        }
    };
    struct Writer {
        std::span<DomainPoint> vertices;
        std::span<std::uint32_t> indices;
        std::uint32_t v = 0, t = 0;
        void patch(const UniformPatch& p, const Sub& s, const UniformSplit& self) {
            const std::uint32_t base = v;
            for (std::uint32_t i = 0; i < p.counts().vertices; ++i) {
                const Point q = self.map(s, p.vertex(i));
                vertices[v++] = {static_cast<std::uint32_t>(q[0]), static_cast<std::uint32_t>(q[1])};
            }
            for (std::uint32_t k = 0; k < p.counts().triangles; ++k) {
                const UniformTriangle tri = p.triangle(k);
                indices[t++] = base + tri[0], indices[t++] = base + tri[1], indices[t++] = base + tri[2];
            }
        }
    };

    // A point of subpatch s from its local (u, v) in units of 65534: exact at depth 0 and 1, rounded (half
    // up) at depth 2 from an exact integer sum.
    Point map(const Sub& s, DomainPoint d) const noexcept {
        const std::int64_t w = std::int64_t{uniform::fixed_one} - d.u - d.v;
        Point r{};
        for (int k = 0; k < 2; ++k) {
            const std::int64_t sum = w * s.corner[0][k] + std::int64_t{d.u} * s.corner[1][k] +
                                     std::int64_t{d.v} * s.corner[2][k]; // units 65534^3 at most 2^63
            r[k] = (sum + std::int64_t{uniform::fixed_one} / 2) / std::int64_t{uniform::fixed_one};
        }
        return r;
    }

    // The intrinsic length of segment a-b (local units of 65534) in the metric whose sides are f.
    static double edge_factor(const std::array<double, 3>& f, DomainPoint a, DomainPoint b) noexcept {
        const double one = uniform::fixed_one;
        const double du = (double(b.u) - double(a.u)) / one, dv = (double(b.v) - double(a.v)) / one;
        const double dw = -du - dv;
        const double s = -f[2] * f[2] * dv * dw - f[0] * f[0] * dw * du - f[1] * f[1] * du * dv;
        return s > 0 ? std::sqrt(s) : 0.0;
    }

    std::uint32_t rounded(double t) const noexcept {
        const std::uint32_t n = tables_->max_factor;
        if (!(t >= 1.5)) return 1u;
        if (!(t < double(n) - 0.5)) return n;
        return static_cast<std::uint32_t>(t + 0.5);
    }

    template <class Visitor>
    void walk(Visitor& visitor) const noexcept {
        const std::int64_t one = uniform_split_fixed_one;
        visit(visitor, Sub{{Point{0, 0}, Point{one, 0}, Point{0, one}}, root_, 0});
    }

    // The dice limit of an edge at this depth: at the root N (+ rounding), below it the table's own longest edge
    // (only edges inside the root patch can exceed N there: a sub-edge of a root edge is at most N).
    double dice_limit(std::uint32_t depth) const noexcept {
        const double n = tables_->max_factor;
        return depth == 0 ? n + 0.5 : n * uniform_split_interior_tolerance;
    }

    // How many pieces a split divides an edge into: a function of the edge's own factor and depth only, so the
    // two patches that share the edge agree whether each of them is diced or split. An edge within the dice
    // limit stays whole (its patch may still split because of another edge).
    std::uint32_t edge_pieces(double factor, std::uint32_t depth) const noexcept {
        const std::uint32_t n = tables_->max_factor;
        if (factor < dice_limit(depth)) return 1u;
        const std::uint32_t t = static_cast<std::uint32_t>(std::floor(factor + 0.5));
        const std::uint32_t k = (t + n - 1) / n;
        return k < 1 ? 1 : k > n ? n : k;
    }

    template <class Visitor>
    void visit(Visitor& visitor, const Sub& s) const noexcept {
        std::array<std::uint32_t, 3> split{};
        for (int i = 0; i < 3; ++i) split[i] = edge_pieces(s.factor[i], s.depth);
        if ((split[0] == 1 && split[1] == 1 && split[2] == 1) || s.depth == uniform_split_max_depth) {
            const UniformPatch p(*tables_, {rounded(s.factor[0]), rounded(s.factor[1]), rounded(s.factor[2])},
                                 options_);
            visitor.patch(p, s, *this);
            return;
        }
        const UniformPatch pattern(*tables_, split, PatchOptions{Layout::shared, Winding::ccw});
        for (std::uint32_t k = 0; k < pattern.counts().triangles; ++k) {
            const UniformTriangle tri = pattern.triangle(k);
            const DomainPoint a = pattern.vertex(tri[0]), b = pattern.vertex(tri[1]),
                              c = pattern.vertex(tri[2]);
            Sub child;
            child.depth = s.depth + 1;
            child.corner = {map(s, a), map(s, b), map(s, c)}; // exact at depth 0 (root corners are multiples)
            child.factor = {child_edge_factor(s, a, b), child_edge_factor(s, b, c), child_edge_factor(s, a, c)};
            visit(visitor, child);
        }
    }

    // A child edge that is a whole parent edge (an edge that stayed whole) keeps the parent's factor exactly,
    // the value the neighbour across it sees; any other child edge is measured in the parent's metric.
    static double child_edge_factor(const Sub& s, DomainPoint a, DomainPoint b) noexcept {
        auto corner = [](DomainPoint p) -> int {
            constexpr std::uint32_t one = uniform::fixed_one;
            if (p.u == 0 && p.v == 0) return 0;
            if (p.u == one && p.v == 0) return 1;
            if (p.u == 0 && p.v == one) return 2;
            return -1;
        };
        const int ca = corner(a), cb = corner(b);
        if (ca >= 0 && cb >= 0 && ca != cb) {
            // Parent edges: 0 = v0v1 (factor[0]), 1 = v1v2 (factor[1]), 2 = v2v0 (factor[2]).
            const int lo = ca < cb ? ca : cb, hi = ca < cb ? cb : ca;
            return s.factor[lo == 0 && hi == 1 ? 0 : lo == 1 && hi == 2 ? 1 : 2];
        }
        return edge_factor(s.factor, a, b);
    }

    const UniformTableSet* tables_;
    PatchOptions options_;
    std::array<double, 3> root_{1, 1, 1};
    Counts counts_;
    std::uint32_t subpatches_ = 0, depth_ = 0;
};

} // namespace ctess::rt
