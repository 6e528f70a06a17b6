#include "surface_formats.hpp"

#include "json_escape.hpp"
#include "svg_writer.hpp"

#include <ctess/surface/grid_strip.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include <fmt/core.h>

namespace ctess::cli {

namespace {

std::string options_text(const SurfaceRequest& r) {
    const rt::AdaptiveOptions& o = r.options;
    return fmt::format("angle {:g}° · distance {:g} · levels {}–{}", o.max_angle_deg, o.max_distance,
                       o.min_level, o.max_level);
}

// JSON has no inf or NaN: a non-finite value (--distance inf, --angle inf) is written as null.
std::string json_number(float v, bool six_digits = false) {
    if (!std::isfinite(v)) return "null";
    return six_digits ? fmt::format("{:.6g}", v) : fmt::format("{}", v);
}

std::string vec3_list(const std::vector<rt::SurfaceVertex>& v, bool normals) {
    std::string out;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const rt::Vec3 p = normals ? v[i].normal : v[i].position;
        out += fmt::format("{}[{:.9g}, {:.9g}, {:.9g}]", i ? ", " : "", p.x, p.y, p.z);
    }
    return out;
}

} // namespace

std::string surface_to_json(const SurfaceMesh& mesh, const SurfaceRequest& r) {
    const rt::AdaptiveOptions& o = r.options;
    std::string out = "{\n";
    out += fmt::format("  \"name\": \"{}\",\n  \"angle\": {},\n  \"distance\": {},\n  \"min_level\": {},\n"
                       "  \"max_level\": {},\n",
                       json_escape(r.name), json_number(o.max_angle_deg), json_number(o.max_distance),
                       o.min_level, o.max_level);
    out += fmt::format("  \"fixed_one\": {},\n", adaptive::fixed_one);
    out += fmt::format("  \"vertex_count\": {},\n  \"triangle_count\": {},\n", mesh.params.size(),
                       mesh.triangles.size() / 3);
    out += "  \"params\": [";
    for (std::size_t i = 0; i < mesh.params.size(); ++i)
        out += fmt::format("{}[{}, {}]", i ? ", " : "", mesh.params[i].p, mesh.params[i].q);
    out += "],\n  \"vertices\": [" + vec3_list(mesh.vertices, false) + "],\n";
    out += "  \"normals\": [" + vec3_list(mesh.vertices, true) + "],\n";
    out += "  \"triangles\": [";
    for (std::size_t t = 0; t < mesh.triangles.size(); t += 3)
        out += fmt::format("{}[{}, {}, {}]", t ? ", " : "", mesh.triangles[t], mesh.triangles[t + 1],
                           mesh.triangles[t + 2]);
    out += "]\n}\n";
    return out;
}

std::string surface_to_obj(const SurfaceMesh& mesh, const SurfaceRequest& r) {
    std::string out = fmt::format("# ctess surface --name {} ({})\n", r.name, options_text(r));
    out += fmt::format("# {} vertices, {} triangles; vt = (u, v) parameters\n", mesh.params.size(),
                       mesh.triangles.size() / 3);
    for (const auto& v : mesh.vertices)
        out += fmt::format("v {:.9g} {:.9g} {:.9g}\n", v.position.x, v.position.y, v.position.z);
    for (const auto& v : mesh.vertices)
        out += fmt::format("vn {:.9g} {:.9g} {:.9g}\n", v.normal.x, v.normal.y, v.normal.z);
    const double one = adaptive::fixed_one;
    for (const auto& p : mesh.params) out += fmt::format("vt {:.9g} {:.9g}\n", p.p / one, p.q / one);
    for (std::size_t t = 0; t < mesh.triangles.size(); t += 3) {
        out += "f";
        for (int k = 0; k < 3; ++k) out += fmt::format(" {0}/{0}/{0}", mesh.triangles[t + k] + 1);
        out += "\n";
    }
    return out;
}

namespace {

constexpr double kWidth = 720, kHeight = 760, kMargin = 60, kTop = 110;

void titles(SvgWriter& svg, const SurfaceMesh& mesh, const SurfaceRequest& r, const std::string& view) {
    svg.text(kMargin - 30, 36, fmt::format("ctess surface · {} · {}", r.name, view),
             "font-size=\"22\" font-weight=\"bold\" fill=\"#1b2838\"");
    svg.text(kMargin - 30, 62,
             fmt::format("{} vertices · {} triangles · chord error {:.2g}", mesh.params.size(),
                         mesh.triangles.size() / 3, mesh.chord_error),
             "font-size=\"15\" fill=\"#445\"");
    svg.text(kMargin - 30, 84, options_text(r), "font-size=\"14\" fill=\"#667\"");
}

} // namespace

