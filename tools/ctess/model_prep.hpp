// A loaded model made ready for the mesh pipeline, shared by `ctess mesh` (cmd_mesh.cpp) and `ctess serve`'s
// /api/model (model_upload.cpp), so that the viewer's GPU pipeline gets exactly the input `ctess mesh`
// tessellates (docs/cli.md, "Models" and "Viewer server"). The library does the work: ctess::models loads and
// finds the adjacency, rt::welded_directions gives the displacement directions; this only holds them
// together.
#pragma once
#include <ctess/runtime/models/adjacency.hpp>
#include <ctess/runtime/models/model.hpp>
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace ctess::cli {

struct PreparedModel {
    models::Model model;
    models::Adjacency adjacency; // position ids and meshoptimizer's 12-index tessellation buffer
    std::size_t open_edges = 0;  // input edges used by one face, by position (0: closed)

    // The pipeline's view of the model: triangles, quads, position ids (seams order their edges by position)
    // and the adjacency (PN-AEN's neighbours, the dominant edges and corners of displacement). Valid while
    // this object lives and is not moved.
    rt::MeshView view() const;
};

// The adjacency and open-edge count of a loaded model. Throws std::runtime_error naming `name` when the model
// has more than 2^32 - 1 vertices or faces (the pipeline counts in 32 bits, as the GPU does).
PreparedModel prepare_model(models::Model&& model, const std::string& name);

// One displacement direction per vertex (3 floats each: rt::welded_directions, one direction per position).
// Throws std::runtime_error naming `name` if the library refuses the mesh.
std::vector<float> displacement_directions(const PreparedModel& prepared, const std::string& name);

// Vector displacement's tangents (docs/algorithm.md §8.7), 4 floats per vertex (glTF TANGENT's layout): the
// model's own when every vertex has one (`source` "model"), else rt::uv_tangents from the uvs ("uv"). Throws
// std::runtime_error naming `name` if the library refuses the mesh.
struct DisplacementTangents {
    std::vector<float> tangents;
    const char* source = "none";
};
DisplacementTangents displacement_tangents(const PreparedModel& prepared, const std::string& name);

// The loader a file name picks (its extension, case-insensitive: .gltf, .glb, .obj), or none.
std::optional<models::ModelKind> model_kind_of(const std::string& name);

// The lower-case extension of a path's last component, without the dot ("" when it has none).
std::string extension_of(const std::string& path);

} // namespace ctess::cli
