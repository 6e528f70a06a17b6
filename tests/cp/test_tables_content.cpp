// The emitted tables against the procedural ground truth, for every entry of both table sets: token points
// against cp::token_points, column starts against cp::column_counts (rule (b)), the zipper bits against
// cp::gap_merge, and the T1 fan positions. The builders are also evaluated in constant expressions here.
#include <ctess/cp/columns.hpp>
#include <ctess/cp/gap.hpp>
#include <ctess/cp/tables.hpp>
#include <ctess/runtime/cp/table_set.hpp>

#include <array>
#include <bit>
#include <cstdint>
#include <vector>

#include <catch2/catch.hpp>

using ctess::rt::CpTableSet;
namespace cp = ctess::cp;
namespace tables = ctess::cp::tables;

// ---- constant evaluation of every builder function (small inputs keep this TU fast) ----
static_assert(tables::shape_count(64) == 16 && tables::shape_count(256) == 24);
static_assert(tables::shape_index(0) == 0 && tables::shape_index(1) == 0 && tables::shape_index(7) == 6);
static_assert(tables::column_chunks(64) == 1 && tables::column_chunks(256) >= 2);
static_assert(tables::token_half_step(1) == 128 && tables::token_half_step(2) == 64 &&
              tables::token_half_step(5) == 16 && tables::token_half_step(24) == 1);
static_assert(tables::token_point_count(64) == 369 && tables::token_point_count(256) == 1609); // sum of n - 1
static_assert(tables::pack_point({0, 128}, 128) == (128 | (tables::slide_up << 8)));
static_assert(tables::unpack_point(tables::pack_point({256, 128}, 128), 128) == cp::PointTrack{256, 128});
static_assert(tables::gap_triangle_count(1, 1) == 5 && tables::gap_triangle_count(24, 24) == 511);
static_assert(tables::gap_word_count(64) > 0);
static_assert([] {
    constexpr auto t = tables::build_token_table<64>();
    return t.records[0].segments == 3 && t.records[15].segments == 64 &&
           t.point[0] == (128 | (tables::slide_up << 8));
}());
static_assert([] {
    tables::ShapeTracks st{};
    tables::fill_shape_tracks(64, st);
    std::array<std::uint16_t, 257> rows{};
    const auto g = tables::pair_reach_gaps(st, 4, 4); // T4 = f in (6, 8]: n = 8, last final 7/8 = 224/256
    // Triforce at a power of two: R = 8, 7, ..., 1 (h = 7).
    const unsigned h = tables::head_column_counts(st, 4, 4, rows.data());
    return g.ff == 256 - 224 && h == 7 && tables::column_head(st, 4, 4) == 7 && rows[0] == 8 &&
           rows[1] == 7 && rows[7] == 1;
}());
static_assert([] {
    std::array<std::uint16_t, 4> c{0, 4, 7, 9}; // C_k = 4.5 k - 0.5 k^2 exactly
    tables::ColumnRecord rec{};
    tables::fit_column_starts(c.data(), 3, rec);
    return rec.a > 4.49f && rec.a < 4.51f && rec.b > 0.49f && rec.b < 0.51f;
}());
static_assert([] {
    tables::ShapeTracks st{};
    tables::fill_shape_tracks(64, st);
    std::array<std::uint16_t, 258> m{};
    const unsigned nl = tables::zipper_merge(st, 4, 4, m.data()); // equal tokens: M(a) = a (triforce zipper)
    for (unsigned a = 0; a <= nl; ++a)
        if (m[a] != a) return false;
    return nl == 8;
}());
static_assert(tables::ColumnChunkPlan<256, 4>::first_shape2[0] == 1 &&
              tables::ColumnChunkPlan<256, 4>::first_shape2[4] == 25);
static_assert([] {
    // (T1, T1): lambda = (0, 256, 256), sigma = (0, 0, 128, 256) give M = (0, 1, 2, 3) (docs §2.6), so the
    // steps are fan, lhs, fan, lhs, fan: bits 1 and 3. The 3rd rhs step (R_3, L, R_2) is step 4.
    constexpr auto g = tables::build_gap_table<64>();
    return g.offset[0] == 0 && g.word[0] == 0b01010u && g.t1_last_fan[0] == 4;
}());
static_assert([] {
    constexpr auto chunk = tables::build_column_chunk<64, 1, 0>();
    // Pair (T4, T4) is the triforce 8: C_7 = 8 + 7 + ... + 2 = 35.
    const auto& rec = chunk.records[(4 - 1) * 16 + 4 - 1];
    return rec.head == 7 && chunk.pool[rec.offset + 7] == 35 && chunk.pool[rec.offset + 8] == 36;
}());

