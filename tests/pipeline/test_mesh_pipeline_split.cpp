// Uniform density at any factor in the mesh pipeline (Pattern::uniform_split, docs/algorithm.md §7.5):
// the clamped uniform pattern's output up to N bit for bit, closed models closed above N (the unwelded
// output welded by exact position bits, and the welded output), the weld equal to an independent weld,
// factors around 1,000 emitted whole, and at 32,768 the counts and the shared edges' points without
// emitting any interior.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include <ctess/runtime/pipeline/mesh_pipeline.hpp>
#include <ctess/runtime/uniform/split.hpp>
#include <ctess/runtime/uniform/table_set.hpp>

#include "mesh_fixtures.hpp"

using namespace ctess;
using namespace pipeline_fixtures;

namespace {

// A regular tetrahedron around the origin (closed, 4 faces, counter-clockwise seen from outside).
Model tetrahedron() {
    Model m;
    const float p[4][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    for (const auto& v : p)
        m.add(v[0], v[1], v[2], v[0], v[1], v[2], 0.5f + 0.25f * v[0], 0.5f + 0.25f * v[1]);
    m.triangles = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    return m;
}

rt::PipelineOptions edge_length(rt::Pattern pattern, float length) {
    rt::PipelineOptions o;
    o.pattern = pattern;
    o.dice.mode = rt::FactorMode::edge_length;
    o.dice.target_edge_length = length;
    return o;
}

bool same_bits(const Output& a, const Output& b) {
    return a.status == b.status && a.indices == b.indices && a.vertices.size() == b.vertices.size() &&
           std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(rt::TessVertex)) == 0;
}

} // namespace

TEST_CASE("uniform_split up to N is the clamped uniform pattern, bit for bit (§7.5)") {
    const std::vector<Model> models = {torus(24, 8, Faces::mixed, true), octasphere(1), open_grid(5)};
    for (const Model& m : models) {
        for (const float length : {0.08f, 0.2f, 0.7f}) {
            const rt::PipelineOptions u = edge_length(rt::Pattern::uniform, length);
            const rt::PipelineOptions s = edge_length(rt::Pattern::uniform_split, length);
            const Output a = unwelded(m.view(), u), b = unwelded(m.view(), s);
            REQUIRE(a.status == rt::PipelineStatus::ok);
            REQUIRE(a.clamped_edges == 0); // every factor within N: the two patterns must agree
            CHECK(same_bits(a, b));
            CHECK(b.clamped_edges == 0);
            const Output wa = welded(m.view(), u), wb = welded(m.view(), s);
            CHECK(same_bits(wa, wb));
        }
    }
}

TEST_CASE("uniform_split above N: closed models stay closed, the weld equals an independent weld") {
    const std::vector<std::pair<const char*, Model>> models = {
        {"mixed torus with a uv seam", torus(8, 4, Faces::mixed, true)},
        {"quad torus", torus(6, 4, Faces::quads)},
        {"octasphere", octasphere(1)},
    };
    std::mt19937 rng(75);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (const auto& [name, m] : models) {
        for (int trial = 0; trial < 2; ++trial) {
            // Factors from about 10 to 130: unsplit and split patches side by side.
            rt::PipelineOptions o =
                camera(rt::Pattern::uniform_split,
                       {6.0f * unit(rng) - 3.0f, -8.0f - 2.0f * unit(rng), 3.0f * unit(rng)},
                       1.0f + unit(rng), 500.0f);
            o.weld.keep_degenerate = trial == 1;
            INFO(name << " trial " << trial);
            const Output u = unwelded(m.view(), o), w = welded(m.view(), o);
            REQUIRE(u.status == rt::PipelineStatus::ok);
            CHECK(u.clamped_edges == 0);
            // Above N: the clamped pattern would have fewer triangles.
            CHECK(u.indices.size() >
                  unwelded(m.view(), camera(rt::Pattern::uniform, o.dice.eye, o.dice.dice_rate, 500.0f))
                      .indices.size());
            check_weld_matches(m.view(), o, u, w);
            CHECK(closed_manifold(directed_edges(u.indices, weld_ids(u.vertices, false))));
            CHECK(closed_manifold(directed_edges(w.indices, weld_ids(w.vertices, false))));
        }
    }
    const Model g = open_grid(4);
    const rt::PipelineOptions o = edge_length(rt::Pattern::uniform_split, 0.005f); // factors 50 to 112
    const Output u = unwelded(g.view(), o), w = welded(g.view(), o);
    check_weld_matches(g.view(), o, u, w);
    check_boundary_subdivided(g, w);
}

