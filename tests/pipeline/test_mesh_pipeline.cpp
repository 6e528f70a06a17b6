// The CPU mesh pipeline (runtime/include/ctess/runtime/pipeline/mesh_pipeline.hpp): tess factors,
// orientation, counts and prefix sums, vertices and triangles, and its documented results for bad input. The
// GPU tests compare the shaders with this pipeline; here it is checked on its own.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <span>
#include <thread>
#include <utility>
#include <vector>

#include <ctess/cp/pattern.hpp>
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>

#include "gpu_checks.hpp"
#include "pipeline_output.hpp"

using namespace ctess;
using namespace ctess::gpu_test;

namespace {
const rt::CpTableSet& tables_for(unsigned max_factor) {
    return max_factor == 64 ? rt::cp_tables_64 : rt::cp_tables_256;
}
} // namespace

TEST_CASE("edge factor: projected length over DiceRate, symmetric in the endpoints") {
    const rt::Vec3 eye{0.0f, 0.0f, 0.0f};
    // An edge of length 1 at distance 10, 1000 px per unit at distance 1, DiceRate 2: 1 * 1000 / 10 / 2 = 50.
    const rt::DiceOptions dice{eye, 1000.0f, 2.0f};
    const rt::Vec3 a{-0.5f, 0.0f, 10.0f}, b{0.5f, 0.0f, 10.0f};
    CHECK(rt::edge_tess_factor(a, b, eye, dice.factor_scale()) == Approx(50.0f).epsilon(1e-6));
    CHECK(rt::edge_tess_factor(a, b, eye, dice.factor_scale()) ==
          rt::edge_tess_factor(b, a, eye, dice.factor_scale()));
    // Twice as far, half the factor; DiceRate 1 doubles it.
    const rt::Vec3 a2{-0.5f, 0.0f, 20.0f}, b2{0.5f, 0.0f, 20.0f};
    CHECK(rt::edge_tess_factor(a2, b2, eye, dice.factor_scale()) == Approx(25.0f).epsilon(1e-6));
    CHECK(rt::edge_tess_factor(a, b, eye, rt::DiceOptions{eye, 1000.0f, 1.0f}.factor_scale()) ==
          Approx(100.0f).epsilon(1e-6));
}

TEST_CASE("edge factor bad input: eye on the midpoint gives +inf (max), a point edge at the eye NaN (T0)") {
    const rt::Vec3 a{-1.0f, 0.0f, 0.0f}, b{1.0f, 0.0f, 0.0f}, eye{0.0f, 0.0f, 0.0f};
    const float f = rt::edge_tess_factor(a, b, eye, 500.0f);
    CHECK(std::isinf(f));
    CHECK(cp::line_state(f, 64) == cp::LineState{cp::token_count(64) - 1, cp::lerp_one});
    const float g = rt::edge_tess_factor(eye, eye, eye, 500.0f);
    CHECK(std::isnan(g));
    CHECK(cp::line_state(g, 64) == cp::LineState{0, 0});
}

