// All compile-time CP tables of one maximum factor (docs/algorithm.md §2, §4):
// the token table, the interior column table (in chunks) and the gap table. This header only gathers the
// builders and the chunk counts; the objects are emitted once, into .rodata, by runtime/src/cp_tables_*.cpp.
#pragma once

#include "tables_columns.hpp"
#include "tables_gap.hpp"
#include "tables_layout.hpp"
#include "tables_tokens.hpp"

namespace ctess::cp::tables {

// Column-table translation units per maximum factor: one is fast at 64; at 256 several keep each unit's
// constant evaluation short and its pool offsets below 2^16: CTESS_COLUMN_CHUNKS_256 (cp_tables_layout.hpp).
constexpr unsigned column_chunks(unsigned max_factor) {
    return max_factor > 64 ? CTESS_COLUMN_CHUNKS_256 : 1u;
}

} // namespace ctess::cp::tables
