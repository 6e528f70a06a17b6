// CpPatchSetup::emit: the whole pattern in emission order, without the random-access lookups
// (docs/algorithm.md §2). A patch without a T0 edge takes the fast path: the edge points once; each column
// as column 0's (0, v) pairs with u put in, a vector of rows at a time, written to the column and to its
// provoking copies; each strip's cells four at a time (24 indices, lanes that grow by 4 per step); the
// zipper without a branch per triangle. The vector types are GCC/Clang vector extensions, 16 bytes (SSE2 on
// x86-64, NEON on AArch64, plain scalar code on a Cortex-M), and on x86-64 a second build of the same body
// with 32-byte vectors for AVX2, chosen at run time. Patches with a T0 edge take the raw emission order and
// skip what the collapse drops.
#include <bit>
#include <cstring>
#include <utility>

#include <ctess/runtime/cp/patch.hpp>

#define CTESS_ALWAYS_INLINE [[gnu::always_inline]] inline

// x86-64 with GCC or Clang: an AVX2 build of the fast path (32-byte stores, half as many), chosen at run
// time.
#if defined(__x86_64__) && defined(__GNUC__)
#define CTESS_EMIT_AVX2 1
#else
#define CTESS_EMIT_AVX2 0
#endif
#if CTESS_EMIT_AVX2
#include <immintrin.h>
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
// A_{j+c+1}), wound; lane k is lane cell_source(k) of x = (first, a, b, 0) plus cell_add(k), with first = A_0
// or its copy, a = C_i, b = C_{i+1}. Both are constants, so a vector of lanes is one shuffle of x and one
// add (pshufd on SSE2, vpermd on AVX2), per winding.
constexpr unsigned cell_source(unsigned k, bool clockwise) {
    // One cell, counter-clockwise: F B A+1 | B B+1 A+1 (0 = first, 1 = a, 2 = b); clockwise swaps the last
    // two lanes of each triangle.
    constexpr unsigned ccw[6] = {0, 2, 1, 2, 2, 1}, cw[6] = {0, 1, 2, 2, 1, 2};
    return clockwise ? cw[k % 6] : ccw[k % 6];
}
constexpr std::uint32_t cell_add(unsigned k, bool clockwise) {
    constexpr std::uint32_t ccw[6] = {0, 0, 1, 0, 1, 1}, cw[6] = {0, 1, 0, 0, 1, 1};
    return (clockwise ? cw[k % 6] : ccw[k % 6]) + k / 6;
}

// Vector k (lanes W k .. W k + W - 1) of the 24 cell lanes.
template <class V, bool clockwise, unsigned k, class X, std::size_t... lane>
CTESS_ALWAYS_INLINE void cell_vector(V& out, const X& x, std::index_sequence<lane...>) noexcept {
    constexpr unsigned W = sizeof...(lane);
    out = __builtin_shufflevector(x, x, cell_source(W * k + lane, clockwise)...) +
          V{cell_add(W * k + lane, clockwise)...};
}
template <class V, bool clockwise, class X, std::size_t... k>
CTESS_ALWAYS_INLINE void cell_vectors(V (&v)[sizeof...(k)], const X& x, std::index_sequence<k...>) noexcept {
    constexpr unsigned W = sizeof(V) / sizeof(std::uint32_t);
    (cell_vector<V, clockwise, k>(v[k], x, std::make_index_sequence<W>{}), ...);
}

// The positions of interior points k .. k + W - 1 of an edge (units of 2^-24), from the W packed points at
// `packed` (docs/algorithm.md §4.1: bits 0-7 the final position on the 256 grid, bit 8 a slide down, bit 9
// a slide up): final * 65536 + slide for a point sliding down, - slide sliding up.
template <class V>
CTESS_ALWAYS_INLINE void edge_positions(V& out, const std::uint16_t* packed, const V& slide) noexcept {
    constexpr unsigned W = sizeof(V) / sizeof(std::uint32_t);
    typedef std::uint16_t H __attribute__((vector_size(2 * W)));
    H raw;
    std::memcpy(&raw, packed, sizeof raw);
    const V p = __builtin_convertvector(raw, V);
    out = ((p & cp::tables::point_final_mask) << 16) + (slide & (0u - ((p >> 8) & 1u))) -
          (slide & (0u - (p >> 9)));
}

