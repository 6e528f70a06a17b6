#include "surface_mesh.hpp"

#include "cli_args.hpp"

#include <ctess/runtime/surface/chord_error.hpp>
#include <ctess/runtime/surface/parametric.hpp>

#include <stdexcept>

#include <fmt/core.h>

namespace ctess::cli {

namespace {

template <class Fn>
auto with_surface(const std::string& name, Fn&& fn) {
    if (name == "sphere") return fn(rt::SphereSurface{});
    if (name == "torus") return fn(rt::TorusSurface{});
    if (name == "ripple") return fn(rt::RippleSurface{});
    throw UsageError(fmt::format("--name: '{}' is not one of: sphere, torus, ripple", name));
}

bool is_option_error(rt::AdaptiveStatus s) {
    return s == rt::AdaptiveStatus::bad_angle || s == rt::AdaptiveStatus::bad_distance ||
           s == rt::AdaptiveStatus::bad_levels;
}

} // namespace

const std::vector<std::string>& surface_names() {
    static const std::vector<std::string> names = {"sphere", "torus", "ripple"};
    return names;
}

SurfaceMesh tessellate_surface(const SurfaceRequest& request) {
    const rt::AdaptiveOptions& opt = request.options;
    if (opt.max_level > surface_cli_max_level)
        throw UsageError(
            fmt::format("--max-level: {} is above the CLI's limit of {} (2^{} triangles at most)",
                        opt.max_level, surface_cli_max_level, surface_cli_max_level + 1));
    const rt::AdaptiveStatus valid = rt::validate(opt);
    if (valid != rt::AdaptiveStatus::ok) throw UsageError(rt::status_message(valid));
    return with_surface(request.name, [&](const auto& surface) {
        std::vector<adaptive::Node> nodes(adaptive::max_nodes(opt.max_level));
        SurfaceMesh out;
        out.params.resize(adaptive::max_vertices(opt.max_level));
        out.vertices.resize(out.params.size());
        const rt::AdaptiveSurface mesh({nodes, out.params, out.vertices}, surface, opt);
        if (is_option_error(mesh.status())) throw UsageError(rt::status_message(mesh.status()));
        if (mesh.status() != rt::AdaptiveStatus::ok)
            throw std::runtime_error(rt::status_message(mesh.status())); // unreachable: worst-case sizes
        const Counts counts = mesh.counts();
        out.params.resize(counts.vertices);
        out.vertices.resize(counts.vertices);
        out.triangles.resize(3 * std::size_t{counts.triangles});
        mesh.emit_triangles(out.triangles);
        for (std::uint32_t i = 0; i < mesh.tree().node_count(); ++i)
            if (mesh.tree().node(i).is_leaf()) out.levels.push_back(mesh.tree().node(i).level);
        out.chord_error = rt::max_chord_error(surface, mesh);
        return out;
    });
}

UniformComparison compare_with_uniform_grid(const SurfaceRequest& request, float target_error) {
    return with_surface(request.name, [&](const auto& surface) {
        UniformComparison c;
        for (std::uint32_t n = 1; n <= comparison_max_segments;
             n = n < 32 ? n + 1 : (n * 26 / 25 > n ? n * 26 / 25 : n + 1)) {
            const float e = rt::grid_chord_error(surface, n, n);
            if (e <= target_error) return UniformComparison{n, 2 * n * n, e, true};
            c = UniformComparison{n, 2 * n * n, e, false};
        }
        return c;
    });
}

} // namespace ctess::cli
