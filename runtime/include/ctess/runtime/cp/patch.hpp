// The CP triangle pattern from the compile-time tables (docs/algorithm.md §2): counts, a bulk emit into
// caller spans, and random access to any vertex or triangle in O(1). Bit-identical to cp::tessellate with the
// default PatternOptions (rule (b) columns, T0 collapse) in both layouts: Layout::provoking (the default) is
// cp::tessellate's provoking layout, Layout::shared is its Layout::shared (one vertex per slot,
// the same order without the appended copies: one per distinct position except where transitional points
// coincide, docs/algorithm.md §2.11). Winding::cw reverses every triangle and keeps the
// provoking vertex first: (a, b, c) becomes (a, c, b).
//
// Three entry points, each paying only for what it needs:
// * cp_counts(): counts only (what a GPU's first pass and an allocator need): CpPatchSetup's counting
//   setup alone;
// * CpPatchSetup: counts and emit(), which writes the whole patch in one pass per part (columns, strips,
//   zipper) without any lookup structure, with 16-byte vectors (and on x86-64 an AVX2 build, chosen at run
//   time);
// * CpPatch: a CpPatchSetup plus the strip and column buckets that make vertex(i) and triangle(p) O(1)
//   (O(h) more setup): build a patch once, query it many times. Its emit() is CpPatchSetup's.
//
//   ctess::rt::CpPatch patch(ctess::rt::cp_tables_64, 5.0f, 9.0f, 3.0f, {ctess::Layout::shared});
//   std::uint32_t n = patch.triangle_count();
//   ctess::rt::CpTriangle t = patch.triangle(n - 1);   // three vertex indices
//   ctess::DomainPoint p = patch.vertex(t[0]);         // exact barycentric (u, v), units of 2^-24
//
// Which layout (docs/algorithm.md §2.11): provoking where flat shading or per-primitive data reads the first
// vertex of each triangle (each triangle's first vertex is its own); shared for smooth shading, welding-free
// meshes and the smallest vertex buffers (CpPatch(32, 32, 32): 561 vertices instead of 1,026).
//
// Embedded style: no heap, no exceptions, no RTTI, no static constructors; a patch is a small value
// (CpPatchSetup 264 bytes on LP64, CpPatch 800 with its two bucket tables). Construction and emit are
// compiled into ctess_runtime_core (runtime/src/cp/patch_setup.cpp, cp_patch_emit.cpp), which both table
// libraries link; the hot lookups are inline here.
//
// Bad input is never undefined behaviour:
// * factors are clamped to [1, max_factor] exactly as cp::line_state does (NaN, -inf, zero, negatives -> 1;
//   +inf and anything above the maximum -> max_factor); line states as cp::clamp_line_state does;
// * vertex(i) with i >= vertex_count() returns {0, 0}; triangle(p) with p >= triangle_count() returns
//   {0, 0, 0}; emit() returns false and writes nothing when a span is too small.
#pragma once
#include <array>
#include <cstdint>
#include <span>

#include <ctess/core/counts.hpp>
#include <ctess/core/domain_point.hpp>
#include <ctess/core/numeric.hpp> // popcount16
#include <ctess/core/patch_concept.hpp>
#include <ctess/core/patch_options.hpp>
#include <ctess/cp/edge_line.hpp> // cp::clamp_line_state, the clamping of line-state input
#include <ctess/cp/line.hpp>
#include <ctess/cp/tables_layout.hpp>

#include "line_state.hpp"
#include "table_set.hpp"

namespace ctess::rt {

using CpTriangle = std::array<std::uint32_t, 3>;

// Counts of the pattern, without building it.
Counts cp_counts(const CpTableSet& tables, cp::LineState s0, cp::LineState s1, cp::LineState s2,
                 PatchOptions options = {}) noexcept;
inline Counts cp_counts(const CpTableSet& tables, float f0, float f1, float f2,
                        PatchOptions options = {}) noexcept {
    return cp_counts(tables, line_state(f0, tables.max_factor), line_state(f1, tables.max_factor),
                     line_state(f2, tables.max_factor), options);
}

// Counts and bulk emission.
class CpPatchSetup {
  public:
    using point_type = DomainPoint; // units of cp::fixed_one = 2^24
    // Factors are clamped to [1, tables.max_factor] (see the header comment).
    CpPatchSetup(const CpTableSet& tables, float f0, float f1, float f2, PatchOptions options = {}) noexcept
        : CpPatchSetup(tables, line_state(f0, tables.max_factor), line_state(f1, tables.max_factor),
                       line_state(f2, tables.max_factor), options, setup_clamped) {}
    CpPatchSetup(const CpTableSet& tables, cp::LineState s0, cp::LineState s1, cp::LineState s2,
                 PatchOptions options = {}) noexcept
        : CpPatchSetup(tables, s0, s1, s2, options, 0u) {}

