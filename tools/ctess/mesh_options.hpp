// The mesh pipeline's options from `ctess mesh`'s arguments, and its unwelded output, shared by `ctess mesh`
// (cmd_mesh.cpp: --stats's `gpu` block) and `ctess serve`'s /api/tessellate (model_upload.hpp), so that the
// viewer's D3D11 side is exactly what `ctess mesh --stats` reports (docs/cli.md, "Models" and "Viewer
// server").
#pragma once
#include "cli_args.hpp"

#include <ctess/runtime/cp/table_set.hpp>
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>
#include <ctess/runtime/uniform/table_set.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace ctess::cli {

// The factor options: exactly one of --factor, --edge-length, --dice-rate (with --camera, --fov and
// --resolution). Throws UsageError naming the option that is wrong.
rt::DiceOptions dice_options_from(const Args& args);

// --pattern (cp, uniform: split at any factor, d3d11-integer, d3d11-pow2, d3d11-odd, d3d11-even), --surface
// (flat, pn, pn-aen, phong), --quad-rule and the factor options. Throws UsageError.
rt::PipelineOptions pipeline_options_from(const Args& args);

// The unwelded pipeline's output (setup_patches, emit_mesh: every patch's own vertices, as the shaders write
// them): one record per patch, totals.vertices vertices, 3 * totals.triangles indices. Throws
// std::runtime_error naming `name` when the pipeline refuses the mesh or the output would have more than
// `max_triangles` triangles (checked from the counts, before anything is emitted).
struct UnweldedOutput {
    rt::PipelineTotals totals;
    std::vector<rt::PatchRecord> records;
    std::vector<rt::TessVertex> vertices;
    std::vector<std::uint32_t> indices;
};
UnweldedOutput unwelded_output(const rt::CpTableSet& cp, const rt::UniformTableSet& uniform,
                               const rt::MeshView& view, const rt::PipelineOptions& options,
                               const std::string& name, std::uint32_t max_triangles);
// Its second half: fills out.vertices and out.indices from out.records and out.totals, setup_patches'
// counts for the same view and options. Throws std::runtime_error naming `name` when emit_mesh refuses.
void emit_unwelded(const rt::CpTableSet& cp, const rt::UniformTableSet& uniform, const rt::MeshView& view,
                   const rt::PipelineOptions& options, const std::string& name, UnweldedOutput& out);

} // namespace ctess::cli
