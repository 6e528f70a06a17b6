// The uniform-density tables for max factor 16, evaluated at compile time.
#include <ctess/runtime/uniform/table_set.hpp>

#include "table_objects.hpp"

namespace ctess::rt {
namespace detail {
constexpr uniform::tables::UniformTables<16> uniform_table_16 = uniform::tables::build_uniform_tables<16>();
} // namespace detail

extern const UniformTableSet uniform_tables_16;
constexpr UniformTableSet uniform_tables_16 = {16,
                                               detail::uniform_table_16.offsets.data(),
                                               detail::uniform_table_16.interior.data(),
                                               detail::uniform_table_16.indices.data(),
                                               detail::uniform_table_16.copy_words.data(),
                                               detail::uniform_table_16.copy_sources.data()};
} // namespace ctess::rt