std::string surface_to_param_svg(const SurfaceMesh& mesh, const SurfaceRequest& r) {
    SvgWriter svg(kWidth, kHeight);
    titles(svg, mesh, r, "parameter domain");
    const double side = std::min(kWidth - 2 * kMargin, kHeight - kTop - kMargin);
    const double x0 = (kWidth - side) / 2, y0 = kHeight - kMargin;
    const double one = adaptive::fixed_one;
    auto px = [&](std::uint32_t i) { return x0 + side * (mesh.params[i].p / one); };
    auto py = [&](std::uint32_t i) { return y0 - side * (mesh.params[i].q / one); };
    // Colour by level, from the mesh's coarsest (light) to its finest (dark): where it refined stands out.
    const auto [lo, hi] = std::minmax_element(mesh.levels.begin(), mesh.levels.end());
    const unsigned lo_level = lo == mesh.levels.end() ? 0 : *lo, hi_level = hi == mesh.levels.end() ? 0 : *hi;
    const double span = hi_level > lo_level ? hi_level - lo_level : 1;
    const double stroke = mesh.triangles.size() > 60000 ? 0.25 : mesh.triangles.size() > 6000 ? 0.4 : 0.8;
    svg.raw(fmt::format("<g stroke=\"#27445f\" stroke-width=\"{}\" stroke-linejoin=\"round\">\n", stroke));
    for (std::size_t t = 0; t < mesh.triangles.size(); t += 3) {
        double xy[6];
        for (int k = 0; k < 3; ++k) {
            xy[2 * k] = px(mesh.triangles[t + k]);
            xy[2 * k + 1] = py(mesh.triangles[t + k]);
        }
        const double depth = (mesh.levels[t / 3] - lo_level) / span;
        const auto mix = [&](int coarse, int fine) {
            return static_cast<int>(std::lround(coarse + (fine - coarse) * depth));
        };
        svg.polygon(xy, 3,
                    fmt::format("fill=\"#{:02x}{:02x}{:02x}\"", mix(238, 70), mix(244, 110), mix(250, 185)));
    }
    svg.raw("</g>\n");
    const std::string label = "font-size=\"15\" fill=\"#1b2838\"";
    svg.text(x0 - 12, y0 + 22, "(0,0)", label);
    svg.text(x0 + side - 22, y0 + 22, "u = 1", label);
    svg.text(x0 - 52, y0 - side + 5, "v = 1", label);
    svg.text(x0 + side / 2 - 150, y0 + 40,
             fmt::format("light: level {} (coarsest) · dark: level {} (finest)", lo_level, hi_level),
             "font-size=\"14\" fill=\"#667\"");
    return svg.finish();
}

