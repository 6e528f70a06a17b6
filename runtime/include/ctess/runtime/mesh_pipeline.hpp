// The CP mesh pipeline on the CPU: per-edge tessellation factors (tess_factor.hpp), the orientation rule per
// base triangle (cp_orientation.hpp), per-patch counts and their exclusive prefix sum, then every output
// vertex (exact barycentrics, then position, normal and uv by surface_eval.hpp) and every output triangle
// (indices in provoking-vertex order). The generated GLSL and WGSL shaders run the same steps with the same
// formulas and the same record layouts; this is the reference they are tested against.
//
// Counts first, then fills (as OpenSubdiv's Bfr::Tessellation): nothing here allocates.
//
//   std::vector<PatchRecord> patches(mesh.triangle_count);
//   PipelineTotals totals;
//   setup_patches(cp_tables_64, mesh, options, patches, totals);
//   std::vector<TessVertex> vertices(totals.vertices);
//   std::vector<std::uint32_t> indices(3 * totals.triangles);
//   emit_mesh(cp_tables_64, mesh, options, patches, vertices, indices);
//
// Bad input: a base triangle with a vertex index >= vertex_count is culled (no vertices, no triangles);
// factors follow tess_factor.hpp and CpPatch's clamping; spans that are too small make the call return false
// and write nothing.
#pragma once
#include <cstdint>
#include <span>

#include <ctess/cp_line.hpp>
#include <ctess/cp_orientation.hpp>

#include "cp_patch.hpp"
#include "cp_table_set.hpp"
#include "surface_eval.hpp"
#include "tess_factor.hpp"

