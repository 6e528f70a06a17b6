// Every line tessellation mode behind one enum: the CP line, the four D3D11 partitionings (one tri-domain
// edge), and the comparison modes of Hable 2026's viewer. Used by `ctess line` and `ctess sweep`.
#pragma once
#include <cstdint>
#include <string_view>

#include "line_compare.hpp"
#include <ctess/cp/line.hpp>
#include <ctess/d3d11/edge.hpp>

namespace ctess {

enum class LineMode : std::uint8_t {
    cp,
    d3d11_integer,
    d3d11_pow2,
    d3d11_odd,
    d3d11_even,
    pow2_subdivision,
    one_at_a_time,
    even_spacing,
};

inline constexpr LineMode all_line_modes[] = {
    LineMode::cp,         LineMode::d3d11_integer,    LineMode::d3d11_pow2,    LineMode::d3d11_odd,
    LineMode::d3d11_even, LineMode::pow2_subdivision, LineMode::one_at_a_time, LineMode::even_spacing};

inline constexpr unsigned max_line_points = cp::max_segments + 1;

constexpr std::string_view line_mode_name(LineMode m) {
    switch (m) {
    case LineMode::cp:
        return "cp";
    case LineMode::d3d11_integer:
        return "d3d11-integer";
    case LineMode::d3d11_pow2:
        return "d3d11-pow2";
    case LineMode::d3d11_odd:
        return "d3d11-odd";
    case LineMode::d3d11_even:
        return "d3d11-even";
    case LineMode::pow2_subdivision:
        return "pow2-subdivision";
    case LineMode::one_at_a_time:
        return "one-at-a-time";
    case LineMode::even_spacing:
        return "even-spacing";
    }
    return "";
}

// False when the name is unknown; `out` is left unchanged then.
constexpr bool parse_line_mode(std::string_view name, LineMode& out) {
    for (LineMode m : all_line_modes)
        if (line_mode_name(m) == name) {
            out = m;
            return true;
        }
    return false;
}

constexpr std::uint32_t line_fixed_one(LineMode m) {
    switch (m) {
    case LineMode::d3d11_integer:
    case LineMode::d3d11_pow2:
    case LineMode::d3d11_odd:
    case LineMode::d3d11_even:
        return d3d11::fixed_one;
    default:
        return cp::fixed_one;
    }
}

// The points of an edge with factor f, endpoints included, sorted, in units of line_fixed_one(m). out needs
// max_line_points entries. CP and comparison modes clamp f to [1, max_factor]; D3D11 modes clamp to their own
// range and cull (return 0) for NaN or f <= 0, as the D3D11 tessellator does.
constexpr unsigned line_points(LineMode m, float f, unsigned max_factor, std::uint32_t* out) {
    switch (m) {
    case LineMode::cp:
        return cp::edge_points(f, max_factor, out);
    case LineMode::d3d11_integer:
        return d3d11::edge_points(d3d11::Partitioning::integer, f, out);
    case LineMode::d3d11_pow2:
        return d3d11::edge_points(d3d11::Partitioning::pow2, f, out);
    case LineMode::d3d11_odd:
        return d3d11::edge_points(d3d11::Partitioning::fractional_odd, f, out);
    case LineMode::d3d11_even:
        return d3d11::edge_points(d3d11::Partitioning::fractional_even, f, out);
    case LineMode::pow2_subdivision:
        return line_compare::pow2_subdivision(f, max_factor, out);
    case LineMode::one_at_a_time:
        return line_compare::one_at_a_time(f, max_factor, out);
    case LineMode::even_spacing:
        return line_compare::even_spacing(f, max_factor, out);
    }
    return 0;
}

} // namespace ctess