    Counts counts() const noexcept { return {vertices_, triangles_}; }
    std::uint32_t vertex_count() const noexcept { return vertices_; }
    std::uint32_t triangle_count() const noexcept { return triangles_; }
    PatchOptions options() const noexcept { return options_; }

    // Writes every vertex (vertex_count() entries) and every triangle (3 indices each), in the order of
    // vertex(i) and triangle(p). Returns false and writes nothing when either span is too small.
    bool emit(std::span<DomainPoint> vertices, std::span<std::uint32_t> indices) const noexcept;

  protected:
    friend Counts cp_counts(const CpTableSet&, cp::LineState, cp::LineState, cp::LineState,
                            PatchOptions) noexcept;
    // setup_counts_only: only what counts() needs (no zipper words, no clamp line: what emit needs);
    // setup_clamped: the line states are line_state()'s, already in range (no cp::clamp_line_state).
    static constexpr unsigned setup_counts_only = 1, setup_clamped = 2;
    CpPatchSetup(const CpTableSet& tables, cp::LineState s0, cp::LineState s1, cp::LineState s2,
                 PatchOptions options, unsigned setup) noexcept;

    struct Edge {
        const std::uint16_t* points = nullptr; // interior points 1..n-1 of the shape token
        std::uint32_t t16 = 0;
        std::uint32_t segments = 0;
        std::int32_t slide = 0; // half_step * (65536 - t16): a sliding point's offset from its final position
    };
    struct Skip { // a run of dropped raw triangles or slots
        std::uint32_t begin = 0;
        std::uint32_t length = 0;
    };

    // Point i of edge e. start * 65536 + (fin - start) * t16 with start = fin + d (d = +half, -half or 0 by
    // the slide) is fin * 65536 + d * (65536 - t16): one multiply by the slide's sign, no branch on it. The
    // end points are selects too; every shape has at least 3 segments, so points[0] exists.
    static std::uint32_t point(const Edge& e, std::uint32_t i) noexcept {
        const bool inside = i - 1u < e.segments - 1u;
        const std::uint32_t value = interior_point(e, e.points[inside ? i - 1u : 0u]);
        const std::uint32_t end = i == 0 ? 0u : cp::fixed_one;
        return inside ? value : end;
    }
    static std::uint32_t interior_point(const Edge& e, std::uint32_t packed) noexcept {
        const std::uint32_t slide = packed >> cp::tables::point_slide_shift;
        const int sign = static_cast<int>(slide & 1u) - static_cast<int>(slide >> 1); // none 0, down 1, up -1
        return static_cast<std::uint32_t>(static_cast<int>(packed & cp::tables::point_final_mask) * 65536 +
                                          sign * e.slide);
    }
    static DomainPoint e1_point(std::uint32_t s) noexcept { return {cp::fixed_one - s, s}; }
    static std::uint32_t skip_forward(const Skip* skip, unsigned count, std::uint32_t i) noexcept {
        for (unsigned k = 0; k < count; ++k) i += i >= skip[k].begin ? skip[k].length : 0u;
        return i;
    }
    // (a, b, c) -> (a, c, b) for Winding::cw.
    CpTriangle wind(std::uint32_t a, std::uint32_t b, std::uint32_t c) const noexcept {
        const std::uint32_t x = (b ^ c) & cw_mask_;
        return {a, b ^ x, c ^ x};
    }

