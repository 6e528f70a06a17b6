// Strict command-line parsing for the ctess CLI: every malformed argument is a UsageError with a clear
// message.
#pragma once
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace ctess::cli {

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// "--key value" pairs after the subcommand; flags listed in `flags` take no value.
class Args {
  public:
    Args(int argc, char** argv, int first, const std::vector<std::string>& known,
         const std::vector<std::string>& flags = {});
    bool has(const std::string& key) const { return values_.count(key) != 0; }
    const std::string& get(const std::string& key) const;
    std::string get_or(const std::string& key, const std::string& fallback) const;

  private:
    std::map<std::string, std::string> values_;
};

// A single float; NaN and infinities are accepted here and judged by the caller.
float parse_float(const std::string& text, const std::string& what);
// "a,b,c": between min_count and max_count floats.
std::vector<float> parse_float_list(const std::string& text, const std::string& what, std::size_t min_count,
                                    std::size_t max_count);
unsigned parse_unsigned(const std::string& text, const std::string& what, unsigned lo, unsigned hi);
// Factors must be finite and > 0; the algorithms clamp the rest (documented in docs/cli.md).
void require_usable_factors(const std::vector<float>& factors, const std::string& what);
std::string choice(const std::string& value, const std::vector<std::string>& allowed,
                   const std::string& what);

} // namespace ctess::cli
