// CP triangle pattern: type selection, exact tiling, no inversion, no fins, watertight boundaries, provoking
// layout, bad input (docs/algorithm.md §2.2 to §2.10).
#include <catch2/catch.hpp>

#include <ctess/cp/pattern.hpp>

#include <array>
#include <cstdio>
#include <limits>
#include <vector>

#include "support/cp_harness.hpp"
#include "support/mesh_checks.hpp"
#include "support/triforce_grid.hpp"

using namespace ctess;
using namespace ctess::test;

namespace {

constexpr cp::PatternOptions flat_options(unsigned max_factor) {
    cp::PatternOptions o;
    o.max_factor = max_factor;
    o.layout = Layout::shared;
    return o;
}

// Constant-evaluation proofs of every public function.
static_assert(cp::pattern_type(state(0, 0), state(0, 0), state(0, 0)) == cp::PatternType::single);
static_assert(cp::pattern_type(state(1, 5), state(16, 7), state(0, 0)) == cp::PatternType::fan);
static_assert(cp::pattern_type(state(2, 0), state(0, 0), state(1, 0)) == cp::PatternType::parallelogram);
static_assert(cp::pattern_counts(1.0f, 1.0f, 1.0f, flat_options(64)) == Counts{3, 1});
static_assert(cp::pattern_counts(64.0f, 1.0f, 1.0f, flat_options(64)) == Counts{66, 64}); // §7.4
static_assert(cp::pattern_counts(4.0f, 8.0f, 16.0f, flat_options(64)) == Counts{40, 50}); // §7.4
constexpr bool max_counts_bound_the_largest_pattern() {
    const Counts big = cp::pattern_counts(16.0f, 16.0f, 16.0f, default_options(64));
    const Counts cap = cp::max_pattern_counts(64);
    return big.vertices <= cap.vertices && big.triangles <= cap.triangles && cap.triangles >= 64 * 64;
}
static_assert(max_counts_bound_the_largest_pattern());
// Filling in a constant expression: (4, 4, 4) is the N = 4 triforce (§7.3) and includes the corner v1.
constexpr bool fills_triforce_4() {
    std::array<DomainPoint, 15> v{};
    std::array<std::uint32_t, 48> i{};
    const Counts c = cp::tessellate(v, i, 4.0f, 4.0f, 4.0f, flat_options(64));
    bool has_v1 = false;
    for (DomainPoint p : v) has_v1 = has_v1 || (p.u == cp::fixed_one && p.v == 0);
    return c == Counts{15, 16} && has_v1;
}
static_assert(fills_triforce_4());
constexpr bool fills_from_states() {
    std::array<DomainPoint, 3> v{};
    std::array<std::uint32_t, 3> i{};
    const Counts c = cp::tessellate(v, i, state(0, 0), state(0, 0), state(0, 0), flat_options(64));
    return c == Counts{3, 1} && v[i[0]] == DomainPoint{0, 0} && v[i[1]] == DomainPoint{cp::fixed_one, 0} &&
           v[i[2]] == DomainPoint{0, cp::fixed_one};
}
static_assert(fills_from_states());

// Checks one mesh of the runner's options; returns "" or the failures. Also checks the count-only call.
std::string check_state_triple(CpRunner& run, cp::LineState s0, cp::LineState s1, cp::LineState s2,
                               const std::vector<std::uint32_t>& p0, const std::vector<std::uint32_t>& p1,
                               const std::vector<std::uint32_t>& p2, std::size_t& degenerate) {
    const MeshView m = run.run(s0, s1, s2);
    if (!run.within_capacity()) return "counts exceed max_pattern_counts";
    std::string out;
    const Counts counted = cp::tessellate({}, {}, s0, s1, s2, run.options());
    if (!(counted == run.counts())) out += "count-only call differs; ";
    const ValidityReport r = check_valid_tessellation(m, cp::fixed_one, p0, p1, p2);
    out += r.failures;
    degenerate += r.area.degenerate;
    if (run.options().layout == Layout::provoking && !unique_first_index(m))
        out += "first index not unique; ";
    if (run.options().layout == Layout::shared) {
        const IndexTopology t = index_topology(m);
        if (!t.no_repeated_index) out += "a triangle repeats an index; ";
        if (!t.edges_unique) out += "a directed index edge is used twice; ";
        if (!t.single_boundary_loop) out += "index boundary is not one loop; ";
        if (t.euler != 1) out += cat("index Euler characteristic ", t.euler, "; ");
    }
    return out;
}

// All token triples at the given lerps, with e0's token in [first, last].
void validate_token_triples(const cp::PatternOptions& options, std::span<const std::uint32_t> lerps,
                            unsigned first, unsigned last) {
    const std::vector<cp::LineState> states = token_states(options.max_factor, lerps);
    std::vector<std::vector<std::uint32_t>> points;
    for (cp::LineState s : states) points.push_back(line_points(s));
    CpRunner run(options);
    FailureLog log;
    std::size_t meshes = 0, triangles = 0, degenerate = 0;
    for (std::size_t a = 0; a < states.size(); ++a) {
        if (states[a].token < first || states[a].token > last) continue;
        for (std::size_t b = 0; b < states.size(); ++b)
            for (std::size_t c = 0; c < states.size(); ++c) {
                const std::string f = check_state_triple(run, states[a], states[b], states[c], points[a],
                                                         points[b], points[c], degenerate);
                ++meshes;
                triangles += run.counts().triangles;
                if (!f.empty()) log.add(cat(describe(states[a], states[b], states[c]), ": ", f));
            }
    }
    std::printf("cp validity max %u e0 T%u..T%u: %zu meshes, %zu triangles, %zu zero-area, %zu failing\n",
                options.max_factor, first, last, meshes, triangles, degenerate, log.count);
    INFO(log.summary());
    REQUIRE(log.count == 0);
}

constexpr std::array<std::uint32_t, 3> zero_half_one{0, cp::lerp_one / 2, cp::lerp_one};

// Random token triples with lerps drawn from {0, 1, random inner}, or random float factors.
void validate_random(const cp::PatternOptions& options, std::size_t count, std::uint64_t seed,
                     bool from_floats) {
    Rng rng(seed);
    CpRunner run(options);
    FailureLog log;
    std::size_t degenerate = 0;
    const unsigned tokens = cp::token_count(options.max_factor);
    for (std::size_t n = 0; n < count; ++n) {
        std::array<cp::LineState, 3> s;
        std::array<float, 3> f{};
        for (unsigned e = 0; e < 3; ++e) {
            if (from_floats) {
                f[e] = rng.factor(0.5f, static_cast<float>(options.max_factor) + 1.0f);
                s[e] = cp::line_state(f[e], options.max_factor);
            } else {
                const std::uint32_t pick = rng.below(4);
                s[e] = state(rng.below(tokens), pick == 0 ? 0 : pick == 1 ? cp::lerp_one : rng.inner_lerp());
            }
        }
        const std::string failures = check_state_triple(run, s[0], s[1], s[2], line_points(s[0]),
                                                        line_points(s[1]), line_points(s[2]), degenerate);
        std::string extra;
        if (from_floats) {
            // The float entry points are line_state() of each factor, then the state overload.
            const MeshView by_state = run.run(s[0], s[1], s[2]);
            const std::vector<DomainPoint> v(by_state.vertices.begin(), by_state.vertices.end());
            const std::vector<std::uint32_t> i(by_state.indices.begin(), by_state.indices.end());
            const MeshView m = run.run(f[0], f[1], f[2]);
            if (!std::equal(v.begin(), v.end(), m.vertices.begin(), m.vertices.end()) ||
                !std::equal(i.begin(), i.end(), m.indices.begin(), m.indices.end()))
                extra += "float overload differs from the state overload; ";
            if (!(cp::pattern_counts(f[0], f[1], f[2], options) == run.counts()))
                extra += "pattern_counts differs; ";
        }
        if (!failures.empty() || !extra.empty()) {
            std::string what = describe(s[0], s[1], s[2]);
            if (from_floats) what += cat(" f=(", f[0], ", ", f[1], ", ", f[2], ")");
            log.add(cat(what, ": ", failures, extra));
        }
    }
    std::printf("cp validity max %u random %s: %zu meshes, %zu zero-area, %zu failing\n", options.max_factor,
                from_floats ? "factors" : "token states", count, degenerate, log.count);
    INFO(log.summary());
    REQUIRE(log.count == 0);
}

} // namespace

