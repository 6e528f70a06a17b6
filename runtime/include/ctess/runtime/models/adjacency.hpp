// Adjacency for PN-AEN and watertight displacement, computed by meshoptimizer (docs/models.md, "Adjacency").
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <ctess/runtime/models/model.hpp>

namespace ctess::models {

struct Adjacency {
    // vertex_count() entries: for each vertex, the first vertex with a bit-identical position
    // (meshopt_generateShadowIndexBuffer over positions). Vertices split at uv or normal seams share an id.
    std::vector<std::uint32_t> position_ids;
    // 12 indices per triangle (meshopt_generateTessellationIndexBuffer): the 3 corners, then per edge the two
    // vertices of the adjacent triangle's matching edge (the edge itself when open), then each corner's
    // dominant vertex. The triangles are the model's triangles, then each quad (a, b, c, d) split into
    // (a, b, c) and (a, c, d): (triangle_count() + 2 * quad_count()) * 12 indices.
    std::vector<std::uint32_t> tessellation_indices;
};

// Throws std::out_of_range for an index >= model.vertex_count() (load_model never returns one).
Adjacency build_adjacency(const Model& model);

// Adjacency::position_ids alone (no tessellation index buffer): vertex_count() entries.
std::vector<std::uint32_t> position_ids(const Model& model);

// Edges (pairs of position ids) used by exactly one face: 0 for a closed model. Triangles give 3 edges, quads
// their 4 boundary edges (not the split diagonal). Throws std::invalid_argument unless position_ids has
// model.vertex_count() entries, std::out_of_range for an index >= model.vertex_count().
std::size_t open_edge_count(const Model& model, std::span<const std::uint32_t> position_ids);

} // namespace ctess::models
