// Exact integer checks on a triangulation of the parameter square [0, one]^2 (adaptive surfaces): returns
// the first violated property as text, or "" when the mesh is conforming.
//
// * every triangle is counter-clockwise with positive area;
// * the doubled areas sum to exactly 2 * one^2 (the square covered once, with one winding);
// * every edge inside the square is used by exactly two triangles, in opposite directions, and every edge on
//   the boundary by exactly one (so no T-junction: a hanging vertex would leave a long edge used once);
// * no two vertices share a parameter.
#pragma once
#include <cstdint>
#include <span>
#include <string>

namespace ctess::analysis {

struct SquarePoint {
    std::int64_t p, q;
};

std::string square_mesh_violation(std::span<const SquarePoint> params,
                                  std::span<const std::uint32_t> triangles, std::int64_t one);

} // namespace ctess::analysis
