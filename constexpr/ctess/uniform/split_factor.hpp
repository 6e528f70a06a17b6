// The exact factors of uniform-density splitting (docs/algorithm.md §3.5, "Exact factors"). A subpatch edge's
// factor is its length in its parent's metric (§3.1), a square root; every decision of the split (an edge's
// pieces, the dice limit, a leaf's rounded factors) reads it as its square in fixed point, f^2 * 2^32 in 64
// bits, computed from the parent's squares with integers only. So the CPU, the Cortex-M4 and the shaders
// (which have no double precision) take the same decisions under any compiler flags, and an edge's two
// patches take them alike (the formula is symmetric in the edge's direction).
//
//   root edge of factor t      s = t^2 * 2^32                       exact (t <= 32768: s <= 2^62)
//   segment (du, dv) inside    s = floor(max(0, q) / 65534^2)       q = -s2 dv dw - s0 dw du - s1 du dv,
//     a parent of squares s                                          dw = -du - dv, exact in 96 bits
//   piece of an edge           the segment rule with dv = 0: floor(s du^2 / 65534^2)
//   rounded factor             floor(f + 1/2) = (floor(2f) + 1) / 2, floor(2f) = the largest m with
//                              m^2 2^30 <= s (at most 65536), exact
//
// No segment of a triangle is longer in its metric than its longest side (the squared length is convex along
// each side of the difference hexagon), so every square stays at most 2^62. du and dv are in the local units
// of the patterns (65534, uniform/quantise.hpp).
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "quantise.hpp"