TEST_CASE("cp pattern: mesh checks detect defects", "[cp_pattern][mesh_checks]") {
    STATIC_REQUIRE(signed_area2(DomainPoint{0, 0}, DomainPoint{4, 0}, DomainPoint{0, 2}) == 8);
    STATIC_REQUIRE(signed_area2(DomainPoint{0, 0}, DomainPoint{0, 2}, DomainPoint{4, 0}) == -8);
    STATIC_REQUIRE(canonical_rotation({DomainPoint{5, 0}, {0, 9}, {0, 1}})[0] == DomainPoint{0, 1});
    STATIC_REQUIRE(canonical_rotation({DomainPoint{5, 0}, {0, 9}, {0, 1}})[1] == DomainPoint{5, 0});
    // The reference triforce passes; each defect is caught by the check meant for it.
    const TriforceGrid g = triforce_grid(4, cp::fixed_one);
    const auto p = uniform_params(4, cp::fixed_one);
    const MeshView good{g.vertices, g.indices};
    REQUIRE(check_valid_tessellation(good, cp::fixed_one, p, p, p).ok());
    REQUIRE(index_topology(good).euler == 1);
    REQUIRE(index_topology(good).single_boundary_loop);
    REQUIRE_FALSE(unique_first_index(good)); // shared vertices lead several triangles

    std::vector<std::uint32_t> flipped = g.indices;
    std::swap(flipped[0], flipped[1]);
    const ValidityReport r_flip = check_valid_tessellation({g.vertices, flipped}, cp::fixed_one, p, p, p);
    REQUIRE(r_flip.area.inverted == 1);
    REQUIRE_FALSE(r_flip.area.covers(cp::fixed_one));

    std::vector<std::uint32_t> holed(g.indices.begin() + 3, g.indices.end());
    const ValidityReport r_hole = check_valid_tessellation({g.vertices, holed}, cp::fixed_one, p, p, p);
    REQUIRE_FALSE(r_hole.ok());
    REQUIRE_FALSE(r_hole.area.covers(cp::fixed_one));

    // A T-junction: split the first triangle's edge e0 at an extra vertex seen only from one side.
    std::vector<DomainPoint> tv = g.vertices;
    std::vector<std::uint32_t> ti = g.indices;
    const auto mid = static_cast<std::uint32_t>(tv.size());
    tv.push_back(
        {(g.vertices[ti[1]].u + g.vertices[ti[2]].u) / 2, (g.vertices[ti[1]].v + g.vertices[ti[2]].v) / 2});
    const std::array<std::uint32_t, 3> first{ti[0], ti[1], ti[2]};
    ti.erase(ti.begin(), ti.begin() + 3);
    ti.insert(ti.end(), {first[0], first[1], mid, first[0], mid, first[2]});
    const ValidityReport r_t = check_valid_tessellation({tv, ti}, cp::fixed_one, p, p, p);
    REQUIRE(r_t.area.covers(cp::fixed_one));
    REQUIRE(r_t.area.inverted == 0);
    REQUIRE_FALSE(r_t.ok()); // the open edges are not the boundary loop
    // Closing it with the zero-area sliver (1, mid, 2) is exactly a fin.
    ti.insert(ti.end(), {first[1], first[2], mid});
    REQUIRE(area_stats({tv, ti}).fins == 1);

    // Wrong boundary points are caught.
    const auto p8 = uniform_params(8, cp::fixed_one);
    REQUIRE_FALSE(check_valid_tessellation(good, cp::fixed_one, p8, p, p).ok());

    // Duplicating vertices keeps the surface.
    std::vector<DomainPoint> dv = g.vertices;
    std::vector<std::uint32_t> di = g.indices;
    for (std::size_t t = 0; t < di.size(); t += 3) {
        dv.push_back(dv[di[t]]);
        di[t] = static_cast<std::uint32_t>(dv.size() - 1);
    }
    REQUIRE(unique_first_index({dv, di}));
    REQUIRE(surface_triangles({dv, di}) == surface_triangles(good));
    REQUIRE(surface_triangles({g.vertices, flipped}) != surface_triangles(good));
}

