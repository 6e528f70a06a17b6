// Per-vertex surface evaluation of a tessellated base triangle: flat interpolation, PN triangles (Vlachos et
// al., seed 003: cubic control points b_ijk, quadratic normals n_ijk) or Phong tessellation (Boubekeur and
// Alexa, seed 003: projection onto the corner tangent planes), each blended with flat by alpha.
//
// Crack-free by construction: a vertex with a zero weight lies on a base edge, and it is evaluated from that
// edge's two endpoints only, ordered by mesh vertex index (lower first) with the parameter measured from the
// lower one. The neighbour across the edge therefore runs the very same operations on the very same values.
// Every CP edge point is exact and mirror-symmetric in 2^-24 units, so both sides also see the same
// parameter. A corner (weight one) is copied. The shaders mirror these functions operation for operation.
#pragma once
#include <cstdint>

#include <ctess/cp_line.hpp>

#include "vec3.hpp"

namespace ctess::rt {

enum class Surface : std::uint32_t { flat = 0, pn_triangles = 1, phong = 2 };

struct SurfaceOptions {
    Surface surface = Surface::flat;
    float alpha = 0.75f; // 0 = flat, 1 = the full PN / Phong surface (seed 003's uTessAlpha)
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

namespace detail {

inline float fixed_weight(std::uint32_t w) {
    return static_cast<float>(w) * (1.0f / static_cast<float>(cp::fixed_one)); // exact: w <= 2^24
}

// PN edge control point b_ij = (2 P_i + P_j - ((P_j - P_i) . N_i) N_i) / 3.
inline Vec3 pn_edge_point(const SurfaceCorner& i, const SurfaceCorner& j) {
    const float w = dot(j.position - i.position, i.normal);
    return (1.0f / 3.0f) * ((2.0f * i.position + j.position) - w * i.normal);
}

// PN edge normal n_ij = N_i + N_j - v_ij (P_j - P_i), v_ij = 2 ((P_j - P_i) . (N_i + N_j)) / |P_j - P_i|^2.
inline Vec3 pn_edge_normal(const SurfaceCorner& i, const SurfaceCorner& j) {
    const Vec3 d = j.position - i.position;
    const float len2 = dot(d, d);
    const float v = len2 > 0.0f ? 2.0f * dot(d, i.normal + j.normal) * (1.0f / len2) : 0.0f;
    return normalize_or_zero((i.normal + j.normal) - v * d);
}

// Phong projection of q onto the tangent plane of corner i.
inline Vec3 phong_project(Vec3 q, const SurfaceCorner& i) {
    return q - dot(q - i.position, i.normal) * i.normal;
}

inline Vec3 blend(Vec3 flat, Vec3 curved, float alpha) {
    return (1.0f - alpha) * flat + alpha * curved;
}

// A point of edge (a, b), a = the lower mesh index, s + t = 1 exactly (t measured from a).
inline SurfacePoint edge_point(const SurfaceCorner& a, const SurfaceCorner& b, float s, float t,
                               const SurfaceOptions& opt) {
    SurfacePoint out;
    const Vec3 flat_p = s * a.position + t * b.position;
    const Vec3 flat_n = s * a.normal + t * b.normal;
    out.uv[0] = s * a.uv[0] + t * b.uv[0];
    out.uv[1] = s * a.uv[1] + t * b.uv[1];
    Vec3 p = flat_p, n = flat_n;
    if (opt.surface == Surface::pn_triangles) {
        const Vec3 bab = pn_edge_point(a, b), bba = pn_edge_point(b, a);
        const float s2 = s * s, t2 = t * t;
        const Vec3 pn =
            (s2 * s) * a.position + (3.0f * s2 * t) * bab + (3.0f * s * t2) * bba + (t2 * t) * b.position;
        const Vec3 nn = s2 * a.normal + t2 * b.normal + (s * t) * pn_edge_normal(a, b);
        p = blend(flat_p, pn, opt.alpha);
        n = blend(flat_n, nn, opt.alpha);
    } else if (opt.surface == Surface::phong) {
        const Vec3 ph = (s * s) * a.position + (t * t) * b.position +
                        (s * t) * (phong_project(b.position, a) + phong_project(a.position, b));
        p = blend(flat_p, ph, opt.alpha);
    }
    out.position = p;
    out.normal = normalize_or_zero(n);
    return out;
}

// A point strictly inside the triangle, weights w0 + w1 + w2 = 1.
inline SurfacePoint interior_point(const SurfaceCorner (&c)[3], float w0, float w1, float w2,
                                   const SurfaceOptions& opt) {
    SurfacePoint out;
    const Vec3 flat_p = w0 * c[0].position + w1 * c[1].position + w2 * c[2].position;
    const Vec3 flat_n = w0 * c[0].normal + w1 * c[1].normal + w2 * c[2].normal;
    out.uv[0] = w0 * c[0].uv[0] + w1 * c[1].uv[0] + w2 * c[2].uv[0];
    out.uv[1] = w0 * c[0].uv[1] + w1 * c[1].uv[1] + w2 * c[2].uv[1];
    Vec3 p = flat_p, n = flat_n;
    if (opt.surface == Surface::pn_triangles) {
        const Vec3 b210 = pn_edge_point(c[0], c[1]), b120 = pn_edge_point(c[1], c[0]);
        const Vec3 b021 = pn_edge_point(c[1], c[2]), b012 = pn_edge_point(c[2], c[1]);
        const Vec3 b102 = pn_edge_point(c[2], c[0]), b201 = pn_edge_point(c[0], c[2]);
        const Vec3 e = (1.0f / 6.0f) * (((b210 + b120) + (b021 + b012)) + (b102 + b201));
        const Vec3 v = (1.0f / 3.0f) * ((c[0].position + c[1].position) + c[2].position);
        const Vec3 b111 = e + 0.5f * (e - v);
        const float q0 = w0 * w0, q1 = w1 * w1, q2 = w2 * w2;
        const Vec3 pn = (q0 * w0) * c[0].position + (q1 * w1) * c[1].position + (q2 * w2) * c[2].position +
                        (3.0f * q0 * w1) * b210 + (3.0f * q1 * w0) * b120 + (3.0f * q1 * w2) * b021 +
                        (3.0f * q2 * w1) * b012 + (3.0f * q2 * w0) * b102 + (3.0f * q0 * w2) * b201 +
                        (6.0f * w0 * w1 * w2) * b111;
        const Vec3 nn = q0 * c[0].normal + q1 * c[1].normal + q2 * c[2].normal +
                        (w0 * w1) * pn_edge_normal(c[0], c[1]) + (w1 * w2) * pn_edge_normal(c[1], c[2]) +
                        (w2 * w0) * pn_edge_normal(c[2], c[0]);
        p = blend(flat_p, pn, opt.alpha);
        n = blend(flat_n, nn, opt.alpha);
    } else if (opt.surface == Surface::phong) {
        const Vec3 ph =
            (w0 * w0) * c[0].position + (w1 * w1) * c[1].position + (w2 * w2) * c[2].position +
            (w0 * w1) * (phong_project(c[1].position, c[0]) + phong_project(c[0].position, c[1])) +
            (w1 * w2) * (phong_project(c[2].position, c[1]) + phong_project(c[1].position, c[2])) +
            (w2 * w0) * (phong_project(c[0].position, c[2]) + phong_project(c[2].position, c[0]));
        p = blend(flat_p, ph, opt.alpha);
    }
    out.position = p;
    out.normal = normalize_or_zero(n);
    return out;
}

} // namespace detail

// The surface point of exact base weights (w0, w1, w2), units of cp::fixed_one, w0 + w1 + w2 = fixed_one.
inline SurfacePoint evaluate_surface(const SurfaceCorner (&c)[3], const std::uint32_t (&w)[3],
                                     const SurfaceOptions& opt) {
    for (unsigned k = 0; k < 3; ++k) {
        if (w[k] == cp::fixed_one) {
            return {c[k].position, normalize_or_zero(c[k].normal), {c[k].uv[0], c[k].uv[1]}};
        }
    }
    for (unsigned k = 0; k < 3; ++k) {
        if (w[k] != 0) continue;
        const unsigned i = (k + 1) % 3, j = (k + 2) % 3; // the edge opposite corner k
        const bool i_first = c[i].index < c[j].index || (c[i].index == c[j].index && i < j);
        const unsigned a = i_first ? i : j, b = i_first ? j : i;
        return detail::edge_point(c[a], c[b], detail::fixed_weight(w[a]), detail::fixed_weight(w[b]), opt);
    }
    return detail::interior_point(c, detail::fixed_weight(w[0]), detail::fixed_weight(w[1]),
                                  detail::fixed_weight(w[2]), opt);
}

} // namespace ctess::rt
