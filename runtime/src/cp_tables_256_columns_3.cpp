// Column table chunk 3 of 4 for max factor 256 (see cp_table_objects.hpp).
#include "cp_table_objects.hpp"

namespace ctess::rt::detail {
constexpr tables::ColumnChunk<256, chunks_256, 3> column_chunk_256_3 =
    tables::build_column_chunk<256, chunks_256, 3>();
} // namespace ctess::rt::detail
