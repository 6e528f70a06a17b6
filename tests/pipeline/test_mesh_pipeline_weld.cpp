// Quads in the mesh pipeline and its welded, indexed output (mesh_pipeline.hpp, docs/algorithm.md §7):
// the factor modes, clamp reporting, the quad rule's edge lengths, and the weld checked against an
// independent weld of the unwelded output (exact position and attribute bits) on closed and open models
// built here: a triangle torus, an all-quad torus, a mixed torus, an octahedron sphere, a torus with a uv
// seam and an open mixed grid; the welded output written in ranges of patches (a caller's threads).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <thread>
#include <unordered_map>
#include <utility>
#include <vector>

#include "mesh_fixtures.hpp"
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>
#include <ctess/runtime/uniform/table_set.hpp>

using namespace ctess;
using namespace pipeline_fixtures;

TEST_CASE("factor modes (docs/algorithm.md §7.1): constant, edge length / L and camera, per edge") {
    Model m;
    m.add(0, 0, 0, 0, 0, 1, 0, 0);
    m.add(3, 0, 0, 0, 0, 1, 1, 0);
    m.add(3, 4, 0, 0, 0, 1, 1, 1);
    m.triangles = {0, 1, 2};
    const rt::MeshView mesh = m.view();
    rt::PipelineOptions o;
    o.dice.mode = rt::FactorMode::constant;
    o.dice.constant_factor = 7.5f;
    rt::PatchRecord rec = rt::setup_patch(rt::cp_tables_64, mesh, 0, o);
    CHECK(rec.factor[0] == 7.5f);
    CHECK(rec.factor[1] == 7.5f);
    CHECK(rec.factor[2] == 7.5f);
    // Edge lengths 3, 4 and 5, L = 0.5: factors 6, 8 and 10 exactly.
    o.dice.mode = rt::FactorMode::edge_length;
    o.dice.target_edge_length = 0.5f;
    rec = rt::setup_patch(rt::cp_tables_64, mesh, 0, o);
    CHECK(rec.factor[0] == 6.0f);
    CHECK(rec.factor[1] == 8.0f);
    CHECK(rec.factor[2] == 10.0f);
    // Bad targets: 0 gives +inf (clamped to max), NaN gives NaN (factor 1); both run.
    o.dice.target_edge_length = 0.0f;
    CHECK(std::isinf(rt::setup_patch(rt::cp_tables_64, mesh, 0, o).factor[0]));
    o.dice.target_edge_length = std::nanf("");
    CHECK(std::isnan(rt::setup_patch(rt::cp_tables_64, mesh, 0, o).factor[0]));
    // A mode outside the enum gives NaN (factor 1), never UB.
    o.dice.mode = static_cast<rt::FactorMode>(9);
    CHECK(std::isnan(rt::setup_patch(rt::cp_tables_64, mesh, 0, o).factor[0]));
    // The camera mode is the default and keeps its formula: 3 * 1000 / 2 / distance 10 at the midpoint.
    rt::PipelineOptions c;
    c.dice.eye = {1.5f, 0.0f, 10.0f};
    c.dice.projection_scale = 1000.0f;
    c.dice.dice_rate = 2.0f;
    CHECK(rt::setup_patch(rt::cp_tables_64, mesh, 0, c).factor[0] == Approx(150.0f));
}

TEST_CASE("clamped factors are reported (PipelineTotals::clamped_edges), once per patch edge") {
    const Model m = torus(8, 4, Faces::mixed);
    const rt::MeshView mesh = m.view();
    const std::uint32_t patch_edges = 3 * mesh.triangle_count + 4 * mesh.quad_count;
    rt::PipelineOptions o;
    o.dice.mode = rt::FactorMode::constant;
    o.dice.constant_factor = 64.0f; // the CP tables' max: not a clamp
    CHECK(unwelded(mesh, o).clamped_edges == 0);
    o.dice.constant_factor = 64.5f;
    CHECK(unwelded(mesh, o).clamped_edges == patch_edges);
    CHECK(welded(mesh, o).clamped_edges == patch_edges);
    // Uniform: N + 0.4 rounds to N (no clamp), N + 0.6 to N + 1 (clamped); a uniform quad's diagonal counts.
    const auto n = static_cast<float>(uniform_set().max_factor);
    o.pattern = rt::Pattern::uniform;
    o.dice.constant_factor = n + 0.4f;
    CHECK(unwelded(mesh, o).clamped_edges == 0);
    o.dice.constant_factor = n + 0.6f;
    CHECK(unwelded(mesh, o).clamped_edges == patch_edges + mesh.quad_count);
    CHECK(welded(mesh, o).clamped_edges == patch_edges + mesh.quad_count);
}

