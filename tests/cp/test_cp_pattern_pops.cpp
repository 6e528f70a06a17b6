// CP triangle pattern poplessness (docs/algorithm.md §2.10): at every token boundary of an
// edge the non-degenerate triangles, as exact position triples, are the same multiset on both sides; inside a
// token triple the index buffer is fixed and positions move continuously.
#include <catch2/catch.hpp>

#include <ctess/cp/pattern.hpp>

#include <array>
#include <cstdio>
#include <vector>

#include "support/cp_harness.hpp"
#include "support/mesh_checks.hpp"

using namespace ctess;
using namespace ctess::test;

namespace {

using Triple = std::array<cp::LineState, 3>;

// Compares the surfaces of two triples that have the same point positions, and checks both meshes' areas.
struct PopChecker {
    explicit PopChecker(const cp::PatternOptions& o) : before(o), after(o) {}
    CpRunner before, after;
    FailureLog log;
    std::size_t pairs = 0;

    void compare(const Triple& a, const Triple& b) {
        ++pairs;
        const MeshView ma = before.run(a[0], a[1], a[2]);
        const MeshView mb = after.run(b[0], b[1], b[2]);
        std::string what;
        for (const MeshView* m : {&ma, &mb}) {
            const AreaStats s = area_stats(*m);
            if (s.inverted != 0 || s.fins != 0 || !s.covers(cp::fixed_one))
                what += cat("invalid mesh (inverted ", s.inverted, ", fins ", s.fins, ", covers ",
                            s.covers(cp::fixed_one) ? "yes" : "no", "); ");
        }
        const auto sa = surface_triangles(ma);
        const auto sb = surface_triangles(mb);
        if (sa != sb) what += cat("POP: ", sa.size(), " vs ", sb.size(), " non-degenerate triangles; ");
        if (!what.empty())
            log.add(cat(describe(a[0], a[1], a[2]), " | ", describe(b[0], b[1], b[2]), ": ", what));
    }
    void require_clean(const char* what) {
        std::printf("cp pops %s: %zu boundary pairs, %zu failing\n", what, pairs, log.count);
        INFO(what << ": " << log.summary());
        REQUIRE(log.count == 0);
    }
};

// One edge crosses every boundary k | k+1 while the other two edges take every token pair, with lerps
// (0, 0), (1, 1) and a seeded random pair: 3 x 16 x 17^2 x 3 = 41,616 comparisons per edge set at max 64.
void single_edge_exhaustive(unsigned edge, unsigned max_factor, std::uint64_t seed) {
    cp::PatternOptions o;
    o.max_factor = max_factor;
    PopChecker check(o);
    Rng rng(seed);
    const unsigned tokens = cp::token_count(max_factor);
    for (unsigned k = 0; k + 1 < tokens; ++k)
        for (unsigned a = 0; a < tokens; ++a)
            for (unsigned b = 0; b < tokens; ++b)
                for (int variant = 0; variant < 3; ++variant) {
                    const std::uint32_t la = variant == 0   ? 0
                                             : variant == 1 ? cp::lerp_one
                                                            : rng.inner_lerp();
                    const std::uint32_t lb = variant == 0   ? 0
                                             : variant == 1 ? cp::lerp_one
                                                            : rng.inner_lerp();
                    Triple before, after;
                    before[edge] = boundary_before(k);
                    after[edge] = boundary_after(k);
                    before[(edge + 1) % 3] = after[(edge + 1) % 3] = state(a, la);
                    before[(edge + 2) % 3] = after[(edge + 2) % 3] = state(b, lb);
                    check.compare(before, after);
                }
    const std::string what = cat("max ", max_factor, " e", edge, " all boundaries");
    check.require_clean(what.c_str());
}

// Sampled version for large maxima: every boundary of the edge, `per_boundary` random states of the other
// edges.
void single_edge_sampled(unsigned edge, unsigned max_factor, unsigned per_boundary, std::uint64_t seed) {
    cp::PatternOptions o;
    o.max_factor = max_factor;
    PopChecker check(o);
    Rng rng(seed);
    const unsigned tokens = cp::token_count(max_factor);
    auto random_state = [&] {
        const std::uint32_t pick = rng.below(4);
        return state(rng.below(tokens), pick == 0 ? 0 : pick == 1 ? cp::lerp_one : rng.inner_lerp());
    };
    for (unsigned k = 0; k + 1 < tokens; ++k)
        for (unsigned n = 0; n < per_boundary; ++n) {
            Triple before, after;
            before[edge] = boundary_before(k);
            after[edge] = boundary_after(k);
            before[(edge + 1) % 3] = after[(edge + 1) % 3] = random_state();
            before[(edge + 2) % 3] = after[(edge + 2) % 3] = random_state();
            check.compare(before, after);
        }
    const std::string what = cat("max ", max_factor, " e", edge, " sampled");
    check.require_clean(what.c_str());
}

} // namespace