TEST_CASE("mesh pipeline: records, prefix sums and emitted patches match CpPatch and cp::tessellate") {
    for (unsigned max_factor : {64u, 256u}) {
        const Scene scene = factor_sweep_grid(max_factor, 6, rt::Surface::flat);
        const rt::MeshView mesh = scene.view();
        std::vector<rt::PatchRecord> rec(mesh.triangle_count);
        rt::PipelineTotals totals;
        REQUIRE(rt::setup_patches(tables_for(max_factor), mesh, scene.options, rec, totals) ==
                rt::PipelineStatus::ok);
        std::uint32_t v = 0, t = 0;
        for (std::uint32_t p = 0; p < mesh.triangle_count; ++p) {
            CHECK(rec[p].first_vertex == v);
            CHECK(rec[p].first_triangle == t);
            v += rec[p].vertex_count;
            t += rec[p].triangle_count;
            // The smallest base edge is the pattern's e2.
            float len2[3];
            for (unsigned k = 0; k < 3; ++k) {
                const float* a = &scene.vertices[scene.indices[3 * p + k] * 8];
                const float* b = &scene.vertices[scene.indices[3 * p + (k + 1) % 3] * 8];
                len2[k] = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                          (b[2] - a[2]) * (b[2] - a[2]);
            }
            const unsigned e2 = (rec[p].rotation + 2) % 3;
            CHECK(len2[e2] <= len2[(e2 + 1) % 3]);
            CHECK(len2[e2] <= len2[(e2 + 2) % 3]);
        }
        CHECK(totals.vertices == v);
        CHECK(totals.triangles == t);
        std::vector<rt::TessVertex> vertices(totals.vertices);
        std::vector<std::uint32_t> indices(3 * std::size_t{totals.triangles});
        REQUIRE(rt::emit_mesh(tables_for(max_factor), mesh, scene.options, rec, vertices, indices) ==
                rt::PipelineStatus::ok);
        // Each patch equals the procedural generator's pattern, rotated onto the base triangle.
        const Counts most = cp::max_pattern_counts(max_factor);
        std::vector<DomainPoint> pv(most.vertices);
        std::vector<std::uint32_t> pi(3 * std::size_t{most.triangles});
        for (std::uint32_t p = 0; p < mesh.triangle_count; ++p) {
            const cp::PatternOptions opt{{}, max_factor};
            const Counts n = cp::tessellate(pv, pi, cp::LineState{rec[p].token[0], rec[p].t16[0]},
                                            cp::LineState{rec[p].token[1], rec[p].t16[1]},
                                            cp::LineState{rec[p].token[2], rec[p].t16[2]}, opt);
            REQUIRE(n.vertices == rec[p].vertex_count);
            REQUIRE(n.triangles == rec[p].triangle_count);
            const cp::Rotation rot{static_cast<std::uint8_t>(rec[p].rotation)};
            for (std::uint32_t i = 0; i < n.vertices; ++i) {
                const DomainPoint base = cp::to_base_point(rot, pv[i]);
                const rt::TessVertex& out = vertices[rec[p].first_vertex + i];
                REQUIRE(out.u == base.u);
                REQUIRE(out.v == base.v);
            }
            for (std::uint32_t k = 0; k < 3 * n.triangles; ++k)
                REQUIRE(indices[3 * std::size_t{rec[p].first_triangle} + k] == rec[p].first_vertex + pi[k]);
        }
    }
}

TEST_CASE("mesh pipeline: flat vertices lie on the base triangle, corners are copied exactly") {
    const Scene scene = factor_sweep_grid(64, 4, rt::Surface::flat);
    const PipelineOutput out = run_cpu(rt::cp_tables_64, scene);
    for (std::uint32_t p = 0; p < scene.patch_count(); ++p) {
        const std::uint32_t* rec = &out.patches[std::size_t{p} * patch_words];
        for (std::uint32_t i = 0; i < rec[7]; ++i) {
            const std::uint32_t* v = &out.vertices[(std::size_t{rec[9]} + i) * 10];
            const double w[3] = {((1u << 24) - v[0] - v[1]) / 16777216.0, v[0] / 16777216.0,
                                 v[1] / 16777216.0};
            for (unsigned c = 0; c < 3; ++c) {
                double expect = 0.0;
                for (unsigned k = 0; k < 3; ++k)
                    expect += w[k] * scene.vertices[scene.indices[3 * p + k] * 8 + c];
                REQUIRE(bits_float(v[2 + c]) == Approx(expect).margin(1e-6));
                for (unsigned k = 0; k < 3; ++k)
                    if (w[k] == 1.0)
                        REQUIRE(bits_float(v[2 + c]) == scene.vertices[scene.indices[3 * p + k] * 8 + c]);
            }
        }
    }
}

TEST_CASE("mesh pipeline: a closed icosphere is watertight on the CPU with flat, PN and Phong") {
    for (unsigned max_factor : {64u, 256u}) {
        for (rt::Surface s : {rt::Surface::flat, rt::Surface::pn_triangles, rt::Surface::phong}) {
            const Scene scene = icosphere(2, s, max_factor == 64 ? 4.0f : 2.0f);
            const CrackReport r = crack_check(scene, run_cpu(tables_for(max_factor), scene));
            CHECK(r.shared_edges == scene.patch_count() * 3 / 2);
            CHECK(r.edge_points > 3 * r.shared_edges);
            CHECK(r.unmatched_points == 0);
            CHECK(r.position_mismatches == 0);
        }
    }
}

