// CP line tessellation: tokens, boundaries, docs/algorithm.md §1.2 positions, mirror exactness, popless
// continuity.
#include <catch2/catch.hpp>

#include <ctess/cp/line.hpp>

#include <limits>
#include <vector>

#include "support/line_checks.hpp"

using namespace ctess;

namespace {

// The examples' values are fractions of the edge; 2^24 units make them exact.
constexpr std::uint32_t at(double fraction) {
    return static_cast<std::uint32_t>(fraction * cp::fixed_one);
}

std::vector<std::uint32_t> points(float f, unsigned max_factor) {
    std::vector<std::uint32_t> p(cp::max_segments + 1);
    p.resize(cp::edge_points(f, max_factor, p.data()));
    return p;
}

std::vector<std::uint32_t> points(cp::LineState s) {
    std::vector<std::uint32_t> p(cp::max_segments + 1);
    p.resize(cp::edge_points(s, p.data()));
    return p;
}

constexpr std::uint32_t first_interior_point_at(float f) {
    std::uint32_t p[cp::max_segments + 1]{};
    cp::edge_points(f, 64, p);
    return p[1];
}

} // namespace

// Constant-evaluation proofs of the public functions.
static_assert(cp::token_count(64) == 17 && cp::token_count(256) == 25);
static_assert(cp::token_info(24).lo == 224 && cp::token_info(24).hi == 256 &&
              cp::token_info(24).segments == 256);
static_assert(cp::line_state(10.3f, 256) == cp::LineState{6, 9830});
static_assert(cp::line_state(2.0f, 64) == cp::LineState{1, 65536});
static_assert(first_interior_point_at(1.5f) == cp::fixed_one / 4);
static_assert(cp::point_position({256, 128}, 65536) == cp::fixed_one / 2);

TEST_CASE("token count and factor ranges follow docs/algorithm.md §1.1", "[cp_line]") {
    for (unsigned max : {64u, 256u}) {
        const unsigned n = cp::token_count(max);
        CHECK(n == (max == 64 ? 17u : 25u));
        CHECK(cp::token_info(0).hi == 1);
        for (unsigned t = 1; t < n; ++t) {
            const auto prev = cp::token_info(t - 1);
            const auto info = cp::token_info(t);
            CHECK(info.lo == prev.hi); // contiguous half-open ranges (lo, hi]
            CHECK(is_pow2(static_cast<std::uint32_t>(info.hi - info.lo)));
            CHECK(info.segments == (t == 1 ? 3u : info.hi));
        }
        CHECK(cp::token_info(n - 1).hi == max);
    }
    // Four blocks per octave from 8 on: T5..T8 cover (8,16], T21..T24 cover (128,256].
    CHECK(cp::token_info(5).lo == 8);
    CHECK(cp::token_info(8).hi == 16);
    CHECK(cp::token_info(21).lo == 128);
    CHECK(cp::token_info(16).hi == 64);
}

TEST_CASE("token boundaries map to the right token and lerp", "[cp_line]") {
    for (unsigned max : {64u, 256u}) {
        for (unsigned t = 1; t < cp::token_count(max); ++t) {
            const auto info = cp::token_info(t);
            // The upper bound belongs to the token at t = 1; one 16.16 step above starts the next at t ~ 0.
            CHECK(cp::line_state(static_cast<float>(info.hi), max) == cp::LineState{t, cp::lerp_one});
            const float above = static_cast<float>(info.lo) + 1.0f / 65536.0f;
            const auto s = cp::line_state(above, max);
            CHECK(s.token == t);
            CHECK(s.t16 <= 1);
        }
    }
}

TEST_CASE("positions match the examples of docs/algorithm.md §1.2", "[cp_line]") {
    using V = std::vector<std::uint32_t>;
    CHECK(points(1.5f, 256) == V{0, at(.25), at(.75), at(1)});
    CHECK(points(2.0f, 256) == V{0, at(.5), at(.5), at(1)});
    CHECK(points(3.0f, 256) == V{0, at(.375), at(.5), at(.625), at(1)});
    CHECK(points(4.0f, 256) == V{0, at(.25), at(.5), at(.75), at(1)});
    CHECK(points(5.0f, 256) == V{0, at(.25), at(.4375), at(.5), at(.5625), at(.75), at(1)});
    CHECK(points(7.5f, 256) ==
          V{0, at(.15625), at(.25), at(.375), at(.5), at(.625), at(.75), at(.84375), at(1)});
    // f = 10.3: t = 0.15 quantised to 16 bits; the point moves 16 units per lerp step.
    const V p = points(10.3f, 256);
    REQUIRE(p.size() == 13);
    CHECK(p[1] == at(.125));
    CHECK(p[2] > at(.240625) - 16);
    CHECK(p[2] < at(.240625) + 16);
    CHECK(p[3] == at(.25));
    CHECK(p[5] == at(.4375));
    CHECK(p[6] == at(.5));
}

