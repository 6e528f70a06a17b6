// `ctess mesh`'s options and unwelded output (mesh_options.hpp).
#include "mesh_options.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/core.h>

namespace ctess::cli {

namespace {

rt::Vec3 parse_vec3(const std::string& text, const std::string& what) {
    const std::vector<float> v = parse_float_list(text, what, 3, 3);
    for (const float f : v)
        if (!std::isfinite(f)) throw UsageError(what + " needs finite numbers");
    return {v[0], v[1], v[2]};
}

float positive_finite(const Args& args, const std::string& key) {
    const float f = parse_float(args.get(key), "--" + key);
    if (!std::isfinite(f) || f <= 0) throw UsageError("--" + key + " must be a finite number > 0");
    return f;
}

rt::Surface surface_from(const std::string& name) {
    if (name == "flat") return rt::Surface::flat;
    if (name == "pn") return rt::Surface::pn_triangles;
    if (name == "pn-aen") return rt::Surface::pn_aen;
    return rt::Surface::phong;
}

} // namespace

// The factor options: exactly one of --factor, --edge-length, --dice-rate (with the camera's options).
rt::DiceOptions dice_options_from(const Args& args) {
    const int modes = args.has("factor") + args.has("edge-length") + args.has("dice-rate");
    if (modes != 1) throw UsageError("give exactly one of --factor, --edge-length and --dice-rate");
    const bool camera_options = args.has("camera") || args.has("fov") || args.has("resolution");
    if (camera_options && !args.has("dice-rate"))
        throw UsageError("--camera, --fov and --resolution go with --dice-rate");
    rt::DiceOptions dice;
    if (args.has("factor")) {
        dice.mode = rt::FactorMode::constant;
        dice.constant_factor = positive_finite(args, "factor");
    } else if (args.has("edge-length")) {
        dice.mode = rt::FactorMode::edge_length;
        dice.target_edge_length = positive_finite(args, "edge-length");
    } else {
        dice.mode = rt::FactorMode::camera;
        dice.dice_rate = positive_finite(args, "dice-rate");
        if (!args.has("camera")) throw UsageError("--dice-rate needs --camera X,Y,Z");
        dice.eye = parse_vec3(args.get("camera"), "--camera");
        const float fov = args.has("fov") ? positive_finite(args, "fov") : 60.0f;
        if (fov >= 180) throw UsageError("--fov must be below 180 degrees");
        const std::vector<float> res =
            parse_float_list(args.get_or("resolution", "1920,1080"), "--resolution", 2, 2);
        if (!(res[0] >= 1 && res[1] >= 1 && res[0] <= 65536 && res[1] <= 65536))
            throw UsageError("--resolution needs W,H between 1 and 65536");
        // Pixels per world unit at distance 1 (tess_factor.hpp): the vertical resolution over 2 tan(fov / 2).
        const double half = fov * std::numbers::pi / 360.0;
        dice.projection_scale = static_cast<float>(res[1] / (2.0 * std::tan(half)));
    }
    return dice;
}

rt::PipelineOptions pipeline_options_from(const Args& args) {
    const std::string pattern =
        choice(args.get_or("pattern", "cp"),
               {"cp", "uniform", "d3d11-integer", "d3d11-pow2", "d3d11-odd", "d3d11-even"}, "--pattern");
    rt::PipelineOptions options;
    options.dice = dice_options_from(args);
    // Uniform density at any factor: patches above the table's N split (docs/algorithm.md §7.5).
    options.pattern = pattern == "cp"              ? rt::Pattern::cp
                      : pattern == "uniform"       ? rt::Pattern::uniform_split
                      : pattern == "d3d11-integer" ? rt::Pattern::d3d11_integer
                      : pattern == "d3d11-pow2"    ? rt::Pattern::d3d11_pow2
                      : pattern == "d3d11-odd"     ? rt::Pattern::d3d11_fractional_odd
                                                   : rt::Pattern::d3d11_fractional_even;
    options.surface.surface =
        surface_from(choice(args.get_or("surface", "flat"), {"flat", "pn", "pn-aen", "phong"}, "--surface"));
    options.quad_rule = choice(args.get_or("quad-rule", "longer-pair"), {"longer-pair", "as-labelled"},
                               "--quad-rule") == "longer-pair"
                            ? rt::QuadRule::longer_pair
                            : rt::QuadRule::as_labelled;
    return options;
}

UnweldedOutput unwelded_output(const rt::CpTableSet& cp, const rt::UniformTableSet& uniform,
                               const rt::MeshView& view, const rt::PipelineOptions& options,
                               const std::string& name, std::uint32_t max_triangles) {
    UnweldedOutput out;
    out.records.resize(view.patch_count());
    rt::PipelineStatus status = rt::setup_patches(cp, uniform, view, options, out.records, out.totals);
    if (status == rt::PipelineStatus::ok && out.totals.triangles > max_triangles)
        throw std::runtime_error(
            fmt::format("{}: the tessellated model would have {} triangles, above the limit of {}", name,
                        out.totals.triangles, max_triangles));
    if (status != rt::PipelineStatus::ok)
        throw std::runtime_error(fmt::format("{}: {}", name, rt::pipeline_status_message(status)));
    emit_unwelded(cp, uniform, view, options, name, out);
    return out;
}

void emit_unwelded(const rt::CpTableSet& cp, const rt::UniformTableSet& uniform, const rt::MeshView& view,
                   const rt::PipelineOptions& options, const std::string& name, UnweldedOutput& out) {
    out.vertices.resize(out.totals.vertices);
    out.indices.resize(3 * std::size_t{out.totals.triangles});
    const rt::PipelineStatus status =
        rt::emit_mesh(cp, uniform, view, options, out.records, out.vertices, out.indices);
    if (status != rt::PipelineStatus::ok)
        throw std::runtime_error(fmt::format("{}: {}", name, rt::pipeline_status_message(status)));
}

} // namespace ctess::cli
