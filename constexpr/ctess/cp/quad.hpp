// Quad patches: split along the diagonal q1-q3 into two CP triangles and force the diagonal's factor
// (docs/algorithm.md §2.12). Quad corners q0, q1, q2, q3 are counter-clockwise; edge k runs q_k -> q_{k+1}.
#pragma once
#include <array>
#include <cstdint>
#include <span>

#include "line.hpp"
#include "pattern.hpp"
#include <ctess/core/counts.hpp>
#include <ctess/core/domain_point.hpp>

namespace ctess::cp {

struct QuadTriangle {
    std::array<std::uint8_t, 3> corner{}; // quad corners used as v0, v1, v2
    std::array<float, 3> factors{};       // f0, f1, f2 of the CP triangle; f1 is the diagonal
};

struct QuadSplit {
    std::array<QuadTriangle, 2> triangles{};
};

// Triangle A = (q0, q1, q3) and B = (q2, q3, q1): counter-clockwise, the diagonal is e1 of both. The diagonal
// takes A's e0 factor (edge q0q1): CP columns stand on e0 and end on the gap at e1, so equal tokens on e0
// and e1 make A's zipper one-to-one and its column lines end exactly on the diagonal's points; when edge
// q2q3 has the same factor, B's columns continue them straight across. Every quad edge keeps its own factor,
// so the patch is watertight against neighbours; the diagonal is shared with one factor. Factors are passed
// through unchanged (the pattern clamps them).
constexpr QuadSplit split_quad(const std::array<float, 4>& edge_factors) {
    const float diagonal = edge_factors[0];
    QuadSplit s;
    s.triangles[0] = {{0, 1, 3}, {edge_factors[0], diagonal, edge_factors[3]}};
    s.triangles[1] = {{2, 3, 1}, {edge_factors[2], diagonal, edge_factors[1]}};
    return s;
}

// The corner indices of a split triangle, given the quad's 4 corner indices (counter-clockwise).
constexpr std::array<std::uint32_t, 3> quad_triangle_corners(const QuadSplit& s, unsigned triangle,
                                                             const std::array<std::uint32_t, 4>& quad) {
    const QuadTriangle& t = s.triangles[triangle & 1u];
    return {quad[t.corner[0]], quad[t.corner[1]], quad[t.corner[2]]};
}

// A pattern point of split triangle A (0) or B (1) in the quad's unit square (units of fixed_one), with
// q0 = (0,0), q1 = (1,0), q2 = (1,1), q3 = (0,1). Exact: A is the identity, B is the point reflection.
constexpr DomainPoint quad_point(unsigned triangle, DomainPoint p) {
    if ((triangle & 1u) == 0) return p;
    return {fixed_one - p.u, fixed_one - p.v};
}

namespace detail {

// The e1 block of a pattern's vertices (the diagonal of a quad half): e1 points are contiguous in the vertex
// order, from v1 to v2 (docs/algorithm.md §2.11), and no other vertex lies on u + v = 1. Returns the first.
constexpr std::uint32_t e1_block_start(const DomainPoint* v, std::uint32_t n) {
    for (std::uint32_t i = 0; i < n; ++i)
        if (std::uint64_t{v[i].u} + v[i].v == fixed_one) return i;
    return n;
}

} // namespace detail

// A whole CP quad (docs/algorithm.md §2.12): the two halves of split_quad, their points mapped into the
// quad's unit square by quad_point, counts first (empty spans), then fill, outputs first; nothing is written
// when a span is short. Triangle A's vertices and triangles come first, then B's.
// * Layout::shared welds the diagonal: B's diagonal points are A's (same positions bit for bit, as both
// halves
//   have the diagonal's factor on e1 and CP lines are mirror-exact), so B contributes only its other
//   vertices.
// * Layout::provoking keeps each half's own diagonal points, so every triangle keeps a first vertex of its
// own. The fill needs no scratch memory: B is tessellated into the tail of the vertex buffer, its vertices
// before the diagonal are moved up over the diagonal, and A is written in front.
namespace detail {
constexpr Counts tessellate_quad_into(DomainPoint* vertices, std::uint32_t* indices,
                                      const std::array<float, 4>& edge_factors, const PatternOptions& opt) {
    const QuadSplit split = split_quad(edge_factors);
    const auto& fa = split.triangles[0].factors;
    const auto& fb = split.triangles[1].factors;
    const Counts a = pattern_counts(fa[0], fa[1], fa[2], opt);
    const Counts b = pattern_counts(fb[0], fb[1], fb[2], opt);
    const bool weld = opt.layout == Layout::shared;
    // The diagonal's points: segments + 1 (a T0 line has one segment).
    const LineState diagonal = line_state(fa[1], pattern_max_factor(opt.max_factor));
    const std::uint32_t nd = weld ? token_info(diagonal.token).segments + 1u : 0u;
    const Counts total{a.vertices + b.vertices - nd, a.triangles + b.triangles};
    if (vertices == nullptr || indices == nullptr) return total;

    // B into the tail, then its vertices before the diagonal block moved up over the block (high to low).
    DomainPoint* vb = vertices + (a.vertices - nd);
    std::uint32_t* ib = indices + 3 * std::size_t{a.triangles};
    tessellate_into(vb, ib, fb[0], fb[1], fb[2], opt);
    const std::uint32_t b0 = weld ? detail::e1_block_start(vb, b.vertices) : 0u;
    for (std::uint32_t i = b0; i-- > 0;) vertices[a.vertices + i] = vb[i];
    tessellate_into(vertices, indices, fa[0], fa[1], fa[2], opt);
    const std::uint32_t a0 = weld ? detail::e1_block_start(vertices, a.vertices) : 0u;
    for (std::uint32_t i = a.vertices; i < total.vertices; ++i) vertices[i] = quad_point(1, vertices[i]);
    // B's index i: before the block a.vertices + i; in it A's mirrored diagonal point (B walks the diagonal
    // from q3 to q1, A from q1 to q3); after it a.vertices + i - nd.
    for (std::uint32_t k = 0; k < 3 * b.triangles; ++k) {
        const std::uint32_t i = ib[k];
        ib[k] = i < b0 ? a.vertices + i : i < b0 + nd ? a0 + (nd - 1 - (i - b0)) : a.vertices + i - nd;
    }
    return total;
}
} // namespace detail

constexpr Counts tessellate_quad(std::span<DomainPoint> vertices, std::span<std::uint32_t> indices,
                                 const std::array<float, 4>& edge_factors, const PatternOptions& opt = {}) {
    const Counts n = detail::tessellate_quad_into(nullptr, nullptr, edge_factors, opt);
    if (!fits(n, vertices.size(), indices.size())) return n;
    return detail::tessellate_quad_into(vertices.data(), indices.data(), edge_factors, opt);
}

} // namespace ctess::cp
