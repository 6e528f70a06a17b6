// Token table builder: per shape token its segment count and the start/final of every interior point
// (docs/algorithm.md §1.2), packed into one u16 per point. A point sits at start*65536 + (final-start)*t16.
#pragma once
#include <array>
#include <cstdint>

#include "line.hpp"
#include "tables_layout.hpp"

namespace ctess::cp::tables {

// Interior points of every shape token (closed form: n - 1 per token).
constexpr unsigned token_point_count(unsigned max_factor) {
    unsigned total = 0;
    for (unsigned t = 1; t < token_count(max_factor); ++t) total += token_info(t).segments - 1u;
    return total;
}

template <unsigned MaxFactor>
struct TokenTable {
    static constexpr unsigned shapes = shape_count(MaxFactor);
    static constexpr unsigned points = token_point_count(MaxFactor);
    std::array<TokenRecord, shapes> records{};
    std::array<std::uint16_t, points> point{};
};

namespace detail {
// Not constexpr on purpose: reaching it during constant evaluation is a compile error that names the cause.
inline void token_point_has_unexpected_slide() {}
} // namespace detail

// The half step of a token's sliding points: half the old segment of its octave, 128 for T1.
constexpr unsigned token_half_step(unsigned token) {
    return token <= 1 ? 128u : (grid >> token_info(token).octave) / 2;
}

constexpr std::uint16_t pack_point(PointTrack p, unsigned half_step) {
    std::uint16_t slide = slide_none;
    if (p.start == p.final + half_step) {
        slide = slide_down;
    } else if (p.start + half_step == p.final) {
        slide = slide_up;
    } else if (p.start != p.final) {
        detail::token_point_has_unexpected_slide();
    }
    return static_cast<std::uint16_t>(p.final | (slide << point_slide_shift));
}

template <unsigned MaxFactor>
constexpr TokenTable<MaxFactor> build_token_table() {
    TokenTable<MaxFactor> table{};
    std::array<PointTrack, max_segments + 1> tracks{};
    unsigned next = 0;
    for (unsigned t = 1; t < token_count(MaxFactor); ++t) {
        const unsigned n = token_points(t, tracks.data()) - 1;
        const unsigned half = token_half_step(t);
        table.records[t - 1] = {static_cast<std::uint16_t>(next), static_cast<std::uint16_t>(n),
                                static_cast<std::uint16_t>(half)};
        for (unsigned i = 1; i < n; ++i) table.point[next++] = pack_point(tracks[i], half);
    }
    return table;
}

// Start and final of a packed interior point (the inverse of pack_point).
constexpr PointTrack unpack_point(std::uint16_t packed, unsigned half_step) {
    const auto final = static_cast<std::uint16_t>(packed & point_final_mask);
    const unsigned slide = packed >> point_slide_shift;
    const unsigned start = slide == slide_down ? final + half_step
                           : slide == slide_up ? final - half_step
                                               : final;
    return {static_cast<std::uint16_t>(start), final};
}

} // namespace ctess::cp::tables