namespace ctess::uniform {

// f^2 * 2^32 (squared_factor_one = 2^32 is f = 1).
using SquaredFactor = std::uint64_t;
inline constexpr std::uint64_t squared_factor_one = std::uint64_t{1} << 32;
inline constexpr std::uint64_t squared_factor_max = std::uint64_t{1} << 62; // f = 32768

constexpr SquaredFactor squared_factor(std::uint32_t t) noexcept {
    return std::uint64_t{t} * t * squared_factor_one; // callers keep t <= 32768
}

namespace split_factor_detail {

// An unsigned 128-bit value in two words: the products s * c below (< 2^96), portable to targets without
// __int128 (the Cortex-M4 build).
struct Wide {
    std::uint64_t hi = 0, lo = 0;
};
// a * b from four 32-bit products (what the shaders do, in 16-bit halves).
constexpr Wide multiply_in_halves(std::uint64_t a, std::uint64_t b) noexcept {
    const std::uint64_t a0 = a & 0xFFFFFFFFu, a1 = a >> 32, b0 = b & 0xFFFFFFFFu, b1 = b >> 32;
    const std::uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    const std::uint64_t middle = (p00 >> 32) + (p01 & 0xFFFFFFFFu) + (p10 & 0xFFFFFFFFu); // < 3 * 2^32
    return {p11 + (p01 >> 32) + (p10 >> 32) + (middle >> 32), (middle << 32) | (p00 & 0xFFFFFFFFu)};
}
constexpr Wide multiply(std::uint64_t a, std::uint64_t b) noexcept {
#if defined(__SIZEOF_INT128__)
    __extension__ using wide_product = unsigned __int128; // one instruction where the target has it
    const wide_product p = static_cast<wide_product>(a) * b;
    return {static_cast<std::uint64_t>(p >> 64), static_cast<std::uint64_t>(p)};
#else
    return multiply_in_halves(a, b);
#endif
}
constexpr Wide add(Wide x, Wide y) noexcept {
    const std::uint64_t lo = x.lo + y.lo;
    return {x.hi + y.hi + (lo < x.lo ? 1u : 0u), lo};
}
constexpr bool less(Wide x, Wide y) noexcept {
    return x.hi != y.hi ? x.hi < y.hi : x.lo < y.lo;
}
constexpr Wide subtract(Wide x, Wide y) noexcept { // x >= y
    return {x.hi - y.hi - (x.lo < y.lo ? 1u : 0u), x.lo - y.lo};
}
// floor(x / 65534^2) for x < 2^96, in two 32-bit steps of long division (each remainder is below
// 65534^2 < 2^32, so each step's dividend fits 64 bits and its quotient 32).
constexpr std::uint64_t divide_by_unit_squared(Wide x) noexcept {
    constexpr std::uint64_t d = std::uint64_t{fixed_one} * fixed_one;
    const std::uint64_t high = (x.hi << 32) | (x.lo >> 32); // x.hi < 2^32
    const std::uint64_t low = ((high % d) << 32) | (x.lo & 0xFFFFFFFFu);
    return ((high / d) << 32) | (low / d);
}

} // namespace split_factor_detail

// The squared factor of segment (du, dv) in the metric whose sides have squared factors s (§3.1; s0 on
// e0 = v0v1, s1 on e1 = v1v2, s2 on e2 = v2v0): floor(max(0, q) / 65534^2), exact.
constexpr SquaredFactor segment_squared_factor(const std::array<SquaredFactor, 3>& s, std::int64_t du,
                                               std::int64_t dv) noexcept {
    namespace d = split_factor_detail;
    const std::int64_t dw = -du - dv;
    // Along a side's direction one coefficient is left: dv = 0 gives s0 du^2, dw = 0 s1 du^2, du = 0 s2 dv^2
    // (every piece of an edge, and the interior edges of a regular grid): the general sum's value, sooner.
    if (du == 0 || dv == 0 || dw == 0) {
        const int k = dv == 0 ? 0 : dw == 0 ? 1 : 2;
        const auto span = static_cast<std::uint64_t>(k == 2 ? (dv < 0 ? -dv : dv) : (du < 0 ? -du : du));
        return d::divide_by_unit_squared(d::multiply(s[k], span * span));
    }
    const std::int64_t c[3] = {-dw * du, -du * dv, -dv * dw}; // the coefficients of s0, s1, s2
    d::Wide positive, negative;
    for (int k = 0; k < 3; ++k) {
        const std::uint64_t magnitude = static_cast<std::uint64_t>(c[k] < 0 ? -c[k] : c[k]);
        const d::Wide term = d::multiply(s[k], magnitude);
        if (c[k] < 0)
            negative = d::add(negative, term);
        else
            positive = d::add(positive, term);
    }
    if (!d::less(negative, positive)) return 0;
    return d::divide_by_unit_squared(d::subtract(positive, negative));
}

// The squared factor of the piece of an edge of squared factor s between parameters a and b (units of
// 65534): the segment rule on the edge, floor(s (b - a)^2 / 65534^2).
constexpr SquaredFactor piece_squared_factor(SquaredFactor s, std::uint32_t a, std::uint32_t b) noexcept {
    return segment_squared_factor({s, s, s}, std::int64_t{b} - std::int64_t{a}, 0);
}

// floor(2f) for f = sqrt(s) / 2^16 (s <= 2^62): the largest m with m^2 2^30 <= s, at most 65536. At run time
// from a float guess, then corrected exactly (the loops make any guess exact, whatever the floating-point
// flags; the shaders guess and correct the same way).
constexpr std::uint32_t floor_twice_factor(SquaredFactor s) noexcept {
    const auto fits = [s](std::uint64_t m) { return (m * m << 30) <= s; }; // m <= 65537: no overflow
    std::uint64_t m = 0;
    if (std::is_constant_evaluated()) {
        for (int bit = 16; bit >= 0; --bit)
            if (fits(m | (std::uint64_t{1} << bit))) m |= std::uint64_t{1} << bit;
        return static_cast<std::uint32_t>(m);
    }
    // A float guess is within one of m (s to float and the square root lose 2^-24 relative: m <= 65536 moves
    // by less than 0.01); single precision is what the Cortex-M4's FPU and the shaders have.
    const float guess = std::sqrt(static_cast<float>(s)) * (1.0f / 32768.0f);
    m = guess >= 65536.0f ? 65536u
                          : static_cast<std::uint64_t>(static_cast<std::int32_t>(guess > 0 ? guess : 0));
    while (m > 0 && !fits(m)) --m;
    while (m < 65536 && fits(m + 1)) ++m;
    return static_cast<std::uint32_t>(m);
}

// floor(f + 1/2): the largest k with 2k - 1 <= floor(2f).
constexpr std::uint32_t rounded_factor(SquaredFactor s) noexcept {
    return (floor_twice_factor(s) + 1) / 2;
}

// The square at which f reaches k - 1/2, (2k - 1)^2 2^30 (k <= 32768): f rounds to k or more from it on.
constexpr SquaredFactor half_below_squared(std::uint32_t k) noexcept {
    return std::uint64_t{2 * k - 1} * (2 * k - 1) << 30;
}

// Whether f is below n + 1/2: floor(2f) < 2n + 1, a comparison.
constexpr bool below_half_past(SquaredFactor s, std::uint32_t n) noexcept {
    return s < half_below_squared(n + 1);
}

// floor(f + 1/2) clamped to [1, n] (n <= 255, a leaf's table factor): the largest k in [1, n] with
// s >= half_below_squared(k). At run time from a float guess (within one of k, whatever it rounds) corrected
// by comparisons; in constant expressions (and in the shaders) by a binary search of those squares.
constexpr std::uint32_t rounded_factor_within(SquaredFactor s, std::uint32_t n) noexcept {
    if (!std::is_constant_evaluated()) {
        const float guess = std::sqrt(static_cast<float>(s)) * (1.0f / 65536.0f) + 0.5f;
        std::uint32_t k = guess >= static_cast<float>(n) ? n
                          : guess < 1.0f                 ? 1u
                                                         : static_cast<std::uint32_t>(guess);
        while (k > 1 && s < half_below_squared(k)) --k;
        while (k < n && s >= half_below_squared(k + 1)) ++k;
        return k;
    }
    std::uint32_t low = 1, high = n; // the answer lies in [low, high]
    while (low < high) {
        const std::uint32_t mid = (low + high + 1) / 2;
        if (s >= half_below_squared(mid))
            low = mid;
        else
            high = mid - 1;
    }
    return low;
}

// The interior dice limit: (n * tolerance)^2 * 2^32 in doubles, rounded up to an integer, so that an edge is
// within it when s < limit (f < n * tolerance, to within the doubles' rounding of the product, below 2^48).
// Its value is a definition: this one expression, computed once per patch (and for the shaders by the
// generator), so every decision and both sides of an edge read the same limit.
constexpr std::uint64_t interior_limit_squared(std::uint32_t n, double tolerance) noexcept {
    const double x = static_cast<double>(n) * tolerance;
    const double limit = x * x * static_cast<double>(squared_factor_one);
    const auto floor_limit = static_cast<std::uint64_t>(limit);
    return static_cast<double>(floor_limit) < limit ? floor_limit + 1 : floor_limit;
}

// The factor as a double (for reports and the Leaf's real factors): never read by a decision.
inline double factor_of(SquaredFactor s) noexcept {
    return std::sqrt(static_cast<double>(s)) / 65536.0;
}

static_assert(squared_factor(32768) == squared_factor_max);
static_assert(rounded_factor(squared_factor(7)) == 7 && rounded_factor(0) == 0 &&
              rounded_factor(squared_factor(32768)) == 32768);
// Halves up: 8.5 = 17 / 2 is exact, 8.5 - 2^-16 rounds down.
static_assert(rounded_factor(piece_squared_factor(squared_factor(17), 0, fixed_one / 2)) == 9);
static_assert(rounded_factor((std::uint64_t{17 * 65536 - 2} * (17 * 65536 - 2)) / 4) == 8);
static_assert(below_half_past(squared_factor(16), 16) && !below_half_past(squared_factor(33) / 4, 16) &&
              below_half_past(squared_factor(33) / 4 - 1, 16));
static_assert(rounded_factor_within(0, 16) == 1 && rounded_factor_within(squared_factor(99), 16) == 16 &&
              rounded_factor_within(half_below_squared(7), 16) == 7 &&
              rounded_factor_within(half_below_squared(7) - 1, 16) == 6);
// A whole edge (du = 65534) keeps its square; both directions of a segment give the same square.
static_assert(piece_squared_factor(squared_factor(300), 0, fixed_one) == squared_factor(300));
static_assert(segment_squared_factor({squared_factor(40), squared_factor(30), squared_factor(20)}, 1234,
                                     -567) ==
              segment_squared_factor({squared_factor(40), squared_factor(30), squared_factor(20)}, -1234,
                                     567));
// The side e1 (du = -dv, a whole side) measures s1; a degenerate metric clamps at 0.
static_assert(segment_squared_factor({squared_factor(40), squared_factor(30), squared_factor(20)}, -65534,
                                     65534) == squared_factor(30));
static_assert(segment_squared_factor({squared_factor(1), squared_factor(1), squared_factor(100)}, -65534,
                                     32767) == 0); // v1 to the middle of the long side
static_assert(interior_limit_squared(16, 1.0) == squared_factor(16));

} // namespace ctess::uniform
