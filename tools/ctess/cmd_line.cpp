// ctess line: the points of one edge for a mode and factor.
#include "cli_args.hpp"
#include "commands.hpp"
#include "json_escape.hpp"

#include "line_modes.hpp"
#include <ctess/core/config.hpp>

#include <string>

#include <fmt/core.h>

namespace ctess::cli {

LineMode line_mode_from(const std::string& name) {
    LineMode mode{};
    if (!parse_line_mode(name, mode)) {
        std::string list;
        for (LineMode m : all_line_modes) {
            if (!list.empty()) list += ", ";
            list += line_mode_name(m);
        }
        throw UsageError(fmt::format("--mode: '{}' is not one of: {}", name, list));
    }
    return mode;
}

unsigned max_factor_from(const Args& args) {
    const std::string text = args.get_or("max", std::to_string(ctess::max_tess_factor));
    return choice(text, {"64", "256"}, "--max") == "64" ? 64u : 256u;
}

int run_line(int argc, char** argv) {
    const Args args(argc, argv, 2, {"mode", "factor", "max", "format"});
    const LineMode mode = line_mode_from(args.get_or("mode", "cp"));
    const float f = parse_float(args.get("factor"), "--factor");
    require_usable_factors({f}, "--factor");
    const unsigned max = max_factor_from(args);
    const std::string format = choice(args.get_or("format", "text"), {"text", "json"}, "--format");

    std::uint32_t p[max_line_points];
    const unsigned n = line_points(mode, f, max, p);
    const std::uint32_t one = line_fixed_one(mode);
    if (format == "json") {
        std::string pts;
        for (unsigned i = 0; i < n; ++i) pts += fmt::format("{}{}", i ? ", " : "", p[i]);
        fmt::print("{{\"mode\": \"{}\", \"factor\": {}, \"max_tess_factor\": {}, \"fixed_one\": {}, "
                   "\"points\": [{}]}}\n",
                   json_escape(line_mode_name(mode)), f, max, one, pts);
        return 0;
    }
    fmt::print("mode {}  factor {:g}  ", line_mode_name(mode), f);
    if (mode == LineMode::cp) {
        const cp::LineState s = cp::line_state(f, max);
        fmt::print("token T{}  lerp {}/65536  ", s.token, s.t16);
    }
    fmt::print("{} points  (exact value / {})\n", n, one);
    for (unsigned i = 0; i < n; ++i) fmt::print("{:4}  {:>10}  {:.8f}\n", i, p[i], p[i] / double(one));
    return 0;
}

} // namespace ctess::cli
