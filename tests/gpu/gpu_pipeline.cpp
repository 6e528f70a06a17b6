#include "gpu_pipeline.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <sys/wait.h>

#include <ctess/runtime/pipeline/mesh_pipeline.hpp>

namespace ctess::gpu_test {

namespace {

constexpr int run_wgsl_past_limits = 3; // run_wgsl.mjs's exit status for a mesh past the limits

// run_wgsl.mjs's result file as u32 words.
std::vector<std::uint32_t> read_result_words(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    const std::streamoff bytes = in ? static_cast<std::streamoff>(in.tellg()) : -1;
    if (bytes < 0 || bytes % 4 != 0) throw std::runtime_error("cannot read the result file " + path);
    std::vector<std::uint32_t> words(static_cast<std::size_t>(bytes) / 4);
    in.seekg(0);
    in.read(reinterpret_cast<char*>(words.data()), bytes);
    if (!in) throw std::runtime_error("cannot read the result file " + path);
    return words;
}

} // namespace

PipelineOutput run_vulkan(vulkan::Runner& runner, const Scene& scene, RunLimits limits) {
    const vulkan::Output gpu = runner.tessellate(
        scene.view(), pipeline_params(scene),
        {limits.max_workgroups, limits.counts_only, limits.split_capacity, limits.max_split_capacity},
        scene.options.displacement);
    PipelineOutput out;
    out.milliseconds = gpu.milliseconds;
    out.counts_milliseconds = gpu.counts_milliseconds;
    out.patches.resize(gpu.patches.size() * patch_words + gen::totals_words);
    if (!gpu.patches.empty()) // memcpy with a null pointer is undefined even for 0 bytes
        std::memcpy(out.patches.data(), gpu.patches.data(), gpu.patches.size() * sizeof(rt::PatchRecord));
    out.patches[gpu.patches.size() * patch_words] = gpu.totals.vertices;
    out.patches[gpu.patches.size() * patch_words + 1] = gpu.totals.triangles;
    out.vertices.resize(gpu.vertices.size() * vertex_words);
    if (!gpu.vertices.empty())
        std::memcpy(out.vertices.data(), gpu.vertices.data(), gpu.vertices.size() * sizeof(rt::TessVertex));
    out.indices = gpu.indices;
    return out;
}

PipelineOutput run_vulkan_welded(vulkan::Runner& runner, const Scene& scene, RunLimits limits) {
    const vulkan::WeldedOutput gpu =
        runner.tessellate_welded(scene.view(), scene.options, {limits.max_workgroups, false, 0, 0});
    PipelineOutput out;
    out.milliseconds = gpu.milliseconds;
    out.counts_milliseconds = gpu.counts_milliseconds;
    out.patches = welded_records(gpu.edges, gpu.patches, gpu.totals);
    out.vertices.resize(gpu.vertices.size() * vertex_words);
    if (!gpu.vertices.empty())
        std::memcpy(out.vertices.data(), gpu.vertices.data(), gpu.vertices.size() * sizeof(rt::TessVertex));
    out.indices = gpu.indices;
    return out;
}

namespace {

// Scene file for run_wgsl.mjs, u32 little-endian: "CTSC", 3, params[gen::param_word::words], vertex
// floats, index word count, then the vertex floats and the index words (binding 3: mesh_index_words). Welded:
// the params are rt::gpu::weld_params (their weld word tells run_wgsl.mjs).
void write_scene_file(const Scene& scene, const std::string& path, bool welded) {
    const std::array<std::uint32_t, pipeline_param_words> params =
        welded ? rt::gpu::weld_params(scene.view(), scene.options) : pipeline_params(scene);
    const std::vector<std::uint32_t> index_words = mesh_index_words(scene);
    const std::vector<float> vertex_floats = mesh_vertex_data(scene); // with displacement's directions
    std::ofstream f(path, std::ios::binary);
    const std::uint32_t head[] = {0x43535443u, 3u};
    f.write(reinterpret_cast<const char*>(head), sizeof head);
    f.write(reinterpret_cast<const char*>(params.data()), sizeof params);
    const std::uint32_t sizes[] = {static_cast<std::uint32_t>(vertex_floats.size()),
                                   static_cast<std::uint32_t>(index_words.size())};
    f.write(reinterpret_cast<const char*>(sizes), sizeof sizes);
    f.write(reinterpret_cast<const char*>(vertex_floats.data()),
            static_cast<std::streamsize>(vertex_floats.size() * 4));
    f.write(reinterpret_cast<const char*>(index_words.data()),
            static_cast<std::streamsize>(index_words.size() * 4));
    if (!f) throw std::runtime_error("cannot write the scene file " + path);
}

// Result file: "CTGO", patch words, vertex words, index words, milliseconds (float bits), then the three
// arrays.
PipelineOutput read_result_file(const std::string& path) {
    const std::vector<std::uint32_t> r = read_result_words(path);
    if (r.size() < 5 || r[0] != 0x4F475443u) throw std::runtime_error("bad Dawn result file " + path);
    const std::size_t np = r[1], nv = r[2], ni = r[3];
    if (r.size() != 5 + np + nv + ni) throw std::runtime_error("truncated Dawn result file " + path);
    PipelineOutput out;
    out.milliseconds = bits_float(r[4]);
    out.patches.assign(r.begin() + 5, r.begin() + 5 + static_cast<std::ptrdiff_t>(np));
    out.vertices.assign(r.begin() + 5 + static_cast<std::ptrdiff_t>(np),
                        r.begin() + 5 + static_cast<std::ptrdiff_t>(np + nv));
    out.indices.assign(r.begin() + 5 + static_cast<std::ptrdiff_t>(np + nv), r.end());
    return out;
}

std::vector<PipelineOutput> run_dawn_jobs(const std::string& node, const std::string& script,
                                          const std::string& shader_dir, unsigned max_factor,
                                          const std::vector<DawnJob>& jobs, RunLimits limits, bool welded) {
    std::string cmd = "CTESS_MAX_WORKGROUPS=" + std::to_string(limits.max_workgroups) +
                      " CTESS_SPLIT_CAPACITY=" + std::to_string(limits.split_capacity) +
                      " CTESS_MAX_SPLIT_CAPACITY=" + std::to_string(limits.max_split_capacity) +
                      (limits.counts_only ? " CTESS_COUNTS_ONLY=1 " : " ") + node + " " + script + " " +
                      shader_dir + " " + std::to_string(max_factor);
    for (const DawnJob& job : jobs) {
        write_scene_file(*job.scene, job.work_file + ".scene", welded);
        std::remove((job.work_file + ".result").c_str());
        cmd += " " + job.work_file + ".scene " + job.work_file + ".result";
    }
    // node's messages go to a file, so that a failure's reason reaches the exception (and ctest's log).
    const std::string messages_path = jobs.empty() ? std::string() : jobs.front().work_file + ".messages";
    if (!messages_path.empty()) cmd += " 2> " + messages_path;
    const int status = std::system(cmd.c_str());
    std::string messages;
    if (!messages_path.empty()) {
        std::ifstream in(messages_path);
        messages.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        std::fputs(messages.c_str(), stderr);
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == run_wgsl_past_limits)
        throw std::runtime_error(
            "the mesh is past the pipeline's limits (run_wgsl.mjs recounted the totals)");
    if (status != 0) throw std::runtime_error("the Dawn run failed: " + cmd + "\n" + messages);
    std::vector<PipelineOutput> out;
    for (const DawnJob& job : jobs) out.push_back(read_result_file(job.work_file + ".result"));
    return out;
}

} // namespace

std::vector<PipelineOutput> run_dawn(const std::string& node, const std::string& script,
                                     const std::string& shader_dir, unsigned max_factor,
                                     const std::vector<DawnJob>& jobs, RunLimits limits) {
    return run_dawn_jobs(node, script, shader_dir, max_factor, jobs, limits, false);
}

std::vector<PipelineOutput> run_dawn_welded(const std::string& node, const std::string& script,
                                            const std::string& shader_dir, unsigned max_factor,
                                            const std::vector<DawnJob>& jobs, RunLimits limits) {
    // As Runner::tessellate_welded: the options the shaders weld, and no split or counts-only run.
    for (const DawnJob& job : jobs)
        if (const rt::PipelineStatus st = rt::gpu::gpu_weld_status(job.scene->view(), job.scene->options);
            st != rt::PipelineStatus::ok)
            throw std::runtime_error(std::string("the shaders do not weld this scene: ") +
                                     rt::pipeline_status_message(st));
    limits.counts_only = false;
    limits.split_capacity = limits.max_split_capacity = 0;
    return run_dawn_jobs(node, script, shader_dir, max_factor, jobs, limits, true);
}

} // namespace ctess::gpu_test
