// The signed-area helper of the analysis library: the one definition of "twice the signed area" that the
// CLI, the report, the tests and the fuzzers use.
#pragma once
#include <cstdint>
#include <type_traits>

#include <ctess/core/domain_point.hpp>

namespace ctess::analysis {

__extension__ using int128 = __int128;

// Twice the signed area of the triangle a, b, c: positive when a -> b -> c runs counter-clockwise with the
// first coordinate to the right and the second up (u, v for ctess::DomainPoint), zero when degenerate.
// Point is any two-member aggregate (DomainPoint {u, v}, the default for braced arguments, or {x, y}).
//
// Integer coordinates (fixed point): exact, as int128, in the coordinate unit squared. For DomainPoint the
// unit is 1 / one, `one` being the fixed_one of the generator that wrote the points (2^16 for D3D11, 2^24 for
// CP, docs/algorithm.md §1.2; 65534 for uniform density and 65534^2 for its split, §3.2, §3.5): the result is
// in units of 1 / one^2, and the whole domain triangle (0,0), (one,0), (0,one) gives one^2. Differences of
// 32-bit coordinates take 33 bits and their products 66, hence int128; 64-bit coordinates are exact while
// they stay within +-2^62. Floating-point coordinates: in that type, in the coordinates' own unit squared
// (rounded as computed).
template <class Point = DomainPoint>
constexpr auto signed_area2(const Point& a, const Point& b, const Point& c) {
    const auto [ax, ay] = a;
    const auto [bx, by] = b;
    const auto [cx, cy] = c;
    using Coordinate = std::remove_cv_t<decltype(ax)>;
    if constexpr (std::is_floating_point_v<Coordinate>) {
        return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    } else {
        static_assert(std::is_integral_v<Coordinate> && sizeof(Coordinate) <= 8,
                      "signed_area2: integer coordinates of at most 64 bits, or floating point");
        const int128 bu = int128{bx} - ax, bv = int128{by} - ay;
        const int128 cu = int128{cx} - ax, cv = int128{cy} - ay;
        return bu * cv - bv * cu;
    }
}

} // namespace ctess::analysis
