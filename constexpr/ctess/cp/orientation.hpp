// Orientation: which base-triangle vertex becomes the pattern's v0 (docs/algorithm.md §2.13). The CP pattern
// is not rotation-invariant, so the rotation must be fixed per base triangle from data that does not change
// per frame (e.g. edge lengths); choosing it from per-frame factors would pop when the minimum changes.
#pragma once
#include <array>
#include <cstdint>

#include "line.hpp"
#include <ctess/core/domain_point.hpp>

namespace ctess::cp {

// Base triangle w0, w1, w2 (counter-clockwise) with edges E0 = w0w1, E1 = w1w2, E2 = w2w0. Rotation r maps
// pattern vertex v_k to w_{(k + r) mod 3}: a cyclic shift, so the winding is kept. Then e0 = E_r,
// e1 = E_{r+1} and e2 = E_{r+2}.
struct Rotation {
    std::uint8_t shift = 0; // 0, 1 or 2
    friend constexpr bool operator==(const Rotation&, const Rotation&) = default;
};

// Puts the smallest edge on e2 (v0-v2). Ties go to the lowest edge index; NaN counts as larger than any
// length, so a NaN never becomes the smallest unless all three are NaN (then edge 0). Pass lengths (or
// squared lengths, or any per-triangle constant measure), not per-frame factors.
constexpr Rotation smallest_edge_rotation(float l0, float l1, float l2) {
    const float l[3] = {l0, l1, l2};
    unsigned smallest = 0;
    for (unsigned k = 1; k < 3; ++k) {
        if (is_nan(l[k])) continue;
        if (is_nan(l[smallest]) || l[k] < l[smallest]) smallest = k;
    }
    return {static_cast<std::uint8_t>((smallest + 1) % 3)}; // E_{r+2} = E_smallest
}

// The base vertex that is pattern vertex v_k.
constexpr unsigned base_vertex(Rotation r, unsigned k) {
    return (k + r.shift) % 3;
}

// Pattern factors (f0, f1, f2) from the base edge factors (E0, E1, E2).
constexpr std::array<float, 3> rotate_factors(Rotation r, const std::array<float, 3>& base_factors) {
    return {base_factors[r.shift % 3], base_factors[(r.shift + 1) % 3], base_factors[(r.shift + 2) % 3]};
}

// A pattern point as the base triangle's (u, v), i.e. the weights of w1 and w2, exactly (units of fixed_one).
// The weights of v0, v1, v2 are (1 - u - v, u, v); v_k's weight moves to w_{(k + r) mod 3}.
constexpr DomainPoint to_base_point(Rotation r, DomainPoint p) {
    const std::uint32_t w[3] = {fixed_one - p.u - p.v, p.u, p.v};
    std::uint32_t base[3] = {0, 0, 0};
    for (unsigned k = 0; k < 3; ++k) base[base_vertex(r, k)] = w[k];
    return {base[1], base[2]};
}

} // namespace ctess::cp