TEST_CASE("cp pattern: max_pattern_counts bounds every pattern under every option", "[cp_pattern]") {
    // Count-only calls over token triples (all at max 64, T18..T24 at max 256: the largest), all 8 options.
    // Counts depend on tokens only (the index buffer is fixed inside a token triple, test_cp_pattern_pops).
    for (unsigned max_factor : {64u, 256u}) {
        const Counts cap = cp::max_pattern_counts(max_factor);
        const unsigned tokens = cp::token_count(max_factor);
        const unsigned first = max_factor == 64 ? 0 : 18;
        Counts worst{};
        FailureLog log;
        for (int variant = 0; variant < 8; ++variant) {
            cp::PatternOptions o;
            o.max_factor = max_factor;
            o.column_rule = (variant & 1) ? cp::ColumnRule::staircase : cp::ColumnRule::minimal;
            o.collapse_t0 = (variant & 2) == 0;
            o.layout = (variant & 4) == 0 ? Layout::provoking : Layout::shared;
            for (unsigned a = first; a < tokens; ++a)
                for (unsigned b = first; b < tokens; ++b)
                    for (unsigned c = first; c < tokens; ++c)
                        for (std::uint32_t t : {cp::lerp_one}) {
                            const Counts n = cp::tessellate({}, {}, state(a, t), state(b, t), state(c, t), o);
                            worst.vertices = std::max(worst.vertices, n.vertices);
                            worst.triangles = std::max(worst.triangles, n.triangles);
                            if (n.vertices > cap.vertices || n.triangles > cap.triangles)
                                log.add(cat(describe(state(a, t), state(b, t), state(c, t)), " options ",
                                            variant, ": ", n.vertices, " vertices, ", n.triangles,
                                            " triangles"));
                        }
        }
        std::printf("cp max_pattern_counts(%u) = {%u, %u}; largest seen {%u, %u}\n", max_factor, cap.vertices,
                    cap.triangles, worst.vertices, worst.triangles);
        INFO("max " << max_factor << ": " << log.summary());
        REQUIRE(log.count == 0);
    }
}

