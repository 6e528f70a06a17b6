// Column table chunk CTESS_COLUMN_CHUNK of the max-256 tables. This file is compiled once per chunk, with
// -DCTESS_COLUMN_CHUNK=k for k in [0, CTESS_COLUMN_CHUNKS_256) (runtime/CMakeLists.txt does so).
#include "table_objects.hpp"

#ifndef CTESS_COLUMN_CHUNK
#error "compile with -DCTESS_COLUMN_CHUNK=k, once per chunk k (see runtime/CMakeLists.txt)"
#endif
static_assert(CTESS_COLUMN_CHUNK >= 0 && CTESS_COLUMN_CHUNK < CTESS_COLUMN_CHUNKS_256);

#define CTESS_CHUNK_NAME_(k) column_chunk_256_##k
#define CTESS_CHUNK_NAME(k) CTESS_CHUNK_NAME_(k)
#define CTESS_CHUNK_CRC_NAME_(k) column_chunk_256_##k##_crc
#define CTESS_CHUNK_CRC_NAME(k) CTESS_CHUNK_CRC_NAME_(k)

namespace ctess::rt::detail {
constexpr tables::ColumnChunk<256, chunks_256, CTESS_COLUMN_CHUNK>
    CTESS_CHUNK_NAME(CTESS_COLUMN_CHUNK) = tables::build_column_chunk<256, chunks_256, CTESS_COLUMN_CHUNK>();
constexpr std::uint32_t
    CTESS_CHUNK_CRC_NAME(CTESS_COLUMN_CHUNK) = crc32::of_column_chunk(CTESS_CHUNK_NAME(CTESS_COLUMN_CHUNK));
} // namespace ctess::rt::detail
