// Surface evaluation on tessellated patches (docs/algorithm.md §6): PN-AEN on split normals and the quad
// surfaces (Phong, PN, PN-AEN). The key property is crack-freeness: every point of a shared edge must come
// out bit for bit the same from both faces, checked exhaustively on closed meshes built here (a cube with
// per-face normals, a cylinder with split caps), while plain PN must crack on the same meshes (so the check
// can fail).
#include <catch2/catch.hpp>

#include <ctess/runtime/surface/eval.hpp>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <vector>

#ifdef CTESS_HAVE_MESHOPTIMIZER
#include <meshoptimizer.h>
#endif

using namespace ctess;
using namespace ctess::rt;

namespace {

constexpr std::uint32_t one = cp::fixed_one;

std::array<std::uint32_t, 3> bits(Vec3 v) {
    return {std::bit_cast<std::uint32_t>(v.x), std::bit_cast<std::uint32_t>(v.y),
            std::bit_cast<std::uint32_t>(v.z)};
}

bool same_bits(Vec3 a, Vec3 b) {
    return bits(a) == bits(b);
}

float length(Vec3 v) {
    return std::sqrt(dot(v, v));
}

Vec3 unit(Vec3 v) {
    return (1.0f / length(v)) * v;
}

// Edge parameters: both ends densely, then a stride through the whole range (about 1,150 values).
std::vector<std::uint32_t> edge_parameters() {
    std::vector<std::uint32_t> r;
    for (std::uint32_t k = 0; k <= 64; ++k) {
        r.push_back(k);
        r.push_back(one - k);
    }
    for (std::uint32_t k = 16411; k < one; k += 16411) r.push_back(k);
    r.push_back(one / 2);
    r.push_back(one / 3);
    return r;
}

// A mesh of triangles and quads (counter-clockwise from outside) over vertices that may share positions with
// different normals (split normals).
struct Mesh {
    std::vector<SurfaceCorner> vertices;
    std::vector<std::vector<std::uint32_t>> faces;

