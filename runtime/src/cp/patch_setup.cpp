// CpPatchSetup's construction (the pattern type, the columns, the counts and the T0 collapse's dropped
// runs), the paths of random access that are not hot (Type 0 and 1, the collapse), and CpPatch's strip
// buckets. docs/algorithm.md §2.
#include <ctess/cp/edge_line.hpp>
#include <ctess/cp/type1.hpp>
#include <ctess/runtime/cp/patch.hpp>

namespace ctess::rt {

// The constructor's steps, inline: each is called once, and the embedded build keeps one function.
// Each edge's points, lerp and segments from its token's record; a T0 edge (token 0) takes shape 1's points
// and collapses.
inline void CpPatchSetup::set_edges(const CpTableSet& tables, const cp::LineState (&s)[3],
                                    unsigned (&shape)[3]) noexcept {
    for (unsigned k = 0; k < 3; ++k) {
        shape[k] = s[k].token == 0 ? 1u : s[k].token;
        const cp::tables::TokenRecord& rec = tables.tokens[shape[k] - 1];
        const std::uint32_t t16 = s[k].t16; // 0 for T0 (cp::clamp_line_state, line_state)
        e_[k] = {tables.points + rec.first_point, t16, rec.segments,
                 static_cast<std::int32_t>(rec.half_step * (65536u - t16))};
    }
    c0_ = s[0].token == 0;
    c1_ = s[1].token == 0;
    c2_ = s[2].token == 0;
    n0_ = e_[0].segments;
    n1_ = e_[1].segments;
    n2_ = e_[2].segments;
}

// Type 1: n1 + 7 slots and n1 + 6 triangles before the collapse (docs/algorithm.md §2.8), T0 edges' slots
// and triangles skipped.
inline void CpPatchSetup::set_fan() noexcept {
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
}

// Triangles the collapse drops (docs/algorithm.md §2.9), as runs of the raw emission order.
inline void CpPatchSetup::skip_collapsed_triangles(const CpTableSet& tables,
                                                   const unsigned (&shape)[3]) noexcept {
    const std::uint32_t z = strips_;
    t1_fan_ = c1_ ? tables.t1_last_fan[shape[0] - 1] : 0u;
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
            if (t1_fan_ == zipper_ - 1) {
                add_triangle_skip(z + n0_, z + n0_ + 2);
            } else {
                add_triangle_skip(z + t1_fan_, z + t1_fan_ + 1);
                add_triangle_skip(z + zipper_ - 1, z + zipper_);
            }
        } else {
            add_triangle_skip(z + zipper_ - 1, z + zipper_); // the last zipper triangle has v2 twice
        }
    } else if (c1_) {
        add_triangle_skip(z, z + 1); // the fans (R_1, L, R_0) and (R_3, L, R_2) have v1 or v2 twice
        add_triangle_skip(z + t1_fan_, z + t1_fan_ + 1);
    }
}

// Type 2: the column record of (e2, e0), the strips, the zipper and the e1 offset; the provoking copies.
inline void CpPatchSetup::set_parallelogram(const CpTableSet& tables, const unsigned (&shape)[3],
                                            bool counts_only) noexcept {
    type_ = 2;
    const unsigned shapes = tables.shapes;
    const CpColumnChunk& chunk = tables.column_chunks[tables.chunk_of_shape2[shape[2] - 1]];
    const cp::tables::ColumnRecord& rec =
        chunk.records[(shape[2] - chunk.first_shape2) * shapes + shape[0] - 1];
    c_ = chunk.pool + rec.offset;
    head_ = rec.head;
    if (!counts_only) {
        gap_ = tables.gap_word + tables.gap_offset[(shape[1] - 1) * shapes + shape[0] - 1];
        const std::uint32_t last0 = point(e_[0], n0_ - 1);
        const std::uint32_t v2 = point(e_[2], shape[2] >= 2 ? n2_ - 1 : 1u);
        clamp_ = last0 < v2 ? last0 : v2;
    }
    const std::uint32_t ch = c_[head_];
    strips_ = 2 * ch + 1 - 2 * head_ - n2_;
    zipper_ = n0_ + n1_ - 1;
    e1_offset_ = c0_ ? n2_ : c2_ ? n0_ : ch + n0_ - head_;
    unique_ = e1_offset_ + (c1_ ? 2u : n1_ + 1);
    plain_strips_ = !c0_ && !c2_;
    const bool copies = plain_strips_ && options_.layout == Layout::provoking;
    copy_mask_ = copies ? ~0u : 0u;
    copy_bias_ = unique_ + 1u - c_[1];
    skip_collapsed_triangles(tables, shape);
    std::uint32_t dropped = 0;
    for (unsigned k = 0; k < tri_skips_; ++k) dropped += tri_skip_[k].length;
    // Copies: every row but the top of columns 1..h-1 provokes a triangle of the strip before it too.
    vertices_ = unique_ + (copies ? ch - c_[1] - (head_ - 1) : 0u);
    triangles_ = strips_ + zipper_ - dropped;
    plain_ = !c0_ && !c1_ && !c2_;
    fast_strips_ = plain_strips_ && head_ != 0 ? strips_ : 0u;
}

