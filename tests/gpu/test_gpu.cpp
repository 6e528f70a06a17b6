// The generated shaders against the CPU mesh pipeline, on the backend CTESS_GPU_BACKEND names: the GLSL as
// SPIR-V on lavapipe, or the WGSL on Dawn (its GLES backend on llvmpipe, or its Vulkan backend on
// SwiftShader), as tests/gpu/CMakeLists.txt sets the environment. Both maximum factors run on every backend.
// No test skips: a missing driver or node module is a failure.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <ctess/runtime/cp/table_set.hpp>

#include "../pipeline/mesh_fixtures.hpp" // the mixed torus and the closedness checks of the CPU tests
#include "gpu_checks.hpp"
#include "gpu_pipeline.hpp"

using namespace ctess;
using namespace ctess::gpu_test;

namespace {

const rt::CpTableSet& tables_for(unsigned max_factor) {
    return max_factor == 64 ? rt::cp_tables_64 : rt::cp_tables_256;
}

// The backend of this run: CTESS_GPU_BACKEND, which tests/gpu/CMakeLists.txt sets per ctest variant. One
// executable serves all three, so it compiles once.
enum class Backend { vulkan, dawn, dawn_swiftshader };
Backend backend() {
    static const Backend chosen = [] {
        const char* name = std::getenv("CTESS_GPU_BACKEND");
        const std::string value = name ? name : "";
        if (value == "vulkan") {
            setenv("VK_DRIVER_FILES", CTESS_LAVAPIPE_ICD, 1); // before the runner makes its instance
            return Backend::vulkan;
        }
        if (value == "dawn") return Backend::dawn;
        if (value == "dawn_swiftshader") return Backend::dawn_swiftshader;
        throw std::runtime_error("set CTESS_GPU_BACKEND to vulkan, dawn or dawn_swiftshader (ctest does)");
    }();
    return chosen;
}
// The node command: Dawn's GLES backend by default (run_wgsl.mjs), its Vulkan backend on SwiftShader for the
// second implementation (XDG_RUNTIME_DIR: the Vulkan loader complains without it, harmlessly).
std::string node_command() {
    if (backend() == Backend::dawn) return CTESS_NODE;
    return "CTESS_DAWN_BACKEND=vulkan VK_DRIVER_FILES=" CTESS_SWIFTSHADER_ICD
           " XDG_RUNTIME_DIR=" CTESS_WORK_DIR " " CTESS_NODE;
}
const char* backend_name() {
    return backend() == Backend::vulkan ? "Vulkan (lavapipe)"
           : backend() == Backend::dawn ? "Dawn (OpenGL ES on llvmpipe)"
                                        : "Dawn (Vulkan on SwiftShader)";
}
} // namespace
// Under the asan-ubsan preset LeakSanitizer finds 128 bytes that lavapipe reallocs and never frees, in a
// module the Vulkan loader has unloaded by exit, so no suppression can name it: leak checks are off for the
// GPU tests only. (A hook ASan reads at start-up; without ASan nothing calls it.)
extern "C" const char* __asan_default_options() {
    return "detect_leaks=0";
}
namespace {
// One device and pipeline per maximum factor, made on first use and kept for the whole run.
vulkan::Runner& runner(unsigned max_factor) {
    static std::unique_ptr<vulkan::Runner> runners[2];
    std::unique_ptr<vulkan::Runner>& r = runners[max_factor == 64 ? 0 : 1];
    if (backend() != Backend::vulkan) throw std::runtime_error("the Vulkan runner on a Dawn variant");
    if (!r) r = std::make_unique<vulkan::Runner>(CTESS_SHADER_DIR, max_factor);
    return *r;
}
// Dawn's work files: the variants run in parallel under ctest, so each has its own names.
std::string dawn_work_file(unsigned max_factor, const char* name) {
    return std::string(CTESS_WORK_DIR) + "/" + (backend() == Backend::dawn ? "dawn_" : "swiftshader_") +
           name + "_" + std::to_string(max_factor);
}
PipelineOutput run_gpu(unsigned max_factor, const Scene& scene, const char* name, RunLimits limits = {}) {
    if (backend() == Backend::vulkan) return run_vulkan(runner(max_factor), scene, limits);
    return run_dawn(node_command(), CTESS_RUN_WGSL, CTESS_SHADER_DIR, max_factor,
                    {{&scene, dawn_work_file(max_factor, name)}}, limits)
        .front();
}
// Several scenes in one Dawn run: node and the pipelines start once (seconds on SwiftShader).
std::vector<PipelineOutput> run_gpu_batch(unsigned max_factor,
                                          const std::vector<std::pair<const char*, Scene>>& scenes,
                                          RunLimits limits = {}) {
    std::vector<PipelineOutput> out;
    if (backend() == Backend::vulkan) {
        for (const auto& entry : scenes)
            out.push_back(run_gpu(max_factor, entry.second, entry.first, limits));
        return out;
    }
    std::vector<DawnJob> jobs;
    for (const auto& [name, scene] : scenes) jobs.push_back({&scene, dawn_work_file(max_factor, name)});
    return run_dawn(node_command(), CTESS_RUN_WGSL, CTESS_SHADER_DIR, max_factor, jobs, limits);
}

const char* surface_name(rt::Surface s) {
    return s == rt::Surface::flat           ? "flat"
           : s == rt::Surface::pn_triangles ? "PN"
           : s == rt::Surface::pn_aen       ? "PN-AEN"
                                            : "Phong";
}

// The uniform pattern's factors sweep [1, N] of the configured uniform tables, which every blob carries.
void check_parity(unsigned max_factor, rt::Surface surface, rt::Pattern pattern = rt::Pattern::cp,
                  unsigned quad_every = 0) {
    const unsigned sweep_max = pattern == rt::Pattern::uniform ? rt::uniform_tables.max_factor : max_factor;
    Scene scene = factor_sweep_grid(sweep_max, 24, surface, quad_every);
    scene.options.pattern = pattern;
    REQUIRE(scene.patch_count() >= 1000);
    const PipelineOutput cpu = run_cpu(tables_for(max_factor), scene);
    const char* work = pattern == rt::Pattern::uniform
                           ? (quad_every ? "parity_uniform_quads" : "parity_uniform")
                           : (quad_every ? "parity_quads" : "parity"); // parallel ctest
    const PipelineOutput gpu = run_gpu(max_factor, scene, work);
    // A second run: the driver's shader cache is warm, so its time is the dispatch itself. Same bits, too.
    const PipelineOutput again = run_gpu(max_factor, scene, work);
    CHECK(again.patches == gpu.patches);
    CHECK(again.vertices == gpu.vertices);
    CHECK(again.indices == gpu.indices);
    const Comparison c = compare(cpu, gpu);
    std::printf(
        "%s, max %u, %s, %s: %u patches (%zu quads), %u vertices, %u triangles; GPU %.1f ms (first run "
        "%.1f ms), CPU %.1f ms; max position error %.2g\n",
        backend_name(), max_factor, pattern_name(pattern), surface_name(surface), scene.patch_count(),
        scene.quads.size() / 4, cpu.total_vertices(), cpu.total_triangles(), again.milliseconds,
        gpu.milliseconds, cpu.milliseconds, c.max_position_error);
    INFO(c.first_difference);
    CHECK(c.sizes_match);
    CHECK(c.patch_mismatches == 0);
    CHECK(c.barycentric_mismatches == 0);
    CHECK(c.index_mismatches == 0);
    CHECK(c.position_outside == 0);
    CHECK(c.attribute_outside == 0);
    // The factors cover [1, max]: every octave has edges, and so do both clamps.
    const std::vector<std::size_t> octaves = factor_octaves(cpu, scene.patch_count(), sweep_max);
    for (std::size_t k = 0; k < octaves.size(); ++k) {
        INFO("octave bin " << k);
        CHECK(octaves[k] > 0);
    }
}

void check_watertight(unsigned max_factor, rt::Surface surface, rt::Pattern pattern = rt::Pattern::cp) {
    Scene scene = icosphere(3, surface, max_factor == 64 ? 4.0f : 3.0f);
    scene.options.pattern = pattern;
    const PipelineOutput gpu =
        run_gpu(max_factor, scene, pattern == rt::Pattern::uniform ? "crack_uniform" : "crack");
    const CrackReport r = crack_check(scene, gpu);
    std::printf(
        "%s, max %u, %s, %s icosphere: %u patches, %zu shared edges, %zu edge points, %zu mismatches\n",
        backend_name(), max_factor, pattern_name(pattern), surface_name(surface), scene.patch_count(),
        r.shared_edges, r.edge_points, r.position_mismatches);
    CHECK(r.shared_edges == scene.patch_count() * 3 / 2); // closed: every edge has two patches
    CHECK(r.edge_points > 3 * r.shared_edges);
    CHECK(r.unmatched_points == 0);
    CHECK(r.position_mismatches == 0);
    // The GPU's icosphere equals the CPU's as well.
    const Comparison c = compare(run_cpu(tables_for(max_factor), scene), gpu);
    INFO(c.first_difference);
    CHECK(c.equal());
}

} // namespace

namespace {
// A long thin triangle whose long edges split three levels deep at N = 16 (a piece of a root edge above
// 16.5 x 256 splits again at depth 2): width 1 / 2,500, seen from above, its long edges about 4,400
// DiceRates, its short one 1 (about 75,000 triangles).
Scene split_strip(rt::Surface surface) {
    Scene s;
    const rt::Vec3 up{0, 0, 1};
    for (const float x : {0.0f, 1.0f})
        for (const float y : {0.0f, 0.0004f}) detail::push_vertex(s, {x, y, 0.0f}, up, x, y);
    s.indices = {0, 2, 3}; // (0, 0), (1, 0), (1, 0.0004)
    s.options.dice.eye = {0.5f, 0.0f, 0.5f};
    s.options.dice.dice_rate = 1.0f;
    s.options.dice.projection_scale = 2200.0f;
    s.options.surface = {surface, 0.75f};
    s.options.pattern = rt::Pattern::uniform_split;
    return s;
}

} // namespace