TEST_CASE("quad records (§7.3): kind word, 192 bytes, counts of both halves, bad input") {
    STATIC_REQUIRE(sizeof(rt::PatchRecord) == 192);
    const Model m = torus(6, 4, Faces::mixed);
    const rt::MeshView mesh = m.view();
    rt::PipelineOptions o;
    o.dice.mode = rt::FactorMode::constant;
    o.dice.constant_factor = 5.0f;
    std::vector<rt::PatchRecord> rec(mesh.patch_count());
    rt::PipelineTotals totals;
    REQUIRE(rt::setup_patches(rt::cp_tables_64, mesh, o, rec, totals) == rt::PipelineStatus::ok);
    for (std::uint32_t p = 0; p < rec.size(); ++p) {
        CHECK(rec[p].kind == (p < mesh.triangle_count ? rt::patch_kind_triangle : rt::patch_kind_quad));
        if (p >= mesh.triangle_count) {
            // Two CP halves of (5, 5, 5): each the (5, 5, 5) triangle's counts.
            const Counts half = rt::CpPatch(rt::cp_tables_64, 5.0f, 5.0f, 5.0f).counts();
            CHECK(rec[p].vertex_count == 2 * half.vertices);
            CHECK(rec[p].triangle_count == 2 * half.triangles);
        }
    }
    // A tampered quad record is refused, and nothing is written.
    std::vector<rt::TessVertex> v(totals.vertices);
    std::vector<std::uint32_t> idx(3 * std::size_t{totals.triangles}, 77u);
    auto bad = rec;
    bad.back().rotation = 4;
    CHECK(rt::emit_mesh(rt::cp_tables_64, mesh, o, bad, v, idx) == rt::PipelineStatus::bad_patch_record);
    bad = rec;
    bad.back().setup[rt::quad_setup_word::b_token] += 1;
    CHECK(rt::emit_mesh(rt::cp_tables_64, mesh, o, bad, v, idx) == rt::PipelineStatus::bad_patch_record);
    CHECK(std::all_of(idx.begin(), idx.end(), [](std::uint32_t i) { return i == 77u; }));
    // A surface value outside the enum is refused.
    rt::PipelineOptions bad_surface = o;
    bad_surface.surface.surface = static_cast<rt::Surface>(9);
    CHECK(rt::setup_patches(rt::cp_tables_64, mesh, bad_surface, rec, totals) ==
          rt::PipelineStatus::bad_option);
    rt::PipelineOptions rule = o;
    rule.quad_rule = static_cast<rt::QuadRule>(7);
    CHECK(rt::setup_patches(rt::cp_tables_64, mesh, rule, rec, totals) == rt::PipelineStatus::bad_option);
    // A quad with an index past the vertices is culled; the rest is unchanged.
    Model culled = m;
    culled.quads[1] = 100000;
    const rt::MeshView cm = culled.view();
    REQUIRE(rt::setup_patches(rt::cp_tables_64, cm, o, rec, totals) == rt::PipelineStatus::ok);
    CHECK(rec[mesh.triangle_count].vertex_count == 0);
    CHECK(rec[mesh.triangle_count].triangle_count == 0);
    const Output w = welded(cm, o);
    CHECK(w.status == rt::PipelineStatus::ok);
}

TEST_CASE("quads and triangles are watertight where they meet (§7.3): exact bits on shared edges") {
    // The unwelded output welded by position bits alone is closed and 2-manifold: every shared edge's points
    // are the same bits on both sides, triangle or quad, CP or uniform.
    // Every surface: quads evaluate their edges by evaluate_surface's own edge rule (§6.2, §7.3).
    for (const rt::Pattern pattern : {rt::Pattern::cp, rt::Pattern::uniform}) {
        for (const Faces faces : {Faces::quads, Faces::mixed}) {
            for (const rt::Surface surface :
                 {rt::Surface::flat, rt::Surface::pn_triangles, rt::Surface::phong, rt::Surface::pn_aen}) {
                const Model m = torus(12, 5, faces);
                rt::PipelineOptions o = camera(pattern, {0.5f, -9.0f, 3.0f}, 2.0f, 250.0f);
                o.surface.surface = surface;
                const Output u = unwelded(m.view(), o);
                REQUIRE(u.status == rt::PipelineStatus::ok);
                INFO("surface " << static_cast<int>(surface));
                CHECK(closed_manifold(directed_edges(u.indices, weld_ids(u.vertices, false))));
            }
        }
    }
}