TEST_CASE("cp pattern: type selection from tokens alone (docs/algorithm.md §2.2)", "[cp_pattern]") {
    for (unsigned a = 0; a < 25; ++a)
        for (unsigned b = 0; b < 25; ++b)
            for (unsigned c = 0; c < 25; ++c) {
                const cp::PatternType expected = (a == 0 && b == 0 && c == 0) ? cp::PatternType::single
                                                 : (a <= 1 && c <= 1)         ? cp::PatternType::fan
                                                                      : cp::PatternType::parallelogram;
                for (std::uint32_t t : {0u, 30000u, cp::lerp_one})
                    if (cp::pattern_type(state(a, t), state(b, t), state(c, t)) != expected) {
                        INFO("tokens " << a << ", " << b << ", " << c << " t16 " << t);
                        REQUIRE(cp::pattern_type(state(a, t), state(b, t), state(c, t)) == expected);
                    }
            }
}

TEST_CASE("cp pattern: Type 0 is the single domain triangle", "[cp_pattern]") {
    for (unsigned max_factor : {64u, 256u})
        for (bool provoking : {false, true})
            for (float f : {1.0f, 0.5f, 0.0f}) {
                cp::PatternOptions o;
                o.max_factor = max_factor;
                o.layout = provoking ? Layout::provoking : Layout::shared;
                CpRunner run(o);
                const MeshView m = run.run(f, f, 1.0f);
                REQUIRE(run.counts() == Counts{3, 1});
                REQUIRE(all_triangles(m) == std::vector<PositionTriangle>{
                                                {DomainPoint{0, 0}, {cp::fixed_one, 0}, {0, cp::fixed_one}}});
            }
}

