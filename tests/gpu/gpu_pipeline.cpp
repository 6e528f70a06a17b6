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

std::string shader_file(const std::string& dir, unsigned max_factor, const char* suffix) {
    std::string path = dir;
    path += "/ctess_mesh_";
    path += std::to_string(max_factor);
    path += suffix;
    return path;
}

// The prefix sum's totals are u32 and wrap: the host recounts the records' counts in 64 bits and refuses a
// run past the pipeline's limits (mesh_pipeline.hpp) before it allocates the output buffers.
void require_pipeline_size(std::uint64_t patches, std::uint64_t vertices, std::uint64_t triangles) {
    const rt::PipelineStatus status = rt::check_pipeline_size(patches, vertices, triangles);
    if (status != rt::PipelineStatus::ok) throw std::runtime_error(rt::pipeline_status_message(status));
}

} // namespace

std::uint32_t layout_patch_words(const std::string& dir, unsigned max_factor) {
    std::ifstream f(shader_file(dir, max_factor, ".layout.json"));
    const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    const std::string key = "\"patch_words\": ";
    const std::size_t at = text.find(key);
    if (at == std::string::npos) throw std::runtime_error("no patch_words in the shaders' layout.json");
    return static_cast<std::uint32_t>(std::stoul(text.substr(at + key.size())));
}

PipelineOutput run_vulkan(VkCompute& vk, const std::string& dir, unsigned max_factor, const Scene& scene,
                          RunLimits limits) {
    // From the shaders' layout, so that a host can also time shaders of another record size.
    const std::uint32_t record_words = layout_patch_words(dir, max_factor);
    const std::array<std::uint32_t, pipeline_param_words> params = pipeline_params(scene);
    const std::vector<std::uint32_t> tables = read_words(shader_file(dir, max_factor, ".uniform.tables.bin"));
    const std::uint32_t n = scene.patch_count();
    require_pipeline_size(n, 0, 0);
    const std::size_t b_params = vk.create_buffer(sizeof params);
    vk.upload(b_params, params.data(), sizeof params);
    const std::size_t b_tables = vk.create_buffer(tables.size() * 4);
    vk.upload(b_tables, tables.data(), tables.size() * 4);
    const std::size_t b_mesh = vk.create_buffer(scene.vertices.size() * 4);
    vk.upload(b_mesh, scene.vertices.data(), scene.vertices.size() * 4);
    const std::vector<std::uint32_t> index_words = mesh_index_words(scene); // indices, then any adjacency
    const std::size_t b_indices = vk.create_buffer(index_words.size() * 4);
    vk.upload(b_indices, index_words.data(), index_words.size() * 4);
    const std::size_t b_patches = vk.create_buffer((std::size_t{n} * record_words + gen::totals_words) * 4);
    const std::size_t b_none = vk.create_buffer(16);

    const std::size_t setup = vk.create_pipeline(shader_file(dir, max_factor, "_patch_setup.spv"));
    const std::size_t scan = vk.create_pipeline(shader_file(dir, max_factor, "_prefix_sum.spv"));
    const std::size_t emit_v = vk.create_pipeline(shader_file(dir, max_factor, "_emit_vertices.spv"));
    const std::size_t emit_t = vk.create_pipeline(shader_file(dir, max_factor, "_emit_triangles.spv"));

    PipelineOutput out;
    const std::size_t first[] = {b_params, b_tables, b_mesh, b_indices, b_patches, b_none, b_none};
    // At most 65,535 workgroups per dimension: the setup pass strides over the rest.
    constexpr std::uint32_t setup_group = gen::setup_workgroup;
    const std::uint32_t setup_groups = std::min((n + setup_group - 1) / setup_group, limits.max_workgroups);
    const VkCompute::Dispatch counts[] = {{setup, setup_groups}, {scan, 1}};
    out.milliseconds = vk.run(first, counts);
    const auto* p = static_cast<const std::uint32_t*>(vk.mapped(b_patches));
    out.patches.assign(p, p + std::size_t{n} * record_words + gen::totals_words);
    if (limits.counts_only) return out;
    // The shader's u32 totals wrap past 2^32 (it then writes the overflow marker): recount them in 64 bits
    // and refuse a mesh past the pipeline's limits before sizing the outputs, as the CPU pipeline does.
    std::uint64_t sum_v = 0, sum_t = 0;
    for (std::size_t t = 0; t < n; ++t) {
        sum_v += out.patches[t * record_words + offsetof(rt::PatchRecord, vertex_count) / 4];
        sum_t += out.patches[t * record_words + offsetof(rt::PatchRecord, triangle_count) / 4];
    }
    require_pipeline_size(n, sum_v, sum_t);
    const std::uint32_t total_v = out.patches[std::size_t{n} * record_words];
    const std::uint32_t total_t = out.patches[std::size_t{n} * record_words + 1];

    const std::size_t b_vertices = vk.create_buffer(std::size_t{total_v} * sizeof(rt::TessVertex));
    const std::size_t b_out_indices = vk.create_buffer(std::size_t{total_t} * 12);
    const std::size_t second[] = {b_params,  b_tables,   b_mesh,       b_indices,
                                  b_patches, b_vertices, b_out_indices};
    const std::uint32_t groups = std::min(n, limits.max_workgroups);
    const VkCompute::Dispatch emits[] = {{emit_v, groups}, {emit_t, groups}};
    out.milliseconds += vk.run(second, emits);
    const auto* v = static_cast<const std::uint32_t*>(vk.mapped(b_vertices));
    out.vertices.assign(v, v + std::size_t{total_v} * vertex_words);
    const auto* i = static_cast<const std::uint32_t*>(vk.mapped(b_out_indices));
    out.indices.assign(i, i + std::size_t{total_t} * 3);
    return out;
}

