// Adjacency through meshoptimizer (docs/models.md, "Adjacency"): the shadow index buffer over positions gives
// the position ids, and meshopt_generateTessellationIndexBuffer the 12-index PN-AEN patches (McDonald and
// Kilgard, "Crack-Free Point-Normal Triangles using Adjacent Edge Normals", NVIDIA 2010).
#include <algorithm>
#include <numeric>
#include <stdexcept>

#include <meshoptimizer.h>

#include <ctess/runtime/models/adjacency.hpp>

namespace ctess::models {

namespace {

// The model's triangles, then each quad (a, b, c, d) as (a, b, c) and (a, c, d).
std::vector<std::uint32_t> triangle_list(const Model& model) {
    std::vector<std::uint32_t> list(model.triangles);
    list.reserve(model.triangles.size() + model.quad_count() * 6);
    for (std::size_t q = 0; q < model.quad_count(); ++q) {
        const std::uint32_t* c = model.quads.data() + 4 * q;
        list.insert(list.end(), {c[0], c[1], c[2], c[0], c[2], c[3]});
    }
    return list;
}

} // namespace

std::vector<std::uint32_t> position_ids(const Model& model) {
    const std::size_t vertex_count = model.vertex_count();
    // The shadow index buffer of the index list 0, 1, ..., n - 1 is one position id per vertex; meshoptimizer
    // takes whole triangles, so the list is padded to a multiple of 3 with its last index and cut back after.
    const std::size_t padded = (vertex_count + 2) / 3 * 3;
    std::vector<std::uint32_t> identity(
        padded, vertex_count == 0 ? 0u : static_cast<std::uint32_t>(vertex_count - 1));
    std::iota(identity.begin(), identity.begin() + static_cast<std::ptrdiff_t>(vertex_count), 0u);
    std::vector<std::uint32_t> ids(padded);
    if (vertex_count != 0)
        meshopt_generateShadowIndexBuffer(ids.data(), identity.data(), padded, model.vertices.data(),
                                          vertex_count, 3 * sizeof(float),
                                          model_vertex_floats * sizeof(float));
    ids.resize(vertex_count);
    return ids;
}

Adjacency build_adjacency(const Model& model) {
    Adjacency adjacency;
    const std::size_t vertex_count = model.vertex_count();
    adjacency.position_ids = position_ids(model);
    const std::vector<std::uint32_t> list = triangle_list(model);
    for (std::uint32_t index : list)
        if (index >= vertex_count)
            throw std::out_of_range("ctess::models::build_adjacency: index out of range");
    adjacency.tessellation_indices.resize(list.size() * 4);
    if (!list.empty())
        meshopt_generateTessellationIndexBuffer(adjacency.tessellation_indices.data(), list.data(),
                                                list.size(), model.vertices.data(), vertex_count,
                                                model_vertex_floats * sizeof(float));
    return adjacency;
}

std::size_t open_edge_count(const Model& model, std::span<const std::uint32_t> position_ids) {
    if (position_ids.size() != model.vertex_count())
        throw std::invalid_argument("ctess::models::open_edge_count: one position id per vertex expected");
    // Every face edge as a (min, max) pair of position ids; an edge seen once is open.
    std::vector<std::uint64_t> edges;
    edges.reserve(model.triangles.size() + model.quads.size());
    auto add_face = [&](const std::uint32_t* corners, unsigned n) {
        for (unsigned i = 0; i < n; ++i) {
            const std::uint32_t a = corners[i], b = corners[(i + 1) % n];
            if (a >= position_ids.size() || b >= position_ids.size())
                throw std::out_of_range("ctess::models::open_edge_count: index out of range");
            const std::uint64_t pa = position_ids[a], pb = position_ids[b];
            edges.push_back(std::min(pa, pb) << 32 | std::max(pa, pb));
        }
    };
    for (std::size_t t = 0; t < model.triangle_count(); ++t) add_face(model.triangles.data() + 3 * t, 3);
    for (std::size_t q = 0; q < model.quad_count(); ++q) add_face(model.quads.data() + 4 * q, 4);
    std::sort(edges.begin(), edges.end());
    std::size_t open = 0;
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        open += j - i == 1;
        i = j;
    }
    return open;
}

} // namespace ctess::models
