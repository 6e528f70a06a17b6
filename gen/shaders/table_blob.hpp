// The CP tables of one maximum factor as one little-endian u32 blob, for shaders that read them from a
// storage buffer. Sections, in order (offsets in words, injected into the shaders as constants):
//   token_range   tokens words:  lo | hi << 16 (factor range (lo, hi] of token t; cp::token_info)
//   token_record  shapes * 2:    first_point | segments << 16, half_step
//   point         u16 pairs:     the packed interior points (cp_tables_layout.hpp), low half first
//   column_record shapes^2 * 4:  pool index of C_0, head h, float bits of a, float bits of b;
//                                pair (s0, s2) at ((s2 - 1) * shapes + s0 - 1) * 4
//   column_pool   u16 pairs:     every chunk's column starts, chunk after chunk
//   gap_offset    u16 pairs:     pair (s0, s1) at (s1 - 1) * shapes + s0 - 1, relative to gap_word
//   gap_word      u32:           zipper words
//   t1_last_fan   shapes words
//   uniform_offset   patterns + 1 words: first interior word | first triangle << 16 of each uniform-density
//                    pattern (uniform::pattern_index order), then the sentinel (docs/algorithm.md §3.3)
//   uniform_interior interior vertex words: u | v << 16 (units of 65534)
//   uniform_triangle bytes, 4 per word (low byte first): i0, i1, i2 of each triangle (canonical numbering,
//                    counter-clockwise), triangle p's at byte 3p
//   padding       blob_padding zero words, so that the lookups' reads past an array stay in the buffer
// docs/shaders.md draws the same layout.
#pragma once
#include <cstdint>
#include <cstring>
#include <vector>

#include <ctess/cp/line.hpp>
#include <ctess/cp/tables_gap.hpp>
#include <ctess/cp/tables_layout.hpp>
#include <ctess/cp/tables_tokens.hpp>
#include <ctess/runtime/cp/table_set.hpp>
#include <ctess/runtime/uniform/table_set.hpp>
#include <ctess/uniform/pattern.hpp>

