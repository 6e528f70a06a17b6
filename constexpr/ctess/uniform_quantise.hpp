// Seed 001's symmetric 16-bit quantisation of uniform-density barycentrics (docs/algorithm.md §3.2):
// 1.0 = 65534, so 0.5 = 32767 is exact; on an edge the smaller (median) coordinate is rounded and the larger
// re-derived, so point i of f and point f - i of f are mirror images bit for bit.
#pragma once
#include <cstdint>

namespace ctess::uniform {

inline constexpr std::uint32_t fixed_one = 65534;

// The quantised weight of an edge's end corner at point i of f segments (0 <= i <= f, f >= 1), rounded half
// up from the exact i / f on the smaller side.
constexpr std::uint32_t edge_parameter(std::uint32_t i, std::uint32_t f) {
    const std::uint32_t small = i <= f - i ? i : f - i;
    const std::uint32_t q = (2u * small * fixed_one + f) / (2u * f);
    return i <= f - i ? q : fixed_one - q;
}

} // namespace ctess::uniform
