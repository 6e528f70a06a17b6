// Exact fixed-point domain points, one type per unit, so that points of different units cannot be mixed
// (docs/algorithm.md §0, "Units"). Each pattern family writes its points in its own unit:
//
//   unit               one           used by
//   units::cp          2^24          CP patterns and the mesh pipeline's base weights (cp::fixed_one)
//   units::d3d11       2^16          the D3D11 tessellator (16.16, as the reference; d3d11::fixed_one)
//   units::uniform     65534         uniform-density patterns (uniform::fixed_one)
//   units::split       65534^2       UniformSplit's points on the root patch
//   units::bintree     2^16          the adaptive bintree's parameter square (adaptive::fixed_one)
//
// Conversions that are exact are functions (exact_convert); the others round by a rule their own function
// names (e.g. rt::uniform_weight_to_fixed).
#pragma once
#include <concepts>
#include <cstdint>

namespace ctess {

namespace units {
struct cp {
    static constexpr std::uint32_t one = 1u << 24;
};
struct d3d11 {
    static constexpr std::uint32_t one = 1u << 16;
};
struct uniform {
    static constexpr std::uint32_t one = 65534;
};
struct split {
    static constexpr std::uint32_t one = 65534u * 65534u;
};
struct bintree {
    static constexpr std::uint32_t one = 1u << 16;
};
} // namespace units

// A point (u, v) of the patch domain in units of Unit::one: the vertex v0 + u (v1 - v0) + v (v2 - v0) of a
// triangle (weights w0 = one - u - v, w1 = u, w2 = v), or (u, v) of the parameter square.
template <class Unit>
struct FixedPoint {
    using unit = Unit;
    static constexpr std::uint32_t one = Unit::one;
    std::uint32_t u = 0;
    std::uint32_t v = 0;
    friend constexpr bool operator==(const FixedPoint&, const FixedPoint&) = default;
};

// Whether every point of unit From is exactly a point of unit To: To::one a multiple of From::one.
template <class From, class To>
inline constexpr bool exactly_convertible = To::one % From::one == 0;

// p in the unit To, exactly (To::one a multiple of From::one; a coordinate in [0, From::one] cannot wrap).
template <class To, class From>
requires exactly_convertible<From, To>
constexpr FixedPoint<To> exact_convert(FixedPoint<From> p) noexcept {
    constexpr std::uint32_t scale = To::one / From::one;
    return {p.u * scale, p.v * scale};
}

} // namespace ctess
