// Column table chunk 2 of 4 for max factor 256 (see cp_table_objects.hpp).
#include "cp_table_objects.hpp"

namespace ctess::rt::detail {
constexpr tables::ColumnChunk<256, chunks_256, 2> column_chunk_256_2 =
    tables::build_column_chunk<256, chunks_256, 2>();
constexpr std::uint32_t column_chunk_256_2_crc = crc32::of_column_chunk(column_chunk_256_2);
} // namespace ctess::rt::detail
