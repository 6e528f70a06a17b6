// Every CP table for max factor 64, evaluated at compile time (one translation unit is fast enough).
#include <ctess/runtime/cp/table_set.hpp>

#include "table_objects.hpp"

namespace ctess::rt {
namespace detail {
constexpr tables::TokenTable<64> token_table_64 = tables::build_token_table<64>();
static_assert(small_tokens_readable_as_vectors(token_table_64));
constexpr tables::GapTable<64> gap_table_64 = tables::build_gap_table<64>();
constexpr tables::ColumnChunk<64, chunks_64, 0> column_chunk_64_0 =
    tables::build_column_chunk<64, chunks_64, 0>();

constexpr std::uint32_t column_chunk_64_0_crc = crc32::of_column_chunk(column_chunk_64_0);

constexpr CpColumnChunk column_chunks_64[] = {
    {column_chunk_64_0.records.data(), column_chunk_64_0.pool.data(), column_chunk_64_0.first_shape2},
};
constexpr auto chunk_of_shape2_64 = tables::ColumnChunkPlan<64, chunks_64>::chunk_of;

using Chunk64 = tables::ColumnChunk<64, chunks_64, 0>;
constexpr CpTableDigest digest_64 = {
    tables::TokenTable<64>::points,
    tables::GapTable<64>::words,
    chunks_64,
    {Chunk64::pairs},
    {Chunk64::pool_size},
    crc32::of_token_table(token_table_64),
    crc32::of_gap_table(gap_table_64),
    crc32::chunk_plan(chunk_of_shape2_64.data(), chunk_of_shape2_64.size(), column_chunks_64, chunks_64),
    {&column_chunk_64_0_crc},
};
} // namespace detail

extern const CpTableSet cp_tables_64;
constexpr CpTableSet cp_tables_64 = {64,
                                     detail::tables::shape_count(64),
                                     detail::token_table_64.records.data(),
                                     detail::token_table_64.point.data(),
                                     detail::chunk_of_shape2_64.data(),
                                     detail::column_chunks_64,
                                     detail::gap_table_64.offset.data(),
                                     detail::gap_table_64.word.data(),
                                     detail::gap_table_64.t1_last_fan.data(),
                                     &detail::digest_64};
} // namespace ctess::rt
