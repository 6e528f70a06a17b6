// Shared by the displacement tests (tests/displace/): both outputs of the mesh pipeline, the seam checks by
// exact position bits, and the meshes they run on (docs/algorithm.md §8).
#pragma once
#include <catch2/catch.hpp>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include <ctess/runtime.hpp>
#include <ctess/runtime/displace/displace.hpp>
#include <ctess/runtime/models.hpp>

namespace displace_test {

using namespace ctess;

struct Output {
    std::vector<rt::TessVertex> vertices;
    std::vector<std::uint32_t> indices;
};

inline Output unwelded(const rt::MeshView& mesh, const rt::PipelineOptions& options) {
    std::vector<rt::PatchRecord> patches(mesh.patch_count());
    rt::PipelineTotals totals;
    REQUIRE(rt::setup_patches(rt::cp_tables, rt::uniform_tables, mesh, options, patches, totals) ==
            rt::PipelineStatus::ok);
    Output o;
    o.vertices.resize(totals.vertices);
    o.indices.resize(3 * std::size_t{totals.triangles});
    REQUIRE(rt::emit_mesh(rt::cp_tables, rt::uniform_tables, mesh, options, patches, o.vertices, o.indices) ==
            rt::PipelineStatus::ok);
    return o;
}

inline Output welded(const rt::MeshView& mesh, const rt::PipelineOptions& options) {
    std::vector<rt::WeldedEdge> edges(rt::weld_edge_capacity(mesh));
    std::vector<rt::WeldedPatch> patches(mesh.patch_count());
    rt::WeldedTotals totals;
    REQUIRE(rt::setup_welded(rt::cp_tables, rt::uniform_tables, mesh, options, edges, patches, totals) ==
            rt::PipelineStatus::ok);
    edges.resize(totals.edges);
    Output o;
    o.vertices.resize(totals.vertices);
    o.indices.resize(3 * std::size_t{totals.triangles});
    REQUIRE(rt::emit_welded_mesh(rt::cp_tables, rt::uniform_tables, mesh, options, edges, patches, o.vertices,
                                 o.indices) == rt::PipelineStatus::ok);
    return o;
}

using PositionKey = std::array<std::uint32_t, 3>;
inline PositionKey key_of(const rt::TessVertex& v) {
    return {std::bit_cast<std::uint32_t>(v.position[0]), std::bit_cast<std::uint32_t>(v.position[1]),
            std::bit_cast<std::uint32_t>(v.position[2])};
}

// Pairs of output vertices (same index in both runs) whose undisplaced positions are bit-identical but whose
// displaced positions are not; and how many vertices share a position with another (the pairs checked).
struct PairCheck {
    std::size_t mismatched = 0, shared = 0;
};
inline PairCheck check_pairs(const Output& base, const Output& displaced) {
    REQUIRE(base.vertices.size() == displaced.vertices.size());
    std::map<PositionKey, PositionKey> first;
    std::map<PositionKey, std::size_t> count;
    PairCheck r;
    for (std::size_t i = 0; i < base.vertices.size(); ++i) {
        const PositionKey k = key_of(base.vertices[i]), d = key_of(displaced.vertices[i]);
        const auto [it, inserted] = first.emplace(k, d);
        if (!inserted && it->second != d) ++r.mismatched;
        ++count[k];
    }
    for (const auto& [k, n] : count)
        if (n > 1) r.shared += n;
    return r;
}

// Directed edges (by exact position) without their reverse: 0 for a closed, consistently wound mesh.
inline std::size_t open_edges_by_position(const Output& o) {
    std::map<PositionKey, std::uint32_t> id;
    std::vector<std::uint32_t> ids(o.vertices.size());
    for (std::size_t i = 0; i < o.vertices.size(); ++i)
        ids[i] = id.emplace(key_of(o.vertices[i]), static_cast<std::uint32_t>(id.size())).first->second;
    std::multiset<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (std::size_t t = 0; t < o.indices.size(); t += 3)
        for (unsigned k = 0; k < 3; ++k) {
            const std::uint32_t a = ids[o.indices[t + k]], b = ids[o.indices[t + (k + 1) % 3]];
            if (a != b) edges.insert({a, b});
        }
    std::size_t open = 0;
    for (const auto& e : edges)
        if (edges.count({e.second, e.first}) != edges.count(e)) ++open;
    return open;
}

// A cube of side 2 whose faces each have their own four vertices: their own normal (hard edges) and their own
// uv chart, cell (f % 3, f / 3) of a 3 x 2 atlas (every edge is a uv seam). faces: 0 triangles, 1 quads,
// 2 a mix.
inline models::Model chart_cube(int faces) {
    models::Model m;
    const float n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (unsigned f = 0; f < 6; ++f) {
        const rt::Vec3 normal{n[f][0], n[f][1], n[f][2]};
        // Two tangents with t1 x t2 = normal (counter-clockwise seen from outside).
        const rt::Vec3 helper = std::fabs(normal.x) > 0.5f ? rt::Vec3{0, 1, 0} : rt::Vec3{1, 0, 0};
        const rt::Vec3 t1{helper.y * normal.z - helper.z * normal.y,
                          helper.z * normal.x - helper.x * normal.z,
                          helper.x * normal.y - helper.y * normal.x};
        const rt::Vec3 t2{normal.y * t1.z - normal.z * t1.y, normal.z * t1.x - normal.x * t1.z,
                          normal.x * t1.y - normal.y * t1.x};
        const float su[4] = {-1, 1, 1, -1}, sv[4] = {-1, -1, 1, 1};
        const auto first = static_cast<std::uint32_t>(m.vertex_count());
        for (unsigned c = 0; c < 4; ++c) {
            const rt::Vec3 p = normal + su[c] * t1 + sv[c] * t2;
            const float u = (static_cast<float>(f % 3) + 0.1f + 0.8f * (su[c] + 1) / 2) / 3.0f;
            const float v = (static_cast<float>(f / 3) + 0.1f + 0.8f * (sv[c] + 1) / 2) / 2.0f;
            const float vertex[8] = {p.x, p.y, p.z, normal.x, normal.y, normal.z, u, v};
            m.vertices.insert(m.vertices.end(), vertex, vertex + 8);
        }
        const bool quad = faces == 1 || (faces == 2 && f % 2 == 0);
        if (quad)
            m.quads.insert(m.quads.end(), {first, first + 1, first + 2, first + 3});
        else
            m.triangles.insert(m.triangles.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
    }
    m.has_normals = m.has_uvs = true;
    return m;
}

inline rt::MeshView view_of(const models::Model& m, const models::Adjacency* adjacency) {
    rt::MeshView v{m.vertices.data(),  static_cast<std::uint32_t>(m.vertex_count()),
                   m.triangles.data(), static_cast<std::uint32_t>(m.triangle_count()),
                   m.quads.data(),     static_cast<std::uint32_t>(m.quad_count())};
    if (adjacency != nullptr) {
        v.position_ids = adjacency->position_ids.data();
        v.adjacency = adjacency->tessellation_indices.data();
    }
    return v;
}

inline rt::PipelineOptions constant_factor(float f, rt::Surface surface) {
    rt::PipelineOptions o;
    o.dice.mode = rt::FactorMode::constant;
    o.dice.constant_factor = f;
    o.surface.surface = surface;
    return o;
}

// The right triangle (0,0,0), (1,0,0), (0,1,0) in z = 0, normal +z, uv = xy.
// Every surface x factor (30: a split uniform patch) x pattern on `mesh` with displacement d: every pair of
// output vertices at one undisplaced position stays bit-identical, and the welded output is closed. `label`
// names the mesh in failures; also(base, moved) adds the caller's checks.
template <class Also>
void check_displaced_seams(const rt::MeshView& mesh, const rt::Displacement& d, int label, Also&& also) {
    for (const rt::Surface surface :
         {rt::Surface::flat, rt::Surface::pn_triangles, rt::Surface::pn_aen, rt::Surface::phong})
        for (const float factor : {1.0f, 2.5f, 9.3f, 30.0f})
            for (const rt::Pattern pattern :
                 {rt::Pattern::cp, rt::Pattern::uniform, rt::Pattern::uniform_split,
                  rt::Pattern::d3d11_fractional_even}) {
                INFO("faces " << label << " surface " << static_cast<int>(surface) << " factor " << factor
                              << " pattern " << static_cast<int>(pattern));
                rt::PipelineOptions options = constant_factor(factor, surface);
                options.pattern = pattern;
                const Output base = unwelded(mesh, options);
                options.displacement = &d;
                const Output moved = unwelded(mesh, options);
                const PairCheck pairs = check_pairs(base, moved);
                CHECK(pairs.shared > 0);
                CHECK(pairs.mismatched == 0);
                CHECK(open_edges_by_position(welded(mesh, options)) == 0);
                also(base, moved);
            }
}

// Factors grown by d.factor_bound (§8.4): d with grown factors against `zero`, the
// same displacement at scale 0 (the undisplaced surface at the same factors): more vertices than plain factor
// 3.5, every pair at one position bit-identical, and the welded output as open as without displacement.
inline void check_grown_seams(const rt::MeshView& mesh, const rt::Displacement& d,
                              const rt::Displacement& zero) {
    rt::PipelineOptions options = constant_factor(3.5f, rt::Surface::pn_aen);
    options.displacement = &zero;
    const Output base = unwelded(mesh, options);
    const std::size_t open_before = open_edges_by_position(welded(mesh, options));
    options.displacement = &d;
    const Output grown = unwelded(mesh, options);
    CHECK(grown.vertices.size() > unwelded(mesh, constant_factor(3.5f, rt::Surface::pn_aen)).vertices.size());
    const PairCheck pairs = check_pairs(base, grown);
    CHECK(pairs.shared > 0);
    CHECK(pairs.mismatched == 0);
    CHECK(open_edges_by_position(welded(mesh, options)) == open_before);
}

inline rt::MeshView unit_triangle() {
    static const float vertices[3 * 8] = {0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0,
                                          0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 0, 1};
    static const std::uint32_t triangle[3] = {0, 1, 2};
    return {vertices, 3, triangle, 1};
}

} // namespace displace_test