TEST_CASE("every power of two gives the uniform partition", "[cp_line]") {
    for (unsigned max : {64u, 256u}) {
        for (unsigned n = 4; n <= max; n *= 2) { // f = 2 is the T1 end state {0, .5, .5, 1}
            const auto p = points(static_cast<float>(n), max);
            REQUIRE(p.size() == n + 1);
            for (unsigned i = 0; i <= n; ++i) CHECK(p[i] == i * (cp::fixed_one / n));
        }
    }
}

TEST_CASE("token tables: sorted tracks, mirror pairs, the 4 KB bound", "[cp_line]") {
    unsigned interior = 0;
    for (unsigned t = 0; t < cp::token_count(256); ++t) {
        cp::PointTrack tr[cp::max_segments + 1]{};
        const unsigned n = cp::token_points(t, tr);
        REQUIRE(n == cp::token_info(t).segments + 1u);
        interior += n - 2;
        for (unsigned i = 0; i < n; ++i) {
            CHECK(tr[i].start + tr[n - 1 - i].start == 256);
            CHECK(tr[i].final + tr[n - 1 - i].final == 256);
            if (i > 0) CHECK(tr[i - 1].final <= tr[i].final);
        }
        // Only the current block moves ("points sliding" column of the token table, docs/algorithm.md §1.1).
        static constexpr unsigned sliding[25] = {0, 2, 2, 2, 2,  2,  2,  2,  2,  4,  4,  4, 4,
                                                 8, 8, 8, 8, 16, 16, 16, 16, 32, 32, 32, 32};
        unsigned moving = 0;
        for (unsigned i = 0; i < n; ++i) moving += tr[i].start != tr[i].final;
        CHECK(moving == sliding[t]);
    }
    CHECK(interior == 1609);     // docs/algorithm.md §1.2: 1,609 interior points for max 256
    CHECK(2 * interior == 3218); // one byte each for start and final: under the post's 4 KB
}

TEST_CASE("mirror exactness and monotonicity over a dense sweep", "[cp_line]") {
    for (unsigned max : {64u, 256u}) {
        for (std::uint32_t f16 = 1u << 16; f16 <= (max << 16); f16 += 97) { // 97/65536 steps hit odd lerps
            const auto p = points(cp::line_state_fixed(f16, max));
            REQUIRE(ctess::test::mirror_exact(p, cp::fixed_one));
            REQUIRE(ctess::test::non_decreasing(p));
        }
    }
}

TEST_CASE("points never jump: continuity within and across tokens", "[cp_line]") {
    for (unsigned max : {64u, 256u}) {
        auto prev = points(cp::line_state_fixed(1u << 16, max));
        for (std::uint32_t f16 = (1u << 16) + 1; f16 <= (max << 16); f16 += 1 + (f16 >> 12)) {
            const auto s = cp::line_state_fixed(f16, max);
            const auto cur = points(s);
            // A point moves at most 128 grid units over a whole token of >= 1 factor unit; per factor step
            // the bound is 128 * 65536 * (step in lerp units), and a token boundary adds nothing (births
            // coincide).
            const std::uint32_t step = 1 + ((f16 - 1) >> 12);
            CHECK(ctess::test::hausdorff(prev, cur) <= 128u * (step + 1));
            prev = cur;
        }
        // Across every boundary the distinct positions are identical: a new point is born on an existing one.
        for (unsigned t = 1; t + 1 < cp::token_count(max); ++t) {
            const auto before = ctess::test::distinct(points(cp::LineState{t, cp::lerp_one}));
            const auto after = ctess::test::distinct(points(cp::LineState{t + 1, 0}));
            CHECK(before == after);
        }
        CHECK(ctess::test::distinct(points(cp::LineState{0, 0})) ==
              ctess::test::distinct(points(cp::LineState{1, 0})));
    }
}

TEST_CASE("the end segment is the largest and never grows with f (docs/algorithm.md §1.2)", "[cp_line]") {
    std::uint32_t last_end = cp::fixed_one;
    for (std::uint32_t f16 = 2u << 16; f16 <= (256u << 16); f16 += 1024) { // steps of 1/64
        const auto p = points(cp::line_state_fixed(f16, 256));
        const std::uint32_t end = p[1] - p[0];
        for (std::size_t i = 1; i < p.size(); ++i) REQUIRE(p[i] - p[i - 1] <= end);
        REQUIRE(end <= last_end);
        last_end = end;
    }
}

TEST_CASE("bad factors are clamped to [1, max]", "[cp_line][bad_input]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (unsigned max : {64u, 256u}) {
        const cp::LineState first{0, 0};
        const cp::LineState last{cp::token_count(max) - 1, cp::lerp_one};
        CHECK(cp::line_state(nan, max) == first);
        CHECK(cp::line_state(-inf, max) == first);
        CHECK(cp::line_state(-5.0f, max) == first);
        CHECK(cp::line_state(0.0f, max) == first);
        CHECK(cp::line_state(1e-40f, max) == first);
        CHECK(cp::line_state(inf, max) == last);
        CHECK(cp::line_state(1e30f, max) == last);
        CHECK(cp::line_state(static_cast<float>(max) + 0.5f, max) == last);
        CHECK(points(nan, max).size() == 2);
        CHECK(points(inf, max).size() == max + 1u);
    }
}
