// The models room's front door: real glTF 2.0 and OBJ files in (ctess::models::load_model), and the adjacency
// that PN-AEN and watertight displacement need, from meshoptimizer (ctess::models::build_adjacency).
// docs/models.md describes what is read, what is refused and why.
#pragma once
#include <ctess/runtime/models/adjacency.hpp>
#include <ctess/runtime/models/height_map.hpp>
#include <ctess/runtime/models/model.hpp>