TEST_CASE(
    "GPU parity, uniform split: leaves of depth 0 to 3, triangles and quads, the split regions regrown") {
    // A factor sweep up to 3 x 400 with every third cell a quad (depths 0 to 2), PN, and the strip (depth 3):
    // every record, barycentric and index the CPU's. Both run from 100 nodes a region (the levels need
    // thousands: grown and run again) and 7 workgroups a dispatch (the roots and emit passes stride over
    // every root and leaf; the levels' count and expand passes are dispatched indirectly, at most 65,535
    // each).
    Scene sweep = factor_sweep_grid(400, 8, rt::Surface::pn_triangles, 3);
    sweep.options.pattern = rt::Pattern::uniform_split;
    const Scene strip = split_strip(rt::Surface::flat);
    const std::vector<std::pair<const char*, Scene>> scenes = {{"split_sweep", sweep},
                                                               {"split_strip", strip}};
    const std::vector<PipelineOutput> gpu = run_gpu_batch(64, scenes, RunLimits{7, false, 100});
    std::array<std::uint32_t, 5> depths{};
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        const Scene& scene = scenes[k].second;
        const PipelineOutput cpu = run_cpu(rt::cp_tables_64, scene);
        const std::array<std::uint32_t, 5> d = split_depths(scene, cpu);
        for (std::size_t j = 0; j < d.size(); ++j) depths[j] += d[j];
        const Comparison c = compare(cpu, gpu[k]);
        std::printf(
            "%s, uniform split, %s: %u patches (%zu quads), leaves of depth 0-3: %u %u %u %u, %u vertices, "
            "%u triangles; GPU %.1f ms; max position error %.2g\n",
            backend_name(), scenes[k].first, scene.patch_count(), scene.quads.size() / 4, d[0], d[1], d[2],
            d[3], cpu.total_vertices(), cpu.total_triangles(), gpu[k].milliseconds, c.max_position_error);
        INFO(scenes[k].first << ": " << c.first_difference);
        CHECK(c.equal());
    }
    for (std::size_t j = 0; j < 4; ++j) CHECK(depths[j] > 0);
}

TEST_CASE("Vulkan host, uniform split: an emit range writes the leaves of its patches, and nothing else",
          "[vulkan]") {
    // The emit passes find the range's leaves by a binary search of the leaves' patches (docs/shaders.md,
    // "Splitting"); 7 workgroups a dispatch stride over them.
    Scene sweep = factor_sweep_grid(400, 8, rt::Surface::flat, 3);
    sweep.options.pattern = rt::Pattern::uniform_split;
    const PipelineOutput cpu = run_cpu(rt::cp_tables_64, sweep);
    auto params = pipeline_params(sweep);
    const std::uint32_t first = 60, end = 100; // triangles and quads
    REQUIRE(end > sweep.indices.size() / 3);
    params[rt::gpu::param_word::first_patch] = first;
    params[rt::gpu::param_word::end_patch] = end;
    const vulkan::Output gpu = runner(64).tessellate(sweep.view(), params, {7});
    const auto* records = reinterpret_cast<const rt::PatchRecord*>(cpu.patches.data());
    const std::size_t v0 = records[first].first_vertex,
                      v1 = records[end - 1].first_vertex + records[end - 1].vertex_count,
                      t0 = records[first].first_triangle,
                      t1 = records[end - 1].first_triangle + records[end - 1].triangle_count;
    REQUIRE(gpu.vertices.size() * vertex_words == cpu.vertices.size());
    REQUIRE(gpu.indices.size() == cpu.indices.size());
    const auto* words = reinterpret_cast<const std::uint32_t*>(gpu.vertices.data());
    std::size_t inside_wrong = 0, outside_written = 0;
    for (std::size_t v = 0; v < gpu.vertices.size(); ++v)
        for (std::size_t k = 0; k < 2; ++k) { // the exact words: base weights
            const std::uint32_t w = words[v * vertex_words + k];
            if (v >= v0 && v < v1)
                inside_wrong += w != cpu.vertices[v * vertex_words + k];
            else
                outside_written += w != 0;
        }
    for (std::size_t i = 0; i < gpu.indices.size(); ++i)
        if (i >= 3 * t0 && i < 3 * t1)
            inside_wrong += gpu.indices[i] != cpu.indices[i];
        else
            outside_written += gpu.indices[i] != 0;
    CHECK(v1 - v0 > 1000);
    CHECK(inside_wrong == 0);
    CHECK(outside_written == 0);
}

TEST_CASE("GPU uniform split: a level past the run's node limit is an error naming the nodes, never a short "
          "output") {
    CHECK_THROWS_WITH(
        run_gpu(64, split_strip(rt::Surface::flat), "split_limit", RunLimits{7, false, 100, 1000}),
        Catch::Contains("nodes per region"));
    // A limit below the hosts' default start begins there: this mesh needs 2,261 nodes at its deepest level.
    const Scene small = split_strip(rt::Surface::flat);
    CHECK_THROWS_WITH(run_gpu(64, small, "split_limit", RunLimits{7, false, 0, 1000}),
                      Catch::Contains("nodes per region") && Catch::Contains("(1000)"));
    const Comparison c = compare(run_cpu(rt::cp_tables_64, small),
                                 run_gpu(64, small, "split_limit", RunLimits{7, false, 0, 2500}));
    INFO(c.first_difference);
    CHECK(c.equal());
}

TEST_CASE("GPU parity: 1152-patch factor sweep, max 64, flat, PN and Phong") {
    check_parity(64, rt::Surface::flat);
    check_parity(64, rt::Surface::pn_triangles);
    check_parity(64, rt::Surface::phong);
}

TEST_CASE("GPU parity: 1152-patch factor sweep, max 256, PN") {
    check_parity(256, rt::Surface::pn_triangles);
}

TEST_CASE("GPU crack test: icosphere with PN and Phong is watertight, max 64 and 256") {
    for (unsigned max_factor : {64u, 256u}) {
        check_watertight(max_factor, rt::Surface::pn_triangles);
        check_watertight(max_factor, rt::Surface::phong);
    }
}

TEST_CASE(
    "GPU parity, uniform pattern: 1152-patch factor sweep over [1, N], flat, PN and Phong, both blobs") {
    check_parity(64, rt::Surface::flat, rt::Pattern::uniform);
    check_parity(64, rt::Surface::pn_triangles, rt::Pattern::uniform);
    check_parity(64, rt::Surface::phong, rt::Pattern::uniform);
    check_parity(256, rt::Surface::pn_triangles, rt::Pattern::uniform);
}

TEST_CASE("GPU crack test, uniform pattern: icosphere with PN and Phong is watertight") {
    check_watertight(64, rt::Surface::pn_triangles, rt::Pattern::uniform);
    check_watertight(64, rt::Surface::phong, rt::Pattern::uniform);
    check_watertight(256, rt::Surface::flat, rt::Pattern::uniform);
}

TEST_CASE("GPU grid-stride, uniform pattern: 7 workgroups per dispatch give the same output") {
    Scene scene = factor_sweep_grid(rt::uniform_tables.max_factor, 24, rt::Surface::flat);
    scene.options.pattern = rt::Pattern::uniform;
    const Comparison c =
        compare(run_cpu(rt::cp_tables_64, scene), run_gpu(64, scene, "stride_uniform", RunLimits{7, false}));
    INFO(c.first_difference);
    CHECK(c.equal());
}

TEST_CASE("GPU grid-stride: 7 workgroups per dispatch give the same output as one per patch") {
    const Scene scene = factor_sweep_grid(64, 24, rt::Surface::flat);
    const Comparison c =
        compare(run_cpu(rt::cp_tables_64, scene), run_gpu(64, scene, "stride", RunLimits{7, false}));
    INFO(c.first_difference);
    CHECK(c.equal());
}

TEST_CASE("GPU totals: beyond 2^32 - 2 vertices the prefix sum writes the overflow marker and hosts refuse") {
    const Scene scene = max_factor_grid(182); // 66,248 patches
    const std::uint32_t n = scene.patch_count();
    // Max 64: 4,098 vertices and 4,096 triangles per patch, 271 M in all: exact totals.
    const PipelineOutput fits = run_gpu(64, scene, "totals", RunLimits{rt::max_dispatch_workgroups, true});
    CHECK(fits.patches[std::size_t{n} * patch_words] == n * 4098u);
    CHECK(fits.patches[std::size_t{n} * patch_words + 1] == n * 4096u);
    // Max 256: 65,538 vertices per patch, 4.34e9 in all.
    const PipelineOutput over = run_gpu(256, scene, "totals", RunLimits{rt::max_dispatch_workgroups, true});
    CHECK(over.patches[std::size_t{n} * patch_words] == totals_overflow);
    CHECK(over.patches[std::size_t{n} * patch_words + 1] == totals_overflow);
    // A full run recounts the totals in 64 bits and refuses before sizing the outputs (the CPU pipeline's
    // limits).
    CHECK_THROWS_WITH(run_gpu(256, scene, "totals"),
                      Catch::Contains("past the pipeline's limits") || Catch::Contains("429,496,729"));
}

TEST_CASE("GPU large output: a 51 MB vertex binding (once past what a collected Dawn instance let through)") {
    const Scene scene = icosphere(3, rt::Surface::pn_triangles, 1.875f);
    const PipelineOutput gpu = run_gpu(256, scene, "large");
    CHECK(gpu.total_vertices() * sizeof(rt::TessVertex) >
          48'000'000ull); // docs/shaders.md: 27 MB aborted node before
    const Comparison c = compare(run_cpu(rt::cp_tables_256, scene), gpu);
    INFO(c.first_difference);
    CHECK(c.equal());
}

