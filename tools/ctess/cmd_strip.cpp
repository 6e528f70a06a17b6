// ctess strip: the single triangle strip of a U x V grid (Cayzac 2007) as JSON.
#include "cli_args.hpp"
#include "commands.hpp"
#include "file_output.hpp"
#include "surface_formats.hpp"

#include <ctess/surface/grid_strip.hpp>

#include <vector>

#include <fmt/core.h>

namespace ctess::cli {

int run_strip(int argc, char** argv) {
    const Args args(argc, argv, 2, {"segments", "format", "out"});
    const std::string text = args.get("segments");
    const auto comma = text.find(',');
    if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
        throw UsageError(fmt::format("--segments: expected U,V (two whole numbers), got '{}'", text));
    const unsigned u = parse_unsigned(text.substr(0, comma), "--segments U", 1, strip_cli_max_segments);
    const unsigned v = parse_unsigned(text.substr(comma + 1), "--segments V", 1, strip_cli_max_segments);
    choice(args.get_or("format", "json"), {"json"}, "--format");
    std::vector<std::uint32_t> indices(grid::strip_index_count(u, v));
    grid::fill_strip_indices(indices, u, v);
    write_text(args.get_or("out", "-"), strip_to_json(u, v, indices));
    return 0;
}

} // namespace ctess::cli
