// Per-vertex surface evaluation of a tessellated base triangle: flat interpolation, PN triangles (Vlachos et
// al. 2001: cubic control points b_ijk, quadratic normals n_ijk) or Phong tessellation (Boubekeur and
// Alexa 2008: projection onto the corner tangent planes), each blended with flat by alpha
// (docs/references.md).
//
// Crack-free by construction: a vertex with a zero weight lies on a base edge, and it is evaluated from that
// edge's two endpoints only, ordered by mesh vertex index (lower first) with the parameter measured from the
// lower one. The neighbour across the edge therefore runs the very same operations on the very same values.
// Every CP edge point is exact and mirror-symmetric in 2^-24 units, so both sides also see the same
// parameter. A corner (weight one) is copied. The shaders mirror these functions operation for operation.
#pragma once
#include <cstdint>

#include <ctess/cp/line.hpp>

#include <ctess/runtime/core/vec3.hpp>

namespace ctess::rt {

enum class Surface : std::uint32_t { flat = 0, pn_triangles = 1, phong = 2 };

struct SurfaceOptions {
    Surface surface = Surface::flat;
    float alpha = 0.75f; // 0 = flat, 1 = the full PN / Phong surface (Dupuy 2011's alpha)
};

struct SurfaceCorner {
    Vec3 position{};
    Vec3 normal{}; // need not be unit length; the output normal is normalised
    float uv[2] = {0.0f, 0.0f};
    std::uint32_t index = 0; // mesh vertex index: orders shared edges
};

struct SurfacePoint {
    Vec3 position{};
    Vec3 normal{};
    float uv[2] = {0.0f, 0.0f};
};

// The surface point of exact base weights (w0, w1, w2), units of cp::fixed_one, w0 + w1 + w2 = fixed_one
// (a CpPatch vertex rotated onto the base triangle). Out of line, in ctess::runtime_core, built with
// -ffp-contract=off -fno-fast-math: the bits do not depend on the caller's floating-point flags.
SurfacePoint evaluate_surface(const SurfaceCorner (&c)[3], const std::uint32_t (&w)[3],
                              const SurfaceOptions& opt) noexcept;

// The bilinear point of a quad q0 q1 q2 q3 (counter-clockwise) at (s, t) of its unit square, units of
// cp::fixed_one, with q0 = (0, 0), q1 = (1, 0), q2 = (1, 1), q3 = (0, 1) (cp::quad_point's square). Points
// on a quad edge come from that edge's two corners only, ordered by mesh index, so quads sharing an edge
// agree bit for bit, as evaluate_surface's triangles do. Position, normal and uv; no PN or Phong.
SurfacePoint evaluate_quad_surface(const SurfaceCorner (&q)[4], std::uint32_t s, std::uint32_t t) noexcept;

} // namespace ctess::rt