TEST_CASE("Vulkan host: options the shaders do not run, bad params and missing files are errors, not output",
          "[vulkan]") {
    const Scene scene = icosphere(1, rt::Surface::flat, 4.0f);
    vulkan::Runner& gpu = runner(64);
    const auto refused = [&](rt::PipelineOptions options, rt::MeshView mesh) {
        CHECK_THROWS_AS(gpu.tessellate(mesh, options), vulkan::Error);
    };
    rt::PipelineOptions options = scene.options;
    options.pattern = rt::Pattern::d3d11_fractional_even;
    refused(options, scene.view());
    options = scene.options;
    options.dice.mode = rt::FactorMode::constant;
    refused(options, scene.view());
    options = scene.options;
    options.quad_rule = static_cast<rt::QuadRule>(7);
    refused(options, scene.view());
    // Params naming more patches than the mesh holds, or an emit range past them.
    auto params = pipeline_params(scene);
    params[rt::gpu::param_word::patch_count] += 1;
    CHECK_THROWS_AS(gpu.tessellate(scene.view(), params), vulkan::Error);
    params = pipeline_params(scene);
    params[rt::gpu::param_word::end_patch] += 1;
    CHECK_THROWS_AS(gpu.tessellate(scene.view(), params), vulkan::Error);
    // The same runner still works afterwards.
    const Comparison c = compare(run_cpu(rt::cp_tables_64, scene), run_gpu(64, scene, "host_errors"));
    CHECK(c.equal());
    CHECK_THROWS_WITH(vulkan::Runner("/nonexistent", 64),
                      Catch::Contains("/nonexistent/ctess_mesh_64_patch_setup.spv"));
    CHECK_THROWS_AS(vulkan::Runner(CTESS_SHADER_DIR, 128), vulkan::Error);
    // MeshView::position_ids: the shaders order edges by vertex index, so the host refuses them.
    rt::MeshView with_ids = scene.view();
    const std::vector<std::uint32_t> ids(with_ids.vertex_count, 0);
    with_ids.position_ids = ids.data();
    CHECK_THROWS_AS(gpu.tessellate(with_ids, scene.options), vulkan::Error);
    // More quads in the params than patches or than the mesh has.
    params = pipeline_params(scene);
    params[rt::gpu::param_word::quad_count] = params[rt::gpu::param_word::patch_count] + 1;
    CHECK_THROWS_AS(gpu.tessellate(scene.view(), params), vulkan::Error);
    params = pipeline_params(scene);
    params[rt::gpu::param_word::quad_count] = 1;
    CHECK_THROWS_AS(gpu.tessellate(scene.view(), params), vulkan::Error);
    // An empty mesh: no patches, zero totals, no output.
    const vulkan::Output empty =
        gpu.tessellate(rt::MeshView{scene.vertices.data(), 3, nullptr, 0}, scene.options);
    CHECK(empty.patches.empty());
    CHECK(empty.totals.vertices == 0);
    CHECK(empty.totals.triangles == 0);
    CHECK(empty.vertices.empty());
    CHECK(empty.indices.empty());
}

// ---- quads (docs/algorithm.md §7.2, §7.3): mixed with triangles in one dispatch ----

TEST_CASE("GPU parity, quads: a mixed grid (every fourth cell a quad), CP and uniform, flat, PN and Phong") {
    check_parity(64, rt::Surface::flat, rt::Pattern::cp, 4);
    check_parity(64, rt::Surface::pn_triangles, rt::Pattern::cp, 4);
    check_parity(64, rt::Surface::phong, rt::Pattern::cp, 4);
    check_parity(256, rt::Surface::pn_triangles, rt::Pattern::cp, 4);
    check_parity(64, rt::Surface::pn_triangles, rt::Pattern::uniform, 4);
    check_parity(256, rt::Surface::phong, rt::Pattern::uniform, 4);
}

namespace {
// A pipeline_fixtures torus as a scene, seen from outside at DiceRate 2 with the surface given.
Scene torus_scene(const pipeline_fixtures::Model& torus, rt::Surface surface) {
    Scene scene;
    scene.vertices = torus.vertices;
    scene.indices = torus.triangles;
    scene.quads = torus.quads;
    scene.options.surface = {surface, 1.0f};
    scene.options.dice.eye = {2.0f, 3.0f, 9.0f};
    scene.options.dice.projection_scale = 300.0f;
    scene.options.dice.dice_rate = 2.0f;
    return scene;
}

// Closed by exact position bits: the independent weld of the CPU tests.
bool closed_by_position(const PipelineOutput& out) {
    std::vector<rt::TessVertex> vertices(out.total_vertices());
    std::memcpy(static_cast<void*>(vertices.data()), out.vertices.data(),
                vertices.size() * sizeof(rt::TessVertex));
    return pipeline_fixtures::closed_manifold(
        pipeline_fixtures::directed_edges(out.indices, pipeline_fixtures::weld_ids(vertices, false)));
}

// The GPU output of a closed mixed torus is closed by position and equals the CPU's.
void check_mixed_torus(unsigned max_factor, rt::Surface surface, rt::Pattern pattern, rt::QuadRule rule) {
    Scene scene = torus_scene(pipeline_fixtures::torus(24, 10, pipeline_fixtures::Faces::mixed), surface);
    scene.options.pattern = pattern;
    scene.options.quad_rule = rule;
    const char* work = pattern == rt::Pattern::uniform         ? "torus_uniform"
                       : pattern == rt::Pattern::uniform_split ? "torus_split"
                                                               : "torus";
    const PipelineOutput gpu = run_gpu(max_factor, scene, work);
    std::printf("%s, max %u, %s, %s mixed torus (%zu quads, %zu triangles): %u vertices, %u triangles\n",
                backend_name(), max_factor, pattern_name(pattern), surface_name(surface),
                scene.quads.size() / 4, scene.indices.size() / 3, gpu.total_vertices(),
                gpu.total_triangles());
    CHECK(gpu.total_triangles() > 20 * scene.patch_count());
    CHECK(closed_by_position(gpu));
    const PipelineOutput cpu = run_cpu(tables_for(max_factor), scene);
    if (pattern == rt::Pattern::uniform_split) CHECK(split_depths(scene, cpu)[1] > 0); // some patches split
    const Comparison c = compare(cpu, gpu);
    INFO(c.first_difference);
    CHECK(c.equal());
}
} // namespace

TEST_CASE("GPU crack test, quads: a mixed torus stays closed on the GPU, both quad rules, every pattern") {
    check_mixed_torus(64, rt::Surface::pn_triangles, rt::Pattern::cp, rt::QuadRule::longer_pair);
    check_mixed_torus(64, rt::Surface::phong, rt::Pattern::cp, rt::QuadRule::as_labelled);
    check_mixed_torus(256, rt::Surface::flat, rt::Pattern::uniform, rt::QuadRule::longer_pair);
    check_mixed_torus(64, rt::Surface::pn_triangles, rt::Pattern::uniform, rt::QuadRule::as_labelled);
    check_mixed_torus(64, rt::Surface::phong, rt::Pattern::uniform_split, rt::QuadRule::longer_pair);
}

#if defined(CTESS_GPU_HAVE_MODELS)
// PN-AEN (docs/algorithm.md §6.1) reads the adjacency after the triangle indices in binding 3
// (docs/shaders.md). The scene: a split-normal icosphere of 320 patches, every region border a uv seam and
// most of them hard edges, adjacency from meshoptimizer.
namespace {

Scene aen_scene(unsigned max_factor, rt::Surface surface, rt::Pattern pattern) {
    // Max 256: 80 larger patches, whose factors pass 64.
    Scene scene = max_factor == 64 ? split_normal_icosphere(2, surface, 6.0f)
                                   : split_normal_icosphere(1, surface, 5.0f);
    scene.options.pattern = pattern;
    return scene;
}

// Position words of the GPU output that differ in bits from the CPU's.
std::size_t position_bit_differences(const PipelineOutput& cpu, const PipelineOutput& gpu) {
    std::size_t n = 0;
    for (std::size_t v = 0;
         v + vertex_words <= cpu.vertices.size() && v + vertex_words <= gpu.vertices.size();
         v += vertex_words)
        for (std::size_t k = 2; k < 5; ++k) n += cpu.vertices[v + k] != gpu.vertices[v + k];
    return n;
}

} // namespace

TEST_CASE(
    "GPU PN-AEN: split-normal icosphere with adjacency, CP and uniform (and split), max 64 and 256: the "
    "CPU's output, watertight") {
    for (unsigned max_factor : {64u, 256u}) {
        for (rt::Pattern pattern : {rt::Pattern::cp, rt::Pattern::uniform, rt::Pattern::uniform_split}) {
            if (pattern == rt::Pattern::uniform_split && max_factor == 256)
                continue; // the same split as 64's
            const Scene scene = aen_scene(max_factor, rt::Surface::pn_aen, pattern);
            INFO("max " << max_factor << ", " << pattern_name(pattern));
            REQUIRE(scene.adjacency.size() == 12 * std::size_t{scene.patch_count()});
            const PipelineOutput gpu = run_gpu(max_factor, scene,
                                               pattern == rt::Pattern::uniform         ? "aen_uniform"
                                               : pattern == rt::Pattern::uniform_split ? "aen_split"
                                                                                       : "aen");
            const PipelineOutput cpu = run_cpu(tables_for(max_factor), scene);
            if (pattern == rt::Pattern::uniform_split) CHECK(split_depths(scene, cpu)[1] > 0); // some split
            const Comparison c = compare(cpu, gpu);
            const CrackReport r = crack_check(scene, gpu);
            std::printf(
                "%s, max %u, %s, PN-AEN split-normal icosphere: %u patches, %u vertices, %zu shared "
                "edges, %zu edge points, %zu cracks; max position error %.2g, %zu of %u position words "
                "differ in bits from the CPU\n",
                backend_name(), max_factor, pattern_name(pattern), scene.patch_count(), cpu.total_vertices(),
                r.shared_edges, r.edge_points, r.position_mismatches, c.max_position_error,
                position_bit_differences(cpu, gpu), 3 * cpu.total_vertices());
            INFO(c.first_difference);
            CHECK(c.equal());
            CHECK(r.shared_edges == scene.patch_count() * 3 / 2); // closed by position
            CHECK(r.edge_points > 3 * r.shared_edges);
            CHECK(r.unmatched_points == 0);
            CHECK(r.position_mismatches == 0);
            float largest = 0.0f; // the base edge factors, before clamping
            for (std::uint32_t t = 0; t < scene.patch_count(); ++t)
                for (unsigned k = 0; k < 3; ++k)
                    largest =
                        std::max(largest, bits_float(cpu.patches[std::size_t{t} * patch_words + 11 + k]));
            CHECK(largest > (max_factor == 64 ? 16.0f : 64.0f));
        }
    }
}