TEST_CASE("quad rule (§7.2): q0q1 on the longer pair bounds the longest output edge") {
    // An all-quad torus whose quads list the short pair first (the user's case). Longest output edge per
    // triangle in DiceRate units: with the rule the p99 stays near the triangles' (below 2.5); as labelled
    // it does not.
    const Model m = torus(48, 6, Faces::quads);
    for (const rt::Pattern pattern : {rt::Pattern::cp}) {
        rt::PipelineOptions o = camera(pattern, {0.5f, -9.0f, 3.0f}, 2.0f);
        const auto rule = longest_edge_stats(unwelded(m.view(), o), o.dice);
        o.quad_rule = rt::QuadRule::as_labelled;
        const auto labelled = longest_edge_stats(unwelded(m.view(), o), o.dice);
        CHECK(rule[1] < 2.5);
        CHECK(labelled[1] > 2.0 * rule[1]);
    }
    // The rule is the quad's own data: any cyclic relabelling of the quads gives the same output bits.
    Model turned = m;
    for (std::size_t q = 0; q < turned.quads.size(); q += 4)
        std::rotate(turned.quads.begin() + static_cast<std::ptrdiff_t>(q),
                    turned.quads.begin() + static_cast<std::ptrdiff_t>(q + 1),
                    turned.quads.begin() + static_cast<std::ptrdiff_t>(q + 4));
    const rt::PipelineOptions o = camera(rt::Pattern::cp, {0.5f, -9.0f, 3.0f}, 2.0f, 250.0f);
    CHECK(key_triangles(unwelded(m.view(), o)) == key_triangles(unwelded(turned.view(), o)));
}

TEST_CASE("welded output (§7.4): equals the unwelded output welded by bits, closed models stay closed") {
    const std::vector<std::pair<const char*, Model>> models = {
        {"triangle torus", torus(8, 4, Faces::triangles)},
        {"quad torus", torus(8, 4, Faces::quads)},
        {"mixed torus", torus(8, 4, Faces::mixed)},
        {"octasphere", octasphere(1)},
    };
    std::mt19937 rng(19);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (const auto& [name, m] : models) {
        for (const rt::Pattern pattern : {rt::Pattern::cp, rt::Pattern::uniform}) {
            for (int trial = 0; trial < 6; ++trial) {
                rt::PipelineOptions o =
                    camera(pattern, {8.0f * unit(rng) - 4.0f, -6.0f - 6.0f * unit(rng), 4.0f * unit(rng)},
                           0.5f + 6.0f * unit(rng));
                if (trial % 3 == 1) {
                    o.dice.mode = rt::FactorMode::constant;
                    o.dice.constant_factor = 1.0f + 8.0f * unit(rng);
                } else if (trial % 3 == 2) {
                    o.dice.mode = rt::FactorMode::edge_length;
                    o.dice.target_edge_length = 0.3f + 0.6f * unit(rng);
                }
                o.weld.keep_degenerate = trial % 4 == 3;
                INFO(name << " pattern " << static_cast<int>(pattern) << " trial " << trial);
                const rt::MeshView mesh = m.view();
                const Output u = unwelded(mesh, o), w = welded(mesh, o);
                check_weld_matches(mesh, o, u, w);
                CHECK(closed_manifold(directed_edges(w.indices, identity(w.vertices.size()))));
            }
        }
    }
}

TEST_CASE("welded output: a uv seam keeps its own vertices, open boundaries are the input's, subdivided") {
    for (const rt::Pattern pattern : {rt::Pattern::cp, rt::Pattern::uniform}) {
        for (const Faces faces : {Faces::triangles, Faces::quads, Faces::mixed}) {
            const Model m = torus(8, 4, faces, true);
            const rt::PipelineOptions o = camera(pattern, {0.5f, -9.0f, 3.0f}, 2.0f, 250.0f);
            const Output u = unwelded(m.view(), o), w = welded(m.view(), o);
            check_weld_matches(m.view(), o, u, w);
            // By index the seam is a boundary (as in the input), subdivided; by position it is closed.
            check_boundary_subdivided(m, w);
            CHECK(closed_manifold(directed_edges(w.indices, weld_ids(w.vertices, false))));
        }
        const Model g = open_grid(6);
        const rt::PipelineOptions o = camera(pattern, {1.0f, 0.5f, 4.0f}, 3.0f);
        const Output u = unwelded(g.view(), o), w = welded(g.view(), o);
        check_weld_matches(g.view(), o, u, w);
        check_boundary_subdivided(g, w);
    }
}

