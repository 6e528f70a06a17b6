// The table objects behind cp_tables_64 and cp_tables_256, declared for the translation units that define
// them or point at them. Each object is defined `constexpr` right after its `extern` declaration: constexpr
// makes a limit hit a compile error instead of a silent run-time initialiser, and the prior extern
// declaration gives it external linkage (docs/algorithm.md §4.5).
#pragma once
#include <ctess/cp/tables.hpp>
#include <ctess/runtime/cp/table_integrity.hpp>

namespace ctess::rt::detail {

namespace tables = ctess::cp::tables;

inline constexpr unsigned chunks_64 = tables::column_chunks(64);
inline constexpr unsigned chunks_256 = tables::column_chunks(256);

extern const tables::TokenTable<64> token_table_64;
extern const tables::GapTable<64> gap_table_64;
extern const tables::ColumnChunk<64, chunks_64, 0> column_chunk_64_0;

extern const tables::TokenTable<256> token_table_256;
extern const tables::GapTable<256> gap_table_256;
#define CTESS_DECLARE_COLUMN_CHUNK_256(k)                                                                    \
    extern const tables::ColumnChunk<256, chunks_256, k> column_chunk_256_##k;
CTESS_FOR_EACH_COLUMN_CHUNK_256(CTESS_DECLARE_COLUMN_CHUNK_256)
#undef CTESS_DECLARE_COLUMN_CHUNK_256

// CRC-32 of each column chunk, computed where the chunk is evaluated (cp_table_integrity.hpp).
extern const std::uint32_t column_chunk_64_0_crc;
#define CTESS_DECLARE_COLUMN_CHUNK_CRC_256(k) extern const std::uint32_t column_chunk_256_##k##_crc;
CTESS_FOR_EACH_COLUMN_CHUNK_256(CTESS_DECLARE_COLUMN_CHUNK_CRC_256)
#undef CTESS_DECLARE_COLUMN_CHUNK_CRC_256

// CpPatchSetup::emit reads an edge's packed points a whole vector (up to 8) at a time; an edge with fewer
// interior points reads on into the following tokens' points (runtime/src/cp/patch_emit.cpp, edge_interior),
// which must lie inside the point table.
template <unsigned MaxFactor>
constexpr bool small_tokens_readable_as_vectors(const tables::TokenTable<MaxFactor>& table) {
    constexpr unsigned vector_points = 8;
    for (const tables::TokenRecord& record : table.records)
        if (record.segments - 1u < vector_points && record.first_point + vector_points > table.point.size())
            return false;
    return true;
}

static_assert(chunks_64 == 1, "max 64 has one column chunk, defined in cp_tables_64.cpp");
static_assert(chunks_256 <= max_column_chunks, "CpTableDigest holds at most max_column_chunks chunks");

} // namespace ctess::rt::detail