// Scene file for run_wgsl.mjs, u32 little-endian: "CTSC", 3, params[gen::param_word::words], vertex
// floats, index word count, then the vertex floats and the index words (binding 3: mesh_index_words). Result
// file: "CTGO", patch words, vertex words, index words, milliseconds (float bits), then the three arrays.
PipelineOutput run_dawn(const std::string& node, const std::string& script, const std::string& shader_dir,
                        unsigned max_factor, const Scene& scene, const std::string& work_file,
                        RunLimits limits) {
    const std::array<std::uint32_t, pipeline_param_words> params = pipeline_params(scene);
    const std::vector<std::uint32_t> index_words = mesh_index_words(scene);
    const std::string scene_path = work_file + ".scene";
    const std::string result_path = work_file + ".result";
    {
        std::ofstream f(scene_path, std::ios::binary);
        const std::uint32_t head[] = {0x43535443u, 3u};
        f.write(reinterpret_cast<const char*>(head), sizeof head);
        f.write(reinterpret_cast<const char*>(params.data()), sizeof params);
        const std::uint32_t sizes[] = {static_cast<std::uint32_t>(scene.vertices.size()),
                                       static_cast<std::uint32_t>(index_words.size())};
        f.write(reinterpret_cast<const char*>(sizes), sizeof sizes);
        f.write(reinterpret_cast<const char*>(scene.vertices.data()),
                static_cast<std::streamsize>(scene.vertices.size() * 4));
        f.write(reinterpret_cast<const char*>(index_words.data()),
                static_cast<std::streamsize>(index_words.size() * 4));
        if (!f) throw std::runtime_error("cannot write the scene file");
    }
    std::remove(result_path.c_str());
    std::string cmd = "CTESS_MAX_WORKGROUPS=" + std::to_string(limits.max_workgroups) +
                      (limits.counts_only ? " CTESS_COUNTS_ONLY=1 " : " ") + node;
    cmd += " ";
    cmd += script;
    cmd += " ";
    cmd += shader_dir;
    cmd += " ";
    cmd += std::to_string(max_factor);
    cmd += " ";
    cmd += scene_path;
    cmd += " ";
    cmd += result_path;
    const int status = std::system(cmd.c_str());
    if (WIFEXITED(status) && WEXITSTATUS(status) == run_wgsl_past_limits)
        throw std::runtime_error(
            "the mesh is past the pipeline's limits (run_wgsl.mjs recounted the totals)");
    if (status != 0) {
        std::string why = "the Dawn run failed: ";
        why += cmd;
        throw std::runtime_error(why);
    }
    const std::vector<std::uint32_t> r = read_words(result_path);
    if (r.size() < 5 || r[0] != 0x4F475443u) throw std::runtime_error("bad Dawn result file");
    const std::size_t np = r[1], nv = r[2], ni = r[3];
    if (r.size() != 5 + np + nv + ni) throw std::runtime_error("truncated Dawn result file");
    PipelineOutput out;
    out.milliseconds = bits_float(r[4]);
    out.patches.assign(r.begin() + 5, r.begin() + 5 + static_cast<std::ptrdiff_t>(np));
    out.vertices.assign(r.begin() + 5 + static_cast<std::ptrdiff_t>(np),
                        r.begin() + 5 + static_cast<std::ptrdiff_t>(np + nv));
    out.indices.assign(r.begin() + 5 + static_cast<std::ptrdiff_t>(np + nv), r.end());
    return out;
}

} // namespace ctess::gpu_test