TEST_CASE("mesh pipeline: PN and Phong leave the flat plane and keep unit normals") {
    const Scene flat = icosphere(1, rt::Surface::flat, 4.0f);
    Scene pn = flat, phong = flat;
    pn.options.surface.surface = rt::Surface::pn_triangles;
    phong.options.surface.surface = rt::Surface::phong;
    const PipelineOutput a = run_cpu(rt::cp_tables_64, flat), b = run_cpu(rt::cp_tables_64, pn),
                         c = run_cpu(rt::cp_tables_64, phong);
    REQUIRE(a.vertices.size() == b.vertices.size());
    REQUIRE(a.vertices.size() == c.vertices.size());
    std::size_t moved_pn = 0, moved_phong = 0;
    for (std::size_t v = 0; v < a.vertices.size(); v += 10) {
        moved_pn += a.vertices[v + 2] != b.vertices[v + 2];
        moved_phong += a.vertices[v + 2] != c.vertices[v + 2];
        for (const PipelineOutput* o : {&a, &b, &c}) {
            const double nx = bits_float(o->vertices[v + 5]), ny = bits_float(o->vertices[v + 6]),
                         nz = bits_float(o->vertices[v + 7]);
            REQUIRE(std::sqrt(nx * nx + ny * ny + nz * nz) == Approx(1.0).margin(1e-5));
        }
    }
    CHECK(moved_pn > a.vertices.size() / 20);
    CHECK(moved_phong > a.vertices.size() / 20);
}

TEST_CASE("mesh pipeline bad input: out-of-range indices cull the patch, small spans write nothing") {
    Scene scene = factor_sweep_grid(64, 3, rt::Surface::flat);
    const std::uint32_t vertices = static_cast<std::uint32_t>(scene.vertices.size() / 8);
    scene.indices[4] = vertices;    // patch 1
    scene.indices[8] = 0xFFFFFFFFu; // patch 2
    const rt::MeshView mesh = scene.view();
    std::vector<rt::PatchRecord> rec(mesh.triangle_count);
    rt::PipelineTotals totals;
    REQUIRE(rt::setup_patches(rt::cp_tables_64, mesh, scene.options, rec, totals) == rt::PipelineStatus::ok);
    CHECK(rec[1].vertex_count == 0);
    CHECK(rec[1].triangle_count == 0);
    CHECK(rec[2].vertex_count == 0);
    CHECK(rec[0].vertex_count > 0);
    CHECK(rec[3].first_vertex == rec[0].vertex_count);
    std::vector<rt::PatchRecord> too_few(mesh.triangle_count - 1);
    CHECK(rt::setup_patches(rt::cp_tables_64, mesh, scene.options, too_few, totals) ==
          rt::PipelineStatus::span_too_small);
    std::vector<rt::TessVertex> v(totals.vertices);
    std::vector<std::uint32_t> idx(3 * std::size_t{totals.triangles});
    std::vector<rt::TessVertex> v_short(totals.vertices - 1);
    std::vector<std::uint32_t> idx_short(idx.size() - 1, 7u);
    CHECK(rt::emit_mesh(rt::cp_tables_64, mesh, scene.options, rec, v_short, idx) ==
          rt::PipelineStatus::span_too_small);
    CHECK(rt::emit_mesh(rt::cp_tables_64, mesh, scene.options, rec, v, idx_short) ==
          rt::PipelineStatus::span_too_small);
    CHECK(idx_short[0] == 7u);
    CHECK(rt::emit_mesh(rt::cp_tables_64, mesh, scene.options, rec, v, idx) == rt::PipelineStatus::ok);
    // NaN positions: factors become NaN, the CP line maps them to T0; nothing is undefined.
    Scene nan_scene = factor_sweep_grid(64, 2, rt::Surface::pn_triangles);
    for (std::size_t k = 0; k < nan_scene.vertices.size(); k += 8)
        nan_scene.vertices[k] = std::numeric_limits<float>::quiet_NaN();
    const PipelineOutput nan_out = run_cpu(rt::cp_tables_64, nan_scene);
    for (std::uint32_t p = 0; p < nan_scene.patch_count(); ++p) {
        CHECK(nan_out.patches[std::size_t{p} * patch_words + 7] ==
              3); // T0 on every edge: the base triangle itself
        CHECK(nan_out.patches[std::size_t{p} * patch_words + 8] == 1);
    }
}

