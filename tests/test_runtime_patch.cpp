// The table-driven runtime against the procedural generator: for every token triple at max 64, and for every
// (tok0, tok2) pair with e1 sampled so that every (tok0, tok1) pair is covered at max 256, at the lerps 0,
// 65536 and a seeded random one per edge, CpPatch's counts, every vertex(i), every triangle(p) and the bulk
// emit equal cp::tessellate's output with the default PatternOptions, element by element.
#include <ctess/cp_pattern.hpp>
#include <ctess/runtime/cp_patch.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "support/cp_harness.hpp"

using ctess::DomainPoint;
using ctess::cp::LineState;
using ctess::rt::CpPatch;
using ctess::rt::CpTableSet;
using ctess::test::cat;

namespace {

struct Comparer {
    const CpTableSet& tables;
    ctess::cp::PatternOptions options;
    std::vector<DomainPoint> ref_v, rt_v;
    std::vector<std::uint32_t> ref_i, rt_i;
    ctess::test::FailureLog log;
    std::uint64_t triples = 0, vertices = 0, triangles = 0;

    explicit Comparer(const CpTableSet& t) : tables(t) {
        options.max_factor = t.max_factor;
        const auto cap = ctess::cp::max_pattern_counts(t.max_factor);
        ref_v.resize(cap.vertices);
        rt_v.resize(cap.vertices);
        ref_i.resize(3 * std::size_t{cap.triangles});
        rt_i.resize(3 * std::size_t{cap.triangles});
    }

    void check(LineState s0, LineState s1, LineState s2) {
        ++triples;
        const auto ref = ctess::cp::tessellate(ref_v.data(), ref_i.data(), s0, s1, s2, options);
        const CpPatch patch(tables, s0, s1, s2);
        const std::string where = ctess::test::describe(s0, s1, s2);
        if (patch.vertex_count() != ref.vertices || patch.triangle_count() != ref.triangles) {
            log.add(cat(where, ": counts ", patch.vertex_count(), "/", patch.triangle_count(), " expected ",
                        ref.vertices, "/", ref.triangles));
            return;
        }
        vertices += ref.vertices;
        triangles += ref.triangles;
        for (std::uint32_t v = 0; v < ref.vertices; ++v) {
            const DomainPoint p = patch.vertex(v);
            if (!(p == ref_v[v])) {
                log.add(cat(where, ": vertex ", v, " = (", p.u, ", ", p.v, ") expected (", ref_v[v].u, ", ",
                            ref_v[v].v, ")"));
                return;
            }
        }
        for (std::uint32_t t = 0; t < ref.triangles; ++t) {
            const auto tri = patch.triangle(t);
            if (tri[0] != ref_i[3 * t] || tri[1] != ref_i[3 * t + 1] || tri[2] != ref_i[3 * t + 2]) {
                log.add(cat(where, ": triangle ", t, " = ", tri[0], " ", tri[1], " ", tri[2], " expected ",
                            ref_i[3 * t], " ", ref_i[3 * t + 1], " ", ref_i[3 * t + 2]));
                return;
            }
        }
        if (!patch.emit(rt_v, rt_i)) {
            log.add(cat(where, ": emit refused buffers of the maximum size"));
            return;
        }
        for (std::uint32_t v = 0; v < ref.vertices; ++v) {
            if (!(rt_v[v] == ref_v[v])) {
                log.add(cat(where, ": emitted vertex ", v, " differs"));
                return;
            }
        }
        for (std::uint32_t k = 0; k < 3 * ref.triangles; ++k) {
            if (rt_i[k] != ref_i[k]) {
                log.add(cat(where, ": emitted index ", k, " = ", rt_i[k], " expected ", ref_i[k]));
                return;
            }
        }
    }
};

// The lerp settings of one token triple: all at 0, all at 1, and a seeded random lerp per edge.
template <class Check>
void for_each_lerp_setting(ctess::test::Rng& rng, unsigned k0, unsigned k1, unsigned k2, Check&& check) {
    using ctess::test::state;
    check(state(k0, 0), state(k1, 0), state(k2, 0));
    check(state(k0, 65536), state(k1, 65536), state(k2, 65536));
    check(state(k0, rng.lerp()), state(k1, rng.lerp()), state(k2, rng.lerp()));
}

} // namespace

TEST_CASE("runtime: every token triple at sampled lerps equals cp::tessellate, max 64", "[runtime][tables]") {
    Comparer cmp(ctess::rt::cp_tables_64);
    ctess::test::Rng rng(64);
    const unsigned nt = ctess::cp::token_count(64);
    for (unsigned k0 = 0; k0 < nt; ++k0)
        for (unsigned k1 = 0; k1 < nt; ++k1)
            for (unsigned k2 = 0; k2 < nt; ++k2)
                for_each_lerp_setting(rng, k0, k1, k2,
                                      [&](LineState a, LineState b, LineState c) { cmp.check(a, b, c); });
    INFO(cmp.log.summary());
    CHECK(cmp.log.count == 0);
    CHECK(cmp.triples == 3u * nt * nt * nt);
}

TEST_CASE("runtime: every (tok0, tok2) and (tok0, tok1) pair at sampled lerps equals cp::tessellate, max 256",
          "[runtime][tables]") {
    Comparer cmp(ctess::rt::cp_tables_256);
    ctess::test::Rng rng(256);
    const unsigned nt = ctess::cp::token_count(256);
    for (unsigned k0 = 0; k0 < nt; ++k0) {
        for (unsigned k2 = 0; k2 < nt; ++k2) {
            // e1: T0 and T1 (the collapse and the fixed T1 coordinates), the top token, and one that runs
            // through every token as k2 does, so that every (tok0, tok1) pair is met.
            const unsigned e1_tokens[] = {0, 1, nt - 1, (k2 + 3 * k0 + 2) % nt};
            for (unsigned k1 : e1_tokens)
                for_each_lerp_setting(rng, k0, k1, k2,
                                      [&](LineState a, LineState b, LineState c) { cmp.check(a, b, c); });
        }
    }
    INFO(cmp.log.summary());
    CHECK(cmp.log.count == 0);
    CHECK(cmp.triples == 3u * 4u * nt * nt);
}
