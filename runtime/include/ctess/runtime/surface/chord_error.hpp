// The chord error of a tessellated parametric surface (docs/surfaces.md §3): the largest distance between
// the surface point f(u, v) and the flat triangle's point at the same (u, v), over 13 sample points per
// triangle (the edge midpoints, the centroid and the other interior points of the barycentric grid of sixths
// with every weight >= 1/6). This parametric distance bounds the distance from the surface to the mesh from
// above (at those samples).
// Used to compare the adaptive mesh with the uniform grid of grid_strip.hpp that reaches the same error.
#pragma once
#include <cmath>
#include <cstdint>

#include <ctess/surface/grid_eval.hpp>

#include "adaptive.hpp"

namespace ctess::rt {

// The error of one triangle with corners at parameters uv[k] and positions p[k].
template <ParametricSurface S>
float triangle_chord_error(const S& surface, const float (&uv)[3][2], const Vec3 (&p)[3]) {
    // Barycentric sample weights, in sixths.
    static constexpr int samples[][3] = {{3, 3, 0}, {0, 3, 3}, {3, 0, 3}, {2, 2, 2}, {4, 1, 1},
                                         {1, 4, 1}, {1, 1, 4}, {1, 3, 2}, {2, 1, 3}, {3, 2, 1},
                                         {1, 2, 3}, {3, 1, 2}, {2, 3, 1}};
    float worst = 0.0f;
    for (const auto& w : samples) {
        const float a = w[0] / 6.0f, b = w[1] / 6.0f, c = w[2] / 6.0f;
        const float u = a * uv[0][0] + b * uv[1][0] + c * uv[2][0];
        const float v = a * uv[0][1] + b * uv[1][1] + c * uv[2][1];
        const Vec3 flat = (a * p[0] + b * p[1]) + c * p[2];
        const float e = detail::length(surface.position(u, v) - flat);
        worst = e > worst ? e : worst;
    }
    return worst;
}

// The chord error of an adaptive tessellation.
template <ParametricSurface S>
float max_chord_error(const S& surface, const AdaptiveSurface& mesh) {
    float worst = 0.0f;
    const adaptive::ConformingBintree& tree = mesh.tree();
    if (mesh.counts().triangles == 0) return worst;
    for (std::uint32_t i = 0; i < tree.node_count(); ++i) {
        const adaptive::Node& n = tree.node(i);
        if (!n.is_leaf()) continue;
        float uv[3][2];
        Vec3 p[3];
        for (int k = 0; k < 3; ++k) {
            const adaptive::ParamPoint pq = tree.param(n.vertex[k]);
            uv[k][0] = to_parameter(pq.p);
            uv[k][1] = to_parameter(pq.q);
            p[k] = mesh.vertex(n.vertex[k]).position;
        }
        const float e = triangle_chord_error(surface, uv, p);
        worst = e > worst ? e : worst;
    }
    return worst;
}

// The chord error of the U x V grid drawn as grid_strip.hpp's triangles (each cell split along its diagonal
// from (x, y + 1) to (x + 1, y)). Evaluates the surface on the fly: no buffers. 0 for invalid sizes.
template <ParametricSurface S>
float grid_chord_error(const S& surface, std::uint32_t u_segments, std::uint32_t v_segments) {
    if (!grid::valid_segments(u_segments, v_segments)) return 0.0f;
    float worst = 0.0f;
    for (std::uint32_t y = 0; y < v_segments; ++y) {
        const float v0 = grid::grid_parameter(y, v_segments), v1 = grid::grid_parameter(y + 1, v_segments);
        for (std::uint32_t x = 0; x < u_segments; ++x) {
            const float u0 = grid::grid_parameter(x, u_segments),
                        u1 = grid::grid_parameter(x + 1, u_segments);
            const Vec3 p00 = surface.position(u0, v0), p10 = surface.position(u1, v0);
            const Vec3 p01 = surface.position(u0, v1), p11 = surface.position(u1, v1);
            const float lower_uv[3][2] = {{u0, v0}, {u1, v0}, {u0, v1}};
            const Vec3 lower[3] = {p00, p10, p01};
            const float upper_uv[3][2] = {{u1, v0}, {u1, v1}, {u0, v1}};
            const Vec3 upper[3] = {p10, p11, p01};
            const float e0 = triangle_chord_error(surface, lower_uv, lower);
            const float e1 = triangle_chord_error(surface, upper_uv, upper);
            worst = e0 > worst ? e0 : worst;
            worst = e1 > worst ? e1 : worst;
        }
    }
    return worst;
}

} // namespace ctess::rt