TEST_CASE("mesh pipeline: emit_mesh_range writes ranges into the whole mesh's buffers, on two threads as one "
          "call") {
    std::vector<Scene> scenes = {
        factor_sweep_grid(64, 3, rt::Surface::flat),
        factor_sweep_grid(64, 5, rt::Surface::pn_triangles, 3), // triangles and quads
        icosphere(2, rt::Surface::pn_triangles, 6.0f)};
#ifdef CTESS_GPU_HAVE_MODELS
    // PN-AEN reads each face's adjacency entries, which only differ from the face's own corners at seams.
    scenes.push_back(split_normal_icosphere(2, rt::Surface::pn_aen, 6.0f));
#endif
    for (const Scene& scene : scenes) {
        const rt::MeshView mesh = scene.view();
        const std::uint32_t n = scene.patch_count(), t = mesh.triangle_count;
        std::vector<rt::PatchRecord> rec(n);
        rt::PipelineTotals totals;
        REQUIRE(rt::setup_patches(rt::cp_tables_64, mesh, scene.options, rec, totals) ==
                rt::PipelineStatus::ok);
        std::vector<rt::TessVertex> whole_v(totals.vertices), v(totals.vertices);
        std::vector<std::uint32_t> whole_i(3 * std::size_t{totals.triangles}), idx(whole_i.size(), 7u);
        REQUIRE(rt::emit_mesh(rt::cp_tables_64, mesh, scene.options, rec, whole_v, whole_i) ==
                rt::PipelineStatus::ok);
        // Patches [a, b): the triangles among them, the quads among them (after every triangle), their
        // adjacency entries (12 per triangle, then 24 per quad), their records.
        const auto range = [&](std::uint32_t a, std::uint32_t b) {
            const std::uint32_t ta = std::min(a, t), tb = std::min(b, t), first_quad = a - ta;
            rt::MeshView r = mesh;
            r.indices = mesh.indices + 3 * std::size_t{ta};
            r.triangle_count = tb - ta;
            if (mesh.quad_indices != nullptr)
                r.quad_indices = mesh.quad_indices + 4 * std::size_t{first_quad};
            r.quad_count = (b - tb) - first_quad;
            if (mesh.adjacency != nullptr)
                r.adjacency = mesh.adjacency + 12 * std::size_t{ta} + 24 * first_quad;
            return std::pair{r, std::span<const rt::PatchRecord>(rec).subspan(a, b - a)};
        };
        // An empty range, a range across the triangles' end, one of quads only (when there are quads).
        std::vector<std::uint32_t> cut = {0, n / 3, n / 3, 2 * n / 3, std::max(2 * n / 3, t + (n - t) / 2),
                                          n};
        rt::PipelineStatus other = rt::PipelineStatus::ok;
        std::thread second([&] {
            for (std::size_t k = 2; k + 1 < cut.size(); ++k) {
                const auto [view, records] = range(cut[k], cut[k + 1]);
                if (const auto s =
                        rt::emit_mesh_range(rt::cp_tables_64, view, scene.options, records, v, idx);
                    s != rt::PipelineStatus::ok)
                    other = s;
            }
        });
        for (std::size_t k = 0; k < 2; ++k) {
            const auto [view, records] = range(cut[k], cut[k + 1]);
            CHECK(rt::emit_mesh_range(rt::cp_tables_64, view, scene.options, records, v, idx) ==
                  rt::PipelineStatus::ok);
        }
        second.join();
        CHECK(other == rt::PipelineStatus::ok);
        CHECK(idx == whole_i);
        CHECK(std::memcmp(v.data(), whole_v.data(), v.size() * sizeof(rt::TessVertex)) == 0);
        // A range is checked as a whole mesh is: offsets that do not run on from its first record's are
        // refused, and so is a range whose end passes the spans; nothing is written.
        rt::TessVertex mark;
        mark.u = 0x5A5A5A5Au, mark.position[0] = -7.0f;
        std::vector<rt::TessVertex> untouched_v(v.size(), mark);
        const std::vector<rt::TessVertex> sentinel = untouched_v;
        std::vector<std::uint32_t> untouched(idx.size(), 9u);
        std::vector<rt::PatchRecord> moved = rec;
        ++moved[n / 3 + 1].first_vertex;
        auto [view, records] = range(n / 3, n);
        records = std::span<const rt::PatchRecord>(moved).subspan(n / 3);
        CHECK(rt::emit_mesh_range(rt::cp_tables_64, view, scene.options, records, untouched_v, untouched) ==
              rt::PipelineStatus::bad_patch_record);
        moved = rec;
        for (std::uint32_t p = n / 3; p < n; ++p) moved[p].first_triangle += 1; // one past the index span
        records = std::span<const rt::PatchRecord>(moved).subspan(n / 3);
        CHECK(rt::emit_mesh_range(rt::cp_tables_64, view, scene.options, records, untouched_v, untouched) ==
              rt::PipelineStatus::span_too_small);
        // emit_mesh takes a whole mesh: its offsets start at 0, even with room in the spans for a shift.
        moved = rec;
        for (rt::PatchRecord& r : moved) ++r.first_vertex, ++r.first_triangle;
        std::vector<rt::TessVertex> roomy_v(v.size() + 1);
        std::vector<std::uint32_t> roomy_i(idx.size() + 3, 9u);
        CHECK(rt::emit_mesh(rt::cp_tables_64, mesh, scene.options, moved, roomy_v, roomy_i) ==
              rt::PipelineStatus::bad_patch_record);
        CHECK(std::all_of(untouched.begin(), untouched.end(), [](std::uint32_t i) { return i == 9u; }));
        CHECK(std::all_of(roomy_i.begin(), roomy_i.end(), [](std::uint32_t i) { return i == 9u; }));
        CHECK(std::memcmp(untouched_v.data(), sentinel.data(), sentinel.size() * sizeof(rt::TessVertex)) ==
              0);
    }
}

