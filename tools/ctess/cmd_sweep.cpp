// ctess sweep: the paths of an edge's points as the factor changes, as an SVG chart.
#include "cli_args.hpp"
#include "commands.hpp"
#include "file_output.hpp"
#include "svg_writer.hpp"

#include "line_modes.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/core.h>

namespace ctess::cli {

namespace {

constexpr double kW = 960, kH = 620, kLeft = 90, kRight = 30, kTop = 90, kBottom = 70;

// The axis' tick spacing: a power of two up to 128 leaving at most 16 intervals; past that (ranges above
// 2048, up to the float maximum) 1, 2 or 5 times a power of ten leaving at most 10, so the labels stay short.
// The grid never has more than 17 lines.
double tick_step(double range) {
    for (double s : {0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0, 128.0})
        if (range / s <= 16) return s;
    for (double decade = 100.0;; decade *= 10.0)
        for (double m : {1.0, 2.0, 5.0})
            if (range / (m * decade) <= 10) return m * decade;
}

// The chart draws one path segment per edge point per step: this bounds the work and the file's size
// (about 36 bytes a segment, so about 72 MB) before anything is computed.
constexpr std::uint64_t max_path_segments = 2'000'000;

} // namespace

int run_sweep(int argc, char** argv) {
    const Args args(argc, argv, 2, {"mode", "from", "to", "steps", "svg", "max"});
    const LineMode mode = line_mode_from(args.get_or("mode", "cp"));
    const float from = parse_float(args.get("from"), "--from");
    const float to = parse_float(args.get("to"), "--to");
    require_usable_factors({from, to}, "--from/--to");
    if (!(to > from)) throw UsageError("--to must be greater than --from");
    const unsigned steps = parse_unsigned(args.get_or("steps", "400"), "--steps", 2, 20000);
    const std::string out_path = args.get("svg");
    const unsigned max = max_factor_from(args);
    const double one = line_fixed_one(mode);
    // Point counts grow with the factor in every mode, so the larger end bounds every step.
    std::vector<std::uint32_t> probe(max_line_points);
    const std::uint64_t points_per_step =
        std::max(line_points(mode, from, max, probe.data()), line_points(mode, to, max, probe.data()));
    if (std::uint64_t{steps} * points_per_step > max_path_segments)
        throw UsageError(
            fmt::format("--steps {} with up to {} points per step would draw {} path segments; the "
                        "limit is {}: use fewer --steps",
                        steps, points_per_step, std::uint64_t{steps} * points_per_step, max_path_segments));

    const double plot_w = kW - kLeft - kRight, plot_h = kH - kTop - kBottom;
    auto X = [&](double f) { return kLeft + plot_w * (f - from) / (double(to) - from); };
    auto Y = [&](double p) { return kTop + plot_h * (1.0 - p); };

    SvgWriter svg(kW, kH);
    svg.text(kLeft - 60, 34,
             fmt::format("ctess sweep · {} · factor {:g} → {:g}", line_mode_name(mode), from, to),
             "font-size=\"22\" font-weight=\"bold\" fill=\"#1b2838\"");
    svg.text(kLeft - 60, 60,
             fmt::format("each curve is one edge point's parameter as the factor grows ({} steps); "
                         "a branch is a point being born",
                         steps),
             "font-size=\"14\" fill=\"#556\"");
    // Grid and axes.
    const double step = tick_step(double(to) - from);
    const double first_tick = std::ceil(from / step);
    for (unsigned k = 0; k <= 16; ++k) { // an index, not f += step: above 2^53 * step, f + step == f
        const double f = (first_tick + k) * step;
        if (f > to + 1e-9) break;
        svg.line(X(f), Y(0), X(f), Y(1), "stroke=\"#e3e6ea\" stroke-width=\"1\"");
        svg.text(X(f) - 10, Y(0) + 22, fmt::format("{:g}", f), "font-size=\"13\" fill=\"#334\"");
    }
    for (double p : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        svg.line(X(from), Y(p), X(to), Y(p), "stroke=\"#e3e6ea\" stroke-width=\"1\"");
        svg.text(kLeft - 44, Y(p) + 5, fmt::format("{:g}", p), "font-size=\"13\" fill=\"#334\"");
    }
    if (mode == LineMode::cp) { // token boundaries, where the sliding block changes
        for (unsigned t = 1; t < cp::token_count(max); ++t) {
            const double lo = cp::token_info(t).lo;
            if (lo <= from || lo >= to) continue;
            svg.line(X(lo), Y(0), X(lo), Y(1),
                     "stroke=\"#f0b27a\" stroke-width=\"1\" stroke-dasharray=\"4 3\"");
            svg.text(X(lo) + 2, Y(1) - 4, fmt::format("T{}", t), "font-size=\"11\" fill=\"#b9601a\"");
        }
    }
    svg.text(kLeft + plot_w / 2 - 50, kH - 22, "tess factor", "font-size=\"15\" fill=\"#1b2838\"");
    svg.raw(
        fmt::format("<text x=\"22\" y=\"{:.1f}\" font-size=\"15\" fill=\"#1b2838\" transform=\"rotate(-90 22 "
                    "{:.1f})\">edge parameter</text>\n",
                    kTop + plot_h / 2 + 50, kTop + plot_h / 2 + 50));
    svg.line(X(from), Y(0), X(to), Y(0), "stroke=\"#1b2838\" stroke-width=\"1.2\"");
    svg.line(X(from), Y(0), X(from), Y(1), "stroke=\"#1b2838\" stroke-width=\"1.2\"");

    // Paths: with an unchanged count, point i continues point i (lists are sorted and points keep their
    // order); when the count changes, each point is joined to the nearest point of the previous step.
    std::string path;
    std::vector<std::uint32_t> prev, cur(max_line_points);
    double prev_f = from;
    for (unsigned s = 0; s <= steps; ++s) {
        const double f = from + (double(to) - from) * s / steps;
        cur.resize(max_line_points);
        cur.resize(line_points(mode, static_cast<float>(f), max, cur.data()));
        if (s > 0 && !prev.empty()) {
            for (std::size_t i = 0; i < cur.size(); ++i) {
                const std::uint32_t p = cur[i];
                if (cur.size() == prev.size()) {
                    path += fmt::format("M{:.1f} {:.1f}L{:.1f} {:.1f}", X(prev_f), Y(prev[i] / one), X(f),
                                        Y(p / one));
                    continue;
                }
                auto it = std::lower_bound(prev.begin(), prev.end(), p);
                std::uint32_t q = it == prev.end() ? prev.back() : *it;
                if (it != prev.begin() && (it == prev.end() || p - *(it - 1) < *it - p)) q = *(it - 1);
                path += fmt::format("M{:.1f} {:.1f}L{:.1f} {:.1f}", X(prev_f), Y(q / one), X(f), Y(p / one));
            }
        }
        prev = cur;
        prev_f = f;
    }
    svg.raw("<path d=\"" + path +
            "\" fill=\"none\" stroke=\"#1f5f99\" stroke-width=\"1.3\" stroke-linecap=\"round\"/>\n");
    write_text(out_path, svg.finish());
    return 0;
}

} // namespace ctess::cli