    std::uint32_t add(Vec3 p, Vec3 n) {
        const auto index = static_cast<std::uint32_t>(vertices.size());
        SurfaceCorner c;
        c.position = p;
        c.normal = n;
        c.uv[0] = p.x + 2.0f * p.z;
        c.uv[1] = p.y - p.z;
        c.index = index;
        vertices.push_back(c);
        return index;
    }
};

using PositionKey = std::array<std::uint32_t, 3>;

// The neighbour of every face edge by position (what meshopt_generateTessellationIndexBuffer finds): edge e
// of face f runs corner e -> e + 1; its neighbour runs the same positions the other way. The neighbour's
// vertices are stored in the neighbour's own order (to, from), so evaluate_*_aen must pair them by position.
struct Adjacency {
    struct Neighbour {
        std::uint32_t face = 0, edge = 0;
    };
    std::vector<std::vector<Neighbour>> neighbour; // [face][edge]
    std::vector<std::vector<AdjacentEdge>> adjacent;
};

Adjacency build_adjacency(const Mesh& m) {
    std::map<std::pair<PositionKey, PositionKey>, Adjacency::Neighbour> edges;
    for (std::uint32_t f = 0; f < m.faces.size(); ++f) {
        const auto& v = m.faces[f];
        for (std::uint32_t e = 0; e < v.size(); ++e) {
            const Vec3 from = m.vertices[v[e]].position, to = m.vertices[v[(e + 1) % v.size()]].position;
            REQUIRE(edges.emplace(std::pair{bits(from), bits(to)}, Adjacency::Neighbour{f, e}).second);
        }
    }
    Adjacency a;
    for (std::uint32_t f = 0; f < m.faces.size(); ++f) {
        const auto& v = m.faces[f];
        a.neighbour.emplace_back();
        a.adjacent.emplace_back();
        for (std::uint32_t e = 0; e < v.size(); ++e) {
            const Vec3 from = m.vertices[v[e]].position, to = m.vertices[v[(e + 1) % v.size()]].position;
            const auto it = edges.find({bits(to), bits(from)});
            REQUIRE(it != edges.end()); // closed: every edge has a neighbour
            const auto& nv = m.faces[it->second.face];
            const std::uint32_t ne = it->second.edge;
            a.neighbour.back().push_back(it->second);
            a.adjacent.back().push_back({{m.vertices[nv[ne]], m.vertices[nv[(ne + 1) % nv.size()]]}});
        }
    }
    return a;
}

// The point at parameter r (units of fixed_one, from corner e) on edge e of face f, evaluated by the face.
// aen: through evaluate_surface_aen / evaluate_quad_surface_aen with the mesh's adjacency.
SurfacePoint edge_point(const Mesh& m, const Adjacency& adj, std::uint32_t f, std::uint32_t e,
                        std::uint32_t r, const SurfaceOptions& opt, bool aen) {
    const auto& v = m.faces[f];
    if (v.size() == 3) {
        const SurfaceCorner c[3] = {m.vertices[v[0]], m.vertices[v[1]], m.vertices[v[2]]};
        std::uint32_t w[3] = {0, 0, 0};
        w[e] = one - r;
        w[(e + 1) % 3] = r;
        if (!aen) return evaluate_surface(c, w, opt);
        const AdjacentEdge a[3] = {adj.adjacent[f][0], adj.adjacent[f][1], adj.adjacent[f][2]};
        return evaluate_surface_aen(c, a, w, opt);
    }
    const SurfaceCorner q[4] = {m.vertices[v[0]], m.vertices[v[1]], m.vertices[v[2]], m.vertices[v[3]]};
    // Edge k of the unit square, r from q[k]: (r, 0), (1, r), (1 - r, 1), (0, 1 - r) (cp::quad_point's
    // square).
    const std::uint32_t s[4] = {r, one, one - r, 0}, t[4] = {0, r, one, one - r};
    if (!aen) return evaluate_quad_surface(q, s[e], t[e], opt);
    const AdjacentEdge a[4] = {adj.adjacent[f][0], adj.adjacent[f][1], adj.adjacent[f][2],
                               adj.adjacent[f][3]};
    return evaluate_quad_surface_aen(q, a, s[e], t[e], opt);
}

struct EdgeCheck {
    std::size_t points = 0, mismatches = 0;
    std::size_t cracked_edges = 0, split_edges = 0, cracked_unsplit_edges = 0;
};

// Every shared edge's points from both faces: the point at r from corner e of face f is the point at one - r
// from the neighbour's corner ne.
EdgeCheck check_shared_edges(const Mesh& m, const Adjacency& adj, const SurfaceOptions& opt, bool aen) {
    EdgeCheck out;
    const auto params = edge_parameters();
    for (std::uint32_t f = 0; f < m.faces.size(); ++f) {
        for (std::uint32_t e = 0; e < m.faces[f].size(); ++e) {
            const auto n = adj.neighbour[f][e];
            std::size_t edge_mismatches = 0;
            for (const std::uint32_t r : params) {
                const SurfacePoint a = edge_point(m, adj, f, e, r, opt, aen);
                const SurfacePoint b = edge_point(m, adj, n.face, n.edge, one - r, opt, aen);
                ++out.points;
                if (!same_bits(a.position, b.position)) ++edge_mismatches;
            }
            // Split: the neighbour's normals at the edge's positions differ from the own.
            const auto& v = m.faces[f];
            const auto& nv = m.faces[n.face];
            const bool split =
                !same_bits(m.vertices[v[e]].normal, m.vertices[nv[(n.edge + 1) % nv.size()]].normal) ||
                !same_bits(m.vertices[v[(e + 1) % v.size()]].normal, m.vertices[nv[n.edge]].normal);
            out.mismatches += edge_mismatches;
            out.split_edges += split;
            out.cracked_edges += edge_mismatches > 0;
            out.cracked_unsplit_edges += edge_mismatches > 0 && !split;
        }
    }
    return out;
}

Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// A cube of side 2 with per-face normals: 24 vertices, every edge a hard edge; as 6 quads or 12 triangles.
// jitter > 0 moves the 8 corners (the same way from every face) and takes each face's normal from its
// diagonals: on the exact cube every edge is perpendicular to both normals, so even plain PN keeps it
// straight.
Mesh hard_cube(bool quads, float jitter = 0.0f) {
    Mesh m;
    const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    auto corner = [&](Vec3 p) {
        const float key = 1.0f + 3.0f * p.x + 5.0f * p.y + 7.0f * p.z;
        return p + jitter * Vec3{std::sin(key), std::sin(2.0f * key), std::cos(3.0f * key)};
    };
    for (unsigned a = 0; a < 3; ++a) {
        for (const float sign : {1.0f, -1.0f}) {
            const Vec3 axis = sign * axes[a];
            const Vec3 u = axes[(a + 1) % 3], v = axes[(a + 2) % 3];
            // u x v = axis a: counter-clockwise from outside on the + face, reversed on the - face.
            const Vec3 du = sign > 0 ? u : v, dv = sign > 0 ? v : u;
            const Vec3 p[4] = {corner(axis + (-1.0f) * du + (-1.0f) * dv), corner(axis + du + (-1.0f) * dv),
                               corner(axis + du + dv), corner(axis + (-1.0f) * du + dv)};
            const Vec3 n = jitter > 0.0f ? unit(cross(p[2] - p[0], p[3] - p[1])) : axis;
            const std::uint32_t i0 = m.add(p[0], n), i1 = m.add(p[1], n), i2 = m.add(p[2], n),
                                i3 = m.add(p[3], n);
            if (quads) {
                m.faces.push_back({i0, i1, i2, i3});
            } else {
                m.faces.push_back({i0, i1, i2});
                m.faces.push_back({i0, i2, i3});
            }
        }
    }
    return m;
}

// A cylinder (radius 1, height 2, `segments` around): smooth sides with radial normals (shared vertices),
// caps with their own vertices and axial normals (split normals at the rims), the caps as triangle fans.
// Sides as quads or as two triangles each.
Mesh split_cylinder(unsigned segments, bool side_quads) {
    Mesh m;
    std::vector<std::uint32_t> side_bottom, side_top, cap_bottom, cap_top;
    std::vector<Vec3> ring;
    for (unsigned k = 0; k < segments; ++k) {
        const double a = 2.0 * 3.14159265358979323846 * k / segments;
        ring.push_back({static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a)), 0.0f});
    }
    for (unsigned k = 0; k < segments; ++k) {
        const Vec3 lo{ring[k].x, ring[k].y, -1.0f}, hi{ring[k].x, ring[k].y, 1.0f};
        side_bottom.push_back(m.add(lo, ring[k]));
        side_top.push_back(m.add(hi, ring[k]));
        cap_bottom.push_back(m.add(lo, {0, 0, -1}));
        cap_top.push_back(m.add(hi, {0, 0, 1}));
    }
    const std::uint32_t centre_bottom = m.add({0, 0, -1}, {0, 0, -1});
    const std::uint32_t centre_top = m.add({0, 0, 1}, {0, 0, 1});
    for (unsigned k = 0; k < segments; ++k) {
        const unsigned n = (k + 1) % segments;
        if (side_quads) {
            m.faces.push_back({side_bottom[k], side_bottom[n], side_top[n], side_top[k]});
        } else {
            m.faces.push_back({side_bottom[k], side_bottom[n], side_top[n]});
            m.faces.push_back({side_bottom[k], side_top[n], side_top[k]});
        }
        m.faces.push_back({centre_top, cap_top[k], cap_top[n]});
        m.faces.push_back({centre_bottom, cap_bottom[n], cap_bottom[k]});
    }
    return m;
}

