// Cortex-M4 object for the cost of verify_tables (runtime/include/ctess/runtime/cp/table_integrity.hpp): its
// code and the CRC's nibble table, measured by size_report apart from the runtime probe.
#include <ctess/runtime/cp/table_integrity.hpp>

bool ctess_verify_tables_probe(const ctess::rt::CpTableSet& tables) {
    return static_cast<bool>(ctess::rt::verify_tables(tables));
}
