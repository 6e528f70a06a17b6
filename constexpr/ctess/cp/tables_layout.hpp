// Record layouts of the compile-time CP tables (docs/algorithm.md §2, §4) and the
// constants that builders and the runtime must agree on.
//
// Tables are indexed by *shape* token: a T0 edge uses T1's points at t = 0 (cp_edge_line.hpp), so T1..T(n-1)
// are the only shapes and shape index = token - 1 (T0 -> 0, like T1).
#pragma once
#include <cstdint>

#include "line.hpp"

// The max-256 column table is split into this many translation units: the one place that sets their number.
// runtime/CMakeLists.txt reads this line; CTESS_FOR_EACH_COLUMN_CHUNK_256 enumerates the chunks.
#define CTESS_COLUMN_CHUNKS_256 4

// X(k) for k = 0 .. CTESS_COLUMN_CHUNKS_256 - 1 (at most 8).
#define CTESS_COLUMN_CHUNKS_1_(X) X(0)
#define CTESS_COLUMN_CHUNKS_2_(X) CTESS_COLUMN_CHUNKS_1_(X) X(1)
#define CTESS_COLUMN_CHUNKS_3_(X) CTESS_COLUMN_CHUNKS_2_(X) X(2)
#define CTESS_COLUMN_CHUNKS_4_(X) CTESS_COLUMN_CHUNKS_3_(X) X(3)
#define CTESS_COLUMN_CHUNKS_5_(X) CTESS_COLUMN_CHUNKS_4_(X) X(4)
#define CTESS_COLUMN_CHUNKS_6_(X) CTESS_COLUMN_CHUNKS_5_(X) X(5)
#define CTESS_COLUMN_CHUNKS_7_(X) CTESS_COLUMN_CHUNKS_6_(X) X(6)
#define CTESS_COLUMN_CHUNKS_8_(X) CTESS_COLUMN_CHUNKS_7_(X) X(7)
#define CTESS_COLUMN_CHUNKS_CAT_(n) CTESS_COLUMN_CHUNKS_##n##_
#define CTESS_COLUMN_CHUNKS_N_(n) CTESS_COLUMN_CHUNKS_CAT_(n)
#define CTESS_FOR_EACH_COLUMN_CHUNK_256(X) CTESS_COLUMN_CHUNKS_N_(CTESS_COLUMN_CHUNKS_256)(X)

namespace ctess::cp::tables {

constexpr unsigned shape_count(unsigned max_factor) {
    return token_count(max_factor) - 1;
}
constexpr unsigned shape_index(unsigned token) {
    return token == 0 ? 0u : token - 1;
}

// Token table: one record per shape token, then its interior points 1..n-1 (the endpoints are 0 and 1).
struct TokenRecord {
    std::uint16_t first_point = 0; // index of interior point 1 in the point table
    std::uint16_t segments = 0;    // n
    std::uint16_t half_step = 0;   // |start - final| of a sliding point on the 256 grid
};

// A packed interior point: bits 0-7 the final position (interior finals are 1..255), bits 8-9 the slide.
inline constexpr unsigned point_final_mask = 0xFF;
inline constexpr unsigned point_slide_shift = 8;
inline constexpr std::uint16_t slide_none = 0; // start == final
inline constexpr std::uint16_t slide_down = 1; // start = final + half_step: slides down to its final
inline constexpr std::uint16_t slide_up = 2;   // start = final - half_step

// Interior column table, per token pair (shape0, shape2): the column starts C_0..C_{h+1} (u16, C_0 = 0,
// C_{h+1} = C_h + 1) where h is the first column with one point; every column from h on has one point.
struct ColumnRecord {
    std::uint16_t offset = 0; // C_0's index in the chunk's pool
    std::uint16_t head = 0;   // h >= 1
    float a = 0.0f;           // C_k ~ a k - b k^2 (least squares, k = 0..h): the lookups' first guess
    float b = 0.0f;
};

// The lookups (tests/support/cp_search.hpp): a first guess, one integer Newton step, then
// this many compares. The tests measure the residual the Newton step leaves, for every element of every pair,
// with the guess moved by -1, 0, +1: at most 1 (vertex, strip) and 2 (copy) at max 64; 7, 7 and 8 at max 256
// under rule (b), more than the notes' 5, which they measured under rules (a) and (a+b).
// The reads reach C up to (h - 1) + window + 1; pools end with spare entries so that they stay in the array.
inline constexpr unsigned search_window = 8;
inline constexpr unsigned pool_padding = search_window + 2;

// Gap table, per pair (shape0, shape1): one bit per zipper triangle, 1 = the lhs advances (the reversed
// triangle), 0 = the rhs advances (a fan). Word = (lhs steps before the word) << 16 | 16 step bits, LSB
// first, so the lhs count before any triangle is the prefix plus one popcount.
inline constexpr unsigned gap_bits_per_word = 16;

} // namespace ctess::cp::tables
