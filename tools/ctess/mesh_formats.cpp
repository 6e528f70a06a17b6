#include "mesh_formats.hpp"
#include "json_escape.hpp"

#include "svg_writer.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

namespace ctess::cli {

std::string factors_text(const std::vector<float>& factors) {
    std::string s;
    for (std::size_t i = 0; i < factors.size(); ++i) s += fmt::format("{}{:g}", i ? ", " : "", factors[i]);
    return s;
}

std::string mesh_to_json(const Mesh& mesh, const PatternRequest& r) {
    std::string out = "{\n";
    out += fmt::format("  \"mode\": \"{}\",\n  \"domain\": \"{}\",\n", json_escape(r.mode),
                       json_escape(r.domain));
    out += "  \"factors\": [";
    for (std::size_t i = 0; i < r.factors.size(); ++i)
        out += fmt::format("{}{}", i ? ", " : "", r.factors[i]);
    out += "],\n";
    if (!is_d3d11_mode(r.mode)) {
        out += fmt::format("  \"max_tess_factor\": {},\n", r.max_factor);
        out += fmt::format("  \"layout\": \"{}\",\n", r.provoking_layout ? "provoking" : "shared");
    }
    if (mesh.uniform.table_max != 0) { // the integers the library used (docs/cli.md, "JSON")
        const auto& u = mesh.uniform;
        out +=
            fmt::format("  \"uniform_factors\": [{}, {}, {}],\n", u.factors[0], u.factors[1], u.factors[2]);
        out += fmt::format("  \"subpatch_count\": {},\n  \"split_depth\": {},\n", u.subpatches, u.depth);
    }
    out += fmt::format("  \"winding\": \"{}\",\n", r.ccw ? "ccw" : "cw");
    out += fmt::format("  \"fixed_one\": {},\n", mesh.fixed_one);
    out += fmt::format("  \"vertex_count\": {},\n", mesh.vertices.size());
    const bool lines = mesh.vertices_per_primitive == 2;
    out += fmt::format("  \"{}_count\": {},\n", lines ? "line" : "triangle", mesh.primitive_count());
    if (!lines) out += fmt::format("  \"degenerate_triangle_count\": {},\n", degenerate_triangles(mesh));
    out += "  \"vertices\": [";
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
        out += fmt::format("{}[{}, {}]", i ? ", " : "", mesh.vertices[i].u, mesh.vertices[i].v);
    out += fmt::format("],\n  \"{}\": [", lines ? "lines" : "triangles");
    for (std::size_t p = 0; p < mesh.primitive_count(); ++p) {
        out += p ? ", [" : "[";
        for (unsigned k = 0; k < mesh.vertices_per_primitive; ++k)
            out += fmt::format("{}{}", k ? ", " : "", mesh.indices[p * mesh.vertices_per_primitive + k]);
        out += "]";
    }
    out += "]\n}\n";
    return out;
}

std::string mesh_to_obj(const Mesh& mesh, const PatternRequest& r) {
    std::string out = fmt::format("# ctess pattern --mode {} --domain {} --factors {}\n", r.mode, r.domain,
                                  factors_text(r.factors));
    out += fmt::format("# vertices are (u, v, 0) domain coordinates; exact values are multiples of 1/{}\n",
                       mesh.fixed_one);
    const double one = mesh.fixed_one;
    for (const auto& p : mesh.vertices) out += fmt::format("v {:.9g} {:.9g} 0\n", p.u / one, p.v / one);
    const char* kind = mesh.vertices_per_primitive == 2 ? "l" : "f";
    for (std::size_t p = 0; p < mesh.primitive_count(); ++p) {
        out += kind;
        for (unsigned k = 0; k < mesh.vertices_per_primitive; ++k)
            out += fmt::format(" {}", mesh.indices[p * mesh.vertices_per_primitive + k] + 1);
        out += "\n";
    }
    return out;
}

namespace {

constexpr double kWidth = 720, kHeight = 700, kMargin = 70, kTop = 96;

// Domain -> picture. Triangles are drawn equilateral: (0,0) bottom left, (1,0) bottom right, (0,1) top;
// uniform-density triangles with their factors as side lengths (when those make a Euclidean triangle), so
// that equal intrinsic lengths look equal. Quads are drawn as a square with (0,0) bottom left.
struct Frame {
    bool square = false;
    double side = kWidth - 2 * kMargin;
    double ux = 1, vx = 0.5, vy = std::sqrt(3.0) / 2.0, x0 = 0; // v1 = (ux, 0), v2 = (vx, vy), unit width
    double bottom = kHeight - kMargin;                          // y of v = 0
    double x(double u, double v) const { return kMargin + side * (square ? u : x0 + u * ux + v * vx); }
    double y(double v) const { return bottom - side * (square ? v : v * vy); }
};

// The integer factors the library used (rounded; split above N) as side lengths.
void shape_uniform_frame(Frame& fr, const UniformUse& use) {
    const double a = use.factors[0], b = use.factors[1], c = use.factors[2];
    if (!(a < b + c && b < a + c && c < a + b)) return; // non-Euclidean: keep the equilateral frame
    const double x2 = (a * a + c * c - b * b) / (2 * a), y2 = std::sqrt(std::max(0.0, c * c - x2 * x2));
    const double lo = std::min(0.0, x2), hi = std::max(a, x2), width = hi - lo;
    fr.ux = a / width, fr.vx = x2 / width, fr.vy = y2 / width, fr.x0 = -lo / width;
}

} // namespace

std::string mesh_to_svg(const Mesh& mesh, const PatternRequest& r, const SvgOptions& options) {
    Frame fr;
    fr.square = r.domain != "tri";
    const bool uniform = mesh.uniform.table_max != 0;
    if (uniform) shape_uniform_frame(fr, mesh.uniform);
    // The uniform mode has one more header line (what the library used); the caption moves below it.
    const double top = kTop + (uniform && !options.caption.empty() ? 22 : 0);
    if (!fr.square)
        fr.side = std::min(kWidth - 2 * kMargin, (kHeight - kMargin - top) / fr.vy);
    else
        fr.side = std::min(kWidth - 2 * kMargin, kHeight - kMargin - top);
    // A flat uniform triangle leaves blank space under the header: shorten the picture by it (the v2 label
    // stays clear of the header). Not for animate's frames (a caption), which keep one size.
    const double blank = uniform && options.caption.empty() ? std::max(0.0, fr.y(1) - top - 24) : 0.0;
    fr.bottom -= blank;
    SvgWriter svg(kWidth, kHeight - blank);
    const double one = mesh.fixed_one;
    auto px = [&](std::uint32_t i) { return fr.x(mesh.vertices[i].u / one, mesh.vertices[i].v / one); };
    auto py = [&](std::uint32_t i) { return fr.y(mesh.vertices[i].v / one); };

    const std::string title = fmt::format("ctess · {} · factors ({})", r.mode, factors_text(r.factors));
    svg.text(kMargin - 40, 34, title, "font-size=\"22\" font-weight=\"bold\" fill=\"#1b2838\"");
    const std::size_t degenerate = degenerate_triangles(mesh);
    std::string stats = fmt::format("{} vertices · {} {}", mesh.vertices.size(), mesh.primitive_count(),
                                    mesh.vertices_per_primitive == 2 ? "line segments" : "triangles");
    if (mesh.vertices_per_primitive == 3) stats += fmt::format(" ({} zero-area, drawn red)", degenerate);
    if (!uniform && !is_d3d11_mode(r.mode)) stats += fmt::format(" · max factor {}", r.max_factor);
    svg.text(kMargin - 40, 60, stats, "font-size=\"15\" fill=\"#445\"");
    // Uniform: the integers used when they differ from the request (rounded), and the split.
    const auto& used = mesh.uniform.factors;
    const bool rounded = uniform && (r.factors[0] != float(used[0]) || r.factors[1] != float(used[1]) ||
                                     r.factors[2] != float(used[2]));
    double line_y = 82;
    if (uniform) {
        std::string what = fmt::format("uniform density, N = {}", mesh.uniform.table_max);
        if (rounded) what += fmt::format(" · used ({}, {}, {})", used[0], used[1], used[2]);
        what += mesh.uniform.subpatches > 1 ? fmt::format(" · split into {} subpatches, depth {}",
                                                          mesh.uniform.subpatches, mesh.uniform.depth)
                                            : std::string(" · one table pattern");
        svg.text(kMargin - 40, line_y, what, "font-size=\"14\" fill=\"#667\"");
        line_y += 22;
    }
    if (!options.caption.empty())
        svg.text(kMargin - 40, line_y, options.caption, "font-size=\"14\" fill=\"#667\"");

    if (mesh.vertices_per_primitive == 3) {
        for (std::size_t t = 0; t < mesh.primitive_count(); ++t) {
            double xy[6];
            for (int k = 0; k < 3; ++k) {
                xy[2 * k] = px(mesh.indices[3 * t + k]);
                xy[2 * k + 1] = py(mesh.indices[3 * t + k]);
            }
            const bool flat = doubled_area(mesh, t) == 0;
            svg.polygon(xy, 3,
                        flat ? "fill=\"none\" stroke=\"#d62728\" stroke-width=\"1.6\""
                             : (t % 2 ? "fill=\"#dbe7f4\" stroke=\"#27445f\" stroke-width=\"0.8\" "
                                        "stroke-linejoin=\"round\""
                                      : "fill=\"#eaf1f9\" stroke=\"#27445f\" stroke-width=\"0.8\" "
                                        "stroke-linejoin=\"round\""));
        }
        if (options.show_provoking) {
            // A dot inside each triangle, near its first (provoking) vertex.
            for (std::size_t t = 0; t < mesh.primitive_count(); ++t) {
                const auto a = mesh.indices[3 * t], b = mesh.indices[3 * t + 1], c = mesh.indices[3 * t + 2];
                const double cx = (px(a) + px(b) + px(c)) / 3, cy = (py(a) + py(b) + py(c)) / 3;
                svg.circle(0.65 * px(a) + 0.35 * cx, 0.65 * py(a) + 0.35 * cy, 2.2, "fill=\"#e07b00\"");
            }
            // Legend at the bottom left, where the widest label still fits at any font's width.
            svg.circle(kMargin - 34, kHeight - blank - 17, 5, "fill=\"#e07b00\"");
            svg.text(kMargin - 24, kHeight - blank - 11, "provoking (first) vertex of each triangle",
                     "font-size=\"16\" fill=\"#445\"");
        }
    } else {
        for (std::size_t p = 0; p < mesh.primitive_count(); ++p)
            svg.line(px(mesh.indices[2 * p]), py(mesh.indices[2 * p]), px(mesh.indices[2 * p + 1]),
                     py(mesh.indices[2 * p + 1]), "stroke=\"#27445f\" stroke-width=\"1.2\"");
    }
    const double radius = mesh.vertices.size() > 2000 ? 0.9 : mesh.vertices.size() > 300 ? 1.6 : 2.6;
    for (std::uint32_t i = 0; i < mesh.vertices.size(); ++i)
        svg.circle(px(i), py(i), radius, "fill=\"#1b2838\"");

    // Corner and edge labels, in the mode's own naming.
    const std::string label = "font-size=\"16\" fill=\"#1b2838\"";
    const std::string edge_label = "font-size=\"15\" fill=\"#2a6f3a\" font-weight=\"bold\"";
    if (!fr.square) {
        const bool cp_names = !is_d3d11_mode(r.mode);
        svg.text(fr.x(0, 0) - 34, fr.y(0) + 22, cp_names ? "v0" : "W (0,0)", label);
        svg.text(fr.x(1, 0) + 6, fr.y(0) + 22, cp_names ? "v1" : "U (1,0)", label);
        svg.text(fr.x(0, 1) - 14, fr.y(1) - 12, cp_names ? "v2" : "V (0,1)", label);
        const auto& f = r.factors;
        auto fv = [&](std::size_t i) {
            if (i >= f.size()) return std::string("?");
            if (uniform && f[i] != float(used[i])) return fmt::format("{:g} → {}", f[i], used[i]);
            return fmt::format("{:g}", f[i]);
        };
        const std::string bottom = cp_names ? "e0 = " + fv(0) : "Veq0 = " + fv(1);
        const std::string left = cp_names ? "e2 = " + fv(2) : "Ueq0 = " + fv(0);
        const std::string right = cp_names ? "e1 = " + fv(1) : "Weq0 = " + fv(2);
        svg.text(fr.x(0.5, 0) - 40, fr.y(0) + 40, bottom, edge_label);
        svg.text(fr.x(0, 0.5) - 110, fr.y(0.5), left, edge_label);
        // kept inside the picture when a shaped uniform triangle puts e1 at the right border (about 9.5 px
        // per character of the bold 15 px label)
        svg.text(std::min(fr.x(0.5, 0.5) + 16, kWidth - 6 - 9.5 * double(right.size())), fr.y(0.5), right,
                 edge_label);
        if (is_d3d11_mode(r.mode) && f.size() == 4)
            svg.text(fr.x(1, 0) - 150, fr.y(1) + 10, "inside = " + fv(3), edge_label);
    } else if (!is_d3d11_mode(r.mode)) { // a CP quad: corners q0..q3, edge k runs q_k -> q_(k+1)
        svg.text(fr.x(0, 0) - 30, fr.y(0) + 22, "q0", label);
        svg.text(fr.x(1, 0) + 6, fr.y(0) + 22, "q1", label);
        svg.text(fr.x(1, 1) + 6, fr.y(1) - 8, "q2", label);
        svg.text(fr.x(0, 1) - 30, fr.y(1) - 8, "q3", label);
        const auto& f = r.factors;
        svg.text(fr.x(0.5, 0) - 30, fr.y(0) + 40, fmt::format("f0 = {:g}", f[0]), edge_label);
        svg.text(fr.x(1, 0.5) + 8, fr.y(0.5), fmt::format("f1 = {:g}", f[1]), edge_label);
        svg.text(fr.x(0.5, 1) - 30, fr.y(1) - 10, fmt::format("f2 = {:g}", f[2]), edge_label);
        svg.text(fr.x(0, 0.5) - 66, fr.y(0.5), fmt::format("f3 = {:g}", f[3]), edge_label);
    } else {
        svg.text(fr.x(0, 0) - 46, fr.y(0) + 22, "(0,0)", label);
        svg.text(fr.x(1, 0) + 6, fr.y(0) + 22, "u = 1", label);
        svg.text(fr.x(0, 1) - 50, fr.y(1) - 8, "v = 1", label);
    }
    return svg.finish();
}

} // namespace ctess::cli