TEST_CASE("cp pops: e0 crosses every token boundary, all other token pairs, max 64", "[cp_pattern][pops]") {
    single_edge_exhaustive(0, 64, 0xe0);
}
TEST_CASE("cp pops: e1 crosses every token boundary, all other token pairs, max 64", "[cp_pattern][pops]") {
    single_edge_exhaustive(1, 64, 0xe1);
}
TEST_CASE("cp pops: e2 crosses every token boundary, all other token pairs, max 64", "[cp_pattern][pops]") {
    single_edge_exhaustive(2, 64, 0xe2);
}

TEST_CASE("cp pops: rule (a) and no T0 collapse, every boundary, all token pairs, max 64",
          "[cp_pattern][pops]") {
    // The independent prototype also ran the staircase rule with and without the collapse: the options rotate
    // with the token pair, the other edges get seeded random lerps.
    const std::array<cp::PatternOptions, 3> variants = [] {
        std::array<cp::PatternOptions, 3> v{default_options(64), default_options(64), default_options(64)};
        v[0].column_rule = v[1].column_rule = cp::ColumnRule::staircase;
        v[1].collapse_t0 = v[2].collapse_t0 = false;
        return v;
    }();
    std::array<PopChecker, 3> checks{PopChecker(variants[0]), PopChecker(variants[1]),
                                     PopChecker(variants[2])};
    Rng rng(0xa0);
    for (unsigned edge = 0; edge < 3; ++edge)
        for (unsigned k = 0; k < 16; ++k)
            for (unsigned a = 0; a < 17; ++a)
                for (unsigned b = 0; b < 17; ++b) {
                    Triple before, after;
                    before[edge] = boundary_before(k);
                    after[edge] = boundary_after(k);
                    before[(edge + 1) % 3] = after[(edge + 1) % 3] = state(a, rng.lerp());
                    before[(edge + 2) % 3] = after[(edge + 2) % 3] = state(b, rng.lerp());
                    checks[(a + b + k) % 3].compare(before, after);
                }
    checks[0].require_clean("max 64 rule a collapse");
    checks[1].require_clean("max 64 rule a no-collapse");
    checks[2].require_clean("max 64 rule b no-collapse");
}

TEST_CASE("cp pops: e0 crosses every token boundary, sampled, max 256", "[cp_pattern][pops]") {
    single_edge_sampled(0, 256, 40, 0x2560);
}
TEST_CASE("cp pops: e1 crosses every token boundary, sampled, max 256", "[cp_pattern][pops]") {
    single_edge_sampled(1, 256, 40, 0x2561);
}
TEST_CASE("cp pops: e2 crosses every token boundary, sampled, max 256", "[cp_pattern][pops]") {
    single_edge_sampled(2, 256, 40, 0x2562);
}