TEST_CASE("welded output: degenerate triangles are dropped unless kept, spans and tampered tables refused") {
    const Model m = torus(12, 5, Faces::mixed);
    const rt::MeshView mesh = m.view();
    rt::PipelineOptions o = camera(rt::Pattern::cp, {0.5f, -9.0f, 3.0f}, 2.0f);
    o.dice.mode = rt::FactorMode::constant;
    o.dice.constant_factor = 2.0f; // CP lines at f = 2 have a zero-length middle segment (§1.2)
    const Output drop = welded(mesh, o);
    o.weld.keep_degenerate = true;
    const Output keep = welded(mesh, o);
    REQUIRE(drop.status == rt::PipelineStatus::ok);
    REQUIRE(keep.status == rt::PipelineStatus::ok);
    // Kept: exactly the unwelded triangle count (the shared layout has the provoking layout's triangles).
    CHECK(keep.indices.size() == unwelded(mesh, o).indices.size());
    CHECK(drop.indices.size() < keep.indices.size());
    CHECK(drop.vertices.size() == keep.vertices.size());

    std::vector<rt::WeldedEdge> edges(rt::weld_edge_capacity(mesh));
    std::vector<rt::WeldedPatch> patches(mesh.patch_count());
    rt::WeldedTotals totals{1, 2, 3, 4};
    std::vector<rt::WeldedEdge> short_edges(edges.size() - 1);
    CHECK(rt::setup_welded(rt::cp_tables_64, mesh, o, short_edges, patches, totals) ==
          rt::PipelineStatus::span_too_small);
    CHECK(totals.vertices == 1);
    REQUIRE(rt::setup_welded(rt::cp_tables_64, mesh, o, edges, patches, totals) == rt::PipelineStatus::ok);
    edges.resize(totals.edges);
    std::vector<rt::TessVertex> v(totals.vertices);
    std::vector<std::uint32_t> idx(3 * std::size_t{totals.triangles}, 77u);
    std::vector<std::uint32_t> short_idx(idx.size() - 1);
    CHECK(rt::emit_welded_mesh(rt::cp_tables_64, mesh, o, edges, patches, v, short_idx) ==
          rt::PipelineStatus::span_too_small);
    auto bad_edges = edges;
    bad_edges[3].vertex_count += 1;
    CHECK(rt::emit_welded_mesh(rt::cp_tables_64, mesh, o, bad_edges, patches, v, idx) ==
          rt::PipelineStatus::bad_patch_record);
    bad_edges = edges;
    std::swap(bad_edges[1], bad_edges[2]);
    CHECK(rt::emit_welded_mesh(rt::cp_tables_64, mesh, o, bad_edges, patches, v, idx) ==
          rt::PipelineStatus::bad_patch_record);
    CHECK(rt::emit_welded_mesh(rt::cp_tables_64, mesh, o, std::span(edges).first(edges.size() - 1), patches,
                               v, idx) == rt::PipelineStatus::bad_patch_record);
    auto bad_patches = patches;
    bad_patches[5].triangle_count += 1;
    CHECK(rt::emit_welded_mesh(rt::cp_tables_64, mesh, o, edges, bad_patches, v, idx) ==
          rt::PipelineStatus::bad_patch_record);
    CHECK(std::all_of(idx.begin(), idx.end(), [](std::uint32_t i) { return i == 77u; }));
    CHECK(rt::emit_welded_mesh(rt::cp_tables_64, mesh, o, edges, patches, v, idx) == rt::PipelineStatus::ok);
}

