// Clamped-parallelogram (CP) tessellation, header-only and constexpr (docs/algorithm.md §1, §2; Hable 2026,
// docs/references.md):
//
//   cp::line_state              one edge: token and lerp of a float factor (cp/line.hpp)
//   cp::smallest_edge_rotation  the orientation rule of a base triangle (cp/orientation.hpp)
//   cp::tessellate              the triangle pattern of three edge factors (cp/pattern.hpp)
//   cp::tessellate_quad         the quad rule: two triangles sharing a diagonal (cp/quad.hpp)
//
// The runtime's O(1) patches over the compile-time tables: <ctess/runtime/cp.hpp>.
#pragma once

#include "core.hpp"
#include "cp/line.hpp"
#include "cp/orientation.hpp"
#include "cp/pattern.hpp"
#include "cp/quad.hpp"
