// The CP runtime: O(1) patches over the compile-time tables (docs/algorithm.md §4). Link ctess::runtime_64 or
// ctess::runtime_256 (or ctess::runtime, the configured one, named ctess::rt::cp_tables in code).
//
//   CpPatch            counts(), vertex(i), triangle(p), emit(points, indices); builds the lookup tables
//   CpPatchSetup       counts() and emit() only: no per-patch lookup tables
//   cp_counts          the counts alone
//   verify_tables      an integrity check of a table set (cp/table_integrity.hpp)
#pragma once

#include <ctess/cp.hpp>

#include "cp/patch.hpp"
#include "cp/table_integrity.hpp"
#include "cp/table_set.hpp"
