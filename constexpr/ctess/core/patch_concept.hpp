// The one shape every runtime pattern family has (docs/api.md, "One patch concept"), in the style of
// OpenSubdiv's Bfr::Tessellation: count, then fill.
//
//   counts()                 how many vertices and triangles (Counts), O(1) after construction
//   emit(points, indices)    writes them; false and nothing written when a span is too short
//   vertex(i), triangle(p)   O(1) random access, where the family has it (IndexedTessPatch)
//
// Families and what they model (static_assert beside each class):
//
//   family        TessPatch   IndexedTessPatch   point_type
//   CpPatch       yes         yes                FixedPoint<units::cp>
//   CpPatchSetup  yes         no (no lookups)    FixedPoint<units::cp>
//   UniformPatch  yes         yes                FixedPoint<units::uniform>
//   UniformSplit  yes         no (a tree walk)   FixedPoint<units::split>
#pragma once
#include <array>
#include <concepts>
#include <cstdint>
#include <span>

#include "counts.hpp"

namespace ctess {

template <class P>
concept TessPatch = requires(const P& patch, std::span<typename P::point_type> points,
                             std::span<std::uint32_t> indices) {
    typename P::point_type;
    { patch.counts() } -> std::same_as<Counts>;
    { patch.emit(points, indices) } -> std::same_as<bool>;
};

template <class P>
concept IndexedTessPatch = TessPatch<P> && requires(const P& patch, std::uint32_t i) {
    { patch.vertex(i) } -> std::same_as<typename P::point_type>;
    { patch.triangle(i) } -> std::convertible_to<std::array<std::uint32_t, 3>>;
};

} // namespace ctess
