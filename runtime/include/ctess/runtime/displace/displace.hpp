// Displacement in the mesh pipeline (docs/algorithm.md §8): every output vertex moves along a direction by
// height = scale * (texel * factor + offset), the texel read from a HeightMap (bilinear, LOD 0) or from a
// function the caller supplies. Set PipelineOptions::displacement to a Displacement; null means none.
//
// Watertight across uv and normal seams (Castaño, "Watertight Tessellation using Displacement Mapping",
// NVIDIA 2010): a patch corner samples its dominant vertex's uv, a point on a patch edge the dominant edge's
// uvs interpolated at its exact parameter, both by the same operations from either side, and every point
// moves along the direction field interpolated from the dominant vertices' directions (one per position), so
// two faces sharing an edge give bit-identical displaced positions. Displaced normals come from the height's
// finite differences in the patch's own parameter space (§8.3).
//
//   std::vector<float> directions(3 * std::size_t{mesh.vertex_count});
//   rt::welded_directions(mesh, directions);           // one direction per position: no cracks at hard edges
//   rt::Displacement d;
//   d.map = image.view();                              // or d.function / d.context
//   d.scale = 0.1f;
//   d.directions = directions.data();
//   options.displacement = &d;                         // then setup_welded / emit_welded_mesh as usual
//
// Vector displacement (§8.7): with mode = DisplacementMode::vector the texel is an RGB vector in tangent
// space, vector = scale * (texel * factor + offset) per channel, and a point moves by x T + y B + z N, the
// frame taken per position from the dominant vertex (N its direction, T its tangent made orthogonal to N, B =
// cross(N, T) * handedness) and interpolated as the directions are:
//
//   std::vector<float> tangents(4 * std::size_t{mesh.vertex_count});
//   rt::uv_tangents(mesh, tangents);                   // or the model's own (glTF TANGENT's layout)
//   d.mode = rt::DisplacementMode::vector;
//   d.map = rgb_image.view();                          // 3 channels (models::load_vector_map)
//   d.tangents = tangents.data();
//
// The evaluation is out of line in ctess::runtime_core, compiled with -ffp-contract=off -fno-fast-math.
#pragma once
#include <cstdint>
#include <span>

#include <ctess/runtime/core/vec3.hpp>
#include <ctess/runtime/displace/height_map.hpp>
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>
#include <ctess/runtime/surface/eval.hpp>

