// A factor's CP line state (token and 16-bit lerp, docs/algorithm.md §1) in closed form, for the runtime:
// cp::line_state_fixed walks the token list (up to 24 steps), this finds the octave with one bit scan and
// the block with one shift. The tests check it against cp::line_state_fixed for every 16.16 factor in
// [0, 256].
#pragma once
#include <bit>
#include <cstdint>

#include <ctess/cp/line.hpp>

namespace ctess::rt {

// f16: the factor in 16.16 fixed point, at most max_factor << 16 (cp::clamp_factor_16_16 gives that).
constexpr cp::LineState line_state_fixed(std::uint32_t f16) noexcept {
    if (f16 <= cp::lerp_one) return {0, 0};
    // f in (2^k, 2^(k+1)]: k = floor(log2(f16 - 1)) - 16.
    const unsigned k = static_cast<unsigned>(std::bit_width(f16 - 1u)) - 17u;
    // Blocks of the octave: T1 = (1, 2], T2 = (2, 4], T3..T4 = (4, 6], (6, 8], then 4 blocks per octave.
    const unsigned width_log2 = k >= 3 ? k - 2 : k == 0 ? 0u : 1u;
    const unsigned first_token = k >= 3 ? 5 + 4 * (k - 3) : k == 0 ? 1u : k == 1 ? 2u : 3u;
    const std::uint32_t octave_lo = (1u << k) << 16;
    const unsigned block = (f16 - 1u - octave_lo) >> (width_log2 + 16);
    const std::uint32_t d = f16 - octave_lo - ((block << width_log2) << 16);
    // d / 2^width_log2, rounded to nearest, ties to even (cp::shift_round_half_even).
    const std::uint32_t q = d >> width_log2;
    const std::uint32_t r = d - (q << width_log2);
    const std::uint32_t half = (1u << width_log2) >> 1;
    const bool up = width_log2 != 0 && (r > half || (r == half && (q & 1u) != 0));
    return {first_token + block, q + (up ? 1u : 0u)};
}

// cp::line_state(f, max_factor), the same results (NaN, f <= 1 -> T0; f >= max_factor -> the last token).
// NaN is read from the bits first: under -ffinite-math-only the caller's compiler may fold f != f to false,
// and a NaN factor must give T0 whatever the caller's flags (docs/api.md, "Crack-free evaluation"). Finite
// factors take exact steps only (a product by 2^16, a truncation, an exact difference).
constexpr cp::LineState line_state(float f, unsigned max_factor) noexcept {
    if ((std::bit_cast<std::uint32_t>(f) & 0x7FFFFFFFu) > 0x7F800000u) return {0, 0};
    return line_state_fixed(cp::clamp_factor_16_16(f, max_factor));
}

} // namespace ctess::rt
