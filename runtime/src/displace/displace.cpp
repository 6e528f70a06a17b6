// Displacement's evaluation (displace.hpp, docs/algorithm.md §8), compiled with -ffp-contract=off
// -fno-fast-math like the surfaces (runtime/CMakeLists.txt): a point on a shared edge is displaced by the
// same operations on the same values from both faces, so the two give the same bits.
#include <ctess/runtime/displace/displace.hpp>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <ctess/cp/line.hpp>

namespace ctess::rt {

namespace {

constexpr std::uint32_t one = cp::fixed_one;
constexpr float inv_one = 1.0f / static_cast<float>(cp::fixed_one); // a power of two: w * inv_one is exact

Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

const float* vertex_data(const MeshView& mesh, std::uint32_t v) {
    return mesh.vertices + std::size_t{v} * mesh_vertex_floats;
}

Vec3 vertex_position(const MeshView& mesh, std::uint32_t v) {
    const float* p = vertex_data(mesh, v);
    return {p[0], p[1], p[2]};
}

bool same_position(const MeshView& mesh, std::uint32_t a, std::uint32_t b) {
    const Vec3 p = vertex_position(mesh, a), q = vertex_position(mesh, b);
    return std::bit_cast<std::uint32_t>(p.x) == std::bit_cast<std::uint32_t>(q.x) &&
           std::bit_cast<std::uint32_t>(p.y) == std::bit_cast<std::uint32_t>(q.y) &&
           std::bit_cast<std::uint32_t>(p.z) == std::bit_cast<std::uint32_t>(q.z);
}

// The order of §6.1's edge rule: positions by their bit patterns, x, then y, then z.
bool position_before(Vec3 a, Vec3 b) {
    const std::uint32_t pa[3] = {std::bit_cast<std::uint32_t>(a.x), std::bit_cast<std::uint32_t>(a.y),
                                 std::bit_cast<std::uint32_t>(a.z)};
    const std::uint32_t pb[3] = {std::bit_cast<std::uint32_t>(b.x), std::bit_cast<std::uint32_t>(b.y),
                                 std::bit_cast<std::uint32_t>(b.z)};
    for (unsigned k = 0; k < 3; ++k)
        if (pa[k] != pb[k]) return pa[k] < pb[k];
    return false;
}

// A corner's dominant vertex (§8.2): meshoptimizer's (tessellation_indices slot 9-11) where the mesh has
// adjacency, else the position id, else the vertex itself. Each is a function of the position alone.
std::uint32_t dominant_vertex(const MeshView& mesh, std::uint32_t v, const std::uint64_t* face,
                              const unsigned* slot) {
    std::uint32_t d = v;
    if (mesh.adjacency != nullptr && face != nullptr)
        d = mesh.adjacency[12 * *face + 9 + *slot];
    else if (mesh.position_ids != nullptr)
        d = mesh.position_ids[v];
    return d < mesh.vertex_count && same_position(mesh, d, v) ? d : v;
}

Vec3 vertex_direction(const Displacement& d, const MeshView& mesh, std::uint32_t v) {
    const float* n = d.directions != nullptr ? d.directions + 3 * std::size_t{v} : vertex_data(mesh, v) + 3;
    return normalize_or_zero({n[0], n[1], n[2]});
}

void move(SurfacePoint& p, float height, Vec3 direction) {
    p.position = p.position + height * direction;
}

bool vector_mode(const DisplacementPatch& patch) {
    return patch.source->mode == DisplacementMode::vector;
}

// A tangent frame (§8.7): t along +u, b, n the displacement direction.
struct Frame {
    Vec3 t, b, n;
};

// Position + x T + y B + z N, the offset summed first (the same operations from every face).
void move_vector(SurfacePoint& p, Vec3 vector, const Frame& f) {
    p.position = p.position + (vector.x * f.t + vector.y * f.b + vector.z * f.n);
}

// The frame field at weights w of the patch's corners (n of them), each axis interpolated and normalised as
// the directions are (zero stays zero).
Frame interpolated_frame(const DisplacementPatch& patch, const unsigned* corner, const float* w, unsigned n) {
    Vec3 t{0, 0, 0}, b{0, 0, 0}, d{0, 0, 0};
    for (unsigned k = 0; k < n; ++k) {
        t = t + w[k] * patch.tangent[corner[k]];
        b = b + w[k] * patch.bitangent[corner[k]];
        d = d + w[k] * patch.direction[corner[k]];
    }
    return {normalize_or_zero(t), normalize_or_zero(b), normalize_or_zero(d)};
}

// The displaced normal of vector mode (§8.7): S = P + D with D = x T + y B + z N in the point's frame
// (its derivatives left out, as §8.3 leaves out dN), so S_u = t_u' + D_u, S_v = t_v' + D_v with D_u, D_v from
// the vector's central differences; t_u', t_v' are the base tangents projected onto N's plane as in
// bend_normal, to which this reduces when the vector is (0, 0, h) and the frame's n is the surface normal.
void bend_normal_vector(SurfacePoint& p, Vec3 tu, Vec3 tv, Vec3 vu, Vec3 vv, const Frame& f) {
    const Vec3 n = normalize_or_zero(p.normal);
    if (!(dot(n, n) > 0.0f)) return;
    const Vec3 pu = tu - dot(tu, n) * n, pv = tv - dot(tv, n) * n;
    const float j = dot(cross(pu, pv), n);
    const Vec3 du = vu.x * f.t + vu.y * f.b + vu.z * f.n, dv = vv.x * f.t + vv.y * f.b + vv.z * f.n;
    if (!(j != 0.0f) || !std::isfinite(dot(du, du)) || !std::isfinite(dot(dv, dv))) return;
    const Vec3 m = cross(pu + du, pv + dv);
    const Vec3 bent = normalize_or_zero((j < 0.0f ? -1.0f : 1.0f) * m);
    if (dot(bent, bent) > 0.0f) p.normal = bent;
}

Vec3 vector_difference(Vec3 plus, Vec3 minus, float step) {
    return (1.0f / (2.0f * step)) * (plus - minus);
}

// The own uv at triangle parameter (a, b) = (w1, w2), and at quad parameter (s, t) (bilinear).
std::array<float, 2> tri_own_uv(const DisplacementPatch& patch, float a, float b) {
    const float(&u)[4][2] = patch.own_uv;
    const float c = 1.0f - a - b;
    return {c * u[0][0] + a * u[1][0] + b * u[2][0], c * u[0][1] + a * u[1][1] + b * u[2][1]};
}

std::array<float, 2> quad_own_uv(const DisplacementPatch& patch, float s, float t) {
    const float(&u)[4][2] = patch.own_uv;
    const float w[4] = {(1.0f - s) * (1.0f - t), s * (1.0f - t), s * t, (1.0f - s) * t};
    return {w[0] * u[0][0] + w[1] * u[1][0] + w[2] * u[2][0] + w[3] * u[3][0],
            w[0] * u[0][1] + w[1] * u[1][1] + w[2] * u[2][1] + w[3] * u[3][1]};
}

Vec3 tri_uv_vector(const DisplacementPatch& patch, float a, float b) {
    const std::array<float, 2> uv = tri_own_uv(patch, a, b);
    return displacement_vector(*patch.source, uv[0], uv[1]);
}

Vec3 quad_uv_vector(const DisplacementPatch& patch, float s, float t) {
    const std::array<float, 2> uv = quad_own_uv(patch, s, t);
    return displacement_vector(*patch.source, uv[0], uv[1]);
}

// Bends p.normal by the height's gradient (§8.3): tangents tu, tv of the patch parameter, the height's
// central differences hu, hv along them. The displaced surface S = P + h N has S_u x S_v = J N + hv (tu' x N)
// + hu (N x tv') with tu', tv' the tangents projected onto N's plane and J = (tu' x tv') . N (the dN terms
// are left out, as bump mapping does; Blinn 1978).
void bend_normal(SurfacePoint& p, Vec3 tu, Vec3 tv, float hu, float hv) {
    const Vec3 n = normalize_or_zero(p.normal);
    if (!(dot(n, n) > 0.0f)) return;
    const Vec3 pu = tu - dot(tu, n) * n, pv = tv - dot(tv, n) * n;
    const float j = dot(cross(pu, pv), n);
    if (!(j != 0.0f) || !std::isfinite(hu) || !std::isfinite(hv)) return;
    const Vec3 m = j * n + hv * cross(pu, n) + hu * cross(n, pv);
    const Vec3 bent = normalize_or_zero((j < 0.0f ? -1.0f : 1.0f) * m);
    if (dot(bent, bent) > 0.0f) p.normal = bent;
}

float tri_uv_height(const DisplacementPatch& patch, float a, float b) {
    const std::array<float, 2> uv = tri_own_uv(patch, a, b);
    return displacement_height(*patch.source, uv[0], uv[1]);
}

float quad_uv_height(const DisplacementPatch& patch, float s, float t) {
    const std::array<float, 2> uv = quad_own_uv(patch, s, t);
    return displacement_height(*patch.source, uv[0], uv[1]);
}

// A point on patch edge k (corner k -> k + 1) with weights wa at corner k and wb at corner k + 1: the
// dominant edge's uvs and the dominant directions, interpolated from the endpoint first in position order
// (the same operations from both faces; equal positions: the larger weight first).
void displace_edge(const DisplacementPatch& patch, unsigned k, std::uint32_t wa, std::uint32_t wb,
                   SurfacePoint& p) {
    unsigned a = k, b = (k + 1) % patch.corners;
    const float* uv_a = patch.edge_uv[k][0];
    const float* uv_b = patch.edge_uv[k][1];
    if (wa == one || wb == one) {
        const unsigned c = wa == one ? a : b;
        if (vector_mode(patch))
            return move_vector(
                p, displacement_vector(*patch.source, patch.corner_uv[c][0], patch.corner_uv[c][1]),
                {patch.tangent[c], patch.bitangent[c], patch.direction[c]});
        move(p, displacement_height(*patch.source, patch.corner_uv[c][0], patch.corner_uv[c][1]),
             patch.direction[c]);
        return;
    }
    const bool swap = position_before(patch.position[b], patch.position[a]) ||
                      (!position_before(patch.position[a], patch.position[b]) && wb > wa);
    if (swap) {
        std::swap(a, b);
        std::swap(uv_a, uv_b);
        std::swap(wa, wb);
    }
    const float ta = static_cast<float>(wa) * inv_one, tb = static_cast<float>(wb) * inv_one;
    const float u = ta * uv_a[0] + tb * uv_b[0], v = ta * uv_a[1] + tb * uv_b[1];
    if (vector_mode(patch)) {
        const unsigned corner[2] = {a, b};
        const float w[2] = {ta, tb};
        return move_vector(p, displacement_vector(*patch.source, u, v),
                           interpolated_frame(patch, corner, w, 2));
    }
    const Vec3 dir = normalize_or_zero(ta * patch.direction[a] + tb * patch.direction[b]);
    move(p, displacement_height(*patch.source, u, v), dir);
}

// Vector mode's triangle point (§8.7): the normal from the vector's differences in the own parameters, then
// the position as displace_triangle_point's (corners and edges through displace_edge, the interior in the
// frame interpolated by the barycentric weights).
void displace_triangle_vector(const DisplacementPatch& patch, const std::uint32_t (&w)[3], float a, float b,
                              SurfacePoint& p) {
    const float step = patch.source->normal_step;
    const unsigned corner[3] = {0, 1, 2};
    const float weight[3] = {static_cast<float>(w[0]) * inv_one, a, b};
    const Frame frame = interpolated_frame(patch, corner, weight, 3);
    const Vec3 vu =
        vector_difference(tri_uv_vector(patch, a + step, b), tri_uv_vector(patch, a - step, b), step);
    const Vec3 vv =
        vector_difference(tri_uv_vector(patch, a, b + step), tri_uv_vector(patch, a, b - step), step);
    bend_normal_vector(p, patch.position[1] - patch.position[0], patch.position[2] - patch.position[0], vu,
                       vv, frame);
    for (unsigned k = 0; k < 3; ++k)
        if (w[(k + 2) % 3] == 0 || w[k] == one) {
            if (w[k] == one) return displace_edge(patch, k, one, 0, p);
            return displace_edge(patch, k, w[k], w[(k + 1) % 3], p);
        }
    move_vector(p, displacement_vector(*patch.source, p.uv[0], p.uv[1]), frame);
}

// A quad point on the boundary goes through displace_edge: a corner (both coordinates at a bound), else edge
// k from q_k with parameter r measured from q_k (the quad_vertex convention: t = 0, s = 1, t = 1, s = 0).
// False for an interior point, which the caller moves.
bool displace_quad_boundary(const DisplacementPatch& patch, std::uint32_t s, std::uint32_t t,
                            SurfacePoint& p) {
    if ((s == 0 || s == one) && (t == 0 || t == one)) {
        const unsigned c = t == 0 ? (s == 0 ? 0 : 1) : (s == one ? 2 : 3);
        displace_edge(patch, c, one, 0, p);
        return true;
    }
    const bool on_edge[4] = {t == 0, s == one, t == one, s == 0};
    const std::uint32_t r[4] = {s, t, one - s, one - t};
    for (unsigned k = 0; k < 4; ++k)
        if (on_edge[k]) {
            displace_edge(patch, k, one - r[k], r[k], p);
            return true;
        }
    return false;
}

void displace_quad_vector(const DisplacementPatch& patch, std::uint32_t s, std::uint32_t t, float fs,
                          float ft, SurfacePoint& p) {
    const float step = patch.source->normal_step;
    const unsigned corner[4] = {0, 1, 2, 3};
    const float weight[4] = {(1.0f - fs) * (1.0f - ft), fs * (1.0f - ft), fs * ft, (1.0f - fs) * ft};
    const Frame frame = interpolated_frame(patch, corner, weight, 4);
    const Vec3 vu =
        vector_difference(quad_uv_vector(patch, fs + step, ft), quad_uv_vector(patch, fs - step, ft), step);
    const Vec3 vv =
        vector_difference(quad_uv_vector(patch, fs, ft + step), quad_uv_vector(patch, fs, ft - step), step);
    const Vec3(&q)[4] = patch.position;
    const Vec3 ts = (1.0f - ft) * (q[1] - q[0]) + ft * (q[2] - q[3]);
    const Vec3 tt = (1.0f - fs) * (q[3] - q[0]) + fs * (q[2] - q[1]);
    bend_normal_vector(p, ts, tt, vu, vv, frame);
    if (displace_quad_boundary(patch, s, t, p)) return;
    move_vector(p, displacement_vector(*patch.source, p.uv[0], p.uv[1]), frame);
}

} // namespace

float displacement_height(const Displacement& d, float u, float v) {
    const float texel = d.function != nullptr ? d.function(d.context, u, v) : sample_bilinear(d.map, u, v);
    return d.scale * (texel * d.factor + d.offset);
}

Vec3 displacement_vector(const Displacement& d, float u, float v) {
    Vec3 texel;
    if (d.vector_function != nullptr) {
        texel = d.vector_function(d.context, u, v);
    } else {
        const Texel3 rgb = sample_bilinear_rgb(d.map, u, v);
        texel = {rgb.x, rgb.y, rgb.z};
    }
    return {d.scale * (texel.x * d.factor + d.offset), d.scale * (texel.y * d.factor + d.offset),
            d.scale * (texel.z * d.factor + d.offset)};
}

float displacement_bound(const Displacement& d) {
    if (d.mode == DisplacementMode::vector) {
        // The longest texel vector (§8.7): per texel, not per channel range, so that the bound is attained.
        const HeightMap& m = d.map;
        if (d.vector_function != nullptr || m.texels == nullptr || m.channels < 3) return 0.0f;
        const std::size_t n = std::size_t{m.width} * m.height;
        // The length in double, rounded to float once: a float dot product overflows once a component passes
        // about 1.8e19 (an EXR texel can), where the length itself is still a float.
        double bound = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const float* t = m.texels + i * m.channels;
            const Vec3 v{d.scale * (t[0] * d.factor + d.offset), d.scale * (t[1] * d.factor + d.offset),
                         d.scale * (t[2] * d.factor + d.offset)};
            const double length = std::sqrt(double{v.x} * v.x + double{v.y} * v.y + double{v.z} * v.z);
            if (length > bound) bound = length; // NaN compares false: skipped
        }
        return static_cast<float>(bound);
    }
    if (d.function != nullptr) return 0.0f;
    const TexelRange r = texel_range(d.map);
    const float lo = std::fabs(d.scale * (r.min * d.factor + d.offset));
    const float hi = std::fabs(d.scale * (r.max * d.factor + d.offset));
    return lo > hi ? lo : hi;
}

