// Surface evaluation, compiled once with contraction and fast-math off (runtime/CMakeLists.txt), so that a
// shared edge's points are bit-identical between the two patches whatever flags the caller uses.
#include <ctess/runtime/surface/eval.hpp>

#include <algorithm>
#include <bit>

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

// The PN cubic at weights (w0, w1, w2) from its six edge control points b = {b210, b120, b021, b012, b102,
// b201} (Vlachos et al. 2001): the centre b111 from them, the position, and the quadratic normal field. PN
// and PN-AEN differ only in b.
struct PnCubic {
    Vec3 position, normal;
};

PnCubic pn_cubic(const SurfaceCorner (&c)[3], const Vec3 (&b)[6], float w0, float w1, float w2) {
    const Vec3 e = (1.0f / 6.0f) * (((b[0] + b[1]) + (b[2] + b[3])) + (b[4] + b[5]));
    const Vec3 v = (1.0f / 3.0f) * ((c[0].position + c[1].position) + c[2].position);
    const Vec3 b111 = e + 0.5f * (e - v);
    const float q0 = w0 * w0, q1 = w1 * w1, q2 = w2 * w2;
    const Vec3 pn = (q0 * w0) * c[0].position + (q1 * w1) * c[1].position + (q2 * w2) * c[2].position +
                    (3.0f * q0 * w1) * b[0] + (3.0f * q1 * w0) * b[1] + (3.0f * q1 * w2) * b[2] +
                    (3.0f * q2 * w1) * b[3] + (3.0f * q2 * w0) * b[4] + (3.0f * q0 * w2) * b[5] +
                    (6.0f * w0 * w1 * w2) * b111;
    const Vec3 nn = q0 * c[0].normal + q1 * c[1].normal + q2 * c[2].normal +
                    (w0 * w1) * pn_edge_normal(c[0], c[1]) + (w1 * w2) * pn_edge_normal(c[1], c[2]) +
                    (w2 * w0) * pn_edge_normal(c[2], c[0]);
    return {pn, nn};
}

// The flat interpolation of a point strictly inside the triangle, its normal not yet normalised: the one
// source of the flat part of interior_point, aen_interior_point and evaluate_surface_points' loop.
inline SurfacePoint flat_interior(const SurfaceCorner (&c)[3], float w0, float w1, float w2) {
    SurfacePoint out;
    out.position = w0 * c[0].position + w1 * c[1].position + w2 * c[2].position;
    out.normal = w0 * c[0].normal + w1 * c[1].normal + w2 * c[2].normal;
    out.uv[0] = w0 * c[0].uv[0] + w1 * c[1].uv[0] + w2 * c[2].uv[0];
    out.uv[1] = w0 * c[0].uv[1] + w1 * c[1].uv[1] + w2 * c[2].uv[1];
    return out;
}

