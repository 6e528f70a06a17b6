// A uniform-density pattern from the compile-time tables (docs/algorithm.md §3): counts, random access to any
// vertex or triangle in O(1), and a bulk emit into caller spans. Bit-identical to the constexpr pattern
// (ctess::uniform::pattern) of the sorted factors, with the corners unswizzled and the winding restored, so
// that edge i of the output (e0 = v0 -> v1, e1 = v1 -> v2, e2 = v0 -> v2) always has factor f_i segments.
//
//   ctess::rt::UniformPatch patch(ctess::rt::uniform_tables_16, 6.0f, 11.0f, 9.0f);
//   ctess::Counts n = patch.counts();
//   std::array<std::uint32_t, 3> t = patch.triangle(0);  // counter-clockwise by default
//   ctess::uniform::Point p = patch.vertex(t[0]);            // exact (u, v), units of uniform::fixed_one =
//   65534
//
// Embedded style: no heap, no exceptions, no RTTI, no static constructors; a patch is a small value.
//
// Factors are rounded to the nearest integer (halves up) and clamped to [1, tables.max_factor]: NaN, -inf,
// zero, negatives and anything below 1.5 give 1; +inf and anything at or above max_factor - 0.5 give
// max_factor. Factors above the table go through ctess::rt::uniform_split instead (§3.5).
// Vertices: the canonical numbering of the sorted pattern (boundary first, then interior), every position
// once; Layout::provoking appends copies after them so that every triangle's first index is its own (§3.4):
// positions [0, V) and the triangles are the shared layout's, only the first index of a triangle whose
// vertex already provokes another one names its copy. vertex(i) with i >= vertices returns {0, 0};
// triangle(p) with p >= triangles returns {0, 0, 0}; emit() returns false and writes nothing when a span is
// too small.
#pragma once
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>

#include <ctess/core/counts.hpp>
#include <ctess/core/domain_point.hpp>
#include <ctess/core/patch_concept.hpp>
#include <ctess/core/patch_options.hpp>
#include <ctess/uniform/factor.hpp>
#include <ctess/uniform/pattern.hpp>
#include <ctess/uniform/quantise.hpp>

#include "table_set.hpp"

namespace ctess::rt {

using UniformTriangle = std::array<std::uint32_t, 3>;

// A factor rounded and clamped to [1, max_factor]: uniform::round_factor, the one rule (uniform/factor.hpp).
constexpr std::uint32_t uniform_factor(float f, std::uint32_t max_factor) noexcept {
    return uniform::round_factor(f, max_factor);
}

class UniformPatch {
  public:
    using point_type = uniform::Point; // units of uniform::fixed_one = 65534
    UniformPatch(const UniformTableSet& tables, float f0, float f1, float f2,
                 PatchOptions options = {}) noexcept
        : UniformPatch(tables,
                       std::array<std::uint32_t, 3>{uniform_factor(f0, tables.max_factor),
                                                    uniform_factor(f1, tables.max_factor),
                                                    uniform_factor(f2, tables.max_factor)},
                       options) {}
    // Integer factors, each already in [1, tables.max_factor] (out-of-range values are clamped).
    UniformPatch(const UniformTableSet& tables, std::array<std::uint32_t, 3> factors,
                 PatchOptions options = {}) noexcept;

    Counts counts() const noexcept { return {distinct_ + copies_, triangles_}; }
    // The sorted factors of the stored pattern (f0 >= f1 >= f2).
    std::array<std::uint32_t, 3> sorted_factors() const noexcept { return sorted_; }

    // Output corner c is the stored pattern's canonical corner corner_source()[c]; flipped() says whether
    // triangle() reverses the stored winding; pattern_index() is uniform::pattern_index of the sorted factors
    // (what the mesh pipeline's shaders store per patch, docs/shaders.md).
    std::array<std::uint8_t, 3> corner_source() const noexcept { return source_; }
    bool flipped() const noexcept { return flip_; }
    std::uint32_t pattern_index() const noexcept {
        return uniform::pattern_index(sorted_[0], sorted_[1], sorted_[2]);
    }