bool displacement_valid(const Displacement& d) {
    const bool numbers = std::isfinite(d.scale) && std::isfinite(d.factor) && std::isfinite(d.offset) &&
                         std::isfinite(d.factor_bound) && d.factor_bound >= 0.0f && d.normal_step > 0.0f &&
                         d.normal_step <= 0.5f;
    if (!numbers) return false;
    // The channel count must be the mode's (§8.7): a map of another count would be read as something else.
    const bool map_read = d.map.texels != nullptr && d.map.width != 0 && d.map.height != 0;
    if (d.mode == DisplacementMode::scalar)
        return d.vector_function == nullptr && (d.function != nullptr || !map_read || d.map.channels == 1);
    if (d.mode == DisplacementMode::vector)
        return d.function == nullptr && d.tangents != nullptr &&
               (d.vector_function != nullptr || !map_read || d.map.channels == 3);
    return false;
}

bool welded_directions(const MeshView& mesh, std::span<float> out) {
    const std::size_t n = mesh.vertex_count;
    if (out.size() < 3 * n || (n > 0 && mesh.vertices == nullptr)) return false;
    const std::uint32_t* id = mesh.position_ids;
    if (id != nullptr)
        for (std::size_t v = 0; v < n; ++v)
            if (id[v] >= n || id[id[v]] != id[v]) return false;
    // Sums at each position's id, in vertex order; then every vertex reads its id's sum (ids last, so that
    // a sum is normalised once, after every vertex that reads it).
    for (std::size_t v = 0; v < 3 * n; ++v) out[v] = 0.0f;
    for (std::size_t v = 0; v < n; ++v) {
        const std::size_t r = id != nullptr ? id[v] : v;
        const float* normal = vertex_data(mesh, static_cast<std::uint32_t>(v)) + 3;
        for (unsigned c = 0; c < 3; ++c) out[3 * r + c] += normal[c];
    }
    for (unsigned pass = 0; pass < 2; ++pass)
        for (std::size_t v = 0; v < n; ++v) {
            const std::size_t r = id != nullptr ? id[v] : v;
            if ((r == v) != (pass == 1)) continue;
            const Vec3 dir = normalize_or_zero({out[3 * r], out[3 * r + 1], out[3 * r + 2]});
            out[3 * v] = dir.x;
            out[3 * v + 1] = dir.y;
            out[3 * v + 2] = dir.z;
        }
    return true;
}