TEST_CASE("welded output: patches that share a pattern (§7.4, patch shapes) in every family and surface") {
    // One constant factor: every patch of a rotation (and quad rule) has the same pattern words, so the weld
    // reads most patches from its shape cache; the result must still be the independent weld of the
    // unwelded output, closed and 2-manifold, in every family, with the PN and Phong surfaces.
    const rt::Pattern patterns[] = {rt::Pattern::cp,
                                    rt::Pattern::uniform,
                                    rt::Pattern::uniform_split,
                                    rt::Pattern::d3d11_integer,
                                    rt::Pattern::d3d11_pow2,
                                    rt::Pattern::d3d11_fractional_odd,
                                    rt::Pattern::d3d11_fractional_even};
    for (const Faces faces : {Faces::triangles, Faces::quads, Faces::mixed}) {
        const Model m = torus(9, 5, faces);
        const rt::MeshView mesh = m.view();
        for (const rt::Pattern pattern : patterns) {
            for (const float factor : {2.0f, 5.5f, 21.0f}) {
                rt::PipelineOptions o;
                o.pattern = pattern;
                o.dice.mode = rt::FactorMode::constant;
                o.dice.constant_factor = factor;
                o.surface.surface = factor == 5.5f ? rt::Surface::pn_triangles : rt::Surface::phong;
                o.weld.keep_degenerate = factor == 2.0f;
                INFO("faces " << static_cast<int>(faces) << " pattern " << static_cast<int>(pattern)
                              << " factor " << factor);
                const Output u = unwelded(mesh, o), w = welded(mesh, o);
                check_weld_matches(mesh, o, u, w);
                CHECK(closed_manifold(directed_edges(w.indices, identity(w.vertices.size()))));
            }
        }
    }
}

namespace {

// A mixed torus with a uv seam, plus what a real model may hold: a vertex no face uses, a triangle with a
// repeated corner (its edges include one with lo == hi), a triangle and a quad with an index past the
// vertices (culled), all in the middle of the face lists so that ranges cut around them.
Model torus_with_strays() {
    Model m = torus(8, 4, Faces::mixed, true);
    const auto n = static_cast<std::uint32_t>(m.vertices.size() / 8);
    m.add(9.0f, 9.0f, 9.0f, 0.0f, 0.0f, 1.0f, 0.25f, 0.75f); // no face reaches it
    const std::size_t t = m.triangles.size() / 2 / 3 * 3, q = m.quads.size() / 2 / 4 * 4;
    m.triangles.insert(m.triangles.begin() + static_cast<std::ptrdiff_t>(t), {0, 0, 5, 1, n + 7, 2});
    m.quads.insert(m.quads.begin() + static_cast<std::ptrdiff_t>(q), {3, 4, n + 2, 6});
    return m;
}

struct WeldedSetup {
    rt::PipelineStatus status = rt::PipelineStatus::ok;
    std::vector<rt::WeldedEdge> edges;
    std::vector<rt::WeldedPatch> patches;
    rt::WeldedTotals totals;
};

WeldedSetup setup(const rt::MeshView& mesh, const rt::PipelineOptions& o) {
    WeldedSetup s;
    s.edges.resize(rt::weld_edge_capacity(mesh));
    s.patches.resize(mesh.patch_count());
    s.status = rt::setup_welded(rt::cp_tables_64, uniform_set(), mesh, o, s.edges, s.patches, s.totals);
    s.edges.resize(s.totals.edges);
    return s;
}

// The output words every range wrote, each range on buffers of its own filled with a marker: a word a range
// left at the marker it did not write (a written word equal to the marker would only hide a write).
constexpr std::uint32_t marker = 0xA5A5A5A5u;

void fill_marker(std::vector<rt::TessVertex>& v) {
    std::array<std::uint32_t, sizeof(rt::TessVertex) / 4> w;
    w.fill(marker);
    std::fill(v.begin(), v.end(), std::bit_cast<rt::TessVertex>(w));
}

std::vector<std::uint32_t> words(const std::vector<rt::TessVertex>& v, const std::vector<std::uint32_t>& i) {
    std::vector<std::uint32_t> w(v.size() * sizeof(rt::TessVertex) / 4 + i.size());
    std::memcpy(w.data(), v.data(), v.size() * sizeof(rt::TessVertex));
    std::copy(i.begin(), i.end(),
              w.begin() + static_cast<std::ptrdiff_t>(v.size() * sizeof(rt::TessVertex) / 4));
    return w;
}

} // namespace

