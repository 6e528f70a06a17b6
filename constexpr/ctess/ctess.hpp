// ctess's front door for the constexpr layer: every public header-only algorithm, all usable in constant
// expressions. Link ctess::ctess (find_package(ctess) or add_subdirectory). docs/api.md maps each concept to
// its header; docs/algorithm.md explains the rules.
//
//   cp::tessellate          the clamped-parallelogram (CP) triangle pattern (and cp_quad.hpp's quads)
//   cp::line_state          one CP edge: token and lerp of a float factor
//   cp::smallest_edge_rotation   the orientation rule for a base triangle
//   d3d11::tessellate_tri   the D3D11 fixed-function tessellator (and _quad, _isoline)
//   uniform::pattern        the uniform-density pattern of a sorted integer triple (seed 001)
//   grid::fill_strip_indices    a U x V grid as one triangle strip (seed 002)
//   adaptive::ConformingBintree   crack-free adaptive bisection of the parameter square (seed 004)
//   ctess::Counts, ctess::PatchOptions   the vocabulary every pattern family shares
#pragma once

#include "config.hpp"
#include "counts.hpp"
#include "domain_point.hpp"
#include "patch_options.hpp"

#include "cp_line.hpp"
#include "cp_orientation.hpp"
#include "cp_pattern.hpp"
#include "cp_quad.hpp"

#include "d3d11_tessellator.hpp"

#include "line_modes.hpp"

#include "uniform_metric.hpp"
#include "uniform_pattern.hpp"
#include "uniform_quantise.hpp"

#include "conforming_bintree.hpp"
#include "grid_eval.hpp"
#include "grid_strip.hpp"
