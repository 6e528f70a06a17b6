// Clamped-parallelogram (CP) line tessellation: tokens, per-token point start/final positions, and the edge
// points of a float factor as exact fixed-point parameters (docs/algorithm.md §1.1, §1.2).
//
// A factor f in [1, max] maps to a token T and a 16-bit lerp t16. Every point of a token has an integer start
// S and final F on the 1/256 grid; its parameter is S*65536 + (F-S)*t16 in units of 2^-24. Points never move
// except the ones of the current block, and a new point is born on an existing one, so the edge is popless.
#pragma once
#include <array>
#include <cstdint>

#include <ctess/core/numeric.hpp>

namespace ctess::cp {

inline constexpr std::uint32_t grid = 256;           // start/final positions are in units of 1/grid
inline constexpr std::uint32_t fixed_one = 1u << 24; // edge parameters are in units of 2^-24
inline constexpr std::uint32_t lerp_one = 1u << 16;  // t16 = 65536 means t = 1
inline constexpr unsigned max_token_count = 25;      // tokens for max factor 256
inline constexpr unsigned max_segments = 256;

// Tokens for a maximum factor 2^K (K >= 3): T0, T1, T2, T3..T4, then 4 blocks per octave from 8 on.
constexpr unsigned token_count(unsigned max_factor) {
    return 5 + 4 * (floor_log2(max_factor) - 3);
}

struct TokenInfo {
    std::uint16_t lo = 0; // factor range (lo, hi]; T0 is f <= 1
    std::uint16_t hi = 1;
    std::uint8_t octave = 0;    // points of this token are inserted while going from 2^k to 2^(k+1) segments
    std::uint8_t block = 0;     // block within the octave
    std::uint8_t blocks = 0;    // blocks in the octave: min(4, 2^(k-1))
    std::uint16_t segments = 1; // segment count, including zero-length segments
};

constexpr TokenInfo token_info(unsigned token) {
    if (token == 0) return {0, 1, 0, 0, 0, 1};
    if (token == 1) return {1, 2, 0, 0, 1, 3};
    if (token == 2) return {2, 4, 1, 0, 1, 4};
    if (token <= 4) {
        const auto b = static_cast<std::uint16_t>(token - 3);
        return {static_cast<std::uint16_t>(4 + 2 * b),
                static_cast<std::uint16_t>(6 + 2 * b),
                2,
                static_cast<std::uint8_t>(b),
                2,
                static_cast<std::uint16_t>(6 + 2 * b)};
    }
    const unsigned k = 3 + (token - 5) / 4;
    const unsigned b = (token - 5) % 4;
    const unsigned width = 1u << (k - 2);
    const unsigned lo = (1u << k) + b * width;
    return {static_cast<std::uint16_t>(lo),
            static_cast<std::uint16_t>(lo + width),
            static_cast<std::uint8_t>(k),
            static_cast<std::uint8_t>(b),
            4,
            static_cast<std::uint16_t>(lo + width)};
}

// A line point: start and final position on the 1/256 grid.
struct PointTrack {
    std::uint16_t start = 0;
    std::uint16_t final = 0;
    friend constexpr bool operator==(const PointTrack&, const PointTrack&) = default;
};

namespace detail {
// Position in the insertion order of new lower-half point m of an octave with M = 2^(k-1) new lower points:
// odd m descending, then even m descending. m = 0 (next to the endpoint) is always split last.
constexpr unsigned insertion_rank(unsigned m, unsigned M) {
    return (m % 2 == 1 ? 0 : M / 2) + (M - 1 - m) / 2;
}
} // namespace detail

// The points 0..N of a token, sorted by final position (ties by start), endpoints included.
// Writes segments+1 entries to out and returns that count.
constexpr unsigned token_points(unsigned token, PointTrack* out) {
    const TokenInfo info = token_info(token);
    if (token == 0) {
        out[0] = {0, 0};
        out[1] = {256, 256};
        return 2;
    }
    if (token == 1) {
        out[0] = {0, 0};
        out[1] = {0, 128};   // A slides in from the start vertex
        out[2] = {256, 128}; // B slides in from the end vertex
        out[3] = {256, 256};
        return 4;
    }
    const unsigned k = info.octave;
    const unsigned S = grid >> k; // old segment length
    const unsigned M = 1u << (k - 1);
    const unsigned per_block = M / info.blocks;
    // Walk the final-position grid of step S/2 upward; positions that are multiples of S are old points.
    unsigned count = 0;
    for (unsigned pos = 0; pos <= grid; pos += S / 2) {
        if (pos % S == 0) {
            out[count++] = {static_cast<std::uint16_t>(pos), static_cast<std::uint16_t>(pos)};
            continue;
        }
        const bool lower = pos < grid / 2;
        const unsigned m = lower ? pos / S : (grid - pos) / S; // parent segment in the lower half
        const unsigned blk = detail::insertion_rank(m, M) / per_block;
        if (blk > info.block) continue; // not born yet
        if (blk < info.block) {
            out[count++] = {static_cast<std::uint16_t>(pos), static_cast<std::uint16_t>(pos)};
        } else {
            // Born at the parent's end nearer the midpoint: upper end in the lower half, and mirrored.
            const unsigned start = lower ? (m + 1) * S : grid - (m + 1) * S;
            out[count++] = {static_cast<std::uint16_t>(start), static_cast<std::uint16_t>(pos)};
        }
    }
    return count;
}

// Factor -> token and 16-bit lerp. Bad input is clamped: NaN and values below 1 give T0 (f = 1); +inf and
// values above max_factor give the last token at t = 1.
struct LineState {
    unsigned token = 0;
    std::uint32_t t16 = 0; // 0..65536
    friend constexpr bool operator==(const LineState&, const LineState&) = default;
};

// The factor as unsigned 16.16 fixed point after clamping to [1, max_factor].
constexpr std::uint32_t clamp_factor_16_16(float f, unsigned max_factor) {
    if (is_nan(f) || f <= 1.0f) return 1u << 16;
    if (f >= static_cast<float>(max_factor)) return max_factor << 16;
    return to_fixed_16_16(f); // f * 65536 <= 2^24 is exact; one rounding to the integer
}

constexpr LineState line_state_fixed(std::uint32_t f16, unsigned max_factor) {
    if (f16 <= (1u << 16)) return {0, 0};
    const unsigned tokens = token_count(max_factor);
    for (unsigned t = 1; t < tokens; ++t) {
        const TokenInfo info = token_info(t);
        if (f16 <= (static_cast<std::uint32_t>(info.hi) << 16)) {
            const unsigned width = info.hi - info.lo; // a power of two
            const std::uint64_t d = f16 - (static_cast<std::uint32_t>(info.lo) << 16);
            return {t, static_cast<std::uint32_t>(shift_round_half_even(d, floor_log2(width)))};
        }
    }
    return {tokens - 1, lerp_one};
}

constexpr LineState line_state(float f, unsigned max_factor) {
    return line_state_fixed(clamp_factor_16_16(f, max_factor), max_factor);
}

// Parameter of a point in units of 2^-24. Exactly mirror-symmetric: the mirror track gives fixed_one - p.
constexpr std::uint32_t point_position(PointTrack p, std::uint32_t t16) {
    const auto s = static_cast<std::int64_t>(p.start) * lerp_one;
    const auto d = (static_cast<std::int64_t>(p.final) - static_cast<std::int64_t>(p.start)) * t16;
    return static_cast<std::uint32_t>(s + d);
}

// The edge points of a line state, endpoints included, in units of 2^-24. out needs segments+1 entries
// (at most 257). Returns the point count.
constexpr unsigned edge_points(LineState state, std::uint32_t* out) {
    std::array<PointTrack, max_segments + 1> tracks{};
    const unsigned count = token_points(state.token, tracks.data());
    for (unsigned i = 0; i < count; ++i) out[i] = point_position(tracks[i], state.t16);
    return count;
}

constexpr unsigned edge_points(float f, unsigned max_factor, std::uint32_t* out) {
    return edge_points(line_state(f, max_factor), out);
}

} // namespace ctess::cp
