// ctess's umbrella header for the constexpr layer (one front door per feature: core.hpp, cp.hpp, d3d11.hpp,
// uniform.hpp, surface.hpp): every public header-only algorithm, all usable in constant
// expressions. Link ctess::ctess (find_package(ctess) or add_subdirectory). docs/api.md maps each concept to
// its header; docs/algorithm.md explains the rules.
//
//   cp::tessellate          the clamped-parallelogram (CP) triangle pattern (and cp/quad.hpp's quads)
//   cp::line_state          one CP edge: token and lerp of a float factor
//   cp::smallest_edge_rotation   the orientation rule for a base triangle
//   d3d11::tessellate_tri   the D3D11 fixed-function tessellator (and _quad, _isoline)
//   uniform::pattern        the uniform-density pattern of a sorted integer triple
//   grid::fill_strip_indices    a U x V grid as one triangle strip
//   adaptive::ConformingBintree   crack-free adaptive bisection of the parameter square
//   ctess::Counts, ctess::PatchOptions   the vocabulary every pattern family shares
#pragma once

#include "core.hpp"
#include "cp.hpp"
#include "d3d11.hpp"
#include "surface.hpp"
#include "uniform.hpp"
