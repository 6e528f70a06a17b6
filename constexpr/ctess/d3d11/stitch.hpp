// D3D11 connectivity between two rows of points (docs/algorithm.md §5.4): the transition stitch between an
// outer edge and the first inner ring, which follows the ruler-function split order, and the regular stitch
// between two rings.
//
// A stitch walks an inner and an outer row by local positions 0, 1, 2, ...; an IndexRow maps a position to
// the global point index. This covers the rows that wrap around to the ring's first point and the rows the
// reference walks backwards (its "patched" indices).
#pragma once
#include <cstdint>

#include "factors.hpp"
#include <ctess/core/patch_options.hpp>

namespace ctess::d3d11 {

using ctess::Winding; // output primitive TRIANGLE_CW / TRIANGLE_CCW; D3D11 defaults to cw

// Appends triangles given in clockwise order; CCW output swaps the last two indices. A null output only
// counts.
struct TriangleWriter {
    std::uint32_t* out = nullptr;
    Winding winding = Winding::cw;
    std::uint32_t count = 0; // indices emitted so far

    constexpr void add(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        if (out != nullptr) {
            out[count] = a;
            out[count + 1] = winding == Winding::cw ? b : c;
            out[count + 2] = winding == Winding::cw ? c : b;
        }
        count += 3;
    }
};

// Position k of a row -> global point index: base + k (or base - k when walked backwards), except one
// position that is redirected (a ring's last point is its first one).
struct IndexRow {
    static constexpr std::uint32_t none = 0xffffffffu;
    std::uint32_t base = 0;
    bool backwards = false;
    std::uint32_t redirected_position = none;
    std::uint32_t redirected_index = 0;

    constexpr std::uint32_t operator()(std::uint32_t k) const {
        if (k == redirected_position) return redirected_index;
        return backwards ? base - k : base + k;
    }
};

constexpr IndexRow forward_row(std::uint32_t base) {
    return {base, false, IndexRow::none, 0};
}
constexpr IndexRow backward_row(std::uint32_t base) {
    return {base, true, IndexRow::none, 0};
}
// A row of `points` positions whose last position is the ring's first point.
constexpr IndexRow closing_row(std::uint32_t base, std::uint32_t points, std::uint32_t ring_first) {
    return {base, false, points - 1, ring_first};
}

// Final position on a 32-point half edge of the point introduced at step i, in ruler-function order:
// {0, 32, 16, 8, 17, 4, 18, 9, 19, 2, ...} (the reference's table; closed form in docs/algorithm.md §5.4).
constexpr std::uint32_t ruler_final_position(std::uint32_t i) {
    if (i == 0) return 0;
    if (i == 1) return 32;
    std::uint32_t z = 0;
    while (((i - 1) >> z & 1u) == 0) ++z;
    return (16u >> z) + (i - 1 - (1u << z)) / (2u << z);
}

inline constexpr unsigned ruler_steps = 33;

// Ring 1: stitch an outer edge to the first inner side. half_points are the contexts' half-edge point counts.
constexpr void stitch_transition(TriangleWriter& w, IndexRow inner, std::uint32_t inner_half_points,
                                 Parity inner_parity, IndexRow outer, std::uint32_t outer_half_points,
                                 Parity outer_parity) {
    // Odd parities count the half edge without the point nearest the middle.
    const std::uint32_t hi = inner_half_points - (inner_parity == Parity::odd ? 1 : 0);
    const std::uint32_t ho = outer_half_points - (outer_parity == Parity::odd ? 1 : 0);
    std::uint32_t i = 0;
    std::uint32_t o = 0;
    const auto advance_outer = [&] {
        w.add(outer(o), outer(o + 1), inner(i));
        ++o;
    };
    const auto advance_inner = [&] {
        w.add(inner(i), outer(o), inner(i + 1));
        ++i;
    };
    if (ruler_final_position(0) < ho) advance_outer();
    for (std::uint32_t s = 1; s < ruler_steps; ++s) {
        if (ruler_final_position(s) < hi) advance_inner();
        if (ruler_final_position(s) < ho) advance_outer();
    }
    if (inner_parity != outer_parity || inner_parity == Parity::odd) {
        if (inner_parity == outer_parity) { // both odd: a quad across the middle
            w.add(inner(i), outer(o), inner(i + 1));
            w.add(inner(i + 1), outer(o), outer(o + 1));
            ++i;
            ++o;
        } else if (inner_parity == Parity::even) { // the inner midpoint fans to the outer middle segment
            w.add(inner(i), outer(o), outer(o + 1));
            ++o;
        } else {
            w.add(inner(i), outer(o), inner(i + 1));
            ++i;
        }
    }
    for (std::uint32_t s = ruler_steps - 1; s >= 1; --s) {
        if (ruler_final_position(s) < ho) advance_outer();
        if (ruler_final_position(s) < hi) advance_inner();
    }
    if (ruler_final_position(0) < ho) advance_outer();
}

// Which way the diagonals of the quads between two equal rows point.
enum class Diagonals : std::uint8_t {
    inside_to_outside,
    inside_to_outside_except_middle, // odd rows: the middle quad is flipped
    mirrored, // toward the corners: outer-to-inner on the first half, then inner-to-outer
};

// Rings >= 2 (trapezoid: one extra outer point at each end) and the quad domain's centre strip.
constexpr void stitch_regular(TriangleWriter& w, bool trapezoid, Diagonals diagonals,
                              std::uint32_t inner_points, IndexRow inner, IndexRow outer) {
    std::uint32_t i = 0;
    std::uint32_t o = 0;
    const auto quad_outer_first = [&] { // diagonal from the outer row's start to the inner row's end
        w.add(outer(o), outer(o + 1), inner(i));
        w.add(inner(i), outer(o + 1), inner(i + 1));
        ++i;
        ++o;
    };
    const auto quad_inner_first = [&] {
        w.add(inner(i), outer(o), outer(o + 1));
        w.add(inner(i), outer(o + 1), inner(i + 1));
        ++i;
        ++o;
    };
    const auto quad_mirrored = [&] {
        w.add(outer(o), inner(i + 1), inner(i));
        w.add(outer(o), outer(o + 1), inner(i + 1));
        ++i;
        ++o;
    };
    if (trapezoid) {
        w.add(outer(o), outer(o + 1), inner(i));
        ++o;
    }
    const auto n = static_cast<std::int32_t>(inner_points);
    std::int32_t p = 0;
    switch (diagonals) {
    case Diagonals::inside_to_outside:
        for (; p < n - 1; ++p) quad_inner_first();
        break;
    case Diagonals::inside_to_outside_except_middle:
        for (; p < n / 2 - 1; ++p) quad_outer_first();
        quad_mirrored();
        for (p += 2; p < n; ++p) quad_outer_first();
        break;
    case Diagonals::mirrored:
        for (; p < n / 2; ++p) quad_mirrored();
        for (; p < n - 1; ++p) quad_inner_first();
        break;
    }
    if (trapezoid) w.add(outer(o), outer(o + 1), inner(i));
}

} // namespace ctess::d3d11
