// Column table chunk 0 of 4 for max factor 256 (see cp_table_objects.hpp).
#include "cp_table_objects.hpp"

namespace ctess::rt::detail {
constexpr tables::ColumnChunk<256, chunks_256, 0> column_chunk_256_0 =
    tables::build_column_chunk<256, chunks_256, 0>();
constexpr std::uint32_t column_chunk_256_0_crc = crc32::of_column_chunk(column_chunk_256_0);
} // namespace ctess::rt::detail
