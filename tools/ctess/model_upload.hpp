// `ctess serve`'s uploads (docs/cli.md, "Viewer server"; docs/viewer.md, "Your model"): a model file's bytes
// in, the model as ctess::models loads it and `ctess mesh` prepares it out (model_prep.hpp); a height map's
// bytes in, its texels as models::load_height_map_from_memory decodes them out. Both answers use one small
// binary container, so that a WebGPU host can hand the arrays to the pipeline without parsing text:
//
//   bytes 0-3   "CTMD"
//   bytes 4-7   u32 version (1), little-endian like everything after it
//   bytes 8-11  u32 H: the JSON header's length in bytes, a multiple of 4 (padded with spaces)
//   bytes 12..  the JSON header (UTF-8): the answer's scalars and "sections": [{"name", "type" ("f32" or
//               "u32"), "offset" (bytes from the start of the body, a multiple of 4), "count" (elements)}]
//   then        the sections, little-endian 32-bit elements, in the order listed
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace ctess::cli {

// An uploaded model's bounds (docs/cli.md, "Viewer server"), checked by the loader as it builds the model
// (node instancing can turn a small glTF into the loader's own 2^26 vertices, about 12 GiB with what
// follows): at these, one upload's arrays and answer stay near 2 GiB.
inline constexpr std::size_t max_upload_vertices = std::size_t{1} << 22;
inline constexpr std::size_t max_upload_faces = std::size_t{1} << 23;

// The model answer: header {"name", "vertex_count", "triangle_count", "quad_count", "has_normals", "has_uvs",
// "dropped_degenerate_faces", "open_edges", "displacement", "sections"}; sections "vertices" (f32, 8 per
// vertex: position, normal, uv), "triangles" (u32, 3 per triangle), "quads" (u32, 4 per quad), "position_ids"
// (u32, 1 per vertex), "adjacency" (u32, 12 per face triangle: the triangles, then each quad's two halves),
// "directions" (f32, 3 per vertex: rt::welded_directions), "displacement_texels" (f32, width * height as the
// height-map answer's "texels"; empty unless the image below decoded). "displacement" is null, or the file's
// KHR_materials_displacement: {"factor", "offset", "embedded_image" (the image is inside the file), then
// "width", "height", "texel_min", "texel_max" when that image decoded, "image_error" (the loader's message)
// when it did not, "image_uri" when the image is a separate file (one upload holds one file)}.
// "tangent_source" ("model", "uv" or "none") names where section "tangents" (f32, 4 per vertex: vector
// displacement's frame, docs/algorithm.md §8.7, as `ctess mesh --displace-vector` takes it; empty for "none",
// a model without uvs) comes from. `name` picks
// the loader by its extension (.gltf, .glb, .obj) and names the model in errors. Throws std::runtime_error
// with a message for the user (the loader's, which names the problem) when the name or the bytes are not a
// model the library reads, or the model is past max_upload_vertices or max_upload_faces.
std::string model_answer(std::span<const std::uint8_t> bytes, const std::string& name);

// The height-map answer: header {"name", "width", "height", "texel_min", "texel_max", "sections"}; section
// "texels" (f32, width * height, row-major, row 0 at v = 0). Throws std::runtime_error as above.
std::string height_map_answer(std::span<const std::uint8_t> bytes, const std::string& name);

// The vector-map answer: header {"name", "width", "height", "channels" (3), "sections"}; section "texels"
// (f32, 3 * width * height: r, g, b per texel, row-major, row 0 at v = 0), as
// models::load_vector_map_from_memory decodes them for `ctess mesh --displace-vector FILE`. Throws
// std::runtime_error as above.
std::string vector_map_answer(std::span<const std::uint8_t> bytes, const std::string& name);

} // namespace ctess::cli