// The same mesh with normals welded per position (the mean of the split normals): no split normals left.
Mesh welded(const Mesh& m) {
    Mesh out = m;
    std::map<PositionKey, Vec3> sum;
    std::map<PositionKey, std::uint32_t> first;
    for (const auto& v : m.vertices) {
        sum[bits(v.position)] = sum[bits(v.position)] + v.normal;
        first.emplace(bits(v.position), v.index);
    }
    for (auto& v : out.vertices) {
        v.normal = unit(sum[bits(v.position)]);
        v.index = first[bits(v.position)]; // one mesh index per position, as a welded mesh has
    }
    return out;
}

SurfaceOptions options(Surface s, float alpha) {
    SurfaceOptions o;
    o.surface = s;
    o.alpha = alpha;
    return o;
}

} // namespace

TEST_CASE(
    "PN-AEN (algorithm.md §6.1): two triangles on a split-normal edge agree bit for bit, plain PN does not",
    "[surface][aen]") {
    // Triangle A = (p0, p1, p2), triangle B = (p1, p0, p3): the edge p0 p1 with different normals on each
    // side and different mesh indices (a hard edge between two split vertices).
    const Vec3 p0{0.1f, -0.3f, 0.2f}, p1{1.3f, 0.2f, -0.1f}, p2{0.6f, 1.1f, 0.4f}, p3{0.7f, -1.2f, 0.5f};
    Mesh m;
    const std::uint32_t a0 = m.add(p0, unit({0.2f, 0.3f, 1.0f})), a1 = m.add(p1, unit({-0.4f, 0.1f, 1.0f}));
    const std::uint32_t a2 = m.add(p2, unit({0.0f, 0.5f, 1.0f}));
    const std::uint32_t b0 = m.add(p0, unit({0.3f, -0.6f, 0.8f})), b1 = m.add(p1, unit({-0.2f, -0.7f, 0.9f}));
    const std::uint32_t b3 = m.add(p3, unit({0.1f, -0.5f, 1.0f}));
    m.faces = {{a0, a1, a2}, {b1, b0, b3}};
    // Only the shared edge has a neighbour; the other edges are boundaries (the own vertices).
    Adjacency adj;
    adj.neighbour = {{{1, 0}, {0, 1}, {0, 2}}, {{0, 0}, {1, 1}, {1, 2}}};
    const auto& v = m.vertices;
    adj.adjacent = {{{{v[b1], v[b0]}}, {{v[a1], v[a2]}}, {{v[a2], v[a0]}}},
                    {{{v[a0], v[a1]}}, {{v[b0], v[b3]}}, {{v[b3], v[b1]}}}};
    for (const float alpha : {0.75f, 1.0f, 0.3f}) {
        CAPTURE(alpha);
        std::size_t pn_mismatches = 0, points = 0;
        for (const std::uint32_t r : edge_parameters()) {
            const SurfacePoint x = edge_point(m, adj, 0, 0, r, options(Surface::pn_aen, alpha), true);
            const SurfacePoint y = edge_point(m, adj, 1, 0, one - r, options(Surface::pn_aen, alpha), true);
            REQUIRE(bits(x.position) == bits(y.position));
            const SurfacePoint px = edge_point(m, adj, 0, 0, r, options(Surface::pn_triangles, alpha), false);
            const SurfacePoint py =
                edge_point(m, adj, 1, 0, one - r, options(Surface::pn_triangles, alpha), false);
            ++points;
            if (!same_bits(px.position, py.position)) ++pn_mismatches;
        }
        // Plain PN builds different control points on each side: the edge cracks away from its corners.
        CHECK(pn_mismatches > points / 2);
    }
}

TEST_CASE(
    "PN-AEN (algorithm.md §6.1): closed meshes with hard edges are crack-free bit for bit, plain PN cracks",
    "[surface][aen]") {
    struct Case {
        const char* name;
        Mesh mesh;
        bool pn_cracks; // every split edge cracks under plain PN (not the exact cube's: straight for PN too)
    };
    const Case cases[] = {
        {"cube, 12 triangles", hard_cube(false), false},
        {"cube, 6 quads", hard_cube(true), false},
        {"jittered cube, 12 triangles", hard_cube(false, 0.15f), true},
        {"jittered cube, 6 quads", hard_cube(true, 0.15f), true},
        {"cylinder, 12 segments, triangles", split_cylinder(12, false), true},
        {"cylinder, 7 segments, quad sides and triangle caps", split_cylinder(7, true), true}};
    for (const auto& c : cases) {
        CAPTURE(c.name);
        const Adjacency adj = build_adjacency(c.mesh);
        for (const float alpha : {0.75f, 1.0f}) {
            CAPTURE(alpha);
            const EdgeCheck aen = check_shared_edges(c.mesh, adj, options(Surface::pn_aen, alpha), true);
            CHECK(aen.mismatches == 0);
            CHECK(aen.points > 20000);
            CHECK(aen.split_edges > 0);
            // Plain PN cracks on every split-normal edge and on no other.
            const EdgeCheck pn =
                check_shared_edges(c.mesh, adj, options(Surface::pn_triangles, alpha), false);
            if (c.pn_cracks) CHECK(pn.cracked_edges == pn.split_edges);
            CHECK(pn.cracked_unsplit_edges == 0);
        }
    }
}