// Two triangles meeting along a hard edge: A = (0, 1, 2), B = (3, 4, 5), vertex 3 at vertex 2's position and
// 4 at 1's, with other normals; the adjacency in meshopt_generateTessellationIndexBuffer's layout, written
// out.
TEST_CASE("mesh pipeline, PN-AEN bad input: an adjacency index past the vertex count is a boundary") {
    Scene scene;
    const float corners[6][rt::mesh_vertex_floats] = {
        {0, 0, 0, 0, 0, 1, 0, 0},          {1, 0, 0, 0, 0, 1, 1, 0},
        {0, 1, 0, 0, 0, 1, 0, 1},          {0, 1, 0, 0.6f, 0.2f, 0.5f, 0, 0},
        {1, 0, 0, 0.6f, 0.2f, 0.5f, 1, 1}, {1, 1, 0.5f, 0.6f, 0.2f, 0.5f, 0, 1},
    };
    scene.vertices.assign(&corners[0][0], &corners[0][0] + 6 * rt::mesh_vertex_floats);
    scene.indices = {0, 1, 2, 3, 4, 5};
    scene.adjacency = {0, 1, 2, 0, 1, 4, 3, 2, 0, 0, 1, 2,  // A: edge 1 (1 -> 2) borders B's (4, 3)
                       3, 4, 5, 2, 1, 4, 5, 5, 3, 3, 4, 5}; // B: edge 0 (3 -> 4) borders A's (2, 1)
    scene.options.dice = {{0.5f, 0.5f, 3.0f}, 200.0f, 2.0f};
    scene.options.surface = {rt::Surface::pn_aen, 1.0f};
    Scene bad = scene, boundary = scene;
    bad.adjacency[5] = 6;                                // one past the end
    bad.adjacency[15] = bad.adjacency[16] = 0xFFFFFFFFu; // both
    boundary.adjacency[5] = 1, boundary.adjacency[6] = 2;
    boundary.adjacency[15] = 3, boundary.adjacency[16] = 4;
    const PipelineOutput good_out = run_cpu(rt::cp_tables_64, scene),
                         bad_out = run_cpu(rt::cp_tables_64, bad);
    const PipelineOutput boundary_out = run_cpu(rt::cp_tables_64, boundary);
    CHECK(bad_out.patches == boundary_out.patches);
    CHECK(bad_out.indices == boundary_out.indices);
    const bool as_boundary = bad_out.vertices == boundary_out.vertices;
    const bool as_good = bad_out.vertices == good_out.vertices;
    CHECK(as_boundary);
    CHECK_FALSE(as_good); // the hard edge's averaged control points are gone
}