    // Fills: out (3 * counts().triangles indices) with the triangles of the shared layout, vertex i written
    // as number[i] (number: one entry per vertex). For a caller that numbers the vertices itself, as the
    // welded UniformSplit's leaves do (docs/algorithm.md §3.5); a provoking patch's copies are not applied.
    void emit_triangles_numbered(std::uint32_t* out, const std::uint32_t* number) const noexcept {
        const auto through = [number](std::uint8_t i) { return number[i]; };
        if (flip_)
            widen_triangles<true>(out, indices_, triangles_, through);
        else
            widen_triangles<false>(out, indices_, triangles_, through);
    }

    // Vertex i as an exact point (u, v), units of 65534; {0, 0} when i >= counts().vertices. In the
    // provoking layout, vertices from distinct_vertices() on are copies.
    uniform::Point vertex(std::uint32_t i) const noexcept {
        if (i >= distinct_ + copies_) return {};
        return canonical_vertex(i < distinct_ ? i : copy_sources_[i - distinct_]);
    }
    // Vertices with a distinct position (the shared layout's count); the copies follow them.
    std::uint32_t distinct_vertices() const noexcept { return distinct_; }
    // Triangle p's three vertex indices in the requested winding; {0, 0, 0} when p >= counts().triangles.
    UniformTriangle triangle(std::uint32_t p) const noexcept {
        if (p >= triangles_) return {0, 0, 0};
        const std::uint8_t* t = indices_ + 3 * p;
        std::uint32_t first = t[0];
        const std::uint32_t g = first_triangle_ + p; // the bit of triangle p in the copy words
        if (copies_ != 0 && (copy_words_[g / uniform::tables::copy_bits_per_word] >>
                                 (g % uniform::tables::copy_bits_per_word) &
                             1u) != 0)
            first = distinct_ + uniform::tables::copies_before(copy_words_, g) - first_copy_;
        return flip_ ? UniformTriangle{first, t[2], t[1]} : UniformTriangle{first, t[1], t[2]};
    }
    // Writes every vertex and every triangle (3 indices each), index_base added to every index (a caller that
    // concatenates patches into one buffer passes its first vertex). Returns false and writes nothing when
    // either span is too small or an index would reach 2^32 - 1 (the primitive-restart value, or wrap). Bit
    // for bit what vertex(i) and triangle(p) give (plus index_base).
    bool emit(std::span<uniform::Point> vertices, std::span<std::uint32_t> indices,
              std::uint32_t index_base = 0) const noexcept {
        if (vertices.size() < distinct_ + copies_ || indices.size() < 3u * triangles_) return false;
        if (index_base > 0xFFFFFFFFu - (distinct_ + copies_)) return false; // an index would reach 0xFFFFFFFF
        emit_vertices(vertices.data());
        emit_triangles(indices.data(), index_base);
        return true;
    }

  private:
    // Canonical vertex i < distinct_ of the stored pattern, mapped to the output corners.
    uniform::Point canonical_vertex(std::uint32_t i) const noexcept {
        const std::uint32_t boundary = sorted_[0] + sorted_[1] + sorted_[2];
        uniform::Point c;
        if (i < boundary)
            c = uniform::boundary_vertex(sorted_[0], sorted_[1], sorted_[2], i);
        else {
            const std::uint32_t word = interior_[i - boundary];
            c = {word & 0xFFFFu, word >> 16};
        }
        const std::uint32_t weight[3] = {uniform::fixed_one - c.u - c.v, c.u, c.v}; // canonical v0, v1, v2
        return {weight[source_[1]], weight[source_[2]]};
    }

