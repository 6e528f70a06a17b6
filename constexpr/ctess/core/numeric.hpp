// Exact numeric helpers usable in constant expressions: float classification, rounding to fixed point,
// bit tricks. Nothing here depends on <cmath>, whose functions are not constexpr in C++20.
#pragma once
#include <bit>
#include <cstdint>

namespace ctess {

constexpr bool is_nan(float x) {
    return x != x;
}
constexpr bool is_finite(float x) {
    return !is_nan(x) && x <= 3.40282347e38f && x >= -3.40282347e38f;
}

// IEEE-754R min/max: a NaN operand yields the other operand (D3D11 relies on this to map NaN to a bound).
constexpr float ieee_fmin(float a, float b) {
    return is_nan(a) ? b : is_nan(b) ? a : (a < b ? a : b);
}
constexpr float ieee_fmax(float a, float b) {
    return is_nan(a) ? b : is_nan(b) ? a : (a > b ? a : b);
}

// Set bits of a 16-bit word, inline: without a popcount instruction in the baseline ISA (x86-64, Cortex-M),
// std::popcount becomes a library call.
constexpr std::uint32_t popcount16(std::uint32_t x) {
    x -= (x >> 1) & 0x5555u;
    x = (x & 0x3333u) + ((x >> 2) & 0x3333u);
    x = (x + (x >> 4)) & 0x0F0Fu;
    return (x + (x >> 8)) & 0x1Fu;
}

// Round a finite, non-negative float below 2^32 to the nearest integer, ties to even.
constexpr std::uint32_t round_half_even_u32(float x) {
    const auto whole = static_cast<std::uint32_t>(x); // truncates; exact for x < 2^32
    const float frac = x - static_cast<float>(whole); // exact: both values share the exponent range
    if (frac > 0.5f || (frac == 0.5f && (whole & 1u) != 0)) return whole + 1;
    return whole;
}

// Unsigned 16.16 fixed point of a float in [0, 65536), round to nearest even (D3D11 §4.2 step 5).
constexpr std::uint32_t to_fixed_16_16(float x) {
    return round_half_even_u32(x * 65536.0f);
}

// Integer division n / 2^s rounded to nearest, ties to even.
constexpr std::uint64_t shift_round_half_even(std::uint64_t n, unsigned s) {
    if (s == 0) return n;
    const std::uint64_t q = n >> s;
    const std::uint64_t r = n & ((std::uint64_t{1} << s) - 1);
    const std::uint64_t half = std::uint64_t{1} << (s - 1);
    return (r > half || (r == half && (q & 1u) != 0)) ? q + 1 : q;
}

// floor(log2(x)), 0 for x <= 1: one bit scan (the runtime clamps every patch's factors through it).
constexpr unsigned floor_log2(std::uint32_t x) {
    return x > 1 ? static_cast<unsigned>(std::bit_width(x)) - 1u : 0u;
}

constexpr bool is_pow2(std::uint32_t x) {
    return x != 0 && (x & (x - 1)) == 0;
}

} // namespace ctess
