// A tessellated patch as the CLI handles it: exact domain points, primitives, and what produced them.
#pragma once
#include <ctess/core/domain_point.hpp>

#include <array>
#include <cstdint>
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

struct Mesh {
    std::vector<DomainPoint> vertices;
    std::vector<std::uint32_t> indices;
    std::uint32_t fixed_one = 0;
    unsigned vertices_per_primitive = 3; // 2 for isolines
    UniformUse uniform;                  // the uniform mode only
    std::size_t primitive_count() const { return indices.size() / vertices_per_primitive; }
};

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