TEST_CASE("setup block: counts equal CpPatch's for every line-state triple, skips fit their words") {
    for (unsigned max_factor : {64u, 256u}) {
        const rt::CpTableSet& tables = tables_for(max_factor);
        const unsigned tokens = cp::token_count(cp::pattern_max_factor(max_factor));
        const std::uint32_t t16s[] = {0u, 1u, 21845u, 65535u, 65536u};
        std::size_t checked = 0, mismatches = 0, overflows = 0;
        for (unsigned a = 0; a < tokens; ++a)
            for (unsigned b = 0; b < tokens; ++b)
                for (unsigned c = 0; c < tokens; ++c)
                    for (std::uint32_t t : t16s) {
                        const cp::LineState s0 = cp::clamp_line_state({a, t}, max_factor);
                        const cp::LineState s1 = cp::clamp_line_state({b, 65536u - t}, max_factor);
                        const cp::LineState s2 = cp::clamp_line_state({c, t / 2}, max_factor);
                        const rt::CpPatch patch(tables, s0, s1, s2);
                        const rt::PatchSetupBlock block = rt::patch_setup_block(tables, s0, s1, s2);
                        ++checked;
                        if (block.vertices != patch.vertex_count() ||
                            block.triangles != patch.triangle_count())
                            ++mismatches;
                        const std::uint32_t flags = block.word[rt::setup_word::flags];
                        const std::uint32_t tri_skips = (flags >> 8) & 15u, slot_skips = (flags >> 12) & 15u;
                        if (tri_skips > 8 || slot_skips > 2) ++overflows;
                        for (unsigned k = 0; k < slot_skips; ++k) // begin and length packed as 16 + 16 bits
                            if (block.word[rt::setup_word::slot_skip + k] >> 16 > 255u) ++overflows;
                    }
        INFO("max " << max_factor << ", " << checked << " triples");
        CHECK(checked == std::size_t{tokens} * tokens * tokens * 5);
        CHECK(mismatches == 0);
        CHECK(overflows == 0);
    }
}

// ---- the uniform pattern (PipelineOptions::pattern = Pattern::uniform) ----

namespace {
// w * 2^24 / 65534 rounded to nearest, in 64 bits (never a tie: 2^24 w is even, 32767 odd).
std::uint32_t exact_fixed(std::uint32_t w) {
    return static_cast<std::uint32_t>((std::uint64_t{w} * 2 * (1u << 24) + 65534) / (2 * 65534));
}
// The factor rule of uniform_patch.hpp, written out: nearest integer (halves up), NaN and < 1.5 give 1.
std::uint32_t expected_factor(float f, std::uint32_t n) {
    if (std::isnan(f) || f < 1.5f) return 1;
    const double r = std::floor(static_cast<double>(f) + 0.5);
    return r >= n ? n : static_cast<std::uint32_t>(r);
}
Scene uniform_scene(Scene s) {
    s.options.pattern = rt::Pattern::uniform;
    return s;
}
} // namespace

TEST_CASE("uniform weights: every 16-bit weight converts to the nearest 2^-24 weight, mirror-exactly") {
    std::size_t wrong = 0, asymmetric = 0;
    for (std::uint32_t w = 0; w <= uniform::fixed_one; ++w) {
        const std::uint32_t a = rt::uniform_weight_to_fixed(w);
        wrong += a != exact_fixed(w);
        asymmetric += rt::uniform_weight_to_fixed(uniform::fixed_one - w) != cp::fixed_one - a;
    }
    CHECK(wrong == 0);
    CHECK(asymmetric == 0);
    CHECK(rt::uniform_weight_to_fixed(0) == 0);
    CHECK(rt::uniform_weight_to_fixed(uniform::fixed_one) == cp::fixed_one);
    CHECK(rt::uniform_weight_to_fixed(0xFFFFu) == cp::fixed_one); // past 1.0: clamped
    // Every edge point i/f of every factor: the point and its mirror f - i convert to complementary weights,
    // so both patches of an edge see the same parameter from the lower mesh vertex.
    std::size_t points = 0, mirror_mismatches = 0;
    for (std::uint32_t f = 1; f <= 64; ++f)
        for (std::uint32_t i = 0; i <= f; ++i, ++points)
            if (rt::uniform_weight_to_fixed(uniform::edge_parameter(i, f)) +
                    rt::uniform_weight_to_fixed(uniform::edge_parameter(f - i, f)) !=
                cp::fixed_one)
                ++mirror_mismatches;
    CHECK(points == 2144);
    CHECK(mirror_mismatches == 0);
}

