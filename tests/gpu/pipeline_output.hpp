// The CP mesh pipeline's outputs as the GPU buffers lay them out, the CPU reference run that fills them
// (runtime/include/ctess/runtime/pipeline/mesh_pipeline.hpp), and their comparison. No GPU API here: the CPU
// tests use it too.
#pragma once
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <ctess/runtime/gpu/shader_interface.hpp>
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>

#include "gpu_scenes.hpp"
#include "shader_layout.hpp" // gen/shaders: the params words and the other constants the shaders share

namespace ctess::gpu_test {

inline std::uint32_t float_bits(float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    return u;
}
inline float bits_float(std::uint32_t u) {
    float f;
    std::memcpy(&f, &u, 4);
    return f;
}
// Record sizes in words, from the CPU structs the GPU layouts copy.
inline constexpr std::uint32_t patch_words = sizeof(rt::PatchRecord) / 4;
inline constexpr std::uint32_t vertex_words = sizeof(rt::TessVertex) / 4;

struct PipelineOutput {
    std::vector<std::uint32_t> patches;  // PatchRecord words per patch, then the two totals
    std::vector<std::uint32_t> vertices; // TessVertex words
    std::vector<std::uint32_t> indices;
    double milliseconds = 0.0; // GPU: submit to completion of all four passes; CPU: the whole pipeline
    double counts_milliseconds =
        -1.0; // of which setup and prefix sum (Vulkan's first submission); -1: not timed
    std::uint32_t total_vertices() const {
        return static_cast<std::uint32_t>(vertices.size() / vertex_words);
    }
    std::uint32_t total_triangles() const { return static_cast<std::uint32_t>(indices.size() / 3); }
};

// The params buffer (rt::gpu::param_word, docs/shaders.md), the emit range covering every patch.
inline constexpr std::size_t pipeline_param_words = rt::gpu::param_word::words;
inline std::array<std::uint32_t, pipeline_param_words> pipeline_params(const Scene& scene) {
    return rt::gpu::pipeline_params(scene.view(), scene.options);
}

// The CPU pipeline with the scene's options; the uniform pattern uses the configured uniform tables
// (rt::uniform_tables), as the shaders' blob does.
inline PipelineOutput run_cpu(const rt::CpTableSet& tables, const Scene& scene) {
    PipelineOutput out;
    const auto start = std::chrono::steady_clock::now();
    const rt::MeshView mesh = scene.view();
    std::vector<rt::PatchRecord> patches(mesh.patch_count());
    rt::PipelineTotals totals;
    if (const rt::PipelineStatus st =
            rt::setup_patches(tables, rt::uniform_tables, mesh, scene.options, patches, totals);
        st != rt::PipelineStatus::ok)
        throw std::runtime_error(std::string("setup_patches: ") + rt::pipeline_status_message(st));
    std::vector<rt::TessVertex> vertices(totals.vertices);
    out.indices.resize(std::size_t{totals.triangles} * 3);
    if (const rt::PipelineStatus st =
            rt::emit_mesh(tables, rt::uniform_tables, mesh, scene.options, patches, vertices, out.indices);
        st != rt::PipelineStatus::ok)
        throw std::runtime_error(std::string("emit_mesh: ") + rt::pipeline_status_message(st));
    out.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    out.patches.resize(patches.size() * patch_words + gen::totals_words);
    std::memcpy(out.patches.data(), patches.data(), patches.size() * sizeof(rt::PatchRecord));
    out.patches[patches.size() * patch_words] = totals.vertices;
    out.patches[patches.size() * patch_words + 1] = totals.triangles;
    out.vertices.resize(vertices.size() * vertex_words);
    std::memcpy(out.vertices.data(), vertices.data(), vertices.size() * sizeof(rt::TessVertex));
    return out;
}

// The welded output (docs/shaders.md, "Welded output") in the same shape: patches holds the edge list
// (rt::WeldedEdge words), then one rt::WeldedPatch per patch, then the totals' vertices, triangles and edges.
inline std::vector<std::uint32_t> welded_records(const std::vector<rt::WeldedEdge>& edges,
                                                 const std::vector<rt::WeldedPatch>& patches,
                                                 const rt::WeldedTotals& totals) {
    std::vector<std::uint32_t> words((edges.size() + patches.size()) * 4);
    if (!edges.empty()) std::memcpy(words.data(), edges.data(), edges.size() * sizeof(rt::WeldedEdge));
    if (!patches.empty())
        std::memcpy(words.data() + edges.size() * 4, patches.data(),
                    patches.size() * sizeof(rt::WeldedPatch));
    words.insert(words.end(), {totals.vertices, totals.triangles, totals.edges});
    return words;
}
static_assert(sizeof(rt::WeldedEdge) == 16 && sizeof(rt::WeldedPatch) == 16);

// rt::setup_welded and rt::emit_welded_mesh with the scene's options.
inline PipelineOutput run_cpu_welded(const rt::CpTableSet& tables, const Scene& scene) {
    PipelineOutput out;
    const auto start = std::chrono::steady_clock::now();
    const rt::MeshView mesh = scene.view();
    std::vector<rt::WeldedEdge> edges(rt::weld_edge_capacity(mesh));
    std::vector<rt::WeldedPatch> patches(mesh.patch_count());
    rt::WeldedTotals totals;
    if (const rt::PipelineStatus st =
            rt::setup_welded(tables, rt::uniform_tables, mesh, scene.options, edges, patches, totals);
        st != rt::PipelineStatus::ok)
        throw std::runtime_error(std::string("setup_welded: ") + rt::pipeline_status_message(st));
    edges.resize(totals.edges);
    std::vector<rt::TessVertex> vertices(totals.vertices);
    out.indices.resize(std::size_t{totals.triangles} * 3);
    if (const rt::PipelineStatus st = rt::emit_welded_mesh(tables, rt::uniform_tables, mesh, scene.options,
                                                           edges, patches, vertices, out.indices);
        st != rt::PipelineStatus::ok)
        throw std::runtime_error(std::string("emit_welded_mesh: ") + rt::pipeline_status_message(st));
    out.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    totals.clamped_edges = 0; // not counted on the GPU
    out.patches = welded_records(edges, patches, totals);
    out.vertices.resize(vertices.size() * vertex_words);
    if (!vertices.empty())
        std::memcpy(out.vertices.data(), vertices.data(), vertices.size() * sizeof(rt::TessVertex));
    return out;
}

struct Comparison {
    std::size_t patch_mismatches = 0; // words of the patch records and totals
    std::size_t barycentric_mismatches = 0;
    std::size_t index_mismatches = 0;
    std::size_t position_outside = 0;  // |gpu - cpu| > 1e-5 * max(1, |cpu|), per component
    std::size_t attribute_outside = 0; // normals and uvs, same bound
    double max_position_error = 0.0;   // relative, as above
    bool sizes_match = false;
    std::string first_difference;
    bool equal() const {
        return sizes_match && patch_mismatches == 0 && barycentric_mismatches == 0 && index_mismatches == 0 &&
               position_outside == 0 && attribute_outside == 0;
    }
};
inline Comparison compare(const PipelineOutput& cpu, const PipelineOutput& gpu) {
    Comparison c;
    c.sizes_match = cpu.patches.size() == gpu.patches.size() && cpu.vertices.size() == gpu.vertices.size() &&
                    cpu.indices.size() == gpu.indices.size();
    auto note = [&c](const char* what, std::size_t at, double a, double b) {
        if (!c.first_difference.empty()) return;
        char buf[160];
        std::snprintf(buf, sizeof buf, "%s at word %zu: cpu %.9g, gpu %.9g", what, at, a, b);
        c.first_difference = buf;
    };
    if (!c.sizes_match) {
        char buf[200];
        std::snprintf(buf, sizeof buf, "sizes differ: patches %zu/%zu vertices %zu/%zu indices %zu/%zu",
                      cpu.patches.size(), gpu.patches.size(), cpu.vertices.size() / vertex_words,
                      gpu.vertices.size() / vertex_words, cpu.indices.size(), gpu.indices.size());
        c.first_difference = buf;
    }
    for (std::size_t k = 0; k < cpu.patches.size() && k < gpu.patches.size(); ++k)
        if (cpu.patches[k] != gpu.patches[k]) {
            ++c.patch_mismatches;
            note("patch record", k, cpu.patches[k], gpu.patches[k]);
        }
    for (std::size_t k = 0; k < cpu.indices.size() && k < gpu.indices.size(); ++k)
        if (cpu.indices[k] != gpu.indices[k]) {
            ++c.index_mismatches;
            note("index", k, cpu.indices[k], gpu.indices[k]);
        }
    for (std::size_t v = 0;
         v + vertex_words <= cpu.vertices.size() && v + vertex_words <= gpu.vertices.size();
         v += vertex_words) {
        for (std::size_t k = 0; k < 2; ++k)
            if (cpu.vertices[v + k] != gpu.vertices[v + k]) {
                ++c.barycentric_mismatches;
                note("barycentric", v + k, cpu.vertices[v + k], gpu.vertices[v + k]);
            }
        for (std::size_t k = 2; k < vertex_words; ++k) {
            const double a = bits_float(cpu.vertices[v + k]), b = bits_float(gpu.vertices[v + k]);
            const double err = std::fabs(a - b) / std::fmax(1.0, std::fabs(a));
            if (k < 5) c.max_position_error = std::fmax(c.max_position_error, err);
            if (!(err <= 1e-5)) {
                ++(k < 5 ? c.position_outside : c.attribute_outside);
                note(k < 5 ? "position" : "normal/uv", v + k, a, b);
            }
        }
    }
    return c;
}

} // namespace ctess::gpu_test
