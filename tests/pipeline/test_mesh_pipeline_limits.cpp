// The mesh pipeline's limits and tampered records (runtime/include/ctess/runtime/pipeline/mesh_pipeline.hpp):
// totals are summed in 64 bits and a mesh past the GPU pipeline's limits is refused with its own status,
// never wrapped; emit_mesh refuses records that setup_patches did not produce and then writes nothing.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <ctess/cp/pattern.hpp>
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>

#include "pipeline_output.hpp"

using namespace ctess;
using rt::PipelineStatus;

namespace {

// The procedural generator's counts of the (max, max, max) pattern, in the pipeline's provoking layout.
Counts full_pattern(unsigned max) {
    const float f = static_cast<float>(max);
    return cp::pattern_counts(f, f, f, cp::PatternOptions{{}, max});
}

} // namespace

TEST_CASE("mesh pipeline limits: the boundaries of check_pipeline_size") {
    CHECK(rt::max_pipeline_patches == 65535u * 64u);
    CHECK(rt::max_pipeline_vertices * 10 <= 0xFFFFFFFFu);
    CHECK((rt::max_pipeline_vertices + 1) * 10 > 0xFFFFFFFFu);
    CHECK(rt::max_pipeline_triangles * 3 <= 0xFFFFFFFFu);
    CHECK((rt::max_pipeline_triangles + 1) * 3 > 0xFFFFFFFFu);
    const std::uint64_t p = rt::max_pipeline_patches, v = rt::max_pipeline_vertices,
                        t = rt::max_pipeline_triangles;
    CHECK(rt::check_pipeline_size(p, v, t) == PipelineStatus::ok);
    CHECK(rt::check_pipeline_size(p + 1, v, t) == PipelineStatus::too_many_patches);
    CHECK(rt::check_pipeline_size(p, v + 1, t) == PipelineStatus::too_many_vertices);
    CHECK(rt::check_pipeline_size(p, v, t + 1) == PipelineStatus::too_many_triangles);
    // Distinct messages naming each limit.
    CHECK(std::strstr(rt::pipeline_status_message(PipelineStatus::too_many_patches), "65,535 x 64"));
    CHECK(std::strstr(rt::pipeline_status_message(PipelineStatus::too_many_vertices), "429,496,729"));
    CHECK(std::strstr(rt::pipeline_status_message(PipelineStatus::too_many_triangles), "1,431,655,765"));
}

TEST_CASE("mesh pipeline limits: 65536 patches at factor 256 are refused and never wrapped") {
    // 65,536 x 65,536 triangles is exactly 2^32: u32 totals used to wrap to 0 triangles. The vertex total
    // (65,538 a patch) passes its limit first, at patch floor(429,496,729 / 65,538) = 6,553: setup stops
    // there.
    const gpu_test::Scene scene = gpu_test::repeated_big_triangle(65536);
    const rt::MeshView mesh = scene.view();
    std::vector<rt::PatchRecord> rec(mesh.triangle_count);
    rt::PipelineTotals totals{7, 7};
    CHECK(rt::setup_patches(rt::cp_tables_256, mesh, scene.options, rec, totals) ==
          PipelineStatus::too_many_vertices);
    CHECK(totals.vertices == 7); // unchanged
    CHECK(totals.triangles == 7);
    const Counts full = full_pattern(256);
    REQUIRE(full.triangles == 256u * 256u); // N^2 at equal powers of two (docs/algorithm.md)
    REQUIRE(rec[0].vertex_count == full.vertices);
    REQUIRE(rec[0].triangle_count == full.triangles);
    const std::uint32_t last = static_cast<std::uint32_t>(rt::max_pipeline_vertices / full.vertices);
    CHECK(last == 6553);
    CHECK(rec[last - 1].first_vertex == (last - 1) * full.vertices);
    CHECK(rec[last].vertex_count == 0); // not written
}

TEST_CASE("mesh pipeline limits: 1048576 patches at factor 64 are refused") {
    const gpu_test::Scene scene = gpu_test::repeated_big_triangle(1u << 20);
    const rt::MeshView mesh = scene.view();
    std::vector<rt::PatchRecord> rec(mesh.triangle_count);
    rt::PipelineTotals totals;
    CHECK(rt::setup_patches(rt::cp_tables_64, mesh, scene.options, rec, totals) ==
          PipelineStatus::too_many_vertices);
    CHECK(rec[0].vertex_count == full_pattern(64).vertices);
    CHECK(rec[0].triangle_count == 64u * 64u);
}