TEST_CASE("GPU PN-AEN: plain PN on the same split-normal icosphere cracks") {
    const Scene scene = aen_scene(64, rt::Surface::pn_triangles, rt::Pattern::cp);
    const PipelineOutput gpu = run_gpu(64, scene, "aen_pn");
    const CrackReport r = crack_check(scene, gpu);
    std::printf("%s, max 64, CP, PN split-normal icosphere: %zu of %zu edge points crack\n", backend_name(),
                r.position_mismatches, r.edge_points);
    CHECK(r.shared_edges == scene.patch_count() * 3 / 2);
    CHECK(r.position_mismatches > r.edge_points / 10); // the hard edges bend differently from each side
    const Comparison c = compare(run_cpu(rt::cp_tables_64, scene), gpu);
    INFO(c.first_difference);
    CHECK(c.equal());
}

TEST_CASE("GPU PN-AEN: an adjacency index past the vertex count, or no adjacency, makes the edge a boundary, "
          "as on the CPU") {
    const Scene good = aen_scene(64, rt::Surface::pn_aen, rt::Pattern::cp);
    const auto vertex_count = static_cast<std::uint32_t>(good.vertices.size() / rt::mesh_vertex_floats);
    // Two hard edges of different triangles: a neighbour's vertex has another normal than the own corner at
    // its position.
    const auto floats = [&good](std::uint32_t v, unsigned at) {
        return &good.vertices[std::size_t{v} * rt::mesh_vertex_floats + at];
    };
    std::vector<std::pair<std::uint32_t, unsigned>> hard; // (triangle, edge)
    for (std::uint32_t t = 0; t < good.patch_count() && hard.size() < 2; ++t)
        for (unsigned e = 0; e < 3; ++e) {
            bool other_normal = false;
            for (unsigned k = 0; k < 2; ++k) {
                const std::uint32_t adj = good.adjacency[12 * t + 3 + 2 * e + k];
                for (unsigned j = 0; j < 2; ++j) {
                    const std::uint32_t own = good.indices[3 * t + (e + j) % 3];
                    other_normal = other_normal || (std::memcmp(floats(adj, 0), floats(own, 0), 12) == 0 &&
                                                    std::memcmp(floats(adj, 3), floats(own, 3), 12) != 0);
                }
            }
            if (other_normal) {
                hard.emplace_back(t, e);
                break;
            }
        }
    REQUIRE(hard.size() == 2);
    Scene bad = good, boundary = good;
    // The first: its second vertex one past the end; the second: both the largest index.
    bad.adjacency[12 * hard[0].first + 4 + 2 * hard[0].second] = vertex_count;
    bad.adjacency[12 * hard[1].first + 3 + 2 * hard[1].second] = 0xFFFFFFFFu;
    bad.adjacency[12 * hard[1].first + 4 + 2 * hard[1].second] = 0xFFFFFFFFu;
    // The documented result (docs/shaders.md): those edges as boundaries, their own two corners.
    for (const auto& [t, e] : hard)
        for (unsigned k = 0; k < 2; ++k)
            boundary.adjacency[12 * t + 3 + 2 * e + k] = good.indices[3 * t + (e + k) % 3];
    const PipelineOutput cpu = run_cpu(rt::cp_tables_64, bad);
    const PipelineOutput gpu = run_gpu(64, bad, "aen_bad");
    const Comparison c = compare(cpu, gpu);
    INFO(c.first_difference);
    CHECK(c.equal());
    // The CPU's result is the boundary form's, bit for bit, and not the good adjacency's (the edges are
    // hard).
    const bool as_boundary = cpu.vertices == run_cpu(rt::cp_tables_64, boundary).vertices;
    const bool as_good = cpu.vertices == run_cpu(rt::cp_tables_64, good).vertices;
    CHECK(as_boundary);
    CHECK_FALSE(as_good);
    // Binding 3 without adjacency words: every edge a boundary, the CPU's MeshView::adjacency = null.
    Scene none = good;
    none.adjacency.clear();
    const Comparison n = compare(run_cpu(rt::cp_tables_64, none), run_gpu(64, none, "aen_none"));
    INFO(n.first_difference);
    CHECK(n.equal());
}
#endif

#if defined(CTESS_GPU_HAVE_MODELS)
namespace {
// The mixed torus with every face on its own vertex copies, each with its own tilted normal: every edge is a
// hard edge and a uv seam; adjacency from meshoptimizer (models::build_adjacency), quads included.
Scene faceted_mixed_torus(rt::Surface surface) {
    const pipeline_fixtures::Model smooth = pipeline_fixtures::torus(16, 8, pipeline_fixtures::Faces::mixed);
    pipeline_fixtures::Model faceted;
    std::uint32_t face = 0;
    const auto copy = [&](std::uint32_t v) {
        const float* a = &smooth.vertices[std::size_t{v} * rt::mesh_vertex_floats];
        const std::uint32_t seed = 7 * (v * 97 + face);
        const rt::Vec3 n =
            rt::normalize_or_zero(rt::Vec3{a[3], a[4], a[5]} +
                                  0.4f * rt::Vec3{detail::unit(seed) - 0.5f, detail::unit(seed + 1) - 0.5f,
                                                  detail::unit(seed + 2) - 0.5f});
        return faceted.add(a[0], a[1], a[2], n.x, n.y, n.z, a[6] + 0.01f * static_cast<float>(face), a[7]);
    };
    for (std::size_t k = 0; k < smooth.triangles.size(); k += 3, ++face)
        for (unsigned c = 0; c < 3; ++c) faceted.triangles.push_back(copy(smooth.triangles[k + c]));
    for (std::size_t k = 0; k < smooth.quads.size(); k += 4, ++face)
        for (unsigned c = 0; c < 4; ++c) faceted.quads.push_back(copy(smooth.quads[k + c]));
    Scene s = torus_scene(faceted, surface);
    add_adjacency(s);
    return s;
}
} // namespace

TEST_CASE("GPU PN-AEN, quads: a faceted mixed torus (every edge hard) is the CPU's output and closed, and PN "
          "opens") {
    for (rt::Pattern pattern : {rt::Pattern::cp, rt::Pattern::uniform}) {
        Scene scene = faceted_mixed_torus(rt::Surface::pn_aen);
        scene.options.pattern = pattern;
        REQUIRE(scene.adjacency.size() == 12 * (scene.indices.size() / 3 + scene.quads.size() / 2));
        const PipelineOutput gpu =
            run_gpu(64, scene, pattern == rt::Pattern::uniform ? "aen_quads_uniform" : "aen_quads");
        const Comparison c = compare(run_cpu(rt::cp_tables_64, scene), gpu);
        std::printf("%s, max 64, %s, PN-AEN faceted mixed torus (%zu quads): %u vertices; max position error "
                    "%.2g\n",
                    backend_name(), pattern_name(pattern), scene.quads.size() / 4, gpu.total_vertices(),
                    c.max_position_error);
        INFO(pattern_name(pattern) << ": " << c.first_difference);
        CHECK(c.equal());
        CHECK(closed_by_position(gpu));
    }
    Scene pn = faceted_mixed_torus(rt::Surface::pn_triangles);
    CHECK_FALSE(closed_by_position(run_gpu(64, pn, "aen_quads_pn")));
}
#endif

