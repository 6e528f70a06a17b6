// ctess pattern: one tessellated patch as JSON, SVG or OBJ.
#include "cli_args.hpp"
#include "commands.hpp"
#include "file_output.hpp"
#include "mesh.hpp"
#include "mesh_formats.hpp"

#include <fmt/core.h>

namespace ctess::cli {

PatternRequest pattern_request_from(const Args& args, const std::string& factors_key) {
    PatternRequest r;
    r.mode = choice(args.get_or("mode", "cp"), pattern_modes(), "--mode");
    r.domain = choice(args.get_or("domain", "tri"), {"tri", "quad", "iso"}, "--domain");
    r.factors = parse_float_list(args.get(factors_key), "--" + factors_key, 2, 6);
    require_usable_factors(r.factors, "--" + factors_key);
    const std::string default_winding = is_d3d11_mode(r.mode) ? "cw" : "ccw";
    r.ccw = choice(args.get_or("winding", default_winding), {"cw", "ccw"}, "--winding") == "ccw";
    r.max_factor = max_factor_from(args);
    r.provoking_layout =
        choice(args.get_or("layout", "provoking"), {"provoking", "shared"}, "--layout") == "provoking";
    r.staircase_columns = choice(args.get_or("column-rule", "minimal"), {"minimal", "staircase"},
                                 "--column-rule") == "staircase";
    if (is_d3d11_mode(r.mode) && (args.has("layout") || args.has("max") || args.has("column-rule")))
        throw UsageError("--layout, --max and --column-rule apply to the cp mode only");
    if (r.mode == "uniform") {
        if (args.has("max") || args.has("column-rule"))
            throw UsageError("--max and --column-rule apply to the cp mode only");
        r.max_factor = CTESS_UNIFORM_MAX_FACTOR; // the configured uniform table
        // one vertex per position by default; provoking appends copies (§3.4), per subpatch when split
        r.provoking_layout = args.get_or("layout", "shared") == "provoking";
    }
    return r;
}

int run_pattern(int argc, char** argv) {
    const Args args(argc, argv, 2,
                    {"mode", "domain", "factors", "winding", "format", "out", "max", "layout", "column-rule"},
                    {"provoking"});
    const PatternRequest r = pattern_request_from(args, "factors");
    const std::string format = choice(args.get_or("format", "json"), {"json", "svg", "obj"}, "--format");
    const Mesh mesh = tessellate(r);
    std::string text;
    if (format == "json")
        text = mesh_to_json(mesh, r);
    else if (format == "obj")
        text = mesh_to_obj(mesh, r);
    else
        text = mesh_to_svg(mesh, r, SvgOptions{args.has("provoking"), {}});
    write_text(args.get_or("out", "-"), text);
    return 0;
}

} // namespace ctess::cli
