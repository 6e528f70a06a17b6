// Type 2 interior: the clamp line K and the column counts R_i (docs/algorithm.md §2.3-2.4,
// docs/algorithm.md §2.3, §2.4).
//
// Column 0 is e2's points 0..n2-1; column i >= 1 stands on e0's point i and holds R_i points
// (u_i, min(v_j, c_i)), c_i = max(0, K - u_i). R depends on the two tokens only, never on the lerps, so the
// topology is fixed inside a token pair and the surface deforms continuously.
#pragma once
#include <array>
#include <cstdint>

#include "edge_line.hpp"

namespace ctess::cp {

enum class ColumnRule : std::uint8_t {
    minimal,  // rule (b): the fewest rows that reach the clamp line at every lerp pair (default)
    staircase // rule (a): rows below the final staircase, N^2 triangles for every equal factor
};

using ColumnCounts = std::array<std::uint16_t, max_segments>; // R_0..R_{n0-1}

namespace detail {
// The track that defines e2's end of the clamp: the last interior point for T2+, A2 for a T0/T1 edge.
constexpr PointTrack clamp_track_e2(unsigned shape_token2, const PointTrack* tracks2, unsigned n2) {
    return shape_token2 >= 2 ? tracks2[n2 - 1] : tracks2[1];
}
} // namespace detail

// Rule (b)'s gaps, max(G0, G2) at the four extreme lerp pairs: ss = (e0 at start, e2 at start), sf = (start,
// final), fs = (final, start), ff = (final, final).
struct ReachGaps {
    int ss = 0, sf = 0, fs = 0, ff = 0;
};

constexpr ReachGaps reach_gaps(PointTrack end0, PointTrack end2) {
    const int g0s = 256 - end0.start, g0f = 256 - end0.final;
    const int g2s = 256 - end2.start, g2f = 256 - end2.final;
    return {g0s > g2s ? g0s : g2s, g0s > g2f ? g0s : g2f, g0f > g2s ? g0f : g2s, g0f > g2f ? g0f : g2f};
}

// Rule (b)'s test: row (an e2 track) reaches the clamp of the column whose e0 point is at us (start) and uf
// (final), at all four extreme lerp pairs: v^b + max(G0^a, G2^b) + u^a >= 256 on the 256 grid.
constexpr bool row_reaches(PointTrack row, const ReachGaps& g, int us, int uf) {
    return row.start + g.ss + us >= 256 && row.final + g.sf + us >= 256 && row.start + g.fs + uf >= 256 &&
           row.final + g.ff + uf >= 256;
}

// Rule (b) for column i >= 1: R_i = 1 + min{k : row k reaches the clamp}. Positions are linear in each lerp
// and the condition is convex, so the four extreme lerp combinations decide it (docs/algorithm.md §2.4).
constexpr unsigned minimal_rows(const PointTrack* tracks0, unsigned n0, const PointTrack* tracks2,
                                unsigned n2, unsigned shape_token2, unsigned i) {
    const ReachGaps g = reach_gaps(tracks0[n0 - 1], detail::clamp_track_e2(shape_token2, tracks2, n2));
    for (unsigned k = 0; k < n2; ++k) {
        if (row_reaches(tracks2[k], g, tracks0[i].start, tracks0[i].final)) return k + 1;
    }
    return n2; // not reached: k = n2-1 always satisfies the condition
}

// Rule (a) for column i >= 1, both tokens >= T2: #{j <= n2-1 : F0[i+1] + F2[j] <= 256}.
constexpr unsigned staircase_rows(const PointTrack* tracks0, const PointTrack* tracks2, unsigned n2,
                                  unsigned i) {
    unsigned rows = 0;
    for (unsigned j = 0; j < n2; ++j) {
        if (tracks0[i + 1].final + tracks2[j].final <= 256) ++rows;
    }
    return rows;
}

// R_0..R_{n0-1} of a token pair (T0 uses T1's points). Pairs with a T0/T1 token use rule (b) under either
// rule: it is their closed form (docs/algorithm.md §2.4). Returns n0, the column count.
constexpr unsigned column_counts(unsigned token0, unsigned token2, ColumnRule rule, std::uint16_t* out) {
    const unsigned shape0 = token0 == 0 ? 1u : token0;
    const unsigned shape2 = token2 == 0 ? 1u : token2;
    std::array<PointTrack, max_segments + 1> tracks0{};
    std::array<PointTrack, max_segments + 1> tracks2{};
    const unsigned n0 = token_points(shape0, tracks0.data()) - 1;
    const unsigned n2 = token_points(shape2, tracks2.data()) - 1;
    const bool staircase = rule == ColumnRule::staircase && shape0 >= 2 && shape2 >= 2;
    out[0] = static_cast<std::uint16_t>(n2);
    for (unsigned i = 1; i < n0; ++i) {
        const unsigned r = staircase ? staircase_rows(tracks0.data(), tracks2.data(), n2, i)
                                     : minimal_rows(tracks0.data(), n0, tracks2.data(), n2, shape2, i);
        out[i] = static_cast<std::uint16_t>(r);
    }
    return n0;
}

// K = min(u_{n0-1}, V2) in units of 2^-24: the clamp line u + v = K bounds every column i >= 1.
constexpr std::uint32_t clamp_line(const EdgeLine& e0, const EdgeLine& e2) {
    const std::uint32_t last0 = e0.pos[e0.segments - 1];
    const std::uint32_t v2 = e2.shape_token >= 2 ? e2.pos[e2.segments - 1] : e2.pos[1];
    return last0 < v2 ? last0 : v2;
}

// The clamp height c_i = max(0, K - u_i) of the column at u_i.
constexpr std::uint32_t column_clamp(std::uint32_t clamp, std::uint32_t u) {
    return clamp > u ? clamp - u : 0;
}

} // namespace ctess::cp
