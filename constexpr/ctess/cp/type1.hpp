// Type 1 (f0 <= 2 and f2 <= 2, not all f <= 1): a hexagon fan around one sliding interior point P plus three
// corner triangles (docs/algorithm.md §2.8).
#pragma once
#include <cstdint>

#include "line.hpp"
#include <ctess/core/domain_point.hpp>

namespace ctess::cp {

// P(t0, t2) with x = (t0 + (1-t0) t2 (1-t2)) / 2, y = (1-t0)(t0 + t2 - t0 t2) / 2, from the 16-bit lerps, in
// units of 2^-24, rounded half up. Exact at the values that join the neighbouring patterns: P = v0 at
// t0 = t2 = 0, the midpoint of e0 at t0 = 1, (t0/2, (1-t0)/2) at t2 = 1. Products stay below 2^50.
constexpr DomainPoint type1_center(std::uint32_t t16_0, std::uint32_t t16_2) {
    const std::uint64_t a = t16_0 > lerp_one ? lerp_one : t16_0;
    const std::uint64_t c = t16_2 > lerp_one ? lerp_one : t16_2;
    const std::uint64_t one = lerp_one;
    const std::uint64_t x = (a << 32) + (one - a) * c * (one - c);
    const std::uint64_t y = (one - a) * (one * (a + c) - a * c);
    const std::uint64_t half = std::uint64_t{1} << 24;
    return {static_cast<std::uint32_t>((x + half) >> 25), static_cast<std::uint32_t>((y + half) >> 25)};
}

// Vertex slots of a Type 1 patch before the T0 collapse: the boundary loop counter-clockwise from v0, then P.
struct Type1Slots {
    unsigned n1 = 3; // e1 segments
    static constexpr unsigned v0 = 0;
    static constexpr unsigned a0 = 1;
    static constexpr unsigned b0 = 2;
    constexpr unsigned e1(unsigned b) const { return 3 + b; } // R_b; R_0 = v1, R_n1 = v2
    constexpr unsigned b2() const { return 4 + n1; }
    constexpr unsigned a2() const { return 5 + n1; }
    constexpr unsigned center() const { return 6 + n1; }
    constexpr unsigned count() const { return 7 + n1; }
    // Hexagon H = (A0, B0, R_1, ..., R_{n1-1}, B2, A2), m = n1 + 3 vertices.
    constexpr unsigned hexagon(unsigned k) const {
        const unsigned m = n1 + 3;
        k %= m;
        if (k == 0) return a0;
        if (k == 1) return b0;
        if (k < m - 2) return e1(k - 1);
        return k == m - 2 ? b2() : a2();
    }
};

// Calls emit(s0, s1, s2) with slots for the n1 + 6 triangles, counter-clockwise, first vertex unique: the
// corners (v0, A0, A2), (v1, R_1, B0), (v2, B2, R_{n1-1}), then the fan (H_{k+1}, P, H_k), k = 0..m-1.
template <class Emit>
constexpr void for_each_type1_triangle(const Type1Slots& s, Emit&& emit) {
    emit(s.v0, s.a0, s.a2());
    emit(s.e1(0), s.e1(1), s.b0);
    emit(s.e1(s.n1), s.b2(), s.e1(s.n1 - 1));
    const unsigned m = s.n1 + 3;
    for (unsigned k = 0; k < m; ++k) emit(s.hexagon(k + 1), s.center(), s.hexagon(k));
}

} // namespace ctess::cp
