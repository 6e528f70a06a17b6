// Writes the bytes of both compile-time uniform table objects to stdout, for the g++ / clang comparison
// (tests/uniform/compare_compilers.cmake).
#include <cstdio>

#include "uniform/table_objects.hpp"

int main() {
    std::fwrite(&ctess::rt::detail::uniform_table_11, 1, sizeof ctess::rt::detail::uniform_table_11, stdout);
    std::fwrite(&ctess::rt::detail::uniform_table_16, 1, sizeof ctess::rt::detail::uniform_table_16, stdout);
    return 0;
}