std::string surface_to_shaded_svg(const SurfaceMesh& mesh, const SurfaceRequest& r) {
    SvgWriter svg(kWidth, kHeight);
    titles(svg, mesh, r, "shaded view");
    // A fixed orthographic camera: turn about z, then tilt towards the viewer.
    const bool flat = r.name == "ripple";
    const double azimuth = flat ? -0.55 : 0.6, elevation = flat ? 0.95 : 0.5;
    const double ca = std::cos(azimuth), sa = std::sin(azimuth), ce = std::cos(elevation),
                 se = std::sin(elevation);
    struct Projected {
        double x, y, depth;
    };
    std::vector<Projected> pts(mesh.vertices.size());
    double lo_x = 1e30, hi_x = -1e30, lo_y = 1e30, hi_y = -1e30;
    const double z_scale = flat ? 4.0 : 1.0; // the ripples are exaggerated vertically to be seen
    for (std::size_t i = 0; i < pts.size(); ++i) {
        const rt::Vec3 p = mesh.vertices[i].position;
        const double x = ca * p.x - sa * p.y, y = sa * p.x + ca * p.y, z = z_scale * p.z;
        pts[i] = {x, se * y + ce * z, ce * y - se * z}; // camera in front (-y) and above: screen up, depth
        lo_x = std::min(lo_x, pts[i].x), hi_x = std::max(hi_x, pts[i].x);
        lo_y = std::min(lo_y, pts[i].y), hi_y = std::max(hi_y, pts[i].y);
    }
    const double scale =
        std::min((kWidth - 2 * kMargin) / (hi_x - lo_x), (kHeight - kTop - kMargin) / (hi_y - lo_y));
    const double cx = kWidth / 2 - scale * (lo_x + hi_x) / 2, cy = kTop + (kHeight - kTop - kMargin) / 2;
    const double mid_y = (lo_y + hi_y) / 2;
    const std::size_t count = mesh.triangles.size() / 3;
    std::vector<std::size_t> order(count);
    std::iota(order.begin(), order.end(), std::size_t{0});
    auto depth = [&](std::size_t t) {
        return pts[mesh.triangles[3 * t]].depth + pts[mesh.triangles[3 * t + 1]].depth +
               pts[mesh.triangles[3 * t + 2]].depth;
    };
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return depth(a) > depth(b); });
    const double light[3] = {-0.45, 0.55, 0.7}; // in view space: from the upper left, towards the viewer
    const double stroke = count > 20000 ? 0.15 : 0.3;
    svg.raw(fmt::format("<g stroke=\"#3a1f2c\" stroke-opacity=\"0.45\" stroke-width=\"{}\" "
                        "stroke-linejoin=\"round\">\n",
                        stroke));
    for (std::size_t t : order) {
        double xy[6], n[3] = {0, 0, 0};
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t i = mesh.triangles[3 * t + k];
            xy[2 * k] = cx + scale * pts[i].x;
            xy[2 * k + 1] = cy - scale * (pts[i].y - mid_y);
            const rt::Vec3 nv = mesh.vertices[i].normal;
            const double x = ca * nv.x - sa * nv.y, y = sa * nv.x + ca * nv.y, z = nv.z;
            n[0] += x, n[1] += se * y + ce * z, n[2] += se * z - ce * y; // n[2] > 0: facing the viewer
        }
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (len > 0 && n[2] / len < -0.05 && !flat) continue; // back face of a closed surface
        const double lambert =
            len > 0 ? std::max(0.0, (n[0] * light[0] + n[1] * light[1] + n[2] * light[2]) / len) : 0;
        const double shade = 0.25 + 0.75 * lambert;
        const int rr = static_cast<int>(std::lround(235 * shade)),
                  gg = static_cast<int>(std::lround(150 * shade)),
                  bb = static_cast<int>(std::lround(180 * shade));
        svg.polygon(xy, 3, fmt::format("fill=\"#{:02x}{:02x}{:02x}\"", rr, gg, bb));
    }
    svg.raw("</g>\n");
    return svg.finish();
}

std::string surface_stats_json(const SurfaceMesh& mesh, const SurfaceRequest& r, const UniformComparison& u) {
    const std::size_t triangles = mesh.triangles.size() / 3;
    return fmt::format(
        "{{\"name\": \"{}\", \"angle\": {}, \"distance\": {}, \"min_level\": {}, \"max_level\": {}, "
        "\"vertices\": {}, \"triangles\": {}, \"max_chord_error\": {}, "
        "\"uniform_grid\": {{\"segments\": {}, \"triangles\": {}, \"max_chord_error\": {}, "
        "\"reached\": {}}}, \"triangle_ratio\": {:.4f}}}\n",
        json_escape(r.name), json_number(r.options.max_angle_deg), json_number(r.options.max_distance),
        r.options.min_level, r.options.max_level, mesh.params.size(), triangles,
        json_number(mesh.chord_error, true), u.segments, u.triangles, json_number(u.chord_error, true),
        u.reached ? "true" : "false", u.triangles ? static_cast<double>(triangles) / u.triangles : 0.0);
}

std::string strip_to_json(std::uint32_t u_segments, std::uint32_t v_segments,
                          std::span<const std::uint32_t> indices) {
    std::string out = fmt::format(
        "{{\"u_segments\": {}, \"v_segments\": {}, \"vertex_count\": {}, \"index_count\": {}, "
        "\"indices\": [",
        u_segments, v_segments, grid::grid_counts(u_segments, v_segments).vertices, indices.size());
    for (std::size_t i = 0; i < indices.size(); ++i) out += fmt::format("{}{}", i ? ", " : "", indices[i]);
    out += "]}\n";
    return out;
}

} // namespace ctess::cli
