// Surface evaluation, compiled once with contraction and fast-math off (runtime/CMakeLists.txt), so that a
// shared edge's points are bit-identical between the two patches whatever flags the caller uses.
#include <ctess/runtime/surface/eval.hpp>

namespace ctess::rt {

namespace detail {

float fixed_weight(std::uint32_t w) {
    return static_cast<float>(w) * (1.0f / static_cast<float>(cp::fixed_one)); // exact: w <= 2^24
}

// PN edge control point b_ij = (2 P_i + P_j - ((P_j - P_i) . N_i) N_i) / 3.
Vec3 pn_edge_point(const SurfaceCorner& i, const SurfaceCorner& j) {
    const float w = dot(j.position - i.position, i.normal);
    return (1.0f / 3.0f) * ((2.0f * i.position + j.position) - w * i.normal);
}

// PN edge normal n_ij = N_i + N_j - v_ij (P_j - P_i), v_ij = 2 ((P_j - P_i) . (N_i + N_j)) / |P_j - P_i|^2.
Vec3 pn_edge_normal(const SurfaceCorner& i, const SurfaceCorner& j) {
    const Vec3 d = j.position - i.position;
    const float len2 = dot(d, d);
    const float v = len2 > 0.0f ? 2.0f * dot(d, i.normal + j.normal) * (1.0f / len2) : 0.0f;
    return normalize_or_zero((i.normal + j.normal) - v * d);
}

// Phong projection of q onto the tangent plane of corner i.
Vec3 phong_project(Vec3 q, const SurfaceCorner& i) {
    return q - dot(q - i.position, i.normal) * i.normal;
}

Vec3 blend(Vec3 flat, Vec3 curved, float alpha) {
    return (1.0f - alpha) * flat + alpha * curved;
}

// A point of edge (a, b), a = the lower mesh index, s + t = 1 exactly (t measured from a).
SurfacePoint edge_point(const SurfaceCorner& a, const SurfaceCorner& b, float s, float t,
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
SurfacePoint interior_point(const SurfaceCorner (&c)[3], float w0, float w1, float w2,
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

SurfacePoint evaluate_surface(const SurfaceCorner (&c)[3], const std::uint32_t (&w)[3],
                              const SurfaceOptions& opt) noexcept {
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

namespace {

// x + 0.0f turns -0.0 into +0.0 and keeps every other value: a shared corner is reached from different edges
// on two quads (1 * -0 + 0 * y on one, 0 * z + 1 * -0 on the other), whose zeros can differ in sign.
SurfacePoint without_negative_zero(SurfacePoint p) {
    p.position = {p.position.x + 0.0f, p.position.y + 0.0f, p.position.z + 0.0f};
    p.normal = {p.normal.x + 0.0f, p.normal.y + 0.0f, p.normal.z + 0.0f};
    p.uv[0] += 0.0f;
    p.uv[1] += 0.0f;
    return p;
}

} // namespace

SurfacePoint evaluate_quad_surface(const SurfaceCorner (&q)[4], std::uint32_t s, std::uint32_t t) noexcept {
    const std::uint32_t one = cp::fixed_one;
    s = s < one ? s : one;
    t = t < one ? t : one;
    // On edge k (q_k -> q_k+1) the parameter measured from q_k is r; the other coordinate is 0 or one.
    const bool on_edge[4] = {t == 0, s == one, t == one, s == 0};
    const std::uint32_t r[4] = {s, t, one - s, one - t};
    for (unsigned k = 0; k < 4; ++k) {
        if (!on_edge[k]) continue;
        const SurfaceCorner& from = q[k];
        const SurfaceCorner& to = q[(k + 1) % 4];
        const bool from_first = from.index < to.index || (from.index == to.index && k < (k + 1) % 4);
        const SurfaceCorner& a = from_first ? from : to;
        const SurfaceCorner& b = from_first ? to : from;
        const std::uint32_t tb = from_first ? r[k] : one - r[k]; // measured from a
        return without_negative_zero(detail::edge_point(a, b, detail::fixed_weight(one - tb),
                                                        detail::fixed_weight(tb), SurfaceOptions{}));
    }
    const float fs = detail::fixed_weight(s), ft = detail::fixed_weight(t);
    const float gs = detail::fixed_weight(one - s), gt = detail::fixed_weight(one - t);
    const float w[4] = {gs * gt, fs * gt, fs * ft, gs * ft};
    Vec3 p{}, n{};
    float uv[2] = {0.0f, 0.0f};
    for (unsigned k = 0; k < 4; ++k) {
        p = p + w[k] * q[k].position;
        n = n + w[k] * q[k].normal;
        uv[0] += w[k] * q[k].uv[0];
        uv[1] += w[k] * q[k].uv[1];
    }
    return without_negative_zero({p, normalize_or_zero(n), {uv[0], uv[1]}});
}

} // namespace ctess::rt
