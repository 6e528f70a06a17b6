// UniformSplit's every decision (docs/algorithm.md §3.5): factor sanitising, edge pieces and the dice
// limit, rounding, child factors, the walks that count and emit, longest_edge. The decisions read exact
// squared factors in integers (uniform/split_factor.hpp), the shaders' arithmetic; the file is still compiled
// with contraction and fast-math off (runtime/CMakeLists.txt, ctess_uniform_core) for longest_edge and the
// real factors it reports (docs/api.md, "Crack-free evaluation").
#include <ctess/runtime/uniform/split.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>

#include <ctess/uniform/factor.hpp>
#include <ctess/uniform/metric.hpp>
#include <ctess/uniform/pattern.hpp>
#include <ctess/uniform/split_factor.hpp>

namespace ctess::rt {

namespace {
// The largest stored pattern's vertices and interior edges (3T - B) / 2: the shared layout's per-level
// arrays.
struct PatternBounds {
    std::uint32_t vertices = 0, interior_edges = 0;
    std::uint32_t provoking = 0; // vertices plus at most one provoking copy per triangle
};
constexpr PatternBounds pattern_bounds() {
    PatternBounds b;
    for (unsigned p = 0; p < uniform::data::pattern_count; ++p) {
        const uniform::data::PatternRecord& r = uniform::data::patterns[p];
        const std::uint32_t boundary = r.f0 + r.f1 + r.f2;
        const std::uint32_t triangles = uniform::triangle_count(boundary, r.interior);
        b.vertices = std::max<std::uint32_t>(b.vertices, boundary + r.interior);
        b.interior_edges = std::max<std::uint32_t>(b.interior_edges, (3 * triangles - boundary) / 2);
        b.provoking = std::max<std::uint32_t>(b.provoking, boundary + r.interior + triangles);
    }
    return b;
}
constexpr PatternBounds bounds = pattern_bounds();

// Storage for N points without the zeroing of their default member initialisers: a std::array<Point, N>
// zeroed all N (hundreds) for every leaf, and only counts().vertices of them are written, then read.
template <class T, std::size_t N>
union Uninitialised {
    T item[N];
    Uninitialised() noexcept {}
};

// The map of map_points() in unsigned 32-bit arithmetic (docs/algorithm.md §3.5). Corner k is 65534 a_k + b_k
// (0 <= b_k < 65534), so a point's exact sum w c0 + u c1 + v c2 (w + u + v = 65534) is 65534 (w a0 + u a1 + v
// a2) + B with B = w b0 + u b1 + v b2 <= 65534 x 65533 < 2^32: the quotient by 65534 is base + u du + v dv +
// B / 65534 (base = 65534 a0, du = a1 - a0, dv = a2 - a0; modulo 2^32, exact, as the result is a root point
// below 2^32) and the remainder B % 65534. At depth 0 and 1 every b_k is 0 (with_remainders = false). Returns
// whether any remainder was a tie (half), whose rounding depends on the root edges: the caller redoes those
// with map(). On x86-64 with GCC or Clang a second build for AVX2 (a 32-bit vector multiply; SSE2 emulates
// it), chosen at run time as CpPatchSetup::emit does.
struct Map32 {
    std::uint32_t base[2], du[2], dv[2];
    std::uint32_t b[3][2];
};
template <bool with_remainders>
inline bool map32_body(const Map32& m, const uniform::Point* in, std::size_t count,
                       uniform::SplitPoint* out) noexcept {
    constexpr std::uint32_t one = uniform::fixed_one, half = one / 2;
    std::uint32_t ties = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t u = in[i].u, v = in[i].v;
        std::uint32_t xy[2];
        for (int k = 0; k < 2; ++k) {
            xy[k] = m.base[k] + u * m.du[k] + v * m.dv[k];
            if constexpr (with_remainders) {
                const std::uint32_t w = one - u - v;
                const std::uint32_t b = w * m.b[0][k] + u * m.b[1][k] + v * m.b[2][k];
                const std::uint32_t q = b / one, r = b - q * one;
                xy[k] += q + (r > half ? 1u : 0u);
                ties |= r == half ? 1u : 0u;
            }
        }
        out[i] = {xy[0], xy[1]};
    }
    return ties != 0;
}
#if defined(__x86_64__) && defined(__GNUC__)
template <bool with_remainders>
__attribute__((target("avx2"))) bool map32_avx2(const Map32& m, const uniform::Point* in, std::size_t count,
                                                uniform::SplitPoint* out) noexcept {
    return map32_body<with_remainders>(m, in, count, out);
}
#endif
template <bool with_remainders>
bool map32(const Map32& m, const uniform::Point* in, std::size_t count, uniform::SplitPoint* out) noexcept {
#if defined(__x86_64__) && defined(__GNUC__)
    if ((__builtin_cpu_init(), __builtin_cpu_supports("avx2")))
        return map32_avx2<with_remainders>(m, in, count, out);
#endif
    return map32_body<with_remainders>(m, in, count, out);
}

// to[k] = from[k] + delta for k < count (the spans do not overlap): a repeated leaf's indices from the last
// leaf's (Writer::leaf). AVX2 build chosen at run time as map32's.
inline void add_copy_body(const std::uint32_t* __restrict from, std::uint32_t* __restrict to,
                          std::size_t count, std::uint32_t delta) noexcept {
    for (std::size_t k = 0; k < count; ++k) to[k] = from[k] + delta;
}
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target("avx2"))) void add_copy_avx2(const std::uint32_t* from, std::uint32_t* to,
                                                   std::size_t count, std::uint32_t delta) noexcept {
    add_copy_body(from, to, count, delta);
}
#endif
void add_copy(const std::uint32_t* from, std::uint32_t* to, std::size_t count, std::uint32_t delta) noexcept {
#if defined(__x86_64__) && defined(__GNUC__)
    if ((__builtin_cpu_init(), __builtin_cpu_supports("avx2"))) return add_copy_avx2(from, to, count, delta);
#endif
    add_copy_body(from, to, count, delta);
}
} // namespace