TEST_CASE("welded output in ranges (§7.4): every split, in any order or on threads, is the one call's output "
          "bit for bit, and no word is written by two ranges") {
    const Model m = torus_with_strays();
    const rt::MeshView mesh = m.view();
    const auto patch_count = static_cast<std::uint32_t>(mesh.patch_count());
    const rt::Pattern patterns[] = {rt::Pattern::cp, rt::Pattern::uniform, rt::Pattern::uniform_split,
                                    rt::Pattern::d3d11_fractional_odd};
    std::mt19937 rng(23);
    for (const rt::Pattern pattern : patterns) {
        for (int trial = 0; trial < 3; ++trial) {
            rt::PipelineOptions o = camera(pattern, {0.5f, -9.0f, 3.0f}, trial == 0 ? 4.0f : 2.0f);
            if (trial == 2) {
                o.dice.mode = rt::FactorMode::constant;
                o.dice.constant_factor = pattern == rt::Pattern::uniform_split ? 20.0f : 2.0f;
                o.weld.keep_degenerate = true;
            }
            o.surface.surface = trial == 1 ? rt::Surface::pn_triangles : rt::Surface::flat;
            INFO("pattern " << static_cast<int>(pattern) << " trial " << trial);
            const Output whole = welded(mesh, o);
            REQUIRE(whole.status == rt::PipelineStatus::ok);
            const std::vector<std::uint32_t> expected = words(whole.vertices, whole.indices);
            const WeldedSetup s = setup(mesh, o);
            REQUIRE(s.status == rt::PipelineStatus::ok);

            // Cut points: welded_range's parts, and random cuts with empty ranges among them.
            std::vector<std::vector<rt::WeldedRange>> splits;
            for (const std::uint32_t parts : {1u, 2u, 3u}) {
                std::vector<rt::WeldedRange> r;
                for (std::uint32_t k = 0; k < parts; ++k)
                    r.push_back(rt::welded_range(mesh, s.patches, k, parts));
                splits.push_back(r);
            }
            std::vector<std::uint32_t> cuts{0, 0, 1, patch_count / 2, patch_count / 2, patch_count - 1};
            for (int k = 0; k < 4; ++k)
                cuts.push_back(std::uniform_int_distribution<std::uint32_t>(0, patch_count)(rng));
            cuts.push_back(patch_count);
            std::sort(cuts.begin(), cuts.end());
            std::vector<rt::WeldedRange> random;
            for (std::size_t k = 0; k + 1 < cuts.size(); ++k) random.push_back({cuts[k], cuts[k + 1]});
            splits.push_back(random);

            for (const std::vector<rt::WeldedRange>& ranges : splits) {
                INFO("ranges " << ranges.size());
                // welded_range covers the patches once, in order.
                REQUIRE(ranges.front().first_patch == 0);
                REQUIRE(ranges.back().end_patch == patch_count);
                for (std::size_t k = 1; k < ranges.size(); ++k)
                    REQUIRE(ranges[k].first_patch == ranges[k - 1].end_patch);
                // Last range first, into one pair of buffers.
                std::vector<rt::TessVertex> v(s.totals.vertices);
                std::vector<std::uint32_t> idx(3 * std::size_t{s.totals.triangles}, marker);
                fill_marker(v);
                for (std::size_t k = ranges.size(); k-- > 0;)
                    REQUIRE(rt::emit_welded_mesh(rt::cp_tables_64, uniform_set(), mesh, o, s.edges, s.patches,
                                                 ranges[k], v, idx) == rt::PipelineStatus::ok);
                CHECK(words(v, idx) == expected);
                // Each range alone: the words it wrote, counted over the ranges, are every word once.
                std::vector<std::uint8_t> writers(expected.size(), 0);
                for (const rt::WeldedRange& r : ranges) {
                    fill_marker(v);
                    std::fill(idx.begin(), idx.end(), marker);
                    REQUIRE(rt::emit_welded_mesh(rt::cp_tables_64, uniform_set(), mesh, o, s.edges, s.patches,
                                                 r, v, idx) == rt::PipelineStatus::ok);
                    const std::vector<std::uint32_t> w = words(v, idx);
                    for (std::size_t j = 0; j < w.size(); ++j)
                        if (w[j] != marker) {
                            ++writers[j];
                            if (w[j] != expected[j]) FAIL_CHECK("range wrote another value at word " << j);
                        }
                }
                std::size_t twice = 0, never = 0;
                for (std::size_t j = 0; j < writers.size(); ++j) {
                    twice += writers[j] > 1;
                    never += writers[j] == 0 && expected[j] != marker;
                }
                CHECK(twice == 0);
                CHECK(never == 0);
            }
            // Two threads at once on one pair of buffers.
            std::vector<rt::TessVertex> v(s.totals.vertices);
            std::vector<std::uint32_t> idx(3 * std::size_t{s.totals.triangles});
            rt::PipelineStatus status[2];
            std::vector<std::thread> threads;
            for (std::uint32_t k = 0; k < 2; ++k)
                threads.emplace_back([&, k] {
                    status[k] =
                        rt::emit_welded_mesh(rt::cp_tables_64, uniform_set(), mesh, o, s.edges, s.patches,
                                             rt::welded_range(mesh, s.patches, k, 2), v, idx);
                });
            for (std::thread& t : threads) t.join();
            CHECK(status[0] == rt::PipelineStatus::ok);
            CHECK(status[1] == rt::PipelineStatus::ok);
            CHECK(words(v, idx) == expected);
        }
    }
}