TEST_CASE("PN, Phong and PN-AEN (algorithm.md §6.2): welded meshes of quads and triangles are crack-free",
          "[surface][quad]") {
    // Welded normals, one index per position: plain PN and Phong must agree across quad-quad and
    // quad-triangle edges too (a quad's edge is the triangles' edge curve, computed by the same call).
    const Mesh meshes[] = {welded(split_cylinder(7, true)), welded(hard_cube(true)),
                           welded(split_cylinder(9, false))};
    for (const auto& m : meshes) {
        const Adjacency adj = build_adjacency(m);
        for (const Surface s : {Surface::flat, Surface::pn_triangles, Surface::phong, Surface::pn_aen}) {
            CAPTURE(static_cast<unsigned>(s));
            CHECK(check_shared_edges(m, adj, options(s, 0.75f), false).mismatches == 0);
            if (s == Surface::pn_aen)
                CHECK(check_shared_edges(m, adj, options(s, 0.75f), true).mismatches == 0);
        }
    }
}

#ifdef CTESS_HAVE_MESHOPTIMIZER
TEST_CASE(
    "PN-AEN (algorithm.md §6.1): adjacency filled from meshopt_generateTessellationIndexBuffer is crack-free",
    "[surface][aen]") {
    // The way a pipeline fills AdjacentEdge: vertices[i[3 + 2e]] and vertices[i[4 + 2e]] of the 12 indices.
    for (const Mesh& m : {hard_cube(false, 0.15f), split_cylinder(12, false)}) {
        std::vector<unsigned> indices;
        for (const auto& f : m.faces) indices.insert(indices.end(), f.begin(), f.end());
        std::vector<float> positions;
        for (const auto& v : m.vertices)
            positions.insert(positions.end(), {v.position.x, v.position.y, v.position.z});
        std::vector<unsigned> tess(indices.size() * 4); // 12 per triangle
        meshopt_generateTessellationIndexBuffer(tess.data(), indices.data(), indices.size(), positions.data(),
                                                m.vertices.size(), 3 * sizeof(float));
        Adjacency adj = build_adjacency(m); // for the neighbour of each edge
        for (std::size_t f = 0; f < m.faces.size(); ++f) {
            for (unsigned e = 0; e < 3; ++e) {
                adj.adjacent[f][e] = {
                    {m.vertices[tess[12 * f + 3 + 2 * e]], m.vertices[tess[12 * f + 4 + 2 * e]]}};
            }
        }
        const EdgeCheck aen = check_shared_edges(m, adj, options(Surface::pn_aen, 0.75f), true);
        CHECK(aen.mismatches == 0);
        // The neighbour really was found: its normals differ from the own on a hard edge, so the result
        // moved.
        const EdgeCheck boundary = check_shared_edges(m, adj, options(Surface::pn_aen, 0.75f), false);
        CHECK(boundary.mismatches > 0);
    }
}
#endif

TEST_CASE(
    "PN-AEN (algorithm.md §6.1): without split normals it is PN, bit for bit inside and on index-ordered "
    "edges",
    "[surface][aen]") {
    // Corners whose mesh index order equals their position-bit order (x increasing, all positive): then the
    // edge order of PN (index) and PN-AEN (position bits) agree and the operations are the same.
    const SurfaceCorner c[3] = {{{0.25f, 0.5f, 0.1f}, unit({0.1f, -0.2f, 1.0f}), {0.0f, 0.0f}, 3},
                                {{1.5f, 0.75f, 0.3f}, unit({0.4f, 0.2f, 1.0f}), {1.0f, 0.0f}, 7},
                                {{2.5f, 1.75f, 0.2f}, unit({-0.3f, 0.5f, 1.0f}), {0.0f, 1.0f}, 9}};
    const AdjacentEdge own[3] = {{{c[1], c[0]}}, {{c[1], c[2]}}, {{c[0], c[2]}}}; // either order pairs
    std::size_t compared = 0;
    const std::uint32_t step = one / 61;
    for (std::uint32_t w0 = 0; w0 <= one; w0 += step) {
        for (std::uint32_t w1 = 0; w0 + w1 <= one; w1 += step) {
            for (int edge = 0; edge < 2; ++edge) {
                const std::uint32_t w[3] = {w0, edge ? one - w0 : w1, edge ? 0 : one - w0 - w1};
                const SurfacePoint pn = evaluate_surface(c, w, options(Surface::pn_triangles, 0.75f));
                const SurfacePoint aen = evaluate_surface_aen(c, own, w, options(Surface::pn_aen, 0.75f));
                const SurfacePoint no_adj = evaluate_surface(c, w, options(Surface::pn_aen, 0.75f));
                REQUIRE(bits(aen.position) == bits(pn.position)); // all positive: no -0 to clear
                REQUIRE(bits(aen.normal) == bits(pn.normal));
                REQUIRE(bits(no_adj.position) == bits(aen.position));
                ++compared;
            }
        }
    }
    CHECK(compared > 3000);
    // Index order against position order: the edge is summed the other way round, equal within rounding.
    SurfaceCorner r[3] = {c[0], c[1], c[2]};
    r[0].index = 10;
    std::uint32_t max_diff_ulps = 0;
    for (std::uint32_t k = 1; k < one; k += 9973) {
        const std::uint32_t w[3] = {k, one - k, 0};
        const Vec3 a = evaluate_surface(r, w, options(Surface::pn_triangles, 1.0f)).position;
        const Vec3 b = evaluate_surface(r, w, options(Surface::pn_aen, 1.0f)).position;
        for (unsigned i = 0; i < 3; ++i) {
            const auto ua = static_cast<std::int64_t>(bits(a)[i]), ub = static_cast<std::int64_t>(bits(b)[i]);
            const auto d = static_cast<std::uint32_t>(ua > ub ? ua - ub : ub - ua);
            max_diff_ulps = d > max_diff_ulps ? d : max_diff_ulps;
        }
    }
    CHECK(max_diff_ulps <= 4);
}