namespace ctess::gen {

inline constexpr unsigned blob_padding = 16;

struct TableBlobLayout {
    std::uint32_t token_range = 0, token_record = 0, point = 0, column_record = 0, column_pool = 0,
                  gap_offset = 0, gap_word = 0, t1_last_fan = 0, uniform_offset = 0, uniform_interior = 0,
                  uniform_triangle = 0, words = 0;
    std::uint32_t tokens = 0, shapes = 0, max_factor = 0, uniform_max_factor = 0;
};

struct TableBlob {
    TableBlobLayout layout;
    std::vector<std::uint32_t> words;
};

namespace detail {
inline void append_u16(std::vector<std::uint32_t>& out, const std::uint16_t* v, std::size_t n) {
    for (std::size_t i = 0; i < n; i += 2) {
        const std::uint32_t lo = v[i];
        const std::uint32_t hi = i + 1 < n ? v[i + 1] : 0u;
        out.push_back(lo | hi << 16);
    }
}
inline std::uint32_t float_bits(float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}
} // namespace detail

inline TableBlob build_table_blob(const rt::CpTableSet& t, const rt::UniformTableSet& u) {
    namespace tables = cp::tables;
    TableBlob blob;
    TableBlobLayout& l = blob.layout;
    std::vector<std::uint32_t>& w = blob.words;
    l.max_factor = t.max_factor;
    l.tokens = cp::token_count(t.max_factor);
    l.shapes = t.shapes;
    const unsigned shapes = t.shapes;

    l.token_range = static_cast<std::uint32_t>(w.size());
    for (unsigned k = 0; k < l.tokens; ++k) {
        const cp::TokenInfo info = cp::token_info(k);
        w.push_back(std::uint32_t{info.lo} | std::uint32_t{info.hi} << 16);
    }
    l.token_record = static_cast<std::uint32_t>(w.size());
    for (unsigned s = 0; s < shapes; ++s) {
        w.push_back(std::uint32_t{t.tokens[s].first_point} | std::uint32_t{t.tokens[s].segments} << 16);
        w.push_back(t.tokens[s].half_step);
    }
    l.point = static_cast<std::uint32_t>(w.size());
    detail::append_u16(w, t.points, tables::token_point_count(t.max_factor));

    // Column records point into one pool made of the chunks' pools, in chunk order.
    unsigned chunks = 0;
    for (unsigned s = 0; s < shapes; ++s)
        chunks = t.chunk_of_shape2[s] + 1u > chunks ? t.chunk_of_shape2[s] + 1u : chunks;
    std::vector<std::uint32_t> chunk_base(chunks, 0), chunk_size(chunks, 0);
    for (unsigned s2 = 1; s2 <= shapes; ++s2) {
        const rt::CpColumnChunk& c = t.column_chunks[t.chunk_of_shape2[s2 - 1]];
        for (unsigned s0 = 1; s0 <= shapes; ++s0) {
            const tables::ColumnRecord& r = c.records[(s2 - c.first_shape2) * shapes + s0 - 1];
            const std::uint32_t end = std::uint32_t{r.offset} + r.head + 2u + tables::pool_padding;
            std::uint32_t& size = chunk_size[t.chunk_of_shape2[s2 - 1]];
            size = end > size ? end : size; // the builder lays the pairs out back to back, padding last
        }
    }
    for (unsigned k = 1; k < chunks; ++k) chunk_base[k] = chunk_base[k - 1] + chunk_size[k - 1];
    l.column_record = static_cast<std::uint32_t>(w.size());
    for (unsigned s2 = 1; s2 <= shapes; ++s2) {
        const unsigned chunk = t.chunk_of_shape2[s2 - 1];
        const rt::CpColumnChunk& c = t.column_chunks[chunk];
        for (unsigned s0 = 1; s0 <= shapes; ++s0) {
            const tables::ColumnRecord& r = c.records[(s2 - c.first_shape2) * shapes + s0 - 1];
            w.push_back(chunk_base[chunk] + r.offset);
            w.push_back(r.head);
            w.push_back(detail::float_bits(r.a));
            w.push_back(detail::float_bits(r.b));
        }
    }
    l.column_pool = static_cast<std::uint32_t>(w.size());
    std::vector<std::uint16_t> pool;
    for (unsigned k = 0; k < chunks; ++k)
        pool.insert(pool.end(), t.column_chunks[k].pool, t.column_chunks[k].pool + chunk_size[k]);
    detail::append_u16(w, pool.data(), pool.size());

    l.gap_offset = static_cast<std::uint32_t>(w.size());
    detail::append_u16(w, t.gap_offset, std::size_t{shapes} * shapes);
    l.gap_word = static_cast<std::uint32_t>(w.size());
    const unsigned gap_words = tables::gap_word_count(t.max_factor);
    w.insert(w.end(), t.gap_word, t.gap_word + gap_words);
    l.t1_last_fan = static_cast<std::uint32_t>(w.size());
    for (unsigned s = 0; s < shapes; ++s) w.push_back(t.t1_last_fan[s]);

    l.uniform_max_factor = u.max_factor;
    const unsigned patterns = uniform::pattern_count(u.max_factor);
    l.uniform_offset = static_cast<std::uint32_t>(w.size());
    for (unsigned p = 0; p <= patterns; ++p)
        w.push_back(std::uint32_t{u.offsets[p].interior} | std::uint32_t{u.offsets[p].triangle} << 16);
    l.uniform_interior = static_cast<std::uint32_t>(w.size());
    w.insert(w.end(), u.interior, u.interior + u.offsets[patterns].interior);
    l.uniform_triangle = static_cast<std::uint32_t>(w.size());
    const std::size_t index_bytes = 3 * std::size_t{u.offsets[patterns].triangle};
    for (std::size_t b = 0; b < index_bytes; b += 4) {
        std::uint32_t word = 0;
        for (std::size_t k = 0; k < 4 && b + k < index_bytes; ++k)
            word |= std::uint32_t{u.indices[b + k]} << (8 * k);
        w.push_back(word);
    }
    w.insert(w.end(), blob_padding, 0u);
    l.words = static_cast<std::uint32_t>(w.size());
    return blob;
}

} // namespace ctess::gen