TEST_CASE("mesh pipeline, uniform: records and outputs equal UniformPatch's pattern on the base triangle") {
    const unsigned n = rt::uniform_tables.max_factor;
    const Scene scene = uniform_scene(factor_sweep_grid(n, 8, rt::Surface::flat));
    const PipelineOutput out = run_cpu(rt::cp_tables_64, scene);
    std::size_t clamped_low = 0, clamped_high = 0;
    for (std::uint32_t p = 0; p < scene.patch_count(); ++p) {
        rt::PatchRecord rec;
        std::memcpy(static_cast<void*>(&rec), &out.patches[std::size_t{p} * patch_words], sizeof rec);
        REQUIRE(rec.rotation == 0);
        std::array<std::uint32_t, 3> f{};
        for (unsigned k = 0; k < 3; ++k) {
            f[k] = expected_factor(rec.factor[k], n);
            REQUIRE(rec.token[k] == f[k]);
            REQUIRE(rec.t16[k] == 0);
            clamped_low += rec.factor[k] < 1.0f;
            clamped_high += rec.factor[k] > static_cast<float>(n);
        }
        const rt::UniformPatch patch(rt::uniform_tables, f, rt::uniform_pipeline_options);
        REQUIRE(rec.vertex_count == patch.counts().vertices);
        REQUIRE(rec.triangle_count == patch.counts().triangles);
        const std::array<std::uint32_t, 3> s = patch.sorted_factors();
        CHECK(rec.setup[rt::uniform_setup_word::pattern] == uniform::pattern_index(s[0], s[1], s[2]));
        for (std::uint32_t i = 0; i < rec.vertex_count; ++i) {
            const uniform::Point q = patch.vertex(i);
            const std::uint32_t* v = &out.vertices[(std::size_t{rec.first_vertex} + i) * vertex_words];
            REQUIRE(v[0] == exact_fixed(q.u));
            REQUIRE(v[1] == exact_fixed(q.v));
            // On base edge Ek the opposite weight is exactly 0 in both units.
            REQUIRE(((1u << 24) - v[0] - v[1] == 0) == (uniform::fixed_one - q.u - q.v == 0));
        }
        for (std::uint32_t t = 0; t < rec.triangle_count; ++t) {
            const rt::UniformTriangle tri = patch.triangle(t);
            for (unsigned k = 0; k < 3; ++k)
                REQUIRE(out.indices[3 * (std::size_t{rec.first_triangle} + t) + k] ==
                        rec.first_vertex + tri[k]);
        }
        // Edge Ek has f_k segments: count the vertices with a zero weight opposite it (corners included).
        for (unsigned k = 0; k < 3; ++k) {
            const unsigned opposite = (k + 2) % 3; // E0 = w0w1 is opposite w2, E1 opposite w0, E2 opposite w1
            std::uint32_t on_edge = 0;
            for (std::uint32_t i = 0; i < rec.vertex_count; ++i) {
                const std::uint32_t* v = &out.vertices[(std::size_t{rec.first_vertex} + i) * vertex_words];
                const std::uint32_t bw[3] = {(1u << 24) - v[0] - v[1], v[0], v[1]};
                on_edge += bw[opposite] == 0;
            }
            REQUIRE(on_edge == f[k] + 1);
        }
    }
    CHECK(clamped_low > 0); // the sweep reaches both clamps
    CHECK(clamped_high > 0);
}