TEST_CASE("uniform_split at factors around 1,000: a closed model emitted whole and crack-free") {
    const Model m = tetrahedron();
    // Edge length 2 sqrt 2; the camera near vertex 0 gives factors from about 600 to 1,300.
    const rt::PipelineOptions o = camera(rt::Pattern::uniform_split, {2.2f, 2.2f, 2.2f}, 1.0f, 1600.0f);
    const Output u = unwelded(m.view(), o);
    REQUIRE(u.status == rt::PipelineStatus::ok);
    CHECK(u.clamped_edges == 0);
    float lo = 1e30f, hi = 0;
    for (std::uint32_t t = 0; t < 4; ++t)
        for (unsigned k = 0; k < 3; ++k) {
            const float* a = &m.vertices[8 * std::size_t{m.triangles[3 * t + k]}];
            const float* b = &m.vertices[8 * std::size_t{m.triangles[3 * t + (k + 1) % 3]}];
            const float f = rt::edge_tess_factor({a[0], a[1], a[2]}, {b[0], b[1], b[2]}, o.dice.eye,
                                                 o.dice.factor_scale());
            lo = std::min(lo, f), hi = std::max(hi, f);
        }
    INFO("factors " << lo << " to " << hi);
    CHECK(lo > 500.0f);
    CHECK(hi > 1000.0f);
    CHECK(u.indices.size() / 3 > 1'000'000);
    CHECK(closed_manifold(directed_edges(u.indices, weld_ids(u.vertices, false))));
}

TEST_CASE(
    "uniform_split at 32,768: counts within the closed-form bound, shared edges agree without emitting") {
    const rt::UniformTableSet& tables = rt::uniform_tables;
    // Uniform density of factor T on every edge: T^2 triangles of side 1 in the root's metric; the split's
    // interior edges are at most 1.433 N long, so its triangles are at least (1 / 1.433)^2 as large: fewer
    // than T^2 x 1.433^2 and more than T^2 / 2 (the table's densest pattern). Counted without emitting.
    const auto check_bound = [](std::uint32_t triangles, double t) {
        CHECK(static_cast<double>(triangles) <= t * t * 1.433 * 1.433);
        CHECK(static_cast<double>(triangles) >= t * t / 2);
    };
    const rt::UniformSplit largest(tables, 32768.0f, 32768.0f, 32768.0f, rt::uniform_pipeline_options);
    check_bound(largest.counts().triangles, 32768.0);
    const Model m = tetrahedron();
    rt::PipelineOptions o;
    o.pattern = rt::Pattern::uniform_split;
    o.dice.mode = rt::FactorMode::constant;
    std::vector<rt::PatchRecord> records(4);
    rt::PipelineTotals totals;
    // One such patch has more vertices than the pipeline's 32-bit vertex words address: refused, not wrapped.
    o.dice.constant_factor = 32768.0f;
    CHECK(rt::setup_patches(rt::cp_tables_64, tables, m.view(), o, records, totals) ==
          rt::PipelineStatus::too_many_vertices);
    o.dice.constant_factor = 8192.0f;
    REQUIRE(rt::setup_patches(rt::cp_tables_64, tables, m.view(), o, records, totals) ==
            rt::PipelineStatus::ok);
    CHECK(totals.clamped_edges == 0);
    const rt::UniformSplit split_8192(tables, 8192.0f, 8192.0f, 8192.0f, rt::uniform_pipeline_options);
    for (const rt::PatchRecord& r : records) {
        CHECK(r.uniform_factor(0) == 8192);
        CHECK(r.triangle_count == split_8192.counts().triangles);
        check_bound(r.triangle_count, 8192.0);
    }
    // Above 32,768 an edge clamps and is reported: a sliver with edges of factor 40,000, 1 and 40,000.
    Model sliver;
    sliver.add(0, 0, 0, 0, 0, 1, 0, 0);
    sliver.add(40000, 0, 0, 0, 0, 1, 1, 0);
    sliver.add(40000, 1, 0, 0, 0, 1, 1, 1);
    sliver.triangles = {0, 1, 2};
    const rt::PipelineOptions per_unit = edge_length(rt::Pattern::uniform_split, 1.0f);
    REQUIRE(rt::setup_patches(rt::cp_tables_64, tables, sliver.view(), per_unit, records, totals) ==
            rt::PipelineStatus::ok);
    CHECK(totals.clamped_edges == 2);
    CHECK(records[0].uniform_factor(0) == 32768);
    CHECK(records[0].uniform_factor(1) == 1);

    // The pipeline numbers a shared edge's points from the edge alone (root_edge_points): they are every
    // patch's own points on that edge, whatever its other two factors (edge_points, no interior output).
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> log_factor(0.0f, std::log(32768.0f));
    for (int trial = 0; trial < 40; ++trial) {
        const float f = trial == 0 ? 32768.0f : std::exp(log_factor(rng));
        const std::uint32_t n = rt::UniformSplit::root_edge_point_count(tables, f);
        std::vector<uniform::SplitPoint> shared(n);
        REQUIRE(rt::UniformSplit::root_edge_points(tables, f, shared));
        for (unsigned k = 0; k < 3; ++k) {
            float g[3] = {std::exp(log_factor(rng)), std::exp(log_factor(rng)), std::exp(log_factor(rng))};
            g[k] = f;
            const rt::UniformSplit split(tables, g[0], g[1], g[2], rt::uniform_pipeline_options);
            INFO("f " << f << " edge " << k << " others " << g[(k + 1) % 3] << ", " << g[(k + 2) % 3]);
            REQUIRE(split.edge_point_count(k) == n);
            std::vector<uniform::SplitPoint> own(n);
            REQUIRE(split.edge_points(k, own));
            // Edge k runs from corner a to corner b: its points are a + x (b - a) for the shared line's x.
            for (std::uint32_t i = 0; i < n; ++i) {
                const std::uint32_t x = shared[i].u;
                CHECK(shared[i].v == 0);
                const std::uint32_t expect_u = k == 0 ? x : k == 1 ? rt::uniform_split_fixed_one - x : 0;
                const std::uint32_t expect_v = k == 0 ? 0 : x;
                if (own[i].u != expect_u || own[i].v != expect_v) {
                    FAIL_CHECK("point " << i << " of " << n);
                    break;
                }
            }
        }
    }
    std::vector<uniform::SplitPoint> short_span(1);
    CHECK_FALSE(rt::UniformSplit::root_edge_points(tables, 100.0f, short_span));
}

