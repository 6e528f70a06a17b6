// Writers for `ctess mesh` (docs/cli.md): a tessellated model as Wavefront OBJ (text, 9 significant digits,
// which round-trips every float), binary little-endian PLY, or binary glTF 2.0 (.glb, through tinygltf).
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ctess::cli {

// One indexed triangle mesh: 8 floats per vertex (position xyz, normal xyz, uv), 3 indices per triangle,
// counter-clockwise. The layout of models::Model and the pipeline's vertex attributes.
struct OutputMesh {
    std::vector<float> vertices;
    std::vector<std::uint32_t> triangles;
    std::size_t vertex_count() const { return vertices.size() / 8; }
    std::size_t triangle_count() const { return triangles.size() / 3; }
};

// `comment` becomes the file's comment (OBJ, PLY) or asset.generator (glTF); one line, no newlines.
std::string mesh_to_obj(const OutputMesh& mesh, std::string_view comment);
std::string mesh_to_ply(const OutputMesh& mesh, std::string_view comment);
std::string mesh_to_glb(const OutputMesh& mesh, std::string_view comment);

} // namespace ctess::cli
