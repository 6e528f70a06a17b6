// A factor's CP line state (token and 16-bit lerp, docs/algorithm.md §1) in closed form, for the runtime:
// cp::line_state_fixed walks the token list (up to 24 steps), this finds the octave with one bit scan and
// the block with one shift. The tests check it against cp::line_state_fixed for every 16.16 factor in
// [0, 256].
#pragma once
#include <bit>
#include <cstdint>

#include <ctess/cp/line.hpp>

namespace ctess::rt {

namespace detail {
// Per octave k (f in (2^k, 2^(k+1)]): the first token and log2 of the token width (docs/algorithm.md §1.1:
// T1 = (1, 2], T2 = (2, 4], T3..T4 = (4, 6], (6, 8], then 4 blocks per octave).
inline constexpr std::uint8_t octave_first_token[8] = {1, 2, 3, 5, 9, 13, 17, 21};
inline constexpr std::uint8_t octave_width_log2[8] = {0, 1, 1, 1, 2, 3, 4, 5};

// round_half_even(d / 2^w) for w <= 8 and d < 2^30, without a branch: (2d + 2^w - 1 + q_0) >> (w + 1),
// where q_0 = (d >> w) & 1 is the quotient's lowest bit (it breaks a tie towards the even quotient).
constexpr std::uint32_t shift_round_half_even(std::uint32_t d, unsigned w) noexcept {
    return (2 * d + (1u << w) - 1u + ((d >> w) & 1u)) >> (w + 1);
}
} // namespace detail

// f16: the factor in 16.16 fixed point, at most 256 << 16 and at most max_factor << 16
// (cp::clamp_factor_16_16 gives that).
constexpr cp::LineState line_state_fixed(std::uint32_t f16) noexcept {
    if (f16 <= cp::lerp_one) return {0, 0};
    // f in (2^k, 2^(k+1)]: k = floor(log2(f16 - 1)) - 16, at most 7.
    const unsigned k = static_cast<unsigned>(std::bit_width(f16 - 1u)) - 17u;
    const unsigned width_log2 = detail::octave_width_log2[k];
    const std::uint32_t octave_lo = (1u << k) << 16;
    const unsigned block = (f16 - 1u - octave_lo) >> (width_log2 + 16);
    const std::uint32_t d = f16 - octave_lo - ((block << width_log2) << 16);
    // d / 2^width_log2, rounded to nearest, ties to even (cp::shift_round_half_even).
    return {detail::octave_first_token[k] + block, detail::shift_round_half_even(d, width_log2)};
}

// cp::clamp_factor_16_16(f, max_factor) from f's bits, for max_factor <= 256: integer steps only, so the
// same on every target and under any floating-point flags. 1 < f < max has an exponent e in [0, 7] and
// f * 65536 = m * 2^(e - 7) for its 24-bit significand m: one shift, rounded to nearest, ties to even, as
// cp::round_half_even_u32 rounds the exact product. The tests check it against cp::clamp_factor_16_16 for
// every float in [1, 256] and around it.
constexpr std::uint32_t factor_16_16(float f, unsigned max_factor) noexcept {
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(f);
    // Not in (1, +inf]: at most 1, negative (the sign bit), NaN or -0: 1.
    if (bits - 0x3F800001u >= 0x7F800000u - 0x3F800000u) return cp::lerp_one;
    if (bits >= std::bit_cast<std::uint32_t>(static_cast<float>(max_factor))) return max_factor << 16;
    const unsigned shift = 134u - (bits >> 23); // 7 - e
    return detail::shift_round_half_even((bits & 0x7FFFFFu) | 0x800000u, shift);
}

// cp::line_state(f, max_factor), the same results (NaN, f <= 1 -> T0; f >= max_factor -> the last token).
// NaN is read from the bits: under -ffinite-math-only the caller's compiler may fold f != f to false, and a
// NaN factor must give T0 whatever the caller's flags (docs/api.md, "Crack-free evaluation").
constexpr cp::LineState line_state(float f, unsigned max_factor) noexcept {
    if (max_factor > 256) [[unlikely]] {
        if ((std::bit_cast<std::uint32_t>(f) & 0x7FFFFFFFu) > 0x7F800000u) return {0, 0};
        return cp::line_state(f, max_factor);
    }
    return line_state_fixed(factor_16_16(f, max_factor));
}

} // namespace ctess::rt
