// A consumer of ctess, built as a user's project would be (tests/consumer/*/CMakeLists.txt) and with the
// flags that break naive evaluation: -O3 -march=native -ffp-contract=fast, GNU extensions on. It tessellates
// a PN-evaluated icosphere (triangles, ctess::rt::CpPatch) and a quad torus (cp::split_quad, two CpPatch
// halves, cp::quad_point, evaluate_quad_surface) with edge factors from each edge's length, welds the output
// by exact position bits and checks that each surface is closed: the boundary of the sum of its triangles is
// empty, i.e. every welded edge is used as often in one direction as in the other (zero-area triangles at
// CP's thresholds cancel their own edges; a crack or a hole leaves edges over). Exit 0 when both are
// watertight.
#include <ctess/runtime.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <vector>

namespace {

using ctess::rt::SurfaceCorner;
using ctess::rt::Vec3;

struct Mesh {
    std::vector<SurfaceCorner> corners;
    std::vector<std::array<std::uint32_t, 4>> faces; // triangles use the first three
};

// An edge's factor from its two corners in index order, so both faces that share it get the same float.
float edge_factor(const Mesh& m, std::uint32_t i, std::uint32_t j, float density) {
    const Vec3 a = m.corners[i < j ? i : j].position, b = m.corners[i < j ? j : i].position;
    const Vec3 d = b - a;
    return std::sqrt(dot(d, d)) * density;
}

struct Welder {
    std::map<std::array<std::uint32_t, 3>, std::uint32_t> ids;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::uint32_t id(const Vec3& p) {
        std::array<std::uint32_t, 3> key{};
        std::memcpy(key.data(), &p, sizeof key);
        return ids.emplace(key, static_cast<std::uint32_t>(ids.size())).first->second;
    }
    // Edges {a, b} used a different number of times as a -> b and as b -> a.
    std::size_t open_edges() const {
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> net; // (lower, higher) -> uses up minus down
        for (const auto& t : triangles)
            for (unsigned k = 0; k < 3; ++k) {
                const std::uint32_t a = t[k], b = t[(k + 1) % 3];
                if (a != b) net[{a < b ? a : b, a < b ? b : a}] += a < b ? 1 : -1;
            }
        std::size_t open = 0;
        for (const auto& e : net) open += e.second != 0;
        return open;
    }
};

Mesh icosphere() {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    const float p[12][3] = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                            {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    const std::uint32_t f[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    Mesh m;
    for (std::uint32_t i = 0; i < 12; ++i) {
        const Vec3 v{p[i][0], p[i][1], p[i][2]};
        m.corners.push_back({v, v, {0.0f, 0.0f}, i});
    }
    for (const auto& tri : f) m.faces.push_back({tri[0], tri[1], tri[2], 0});
    return m;
}

Mesh quad_torus(std::uint32_t rings, std::uint32_t sides) {
    Mesh m;
    const float two_pi = 6.2831853f;
    for (std::uint32_t i = 0; i < rings; ++i)
        for (std::uint32_t j = 0; j < sides; ++j) {
            const float a = two_pi * static_cast<float>(i) / static_cast<float>(rings);
            const float b = two_pi * static_cast<float>(j) / static_cast<float>(sides);
            const Vec3 n{std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), std::sin(b)};
            const Vec3 c{2.0f * std::cos(a), 2.0f * std::sin(a), 0.0f};
            m.corners.push_back({c + 0.7f * n, n, {0.0f, 0.0f}, i * sides + j});
        }
    for (std::uint32_t i = 0; i < rings; ++i)
        for (std::uint32_t j = 0; j < sides; ++j) {
            const std::uint32_t i1 = (i + 1) % rings, j1 = (j + 1) % sides;
            m.faces.push_back({i * sides + j, i1 * sides + j, i1 * sides + j1, i * sides + j1});
        }
    return m;
}

std::size_t tessellate_triangles(const Mesh& m, float density, Welder& out) {
    const ctess::rt::SurfaceOptions pn{ctess::rt::Surface::pn_triangles, 1.0f};
    std::vector<ctess::DomainPoint> points;
    std::vector<std::uint32_t> indices;
    for (const auto& f : m.faces) {
        const ctess::rt::CpPatch patch(ctess::rt::cp_tables, edge_factor(m, f[0], f[1], density),
                                       edge_factor(m, f[1], f[2], density),
                                       edge_factor(m, f[2], f[0], density));
        points.resize(patch.vertex_count());
        indices.resize(3 * std::size_t{patch.triangle_count()});
        if (!patch.emit(points, indices)) return 1;
        const SurfaceCorner c[3] = {m.corners[f[0]], m.corners[f[1]], m.corners[f[2]]};
        std::vector<std::uint32_t> id(points.size());
        for (std::size_t i = 0; i < points.size(); ++i) {
            const std::uint32_t w[3] = {ctess::cp::fixed_one - points[i].u - points[i].v, points[i].u,
                                        points[i].v};
            id[i] = out.id(ctess::rt::evaluate_surface(c, w, pn).position);
        }
        for (std::size_t t = 0; t < indices.size(); t += 3)
            out.triangles.push_back({id[indices[t]], id[indices[t + 1]], id[indices[t + 2]]});
    }
    return 0;
}

std::size_t tessellate_quads(const Mesh& m, float density, Welder& out) {
    std::vector<ctess::DomainPoint> points;
    std::vector<std::uint32_t> indices;
    for (const auto& f : m.faces) {
        const std::array<float, 4> factors = {
            edge_factor(m, f[0], f[1], density), edge_factor(m, f[1], f[2], density),
            edge_factor(m, f[2], f[3], density), edge_factor(m, f[3], f[0], density)};
        const ctess::cp::QuadSplit split = ctess::cp::split_quad(factors);
        const SurfaceCorner q[4] = {m.corners[f[0]], m.corners[f[1]], m.corners[f[2]], m.corners[f[3]]};
        for (unsigned half = 0; half < 2; ++half) {
            const auto& tf = split.triangles[half].factors;
            const ctess::rt::CpPatch patch(ctess::rt::cp_tables, tf[0], tf[1], tf[2]);
            points.resize(patch.vertex_count());
            indices.resize(3 * std::size_t{patch.triangle_count()});
            if (!patch.emit(points, indices)) return 1;
            std::vector<std::uint32_t> id(points.size());
            for (std::size_t i = 0; i < points.size(); ++i) {
                const ctess::DomainPoint s = ctess::cp::quad_point(half, points[i]);
                id[i] = out.id(ctess::rt::evaluate_quad_surface(q, s.u, s.v).position);
            }
            for (std::size_t t = 0; t < indices.size(); t += 3)
                out.triangles.push_back({id[indices[t]], id[indices[t + 1]], id[indices[t + 2]]});
        }
    }
    return 0;
}

} // namespace

int main() {
    int failures = 0;
    for (const float density : {2.3f, 7.9f, 21.7f}) {
        Welder sphere, torus;
        const std::size_t sphere_bad =
            tessellate_triangles(icosphere(), density, sphere) + sphere.open_edges();
        const std::size_t torus_bad =
            tessellate_quads(quad_torus(12, 8), density, torus) + torus.open_edges();
        std::printf(
            "density %.1f: icosphere %zu triangles, %zu open edges; quad torus %zu triangles, %zu open "
            "edges\n",
            static_cast<double>(density), sphere.triangles.size(), sphere_bad, torus.triangles.size(),
            torus_bad);
        failures += sphere_bad != 0 || torus_bad != 0 || sphere.triangles.size() <= 20 ||
                    torus.triangles.size() <= 2 * 96;
    }
    std::printf("%s\n", failures == 0 ? "watertight" : "NOT watertight");
    return failures == 0 ? 0 : 1;
}