TEST_CASE("cp pattern: every token triple at t in {0, 1/2, 1} tiles exactly, max 64, e0 T0..T9",
          "[cp_pattern]") {
    validate_token_triples(default_options(64), zero_half_one, 0, 9);
}
TEST_CASE("cp pattern: every token triple at t in {0, 1/2, 1} tiles exactly, max 64, e0 T10..T13",
          "[cp_pattern]") {
    validate_token_triples(default_options(64), zero_half_one, 10, 13);
}
TEST_CASE("cp pattern: every token triple at t in {0, 1/2, 1} tiles exactly, max 64, e0 T14..T16",
          "[cp_pattern]") {
    validate_token_triples(default_options(64), zero_half_one, 14, 16);
}

TEST_CASE("cp pattern: Type 1 over a dense lerp grid of e0 and e2, every e1 token", "[cp_pattern]") {
    // The sliding point P must stay strictly inside the hexagon for every (t0, t2) and every e1 state
    // (docs/algorithm.md §2.8): 37 lerps per edge plus T0, e1 in every token at t in {0, 1/2, 1}, both
    // layouts.
    std::vector<cp::LineState> small{{0, 0}};
    for (std::uint32_t k = 0; k <= 36; ++k) small.push_back({1, (k * cp::lerp_one + 18) / 36});
    const std::vector<cp::LineState> e1_states = token_states(64, zero_half_one);
    for (bool provoking : {true, false}) {
        cp::PatternOptions o = default_options(64);
        o.layout = provoking ? Layout::provoking : Layout::shared;
        CpRunner run(o);
        FailureLog log;
        std::size_t degenerate = 0, meshes = 0;
        for (cp::LineState s0 : small)
            for (cp::LineState s2 : small)
                for (cp::LineState s1 : e1_states) {
                    if (s0.token == 0 && s2.token == 0 && s1.token == 0) continue; // Type 0
                    ++meshes;
                    std::string f =
                        cp::pattern_type(s0, s1, s2) == cp::PatternType::fan ? "" : "not Type 1; ";
                    f += check_state_triple(run, s0, s1, s2, line_points(s0), line_points(s1),
                                            line_points(s2), degenerate);
                    if (!f.empty()) log.add(cat(describe(s0, s1, s2), ": ", f));
                }
        std::printf("cp validity Type 1 sweep (%s): %zu meshes, %zu zero-area, %zu failing\n",
                    provoking ? "provoking" : "flat", meshes, degenerate, log.count);
        INFO(log.summary());
        REQUIRE(log.count == 0);
    }
}

TEST_CASE("cp pattern: random factors and token states tile exactly, max 64", "[cp_pattern]") {
    validate_random(default_options(64), 3000, 0x5eed64, true);
    validate_random(default_options(64), 3000, 0x64, false);
}

TEST_CASE("cp pattern: random factors and token states tile exactly, max 256", "[cp_pattern]") {
    cp::PatternOptions o;
    o.max_factor = 256;
    validate_random(o, 250, 0x5eed256, true);
    validate_random(o, 250, 0x256, false);
}

