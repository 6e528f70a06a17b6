// The CP triangle pattern from the compile-time tables: counts, random access to any vertex or triangle in
// O(1), and a bulk emit into caller spans. Bit-identical to cp::tessellate with the default PatternOptions
// (rule (b) columns, T0 collapse, provoking layout): same vertices, same triangles, same order.
//
// Embedded style: no heap, no exceptions, no RTTI, no static constructors; a patch is a small value (560
// bytes on LP64, 256 of them the strip buckets). The constructor precomputes a per-patch bucket table of the
// strips (O(h + 256) work), so that triangle(p) is a bucket load plus one branchless step, and a copy's
// vertex(i) reuses it: build a patch once, query it many times.
//
//   ctess::rt::CpPatch patch(ctess::rt::cp_tables_64, 5.0f, 9.0f, 3.0f);
//   std::uint32_t n = patch.triangle_count();
//   ctess::rt::CpTriangle t = patch.triangle(n - 1);   // three vertex indices
//   ctess::DomainPoint p = patch.vertex(t[0]);         // exact barycentric (u, v), units of 2^-24
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

#include <ctess/cp_edge_line.hpp>
#include <ctess/cp_line.hpp>
#include <ctess/cp_tables_layout.hpp>
#include <ctess/cp_type1.hpp>
#include <ctess/domain_point.hpp>

#include "cp_search.hpp"
#include "cp_table_set.hpp"

namespace ctess::rt {

struct CpCounts {
    std::uint32_t vertices = 0;
    std::uint32_t triangles = 0;
};

using CpTriangle = std::array<std::uint32_t, 3>;

class CpPatch {
  public:
    // Factors are clamped to [1, tables.max_factor] (see the header comment).
    CpPatch(const CpTableSet& tables, float f0, float f1, float f2) noexcept
        : CpPatch(tables, cp::line_state(f0, tables.max_factor), cp::line_state(f1, tables.max_factor),
                  cp::line_state(f2, tables.max_factor)) {}
    CpPatch(const CpTableSet& tables, cp::LineState s0, cp::LineState s1, cp::LineState s2) noexcept;

    CpCounts counts() const noexcept { return {vertices_, triangles_}; }
    std::uint32_t vertex_count() const noexcept { return vertices_; }
    std::uint32_t triangle_count() const noexcept { return triangles_; }

    // Vertex i as an exact point (u, v) of the domain, units of 2^-24; {0, 0} when i >= vertex_count().
    DomainPoint vertex(std::uint32_t i) const noexcept;
    // Triangle p's three vertex indices, counter-clockwise, provoking vertex first; {0, 0, 0} when
    // p >= triangle_count().
    CpTriangle triangle(std::uint32_t p) const noexcept;
    // Writes every vertex (vertex_count() entries) and every triangle (3 indices each). Returns false and
    // writes nothing when either span is too small.
    bool emit(std::span<DomainPoint> vertices, std::span<std::uint32_t> indices) const noexcept;

  private:
    struct Edge {
        const std::uint16_t* points = nullptr; // interior points 1..n-1 of the shape token
        std::uint32_t t16 = 0;
        std::uint32_t segments = 0;
        std::uint32_t half_step = 0;
        unsigned token = 0;
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
        const std::uint32_t packed = e.points[inside ? i - 1u : 0u];
        const std::uint32_t slide = packed >> cp::tables::point_slide_shift;
        const int sign = static_cast<int>(slide & 1u) - static_cast<int>(slide >> 1); // none 0, down 1, up -1
        const std::uint32_t value = static_cast<std::uint32_t>(
            static_cast<int>(packed & cp::tables::point_final_mask) * 65536 + sign * e.slide);
        const std::uint32_t end = i == 0 ? 0u : cp::fixed_one;
        return inside ? value : end;
    }
    static DomainPoint e1_point(std::uint32_t s) noexcept { return {cp::fixed_one - s, s}; }
    // Set bits of a 16-bit word, inline: without a popcount instruction in the baseline ISA (x86-64,
    // Cortex-M), std::popcount becomes a library call.
    static std::uint32_t popcount16(std::uint32_t x) noexcept {
        x -= (x >> 1) & 0x5555u;
        x = (x & 0x3333u) + ((x >> 2) & 0x3333u);
        x = (x + (x >> 4)) & 0x0F0Fu;
        return (x + (x >> 8)) & 0x1Fu;
    }
    static std::uint32_t skip_forward(const Skip* skip, unsigned count, std::uint32_t i) noexcept {
        for (unsigned k = 0; k < count; ++k) i += i >= skip[k].begin ? skip[k].length : 0u;
        return i;
    }
    void add_triangle_skip(std::uint32_t begin, std::uint32_t end) noexcept {
        if (end > begin) tri_skip_[tri_skips_++] = {begin, end - begin};
    }

