// The table-driven runtime against the procedural generator: for every token triple at max 64, and for every
// (tok0, tok2) pair with e1 sampled so that every (tok0, tok1) pair is covered at max 256, at the lerps 0,
// 65536 and a seeded random one per edge, in both layouts and both windings: cp_counts, CpPatch's counts,
// every vertex(i), every triangle(p), and the bulk emit of CpPatch and of CpPatchSetup equal cp::tessellate's
// output (the same layout; clockwise = each reference triangle (a, b, c) as (a, c, b)),
// element by element, also the portable build of the fast path where emit() takes the AVX2 one; emit into
// spans of exactly the counts writes nothing past them.
// The closed-form line state equals cp::line_state_fixed for every 16.16 factor.
#include <ctess/cp/pattern.hpp>
#include <ctess/runtime/cp/line_state.hpp>
#include <ctess/runtime/cp/patch.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include "support/cp_harness.hpp"

using ctess::DomainPoint;
using ctess::Layout;
using ctess::PatchOptions;
using ctess::Winding;
using ctess::cp::LineState;
using ctess::rt::CpPatch;
using ctess::rt::CpPatchSetup;
using ctess::rt::CpTableSet;
using ctess::test::cat;

namespace {

const std::vector<PatchOptions> all_options = {{Layout::provoking, Winding::ccw},
                                               {Layout::provoking, Winding::cw},
                                               {Layout::shared, Winding::ccw},
                                               {Layout::shared, Winding::cw}};

// CpPatchSetup's portable fast path, reached through its protected member.
struct BaselineEmit : CpPatchSetup {
    using CpPatchSetup::CpPatchSetup;
    using CpPatchSetup::emit_baseline;
};

struct Comparer {
    const CpTableSet& tables;
    PatchOptions patch_options;
    ctess::cp::PatternOptions options;
    std::vector<DomainPoint> ref_v, rt_v;
    std::vector<std::uint32_t> ref_i, rt_i;
    ctess::test::FailureLog log;
    std::uint64_t triples = 0, vertices = 0, triangles = 0;
    ctess::Counts last{};
    static constexpr std::size_t guard = 8;

    Comparer(const CpTableSet& t, PatchOptions o) : tables(t), patch_options(o) {
        options.max_factor = t.max_factor;
        options.layout = o.layout;
        const auto cap = ctess::cp::max_pattern_counts(t.max_factor);
        ref_v.resize(cap.vertices);
        rt_v.resize(cap.vertices + guard);
        ref_i.resize(3 * std::size_t{cap.triangles});
        rt_i.resize(3 * std::size_t{cap.triangles} + guard);
    }

    void check(LineState s0, LineState s1, LineState s2) {
        ++triples;
        const auto ref = ctess::cp::tessellate(ref_v, ref_i, s0, s1, s2, options);
        if (patch_options.winding == Winding::cw)
            for (std::uint32_t t = 0; t < ref.triangles; ++t) std::swap(ref_i[3 * t + 1], ref_i[3 * t + 2]);
        const CpPatch patch(tables, s0, s1, s2, patch_options);
        const std::string where =
            cat(ctess::test::describe(s0, s1, s2), " layout ", static_cast<int>(patch_options.layout),
                " winding ", static_cast<int>(patch_options.winding));
        const ctess::Counts counts = ctess::rt::cp_counts(tables, s0, s1, s2, patch_options);
        if (patch.vertex_count() != ref.vertices || patch.triangle_count() != ref.triangles ||
            !(counts == patch.counts())) {
            log.add(cat(where, ": counts ", patch.vertex_count(), "/", patch.triangle_count(), " expected ",
                        ref.vertices, "/", ref.triangles));
            return;
        }
        vertices += ref.vertices;
        triangles += ref.triangles;
        last = ref;
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
        check_emitted(where);
        check_exact_spans(cat(where, " (CpPatchSetup)"),
                          [&](std::span<DomainPoint> v, std::span<std::uint32_t> i) {
                              return CpPatchSetup(tables, s0, s1, s2, patch_options).emit(v, i);
                          });
        // The portable build of the fast path, which emit() skips on a machine with AVX2.
        check_exact_spans(
            cat(where, " (baseline)"), [&](std::span<DomainPoint> v, std::span<std::uint32_t> i) {
                BaselineEmit(tables, s0, s1, s2, patch_options).emit_baseline(v.data(), i.data());
                return true;
            });
    }

