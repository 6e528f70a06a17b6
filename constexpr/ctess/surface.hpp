// Parametric surfaces, header-only and constexpr: a U x V grid as one triangle strip (surface/grid_strip.hpp,
// surface/grid_eval.hpp) and crack-free adaptive bisection of the parameter square
// (surface/conforming_bintree.hpp; docs/surfaces.md). Evaluation of meshes: <ctess/runtime/surface.hpp>.
#pragma once

#include "core.hpp"
#include "surface/conforming_bintree.hpp"
#include "surface/grid_eval.hpp"
#include "surface/grid_strip.hpp"