    // The bulk path (docs/algorithm.md §3.4): canonical_vertex's arithmetic without a branch or a division
    // per vertex, the copies read back from the output, the triangles in one pass with a running copy rank.
    void emit_vertices(uniform::Point* out) const noexcept {
        // The members as locals: out is uint32_t pairs too, so the compiler would reload them after every
        // store.
        const std::uint32_t f0 = sorted_[0], f1 = sorted_[1], f2 = sorted_[2];
        const std::uint32_t boundary = f0 + f1 + f2, interior = distinct_ - boundary, copies = copies_;
        const std::uint32_t* const interior_words = interior_;
        const std::uint8_t* const copy_sources = copy_sources_;
        // Output coordinate k is weight source_[k + 1] of (one - u - v, u, v), picked by masks (no branch).
        std::uint32_t mask[2][3];
        for (int k = 0; k < 2; ++k)
            for (std::uint8_t c = 0; c < 3; ++c) mask[k][c] = source_[k + 1] == c ? ~0u : 0u;
        const std::uint32_t m00 = mask[0][0], m01 = mask[0][1], m02 = mask[0][2], m10 = mask[1][0],
                            m11 = mask[1][1], m12 = mask[1][2];
        const auto put = [=](uniform::Point* d, std::uint32_t u, std::uint32_t v) {
            const std::uint32_t w = uniform::fixed_one - u - v;
            *d = {(w & m00) | (u & m01) | (v & m02), (w & m10) | (u & m11) | (v & m12)};
        };
        // The boundary as uniform::boundary_vertex numbers it: e0 (p, 0), e1 (one - p, p), e2 (0, p) from v2.
        const std::uint32_t r0 = uniform::edge_reciprocal(f0), r1 = uniform::edge_reciprocal(f1),
                            r2 = uniform::edge_reciprocal(f2);
        uniform::Point* d = out;
        for (std::uint32_t k = 0; k < f0; ++k) put(d++, uniform::edge_parameter(k, f0, r0), 0);
        for (std::uint32_t k = 0; k < f1; ++k) {
            const std::uint32_t p = uniform::edge_parameter(k, f1, r1);
            put(d++, uniform::fixed_one - p, p);
        }
        for (std::uint32_t k = 0; k < f2; ++k) put(d++, 0, uniform::edge_parameter(f2 - k, f2, r2));
        for (std::uint32_t j = 0; j < interior; ++j) {
            const std::uint32_t word = interior_words[j];
            put(d + j, word & 0xFFFFu, word >> 16);
        }
        uniform::Point* const copy = out + boundary + interior;
        for (std::uint32_t k = 0; k < copies; ++k) copy[k] = out[copy_sources[k]];
    }

    // The stored index bytes widened, then the copied triangles' first indices overwritten in triangle order
    // (their rank is the running count, what copies_before gives triangle(p)).
    void emit_triangles(std::uint32_t* out, std::uint32_t base) const noexcept {
        const auto plus_base = [base](std::uint8_t i) { return base + i; };
        if (flip_)
            widen_triangles<true>(out, indices_, triangles_, plus_base);
        else
            widen_triangles<false>(out, indices_, triangles_, plus_base);
        if (copies_ == 0) return;
        constexpr std::uint32_t bits = uniform::tables::copy_bits_per_word;
        const std::uint32_t first = first_triangle_, end = first_triangle_ + triangles_;
        std::uint32_t next_copy = base + distinct_;
        for (std::uint32_t w = first / bits; w * bits < end; ++w) {
            std::uint32_t word = copy_words_[w] & 0xFFFFu;
            if (w * bits < first) word &= ~0u << (first - w * bits); // the previous pattern's triangles
            if ((w + 1) * bits > end) word &= (1u << (end - w * bits)) - 1u; // the next pattern's
            for (; word != 0; word &= word - 1)
                out[3 * (w * bits + static_cast<std::uint32_t>(std::countr_zero(word)) - first)] =
                    next_copy++;
        }
    }

