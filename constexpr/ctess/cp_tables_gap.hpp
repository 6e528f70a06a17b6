// Gap table builder: per token pair (shape0, shape1) the zipper between the column tops and e1
// (docs/algorithm.md §2.6) as one bit per triangle with a running lhs count (cp_tables_layout.hpp). The
// zipper depends on the final positions only, so it is fixed within a token pair.
#pragma once
#include <array>
#include <cstdint>

#include "cp_line.hpp"
#include "cp_tables_columns.hpp"
#include "cp_tables_layout.hpp"

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

// M(0..nL), exactly as cp::gap_merge computes it, in one pass: both searches move forward only, because the
// lhs coordinates grow with a and the rhs coordinates with b. Returns nL. Checked against cp::gap_merge.
constexpr unsigned zipper_merge(const ShapeTracks& st, unsigned s0, unsigned s1, std::uint16_t* merge) {
    const unsigned nl = st.segments[s0] < 3 ? 3u : st.segments[s0];
    const unsigned n1 = st.segments[s1];
    auto lambda = [&](unsigned a) -> unsigned {
        if (s0 < 2) return a == 0 ? 0u : 256u;
        return st.track[s0][a + 1].final;
    };
    auto sigma = [&](unsigned b) -> unsigned {
        if (s1 < 2) return b == 0 ? 0u : b == 1 ? 0u : b == 2 ? 128u : 256u;
        return st.track[s1][b].final;
    };
    merge[0] = 0;
    merge[nl] = static_cast<std::uint16_t>(n1);
    unsigned ceil_b = 0;  // min{b : sigma_b >= lambda_a}
    unsigned floor_b = 0; // max{b : sigma_b < lambda_{a+1}}
    for (unsigned a = 0; a + 1 < nl; ++a) {
        unsigned m = 0;
        if (lambda(a) + lambda(a + 1) <= 256) {
            while (ceil_b < n1 && sigma(ceil_b) < lambda(a)) ++ceil_b;
            m = ceil_b;
        } else {
            while (floor_b + 1 <= n1 && sigma(floor_b + 1) < lambda(a + 1)) ++floor_b;
            m = floor_b;
        }
        merge[a + 1] = static_cast<std::uint16_t>(m);
    }
    if (nl > 1 && merge[1] < 1) merge[1] = 1;
    for (unsigned a = 1; a < nl; ++a) {
        const unsigned m = merge[a] > merge[a - 1] ? merge[a] : merge[a - 1];
        merge[a] = static_cast<std::uint16_t>(m < n1 ? m : n1);
    }
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
            std::uint32_t bits = 0, lhs_before = 0, lhs_total = 0;
            unsigned n = 0;
            auto put = [&](bool lhs) {
                bits |= static_cast<std::uint32_t>(lhs) << n;
                lhs_total += lhs ? 1u : 0u;
                if (++n == gap_bits_per_word) {
                    out.word[next++] = (lhs_before << 16) | bits;
                    lhs_before = lhs_total;
                    bits = 0;
                    n = 0;
                }
            };
            for (unsigned a = 0; a < nl; ++a) {
                for (unsigned b = merge[a]; b < merge[a + 1]; ++b) put(false);
                if (a + 1 < nl) put(true);
            }
            if (n != 0) out.word[next++] = (lhs_before << 16) | bits;
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
