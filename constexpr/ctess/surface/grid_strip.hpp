// Grid triangle strips (Cayzac 2007, docs/surfaces.md §1): a U x V grid of segments on [0, 1]^2 drawn as one
// triangle strip with no restart. Row r runs left to right when r is even and right to left when r is odd,
// so each row ends where the next begins; two zero-area "turn-around" triangles join consecutive rows.
//
// Vertex (x, y), 0 <= x <= U, 0 <= y <= V, has index y * (U + 1) + x (row-major). The strip has
// 2 * (U + 1) * V indices and every index is a closed form of its position (no loop state), so any index can
// be computed on its own: by a GPU thread, or in a constant expression.
//
// Strip triangle k is (s[k], s[k+1], s[k+2]) for even k and (s[k+1], s[k], s[k+2]) for odd k (the usual strip
// rule); every non-degenerate one is clockwise in (u, v) with v up (u right), so counter-clockwise with v
// down. Every grid cell is split along its diagonal from (x, y + 1) to (x + 1, y).
#pragma once
#include <cstdint>
#include <span>

#include <ctess/core/counts.hpp>

namespace ctess::grid {

// The largest segment count per direction: keeps every index and count inside 32 bits
// (2 * (max + 1) * max < 2^31).
inline constexpr std::uint32_t max_segments = 16384;

constexpr bool valid_segments(std::uint32_t u_segments, std::uint32_t v_segments) {
    return u_segments >= 1 && v_segments >= 1 && u_segments <= max_segments && v_segments <= max_segments;
}

// Vertices of the grid and triangles of its triangle list (the strip's non-degenerate triangles): {0, 0}
// for segment counts outside [1, max_segments].
constexpr Counts grid_counts(std::uint32_t u_segments, std::uint32_t v_segments) {
    if (!valid_segments(u_segments, v_segments)) return {};
    return {(u_segments + 1) * (v_segments + 1), 2 * u_segments * v_segments};
}

// Indices of the single strip (0 for segment counts outside [1, max_segments]).
constexpr std::uint32_t strip_index_count(std::uint32_t u_segments, std::uint32_t v_segments) {
    if (!valid_segments(u_segments, v_segments)) return 0;
    return 2 * (u_segments + 1) * v_segments;
}

// Triangles the strip draws, degenerate ones included: strip_index_count - 2.
constexpr std::uint32_t strip_triangle_count(std::uint32_t u_segments, std::uint32_t v_segments) {
    const std::uint32_t n = strip_index_count(u_segments, v_segments);
    return n >= 2 ? n - 2 : 0;
}

// The strip's index at position i < strip_index_count (Cayzac 2007's strip, closed form): within a row, even
// positions are on the row's lower line and odd ones on its upper line; odd rows run backwards; at a row
// change the parity flips, which repeats the row's last column once more (the turn-around).
constexpr std::uint32_t strip_index(std::uint32_t i, std::uint32_t u_segments) {
    const std::uint32_t stride = u_segments + 1; // vertices per grid row
    const std::uint32_t twice = 2 * stride;      // strip positions per grid row
    std::uint32_t x = (i / 2) % twice;
    if (x >= stride) x = (twice - 1) - x; // odd rows run right to left
    std::uint32_t y = i / twice;
    if (((i & 1u) ^ (y & 1u)) != 0) ++y;
    return y * stride + x;
}

// Whether strip triangle k is one of the two zero-area turn-around triangles after each row but the last.
constexpr bool strip_triangle_is_turnaround(std::uint32_t k, std::uint32_t u_segments) {
    return k % (2 * (u_segments + 1)) >= 2 * u_segments;
}

// Fills the strip. False (nothing written) for invalid segment counts or a span shorter than
// strip_index_count.
constexpr bool fill_strip_indices(std::span<std::uint32_t> indices, std::uint32_t u_segments,
                                  std::uint32_t v_segments) {
    const std::uint32_t n = strip_index_count(u_segments, v_segments);
    if (n == 0 || indices.size() < n) return false;
    for (std::uint32_t i = 0; i < n; ++i) indices[i] = strip_index(i, u_segments);
    return true;
}

// The strip as a triangle list without the turn-around triangles: 3 * grid_counts().triangles indices, in
// strip order and with the strip's winding (odd strip triangles have their first two indices swapped). False
// (nothing written) for invalid segment counts or a span that is too short.
constexpr bool fill_triangle_list(std::span<std::uint32_t> indices, std::uint32_t u_segments,
                                  std::uint32_t v_segments) {
    const std::uint32_t triangles = grid_counts(u_segments, v_segments).triangles;
    if (triangles == 0 || indices.size() < 3 * std::size_t{triangles}) return false;
    const std::uint32_t strip_triangles = strip_triangle_count(u_segments, v_segments);
    std::uint32_t out = 0;
    for (std::uint32_t k = 0; k < strip_triangles; ++k) {
        if (strip_triangle_is_turnaround(k, u_segments)) continue;
        const std::uint32_t a = strip_index(k, u_segments), b = strip_index(k + 1, u_segments);
        indices[out++] = (k & 1u) ? b : a;
        indices[out++] = (k & 1u) ? a : b;
        indices[out++] = strip_index(k + 2, u_segments);
    }
    return true;
}

// Cayzac 2007's 3 x 4 example, the first 24 of its 32 indices.
static_assert([] {
    constexpr std::uint32_t seed[] = {0, 4, 1, 5, 2, 6,  3, 7,  11, 7,  10, 6,
                                      9, 5, 8, 4, 8, 12, 9, 13, 10, 14, 11, 15};
    for (std::uint32_t i = 0; i < 24; ++i)
        if (strip_index(i, 3) != seed[i]) return false;
    return strip_index_count(3, 4) == 32;
}());

} // namespace ctess::grid
