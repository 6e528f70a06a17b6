// verify_tables (runtime/include/ctess/runtime/cp/table_integrity.hpp): the compile-time CRC-32 of every
// table object matches the tables in the binary, for both maximum factors; any single flipped bit in a copy
// of any table object is caught and named; the CRC is the standard CRC-32.
#include <catch2/catch.hpp>

#include <cstring>
#include <string>
#include <vector>

#include <ctess/runtime/cp/table_integrity.hpp>

using namespace ctess;
using rt::TableCheck;

namespace {

// A bitwise CRC-32 (no table), independent of the nibble-table implementation under test.
std::uint32_t reference_crc(const std::vector<std::uint8_t>& bytes) {
    std::uint32_t c = 0xFFFFFFFFu;
    for (std::uint8_t b : bytes) {
        c ^= b;
        for (int k = 0; k < 8; ++k) c = (c & 1) ? (c >> 1) ^ 0xEDB88320u : c >> 1;
    }
    return ~c;
}

template <typename T>
void append_le(std::vector<std::uint8_t>& out, const T* p, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
        std::uint8_t b[sizeof(T)];
        std::memcpy(b, &p[i], sizeof(T)); // little-endian host: the bytes are the values' LE bytes
        out.insert(out.end(), b, b + sizeof(T));
    }
}

// A deep copy of a table set, pointing at vectors the test may corrupt.
struct TableCopy {
    std::vector<cp::tables::TokenRecord> tokens;
    std::vector<std::uint16_t> points, gap_offset, t1_last_fan;
    std::vector<std::uint8_t> chunk_of_shape2;
    std::vector<std::uint32_t> gap_word;
    std::vector<std::vector<cp::tables::ColumnRecord>> records;
    std::vector<std::vector<std::uint16_t>> pools;
    std::vector<rt::CpColumnChunk> chunks;
    rt::CpTableSet set;

    explicit TableCopy(const rt::CpTableSet& t) : set(t) {
        const rt::CpTableDigest& d = *t.digest;
        tokens.assign(t.tokens, t.tokens + t.shapes);
        points.assign(t.points, t.points + d.token_points);
        gap_offset.assign(t.gap_offset, t.gap_offset + std::size_t{t.shapes} * t.shapes);
        gap_word.assign(t.gap_word, t.gap_word + d.gap_words);
        t1_last_fan.assign(t.t1_last_fan, t.t1_last_fan + t.shapes);
        chunk_of_shape2.assign(t.chunk_of_shape2, t.chunk_of_shape2 + t.shapes);
        for (unsigned k = 0; k < d.chunks; ++k) {
            records.emplace_back(t.column_chunks[k].records, t.column_chunks[k].records + d.chunk_pairs[k]);
            pools.emplace_back(t.column_chunks[k].pool, t.column_chunks[k].pool + d.chunk_pool[k]);
        }
        for (unsigned k = 0; k < d.chunks; ++k)
            chunks.push_back({records[k].data(), pools[k].data(), t.column_chunks[k].first_shape2});
        set.tokens = tokens.data();
        set.points = points.data();
        set.gap_offset = gap_offset.data();
        set.gap_word = gap_word.data();
        set.t1_last_fan = t1_last_fan.data();
        set.chunk_of_shape2 = chunk_of_shape2.data();
        set.column_chunks = chunks.data();
    }
};

template <typename T>
void flip_bit(std::vector<T>& v, std::size_t bit) {
    auto* bytes = reinterpret_cast<std::uint8_t*>(v.data());
    bytes[(bit / 8) % (v.size() * sizeof(T))] ^= static_cast<std::uint8_t>(1u << (bit % 8));
}

} // namespace

TEST_CASE("CRC-32: the standard check value") {
    const char* text = "123456789";
    std::uint32_t c = rt::crc32::start;
    for (const char* p = text; *p; ++p) c = rt::crc32::byte(c, static_cast<std::uint8_t>(*p));
    CHECK(rt::crc32::finish(c) == 0xCBF43926u);
    CHECK(reference_crc({'1', '2', '3', '4', '5', '6', '7', '8', '9'}) == 0xCBF43926u);
}

