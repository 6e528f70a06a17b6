// SVG plots of the reports (ctess_report, ctess_wobble): a line plot with a legend and a horizontal bar plot,
// white background, sized for a README at 720 pixels wide.
#pragma once
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <fmt/core.h>

namespace ctess::report {

struct Series {
    std::string name, colour, dash;
    std::vector<std::pair<double, double>> points;
};

// Axis ticks at multiples of 1, 2, 2.5 or 5 times a power of ten, about `count` of them over [lo, hi].
inline std::vector<double> ticks(double lo, double hi, int count) {
    const double raw = (hi - lo) / count, decade = std::pow(10.0, std::floor(std::log10(raw)));
    double step = decade;
    for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
        if (m * decade >= raw) {
            step = m * decade;
            break;
        }
    std::vector<double> out;
    for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step)
        out.push_back(std::fabs(t) < 1e-9 * step ? 0.0 : t); // no "-0"

    return out;
}

inline std::string line_plot(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                             const std::vector<Series>& series) {
    const double W = 720, H = 420, L = 70, R = 215, T = 40, B = 50;
    double x0 = 1e300, x1 = -1e300, y1 = 0;
    for (const auto& s : series)
        for (const auto& [x, y] : s.points) x0 = std::min(x0, x), x1 = std::max(x1, x), y1 = std::max(y1, y);
    if (y1 <= 0) y1 = 1;
    std::vector<double> yt = ticks(0, y1, 4);
    const std::vector<double> xt = ticks(x0, x1, 6);
    if (yt.back() < y1) yt.push_back(yt.back() + (yt[1] - yt[0])); // the top line is a tick
    y1 = yt.back();
    auto px = [&](double x) { return L + (x - x0) / (x1 - x0) * (W - L - R); };
    auto py = [&](double y) { return H - B - y / y1 * (H - T - B); };
    std::string o =
        fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" "
                    "font-family=\"sans-serif\" font-size=\"13\">\n<rect width=\"100%\" height=\"100%\" "
                    "fill=\"white\"/>\n<text x=\"{}\" y=\"24\" font-size=\"16\">{}</text>\n",
                    W, H, L, title);
    for (double y : yt) {
        o += fmt::format("<line x1=\"{}\" y1=\"{:.1f}\" x2=\"{}\" y2=\"{:.1f}\" stroke=\"#ddd\"/>\n", L,
                         py(y), W - R, py(y));
        o += fmt::format("<text x=\"{}\" y=\"{:.1f}\" text-anchor=\"end\">{:.4g}</text>\n", L - 6, py(y) + 4,
                         y);
    }
    for (double x : xt)
        o += fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">{:.4g}</text>\n", px(x),
                         H - B + 18, x);
    o += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", (L + W - R) / 2, H - 10,
                     xlabel);
    o += fmt::format(
        "<text x=\"16\" y=\"{}\" transform=\"rotate(-90 16 {})\" text-anchor=\"middle\">{}</text>\n",
        (T + H - B) / 2, (T + H - B) / 2, ylabel);
    for (std::size_t k = 0; k < series.size(); ++k) {
        const Series& s = series[k];
        std::string pts;
        for (const auto& [x, y] : s.points) pts += fmt::format("{:.1f},{:.1f} ", px(x), py(y));
        const std::string dash = s.dash.empty() ? "" : fmt::format(" stroke-dasharray=\"{}\"", s.dash);
        o += fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"2\"{} points=\"{}\"/>\n",
                         s.colour, dash, pts);
        const double ly = T + 20 + 22.0 * k;
        o += fmt::format(
            "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"3\"{}/>\n",
            W - R + 12, ly, W - R + 36, ly, s.colour, dash);
        o += fmt::format("<text x=\"{}\" y=\"{}\">{}</text>\n", W - R + 42, ly + 4, s.name);
    }
    return o + "</svg>\n";
}

inline std::string bar_plot(const std::string& title, const std::vector<Series>& bars) {
    const double W = 720, L = 200, R = 60, T = 40, row = 34;
    const double H = T + row * bars.size() + 20;
    double vmax = 0;
    for (const auto& b : bars) vmax = std::max(vmax, b.points[0].second);
    std::string o =
        fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" "
                    "font-family=\"sans-serif\" font-size=\"13\">\n<rect width=\"100%\" height=\"100%\" "
                    "fill=\"white\"/>\n<text x=\"10\" y=\"24\" font-size=\"16\">{}</text>\n",
                    W, H, title);
    for (std::size_t k = 0; k < bars.size(); ++k) {
        const double y = T + row * k, w = bars[k].points[0].second / vmax * (W - L - R);
        o += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>\n", L - 8, y + 18,
                         bars[k].name);
        o += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{:.1f}\" height=\"24\" fill=\"{}\"/>\n", L, y + 2,
                         w, bars[k].colour);
        o += fmt::format("<text x=\"{:.1f}\" y=\"{}\">{:.2f}×</text>\n", L + w + 6, y + 18,
                         bars[k].points[0].second);
    }
    return o + "</svg>\n";
}

inline void write(const std::filesystem::path& path, const std::string& text) {
    std::ofstream f(path, std::ios::binary);
    f << text;
    if (!f) throw std::runtime_error("cannot write " + path.string());
}

} // namespace ctess::report
