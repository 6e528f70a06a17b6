// The clamped-parallelogram (CP) triangle pattern, computed directly from three edge factors
// (docs/algorithm.md §2). This procedural generator is the reference that compile-time tables must match.
//
// Domain: a vertex {u, v} (units of fixed_one = 2^24) is v0 + u(v1 - v0) + v(v2 - v0). e0 = v0->v1 (v = 0),
// e1 = v1->v2 (u + v = 1), e2 = v0->v2 (u = 0); factors f0, f1, f2 belong to e0, e1, e2.
//
// Bad input: factors are clamped to [1, max_factor] (NaN, -inf, zero and negatives give 1; +inf and huge
// values give max_factor), see line_state(). Line states are clamped by clamp_line_state(); max_factor by
// pattern_max_factor(). No input is undefined behaviour.
#pragma once
#include <array>
#include <cstdint>

#include "columns.hpp"
#include "edge_line.hpp"
#include "gap.hpp"
#include "line.hpp"
#include "type1.hpp"
#include <ctess/core/config.hpp>
#include <span>

#include <ctess/core/counts.hpp>
#include <ctess/core/domain_point.hpp>
#include <ctess/core/patch_options.hpp>

namespace ctess::cp {

enum class PatternType : std::uint8_t {
    single,       // Type 0: every factor <= 1, the base triangle
    fan,          // Type 1: f0 <= 2 and f2 <= 2, hexagon fan around P
    parallelogram // Type 2: the clamped parallelogram
};

// The shared PatchOptions (layout: provoking appends copies so every triangle's first index is unique;
// winding in (u, v), cw swaps each triangle's last two indices) and CP's own.
struct PatternOptions : PatchOptions {
    unsigned max_factor = ctess::max_tess_factor; // 64 or 256; factors are clamped to [1, max_factor]
    ColumnRule column_rule = ColumnRule::minimal;
    bool collapse_t0 = true; // merge the coincident vertices of T0 edges, drop the triangles that repeat one
};

// The type follows from the tokens alone (the lerps never change it).
constexpr PatternType pattern_type(LineState s0, LineState s1, LineState s2) {
    if (s0.token == 0 && s1.token == 0 && s2.token == 0) return PatternType::single;
    if (s0.token <= 1 && s2.token <= 1) return PatternType::fan;
    return PatternType::parallelogram;
}

namespace detail {

// Upper bound of unique vertices of a patch: n0 columns of at most n2 points, plus e1.
inline constexpr std::uint32_t max_unique_vertices = max_segments * max_segments + max_segments + 1;

// Collects triangles: drops those that repeat an index (T0 collapse), and in the provoking layout gives a
// triangle whose first vertex already provokes another triangle a fresh copy of it, appended after the unique
// vertices in emission order. Clockwise output swaps the last two indices, so the provoking vertex stays
// first.
struct TriangleSink {
    DomainPoint* vertices = nullptr;
    std::uint32_t* indices = nullptr;
    bool provoking = true;
    bool clockwise = false;
    std::uint32_t unique = 0;
    std::uint32_t copies = 0;
    std::uint32_t triangles = 0;
    std::array<std::uint64_t, (max_unique_vertices + 63) / 64> claimed{};

