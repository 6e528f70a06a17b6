// Karis 2026's symmetric 16-bit quantisation of uniform-density barycentrics (docs/algorithm.md §3.2):
// 1.0 = 65534, so 0.5 = 32767 is exact; on an edge the smaller (median) coordinate is rounded and the larger
// re-derived, so point i of f and point f - i of f are mirror images bit for bit.
#pragma once
#include <cstdint>

#include <ctess/core/fixed_point.hpp>

namespace ctess::uniform {

inline constexpr std::uint32_t fixed_one = units::uniform::one;
// A point of a uniform-density pattern (units of 65534) and of a split patch on its root (units of 65534^2).
using Point = FixedPoint<units::uniform>;
using SplitPoint = FixedPoint<units::split>;

// The quantised weight of an edge's end corner at point i of f segments (0 <= i <= f, f >= 1), rounded half
// up from the exact i / f on the smaller side.
constexpr std::uint32_t edge_parameter(std::uint32_t i, std::uint32_t f) {
    const std::uint32_t small = i <= f - i ? i : f - i;
    const std::uint32_t q = (2u * small * fixed_one + f) / (2u * f);
    return i <= f - i ? q : fixed_one - q;
}

// edge_parameter without a division, for a bulk emit (docs/algorithm.md §3.4): the rounded quotient by 2f as
// a multiply by edge_reciprocal(f) = ceil(2^32 / 2f) and a shift. Exact up to f = 238 (the first failure is
// at 239); the static_assert below checks equality with edge_parameter for every 0 <= i <= f <= 128.
constexpr std::uint32_t edge_reciprocal(std::uint32_t f) {
    return 0xFFFFFFFFu / (2u * f) + 1u;
}

constexpr std::uint32_t edge_parameter(std::uint32_t i, std::uint32_t f, std::uint32_t reciprocal) {
    const std::uint32_t small = i <= f - i ? i : f - i;
    const std::uint64_t numerator = 2u * small * fixed_one + f;
    const std::uint32_t q = static_cast<std::uint32_t>(numerator * reciprocal >> 32);
    return i <= f - i ? q : fixed_one - q;
}

// Whether the reciprocal form equals the division for every 0 <= i <= f <= max_f (exhaustive).
constexpr bool edge_reciprocal_exact(std::uint32_t max_f) {
    for (std::uint32_t f = 1; f <= max_f; ++f)
        for (std::uint32_t i = 0; i <= f; ++i)
            if (edge_parameter(i, f, edge_reciprocal(f)) != edge_parameter(i, f)) return false;
    return true;
}
static_assert(edge_reciprocal_exact(128), "the reciprocal edge parameter must equal the division");

} // namespace ctess::uniform
