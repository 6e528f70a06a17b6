// ctess surface: adaptive tessellation of a built-in surface (Męciński 2011) as JSON, OBJ, SVG, or the
// comparison with a uniform grid of the same chord error.
#include "cli_args.hpp"
#include "commands.hpp"
#include "file_output.hpp"
#include "surface_formats.hpp"
#include "surface_mesh.hpp"

#include <fmt/core.h>

namespace ctess::cli {

int run_surface(int argc, char** argv) {
    const Args args(argc, argv, 2,
                    {"name", "angle", "distance", "min-level", "max-level", "format", "view", "out"});
    SurfaceRequest r;
    r.name = choice(args.get("name"), surface_names(), "--name");
    if (args.has("angle")) r.options.max_angle_deg = parse_float(args.get("angle"), "--angle");
    if (args.has("distance")) r.options.max_distance = parse_float(args.get("distance"), "--distance");
    if (args.has("min-level"))
        r.options.min_level = parse_unsigned(args.get("min-level"), "--min-level", 0, surface_cli_max_level);
    if (args.has("max-level"))
        r.options.max_level = parse_unsigned(args.get("max-level"), "--max-level", 0, surface_cli_max_level);
    const std::string format =
        choice(args.get_or("format", "json"), {"json", "obj", "svg", "stats"}, "--format");
    const std::string view = choice(args.get_or("view", "param"), {"param", "shaded"}, "--view");
    if (args.has("view") && format != "svg") throw UsageError("--view applies to --format svg only");

    const SurfaceMesh mesh = tessellate_surface(r);
    std::string text;
    if (format == "json")
        text = surface_to_json(mesh, r);
    else if (format == "obj")
        text = surface_to_obj(mesh, r);
    else if (format == "svg")
        text = view == "param" ? surface_to_param_svg(mesh, r) : surface_to_shaded_svg(mesh, r);
    else
        text = surface_stats_json(mesh, r, compare_with_uniform_grid(r, mesh.chord_error));
    write_text(args.get_or("out", "-"), text);
    return 0;
}

} // namespace ctess::cli