TEST_CASE("PN-AEN (algorithm.md §6.1): the interior meets the edge, corners are copied, bad adjacency is a "
          "boundary",
          "[surface][aen]") {
    const Mesh m = hard_cube(false, 0.15f);
    const Adjacency adj = build_adjacency(m);
    const auto& f = m.faces[0];
    const SurfaceCorner c[3] = {m.vertices[f[0]], m.vertices[f[1]], m.vertices[f[2]]};
    const AdjacentEdge a[3] = {adj.adjacent[0][0], adj.adjacent[0][1], adj.adjacent[0][2]};
    const SurfaceOptions opt = options(Surface::pn_aen, 1.0f);
    // Continuity: a point one 2^-24 step inside the edge is within float rounding of the edge point.
    float worst = 0.0f;
    for (std::uint32_t k = 1; k < one; k += 65537) {
        const std::uint32_t on_edge[3] = {one - k, k, 0}, inside[3] = {one - k - 1, k, 1};
        if (k + 1 > one) continue;
        const Vec3 d = evaluate_surface_aen(c, a, on_edge, opt).position -
                       evaluate_surface_aen(c, a, inside, opt).position;
        worst = std::fmax(worst, length(d));
    }
    CHECK(worst < 2e-6f);
    // Corners: the own position and normal exactly.
    for (unsigned k = 0; k < 3; ++k) {
        std::uint32_t w[3] = {0, 0, 0};
        w[k] = one;
        const SurfacePoint p = evaluate_surface_aen(c, a, w, opt);
        CHECK(bits(p.position) == bits(c[k].position + Vec3{0.0f, 0.0f, 0.0f}));
        CHECK(bits(p.normal) == bits(c[k].normal));
    }
    // Adjacency whose positions match neither order is a boundary (the own normals); swapped order is the
    // same.
    AdjacentEdge junk[3] = {a[0], a[1], a[2]}, swapped[3] = {a[0], a[1], a[2]};
    const AdjacentEdge own[3] = {{{c[0], c[1]}}, {{c[1], c[2]}}, {{c[2], c[0]}}};
    junk[0].vertex[1].position.x += 1.0f;
    std::swap(swapped[0].vertex[0], swapped[0].vertex[1]);
    const AdjacentEdge own_then_rest[3] = {own[0], a[1], a[2]};
    for (std::uint32_t k = 0; k <= one; k += 1048573) {
        for (const std::uint32_t j : {0u, 3u}) {
            if (k + j > one) continue;
            const std::uint32_t w[3] = {one - k - j, k, j};
            CHECK(bits(evaluate_surface_aen(c, junk, w, opt).position) ==
                  bits(evaluate_surface_aen(c, own_then_rest, w, opt).position));
            CHECK(bits(evaluate_surface_aen(c, swapped, w, opt).position) ==
                  bits(evaluate_surface_aen(c, a, w, opt).position));
        }
    }
    // The hard edge moved the surface: the neighbour's normals were used.
    const std::uint32_t mid[3] = {one / 2, one / 2, 0};
    CHECK(!same_bits(evaluate_surface_aen(c, a, mid, opt).position,
                     evaluate_surface_aen(c, own, mid, opt).position));
}

