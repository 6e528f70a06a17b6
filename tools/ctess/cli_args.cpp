#include "cli_args.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string_view>

#include <fmt/core.h>

namespace ctess::cli {

Args::Args(int argc, char** argv, int first, const std::vector<std::string>& known,
           const std::vector<std::string>& flags) {
    for (int i = first; i < argc; ++i) {
        const std::string_view key = argv[i];
        if (!key.starts_with("--")) throw UsageError(fmt::format("unexpected argument '{}'", key));
        const std::string name(key.substr(2));
        const bool is_flag = std::find(flags.begin(), flags.end(), name) != flags.end();
        if (!is_flag && std::find(known.begin(), known.end(), name) == known.end())
            throw UsageError(fmt::format("unknown option '{}'", key));
        if (values_.count(name)) throw UsageError(fmt::format("option '{}' given twice", key));
        if (is_flag) {
            values_.emplace(name,
                            "1"); // emplace: operator=(const char*) trips a g++ 12 -Wrestrict false positive
            continue;
        }
        if (i + 1 >= argc) throw UsageError(fmt::format("option '{}' needs a value", key));
        values_.emplace(name, argv[++i]);
    }
}

const std::string& Args::get(const std::string& key) const {
    auto it = values_.find(key);
    if (it == values_.end()) throw UsageError(fmt::format("missing required option '--{}'", key));
    return it->second;
}

std::string Args::get_or(const std::string& key, const std::string& fallback) const {
    auto it = values_.find(key);
    return it == values_.end() ? fallback : it->second;
}

float parse_float(const std::string& text, const std::string& what) {
    float value = 0.0f;
    const char* begin = text.data();
    const char* end = begin + text.size();
    if (begin != end && *begin == '+') ++begin; // from_chars rejects a leading '+'
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (text.empty() || ec == std::errc::invalid_argument || ptr != end)
        throw UsageError(fmt::format("{}: '{}' is not a number", what, text));
    if (ec == std::errc::result_out_of_range)
        throw UsageError(fmt::format("{}: '{}' is out of the float range", what, text));
    return value;
}

std::vector<float> parse_float_list(const std::string& text, const std::string& what, std::size_t min_count,
                                    std::size_t max_count) {
    std::vector<float> out;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        const std::string item =
            text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        out.push_back(parse_float(item, fmt::format("{} item {}", what, out.size() + 1)));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (out.size() < min_count || out.size() > max_count) {
        const std::string want = min_count == max_count ? fmt::format("{}", min_count)
                                                        : fmt::format("{} to {}", min_count, max_count);
        throw UsageError(
            fmt::format("{}: expected {} comma-separated values, got {}", what, want, out.size()));
    }
    return out;
}

unsigned parse_unsigned(const std::string& text, const std::string& what, unsigned lo, unsigned hi) {
    unsigned value = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc{} || ptr != text.data() + text.size())
        throw UsageError(fmt::format("{}: '{}' is not a whole number", what, text));
    if (value < lo || value > hi)
        throw UsageError(fmt::format("{}: {} is outside [{}, {}]", what, value, lo, hi));
    return value;
}

void require_usable_factors(const std::vector<float>& factors, const std::string& what) {
    for (std::size_t i = 0; i < factors.size(); ++i) {
        const float f = factors[i];
        if (std::isnan(f) || std::isinf(f) || f <= 0.0f)
            throw UsageError(fmt::format("{} item {} is {}: factors must be finite and greater than 0 "
                                         "(the library itself culls or clamps such values, see docs/cli.md)",
                                         what, i + 1, f));
    }
}

std::string choice(const std::string& value, const std::vector<std::string>& allowed,
                   const std::string& what) {
    if (std::find(allowed.begin(), allowed.end(), value) != allowed.end()) return value;
    std::string list;
    for (const auto& a : allowed) {
        if (!list.empty()) list += ", ";
        list += a;
    }
    throw UsageError(fmt::format("{}: '{}' is not one of: {}", what, value, list));
}

} // namespace ctess::cli
