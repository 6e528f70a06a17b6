// Column table chunk 3 of 4 for max factor 256 (see cp_table_objects.hpp).
#include "cp_table_objects.hpp"

namespace ctess::rt::detail {
constexpr tables::ColumnChunk<256, chunks_256, 3> column_chunk_256_3 =
    tables::build_column_chunk<256, chunks_256, 3>();
constexpr std::uint32_t column_chunk_256_3_crc = crc32::of_column_chunk(column_chunk_256_3);
} // namespace ctess::rt::detail