// ---- displacement (docs/algorithm.md §8, docs/shaders.md "Displacement"): triangle meshes ----
namespace {
// A 64 x 48 height texture of a few waves and a hash (procedural-looking, no symmetry), and the Displacement
// that reads it: the scene keeps pointers to both, so they outlive it.
struct DisplacementData {
    std::vector<float> texels;
    std::vector<float> directions; // 3 per mesh vertex: welded_directions
    std::vector<float> tangents;   // vector mode: 4 per mesh vertex, uv_tangents
    rt::Displacement d;
};
std::unique_ptr<DisplacementData> height_texture(rt::AddressMode address, float scale, float factor_bound) {
    auto data = std::make_unique<DisplacementData>();
    const std::uint32_t width = 64, height = 48;
    data->texels.resize(std::size_t{width} * height);
    for (std::uint32_t j = 0; j < height; ++j)
        for (std::uint32_t i = 0; i < width; ++i)
            data->texels[std::size_t{j} * width + i] =
                std::sin(0.31f * static_cast<float>(i)) * std::cos(0.23f * static_cast<float>(j)) +
                0.25f * detail::unit(j * width + i);
    data->d.map = {data->texels.data(), width, height, address};
    data->d.scale = scale;
    data->d.factor = 1.5f;
    data->d.offset = -0.2f;
    data->d.factor_bound = factor_bound;
    data->d.normal_step = 1.0f / 128.0f;
    return data;
}
// The same for vector displacement (docs/algorithm.md §8.7): a 64 x 48 RGB texture whose three channels are
// different uv-dependent waves plus a hash, so that seams matter and every axis of the frame moves points.
std::unique_ptr<DisplacementData> vector_texture(rt::AddressMode address, float scale, float factor_bound) {
    auto data = height_texture(address, scale, factor_bound);
    const std::uint32_t width = data->d.map.width, height = data->d.map.height;
    data->texels.resize(3 * std::size_t{width} * height);
    for (std::uint32_t j = 0; j < height; ++j)
        for (std::uint32_t i = 0; i < width; ++i) {
            const auto x = static_cast<float>(i), y = static_cast<float>(j);
            float* t = &data->texels[3 * (std::size_t{j} * width + i)];
            t[0] = std::sin(0.37f * x + 0.11f * y) + 0.25f * detail::unit(3 * (j * width + i));
            t[1] = std::cos(0.19f * x - 0.29f * y) + 0.25f * detail::unit(3 * (j * width + i) + 1);
            t[2] = std::sin(0.31f * x) * std::cos(0.23f * y) + 0.25f * detail::unit(3 * (j * width + i) + 2);
        }
    data->d.mode = rt::DisplacementMode::vector;
    data->d.map = {data->texels.data(), width, height, address, 3};
    return data;
}
// Binds the texture (and, with directions, welded_directions of the scene; in vector mode uv_tangents of the
// scene) to the scene's options.
void displace(Scene& scene, DisplacementData& data, bool directions) {
    if (data.d.mode == rt::DisplacementMode::vector) {
        data.tangents.resize(4 * (scene.vertices.size() / rt::mesh_vertex_floats));
        REQUIRE(rt::uv_tangents(scene.view(), data.tangents));
        data.d.tangents = data.tangents.data();
    }
    if (directions) {
        data.directions.resize(3 * (scene.vertices.size() / rt::mesh_vertex_floats));
        REQUIRE(rt::welded_directions(scene.view(), data.directions));
        data.d.directions = data.directions.data();
    }
    scene.options.displacement = &data.d;
}

// One displaced parity case: a factor-sweep grid whose uvs run from -0.7 to 1.8, so that both address modes
// matter, displaced by the texture.
struct DisplacedCase {
    Scene scene;
    std::unique_ptr<DisplacementData> data;
    rt::AddressMode address;
    bool directions;
};
// vector: an RGB vector map in tangent space (§8.7) instead of the height map, on a smaller grid (cells).
DisplacedCase displaced_case(unsigned max_factor, rt::Surface surface, rt::Pattern pattern,
                             rt::AddressMode address, bool directions, unsigned quad_every = 0,
                             bool vector = false, unsigned cells = 12) {
    const unsigned sweep_max = pattern == rt::Pattern::uniform ? rt::uniform_tables.max_factor : max_factor;
    DisplacedCase c{factor_sweep_grid(sweep_max, cells, surface, quad_every),
                    vector ? vector_texture(address, 0.02f, 0.004f) : height_texture(address, 0.02f, 0.004f),
                    address, directions};
    c.scene.options.pattern = pattern;
    for (std::size_t v = 0; v < c.scene.vertices.size(); v += rt::mesh_vertex_floats) {
        c.scene.vertices[v + 6] = 2.5f * c.scene.vertices[v + 6] - 0.7f;
        c.scene.vertices[v + 7] = 2.5f * c.scene.vertices[v + 7] - 0.7f;
    }
    displace(c.scene, *c.data, directions);
    return c;
}

// Runs the cases (one Dawn run per maximum factor) and checks each against the CPU: records, counts (grown
// factors), barycentrics and indices exactly, positions and normals within compare's bound.
// The largest normal component difference (compare bounds it by 1e-5).
double max_normal_error(const PipelineOutput& cpu, const PipelineOutput& gpu) {
    double normal_error = 0.0;
    for (std::size_t v = 0;
         v + vertex_words <= cpu.vertices.size() && v + vertex_words <= gpu.vertices.size();
         v += vertex_words)
        for (std::size_t k = 5; k < 8; ++k)
            normal_error =
                std::fmax(normal_error, std::fabs(static_cast<double>(bits_float(cpu.vertices[v + k])) -
                                                  bits_float(gpu.vertices[v + k])));
    return normal_error;
}
// Checks the GPU outputs of the cases (in order, from one batch) against the CPU.
void check_displaced_outputs(unsigned max_factor,
                             const std::vector<std::pair<const char*, DisplacedCase>>& cases,
                             const std::vector<PipelineOutput>& outputs) {
    REQUIRE(outputs.size() >= cases.size());
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const Scene& scene = cases[i].second.scene;
        const PipelineOutput cpu = run_cpu(tables_for(max_factor), scene);
        const PipelineOutput& gpu = outputs[i];
        const Comparison c = compare(cpu, gpu);
        const double normal_error = max_normal_error(cpu, gpu);
        // The growth is real: without it the counts are smaller.
        Scene plain = scene;
        plain.options.displacement = nullptr;
        const PipelineOutput undisplaced = run_cpu(tables_for(max_factor), plain);
        std::printf("%s, max %u, %s%s, %s, %s, %s directions: displaced grid of %u patches (%zu quads), %u "
                    "vertices (%u undisplaced); max position error %.2g, normal error %.2g\n",
                    backend_name(), max_factor,
                    scene.options.displacement->mode == rt::DisplacementMode::vector ? "vector, " : "",
                    pattern_name(scene.options.pattern), surface_name(scene.options.surface.surface),
                    cases[i].second.address == rt::AddressMode::repeat ? "repeat" : "clamp",
                    cases[i].second.directions ? "welded" : "no", scene.patch_count(), scene.quads.size() / 4,
                    cpu.total_vertices(), undisplaced.total_vertices(), c.max_position_error, normal_error);
        INFO(cases[i].first << ": " << c.first_difference);
        CHECK(c.equal());
        CHECK(cpu.total_vertices() > undisplaced.total_vertices());
    }
}
void check_displaced_parity(unsigned max_factor,
                            const std::vector<std::pair<const char*, DisplacedCase>>& cases) {
    std::vector<std::pair<const char*, Scene>> scenes;
    for (const auto& [work, c] : cases) scenes.emplace_back(work, c.scene);
    check_displaced_outputs(max_factor, cases, run_gpu_batch(max_factor, scenes));
}
} // namespace

TEST_CASE(
    "GPU displacement parity: a displaced grid equals the CPU's, CP and uniform, flat and PN, both address "
    "modes, with and without directions") {
    using rt::AddressMode, rt::Pattern, rt::Surface;
    std::vector<std::pair<const char*, DisplacedCase>> cases;
    cases.emplace_back("disp_cp_flat",
                       displaced_case(64, Surface::flat, Pattern::cp, AddressMode::repeat, true));
    cases.emplace_back("disp_cp_pn",
                       displaced_case(64, Surface::pn_triangles, Pattern::cp, AddressMode::clamp, false));
    cases.emplace_back("disp_uniform_pn", displaced_case(64, Surface::pn_triangles, Pattern::uniform,
                                                         AddressMode::repeat, true));
    cases.emplace_back("disp_uniform_flat",
                       displaced_case(64, Surface::flat, Pattern::uniform, AddressMode::clamp, false));
    check_displaced_parity(64, cases);
    cases.clear();
    cases.emplace_back("disp_cp_pn_256",
                       displaced_case(256, Surface::pn_triangles, Pattern::cp, AddressMode::repeat, false));
    check_displaced_parity(256, cases);
}

TEST_CASE("GPU displacement parity, quads: a displaced mixed grid equals the CPU's, CP, uniform and split") {
    using rt::AddressMode, rt::Pattern, rt::Surface;
    std::vector<std::pair<const char*, DisplacedCase>> cases;
    cases.emplace_back("disp_quads_cp",
                       displaced_case(64, Surface::pn_triangles, Pattern::cp, AddressMode::repeat, true, 3));
    cases.emplace_back("disp_quads_uniform",
                       displaced_case(64, Surface::flat, Pattern::uniform, AddressMode::clamp, false, 3));
    // Factors up to about 3 x 64: the split's leaves through both displaced vertex passes.
    cases.emplace_back("disp_quads_split", displaced_case(64, Surface::pn_triangles, Pattern::uniform_split,
                                                          AddressMode::repeat, true, 3));
    check_displaced_parity(64, cases);
}

TEST_CASE("Vulkan host: pipelines created up front or on first use give the same output, and a missing pass "
          "file is the constructor's error either way",
          "[vulkan]") {
    using rt::AddressMode, rt::Pattern, rt::Surface;
    // A displaced mixed grid runs six of the eight passes (setup, prefix sum, the displaced vertices and the
    // triangles of both kinds); the shared runner creates them on first use.
    const DisplacedCase c =
        displaced_case(64, Surface::pn_triangles, Pattern::cp, AddressMode::repeat, true, 3);
    const PipelineOutput on_first_use = run_vulkan(runner(64), c.scene);
    vulkan::Runner all_now(CTESS_SHADER_DIR, 64, vulkan::MeshPipeline::Creation::all_now);
    const PipelineOutput up_front = run_vulkan(all_now, c.scene);
    CHECK(on_first_use.patches == up_front.patches);
    CHECK(on_first_use.vertices == up_front.vertices);
    CHECK(on_first_use.indices == up_front.indices);
    CHECK(compare(run_cpu(rt::cp_tables_64, c.scene), on_first_use).equal());
    // A shader folder without the displaced quad pass: refused when the runner is made, not in a later run.
    const auto dir = std::filesystem::temp_directory_path() / "ctess_test_missing_pass";
    std::filesystem::remove_all(dir);
    std::filesystem::copy(CTESS_SHADER_DIR, dir);
    std::filesystem::remove(dir / "ctess_mesh_64_emit_displaced_quad_vertices.spv");
    for (const auto creation :
         {vulkan::MeshPipeline::Creation::all_now, vulkan::MeshPipeline::Creation::on_first_use})
        CHECK_THROWS_WITH(vulkan::Runner(dir.string(), 64, creation),
                          Catch::Contains("ctess_mesh_64_emit_displaced_quad_vertices.spv"));
    std::filesystem::remove_all(dir);
}

