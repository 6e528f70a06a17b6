// The comparison line modes of Hable 2026's viewer: mirror exactness, monotonicity, and which of them pop.
#include <catch2/catch.hpp>

#include "line_compare.hpp"

#include <vector>

#include "support/line_checks.hpp"

using namespace ctess;

namespace {

using ModeFn = unsigned (*)(float, unsigned, std::uint32_t*);

std::vector<std::uint32_t> run(ModeFn fn, float f, unsigned max = 256) {
    std::vector<std::uint32_t> p(2 * cp::max_segments + 2);
    p.resize(fn(f, max, p.data()));
    return p;
}

constexpr unsigned count_at(ModeFn fn, float f) {
    std::uint32_t p[2 * cp::max_segments + 2]{};
    return fn(f, 256, p);
}

} // namespace

static_assert(count_at(line_compare::pow2_subdivision, 5.0f) == 9);
static_assert(count_at(line_compare::one_at_a_time, 10.3f) == 13);
static_assert(count_at(line_compare::even_spacing, 7.0f) == 9);

TEST_CASE("comparison modes are mirror-exact and sorted over a dense sweep", "[line_modes]") {
    for (ModeFn fn :
         {line_compare::pow2_subdivision, line_compare::one_at_a_time, line_compare::even_spacing}) {
        for (float f = 0.75f; f <= 260.0f; f += 1.0f / 64.0f) {
            const auto p = run(fn, f);
            REQUIRE(p.front() == 0);
            REQUIRE(p.back() == cp::fixed_one);
            REQUIRE(ctess::test::mirror_exact(p, cp::fixed_one));
            REQUIRE(ctess::test::non_decreasing(p));
        }
    }
}

TEST_CASE("powers of two are uniform in every comparison mode", "[line_modes]") {
    for (ModeFn fn :
         {line_compare::pow2_subdivision, line_compare::one_at_a_time, line_compare::even_spacing}) {
        for (unsigned n = 4; n <= 256; n *= 2) {
            const auto p = run(fn, static_cast<float>(n));
            REQUIRE(p.size() == n + 1);
            for (unsigned i = 0; i <= n; ++i) CHECK(p[i] == i * (cp::fixed_one / n));
        }
    }
}

TEST_CASE("Hable 2026: 10.3 puts the pivot 15 % into its half-segment when inserting one at a time",
          "[line_modes]") {
    // Mirrored per half: (10.3 - 8) / 2 = 1.15 new points per half, so one is in and the pivot is at t =
    // 0.15.
    const auto p = run(line_compare::one_at_a_time, 10.3f);
    REQUIRE(p.size() == 13);
    CHECK(p[1] == cp::fixed_one / 16);
    CHECK(p[2] == cp::fixed_one / 8);
    const double pivot = p[3] / double(cp::fixed_one);
    CHECK(pivot == Approx(0.125 + 0.0625 * 0.15).margin(1e-4));
}

TEST_CASE("even spacing moves every point but one at a time moves only the pivot", "[line_modes]") {
    // Between f = 10.5 and 11 the first interior point is not the pivot: even spacing moves it (it sits at
    // 1/f), one at a time does not.
    CHECK(run(line_compare::even_spacing, 10.5f)[1] != run(line_compare::even_spacing, 11.0f)[1]);
    CHECK(run(line_compare::one_at_a_time, 10.5f)[1] == run(line_compare::one_at_a_time, 11.0f)[1]);
}

TEST_CASE("continuity: lerped modes never jump, plain subdivision pops", "[line_modes]") {
    const float h = 1.0f / 256.0f;
    for (ModeFn fn : {line_compare::one_at_a_time, line_compare::even_spacing}) {
        for (float f = 1.0f; f + h <= 256.0f; f += h) {
            // Slope bound: a point moves at most half a segment of the octave per unit of progress, and the
            // even-spacing rescale moves points by at most |d(i/f)| <= h over the edge.
            REQUIRE(ctess::test::hausdorff(run(fn, f), run(fn, f + h)) <= cp::fixed_one / 256 + 64);
        }
    }
    // Plain subdivision is the negative control: just above 4 the new point 1/8 is 1/8 away from any old one.
    CHECK(ctess::test::hausdorff(run(line_compare::pow2_subdivision, 4.0f),
                                 run(line_compare::pow2_subdivision, 4.0f + h)) == cp::fixed_one / 8);
}

TEST_CASE("comparison modes clamp bad factors to [1, max]", "[line_modes][bad_input]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (ModeFn fn :
         {line_compare::pow2_subdivision, line_compare::one_at_a_time, line_compare::even_spacing}) {
        CHECK(run(fn, nan).size() == 2);
        CHECK(run(fn, -inf).size() == 2);
        CHECK(run(fn, -3.0f).size() == 2);
        CHECK(run(fn, 0.0f).size() == 2);
        CHECK(run(fn, inf, 64).size() == 65);
        CHECK(run(fn, 1e30f, 256).size() == 257);
    }
}