// The interior points 1 .. n - 1 of an edge into out[0 .. n - 2], whole vectors: the last vector ends on
// point n - 1 (overlapping the one before, the same values) when the edge has W or more of them; an edge of
// fewer reads W packed points from its first, past its own into the next token's (the point table holds the
// tokens in order and the larger ones last: checked where the tables are defined) and writes up to
// out[W - 1]. Returns nothing past out[n - 2] that the caller may use.
template <class V>
CTESS_ALWAYS_INLINE void edge_interior(std::uint32_t* out, const std::uint16_t* points,
                                       std::uint32_t segments, std::uint32_t slide_offset) noexcept {
    constexpr unsigned W = sizeof(V) / sizeof(std::uint32_t);
    const std::uint32_t m = segments - 1;
    const V slide = V{} + slide_offset;
    for (std::uint32_t k = 0; k < m; k += W) {
        const std::uint32_t at = k + W <= m || m < W ? k : m - W;
        V pos;
        edge_positions(pos, points + at, slide);
        store(out + at, pos);
    }
}

#if CTESS_EMIT_AVX2
// The zipper (docs/algorithm.md §2.6) eight triangles at a time, for a zipper of 8 or more: triangle k of a
// group is (L_{a+1} on a step on L, else R_{b+1}; L_a; R_b) with a = a0 + (the steps on L before it), the
// gap bits' exclusive prefix count. The counts come from one multiply (each bit spread to a byte, then a
// byte-wise prefix sum), L_a and L_{a+1} from a window of the column tops by one vpermd each, and the three
// vectors are interleaved into 24 indices by three vpermd and two blends per output vector. The last 1..7
// triangles are the group that ends on the zipper's last triangle (rewriting the ones before it with the
// same values), so nothing is written past the zipper. tops needs 8 readable entries past n0.
#define CTESS_AVX2_INLINE [[gnu::always_inline]] inline __attribute__((target("avx2")))

// Output vector `triangle` (lane l: triangle (8 m + l) / 3 of the group), its component 1 lanes (mask1) from
// second and its component 2 lanes (mask2) from third.
template <int mask1, int mask2>
CTESS_AVX2_INLINE void put_triangles(std::uint32_t* at, const __m256i& triangle, const __m256i& first,
                                     const __m256i& second, const __m256i& third) noexcept {
    const __m256i v =
        _mm256_blend_epi32(_mm256_blend_epi32(_mm256_permutevar8x32_epi32(first, triangle),
                                              _mm256_permutevar8x32_epi32(second, triangle), mask1),
                           _mm256_permutevar8x32_epi32(third, triangle), mask2);
    std::memcpy(at, &v, sizeof v);
}

// Triangles q .. q + 7 of the zipper, a0 steps on L before them, bits8 their gap bits (written at o + 3 q);
// returns the group's steps on L.
CTESS_AVX2_INLINE std::uint32_t zipper_group(std::uint32_t* o, const std::uint32_t* tops, std::uint32_t bits8,
                                             std::uint32_t q, std::uint32_t a0, std::uint32_t e1_offset,
                                             bool clockwise) noexcept {
    std::uint64_t y = (bits8 * 0x0101010101010101ull) & 0x8040201008040201ull; // bit k in byte k
    y = ((y + 0x7F7F7F7F7F7F7F7Full) >> 7) & 0x0101010101010101ull;            // byte k: bit k
    const std::uint64_t inclusive = y * 0x0101010101010101ull;                 // byte k: steps on L up to k
    const __m256i step = _mm256_cvtepu8_epi32(_mm_cvtsi64_si128(static_cast<long long>(y)));
    const __m256i before = _mm256_cvtepu8_epi32(_mm_cvtsi64_si128(static_cast<long long>(inclusive << 8)));
    __m256i window;
    std::memcpy(&window, tops + a0, sizeof window);
    const __m256i l = _mm256_permutevar8x32_epi32(window, before);
    std::memcpy(&window, tops + a0 + 1, sizeof window);
    const __m256i l_next = _mm256_permutevar8x32_epi32(window, before);
    const __m256i r = _mm256_add_epi32(_mm256_set1_epi32(static_cast<int>(e1_offset + q - a0)),
                                       _mm256_sub_epi32(_mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7), before));
    const __m256i first = _mm256_blendv_epi8(_mm256_add_epi32(r, _mm256_set1_epi32(1)), l_next,
                                             _mm256_sub_epi32(_mm256_setzero_si256(), step));
    const __m256i second = clockwise ? r : l, third = clockwise ? l : r;
    std::uint32_t* const out = o + 3 * q;
    // Lane l of output vector m is index 8 m + l: triangle (8 m + l) / 3, component (8 m + l) % 3.
    put_triangles<0x92, 0x24>(out, _mm256_setr_epi32(0, 0, 0, 1, 1, 1, 2, 2), first, second, third);
    put_triangles<0x24, 0x49>(out + 8, _mm256_setr_epi32(2, 3, 3, 3, 4, 4, 4, 5), first, second, third);
    put_triangles<0x49, 0x92>(out + 16, _mm256_setr_epi32(5, 5, 6, 6, 6, 7, 7, 7), first, second, third);
    return static_cast<std::uint32_t>(inclusive >> 56);
}