TEST_CASE("welded output in ranges: ranges outside the patches, bad offsets and bad counts write nothing") {
    const Model m = torus_with_strays();
    const rt::MeshView mesh = m.view();
    const auto patch_count = static_cast<std::uint32_t>(mesh.patch_count());
    const rt::PipelineOptions o = camera(rt::Pattern::cp, {0.5f, -9.0f, 3.0f}, 2.0f);
    const WeldedSetup s = setup(mesh, o);
    REQUIRE(s.status == rt::PipelineStatus::ok);
    std::vector<rt::TessVertex> v(s.totals.vertices);
    std::vector<std::uint32_t> idx(3 * std::size_t{s.totals.triangles}, marker);
    fill_marker(v);
    const std::vector<std::uint32_t> untouched = words(v, idx);
    const auto emit = [&](const std::vector<rt::WeldedPatch>& patches, rt::WeldedRange r) {
        return rt::emit_welded_mesh(rt::cp_tables_64, uniform_set(), mesh, o, s.edges, patches, r, v, idx);
    };
    CHECK(emit(s.patches, {5, 4}) == rt::PipelineStatus::bad_range);
    CHECK(emit(s.patches, {0, patch_count + 1}) == rt::PipelineStatus::bad_range);
    CHECK(emit(s.patches, {patch_count + 1, patch_count + 1}) == rt::PipelineStatus::bad_range);
    // Offsets are checked over every patch (a range never overlaps another), counts over the range's own.
    auto bad = s.patches;
    bad[patch_count - 2].vertex_count += 1;
    CHECK(emit(bad, {0, 3}) == rt::PipelineStatus::bad_patch_record);
    bad = s.patches;
    bad.back().triangle_count += 1; // the last record's counts: only its own range reruns them
    CHECK(emit(bad, {patch_count - 1, patch_count}) == rt::PipelineStatus::bad_patch_record);
    // Empty ranges write nothing, also at the end; the range of the last patch writes the vertex no face
    // reaches (the stray vertex, last of the mesh).
    CHECK(emit(s.patches, {3, 3}) == rt::PipelineStatus::ok);
    CHECK(emit(s.patches, {patch_count, patch_count}) == rt::PipelineStatus::ok);
    CHECK(words(v, idx) == untouched);
    CHECK(emit(s.patches, {patch_count - 1, patch_count}) == rt::PipelineStatus::ok);
    const std::uint32_t stray = static_cast<std::uint32_t>(m.vertices.size() / 8 - 1);
    CHECK(v[stray].position[0] == 9.0f);
    CHECK(v[stray].position[2] == 9.0f);
    // welded_range: parts 0 is one part; a part past the last is empty at the end.
    CHECK(rt::welded_range(mesh, s.patches, 0, 0).end_patch == patch_count);
    const rt::WeldedRange past = rt::welded_range(mesh, s.patches, 5, 2);
    CHECK(past.first_patch == patch_count);
    CHECK(past.end_patch == patch_count);
    CHECK(rt::welded_range(mesh, {}, 0, 2).end_patch == 0);
    // Records past the mesh's patches are not cut into ranges.
    std::vector<rt::WeldedPatch> longer = s.patches;
    longer.resize(longer.size() + 5, longer.back());
    CHECK(rt::welded_range(mesh, longer, 1, 2).end_patch == patch_count);

    // A mesh without faces has no ranges (each would be {0, 0} and write the same vertices): bad_range, and
    // the call without a range writes its vertices.
    Model bare;
    bare.add(1.0f, 2.0f, 3.0f, 0.0f, 0.0f, 1.0f, 0.5f, 0.5f);
    bare.add(4.0f, 5.0f, 6.0f, 0.0f, 0.0f, 1.0f, 0.5f, 0.5f);
    const rt::MeshView faceless = bare.view();
    const WeldedSetup b = setup(faceless, o);
    REQUIRE(b.status == rt::PipelineStatus::ok);
    REQUIRE(b.totals.vertices == 2);
    std::vector<rt::TessVertex> bv(2);
    std::vector<std::uint32_t> bi;
    const rt::WeldedRange only = rt::welded_range(faceless, b.patches, 0, 2);
    CHECK(only.first_patch == 0);
    CHECK(only.end_patch == 0);
    CHECK(rt::emit_welded_mesh(rt::cp_tables_64, uniform_set(), faceless, o, b.edges, b.patches, only, bv,
                               bi) == rt::PipelineStatus::bad_range);
    CHECK(bv[1].position[0] == 0.0f);
    CHECK(rt::emit_welded_mesh(rt::cp_tables_64, uniform_set(), faceless, o, b.edges, b.patches, bv, bi) ==
          rt::PipelineStatus::ok);
    CHECK(bv[1].position[0] == 4.0f);
}

