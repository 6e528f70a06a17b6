// The mesh pipeline's CPU reference (mesh_pipeline.hpp), compiled once with contraction and fast-math off
// (runtime/CMakeLists.txt): the per-edge factors, the patch setup and the emit loop decide counts and shared
// edges' points, so they must not change with the caller's flags (docs/api.md, "Crack-free evaluation").
// The loops are written once over the pattern family; each family contributes its setup, its record check
// and its base points.
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>

#include <concepts>
#include <cstdint>
#include <span>

#include <ctess/core/patch_concept.hpp>

namespace ctess::rt {

namespace {

Vec3 mesh_position(const MeshView& mesh, std::uint32_t v) {
    const float* p = mesh.vertices + std::size_t{v} * mesh_vertex_floats;
    return {p[0], p[1], p[2]};
}

SurfaceCorner mesh_corner(const MeshView& mesh, std::uint32_t v) {
    const float* p = mesh.vertices + std::size_t{v} * mesh_vertex_floats;
    return {{p[0], p[1], p[2]}, {p[3], p[4], p[5]}, {p[6], p[7]}, v};
}

bool base_triangle(const MeshView& mesh, std::uint32_t t, std::uint32_t (&w)[3]) {
    for (unsigned k = 0; k < 3; ++k) w[k] = mesh.indices[std::size_t{t} * 3 + k];
    return w[0] < mesh.vertex_count && w[1] < mesh.vertex_count && w[2] < mesh.vertex_count;
}

// The unclamped factors of base edges E0, E1, E2 (endpoints in mesh-index order, so neighbours agree) and the
// edges' squared lengths.
void base_edges(const MeshView& mesh, const std::uint32_t (&w)[3], const DiceOptions& dice,
                float (&factor)[3], float (&length2)[3]) {
    const float scale = dice.factor_scale();
    for (unsigned k = 0; k < 3; ++k) {
        const std::uint32_t i = w[k], j = w[(k + 1) % 3];
        const Vec3 a = mesh_position(mesh, i < j ? i : j);
        const Vec3 b = mesh_position(mesh, i < j ? j : i);
        factor[k] = edge_tess_factor(a, b, dice.eye, scale);
        const Vec3 d = b - a;
        length2[k] = dot(d, d);
    }
}

// The output vertex of exact base weights (w1, w2) = (base.u, base.v), units of cp::fixed_one.
TessVertex surface_vertex(const SurfaceCorner (&corner)[3], DomainPoint base, const SurfaceOptions& surface) {
    const std::uint32_t w[3] = {cp::fixed_one - base.u - base.v, base.u, base.v};
    const SurfacePoint s = evaluate_surface(corner, w, surface);
    return {base.u,
            base.v,
            {s.position.x, s.position.y, s.position.z},
            {s.normal.x, s.normal.y, s.normal.z},
            {s.uv[0], s.uv[1]}};
}

// The CP family (docs/algorithm.md §2): rotation by the smallest edge, CP line states, the setup block.
struct CpFamily {
    using patch_type = CpPatch;
    const CpTableSet& tables;

    void setup(PatchRecord& rec, const float (&length2)[3]) const {
        const cp::Rotation rot = cp::smallest_edge_rotation(length2[0], length2[1], length2[2]);
        rec.rotation = rot.shift;
        cp::LineState s[3];
        for (unsigned k = 0; k < 3; ++k) {
            s[k] = cp::clamp_line_state(cp::line_state(rec.factor[(k + rot.shift) % 3], tables.max_factor),
                                        tables.max_factor);
            rec.token[k] = s[k].token;
            rec.t16[k] = s[k].t16;
        }
        // One CpPatchSetup gives both the counts and the block.
        const PatchSetupBlock block = patch_setup_block(tables, s[0], s[1], s[2]);
        rec.vertex_count = block.vertices;
        rec.triangle_count = block.triangles;
        for (unsigned k = 0; k < setup_word::words; ++k) rec.setup[k] = block.word[k];
    }
    // The counts a record must have (none for a culled patch); false when setup() cannot have written it.
    bool record_counts(const PatchRecord& rec, bool culled, Counts& counts) const {
        if (rec.rotation > 2) return false;
        if (!culled) counts = patch_of(tables, rec).counts();
        return true;
    }
    patch_type patch(const PatchRecord& rec) const { return patch_of(tables, rec); }
    static DomainPoint base_point(const patch_type& patch, const PatchRecord& rec, std::uint32_t i) {
        return cp::to_base_point(cp::Rotation{static_cast<std::uint8_t>(rec.rotation)}, patch.vertex(i));
    }
};

// The uniform family (§3.4): rotation 0, each base edge's factor rounded and clamped to [1, N].
struct UniformFamily {
    using patch_type = UniformPatch;
    const UniformTableSet& tables;

