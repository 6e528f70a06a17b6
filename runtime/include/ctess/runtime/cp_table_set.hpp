// A view of the compile-time CP tables of one maximum factor, as the runtime reads them. The two sets,
// cp_tables_64 and cp_tables_256, are constant-initialised objects in the ctess_runtime_64 and
// ctess_runtime_256 libraries (no dynamic initialisation; the tables themselves are in .rodata).
#pragma once
#include <cstdint>

#include <ctess/config.hpp>
#include <ctess/cp_tables_layout.hpp>

namespace ctess::rt {

struct CpColumnChunk {
    const cp::tables::ColumnRecord* records; // (s2 - first_shape2) * shapes + s0 - 1
    const std::uint16_t* pool;
    unsigned first_shape2;
};

struct CpTableSet {
    unsigned max_factor; // 64 or 256
    unsigned shapes;     // shape tokens T1..T(shapes)
    const cp::tables::TokenRecord* tokens;
    const std::uint16_t* points;
    const std::uint8_t* chunk_of_shape2; // [shape index of e2]
    const CpColumnChunk* column_chunks;
    const std::uint16_t* gap_offset; // [(s1 - 1) * shapes + s0 - 1]
    const std::uint32_t* gap_word;
    const std::uint16_t* t1_last_fan; // [s0 - 1]
};

extern const CpTableSet cp_tables_64;  // ctess_runtime_64
extern const CpTableSet cp_tables_256; // ctess_runtime_256

// The configured table set (CMake option CTESS_MAX_TESS_FACTOR, linked by ctess::runtime): code written
// against cp_tables compiles and links in both builds.
#if CTESS_MAX_TESS_FACTOR == 256
inline constexpr const CpTableSet& cp_tables = cp_tables_256;
#else
inline constexpr const CpTableSet& cp_tables = cp_tables_64;
#endif

} // namespace ctess::rt