namespace ctess::rt {

inline constexpr unsigned mesh_vertex_floats = 8; // position xyz, normal xyz, uv

struct MeshView {
    const float* vertices = nullptr; // mesh_vertex_floats per vertex
    std::uint32_t vertex_count = 0;
    const std::uint32_t* indices = nullptr; // 3 per base triangle, counter-clockwise
    std::uint32_t triangle_count = 0;
};

struct PipelineOptions {
    DiceOptions dice{};
    SurfaceOptions surface{};
};

// One base triangle (patch). 16 words: the GPU's patch buffer uses this layout.
struct PatchRecord {
    std::uint32_t rotation = 0;  // cp::Rotation::shift: pattern vertex v_k is base vertex (k + rotation) % 3
    std::uint32_t token[3] = {}; // pattern edges e0, e1, e2: CP line state
    std::uint32_t t16[3] = {};
    std::uint32_t vertex_count = 0;
    std::uint32_t triangle_count = 0;
    std::uint32_t first_vertex = 0; // exclusive prefix sums over the patches
    std::uint32_t first_triangle = 0;
    float factor[3] = {}; // base edges E0 = w0w1, E1 = w1w2, E2 = w2w0, before clamping
    std::uint32_t reserved[2] = {};
};
static_assert(sizeof(PatchRecord) == 64);

// One output vertex. 10 words: the GPU's vertex buffer uses this layout.
struct TessVertex {
    std::uint32_t u = 0, v = 0; // base weights of w1 and w2, units of 2^-24 (w0 = 2^24 - u - v)
    float position[3] = {};
    float normal[3] = {};
    float uv[2] = {};
};
static_assert(sizeof(TessVertex) == 40);

struct PipelineTotals {
    std::uint32_t vertices = 0;
    std::uint32_t triangles = 0;
};

namespace detail {

inline Vec3 mesh_position(const MeshView& mesh, std::uint32_t v) {
    const float* p = mesh.vertices + std::size_t{v} * mesh_vertex_floats;
    return {p[0], p[1], p[2]};
}

inline SurfaceCorner mesh_corner(const MeshView& mesh, std::uint32_t v) {
    const float* p = mesh.vertices + std::size_t{v} * mesh_vertex_floats;
    return {{p[0], p[1], p[2]}, {p[3], p[4], p[5]}, {p[6], p[7]}, v};
}

inline bool base_triangle(const MeshView& mesh, std::uint32_t t, std::uint32_t (&w)[3]) {
    for (unsigned k = 0; k < 3; ++k) w[k] = mesh.indices[std::size_t{t} * 3 + k];
    return w[0] < mesh.vertex_count && w[1] < mesh.vertex_count && w[2] < mesh.vertex_count;
}

} // namespace detail

// Patch t's rotation, line states and counts (first_vertex and first_triangle are left 0).
inline PatchRecord setup_patch(const CpTableSet& tables, const MeshView& mesh, std::uint32_t t,
                               const PipelineOptions& options) {
    PatchRecord rec;
    std::uint32_t w[3];
    if (!detail::base_triangle(mesh, t, w)) return rec;
    const float scale = options.dice.factor_scale();
    float length2[3];
    for (unsigned k = 0; k < 3; ++k) {
        const std::uint32_t i = w[k], j = w[(k + 1) % 3];
        const Vec3 a = detail::mesh_position(mesh, i < j ? i : j);
        const Vec3 b = detail::mesh_position(mesh, i < j ? j : i);
        rec.factor[k] = edge_tess_factor(a, b, options.dice.eye, scale);
        const Vec3 d = b - a;
        length2[k] = dot(d, d);
    }
    const cp::Rotation rot = cp::smallest_edge_rotation(length2[0], length2[1], length2[2]);
    rec.rotation = rot.shift;
    cp::LineState s[3];
    for (unsigned k = 0; k < 3; ++k) {
        s[k] = cp::clamp_line_state(cp::line_state(rec.factor[(k + rot.shift) % 3], tables.max_factor),
                                    tables.max_factor);
        rec.token[k] = s[k].token;
        rec.t16[k] = s[k].t16;
    }
    const Counts counts = cp_counts(tables, s[0], s[1], s[2]);
    rec.vertex_count = counts.vertices;
    rec.triangle_count = counts.triangles;
    return rec;
}

// Every patch's record, with the exclusive prefix sums. False (nothing written) if patches is too small.
inline bool setup_patches(const CpTableSet& tables, const MeshView& mesh, const PipelineOptions& options,
                          std::span<PatchRecord> patches, PipelineTotals& totals) {
    if (patches.size() < mesh.triangle_count) return false;
    PipelineTotals sum;
    for (std::uint32_t t = 0; t < mesh.triangle_count; ++t) {
        PatchRecord rec = setup_patch(tables, mesh, t, options);
        rec.first_vertex = sum.vertices;
        rec.first_triangle = sum.triangles;
        sum.vertices += rec.vertex_count;
        sum.triangles += rec.triangle_count;
        patches[t] = rec;
    }
    totals = sum;
    return true;
}

inline CpPatch patch_of(const CpTableSet& tables, const PatchRecord& rec) {
    return CpPatch(tables, cp::LineState{rec.token[0], rec.t16[0]}, cp::LineState{rec.token[1], rec.t16[1]},
                   cp::LineState{rec.token[2], rec.t16[2]});
}

// Vertex i of a patch: exact base weights, then the surface.
inline TessVertex patch_vertex(const CpPatch& patch, const PatchRecord& rec, const SurfaceCorner (&corner)[3],
                               std::uint32_t i, const SurfaceOptions& surface) {
    const DomainPoint base =
        cp::to_base_point(cp::Rotation{static_cast<std::uint8_t>(rec.rotation)}, patch.vertex(i));
    const std::uint32_t w[3] = {cp::fixed_one - base.u - base.v, base.u, base.v};
    const SurfacePoint s = evaluate_surface(corner, w, surface);
    return {base.u,
            base.v,
            {s.position.x, s.position.y, s.position.z},
            {s.normal.x, s.normal.y, s.normal.z},
            {s.uv[0], s.uv[1]}};
}

// Every vertex and triangle of the mesh, at the records' offsets. False (nothing written) if a span is too
// small for the records' counts.
inline bool emit_mesh(const CpTableSet& tables, const MeshView& mesh, const PipelineOptions& options,
                      std::span<const PatchRecord> patches, std::span<TessVertex> vertices,
                      std::span<std::uint32_t> indices) {
    if (patches.size() < mesh.triangle_count) return false;
    for (std::uint32_t t = 0; t < mesh.triangle_count; ++t) {
        const PatchRecord& rec = patches[t];
        if (std::size_t{rec.first_vertex} + rec.vertex_count > vertices.size() ||
            (std::size_t{rec.first_triangle} + rec.triangle_count) * 3 > indices.size())
            return false;
    }
    for (std::uint32_t t = 0; t < mesh.triangle_count; ++t) {
        const PatchRecord& rec = patches[t];
        std::uint32_t w[3];
        if (!detail::base_triangle(mesh, t, w) || rec.vertex_count == 0) continue;
        const SurfaceCorner corner[3] = {detail::mesh_corner(mesh, w[0]), detail::mesh_corner(mesh, w[1]),
                                         detail::mesh_corner(mesh, w[2])};
        const CpPatch patch = patch_of(tables, rec);
        for (std::uint32_t i = 0; i < rec.vertex_count; ++i)
            vertices[rec.first_vertex + i] = patch_vertex(patch, rec, corner, i, options.surface);
        for (std::uint32_t p = 0; p < rec.triangle_count; ++p) {
            const CpTriangle tri = patch.triangle(p);
            for (unsigned k = 0; k < 3; ++k)
                indices[3 * (std::size_t{rec.first_triangle} + p) + k] = rec.first_vertex + tri[k];
        }
    }
    return true;
}

} // namespace ctess::rt
