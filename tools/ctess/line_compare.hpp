// The comparison line modes of Hable 2026's viewer, mirrored so that shared edges never crack. They exist
// to show, next to the CP line, why the CP line was chosen (docs/algorithm.md §1.4):
//   pow2_subdivision: uniform 2^ceil(log2 f) segments; pops at every power of two.
//   one_at_a_time:    subdivision points inserted one per half at a time, ascending from the edge ends, the
//                     newest ("pivot") lerped in from the lower end of its parent segment.
//   even_spacing:     D3D-style: the same segment count, all segments of length 1/f except the pivot's.
// Positions are in units of 2^-24 (cp::fixed_one); factors are clamped to [1, max] like the CP line.
#pragma once
#include <cstdint>

#include <ctess/core/numeric.hpp>
#include <ctess/cp/line.hpp>

namespace ctess::line_compare {

inline constexpr std::uint32_t fixed_one = cp::fixed_one;
inline constexpr std::uint32_t half = fixed_one / 2;

// Progress through the octave (2^k, 2^(k+1)] of a clamped 16.16 factor: k, the count c of new points per half
// that are fully in, and the pivot lerp t16 in (0, 65536]. k = 0 is the 1 -> 2 slide from both endpoints.
struct OctaveProgress {
    unsigned k = 0;
    std::uint32_t full = 0;
    std::uint32_t t16 = 0;
};

constexpr OctaveProgress octave_progress(std::uint32_t f16) {
    if (f16 <= (1u << 16)) return {0, 0, 0};
    unsigned k = 0;
    while ((std::uint32_t{2} << (k + 16)) < f16) ++k; // f in (2^k, 2^(k+1)]
    const std::uint32_t lo = std::uint32_t{1} << (k + 16);
    if (k == 0) return {0, 0, f16 - lo};
    // Per half, the progress is (f - 2^k) / 2 new points.
    const auto x16 = static_cast<std::uint32_t>(shift_round_half_even(f16 - lo, 1));
    const std::uint32_t full = (x16 == 0) ? 0 : (x16 - 1) >> 16; // ceil(x) - 1
    return {k, full, x16 - (full << 16)};
}

// Writes the mirrored upper half of a lower half [0 .. midpoint] of `count` points (midpoint included).
constexpr unsigned mirror_upper_half(std::uint32_t* out, unsigned count, bool midpoint_shared) {
    unsigned n = count;
    for (unsigned i = midpoint_shared ? count - 1 : count; i-- > 0;) out[n++] = fixed_one - out[i];
    return n;
}

constexpr unsigned pow2_subdivision(float f, unsigned max_factor, std::uint32_t* out) {
    const std::uint32_t f16 = cp::clamp_factor_16_16(f, max_factor);
    std::uint32_t n = 1;
    while ((n << 16) < f16) n <<= 1;
    for (std::uint32_t i = 0; i <= n; ++i) out[i] = i * (fixed_one / n);
    return n + 1;
}

constexpr unsigned one_at_a_time(float f, unsigned max_factor, std::uint32_t* out) {
    const std::uint32_t f16 = cp::clamp_factor_16_16(f, max_factor);
    if (f16 <= (1u << 16)) {
        out[0] = 0;
        out[1] = fixed_one;
        return 2;
    }
    const OctaveProgress p = octave_progress(f16);
    if (p.k == 0) { // two points slide in from the endpoints and meet at the midpoint
        out[0] = 0;
        out[1] = p.t16 << 7;
        return mirror_upper_half(out, 2, false);
    }
    const std::uint32_t seg = fixed_one >> p.k; // old segment length
    const std::uint32_t old_half = 1u << (p.k - 1);
    unsigned n = 0;
    for (std::uint32_t m = 0; m < old_half; ++m) {
        out[n++] = m * seg;
        if (m < p.full) out[n++] = m * seg + seg / 2;
        if (m == p.full) out[n++] = m * seg + (p.t16 << (7 - p.k)); // (seg/2) * t16 / 65536, exact
    }
    out[n++] = half;
    return mirror_upper_half(out, n, true);
}

constexpr unsigned even_spacing(float f, unsigned max_factor, std::uint32_t* out) {
    const std::uint32_t f16 = cp::clamp_factor_16_16(f, max_factor);
    const OctaveProgress p = octave_progress(f16);
    if (f16 <= (1u << 16) || p.k == 0) return one_at_a_time(f, max_factor, out);
    // Segment i of the lower half has length 1/f, except segment 2*full (the pivot's), of length t/f.
    const std::uint32_t segments = (1u << (p.k - 1)) + p.full + 1; // per half
    unsigned n = 0;
    for (std::uint32_t i = 0; i < segments; ++i) {
        std::uint64_t units16 = std::uint64_t{i} << 16; // i segments, in 1/65536 of a full segment
        if (i > 2 * p.full) units16 = (std::uint64_t{i - 1} << 16) + p.t16;
        out[n++] = static_cast<std::uint32_t>(((units16 << 24) + f16 / 2) / f16);
    }
    out[n++] = half;
    return mirror_upper_half(out, n, true);
}

} // namespace ctess::line_compare
