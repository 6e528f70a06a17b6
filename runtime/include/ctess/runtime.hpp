// ctess's umbrella header for the embedded runtime (one front door per feature: runtime/cp.hpp, uniform.hpp,
// pipeline.hpp, surface.hpp, displace.hpp): O(1) patches over the compile-time tables, the CPU mesh
// pipeline, crack-free surface evaluation and displacement. Link ctess::runtime (the configured tables, named
// ctess::rt::cp_tables and ctess::rt::uniform_tables in code), or pick per table set: ctess::runtime_64 /
// ctess::runtime_256 (cp_tables_64 / cp_tables_256), ctess::uniform_runtime_11 / _16.
//
//   ctess::rt::CpPatch patch(ctess::rt::cp_tables, 10.3f, 6.0f, 3.0f);
//   ctess::Counts n = patch.counts();                  // size the buffers, then fill
//   patch.emit(vertices, indices);                      // or vertex(i) / triangle(p) in O(1)
//   ctess::rt::SurfacePoint s = ctess::rt::evaluate_surface(corners, weights, options);
#pragma once

#include <ctess/ctess.hpp>

#include "runtime/cp.hpp"
#include "runtime/displace.hpp"
#include "runtime/pipeline.hpp"
#include "runtime/surface.hpp"
#include "runtime/uniform.hpp"