// Figures for docs/algorithm.md §7 (run by hand: test_mesh_pipeline_weld "[figures]").
TEST_CASE("figures: longest output edge, zero-area fraction, weld ratio", "[.][figures]") {
    const rt::Vec3 eye{0.5f, -9.0f, 3.0f};
    const Model quads = torus(48, 6, Faces::quads), tris = torus(48, 6, Faces::triangles);
    for (const rt::QuadRule rule : {rt::QuadRule::as_labelled, rt::QuadRule::longer_pair}) {
        rt::PipelineOptions o = camera(rt::Pattern::cp, eye, 2.0f);
        o.quad_rule = rule;
        const auto s = longest_edge_stats(unwelded(quads.view(), o), o.dice);
        std::printf("quad torus 48x6 CP, %s: longest edge p50 %.2f p99 %.2f max %.2f\n",
                    rule == rt::QuadRule::as_labelled ? "as labelled" : "longer pair", s[0], s[1], s[2]);
    }
    for (const rt::Pattern pattern : {rt::Pattern::cp, rt::Pattern::uniform}) {
        const char* name = pattern == rt::Pattern::cp ? "CP" : "uniform";
        rt::PipelineOptions o = camera(pattern, eye, 2.0f);
        const auto t = longest_edge_stats(unwelded(tris.view(), o), o.dice);
        const auto q = longest_edge_stats(unwelded(quads.view(), o), o.dice);
        std::printf("%s triangle torus: p50 %.2f p99 %.2f max %.2f; quad torus: p50 %.2f p99 %.2f max %.2f\n",
                    name, t[0], t[1], t[2], q[0], q[1], q[2]);
        for (const auto* m : {&tris, &quads}) {
            const Output u = unwelded(m->view(), o), w = welded(m->view(), o);
            std::size_t coincident = 0, zero_area = 0;
            for (std::size_t i = 0; i < u.indices.size(); i += 3) {
                const rt::TessVertex& a = u.vertices[u.indices[i]];
                const rt::TessVertex& b = u.vertices[u.indices[i + 1]];
                const rt::TessVertex& c = u.vertices[u.indices[i + 2]];
                const bool co = !std::memcmp(a.position, b.position, 12) ||
                                !std::memcmp(b.position, c.position, 12) ||
                                !std::memcmp(a.position, c.position, 12);
                const double e1[3] = {double(b.position[0]) - a.position[0],
                                      double(b.position[1]) - a.position[1],
                                      double(b.position[2]) - a.position[2]};
                const double e2[3] = {double(c.position[0]) - a.position[0],
                                      double(c.position[1]) - a.position[1],
                                      double(c.position[2]) - a.position[2]};
                const double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2],
                             cz = e1[0] * e2[1] - e1[1] * e2[0];
                coincident += co;
                zero_area += (cx * cx + cy * cy + cz * cz) < 1e-20;
            }
            const double n = static_cast<double>(u.indices.size() / 3);
            std::printf(
                "  %s %s: %zu triangles, %zu (%.2f%%) with coincident corners, %.2f%% zero area; welded %zu "
                "triangles; vertices %zu unwelded / %zu welded = %.2f\n",
                name, m == &tris ? "triangle torus" : "quad torus", u.indices.size() / 3, coincident,
                100.0 * static_cast<double>(coincident) / n, 100.0 * static_cast<double>(zero_area) / n,
                w.indices.size() / 3, u.vertices.size(), w.vertices.size(),
                static_cast<double>(u.vertices.size()) / static_cast<double>(w.vertices.size()));
        }
    }
}