    // Type 2 columns: C_i for i <= h, then one row per column.
    std::uint32_t col_start(std::uint32_t i) const noexcept {
        const std::uint32_t k = i < head_ ? i : head_;
        return c_[k] + (i - k);
    }
    std::uint32_t col_rows(std::uint32_t i) const noexcept { return col_start(i + 1) - col_start(i); }
    std::uint32_t e1_index(std::uint32_t b) const noexcept {
        if (c1_) return e1_offset_ + (b <= 1 ? 0u : 1u);
        return e1_offset_ + b;
    }
    std::uint32_t col_index(std::uint32_t i, std::uint32_t j) const noexcept {
        if (c2_) {
            if (i == 0) return j == 2 ? e1_index(n1_) : 0u;
            return i;
        }
        if (c0_) {
            if (i == 2) return e1_index(0);
            if (i == 1) return j;
        }
        return col_start(i) + j;
    }
    std::uint32_t lhs_index(std::uint32_t a) const noexcept {
        const std::uint32_t i = n0_ - 1 - a;
        return col_index(i, col_rows(i) - 1);
    }
    // Row j of column i: column 0 (u = 0) is never clamped, column i >= 1 is clamped to K - u.
    DomainPoint column_point(std::uint32_t i, std::uint32_t j) const noexcept {
        const std::uint32_t v2 = point(e_[2], j);
        const std::uint32_t u = point(e_[0], i);
        const std::uint32_t top = i == 0 ? ~0u : clamp_ > u ? clamp_ - u : 0u;
        return {u, v2 < top ? v2 : top};
    }
    // Zipper triangle q of a patch without a T0 edge: L_a = top of column n0-1-a = C_{n0-a} - 1, R_b = e1
    // point b.
    CpTriangle zipper_triangle(std::uint32_t q) const noexcept {
        const std::uint32_t w = gap_[q / cp::tables::gap_bits_per_word];
        const std::uint32_t bit = q % cp::tables::gap_bits_per_word;
        const std::uint32_t bits = w & 0xFFFFu;
        const std::uint32_t a = (w >> 16) + popcount16(bits & ((1u << bit) - 1u));
        const std::uint32_t b = q - a;
        const std::uint32_t lhs =
            0u - ((bits >> bit) & 1u); // all ones: a step on L; a mask, see strip_triangle
        const std::uint32_t rb = e1_offset_ + b;
        return wind(rb + 1 + ((col_start(n0_ - a - 1) - 1u - rb - 1) & lhs), col_start(n0_ - a) - 1u, rb);
    }

    // Out of line (runtime/src/cp/patch_setup.cpp): the single triangle, the Type 1 fan and the T0 collapse.
    DomainPoint small_vertex(std::uint32_t i) const noexcept; // Type 0 and 1
    DomainPoint slot_point(std::uint32_t s) const noexcept;   // Type 1 slots (cp::Type1Slots)
    std::uint32_t slot_index(std::uint32_t s) const noexcept;
    CpTriangle collapsed_triangle(std::uint32_t r) const noexcept; // raw triangle r of a Type 0 or 1 patch
    // Strip triangle r of a Type 2 patch with T0 collapse, from its strip i (PS_i <= r < PS_{i+1}).
    CpTriangle collapsed_strip_triangle(std::uint32_t i, std::uint32_t r) const noexcept;
    CpTriangle collapsed_zipper_triangle(std::uint32_t q) const noexcept;
    bool dropped(std::uint32_t r) const noexcept;
    // Strip triangle r of strip i of a patch with plain strips (see CpPatch::strip_triangle).
    CpTriangle plain_strip_triangle(std::uint32_t i, std::uint32_t r) const noexcept {
        const std::uint16_t* col = c_ + i;
        const std::uint32_t a = col[0], b = col[1], cells = 2 * (col[2] - b - 1u);
        const std::uint32_t o = r + n2_ + 2 * i - a - b;
        const std::uint32_t m = o < cells ? o : cells;
        const std::uint32_t s = (m + 1) >> 1, j = o - s;
        // First vertex A_j of column i >= 1 already provoked a triangle of strip i - 1: use its copy.
        // Masks, not ternaries: GCC branches on a ternary, and strip 0 holds a large share of the triangles.
        const std::uint32_t first =
            a + j + ((copy_bias_ - i) & (0u - static_cast<std::uint32_t>(i != 0)) & copy_mask_);
        const std::uint32_t odd = 0u - (m & 1u); // all ones: odd cell, whose first vertex is B_j
        return wind(first + ((b + s - 1 - first) & odd), b + s, a + j + 1);
    }
    friend struct CpPatchEmitter;        // the fast path of emit (runtime/src/cp/patch_emit.cpp)
    friend struct PatchSetupBlockWriter; // the GPU pipeline's per-patch block (patch_setup_block.hpp)
    void emit_collapsed(DomainPoint* vertices, std::uint32_t* indices) const noexcept;
    // emit() without the run-time choice of an AVX2 build on x86-64 (for the tests); spans unchecked.
    void emit_baseline(DomainPoint* vertices, std::uint32_t* indices) const noexcept;
    void add_triangle_skip(std::uint32_t begin, std::uint32_t end) noexcept {
        if (end > begin) tri_skip_[tri_skips_++] = {begin, end - begin};
    }
    // The constructor's steps (runtime/src/cp/patch_setup.cpp; docs/algorithm.md §4): the three edges, then
    // the pattern of the type they give.
    void set_edges(const CpTableSet& tables, const cp::LineState (&s)[3], unsigned (&shape)[3]) noexcept;
    void set_fan() noexcept; // Type 1
    void set_parallelogram(const CpTableSet& tables, const unsigned (&shape)[3], bool counts_only) noexcept;
    void skip_collapsed_triangles(const CpTableSet& tables, const unsigned (&shape)[3]) noexcept;