TEST_CASE("cp pattern: non-default options tile exactly and keep the surface", "[cp_pattern]") {
    // Staircase rule (a), no T0 collapse, flat layout: each is valid, and the rule and the collapse only add
    // or remove zero-area triangles (docs/algorithm.md §2.4, §2.9), so the non-degenerate surface is
    // unchanged.
    for (unsigned max_factor : {64u, 256u}) {
        Rng rng(max_factor * 7919u);
        const unsigned tokens = cp::token_count(max_factor);
        FailureLog log;
        const std::size_t count = max_factor == 64 ? 1500 : 120;
        for (std::size_t n = 0; n < count; ++n) {
            std::array<cp::LineState, 3> s;
            for (auto& e : s) {
                // Small tokens are where the rules differ most: draw T0..T3 half of the time.
                const unsigned tok = rng.below(2) == 0 ? rng.below(4) : rng.below(tokens);
                const std::uint32_t pick = rng.below(4);
                e = state(tok, pick == 0 ? 0 : pick == 1 ? cp::lerp_one : rng.inner_lerp());
            }
            std::vector<PositionTriangle> reference;
            for (int variant = 0; variant < 8; ++variant) {
                cp::PatternOptions o;
                o.max_factor = max_factor;
                o.column_rule = (variant & 1) ? cp::ColumnRule::staircase : cp::ColumnRule::minimal;
                o.collapse_t0 = (variant & 2) == 0;
                o.layout = (variant & 4) == 0 ? Layout::provoking : Layout::shared;
                CpRunner run(o);
                std::size_t degenerate = 0;
                std::string f = check_state_triple(run, s[0], s[1], s[2], line_points(s[0]),
                                                   line_points(s[1]), line_points(s[2]), degenerate);
                const auto surface = surface_triangles(run.run(s[0], s[1], s[2]));
                if (variant == 0)
                    reference = surface;
                else if (surface != reference)
                    f += "surface differs from the default options; ";
                if (!f.empty())
                    log.add(cat(describe(s[0], s[1], s[2]), " rule ", (variant & 1) ? "a" : "b",
                                (variant & 2) ? " no-collapse" : " collapse",
                                (variant & 4) ? " flat" : " provoking", ": ", f));
            }
        }
        INFO("max " << max_factor << ": " << log.summary());
        REQUIRE(log.count == 0);
    }
}

TEST_CASE("cp pattern: unequal-factor counts (docs/algorithm.md §2.14)", "[cp_pattern]") {
    struct Row {
        float f0, f1, f2;
        cp::PatternType type;
        std::uint32_t vertices, triangles, non_degenerate;
    };
    using PT = cp::PatternType;
    const Row rows[] = {
        {16, 8, 4, PT::parallelogram, 49, 68, 68},
        {4, 8, 16, PT::parallelogram, 40, 50, 50},
        {8, 16, 4, PT::parallelogram, 37, 44, 44},
        {32, 32, 8, PT::parallelogram, 177, 280, 280},
        {8, 32, 32, PT::parallelogram, 156, 238, 238},
        {5, 9, 3, PT::parallelogram, 26, 30, 26},
        {3, 9, 5, PT::parallelogram, 24, 26, 22},
        {64, 1, 1, PT::parallelogram, 66, 64, 64},
        {1, 64, 1, PT::fan, 66, 64, 64},
        {1, 1, 64, PT::parallelogram, 66, 64, 64},
        {1.5f, 1, 1, PT::fan, 6, 5, 5},
        {1, 1.5f, 1, PT::fan, 5, 3, 3},
        {1.5f, 20, 1.2f, PT::fan, 27, 26, 26},
        {2.5f, 1.2f, 40, PT::parallelogram, 75, 101, 57},
        {40, 1.2f, 2.5f, PT::parallelogram, 104, 159, 97},
        {64, 64, 2, PT::parallelogram, 162, 191, 190},
        {2, 64, 64, PT::parallelogram, 194, 255, 128},
    };
    for (unsigned max_factor : {64u, 256u})
        for (const Row& r : rows) {
            INFO("max " << max_factor << " f = (" << r.f0 << ", " << r.f1 << ", " << r.f2 << ")");
            CpRunner run(flat_options(max_factor));
            const MeshView m = run.run(r.f0, r.f1, r.f2);
            CHECK(cp::pattern_type(cp::line_state(r.f0, max_factor), cp::line_state(r.f1, max_factor),
                                   cp::line_state(r.f2, max_factor)) == r.type);
            CHECK(run.counts() == Counts{r.vertices, r.triangles});
            CHECK(surface_triangles(m).size() == r.non_degenerate);
            CHECK(check_cp_mesh(m, cp::line_state(r.f0, max_factor), cp::line_state(r.f1, max_factor),
                                cp::line_state(r.f2, max_factor))
                      .ok());
        }
}