// The walks over the split tree, on a copy of the patch's settings.
struct UniformSplit::Impl {
    const UniformTableSet* tables_;
    PatchOptions options_;
    std::array<double, 3> root_;                         // the rounded root factors, for longest_edge only
    std::array<uniform::SquaredFactor, 3> root_squared_; // the same, exact: what the decisions read
    std::uint64_t interior_limit_; // interior_limit_squared(N, tolerance): the interior dice limit
    std::uint32_t depth_limit_;    // leaves at this depth are diced (factors clamped to N), §3.5

    using Point = std::array<std::int64_t, 2>; // units of 65534^2
    struct Sub {
        std::array<Point, 3> corner;
        std::array<uniform::SquaredFactor, 3> factor; // exact squares (split_factor.hpp)
        std::uint32_t depth;
    };
    // Counted in 64 bits: the constructor checks the totals against 32-bit counts (§3.5, "Counts").
    struct Counter {
        std::uint64_t vertices = 0, triangles = 0;
        std::uint32_t subpatches = 0, depth = 0;
        // The first leaves' corners and rounded factors (UniformSplit::leaf_list_): emit() reads them back
        // when the walk has no more than the list holds.
        std::span<UniformSplit::ListedLeaf> list;
        // A leaf's counts depend on its rounded factors only: the last leaf's are reused when they repeat
        // (the leaves of a regular split all round alike).
        std::uint32_t last_factors = 0; // leaf_key() of the last leaf; 0: none
        Counts last_counts;
        void leaf(const Sub& s, const Impl& self) {
            const std::array<std::uint32_t, 3> r = self.leaf_factors(s);
            if (leaf_key(r) != last_factors) {
                last_counts = UniformPatch(*self.tables_, r, self.options_).counts();
                last_factors = leaf_key(r);
            }
            vertices += last_counts.vertices;
            triangles += last_counts.triangles;
            if (subpatches < list.size()) {
                UniformSplit::ListedLeaf& l = list[subpatches];
                for (int c = 0; c < 3; ++c)
                    for (int k = 0; k < 2; ++k) l.corner[c][k] = static_cast<std::uint32_t>(s.corner[c][k]);
                l.factors = r;
            }
            ++subpatches;
            depth = s.depth > depth ? s.depth : depth;
        }
    };
    struct Writer {
        Writer(std::span<uniform::SplitPoint> out_vertices, std::span<std::uint32_t> out_indices) noexcept
            : vertices(out_vertices), indices(out_indices) {}
        std::span<uniform::SplitPoint> vertices;
        std::span<std::uint32_t> indices;
        std::uint32_t v = 0, t = 0;
        bool ok = true;
        // The last leaf written: its rounded factors (a leaf's pattern output depends on them and the options
        // only), its pattern's points (local units) and where its vertices and indices went. A leaf that
        // rounds alike (every leaf of a regular split) reuses the points and copies the indices from the
        // output with one add (docs/algorithm.md §3.5, "Leaf reuse"); only the map into the root is per leaf.
        std::uint32_t last_factors = 0; // leaf_key() of the last leaf; 0: none
        Counts last_counts;
        std::uint32_t last_v = 0, last_t = 0;
        Uninitialised<uniform::Point, bounds.provoking> local;

        // Every leaf is checked against what is left of the spans, not against counts() (§3.5).
        void leaf(const Sub& s, const Impl& self) { listed_leaf(s, self.leaf_factors(s), self); }
        // A leaf of rounded factors r: map_points reads s's corners only.
        void listed_leaf(const Sub& s, const std::array<std::uint32_t, 3>& r, const Impl& self) {
            if (!ok) return;
            const std::uint32_t key = leaf_key(r);
            if (key == last_factors) {
                const Counts n = last_counts;
                if (n.vertices > vertices.size() - v || n.index_count() > indices.size() - t) {
                    ok = false;
                    return;
                }
                // The last leaf's indices are its local ones plus last_v, just before t (no wrap: both
                // checked).
                add_copy(indices.data() + last_t, indices.data() + t, n.index_count(), v - last_v);
            } else {
                const UniformPatch p(*self.tables_, r, self.options_);
                const Counts n = p.counts();
                last_factors = 0;
                // The stack buffer fits every pattern; emit() refuses an index base that would wrap.
                if (n.vertices > vertices.size() - v || n.index_count() > indices.size() - t ||
                    !p.emit(std::span<uniform::Point>(local.item, n.vertices),
                            indices.subspan(t, n.index_count()), v)) {
                    ok = false;
                    return;
                }
                last_factors = key;
                last_counts = n;
            }
            const Counts n = last_counts;
            self.map_points(s, std::span<const uniform::Point>(local.item, n.vertices),
                            vertices.subspan(v, n.vertices));
            last_v = v, last_t = t;
            v += n.vertices, t += n.index_count();
        }
    };
    struct LeafCaller {
        UniformSplit::LeafCallback callback;
        void* context;
        void patch(const UniformPatch& p, const Sub& s, const Impl&) const {
            const std::array<double, 3> real{uniform::factor_of(s.factor[0]), uniform::factor_of(s.factor[1]),
                                             uniform::factor_of(s.factor[2])};
            callback(context, UniformSplit::Leaf{p, real, s.factor, s.corner, s.depth});
        }
    };
    struct EdgeMeter {
        double longest = 0;
        void patch(const UniformPatch& p, const Sub& s, const Impl& self) {
            constexpr double one = uniform_split_fixed_one;
            for (std::uint32_t k = 0; k < p.counts().triangles; ++k) {
                const UniformTriangle tri = p.triangle(k);
                for (int e = 0; e < 3; ++e) {
                    const Point a = self.map(s, p.vertex(tri[e])),
                                b = self.map(s, p.vertex(tri[(e + 1) % 3]));
                    const double len = uniform::intrinsic_length(self.root_, double(b[0] - a[0]) / one,
                                                                 double(b[1] - a[1]) / one);
                    longest = len > longest ? len : longest;
                }
            }
        }
    };

    bool welded() const noexcept { return options_.layout == Layout::shared; }

