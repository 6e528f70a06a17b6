// A tessellated patch as the CLI handles it: exact domain points, primitives, and what produced them.
#pragma once
#include <ctess/core/domain_point.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace ctess::cli {

struct PatternRequest {
    std::string mode = "cp";        // cp, d3d11-integer, d3d11-pow2, d3d11-odd, d3d11-even, uniform
    std::string domain = "tri";     // tri; quad and iso for D3D11 modes
    std::vector<float> factors;     // cp: n0,n1,n2; D3D11 in the reference's order
    bool ccw = false;               // output winding
    unsigned max_factor = 64;       // CP only
    bool provoking_layout = true;   // CP only
    bool staircase_columns = false; // CP only: column rule (a) instead of the minimal rule (b)
};

// What the uniform mode used (docs/algorithm.md §3.4, §3.5): the rounded, clamped integer factors in request
// order, the table's N, and the split (1 subpatch, depth 0 when the factors fit the table). table_max is 0
// for the other modes.
struct UniformUse {
    std::array<std::uint32_t, 3> factors{};
    std::uint32_t table_max = 0;
    std::uint32_t subpatches = 1, depth = 0;
};

// A point of Mesh::vertices in units of Mesh::fixed_one: the CLI keeps the patterns of every family in one
// type with their unit beside them (the library types its points by unit, core/fixed_point.hpp).
struct MeshPoint {
    std::uint32_t u = 0, v = 0;
    friend bool operator==(const MeshPoint&, const MeshPoint&) = default;
};

struct Mesh {
    std::vector<MeshPoint> vertices;
    std::vector<std::uint32_t> indices;
    std::uint32_t fixed_one = 0;
    unsigned vertices_per_primitive = 3; // 2 for isolines
    UniformUse uniform;                  // the uniform mode only
    std::size_t primitive_count() const { return indices.size() / vertices_per_primitive; }
};

// The mesh's vertices from points of one unit, and that unit.
template <class Unit>
void set_points(Mesh& mesh, std::span<const FixedPoint<Unit>> points) {
    mesh.fixed_one = Unit::one;
    mesh.vertices.resize(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) mesh.vertices[i] = {points[i].u, points[i].v};
}

// Counts, then fill, of any runtime patch (counts() and emit(points, indices), core/patch_concept.hpp).
template <class Patch>
void emit_patch(Mesh& mesh, const Patch& patch) {
    std::vector<typename Patch::point_type> points(patch.counts().vertices);
    mesh.indices.resize(patch.counts().index_count());
    patch.emit(points, mesh.indices);
    set_points(mesh, std::span<const typename Patch::point_type>(points));
}

const std::vector<std::string>& pattern_modes();
bool is_d3d11_mode(const std::string& mode);
// Validates the factor count for the mode and domain (UsageError otherwise), then tessellates.
Mesh tessellate(const PatternRequest& request);
// The uniform-density mode (mesh_uniform.cpp): three edge factors, the configured table's patterns.
Mesh tessellate_uniform(const PatternRequest& request);
// Twice the signed area of triangle t, in units of fixed_one^2 (exact; saturated beyond 64 bits).
std::int64_t doubled_area(const Mesh& mesh, std::size_t t);
std::size_t degenerate_triangles(const Mesh& mesh);

} // namespace ctess::cli
