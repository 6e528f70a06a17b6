// The vocabulary every pattern family shares (docs/api.md, "One vocabulary"): Counts (count, then fill),
// PatchOptions (layout and winding), the patch concept (TessPatch), exact fixed-point points per unit
// (FixedPoint) and the build-time configuration.
#pragma once

#include "core/config.hpp"
#include "core/counts.hpp"
#include "core/domain_point.hpp"
#include "core/fixed_point.hpp"
#include "core/patch_concept.hpp"
#include "core/patch_options.hpp"