    // A point of subpatch s from its local (u, v) in units of 65534: exact at depth 0 and 1, rounded
    // (round_unit) below from an exact integer sum (corners below 2^32, weights at most 65534: below 2^49). A
    // point on an edge of s has weight 0 on the third corner, so the sum is the edge's endpoints' alone
    // (lerp()).
    Point map(const Sub& s, uniform::Point d) const noexcept {
        const std::int64_t w = std::int64_t{uniform::fixed_one} - d.u - d.v;
        Point r{};
        for (int k = 0; k < 2; ++k) {
            const std::int64_t sum = w * s.corner[0][k] + std::int64_t{d.u} * s.corner[1][k] +
                                     std::int64_t{d.v} * s.corner[2][k]; // units 65534^3 at most 2^63
            r[k] = sum;
        }
        const std::uint32_t edges = (w == 0 ? 7u : root_edges_of(s.corner[0])) &
                                    (d.u == 0 ? 7u : root_edges_of(s.corner[1])) &
                                    (d.v == 0 ? 7u : root_edges_of(s.corner[2]));
        for (int k = 0; k < 2; ++k) r[k] = round_unit(r[k], edges != 0);
        return r;
    }
    // sum / 65534 rounded to nearest (sums are never negative). Ties (possible from depth 2 on) round half
    // to even on the root's edges and half up elsewhere. A neighbour sharing a root edge may run its
    // coordinate the other way (u' = 65534^2 - u, its sum 65534^3 - the sum): only ties to even give it
    // 65534^2 - the rounded u, the same point, and keep u + v = 65534^2 on e1. Inside the patch both sides
    // of an edge use the same coordinates, and half up there keeps every output up to N^2 unchanged.
    static std::int64_t round_unit(std::int64_t sum, bool on_root_edge) noexcept {
        constexpr std::int64_t one = uniform::fixed_one, half = one / 2;
        const std::int64_t q = sum / one, r = sum % one;
        return q + (r > half || (r == half && (!on_root_edge || (q & 1) != 0)) ? 1 : 0);
    }
    // The root edges a point lies on: bit 0 e0 (v = 0), bit 1 e1 (u + v = 65534^2), bit 2 e2 (u = 0). A
    // point whose every weighted corner lies on root edge j lies on j.
    static std::uint32_t root_edges_of(const Point& p) noexcept {
        return (p[1] == 0 ? 1u : 0u) | (p[0] + p[1] == std::int64_t{uniform_split_fixed_one} ? 2u : 0u) |
               (p[0] == 0 ? 4u : 0u);
    }

    // map() of every point of in, written to out (as long as in), in unsigned 32-bit arithmetic (Map32
    // above): the same integers. Corners that are multiples of 65534 (always at depth 0 and 1: a corner there
    // is the root's pattern point times 65534) have no remainders; below, a tie's rounding reads the root
    // edges, so a leaf with a tie is redone by map().
    void map_points(const Sub& s, std::span<const uniform::Point> in,
                    std::span<uniform::SplitPoint> out) const noexcept {
        constexpr std::int64_t unit = uniform::fixed_one;
        bool multiples = true;
        Map32 m;
        std::uint32_t a[3][2];
        for (int c = 0; c < 3; ++c) {
            for (int k = 0; k < 2; ++k) {
                const std::int64_t x = s.corner[c][k]; // 0 <= x <= 65534^2
                a[c][k] = static_cast<std::uint32_t>(x / unit);
                m.b[c][k] = static_cast<std::uint32_t>(x % unit);
                multiples = multiples && m.b[c][k] == 0;
            }
        }
        for (int k = 0; k < 2; ++k)
            m.base[k] = a[0][k] * uniform::fixed_one, m.du[k] = a[1][k] - a[0][k],
            m.dv[k] = a[2][k] - a[0][k];
        const bool ties = multiples ? map32<false>(m, in.data(), in.size(), out.data())
                                    : map32<true>(m, in.data(), in.size(), out.data());
        if (ties) { // rare (depth 2 and below only): map() rounds each tie by the root edges
            for (std::size_t i = 0; i < in.size(); ++i) {
                const Point q = map(s, in[i]);
                out[i] = {static_cast<std::uint32_t>(q[0]), static_cast<std::uint32_t>(q[1])};
            }
        }
    }

    // The squared intrinsic length of segment a-b (local units of 65534) in the metric whose sides have the
    // squared factors f, exact (split_factor.hpp).
    static uniform::SquaredFactor edge_factor(const std::array<uniform::SquaredFactor, 3>& f,
                                              uniform::Point a, uniform::Point b) noexcept {
        return uniform::segment_squared_factor(f, std::int64_t{b.u} - std::int64_t{a.u},
                                               std::int64_t{b.v} - std::int64_t{a.v});
    }

    // A leaf's factor: rounded half up and clamped to [1, N].
    std::uint32_t rounded(uniform::SquaredFactor s) const noexcept {
        return uniform::rounded_factor_within(s, tables_->max_factor);
    }

    template <class Visitor>
    void walk(Visitor& visitor) const noexcept {
        visit(visitor, root());
    }
    // The Writer over the split's leaf list (UniformSplit::leaf_list_) instead of the walk that listed them,
    // or the walk when the split has more leaves than the list holds.
    void write_leaves(Writer& w, const UniformSplit& split) const noexcept {
        if (split.listed_leaves_ == 0) return walk(w);
        Sub s{};
        for (const UniformSplit::ListedLeaf& l :
             std::span<const UniformSplit::ListedLeaf>(split.leaf_list_.data(), split.listed_leaves_)) {
            for (int c = 0; c < 3; ++c) s.corner[c] = Point{l.corner[c][0], l.corner[c][1]};
            w.listed_leaf(s, l.factors, *this);
        }
    }
    Sub root() const noexcept {
        const std::int64_t one = uniform_split_fixed_one;
        return Sub{{Point{0, 0}, Point{one, 0}, Point{0, one}}, root_squared_, 0};
    }

