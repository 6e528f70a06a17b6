// Surfaces in the runtime: crack-free evaluation of flat, PN-triangle and Phong patches under any compiler
// flags (surface/eval.hpp, docs/surfaces.md), and adaptive parametric tessellation (surface/adaptive.hpp).
#pragma once

#include <ctess/surface.hpp>

#include "surface/adaptive.hpp"
#include "surface/chord_error.hpp"
#include "surface/eval.hpp"
#include "surface/parametric.hpp"
