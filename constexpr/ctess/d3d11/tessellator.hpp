// The D3D11 fixed-function tessellator (docs/algorithm.md §5), bit-exact with Microsoft's reference
// CHWTessellator, for the triangle, quad and isoline domains.
//
// Points are (u, v) in 16.16 (for triangles w = 1 - u - v) in the reference's output order; indices are in
// the reference's order, 3 per triangle (TRIANGLE_CW or TRIANGLE_CCW) or 2 per isoline segment. Arguments:
// outputs, then factors, then options, as everywhere (patch_options.hpp). Pass null outputs to get the counts
// only (ctess::Counts for triangles, IsolineCounts for segments); otherwise size the buffers with the
// returned counts or the max_*_counts.
//
// Bad factors (see d3d11_factors.hpp): an edge factor (isoline: density or detail) that is NaN, zero,
// negative or -inf culls the patch, which returns {0, 0}; every other value, including +inf, huge and
// denormal ones, is clamped to the partitioning's range; a NaN or non-positive inside factor takes the lower
// bound.
#pragma once
#include <array>
#include <cstdint>
#include <span>

#include "edge.hpp"
#include "factors.hpp"
#include "stitch.hpp"
#include <ctess/core/counts.hpp>
#include <ctess/core/domain_point.hpp>