TEST_CASE("cp pops: f < 2 transitions T0|T1|T2 on each edge (Type 0 -> 1 -> 2)", "[cp_pattern][pops]") {
    // Dense over the small-factor regime: every edge crosses T0|T1 and T1|T2 with the other edges in T0, T1
    // or T2 at many lerps, for both maxima, both column rules and with and without the T0 collapse.
    for (unsigned max_factor : {64u, 256u})
        for (bool staircase : {false, true})
            for (bool collapse : {true, false}) {
                cp::PatternOptions o;
                o.max_factor = max_factor;
                o.column_rule = staircase ? cp::ColumnRule::staircase : cp::ColumnRule::minimal;
                o.collapse_t0 = collapse;
                PopChecker check(o);
                const std::uint32_t lerps[] = {0, 1, 9000, 32768, 50000, 65535, 65536};
                std::vector<cp::LineState> small{{0, 0}};
                for (unsigned t = 1; t <= 3; ++t)
                    for (std::uint32_t l : lerps) small.push_back({t, l});
                for (unsigned edge = 0; edge < 3; ++edge)
                    for (unsigned k = 0; k < 2; ++k)
                        for (cp::LineState a : small)
                            for (cp::LineState b : small) {
                                Triple before, after;
                                before[edge] = boundary_before(k);
                                after[edge] = boundary_after(k);
                                before[(edge + 1) % 3] = after[(edge + 1) % 3] = a;
                                before[(edge + 2) % 3] = after[(edge + 2) % 3] = b;
                                check.compare(before, after);
                            }
                const std::string what = cat("f<2 max ", max_factor, staircase ? " rule a" : " rule b",
                                             collapse ? " collapse" : " no-collapse");
                check.require_clean(what.c_str());
            }
}

TEST_CASE("cp pops: several edges cross at once", "[cp_pattern][pops]") {
    // All three edges cross boundaries k0, k1, k2 together (every combination at max 64, equal factors moving
    // together among them), then two edges at once with the third at a random state.
    {
        PopChecker check(default_options(64));
        for (unsigned k0 = 0; k0 < 16; ++k0)
            for (unsigned k1 = 0; k1 < 16; ++k1)
                for (unsigned k2 = 0; k2 < 16; ++k2)
                    check.compare({boundary_before(k0), boundary_before(k1), boundary_before(k2)},
                                  {boundary_after(k0), boundary_after(k1), boundary_after(k2)});
        check.require_clean("max 64 three edges at once");
    }
    {
        cp::PatternOptions o;
        o.max_factor = 256;
        PopChecker check(o);
        for (unsigned k = 0; k < 24; ++k) // equal factors crossing together
            check.compare({boundary_before(k), boundary_before(k), boundary_before(k)},
                          {boundary_after(k), boundary_after(k), boundary_after(k)});
        Rng rng(99);
        for (int n = 0; n < 150; ++n) {
            const unsigned k0 = rng.below(24), k1 = rng.below(24), k2 = rng.below(24);
            check.compare({boundary_before(k0), boundary_before(k1), boundary_before(k2)},
                          {boundary_after(k0), boundary_after(k1), boundary_after(k2)});
        }
        check.require_clean("max 256 three edges at once");
    }
    for (unsigned max_factor : {64u, 256u}) {
        cp::PatternOptions o;
        o.max_factor = max_factor;
        PopChecker check(o);
        Rng rng(max_factor + 2);
        const unsigned tokens = cp::token_count(max_factor);
        const unsigned samples = max_factor == 64 ? 1500 : 150;
        for (unsigned n = 0; n < samples; ++n) {
            const unsigned still = rng.below(3);
            Triple before, after;
            for (unsigned e = 0; e < 3; ++e) {
                if (e == still) {
                    before[e] = after[e] = state(rng.below(tokens), rng.lerp());
                } else {
                    const unsigned k = rng.below(tokens - 1);
                    before[e] = boundary_before(k);
                    after[e] = boundary_after(k);
                }
            }
            check.compare(before, after);
        }
        const std::string what = cat("max ", max_factor, " two edges at once");
        check.require_clean(what.c_str());
    }
}

