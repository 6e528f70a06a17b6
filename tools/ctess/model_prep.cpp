// The model preparation `ctess mesh` and `ctess serve` share (model_prep.hpp).
#include "model_prep.hpp"

#include <ctess/runtime/displace/displace.hpp>

#include <cctype>
#include <stdexcept>

#include <fmt/core.h>

namespace ctess::cli {

std::string extension_of(const std::string& path) {
    const auto dot = path.find_last_of('.');
    const auto slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    std::string ext = path.substr(dot + 1);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

std::optional<models::ModelKind> model_kind_of(const std::string& name) {
    const std::string ext = extension_of(name);
    if (ext == "gltf") return models::ModelKind::gltf_text;
    if (ext == "glb") return models::ModelKind::gltf_binary;
    if (ext == "obj") return models::ModelKind::obj;
    return std::nullopt;
}

PreparedModel prepare_model(models::Model&& model, const std::string& name) {
    // The pipeline counts in 32 bits (the GPU's words); the loaders' own bounds keep models far below.
    if (model.vertex_count() > 0xFFFFFFFFu || model.triangle_count() > 0xFFFFFFFFu ||
        model.quad_count() > 0xFFFFFFFFu)
        throw std::runtime_error(fmt::format("{}: more than 2^32 - 1 vertices or faces", name));
    PreparedModel prepared;
    prepared.model = std::move(model);
    prepared.adjacency = models::build_adjacency(prepared.model);
    prepared.open_edges = models::open_edge_count(prepared.model, prepared.adjacency.position_ids);
    return prepared;
}

rt::MeshView PreparedModel::view() const {
    rt::MeshView v;
    v.vertices = model.vertices.data();
    v.vertex_count = static_cast<std::uint32_t>(model.vertex_count());
    v.indices = model.triangles.data();
    v.triangle_count = static_cast<std::uint32_t>(model.triangle_count());
    v.quad_indices = model.quads.data();
    v.quad_count = static_cast<std::uint32_t>(model.quad_count());
    v.position_ids = adjacency.position_ids.data();
    v.adjacency = adjacency.tessellation_indices.data();
    return v;
}

std::vector<float> displacement_directions(const PreparedModel& prepared, const std::string& name) {
    std::vector<float> directions(3 * prepared.model.vertex_count());
    if (!rt::welded_directions(prepared.view(), directions))
        throw std::runtime_error(name + ": cannot compute the displacement directions");
    return directions;
}

DisplacementTangents displacement_tangents(const PreparedModel& prepared, const std::string& name) {
    const models::Model& model = prepared.model;
    DisplacementTangents out;
    if (model.has_tangents && model.tangents.size() == 4 * model.vertex_count()) {
        out.tangents = model.tangents;
        out.source = "model";
        return out;
    }
    out.tangents.resize(4 * model.vertex_count());
    if (!rt::uv_tangents(prepared.view(), out.tangents))
        throw std::runtime_error(name + ": cannot compute the displacement tangents");
    out.source = "uv";
    return out;
}

} // namespace ctess::cli
