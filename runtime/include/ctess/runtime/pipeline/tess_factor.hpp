// Edge tessellation factors from projected edge length (Karis 2026): an edge's world-space undisplaced
// length, projected to pixels as if the edge were perpendicular to the view vector, divided by a DiceRate in
// pixels, clamped to [1, max_factor].
//
//   factor = clamp( sqrt(|b - a|^2 * (1 / |m - eye|^2)) * factor_scale, 1, max_factor ),  m = (a + b) / 2,
//   factor_scale = projection_scale / dice_rate,  projection_scale = viewport_height / (2 tan(fov_y / 2)).
//
// Shared edges get the same factor bit for bit: callers pass the endpoints in a fixed order (lower mesh
// vertex index first), and every step is symmetric anyway. The shaders do the same operations in the same
// order.
//
// Bad input: an eye on the edge's midpoint makes the distance 0 and the factor +inf, which clamps to
// max_factor; a zero-length edge at the eye gives NaN, which the CP line maps to T0 (factor 1). Neither is
// UB.
//
// Three factor modes (DiceOptions::mode, issue #19), each a function of one edge's own data only, so that
// every face sharing the edge gets the same factor bit for bit (docs/algorithm.md §7.1):
// * FactorMode::camera (default): the projected length above;
// * FactorMode::constant: factor = constant_factor for every edge;
// * FactorMode::edge_length: factor = |b - a| / target_edge_length (world units; a target of 0 gives +inf,
//   a NaN or negative target NaN or a negative factor: the patterns clamp them to max or 1).
// The GPU shaders implement the camera mode only (docs/shaders.md); the other two are CPU pipeline modes.
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>

#include <ctess/runtime/core/vec3.hpp>

namespace ctess::rt {

enum class FactorMode : std::uint32_t { camera = 0, constant = 1, edge_length = 2 };

struct DiceOptions {
    Vec3 eye{};                       // camera position, world space
    float projection_scale = 1000.0f; // pixels per world unit at distance 1
    float dice_rate = 2.0f;           // pixels per tessellated segment (UE's default is 2)
    // The one scale the factor needs; the GPU gets this float, so both sides use the same value.
    float factor_scale() const { return projection_scale / dice_rate; }
    FactorMode mode = FactorMode::camera;
    float constant_factor = 1.0f;    // FactorMode::constant
    float target_edge_length = 1.0f; // FactorMode::edge_length: world units per tessellated segment
};

// Unclamped factor of edge (a, b); CP's line_state clamps it to [1, max] (and maps NaN to T0).
inline float edge_tess_factor(Vec3 a, Vec3 b, Vec3 eye, float factor_scale) {
    const Vec3 d = b - a;
    const Vec3 m = 0.5f * (a + b);
    const Vec3 e = m - eye;
    const float len2 = dot(d, d);
    const float dist2 = dot(e, e);
    return std::sqrt(len2 * (1.0f / dist2)) * factor_scale;
}

// The unclamped factor of edge (a, b) in the mode of dice; pass the endpoints in a fixed order (lower mesh
// vertex index first) so that neighbours agree. A mode value outside the enum gives NaN (factor 1).
inline float edge_factor(Vec3 a, Vec3 b, const DiceOptions& dice) {
    switch (dice.mode) {
    case FactorMode::camera:
        return edge_tess_factor(a, b, dice.eye, dice.factor_scale());
    case FactorMode::constant:
        return dice.constant_factor;
    case FactorMode::edge_length: {
        const Vec3 d = b - a;
        return std::sqrt(dot(d, d)) / dice.target_edge_length;
    }
    }
    return std::numeric_limits<float>::quiet_NaN();
}

} // namespace ctess::rt