TEST_CASE("uniform_split at 32,768: quads and the welded output are refused from their counts, not emitted") {
    // One quad (two halves of about 1.07 billion triangles each) and the tetrahedron's welded output: both
    // past the pipeline's 32-bit vertex words, refused before any pattern is generated (a generated half
    // would need some 17 GB).
    Model quad;
    quad.add(0, 0, 0, 0, 0, 1, 0, 0);
    quad.add(1, 0, 0, 0, 0, 1, 1, 0);
    quad.add(1, 1, 0, 0, 0, 1, 1, 1);
    quad.add(0, 1, 0, 0, 0, 1, 0, 1);
    quad.quads = {0, 1, 2, 3};
    rt::PipelineOptions o;
    o.pattern = rt::Pattern::uniform_split;
    o.dice.mode = rt::FactorMode::constant;
    o.dice.constant_factor = 32768.0f;
    std::vector<rt::PatchRecord> records(1);
    rt::PipelineTotals totals;
    CHECK(rt::setup_patches(rt::cp_tables_64, rt::uniform_tables, quad.view(), o, records, totals) ==
          rt::PipelineStatus::too_many_vertices);
    for (const Model& m : {quad, tetrahedron()}) {
        std::vector<rt::WeldedEdge> edges(rt::weld_edge_capacity(m.view()));
        std::vector<rt::WeldedPatch> patches(m.view().patch_count());
        rt::WeldedTotals welded;
        CHECK(rt::setup_welded(rt::cp_tables_64, rt::uniform_tables, m.view(), o, edges, patches, welded) ==
              rt::PipelineStatus::too_many_vertices);
    }
}

TEST_CASE("uniform_split needs the uniform tables, an unknown pattern is refused") {
    const Model m = tetrahedron();
    rt::PipelineOptions o;
    o.pattern = rt::Pattern::uniform_split;
    std::vector<rt::PatchRecord> records(4);
    rt::PipelineTotals totals;
    CHECK(rt::setup_patches(rt::cp_tables_64, m.view(), o, records, totals) ==
          rt::PipelineStatus::no_uniform_tables);
    o.pattern = static_cast<rt::Pattern>(7);
    CHECK(rt::setup_patches(rt::cp_tables_64, rt::uniform_tables, m.view(), o, records, totals) ==
          rt::PipelineStatus::bad_option);
}