bool uv_tangents(const MeshView& mesh, std::span<float> out) {
    const std::size_t n = mesh.vertex_count;
    if (out.size() < 4 * n || (n > 0 && mesh.vertices == nullptr)) return false;
    // Every face triangle's three vertex indices (a quad as (q0, q1, q2), (q0, q2, q3)), checked first so
    // that nothing is written on a bad index.
    std::vector<std::uint32_t> corners;
    corners.reserve(3 * (std::size_t{mesh.triangle_count} + 2 * std::size_t{mesh.quad_count}));
    if (mesh.triangle_count > 0 && mesh.indices == nullptr) return false;
    if (mesh.quad_count > 0 && mesh.quad_indices == nullptr) return false;
    for (std::size_t i = 0; i < 3 * std::size_t{mesh.triangle_count}; ++i) corners.push_back(mesh.indices[i]);
    for (std::size_t q = 0; q < mesh.quad_count; ++q) {
        const std::uint32_t* c = mesh.quad_indices + 4 * q;
        corners.insert(corners.end(), {c[0], c[1], c[2], c[0], c[2], c[3]});
    }
    for (const std::uint32_t v : corners)
        if (v >= n) return false;
    // Lengyel's sums per vertex: dP/du (sdir) and dP/dv (tdir) of every face triangle at the vertex.
    std::vector<Vec3> sdir(n, Vec3{0, 0, 0}), tdir(n, Vec3{0, 0, 0});
    for (std::size_t f = 0; f < corners.size(); f += 3) {
        const std::uint32_t i[3] = {corners[f], corners[f + 1], corners[f + 2]};
        const float* p[3] = {vertex_data(mesh, i[0]), vertex_data(mesh, i[1]), vertex_data(mesh, i[2])};
        const Vec3 e1{p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
        const Vec3 e2{p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
        const float s1 = p[1][6] - p[0][6], t1 = p[1][7] - p[0][7];
        const float s2 = p[2][6] - p[0][6], t2 = p[2][7] - p[0][7];
        const float det = s1 * t2 - s2 * t1;
        if (!(det != 0.0f) || !std::isfinite(det)) continue;
        const float r = 1.0f / det;
        const Vec3 su = r * (t2 * e1 - t1 * e2), sv = r * (s1 * e2 - s2 * e1);
        if (!std::isfinite(dot(su, su)) || !std::isfinite(dot(sv, sv))) continue;
        for (const std::uint32_t v : i) {
            sdir[v] = sdir[v] + su;
            tdir[v] = tdir[v] + sv;
        }
    }
    for (std::size_t v = 0; v < n; ++v) {
        const float* own = vertex_data(mesh, static_cast<std::uint32_t>(v));
        const Vec3 normal = normalize_or_zero({own[3], own[4], own[5]});
        const Vec3 t = normalize_or_zero(sdir[v] - dot(sdir[v], normal) * normal);
        const bool unusable = !(dot(t, t) > 0.0f);
        out[4 * v] = unusable ? 0.0f : t.x;
        out[4 * v + 1] = unusable ? 0.0f : t.y;
        out[4 * v + 2] = unusable ? 0.0f : t.z;
        out[4 * v + 3] = dot(cross(normal, t), tdir[v]) < 0.0f ? -1.0f : 1.0f;
    }
    return true;
}

DisplacementPatch displacement_patch(const Displacement& d, const MeshView& mesh, unsigned n,
                                     const std::uint32_t* vertex, const PatchFaces& faces) {
    DisplacementPatch patch;
    patch.source = &d;
    patch.corners = n == 4 ? 4 : 3;
    for (unsigned k = 0; k < patch.corners; ++k) {
        const std::uint32_t v = vertex[k];
        const std::uint32_t dom = dominant_vertex(mesh, v, &faces.corner_face[k], &faces.corner_slot[k]);
        const float* own = vertex_data(mesh, v);
        patch.position[k] = {own[0], own[1], own[2]};
        patch.own_uv[k][0] = own[6];
        patch.own_uv[k][1] = own[7];
        patch.corner_uv[k][0] = vertex_data(mesh, dom)[6];
        patch.corner_uv[k][1] = vertex_data(mesh, dom)[7];
        patch.direction[k] = vertex_direction(d, mesh, dom);
        if (d.mode == DisplacementMode::vector && d.tangents != nullptr) {
            // The dominant vertex's frame (§8.7): T made orthogonal to the direction N, B = cross(N, T) w.
            const float* t = d.tangents + 4 * std::size_t{dom};
            const Vec3 nd = patch.direction[k];
            const Vec3 raw{t[0], t[1], t[2]};
            patch.tangent[k] = normalize_or_zero(raw - dot(raw, nd) * nd);
            patch.bitangent[k] = (t[3] < 0.0f ? -1.0f : 1.0f) * cross(nd, patch.tangent[k]);
        }
    }
    // The dominant edge (§8.2): of the own edge and the neighbour's (meshoptimizer's slots 3-8, paired by
    // position), the one whose vertices, taken in position order, are lexicographically smaller. The
    // neighbour sees the same two edges, so it picks the same one.
    for (unsigned k = 0; k < patch.corners; ++k) {
        const std::uint32_t a = vertex[k], b = vertex[(k + 1) % patch.corners];
        std::uint32_t pick[2] = {a, b};
        if (mesh.adjacency != nullptr) {
            const std::uint32_t* t = mesh.adjacency + 12 * faces.edge_face[k] + 3 + 2 * faces.edge_slot[k];
            std::uint32_t c = t[0], e = t[1];
            if (c < mesh.vertex_count && e < mesh.vertex_count) {
                if (!same_position(mesh, c, a)) std::swap(c, e);
                if (same_position(mesh, c, a) && same_position(mesh, e, b)) {
                    const bool a_first = !position_before(vertex_position(mesh, b), vertex_position(mesh, a));
                    const std::uint32_t own_key[2] = {a_first ? a : b, a_first ? b : a};
                    const std::uint32_t adj_key[2] = {a_first ? c : e, a_first ? e : c};
                    if (adj_key[0] < own_key[0] || (adj_key[0] == own_key[0] && adj_key[1] < own_key[1])) {
                        pick[0] = c;
                        pick[1] = e;
                    }
                }
            }
        }
        for (unsigned end = 0; end < 2; ++end) {
            patch.edge_uv[k][end][0] = vertex_data(mesh, pick[end])[6];
            patch.edge_uv[k][end][1] = vertex_data(mesh, pick[end])[7];
        }
    }
    return patch;
}

void displace_triangle_point(const DisplacementPatch& patch, const std::uint32_t (&w)[3], SurfacePoint& p) {
    if (patch.source == nullptr) return;
    const Displacement& d = *patch.source;
    // The normal first, from the own parameterisation (it reads the undisplaced p.normal only).
    const float a = static_cast<float>(w[1]) * inv_one, b = static_cast<float>(w[2]) * inv_one;
    const float step = d.normal_step;
    if (vector_mode(patch)) return displace_triangle_vector(patch, w, a, b, p);
    const float hu = (tri_uv_height(patch, a + step, b) - tri_uv_height(patch, a - step, b)) / (2.0f * step);
    const float hv = (tri_uv_height(patch, a, b + step) - tri_uv_height(patch, a, b - step)) / (2.0f * step);
    bend_normal(p, patch.position[1] - patch.position[0], patch.position[2] - patch.position[0], hu, hv);
    // Then the position: a corner, an edge point (edge k has zero weight at corner k + 2) or an interior one.
    for (unsigned k = 0; k < 3; ++k)
        if (w[(k + 2) % 3] == 0 || w[k] == one) {
            if (w[k] == one) return displace_edge(patch, k, one, 0, p);
            return displace_edge(patch, k, w[k], w[(k + 1) % 3], p);
        }
    const float t[3] = {static_cast<float>(w[0]) * inv_one, a, b};
    const Vec3 dir =
        normalize_or_zero(t[0] * patch.direction[0] + t[1] * patch.direction[1] + t[2] * patch.direction[2]);
    move(p, displacement_height(d, p.uv[0], p.uv[1]), dir);
}

void displace_quad_point(const DisplacementPatch& patch, std::uint32_t s, std::uint32_t t, SurfacePoint& p) {
    if (patch.source == nullptr) return;
    const Displacement& d = *patch.source;
    const float fs = static_cast<float>(s) * inv_one, ft = static_cast<float>(t) * inv_one;
    const float step = d.normal_step;
    if (vector_mode(patch)) return displace_quad_vector(patch, s, t, fs, ft, p);
    const float hu =
        (quad_uv_height(patch, fs + step, ft) - quad_uv_height(patch, fs - step, ft)) / (2.0f * step);
    const float hv =
        (quad_uv_height(patch, fs, ft + step) - quad_uv_height(patch, fs, ft - step)) / (2.0f * step);
    const Vec3(&q)[4] = patch.position;
    const Vec3 ts = (1.0f - ft) * (q[1] - q[0]) + ft * (q[2] - q[3]);
    const Vec3 tt = (1.0f - fs) * (q[3] - q[0]) + fs * (q[2] - q[1]);
    bend_normal(p, ts, tt, hu, hv);
    if (displace_quad_boundary(patch, s, t, p)) return;
    const float w[4] = {(1.0f - fs) * (1.0f - ft), fs * (1.0f - ft), fs * ft, (1.0f - fs) * ft};
    const Vec3 dir = normalize_or_zero(w[0] * patch.direction[0] + w[1] * patch.direction[1] +
                                       w[2] * patch.direction[2] + w[3] * patch.direction[3]);
    move(p, displacement_height(d, p.uv[0], p.uv[1]), dir);
}

float displaced_edge_factor(const Displacement& d, float factor, Vec3 a, Vec3 b) {
    if (!(d.factor_bound > 0.0f)) return factor;
    const Vec3 e = b - a;
    const float length = std::sqrt(dot(e, e));
    if (!(length > 0.0f)) return factor;
    return factor * (1.0f + 2.0f * d.factor_bound / length);
}

} // namespace ctess::rt
