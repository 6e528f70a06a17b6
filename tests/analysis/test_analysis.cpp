// The analysis library's own pieces (tools/analysis): the signed-area helper's sign, unit and width, and the
// movement metrics on patterns whose moves are known.
#include <catch2/catch.hpp>

#include <ctess/analysis/movement.hpp>
#include <ctess/analysis/signed_area.hpp>
#include <ctess/core/domain_point.hpp>

#include <cstdint>
#include <limits>
#include <vector>

using ctess::DomainPoint;
using ctess::analysis::int128;
using ctess::analysis::signed_area2;

TEST_CASE("signed_area2: counter-clockwise positive, exact in the squared fixed-point unit", "[analysis]") {
    STATIC_REQUIRE(signed_area2({0, 0}, {4, 0}, {0, 2}) == 8);
    STATIC_REQUIRE(signed_area2({0, 0}, {0, 2}, {4, 0}) == -8);
    STATIC_REQUIRE(signed_area2({3, 3}, {5, 5}, {7, 7}) == 0);
    // The whole domain triangle gives one^2; with one = 65534^2 (a split uniform patch) that needs 128 bits.
    constexpr std::uint32_t one = 65534u * 65534u;
    constexpr int128 full = signed_area2(DomainPoint{0, 0}, DomainPoint{one, 0}, DomainPoint{0, one});
    STATIC_REQUIRE(full == int128{one} * one);
    STATIC_REQUIRE(full > std::numeric_limits<std::int64_t>::max());
    // Largest coordinates and differences of both signs.
    constexpr std::uint32_t top = std::numeric_limits<std::uint32_t>::max();
    STATIC_REQUIRE(signed_area2(DomainPoint{top, 0}, DomainPoint{top, top}, DomainPoint{0, 0}) ==
                   int128{top} * top);
}

TEST_CASE("signed_area2: signed integer and floating-point points", "[analysis]") {
    struct Grid {
        std::int64_t x, y;
    };
    CHECK(signed_area2(Grid{0, 0}, Grid{-1, 0}, Grid{0, -1}) == 1);
    struct Metric {
        double x, y;
    };
    CHECK(signed_area2(Metric{0, 0}, Metric{1, 0}, Metric{0.5, 0.25}) == 0.25);
}

TEST_CASE("movement: edge points matched in order, pops measured to the nearest point", "[analysis]") {
    using ctess::analysis::edge_moves;
    // Two points slide by 0.1 each: no pop.
    const auto slide = edge_moves({0.25, 0.75}, {0.35, 0.65});
    CHECK(slide.total == Approx(0.2));
    CHECK(slide.largest == Approx(0.1));
    CHECK(slide.unmatched == 0);
    CHECK(slide.pop == 0);
    // A point is born at 0.5 beside one that stays: it pops from the nearest point (0.25 away).
    const auto born = edge_moves({0.25}, {0.25, 0.5});
    CHECK(born.total == 0);
    CHECK(born.unmatched == 1);
    CHECK(born.pop == Approx(0.25));
}

TEST_CASE("movement: a sweep over an unchanging pattern moves nothing", "[analysis]") {
    const ctess::analysis::PatternFunction single = [](const ctess::analysis::Factors&,
                                                       ctess::analysis::Pattern& p) {
        p.w = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0.5, 0}};
        p.indices = {0, 3, 2, 3, 1, 2};
    };
    const auto m = ctess::analysis::sweep(single, {2, 2, 2}, {4, 4, 4}, 8);
    CHECK(m.all == 0);
    CHECK(m.edges == 0);
    CHECK(m.unmatched == 0);
    CHECK(m.pop == 0);
    CHECK(m.cumulative.size() == 9);
}