    // Whether an edge is within the dice limit at this depth: on the root's boundary f < N + 1/2 at every
    // depth (a piece of a root edge above 256 can be above N: 5000 / 16 / 16 = 19.5 must split again, not
    // clamp), inside the root f < tolerance x N. Up to N^2 a root edge's pieces are at most N.
    bool within_dice_limit(uniform::SquaredFactor s, std::uint32_t depth,
                           bool on_root_boundary) const noexcept {
        return depth == 0 || on_root_boundary ? uniform::below_half_past(s, tables_->max_factor)
                                              : s < interior_limit_;
    }
    // Whether a subpatch's edge from corner a to b lies on the root's boundary (both on one root edge).
    static bool on_boundary(const Point& a, const Point& b) noexcept {
        return (root_edges_of(a) & root_edges_of(b)) != 0;
    }
    static bool edge_on_boundary(const Sub& s, int i) noexcept {
        return i == 0   ? on_boundary(s.corner[0], s.corner[1])
               : i == 1 ? on_boundary(s.corner[1], s.corner[2])
                        : on_boundary(s.corner[0], s.corner[2]);
    }

    // How many pieces a split divides an edge into: a function of the edge's own factor and depth only, so
    // the two patches that share the edge agree whether each of them is diced or split. An edge within the
    // dice limit stays whole (its patch may still split because of another edge).
    std::uint32_t edge_pieces(uniform::SquaredFactor factor, std::uint32_t depth,
                              bool on_root_boundary) const noexcept {
        const std::uint32_t n = tables_->max_factor;
        if (within_dice_limit(factor, depth, on_root_boundary)) return 1u;
        const std::uint32_t t = uniform::rounded_factor(factor);
        const std::uint32_t k = (t + n - 1) / n;
        return k < 1 ? 1 : k > n ? n : k;
    }

    // Node s's split factors, or all 1 when it is diced (a leaf).
    std::array<std::uint32_t, 3> split_of(const Sub& s) const noexcept {
        std::array<std::uint32_t, 3> split{1, 1, 1};
        if (s.depth >= depth_limit_) return split;
        for (int i = 0; i < 3; ++i) split[i] = edge_pieces(s.factor[i], s.depth, edge_on_boundary(s, i));
        return split;
    }
    static bool is_leaf(const std::array<std::uint32_t, 3>& split) noexcept {
        return split[0] == 1 && split[1] == 1 && split[2] == 1;
    }
    // A leaf's factors rounded and clamped to [1, N]: with the options, all its pattern output depends on.
    std::array<std::uint32_t, 3> leaf_factors(const Sub& s) const noexcept {
        return {rounded(s.factor[0]), rounded(s.factor[1]), rounded(s.factor[2])};
    }
    // Rounded leaf factors (each in [1, N], N <= 255) as one word, never 0.
    static std::uint32_t leaf_key(const std::array<std::uint32_t, 3>& r) noexcept {
        static_assert(uniform::data_max_factor < 256);
        return r[0] << 16 | r[1] << 8 | r[2];
    }
    UniformPatch leaf_patch(const Sub& s) const noexcept {
        return UniformPatch(*tables_, leaf_factors(s), options_);
    }
    // A split node's pattern with its vertices read once (vertex(i) divides on every call) and mapped into
    // the root once (map_points: map()'s integers), instead of three map() calls per child, each vertex
    // shared by up to six children; its stack share is two pattern-sized point arrays.
    struct SplitPattern {
        UniformPatch patch;
        Uninitialised<uniform::Point, bounds.vertices> points;       // the first counts().vertices written
        Uninitialised<uniform::SplitPoint, bounds.vertices> on_root; // the same points mapped by s
        const uniform::Point* point = points.item;
        const uniform::SplitPoint* mapped = on_root.item;
        SplitPattern(const Impl& impl, const Sub& s, const UniformPatch& p) noexcept : patch(p) {
            const std::uint32_t n = p.counts().vertices;
            for (std::uint32_t i = 0; i < n; ++i) points.item[i] = p.vertex(i);
            impl.map_points(s, std::span<const uniform::Point>(points.item, n),
                            std::span<uniform::SplitPoint>(on_root.item, n));
        }
        SplitPattern(const SplitPattern&) = delete; // point and mapped point into the object
    };
    SplitPattern split_pattern(const Sub& s, const std::array<std::uint32_t, 3>& split) const noexcept {
        return SplitPattern(*this, s,
                            UniformPatch(*tables_, split, PatchOptions{Layout::shared, Winding::ccw}));
    }
    // The subpatch of s on the split pattern's triangle tri (counter-clockwise).
    Sub child(const Sub& s, const SplitPattern& pattern, const UniformTriangle& tri) const noexcept {
        const uniform::Point a = pattern.point[tri[0]], b = pattern.point[tri[1]], c = pattern.point[tri[2]];
        const auto corner = [&](std::uint32_t i) { return Point{pattern.mapped[i].u, pattern.mapped[i].v}; };
        Sub c_sub;
        c_sub.depth = s.depth + 1;
        c_sub.corner = {corner(tri[0]), corner(tri[1]), corner(tri[2])}; // map() of a, b, c
        c_sub.factor = {child_edge_factor(s, a, b), child_edge_factor(s, b, c), child_edge_factor(s, a, c)};
        return c_sub;
    }

    template <class Visitor>
    void visit(Visitor& visitor, const Sub& s) const noexcept {
        const std::array<std::uint32_t, 3> split = split_of(s);
        if (is_leaf(split)) {
            if constexpr (requires { visitor.leaf(s, *this); })
                visitor.leaf(s, *this); // builds its UniformPatch only when it needs one
            else
                visitor.patch(leaf_patch(s), s, *this);
            return;
        }
        const SplitPattern pattern = split_pattern(s, split);
        for (std::uint32_t k = 0; k < pattern.patch.counts().triangles; ++k)
            visit(visitor, child(s, pattern, pattern.patch.triangle(k)));
    }

