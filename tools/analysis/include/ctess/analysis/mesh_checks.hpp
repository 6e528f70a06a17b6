// Exact integer checks on a tessellation of the unit domain triangle, for any algorithm (CP, D3D11, uniform
// density): closedness, manifoldness, edge matching and exact coverage.
//
// Positions are ctess::DomainPoint {u, v} in units of `one`: the point v0 + u(v1-v0) + v(v2-v0). The domain
// triangle is (0,0), (one,0), (0,one); its boundary loop runs e0 = v0->v1 (v = 0), e1 = v1->v2 (u + v = one,
// parameter s = v from v1) and e2 = v0->v2 (u = 0, walked back from v2 to v0). Doubled areas are exact
// (signed_area.hpp) and their sum is an int128.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <ctess/analysis/signed_area.hpp>
#include <ctess/core/domain_point.hpp>

namespace ctess::analysis {

// One position as a sortable key (u high, v low).
template <class Unit>
constexpr std::uint64_t position_key(FixedPoint<Unit> p) {
    return (std::uint64_t{p.u} << 32) | p.v;
}

// A triangle as three exact positions, in emitted (winding) order.
using PositionTriangle = std::array<DomainPoint, 3>;

// Rotates the triangle (keeping the winding) so that its smallest position comes first.
constexpr PositionTriangle canonical_rotation(PositionTriangle t) {
    std::size_t first = 0;
    for (std::size_t i = 1; i < 3; ++i)
        if (position_key(t[i]) < position_key(t[first])) first = i;
    return {t[first], t[(first + 1) % 3], t[(first + 2) % 3]};
}

constexpr bool position_triangle_less(const PositionTriangle& a, const PositionTriangle& b) {
    for (std::size_t i = 0; i < 3; ++i)
        if (position_key(a[i]) != position_key(b[i])) return position_key(a[i]) < position_key(b[i]);
    return false;
}

// The checks work in any unit (`one` is their argument) on (u, v) pairs carried as DomainPoint; points of
// another FixedPoint type enter through check_points, which copies their coordinates unchanged.
template <class Unit>
std::vector<DomainPoint> check_points(std::span<const FixedPoint<Unit>> points) {
    std::vector<DomainPoint> out(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) out[i] = {points[i].u, points[i].v};
    return out;
}
template <class Unit>
std::vector<DomainPoint> check_points(const std::vector<FixedPoint<Unit>>& points) {
    return check_points(std::span<const FixedPoint<Unit>>(points));
}
template <class Unit>
constexpr DomainPoint check_point(FixedPoint<Unit> p) {
    return {p.u, p.v};
}

struct MeshView {
    std::span<const DomainPoint> vertices;
    std::span<const std::uint32_t> indices; // 3 per triangle
    std::size_t triangle_count() const { return indices.size() / 3; }
    PositionTriangle triangle(std::size_t t) const {
        return {vertices[indices[3 * t]], vertices[indices[3 * t + 1]], vertices[indices[3 * t + 2]]};
    }
};

// Every index refers to a vertex, and every vertex is referenced.
bool indices_in_range(const MeshView& m);
std::size_t unreferenced_vertex_count(const MeshView& m);

// Every vertex lies in the closed domain triangle.
bool vertices_in_domain(const MeshView& m, std::uint32_t one);

struct AreaStats {
    std::size_t triangles = 0;
    std::size_t inverted = 0;   // negative area
    std::size_t degenerate = 0; // zero area
    std::size_t fins = 0;       // zero area with three distinct positions: a T-junction in disguise
    int128 area2_sum = 0;
    // Exact tiling of the unit domain triangle: the doubled areas sum to one^2.
    bool covers(std::uint32_t one) const { return area2_sum == int128{one} * one; }
};

AreaStats area_stats(const MeshView& m);

// The multiset of non-degenerate triangles as canonically rotated position triples, sorted. Two meshes with
// equal multisets describe the same piecewise-linear surface: this is the exact pop comparison.
std::vector<PositionTriangle> surface_triangles(const MeshView& m);

// Every triangle, degenerate ones included (e.g. to compare two index layouts of the same mesh).
std::vector<PositionTriangle> all_triangles(const MeshView& m);

using DirectedEdge = std::pair<std::uint64_t, std::uint64_t>; // position keys, from -> to

// The boundary loop of the domain as directed position edges between consecutive distinct points. Each list
// holds an edge's parameters (units of one, sorted, endpoints included): e0 and e2 from v0, e1 from v1.
std::vector<DirectedEdge> boundary_loop_edges(std::span<const std::uint32_t> e0,
                                              std::span<const std::uint32_t> e1,
                                              std::span<const std::uint32_t> e2, std::uint32_t one);

// Conformity of the non-degenerate triangles on exact positions: each directed edge is used at most once,
// every edge used in one direction only is a boundary-loop edge and every boundary-loop edge is used, and the
// Euler characteristic V - E + F of the non-degenerate triangles is 1 (a disk). Zero-area triangles are left
// out: with no fins they all have two coincident corners, so their edges cancel among themselves.
struct SurfaceTopology {
    bool edges_unique = true;     // no directed position edge used twice
    bool boundary_matches = true; // unpaired edges == the boundary loop
    long long euler = 0;
    std::size_t unpaired = 0;
    std::size_t expected_boundary = 0;
};

// Directed edges over dense ids [0, id_count): whether each is used once, how many have their reverse, and
// the ones that do not (sorted). Linear time: adjacency lists by source, each sorted (they are short).
using IdEdge = std::pair<std::uint32_t, std::uint32_t>;
struct EdgeCensus {
    bool unique = true;
    std::size_t paired = 0;
    std::vector<IdEdge> unpaired;
};

EdgeCensus edge_census(std::size_t id_count, std::span<const IdEdge> edges);

// Dense ids of the distinct positions: id_of_vertex[i] is vertex i's id, keys[id] its position key (sorted).
struct Weld {
    std::vector<std::uint32_t> id_of_vertex;
    std::vector<std::uint64_t> keys;
};

Weld weld_positions(std::span<const DomainPoint> vertices);

SurfaceTopology surface_topology(const MeshView& m, std::span<const DirectedEdge> boundary);

// The index mesh itself (degenerate triangles included) is a topological disk: no triangle repeats an index,
// each directed index edge is used at most once, the edges used in one direction only form one closed loop,
// and V - E + F = 1 over the referenced vertices. Only meaningful for layouts with one vertex per mesh
// vertex.
struct IndexTopology {
    bool no_repeated_index = true;
    bool edges_unique = true;
    bool single_boundary_loop = true;
    long long euler = 0;
};

IndexTopology index_topology(const MeshView& m);

// Distinct parameters of the vertices lying on each domain edge: e0 (v = 0) by u, e1 (u + v = one) by s = v,
// and e2 (u = 0) by v. Sorted. Compare with the distinct line points of each edge.
struct EdgeVertexParams {
    std::vector<std::uint32_t> e0, e1, e2;
};

EdgeVertexParams edge_vertex_params(const MeshView& m, std::uint32_t one);

// The first index of every triangle is unique across the mesh (a flat-shading provoking vertex per triangle).
bool unique_first_index(const MeshView& m);

// All checks that make a mesh a valid, watertight tessellation of the domain with the given edge parameters.
// failures is empty when valid, else a short description of every failed check; area holds the area counts.
struct ValidityReport {
    AreaStats area;
    std::string failures;
    bool ok() const { return failures.empty(); }
};

ValidityReport check_valid_tessellation(const MeshView& m, std::uint32_t one,
                                        std::span<const std::uint32_t> e0, std::span<const std::uint32_t> e1,
                                        std::span<const std::uint32_t> e2);

} // namespace ctess::analysis