namespace {

// Inside a token triple: the index buffer is the same at every lerp, and one step of t16 on one edge moves
// every vertex by at most twice that edge's longest point track (interior coordinates are min/max/differences
// of line parameters; the Type-1 point is 1/2-Lipschitz) plus one unit of rounding per coordinate.
void inside_tokens(unsigned max_factor, unsigned triples, std::uint64_t seed) {
    cp::PatternOptions o;
    o.max_factor = max_factor;
    CpRunner base(o), moved(o);
    Rng rng(seed);
    FailureLog log;
    const unsigned tokens = cp::token_count(max_factor);
    for (unsigned n = 0; n < triples; ++n) {
        Triple s;
        for (auto& e : s) e = state(rng.below(tokens), rng.lerp());
        const auto random_lerps = [&] {
            Triple r = s;
            for (auto& e : r) e = state(e.token, rng.lerp());
            return r;
        };
        const Triple a = random_lerps();
        const MeshView ma = base.run(a[0], a[1], a[2]);
        // Topology: any other lerps of the same tokens.
        for (int k = 0; k < 3; ++k) {
            Triple b = random_lerps();
            if (k == 0)
                for (auto& e : b) e = state(e.token, 0);
            if (k == 1)
                for (auto& e : b) e = state(e.token, cp::lerp_one);
            const MeshView mb = moved.run(b[0], b[1], b[2]);
            if (!(base.counts() == moved.counts()) ||
                !std::equal(ma.indices.begin(), ma.indices.end(), mb.indices.begin(), mb.indices.end()))
                log.add(cat(describe(a[0], a[1], a[2]), " vs ", describe(b[0], b[1], b[2]),
                            ": index buffer differs"));
        }
        // Continuity: one t16 step on each edge, at random lerps and at both ends of the token.
        for (unsigned e = 0; e < 3; ++e) {
            if (a[e].token == 0) continue;
            const std::uint32_t bound = 2 * max_track_length(a[e].token) + 1;
            for (std::uint32_t from : {0u, cp::lerp_one - 1, a[e].t16 == cp::lerp_one ? 0u : a[e].t16}) {
                Triple lo = a, hi = a;
                lo[e].t16 = from;
                hi[e].t16 = from + 1;
                const MeshView ml = base.run(lo[0], lo[1], lo[2]);
                const MeshView mh = moved.run(hi[0], hi[1], hi[2]);
                if (!(base.counts() == moved.counts()) ||
                    !std::equal(ml.indices.begin(), ml.indices.end(), mh.indices.begin(), mh.indices.end())) {
                    log.add(
                        cat(describe(lo[0], lo[1], lo[2]), " -> t16+1 on e", e, ": index buffer differs"));
                    continue;
                }
                std::uint32_t worst = 0;
                for (std::size_t v = 0; v < ml.vertices.size(); ++v) {
                    const auto du = ml.vertices[v].u > mh.vertices[v].u ? ml.vertices[v].u - mh.vertices[v].u
                                                                        : mh.vertices[v].u - ml.vertices[v].u;
                    const auto dv = ml.vertices[v].v > mh.vertices[v].v ? ml.vertices[v].v - mh.vertices[v].v
                                                                        : mh.vertices[v].v - ml.vertices[v].v;
                    worst = std::max({worst, du, dv});
                }
                if (worst > bound)
                    log.add(cat(describe(lo[0], lo[1], lo[2]), " -> t16+1 on e", e, ": a vertex moved ",
                                worst, " > ", bound));
            }
        }
    }
    std::printf("cp inside tokens max %u: %u token triples, %zu failing\n", max_factor, triples, log.count);
    INFO(log.summary());
    REQUIRE(log.count == 0);
}

} // namespace

TEST_CASE("cp pops: inside a token triple, fixed topology and continuous positions, max 64",
          "[cp_pattern][pops]") {
    inside_tokens(64, 2000, 0x1a64);
}
TEST_CASE("cp pops: inside a token triple, fixed topology and continuous positions, max 256",
          "[cp_pattern][pops]") {
    inside_tokens(256, 200, 0x1a256);
}
