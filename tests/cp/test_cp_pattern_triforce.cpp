// CP triangle pattern with equal factors (docs/algorithm.md §2.10, §2.14): exact uniform
// triforce at every power of two, and the table of counts for both column rules.
#include <catch2/catch.hpp>

#include <ctess/cp/pattern.hpp>

#include <array>
#include <vector>

#include "support/cp_harness.hpp"
#include "support/mesh_checks.hpp"
#include "support/triforce_grid.hpp"

using namespace ctess;
using namespace ctess::test;

namespace {

cp::PatternOptions options(unsigned max_factor, cp::ColumnRule rule, bool collapse = true,
                           bool provoking = false) {
    cp::PatternOptions o;
    o.max_factor = max_factor;
    o.column_rule = rule;
    o.collapse_t0 = collapse;
    o.layout = provoking ? Layout::provoking : Layout::shared;
    return o;
}

constexpr cp::PatternOptions flat64() {
    cp::PatternOptions o;
    o.max_factor = 64;
    o.layout = Layout::shared;
    return o;
}
static_assert(cp::pattern_counts(8.0f, 8.0f, 8.0f, flat64()) == Counts{45, 64});
static_assert(cp::pattern_counts(1.5f, 1.5f, 1.5f, flat64()) == Counts{10, 9});

constexpr std::uint32_t triforce_vertices(std::uint32_t n) {
    return (n + 1) * (n + 2) / 2;
}

// d_T, the deficit of the independent prototype's equal-factor table: rule (b) emits N^2 - d_T triangles for
// equal tokens T >= T2.
constexpr std::array<std::uint32_t, 25> rule_b_deficit{0,  0,  0,  6, 0,  6,  10,  18, 0,  10,  18,  34, 0,
                                                       18, 34, 66, 0, 34, 66, 130, 0,  66, 130, 258, 0};

} // namespace

TEST_CASE("cp triforce: equal powers of two are exactly the uniform triforce grid",
          "[cp_pattern][triforce]") {
    for (unsigned max_factor : {64u, 256u})
        for (std::uint32_t n = 4; n <= max_factor; n *= 2) {
            const TriforceGrid g = triforce_grid(n, cp::fixed_one);
            const auto grid = all_triangles({g.vertices, g.indices});
            const auto f = static_cast<float>(n);
            for (cp::ColumnRule rule : {cp::ColumnRule::minimal, cp::ColumnRule::staircase})
                for (bool collapse : {true, false}) {
                    INFO("max " << max_factor << " N " << n << " rule "
                                << (rule == cp::ColumnRule::minimal ? "b" : "a")
                                << (collapse ? " collapse" : " no-collapse"));
                    CpRunner run(options(max_factor, rule, collapse));
                    const MeshView m = run.run(f, f, f);
                    REQUIRE(run.counts() == Counts{triforce_vertices(n), n * n});
                    REQUIRE(area_stats(m).degenerate == 0);
                    REQUIRE(all_triangles(m) ==
                            grid); // positions are exactly (i/N, j/N), cells as the grid's

                    CpRunner provoking(options(max_factor, rule, collapse, true));
                    const MeshView p = provoking.run(f, f, f);
                    REQUIRE(provoking.counts().triangles == n * n);
                    REQUIRE(unique_first_index(p));
                    REQUIRE(all_triangles(p) == grid);
                }
        }
}