namespace ctess::d3d11 {

struct TessOptions {
    Partitioning partitioning = Partitioning::integer;
    Winding winding = default_winding;
};

// The isoline domain's counts: points and line segments (2 indices each).
struct IsolineCounts {
    std::uint32_t vertices = 0;
    std::uint32_t segments = 0;
    constexpr std::uint32_t index_count() const { return 2 * segments; }
    friend constexpr bool operator==(const IsolineCounts&, const IsolineCounts&) = default;
};

// Buffer sizes that fit any factors: factor 64 everywhere (65 points per edge).
inline constexpr Counts max_tri_counts = {3169, 6144};
inline constexpr Counts max_quad_counts = {65 * 65, 2 * 64 * 64};
inline constexpr IsolineCounts max_isoline_counts = {65 * 64, 64 * 64};

namespace detail {

struct PointWriter {
    Point* out = nullptr;
    std::uint32_t count = 0;
    constexpr void add(std::uint32_t u, std::uint32_t v) {
        if (out != nullptr) out[count] = {u, v};
        ++count;
    }
};

constexpr std::uint32_t max_u32(std::uint32_t a, std::uint32_t b) {
    return a > b ? a : b;
}
constexpr std::uint32_t min_u32(std::uint32_t a, std::uint32_t b) {
    return a < b ? a : b;
}

// Inside rows have at least 3 (even) or 4 (odd) points, which allows degenerate transitions for inside 1.
constexpr std::uint32_t inside_point_count(FixedFactor f) {
    return max_u32(point_count(f), f.parity == Parity::odd ? 4 : 3);
}

// Both domains start at the first point of the outer edge and spiral inward; index q along an edge runs
// against the 1-D parameter on the edges that the ring walks backwards.
constexpr std::uint32_t edge_param_index(bool reversed, std::uint32_t first, std::uint32_t last,
                                         std::uint32_t p) {
    return reversed ? last - (p - first) : p;
}

} // namespace detail

// ---- triangle domain ----

// factors: {Ueq0, Veq0, Weq0, inside}.
namespace detail {
constexpr Counts tessellate_tri_into(Point* points, std::uint32_t* indices,
                                     const std::array<float, 4>& factors, const TessOptions& options) {
    const Partitioning mode = options.partitioning;
    for (unsigned e = 0; e < 3; ++e)
        if (culls(factors[e])) return {};

    const float clamped_edges[3] = {clamped_edge_float(mode, factors[0]),
                                    clamped_edge_float(mode, factors[1]),
                                    clamped_edge_float(mode, factors[2])};
    const FixedFactor edge[3] = {process_edge_factor(mode, factors[0]), process_edge_factor(mode, factors[1]),
                                 process_edge_factor(mode, factors[2])};
    const FixedFactor inside =
        process_inside_factor(mode, factors[3], inside_lower_bound(mode, clamped_edges));

    detail::PointWriter pw{points};
    TriangleWriter tw{indices, options.winding};

    if (mode != Partitioning::fractional_even && inside.value == fixed_one && edge[0].value == fixed_one &&
        edge[1].value == fixed_one && edge[2].value == fixed_one) {
        pw.add(0, fixed_one); // V
        pw.add(0, 0);         // W
        pw.add(fixed_one, 0); // U
        tw.add(0, 1, 2);
        return {pw.count, tw.count / 3};
    }

    const EdgeContext edge_ctx[3] = {edge_context(edge[0]), edge_context(edge[1]), edge_context(edge[2])};
    const EdgeContext inside_ctx = edge_context(inside);
    const std::uint32_t edge_points_n[3] = {point_count(edge[0]), point_count(edge[1]), point_count(edge[2])};
    const std::uint32_t ni = detail::inside_point_count(inside);
    const bool odd_inside = inside.parity == Parity::odd;

    // Counts first: the outer ring shares its corners; the inner rings hold 3R^2 (odd) or 3R(R+1)+1 points.
    const std::uint32_t rings = (ni >> 1) - 1;
    const std::uint32_t outer_total = edge_points_n[0] + edge_points_n[1] + edge_points_n[2] - 3;
    const std::uint32_t point_total =
        outer_total + (odd_inside ? 3 * rings * rings : 3 * rings * (rings + 1) + 1);
    std::uint32_t tri_total = odd_inside ? 1 : 0;
    {
        std::uint32_t outer_n[3] = {edge_points_n[0], edge_points_n[1], edge_points_n[2]};
        for (std::uint32_t r = 1; r < ((ni + 1) >> 1); ++r) {
            for (auto& n_out : outer_n) {
                tri_total += ni - 2 * r + n_out - 2;
                n_out = ni - 2 * r;
            }
        }
    }
    if (points == nullptr && indices == nullptr) return {point_total, tri_total};

    if (points != nullptr) {
        // Outer edges: Ueq0 from V to W, Veq0 from W to U, Weq0 from U to V; each edge's last point is the
        // next edge's first.
        for (unsigned e = 0; e < 3; ++e) {
            const std::uint32_t last = edge_points_n[e] - 1;
            for (std::uint32_t p = 0; p < last; ++p) {
                const std::uint32_t loc =
                    place_point(edge_ctx[e], detail::edge_param_index(e != 1, 0, last, p));
                if (e == 0)
                    pw.add(0, loc);
                else if (e == 1)
                    pw.add(loc, 0);
                else
                    pw.add(loc, fixed_one - loc);
            }
        }
        // Inner rings, in the same edge order. Inside positions shrink by 2/3 toward the centre.
        for (std::uint32_t r = 1; r < (ni >> 1); ++r) {
            const std::uint32_t first = r;
            const std::uint32_t last = ni - 1 - r;
            const std::uint32_t perp = (place_point(inside_ctx, r) * 0xAAAAu + fixed_half) >> 16;
            const std::uint32_t shift = (perp + 1) / 2;
            for (unsigned e = 0; e < 3; ++e) {
                for (std::uint32_t p = first; p < last; ++p) {
                    const std::uint32_t loc =
                        place_point(inside_ctx, detail::edge_param_index(e != 1, first, last, p));
                    const std::uint32_t a = loc - shift;
                    if (e == 0)
                        pw.add(perp, a);
                    else if (e == 1)
                        pw.add(a, perp);
                    else
                        pw.add(a, fixed_one - a - perp);
                }
            }
        }
        if (!odd_inside) pw.add(0x5555, 0x5555); // the centre
    }

    if (indices != nullptr) {
        std::uint32_t outer_n[3] = {edge_points_n[0], edge_points_n[1], edge_points_n[2]};
        std::uint32_t inner_base = outer_total;
        std::uint32_t outer_base = 0;
        for (std::uint32_t r = 1; r < ((ni + 1) >> 1); ++r) {
            const std::uint32_t n_in = ni - 2 * r;
            const std::uint32_t ring_inner_first = inner_base;
            const std::uint32_t ring_outer_first = outer_base;
            for (unsigned e = 0; e < 3; ++e) {
                const bool closing = e == 2; // its last points are the ring's first ones
                const IndexRow in_row =
                    closing ? closing_row(inner_base, n_in, ring_inner_first) : forward_row(inner_base);
                const IndexRow out_row =
                    closing ? closing_row(outer_base, outer_n[e], ring_outer_first) : forward_row(outer_base);
                if (r == 1) {
                    stitch_transition(tw, in_row, inside_ctx.half_points, inside.parity, out_row,
                                      edge_ctx[e].half_points, edge[e].parity);
                } else {
                    stitch_regular(tw, true, Diagonals::mirrored, n_in, in_row, out_row);
                }
                outer_base += outer_n[e] - 1;
                inner_base += n_in - 1;
                outer_n[e] = n_in;
            }
        }
        if (odd_inside) tw.add(outer_base, outer_base + 1, outer_base + 2); // the centre triangle
    }
    return {point_total, tri_total};
}

} // namespace detail

// ---- quad domain ----

// factors: {Ueq0, Veq0, Ueq1, Veq1, insideU, insideV}.
namespace detail {
constexpr Counts tessellate_quad_into(Point* points, std::uint32_t* indices,
                                      const std::array<float, 6>& factors, const TessOptions& options) {
    const Partitioning mode = options.partitioning;
    for (unsigned e = 0; e < 4; ++e)
        if (culls(factors[e])) return {};

    // The odd picture-frame test sees the clamped edges and the raw inside factors.
    const float frame_test[6] = {clamped_edge_float(mode, factors[0]),
                                 clamped_edge_float(mode, factors[1]),
                                 clamped_edge_float(mode, factors[2]),
                                 clamped_edge_float(mode, factors[3]),
                                 factors[4],
                                 factors[5]};
    const float inside_lo = inside_lower_bound(mode, frame_test);
    FixedFactor edge[4] = {};
    for (unsigned e = 0; e < 4; ++e) edge[e] = process_edge_factor(mode, factors[e]);
    const FixedFactor inside[2] = {process_inside_factor(mode, factors[4], inside_lo),
                                   process_inside_factor(mode, factors[5], inside_lo)};

    detail::PointWriter pw{points};
    TriangleWriter tw{indices, options.winding};

    if (mode != Partitioning::fractional_even && inside[0].value == fixed_one &&
        inside[1].value == fixed_one && edge[0].value == fixed_one && edge[1].value == fixed_one &&
        edge[2].value == fixed_one && edge[3].value == fixed_one) {
        pw.add(0, 0);
        pw.add(fixed_one, 0);
        pw.add(fixed_one, fixed_one);
        pw.add(0, fixed_one);
        tw.add(0, 1, 3);
        tw.add(1, 2, 3);
        return {pw.count, tw.count / 3};
    }

    EdgeContext edge_ctx[4] = {};
    std::uint32_t edge_points_n[4] = {};
    for (unsigned e = 0; e < 4; ++e) {
        edge_ctx[e] = edge_context(edge[e]);
        edge_points_n[e] = point_count(edge[e]);
    }
    const EdgeContext inside_ctx[2] = {edge_context(inside[0]), edge_context(inside[1])};
    const std::uint32_t ni[2] = {detail::inside_point_count(inside[0]),
                                 detail::inside_point_count(inside[1])};
    const bool even_u = inside[0].parity == Parity::even;
    const bool even_v = inside[1].parity == Parity::even;

    const std::uint32_t outer_total =
        edge_points_n[0] + edge_points_n[1] + edge_points_n[2] + edge_points_n[3] - 4;
    const std::uint32_t point_total = outer_total + (ni[0] - 2) * (ni[1] - 2);

    // Rings run while both axes have rows left; an even axis ends in a degenerate ring (a row of points), and
    // the sides stitched to that row walk it backwards or wrap differently.
    const std::uint32_t rows_to_centre[2] = {(ni[0] + 1) >> 1, (ni[1] + 1) >> 1};
    const std::uint32_t ring_end = detail::min_u32(rows_to_centre[0], rows_to_centre[1]);
    // Index by the axis a side runs along: its inner row collapses when the other axis does.
    const std::uint32_t degenerate_ring[2] = {even_v ? rows_to_centre[1] - 1 : IndexRow::none,
                                              even_u ? rows_to_centre[0] - 1 : IndexRow::none};
    // The centre strip left when the smaller axis is odd: its quad count.
    const bool strip_along_u = ni[0] > ni[1] && !even_v;
    const bool strip_along_v = !(ni[0] > ni[1]) && !even_u;
    std::uint32_t strip_quads = 0;
    if (strip_along_u) strip_quads = ((ni[0] >> 1) - (ni[1] >> 1)) * 2 + (even_u ? 2 : 1);
    if (strip_along_v) strip_quads = ((ni[1] >> 1) - (ni[0] >> 1)) * 2 + (even_v ? 2 : 1);

    std::uint32_t tri_total = 2 * strip_quads;
    {
        std::uint32_t outer_n[4] = {edge_points_n[0], edge_points_n[1], edge_points_n[2], edge_points_n[3]};
        for (std::uint32_t r = 1; r < ring_end; ++r) {
            for (unsigned e = 0; e < 4; ++e) {
                const std::uint32_t n_in = ni[(e + 1) & 1] - 2 * r;
                tri_total += n_in + outer_n[e] - 2;
                outer_n[e] = n_in;
            }
        }
    }
    if (points == nullptr && indices == nullptr) return {point_total, tri_total};

    if (points != nullptr) {
        // Outer edges clockwise from (0, 1): Ueq0 down, Veq0 right, Ueq1 up, Veq1 left.
        for (unsigned e = 0; e < 4; ++e) {
            const std::uint32_t last = edge_points_n[e] - 1;
            for (std::uint32_t p = 0; p < last; ++p) {
                const bool reversed = e == 0 || e == 3;
                const std::uint32_t loc =
                    place_point(edge_ctx[e], detail::edge_param_index(reversed, 0, last, p));
                if (e & 1)
                    pw.add(loc, e == 3 ? fixed_one : 0);
                else
                    pw.add(e == 2 ? fixed_one : 0, loc);
            }
        }
        // Inner rings, same order, spiralling inward.
        const std::uint32_t point_rings = detail::min_u32(ni[0], ni[1]) >> 1;
        for (std::uint32_t r = 1; r < point_rings; ++r) {
            const std::uint32_t last[2] = {ni[0] - 1 - r, ni[1] - 1 - r};
            for (unsigned e = 0; e < 4; ++e) {
                const unsigned across = e & 1;      // axis of the constant coordinate
                const unsigned along = (e + 1) & 1; // axis the side runs along
                const std::uint32_t perp = place_point(inside_ctx[across], e < 2 ? r : last[across]);
                const bool reversed = e == 0 || e == 3;
                for (std::uint32_t p = r; p < last[along]; ++p) {
                    const std::uint32_t loc =
                        place_point(inside_ctx[along], detail::edge_param_index(reversed, r, last[along], p));
                    if (along == 1)
                        pw.add(perp, loc);
                    else
                        pw.add(loc, perp);
                }
            }
        }
        // An even smaller axis leaves a middle row of points instead of a last ring.
        if (ni[0] > ni[1] && even_v) {
            for (std::uint32_t p = point_rings; p <= ni[0] - 1 - point_rings; ++p)
                pw.add(place_point(inside_ctx[0], p), fixed_half);
        } else if (!(ni[0] > ni[1]) && even_u) {
            for (std::uint32_t p = ni[1] - point_rings; p-- > point_rings;) // v descending
                pw.add(fixed_half, place_point(inside_ctx[1], p));
        }
    }

    if (indices != nullptr) {
        std::uint32_t outer_n[4] = {edge_points_n[0], edge_points_n[1], edge_points_n[2], edge_points_n[3]};
        std::uint32_t inner_base = outer_total;
        std::uint32_t outer_base = 0;
        for (std::uint32_t r = 1; r < ring_end; ++r) {
            const std::uint32_t ring_inner_first = inner_base;
            const std::uint32_t ring_outer_first = outer_base;
            for (unsigned e = 0; e < 4; ++e) {
                const unsigned along = (e + 1) & 1;
                const std::uint32_t n_in = ni[along] - 2 * r;
                const bool degenerate = r == degenerate_ring[along];
                IndexRow in_row = forward_row(inner_base);
                IndexRow out_row = forward_row(outer_base);
                if (e == 3) {
                    out_row = closing_row(outer_base, outer_n[e], ring_outer_first);
                    in_row = degenerate ? backward_row(inner_base)
                                        : closing_row(inner_base, n_in, ring_inner_first);
                } else if (e == 2 && degenerate) {
                    in_row = backward_row(inner_base);
                }
                if (r == 1) {
                    stitch_transition(tw, in_row, inside_ctx[along].half_points, inside[along].parity,
                                      out_row, edge_ctx[e].half_points, edge[e].parity);
                } else {
                    stitch_regular(tw, true, Diagonals::mirrored, n_in, in_row, out_row);
                }
                outer_base += outer_n[e] - 1;
                inner_base = (e == 2 && degenerate) ? inner_base - (n_in - 1) : inner_base + (n_in - 1);
                outer_n[e] = n_in;
            }
        }
        // Odd smaller axis: a strip of quads along the longer axis, between the innermost ring's two long
        // sides. The inner row runs backwards and, along u, starts at the ring's first point.
        if (strip_along_u) {
            const IndexRow in_row{outer_base + 2 * strip_quads + 2, true, 0, outer_base};
            stitch_regular(tw, false, Diagonals::inside_to_outside, strip_quads + 1, in_row,
                           forward_row(outer_base + 1));
        } else if (strip_along_v) {
            stitch_regular(
                tw, false, even_v ? Diagonals::inside_to_outside : Diagonals::inside_to_outside_except_middle,
                strip_quads + 1, backward_row(outer_base + 2 * strip_quads + 1), forward_row(outer_base));
        }
    }
    return {point_total, tri_total};
}

} // namespace detail

// ---- isoline domain ----

// factors: {density, detail}. Density is always integer (rounded up, [1, 64]); lines sit at v = 0 .. < 1
// (none at v = 1); detail follows the partitioning. Segments connect consecutive points of each line.
namespace detail {
constexpr IsolineCounts tessellate_isoline_into(Point* points, std::uint32_t* indices,
                                                const std::array<float, 2>& factors,
                                                const TessOptions& options) {
    if (culls(factors[0]) || culls(factors[1])) return {};
    const FixedFactor density = process_edge_factor(Partitioning::integer, factors[0]);
    const FixedFactor detail_f = process_edge_factor(options.partitioning, factors[1]);
    const std::uint32_t lines = point_count(density) - 1;
    const std::uint32_t per_line = point_count(detail_f);
    const IsolineCounts counts{lines * per_line, lines * (per_line - 1)};
    if (points != nullptr) {
        const EdgeContext density_ctx = edge_context(density);
        const EdgeContext detail_ctx = edge_context(detail_f);
        detail::PointWriter pw{points};
        for (std::uint32_t l = 0; l < lines; ++l) {
            const std::uint32_t v = place_point(density_ctx, l);
            for (std::uint32_t p = 0; p < per_line; ++p) pw.add(place_point(detail_ctx, p), v);
        }
    }
    if (indices != nullptr) {
        std::uint32_t k = 0;
        for (std::uint32_t l = 0; l < lines; ++l) {
            for (std::uint32_t p = 1; p < per_line; ++p) {
                indices[k++] = l * per_line + p - 1;
                indices[k++] = l * per_line + p;
            }
        }
    }
    return counts;
}

} // namespace detail

// Count, then fill (docs/api.md, "Sized outputs"): each returns the pattern's counts and writes it only when
// both spans are large enough; with a shorter span (empty spans: count only) nothing is written.
// Triangle factors: {Ueq0, Veq0, Weq0, inside}.
constexpr Counts tessellate_tri(std::span<Point> points, std::span<std::uint32_t> indices,
                                const std::array<float, 4>& factors, const TessOptions& options = {}) {
    const Counts n = detail::tessellate_tri_into(nullptr, nullptr, factors, options);
    if (!fits(n, points.size(), indices.size())) return n;
    return detail::tessellate_tri_into(points.data(), indices.data(), factors, options);
}
// Quad factors: {Ueq0, Veq0, Ueq1, Veq1, insideU, insideV}.
constexpr Counts tessellate_quad(std::span<Point> points, std::span<std::uint32_t> indices,
                                 const std::array<float, 6>& factors, const TessOptions& options = {}) {
    const Counts n = detail::tessellate_quad_into(nullptr, nullptr, factors, options);
    if (!fits(n, points.size(), indices.size())) return n;
    return detail::tessellate_quad_into(points.data(), indices.data(), factors, options);
}
// Isoline factors: {density, detail}; 2 indices per segment.
constexpr IsolineCounts tessellate_isoline(std::span<Point> points, std::span<std::uint32_t> indices,
                                           const std::array<float, 2>& factors,
                                           const TessOptions& options = {}) {
    const IsolineCounts n = detail::tessellate_isoline_into(nullptr, nullptr, factors, options);
    if (n.vertices > points.size() || n.index_count() > indices.size()) return n;
    return detail::tessellate_isoline_into(points.data(), indices.data(), factors, options);
}

} // namespace ctess::d3d11
