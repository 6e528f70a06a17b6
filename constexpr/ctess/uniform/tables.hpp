// The uniform-density storage tables for maximum factor N (11 or 16), built in constant expressions from the
// pattern data (docs/algorithm.md §3.3): only interior vertices are stored (the boundary is implicit at the
// symmetric i/f), as (v << 16) | u words; triangles as three 8-bit canonical indices; one offset record per
// pattern plus a sentinel. The pattern of a sorted triple is offsets[pattern_index(f0, f1, f2)].
// Triangles are stored rotated for the provoking layout (§3.4, uniform_provoking.hpp); copy words mark the
// triangles whose first vertex needs a copy, and copy sources name the vertex each copy repeats.
#pragma once
#include <array>
#include <bit>
#include <cstdint>

#include <ctess/core/numeric.hpp>
#include <ctess/uniform/pattern.hpp>
#include <ctess/uniform/provoking.hpp>

namespace ctess::uniform::tables {

struct Offset {
    std::uint16_t interior; // first interior vertex word
    std::uint16_t triangle; // first triangle (3 index bytes each)
};

// Copy words: bit t % 16 of word t / 16 is set when triangle t (counted over all patterns) takes a copy of
// its first vertex; the high 16 bits count the copies before that word, so a copy's rank is a load, a mask
// and a popcount.
inline constexpr unsigned copy_bits_per_word = 16;

// The copies of the first n patterns: each needs max(T - V, 0) (the builder checks it reaches that bound).
constexpr unsigned total_copies(unsigned n) {
    unsigned total = 0;
    for (unsigned p = 0; p < n; ++p) {
        const data::PatternRecord& r = data::patterns[p];
        const unsigned vertices = r.f0 + r.f1 + r.f2 + r.interior;
        const unsigned triangles = pattern_offsets.triangle[p + 1] - pattern_offsets.triangle[p];
        total += provoking_copy_bound(vertices, triangles);
    }
    return total;
}

// The most vertices of any of the first n patterns (the packed indices are 8-bit).
constexpr unsigned max_pattern_vertices(unsigned n) {
    unsigned most = 0;
    for (unsigned p = 0; p < n; ++p) {
        const data::PatternRecord& r = data::patterns[p];
        const unsigned vertices = r.f0 + r.f1 + r.f2 + r.interior;
        most = vertices > most ? vertices : most;
    }
    return most;
}

// The copy rank of global triangle t: copies of the triangles before it.
constexpr unsigned copies_before(const std::uint32_t* copy_words, unsigned t) {
    const std::uint32_t w = copy_words[t / copy_bits_per_word];
    const std::uint32_t below = (1u << (t % copy_bits_per_word)) - 1u;
    return (w >> 16) + popcount16(w & below); // the bit count inline (numeric.hpp)
}

namespace detail {
// Not constexpr: reaching it in a constant expression stops the build (a pattern without a saturating
// matching, which would need more copies than max(T - V, 0)).
inline void provoking_matching_not_saturating() {}
} // namespace detail

template <unsigned N>
struct UniformTables {
    static constexpr unsigned patterns = pattern_count(N);
    static constexpr unsigned interior_words = pattern_offsets.interior[patterns];
    static constexpr unsigned triangles = pattern_offsets.triangle[patterns];
    static_assert(N >= 1 && N <= data_max_factor, "the pattern data stops at data_max_factor");
    static_assert(interior_words < 65536 && triangles < 65536, "offsets are 16-bit");
    static_assert(max_pattern_vertices(patterns) <= 256, "indices are 8-bit: at most 256 vertices");
    static constexpr unsigned copies = total_copies(patterns);
    static_assert(copies < 65536, "copy ranks are 16-bit");

    std::array<Offset, patterns + 1> offsets{};
    std::array<std::uint32_t, interior_words> interior{};
    std::array<std::uint8_t, 3 * triangles> indices{}; // rotated: the first index provokes (§3.4)
    std::array<std::uint32_t, triangles / copy_bits_per_word + 1> copy_words{};
    std::array<std::uint8_t, copies> copy_sources{}; // the canonical vertex each copy repeats
};

template <unsigned N>
constexpr UniformTables<N> build_uniform_tables() {
    UniformTables<N> t;
    for (unsigned p = 0; p <= t.patterns; ++p)
        t.offsets[p] = {static_cast<std::uint16_t>(pattern_offsets.interior[p]),
                        static_cast<std::uint16_t>(pattern_offsets.triangle[p])};
    for (unsigned i = 0; i < t.interior_words; ++i)
        t.interior[i] = static_cast<std::uint32_t>(data::interior[i].v) << 16 | data::interior[i].u;
    unsigned copy = 0;
    for (unsigned p = 0; p < t.patterns; ++p) {
        const Pattern pat{data::patterns[p].f0, data::patterns[p].f1, data::patterns[p].f2, p};
        const ProvokingChoice choice = provoking_choice(pat);
        if (choice.copies != provoking_copy_bound(pat.vertex_count(), pat.triangle_count()))
            detail::provoking_matching_not_saturating();
        for (unsigned k = 0; k < pat.triangle_count(); ++k) {
            const unsigned g = pattern_offsets.triangle[p] + k;
            const auto c = pat.triangle(k);
            const unsigned r = choice.rotation[k];
            for (unsigned j = 0; j < 3; ++j) t.indices[3 * g + j] = static_cast<std::uint8_t>(c[(r + j) % 3]);
            if (!choice.copied[k]) continue;
            t.copy_words[g / copy_bits_per_word] |= 1u << (g % copy_bits_per_word);
            t.copy_sources[copy++] = static_cast<std::uint8_t>(c[r]);
        }
    }
    std::uint32_t before = 0;
    for (std::uint32_t& w : t.copy_words) {
        const std::uint32_t bits = w;
        w = bits | before << 16;
        before += static_cast<std::uint32_t>(std::popcount(bits));
    }
    return t;
}

} // namespace ctess::uniform::tables
