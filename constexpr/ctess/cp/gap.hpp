// Type 2 gap zipper: merges the column tops (lhs) with e1's points (rhs) (docs/algorithm.md §2.6).
// The topology depends on (tok0, tok1) only.
#pragma once
#include <array>
#include <cstdint>

#include "edge_line.hpp"

namespace ctess::cp {

// Topology coordinate of each lhs point L_a (the top of column n0-1-a), on the 256 grid. T2+: F0[a+1], the
// mirror of the column's final position. T0/T1: (0, 256, 256) for (B0's column, A0's column, column 0), the
// birth positions mirrored, so that B0 covers only [v1, R_1]. tracks0: e0's shape tracks, n0 its segments.
// Returns nL = n0.
constexpr unsigned gap_lhs_coords(unsigned shape_token0, const PointTrack* tracks0, unsigned n0,
                                  std::uint16_t* lambda) {
    if (shape_token0 < 2) {
        lambda[0] = 0;
        lambda[1] = 256;
        lambda[2] = 256;
        return 3;
    }
    for (unsigned a = 0; a < n0; ++a) lambda[a] = tracks0[a + 1].final;
    return n0;
}
constexpr unsigned gap_lhs_coords(const EdgeLine& e0, std::uint16_t* lambda) {
    return gap_lhs_coords(e0.shape_token, e0.tracks.data(), e0.segments, lambda);
}

// Topology coordinate of each rhs point R_b (e1's point b, from v1). T2+: F1[b]. T0/T1: (0, 0, 128, 256)
// for (v1, A1, B1, v2): A1 keeps its birth position, B1 its final one. Returns n1.
constexpr unsigned gap_rhs_coords(unsigned shape_token1, const PointTrack* tracks1, unsigned n1,
                                  std::uint16_t* sigma) {
    if (shape_token1 < 2) {
        sigma[0] = 0;
        sigma[1] = 0;
        sigma[2] = 128;
        sigma[3] = 256;
        return 3;
    }
    for (unsigned b = 0; b <= n1; ++b) sigma[b] = tracks1[b].final;
    return n1;
}
constexpr unsigned gap_rhs_coords(const EdgeLine& e1, std::uint16_t* sigma) {
    return gap_rhs_coords(e1.shape_token, e1.tracks.data(), e1.segments, sigma);
}

// M(a), a = 0..nL: lhs point a fans the rhs points M(a)..M(a+1). Lower half: ceil by the departing lhs
// coordinate; upper half: strict floor of the arriving one. Both make a newborn point add only zero-area
// triangles. M(1) >= 1: the first triangle goes up the rhs, as triforce does. Both coordinate sequences are
// non-decreasing, so each search resumes where it stopped: one pass (the table builder runs this for every
// token pair).
constexpr void gap_merge(const std::uint16_t* lambda, unsigned nL, const std::uint16_t* sigma, unsigned n1,
                         std::uint16_t* merge) {
    merge[0] = 0;
    merge[nL] = static_cast<std::uint16_t>(n1);
    unsigned ceil_b = 0;  // min{b : sigma_b >= lambda_a}
    unsigned floor_b = 0; // max{b : sigma_b < lambda_{a+1}}
    for (unsigned a = 0; a + 1 < nL; ++a) {
        unsigned m = 0;
        if (lambda[a] + lambda[a + 1] <= 256) {
            while (ceil_b < n1 && sigma[ceil_b] < lambda[a]) ++ceil_b;
            m = ceil_b;
        } else {
            while (floor_b + 1 <= n1 && sigma[floor_b + 1] < lambda[a + 1]) ++floor_b;
            m = floor_b;
        }
        merge[a + 1] = static_cast<std::uint16_t>(m);
    }
    if (nL > 1 && merge[1] < 1) merge[1] = 1;
    for (unsigned a = 1; a < nL; ++a) {
        const unsigned m = merge[a] > merge[a - 1] ? merge[a] : merge[a - 1];
        merge[a] = static_cast<std::uint16_t>(m < n1 ? m : n1);
    }
}

// A gap corner: an lhs point L_index or an rhs point R_index.
struct GapCorner {
    bool rhs = false;
    unsigned index = 0;
};

// Calls emit(c0, c1, c2) for each of the n0 + n1 - 1 gap triangles, counter-clockwise, with the newly
// advanced point first: the fan (R_{b+1}, L_a, R_b), then the reversed triangle (L_{a+1}, L_a, R_{M(a+1)}).
template <class Emit>
constexpr void for_each_gap_triangle(const std::uint16_t* merge, unsigned nL, Emit&& emit) {
    for (unsigned a = 0; a < nL; ++a) {
        for (unsigned b = merge[a]; b < merge[a + 1]; ++b) {
            emit(GapCorner{true, b + 1}, GapCorner{false, a}, GapCorner{true, b});
        }
        if (a + 1 < nL) emit(GapCorner{false, a + 1}, GapCorner{false, a}, GapCorner{true, merge[a + 1]});
    }
}

} // namespace ctess::cp
