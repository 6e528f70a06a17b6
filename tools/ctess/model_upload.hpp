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
#include "cli_args.hpp"
#include "model_prep.hpp"

#include <ctess/runtime/models/height_map.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>

namespace ctess::cli {

// An uploaded model's bounds (docs/cli.md, "Viewer server"), checked by the loader as it builds the model
// (node instancing can turn a small glTF into the loader's own 2^26 vertices, about 12 GiB with what
// follows): at these, one upload's arrays and answer stay near 2 GiB.
inline constexpr std::size_t max_upload_vertices = std::size_t{1} << 22;
inline constexpr std::size_t max_upload_faces = std::size_t{1} << 23;

// An uploaded model as the server holds it (`name` picks the loader by its extension: .gltf, .glb, .obj):
// loaded with the viewer's limits, prepared as `ctess mesh`
// prepares it (model_prep.hpp), its displacement directions and tangents, and the file's own embedded
// KHR_materials_displacement image decoded (image_error when it did not decode). Throws std::runtime_error
// with a message for the user (the loader's, which names the problem) when the name or the bytes are not a
// model the library reads, or the model is past max_upload_vertices or max_upload_faces.
struct HeldModel {
    std::string name;
    PreparedModel prepared;
    std::vector<float> directions;
    DisplacementTangents tangents;
    models::HeightImage image;
    std::string image_error;
};
std::shared_ptr<const HeldModel> load_uploaded_model(std::span<const std::uint8_t> bytes,
                                                     const std::string& name);

// The model answer: header {"id" (the server's number for the held model, for /api/tessellate), "name",
// "vertex_count", "triangle_count", "quad_count", "has_normals", "has_uvs", "dropped_degenerate_faces",
// "open_edges", "displacement", "sections"}; sections "vertices" (f32, 8 per vertex: position, normal, uv),
// "triangles" (u32, 3 per triangle), "quads" (u32, 4 per quad), "position_ids" (u32, 1 per vertex),
// "adjacency" (u32, 12 per face triangle: the triangles, then each quad's two halves), "directions" (f32, 3
// per vertex: rt::welded_directions), "displacement_texels" (f32, width * height as the height-map answer's
// "texels"; empty unless the image below decoded). "displacement" is null, or the file's
// KHR_materials_displacement: {"factor", "offset", "embedded_image" (the image is inside the file), then
// "width", "height", "texel_min", "texel_max" when that image decoded, "image_error" (the loader's message)
// when it did not, "image_uri" when the image is a separate file (one upload holds one file)}.
// "tangent_source" ("model", "uv" or "none") names where section "tangents" (f32, 4 per vertex: vector
// displacement's frame, docs/algorithm.md §8.7, as `ctess mesh --displace-vector` takes it; empty for "none",
// a model without uvs) comes from.
std::string model_answer(const HeldModel& model, std::uint64_t id);

// An uploaded height map (`vector` false: models::load_height_map_from_memory, as `--displace FILE` reads it)
// or vector map (true: load_vector_map_from_memory, `--displace-vector FILE`), held by the server. Throws
// std::runtime_error with the loader's message.
struct HeldMap {
    std::string name;
    models::HeightImage image; // channels 1 or 3
};
std::shared_ptr<const HeldMap> load_uploaded_map(std::span<const std::uint8_t> bytes, const std::string& name,
                                                 bool vector);

// The map answer: header {"id", "name", "width", "height", "channels" (1 or 3), "texel_min", "texel_max" (a
// height map only; null if not finite), "sections"}; section "texels" (f32, channels * width * height,
// row-major, row 0 at v = 0).
std::string map_answer(const HeldMap& map, std::uint64_t id);

// At most this many triangles from /api/tessellate (about 200 MiB of answer).
inline constexpr std::uint32_t max_tessellate_triangles = std::uint32_t{1} << 22;

// /api/tessellate: a D3D11 pattern over a held model, as `ctess mesh --stats` computes its `gpu` block (the
// unwelded pipeline, mesh_options.hpp), for the viewer to draw beside the GPU's CP and uniform. `args` holds
// `ctess mesh`'s pattern (d3d11-integer, -pow2, -odd, -even), surface, quad-rule, dice-rate, camera, fov and
// resolution, and displace (none, map: `map`, or model: the model's own image with its factor and offset),
// displace-scale, displace-offset, displace-address and displace-grow (1: grown by the bound). Answer: header
// {"vertices", "triangles", "clamped_edges", "sections"}; sections "records" (u32, 48 per patch:
// rt::PatchRecord), "vertices" (u32, 10 per vertex: rt::TessVertex), "indices" (u32, 3 per triangle). Throws
// UsageError for bad options and std::runtime_error when the pipeline refuses or the output is past
// max_tessellate_triangles.
std::string tessellate_answer(const HeldModel& model, const HeldMap* map, const Args& args);

} // namespace ctess::cli