TEST_CASE("verify_tables passes on the tables in the binary, max 64 and 256") {
    for (const rt::CpTableSet* t : {&rt::cp_tables_64, &rt::cp_tables_256}) {
        INFO("max " << t->max_factor);
        const rt::TableCheckResult r = rt::verify_tables(*t);
        CHECK(r.failed == TableCheck::ok);
        CHECK(static_cast<bool>(r));
        // The compile-time constants equal a bitwise CRC over the same values, computed here at run time.
        const rt::CpTableDigest& d = *t->digest;
        std::vector<std::uint8_t> bytes;
        for (unsigned s = 0; s < t->shapes; ++s) {
            const cp::tables::TokenRecord& rec = t->tokens[s];
            append_le(bytes, &rec.first_point, 1);
            append_le(bytes, &rec.segments, 1);
            append_le(bytes, &rec.half_step, 1);
        }
        append_le(bytes, t->points, d.token_points);
        CHECK(reference_crc(bytes) == d.token_crc);
        bytes.clear();
        append_le(bytes, t->gap_offset, std::size_t{t->shapes} * t->shapes);
        append_le(bytes, t->gap_word, d.gap_words);
        append_le(bytes, t->t1_last_fan, t->shapes);
        CHECK(reference_crc(bytes) == d.gap_crc);
        for (unsigned k = 0; k < d.chunks; ++k) {
            bytes.clear();
            append_le(bytes, t->column_chunks[k].records,
                      d.chunk_pairs[k]); // 2 + 2 + 4 + 4 bytes, no padding
            append_le(bytes, t->column_chunks[k].pool, d.chunk_pool[k]);
            CHECK(reference_crc(bytes) == *d.chunk_crc[k]);
        }
    }
}

TEST_CASE("verify_tables catches one flipped bit in a copy of any table object") {
    static_assert(sizeof(cp::tables::TokenRecord) == 6 && sizeof(cp::tables::ColumnRecord) == 12,
                  "every byte of a record is a value byte");
    for (const rt::CpTableSet* t : {&rt::cp_tables_64, &rt::cp_tables_256}) {
        INFO("max " << t->max_factor);
        TableCopy copy(*t);
        REQUIRE(rt::verify_tables(copy.set).failed == TableCheck::ok);
        // First, last and some middle bits of every object; each flip is undone before the next.
        const auto check_flips = [&](auto& v, TableCheck expected, unsigned chunk, const char* what) {
            const std::size_t bits = v.size() * sizeof(v[0]) * 8;
            for (std::size_t bit : {std::size_t{0}, bits - 1, bits / 2 + 3, bits / 3 + 5, bits / 7}) {
                INFO(what << " bit " << bit);
                flip_bit(v, bit);
                const rt::TableCheckResult r = rt::verify_tables(copy.set);
                CHECK(r.failed == expected);
                CHECK(r.chunk == chunk);
                CHECK_FALSE(static_cast<bool>(r));
                flip_bit(v, bit);
            }
        };
        check_flips(copy.tokens, TableCheck::token_table, 0, "token records");
        check_flips(copy.points, TableCheck::token_table, 0, "token points");
        check_flips(copy.gap_offset, TableCheck::gap_table, 0, "gap offsets");
        check_flips(copy.gap_word, TableCheck::gap_table, 0, "gap words");
        check_flips(copy.t1_last_fan, TableCheck::gap_table, 0, "T1 last fans");
        check_flips(copy.chunk_of_shape2, TableCheck::chunk_plan, 0, "chunk plan");
        for (unsigned k = 0; k < copy.records.size(); ++k) {
            check_flips(copy.records[k], TableCheck::column_chunk, k, "column records");
            check_flips(copy.pools[k], TableCheck::column_chunk, k, "column pool");
        }
        REQUIRE(rt::verify_tables(copy.set).failed == TableCheck::ok); // every flip was undone
    }
}