    void setup(PatchRecord& rec, const float (&)[3]) const {
        for (unsigned k = 0; k < 3; ++k)
            rec.set_uniform_factor(k, uniform_factor(rec.factor[k], tables.max_factor));
        const UniformPatch patch = uniform_patch_of(tables, rec);
        rec.vertex_count = patch.counts().vertices;
        rec.triangle_count = patch.counts().triangles;
        uniform_setup_words(rec.setup, patch);
    }
    bool record_counts(const PatchRecord& rec, bool culled, Counts& counts) const {
        if (culled) return true;
        if (rec.rotation != 0) return false;
        for (unsigned k = 0; k < 3; ++k)
            if (rec.uniform_factor(k) < 1 || rec.uniform_factor(k) > tables.max_factor || rec.t16[k] != 0)
                return false;
        counts = uniform_patch_of(tables, rec).counts();
        return true;
    }
    patch_type patch(const PatchRecord& rec) const { return uniform_patch_of(tables, rec); }
    static DomainPoint base_point(const patch_type& patch, const PatchRecord&, std::uint32_t i) {
        return uniform_base_point(patch, i);
    }
};

// What a family gives the loops below: an indexed patch type and its setup, record check and base points.
template <class F>
concept PipelineFamily = IndexedTessPatch<typename F::patch_type> &&
    requires(const F& f, PatchRecord& rec, const PatchRecord& crec, const float (&l)[3], Counts& counts,
             const typename F::patch_type& p) {
    f.setup(rec, l);
    { f.record_counts(crec, true, counts) } -> std::same_as<bool>;
    { f.patch(crec) } -> std::same_as<typename F::patch_type>;
    { f.base_point(p, crec, 0u) } -> std::same_as<DomainPoint>;
};

template <PipelineFamily F>
PatchRecord setup_record(const F& family, const MeshView& mesh, std::uint32_t t,
                         const PipelineOptions& options) {
    PatchRecord rec;
    std::uint32_t w[3];
    if (!base_triangle(mesh, t, w)) return rec;
    float length2[3];
    base_edges(mesh, w, options.dice, rec.factor, length2);
    family.setup(rec, length2);
    return rec;
}

PipelineStatus check_pattern(const UniformTableSet* uniform, const PipelineOptions& options) {
    if (options.pattern != Pattern::cp && options.pattern != Pattern::uniform)
        return PipelineStatus::bad_option;
    if (options.pattern == Pattern::uniform && uniform == nullptr) return PipelineStatus::no_uniform_tables;
    return PipelineStatus::ok;
}

template <PipelineFamily F>
PipelineStatus setup_all(const F& family, const MeshView& mesh, const PipelineOptions& options,
                         std::span<PatchRecord> patches, PipelineTotals& totals) {
    if (const PipelineStatus s = check_pipeline_size(mesh.triangle_count, 0, 0); s != PipelineStatus::ok)
        return s;
    std::uint64_t vertices = 0, triangles = 0;
    for (std::uint32_t t = 0; t < mesh.triangle_count; ++t) {
        PatchRecord rec = setup_record(family, mesh, t, options);
        rec.first_vertex = static_cast<std::uint32_t>(vertices);
        rec.first_triangle = static_cast<std::uint32_t>(triangles);
        vertices += rec.vertex_count;
        triangles += rec.triangle_count;
        if (const PipelineStatus s = check_pipeline_size(0, vertices, triangles); s != PipelineStatus::ok)
            return s;
        patches[t] = rec;
    }
    totals = {static_cast<std::uint32_t>(vertices), static_cast<std::uint32_t>(triangles)};
    return PipelineStatus::ok;
}

PipelineStatus setup_patches(const CpTableSet& tables, const UniformTableSet* uniform, const MeshView& mesh,
                             const PipelineOptions& options, std::span<PatchRecord> patches,
                             PipelineTotals& totals) {
    if (patches.size() < mesh.triangle_count) return PipelineStatus::span_too_small;
    if (const PipelineStatus s = check_pattern(uniform, options); s != PipelineStatus::ok) return s;
    return options.pattern == Pattern::uniform
               ? setup_all(UniformFamily{*uniform}, mesh, options, patches, totals)
               : setup_all(CpFamily{tables}, mesh, options, patches, totals);
}

// Checks every record and the spans, then writes every patch's vertices and triangles.
template <PipelineFamily F>
PipelineStatus emit_all(const F& family, const MeshView& mesh, const PipelineOptions& options,
                        std::span<const PatchRecord> patches, std::span<TessVertex> vertices,
                        std::span<std::uint32_t> indices) {
    if (const PipelineStatus s = check_pipeline_size(mesh.triangle_count, 0, 0); s != PipelineStatus::ok)
        return s;
    std::uint64_t vertex_sum = 0, triangle_sum = 0;
    for (std::uint32_t t = 0; t < mesh.triangle_count; ++t) {
        const PatchRecord& rec = patches[t];
        std::uint32_t w[3];
        const bool culled = !base_triangle(mesh, t, w);
        Counts counts;
        if (!family.record_counts(rec, culled, counts) || rec.first_vertex != vertex_sum ||
            rec.first_triangle != triangle_sum || rec.vertex_count != counts.vertices ||
            rec.triangle_count != counts.triangles)
            return PipelineStatus::bad_patch_record;
        vertex_sum += rec.vertex_count;
        triangle_sum += rec.triangle_count;
        if (const PipelineStatus s = check_pipeline_size(0, vertex_sum, triangle_sum);
            s != PipelineStatus::ok)
            return s;
    }
    if (vertex_sum > vertices.size() || 3 * triangle_sum > indices.size())
        return PipelineStatus::span_too_small;
    for (std::uint32_t t = 0; t < mesh.triangle_count; ++t) {
        const PatchRecord& rec = patches[t];
        std::uint32_t w[3];
        if (!base_triangle(mesh, t, w) || rec.vertex_count == 0) continue;
        const SurfaceCorner corner[3] = {mesh_corner(mesh, w[0]), mesh_corner(mesh, w[1]),
                                         mesh_corner(mesh, w[2])};
        std::uint32_t* out = indices.data() + 3 * std::size_t{rec.first_triangle};
        const typename F::patch_type patch = family.patch(rec);
        for (std::uint32_t i = 0; i < rec.vertex_count; ++i)
            vertices[rec.first_vertex + i] =
                surface_vertex(corner, family.base_point(patch, rec, i), options.surface);
        for (std::uint32_t p = 0; p < rec.triangle_count; ++p) {
            const std::array<std::uint32_t, 3> tri = patch.triangle(p);
            for (unsigned k = 0; k < 3; ++k) out[3 * p + k] = rec.first_vertex + tri[k];
        }
    }
    return PipelineStatus::ok;
}

PipelineStatus emit_mesh(const CpTableSet& tables, const UniformTableSet* uniform, const MeshView& mesh,
                         const PipelineOptions& options, std::span<const PatchRecord> patches,
                         std::span<TessVertex> vertices, std::span<std::uint32_t> indices) {
    if (patches.size() < mesh.triangle_count) return PipelineStatus::span_too_small;
    if (const PipelineStatus s = check_pattern(uniform, options); s != PipelineStatus::ok) return s;
    return options.pattern == Pattern::uniform
               ? emit_all(UniformFamily{*uniform}, mesh, options, patches, vertices, indices)
               : emit_all(CpFamily{tables}, mesh, options, patches, vertices, indices);
}

} // namespace

PatchRecord setup_patch(const CpTableSet& tables, const MeshView& mesh, std::uint32_t t,
                        const PipelineOptions& options) {
    return setup_record(CpFamily{tables}, mesh, t, options);
}

PatchRecord setup_uniform_patch(const UniformTableSet& tables, const MeshView& mesh, std::uint32_t t,
                                const PipelineOptions& options) {
    return setup_record(UniformFamily{tables}, mesh, t, options);
}

PipelineStatus setup_patches(const CpTableSet& tables, const MeshView& mesh, const PipelineOptions& options,
                             std::span<PatchRecord> patches, PipelineTotals& totals) {
    return setup_patches(tables, nullptr, mesh, options, patches, totals);
}

PipelineStatus setup_patches(const CpTableSet& tables, const UniformTableSet& uniform, const MeshView& mesh,
                             const PipelineOptions& options, std::span<PatchRecord> patches,
                             PipelineTotals& totals) {
    return setup_patches(tables, &uniform, mesh, options, patches, totals);
}

TessVertex patch_vertex(const CpPatch& patch, const PatchRecord& rec, const SurfaceCorner (&corner)[3],
                        std::uint32_t i, const SurfaceOptions& surface) {
    return surface_vertex(corner, CpFamily::base_point(patch, rec, i), surface);
}

PipelineStatus emit_mesh(const CpTableSet& tables, const MeshView& mesh, const PipelineOptions& options,
                         std::span<const PatchRecord> patches, std::span<TessVertex> vertices,
                         std::span<std::uint32_t> indices) {
    return emit_mesh(tables, nullptr, mesh, options, patches, vertices, indices);
}

PipelineStatus emit_mesh(const CpTableSet& tables, const UniformTableSet& uniform, const MeshView& mesh,
                         const PipelineOptions& options, std::span<const PatchRecord> patches,
                         std::span<TessVertex> vertices, std::span<std::uint32_t> indices) {
    return emit_mesh(tables, &uniform, mesh, options, patches, vertices, indices);
}

} // namespace ctess::rt
