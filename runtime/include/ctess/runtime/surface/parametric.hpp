// The built-in parametric surfaces of adaptive tessellation (docs/surfaces.md §2), each a map of
// (u, v) in [0, 1]^2 to 3D with a counter-clockwise (u right, v up) parameter triangle facing outwards.
//
// * Sphere: unit sphere, u = longitude, v = latitude from the south pole. Analytic normal.
// * Torus: major radius 1, minor radius 0.35, u around the axis, v around the tube. Analytic normal.
// * Ripple: the square [-1, 1]^2 with ripples z = A sin(16 pi u) e(v) in the band v < 1/2 (e(v) = sin^2(2 pi
// v)
//   there, 0 above). Every dyadic u of step 1/16 or coarser is a zero of the sine, so all coarse samples lie
//   on the plane z = 0 and the chord-distance test sees a flat surface: Męciński 2011's sinusoid. Normals
//   come from finite differences (no normal() member), so that path is exercised too.
#pragma once
#include <cmath>

#include <ctess/runtime/core/vec3.hpp>

namespace ctess::rt {

inline constexpr float pi_f = 3.14159265358979f;

struct SphereSurface {
    Vec3 position(float u, float v) const {
        const float theta = 2.0f * pi_f * u, phi = pi_f * v;
        return {std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), -std::cos(phi)};
    }
    Vec3 normal(float u, float v) const { return position(u, v); }
};

struct TorusSurface {
    float major = 1.0f, minor = 0.35f;
    Vec3 position(float u, float v) const {
        const float theta = 2.0f * pi_f * u, phi = 2.0f * pi_f * v;
        const float ring = major + minor * std::cos(phi);
        return {ring * std::cos(theta), ring * std::sin(theta), minor * std::sin(phi)};
    }
    Vec3 normal(float u, float v) const {
        const float theta = 2.0f * pi_f * u, phi = 2.0f * pi_f * v;
        return {std::cos(phi) * std::cos(theta), std::cos(phi) * std::sin(theta), std::sin(phi)};
    }
};

struct RippleSurface {
    float amplitude = 0.03f;
    // The envelope of the ripples: sin^2(2 pi v) for v < 1/2, else 0 (continuous with its derivative).
    static float envelope(float v) {
        if (!(v < 0.5f)) return 0.0f;
        const float s = std::sin(2.0f * pi_f * v);
        return s * s;
    }
    Vec3 position(float u, float v) const {
        return {2.0f * u - 1.0f, 2.0f * v - 1.0f, amplitude * std::sin(16.0f * pi_f * u) * envelope(v)};
    }
};

} // namespace ctess::rt