    Edge e_[3]{};
    const std::uint16_t* c_ = nullptr;   // column starts C_0..C_{h+1}
    const std::uint32_t* gap_ = nullptr; // zipper words
    PatchOptions options_{};
    std::uint8_t type_ = 0;                     // 0 single, 1 fan, 2 parallelogram (cp::PatternType)
    bool c0_ = false, c1_ = false, c2_ = false; // T0 edges, collapsed
    bool plain_strips_ = false;                 // Type 2 without T0 on e0 or e2: column i is C_i + j
    bool plain_ = false;                        // Type 2 without a T0 edge: the fast paths, no skips
    std::uint32_t cw_mask_ = 0;                 // all ones for Winding::cw
    std::uint32_t copy_mask_ = 0;               // all ones when strips use provoking copies
    std::uint32_t head_ = 0, n0_ = 0, n1_ = 0, n2_ = 0, t1_fan_ = 0;
    std::uint32_t copy_bias_ = 0;   // copy of A_j in column i >= 1: C_i - i + j + copy_bias_
    std::uint32_t fast_strips_ = 0; // strips_ when triangle p < strips_ is strip_triangle(p), else 0
    std::uint32_t clamp_ = 0;       // K
    std::uint32_t e1_offset_ = 0, unique_ = 0, strips_ = 0, zipper_ = 0;
    std::uint32_t vertices_ = 0, triangles_ = 0;
    std::array<Skip, 8> tri_skip_{};
    unsigned tri_skips_ = 0;
    std::array<Skip, 4> slot_skip_{};
    unsigned slot_skips_ = 0;
};

// A bucket index of a non-decreasing sequence 0 = S_0 <= S_1 <= ... <= S_n over [0, total): bucket b holds
// [b, b + 1) << shift and first[b] is the largest k with S_k <= b << shift. The shift keeps the buckets at
// most 256 (total <= 256 << shift). From wide_from on, a bucket may hold two or more later starts; before
// it, at most one, so a lookup is a bucket load and one branchless step.
struct CpBuckets {
    static constexpr unsigned size = 256;
    std::array<std::uint8_t, size + 1> first{}; // the extra entry is scratch for the count
    std::uint32_t shift = 0, wide_from = ~0u;
};

// Counts, emit and O(1) random access.
class CpPatch : public CpPatchSetup {
  public:
    CpPatch(const CpTableSet& tables, float f0, float f1, float f2, PatchOptions options = {}) noexcept
        : CpPatchSetup(tables, f0, f1, f2, options) {
        build_buckets();
    }
    CpPatch(const CpTableSet& tables, cp::LineState s0, cp::LineState s1, cp::LineState s2,
            PatchOptions options = {}) noexcept
        : CpPatchSetup(tables, s0, s1, s2, options) {
        build_buckets();
    }

    // Vertex i as an exact point (u, v) of the domain, units of 2^-24; {0, 0} when i >= vertex_count().
    DomainPoint vertex(std::uint32_t i) const noexcept {
        if (i >= vertices_) return {0, 0};
        if (type_ == 2) return type2_vertex(i);
        return small_vertex(i);
    }
    // Triangle p's three vertex indices, counter-clockwise (Winding::ccw) or clockwise, provoking vertex
    // first; {0, 0, 0} when p >= triangle_count().
    CpTriangle triangle(std::uint32_t p) const noexcept {
        if (p >= triangles_) return {0, 0, 0};
        if (p < fast_strips_) return strip_triangle(p);
        if (plain_) return zipper_triangle(p - strips_);
        const std::uint32_t r = skip_forward(tri_skip_.data(), tri_skips_, p);
        if (type_ != 2) return collapsed_triangle(r);
        if (r >= strips_) return collapsed_zipper_triangle(r - strips_);
        return plain_strips_ ? strip_triangle(r) : collapsed_strip_triangle(strip_of(r), r);
    }