    // Spans of exactly the counts, with guard elements after them that emit must not touch.
    template <class Emit>
    void check_exact_spans(const std::string& where, Emit&& emit) {
        const std::size_t nv = last.vertices, ni = 3 * std::size_t{last.triangles};
        std::fill_n(rt_v.begin(), nv + guard, DomainPoint{~0u, ~0u});
        std::fill_n(rt_i.begin(), ni + guard, ~0u);
        if (!emit(std::span(rt_v.data(), nv), std::span(rt_i.data(), ni))) {
            log.add(cat(where, ": emit refused spans of exactly its counts"));
            return;
        }
        check_emitted(where);
        for (std::size_t k = 0; k < guard; ++k) {
            if (!(rt_v[nv + k] == DomainPoint{~0u, ~0u}) || rt_i[ni + k] != ~0u) {
                log.add(cat(where, ": emit wrote past its spans"));
                return;
            }
        }
    }

    void check_emitted(const std::string& where) {
        for (std::uint32_t v = 0; v < last.vertices; ++v) {
            if (!(rt_v[v] == ref_v[v])) {
                log.add(cat(where, ": emitted vertex ", v, " differs"));
                return;
            }
        }
        for (std::uint32_t k = 0; k < 3 * last.triangles; ++k) {
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
    const PatchOptions options = GENERATE(from_range(all_options));
    Comparer cmp(ctess::rt::cp_tables_64, options);
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
    const PatchOptions options = GENERATE(from_range(all_options));
    Comparer cmp(ctess::rt::cp_tables_256, options);
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

TEST_CASE("runtime: the closed-form line state equals cp::line_state_fixed for every 16.16 factor",
          "[runtime][line_state]") {
    for (const unsigned max_factor : {64u, 256u}) {
        std::uint32_t mismatches = 0, first_bad = 0;
        for (std::uint32_t f16 = 0; f16 <= (max_factor << 16); ++f16) {
            if (ctess::rt::line_state_fixed(f16) != ctess::cp::line_state_fixed(f16, max_factor)) {
                if (mismatches++ == 0) first_bad = f16;
            }
        }
        INFO("max " << max_factor << ", first mismatch at f16 = " << first_bad);
        CHECK(mismatches == 0);
    }
    for (const float f : {-1.0f, 0.0f, 1.0f, 1.0001f, 2.5f, 63.99f, 64.0f, 1e9f}) {
        CHECK(ctess::rt::line_state(f, 64) == ctess::cp::line_state(f, 64));
        CHECK(ctess::rt::line_state(f, 256) == ctess::cp::line_state(f, 256));
    }
}

// The runtime's factor_16_16 reads the float's bits (a shift of the significand); cp::clamp_factor_16_16
// multiplies and rounds in float arithmetic. Every exponent from 0.5 to 512 with every value of the
// significand's low 9 bits (the shift's rounding reads at most 8, and the quotient's lowest bit) under 130
// spread high parts, every float within 4096 steps of 1, 2, 64 and 256, then the special values.
TEST_CASE("runtime: the 16.16 factor from a float's bits equals cp::clamp_factor_16_16",
          "[runtime][line_state]") {
    std::vector<std::uint32_t> floats;
    for (std::uint32_t exponent = 126; exponent <= 136; ++exponent)
        for (std::uint32_t high = 0; high < (1u << 14); high += 127)
            for (std::uint32_t low = 0; low < 512; ++low) floats.push_back(exponent << 23 | high << 9 | low);
    for (const float centre : {1.0f, 2.0f, 64.0f, 256.0f})
        for (std::uint32_t k = 0; k < 8192; ++k)
            floats.push_back(std::bit_cast<std::uint32_t>(centre) - 4096 + k);
    for (const unsigned max_factor : {64u, 256u}) {
        std::uint32_t mismatches = 0, first_bad = 0;
        for (const std::uint32_t bits : floats) {
            const float f = std::bit_cast<float>(bits);
            if (ctess::rt::factor_16_16(f, max_factor) != ctess::cp::clamp_factor_16_16(f, max_factor)) {
                if (mismatches++ == 0) first_bad = bits;
            }
        }
        INFO("max " << max_factor << ", first mismatch at float bits " << first_bad);
        CHECK(mismatches == 0);
        const float nan = std::numeric_limits<float>::quiet_NaN(),
                    inf = std::numeric_limits<float>::infinity();
        for (const float f : {nan, -nan, inf, -inf, 0.0f, -0.0f, -1.5f, -300.0f, 1e-40f, -1e-40f, 1e30f,
                              std::numeric_limits<float>::max(), std::numeric_limits<float>::denorm_min()}) {
            CHECK(ctess::rt::line_state(f, max_factor) == ctess::cp::line_state(f, max_factor));
            if (f == f)
                CHECK(ctess::rt::factor_16_16(f, max_factor) == ctess::cp::clamp_factor_16_16(f, max_factor));
        }
    }
}
