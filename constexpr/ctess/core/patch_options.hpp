// Options every pattern family shares (docs/api.md): the output winding and the vertex layout.
//
// * Layout::provoking: every triangle's first index is unique within the patch, so flat shading and
//   per-primitive data can use the provoking vertex; vertices that would provoke twice are appended as
//   copies after the distinct positions. The default where it matters (CP).
// * Layout::shared: one vertex per pattern slot, used by every triangle that touches it, for smooth shading
//   and the smallest vertex buffers. Uniform slots are distinct positions; D3D11's fractional partitionings
//   keep the reference's coincident points (docs/api.md, "A slot is not always a position"). A CP pattern in
//   a transitional state places some slots at one position (docs/algorithm.md §2.11) and keeps them apart, so
//   that the index buffer stays the same while a factor moves within a token triple (no pops). One vertex
//   per position over a whole mesh is the pipeline's welded output (docs/api.md, "Which layout").
//
// Argument order everywhere: outputs first, then inputs, then options (as meshoptimizer).
#pragma once
#include <cstdint>

namespace ctess {

enum class Winding : std::uint8_t { cw, ccw };
enum class Layout : std::uint8_t { provoking, shared };

// The one winding default of every family (D3D11 included): counter-clockwise in (u, v).
inline constexpr Winding default_winding = Winding::ccw;

struct PatchOptions {
    Layout layout = Layout::provoking;
    Winding winding = default_winding;
    friend constexpr bool operator==(const PatchOptions&, const PatchOptions&) = default;
};

} // namespace ctess
