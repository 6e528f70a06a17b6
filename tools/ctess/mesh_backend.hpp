// `ctess mesh --backend vulkan|webgpu` (docs/cli.md, "GPU backends"): the generated shaders' unwelded output
// for a model, from ctess::vulkan's Runner in this process or from Dawn in a node child process
// (share/ctess/shaders/ctess_mesh_node.mjs). The CPU backend is unwelded_output (mesh_options.hpp).
#pragma once
#include "mesh_options.hpp"

#include <ctess/runtime/pipeline/mesh_pipeline.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace ctess::cli {

struct GpuRun {
    std::string shader_dir; // the generated shaders, the table blobs and the node module
    unsigned max_factor = 64;
    double timeout_seconds = 600; // webgpu: node is killed after this long (--backend-timeout)
};

// SIGINT, SIGTERM or SIGHUP while node ran: node's process group is killed and the scratch folder removed on
// the way out; ctess's main then raises the signal again (the exit status a shell expects of it).
class Interrupted : public std::runtime_error {
  public:
    explicit Interrupted(int signal_number)
        : std::runtime_error("--backend webgpu: interrupted; node was stopped"),
          signal_number_(signal_number) {}
    int signal_number() const noexcept { return signal_number_; }

  private:
    int signal_number_;
};

// Whether this ctess was built with ctess::vulkan (Debian libvulkan-dev).
bool have_vulkan_backend();

// The shaders' output (records with totals, vertices, indices) for mesh and options, which
// rt::gpu::gpu_options_status must accept. Every output is checked before it is returned: the record and
// vertex counts the mesh's patch count implies, every index below the vertex count. Throws std::runtime_error
// with a message that names the backend and the cause: built without Vulkan, no device or adapter, a missing
// shader file, node or the npm package `webgpu` missing, node past the timeout (then killed), a malformed
// result. `device` gets the device's name.
UnweldedOutput vulkan_output(const GpuRun& run, const rt::MeshView& mesh, const rt::PipelineOptions& options,
                             std::string& device);
UnweldedOutput webgpu_output(const GpuRun& run, const rt::MeshView& mesh, const rt::PipelineOptions& options,
                             std::string& device);

// The shaders' welded output (docs/shaders.md, "Welded output"): rt::setup_welded's edges, records and totals
// and rt::emit_welded_mesh's vertices and indices, for Pattern::cp and Pattern::uniform
// (rt::gpu::gpu_weld_status must accept them). Checked as the unwelded output is (sizes, every index below
// the vertex count); the same errors.
struct WeldedGpuOutput {
    rt::WeldedTotals totals;
    std::vector<rt::WeldedEdge> edges;
    std::vector<rt::WeldedPatch> patches;
    std::vector<rt::TessVertex> vertices;
    std::vector<std::uint32_t> indices;
};
WeldedGpuOutput vulkan_welded_output(const GpuRun& run, const rt::MeshView& mesh,
                                     const rt::PipelineOptions& options, std::string& device);
WeldedGpuOutput webgpu_welded_output(const GpuRun& run, const rt::MeshView& mesh,
                                     const rt::PipelineOptions& options, std::string& device);

} // namespace ctess::cli