TEST_CASE("Quad surfaces (algorithm.md §6.2): corners exact, flat unchanged, planar quads stay bilinear",
          "[surface][quad]") {
    // A non-parallelogram planar quad in z = 0.5 with the plane's normal at every corner.
    const SurfaceCorner q[4] = {{{0.0f, 0.0f, 0.5f}, {0, 0, 2}, {0.0f, 0.0f}, 4},
                                {{2.0f, 0.25f, 0.5f}, {0, 0, 2}, {1.0f, 0.0f}, 1},
                                {{1.75f, 1.5f, 0.5f}, {0, 0, 2}, {1.0f, 1.0f}, 9},
                                {{-0.25f, 1.0f, 0.5f}, {0, 0, 2}, {0.0f, 1.0f}, 2}};
    const std::uint32_t st[4][2] = {{0, 0}, {one, 0}, {one, one}, {0, one}};
    for (const Surface s : {Surface::flat, Surface::pn_triangles, Surface::phong, Surface::pn_aen}) {
        CAPTURE(static_cast<unsigned>(s));
        for (unsigned k = 0; k < 4; ++k) {
            const SurfacePoint p = evaluate_quad_surface(q, st[k][0], st[k][1], options(s, 1.0f));
            CHECK(bits(p.position) == bits(q[k].position));
            CHECK(bits(p.normal) == bits(Vec3{0, 0, 1}));
            CHECK(p.uv[0] == q[k].uv[0]);
            CHECK(p.uv[1] == q[k].uv[1]);
        }
        float worst = 0.0f;
        for (std::uint32_t u = 0; u <= one; u += one / 37) {
            for (std::uint32_t v = 0; v <= one; v += one / 41) {
                const SurfacePoint flat = evaluate_quad_surface(q, u, v);
                const SurfacePoint p = evaluate_quad_surface(q, u, v, options(s, 1.0f));
                if (s == Surface::flat) REQUIRE(bits(p.position) == bits(flat.position)); // the same function
                // The plane's normals make PN's edge points the edge thirds and the net the bilinear one;
                // Phong projects onto the plane itself. Only rounding is left.
                worst = std::fmax(worst, length(p.position - flat.position));
                CHECK(std::fabs(p.position.z - 0.5f) < 3e-7f);
                CHECK((p.normal.x == 0.0f && p.normal.y == 0.0f && std::fabs(p.normal.z - 1.0f) < 1e-6f));
            }
        }
        CHECK(worst < 1e-6f);
    }
}

TEST_CASE("Quad surfaces (algorithm.md §6.2): PN and Phong quads on a sphere are closer than flat",
          "[surface][quad]") {
    // Four points of the unit sphere around +z with radial normals: a curved surface lies nearer the sphere.
    const float c = 0.5f, z = std::sqrt(1.0f - 2.0f * c * c);
    const SurfaceCorner q[4] = {{{-c, -c, z}, {-c, -c, z}, {0, 0}, 0},
                                {{c, -c, z}, {c, -c, z}, {1, 0}, 1},
                                {{c, c, z}, {c, c, z}, {1, 1}, 2},
                                {{-c, c, z}, {-c, c, z}, {0, 1}, 3}};
    auto max_radial_error = [&](Surface s) {
        float worst = 0.0f;
        for (std::uint32_t u = 0; u <= one; u += one / 16) {
            for (std::uint32_t v = 0; v <= one; v += one / 16) {
                const SurfacePoint p = evaluate_quad_surface(q, u, v, options(s, 1.0f));
                worst = std::fmax(worst, std::fabs(length(p.position) - 1.0f));
                // The normal points outwards, near the radial direction.
                REQUIRE(dot(p.normal, unit(p.position)) > 0.95f);
            }
        }
        return worst;
    };
    // The same corners as two PN triangles (q0 q1 q3) and (q2 q3 q1): the quad must do as well as they do.
    auto max_radial_error_triangles = [&](Surface s) {
        float worst = 0.0f;
        for (std::uint32_t u = 0; u <= one; u += one / 16) {
            for (std::uint32_t v = 0; u + v <= one; v += one / 16) {
                const std::uint32_t w[3] = {one - u - v, u, v};
                for (const auto& t : {std::array{q[0], q[1], q[3]}, std::array{q[2], q[3], q[1]}}) {
                    const SurfaceCorner c3[3] = {t[0], t[1], t[2]};
                    const SurfacePoint p = evaluate_surface(c3, w, options(s, 1.0f));
                    worst = std::fmax(worst, std::fabs(length(p.position) - 1.0f));
                }
            }
        }
        return worst;
    };
    const float flat = max_radial_error(Surface::flat);
    CHECK(flat > 0.25f); // 1 - 1/sqrt(2) at the centre
    for (const Surface s : {Surface::pn_triangles, Surface::phong}) {
        CAPTURE(static_cast<unsigned>(s));
        const float quad = max_radial_error(s);
        CHECK(quad < flat / 2);
        CHECK(quad <= 1.01f * max_radial_error_triangles(s));
    }
    CHECK(max_radial_error(Surface::pn_aen) == max_radial_error(Surface::pn_triangles));
}