TEST_CASE("cp pattern: T0 collapse examples (docs/algorithm.md §2.9)", "[cp_pattern]") {
    cp::PatternOptions o = flat_options(64);
    o.collapse_t0 = false;
    CHECK(cp::pattern_counts(64, 1, 1, o).triangles == 130);
    CHECK(cp::pattern_counts(1, 1, 64, o).triangles == 194);
    o.collapse_t0 = true;
    CHECK(cp::pattern_counts(64, 1, 1, o).triangles == 64);
    CHECK(cp::pattern_counts(1, 1, 64, o).triangles == 64);
}

TEST_CASE("cp pattern: the flat layout gives the max-256 pattern for the same states at max 64",
          "[cp_pattern]") {
    // Tables, types and zippers depend on tokens only; T0..T16 are the same tokens for both maxima.
    CpRunner run64(flat_options(64));
    CpRunner run256(flat_options(256));
    Rng rng(17);
    for (int n = 0; n < 400; ++n) {
        std::array<cp::LineState, 3> s;
        for (auto& e : s) e = state(rng.below(17), rng.below(3) == 0 ? 0 : rng.lerp());
        const MeshView a = run64.run(s[0], s[1], s[2]);
        const MeshView b = run256.run(s[0], s[1], s[2]);
        INFO(describe(s[0], s[1], s[2]));
        REQUIRE(run64.counts() == run256.counts());
        REQUIRE(std::equal(a.vertices.begin(), a.vertices.end(), b.vertices.begin(), b.vertices.end()));
        REQUIRE(std::equal(a.indices.begin(), a.indices.end(), b.indices.begin(), b.indices.end()));
    }
}

namespace {
// The distinct boundary parameters of edge e as seen walking the patch's boundary loop counter-clockwise:
// e0 from v0 (u), e1 from v1 (v), e2 from v2 (one - v).
std::vector<std::uint32_t> loop_params(const MeshView& m, unsigned e) {
    const EdgeVertexParams p = edge_vertex_params(m, cp::fixed_one);
    std::vector<std::uint32_t> out = e == 0 ? p.e0 : e == 1 ? p.e1 : p.e2;
    if (e == 2)
        for (auto& x : out) x = cp::fixed_one - x;
    std::sort(out.begin(), out.end());
    return out;
}
} // namespace

TEST_CASE("cp pattern: neighbouring patches agree on their shared edge", "[cp_pattern]") {
    // Patch A walks the shared edge one way and patch B the other, so B's loop parameter is one minus A's.
    for (unsigned max_factor : {64u, 256u}) {
        Rng rng(max_factor + 3);
        cp::PatternOptions o;
        o.max_factor = max_factor;
        CpRunner run_a(o), run_b(o);
        const float hi = static_cast<float>(max_factor) + 1.0f;
        for (int n = 0; n < 150; ++n) {
            const float shared = n < 20 ? 1.0f + static_cast<float>(n) * 0.1f : rng.factor(0.5f, hi);
            for (unsigned ea = 0; ea < 3; ++ea)
                for (unsigned eb = 0; eb < 3; ++eb) {
                    std::array<float, 3> fa{rng.factor(0.5f, hi), rng.factor(0.5f, hi), rng.factor(0.5f, hi)};
                    std::array<float, 3> fb{rng.factor(0.5f, hi), rng.factor(0.5f, hi), rng.factor(0.5f, hi)};
                    fa[ea] = shared;
                    fb[eb] = shared;
                    const auto pa = loop_params(run_a.run(fa[0], fa[1], fa[2]), ea);
                    auto pb = loop_params(run_b.run(fb[0], fb[1], fb[2]), eb);
                    for (auto& x : pb) x = cp::fixed_one - x;
                    std::sort(pb.begin(), pb.end());
                    INFO("max " << max_factor << " shared f " << shared << " on A.e" << ea << " and B.e"
                                << eb);
                    REQUIRE(pa == pb);
                }
        }
    }
}

