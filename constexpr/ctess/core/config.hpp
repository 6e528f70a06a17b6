// Build-time configuration: the maximum CP tessellation factor (CMake option CTESS_MAX_TESS_FACTOR).
#pragma once

#ifndef CTESS_MAX_TESS_FACTOR
#define CTESS_MAX_TESS_FACTOR 64
#endif

namespace ctess {

inline constexpr unsigned max_tess_factor = CTESS_MAX_TESS_FACTOR;
static_assert(max_tess_factor == 64 || max_tess_factor == 256, "CTESS_MAX_TESS_FACTOR must be 64 or 256");

} // namespace ctess
