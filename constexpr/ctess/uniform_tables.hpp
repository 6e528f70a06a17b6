// The uniform-density storage tables for maximum factor N (11 or 16), built in constant expressions from the
// pattern data (docs/algorithm.md §3.3): only interior vertices are stored (the boundary is implicit at the
// symmetric i/f), as (v << 16) | u words; triangles as three 8-bit canonical indices; one offset record per
// pattern plus a sentinel. The pattern of a sorted triple is offsets[pattern_index(f0, f1, f2)].
#pragma once
#include <array>
#include <cstdint>

#include <ctess/uniform_pattern.hpp>

namespace ctess::uniform::tables {

struct Offset {
    std::uint16_t interior; // first interior vertex word
    std::uint16_t triangle; // first triangle (3 index bytes each)
};

template <unsigned N>
struct UniformTables {
    static constexpr unsigned patterns = pattern_count(N);
    static constexpr unsigned interior_words = pattern_offsets.interior[patterns];
    static constexpr unsigned triangles = pattern_offsets.triangle[patterns];
    static_assert(N >= 1 && N <= data_max_factor, "the pattern data stops at data_max_factor");
    static_assert(interior_words < 65536 && triangles < 65536, "offsets are 16-bit");
    static_assert(3 * N + (N - 1) * (N - 2) / 2 < 256 || N > 16, "indices are 8-bit");

    std::array<Offset, patterns + 1> offsets{};
    std::array<std::uint32_t, interior_words> interior{};
    std::array<std::uint8_t, 3 * triangles> indices{};
};

template <unsigned N>
constexpr UniformTables<N> build_uniform_tables() {
    UniformTables<N> t;
    for (unsigned p = 0; p <= t.patterns; ++p)
        t.offsets[p] = {static_cast<std::uint16_t>(pattern_offsets.interior[p]),
                        static_cast<std::uint16_t>(pattern_offsets.triangle[p])};
    for (unsigned i = 0; i < t.interior_words; ++i)
        t.interior[i] = static_cast<std::uint32_t>(data::interior[i].v) << 16 | data::interior[i].u;
    for (unsigned i = 0; i < t.triangles; ++i) {
        t.indices[3 * i] = data::triangles[i].i0;
        t.indices[3 * i + 1] = data::triangles[i].i1;
        t.indices[3 * i + 2] = data::triangles[i].i2;
    }
    return t;
}

} // namespace ctess::uniform::tables