TEST_CASE("mesh pipeline, uniform: a closed icosphere is watertight on the CPU with flat, PN and Phong") {
    for (rt::Surface s : {rt::Surface::flat, rt::Surface::pn_triangles, rt::Surface::phong}) {
        const Scene scene = uniform_scene(icosphere(2, s, 4.0f));
        const CrackReport r = crack_check(scene, run_cpu(rt::cp_tables_64, scene));
        CHECK(r.shared_edges == scene.patch_count() * 3 / 2);
        CHECK(r.edge_points > 3 * r.shared_edges);
        CHECK(r.unmatched_points == 0);
        CHECK(r.position_mismatches == 0);
    }
}

TEST_CASE("mesh pipeline, uniform bad input: missing tables, bad options, tampered records, NaN factors") {
    Scene scene = uniform_scene(factor_sweep_grid(16, 3, rt::Surface::flat));
    const rt::MeshView mesh = scene.view();
    std::vector<rt::PatchRecord> rec(mesh.triangle_count);
    rt::PipelineTotals totals{12345u, 678u};
    // The CP-only overloads have no uniform tables.
    CHECK(rt::setup_patches(rt::cp_tables_64, mesh, scene.options, rec, totals) ==
          rt::PipelineStatus::no_uniform_tables);
    CHECK(totals.vertices == 12345u);
    rt::PipelineOptions bad = scene.options;
    bad.pattern = static_cast<rt::Pattern>(7);
    CHECK(rt::setup_patches(rt::cp_tables_64, rt::uniform_tables, mesh, bad, rec, totals) ==
          rt::PipelineStatus::bad_option);
    REQUIRE(rt::setup_patches(rt::cp_tables_64, rt::uniform_tables, mesh, scene.options, rec, totals) ==
            rt::PipelineStatus::ok);
    std::vector<rt::TessVertex> v(totals.vertices);
    std::vector<std::uint32_t> idx(3 * std::size_t{totals.triangles}, 7u);
    CHECK(rt::emit_mesh(rt::cp_tables_64, mesh, scene.options, rec, v, idx) ==
          rt::PipelineStatus::no_uniform_tables);
    CHECK(rt::emit_mesh(rt::cp_tables_64, rt::uniform_tables, mesh, bad, rec, v, idx) ==
          rt::PipelineStatus::bad_option);
    // Records that setup_patches could not have written: a rotation, a factor of 0 or past N, a t16.
    for (int tamper = 0; tamper < 4; ++tamper) {
        std::vector<rt::PatchRecord> t = rec;
        if (tamper == 0) t[1].rotation = 1;
        if (tamper == 1) t[1].token[0] = 0;
        if (tamper == 2) t[1].token[2] = rt::uniform_tables.max_factor + 1;
        if (tamper == 3) t[1].t16[1] = 5;
        CHECK(rt::emit_mesh(rt::cp_tables_64, rt::uniform_tables, mesh, scene.options, t, v, idx) ==
              rt::PipelineStatus::bad_patch_record);
    }
    CHECK(idx[0] == 7u); // nothing written
    // CP records are not uniform records: the counts differ.
    std::vector<rt::PatchRecord> cp_rec(mesh.triangle_count);
    Scene cp_scene = scene;
    cp_scene.options.pattern = rt::Pattern::cp;
    REQUIRE(rt::setup_patches(rt::cp_tables_64, mesh, cp_scene.options, cp_rec, totals) ==
            rt::PipelineStatus::ok);
    CHECK(rt::emit_mesh(rt::cp_tables_64, rt::uniform_tables, mesh, scene.options, cp_rec, v, idx) ==
          rt::PipelineStatus::bad_patch_record);
    // NaN positions: NaN factors give factor 1 on every edge, the base triangle itself.
    Scene nan_scene = uniform_scene(factor_sweep_grid(16, 2, rt::Surface::pn_triangles));
    for (std::size_t k = 0; k < nan_scene.vertices.size(); k += 8)
        nan_scene.vertices[k] = std::numeric_limits<float>::quiet_NaN();
    const PipelineOutput nan_out = run_cpu(rt::cp_tables_64, nan_scene);
    for (std::uint32_t p = 0; p < nan_scene.patch_count(); ++p) {
        CHECK(nan_out.patches[std::size_t{p} * patch_words + 7] == 3);
        CHECK(nan_out.patches[std::size_t{p} * patch_words + 8] == 1);
    }
}
