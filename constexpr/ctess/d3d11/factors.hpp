// D3D11 tessellation factor processing (docs/algorithm.md §5.1): culling, clamping to the partitioning's
// range, integer rounding, parity and the conversion to unsigned 16.16 fixed point. Everything after this
// step is integer math.
//
// Bad input, as the hardware reference defines it:
//   * an edge factor that is NaN, zero, negative or -inf culls the patch (the inside factor never culls);
//   * anything else is clamped to the partitioning's range with IEEE-754R min/max, so +inf and huge values
//   give
//     the upper bound, and a positive denormal gives the lower bound;
//   * an inside factor that is NaN, zero, negative or -inf gives the lower bound.
#pragma once
#include <cstddef>
#include <cstdint>

#include <ctess/core/fixed_point.hpp>
#include <ctess/core/numeric.hpp>

namespace ctess::d3d11 {

inline constexpr std::uint32_t fixed_one = units::d3d11::one; // 16.16
// A point of a D3D11 domain in units of fixed_one (the reference tessellator's 16.16).
using Point = FixedPoint<units::d3d11>;
inline constexpr std::uint32_t fixed_half = fixed_one / 2;

// Values as in D3D11_TESSELLATOR_PARTITIONING. pow2 behaves exactly like integer in the hardware (the
// reference's CHWTessellator): rounding up to a power of two is the HLSL hull shader's job, not the
// tessellator's.
enum class Partitioning : std::uint8_t { integer, pow2, fractional_odd, fractional_even };

// Point spacing of one factor. Integer partitioning picks it per factor from the rounded value.
enum class Parity : std::uint8_t { even, odd };

constexpr bool is_integer_partitioning(Partitioning p) {
    return p == Partitioning::integer || p == Partitioning::pow2;
}

struct FactorRange {
    float lo = 1.0f;
    float hi = 64.0f;
};

// Edge factor range of a partitioning: integer/pow2 [1, 64], fractional_odd [1, 63], fractional_even [2, 64].
constexpr FactorRange factor_range(Partitioning p) {
    switch (p) {
    case Partitioning::fractional_odd:
        return {1.0f, 63.0f};
    case Partitioning::fractional_even:
        return {2.0f, 64.0f};
    default:
        return {1.0f, 64.0f};
    }
}

// Isoline density is always integer and ranges over [1, 64].
inline constexpr FactorRange isoline_density_range = {1.0f, 64.0f};

// Fractional_odd raises the inside lower bound to 1 + 2^-16 once any factor would exceed 1 in fixed point
// (> 1 + 2^-17), so that the patch always gets a "picture frame" of at least 3 inside segments.
inline constexpr float odd_frame_threshold = 1.0f + 1.0f / 131072.0f;
inline constexpr float odd_frame_inside_lo = 1.0f + 1.0f / 65536.0f;

// NaN, zero, negatives and -inf cull; a positive denormal does not.
constexpr bool culls(float edge_factor) {
    return !(edge_factor > 0.0f);
}

// Clamp with IEEE-754R min/max, NaN -> lo.
constexpr float clamp_factor(float f, FactorRange r) {
    return ieee_fmin(r.hi, ieee_fmax(r.lo, f));
}

// ceil of a clamped factor in [1, 64]; exact since such a float and its integer part are both representable.
constexpr float ceil_factor(float f) {
    const auto whole = static_cast<std::uint32_t>(f);
    return static_cast<float>(whole) < f ? static_cast<float>(whole + 1) : static_cast<float>(whole);
}

constexpr Parity parity_of_integer(float rounded) {
    return (static_cast<std::uint32_t>(rounded) & 1u) != 0 ? Parity::odd : Parity::even;
}

// The fractional modes fix the parity for every factor.
constexpr Parity mode_parity(Partitioning p) {
    return p == Partitioning::fractional_odd ? Parity::odd : Parity::even;
}

// A factor ready for point placement: unsigned 16.16 value and parity.
struct FixedFactor {
    std::uint32_t value = fixed_one;
    Parity parity = Parity::odd;
    friend constexpr bool operator==(const FixedFactor&, const FixedFactor&) = default;
};

// An edge factor (or isoline detail) that did not cull: clamp, round up for integer modes, convert.
constexpr FixedFactor process_edge_factor(Partitioning p, float f) {
    float clamped = clamp_factor(f, factor_range(p));
    if (!is_integer_partitioning(p)) return {to_fixed_16_16(clamped), mode_parity(p)};
    clamped = ceil_factor(clamped);
    return {to_fixed_16_16(clamped), parity_of_integer(clamped)};
}

// An inside factor, given the lower bound in force (see odd_frame_inside_lo). Integer modes count an inside
// factor of exactly 1 as even, which turns the centre into a single point that the transition stitches to.
constexpr FixedFactor process_inside_factor(Partitioning p, float f, float lo) {
    float clamped = clamp_factor(f, {lo, factor_range(p).hi});
    if (!is_integer_partitioning(p)) return {to_fixed_16_16(clamped), mode_parity(p)};
    clamped = ceil_factor(clamped);
    const Parity parity = clamped == 1.0f ? Parity::even : parity_of_integer(clamped);
    return {to_fixed_16_16(clamped), parity};
}

// The inside lower bound for a patch whose edges (already clamped, as floats) are given. Quads also pass
// their raw inside factors here, as the reference does; triangles pass only the edges.
template <std::size_t N>
constexpr float inside_lower_bound(Partitioning p, const float (&factors)[N]) {
    if (p != Partitioning::fractional_odd) return factor_range(p).lo;
    for (const float f : factors)
        if (f > odd_frame_threshold) return odd_frame_inside_lo;
    return factor_range(p).lo;
}

// Edge factor after clamping and integer rounding, still as a float (the odd picture-frame test uses it).
constexpr float clamped_edge_float(Partitioning p, float f) {
    const float clamped = clamp_factor(f, factor_range(p));
    return is_integer_partitioning(p) ? ceil_factor(clamped) : clamped;
}

} // namespace ctess::d3d11
