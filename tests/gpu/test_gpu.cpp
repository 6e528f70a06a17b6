// The generated shaders against the CPU mesh pipeline, on one backend per build of this file:
// CTESS_GPU_VULKAN (GLSL -> SPIR-V on lavapipe) or CTESS_GPU_DAWN (WGSL on Dawn: its GLES backend on
// llvmpipe, or its Vulkan backend on SwiftShader, as tests/gpu/CMakeLists.txt sets the environment). Both
// maximum factors run in every build. No test skips: a missing driver or node module is a failure.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <ctess/runtime/cp/table_set.hpp>

#include "gpu_checks.hpp"
#include "gpu_pipeline.hpp"

using namespace ctess;
using namespace ctess::gpu_test;

namespace {

const rt::CpTableSet& tables_for(unsigned max_factor) {
    return max_factor == 64 ? rt::cp_tables_64 : rt::cp_tables_256;
}

#if defined(CTESS_GPU_VULKAN)
const char* const backend_name = "Vulkan (lavapipe)";
} // namespace
// Under the asan-ubsan preset LeakSanitizer finds 128 bytes that lavapipe reallocs and never frees, in a
// module the Vulkan loader has unloaded by exit, so no suppression can name it: leak checks are off for the
// Vulkan tests only. (A hook ASan reads at start-up; without ASan nothing calls it.)
extern "C" const char* __asan_default_options() {
    return "detect_leaks=0";
}
namespace {
VkCompute& device() {
    static std::unique_ptr<VkCompute> vk = std::make_unique<VkCompute>();
    return *vk;
}
PipelineOutput run_gpu(unsigned max_factor, const Scene& scene, const char*, RunLimits limits = {}) {
    return run_vulkan(device(), CTESS_SHADER_DIR, max_factor, scene, limits);
}
#elif defined(CTESS_GPU_DAWN)
const char* const backend_name = CTESS_GPU_BACKEND_NAME;
PipelineOutput run_gpu(unsigned max_factor, const Scene& scene, const char* name, RunLimits limits = {}) {
    std::string work = CTESS_WORK_DIR;
    work += "/";
    work += CTESS_GPU_WORK_PREFIX; // ctest runs the variants in parallel
    work += name;
    work += "_";
    work += std::to_string(max_factor);
    return run_dawn(CTESS_DAWN_ENV CTESS_NODE, CTESS_RUN_WGSL, CTESS_SHADER_DIR, max_factor, scene, work,
                    limits);
}
#else
#error "define CTESS_GPU_VULKAN or CTESS_GPU_DAWN"
#endif

const char* surface_name(rt::Surface s) {
    return s == rt::Surface::flat           ? "flat"
           : s == rt::Surface::pn_triangles ? "PN"
           : s == rt::Surface::pn_aen       ? "PN-AEN"
                                            : "Phong";
}

const char* pattern_name(rt::Pattern p) {
    return p == rt::Pattern::cp ? "CP" : "uniform";
}

// The uniform pattern's factors sweep [1, N] of the configured uniform tables, which every blob carries.
void check_parity(unsigned max_factor, rt::Surface surface, rt::Pattern pattern = rt::Pattern::cp) {
    const unsigned sweep_max = pattern == rt::Pattern::uniform ? rt::uniform_tables.max_factor : max_factor;
    Scene scene = factor_sweep_grid(sweep_max, 24, surface);
    scene.options.pattern = pattern;
    REQUIRE(scene.patch_count() >= 1000);
    const PipelineOutput cpu = run_cpu(tables_for(max_factor), scene);
    const char* work =
        pattern == rt::Pattern::uniform ? "parity_uniform" : "parity"; // ctest runs tests in parallel
    const PipelineOutput gpu = run_gpu(max_factor, scene, work);
    // A second run: the driver's shader cache is warm, so its time is the dispatch itself. Same bits, too.
    const PipelineOutput again = run_gpu(max_factor, scene, work);
    CHECK(again.patches == gpu.patches);
    CHECK(again.vertices == gpu.vertices);
    CHECK(again.indices == gpu.indices);
    const Comparison c = compare(cpu, gpu);
    std::printf("%s, max %u, %s, %s: %u patches, %u vertices, %u triangles; GPU %.1f ms (first run %.1f ms), "
                "CPU %.1f ms; max position error %.2g\n",
                backend_name, max_factor, pattern_name(pattern), surface_name(surface), scene.patch_count(),
                cpu.total_vertices(), cpu.total_triangles(), again.milliseconds, gpu.milliseconds,
                cpu.milliseconds, c.max_position_error);
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
        backend_name, max_factor, pattern_name(pattern), surface_name(surface), scene.patch_count(),
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

TEST_CASE("GPU PN-AEN: split-normal icosphere with adjacency, CP and uniform, max 64 and 256: the CPU's "
          "output, watertight") {
    for (unsigned max_factor : {64u, 256u}) {
        for (rt::Pattern pattern : {rt::Pattern::cp, rt::Pattern::uniform}) {
            const Scene scene = aen_scene(max_factor, rt::Surface::pn_aen, pattern);
            INFO("max " << max_factor << ", " << pattern_name(pattern));
            REQUIRE(scene.adjacency.size() == 12 * std::size_t{scene.patch_count()});
            const PipelineOutput gpu =
                run_gpu(max_factor, scene, pattern == rt::Pattern::uniform ? "aen_uniform" : "aen");
            const PipelineOutput cpu = run_cpu(tables_for(max_factor), scene);
            const Comparison c = compare(cpu, gpu);
            const CrackReport r = crack_check(scene, gpu);
            std::printf(
                "%s, max %u, %s, PN-AEN split-normal icosphere: %u patches, %u vertices, %zu shared "
                "edges, %zu edge points, %zu cracks; max position error %.2g, %zu of %u position words "
                "differ in bits from the CPU\n",
                backend_name, max_factor, pattern_name(pattern), scene.patch_count(), cpu.total_vertices(),
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
    std::printf("%s, max 64, CP, PN split-normal icosphere: %zu of %zu edge points crack\n", backend_name,
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