    // A child edge that is a whole parent edge (an edge that stayed whole) keeps the parent's factor exactly,
    // the value the neighbour across it sees; any other child edge is measured in the parent's metric.
    static uniform::SquaredFactor child_edge_factor(const Sub& s, uniform::Point a,
                                                    uniform::Point b) noexcept {
        auto corner = [](uniform::Point p) -> int {
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

    // The point at parameter t (units of 65534) from a to b: map() of a point on an edge of a subpatch whose
    // corners a and b are, the same integer sum (the third weight is 0). Walked from b, the parameter is
    // 65534 - t (symmetric quantisation, §3.2), and the sum is the same: both sides agree bit for bit.
    static Point lerp(const Point& a, const Point& b, std::uint32_t t) noexcept {
        constexpr std::int64_t one = uniform::fixed_one;
        Point r{};
        const std::uint32_t edges = (t == one ? 7u : root_edges_of(a)) & (t == 0 ? 7u : root_edges_of(b));
        for (int k = 0; k < 2; ++k) r[k] = round_unit((one - t) * a[k] + std::int64_t{t} * b[k], edges != 0);
        return r;
    }
    // The points an edge of factor f at `depth` from a to b carries after a, b included: the decisions of
    // visit() and segments() (edge_pieces, the depth limit, piece_factor, rounded), in the edge's order.
    template <class Out>
    void edge_walk(const Point& a, const Point& b, uniform::SquaredFactor f, std::uint32_t depth,
                   Out& out) const noexcept {
        const std::uint32_t k = depth >= depth_limit_ ? 1u : edge_pieces(f, depth, true);
        if (k == 1) {
            const std::uint32_t r = rounded(f);
            for (std::uint32_t i = 1; i <= r; ++i) out(lerp(a, b, uniform::edge_parameter(i, r)));
            return;
        }
        for (std::uint32_t s = 0; s < k; ++s)
            edge_walk(lerp(a, b, uniform::edge_parameter(s, k)),
                      lerp(a, b, uniform::edge_parameter(s + 1, k)), piece_factor(f, k, s), depth + 1, out);
    }
    // Root edge j's corners: e0 = v0 -> v1, e1 = v1 -> v2, e2 = v0 -> v2 (§3.1).
    std::array<Point, 2> root_edge(std::uint32_t j) const noexcept {
        const std::array<Point, 3> c = root().corner;
        return j == 0   ? std::array<Point, 2>{c[0], c[1]}
               : j == 1 ? std::array<Point, 2>{c[1], c[2]}
                        : std::array<Point, 2>{c[0], c[2]};
    }
    // The points on root edge j, both corners included: root_edge_count(j) of them, written by the decisions
    // of segments() (edge_points, root_edge_points). False, nothing written, when out is too short.
    std::uint32_t root_edge_count(std::uint32_t j) const noexcept {
        return segments(root_squared_[j], 0, true) + 1;
    }
    bool write_root_edge(std::uint32_t j, std::span<uniform::SplitPoint> out) const noexcept {
        const std::uint32_t n = root_edge_count(j);
        if (out.size() < n) return false;
        const std::array<Point, 2> ends = root_edge(j);
        std::uint32_t written = 0;
        auto put = [&](const Point& p) {
            if (written < n)
                out[written] = {static_cast<std::uint32_t>(p[0]), static_cast<std::uint32_t>(p[1])};
            ++written;
        };
        put(ends[0]);
        edge_walk(ends[0], ends[1], root_squared_[j], 0, put);
        return written == n; // the same decisions as segments(): always
    }

    // --- The shared layout (§3.5): one vertex per exact position, numbered by the node that owns it. ---

    // The final segments on an edge of factor f of a node at `depth`: a function of the edge alone, the same
    // walk as visit() (a piece of a split edge is f times its symmetric parameter span, as child_edge_factor
    // computes it on any of the parent's edges: the same integers).
    std::uint32_t segments(uniform::SquaredFactor f, std::uint32_t depth,
                           bool on_root_boundary) const noexcept {
        const std::uint32_t k = depth >= depth_limit_ ? 1u : edge_pieces(f, depth, on_root_boundary);
        if (k == 1) return rounded(f);
        std::uint32_t total = 0;
        for (std::uint32_t s = 0; s < k; ++s)
            total += segments(piece_factor(f, k, s), depth + 1, on_root_boundary);
        return total;
    }
    static uniform::SquaredFactor piece_factor(uniform::SquaredFactor f, std::uint32_t k,
                                               std::uint32_t s) noexcept {
        return uniform::piece_squared_factor(f, uniform::edge_parameter(s, k),
                                             uniform::edge_parameter(s + 1, k));
    }

    // The points of one welded segment: at distance d (in segments) from its `first` end, d = 0 is first,
    // d = n is last, anything between is base + d - 1.
    struct Line {
        std::uint32_t first = 0, last = 0, base = 0, n = 0;
        std::uint32_t at(std::uint32_t d) const noexcept {
            return d == 0 ? first : d == n ? last : base + d - 1;
        }
    };
    // A node's edge as a stretch of a Line: its point i (from the edge's own start) is at distance
    // origin + i (forward) or origin - i along the line; `count` segments.
    struct EdgeRef {
        Line line;
        std::uint32_t origin = 0, count = 0;
        bool forward = true;
        std::uint32_t at(std::uint32_t i) const noexcept {
            return line.at(forward ? origin + i : origin - i);
        }
        // The stretch between distances `from` and `to` along this edge.
        EdgeRef piece(std::uint32_t from, std::uint32_t to) const noexcept {
            return {line, forward ? origin + from : origin - from, to > from ? to - from : from - to,
                    (to > from) == forward};
        }
    };
    struct Welder {
        Welder(std::span<uniform::SplitPoint> out_vertices, std::span<std::uint32_t> out_indices) noexcept
            : vertices(out_vertices), indices(out_indices) {}
        std::span<uniform::SplitPoint> vertices;
        std::span<std::uint32_t> indices;
        std::uint32_t next = 0, t = 0; // the next interior number, the next index slot
        bool ok = true;                // every write so far fell inside the spans
        // The last leaf's pattern, kept for the next leaf that rounds alike (docs/algorithm.md §3.5, "Leaf
        // reuse"): its rounded factors, counts, stored triangles, its points (local units) and, per boundary
        // point, the leaf side and step it lies at (locate()), all functions of the rounded factors.
        std::uint32_t last_factors = 0; // leaf_key() of the last leaf; 0: none
        std::optional<UniformPatch> last_patch;
        Uninitialised<uniform::Point, bounds.vertices> local;
        std::array<std::uint8_t, bounds.vertices> side;  // boundary point -> leaf side j (3: none)
        std::array<std::uint16_t, bounds.vertices> step; // boundary point -> its step on that side
    };

    // Step i of a boundary point p (local units of 65534) on edge j with k segments (e0: v = 0 from v0,
    // e1: u + v = 1 from v1, e2: u = 0 from v0), or -1 when p is not on it. Parameters are i / k quantised
    // (§3.2): far apart for k <= N, so rounding p's parameter * k recovers i exactly.
    static int step_on(uniform::Point p, int j, std::uint32_t k) noexcept {
        constexpr std::uint32_t one = uniform::fixed_one;
        const bool on = j == 0 ? p.v == 0 : j == 1 ? p.u + p.v == one : p.u == 0;
        if (!on) return -1;
        const std::uint32_t t = j == 0 ? p.u : p.v;
        return static_cast<int>((t * k + one / 2) / one);
    }
    // The edge of a node's side j that holds a boundary point, and its step there (both found by step_on).
    static bool locate(uniform::Point p, const std::array<std::uint32_t, 3>& k, int& j, std::uint32_t& step) {
        for (j = 0; j < 3; ++j) {
            const int s = step_on(p, j, k[j]);
            if (s >= 0) return step = static_cast<std::uint32_t>(s), true;
        }
        return false;
    }

    void weld_root(Welder& w) const noexcept {
        // The root's corners 0, 1, 2, then the points of e0, e1, e2 in order: B numbers in all.
        std::array<std::uint32_t, 3> n{};
        for (int j = 0; j < 3; ++j) n[j] = segments(root_squared_[j], 0, true);
        const Line e0{0, 1, 3, n[0]}, e1{1, 2, 3 + n[0] - 1, n[1]}, e2{0, 2, 3 + n[0] - 1 + n[1] - 1, n[2]};
        w.next = n[0] + n[1] + n[2];
        const std::array<EdgeRef, 3> edges{EdgeRef{e0, 0, n[0], true}, EdgeRef{e1, 0, n[1], true},
                                           EdgeRef{e2, 0, n[2], true}};
        weld_visit(w, root(), edges);
    }

    void weld_visit(Welder& w, const Sub& s, const std::array<EdgeRef, 3>& edges) const noexcept {
        if (!w.ok) return;
        const std::array<std::uint32_t, 3> split = split_of(s);
        if (is_leaf(split))
            weld_leaf(w, s, edges);
        else
            weld_split(w, s, edges, split);
    }

    // A welded leaf: its pattern's points (local units) and boundary steps from the last leaf when it rounds
    // alike, else from its UniformPatch; the boundary points numbered by their edges, the interior ones here;
    // the points mapped into the root and written at their numbers, the triangles written from the stored
    // index bytes through that numbering in one pass.
    void weld_leaf(Welder& w, const Sub& s, const std::array<EdgeRef, 3>& edges) const noexcept {
        if (!w.ok) return;
        Uninitialised<uniform::SplitPoint, bounds.vertices> on_root;
        uniform::SplitPoint* const mapped = on_root.item;  // on the root
        std::array<std::uint32_t, bounds.vertices> number; // local vertex -> global
        const std::array<std::uint32_t, 3> r = leaf_factors(s);
        uniform::Point* const point = w.local.item; // local
        if (leaf_key(r) != w.last_factors) {
            const UniformPatch p(*tables_, r, options_); // Layout::shared: no copies
            const Counts c = p.counts();
            w.last_factors = 0;
            // The points into the buffer (it fits every pattern), the indices where the renumbered ones go.
            if (c.index_count() > w.indices.size() - w.t ||
                !p.emit(std::span<uniform::Point>(point, c.vertices),
                        w.indices.subspan(w.t, c.index_count()))) {
                w.ok = false;
                return;
            }
            // The leaf's own segments per edge equal its edges' counts (the same segments() walk).
            for (std::uint32_t i = 0; i < r[0] + r[1] + r[2]; ++i) {
                int j = 0;
                std::uint32_t at = 0;
                const bool found = locate(point[i], r, j, at);
                w.side[i] = static_cast<std::uint8_t>(found ? j : 3);
                w.step[i] = static_cast<std::uint16_t>(found ? at : 0);
            }
            w.last_factors = leaf_key(r);
            w.last_patch.emplace(p);
        }
        const Counts n = w.last_patch->counts();
        if (n.index_count() > w.indices.size() - w.t) {
            w.ok = false;
            return;
        }
        const std::uint32_t boundary = r[0] + r[1] + r[2];
        std::uint32_t largest = 0; // of the boundary numbers
        for (std::uint32_t i = 0; i < boundary; ++i) {
            number[i] = w.side[i] < 3 ? edges[w.side[i]].at(w.step[i]) : 0;
            largest = number[i] > largest ? number[i] : largest;
        }
        // The interior points are numbered in a row: mapped straight into the output, no scatter.
        const std::uint32_t interior = n.vertices - boundary, first_interior = w.next;
        for (std::uint32_t i = boundary; i < n.vertices; ++i) number[i] = first_interior + (i - boundary);
        w.next += interior;
        // Every number is checked before any point is written: a leaf is written whole or not at all.
        if ((boundary != 0 && largest >= w.vertices.size()) ||
            (interior != 0 && std::uint64_t{first_interior} + interior > w.vertices.size())) {
            w.ok = false;
            return;
        }
        map_points(s, std::span<const uniform::Point>(point, boundary),
                   std::span<uniform::SplitPoint>(mapped, boundary));
        for (std::uint32_t i = 0; i < boundary; ++i) w.vertices[number[i]] = mapped[i];
        map_points(s, std::span<const uniform::Point>(point + boundary, interior),
                   w.vertices.subspan(first_interior, interior));
        // The triangles renumbered as they are widened from the stored bytes. (Copying the last leaf's
        // indices with one add and rewriting only the slots of boundary points took as many instructions as
        // this gather.)
        w.last_patch->emit_triangles_numbered(w.indices.data() + w.t, number.data());
        w.t += n.index_count();
    }

    // A split node numbers its pattern's interior vertices and interior edges' points, then its subpatches.
    // One split node of the shared layout: its pattern's vertices and interior edges numbered, and the
    // EdgeRef of each pattern edge for the subpatches (§3.5, "The shared layout").
    struct SplitNode {
        const Impl& self;
        const Sub& s;
        const std::array<EdgeRef, 3>& edges;
        const std::array<std::uint32_t, 3>& split;
        const SplitPattern pattern;
        const std::uint32_t boundary;
        // pattern vertex -> global; every entry below the pattern's count is written before it is read
        std::array<std::uint32_t, bounds.vertices> number;
        // Distances (in final segments) of each split point along this node's edges.
        std::array<std::array<std::uint32_t, uniform::data_max_factor + 1>, 3> offset{};
        // Interior edges, each owned by its half-edge from the lower to the higher pattern vertex; the first
        // owned_count used, sorted by (lower, higher) to look up from either side.
        struct Owned {
            std::uint32_t key, base;
        };
        std::array<Owned, bounds.interior_edges> owned;
        std::uint32_t owned_count = 0;

        SplitNode(const Impl& impl, const Sub& sub, const std::array<EdgeRef, 3>& node_edges,
                  const std::array<std::uint32_t, 3>& node_split) noexcept
            : self(impl), s(sub), edges(node_edges), split(node_split),
              pattern(impl.split_pattern(sub, node_split)),
              boundary(node_split[0] + node_split[1] + node_split[2]) {
            for (int j = 0; j < 3; ++j) {
                offset[j][split[j]] = edges[j].count;
                for (std::uint32_t p = 0; p + 1 < split[j]; ++p)
                    offset[j][p + 1] = offset[j][p] + self.segments(piece_factor(s.factor[j], split[j], p),
                                                                    s.depth + 1, edge_on_boundary(s, j));
            }
        }
        // Whether pattern edge a-b lies on this node's side j, and its endpoints' steps there.
        bool along(std::uint32_t a, std::uint32_t b, int& j, std::uint32_t& sa, std::uint32_t& sb) const {
            if (a >= boundary || b >= boundary) return false;
            for (j = 0; j < 3; ++j) {
                const int x = step_on(pattern.point[a], j, split[j]),
                          y = step_on(pattern.point[b], j, split[j]);
                if (x >= 0 && y >= 0) return sa = std::uint32_t(x), sb = std::uint32_t(y), true;
            }
            return false;
        }
        std::uint32_t edge_segments(std::uint32_t a, std::uint32_t b) const {
            // Only used for edges inside the node (along() finds the others): never on the root's boundary.
            return self.segments(child_edge_factor(s, pattern.point[a], pattern.point[b]), s.depth + 1,
                                 false);
        }
        // The pattern's vertices: boundary ones on this node's edges, interior ones numbered here.
        void number_vertices(Welder& w) {
            const std::uint32_t all = pattern.patch.counts().vertices;
            for (std::uint32_t i = 0; i < all; ++i) {
                int j = 0;
                std::uint32_t step = 0;
                number[i] = i >= boundary                              ? w.next + (i - boundary)
                            : locate(pattern.point[i], split, j, step) ? edges[j].at(offset[j][step])
                                                                       : 0;
            }
            w.next += all - boundary;
        }
        // The interior edges' points, numbered in triangle order.
        void number_interior_edges(Welder& w) {
            for (std::uint32_t t = 0; t < pattern.patch.counts().triangles; ++t) {
                const UniformTriangle tri = pattern.patch.triangle(t);
                for (int e = 0; e < 3; ++e) {
                    const std::uint32_t a = tri[e], b = tri[(e + 1) % 3];
                    int j = 0;
                    std::uint32_t sa = 0, sb = 0;
                    if (a > b || along(a, b, j, sa, sb)) continue;
                    owned[owned_count++] = {(a << 16) | b, w.next};
                    w.next += edge_segments(a, b) - 1;
                }
            }
            std::sort(owned.begin(), owned.begin() + owned_count,
                      [](const Owned& x, const Owned& y) { return x.key < y.key; });
        }
        // Pattern edge a-b as seen from a: a piece of one of this node's edges, or an owned interior edge.
        EdgeRef edge_ref(std::uint32_t a, std::uint32_t b) const {
            int j = 0;
            std::uint32_t sa = 0, sb = 0;
            if (along(a, b, j, sa, sb)) return edges[j].piece(offset[j][sa], offset[j][sb]);
            const std::uint32_t lo = a < b ? a : b, hi = a < b ? b : a, n = edge_segments(lo, hi);
            const Owned* o = std::lower_bound(owned.begin(), owned.begin() + owned_count, (lo << 16) | hi,
                                              [](const Owned& x, std::uint32_t key) { return x.key < key; });
            const Line line{number[lo], number[hi], o->base, n};
            return a == lo ? EdgeRef{line, 0, n, true} : EdgeRef{line, n, n, false};
        }
    };

    // A split node numbers its pattern's interior vertices and interior edges' points, then its subpatches.
    void weld_split(Welder& w, const Sub& s, const std::array<EdgeRef, 3>& edges,
                    const std::array<std::uint32_t, 3>& split) const noexcept {
        SplitNode node(*this, s, edges, split);
        node.number_vertices(w);
        node.number_interior_edges(w);
        for (std::uint32_t t = 0; t < node.pattern.patch.counts().triangles; ++t) {
            const UniformTriangle tri = node.pattern.patch.triangle(t);
            weld_visit(w, child(s, node.pattern, tri),
                       {node.edge_ref(tri[0], tri[1]), node.edge_ref(tri[1], tri[2]),
                        node.edge_ref(tri[0], tri[2])});
        }
    }
};

UniformSplit::UniformSplit(const UniformTableSet& tables, float f0, float f1, float f2, PatchOptions options,
                           double interior_tolerance) noexcept
    : tables_(&tables), options_(options) {
    const std::uint32_t n = tables.max_factor;
    tolerance_ = !(interior_tolerance > uniform_split_strict_tolerance)  ? uniform_split_strict_tolerance
                 : interior_tolerance > uniform_split_interior_tolerance ? uniform_split_interior_tolerance
                                                                         : interior_tolerance;
    // The one rounding rule of uniform factors (uniform/factor.hpp), clamped to uniform_split_max_factor.
    for (int i = 0; i < 3; ++i)
        root_[i] = uniform::round_factor(i == 0 ? f0 : i == 1 ? f1 : f2, uniform_split_max_factor);
    depth_limit_ =
        uniform_split_depth_limit(n, static_cast<std::uint32_t>(std::max({root_[0], root_[1], root_[2]})));
    const Impl impl = make_impl();
    Impl::Counter c;
    c.list = leaf_list_;
    impl.walk(c);
    listed_leaves_ = c.subpatches <= listed_leaf_capacity ? c.subpatches : 0u;
    std::uint64_t vertices = c.vertices;
    if (impl.welded() && c.depth > 0) { // Euler on a disk: V = 1 + (T + B) / 2 (§3.5)
        std::uint64_t boundary = 0;
        for (int i = 0; i < 3; ++i) boundary += impl.segments(impl.root_squared_[i], 0, true);
        vertices = 1 + (c.triangles + boundary) / 2;
    }
    // Counts that do not fit 32 bits (3T indices, below the primitive-restart value) give an empty patch
    // that emits nothing (§3.5, "Counts"): never a wrapped count. The same for the leaves' own vertices
    // (leaf_counts(), emit_leaves()).
    if (vertices >= 0xFFFFFFFFu || 3 * c.triangles >= 0xFFFFFFFFu) {
        overflow_ = true;
        return;
    }
    counts_ = Counts{static_cast<std::uint32_t>(vertices), static_cast<std::uint32_t>(c.triangles)};
    if (c.vertices < 0xFFFFFFFFu)
        leaf_counts_ =
            Counts{static_cast<std::uint32_t>(c.vertices), static_cast<std::uint32_t>(c.triangles)};
    subpatches_ = c.subpatches;
    depth_ = c.depth;
}

// The walks' settings: the rounded root factors (integers in [1, 32768]) squared exactly, the interior dice
// limit from the tolerance once (split_factor.hpp).
UniformSplit::Impl UniformSplit::impl_of(const UniformTableSet& tables, PatchOptions options,
                                         std::array<double, 3> root, double tolerance,
                                         std::uint32_t depth_limit) noexcept {
    std::array<uniform::SquaredFactor, 3> squared{};
    for (int i = 0; i < 3; ++i) squared[i] = uniform::squared_factor(static_cast<std::uint32_t>(root[i]));
    return Impl{
        &tables,    options, root, squared, uniform::interior_limit_squared(tables.max_factor, tolerance),
        depth_limit};
}

UniformSplit::Impl UniformSplit::make_impl() const noexcept {
    return impl_of(*tables_, options_, root_, tolerance_, depth_limit_);
}

std::uint32_t UniformSplit::edge_point_count(std::uint32_t edge) const noexcept {
    return edge > 2 || overflow_ ? 0 : make_impl().root_edge_count(edge);
}

bool UniformSplit::edge_points(std::uint32_t edge, std::span<point_type> out) const noexcept {
    return edge <= 2 && !overflow_ && make_impl().write_root_edge(edge, out);
}

// A patch with every root edge of factor f: its edge 0 is any root edge of that factor (§3.5).
UniformSplit::Impl UniformSplit::edge_impl(const UniformTableSet& tables, float f) noexcept {
    const std::uint32_t r = uniform::round_factor(f, uniform_split_max_factor);
    return impl_of(tables, PatchOptions{}, {double(r), double(r), double(r)},
                   uniform_split_interior_tolerance, uniform_split_depth_limit(tables.max_factor, r));
}

std::uint32_t UniformSplit::root_edge_point_count(const UniformTableSet& tables, float f) noexcept {
    return edge_impl(tables, f).root_edge_count(0);
}

bool UniformSplit::root_edge_points(const UniformTableSet& tables, float f,
                                    std::span<point_type> out) noexcept {
    return edge_impl(tables, f).write_root_edge(0, out);
}

void UniformSplit::for_each_leaf(LeafCallback callback, void* context) const noexcept {
    const Impl impl = make_impl();
    Impl::LeafCaller c{callback, context};
    impl.walk(c);
}

double UniformSplit::longest_edge() const noexcept {
    const Impl impl = make_impl();
    Impl::EdgeMeter m;
    impl.walk(m);
    return m.longest;
}

bool UniformSplit::emit(std::span<point_type> vertices, std::span<std::uint32_t> indices) const noexcept {
    if (vertices.size() < counts_.vertices || indices.size() < counts_.index_count()) return false;
    return uniform_split_detail::emit_checked(*this, vertices, indices);
}

bool UniformSplit::emit_leaves(std::span<point_type> vertices,
                               std::span<std::uint32_t> indices) const noexcept {
    if (overflow_ || leaf_counts_.triangles == 0 || vertices.size() < leaf_counts_.vertices ||
        indices.size() < leaf_counts_.index_count())
        return false;
    const Impl impl = make_impl();
    Impl::Writer w{vertices, indices};
    impl.write_leaves(w, *this);
    return w.ok && w.v == leaf_counts_.vertices && w.t == leaf_counts_.index_count();
}

namespace uniform_split_detail {

// The walk's own checks: every leaf against what is left of the spans, every welded vertex number against
// the vertex span; then the totals against counts().
bool emit_checked(const UniformSplit& split, std::span<UniformSplit::point_type> vertices,
                  std::span<std::uint32_t> indices) noexcept {
    if (split.overflow_) return false;
    const UniformSplit::Impl impl = split.make_impl();
    const Counts counts = split.counts_;
    if (impl.welded() && split.depth_ > 0) {
        UniformSplit::Impl::Welder w{vertices, indices};
        impl.weld_root(w);
        return w.ok && w.next == counts.vertices && w.t == counts.index_count();
    }
    UniformSplit::Impl::Writer w{vertices, indices};
    impl.write_leaves(w, split);
    return w.ok && w.v == counts.vertices && w.t == counts.index_count();
}

} // namespace uniform_split_detail

} // namespace ctess::rt