// A point strictly inside the triangle, weights w0 + w1 + w2 = 1.
SurfacePoint interior_point(const SurfaceCorner (&c)[3], float w0, float w1, float w2,
                            const SurfaceOptions& opt) {
    SurfacePoint out = flat_interior(c, w0, w1, w2);
    const Vec3 flat_p = out.position, flat_n = out.normal;
    Vec3 p = flat_p, n = flat_n;
    if (opt.surface == Surface::pn_triangles) {
        const PnCubic pn =
            pn_cubic(c,
                     {pn_edge_point(c[0], c[1]), pn_edge_point(c[1], c[0]), pn_edge_point(c[1], c[2]),
                      pn_edge_point(c[2], c[1]), pn_edge_point(c[2], c[0]), pn_edge_point(c[0], c[2])},
                     w0, w1, w2);
        p = blend(flat_p, pn.position, opt.alpha);
        n = blend(flat_n, pn.normal, opt.alpha);
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

namespace {

// Every edge a boundary: the neighbour's vertices are the own ones (PN-AEN then is PN, docs/algorithm.md
// §6.1).
template <unsigned N>
struct BoundaryEdges {
    AdjacentEdge edge[N];
    explicit BoundaryEdges(const SurfaceCorner (&c)[N]) {
        for (unsigned e = 0; e < N; ++e) edge[e] = {{c[e], c[(e + 1) % N]}};
    }
};

} // namespace

SurfacePoint evaluate_surface(const SurfaceCorner (&c)[3], const std::uint32_t (&w)[3],
                              const SurfaceOptions& opt) noexcept {
    if (opt.surface == Surface::pn_aen) return evaluate_surface_aen(c, BoundaryEdges<3>(c).edge, w, opt);
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

void evaluate_surface_points(std::span<SurfacePoint> out, const SurfaceCorner (&c)[3],
                             std::span<const DomainPoint> base, const SurfaceOptions& opt) noexcept {
    const std::size_t n = std::min(out.size(), base.size());
    for (std::size_t k = 0; k < n; ++k) {
        const std::uint32_t w1 = base[k].u, w2 = base[k].v, w0 = cp::fixed_one - w1 - w2;
        const bool interior = w0 != 0 && w1 != 0 && w2 != 0 && w1 < cp::fixed_one && w2 < cp::fixed_one &&
                              w1 + w2 < cp::fixed_one;
        if (opt.surface != Surface::flat || !interior) {
            out[k] = evaluate_surface(c, {w0, w1, w2}, opt);
            continue;
        }
        // evaluate_surface's flat interior path inlined: no call, no struct return per point.
        SurfacePoint p = detail::flat_interior(c, detail::fixed_weight(w0), detail::fixed_weight(w1),
                                               detail::fixed_weight(w2));
        p.normal = normalize_or_zero(p.normal);
        out[k] = p;
    }
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

// ---- PN-AEN and quad surfaces (docs/algorithm.md §6) ----

namespace detail {

// pn_edge_point with the normal passed apart, so that the neighbour's normal at the same position can be
// used; the same operations in the same order.
Vec3 pn_control(Vec3 pi, Vec3 ni, Vec3 pj) {
    const float w = dot(pj - pi, ni);
    return (1.0f / 3.0f) * ((2.0f * pi + pj) - w * ni);
}

// The PN-AEN edge control point: the mean of the PN control points built with both sides' normals at the
// same position (McDonald and Kilgard 2010). IEEE addition commutes, so either side gets the same bits
// whichever normal is its own; with ni_adj == ni it is the PN point exactly (x + x and * 0.5 are exact below
// overflow).
Vec3 aen_control(Vec3 pi, Vec3 ni, Vec3 ni_adj, Vec3 pj) {
    return 0.5f * (pn_control(pi, ni, pj) + pn_control(pi, ni_adj, pj));
}

bool same_bits(Vec3 a, Vec3 b) {
    return std::bit_cast<std::uint32_t>(a.x) == std::bit_cast<std::uint32_t>(b.x) &&
           std::bit_cast<std::uint32_t>(a.y) == std::bit_cast<std::uint32_t>(b.y) &&
           std::bit_cast<std::uint32_t>(a.z) == std::bit_cast<std::uint32_t>(b.z);
}

// A total order on positions by their bit patterns (x, then y, then z): both sides of a split-normal edge
// hold the same positions but different mesh indices, so the position, not the index, orders the edge.
// Integer comparisons: NaN orders like any other value.
bool position_before(Vec3 a, Vec3 b) {
    const std::uint32_t ka[3] = {std::bit_cast<std::uint32_t>(a.x), std::bit_cast<std::uint32_t>(a.y),
                                 std::bit_cast<std::uint32_t>(a.z)};
    const std::uint32_t kb[3] = {std::bit_cast<std::uint32_t>(b.x), std::bit_cast<std::uint32_t>(b.y),
                                 std::bit_cast<std::uint32_t>(b.z)};
    for (unsigned k = 0; k < 3; ++k) {
        if (ka[k] != kb[k]) return ka[k] < kb[k];
    }
    return false;
}

Vec3 without_negative_zero(Vec3 p) {
    return {p.x + 0.0f, p.y + 0.0f, p.z + 0.0f};
}

// The neighbour's normals at the two ends of edge (from, to).
struct EdgeNormals {
    Vec3 at_from, at_to;
};

// Pairs each vertex of the neighbour's edge with the own corner of bit-identical position (either order); an
// edge whose positions do not match is a boundary and keeps the own normals (docs/algorithm.md §6.1).
EdgeNormals adjacent_normals(const SurfaceCorner& from, const SurfaceCorner& to, const AdjacentEdge& adj) {
    const SurfaceCorner& v0 = adj.vertex[0];
    const SurfaceCorner& v1 = adj.vertex[1];
    if (same_bits(v0.position, from.position) && same_bits(v1.position, to.position))
        return {v0.normal, v1.normal};
    if (same_bits(v1.position, from.position) && same_bits(v0.position, to.position))
        return {v1.normal, v0.normal};
    return {from.normal, to.normal};
}

// Whether the end of weight wa comes first on a PN-AEN edge: lower position bits first; equal positions (a
// degenerate edge) put the larger weight first, so both sides still pick the same end unless the weights tie,
// where the two orders differ at most in the sign of zeros, which the caller clears.
bool aen_first(const SurfaceCorner& a, std::uint32_t wa, const SurfaceCorner& b, std::uint32_t wb) {
    if (same_bits(a.position, b.position)) return wa >= wb;
    return position_before(a.position, b.position);
}

// A point of a PN-AEN edge: a first (aen_first), s + t = 1 exactly, t measured from a; a_adj and b_adj are
// the neighbour's normals at a and b. The operations of edge_point's PN branch with averaged control points.
SurfacePoint aen_edge_point(const SurfaceCorner& a, Vec3 a_adj, const SurfaceCorner& b, Vec3 b_adj, float s,
                            float t, float alpha) {
    SurfacePoint out;
    const Vec3 flat_p = s * a.position + t * b.position;
    const Vec3 flat_n = s * a.normal + t * b.normal;
    out.uv[0] = s * a.uv[0] + t * b.uv[0];
    out.uv[1] = s * a.uv[1] + t * b.uv[1];
    const Vec3 bab = aen_control(a.position, a.normal, a_adj, b.position);
    const Vec3 bba = aen_control(b.position, b.normal, b_adj, a.position);
    const float s2 = s * s, t2 = t * t;
    const Vec3 pn =
        (s2 * s) * a.position + (3.0f * s2 * t) * bab + (3.0f * s * t2) * bba + (t2 * t) * b.position;
    const Vec3 nn = s2 * a.normal + t2 * b.normal + (s * t) * pn_edge_normal(a, b);
    out.position = without_negative_zero(blend(flat_p, pn, alpha));
    out.normal = normalize_or_zero(blend(flat_n, nn, alpha));
    return out;
}

// A PN-AEN point strictly inside the triangle: interior_point's PN branch with averaged edge control points
// (en[e] = the neighbour's normals on edge c[e] -> c[e+1]); the centre b111 from them as in PN.
SurfacePoint aen_interior_point(const SurfaceCorner (&c)[3], const EdgeNormals (&en)[3], float w0, float w1,
                                float w2, float alpha) {
    SurfacePoint out = flat_interior(c, w0, w1, w2);
    const Vec3 flat_p = out.position, flat_n = out.normal;
    const PnCubic pn = pn_cubic(c,
                                {aen_control(c[0].position, c[0].normal, en[0].at_from, c[1].position),
                                 aen_control(c[1].position, c[1].normal, en[0].at_to, c[0].position),
                                 aen_control(c[1].position, c[1].normal, en[1].at_from, c[2].position),
                                 aen_control(c[2].position, c[2].normal, en[1].at_to, c[1].position),
                                 aen_control(c[2].position, c[2].normal, en[2].at_from, c[0].position),
                                 aen_control(c[0].position, c[0].normal, en[2].at_to, c[2].position)},
                                w0, w1, w2);
    out.position = without_negative_zero(blend(flat_p, pn.position, alpha));
    out.normal = normalize_or_zero(blend(flat_n, pn.normal, alpha));
    return out;
}

// The quad surfaces of docs/algorithm.md §6.2: Phong, PN (en == nullptr) or PN-AEN (en = the neighbour's
// normals per edge). s, t already clamped to [0, one].
SurfacePoint quad_point(const SurfaceCorner (&q)[4], const EdgeNormals* en, std::uint32_t s, std::uint32_t t,
                        const SurfaceOptions& opt) {
    const std::uint32_t one = cp::fixed_one;
    const bool aen = en != nullptr;
    // A corner is copied, as evaluate_surface copies a weight-one corner.
    if ((s == 0 || s == one) && (t == 0 || t == one)) {
        const SurfaceCorner& c = q[s == 0 ? (t == 0 ? 0 : 3) : (t == 0 ? 1 : 2)];
        return {aen ? without_negative_zero(c.position) : c.position,
                normalize_or_zero(c.normal),
                {c.uv[0], c.uv[1]}};
    }
    // An edge point: the very call evaluate_surface (evaluate_surface_aen) makes for a triangle's edge.
    const bool on_edge[4] = {t == 0, s == one, t == one, s == 0};
    const std::uint32_t r[4] = {s, t, one - s, one - t}; // measured from q[k] along edge k
    for (unsigned k = 0; k < 4; ++k) {
        if (!on_edge[k]) continue;
        const SurfaceCorner& from = q[k];
        const SurfaceCorner& to = q[(k + 1) % 4];
        if (aen) {
            const bool from_first = aen_first(from, one - r[k], to, r[k]);
            const std::uint32_t tb = from_first ? r[k] : one - r[k]; // measured from the first end
            return from_first ? aen_edge_point(from, en[k].at_from, to, en[k].at_to, fixed_weight(one - tb),
                                               fixed_weight(tb), opt.alpha)
                              : aen_edge_point(to, en[k].at_to, from, en[k].at_from, fixed_weight(one - tb),
                                               fixed_weight(tb), opt.alpha);
        }
        const bool from_first = from.index < to.index || (from.index == to.index && k < (k + 1) % 4);
        const SurfaceCorner& a = from_first ? from : to;
        const SurfaceCorner& b = from_first ? to : from;
        const std::uint32_t tb = from_first ? r[k] : one - r[k];
        return edge_point(a, b, fixed_weight(one - tb), fixed_weight(tb), opt);
    }
    // Inside: bilinear weights of q0 (0,0), q1 (1,0), q2 (1,1), q3 (0,1).
    const float fs = fixed_weight(s), ft = fixed_weight(t);
    const float gs = fixed_weight(one - s), gt = fixed_weight(one - t);
    const float w[4] = {gs * gt, fs * gt, fs * ft, gs * ft};
    SurfacePoint out;
    Vec3 flat_p{}, flat_n{};
    for (unsigned k = 0; k < 4; ++k) {
        flat_p = flat_p + w[k] * q[k].position;
        flat_n = flat_n + w[k] * q[k].normal;
        out.uv[0] += w[k] * q[k].uv[0];
        out.uv[1] += w[k] * q[k].uv[1];
    }
    if (opt.surface == Surface::phong) {
        // Boubekeur and Alexa 2008 on quads: p* = sum_k w_k pi_k(p), p the bilinear point; normals stay
        // linear.
        Vec3 ph{};
        for (unsigned k = 0; k < 4; ++k) ph = ph + w[k] * phong_project(flat_p, q[k]);
        out.position = blend(flat_p, ph, opt.alpha);
        out.normal = normalize_or_zero(flat_n);
        return out;
    }
    // PN quad: bicubic Bezier net b[i][j] (i along s, j along t). Boundary: the corners and the PN (PN-AEN)
    // edge control points, so each boundary curve is the triangles' edge curve. Inside: the parallelogram
    // rule plus the bilinear twist D = (q0 + q2 - q1 - q3) / 9, which makes a planar quad with its plane's
    // normals the bilinear quad itself (the degree-elevated bilinear net; docs/algorithm.md §6.2).
    auto ctrl = [&](unsigned i, unsigned edge, bool at_from, unsigned j) {
        if (!aen) return pn_control(q[i].position, q[i].normal, q[j].position);
        return aen_control(q[i].position, q[i].normal, at_from ? en[edge].at_from : en[edge].at_to,
                           q[j].position);
    };
    Vec3 b[4][4];
    b[0][0] = q[0].position;
    b[3][0] = q[1].position;
    b[3][3] = q[2].position;
    b[0][3] = q[3].position;
    b[1][0] = ctrl(0, 0, true, 1);
    b[2][0] = ctrl(1, 0, false, 0);
    b[3][1] = ctrl(1, 1, true, 2);
    b[3][2] = ctrl(2, 1, false, 1);
    b[2][3] = ctrl(2, 2, true, 3);
    b[1][3] = ctrl(3, 2, false, 2);
    b[0][2] = ctrl(3, 3, true, 0);
    b[0][1] = ctrl(0, 3, false, 3);
    const Vec3 twist = (1.0f / 9.0f) * ((q[0].position + q[2].position) - (q[1].position + q[3].position));
    b[1][1] = ((b[1][0] + b[0][1]) - q[0].position) + twist;
    b[2][1] = ((b[2][0] + b[3][1]) - q[1].position) - twist;
    b[2][2] = ((b[2][3] + b[3][2]) - q[2].position) + twist;
    b[1][2] = ((b[1][3] + b[0][2]) - q[3].position) - twist;
    const float bs[4] = {gs * gs * gs, 3.0f * gs * gs * fs, 3.0f * gs * fs * fs, fs * fs * fs};
    const float bt[4] = {gt * gt * gt, 3.0f * gt * gt * ft, 3.0f * gt * ft * ft, ft * ft * ft};
    Vec3 pn{};
    for (unsigned j = 0; j < 4; ++j) {
        Vec3 row{};
        for (unsigned i = 0; i < 4; ++i) row = row + bs[i] * b[i][j];
        pn = pn + bt[j] * row;
    }
    // Normals: the biquadratic whose boundary is the triangles' quadratic edge normal s^2 Na + t^2 Nb + st
    // n_ab (Vlachos et al. 2001): edge middle control normal n_ab / 2 (Bernstein's 2st), centre their mean.
    const Vec3 m[4] = {0.5f * pn_edge_normal(q[0], q[1]), 0.5f * pn_edge_normal(q[1], q[2]),
                       0.5f * pn_edge_normal(q[2], q[3]), 0.5f * pn_edge_normal(q[3], q[0])};
    const Vec3 nq[3][3] = {{q[0].normal, m[3], q[3].normal},
                           {m[0], 0.25f * ((m[0] + m[1]) + (m[2] + m[3])), m[2]},
                           {q[1].normal, m[1], q[2].normal}};
    const float cs[3] = {gs * gs, 2.0f * gs * fs, fs * fs};
    const float ct[3] = {gt * gt, 2.0f * gt * ft, ft * ft};
    Vec3 nn{};
    for (unsigned j = 0; j < 3; ++j) {
        Vec3 row{};
        for (unsigned i = 0; i < 3; ++i) row = row + cs[i] * nq[i][j];
        nn = nn + ct[j] * row;
    }
    const Vec3 p = blend(flat_p, pn, opt.alpha);
    out.position = aen ? without_negative_zero(p) : p;
    out.normal = normalize_or_zero(blend(flat_n, nn, opt.alpha));
    return out;
}

} // namespace detail

SurfacePoint evaluate_surface_aen(const SurfaceCorner (&c)[3], const AdjacentEdge (&adjacent)[3],
                                  const std::uint32_t (&w)[3], const SurfaceOptions& opt) noexcept {
    if (opt.surface != Surface::pn_aen) return evaluate_surface(c, w, opt);
    for (unsigned k = 0; k < 3; ++k) {
        if (w[k] == cp::fixed_one) {
            return {detail::without_negative_zero(c[k].position),
                    normalize_or_zero(c[k].normal),
                    {c[k].uv[0], c[k].uv[1]}};
        }
    }
    detail::EdgeNormals en[3];
    for (unsigned e = 0; e < 3; ++e) en[e] = detail::adjacent_normals(c[e], c[(e + 1) % 3], adjacent[e]);
    for (unsigned k = 0; k < 3; ++k) {
        if (w[k] != 0) continue;
        const unsigned i = (k + 1) % 3, j = (k + 2) % 3; // the edge opposite corner k is edge i: c[i] -> c[j]
        if (detail::aen_first(c[i], w[i], c[j], w[j])) {
            return detail::aen_edge_point(c[i], en[i].at_from, c[j], en[i].at_to, detail::fixed_weight(w[i]),
                                          detail::fixed_weight(w[j]), opt.alpha);
        }
        return detail::aen_edge_point(c[j], en[i].at_to, c[i], en[i].at_from, detail::fixed_weight(w[j]),
                                      detail::fixed_weight(w[i]), opt.alpha);
    }
    return detail::aen_interior_point(c, en, detail::fixed_weight(w[0]), detail::fixed_weight(w[1]),
                                      detail::fixed_weight(w[2]), opt.alpha);
}

SurfacePoint evaluate_quad_surface(const SurfaceCorner (&q)[4], std::uint32_t s, std::uint32_t t,
                                   const SurfaceOptions& opt) noexcept {
    if (opt.surface == Surface::pn_aen)
        return evaluate_quad_surface_aen(q, BoundaryEdges<4>(q).edge, s, t, opt);
    if (opt.surface != Surface::pn_triangles && opt.surface != Surface::phong)
        return evaluate_quad_surface(q, s, t);
    const std::uint32_t one = cp::fixed_one;
    return detail::quad_point(q, nullptr, s < one ? s : one, t < one ? t : one, opt);
}

SurfacePoint evaluate_quad_surface_aen(const SurfaceCorner (&q)[4], const AdjacentEdge (&adjacent)[4],
                                       std::uint32_t s, std::uint32_t t, const SurfaceOptions& opt) noexcept {
    if (opt.surface != Surface::pn_aen) return evaluate_quad_surface(q, s, t, opt);
    detail::EdgeNormals en[4];
    for (unsigned e = 0; e < 4; ++e) en[e] = detail::adjacent_normals(q[e], q[(e + 1) % 4], adjacent[e]);
    const std::uint32_t one = cp::fixed_one;
    return detail::quad_point(q, en, s < one ? s : one, t < one ? t : one, opt);
}

} // namespace ctess::rt