TEST_CASE("mesh pipeline limits: more base triangles than the setup dispatch allows") {
    gpu_test::Scene scene = gpu_test::repeated_big_triangle(1);
    rt::MeshView mesh = scene.view();
    mesh.triangle_count = static_cast<std::uint32_t>(rt::max_pipeline_patches + 1); // refused before any read
    std::vector<rt::PatchRecord> rec(mesh.triangle_count);
    rt::PipelineTotals totals;
    CHECK(rt::setup_patches(rt::cp_tables_64, mesh, scene.options, rec, totals) ==
          PipelineStatus::too_many_patches);
    CHECK(rt::emit_mesh(rt::cp_tables_64, mesh, scene.options, rec, {}, {}) ==
          PipelineStatus::too_many_patches);
}

TEST_CASE("mesh pipeline: tampered patch records are refused and nothing is written") {
    gpu_test::Scene scene = gpu_test::factor_sweep_grid(64, 3, rt::Surface::flat);
    scene.indices[4] = 0xFFFFFFFFu; // patch 1 is culled
    const rt::MeshView mesh = scene.view();
    std::vector<rt::PatchRecord> good(mesh.triangle_count);
    rt::PipelineTotals totals;
    REQUIRE(rt::setup_patches(rt::cp_tables_64, mesh, scene.options, good, totals) == PipelineStatus::ok);
    REQUIRE(good[1].vertex_count == 0);
    REQUIRE(good[2].vertex_count > 3);
    using Tamper = void (*)(std::vector<rt::PatchRecord>&);
    const Tamper tampers[] = {
        [](std::vector<rt::PatchRecord>& r) { ++r[2].vertex_count; },
        [](std::vector<rt::PatchRecord>& r) { --r[2].triangle_count; },
        [](std::vector<rt::PatchRecord>& r) { ++r[3].first_vertex; },
        [](std::vector<rt::PatchRecord>& r) { r[3].first_triangle = 0; },
        [](std::vector<rt::PatchRecord>& r) { r[2].rotation = 3; },
        [](std::vector<rt::PatchRecord>& r) { r[2].token[0] = 0; }, // counts no longer those of its states
        [](std::vector<rt::PatchRecord>& r) {
            r[1].vertex_count = 3, r[1].triangle_count = 1;
        }, // culled patch
        [](std::vector<rt::PatchRecord>& r) { r[2].vertex_count = 0xFFFFFFFFu; },
    };
    for (std::size_t k = 0; k < std::size(tampers); ++k) {
        INFO("tamper " << k);
        std::vector<rt::PatchRecord> rec = good;
        tampers[k](rec);
        std::vector<rt::TessVertex> v(totals.vertices + 64);
        std::vector<std::uint32_t> idx(3 * std::size_t{totals.triangles} + 64, 7u);
        CHECK(rt::emit_mesh(rt::cp_tables_64, mesh, scene.options, rec, v, idx) ==
              PipelineStatus::bad_patch_record);
        CHECK(std::all_of(idx.begin(), idx.end(), [](std::uint32_t i) { return i == 7u; }));
    }
}

TEST_CASE("mesh pipeline: zero-area triangles and infinite positions give valid meshes") {
    gpu_test::Scene scene = gpu_test::factor_sweep_grid(64, 3, rt::Surface::pn_triangles);
    const std::uint32_t n = scene.patch_count();
    for (std::uint32_t t = 0; t < n; t += 3)
        scene.indices[3 * t + 1] = scene.indices[3 * t + 2] = scene.indices[3 * t];
    scene.vertices[8 * 5] = std::numeric_limits<float>::infinity();
    scene.vertices[8 * 7 + 1] = -std::numeric_limits<float>::infinity();
    const gpu_test::PipelineOutput out = gpu_test::run_cpu(rt::cp_tables_64, scene);
    const std::uint32_t vertices = static_cast<std::uint32_t>(out.vertices.size() / 10);
    for (std::uint32_t i : out.indices) REQUIRE(i < vertices);
    for (std::uint32_t t = 0; t < n; t += 3) { // a point triangle: every factor NaN -> T0
        CHECK(out.patches[std::size_t{t} * gpu_test::patch_words + 7] == 3);
        CHECK(out.patches[std::size_t{t} * gpu_test::patch_words + 8] == 1);
    }
}