#if defined(CTESS_GPU_HAVE_MODELS)
TEST_CASE(
    "GPU displacement watertight: an icosphere with uv seams is closed with adjacency and cracks without") {
    // PN-AEN orders edge points by position, so the undisplaced surface is closed across the seams either
    // way.
    const auto data = height_texture(rt::AddressMode::repeat, 0.05f, 0.0f);
    std::vector<std::pair<const char*, Scene>> scenes; // per pattern: with adjacency, then without
    for (rt::Pattern pattern : {rt::Pattern::cp, rt::Pattern::uniform}) {
        Scene scene = split_normal_icosphere(2, rt::Surface::pn_aen, 6.0f, false);
        scene.options.pattern = pattern;
        displace(scene, *data, false);
        Scene without = scene;
        without.adjacency.clear();
        const bool uniform = pattern == rt::Pattern::uniform;
        scenes.emplace_back(uniform ? "disp_seam_uniform" : "disp_seam", scene);
        scenes.emplace_back(uniform ? "disp_seam_open_uniform" : "disp_seam_open", without);
    }
    const std::vector<PipelineOutput> outputs = run_gpu_batch(64, scenes);
    REQUIRE(outputs.size() == scenes.size());
    for (std::size_t i = 0; i < scenes.size(); i += 2) {
        const Scene &scene = scenes[i].second, &without = scenes[i + 1].second;
        const PipelineOutput &gpu = outputs[i], &open = outputs[i + 1];
        INFO(pattern_name(scene.options.pattern));
        const Comparison c = compare(run_cpu(rt::cp_tables_64, scene), gpu);
        const CrackReport r = crack_check(scene, gpu);
        const CrackReport o = crack_check(without, open);
        std::printf(
            "%s, max 64, %s, displaced PN-AEN icosphere with uv seams: %u vertices, %zu edge points, %zu "
            "cracks with adjacency, %zu without; max position error %.2g\n",
            backend_name(), pattern_name(scene.options.pattern), gpu.total_vertices(), r.edge_points,
            r.position_mismatches, o.position_mismatches, c.max_position_error);
        INFO(c.first_difference);
        CHECK(c.equal());
        CHECK(closed_by_position(gpu));
        CHECK(r.position_mismatches == 0);
        CHECK(r.unmatched_points == 0);
        CHECK_FALSE(closed_by_position(open));
        CHECK(o.position_mismatches > 0);
        const Comparison oc = compare(run_cpu(rt::cp_tables_64, without), open);
        INFO(oc.first_difference);
        CHECK(oc.equal());
    }
}
#endif

TEST_CASE("GPU displacement bad input: a NaN scale is an error") {
    Scene scene = factor_sweep_grid(64, 4, rt::Surface::flat);
    const auto data = height_texture(rt::AddressMode::repeat, 0.02f, 0.0f);
    displace(scene, *data, false);
    // A NaN scale: the CPU's bad_option, and the hosts refuse it with their reason (Vulkan:
    // displacement_valid; the JS host: its own check, in node's message).
    data->d.scale = std::nanf("");
    CHECK_THROWS_WITH(run_gpu(64, scene, "disp_nan"),
                      Catch::Contains("Displacement is not valid") || Catch::Contains("displacement: scale"));
}

TEST_CASE(
    "Vulkan host, displacement: a HeightFunction and texels or data that the params do not describe are "
    "errors, and an empty map is the CPU's output",
    "[vulkan]") {
    Scene scene = factor_sweep_grid(64, 4, rt::Surface::flat);
    const auto data = height_texture(rt::AddressMode::repeat, 0.02f, 0.0f);
    displace(scene, *data, false);
    vulkan::Runner& gpu = runner(64);
    // A HeightFunction is CPU code.
    rt::Displacement function = data->d;
    function.function = [](const void*, float u, float v) { return u * v; };
    rt::PipelineOptions options = scene.options;
    options.displacement = &function;
    CHECK(rt::gpu::gpu_options_status(scene.view(), options) == rt::PipelineStatus::bad_option);
    CHECK_THROWS_AS(gpu.tessellate(scene.view(), options), vulkan::Error);
    CHECK_THROWS_WITH(gpu.tessellate(scene.view(), pipeline_params(scene), {}, &function),
                      Catch::Contains("HeightFunction"));
    // Vector displacement (docs/algorithm.md §8.7) runs from a 3-channel map and tangents; a VectorFunction
    // (CPU code), a map of another channel count, missing tangents, and params whose vector flag is not the
    // Displacement's mode are refused before anything is uploaded.
    std::vector<float> tangents(4 * std::size_t{scene.view().vertex_count}, 0.0f);
    const float rgb[3] = {0.5f, 0.5f, 0.5f};
    rt::Displacement vector = data->d;
    vector.mode = rt::DisplacementMode::vector;
    vector.map = {rgb, 1, 1, rt::AddressMode::repeat, 3};
    vector.tangents = tangents.data();
    REQUIRE(rt::displacement_valid(vector));
    options.displacement = &vector;
    CHECK(rt::gpu::gpu_options_status(scene.view(), options) == rt::PipelineStatus::ok);
    const auto vector_params = rt::gpu::pipeline_params(scene.view(), options);
    CHECK((vector_params[rt::gpu::param_word::displacement_flags] & rt::gpu::displacement_flag::vector) != 0);
    rt::Displacement vector_function = vector;
    vector_function.vector_function = [](const void*, float u, float v) { return rt::Vec3{u, v, 0.0f}; };
    rt::Displacement grey_map = vector; // a one-channel map read as vectors
    grey_map.map.channels = 1;
    rt::Displacement no_tangents = vector;
    no_tangents.tangents = nullptr;
    for (const rt::Displacement* bad : {&vector_function, &grey_map, &no_tangents}) {
        options.displacement = bad;
        CHECK(rt::gpu::gpu_options_status(scene.view(), options) == rt::PipelineStatus::bad_option);
        CHECK_THROWS_AS(gpu.tessellate(scene.view(), options), vulkan::Error);
        CHECK_THROWS_AS(gpu.tessellate(scene.view(), vector_params, {}, bad), vulkan::Error);
    }
    CHECK_THROWS_WITH(gpu.tessellate(scene.view(), vector_params, {}, &vector_function),
                      Catch::Contains("VectorFunction"));
    CHECK_THROWS_WITH(gpu.tessellate(scene.view(), vector_params, {}, &data->d),
                      Catch::Contains("params name vector displacement but the Displacement is scalar"));
    CHECK_THROWS_WITH(gpu.tessellate(scene.view(), pipeline_params(scene), {}, &vector),
                      Catch::Contains("lack its flag"));
    // An RGB texture larger than binding 3 allows (3 floats a texel): refused before anything is uploaded.
    rt::Displacement huge_vector = vector;
    huge_vector.map.width = 32768;
    huge_vector.map.height = 16384;
    options.displacement = &huge_vector;
    CHECK_THROWS_WITH(gpu.tessellate(scene.view(), options), Catch::Contains("RGB texels"));
    // Params whose width x height is not the map's texel count.
    auto params = pipeline_params(scene);
    params[rt::gpu::param_word::height_map_width] += 1;
    CHECK_THROWS_WITH(gpu.tessellate(scene.view(), params, {}, &data->d), Catch::Contains("does not match"));
    // Params that displace without a Displacement, or name directions it does not have.
    params = pipeline_params(scene);
    CHECK_THROWS_AS(gpu.tessellate(scene.view(), params), vulkan::Error);
    params[rt::gpu::param_word::displacement_flags] |= rt::gpu::displacement_flag::directions;
    CHECK_THROWS_WITH(gpu.tessellate(scene.view(), params, {}, &data->d), Catch::Contains("directions"));
    // A texture larger than binding 3 allows: refused before anything is read or uploaded.
    rt::Displacement huge = data->d;
    huge.map.width = huge.map.height = 65536;
    options.displacement = &huge;
    CHECK_THROWS_WITH(gpu.tessellate(scene.view(), options), Catch::Contains("maxStorageBufferRange"));
    // An empty map samples 0 (height = scale * offset), as on the CPU.
    rt::Displacement empty = data->d;
    empty.map.texels = nullptr;
    Scene flat = scene;
    flat.options.displacement = &empty;
    const Comparison c = compare(run_cpu(rt::cp_tables_64, flat), run_gpu(64, flat, "disp_empty"));
    INFO(c.first_difference);
    CHECK(c.equal());
}

#if defined(CTESS_GPU_HAVE_MODELS)
TEST_CASE("GPU displacement watertight, quads: a faceted mixed torus (every edge a uv seam) is closed with "
          "adjacency and opens without") {
    Scene scene = faceted_mixed_torus(rt::Surface::pn_aen);
    const auto data = height_texture(rt::AddressMode::repeat, 0.05f, 0.0f);
    displace(scene, *data, false);
    Scene without = scene;
    without.adjacency.clear();
    const std::vector<PipelineOutput> outputs =
        run_gpu_batch(64, {{"disp_torus", scene}, {"disp_torus_open", without}});
    REQUIRE(outputs.size() == 2);
    const PipelineOutput &gpu = outputs[0], &open = outputs[1];
    const Comparison c = compare(run_cpu(rt::cp_tables_64, scene), gpu);
    std::printf("%s, max 64, CP, displaced PN-AEN faceted mixed torus (%zu quads): %u vertices; max position "
                "error %.2g\n",
                backend_name(), scene.quads.size() / 4, gpu.total_vertices(), c.max_position_error);
    INFO(c.first_difference);
    CHECK(c.equal());
    CHECK(closed_by_position(gpu));
    CHECK_FALSE(closed_by_position(open));
}
#endif

