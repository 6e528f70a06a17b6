// Gap table builder: per token pair (shape0, shape1) the zipper between the column tops and e1
// (docs/algorithm.md §2.6) as one bit per triangle with a running lhs count (cp_tables_layout.hpp). The
// zipper depends on the final positions only, so it is fixed within a token pair.
#pragma once
#include <array>
#include <bit>
#include <cstdint>

#include "gap.hpp"
#include "line.hpp"
#include "tables_columns.hpp"
#include "tables_layout.hpp"

namespace ctess::cp::tables {

// Zipper triangles of a pair: nL + n1 - 1, with nL = n0 (3 for T1).
constexpr unsigned gap_triangle_count(unsigned s0, unsigned s1) {
    return token_info(s0).segments + token_info(s1).segments - 1u;
}

constexpr unsigned gap_word_count(unsigned max_factor) {
    unsigned total = 0;
    const unsigned shapes = shape_count(max_factor);
    for (unsigned s1 = 1; s1 <= shapes; ++s1)
        for (unsigned s0 = 1; s0 <= shapes; ++s0)
            total += (gap_triangle_count(s0, s1) + gap_bits_per_word - 1) / gap_bits_per_word;
    return total;
}

template <unsigned MaxFactor>
struct GapTable {
    static constexpr unsigned shapes = shape_count(MaxFactor);
    static constexpr unsigned words = gap_word_count(MaxFactor);
    // Pair (s0, s1) starts at word[offset[(s1 - 1) * shapes + s0 - 1]].
    std::array<std::uint16_t, shapes * shapes> offset{};
    std::array<std::uint32_t, words> word{};
    // For e1 in T0 (collapsed, docs §2.9): the zipper index of the fan (R_3, L, R_2) of pair (s0, T1).
    std::array<std::uint16_t, shapes> t1_last_fan{};
};

// M(0..nL) of pair (s0, s1): cp::gap_merge over cp::gap_lhs_coords and cp::gap_rhs_coords. Returns nL.
constexpr unsigned zipper_merge(const ShapeTracks& st, unsigned s0, unsigned s1, std::uint16_t* merge) {
    std::uint16_t lambda[max_segments + 1]{};
    std::uint16_t sigma[max_segments + 1]{};
    const unsigned nl = gap_lhs_coords(s0, st.track[s0].data(), st.segments[s0], lambda);
    const unsigned n1 = gap_rhs_coords(s1, st.track[s1].data(), st.segments[s1], sigma);
    gap_merge(lambda, nl, sigma, n1, merge);
    return nl;
}

template <unsigned MaxFactor>
constexpr GapTable<MaxFactor> build_gap_table() {
    using Out = GapTable<MaxFactor>;
    Out out{};
    ShapeTracks st{};
    fill_shape_tracks(MaxFactor, st);
    std::array<std::uint16_t, max_segments + 2> merge{};
    unsigned next = 0;
    for (unsigned s1 = 1; s1 <= Out::shapes; ++s1) {
        for (unsigned s0 = 1; s0 <= Out::shapes; ++s0) {
            out.offset[(s1 - 1) * Out::shapes + s0 - 1] = static_cast<std::uint16_t>(next);
            const unsigned nl = zipper_merge(st, s0, s1, merge.data());
            // Step q is bit q % 16 of word q / 16; the lhs steps (1 bits) before step q are a, the rhs steps
            // (0 bits) are q - a, so the bit positions follow from M directly.
            const unsigned total = gap_triangle_count(s0, s1);
            const unsigned words = (total + gap_bits_per_word - 1) / gap_bits_per_word;
            std::uint32_t* w = out.word.data() + next;
            for (unsigned a = 1; a < nl; ++a) {
                const unsigned q = (a - 1) + merge[a]; // the reversed triangle that ends lhs point a - 1
                w[q / gap_bits_per_word] |= 1u << (q % gap_bits_per_word);
            }
            std::uint32_t lhs_before = 0;
            for (unsigned k = 0; k < words; ++k) {
                const std::uint32_t bits = w[k];
                w[k] = bits | (lhs_before << 16);
                lhs_before += static_cast<std::uint32_t>(std::popcount(bits));
            }
            next += words;
            if (s1 == 1) {
                unsigned lhs_steps = 0;
                for (unsigned a = 1; a < nl; ++a) lhs_steps += merge[a] <= 2 ? 1u : 0u;
                out.t1_last_fan[s0 - 1] = static_cast<std::uint16_t>(2 + lhs_steps);
            }
        }
    }
    if (next != Out::words) detail::column_table_size_pass_disagrees();
    return out;
}

} // namespace ctess::cp::tables
