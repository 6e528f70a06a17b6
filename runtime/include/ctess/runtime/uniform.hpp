// The uniform-density runtime (docs/algorithm.md §3.4, §3.5). Link ctess::uniform_runtime_11 or _16 (or
// ctess::uniform_runtime, named ctess::rt::uniform_tables in code).
//
//   UniformPatch       factors up to the table's N: counts(), vertex(i), triangle(p), emit(points, indices)
//   UniformSplit       any factor: the table's own patterns split and diced; counts() and emit()
#pragma once

#include <ctess/uniform.hpp>

#include "uniform/patch.hpp"
#include "uniform/split.hpp"
#include "uniform/table_set.hpp"