CpPatchSetup::CpPatchSetup(const CpTableSet& tables, cp::LineState s0, cp::LineState s1, cp::LineState s2,
                           PatchOptions options, unsigned setup) noexcept
    : options_(options) {
    // The two table sets' maxima as constants, so that the token count folds (no log2 loop per call).
    auto clamp = [max = tables.max_factor](cp::LineState state) {
        return max == 64    ? cp::clamp_line_state(state, 64)
               : max == 256 ? cp::clamp_line_state(state, 256)
                            : cp::clamp_line_state(state, max);
    };
    const bool clamped = (setup & setup_clamped) != 0; // line_state() gives states in range
    const cp::LineState s[3] = {clamped ? s0 : clamp(s0), clamped ? s1 : clamp(s1), clamped ? s2 : clamp(s2)};
    cw_mask_ = options.winding == Winding::cw ? ~0u : 0u;
    unsigned shape[3];
    set_edges(tables, s, shape);
    // Type 2 first: it is what every factor above 2 on e0 or e2 gives (docs/algorithm.md §2.2).
    if (s[0].token > 1 || s[2].token > 1) {
        set_parallelogram(tables, shape, (setup & setup_counts_only) != 0);
    } else if (c0_ && c1_ && c2_) { // Type 0
        type_ = 0;
        vertices_ = 3;
        triangles_ = 1;
    } else {
        set_fan();
    }
}

Counts cp_counts(const CpTableSet& tables, cp::LineState s0, cp::LineState s1, cp::LineState s2,
                 PatchOptions options) noexcept {
    return CpPatchSetup(tables, s0, s1, s2, options, CpPatchSetup::setup_counts_only).counts();
}

bool CpPatchSetup::dropped(std::uint32_t r) const noexcept {
    for (unsigned k = 0; k < tri_skips_; ++k)
        if (r - tri_skip_[k].begin < tri_skip_[k].length) return true;
    return false;
}

DomainPoint CpPatchSetup::slot_point(std::uint32_t s) const noexcept {
    if (s == 0) return {0, 0};
    if (s <= 2) return {point(e_[0], s), 0};
    if (s <= 3 + n1_) return e1_point(point(e_[1], s - 3));
    if (s == 4 + n1_) return {0, point(e_[2], 2)};
    if (s == 5 + n1_) return {0, point(e_[2], 1)};
    return cp::type1_center(e_[0].t16, e_[2].t16);
}

