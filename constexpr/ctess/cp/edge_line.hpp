// One edge of a CP patch: its line points as tracks (start/final on the 256 grid) and as exact positions.
// Inside a Type 1 or Type 2 patch a T0 edge is processed as T1 at t = 0 (docs/algorithm.md §2.2), so that
// its two interior points A and B exist and sit on the endpoints.
#pragma once
#include <array>
#include <cstdint>

#include "line.hpp"

namespace ctess::cp {

// The maximum factor a pattern uses: 64 and 256 are the supported values; anything else is clamped to
// [8, 256] and rounded down to a power of two, so the token range is always well defined.
constexpr unsigned pattern_max_factor(unsigned max_factor) {
    if (max_factor <= 8) return 8;
    if (max_factor >= max_segments) return max_segments;
    return 1u << floor_log2(max_factor);
}

// Bad line states are clamped, never undefined: a token past the last one becomes the last token at t = 1,
// t16 above 65536 becomes 65536, and T0 always has t16 = 0 (T0 has no lerp).
constexpr LineState clamp_line_state(LineState s, unsigned max_factor) {
    const unsigned tokens = token_count(pattern_max_factor(max_factor));
    if (s.token >= tokens) return {tokens - 1, lerp_one};
    if (s.token == 0) return {0, 0};
    return {s.token, s.t16 > lerp_one ? lerp_one : s.t16};
}

struct EdgeLine {
    unsigned token = 0;       // the edge's own token (0 = T0)
    unsigned shape_token = 1; // the token whose points are used: T0 is processed as T1
    std::uint32_t t16 = 0;
    unsigned segments = 0; // n: the points are 0..n, endpoints included
    std::array<PointTrack, max_segments + 1> tracks{};
    std::array<std::uint32_t, max_segments + 1> pos{}; // parameter along the edge, units of 2^-24
};

// s must already be clamped (clamp_line_state).
constexpr EdgeLine make_edge_line(LineState s) {
    EdgeLine e;
    e.token = s.token;
    e.shape_token = s.token == 0 ? 1u : s.token;
    e.t16 = s.token == 0 ? 0u : s.t16;
    e.segments = token_points(e.shape_token, e.tracks.data()) - 1;
    for (unsigned i = 0; i <= e.segments; ++i) e.pos[i] = point_position(e.tracks[i], e.t16);
    return e;
}

} // namespace ctess::cp
