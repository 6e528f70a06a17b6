// Quad patches: split along the diagonal q1-q3 into two CP triangles and force the diagonal's factor
// (docs/algorithm.md §2.12). Quad corners q0, q1, q2, q3 are counter-clockwise; edge k runs q_k -> q_{k+1}.
#pragma once
#include <array>
#include <cstdint>

#include "cp_line.hpp"
#include "domain_point.hpp"

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

} // namespace ctess::cp
