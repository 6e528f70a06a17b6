// Runs the mesh pipeline on Vulkan (the generated GLSL as SPIR-V, through the installed host
// <ctess/runtime/gpu/vulkan.hpp>) and on Dawn (the generated WGSL, through node and the installed
// ctess_webgpu.mjs), with every output as the GPU buffers lay it out (pipeline_output.hpp).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <ctess/runtime/cp/table_set.hpp>

#include <ctess/runtime/gpu/vulkan.hpp>

#include "pipeline_output.hpp"

namespace ctess::gpu_test {

// How a host dispatches: at most max_workgroups per dispatch (the passes stride over the rest; 65,535 is the
// one-dispatch limit), and with counts_only only the setup and prefix-sum passes run (no outputs).
struct RunLimits {
    std::uint32_t max_workgroups = rt::max_dispatch_workgroups;
    bool counts_only = false;
    // Pattern::uniform_split: the split regions' first capacity and their limit (0: the hosts' defaults).
    std::uint32_t split_capacity = 0;
    std::uint32_t max_split_capacity = 0;
};
// The totals a prefix sum writes when a mesh's vertex or triangle total does not fit in u32.
inline constexpr std::uint32_t totals_overflow = gen::totals_overflow;

// Both throw std::runtime_error on failure, and when the totals overflow (unless counts_only).
PipelineOutput run_vulkan(vulkan::Runner& runner, const Scene& scene, RunLimits limits = {});
// The welded output (Runner::tessellate_welded) in run_cpu_welded's shape.
PipelineOutput run_vulkan_welded(vulkan::Runner& runner, const Scene& scene, RunLimits limits = {});
// One scene of a Dawn run and the path its scene and result files start with.
struct DawnJob {
    const Scene* scene;
    std::string work_file;
};
// Writes each job's scene file, runs `node run_wgsl.mjs` once for all of them (node and the pipelines start
// once), reads the results back in job order. `node` is a shell command prefix: the node binary, optionally
// preceded by environment assignments.
std::vector<PipelineOutput> run_dawn(const std::string& node, const std::string& script,
                                     const std::string& shader_dir, unsigned max_factor,
                                     const std::vector<DawnJob>& jobs, RunLimits limits = {});
// The welded output (docs/shaders.md, "Welded output") of each job's scene in run_cpu_welded's shape, as
// run_vulkan_welded: the scene files carry rt::gpu::weld_params, which run_wgsl.mjs runs welded. Throws when
// rt::gpu::gpu_weld_status refuses a scene.
std::vector<PipelineOutput> run_dawn_welded(const std::string& node, const std::string& script,
                                            const std::string& shader_dir, unsigned max_factor,
                                            const std::vector<DawnJob>& jobs, RunLimits limits = {});

} // namespace ctess::gpu_test
