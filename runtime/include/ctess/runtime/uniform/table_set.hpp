// A view of the compile-time uniform-density tables of one maximum factor (docs/algorithm.md §3.3), as the
// runtime reads them. uniform_tables_11 and uniform_tables_16 are constant-initialised objects in the
// ctess_uniform_runtime_11 and ctess_uniform_runtime_16 libraries; the tables themselves are in .rodata.
#pragma once
#include <cstdint>

#include <ctess/uniform/tables.hpp>

namespace ctess::rt {

struct UniformTableSet {
    unsigned max_factor;                    // 11 or 16
    const uniform::tables::Offset* offsets; // [pattern_index(f0, f1, f2)], plus a sentinel
    const std::uint32_t* interior;          // (v << 16) | u
    const std::uint8_t* indices;            // 3 per triangle, canonical numbering, provoking vertex first
    const std::uint32_t* copy_words;        // per 16 triangles: which take a copy, copies before (§3.4)
    const std::uint8_t* copy_sources;       // the canonical vertex of each copy
};

extern const UniformTableSet uniform_tables_11; // ctess_uniform_runtime_11
extern const UniformTableSet uniform_tables_16; // ctess_uniform_runtime_16

} // namespace ctess::rt

#if defined(CTESS_UNIFORM_MAX_FACTOR)
namespace ctess::rt {
// The table set the build configured (CTESS_UNIFORM_MAX_FACTOR, 16 or 11); link ctess::uniform_runtime.
#if CTESS_UNIFORM_MAX_FACTOR == 11
inline constexpr const UniformTableSet& uniform_tables = uniform_tables_11;
#else
inline constexpr const UniformTableSet& uniform_tables = uniform_tables_16;
#endif
} // namespace ctess::rt
#endif
