// A view of the compile-time CP tables of one maximum factor, as the runtime reads them. The two sets,
// cp_tables_64 and cp_tables_256, are constant-initialised objects in the ctess_runtime_64 and
// ctess_runtime_256 libraries (no dynamic initialisation; the tables themselves are in .rodata).
#pragma once
#include <cstdint>

#include <ctess/core/config.hpp>
#include <ctess/cp/tables_layout.hpp>

namespace ctess::rt {

struct CpColumnChunk {
    const cp::tables::ColumnRecord* records; // (s2 - first_shape2) * shapes + s0 - 1
    const std::uint16_t* pool;
    unsigned first_shape2;
};

inline constexpr unsigned max_column_chunks = CTESS_COLUMN_CHUNKS_256;

// Every table object's size and the CRC-32 the compiler computed over it (verify_tables in
// cp_table_integrity.hpp). A column chunk's CRC is computed in the translation unit that evaluates that
// chunk, hence the pointers.
struct CpTableDigest {
    unsigned token_points; // entries of CpTableSet::points
    unsigned gap_words;    // entries of CpTableSet::gap_word
    unsigned chunks;       // column chunks
    unsigned chunk_pairs[max_column_chunks];
    unsigned chunk_pool[max_column_chunks];
    std::uint32_t token_crc;      // records, then points
    std::uint32_t gap_crc;        // offsets, words, T1 last fans
    std::uint32_t chunk_plan_crc; // chunk_of_shape2, then each chunk's first_shape2
    const std::uint32_t* chunk_crc[max_column_chunks];
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
    const CpTableDigest* digest;      // for verify_tables (cp_table_integrity.hpp)
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