// ---- vector displacement (docs/algorithm.md §8.7): RGB vectors in tangent space, its own two passes ----
// One batch (one Dawn run: its two passes compile once): small grids against the CPU, then uv seams.
TEST_CASE(
    "GPU vector displacement: grids equal the CPU's (CP and uniform, flat and PN, triangles and quads), "
    "uv seams are closed with adjacency and crack without") {
    using rt::AddressMode, rt::Pattern, rt::Surface;
    std::vector<std::pair<const char*, DisplacedCase>> cases;
    cases.emplace_back("vec_cp_flat",
                       displaced_case(64, Surface::flat, Pattern::cp, AddressMode::repeat, true, 0, true, 8));
    cases.emplace_back("vec_uniform_pn", displaced_case(64, Surface::pn_triangles, Pattern::uniform,
                                                        AddressMode::clamp, false, 0, true, 8));
    cases.emplace_back("vec_quads_cp", displaced_case(64, Surface::pn_triangles, Pattern::cp,
                                                      AddressMode::clamp, true, 3, true, 8));
    cases.emplace_back("vec_quads_uniform", displaced_case(64, Surface::flat, Pattern::uniform,
                                                           AddressMode::repeat, false, 3, true, 8));
    std::vector<std::pair<const char*, Scene>> scenes;
    for (const auto& [work, c] : cases) scenes.emplace_back(work, c.scene);
#if defined(CTESS_GPU_HAVE_MODELS)
    // An icosphere of 20 uv charts (PN-AEN, shared normals: the undisplaced surface is closed either way) and
    // the faceted mixed torus (every edge a uv seam and a hard edge), with their tangents from the uvs: a
    // vector that depends on uv and a frame per vertex copy, so only the dominant vertices' frames and uvs
    // keep them closed. Without adjacency (the control) every vertex is its own dominant vertex.
    Scene sphere = split_normal_icosphere(1, Surface::pn_aen, 12.0f, false);
    Scene torus = faceted_mixed_torus(Surface::pn_aen);
    const auto sphere_data = vector_texture(AddressMode::repeat, 0.05f, 0.0f);
    const auto torus_data = vector_texture(AddressMode::repeat, 0.05f, 0.0f);
    displace(sphere, *sphere_data, false);
    displace(torus, *torus_data, false);
    Scene sphere_open = sphere, torus_open = torus;
    sphere_open.adjacency.clear();
    torus_open.adjacency.clear();
    const std::size_t seams = scenes.size();
    scenes.emplace_back("vec_seam", sphere);
    scenes.emplace_back("vec_seam_open", sphere_open);
    scenes.emplace_back("vec_torus", torus);
    scenes.emplace_back("vec_torus_open", torus_open);
#endif
    const std::vector<PipelineOutput> outputs = run_gpu_batch(64, scenes);
    REQUIRE(outputs.size() == scenes.size());
    check_displaced_outputs(64, cases, outputs);
#if defined(CTESS_GPU_HAVE_MODELS)
    for (std::size_t i = seams; i < scenes.size(); i += 2) {
        const Scene &scene = scenes[i].second, &without = scenes[i + 1].second;
        const PipelineOutput &gpu = outputs[i], &open = outputs[i + 1];
        INFO(scenes[i].first);
        const PipelineOutput cpu = run_cpu(rt::cp_tables_64, scene);
        const Comparison c = compare(cpu, gpu);
        std::printf("%s, max 64, CP, vector-displaced PN-AEN %s (%zu quads): %u vertices; max position error "
                    "%.2g, normal error %.2g; closed %d with adjacency, %d without\n",
                    backend_name(), scenes[i].first, scene.quads.size() / 4, gpu.total_vertices(),
                    c.max_position_error, max_normal_error(cpu, gpu), closed_by_position(gpu) ? 1 : 0,
                    closed_by_position(open) ? 1 : 0);
        INFO(c.first_difference);
        CHECK(c.equal());
        CHECK(closed_by_position(gpu));
        CHECK_FALSE(closed_by_position(open));
        const Comparison oc = compare(run_cpu(rt::cp_tables_64, without), open);
        INFO(oc.first_difference);
        CHECK(oc.equal());
    }
#endif
}

// The second WebGPU implementation (Dawn's Vulkan backend on SwiftShader) runs only this case: one scene per
// feature, each against the CPU, in one node run (tests/gpu/CMakeLists.txt). The other backends run it too.
TEST_CASE("GPU second implementation: CP PN, uniform Phong, quads, PN-AEN, displacement, vector "
          "displacement and splitting, each against the CPU",
          "[second-implementation]") {
    std::vector<std::pair<const char*, Scene>> scenes;
    scenes.emplace_back("one_cp", factor_sweep_grid(64, 24, rt::Surface::pn_triangles));
    Scene uniform = factor_sweep_grid(rt::uniform_tables.max_factor, 24, rt::Surface::phong);
    uniform.options.pattern = rt::Pattern::uniform;
    scenes.emplace_back("one_uniform", uniform);
    scenes.emplace_back("one_quads", factor_sweep_grid(64, 24, rt::Surface::pn_triangles, 4));
#if defined(CTESS_GPU_HAVE_MODELS)
    scenes.emplace_back("one_aen_quads", faceted_mixed_torus(rt::Surface::pn_aen));
#endif
    // Displacement, triangles and quads (both displaced passes), welded directions.
    const DisplacedCase displaced =
        displaced_case(64, rt::Surface::pn_triangles, rt::Pattern::cp, rt::AddressMode::repeat, true, 3);
    scenes.emplace_back("one_displaced", displaced.scene);
    // Vector displacement (§8.7) on triangles: SwiftShader compiles the vector quad pass for about a minute
    // on this 2-core machine; the other backends run the quads ("GPU vector displacement").
    const DisplacedCase vector = displaced_case(64, rt::Surface::pn_triangles, rt::Pattern::cp,
                                                rt::AddressMode::repeat, true, 0, true, 8);
    scenes.emplace_back("one_vector_displaced", vector.scene);
    // Splitting: a small sweep above N with quads (depths 0 to 2) and the strip (depth 3).
    Scene split = factor_sweep_grid(300, 4, rt::Surface::pn_triangles, 2);
    split.options.pattern = rt::Pattern::uniform_split;
    scenes.emplace_back("one_split", split);
    scenes.emplace_back("one_split_strip", split_strip(rt::Surface::flat));
    const std::vector<PipelineOutput> outputs = run_gpu_batch(64, scenes);
    REQUIRE(outputs.size() == scenes.size());
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        const auto& [work, scene] = scenes[i];
        const PipelineOutput& gpu = outputs[i];
        const PipelineOutput cpu = run_cpu(rt::cp_tables_64, scene);
        const Comparison c = compare(cpu, gpu);
        std::printf(
            "%s, %s: %u patches (%zu quads), %u vertices; max position error %.2g, normal error %.2g\n",
            backend_name(), work, scene.patch_count(), scene.quads.size() / 4, gpu.total_vertices(),
            c.max_position_error, max_normal_error(cpu, gpu));
        INFO(work << ": " << c.first_difference);
        CHECK(c.equal());
    }
}

// The welded output on the GPU (docs/shaders.md, "Welded output"): setup_welded's edges, patch records and
// totals, and emit_welded_mesh's vertices and indices, bit for bit (positions within the bound).
namespace {
PipelineOutput run_gpu_welded(unsigned max_factor, const Scene& scene, const char* name,
                              RunLimits limits = {}) {
    if (backend() == Backend::vulkan) return run_vulkan_welded(runner(max_factor), scene, limits);
    std::string work = std::string("welded_") + name; // a file name in a shell command: no spaces
    std::replace(work.begin(), work.end(), ' ', '_');
    return run_dawn_welded(node_command(), CTESS_RUN_WGSL, CTESS_SHADER_DIR, max_factor,
                           {{&scene, dawn_work_file(max_factor, work.c_str())}}, limits)
        .front();
}
void check_welded(unsigned max_factor, const Scene& scene, const char* name, RunLimits limits = {}) {
    const PipelineOutput cpu = run_cpu_welded(tables_for(max_factor), scene);
    const PipelineOutput gpu = run_gpu_welded(max_factor, scene, name, limits);
    std::printf(
        "%s, max %u, %s, %s, welded %s: %u patches, %u vertices, %u triangles; GPU %.1f ms, CPU %.1f ms\n",
        backend_name(), max_factor, pattern_name(scene.options.pattern),
        surface_name(scene.options.surface.surface), name, scene.patch_count(), cpu.total_vertices(),
        cpu.total_triangles(), gpu.milliseconds, cpu.milliseconds);
    const Comparison c = compare(cpu, gpu);
    INFO(name << ": " << c.first_difference);
    CHECK(c.equal());
}
} // namespace

TEST_CASE(
    "GPU welded output: the CPU's weld bit for bit, CP and uniform, triangles and quads, every surface") {
    for (const rt::Pattern pattern : {rt::Pattern::cp, rt::Pattern::uniform}) {
        Scene torus = torus_scene(pipeline_fixtures::torus(24, 10, pipeline_fixtures::Faces::mixed),
                                  rt::Surface::pn_triangles);
        torus.options.pattern = pattern;
        check_welded(64, torus, "mixed torus");
        Scene sweep = factor_sweep_grid(pattern == rt::Pattern::uniform ? rt::uniform_tables.max_factor : 64,
                                        12, rt::Surface::phong, 4);
        sweep.options.pattern = pattern;
        check_welded(64, sweep, "sweep grid");
    }
}

namespace {
// Faces the weld's general path takes (docs/algorithm.md §7.4): a triangle and a quad with a repeated corner,
// a culled triangle (an index past the vertices) and a mesh vertex no face reaches, added to a scene.
void add_awkward_faces(Scene& s, bool faces = true) {
    const auto n = static_cast<std::uint32_t>(s.vertices.size() / rt::mesh_vertex_floats);
    if (faces) s.indices.insert(s.indices.end(), {0, 0, 5, 7, 7, 7, 1, 2, n + 7, 9, 3, 9});
    if (faces && !s.quads.empty()) s.quads.insert(s.quads.end(), {3, 3, 4, 10, 6, 11, 6, 12});
    const float* v = &s.vertices[0];
    detail::push_vertex(s, {v[0] + 0.25f, v[1] - 0.5f, v[2] + 0.125f}, {0, 0, 1}, 0.3f,
                        0.7f); // reached by no face
}
// The welded output's edges by index: how many edges of the kept triangles are used once, twice, more.
std::array<std::size_t, 3> edge_uses(const PipelineOutput& out) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> uses;
    for (std::size_t t = 0; t + 3 <= out.indices.size(); t += 3)
        for (unsigned k = 0; k < 3; ++k) {
            const std::uint32_t a = out.indices[t + k], b = out.indices[t + (k + 1) % 3];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    std::array<std::size_t, 3> count{};
    for (const auto& [edge, n] : uses) ++count[std::min<std::size_t>(n, 3) - 1];
    return count;
}
} // namespace