    // Triangles' index bytes to 32-bit indices through index (plus a base, or a caller's numbering): a flat
    // loop (vectorised by the compiler for a base), or one pass of corner triples with corners 1 and 2
    // swapped when flipped.
    template <bool flipped, class Index>
    static void widen_triangles(std::uint32_t* out, const std::uint8_t* in, std::uint32_t triangles,
                                Index index) noexcept {
        const std::size_t n = std::size_t{3} * triangles;
        if constexpr (flipped)
            for (std::size_t k = 0; k < n; k += 3)
                out[k] = index(in[k]), out[k + 1] = index(in[k + 2]), out[k + 2] = index(in[k + 1]);
        else
            for (std::size_t k = 0; k < n; ++k) out[k] = index(in[k]);
    }

    std::array<std::uint32_t, 3> sorted_{1, 1, 1};
    std::array<std::uint8_t, 3> source_{0, 1, 2}; // output corner -> canonical corner
    bool flip_ = false;
    std::uint32_t distinct_ = 0;
    std::uint32_t copies_ = 0; // 0 in the shared layout
    std::uint32_t triangles_ = 0;
    std::uint32_t first_triangle_ = 0; // over all patterns, for the copy words
    std::uint32_t first_copy_ = 0;     // copies of the patterns before this one
    const std::uint32_t* interior_ = nullptr;
    const std::uint8_t* indices_ = nullptr;
    const std::uint32_t* copy_words_ = nullptr;
    const std::uint8_t* copy_sources_ = nullptr; // this pattern's first copy source
};

inline UniformPatch::UniformPatch(const UniformTableSet& tables, std::array<std::uint32_t, 3> factors,
                                  PatchOptions options) noexcept {
    for (std::uint32_t& f : factors) f = f < 1 ? 1u : f > tables.max_factor ? tables.max_factor : f;
    // order[k]: the output edge that gets the canonical edge k (descending factors, ties by edge index).
    std::array<std::uint8_t, 3> order{0, 1, 2};
    if (factors[order[1]] > factors[order[0]]) std::swap(order[0], order[1]);
    if (factors[order[2]] > factors[order[1]]) std::swap(order[1], order[2]);
    if (factors[order[1]] > factors[order[0]]) std::swap(order[0], order[1]);
    for (int k = 0; k < 3; ++k) sorted_[k] = factors[order[k]];
    // The corner opposite an edge: e0 -> v2, e1 -> v0, e2 -> v1. Canonical v2, v0, v1 sit opposite the
    // canonical e0, e1, e2; each goes to the output corner opposite the output edge of the same factor.
    constexpr std::uint8_t opposite[3] = {2, 0, 1};
    const std::uint8_t target[3] = {opposite[order[1]], opposite[order[2]],
                                    opposite[order[0]]}; // of v0, v1, v2
    for (std::uint8_t c = 0; c < 3; ++c) source_[target[c]] = c;
    const bool odd = (target[1] + 3 - target[0]) % 3 != 1; // a reflection reverses the winding
    flip_ = odd != (options.winding == Winding::cw);
    const std::uint32_t index = uniform::pattern_index(sorted_[0], sorted_[1], sorted_[2]);
    const uniform::tables::Offset first = tables.offsets[index], next = tables.offsets[index + 1];
    const std::uint32_t interior = static_cast<std::uint32_t>(next.interior - first.interior);
    distinct_ = sorted_[0] + sorted_[1] + sorted_[2] + interior;
    triangles_ = static_cast<std::uint32_t>(next.triangle - first.triangle);
    interior_ = tables.interior + first.interior;
    indices_ = tables.indices + 3u * first.triangle;
    if (options.layout == Layout::provoking) {
        first_triangle_ = first.triangle;
        first_copy_ = uniform::tables::copies_before(tables.copy_words, first.triangle);
        copies_ = uniform::tables::copies_before(tables.copy_words, next.triangle) - first_copy_;
        copy_words_ = tables.copy_words;
        copy_sources_ = tables.copy_sources + first_copy_;
    }
}

static_assert(IndexedTessPatch<UniformPatch>);

} // namespace ctess::rt
