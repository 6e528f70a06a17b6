// A triangle/quad model read from a glTF 2.0 (.gltf, .glb) or Wavefront OBJ file (docs/models.md).
// Loading never throws: every failure, including running out of memory, comes back as a LoadError that names
// the file and the problem, and no partial model is returned.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace ctess::models {

// Floats per vertex in Model::vertices: position xyz, normal xyz, uv (ctess::rt::mesh_vertex_floats).
inline constexpr unsigned model_vertex_floats = 8;

struct Model {
    std::vector<float> vertices;          // model_vertex_floats per vertex: vertex_count() * 8 floats
    std::vector<std::uint32_t> triangles; // 3 indices per triangle, counter-clockwise: triangle_count() * 3
    std::vector<std::uint32_t> quads;     // 4 indices per quad, in the file's order around the face
    // false: zeros were written for the missing attribute (no normals are generated; docs/models.md). When
    // some primitives or faces have the attribute and others do not, the flag is false.
    bool has_normals = false, has_uvs = false;
    // glTF TANGENT, 4 floats per vertex (xyz by the node's matrix, renormalised; w the handedness, negated
    // under a mirroring node), rt::Displacement::tangents' layout (docs/algorithm.md §8.7). Filled only when
    // every loaded primitive has it (has_tangents); else empty. OBJ files have none.
    std::vector<float> tangents;
    bool has_tangents = false;
    // KHR_materials_displacement (unofficial, issue KhronosGroup/glTF#948): read from the first material of a
    // loaded primitive that has it.
    struct Displacement {
        bool present = false;
        std::string image_uri; // the image's uri; empty when the image is embedded or absent
        // An embedded image's encoded bytes (a data: uri or a buffer view), for load_height_map_from_memory.
        std::vector<std::uint8_t> image_bytes;
        int texture = -1; // index into the glTF file's textures, -1: none
        float factor = 1, offset = 0;
    } displacement;
    // Faces whose corners do not have distinct positions (a zero-length edge), dropped and counted here.
    std::uint32_t dropped_degenerate_faces = 0;

    std::size_t vertex_count() const { return vertices.size() / model_vertex_floats; }
    std::size_t triangle_count() const { return triangles.size() / 3; }
    std::size_t quad_count() const { return quads.size() / 4; }
};

struct LoadError {
    std::string message; // "<file>: <problem>"
};

// Either a model or an error, never both.
struct LoadResult {
    std::optional<Model> model;
    LoadError error; // empty message when model is set
    bool ok() const { return model.has_value(); }
    explicit operator bool() const { return ok(); }
};

enum class ModelKind { gltf_text, gltf_binary, obj };

// Bounds a caller puts on a loaded model, checked as it is built, before each primitive's (glTF) or vertex's
// (OBJ) memory is taken: glTF node instancing can multiply a small file's geometry. The defaults add none to
// the loaders' own (glTF: 2^26 vertices, 2^27 indices; docs/models.md). `what` names the bound in the error:
// "more than N vertices, past <what>".
struct LoadLimits {
    std::size_t max_vertices = SIZE_MAX;
    std::size_t max_faces = SIZE_MAX; // triangles and quads
    std::string what = "the caller's limit";
};

// Reads .gltf, .glb or .obj (the extension, case-insensitive, picks the loader; the content is then checked:
// a .glb must start with the binary glTF magic, a .gltf with a JSON object, an .obj must be text). External
// buffers and images of a .gltf are looked up next to it.
LoadResult load_model(const std::string& path);

// The same from bytes in memory, for fuzzers and embedded assets. No file is ever opened: a glTF that refers
// to an external buffer is an error. `name` is what error messages call the input.
LoadResult load_model_from_memory(std::span<const std::uint8_t> bytes, ModelKind kind,
                                  const std::string& name = "<memory>", const LoadLimits& limits = {});

} // namespace ctess::models