TEST_CASE("Quad surfaces (algorithm.md §6.2): a quad and a triangle sharing an edge agree bit for bit",
          "[surface][quad]") {
    // Quad (p0 p1 p2 p3) and triangle (p2 p1 p4) share the edge p1 p2; shared vertices, curved normals.
    Mesh m;
    const std::uint32_t i0 = m.add({0.0f, 0.0f, 0.0f}, unit({-0.3f, -0.3f, 1.0f}));
    const std::uint32_t i1 = m.add({1.1f, 0.1f, 0.2f}, unit({0.4f, -0.2f, 1.0f}));
    const std::uint32_t i2 = m.add({0.9f, 1.2f, -0.1f}, unit({0.2f, 0.5f, 1.0f}));
    const std::uint32_t i3 = m.add({-0.1f, 0.8f, 0.1f}, unit({-0.5f, 0.1f, 1.0f}));
    const std::uint32_t i4 = m.add({2.0f, 0.7f, 0.3f}, unit({0.7f, 0.1f, 1.0f}));
    m.faces = {{i0, i1, i2, i3}, {i2, i1, i4}};
    Adjacency adj;
    adj.neighbour = {{{0, 0}, {1, 0}, {0, 2}, {0, 3}}, {{0, 1}, {1, 1}, {1, 2}}};
    const auto& v = m.vertices;
    adj.adjacent = {{{{v[i0], v[i1]}}, {{v[i2], v[i1]}}, {{v[i2], v[i3]}}, {{v[i3], v[i0]}}},
                    {{{v[i1], v[i2]}}, {{v[i1], v[i4]}}, {{v[i4], v[i2]}}}};
    for (const Surface s : {Surface::flat, Surface::pn_triangles, Surface::phong, Surface::pn_aen}) {
        CAPTURE(static_cast<unsigned>(s));
        for (const std::uint32_t r : edge_parameters()) {
            const SurfacePoint a = edge_point(m, adj, 0, 1, r, options(s, 0.75f), false);
            const SurfacePoint b = edge_point(m, adj, 1, 0, one - r, options(s, 0.75f), false);
            if (s == Surface::flat) {
                // The flat quad clears -0 and the flat triangle does not (kept as they were); otherwise
                // equal.
                REQUIRE(bits(a.position + Vec3{}) == bits(b.position + Vec3{}));
                continue;
            }
            REQUIRE(bits(a.position) == bits(b.position));
            REQUIRE(bits(a.normal) == bits(b.normal));
            REQUIRE(a.uv[0] == b.uv[0]);
            REQUIRE(a.uv[1] == b.uv[1]);
            if (s == Surface::pn_aen) {
                const SurfacePoint x = edge_point(m, adj, 0, 1, r, options(s, 0.75f), true);
                const SurfacePoint y = edge_point(m, adj, 1, 0, one - r, options(s, 0.75f), true);
                REQUIRE(bits(x.position) == bits(y.position));
            }
        }
    }
}

TEST_CASE("Surface evaluation (algorithm.md §6.3): NaN and infinity give no UB and a documented result",
          "[surface][bad-input]") {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const SurfaceCorner good[4] = {{{0, 0, 0}, {0, 0, 1}, {0, 0}, 0},
                                   {{1, 0, 0}, {0, 0, 1}, {1, 0}, 1},
                                   {{1, 1, 0}, {0, 0, 1}, {1, 1}, 2},
                                   {{0, 1, 0}, {0, 0, 1}, {0, 1}, 3}};
    const SurfaceCorner tri[3] = {good[0], good[1], good[2]};
    const AdjacentEdge tri_adj[3] = {{{good[1], good[0]}}, {{good[2], good[1]}}, {{good[0], good[2]}}};
    for (const Surface s : {Surface::pn_triangles, Surface::phong, Surface::pn_aen}) {
        CAPTURE(static_cast<unsigned>(s));
        for (const Vec3 bad_position : {Vec3{nan, 0, 0}, Vec3{inf, 0, 0}}) {
            SurfaceCorner q[4] = {good[0], good[1], good[2], good[3]};
            q[2].position = bad_position;
            // The corner is copied as it is; points that read it are not finite; points that do not are.
            CHECK(std::isnan(evaluate_quad_surface(q, one, one, options(s, 0.75f)).position.x) ==
                  std::isnan(bad_position.x));
            const Vec3 inside = evaluate_quad_surface(q, one / 2, one / 3, options(s, 0.75f)).position;
            CHECK(!std::isfinite(inside.x + inside.y + inside.z));
            const Vec3 far_edge = evaluate_quad_surface(q, one / 3, 0, options(s, 0.75f)).position;
            CHECK(std::isfinite(far_edge.x + far_edge.y + far_edge.z));
            SurfaceCorner t[3] = {tri[0], tri[1], tri[2]};
            t[2].position = bad_position;
            const std::uint32_t w[3] = {one / 3, one / 3, one - 2 * (one / 3)};
            const Vec3 p = evaluate_surface_aen(t, tri_adj, w, options(s, 0.75f)).position;
            CHECK(!std::isfinite(p.x + p.y + p.z));
        }
        // A non-finite normal: the output normal is not finite or zero, never a trap; a zero normal stays
        // zero.
        SurfaceCorner q[4] = {good[0], good[1], good[2], good[3]};
        q[0].normal = {inf, nan, 0};
        const SurfacePoint p = evaluate_quad_surface(q, one / 4, one / 4, options(s, 0.75f));
        CHECK(!std::isfinite(p.position.x + p.position.y + p.position.z + p.normal.x + p.normal.y +
                             p.normal.z));
        for (auto& c : q) c.normal = {0, 0, 0};
        const SurfacePoint z = evaluate_quad_surface(q, one / 4, one / 4, options(s, 0.75f));
        CHECK(bits(z.normal) == bits(Vec3{}));
        CHECK(std::isfinite(z.position.x + z.position.y + z.position.z));
        // s, t beyond one are clamped to one (as the flat quad does): the corner.
        CHECK(bits(evaluate_quad_surface(good, 5 * one, ~0u, options(s, 0.75f)).position) ==
              bits(good[2].position));
        // A NaN alpha gives NaN positions inside, and no trap.
        CHECK(std::isnan(evaluate_quad_surface(good, one / 2, one / 2, options(s, nan)).position.x));
    }
    // An unknown surface value evaluates flat, as evaluate_surface does.
    SurfaceOptions unknown;
    unknown.surface = static_cast<Surface>(7);
    CHECK(bits(evaluate_quad_surface(good, one / 3, one / 5, unknown).position) ==
          bits(evaluate_quad_surface(good, one / 3, one / 5).position));
}