namespace ctess::rt {

// A procedural height: the "texel" at (u, v); the pipeline applies scale, factor and offset to it.
using HeightFunction = float (*)(const void* context, float u, float v);
// A procedural vector texel (tangent space: x along T, y along B, z along N) for DisplacementMode::vector.
using VectorFunction = Vec3 (*)(const void* context, float u, float v);

// What the texel is (docs/algorithm.md §8.7).
enum class DisplacementMode : std::uint8_t {
    scalar = 0, // a height along the direction: map of 1 channel or HeightFunction (the default)
    vector = 1, // a tangent-space vector: map of 3 channels (RGB) or VectorFunction, and tangents
};

struct Displacement {
    HeightMap map{};                                  // the texture, read when function is null
    HeightFunction function = nullptr;                // a procedural texel instead of the map
    const void* context = nullptr;                    // passed to function
    float scale = 1.0f, factor = 1.0f, offset = 0.0f; // height = scale * (texel * factor + offset)
    // Optional: 3 floats per mesh vertex, the direction each vertex moves along; equal positions must hold
    // equal directions (welded_directions). Null: the dominant vertex's own normal.
    const float* directions = nullptr;
    // > 0: an edge of world length L gets factor * (1 + 2 * factor_bound / L), as if displacement could
    // lengthen it by the bound at both ends (§8.4). displacement_bound() is the texture's own bound.
    float factor_bound = 0.0f;
    // The finite-difference step of the displaced normals, in the patch's parameter (§8.3), in (0, 0.5].
    float normal_step = 1.0f / 256.0f;
    // Vector displacement (§8.7). In vector mode `function` must be null and `vector_function`, when set,
    // replaces the map; in scalar mode `vector_function` must be null (displacement_valid).
    DisplacementMode mode = DisplacementMode::scalar;
    VectorFunction vector_function = nullptr;
    // Vector mode: 4 floats per mesh vertex, glTF TANGENT's layout: the tangent xyz (along +u) and the
    // handedness w (B = cross(N, T) * w, w < 0 gives -1, anything else +1). Required in vector mode; the
    // frame is read at dominant vertices only, so any per-vertex tangents give one frame per position.
    const float* tangents = nullptr;
};

// scale * (texel * factor + offset) at (u, v).
float displacement_height(const Displacement& d, float u, float v);
// Vector mode: the tangent-space vector scale * (texel * factor + offset), per channel, at (u, v) (the texel
// from vector_function, else sample_bilinear_rgb of the map).
Vec3 displacement_vector(const Displacement& d, float u, float v);

// The largest |height| the map can give (from its texel range); in vector mode the largest length of a
// texel's vector (texels with a NaN channel skipped); 0 for a function source (the caller knows its bound)
// or an empty map.
float displacement_bound(const Displacement& d);

// True when scale, factor, offset and factor_bound are finite, factor_bound >= 0, normal_step is in
// (0, 0.5], and the source fits the mode: scalar mode has no vector_function and, reading a non-empty map,
// a map of 1 channel; vector mode has no (scalar) function, has tangents and, reading a non-empty map, a map
// of 3 channels; a mode outside the enum is refused. The pipeline answers PipelineStatus::bad_option
// otherwise.
bool displacement_valid(const Displacement& d);

// One direction per position: out[3v..3v+2] = the normalised sum of the normals of every vertex at vertex v's
// position (mesh.position_ids; without them each vertex's own normal, normalised). A zero sum gives zero (the
// vertex does not move). False, and nothing written, when out is shorter than 3 * vertex_count or a
// position id is out of range or not its own id.
bool welded_directions(const MeshView& mesh, std::span<float> out);

// Per-vertex tangents from the uv gradients (Lengyel 2001, "Computing Tangent Space Basis Vectors for an
// Arbitrary Mesh"; docs/algorithm.md §8.7): out[4v..4v+3] = the tangent xyz and handedness w of vertex v.
// Each face triangle (a quad as (q0, q1, q2) and (q0, q2, q3)) adds its dP/du and dP/dv to its three
// vertices; the sum of dP/du is made orthogonal to the vertex's own normal (Gram-Schmidt) and normalised, and
// w is -1 where cross(N, T) points against the summed dP/dv, else +1. A face whose uv area is zero or whose
// gradients are not finite adds nothing; a vertex with no usable tangent gets (0, 0, 0, 1), so the vector's
// x and y move nothing there. False, and nothing written, when out is shorter than 4 * vertex_count or a
// face index is out of range.
bool uv_tangents(const MeshView& mesh, std::span<float> out);

// --- The mesh pipeline's hook (mesh_pipeline.cpp); public so that tests can drive it directly ---

// What one patch's displacement reads, set up once per patch: per corner the dominant vertex's uv and
// direction, per edge the dominant edge's uvs, and the own corners for the finite differences.
struct DisplacementPatch {
    const Displacement* source = nullptr;    // null: no displacement
    unsigned corners = 3;                    // 3 (a triangle) or 4 (a quad)
    float corner_uv[4][2] = {};              // the dominant vertex's uv
    Vec3 direction[4] = {};                  // the dominant vertex's direction, normalised
    Vec3 tangent[4] = {}, bitangent[4] = {}; // vector mode: the dominant vertex's T and B (§8.7)
    float edge_uv[4][2][2] = {}; // edge k (corner k -> k + 1): the dominant edge's uv at both ends
    Vec3 position[4] = {};       // the own corners' positions and uvs
    float own_uv[4][2] = {};
};

// The patch's faces in MeshView::adjacency: the face triangle and its corner or edge slot (0-2) that each
// patch corner and patch edge is (a quad's corners and edges lie on its two face triangles).
struct PatchFaces {
    std::uint64_t corner_face[4] = {};
    unsigned corner_slot[4] = {};
    std::uint64_t edge_face[4] = {};
    unsigned edge_slot[4] = {};
};

// Sets up a patch of n = 3 or 4 corners whose mesh vertices are vertex[0..n-1] (all < mesh.vertex_count).
DisplacementPatch displacement_patch(const Displacement& d, const MeshView& mesh, unsigned n,
                                     const std::uint32_t* vertex, const PatchFaces& faces);

// Moves p, the surface point of triangle weights w (units of cp::fixed_one, summing to it), and bends its
// normal; the patch has 3 corners.
void displace_triangle_point(const DisplacementPatch& patch, const std::uint32_t (&w)[3], SurfacePoint& p);
// The same for quad point (s, t) of the unit square (units of cp::fixed_one); the patch has 4 corners.
void displace_quad_point(const DisplacementPatch& patch, std::uint32_t s, std::uint32_t t, SurfacePoint& p);

// The factor of an edge from a to b grown by d.factor_bound (unchanged when it is 0).
float displaced_edge_factor(const Displacement& d, float factor, Vec3 a, Vec3 b);

} // namespace ctess::rt
