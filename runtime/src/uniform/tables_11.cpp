// The uniform-density tables for max factor 11, evaluated at compile time.
#include <ctess/runtime/uniform/table_set.hpp>

#include "table_objects.hpp"

namespace ctess::rt {
namespace detail {
constexpr uniform::tables::UniformTables<11> uniform_table_11 = uniform::tables::build_uniform_tables<11>();
} // namespace detail

extern const UniformTableSet uniform_tables_11;
constexpr UniformTableSet uniform_tables_11 = {11,
                                               detail::uniform_table_11.offsets.data(),
                                               detail::uniform_table_11.interior.data(),
                                               detail::uniform_table_11.indices.data(),
                                               detail::uniform_table_11.copy_words.data(),
                                               detail::uniform_table_11.copy_sources.data()};
} // namespace ctess::rt
