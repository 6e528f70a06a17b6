// The D3D11 fixed-function tessellator, bit-exact (docs/algorithm.md §5; the D3D11 functional spec,
// docs/references.md): d3d11::tessellate_tri, tessellate_quad and tessellate_isoline with the integer, pow2,
// fractional_odd and fractional_even partitionings.
#pragma once

#include "core.hpp"
#include "d3d11/tessellator.hpp"
