// CpPatchSetup::emit: the whole pattern in emission order, without the random-access lookups
// (docs/algorithm.md §2). A patch without a T0 edge takes the fast path: the edge points once, each column
// as a run of (u, min(v, K - u)) pairs written two at a time with its provoking copies, each strip's cells
// as a template of two cells that grows by 2 per step (three 16-byte stores per four triangles), and the
// zipper without a branch per triangle. The vector types are GCC/Clang vector extensions: SSE2 on x86-64,
// NEON on AArch64, plain scalar code on a Cortex-M.
#include <cstring>

#include <ctess/runtime/cp_patch.hpp>

namespace ctess::rt {

namespace {

using u32x4 = std::uint32_t __attribute__((vector_size(16)));

inline void store(void* out, u32x4 v) noexcept {
    std::memcpy(out, &v, sizeof v);
}

inline u32x4 load(const std::uint32_t* in) noexcept {
    u32x4 v;
    std::memcpy(&v, in, sizeof v);
    return v;
}

// Four strip cells j..j+3 as 24 lanes: cell c is (A_{j+c}, B_{j+c}, A_{j+c+1}), (B_{j+c}, B_{j+c+1},
// A_{j+c+1}), wound; lane k is (first, a or b by the masks) + add, with first = A_0 or its copy, a = C_i,
// b = C_{i+1}. (32-byte vector types are no faster: GCC lowers them badly without AVX.)
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

bool CpPatchSetup::emit(std::span<DomainPoint> vertices, std::span<std::uint32_t> indices) const noexcept {
    if (vertices.size() < vertices_ || indices.size() / 3 < triangles_) return false;
    if (plain_)
        emit_type2_plain(vertices.data(), indices.data());
    else
        emit_collapsed(vertices.data(), indices.data());
    return true;
}

void CpPatchSetup::emit_type2_plain(DomainPoint* out_v, std::uint32_t* out_i) const noexcept {
    // The members as locals: the output is uint32_t too, so the compiler would reload them after every store.
    const std::uint16_t* const c = c_;
    const std::uint32_t n0 = n0_, n1 = n1_, n2 = n2_, head = head_, clamp = clamp_, e1_offset = e1_offset_;
    auto start = [c, head](std::uint32_t i) { // col_start
        const std::uint32_t k = i < head ? i : head;
        return c[k] + (i - k);
    };
    // Column 0 as (0, v) pairs: column i is (u_i, min(v_j, K - u_i)), two rows a vector.
    alignas(16) std::uint32_t column0[2 * cp::max_segments + 4];
    column0[0] = 0, column0[1] = 0;
    for (std::uint32_t j = 1; j < n2; ++j) {
        column0[2 * j] = 0;
        column0[2 * j + 1] = interior_point(e_[2], e_[2].points[j - 1]);
    }
    std::memcpy(out_v, column0, sizeof(DomainPoint) * n2);
    const bool copies = copy_mask_ != 0;
    DomainPoint* copy = out_v + unique_;
    for (std::uint32_t i = 1; i < n0; ++i) {
        const std::uint32_t u = interior_point(e_[0], e_[0].points[i - 1]);
        const std::uint32_t top = clamp > u ? clamp - u : 0u;
        const std::uint32_t first_row = start(i), rows = start(i + 1) - first_row;
        DomainPoint* col = out_v + first_row;
        // v grows with the row, so the rows above the clamp line K - u are a suffix: usually the top row or
        // none. Below it a pair of rows is column 0's pair with u put in; the rest take the clamp.
        std::uint32_t free_rows = rows;
        while (free_rows > 0 && column0[2 * free_rows - 1] > top) --free_rows;
        const u32x4 lane_u = {u, 0, u, 0};
        auto one = [&](std::uint32_t j) {
            const std::uint32_t v = column0[2 * j + 1];
            return DomainPoint{u, v < top ? v : top};
        };
        std::uint32_t j = 0;
        if (copies && i < head) { // rows 0..rows-2 provoke a triangle of strip i - 1 too: copies
            const std::uint32_t pairs_end = free_rows < rows - 1 ? free_rows : rows - 1;
            for (; j + 2 <= pairs_end; j += 2) {
                const u32x4 w = load(column0 + 2 * j) | lane_u;
                store(col + j, w);
                store(copy + j, w);
            }
            for (; j < rows; ++j) {
                const DomainPoint p = one(j); // not re-read from col: that would stall on store forwarding
                col[j] = p;
                if (j + 1 < rows) copy[j] = p;
            }
            copy += rows - 1;
        } else {
            for (; j + 2 <= free_rows; j += 2) store(col + j, load(column0 + 2 * j) | lane_u);
            for (; j < rows; ++j) col[j] = one(j);
        }
    }
    for (std::uint32_t b = 0; b <= n1; ++b) out_v[e1_offset + b] = e1_point(point(e_[1], b));

    // Strips: cells (A_j, B_j, A_{j+1}), (B_j, B_{j+1}, A_{j+1}), then the fan (A_j, B_{nb-1}, A_{j+1}),
    // A_j's copy first in columns i >= 1 (provoking layout).
    const std::uint32_t swap = cw_mask_ & 1u; // lane of b in (a, b, c): 1, or 2 when clockwise
    const CellLanes& lanes = cell_lanes[swap];
    std::uint32_t* o = out_i;
    std::uint32_t next_copy = unique_;
    for (std::uint32_t i = 0; i < head; ++i) {
        const std::uint32_t a = c[i], b = c[i + 1];
        const std::uint32_t na = b - a, nb = c[i + 2] - b;
        const std::uint32_t first = i >= 1 && copies ? next_copy : a;
        // Each lane is first, a or b plus a constant: masks, no trip through memory (a vector loaded right
        // after scalar stores to it would stall on store forwarding).
        const std::uint32_t cells = nb - 1;
        if (cells != 0) {
            const u32x4 sf = u32x4{} + first, sa = u32x4{} + a, sb = u32x4{} + b;
            u32x4 v[6];
            for (unsigned k = 0; k < 3; ++k) { // cells 0 and 1; cells 2 and 3 are the same plus 2
                v[k] = ((sf & load(lanes.f + 4 * k)) | (sa & load(lanes.a + 4 * k)) |
                        (sb & load(lanes.b + 4 * k))) +
                       load(lanes.add + 4 * k);
                v[k + 3] = v[k] + 2;
            }
            std::uint32_t j = 0;
            for (; j + 4 <= cells; j += 4) {
                for (unsigned k = 0; k < 6; ++k) {
                    store(o + 4 * k, v[k]);
                    v[k] += 4;
                }
                o += 24;
            }
            // The last 1-3 cells (6 lanes each) in whole vectors: up to 2 lanes past them, which the fan, the
            // next strip or the zipper (at least 5 triangles) rewrite.
            const std::uint32_t rem = cells - j;
            if (rem != 0) {
                store(o, v[0]);
                store(o + 4, v[1]);
                if (rem >= 2) store(o + 8, v[2]);
                if (rem == 3) store(o + 12, v[3]), store(o + 16, v[4]);
                o += 6 * rem;
            }
        }
        const std::uint32_t tip = b + nb - 1;
        for (std::uint32_t j = nb - 1; j + 1 < na; ++j) {
            o[0] = first + j, o[1 + swap] = tip, o[2 - swap] = a + j + 1;
            o += 3;
        }
        if (i >= 1) next_copy += na - 1;
    }
    // Zipper: L_a = top of column n0-1-a = C_{n0-a} - 1, R_b = e1 point b; a gap bit says which side steps,
    // chosen by selects (the bits are a coin toss to a branch predictor).
    const std::uint32_t* const gap = gap_;
    std::uint32_t la = start(n0) - 1, a = 0, rb = e1_offset;
    for (std::uint32_t q = 0, zipper = zipper_; q < zipper; ++q) {
        const std::uint32_t w = gap[q / cp::tables::gap_bits_per_word];
        const std::uint32_t step = (w >> (q % cp::tables::gap_bits_per_word)) & 1u;
        const std::uint32_t on_l = 0u - step; // masks: GCC turns the ternaries into a branch
        a += step;
        const std::uint32_t next = start(n0 - a) - 1;
        o[0] = (next & on_l) | ((rb + 1) & ~on_l), o[1 + swap] = la, o[2 - swap] = rb;
        la = (next & on_l) | (la & ~on_l);
        rb += step ^ 1u;
        o += 3;
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

} // namespace ctess::rt
