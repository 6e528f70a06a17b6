// The token and gap tables for max factor 256 and the table set that points at every chunk. The column
// table is evaluated in cp_tables_256_columns_*.cpp, one chunk per translation unit.
#include <ctess/runtime/cp_table_set.hpp>

#include "cp_table_objects.hpp"

namespace ctess::rt {
namespace detail {
constexpr tables::TokenTable<256> token_table_256 = tables::build_token_table<256>();
constexpr tables::GapTable<256> gap_table_256 = tables::build_gap_table<256>();

#define CTESS_CHUNK_256(k)                                                                                   \
    {                                                                                                        \
        column_chunk_256_##k.records.data(), column_chunk_256_##k.pool.data(),                               \
            column_chunk_256_##k.first_shape2                                                                \
    }
constexpr CpColumnChunk column_chunks_256[] = {CTESS_CHUNK_256(0), CTESS_CHUNK_256(1), CTESS_CHUNK_256(2),
                                               CTESS_CHUNK_256(3)};
#undef CTESS_CHUNK_256
constexpr auto chunk_of_shape2_256 = tables::ColumnChunkPlan<256, chunks_256>::chunk_of;

template <unsigned K> using Chunk256 = tables::ColumnChunk<256, chunks_256, K>;
constexpr CpTableDigest digest_256 = {
    tables::TokenTable<256>::points,
    tables::GapTable<256>::words,
    chunks_256,
    {Chunk256<0>::pairs, Chunk256<1>::pairs, Chunk256<2>::pairs, Chunk256<3>::pairs},
    {Chunk256<0>::pool_size, Chunk256<1>::pool_size, Chunk256<2>::pool_size, Chunk256<3>::pool_size},
    crc32::of_token_table(token_table_256),
    crc32::of_gap_table(gap_table_256),
    crc32::chunk_plan(chunk_of_shape2_256.data(), chunk_of_shape2_256.size(), column_chunks_256, chunks_256),
    {&column_chunk_256_0_crc, &column_chunk_256_1_crc, &column_chunk_256_2_crc, &column_chunk_256_3_crc},
};
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