std::uint32_t CpPatchSetup::slot_index(std::uint32_t s) const noexcept {
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

DomainPoint CpPatchSetup::small_vertex(std::uint32_t i) const noexcept {
    if (type_ == 1) return slot_point(skip_forward(slot_skip_.data(), slot_skips_, i));
    return i == 0   ? DomainPoint{0, 0}
           : i == 1 ? DomainPoint{cp::fixed_one, 0}
                    : DomainPoint{0, cp::fixed_one};
}

// Type 1 slots: v0, A0, B0, e1 points 0..n1, B2, A2, P (cp::Type1Slots); the hexagon is the boundary loop
// without v0.
CpTriangle CpPatchSetup::collapsed_triangle(std::uint32_t r) const noexcept {
    if (type_ == 0) return wind(0, 1, 2);
    auto hexagon_slot = [m = n1_ + 3, n1 = n1_](std::uint32_t k) -> std::uint32_t {
        k %= m;
        if (k == 0) return 1;
        if (k == 1) return 2;
        if (k < m - 2) return 3 + (k - 1);
        return k == m - 2 ? 4 + n1 : 5 + n1;
    };
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
    return wind(slot_index(a), slot_index(b), slot_index(c));
}

CpTriangle CpPatchSetup::collapsed_strip_triangle(std::uint32_t i, std::uint32_t r) const noexcept {
    if (plain_strips_) return plain_strip_triangle(i, r);
    const std::uint16_t* c = c_;
    const std::uint32_t o = r - (c[i] + c[i + 1] - 2 * i - n2_);
    const std::uint32_t nb = static_cast<std::uint32_t>(c[i + 2] - c[i + 1]);
    if (o < 2 * (nb - 1)) {
        const std::uint32_t j = o >> 1;
        if (o & 1u) return wind(col_index(i + 1, j), col_index(i + 1, j + 1), col_index(i, j + 1));
        return wind(col_index(i, j), col_index(i + 1, j), col_index(i, j + 1));
    }
    const std::uint32_t j = o - (nb - 1);
    return wind(col_index(i, j), col_index(i + 1, nb - 1), col_index(i, j + 1));
}

CpTriangle CpPatchSetup::collapsed_zipper_triangle(std::uint32_t q) const noexcept {
    const std::uint32_t w = gap_[q / cp::tables::gap_bits_per_word];
    const std::uint32_t bit = q % cp::tables::gap_bits_per_word;
    const std::uint32_t bits = w & 0xFFFFu;
    const std::uint32_t a = (w >> 16) + popcount16(bits & ((1u << bit) - 1u));
    const std::uint32_t b = q - a;
    if ((bits >> bit) & 1u) return wind(lhs_index(a + 1), lhs_index(a), e1_index(b));
    return wind(e1_index(b + 1), lhs_index(a), e1_index(b));
}

namespace {

// Bucket b's entry is the number of k in [1, n) with S_k <= b << shift: each S_k adds one to the buckets
// from ceil(S_k / width) on. Counting, then a prefix sum: both loops have fixed trip counts and selects only,
// so the constructor pays no misprediction per bucket. A start inside a bucket (not on its first element) is
// one step of the lookup; two in the same bucket make the buckets from there on wide.
template <class Start>
void build(CpBuckets& buckets, std::uint32_t total, std::uint32_t n, Start start) noexcept {
    static_assert(cp::max_segments <= 256, "strip and column indices (< h < n0) must fit the u8 buckets");
    if (total == 0 || n == 0) return;
    std::uint32_t shift = 0;
    while (((total - 1) >> shift) >= CpBuckets::size) ++shift;
    const std::uint32_t used = ((total - 1) >> shift) + 1;
    const std::uint32_t inside = (1u << shift) - 1u;
    std::uint8_t* count = buckets.first.data();
    std::uint32_t last_inner = ~0u; // bucket of the last start inside a bucket
    std::uint32_t wide = ~0u;       // first bucket with two
    for (std::uint32_t k = 1; k < n; ++k) {
        const std::uint32_t s = start(k);
        ++count[(s + inside) >> shift];
        const std::uint32_t bucket = (s & inside) != 0 ? s >> shift : ~1u;
        wide = bucket == last_inner && bucket < wide ? bucket : wide;
        last_inner = bucket != ~1u ? bucket : last_inner;
    }
    std::uint32_t i = 0;
    for (std::uint32_t b = 0; b < used; ++b) {
        i += count[b];
        count[b] = static_cast<std::uint8_t>(i);
    }
    count[used] = 0;
    buckets.shift = shift;
    buckets.wide_from = wide == ~0u ? ~0u : wide << shift;
}

} // namespace

// The strips (for triangle(p) and the copies' vertex(i)), and the head columns (for the columns' own
// vertex(i), where the columns are plain).
void CpPatch::build_buckets() noexcept {
    if (type_ != 2 || head_ == 0) return;
    const std::uint16_t* c = c_;
    const std::uint32_t n2 = n2_;
    build(strip_buckets_, strips_, head_, [c, n2](std::uint32_t k) { return c[k] + c[k + 1] - 2 * k - n2; });
    if (plain_strips_)
        build(column_buckets_, c[head_], head_, [c](std::uint32_t k) { return std::uint32_t{c[k]}; });
}

} // namespace ctess::rt
