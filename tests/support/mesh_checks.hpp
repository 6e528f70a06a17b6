// The tests' mesh checks: the analysis library's (ctess/analysis/mesh_checks.hpp: closedness, manifoldness,
// edge matching, exact areas), named in ctess::test, and cat() for the tests' messages.
#pragma once
#include <string>
#include <type_traits>

#include <ctess/analysis/mesh_checks.hpp>

namespace ctess::test {

using namespace ctess::analysis;

// Joins text and numbers (appending avoids g++ 12's false -Wrestrict on "literal" + std::string at -O3).
namespace detail {
inline void append_text(std::string& s, const std::string& part) {
    s += part;
}
inline void append_text(std::string& s, const char* part) {
    s += part;
}
template <class Number>
requires std::is_arithmetic_v<Number>
void append_text(std::string& s, Number part) {
    s += std::to_string(part);
}
} // namespace detail
template <class... Parts>
std::string cat(const Parts&... parts) {
    std::string s;
    (detail::append_text(s, parts), ...);
    return s;
}

} // namespace ctess::test
