// Evaluating a surface f(u, v) on the vertices of a U x V grid (docs/surfaces.md §1), in the vertex order of
// grid_strip.hpp: vertex (x, y) at index y * (U + 1) + x, u = x / U, v = y / V. Each parameter is one
// division of exact integers (no accumulated increments), so the last row and column are exactly 1.
//
// f is any callable taking (float u, float v); it is a template parameter, so the call is inlined in the
// loop (no std::function). The function is constexpr whenever f is.
#pragma once
#include <cstdint>
#include <span>
#include <type_traits>

#include "grid_strip.hpp"

namespace ctess::grid {

// The grid parameter of column (or row) i of n segments.
constexpr float grid_parameter(std::uint32_t i, std::uint32_t n) {
    return static_cast<float>(i) / static_cast<float>(n);
}

// Writes f(u, v) for every grid vertex into `vertices`. False (nothing written) for invalid segment counts or
// a span shorter than grid_counts().vertices.
template <class Vertex, class SurfaceFn>
requires std::is_assignable_v<Vertex&, std::invoke_result_t<SurfaceFn&, float, float>>
constexpr bool evaluate_grid(std::span<Vertex> vertices, std::uint32_t u_segments, std::uint32_t v_segments,
                             SurfaceFn&& f) {
    const std::uint32_t n = grid_counts(u_segments, v_segments).vertices;
    if (n == 0 || vertices.size() < n) return false;
    std::uint32_t at = 0;
    for (std::uint32_t y = 0; y <= v_segments; ++y) {
        const float v = grid_parameter(y, v_segments);
        for (std::uint32_t x = 0; x <= u_segments; ++x) vertices[at++] = f(grid_parameter(x, u_segments), v);
    }
    return true;
}

} // namespace ctess::grid
