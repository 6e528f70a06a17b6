// The one rounding rule of uniform-density factors (docs/algorithm.md §3.4): a float edge factor to the
// integer factor of a stored pattern. UniformPatch, UniformSplit's root, the mesh pipeline, the CLI, the
// report and the shaders (which the generator gives the same rule) all call or mirror this function.
//
//   NaN, -inf, -0, negatives and anything below 1.5   ->  1
//   [1.5, max_factor - 0.5)                           ->  the nearest integer, halves up
//   max_factor - 0.5 and above, +inf                  ->  max_factor
//
// Computed on the float's bits with integers only, so that no compiler flag (-ffast-math, which may assume
// no NaN and reassociate, or FMA contraction) can change a result: both patches on an edge round alike.
#pragma once
#include <bit>
#include <cstdint>

namespace ctess::uniform {

// max_factor in [1, 2^23].
constexpr std::uint32_t round_factor(float f, std::uint32_t max_factor) noexcept {
    constexpr std::uint32_t one_and_a_half = 0x3FC00000u; // 1.5f
    constexpr std::uint32_t infinity = 0x7F800000u;
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(f);
    // Negative floats have the sign bit (bits >= 2^31), NaNs lie above +inf: every one of them gives 1.
    if (bits < one_and_a_half || bits > infinity) return 1u;
    const std::uint32_t exponent = (bits >> 23) - 127u; // f in [2^exponent, 2^(exponent + 1)), exponent >= 0
    if (exponent >= 23u) return max_factor;             // f >= 2^23 (+inf too) is above any max_factor
    const std::uint32_t mantissa = (bits & 0x7FFFFFu) | 0x800000u; // f = mantissa * 2^(exponent - 23)
    const std::uint32_t shift = 23u - exponent;                    // in [1, 23]
    const std::uint32_t rounded = (mantissa + (1u << (shift - 1u))) >> shift; // halves up, exact
    return rounded < max_factor ? rounded : max_factor;
}

// Whether f rounds to a factor of a table of maximum n (else UniformSplit splits it, §3.5).
constexpr bool within_table(float f, std::uint32_t n) noexcept {
    return round_factor(f, n + 1u) <= n;
}

static_assert(round_factor(1.4999999f, 16) == 1 && round_factor(1.5f, 16) == 2 &&
              round_factor(2.5f, 16) == 3);
static_assert(round_factor(3.4999998f, 16) == 3); // f + 0.5f in float would round this tie up to 4
static_assert(round_factor(15.5f, 16) == 16 && round_factor(1e30f, 16) == 16 && round_factor(-2.0f, 16) == 1);
static_assert(round_factor(std::bit_cast<float>(0x7F800000u), 16) == 16); // +inf
static_assert(round_factor(std::bit_cast<float>(0x7FC00000u), 16) == 1);  // NaN
static_assert(round_factor(std::bit_cast<float>(0xFF800000u), 16) == 1);  // -inf
static_assert(round_factor(300.7f, 256) == 256 && round_factor(255.49998f, 256) == 255);
static_assert(within_table(16.49f, 16) && !within_table(16.5f, 16));

} // namespace ctess::uniform