  private:
    // Strip of raw triangle r < strips_: the largest i with PS_i = C_i + C_{i+1} - 2i - R_0 <= r. Bucket
    // r >> bucket_shift_ holds the strip of its first triangle; most buckets hold at most one more strip
    // start, which one branchless step settles. Strips get shorter towards the end, so the buckets that hold
    // two or more lie at r >= wide_from_: a loop finishes those, a branch rarely taken (0.4 % of the strip
    // triangles at (64, 64, 64), none at 8 or 32). Returns i; col points at C_i.
    std::uint32_t strip_of(std::uint32_t r, const std::uint16_t*& col) const noexcept {
        std::uint32_t i = strip_buckets_.first[r >> strip_buckets_.shift];
        const std::uint32_t target = r + n2_ + 2; // PS_{i+1} <= r  <=>  C_{i+1} + C_{i+2} <= r + R_0 + 2 + 2i
        col = c_ + i;
        const std::uint32_t step = col[1] + col[2] <= target + 2 * i ? 1u : 0u;
        i += step;
        col += step;
        if (r >= strip_buckets_.wide_from) [[unlikely]] {
            while (col[1] + col[2] <= target + 2 * i) ++i, ++col; // PS_h = strips_ > r stops it
        }
        return i;
    }
    // Head column of vertex v < C_h: the largest i with C_i <= v, from the column buckets.
    std::uint32_t column_of(std::uint32_t v) const noexcept {
        std::uint32_t i = column_buckets_.first[v >> column_buckets_.shift];
        const std::uint16_t* col = c_ + i;
        const std::uint32_t step = col[1] <= v ? 1u : 0u;
        i += step;
        col += step;
        if (v >= column_buckets_.wide_from) [[unlikely]] {
            while (col[1] <= v) ++i, ++col; // C_h > v stops it
        }
        return i;
    }
    std::uint32_t strip_of(std::uint32_t r) const noexcept {
        const std::uint16_t* col = nullptr;
        return strip_of(r, col);
    }
    // Strip triangle r of a patch without a T0 edge on e0 or e2 (so col_index(i, j) = C_i + j and, in the
    // provoking layout, every column i >= 1 has copies). Strip i joins column i (A, a = C_i) and column i + 1
    // (B, b = C_{i+1}, nb rows): cells (A_j, B_j, A_{j+1}) and (B_j, B_{j+1}, A_{j+1}) for j < nb - 1, then
    // the fan (A_j, B_{nb-1}, A_{j+1}). With o = r - PS_i and m = min(o, 2 (nb - 1)), triangle o has taken
    // s = ceil(m / 2) steps on B and o - s on A, and it is an odd cell when m is odd: one formula for all
    // three kinds, no branch.
    CpTriangle strip_triangle(std::uint32_t r) const noexcept { return plain_strip_triangle(strip_of(r), r); }
    DomainPoint type2_vertex(std::uint32_t v) const noexcept;

    void build_buckets() noexcept;

    CpBuckets strip_buckets_;  // over the raw strip triangles: S_k = PS_k, the first raw triangle of strip k
    CpBuckets column_buckets_; // over the head columns' vertices: S_k = C_k
};

// Copy k = v - unique_ of the provoking layout is column i >= 1, row j, with k = D_i + j and
// D_i = Y_i - Y_1, Y_x = C_x - x: i is the largest with Y_i <= t = k + Y_1. As PS_i = Y_i + Y_{i+1} + 1 - R_0
// and Y does not decrease, the strip of r = 2t + 1 - R_0 is i - 1 or i: the strip buckets and one step find
// it. The columns' own points come from the column buckets.
inline DomainPoint CpPatch::type2_vertex(std::uint32_t v) const noexcept {
    if (v - e1_offset_ < unique_ - e1_offset_) { // e1's points
        const std::uint32_t b = v - e1_offset_;
        return e1_point(point(e_[1], c1_ ? b * n1_ : b));
    }
    if (c0_) return column_point(0, v);
    if (c2_) return column_point(v, 0);
    const std::uint16_t* c = c_;
    const std::uint32_t ch = c[head_];
    if (v - ch < e1_offset_ - ch) return column_point(head_ + (v - ch), 0); // the tail: one row per column
    if (v >= unique_) {
        const std::uint32_t t = v - unique_ + c[1] - 1u;
        const int r = 2 * static_cast<int>(t) + 1 - static_cast<int>(n2_);
        const std::uint32_t last = strips_ - 1u;
        const std::uint32_t rc = r < 0                                  ? 0u
                                 : static_cast<std::uint32_t>(r) < last ? static_cast<std::uint32_t>(r)
                                                                        : last;
        const std::uint16_t* col = nullptr;
        std::uint32_t i = strip_of(rc, col);
        i += col[1] - i - 1u <= t ? 1u : 0u;
        return column_point(i, t - (c[i] - i));
    }
    const std::uint32_t i = column_of(v);
    return column_point(i, v - c[i]);
}

static_assert(TessPatch<CpPatchSetup>);
static_assert(IndexedTessPatch<CpPatch>);

} // namespace ctess::rt
