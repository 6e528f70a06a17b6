// D3D11 point placement along one edge (docs/algorithm.md §5.2): the per-factor context and the 16.16
// position of point p.
//
// A fractional factor lies between two uniform partitions, floor and ceil of the half factor. Each point is
// the fixed-point lerp of its positions on both; one point (the "split", chosen by the ruler function) is
// duplicated on the floor partition. Only the lower half is computed; the upper half is its complement, so
// every edge is exactly mirror-symmetric and two patches sharing an edge place identical points.
#pragma once
#include <cstdint>

#include "factors.hpp"

namespace ctess::d3d11 {

// 16.16 reciprocal of a segment count, rounded to nearest: reproduces the reference's 64-entry table.
constexpr std::uint32_t fixed_reciprocal(std::uint32_t segments) {
    return segments == 0 ? 0xffffffffu : (fixed_one + segments / 2) / segments;
}

// x without its highest set bit (0 stays 0).
constexpr std::uint32_t remove_msb(std::uint32_t x) {
    if (x == 0) return 0;
    return x & ~(std::uint32_t{1} << floor_log2(x));
}

constexpr std::uint32_t fixed_floor(std::uint32_t x) {
    return x & ~(fixed_one - 1);
}
constexpr std::uint32_t fixed_ceil(std::uint32_t x) {
    return (x & (fixed_one - 1)) != 0 ? fixed_floor(x) + fixed_one : x;
}

// Points on an edge, both endpoints included. "+1" rounds the halving up, so a factor one unit above an
// integer of the right parity already gets the next segment count.
constexpr std::uint32_t point_count(FixedFactor f) {
    const std::uint32_t half = (f.value + 1) / 2;
    if (f.parity == Parity::odd) return (fixed_ceil(fixed_half + half) * 2) >> 16;
    return ((fixed_ceil(half) * 2) >> 16) + 1;
}

// Everything point placement needs about one factor.
struct EdgeContext {
    std::uint32_t inv_floor_segments = 0; // 16.16 reciprocal of the floor partition's segment count
    std::uint32_t inv_ceil_segments = 0;
    std::uint32_t half_fraction = 0; // lerp weight of the ceil partition, 16.16
    std::uint32_t half_points = 0;   // points on the half edge (even: without the fixed midpoint)
    std::uint32_t split_point = 0;   // the point duplicated on the floor partition
    Parity parity = Parity::odd;
};

constexpr EdgeContext edge_context(FixedFactor f) {
    const bool odd = f.parity == Parity::odd;
    std::uint32_t half = (f.value + 1) / 2;
    // Odd partitions are offset by half a segment; an even factor of exactly 1 behaves as 2.
    if (odd || half == fixed_half) half += fixed_half;
    const std::uint32_t lo = fixed_floor(half);
    const std::uint32_t hi = fixed_ceil(half);
    EdgeContext c;
    c.parity = f.parity;
    c.half_fraction = half - lo;
    c.half_points = hi >> 16;
    if (lo == hi) {
        c.split_point = c.half_points + 1; // no split: never reached
    } else if (odd) {
        // Ruler function: splits start at the outermost point of each power-of-two epoch and march inward;
        // at the first odd step the corners split, so new points emerge from the endpoints.
        c.split_point = lo == fixed_one ? 0 : 2 * remove_msb((lo >> 16) - 1) + 1;
    } else {
        c.split_point = 2 * remove_msb(lo >> 16) + 1;
    }
    const std::uint32_t odd_offset = odd ? 1 : 0;
    c.inv_floor_segments = fixed_reciprocal(((lo * 2) >> 16) - odd_offset);
    c.inv_ceil_segments = fixed_reciprocal(((hi * 2) >> 16) - odd_offset);
    return c;
}

// Position of point p (0 <= p < point_count) in 16.16. Unsigned 32-bit arithmetic, as the reference: the
// products stay below 2^31 because lower-half positions are at most 0.5.
constexpr std::uint32_t place_point(const EdgeContext& c, std::uint32_t p) {
    bool flip = false;
    if (p >= c.half_points) {
        p = 2 * c.half_points - p - (c.parity == Parity::odd ? 1 : 0);
        flip = true;
    }
    if (p == c.half_points) return fixed_half; // the even midpoint, exact
    const std::uint32_t on_floor = p > c.split_point ? p - 1 : p;
    const std::uint32_t loc_floor = on_floor * c.inv_floor_segments;
    const std::uint32_t loc_ceil = p * c.inv_ceil_segments;
    const std::uint32_t wide = loc_floor * (fixed_one - c.half_fraction) + loc_ceil * c.half_fraction;
    const std::uint32_t loc = (wide + fixed_half) >> 16;
    return flip ? fixed_one - loc : loc;
}

inline constexpr unsigned max_edge_points = 65;

// One edge as a triangle-domain edge of this partitioning places it: factor clamped to the mode's range (NaN
// and <= 0 cull and return 0; +inf and huge give the upper bound), rounded up for integer/pow2, parity of the
// mode (integer: of the rounded value). Writes the points 0..N-1 in 16.16, p(0) = 0 and p(N-1) = 65536, when
// out is not null, and returns N (at most max_edge_points).
constexpr unsigned edge_points(Partitioning partitioning, float factor, std::uint32_t* out) {
    if (culls(factor)) return 0;
    const FixedFactor f = process_edge_factor(partitioning, factor);
    const std::uint32_t n = point_count(f);
    if (out != nullptr) {
        const EdgeContext c = edge_context(f);
        for (std::uint32_t p = 0; p < n; ++p) out[p] = place_point(c, p);
    }
    return n;
}

} // namespace ctess::d3d11
