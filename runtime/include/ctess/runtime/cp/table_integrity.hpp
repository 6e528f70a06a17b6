// Table integrity for embedded users: verify_tables(tables) recomputes a CRC-32 of every table object of a
// CpTableSet and compares it with the CRC the compiler computed over the same constexpr-built tables, so a
// corrupted flash page (or a bad linker script) is caught before the tables are used.
//
//   if (!ctess::rt::verify_tables(ctess::rt::cp_tables_64)) enter_safe_mode();
//
// The CRC (IEEE 802.3, reflected polynomial 0xEDB88320, as zlib's crc32) runs over each table's values in a
// fixed little-endian order (u16 and u32 entries, float bit patterns; records field by field), not over raw
// object bytes, so that padding never counts and the constant is the same on every target. A nibble table
// (16 words) keeps the code small. No heap, no exceptions; O(table bytes).
#pragma once
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

#include <ctess/cp/tables_layout.hpp>

#include "table_set.hpp"

namespace ctess::rt {

namespace crc32 {

inline constexpr std::array<std::uint32_t, 16> nibble_table = [] {
    std::array<std::uint32_t, 16> t{};
    for (std::uint32_t n = 0; n < 16; ++n) {
        std::uint32_t c = n;
        for (int k = 0; k < 4; ++k) c = (c & 1) ? (c >> 1) ^ 0xEDB88320u : c >> 1;
        t[n] = c;
    }
    return t;
}();

// Running CRC values are kept inverted (start with `start`, finish with `finish`).
inline constexpr std::uint32_t start = 0xFFFFFFFFu;
constexpr std::uint32_t finish(std::uint32_t c) {
    return ~c;
}

constexpr std::uint32_t byte(std::uint32_t c, std::uint8_t b) {
    c ^= b;
    c = (c >> 4) ^ nibble_table[c & 15];
    return (c >> 4) ^ nibble_table[c & 15];
}
constexpr std::uint32_t value(std::uint32_t c, std::uint8_t x) {
    return byte(c, x);
}
constexpr std::uint32_t value(std::uint32_t c, std::uint16_t x) {
    return byte(byte(c, static_cast<std::uint8_t>(x)), static_cast<std::uint8_t>(x >> 8));
}
constexpr std::uint32_t value(std::uint32_t c, std::uint32_t x) {
    return value(value(c, static_cast<std::uint16_t>(x)), static_cast<std::uint16_t>(x >> 16));
}
constexpr std::uint32_t value(std::uint32_t c, float x) {
    return value(c, std::bit_cast<std::uint32_t>(x));
}
constexpr std::uint32_t value(std::uint32_t c, const cp::tables::TokenRecord& r) {
    return value(value(value(c, r.first_point), r.segments), r.half_step);
}
constexpr std::uint32_t value(std::uint32_t c, const cp::tables::ColumnRecord& r) {
    return value(value(value(value(c, r.offset), r.head), r.a), r.b);
}
template <typename T>
constexpr std::uint32_t values(std::uint32_t c, const T* p, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) c = value(c, p[i]);
    return c;
}

// One table object: the same functions at compile time (over the constexpr objects) and at run time (over
// the CpTableSet's pointers).
constexpr std::uint32_t token_table(const cp::tables::TokenRecord* records, std::size_t shapes,
                                    const std::uint16_t* points, std::size_t point_count) {
    return finish(values(values(start, records, shapes), points, point_count));
}
constexpr std::uint32_t gap_table(const std::uint16_t* offset, std::size_t shapes, const std::uint32_t* word,
                                  std::size_t words, const std::uint16_t* t1_last_fan) {
    return finish(values(values(values(start, offset, shapes * shapes), word, words), t1_last_fan, shapes));
}
constexpr std::uint32_t column_chunk(const cp::tables::ColumnRecord* records, std::size_t pairs,
                                     const std::uint16_t* pool, std::size_t pool_size) {
    return finish(values(values(start, records, pairs), pool, pool_size));
}
// Which chunk holds each e2 shape, then each chunk's first shape.
constexpr std::uint32_t chunk_plan(const std::uint8_t* chunk_of_shape2, std::size_t shapes,
                                   const CpColumnChunk* chunks, std::size_t chunk_count) {
    std::uint32_t c = values(start, chunk_of_shape2, shapes);
    for (std::size_t k = 0; k < chunk_count; ++k)
        c = value(c, static_cast<std::uint32_t>(chunks[k].first_shape2));
    return finish(c);
}
template <typename Table>
constexpr std::uint32_t of_token_table(const Table& t) {
    return token_table(t.records.data(), t.records.size(), t.point.data(), t.point.size());
}
template <typename Table>
constexpr std::uint32_t of_gap_table(const Table& t) {
    return gap_table(t.offset.data(), t.t1_last_fan.size(), t.word.data(), t.word.size(),
                     t.t1_last_fan.data());
}
template <typename Chunk>
constexpr std::uint32_t of_column_chunk(const Chunk& c) {
    return column_chunk(c.records.data(), c.records.size(), c.pool.data(), c.pool.size());
}

} // namespace crc32

// verify_tables' result: ok, or the first table object whose CRC differs.
enum class TableCheck : std::uint8_t { ok, token_table, gap_table, chunk_plan, column_chunk };

struct TableCheckResult {
    TableCheck failed = TableCheck::ok;
    unsigned chunk = 0; // for column_chunk
    explicit operator bool() const { return failed == TableCheck::ok; }
};

// Recomputes every table object's CRC-32 and compares it with the compile-time constant in tables.digest.
inline TableCheckResult verify_tables(const CpTableSet& tables) {
    const CpTableDigest& d = *tables.digest;
    if (crc32::token_table(tables.tokens, tables.shapes, tables.points, d.token_points) != d.token_crc)
        return {TableCheck::token_table, 0};
    if (crc32::gap_table(tables.gap_offset, tables.shapes, tables.gap_word, d.gap_words,
                         tables.t1_last_fan) != d.gap_crc)
        return {TableCheck::gap_table, 0};
    if (crc32::chunk_plan(tables.chunk_of_shape2, tables.shapes, tables.column_chunks, d.chunks) !=
        d.chunk_plan_crc)
        return {TableCheck::chunk_plan, 0};
    for (unsigned k = 0; k < d.chunks; ++k) {
        const CpColumnChunk& c = tables.column_chunks[k];
        if (crc32::column_chunk(c.records, d.chunk_pairs[k], c.pool, d.chunk_pool[k]) != *d.chunk_crc[k])
            return {TableCheck::column_chunk, k};
    }
    return {};
}

} // namespace ctess::rt
