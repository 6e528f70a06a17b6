// Interior column table builder: per token pair (shape0, shape2) the column starts C_k of the Type 2
// parallelogram (docs/algorithm.md §2.3-2.4, rule (b), the default) and a least-squares quadratic that gives
// the reverse lookups their first guess (docs/algorithm.md §4.4).
//
// The table is split into chunks by shape2 ranges, so that the heavy constant evaluation can run in several
// translation units. Sizes come from a cheap closed pass (the first column with one point); the fill pass
// checks them.
#pragma once
#include <array>
#include <cstdint>

#include "columns.hpp"
#include "line.hpp"
#include "tables_layout.hpp"

namespace ctess::cp::tables {

// The points of every shape token, built once per evaluation and passed by reference.
struct ShapeTracks {
    std::array<std::array<PointTrack, max_segments + 1>, max_token_count> track{};
    std::array<unsigned, max_token_count> segments{};
};

constexpr void fill_shape_tracks(unsigned max_factor, ShapeTracks& out) {
    for (unsigned t = 1; t < token_count(max_factor); ++t)
        out.segments[t] = token_points(t, out.track[t].data()) - 1;
}

// Rule (b) through cp::reach_gaps and cp::row_reaches, the procedural rule's own test (cp_columns.hpp).
constexpr ReachGaps pair_reach_gaps(const ShapeTracks& st, unsigned s0, unsigned s2) {
    return reach_gaps(st.track[s0][st.segments[s0] - 1],
                      cp::detail::clamp_track_e2(s2, st.track[s2].data(), st.segments[s2]));
}

// h: the first column i >= 1 with one point (row 0 already reaches the clamp). R is non-increasing, so every
// later column has one point too.
constexpr unsigned column_head(const ShapeTracks& st, unsigned s0, unsigned s2) {
    const ReachGaps g = pair_reach_gaps(st, s0, s2);
    const unsigned n0 = st.segments[s0];
    const PointTrack* t0 = st.track[s0].data();
    const PointTrack row0 = st.track[s2][0];
    for (unsigned i = 1; i < n0; ++i) {
        const int us = t0[i].start, uf = t0[i].final;
        if (row_reaches(row0, g, us, uf)) return i;
    }
    return n0 - 1;
}

// R_0..R_h of a pair (R_0 = n2), each column's rows found by walking down from the previous column's count:
// rows only shrink with i, and reaching is monotone in k. Returns h. Checked against cp::column_counts for
// every pair by the tests.
constexpr unsigned head_column_counts(const ShapeTracks& st, unsigned s0, unsigned s2, std::uint16_t* rows) {
    const ReachGaps g = pair_reach_gaps(st, s0, s2);
    const unsigned n0 = st.segments[s0];
    const unsigned n2 = st.segments[s2];
    const PointTrack* t0 = st.track[s0].data();
    const PointTrack* t2 = st.track[s2].data();
    rows[0] = static_cast<std::uint16_t>(n2);
    unsigned k = n2 - 1;
    for (unsigned i = 1; i < n0; ++i) {
        const int us = t0[i].start, uf = t0[i].final;
        while (k > 0 && row_reaches(t2[k - 1], g, us, uf)) --k;
        rows[i] = static_cast<std::uint16_t>(k + 1);
        if (k == 0) return i;
    }
    return n0 - 1;
}

// Chunk plan: chunk c holds the pairs with shape2 in [first_shape2(c), first_shape2(c+1)), balanced by the
// number of e2 points (the work and the pool grow with n2).
template <unsigned MaxFactor, unsigned Chunks>
struct ColumnChunkPlan {
    static constexpr unsigned shapes = shape_count(MaxFactor);
    static constexpr std::array<std::uint8_t, Chunks + 1> first_shape2 = [] {
        std::array<std::uint8_t, Chunks + 1> first{};
        unsigned total = 0;
        for (unsigned s = 1; s <= shapes; ++s) total += token_info(s).segments;
        unsigned acc = 0, c = 1;
        first[0] = 1;
        for (unsigned s = 1; s <= shapes && c < Chunks; ++s) {
            acc += token_info(s).segments;
            if (acc * Chunks >= total * c) first[c++] = static_cast<std::uint8_t>(s + 1);
        }
        for (; c <= Chunks; ++c) first[c] = static_cast<std::uint8_t>(shapes + 1);
        return first;
    }();
    // chunk_of[shape index of e2]
    static constexpr std::array<std::uint8_t, shapes> chunk_of = [] {
        std::array<std::uint8_t, shapes> of{};
        for (unsigned c = 0; c < Chunks; ++c)
            for (unsigned s = first_shape2[c]; s < first_shape2[c + 1]; ++s)
                of[s - 1] = static_cast<std::uint8_t>(c);
        return of;
    }();
};

template <unsigned MaxFactor, unsigned Chunks, unsigned Chunk>
struct ColumnChunk {
    using Plan = ColumnChunkPlan<MaxFactor, Chunks>;
    static constexpr unsigned shapes = Plan::shapes;
    static constexpr unsigned first_shape2 = Plan::first_shape2[Chunk];
    static constexpr unsigned last_shape2 = Plan::first_shape2[Chunk + 1];
    static constexpr unsigned pairs = (last_shape2 - first_shape2) * shapes;
    // Pool entries: C_0..C_{h+1} per pair, plus the padding.
    static constexpr unsigned pool_size = [] {
        ShapeTracks st{};
        fill_shape_tracks(MaxFactor, st);
        unsigned total = pool_padding;
        for (unsigned s2 = first_shape2; s2 < last_shape2; ++s2)
            for (unsigned s0 = 1; s0 <= shapes; ++s0) total += column_head(st, s0, s2) + 2;
        return total;
    }();
    static_assert(pool_size <= 65536, "chunk pool offsets must fit u16: use more chunks");
    // Record of pair (s0, s2) = records[(s2 - first_shape2) * shapes + s0 - 1].
    std::array<ColumnRecord, pairs> records{};
    std::array<std::uint16_t, pool_size> pool{};
};

namespace detail {
// Not constexpr on purpose: reaching it during constant evaluation is a compile error naming the cause.
inline void column_table_size_pass_disagrees() {}
} // namespace detail

// Least-squares fit of C_k ~ a k - b k^2 over k = 0..h (through the origin), in double, rounded to float.
constexpr void fit_column_starts(const std::uint16_t* starts, unsigned h, ColumnRecord& rec) {
    if (h < 2) {
        rec.a = static_cast<float>(starts[h]) / static_cast<float>(h);
        rec.b = 0.0f;
        return;
    }
    double s2 = 0, s3 = 0, s4 = 0, t1 = 0, t2 = 0;
    for (unsigned k = 1; k <= h; ++k) {
        const double x = k, c = starts[k];
        s2 += x * x;
        s3 += x * x * x;
        s4 += x * x * x * x;
        t1 += x * c;
        t2 += x * x * c;
    }
    // [s2 -s3; s3 -s4] [a; b] = [t1; t2]
    const double det = s3 * s3 - s2 * s4;
    rec.a = static_cast<float>((s3 * t2 - s4 * t1) / det);
    rec.b = static_cast<float>((s2 * t2 - s3 * t1) / det);
}

template <unsigned MaxFactor, unsigned Chunks, unsigned Chunk>
constexpr ColumnChunk<MaxFactor, Chunks, Chunk> build_column_chunk() {
    using Out = ColumnChunk<MaxFactor, Chunks, Chunk>;
    Out out{};
    ShapeTracks st{};
    fill_shape_tracks(MaxFactor, st);
    std::array<std::uint16_t, max_segments + 1> rows{};
    unsigned next = 0;
    for (unsigned s2 = Out::first_shape2; s2 < Out::last_shape2; ++s2) {
        for (unsigned s0 = 1; s0 <= Out::shapes; ++s0) {
            const unsigned h = head_column_counts(st, s0, s2, rows.data());
            if (h != column_head(st, s0, s2)) detail::column_table_size_pass_disagrees();
            ColumnRecord& rec = out.records[(s2 - Out::first_shape2) * Out::shapes + s0 - 1];
            rec.offset = static_cast<std::uint16_t>(next);
            rec.head = static_cast<std::uint16_t>(h);
            std::uint16_t* c = out.pool.data() + next;
            c[0] = 0;
            for (unsigned k = 0; k < h; ++k) c[k + 1] = static_cast<std::uint16_t>(c[k] + rows[k]);
            c[h + 1] = static_cast<std::uint16_t>(c[h] + 1);
            fit_column_starts(c, h, rec);
            next += h + 2;
        }
    }
    if (next + pool_padding != Out::pool_size) detail::column_table_size_pass_disagrees();
    return out;
}

} // namespace ctess::cp::tables
