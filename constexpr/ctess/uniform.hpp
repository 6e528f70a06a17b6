// Uniform-density patterns (docs/algorithm.md §3; Karis 2026, docs/references.md), header-only and constexpr:
//
//   uniform::round_factor       the one rounding rule of float factors (uniform/factor.hpp)
//   uniform::pattern            the stored pattern of a sorted integer triple (uniform/pattern.hpp)
//   uniform::intrinsic_length   the metric every edge length is measured in (uniform/metric.hpp)
//   uniform::edge_parameter     the quantised boundary parameters (uniform/quantise.hpp)
//   uniform::segment_squared_factor  the exact squared factors splitting decides on (uniform/split_factor.hpp)
//
// The runtime's O(1) patches and splitting above the table: <ctess/runtime/uniform.hpp>.
#pragma once

#include "core.hpp"
#include "uniform/factor.hpp"
#include "uniform/metric.hpp"
#include "uniform/pattern.hpp"
#include "uniform/quantise.hpp"
#include "uniform/split_factor.hpp"
