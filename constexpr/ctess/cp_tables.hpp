// All compile-time CP tables of one maximum factor (docs/algorithm.md §2, §3):
// the token table, the interior column table (in chunks) and the gap table. This header only gathers the
// builders and the chunk counts; the objects are emitted once, into .rodata, by runtime/src/cp_tables_*.cpp.
#pragma once

#include "cp_tables_columns.hpp"
#include "cp_tables_gap.hpp"
#include "cp_tables_layout.hpp"
#include "cp_tables_tokens.hpp"

#define CTESS_COLUMN_CHUNKS_256 4

// X(k) for k = 0 .. CTESS_COLUMN_CHUNKS_256 - 1 (at most 8).
#define CTESS_COLUMN_CHUNKS_1_(X) X(0)
#define CTESS_COLUMN_CHUNKS_2_(X) CTESS_COLUMN_CHUNKS_1_(X) X(1)
#define CTESS_COLUMN_CHUNKS_3_(X) CTESS_COLUMN_CHUNKS_2_(X) X(2)
#define CTESS_COLUMN_CHUNKS_4_(X) CTESS_COLUMN_CHUNKS_3_(X) X(3)
#define CTESS_COLUMN_CHUNKS_5_(X) CTESS_COLUMN_CHUNKS_4_(X) X(4)
#define CTESS_COLUMN_CHUNKS_6_(X) CTESS_COLUMN_CHUNKS_5_(X) X(5)
#define CTESS_COLUMN_CHUNKS_7_(X) CTESS_COLUMN_CHUNKS_6_(X) X(6)
#define CTESS_COLUMN_CHUNKS_8_(X) CTESS_COLUMN_CHUNKS_7_(X) X(7)
#define CTESS_COLUMN_CHUNKS_CAT_(n) CTESS_COLUMN_CHUNKS_##n##_
#define CTESS_COLUMN_CHUNKS_N_(n) CTESS_COLUMN_CHUNKS_CAT_(n)
#define CTESS_FOR_EACH_COLUMN_CHUNK_256(X) CTESS_COLUMN_CHUNKS_N_(CTESS_COLUMN_CHUNKS_256)(X)

namespace ctess::cp::tables {

// Column-table translation units per maximum factor: one is fast at 64; at 256 several keep each unit's
// constant evaluation short and its pool offsets below 2^16. CTESS_COLUMN_CHUNKS_256 is the one place that
// sets their number: runtime/CMakeLists.txt reads it, and CTESS_FOR_EACH_COLUMN_CHUNK_256 enumerates them.
constexpr unsigned column_chunks(unsigned max_factor) {
    return max_factor > 64 ? CTESS_COLUMN_CHUNKS_256 : 1u;
}

} // namespace ctess::cp::tables