TEST_CASE("cp pattern: provoking layout has unique first indices and the flat layout's triangles",
          "[cp_pattern]") {
    for (unsigned max_factor : {64u, 256u}) {
        cp::PatternOptions provoking;
        provoking.max_factor = max_factor;
        CpRunner run_p(provoking), run_f(flat_options(max_factor));
        Rng rng(max_factor * 31u);
        const unsigned tokens = cp::token_count(max_factor);
        FailureLog log;
        const int count = max_factor == 64 ? 3000 : 200;
        for (int n = 0; n < count; ++n) {
            std::array<cp::LineState, 3> s;
            for (auto& e : s) {
                const std::uint32_t pick = rng.below(4);
                e = state(rng.below(tokens), pick == 0 ? 0 : pick == 1 ? cp::lerp_one : rng.inner_lerp());
            }
            const MeshView p = run_p.run(s[0], s[1], s[2]);
            const MeshView f = run_f.run(s[0], s[1], s[2]);
            std::string what;
            if (!unique_first_index(p)) what += "first index not unique; ";
            if (run_p.counts().triangles != run_f.counts().triangles) what += "triangle counts differ; ";
            if (all_triangles(p) != all_triangles(f)) what += "position triangles differ; ";
            if (!what.empty()) log.add(cat(describe(s[0], s[1], s[2]), ": ", what));
        }
        INFO("max " << max_factor << ": " << log.summary());
        REQUIRE(log.count == 0);
    }
}

TEST_CASE("cp pattern: bad factors behave as factors clamped to [1, max] (NaN -> 1)", "[cp_pattern]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const float denorm = std::numeric_limits<float>::denorm_min();
    for (unsigned max_factor : {64u, 256u}) {
        const float maxf = static_cast<float>(max_factor);
        struct Bad {
            float value, clamped;
        };
        const Bad bad[] = {{nan, 1},      {-nan, 1},           {-inf, 1},
                           {-1.0f, 1},    {-0.0f, 1},          {0.0f, 1},
                           {denorm, 1},   {0.999f, 1},         {inf, maxf},
                           {1e30f, maxf}, {maxf + 0.5f, maxf}, {std::numeric_limits<float>::max(), maxf},
                           {1e9f, maxf}};
        cp::PatternOptions o;
        o.max_factor = max_factor;
        CpRunner run_bad(o), run_ok(o);
        for (const Bad& b : bad)
            for (unsigned e = 0; e < 3; ++e)
                for (float other : {1.0f, 2.5f, 7.0f, maxf}) {
                    std::array<float, 3> fb{other, 3.25f, other}, fo = fb;
                    fb[e] = b.value;
                    fo[e] = b.clamped;
                    const MeshView mb = run_bad.run(fb[0], fb[1], fb[2]);
                    const MeshView mo = run_ok.run(fo[0], fo[1], fo[2]);
                    INFO("max " << max_factor << " bad " << b.value << " on e" << e << " others " << other);
                    REQUIRE(run_bad.counts() == run_ok.counts());
                    REQUIRE(cp::pattern_counts(fb[0], fb[1], fb[2], o) == run_ok.counts());
                    REQUIRE(std::equal(mb.vertices.begin(), mb.vertices.end(), mo.vertices.begin(),
                                       mo.vertices.end()));
                    REQUIRE(std::equal(mb.indices.begin(), mb.indices.end(), mo.indices.begin(),
                                       mo.indices.end()));
                }
    }
}