    constexpr void add(std::uint32_t i0, std::uint32_t i1, std::uint32_t i2) {
        if (i0 == i1 || i1 == i2 || i0 == i2) return;
        if (provoking) {
            const std::uint64_t bit = std::uint64_t{1} << (i0 % 64);
            if ((claimed[i0 / 64] & bit) != 0) {
                const std::uint32_t copy = unique + copies++;
                if (vertices != nullptr) vertices[copy] = vertices[i0];
                i0 = copy;
            } else {
                claimed[i0 / 64] |= bit;
            }
        }
        if (indices != nullptr) {
            indices[3 * triangles] = i0;
            indices[3 * triangles + 1] = clockwise ? i2 : i1;
            indices[3 * triangles + 2] = clockwise ? i1 : i2;
        }
        ++triangles;
    }
    constexpr Counts counts() const { return {unique + copies, triangles}; }
};

constexpr DomainPoint e1_point(std::uint32_t s) {
    return {fixed_one - s, s};
}

constexpr Counts single_pattern(TriangleSink& sink) {
    sink.unique = 3;
    if (sink.vertices != nullptr) {
        sink.vertices[0] = {0, 0};
        sink.vertices[1] = {fixed_one, 0};
        sink.vertices[2] = {0, fixed_one};
    }
    sink.add(0, 1, 2);
    return sink.counts();
}

constexpr Counts fan_pattern(const EdgeLine& e0, const EdgeLine& e1, const EdgeLine& e2, bool collapse,
                             TriangleSink& sink) {
    const Type1Slots s{e1.segments};
    const bool c0 = collapse && e0.token == 0;
    const bool c1 = collapse && e1.token == 0;
    const bool c2 = collapse && e2.token == 0;
    std::array<std::uint32_t, max_segments + 8> target{};
    for (unsigned r = 0; r < s.count(); ++r) target[r] = r;
    if (c1) {
        target[s.e1(1)] = s.e1(0);
        target[s.e1(2)] = s.e1(3);
    }
    if (c2) {
        target[s.a2()] = s.v0;
        target[s.b2()] = s.e1(s.n1);
    }
    if (c0) {
        target[s.a0] = s.v0;
        target[s.b0] = s.e1(0);
    }
    if (c0 && c2) target[s.center()] = s.v0;

    std::array<DomainPoint, max_segments + 8> pos{};
    pos[s.v0] = {0, 0};
    pos[s.a0] = {e0.pos[1], 0};
    pos[s.b0] = {e0.pos[2], 0};
    for (unsigned b = 0; b <= s.n1; ++b) pos[s.e1(b)] = e1_point(e1.pos[b]);
    pos[s.b2()] = {0, e2.pos[2]};
    pos[s.a2()] = {0, e2.pos[1]};
    pos[s.center()] = type1_center(e0.t16, e2.t16);

    std::array<std::uint32_t, max_segments + 8> index{};
    std::uint32_t kept = 0;
    for (unsigned r = 0; r < s.count(); ++r) {
        if (target[r] != r) continue;
        if (sink.vertices != nullptr) sink.vertices[kept] = pos[r];
        index[r] = kept++;
    }
    for (unsigned r = 0; r < s.count(); ++r) index[r] = index[target[r]];
    sink.unique = kept;
    for_each_type1_triangle(
        s, [&](unsigned a, unsigned b, unsigned c) { sink.add(index[a], index[b], index[c]); });
    return sink.counts();
}

constexpr Counts parallelogram_pattern(const EdgeLine& e0, const EdgeLine& e1, const EdgeLine& e2,
                                       ColumnRule rule, bool collapse, TriangleSink& sink) {
    ColumnCounts rows{};
    const unsigned n0 = column_counts(e0.token, e2.token, rule, rows.data());
    const unsigned n1 = e1.segments;
    const std::uint32_t clamp = clamp_line(e0, e2);
    const bool c0 = collapse && e0.token == 0;
    const bool c1 = collapse && e1.token == 0;
    const bool c2 = collapse && e2.token == 0;

    // Column i's first output index, after the collapse removed merged points.
    std::array<std::uint32_t, max_segments + 1> offset{};
    for (unsigned i = 0; i < n0; ++i) {
        const unsigned kept = c2 ? 1u : (c0 && (i == 1 || i == 2)) ? 0u : rows[i];
        offset[i + 1] = offset[i] + kept;
    }
    const std::uint32_t e1_offset = offset[n0];
    auto e1_index = [&](unsigned b) -> std::uint32_t {
        if (c1) return e1_offset + (b <= 1 ? 0u : 1u); // A1 -> v1, B1 -> v2
        return e1_offset + b;
    };
    auto column_index = [&](unsigned i, unsigned j) -> std::uint32_t {
        if (c2) {
            if (i == 0 && j == 2) return e1_index(n1); // B2 -> v2
            j = 0;                                     // A2 -> v0; column points -> their e0 point
        }
        if (c0) {
            if (i == 2) return e1_index(0); // B0 -> v1
            if (i == 1) i = 0;              // A0's column -> column 0
        }
        return offset[i] + j;
    };
    auto kept_point = [&](unsigned i, unsigned j) {
        if (c2) return j == 0;
        if (c0) return i != 1 && i != 2;
        return true;
    };
    sink.unique = e1_offset + (c1 ? 2u : n1 + 1);

    if (sink.vertices != nullptr) {
        for (unsigned i = 0; i < n0; ++i) {
            const std::uint32_t u = i == 0 ? 0u : e0.pos[i];
            const std::uint32_t top = i == 0 ? fixed_one : column_clamp(clamp, u);
            for (unsigned j = 0; j < rows[i]; ++j) {
                if (!kept_point(i, j)) continue;
                const std::uint32_t v = e2.pos[j] < top ? e2.pos[j] : top;
                sink.vertices[column_index(i, j)] = {u, v};
            }
        }
        for (unsigned b = 0; b <= n1; ++b) {
            if (c1 && (b == 1 || b == 2)) continue;
            sink.vertices[e1_index(b)] = e1_point(e1.pos[b]);
        }
    }

    // Strips between columns i and i+1 (|B| <= |A|): cells along u + v = const, then a fan to B's top.
    for (unsigned i = 0; i + 1 < n0; ++i) {
        const unsigned na = rows[i];
        const unsigned nb = rows[i + 1] < na ? rows[i + 1] : na;
        for (unsigned j = 0; j + 1 < nb; ++j) {
            sink.add(column_index(i, j), column_index(i + 1, j), column_index(i, j + 1));
            sink.add(column_index(i + 1, j), column_index(i + 1, j + 1), column_index(i, j + 1));
        }
        for (unsigned j = nb - 1; j + 1 < na; ++j) {
            sink.add(column_index(i, j), column_index(i + 1, nb - 1), column_index(i, j + 1));
        }
    }

    // Gap zipper between the column tops (lhs, from column n0-1 down to column 0) and e1.
    std::array<std::uint16_t, max_segments + 1> lambda{};
    std::array<std::uint16_t, max_segments + 1> sigma{};
    std::array<std::uint16_t, max_segments + 1> merge{};
    const unsigned nl = gap_lhs_coords(e0, lambda.data());
    gap_rhs_coords(e1, sigma.data());
    gap_merge(lambda.data(), nl, sigma.data(), n1, merge.data());
    auto corner_index = [&](GapCorner c) -> std::uint32_t {
        if (c.rhs) return e1_index(c.index);
        const unsigned i = n0 - 1 - c.index;
        return column_index(i, rows[i] - 1u);
    };
    for_each_gap_triangle(merge.data(), nl, [&](GapCorner a, GapCorner b, GapCorner c) {
        sink.add(corner_index(a), corner_index(b), corner_index(c));
    });
    return sink.counts();
}

} // namespace detail

// Writes the pattern of three line states. Outputs first, then inputs, then options (patch_options.hpp).
// vertices: Counts::vertices entries, indices: 3 per triangle, counter-clockwise in (u, v) (opt.winding),
// provoking vertex first.
// Vertex order: Type 0: v0, v1, v2. Type 1: v0, A0, B0, e1 points from v1 to v2, B2, A2, P. Type 2: column 0
// (e2 points from v0), column 1, ..., column n0-1 (each from its e0 point up), then e1 points from v1 to v2.
// The T0 collapse removes merged vertices from that order; the provoking layout appends copies after it.
namespace detail {
// The fill behind tessellate(): unchecked pointers, null = count only.
constexpr Counts tessellate_into(DomainPoint* vertices, std::uint32_t* indices, LineState s0, LineState s1,
                                 LineState s2, const PatternOptions& opt) {
    const unsigned max_factor = pattern_max_factor(opt.max_factor);
    s0 = clamp_line_state(s0, max_factor);
    s1 = clamp_line_state(s1, max_factor);
    s2 = clamp_line_state(s2, max_factor);
    detail::TriangleSink sink;
    sink.vertices = vertices;
    sink.indices = indices;
    sink.provoking = opt.layout == Layout::provoking;
    sink.clockwise = opt.winding == Winding::cw;
    const PatternType type = pattern_type(s0, s1, s2);
    if (type == PatternType::single) return detail::single_pattern(sink);
    const EdgeLine e0 = make_edge_line(s0);
    const EdgeLine e1 = make_edge_line(s1);
    const EdgeLine e2 = make_edge_line(s2);
    if (type == PatternType::fan) return detail::fan_pattern(e0, e1, e2, opt.collapse_t0, sink);
    return detail::parallelogram_pattern(e0, e1, e2, opt.column_rule, opt.collapse_t0, sink);
}

constexpr Counts tessellate_into(DomainPoint* vertices, std::uint32_t* indices, float f0, float f1, float f2,
                                 const PatternOptions& opt) {
    const unsigned max_factor = pattern_max_factor(opt.max_factor);
    return tessellate_into(vertices, indices, line_state(f0, max_factor), line_state(f1, max_factor),
                           line_state(f2, max_factor), opt);
}
} // namespace detail

// Count, then fill (docs/api.md, "Sized outputs"): returns the pattern's counts and writes it only when both
// spans are large enough; with a shorter span (empty spans: count only) nothing is written.
constexpr Counts tessellate(std::span<DomainPoint> vertices, std::span<std::uint32_t> indices, LineState s0,
                            LineState s1, LineState s2, const PatternOptions& opt = {}) {
    const Counts n = detail::tessellate_into(nullptr, nullptr, s0, s1, s2, opt);
    if (!fits(n, vertices.size(), indices.size())) return n;
    return detail::tessellate_into(vertices.data(), indices.data(), s0, s1, s2, opt);
}

// line_state() of each factor (clamped to [1, max_factor]), then the pattern above.
constexpr Counts tessellate(std::span<DomainPoint> vertices, std::span<std::uint32_t> indices, float f0,
                            float f1, float f2, const PatternOptions& opt = {}) {
    const unsigned max_factor = pattern_max_factor(opt.max_factor);
    return tessellate(vertices, indices, line_state(f0, max_factor), line_state(f1, max_factor),
                      line_state(f2, max_factor), opt);
}

constexpr Counts pattern_counts(float f0, float f1, float f2, const PatternOptions& opt = {}) {
    return detail::tessellate_into(nullptr, nullptr, f0, f1, f2, opt);
}

// Upper bound of the counts over every input and every option, for sizing buffers: the top token on all
// three edges is the largest pattern (the triforce, checked exhaustively by the tests), with M^2 triangles
// and M^2 + 2 vertices in the provoking layout ((M+1)(M+2)/2 unique plus one copy per doubled interior
// point).
constexpr Counts max_pattern_counts(unsigned max_factor) {
    const std::uint32_t m = pattern_max_factor(max_factor);
    return {m * m + 2, m * m};
}

} // namespace ctess::cp
