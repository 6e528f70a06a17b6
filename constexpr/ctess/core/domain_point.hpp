// A point of the tessellation domain as exact fixed-point coordinates. The unit (fixed_one) depends on the
// algorithm: 2^16 for D3D11 (16.16, as the reference), 2^24 for CP (1/256 grid with a 16-bit lerp).
#pragma once
#include <cstdint>

#include "fixed_point.hpp"

namespace ctess {

struct DomainPoint {
    std::uint32_t u = 0;
    std::uint32_t v = 0;
    friend constexpr bool operator==(const DomainPoint&, const DomainPoint&) = default;
};

} // namespace ctess