    // Type 2
    std::uint32_t col_start(std::uint32_t i) const noexcept {
        return i <= head_ ? c_[i] : c_[head_] + (i - head_);
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
    DomainPoint type2_vertex(std::uint32_t v) const noexcept;
    // Strip of raw triangle r < strips_: the largest i with PS_i = C_i + C_{i+1} - 2i - R_0 <= r. Bucket
    // r >> bucket_shift_ holds the strip lo of its first triangle; most buckets hold at most one more strip
    // start, which one branchless step settles. Strips get shorter towards the end, so the buckets that hold
    // two or more lie at r >= wide_from_: a loop finishes those, a branch rarely taken (0.4 % of the strip
    // triangles at (64, 64, 64), none at 8 or 32). Returns i; col points at C_i.
    std::uint32_t strip_of(std::uint32_t r, const std::uint16_t*& col) const noexcept {
        std::uint32_t i = strip_bucket_[r >> bucket_shift_];
        const std::uint32_t target = r + n2_ + 2; // PS_{i+1} <= r  <=>  C_{i+1} + C_{i+2} <= r + R_0 + 2 + 2i
        col = c_ + i;
        const std::uint32_t step = col[1] + col[2] <= target + 2 * i ? 1u : 0u;
        i += step;
        col += step;
        if (r >= wide_from_) [[unlikely]] {
            while (col[1] + col[2] <= target + 2 * i) ++i, ++col; // PS_h = strips_ > r stops it
        }
        return i;
    }
    std::uint32_t strip_of(std::uint32_t r) const noexcept {
        const std::uint16_t* col = nullptr;
        return strip_of(r, col);
    }
    void build_strip_buckets() noexcept;
    CpTriangle strip_triangle(std::uint32_t r) const noexcept;
    CpTriangle zipper_triangle(std::uint32_t q) const noexcept;
    CpTriangle type2_triangle(std::uint32_t r) const noexcept;
    void emit_type2_plain(DomainPoint* vertices, std::uint32_t* indices) const noexcept;

    // Type 1 slots: v0, A0, B0, e1 points 0..n1, B2, A2, P (cp::Type1Slots)
    std::uint32_t slot_index(std::uint32_t s) const noexcept;
    DomainPoint slot_point(std::uint32_t s) const noexcept;
    std::uint32_t hexagon_slot(std::uint32_t k) const noexcept {
        const std::uint32_t m = n1_ + 3;
        k %= m;
        if (k == 0) return 1;
        if (k == 1) return 2;
        if (k < m - 2) return 3 + (k - 1);
        return k == m - 2 ? 4 + n1_ : 5 + n1_;
    }
    CpTriangle type1_triangle(std::uint32_t r) const noexcept;

    Edge e_[3]{};
    unsigned type_ = 0;                         // 0 single, 1 fan, 2 parallelogram (cp::PatternType)
    bool c0_ = false, c1_ = false, c2_ = false; // T0 edges, collapsed
    bool copies_ = false;                       // Type 2 provoking copies (none when e0 or e2 collapse)
    const std::uint16_t* c_ = nullptr;          // column starts C_0..C_{h+1}
    const std::uint32_t* gap_ = nullptr;        // zipper words
    std::uint32_t head_ = 0, n0_ = 0, n1_ = 0, n2_ = 0;
    float a_ = 0.0f, b_ = 0.0f;
    std::uint32_t copy_bias_ = 0;   // copy of A_j in column i >= 1: C_i - i + j + copy_bias_
    bool plain_ = false;            // Type 2 without a T0 edge: the fast paths, no skips
    std::uint32_t fast_strips_ = 0; // strips_ when triangle p < strips_ is strip_triangle(p), else 0
    // Strip buckets: bucket b holds the raw strip triangles [b, b + 1) << bucket_shift_; strip_bucket_[b] is
    // the strip of its first one. From wide_from_ on, a bucket may hold two or more later strip starts. The
    // extra entry is scratch for the constructor's count.
    static constexpr unsigned strip_buckets = 256;
    std::array<std::uint8_t, strip_buckets + 1> strip_bucket_{};
    std::uint32_t bucket_shift_ = 0, wide_from_ = ~0u;
    std::uint32_t clamp_ = 0; // K
    std::uint32_t e1_offset_ = 0, unique_ = 0, strips_ = 0, zipper_ = 0;
    std::uint32_t vertices_ = 0, triangles_ = 0;
    std::array<Skip, 8> tri_skip_{};
    unsigned tri_skips_ = 0;
    std::array<Skip, 4> slot_skip_{};
    unsigned slot_skips_ = 0;
};

inline CpPatch::CpPatch(const CpTableSet& tables, cp::LineState s0, cp::LineState s1,
                        cp::LineState s2) noexcept {
    const unsigned max_factor = cp::pattern_max_factor(tables.max_factor);
    const cp::LineState s[3] = {cp::clamp_line_state(s0, max_factor), cp::clamp_line_state(s1, max_factor),
                                cp::clamp_line_state(s2, max_factor)};
    for (unsigned k = 0; k < 3; ++k) {
        const unsigned shape = s[k].token == 0 ? 1u : s[k].token;
        const cp::tables::TokenRecord& rec = tables.tokens[shape - 1];
        const std::uint32_t t16 = s[k].token == 0 ? 0u : s[k].t16;
        e_[k] = {tables.points + rec.first_point,
                 t16,
                 rec.segments,
                 rec.half_step,
                 s[k].token,
                 static_cast<std::int32_t>(rec.half_step * (65536u - t16))};
    }
    c0_ = s[0].token == 0;
    c1_ = s[1].token == 0;
    c2_ = s[2].token == 0;
    n0_ = e_[0].segments;
    n1_ = e_[1].segments;
    n2_ = e_[2].segments;
    if (c0_ && c1_ && c2_) { // Type 0
        type_ = 0;
        vertices_ = 3;
        triangles_ = 1;
        return;
    }
    if (s[0].token <= 1 && s[2].token <= 1) { // Type 1: n1 + 7 slots, n1 + 6 triangles before the collapse
        type_ = 1;
        std::uint32_t dropped_slots = 0;
        auto drop_slots = [&](std::uint32_t begin, std::uint32_t end) {
            slot_skip_[slot_skips_++] = {begin, end - begin};
            dropped_slots += end - begin;
        };
        if (c0_) drop_slots(1, 3);
        if (c1_) drop_slots(4, 6);
        if (c2_) drop_slots(4 + n1_, c0_ ? 7 + n1_ : 6 + n1_);
        auto drop = [&](bool when, std::uint32_t at) {
            if (when) add_triangle_skip(at, at + 1);
        };
        drop(c0_ || c2_, 0);
        drop(c0_ || c1_, 1);
        drop(c1_ || c2_, 2);
        drop(c0_ && c2_, 3);
        drop(c0_ && c1_, 4);
        drop(c1_ && c2_, n1_ + 3);
        drop(c0_ && c2_, n1_ + 4);
        drop(c0_ && c2_, n1_ + 5);
        std::uint32_t dropped = 0;
        for (unsigned k = 0; k < tri_skips_; ++k) dropped += tri_skip_[k].length;
        vertices_ = n1_ + 7 - dropped_slots;
        triangles_ = n1_ + 6 - dropped;
        return;
    }
    type_ = 2;
    const unsigned shapes = tables.shapes;
    const unsigned sh0 = s[0].token == 0 ? 1u : s[0].token;
    const unsigned sh1 = s[1].token == 0 ? 1u : s[1].token;
    const unsigned sh2 = s[2].token == 0 ? 1u : s[2].token;
    const CpColumnChunk& chunk = tables.column_chunks[tables.chunk_of_shape2[sh2 - 1]];
    const cp::tables::ColumnRecord& rec = chunk.records[(sh2 - chunk.first_shape2) * shapes + sh0 - 1];
    c_ = chunk.pool + rec.offset;
    head_ = rec.head;
    a_ = rec.a;
    b_ = rec.b;
    gap_ = tables.gap_word + tables.gap_offset[(sh1 - 1) * shapes + sh0 - 1];
    const std::uint32_t last0 = point(e_[0], n0_ - 1);
    const std::uint32_t v2 = point(e_[2], sh2 >= 2 ? n2_ - 1 : 1u);
    clamp_ = last0 < v2 ? last0 : v2;
    const std::uint32_t ch = c_[head_];
    strips_ = 2 * ch + 1 - 2 * head_ - n2_;
    zipper_ = n0_ + n1_ - 1;
    e1_offset_ = c0_ ? n2_ : c2_ ? n0_ : ch + n0_ - head_;
    unique_ = e1_offset_ + (c1_ ? 2u : n1_ + 1);
    copies_ = !c0_ && !c2_;
    copy_bias_ = unique_ + 1u - c_[1];
    const std::uint32_t copies = copies_ ? ch - c_[1] - (head_ - 1) : 0u;
    // Triangles the collapse drops (docs/algorithm.md §2.9), as runs of the raw emission order.
    const std::uint32_t z = strips_;
    const std::uint32_t t1_fan = c1_ ? tables.t1_last_fan[sh0 - 1] : 0u;
    if (c0_) {
        add_triangle_skip(0, 2 * n2_ - 2); // strip 0: A0's column merges with column 0
        if (c1_) {
            add_triangle_skip(z, z + 2);
            add_triangle_skip(z + 3, z + 5);
        } else {
            add_triangle_skip(z, z + 1);
            add_triangle_skip(z + n1_, z + n1_ + 1);
        }
    } else if (c2_) {
        const std::uint32_t r1 = c_[2] - c_[1];
        add_triangle_skip(0, r1); // of the strips only strip 0's last triangle (v0, u1, v2) keeps its area
        add_triangle_skip(r1 + 1, strips_);
        if (c1_) {
            add_triangle_skip(z, z + 1);
            if (t1_fan == zipper_ - 1) {
                add_triangle_skip(z + n0_, z + n0_ + 2);
            } else {
                add_triangle_skip(z + t1_fan, z + t1_fan + 1);
                add_triangle_skip(z + zipper_ - 1, z + zipper_);
            }
        } else {
            add_triangle_skip(z + zipper_ - 1, z + zipper_); // the last zipper triangle has v2 twice
        }
    } else if (c1_) {
        add_triangle_skip(z, z + 1); // the fans (R_1, L, R_0) and (R_3, L, R_2) have v1 or v2 twice
        add_triangle_skip(z + t1_fan, z + t1_fan + 1);
    }
    std::uint32_t dropped = 0;
    for (unsigned k = 0; k < tri_skips_; ++k) dropped += tri_skip_[k].length;
    vertices_ = unique_ + copies;
    triangles_ = strips_ + zipper_ - dropped;
    plain_ = !c0_ && !c1_ && !c2_;
    // Without a T0 edge on e0 or e2 the strips have copies and nothing before the zipper is dropped.
    fast_strips_ = copies_ && head_ != 0 ? strips_ : 0u;
    build_strip_buckets();
}

// Bucket b's strip is the number of strips k in [1, h-1] with PS_k <= b << shift: each strip adds one to
// the buckets from ceil(PS_k / width) on. Counting, then a prefix sum: both loops have fixed trip counts and
// selects only, so the constructor pays no misprediction per bucket. A strip start inside a bucket (not on
// its first triangle) is one step of strip_of; two in the same bucket make the patch's buckets wide.
inline void CpPatch::build_strip_buckets() noexcept {
    static_assert(cp::max_segments <= 256, "strip indices (< h < n0) must fit the u8 buckets");
    if (strips_ == 0 || head_ == 0) return;
    while (((strips_ - 1) >> bucket_shift_) >= strip_buckets) ++bucket_shift_;
    const std::uint32_t used = ((strips_ - 1) >> bucket_shift_) + 1;
    const std::uint32_t inside = (1u << bucket_shift_) - 1u;
    const std::uint16_t* c = c_;
    std::uint8_t* count = strip_bucket_.data();
    std::uint32_t last_inner = ~0u; // bucket of the last strip start inside a bucket
    std::uint32_t wide = ~0u;       // first bucket with two
    for (std::uint32_t k = 1; k < head_; ++k) {
        const std::uint32_t ps = c[k] + c[k + 1] - 2 * k - n2_;
        ++count[(ps + inside) >> bucket_shift_];
        const std::uint32_t bucket = (ps & inside) != 0 ? ps >> bucket_shift_ : ~1u;
        wide = bucket == last_inner && bucket < wide ? bucket : wide;
        last_inner = bucket != ~1u ? bucket : last_inner;
    }
    std::uint32_t i = 0;
    for (std::uint32_t b = 0; b < used; ++b) {
        i += count[b];
        count[b] = static_cast<std::uint8_t>(i);
    }
    count[used] = 0;
    wide_from_ = wide == ~0u ? ~0u : wide << bucket_shift_;
}

inline DomainPoint CpPatch::slot_point(std::uint32_t s) const noexcept {
    if (s == 0) return {0, 0};
    if (s <= 2) return {point(e_[0], s), 0};
    if (s <= 3 + n1_) return e1_point(point(e_[1], s - 3));
    if (s == 4 + n1_) return {0, point(e_[2], 2)};
    if (s == 5 + n1_) return {0, point(e_[2], 1)};
    return cp::type1_center(e_[0].t16, e_[2].t16);
}

inline std::uint32_t CpPatch::slot_index(std::uint32_t s) const noexcept {
    if (c1_ && s == 4) s = 3;
    if (c1_ && s == 5) s = 3 + n1_;
    if (c2_ && s == 5 + n1_) s = 0;
    if (c2_ && s == 4 + n1_) s = 3 + n1_;
    if (c0_ && s == 1) s = 0;
    if (c0_ && s == 2) s = 3;
    if (c0_ && c2_ && s == 6 + n1_) s = 0;
    std::uint32_t below = 0;
    for (unsigned k = 0; k < slot_skips_; ++k) below += s > slot_skip_[k].begin ? slot_skip_[k].length : 0u;
    return s - below;
}

inline CpTriangle CpPatch::type1_triangle(std::uint32_t r) const noexcept {
    std::uint32_t a = 0, b = 0, c = 0;
    if (r == 0) {
        a = 0, b = 1, c = 5 + n1_;
    } else if (r == 1) {
        a = 3, b = 4, c = 2;
    } else if (r == 2) {
        a = 3 + n1_, b = 4 + n1_, c = 2 + n1_;
    } else {
        a = hexagon_slot(r - 2), b = 6 + n1_, c = hexagon_slot(r - 3);
    }
    return {slot_index(a), slot_index(b), slot_index(c)};
}

// Copy k = v - unique_ of the provoking layout is column i >= 1, row j, with k = D_i + j and
// D_i = Y_i - Y_1, Y_x = C_x - x: i is the largest with Y_i <= t = k + Y_1. As PS_i = Y_i + Y_{i+1} + 1 - R_0
// and Y does not decrease, the strip of r = 2t + 1 - R_0 is i - 1 or i: the strip buckets and one step find
// it. The columns' own points keep the float first guess of cp_search.hpp.
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
    auto y = [c](int x) { return static_cast<int>(c[x]); };
    const std::uint32_t i =
        search_from(y, head_, static_cast<int>(v), search_first_guess(a_, b_, static_cast<float>(v), head_));
    return column_point(i, v - c[i]);
}

// Strip triangle r of a patch without a T0 edge on e0 or e2 (so col_index(i, j) = C_i + j and every column
// i >= 1 has copies). Strip i joins column i (A, a = C_i) and column i + 1 (B, b = C_{i+1}, nb rows): cells
// (A_j, B_j, A_{j+1}) and (B_j, B_{j+1}, A_{j+1}) for j < nb - 1, then the fan (A_j, B_{nb-1}, A_{j+1}).
// With o = r - PS_i and m = min(o, 2 (nb - 1)), triangle o has taken s = ceil(m / 2) steps on B and o - s
// on A, and it is an odd cell when m is odd: one formula for all three kinds, no branch.
inline CpTriangle CpPatch::strip_triangle(std::uint32_t r) const noexcept {
    const std::uint16_t* col = nullptr;
    const std::uint32_t i = strip_of(r, col);
    const std::uint32_t a = col[0], b = col[1], cells = 2 * (col[2] - b - 1u);
    const std::uint32_t o = r + n2_ + 2 * i - a - b;
    const std::uint32_t m = o < cells ? o : cells;
    const std::uint32_t s = (m + 1) >> 1, j = o - s;
    // First vertex A_j of column i >= 1 already provoked a triangle of strip i - 1: use its copy.
    // A mask, not a ternary: GCC branches on the ternary, and strip 0 holds a large share of the triangles.
    const std::uint32_t first = a + j + ((copy_bias_ - i) & (0u - static_cast<std::uint32_t>(i != 0)));
    const std::uint32_t odd = 0u - (m & 1u); // all ones: odd cell, whose first vertex is B_j
    return {first + ((b + s - 1 - first) & odd), b + s, a + j + 1};
}

// Zipper triangle q of a patch without a T0 edge: L_a = top of column n0-1-a = C_{n0-a} - 1, R_b = e1 point
// b.
inline CpTriangle CpPatch::zipper_triangle(std::uint32_t q) const noexcept {
    const std::uint32_t w = gap_[q / cp::tables::gap_bits_per_word];
    const std::uint32_t bit = q % cp::tables::gap_bits_per_word;
    const std::uint32_t bits = w & 0xFFFFu;
    const std::uint32_t a = (w >> 16) + popcount16(bits & ((1u << bit) - 1u));
    const std::uint32_t b = q - a;
    const std::uint32_t lhs = 0u - ((bits >> bit) & 1u); // all ones: a step on L; a mask, see strip_triangle
    auto top = [this](std::uint32_t col) { // C_col - 1 for col in [0, n0]; the tail has one row per column
        const std::uint32_t k = col < head_ ? col : head_;
        return c_[k] + (col - k) - 1u;
    };
    const std::uint32_t la = top(n0_ - a);
    const std::uint32_t rb = e1_offset_ + b;
    return {rb + 1 + ((top(n0_ - a - 1) - rb - 1) & lhs), la, rb};
}

inline CpTriangle CpPatch::type2_triangle(std::uint32_t r) const noexcept {
    if (!c0_ && !c1_ && !c2_) return r < strips_ ? strip_triangle(r) : zipper_triangle(r - strips_);
    if (r < strips_) {
        if (copies_) return strip_triangle(r);
        const std::uint16_t* c = c_;
        const std::uint32_t i = strip_of(r);
        const std::uint32_t o = r - (c[i] + c[i + 1] - 2 * i - n2_);
        const std::uint32_t nb = static_cast<std::uint32_t>(c[i + 2] - c[i + 1]);
        if (o < 2 * (nb - 1)) {
            const std::uint32_t j = o >> 1;
            if (o & 1u) return {col_index(i + 1, j), col_index(i + 1, j + 1), col_index(i, j + 1)};
            return {col_index(i, j), col_index(i + 1, j), col_index(i, j + 1)};
        }
        const std::uint32_t j = o - (nb - 1);
        return {col_index(i, j), col_index(i + 1, nb - 1), col_index(i, j + 1)};
    }
    const std::uint32_t q = r - strips_;
    const std::uint32_t w = gap_[q / cp::tables::gap_bits_per_word];
    const std::uint32_t bit = q % cp::tables::gap_bits_per_word;
    const std::uint32_t bits = w & 0xFFFFu;
    const std::uint32_t a = (w >> 16) + popcount16(bits & ((1u << bit) - 1u));
    const std::uint32_t b = q - a;
    if ((bits >> bit) & 1u) return {lhs_index(a + 1), lhs_index(a), e1_index(b)};
    return {e1_index(b + 1), lhs_index(a), e1_index(b)};
}

inline DomainPoint CpPatch::vertex(std::uint32_t i) const noexcept {
    if (i >= vertices_) return {0, 0};
    if (type_ == 2) return type2_vertex(i);
    if (type_ == 1) return slot_point(skip_forward(slot_skip_.data(), slot_skips_, i));
    return i == 0   ? DomainPoint{0, 0}
           : i == 1 ? DomainPoint{cp::fixed_one, 0}
                    : DomainPoint{0, cp::fixed_one};
}

inline CpTriangle CpPatch::triangle(std::uint32_t p) const noexcept {
    if (p >= triangles_) return {0, 0, 0};
    if (p < fast_strips_) return strip_triangle(p);
    if (plain_) return zipper_triangle(p - strips_);
    const std::uint32_t r = skip_forward(tri_skip_.data(), tri_skips_, p);
    if (type_ == 2) return type2_triangle(r);
    if (type_ == 1) return type1_triangle(r);
    return {0, 1, 2};
}

// Type 2 without a T0 edge: columns, copies, strips and zipper written in one pass each.
inline void CpPatch::emit_type2_plain(DomainPoint* out_v, std::uint32_t* out_i) const noexcept {
    const std::uint16_t* c = c_;
    for (std::uint32_t j = 0; j < n2_; ++j) out_v[j] = {0, point(e_[2], j)};
    for (std::uint32_t i = 1; i < n0_; ++i) {
        const std::uint32_t u = point(e_[0], i);
        const std::uint32_t top = clamp_ > u ? clamp_ - u : 0u;
        const std::uint32_t first = col_start(i), rows = col_rows(i);
        for (std::uint32_t j = 0; j < rows; ++j) {
            const std::uint32_t v2 = point(e_[2], j);
            out_v[first + j] = {u, v2 < top ? v2 : top};
        }
    }
    for (std::uint32_t b = 0; b <= n1_; ++b) out_v[e1_offset_ + b] = e1_point(point(e_[1], b));
    std::uint32_t copy = unique_;
    for (std::uint32_t i = 1; i < head_; ++i)
        for (std::uint32_t j = 0; j + 1 < static_cast<std::uint32_t>(c[i + 1] - c[i]); ++j)
            out_v[copy++] = out_v[c[i] + j];

    std::uint32_t* o = out_i;
    copy = unique_;
    for (std::uint32_t i = 0; i < head_; ++i) {
        const std::uint32_t a = c[i], b = c[i + 1];
        const std::uint32_t na = b - a, nb = c[i + 2] - b;
        const std::uint32_t first = i >= 1 ? copy : a;
        for (std::uint32_t j = 0; j + 1 < nb; ++j) {
            o[0] = first + j, o[1] = b + j, o[2] = a + j + 1;
            o[3] = b + j, o[4] = b + j + 1, o[5] = a + j + 1;
            o += 6;
        }
        for (std::uint32_t j = nb - 1; j + 1 < na; ++j) {
            o[0] = first + j, o[1] = b + nb - 1, o[2] = a + j + 1;
            o += 3;
        }
        if (i >= 1) copy += na - 1;
    }
    // Zipper: L_a = top of column n0-1-a = C_{n0-a} - 1.
    std::uint32_t la = col_start(n0_) - 1, a = 0, rb = e1_offset_;
    for (std::uint32_t q = 0; q < zipper_; ++q) {
        const std::uint32_t w = gap_[q / cp::tables::gap_bits_per_word];
        if ((w >> (q % cp::tables::gap_bits_per_word)) & 1u) {
            ++a;
            const std::uint32_t next = col_start(n0_ - a) - 1;
            o[0] = next, o[1] = la, o[2] = rb;
            la = next;
        } else {
            o[0] = rb + 1, o[1] = la, o[2] = rb;
            ++rb;
        }
        o += 3;
    }
}

inline bool CpPatch::emit(std::span<DomainPoint> vertices, std::span<std::uint32_t> indices) const noexcept {
    if (vertices.size() < vertices_ || indices.size() / 3 < triangles_) return false;
    if (type_ == 2 && !c0_ && !c1_ && !c2_) {
        emit_type2_plain(vertices.data(), indices.data());
        return true;
    }
    for (std::uint32_t v = 0; v < vertices_; ++v) vertices[v] = vertex(v);
    for (std::uint32_t p = 0; p < triangles_; ++p) {
        const CpTriangle t = triangle(p);
        indices[3 * p] = t[0], indices[3 * p + 1] = t[1], indices[3 * p + 2] = t[2];
    }
    return true;
}

} // namespace ctess::rt
