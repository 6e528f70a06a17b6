// The table objects behind uniform_tables_11 and uniform_tables_16, declared for the translation units that
// define them or point at them (extern, then constexpr: external linkage and compile-time evaluation).
#pragma once
#include <ctess/uniform/tables.hpp>

namespace ctess::rt::detail {

extern const uniform::tables::UniformTables<11> uniform_table_11;
extern const uniform::tables::UniformTables<16> uniform_table_16;

} // namespace ctess::rt::detail