TEST_CASE("Quad surfaces (algorithm.md §6.2): the interior meets every edge (the bicubic net's boundary is "
          "the edge "
          "curve)",
          "[surface][quad]") {
    // A curved, non-planar quad; the edge points come from edge_point, the inside from the control net, so a
    // misplaced net point shows as a jump between an edge point and its neighbour one 2^-24 step inside.
    const SurfaceCorner q[4] = {{{0.0f, 0.0f, 0.0f}, unit({-0.3f, -0.3f, 1.0f}), {0, 0}, 5},
                                {{1.1f, 0.1f, 0.2f}, unit({0.4f, -0.2f, 1.0f}), {1, 0}, 2},
                                {{0.9f, 1.2f, -0.1f}, unit({0.2f, 0.5f, 1.0f}), {1, 1}, 7},
                                {{-0.1f, 0.8f, 0.3f}, unit({-0.5f, 0.1f, 1.0f}), {0, 1}, 1}};
    for (const Surface s : {Surface::pn_triangles, Surface::phong, Surface::pn_aen}) {
        CAPTURE(static_cast<unsigned>(s));
        float worst_position = 0.0f, worst_normal = 0.0f;
        for (std::uint32_t r = 1; r < one; r += 65521) {
            // Edge k's point (s, t) and the point one step towards the inside.
            const std::uint32_t edge[4][2] = {{r, 0}, {one, r}, {r, one}, {0, r}};
            const std::uint32_t inside[4][2] = {{r, 1}, {one - 1, r}, {r, one - 1}, {1, r}};
            for (unsigned k = 0; k < 4; ++k) {
                const SurfacePoint a = evaluate_quad_surface(q, edge[k][0], edge[k][1], options(s, 1.0f));
                const SurfacePoint b = evaluate_quad_surface(q, inside[k][0], inside[k][1], options(s, 1.0f));
                worst_position = std::fmax(worst_position, length(a.position - b.position));
                worst_normal = std::fmax(worst_normal, length(a.normal - b.normal));
            }
        }
        CHECK(worst_position < 2e-6f);
        CHECK(worst_normal < 2e-6f);
    }
}

TEST_CASE(
    "Bulk evaluation: evaluate_surface_points equals evaluate_surface bit for bit, writing only its count",
    "[surface][bulk]") {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const SurfaceCorner curved[3] = {{{0.1f, -0.2f, 0.3f}, unit({-0.3f, -0.2f, 1.0f}), {0.0f, 0.1f}, 7},
                                     {{1.3f, 0.1f, -0.2f}, unit({0.4f, -0.1f, 1.0f}), {1.0f, 0.2f}, 2},
                                     {{0.2f, 1.1f, 0.4f}, {0.1f, 0.5f, 2.0f}, {0.3f, 0.9f}, 9}};
    // Interior, edge and corner points, both ends of every edge densely, and weights past the triangle
    // (u + v > one, u or v > one): each must take the path evaluate_surface takes.
    std::vector<DomainPoint> base;
    std::uint32_t seed = 12345;
    for (int k = 0; k < 4000; ++k) {
        seed = seed * 1664525u + 1013904223u;
        const std::uint32_t u = (seed >> 8) % (one + 1);
        seed = seed * 1664525u + 1013904223u;
        base.push_back({u, (seed >> 8) % (one + 1 - u)});
    }
    for (const std::uint32_t t : edge_parameters()) {
        base.push_back({t, 0});
        base.push_back({0, t});
        base.push_back({t, one - t});
    }
    for (const DomainPoint p : {DomainPoint{0, 0}, DomainPoint{one, 0}, DomainPoint{0, one},
                                DomainPoint{one, 1}, DomainPoint{one / 2 + 1, one / 2}, DomainPoint{~0u, 3},
                                DomainPoint{5, ~0u}, DomainPoint{one + 1, 0}})
        base.push_back(p);
    SurfaceCorner bad_corners[3] = {curved[0], curved[1], curved[2]};
    bad_corners[1].position = {nan, 0, 0};
    bad_corners[2].normal = {inf, 0, 0};
    const SurfaceCorner(&bad)[3] = bad_corners;
    for (const auto* c : {&curved, &bad}) {
        for (const unsigned s : {0u, 1u, 2u, 3u, 7u}) { // 7: an unknown surface evaluates flat
            CAPTURE(s);
            const SurfaceOptions opt = options(static_cast<Surface>(s), 0.75f);
            std::vector<SurfacePoint> out(base.size() + 1);
            out.back().position = {-1.0f, -2.0f, -3.0f}; // past base's count: left as it is
            evaluate_surface_points(out, *c, base, opt);
            for (std::size_t k = 0; k < base.size(); ++k) {
                const std::uint32_t w[3] = {one - base[k].u - base[k].v, base[k].u, base[k].v};
                const SurfacePoint e = evaluate_surface(*c, w, opt);
                INFO("point " << base[k].u << ", " << base[k].v);
                REQUIRE(bits(out[k].position) == bits(e.position));
                REQUIRE(bits(out[k].normal) == bits(e.normal));
                REQUIRE(std::bit_cast<std::uint32_t>(out[k].uv[0]) == std::bit_cast<std::uint32_t>(e.uv[0]));
                REQUIRE(std::bit_cast<std::uint32_t>(out[k].uv[1]) == std::bit_cast<std::uint32_t>(e.uv[1]));
            }
            CHECK(bits(out.back().position) == bits(Vec3{-1.0f, -2.0f, -3.0f}));
            // A shorter out span: only its size is written.
            std::vector<SurfacePoint> few(3);
            evaluate_surface_points(few, *c, base, opt);
            CHECK(bits(few[2].position) == bits(out[2].position));
        }
    }
}
