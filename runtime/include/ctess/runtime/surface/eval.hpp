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
//
// The shaders run PN-AEN (McDonald and Kilgard 2010) and the quad surfaces (flat, Phong, PN quad, PN-AEN
// quad) too (docs/shaders.md). PN-AEN orders an edge by position bits instead of mesh index: the two sides of
// a split-normal edge hold different vertices at the same positions.
#pragma once
#include <cstdint>
#include <span>

#include <ctess/core/domain_point.hpp>
#include <ctess/cp/line.hpp>

#include <ctess/runtime/core/vec3.hpp>

namespace ctess::rt {

// pn_aen: PN triangles whose edge control points average both sides' normals (McDonald and Kilgard 2010), so
// split normals (hard edges, seams) do not crack; docs/algorithm.md §6.1. Without adjacency data
// (evaluate_surface, evaluate_quad_surface) every edge counts as a boundary: PN with a position-ordered edge.
enum class Surface : std::uint32_t { flat = 0, pn_triangles = 1, phong = 2, pn_aen = 3 };

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
// Surface::pn_aen here has no adjacency: evaluate_surface_aen with every edge a boundary.
SurfacePoint evaluate_surface(const SurfaceCorner (&c)[3], const std::uint32_t (&w)[3],
                              const SurfaceOptions& opt) noexcept;

// Many points of one triangle at once. Fills: out[k] = evaluate_surface(c, {fixed_one - base[k].u -
// base[k].v, base[k].u, base[k].v}, opt), bit for bit, for k < min(out.size(), base.size()) (one SurfacePoint
// per base point). The flat surface's interior points run without a call per point (the mesh pipeline's
// emits, welded and unwelded, docs/algorithm.md §7); every other point goes through evaluate_surface.
void evaluate_surface_points(std::span<SurfacePoint> out, const SurfaceCorner (&c)[3],
                             std::span<const DomainPoint> base, const SurfaceOptions& opt) noexcept;

// The neighbour's side of one edge, for PN-AEN: the two vertices of the adjacent triangle (or quad) on the
// edge, in either order, e.g. vertices[i[3 + 2e]] and vertices[i[4 + 2e]] of
// meshopt_generateTessellationIndexBuffer's 12 indices per triangle. Only their positions and normals are
// read. Each is paired with the own corner of bit-identical position; where neither order matches both
// positions, the edge is a boundary (the own normals stand in for the neighbour's). docs/algorithm.md §6.1.
struct AdjacentEdge {
    SurfaceCorner vertex[2];
};

// PN-AEN: the point of exact weights w (as evaluate_surface) on the triangle c, whose edge e (c[e] -> c[e+1])
// borders adjacent[e]. Edge control points are the average of the PN control points built with the own and
// with the neighbour's normals; the centre comes from those averaged points as in PN. A point with a zero
// weight is evaluated from its edge's data only, endpoints ordered by position bits, so both sides of a
// split-normal edge give bit-identical positions. The normal is the own PN normal field (per-side shading
// normals, as McDonald and Kilgard keep them); uv is the own. Zeros of the position are +0.0. A surface other
// than pn_aen ignores adjacent and returns evaluate_surface(c, w, opt).
SurfacePoint evaluate_surface_aen(const SurfaceCorner (&c)[3], const AdjacentEdge (&adjacent)[3],
                                  const std::uint32_t (&w)[3], const SurfaceOptions& opt) noexcept;

// The bilinear point of a quad q0 q1 q2 q3 (counter-clockwise) at (s, t) of its unit square, units of
// cp::fixed_one, with q0 = (0, 0), q1 = (1, 0), q2 = (1, 1), q3 = (0, 1) (cp::quad_point's square). Points
// on a quad edge come from that edge's two corners only, ordered by mesh index, so quads sharing an edge
// agree bit for bit, as evaluate_surface's triangles do. Position, normal and uv; no PN or Phong.
SurfacePoint evaluate_quad_surface(const SurfaceCorner (&q)[4], std::uint32_t s, std::uint32_t t) noexcept;

// The quad surface of opt at (s, t) (docs/algorithm.md §6.2). Surface::flat is the function above, bit for
// bit. phong: the bilinear point projected onto the four corner tangent planes and blended bilinearly
// (Boubekeur and Alexa 2008); pn_triangles: a bicubic Bezier patch whose boundary control points are the PN
// edge points, so each edge is the PN triangles' edge curve; pn_aen: the same patch on PN-AEN edge points
// with every edge a boundary. For these three a corner is copied and an edge point is computed exactly as
// evaluate_surface (evaluate_surface_aen for pn_aen) computes it, so a quad and a triangle sharing an edge
// agree bit for bit.
SurfacePoint evaluate_quad_surface(const SurfaceCorner (&q)[4], std::uint32_t s, std::uint32_t t,
                                   const SurfaceOptions& opt) noexcept;

// PN-AEN on a quad: edge e (q[e] -> q[e+1]) borders adjacent[e], as for evaluate_surface_aen. A surface other
// than pn_aen ignores adjacent and returns evaluate_quad_surface(q, s, t, opt).
SurfacePoint evaluate_quad_surface_aen(const SurfaceCorner (&q)[4], const AdjacentEdge (&adjacent)[4],
                                       std::uint32_t s, std::uint32_t t, const SurfaceOptions& opt) noexcept;

} // namespace ctess::rt
