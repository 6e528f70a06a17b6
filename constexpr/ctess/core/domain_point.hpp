// DomainPoint: a point of a CP pattern or of the mesh pipeline's base triangle, in units of 2^-24
// (FixedPoint<units::cp>). The other families have their own point types (core/fixed_point.hpp):
// d3d11::Point (2^16), uniform::Point (65534) and uniform::SplitPoint (65534^2); mixing them does not
// compile.
#pragma once
#include <cstdint>

#include "fixed_point.hpp"

namespace ctess {

using DomainPoint = FixedPoint<units::cp>;

} // namespace ctess