// The zipper (docs/algorithm.md §2.6) eight triangles at a time, for a zipper of 8 or more: triangle k of a
// group is (L_{a+1} on a step on L, else R_{b+1}; L_a; R_b) with a = a0 + (the steps on L before it), the
// gap bits' exclusive prefix count. The counts come from one multiply (each bit spread to a byte, then a
// byte-wise prefix sum), L_a and L_{a+1} from a window of the column tops by one vpermd each, and the three
// vectors are interleaved into 24 indices by three vpermd and two blends per output vector. The last 1..7
// triangles are the group that ends on the zipper's last triangle (rewriting the ones before it with the
// same values), so nothing is written past the zipper. tops needs 8 readable entries past n0.
__attribute__((target("avx2"))) void zipper_avx2(std::uint32_t* o, const std::uint32_t* tops,
                                                 const std::uint32_t* gap, std::uint32_t zipper,
                                                 std::uint32_t e1_offset, bool clockwise) noexcept {
    std::uint32_t q = 0, a = 0;
    for (; q + 8 <= zipper; q += 8)
        a += zipper_group(o, tops, (gap[q / 16] >> (q % 16)) & 0xFFu, q, a, e1_offset, clockwise);
    if (q < zipper) {
        const std::uint32_t start = zipper - 8, shift = start % 16;
        const std::uint32_t w = gap[start / 16];
        std::uint32_t bits = (w & 0xFFFFu) >> shift;
        if (shift > 8) bits |= (gap[start / 16 + 1] & 0xFFFFu) << (16 - shift);
        zipper_group(o, tops, bits & 0xFFu, start, (w >> 16) + popcount16(w & ((1u << shift) - 1u)),
                     e1_offset, clockwise);
    }
}
#endif

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
    // Column 0 as (0, v) pairs: column i is (u_i, min(v_j, K - u_i)), W / 2 rows a vector. Written to the
    // output in the same loop: a separate memcpy of n2 points was a `rep movsq`, whose start-up cost is a
    // large part of a small patch. The pairs past n2 are zero: the columns read whole vectors.
    constexpr std::uint32_t half = W / 2;
    // A typedef: GCC drops a dependent vector_size on an alias declaration (S would be a plain int).
    typedef std::int32_t S __attribute__((vector_size(sizeof(V))));
    typedef std::uint64_t Q __attribute__((vector_size(sizeof(V))));
    static_assert(sizeof(S) == sizeof(V) && sizeof(Q) == sizeof(V));
    // The interior points of e2, then e0, then e1, whole vectors (edge_interior), into one scratch array that
    // later holds the zipper's column tops.
    std::uint32_t scratch[cp::max_segments + 1 + W];
    auto interior = [&scratch](const CpPatchSetup::Edge& e) {
        edge_interior<V>(scratch + 1, e.points, e.segments, static_cast<std::uint32_t>(e.slide));
        return static_cast<const std::uint32_t*>(scratch); // [i]: point i, 1 <= i < n
    };
    alignas(32) std::uint32_t column0[2 * (cp::max_segments + half)];
    column0[0] = 0, column0[1] = 0;
    out_v[0] = {0, 0};
    {
        const std::uint32_t* const v2 = interior(p.e_[2]);
        for (std::uint32_t j = 1; j < n2; ++j) {
            const std::uint32_t v = v2[j];
            column0[2 * j] = 0;
            column0[2 * j + 1] = v;
            out_v[j] = {0, v};
        }
    }
    store(column0 + 2 * n2, V{});
    // (x, y) in every pair of lanes: one 64-bit broadcast where the pair is one little-endian word.
    V even; // all ones in the u lanes
    even_lanes(even);
    auto set_pairs = [&](V& out, std::uint32_t x, std::uint32_t y) {
        if constexpr (std::endian::native == std::endian::little)
            out = (V)(Q{} + (x | std::uint64_t{y} << 32));
        else
            out = (even & x) | (~even & y);
    };
    // Head columns 1..h-1 (R_i rows at C_i). Every row is column 0's pair with u put in and v clamped to
    // K - u (the rows above the clamp line, usually the top one or none, take K - u): an or and a min,
    // whole vectors, no scalar tail. The stores run up to half - 1 points past the column, into the next
    // column, the tail columns or e1's points (n1 + 1 >= 4 points), which are written after it. The min is
    // signed (SSE2 compares signed 32-bit lanes only): every coordinate is at most 2^24, and the u lanes'
    // limit is 2^31 - 1. Rows 0..R_i - 2 provoke a triangle of strip i - 1 too (docs/algorithm.md §2.11):
    // copies, in the same stores while whole vectors stay inside the vertex span (the next column's copies
    // overwrite the rest); otherwise row by row.
    const bool copies = p.copy_mask_ != 0;
    std::uint32_t copy = p.unique_;
    const std::uint32_t copies_end = p.vertices_;
    const std::uint32_t* const u0 = interior(p.e_[0]);
    for (std::uint32_t i = 1; i < head; ++i) {
        const std::uint32_t u = u0[i];
        const std::uint32_t top = clamp > u ? clamp - u : 0u;
        const std::uint32_t row0 = c[i], rows = c[i + 1] - row0;
        V lane_u, limit;
        set_pairs(lane_u, u, 0u);
        set_pairs(limit, 0x7FFFFFFFu, top);
        const std::uint32_t vectors = (rows + half - 1) / half;
        DomainPoint* const col = out_v + row0;
        if (copies && copy + vectors * half <= copies_end) {
            for (std::uint32_t k = 0; k < vectors; ++k) {
                V w;
                load(w, column0 + 2 * half * k);
                w |= lane_u;
                w = (S)w < (S)limit ? w : limit;
                store(col + half * k, w);
                store(out_v + copy + half * k, w);
            }
        } else {
            for (std::uint32_t k = 0; k < vectors; ++k) {
                V w;
                load(w, column0 + 2 * half * k);
                w |= lane_u;
                w = (S)w < (S)limit ? w : limit;
                store(col + half * k, w);
            }
            if (copies) {
                for (std::uint32_t j = 0; j + 1 < rows; ++j) {
                    const std::uint32_t v = column0[2 * j + 1];
                    out_v[copy + j] = {u,
                                       v < top ? v : top}; // not re-read from col: a store-forwarding stall
                }
            }
        }
        copy += copies ? rows - 1 : 0u;
    }
    // Tail columns h..n0-1: one row each, their e0 point (v_0 = 0 is below every clamp), at C_h + (i - h).
    {
        const std::uint32_t from = head > 1 ? head : 1u;
        DomainPoint* const tail = out_v + c[head] - head;
        for (std::uint32_t i = from; i < n0; ++i) tail[i] = {u0[i], 0u};
    }
    // e1's points: its two corners, then the interior points.
    {
        DomainPoint* const e1 = out_v + e1_offset;
        const std::uint32_t* const s1 = interior(p.e_[1]);
        e1[0] = CpPatchSetup::e1_point(0);
        for (std::uint32_t b = 1; b < n1; ++b) e1[b] = CpPatchSetup::e1_point(s1[b]);
        e1[n1] = CpPatchSetup::e1_point(cp::fixed_one);
    }

    // Strips (docs/algorithm.md §2.5): cells (A_j, B_j, A_{j+1}), (B_j, B_{j+1}, A_{j+1}), then the fan
    // (A_j, B_{nb-1}, A_{j+1}), A_j's copy first in columns i >= 1 (provoking layout, §2.11). The fan's first
    // triangle (j = nb - 1) is the first half of a cell nb - 1 (B_{nb-1} is the fan's tip), so it is written
    // with the cells: a strip of equal factors (R_{i+1} = R_i - 1) is one run of vector stores.
    const bool clockwise = p.cw_mask_ != 0;
    const std::uint32_t swap = p.cw_mask_ & 1u; // lane of b in (a, b, c): 1, or 2 when clockwise
    std::uint32_t* o = out_i;
    std::uint32_t* const out_end = out_i + 3 * std::size_t{p.triangles_};
    // The zipper's column tops, L_a = top of column n0-1-a = C_{n0-a} - 1, filled on the way.
    std::uint32_t* const tops = scratch;
    typedef std::uint32_t X __attribute__((vector_size(16)));
    constexpr unsigned count = 24 / W; // four cells, 24 lanes
    // First vertex of strip i's A_j: a + j in strip 0 (and without copies), else A_j's copy, a + j + bias
    // with bias = unique_ + 1 - C_1 - i (the copies of columns 1..i-1 come before, docs/algorithm.md §2.11).
    const std::uint32_t copy_mask = p.copy_mask_, copy_bias = p.unique_ + 1u - c[1];
    std::uint32_t bias = 0;
    for (std::uint32_t i = 0, a = c[0], b = c[1]; i < head; ++i) {
        const std::uint32_t next = c[i + 2];
        const std::uint32_t na = b - a, nb = next - b;
        tops[n0 - i] = a - 1u;
        const std::uint32_t first = a + bias;
        // At least 3: a column before h has two rows or more (R_i >= 2 > R_{i+1} or cells).
        const std::uint32_t lanes = 6 * (nb - 1) + (na > nb ? 3u : 0u);
        // Each lane is first, a or b plus a constant: one shuffle of (first, a, b) and an add, in registers
        // (a vector loaded right after scalar stores to it would stall on store forwarding).
        const X x = {first, a, b, 0u};
        V v[count];
        if (clockwise)
            cell_vectors<V, true>(v, x, std::make_index_sequence<count>{});
        else
            cell_vectors<V, false>(v, x, std::make_index_sequence<count>{});
        std::uint32_t* const strip_end = o + lanes;
        if (out_end - strip_end >= 24) {
            // Whole groups of four cells: up to 21 lanes past the strip, which what follows (the fan, the
            // next strips, the zipper) rewrites; the check keeps them inside the caller's span.
            do {
#pragma GCC unroll 8
                for (unsigned k = 0; k < count; ++k) {
                    store(o + W * k, v[k]);
                    v[k] += 4;
                }
                o += 24;
            } while (o < strip_end);
        } else {
            for (; o + 24 <= strip_end; o += 24) {
#pragma GCC unroll 8
                for (unsigned k = 0; k < count; ++k) {
                    store(o + W * k, v[k]);
                    v[k] += 4;
                }
            }
            // The last lanes in whole vectors: up to W - 1 past them, inside the zipper (at least 5
            // triangles, 15 indices), which is written after.
            const std::size_t stores = (static_cast<std::size_t>(strip_end - o) + W - 1) / W;
#pragma GCC unroll 8
            for (unsigned k = 0; k < count; ++k) // a fixed trip count keeps v in registers
                if (k < stores) store(o + W * k, v[k]);
        }
        o = strip_end;
        const std::uint32_t tip = b + nb - 1;
        for (std::uint32_t j = nb; j + 1 < na; ++j) {
            o[0] = first + j, o[1 + swap] = tip, o[2 - swap] = a + j + 1;
            o += 3;
        }
        bias = (copy_bias - i - 1) & copy_mask;
        a = b, b = next;
    }
    for (std::uint32_t i = head, ch = c[head]; i <= n0; ++i) tops[n0 - i] = ch + (i - head) - 1u;
    // Zipper (§2.6): L_a, R_b = e1 point b; a gap bit says which side steps. Triangle q is (L_{a+1} on a step
    // on L, else R_{b+1}; L_a; R_b): two loads and a select per triangle, as masks (the bits are a coin toss
    // to a branch predictor, and GCC turns a ternary into a branch).
    const std::uint32_t* const gap = p.gap_;
#if CTESS_EMIT_AVX2
    if constexpr (W == 8) {
        if (p.zipper_ >= 8) {
            zipper_avx2(o, tops, gap, p.zipper_, e1_offset, clockwise);
            return;
        }
    }
#endif
    const std::uint32_t* t = tops;
    std::uint32_t rb = e1_offset;
    // One gap word per gap_bits_per_word triangles, its bits shifted out one per triangle.
    for (std::uint32_t q = 0, zipper = p.zipper_; q < zipper; q += cp::tables::gap_bits_per_word) {
        std::uint32_t bits = gap[q / cp::tables::gap_bits_per_word];
        const std::uint32_t left = zipper - q;
        const std::uint32_t run = left < cp::tables::gap_bits_per_word ? left : cp::tables::gap_bits_per_word;
        for (std::uint32_t k = 0; k < run; ++k) {
            const std::uint32_t step = bits & 1u;
            bits >>= 1;
            const std::uint32_t next_r = rb + 1, next_l = t[1]; // both loaded: a cmov, not a branch
            o[0] = step != 0 ? next_l : next_r, o[1 + swap] = t[0], o[2 - swap] = rb;
            t += step;
            rb = next_r - step;
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