namespace {

std::vector<cp::PointTrack> tracks_of(unsigned token) {
    std::vector<cp::PointTrack> t(cp::max_segments + 1);
    t.resize(cp::token_points(token, t.data()));
    return t;
}

void check_tokens(const CpTableSet& t) {
    for (unsigned s = 1; s <= t.shapes; ++s) {
        const tables::TokenRecord& rec = t.tokens[s - 1];
        const auto truth = tracks_of(s);
        INFO("max " << t.max_factor << " token T" << s);
        REQUIRE(rec.segments + 1u == truth.size());
        for (unsigned i = 1; i < rec.segments; ++i)
            REQUIRE(tables::unpack_point(t.points[rec.first_point + i - 1], rec.half_step) == truth[i]);
    }
}

void check_columns(const CpTableSet& t) {
    cp::ColumnCounts rows{};
    std::uint64_t columns = 0;
    for (unsigned s2 = 1; s2 <= t.shapes; ++s2) {
        for (unsigned s0 = 1; s0 <= t.shapes; ++s0) {
            const ctess::rt::CpColumnChunk& chunk = t.column_chunks[t.chunk_of_shape2[s2 - 1]];
            REQUIRE(s2 >= chunk.first_shape2);
            const tables::ColumnRecord& rec = chunk.records[(s2 - chunk.first_shape2) * t.shapes + s0 - 1];
            const std::uint16_t* c = chunk.pool + rec.offset;
            const unsigned n0 = cp::column_counts(s0, s2, cp::ColumnRule::minimal, rows.data());
            INFO("max " << t.max_factor << " pair (T" << s0 << ", T" << s2 << ")");
            REQUIRE(rec.head >= 1);
            REQUIRE(rec.head < n0);
            REQUIRE(c[0] == 0);
            for (unsigned i = 0; i < n0; ++i) {
                const unsigned stored = i < rec.head ? c[i + 1] - c[i] : 1u;
                REQUIRE(stored == rows[i]);
                ++columns;
            }
            REQUIRE(c[rec.head + 1] == c[rec.head] + 1);
            REQUIRE(rows[rec.head - 1] >= 2); // h is the first column with one point
        }
    }
    CHECK(columns > 0);
}

// The zipper of a pair as the generator builds it, one bit per triangle (1 = lhs advances).
std::vector<bool> zipper_steps(unsigned s0, unsigned s1) {
    const cp::EdgeLine e0 = cp::make_edge_line({s0, 0});
    const cp::EdgeLine e1 = cp::make_edge_line({s1, 0});
    std::array<std::uint16_t, cp::max_segments + 1> lambda{}, sigma{}, merge{};
    const unsigned nl = cp::gap_lhs_coords(e0, lambda.data());
    cp::gap_rhs_coords(e1, sigma.data());
    cp::gap_merge(lambda.data(), nl, sigma.data(), e1.segments, merge.data());
    std::vector<bool> steps;
    cp::for_each_gap_triangle(
        merge.data(), nl, [&](cp::GapCorner a, cp::GapCorner, cp::GapCorner) { steps.push_back(!a.rhs); });
    return steps;
}

void check_gap(const CpTableSet& t) {
    for (unsigned s1 = 1; s1 <= t.shapes; ++s1) {
        for (unsigned s0 = 1; s0 <= t.shapes; ++s0) {
            const auto steps = zipper_steps(s0, s1);
            const std::uint32_t* w = t.gap_word + t.gap_offset[(s1 - 1) * t.shapes + s0 - 1];
            INFO("max " << t.max_factor << " pair (T" << s0 << ", T" << s1 << ")");
            REQUIRE(steps.size() == tables::gap_triangle_count(s0, s1));
            unsigned lhs = 0;
            for (unsigned q = 0; q < steps.size(); ++q) {
                const std::uint32_t word = w[q / 16];
                const std::uint32_t below = (word & 0xFFFFu) & ((1u << (q % 16)) - 1u);
                REQUIRE((word >> 16) + static_cast<unsigned>(std::popcount(below)) == lhs);
                REQUIRE(((word >> (q % 16)) & 1u) == (steps[q] ? 1u : 0u));
                lhs += steps[q] ? 1u : 0u;
            }
            if (s1 == 1) { // the fan (R_3, L, R_2): the third rhs step
                unsigned rhs = 0, at = 0;
                for (unsigned q = 0; q < steps.size(); ++q)
                    if (!steps[q] && rhs++ == 2) at = q;
                REQUIRE(t.t1_last_fan[s0 - 1] == at);
            }
        }
    }
}

} // namespace

TEST_CASE("tables: token points equal cp::token_points for every token", "[tables]") {
    check_tokens(ctess::rt::cp_tables_64);
    check_tokens(ctess::rt::cp_tables_256);
}

TEST_CASE("tables: column starts equal cp::column_counts (rule b) for every token pair", "[tables]") {
    check_columns(ctess::rt::cp_tables_64);
    check_columns(ctess::rt::cp_tables_256);
}

TEST_CASE("tables: zipper bits and lhs prefixes equal cp::gap_merge for every token pair", "[tables]") {
    check_gap(ctess::rt::cp_tables_64);
    check_gap(ctess::rt::cp_tables_256);
}

TEST_CASE("tables: the 64 set is the prefix of the 256 set (tokens below 64 are identical)", "[tables]") {
    const CpTableSet& a = ctess::rt::cp_tables_64;
    const CpTableSet& b = ctess::rt::cp_tables_256;
    for (unsigned s = 1; s <= a.shapes; ++s) {
        REQUIRE(a.tokens[s - 1].segments == b.tokens[s - 1].segments);
        for (unsigned i = 0; i + 1 < a.tokens[s - 1].segments; ++i)
            REQUIRE(a.points[a.tokens[s - 1].first_point + i] == b.points[b.tokens[s - 1].first_point + i]);
    }
}
