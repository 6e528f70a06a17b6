// The D3D11 patterns in the mesh pipeline (Pattern::d3d11_*, docs/algorithm.md §7.6): every base edge carries
// exactly the points the D3D11 edge rule places for its factor (§5.2), triangles keep the base triangle's
// winding, closed models stay closed (unwelded by exact position bits, and welded) with triangles, quads and
// a uv seam, the weld equals an independent weld, open boundaries are the input's subdivided, clamps are
// reported and no face is culled.
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include <ctess/d3d11/edge.hpp>
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>

#include "mesh_fixtures.hpp"

using namespace ctess;
using namespace pipeline_fixtures;

namespace {

struct Mode {
    rt::Pattern pattern;
    d3d11::Partitioning partitioning;
};
constexpr Mode modes[] = {{rt::Pattern::d3d11_integer, d3d11::Partitioning::integer},
                          {rt::Pattern::d3d11_pow2, d3d11::Partitioning::pow2},
                          {rt::Pattern::d3d11_fractional_odd, d3d11::Partitioning::fractional_odd},
                          {rt::Pattern::d3d11_fractional_even, d3d11::Partitioning::fractional_even}};

} // namespace

TEST_CASE(
    "D3D11 in the pipeline: each base edge has the D3D11 edge rule's points, triangles wound as the base") {
    // One triangle, edges of factor 13.2 (E0), 17.2 (E1) and 12.0 (E2) in edge-length units.
    Model m;
    m.add(0, 0, 0, 0, 0, 1, 0, 0);
    m.add(3.3f, 0, 0, 0, 0, 1, 1, 0);
    m.add(0.2f, 3.0f, 0, 0, 0, 1, 0, 1);
    m.triangles = {0, 1, 2};
    rt::PipelineOptions o;
    o.dice.mode = rt::FactorMode::edge_length;
    o.dice.target_edge_length = 0.25f;
    const float f[3] = {rt::edge_factor({0, 0, 0}, {3.3f, 0, 0}, o.dice),
                        rt::edge_factor({3.3f, 0, 0}, {0.2f, 3.0f, 0}, o.dice),
                        rt::edge_factor({0, 0, 0}, {0.2f, 3.0f, 0}, o.dice)};
    for (const Mode& mode : modes) {
        o.pattern = mode.pattern;
        const Output u = unwelded(m.view(), o);
        REQUIRE(u.status == rt::PipelineStatus::ok);
        // The points on base edge Ek (the weight of the opposite corner is 0), by their parameter.
        std::set<std::uint32_t> on_edge[3];
        for (const rt::TessVertex& v : u.vertices) {
            const std::uint32_t w[3] = {cp::fixed_one - v.u - v.v, v.u, v.v};
            for (unsigned k = 0; k < 3; ++k)
                if (w[(k + 2) % 3] == 0) on_edge[k].insert(w[(k + 1) % 3]);
        }
        for (unsigned k = 0; k < 3; ++k) {
            const d3d11::FixedFactor factor = d3d11::process_edge_factor(mode.partitioning, f[k]);
            const d3d11::EdgeContext context = d3d11::edge_context(factor);
            std::set<std::uint32_t> expected;
            for (std::uint32_t p = 0; p < d3d11::point_count(factor); ++p)
                expected.insert(d3d11::place_point(context, p) * 256u);
            INFO("partitioning " << static_cast<int>(mode.partitioning) << " edge " << k << " factor "
                                 << f[k]);
            CHECK(on_edge[k] == expected);
        }
        // Counter-clockwise in base weights, as the base triangle: no triangle has negative area.
        std::size_t positive = 0;
        for (std::size_t t = 0; t < u.indices.size(); t += 3) {
            const rt::TessVertex &a = u.vertices[u.indices[t]], &b = u.vertices[u.indices[t + 1]],
                                 &c = u.vertices[u.indices[t + 2]];
            const std::int64_t area = (std::int64_t{b.u} - a.u) * (std::int64_t{c.v} - a.v) -
                                      (std::int64_t{b.v} - a.v) * (std::int64_t{c.u} - a.u);
            CHECK(area >= 0);
            positive += area > 0;
        }
        CHECK(positive > 0);
    }
}

TEST_CASE("D3D11 in the pipeline: closed models stay closed, the weld equals an independent weld") {
    const std::vector<std::pair<const char*, Model>> models = {
        {"mixed torus with a uv seam", torus(8, 4, Faces::mixed, true)},
        {"quad torus", torus(8, 4, Faces::quads)},
        {"octasphere", octasphere(1)},
    };
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (const Mode& mode : modes)
        for (const auto& [name, m] : models)
            for (int trial = 0; trial < 2; ++trial) {
                rt::PipelineOptions o = camera(
                    mode.pattern, {8.0f * unit(rng) - 4.0f, -6.0f - 6.0f * unit(rng), 4.0f * unit(rng)},
                    2.0f + 4.0f * unit(rng), 400.0f);
                o.weld.keep_degenerate = trial == 1;
                INFO(name << " partitioning " << static_cast<int>(mode.partitioning) << " trial " << trial);
                const Output u = unwelded(m.view(), o), w = welded(m.view(), o);
                check_weld_matches(m.view(), o, u, w);
                CHECK(closed_manifold(directed_edges(u.indices, weld_ids(u.vertices, false))));
                CHECK(closed_manifold(directed_edges(w.indices, weld_ids(w.vertices, false))));
            }
    const Model g = open_grid(5);
    for (const Mode& mode : modes) {
        const rt::PipelineOptions o = camera(mode.pattern, {1.0f, 0.5f, 4.0f}, 3.0f);
        const Output u = unwelded(g.view(), o), w = welded(g.view(), o);
        check_weld_matches(g.view(), o, u, w);
        check_boundary_subdivided(g, w);
    }
}

TEST_CASE("D3D11 in the pipeline: clamps are reported, no face is culled") {
    Model m;
    m.add(0, 0, 0, 0, 0, 1, 0, 0);
    m.add(100, 0, 0, 0, 0, 1, 1, 0);
    m.add(100, 50, 0, 0, 0, 1, 1, 1);
    m.add(100, 50, 0, 0, 0, 1, 1, 1); // the quad's edge q2q3 has length 0: factor 0, which D3D11 culls
    m.triangles = {0, 1, 2};
    m.quads = {0, 1, 2, 3};
    rt::PipelineOptions o;
    o.dice.mode = rt::FactorMode::edge_length;
    o.dice.target_edge_length = 1.0f; // factors 100 (E0), 50 (E1) and 111.8 (E2)
    for (const Mode& mode : modes) {
        o.pattern = mode.pattern;
        std::vector<rt::PatchRecord> records(2);
        rt::PipelineTotals totals;
        REQUIRE(rt::setup_patches(rt::cp_tables_64, m.view(), o, records, totals) == rt::PipelineStatus::ok);
        // The triangle's 100 and 111.8; the quad's 100 and 111.8 (its shorter diagonal, q1q3, is 50).
        CHECK(totals.clamped_edges == 4);
        // The quad's half A = (q0, q1, q3) is the triangle's shape with the same edge factors, so the rest of
        // the quad's count is half B = (q2, q3, q1), edges 0 (raised to 1), 50 and 50: tessellated, not
        // culled.
        const std::uint32_t half_a = records[0].triangle_count;
        REQUIRE(records[1].triangle_count > half_a);
        CHECK(records[1].triangle_count - half_a >= 50);
        const Output u = unwelded(m.view(), o);
        REQUIRE(u.status == rt::PipelineStatus::ok);
        CHECK(u.indices.size() == 3 * std::size_t{totals.triangles});
    }
}
