// The uniform-density pattern (docs/algorithm.md §3) as the mesh pipeline uses it: one UniformPatch per base
// triangle, its 16-bit barycentrics (1.0 = 65534) converted to the pipeline's exact base weights (units of
// cp::fixed_one = 2^24), and the setup words the GPU's emit passes read (docs/shaders.md, "Patch records").
//
// The conversion is w * 2^24 / 65534 rounded to nearest. 2^24 * w is even and 65534 / 2 = 32767 is odd, so
// the quotient is never a half: round-to-nearest is then mirror-exact, to_fixed(65534 - w) = 2^24 -
// to_fixed(w). Hence a vertex on a base edge keeps a weight of exactly 0 on the opposite corner, and both
// patches along the edge get the same 2^24 parameters (evaluate_surface's edge rule, surface_eval.hpp). Only
// 32-bit integers, as the shaders have: w * 2^24 / 65534 = 256 w + 256 w / 32767, and the remainder rounds as
// (512 w + 32767) / 65534 (at most 33,553,408 + 32,767).
//
// Factors are rounded and clamped to [1, N] as UniformPatch does (uniform_factor); the pipeline does not
// split above N (uniform_split.hpp): it clamps.
#pragma once
#include <cstdint>

#include <ctess/cp/line.hpp>
#include <ctess/uniform/quantise.hpp>

#include "patch.hpp"

namespace ctess::rt {

// A 16-bit uniform weight (units of 65534) in units of cp::fixed_one; weights above 65534 are clamped.
constexpr std::uint32_t uniform_weight_to_fixed(std::uint32_t w) noexcept {
    w = w < uniform::fixed_one ? w : uniform::fixed_one;
    return 256u * w + (512u * w + 32767u) / 65534u;
}
static_assert(uniform_weight_to_fixed(uniform::fixed_one) == cp::fixed_one);
static_assert(uniform_weight_to_fixed(32767) == cp::fixed_one / 2);

// The uniform setup block's words (inside PatchRecord::setup; the rest of the block is zero).
namespace uniform_setup_word {
inline constexpr unsigned pattern = 0; // uniform::pattern_index of the sorted factors
inline constexpr unsigned sorted = 1;  // f0 | f1 << 8 | f2 << 16, f0 >= f1 >= f2
inline constexpr unsigned corners = 2; // source of output corner c at bits 4c (2 bits), flip at bit 12
} // namespace uniform_setup_word

inline void uniform_setup_words(std::uint32_t* setup, const UniformPatch& patch) noexcept {
    const std::array<std::uint32_t, 3> f = patch.sorted_factors();
    const std::array<std::uint8_t, 3> source = patch.corner_source();
    setup[uniform_setup_word::pattern] = patch.pattern_index();
    setup[uniform_setup_word::sorted] = f[0] | f[1] << 8 | f[2] << 16;
    setup[uniform_setup_word::corners] = std::uint32_t{source[0]} | std::uint32_t{source[1]} << 4 |
                                         std::uint32_t{source[2]} << 8 | (patch.flipped() ? 1u : 0u) << 12;
}

// Vertex i of a patch as base weights of w1 and w2 in units of cp::fixed_one (w0 = fixed_one - u - v).
inline DomainPoint uniform_base_point(const UniformPatch& patch, std::uint32_t i) noexcept {
    const uniform::Point p = patch.vertex(i);
    return {uniform_weight_to_fixed(p.u), uniform_weight_to_fixed(p.v)};
}

} // namespace ctess::rt
