// CpPatchSetup::emit: the whole pattern in emission order, without the random-access lookups
// (docs/algorithm.md §2). A patch without a T0 edge takes the fast path: the edge points once; each column
// as column 0's (0, v) pairs with u put in, a vector of rows at a time, written to the column and to its
// provoking copies; each strip's cells four at a time (24 indices, lanes that grow by 4 per step); the
// zipper without a branch per triangle. The vector types are GCC/Clang vector extensions, 16 bytes (SSE2 on
// x86-64, NEON on AArch64, plain scalar code on a Cortex-M), and on x86-64 a second build of the same body
// with 32-byte vectors for AVX2, chosen at run time. Patches with a T0 edge take the raw emission order and
// skip what the collapse drops.
#include <cstring>

#include <ctess/runtime/cp/patch.hpp>

#define CTESS_ALWAYS_INLINE [[gnu::always_inline]] inline

// x86-64 with GCC or Clang: an AVX2 build of the fast path (32-byte stores, half as many), chosen at run
// time.
#if defined(__x86_64__) && defined(__GNUC__)
#define CTESS_EMIT_AVX2 1
#else
#define CTESS_EMIT_AVX2 0
#endif

namespace ctess::rt {

namespace {

using u32x4 = std::uint32_t __attribute__((vector_size(16)));

// By reference and always inline: a 32-byte vector passed by value outside an AVX function would change the
// ABI (-Wpsabi).
template <class V>
CTESS_ALWAYS_INLINE void store(void* out, const V& v) noexcept {
    std::memcpy(out, &v, sizeof v);
}

// Out parameters, not return values, for the same reason.
template <class V>
CTESS_ALWAYS_INLINE void load(V& v, const std::uint32_t* in) noexcept {
    std::memcpy(&v, in, sizeof v);
}

template <class V>
CTESS_ALWAYS_INLINE void even_lanes(V& m) noexcept {
    m = V{};
    for (unsigned k = 0; k < sizeof(V) / sizeof(std::uint32_t); k += 2) m[k] = ~0u;
}

// Four strip cells j..j+3 as 24 lanes: cell c is (A_{j+c}, B_{j+c}, A_{j+c+1}), (B_{j+c}, B_{j+c+1},
// A_{j+c+1}), wound; lane k is (first, a or b by the masks) + add, with first = A_0 or its copy, a = C_i,
// b = C_{i+1}.
struct CellLanes {
    std::uint32_t f[24], a[24], b[24], add[24];
};
constexpr CellLanes make_cell_lanes(bool clockwise) {
    // One cell, counter-clockwise: F B A+1 | B B+1 A+1 (0 = first, 1 = a, 2 = b).
    unsigned src[6] = {0, 2, 1, 2, 2, 1};
    std::uint32_t add[6] = {0, 0, 1, 0, 1, 1};
    if (clockwise) {
        for (unsigned t = 0; t < 2; ++t) {
            const unsigned s1 = src[3 * t + 1];
            const std::uint32_t a1 = add[3 * t + 1];
            src[3 * t + 1] = src[3 * t + 2], add[3 * t + 1] = add[3 * t + 2];
            src[3 * t + 2] = s1, add[3 * t + 2] = a1;
        }
    }
    CellLanes l{};
    for (unsigned k = 0; k < 24; ++k) {
        l.f[k] = src[k % 6] == 0 ? ~0u : 0u;
        l.a[k] = src[k % 6] == 1 ? ~0u : 0u;
        l.b[k] = src[k % 6] == 2 ? ~0u : 0u;
        l.add[k] = add[k % 6] + k / 6;
    }
    return l;
}
constexpr CellLanes cell_lanes[2] = {make_cell_lanes(false), make_cell_lanes(true)};

} // namespace

// The fast path of a patch without a T0 edge, for a vector of W lanes; a friend of CpPatchSetup.
struct CpPatchEmitter {
    template <class V>
    static void plain(const CpPatchSetup& p, DomainPoint* out_v, std::uint32_t* out_i) noexcept;
    static void plain_baseline(const CpPatchSetup& p, DomainPoint* out_v, std::uint32_t* out_i) noexcept;
#if CTESS_EMIT_AVX2
    __attribute__((target("avx2"))) static void plain_avx2(const CpPatchSetup& p, DomainPoint* out_v,
                                                           std::uint32_t* out_i) noexcept;
#endif
};

bool CpPatchSetup::emit(std::span<DomainPoint> vertices, std::span<std::uint32_t> indices) const noexcept {
    if (vertices.size() < vertices_ || indices.size() / 3 < triangles_) return false;
    if (!plain_) emit_collapsed(vertices.data(), indices.data());
#if CTESS_EMIT_AVX2
    // __builtin_cpu_init is a no-op once done; it makes the check valid even before libgcc's constructor ran
    // (an emit() from another static constructor).
    else if ((__builtin_cpu_init(), __builtin_cpu_supports("avx2")))
        CpPatchEmitter::plain_avx2(*this, vertices.data(), indices.data());
#endif
    else
        CpPatchEmitter::plain_baseline(*this, vertices.data(), indices.data());
    return true;
}

void CpPatchSetup::emit_baseline(DomainPoint* vertices, std::uint32_t* indices) const noexcept {
    if (plain_)
        CpPatchEmitter::plain_baseline(*this, vertices, indices);
    else
        emit_collapsed(vertices, indices);
}

template <class V>
CTESS_ALWAYS_INLINE void CpPatchEmitter::plain(const CpPatchSetup& p, DomainPoint* out_v,
                                               std::uint32_t* out_i) noexcept {
    constexpr unsigned W = sizeof(V) / sizeof(std::uint32_t); // lanes: 4 (SSE2, NEON) or 8 (AVX2)
    // The members as locals: the output is uint32_t too, so the compiler would reload them after every store.
    const std::uint16_t* const c = p.c_;
    const std::uint32_t n0 = p.n0_, n1 = p.n1_, n2 = p.n2_, head = p.head_, clamp = p.clamp_,
                        e1_offset = p.e1_offset_;
    auto start = [c, head](std::uint32_t i) { // col_start
        const std::uint32_t k = i < head ? i : head;
        return c[k] + (i - k);
    };
    // Column 0 as (0, v) pairs: column i is (u_i, min(v_j, K - u_i)), W / 2 rows a vector. Written to the
    // output in the same loop: a separate memcpy of n2 points was a `rep movsq`, whose start-up cost is a
    // large part of a small patch. The pairs past n2 are zero: the columns read whole vectors.
    constexpr std::uint32_t half = W / 2;
    // A typedef: GCC drops a dependent vector_size on an alias declaration (S would be a plain int).
    typedef std::int32_t S __attribute__((vector_size(sizeof(V))));
    static_assert(sizeof(S) == sizeof(V));
    alignas(32) std::uint32_t column0[2 * (cp::max_segments + half)];
    column0[0] = 0, column0[1] = 0;
    out_v[0] = {0, 0};
    for (std::uint32_t j = 1; j < n2; ++j) {
        const std::uint32_t v = CpPatchSetup::interior_point(p.e_[2], p.e_[2].points[j - 1]);
        column0[2 * j] = 0;
        column0[2 * j + 1] = v;
        out_v[j] = {0, v};
    }
    store(column0 + 2 * n2, V{});
    const bool copies = p.copy_mask_ != 0;
    DomainPoint* copy = out_v + p.unique_;
    DomainPoint* const copies_end = out_v + p.vertices_;
    V even; // all ones in the u lanes
    even_lanes(even);
    for (std::uint32_t i = 1; i < n0; ++i) {
        const std::uint32_t u = CpPatchSetup::interior_point(p.e_[0], p.e_[0].points[i - 1]);
        const std::uint32_t top = clamp > u ? clamp - u : 0u;
        const std::uint32_t first_row = start(i), rows = start(i + 1) - first_row;
        DomainPoint* col = out_v + first_row;
        // Every row is column 0's pair with u put in and v clamped to K - u (the rows above the clamp line,
        // usually the top one or none, take K - u): an or and a min, whole vectors, no scalar tail. The
        // stores run up to half - 1 points past the column, into the next column or e1's points (n1 + 1 >= 4
        // points), which are written after it. The min is signed (SSE2 compares signed 32-bit lanes only):
        // every coordinate is at most 2^24, and the u lanes' limit is 2^31 - 1.
        const V lane_u = even & u, limit = (even & 0x7FFFFFFFu) | top;
        const std::uint32_t vectors = (rows + half - 1) / half;
        // Rows 0..rows-2 of a column i < h provoke a triangle of strip i - 1 too: copies, in the same
        // stores while whole vectors stay inside the vertex span (the next column's copies overwrite the
        // rest); the last columns' copies row by row.
        const bool with_copies = copies && i < head;
        const bool whole_copies = with_copies && copy + vectors * half <= copies_end;
        for (std::uint32_t k = 0; k < vectors; ++k) {
            V w;
            load(w, column0 + 2 * half * k);
            w |= lane_u;
            w = (S)w < (S)limit ? w : limit;
            store(col + half * k, w);
            if (whole_copies) store(copy + half * k, w);
        }
        if (with_copies) {
            if (!whole_copies) {
                for (std::uint32_t j = 0; j + 1 < rows; ++j) {
                    const std::uint32_t v = column0[2 * j + 1];
                    copy[j] = {u, v < top ? v : top}; // not re-read from col: a store-forwarding stall
                }
            }
            copy += rows - 1;
        }
    }
    // e1's points: its two corners, then the interior points without point()'s selects.
    DomainPoint* const e1 = out_v + e1_offset;
    e1[0] = CpPatchSetup::e1_point(0);
    for (std::uint32_t b = 1; b < n1; ++b)
        e1[b] = CpPatchSetup::e1_point(CpPatchSetup::interior_point(p.e_[1], p.e_[1].points[b - 1]));
    e1[n1] = CpPatchSetup::e1_point(cp::fixed_one);

    // Strips: cells (A_j, B_j, A_{j+1}), (B_j, B_{j+1}, A_{j+1}), then the fan (A_j, B_{nb-1}, A_{j+1}),
    // A_j's copy first in columns i >= 1 (provoking layout).
    const std::uint32_t swap = p.cw_mask_ & 1u; // lane of b in (a, b, c): 1, or 2 when clockwise
    const CellLanes& lanes = cell_lanes[swap];
    std::uint32_t* o = out_i;
    std::uint32_t next_copy = p.unique_;
    for (std::uint32_t i = 0; i < head; ++i) {
        const std::uint32_t a = c[i], b = c[i + 1];
        const std::uint32_t na = b - a, nb = c[i + 2] - b;
        const std::uint32_t first = i >= 1 && copies ? next_copy : a;
        // Each lane is first, a or b plus a constant: masks, no trip through memory (a vector loaded right
        // after scalar stores to it would stall on store forwarding).
        const std::uint32_t cells = nb - 1;
        if (cells != 0) {
            // 24 lanes (four cells) in 24 / W vectors; with W = 4 the last three are the first three plus 2.
            constexpr unsigned count = 24 / W, from_table = 12 % W == 0 ? 12 / W : count;
            const V sf = V{} + first, sa = V{} + a, sb = V{} + b;
            V v[count];
#pragma GCC unroll 8
            for (unsigned k = 0; k < from_table; ++k) {
                V mask_f, mask_a, mask_b, add;
                load(mask_f, lanes.f + W * k), load(mask_a, lanes.a + W * k), load(mask_b, lanes.b + W * k);
                load(add, lanes.add + W * k);
                v[k] = ((sf & mask_f) | (sa & mask_a) | (sb & mask_b)) + add;
            }
#pragma GCC unroll 8
            for (unsigned k = from_table; k < count; ++k) v[k] = v[k - from_table] + 2;
            std::uint32_t j = 0;
            for (; j + 4 <= cells; j += 4) {
#pragma GCC unroll 8
                for (unsigned k = 0; k < count; ++k) {
                    store(o + W * k, v[k]);
                    v[k] += 4;
                }
                o += 24;
            }
            // The last 1-3 cells (6 lanes each) in whole vectors: up to W - 2 lanes past them, which the fan,
            // the next strip or the zipper (at least 5 triangles, 15 indices) rewrite.
            const std::uint32_t rem = cells - j;
            const unsigned stores = (6 * rem + W - 1) / W;
#pragma GCC unroll 8
            for (unsigned k = 0; k < count; ++k) // a fixed trip count keeps v in registers
                if (k < stores) store(o + W * k, v[k]);
            o += 6 * rem;
        }
        const std::uint32_t tip = b + nb - 1;
        for (std::uint32_t j = nb - 1; j + 1 < na; ++j) {
            o[0] = first + j, o[1 + swap] = tip, o[2 - swap] = a + j + 1;
            o += 3;
        }
        if (i >= 1) next_copy += na - 1;
    }
    // Zipper: L_a = top of column n0-1-a = C_{n0-a} - 1, R_b = e1 point b; a gap bit says which side steps.
    // Triangle q is (L_{a+1} on a step on L, else R_{b+1}; L_a; R_b): the tops first, so that the loop is
    // two loads and a select per triangle (the bits are a coin toss to a branch predictor).
    std::uint32_t tops[cp::max_segments + 1];
    for (std::uint32_t i = 0; i < head; ++i) tops[n0 - i] = c[i] - 1u; // C_i - 1 for i < h
    for (std::uint32_t i = head; i <= n0; ++i) tops[n0 - i] = c[head] + (i - head) - 1u;
    const std::uint32_t* const gap = p.gap_;
    std::uint32_t a = 0, rb = e1_offset;
    // One gap word per gap_bits_per_word triangles, its bits shifted out one per triangle.
    for (std::uint32_t q = 0, zipper = p.zipper_; q < zipper; q += cp::tables::gap_bits_per_word) {
        std::uint32_t bits = gap[q / cp::tables::gap_bits_per_word];
        const std::uint32_t left = zipper - q;
        const std::uint32_t run = left < cp::tables::gap_bits_per_word ? left : cp::tables::gap_bits_per_word;
        for (std::uint32_t k = 0; k < run; ++k) {
            const std::uint32_t step = bits & 1u;
            bits >>= 1;
            const std::uint32_t on_l = 0u - step; // a mask: GCC turns the ternary into a branch
            o[0] = (tops[a + 1] & on_l) | ((rb + 1) & ~on_l), o[1 + swap] = tops[a], o[2 - swap] = rb;
            a += step;
            rb += step ^ 1u;
            o += 3;
        }
    }
}

// Patches with a T0 edge (and Types 0 and 1): the raw emission order, skipping the triangles the collapse
// drops.
void CpPatchSetup::emit_collapsed(DomainPoint* out_v, std::uint32_t* out_i) const noexcept {
    std::uint32_t* o = out_i;
    auto put = [&o](const CpTriangle& t) {
        o[0] = t[0], o[1] = t[1], o[2] = t[2];
        o += 3;
    };
    if (type_ != 2) {
        for (std::uint32_t v = 0; v < vertices_; ++v) out_v[v] = small_vertex(v);
        for (std::uint32_t p = 0; p < triangles_; ++p)
            put(collapsed_triangle(skip_forward(tri_skip_.data(), tri_skips_, p)));
        return;
    }
    if (c0_) {
        for (std::uint32_t v = 0; v < e1_offset_; ++v) out_v[v] = column_point(0, v);
    } else if (c2_) {
        for (std::uint32_t v = 0; v < e1_offset_; ++v) out_v[v] = column_point(v, 0);
    } else {
        for (std::uint32_t i = 0; i < n0_; ++i)
            for (std::uint32_t j = 0, rows = col_rows(i); j < rows; ++j)
                out_v[col_start(i) + j] = column_point(i, j);
    }
    for (std::uint32_t b = 0; b < unique_ - e1_offset_; ++b)
        out_v[e1_offset_ + b] = e1_point(point(e_[1], c1_ ? b * n1_ : b));
    if (copy_mask_ != 0) {
        DomainPoint* copy = out_v + unique_;
        for (std::uint32_t i = 1; i < head_; ++i)
            for (std::uint32_t j = 0; j + 1 < col_rows(i); ++j) *copy++ = out_v[c_[i] + j];
    }
    std::uint32_t r = 0;
    for (std::uint32_t i = 0; i < head_; ++i) {
        const std::uint32_t end = c_[i + 1] + c_[i + 2] - 2 * (i + 1) - n2_; // PS_{i+1}
        for (; r < end; ++r)
            if (!dropped(r)) put(collapsed_strip_triangle(i, r));
    }
    for (std::uint32_t q = 0; q < zipper_; ++q)
        if (!dropped(strips_ + q)) put(collapsed_zipper_triangle(q));
}

void CpPatchEmitter::plain_baseline(const CpPatchSetup& p, DomainPoint* out_v,
                                    std::uint32_t* out_i) noexcept {
    plain<u32x4>(p, out_v, out_i);
}

#if CTESS_EMIT_AVX2
void CpPatchEmitter::plain_avx2(const CpPatchSetup& p, DomainPoint* out_v, std::uint32_t* out_i) noexcept {
    using u32x8 = std::uint32_t __attribute__((vector_size(32)));
    plain<u32x8>(p, out_v, out_i);
}
#endif

} // namespace ctess::rt
