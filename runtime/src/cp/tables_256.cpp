// The token and gap tables for max factor 256 and the table set that points at every chunk. The column
// table is evaluated in cp_tables_256_columns.cpp, compiled once per chunk.
#include <ctess/runtime/cp/table_set.hpp>

#include "table_objects.hpp"

namespace ctess::rt {
namespace detail {
constexpr tables::TokenTable<256> token_table_256 = tables::build_token_table<256>();
static_assert(small_tokens_readable_as_vectors(token_table_256));
constexpr tables::GapTable<256> gap_table_256 = tables::build_gap_table<256>();

#define CTESS_CHUNK_256(k)                                                                                   \
    {column_chunk_256_##k.records.data(), column_chunk_256_##k.pool.data(),                                  \
     column_chunk_256_##k.first_shape2},
constexpr CpColumnChunk column_chunks_256[] = {CTESS_FOR_EACH_COLUMN_CHUNK_256(CTESS_CHUNK_256)};
#undef CTESS_CHUNK_256
constexpr auto chunk_of_shape2_256 = tables::ColumnChunkPlan<256, chunks_256>::chunk_of;

template <unsigned K>
using Chunk256 = tables::ColumnChunk<256, chunks_256, K>;
constexpr CpTableDigest digest_256 = {
    tables::TokenTable<256>::points,
    tables::GapTable<256>::words,
    chunks_256,
#define CTESS_CHUNK_PAIRS_256(k) Chunk256<k>::pairs,
#define CTESS_CHUNK_POOL_256(k) Chunk256<k>::pool_size,
#define CTESS_CHUNK_CRC_256(k) &column_chunk_256_##k##_crc,
    {CTESS_FOR_EACH_COLUMN_CHUNK_256(CTESS_CHUNK_PAIRS_256)},
    {CTESS_FOR_EACH_COLUMN_CHUNK_256(CTESS_CHUNK_POOL_256)},
    crc32::of_token_table(token_table_256),
    crc32::of_gap_table(gap_table_256),
    crc32::chunk_plan(chunk_of_shape2_256.data(), chunk_of_shape2_256.size(), column_chunks_256, chunks_256),
    {CTESS_FOR_EACH_COLUMN_CHUNK_256(CTESS_CHUNK_CRC_256)},
};
#undef CTESS_CHUNK_PAIRS_256
#undef CTESS_CHUNK_POOL_256
#undef CTESS_CHUNK_CRC_256
} // namespace detail

extern const CpTableSet cp_tables_256;
constexpr CpTableSet cp_tables_256 = {256,
                                      detail::tables::shape_count(256),
                                      detail::token_table_256.records.data(),
                                      detail::token_table_256.point.data(),
                                      detail::chunk_of_shape2_256.data(),
                                      detail::column_chunks_256,
                                      detail::gap_table_256.offset.data(),
                                      detail::gap_table_256.word.data(),
                                      detail::gap_table_256.t1_last_fan.data(),
                                      &detail::digest_256};
} // namespace ctess::rt