TEST_CASE(
    "GPU welded output: a closed mixed torus stays closed and 2-manifold by index, both maximum factors") {
    for (const unsigned max_factor : {64u, 256u}) {
        Scene torus = torus_scene(pipeline_fixtures::torus(24, 10, pipeline_fixtures::Faces::mixed),
                                  max_factor == 64 ? rt::Surface::phong : rt::Surface::flat);
        const PipelineOutput cpu = run_cpu_welded(tables_for(max_factor), torus);
        const PipelineOutput gpu =
            run_gpu_welded(max_factor, torus, max_factor == 64 ? "weld_closed" : "weld_closed_256");
        const Comparison c = compare(cpu, gpu);
        INFO(c.first_difference);
        CHECK(c.equal());
        const std::array<std::size_t, 3> uses = edge_uses(gpu);
        CHECK(uses[0] == 0); // no open edge
        CHECK(uses[2] == 0); // no edge of three triangles
        CHECK(uses[1] > 30 * torus.patch_count());
    }
}

TEST_CASE("GPU welded output: repeated corners, culled faces, a vertex no face reaches, kept degenerate "
          "triangles, 7 workgroups a dispatch") {
    std::vector<std::pair<const char*, Scene>> scenes;
    for (const rt::Pattern pattern : {rt::Pattern::cp, rt::Pattern::uniform})
        for (const bool keep : {false, true}) {
            Scene s = factor_sweep_grid(pattern == rt::Pattern::uniform ? rt::uniform_tables.max_factor : 64,
                                        8, keep ? rt::Surface::pn_triangles : rt::Surface::flat, 3);
            s.options.pattern = pattern;
            s.options.weld.keep_degenerate = keep;
            add_awkward_faces(s);
            check_welded(64, s,
                         pattern == rt::Pattern::cp ? (keep ? "awkward_cp_keep" : "awkward_cp")
                                                    : (keep ? "awkward_uniform_keep" : "awkward_uniform"),
                         RunLimits{7});
        }
}

TEST_CASE("GPU welded output: displaced by a height and a vector map, with an unreached vertex") {
    using rt::AddressMode, rt::Pattern, rt::Surface;
    for (const bool vector : {false, true}) {
        // displaced_case's grid and maps, with the awkward faces and the unreached vertex added before the
        // directions (and tangents) are made for every vertex.
        DisplacedCase c{factor_sweep_grid(64, 12, Surface::pn_triangles, 3),
                        vector ? vector_texture(AddressMode::repeat, 0.02f, 0.004f)
                               : height_texture(AddressMode::repeat, 0.02f, 0.004f),
                        AddressMode::repeat, true};
        for (std::size_t v = 0; v < c.scene.vertices.size(); v += rt::mesh_vertex_floats) {
            c.scene.vertices[v + 6] = 2.5f * c.scene.vertices[v + 6] - 0.7f;
            c.scene.vertices[v + 7] = 2.5f * c.scene.vertices[v + 7] - 0.7f;
        }
        add_awkward_faces(c.scene, !vector); // the uv tangents of vector mode need whole faces
        displace(c.scene, *c.data, true);
        check_welded(64, c.scene, vector ? "weld_vector" : "weld_height");
    }
}

#if defined(CTESS_GPU_HAVE_MODELS)
TEST_CASE("GPU welded output: PN-AEN on the split-normal icosphere (uv seams and hard edges)") {
    for (const rt::Pattern pattern : {rt::Pattern::cp, rt::Pattern::uniform})
        check_welded(64, aen_scene(64, rt::Surface::pn_aen, pattern),
                     pattern == rt::Pattern::cp ? "weld_aen" : "weld_aen_uniform");
}
#endif

// The split pattern's weld, by one sort over the mesh (docs/shaders.md, "Welded output", "The split
// pattern"): splits of depth 0 to 3 with quads, a closed mixed torus (closed and 2-manifold by index),
// awkward faces with kept degenerate triangles, and PN-AEN across uv seams and hard edges.
TEST_CASE("GPU welded output: the split pattern, depths 0 to 3, quads, a closed torus, awkward faces") {
    Scene sweep = factor_sweep_grid(300, 4, rt::Surface::pn_triangles, 2);
    sweep.options.pattern = rt::Pattern::uniform_split;
    check_welded(64, sweep, "weld_split_sweep");
    check_welded(64, split_strip(rt::Surface::flat), "weld_split_strip", RunLimits{7});
    Scene torus =
        torus_scene(pipeline_fixtures::torus(24, 10, pipeline_fixtures::Faces::mixed), rt::Surface::phong);
    torus.options.pattern = rt::Pattern::uniform_split;
    const PipelineOutput cpu = run_cpu_welded(tables_for(64), torus);
    CHECK(split_depths(torus, run_cpu(tables_for(64), torus))[1] > 0); // some patches split
    const PipelineOutput gpu = run_gpu_welded(64, torus, "weld_split_torus");
    const Comparison c = compare(cpu, gpu);
    INFO(c.first_difference);
    CHECK(c.equal());
    const std::array<std::size_t, 3> uses = edge_uses(gpu);
    CHECK(uses[0] == 0);
    CHECK(uses[2] == 0);
    for (const bool keep : {false, true}) {
        Scene s = factor_sweep_grid(200, 6, keep ? rt::Surface::pn_triangles : rt::Surface::flat, 3);
        s.options.pattern = rt::Pattern::uniform_split;
        s.options.weld.keep_degenerate = keep;
        add_awkward_faces(s);
        check_welded(64, s, keep ? "weld_split_awkward_keep" : "weld_split_awkward", RunLimits{5});
    }
#if defined(CTESS_GPU_HAVE_MODELS)
    check_welded(64, aen_scene(64, rt::Surface::pn_aen, rt::Pattern::uniform_split), "weld_aen_split");
#endif
}

TEST_CASE("Vulkan host: the unwelded entry point refuses welded params, an error, not output", "[vulkan]") {
    Scene s = factor_sweep_grid(64, 4, rt::Surface::flat);
    CHECK_THROWS_WITH(runner(64).tessellate(s.view(), rt::gpu::weld_params(s.view(), s.options)),
                      Catch::Contains("tessellate_welded"));
}

// The welded output on the second WebGPU implementation too (Dawn's Vulkan backend on SwiftShader): one run
// of a mixed grid (CP, PN, repeated corners, a culled face, a vertex no face reaches).
TEST_CASE("GPU second implementation: the welded output against the CPU's", "[second-implementation]") {
    Scene s = factor_sweep_grid(64, 8, rt::Surface::pn_triangles, 3);
    add_awkward_faces(s);
    check_welded(64, s, "second_welded");
}

// Software drivers end an invocation's loops after 65,535 iterations in all (llvmpipe, silently): the count
// and triangle passes run a patch per workgroup in batches, so 16 patches of 2,145 slots through one
// workgroup a dispatch weld as the CPU does; a mesh with a patch past rt::gpu::weld_max_patch_slots (past one
// workgroup's sort) is welded by one sort over the mesh, as the split pattern is.
TEST_CASE("GPU welded output: one workgroup a dispatch for 16 large patches, a patch past the slot limit "
          "welded by the sort over the mesh") {
    Scene big = repeated_big_triangle(16);
    check_welded(64, big, "weld_batches", RunLimits{1});
    // Max 256: the (256, 256, 256) pattern has more slots than the weld takes in one workgroup.
    Scene one = repeated_big_triangle(2);
    REQUIRE(run_cpu(rt::cp_tables_256, one).total_vertices() > 2 * rt::gpu::weld_max_patch_slots);
    check_welded(256, one, "weld_sorted_cp", RunLimits{3});
    // With a quad, a triangle and a quad with repeated corners, a culled triangle and a vertex no face
    // reaches; PN (positions from the last patch that reaches a point).
    Scene mixed = repeated_big_triangle(2);
    mixed.options.surface = {rt::Surface::pn_triangles, 0.0f};
    detail::push_vertex(mixed, {100.0f, 100.0f, 1.5f}, {0.0f, 0.6f, 0.8f}, 1.0f, 1.0f);
    detail::push_vertex(mixed, {0.0f, -50.0f, 1.0f}, {0, 0, 1}, 0.5f, 0.5f); // reached by no face
    mixed.indices.insert(mixed.indices.end(), {0, 0, 1, 1, 2, 99, 2, 1, 3});
    mixed.quads = {0, 1, 3, 2, 1, 1, 3, 2};
    const PipelineOutput unwelded = run_cpu(rt::cp_tables_256, mixed);
    std::uint32_t largest = 0;
    for (std::size_t p = 0; p < mixed.patch_count(); ++p) {
        rt::PatchRecord r;
        std::memcpy(static_cast<void*>(&r), &unwelded.patches[p * (sizeof r / 4)], sizeof r);
        largest = std::max(largest, r.vertex_count);
    }
    REQUIRE(largest > rt::gpu::weld_max_patch_slots);
    check_welded(256, mixed, "weld_sorted_mixed");
    // Just under the limit at max 256: the eye moved away until the patch has at most 16,384 slots.
    Scene under = repeated_big_triangle(1);
    for (float z = 1.0f;; z *= 1.25f) {
        under.options.dice.eye = {0.0f, 30.0f, z};
        if (run_cpu(rt::cp_tables_256, under).total_vertices() <= rt::gpu::weld_max_patch_slots) break;
    }
    INFO("slots " << run_cpu(rt::cp_tables_256, under).total_vertices());
    CHECK(run_cpu(rt::cp_tables_256, under).total_vertices() > rt::gpu::weld_max_patch_slots / 2);
    check_welded(256, under, "weld_large_patch");
}
