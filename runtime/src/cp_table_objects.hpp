// The table objects behind cp_tables_64 and cp_tables_256, declared for the translation units that define
// them or point at them. Each object is defined `constexpr` right after its `extern` declaration: constexpr
// makes a limit hit a compile error instead of a silent run-time initialiser, and the prior extern
// declaration gives it external linkage (shared/notes/constexpr_feasibility.md P1, P2).
#pragma once
#include <ctess/cp_tables.hpp>
#include <ctess/runtime/cp_table_integrity.hpp>

namespace ctess::rt::detail {

namespace tables = ctess::cp::tables;

inline constexpr unsigned chunks_64 = tables::column_chunks(64);
inline constexpr unsigned chunks_256 = tables::column_chunks(256);

extern const tables::TokenTable<64> token_table_64;
extern const tables::GapTable<64> gap_table_64;
extern const tables::ColumnChunk<64, chunks_64, 0> column_chunk_64_0;

extern const tables::TokenTable<256> token_table_256;
extern const tables::GapTable<256> gap_table_256;
extern const tables::ColumnChunk<256, chunks_256, 0> column_chunk_256_0;
extern const tables::ColumnChunk<256, chunks_256, 1> column_chunk_256_1;
extern const tables::ColumnChunk<256, chunks_256, 2> column_chunk_256_2;
extern const tables::ColumnChunk<256, chunks_256, 3> column_chunk_256_3;

// CRC-32 of each column chunk, computed where the chunk is evaluated (cp_table_integrity.hpp).
extern const std::uint32_t column_chunk_64_0_crc;
extern const std::uint32_t column_chunk_256_0_crc;
extern const std::uint32_t column_chunk_256_1_crc;
extern const std::uint32_t column_chunk_256_2_crc;
extern const std::uint32_t column_chunk_256_3_crc;

static_assert(chunks_64 == 1 && chunks_256 == 4, "update the declarations and runtime/CMakeLists.txt");

} // namespace ctess::rt::detail
