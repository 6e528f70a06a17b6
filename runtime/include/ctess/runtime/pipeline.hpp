// The CPU mesh pipeline, the reference the GLSL and WGSL shaders are tested against bit for bit
// (docs/shaders.md): per-edge factors, patch records with prefix sums, then every vertex and triangle.
//
//   setup_patches      every base triangle's record and the totals (count)
//   emit_mesh          every output vertex and triangle (fill)
//   edge_tess_factor   the DiceRate factor of one edge (pipeline/tess_factor.hpp)
#pragma once

#include "cp.hpp"
#include "pipeline/mesh_pipeline.hpp"
#include "pipeline/tess_factor.hpp"
#include "uniform.hpp"