TEST_CASE("cp triforce: equal-factor counts (docs/algorithm.md §2.14)", "[cp_pattern][triforce]") {
    struct Row {
        float f;
        std::uint32_t vertices_b, triangles_b, degenerate_b, vertices_a, triangles_a, degenerate_a;
    };
    std::vector<Row> rows = {
        {1, 3, 1, 0, 3, 1, 0},
        {1.5f, 10, 9, 0, 10, 9, 0},
        {2, 10, 9, 5, 10, 9, 5},
        {4, 15, 16, 0, 15, 16, 0},
        {8, 45, 64, 0, 45, 64, 0},
        {16, 153, 256, 0, 153, 256, 0},
        {32, 561, 1024, 0, 561, 1024, 0},
        {64, 2145, 4096, 0, 2145, 4096, 0},
        {128, triforce_vertices(128), 128 * 128, 0, triforce_vertices(128), 128 * 128, 0},
        {256, triforce_vertices(256), 256 * 256, 0, triforce_vertices(256), 256 * 256, 0},
        {5, 25, 30, 0, 28, 36, 6},
        {10.3f, 86, 134, 0, 91, 144, 10},
        {24, 316, 558, 0, 325, 576, 18},
        {48, 1208, 2270, 0, 1225, 2304, 34},
    };
    for (unsigned max_factor : {64u, 256u})
        for (const Row& r : rows) {
            if (r.f > static_cast<float>(max_factor)) continue;
            INFO("max " << max_factor << " f " << r.f);
            CpRunner b(options(max_factor, cp::ColumnRule::minimal));
            CpRunner a(options(max_factor, cp::ColumnRule::staircase));
            const MeshView mb = b.run(r.f, r.f, r.f);
            const MeshView ma = a.run(r.f, r.f, r.f);
            CHECK(b.counts() == Counts{r.vertices_b, r.triangles_b});
            CHECK(area_stats(mb).degenerate == r.degenerate_b);
            CHECK(a.counts() == Counts{r.vertices_a, r.triangles_a});
            CHECK(area_stats(ma).degenerate == r.degenerate_a);
            CHECK(surface_triangles(ma) == surface_triangles(mb));
        }
}

TEST_CASE("cp triforce: Type 1 at f = 2 is the n = 2 triforce, at f = 1.5 the N = 3 topology",
          "[cp_pattern][triforce]") {
    for (unsigned max_factor : {64u, 256u}) {
        CpRunner run(options(max_factor, cp::ColumnRule::minimal));
        const TriforceGrid g2 = triforce_grid(2, cp::fixed_one);
        REQUIRE(surface_triangles(run.run(2.0f, 2.0f, 2.0f)) == surface_triangles({g2.vertices, g2.indices}));
        const MeshView m = run.run(1.5f, 1.5f, 1.5f);
        REQUIRE(run.counts() == Counts{10, 9});
        REQUIRE(area_stats(m).degenerate == 0);
        REQUIRE(index_topology(m).euler == 1);
    }
}

TEST_CASE("cp triforce: equal tokens give N^2 with rule (a) and N^2 - d_T with rule (b)",
          "[cp_pattern][triforce]") {
    // Counts depend on tokens only, so any lerps (equal or not) give them. Rule (a)'s d_T extra triangles are
    // all zero-area and the surfaces are the same. Rule (b) itself is not free of zero-area triangles at
    // every lerp: columns are sized for the worst lerp, so e.g. T2 at t = 1/2 (f = 3) has 2; §7.3 lists 0
    // only for its rows.
    for (unsigned max_factor : {64u, 256u}) {
        Rng rng(max_factor);
        for (unsigned token = 2; token < cp::token_count(max_factor); ++token) {
            const std::uint32_t n = cp::token_info(token).segments;
            const std::uint32_t d = rule_b_deficit[token];
            CpRunner b(options(max_factor, cp::ColumnRule::minimal));
            CpRunner a(options(max_factor, cp::ColumnRule::staircase));
            for (std::uint32_t t : {cp::lerp_one / 2, cp::lerp_one, rng.inner_lerp()}) {
                INFO("max " << max_factor << " T" << token << " t16 " << t);
                const cp::LineState s{token, t};
                const MeshView mb = b.run(s, s, s);
                const MeshView ma = a.run(s, s, s);
                CHECK(b.counts().triangles == n * n - d);
                CHECK(a.counts() == Counts{triforce_vertices(n), n * n});
                CHECK(area_stats(ma).degenerate == area_stats(mb).degenerate + d);
                CHECK(surface_triangles(ma) == surface_triangles(mb));
            }
            for (int k = 0; k < 3; ++k) { // unequal lerps, token starts included
                const cp::LineState s0{token, k == 0 ? 0 : rng.lerp()}, s1{token, rng.lerp()},
                    s2{token, rng.lerp()};
                INFO("max " << max_factor << " " << describe(s0, s1, s2));
                b.run(s0, s1, s2);
                a.run(s0, s1, s2);
                CHECK(b.counts().triangles == n * n - d);
                CHECK(a.counts() == Counts{triforce_vertices(n), n * n});
            }
        }
    }
}
