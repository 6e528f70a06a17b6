// ctess_report: the quality report of CP against its peers (D3D11 fractional_even / fractional_odd / integer,
// OpenSubdiv's Bfr::Tessellation) on the same edge factors. Writes OUT_DIR/report.md and three SVG plots.
//
//   ./build/release/bench/ctess_report OUT_DIR [MACHINE_NAME]
//
// Generators are rows of one table (`generators` below): adding one (e.g. a uniform-density patch) is one
// function that fills a Pattern and one row. Every generator works in its own domain coordinates, converted
// to barycentric weights (w0, w1, w2); lengths and angles use the domain's own metric, the equilateral
// triangle with unit edges. Exit status 0, or 1 with a message.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/core.h>
#include <meshoptimizer.h>
#include <opensubdiv/bfr/parameterization.h>
#include <opensubdiv/bfr/tessellation.h>
#include <opensubdiv/sdc/types.h>

#include <ctess/cp_pattern.hpp>
#include <ctess/d3d11_tessellator.hpp>
#include <ctess/runtime/cp_patch.hpp>

#include "efficiency.hpp"

namespace {

using Factors = std::array<float, 3>;

// One tessellation: barycentric weights per vertex, three indices per triangle.
struct Pattern {
    std::vector<std::array<double, 3>> w;
    std::vector<std::uint32_t> indices;
};

// ---- generators ----

void cp_pattern(const Factors& f, Pattern& out) {
    static std::vector<ctess::DomainPoint> v(ctess::cp::max_pattern_counts(256).vertices);
    static std::vector<std::uint32_t> i(3 * ctess::cp::max_pattern_counts(256).triangles);
    ctess::cp::PatternOptions opt;
    opt.max_factor = 64;
    const ctess::Counts n = ctess::cp::tessellate(v.data(), i.data(), f[0], f[1], f[2], opt);
    out.w.resize(n.vertices);
    const double one = ctess::cp::fixed_one;
    for (std::uint32_t k = 0; k < n.vertices; ++k)
        out.w[k] = {(one - v[k].u - v[k].v) / one, v[k].u / one, v[k].v / one};
    out.indices.assign(i.begin(), i.begin() + 3 * n.triangles);
}

// D3D11 edge factor k is the edge opposite domain vertex k; inside = the average of the edges (ctess
// efficiency's second baseline).
template <ctess::d3d11::Partitioning P>
void d3d11_pattern(const Factors& f, Pattern& out) {
    static std::vector<ctess::DomainPoint> v(ctess::d3d11::max_tri_counts.vertices);
    static std::vector<std::uint32_t> i(ctess::d3d11::max_tri_counts.index_count());
    const ctess::d3d11::TessOptions opt{P, ctess::Winding::ccw};
    const float inside = (f[0] + f[1] + f[2]) / 3.0f;
    const ctess::Counts n = ctess::d3d11::tessellate_tri(v.data(), i.data(), {f[0], f[1], f[2], inside}, opt);
    out.w.resize(n.vertices);
    const double one = 65536.0;
    for (std::uint32_t k = 0; k < n.vertices; ++k)
        out.w[k] = {(one - v[k].u - v[k].v) / one, v[k].u / one, v[k].v / one};
    out.indices.assign(i.begin(), i.begin() + n.index_count());
}

// OpenSubdiv: integer rates, ceil of each factor (a rate never under-tessellates the requested factor).
namespace Bfr = OpenSubdiv::Bfr;
void osd_pattern(const Factors& f, Pattern& out) {
    static const Bfr::Parameterization param{OpenSubdiv::Sdc::SCHEME_LOOP, 3};
    Bfr::Tessellation::Options options;
    options.SetFacetSize(3);
    int rates[3];
    for (int k = 0; k < 3; ++k) rates[k] = std::max(1, static_cast<int>(std::ceil(f[k])));
    const Bfr::Tessellation t(param, 3, rates, options);
    std::vector<float> uv(2 * static_cast<std::size_t>(t.GetNumCoords()));
    std::vector<int> facets(3 * static_cast<std::size_t>(t.GetNumFacets()));
    t.GetCoords(uv.data());
    t.GetFacets(facets.data());
    out.w.resize(uv.size() / 2);
    for (std::size_t k = 0; k < out.w.size(); ++k) {
        const double u = uv[2 * k], v = uv[2 * k + 1];
        out.w[k] = {1.0 - u - v, u, v};
    }
    out.indices.assign(facets.begin(), facets.end());
}

// Emission only (what a renderer calls per patch), for the speed column: returns the triangle count.
std::uint32_t cp_emit(const Factors& f) {
    static std::vector<ctess::DomainPoint> v(ctess::cp::max_pattern_counts(64).vertices);
    static std::vector<std::uint32_t> i(3 * ctess::cp::max_pattern_counts(64).triangles);
    const ctess::rt::CpPatch patch(ctess::rt::cp_tables_64, f[0], f[1], f[2]);
    patch.emit(v, i);
    return patch.triangle_count();
}
template <ctess::d3d11::Partitioning P>
std::uint32_t d3d11_emit(const Factors& f) {
    static std::vector<ctess::DomainPoint> v(ctess::d3d11::max_tri_counts.vertices);
    static std::vector<std::uint32_t> i(ctess::d3d11::max_tri_counts.index_count());
    const ctess::d3d11::TessOptions opt{P, ctess::Winding::ccw};
    return ctess::d3d11::tessellate_tri(v.data(), i.data(), {f[0], f[1], f[2], (f[0] + f[1] + f[2]) / 3.0f},
                                        opt)
        .triangles;
}
std::uint32_t osd_emit(const Factors& f) {
    static const Bfr::Parameterization param{OpenSubdiv::Sdc::SCHEME_LOOP, 3};
    static std::vector<float> uv(2 * 4096 * 8);
    static std::vector<int> facets(3 * 4096 * 8);
    Bfr::Tessellation::Options options;
    options.SetFacetSize(3);
    int rates[3];
    for (int k = 0; k < 3; ++k) rates[k] = std::max(1, static_cast<int>(std::ceil(f[k])));
    const Bfr::Tessellation t(param, 3, rates, options);
    t.GetCoords(uv.data());
    t.GetFacets(facets.data());
    return static_cast<std::uint32_t>(t.GetNumFacets());
}

struct Generator {
    const char* name;
    const char* colour;
    void (*pattern)(const Factors&, Pattern&);
    std::uint32_t (*emit)(const Factors&);
};

// The hook: one row per generator.
const Generator generators[] = {
    {"CP", "#d62728", cp_pattern, cp_emit},
    {"D3D11 fractional_even", "#1f77b4", d3d11_pattern<ctess::d3d11::Partitioning::fractional_even>,
     d3d11_emit<ctess::d3d11::Partitioning::fractional_even>},
    {"D3D11 fractional_odd", "#2ca02c", d3d11_pattern<ctess::d3d11::Partitioning::fractional_odd>,
     d3d11_emit<ctess::d3d11::Partitioning::fractional_odd>},
    {"D3D11 integer", "#9467bd", d3d11_pattern<ctess::d3d11::Partitioning::integer>,
     d3d11_emit<ctess::d3d11::Partitioning::integer>},
    {"OpenSubdiv", "#ff7f0e", osd_pattern, osd_emit},
};

// ---- measures ----

struct Point2 {
    double x, y;
};
Point2 to_metric(const std::array<double, 3>& w) { // equilateral triangle, unit edges
    return {w[1] + 0.5 * w[2], w[2] * std::sqrt(3.0) / 2.0};
}
double dist(Point2 a, Point2 b) {
    return std::hypot(a.x - b.x, a.y - b.y);
}

struct Quality {
    std::size_t triangles = 0, zero_area = 0, vertices = 0;
    double acmr16 = 0, atvr16 = 0, acmr32 = 0, atvr32 = 0;
    double longest_edge = 0, smallest_angle = 180; // over the triangles of non-zero area, degrees
};

Quality measure(const Pattern& p) {
    Quality q;
    q.triangles = p.indices.size() / 3;
    q.vertices = p.w.size();
    for (std::size_t t = 0; t < q.triangles; ++t) {
        const Point2 a = to_metric(p.w[p.indices[3 * t]]), b = to_metric(p.w[p.indices[3 * t + 1]]),
                     c = to_metric(p.w[p.indices[3 * t + 2]]);
        const double area2 = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        const double ab = dist(a, b), bc = dist(b, c), ca = dist(c, a);
        if (std::fabs(area2) <= 1e-12) {
            ++q.zero_area;
            continue;
        }
        q.longest_edge = std::max({q.longest_edge, ab, bc, ca});
        auto angle = [](double opposite, double s1, double s2) {
            return std::acos(
                       std::clamp((s1 * s1 + s2 * s2 - opposite * opposite) / (2 * s1 * s2), -1.0, 1.0)) *
                   180.0 / 3.14159265358979323846;
        };
        q.smallest_angle =
            std::min({q.smallest_angle, angle(bc, ab, ca), angle(ca, ab, bc), angle(ab, bc, ca)});
    }
    const auto s16 = meshopt_analyzeVertexCache(p.indices.data(), p.indices.size(), p.w.size(), 16, 0, 0);
    const auto s32 = meshopt_analyzeVertexCache(p.indices.data(), p.indices.size(), p.w.size(), 32, 0, 0);
    q.acmr16 = s16.acmr;
    q.atvr16 = s16.atvr;
    q.acmr32 = s32.acmr;
    q.atvr32 = s32.atvr;
    return q;
}

// A pattern split by where its vertices lie: corners, the points of each edge (their parameter along it, in
// order), and the interior points in output order.
struct Places {
    std::array<Point2, 3> corner{};
    std::array<std::vector<double>, 3> edge; // edge k: opposite corner k (w_k = 0), parameter w_{k+1}
    std::vector<Point2> interior;
};
Places places(const Pattern& p) {
    Places out;
    for (const auto& w : p.w) {
        int zeros = 0, zero = 0;
        for (int k = 0; k < 3; ++k)
            if (std::fabs(w[k]) <= 1e-9) ++zeros, zero = k;
        if (zeros >= 2) {
            const int corner = w[0] > w[1] ? (w[0] > w[2] ? 0 : 2) : (w[1] > w[2] ? 1 : 2);
            out.corner[corner] = to_metric(w);
        } else if (zeros == 1) {
            out.edge[zero].push_back(w[(zero + 1) % 3]);
        } else {
            out.interior.push_back(to_metric(w));
        }
    }
    for (auto& e : out.edge) {
        std::sort(e.begin(), e.end());
        e.erase(std::unique(e.begin(), e.end()), e.end()); // a provoking copy is the same point
    }
    return out;
}

// Edge points keep their identity in order: between two steps, the points of the shorter list are matched to
// the longer list's in order, choosing the points that appear (or disappear) so that the total move is
// least. Returns the path length (parameter = length along the unit edge) and the count left unmatched.
std::pair<double, std::size_t> edge_moves(const std::vector<double>& a, const std::vector<double>& b) {
    const std::vector<double>& s = a.size() <= b.size() ? a : b;
    const std::vector<double>& l = a.size() <= b.size() ? b : a;
    const std::size_t n = s.size(), m = l.size();
    std::vector<double> dp(m + 1, 0.0), next(m + 1);
    for (std::size_t i = 1; i <= n; ++i) {
        next[0] = 1e300;
        for (std::size_t j = 1; j <= m; ++j)
            next[j] = std::min(next[j - 1], dp[j - 1] + std::fabs(s[i - 1] - l[j - 1]));
        dp.swap(next);
    }
    return {dp[m], m - n};
}

// Interior points have no order to keep: the closest pairs (within r, a bound on one step's move) are matched
// first, each point at most once; the rest appear or vanish. Returns the path length and the unmatched count.
std::pair<double, std::size_t> interior_moves(const std::vector<Point2>& a, const std::vector<Point2>& b,
                                              double r) {
    const int cells = static_cast<int>(std::ceil(1.0 / r)) + 1;
    std::vector<std::vector<std::uint32_t>> grid(static_cast<std::size_t>(cells) * cells);
    auto cell = [&](double x) { return std::clamp(static_cast<int>(x / r), 0, cells - 1); };
    for (std::uint32_t j = 0; j < b.size(); ++j) grid[cell(b[j].y) * cells + cell(b[j].x)].push_back(j);
    std::vector<std::tuple<double, std::uint32_t, std::uint32_t>> pairs;
    for (std::uint32_t i = 0; i < a.size(); ++i) {
        const int cx = cell(a[i].x), cy = cell(a[i].y);
        for (int y = std::max(0, cy - 1); y <= std::min(cells - 1, cy + 1); ++y)
            for (int x = std::max(0, cx - 1); x <= std::min(cells - 1, cx + 1); ++x)
                for (std::uint32_t j : grid[y * cells + x]) {
                    const double d = dist(a[i], b[j]);
                    if (d <= r) pairs.push_back({d, i, j});
                }
    }
    std::sort(pairs.begin(), pairs.end());
    std::vector<bool> used_a(a.size()), used_b(b.size());
    double total = 0;
    std::size_t matched = 0;
    for (const auto& [d, i, j] : pairs) {
        if (used_a[i] || used_b[j]) continue;
        used_a[i] = used_b[j] = true;
        total += d;
        ++matched;
    }
    return {total, a.size() + b.size() - 2 * matched};
}

struct Movement {
    double all = 0, edges = 0; // path length per unit factor change
    std::size_t unmatched = 0; // vertices without a partner in the next step (appear or disappear)
    std::vector<std::pair<double, double>> cumulative; // factor, edge-point path length so far
};

// Sweep from `from` to `to` in `steps` equal steps.
Movement sweep(const Generator& g, const Factors& from, const Factors& to, int steps) {
    Movement m;
    Pattern p;
    auto at = [&](int s) {
        const double t = double(s) / steps;
        Factors f;
        for (int k = 0; k < 3; ++k) f[k] = static_cast<float>(from[k] + (to[k] - from[k]) * t);
        return f;
    };
    g.pattern(at(0), p);
    Places prev = places(p);
    double total = 0, edges = 0;
    m.cumulative.push_back({from[0], 0});
    for (int s = 1; s <= steps; ++s) {
        g.pattern(at(s), p);
        Places next = places(p);
        for (int k = 0; k < 3; ++k) {
            total += dist(prev.corner[k], next.corner[k]);
            const auto [d, unmatched] = edge_moves(prev.edge[k], next.edge[k]);
            edges += d;
            total += d;
            m.unmatched += unmatched;
        }
        // A persistent point moves less than the point spacing (1 / factor) per step.
        const Factors f = at(s);
        const double r = 1.5 / std::max({1.0f, f[0], f[1], f[2]});
        const auto [d, unmatched] = interior_moves(prev.interior, next.interior, r);
        total += d;
        m.unmatched += unmatched;
        m.cumulative.push_back({at(s)[0], edges});
        prev = std::move(next);
    }
    double span = 0;
    for (int k = 0; k < 3; ++k) span = std::max(span, double(std::fabs(to[k] - from[k])));
    m.all = total / span;
    m.edges = edges / span;
    return m;
}

// Triangles per second of `emit` over the factor sets, several rounds, the best round kept.
double emission_rate(const Generator& g, const std::vector<Factors>& sets) {
    double best = 0;
    for (int round = 0; round < 5; ++round) {
        std::uint64_t triangles = 0;
        const auto start = std::chrono::steady_clock::now();
        for (int rep = 0; rep < 20; ++rep)
            for (const Factors& f : sets) triangles += g.emit(f);
        const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        best = std::max(best, double(triangles) / s);
    }
    return best;
}

// ---- SVG ----

struct Series {
    std::string name, colour;
    std::vector<std::pair<double, double>> points;
};

std::string line_plot(const std::string& title, const std::string& xlabel, const std::string& ylabel,
                      const std::vector<Series>& series) {
    const double W = 720, H = 420, L = 70, R = 200, T = 40, B = 50;
    double x0 = 1e300, x1 = -1e300, y1 = 0;
    for (const auto& s : series)
        for (const auto& [x, y] : s.points) x0 = std::min(x0, x), x1 = std::max(x1, x), y1 = std::max(y1, y);
    if (y1 <= 0) y1 = 1;
    auto px = [&](double x) { return L + (x - x0) / (x1 - x0) * (W - L - R); };
    auto py = [&](double y) { return H - B - y / y1 * (H - T - B); };
    std::string o =
        fmt::format("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" "
                    "font-family=\"sans-serif\" font-size=\"13\">\n<rect width=\"100%\" height=\"100%\" "
                    "fill=\"white\"/>\n<text x=\"{}\" y=\"24\" font-size=\"16\">{}</text>\n",
                    W, H, L, title);
    for (int k = 0; k <= 4; ++k) {
        const double y = y1 * k / 4, x = x0 + (x1 - x0) * k / 4;
        o += fmt::format("<line x1=\"{}\" y1=\"{:.1f}\" x2=\"{}\" y2=\"{:.1f}\" stroke=\"#ddd\"/>\n", L,
                         py(y), W - R, py(y));
        o += fmt::format("<text x=\"{}\" y=\"{:.1f}\" text-anchor=\"end\">{:.4g}</text>\n", L - 6, py(y) + 4,
                         y);
        o += fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">{:.4g}</text>\n", px(x),
                         H - B + 18, x);
    }
    o += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", (L + W - R) / 2, H - 10,
                     xlabel);
    o += fmt::format(
        "<text x=\"16\" y=\"{}\" transform=\"rotate(-90 16 {})\" text-anchor=\"middle\">{}</text>\n",
        (T + H - B) / 2, (T + H - B) / 2, ylabel);
    for (std::size_t k = 0; k < series.size(); ++k) {
        const Series& s = series[k];
        std::string pts;
        for (const auto& [x, y] : s.points) pts += fmt::format("{:.1f},{:.1f} ", px(x), py(y));
        o += fmt::format("<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"2\" points=\"{}\"/>\n",
                         s.colour, pts);
        const double ly = T + 20 + 22.0 * k;
        o += fmt::format("<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{}\" stroke-width=\"3\"/>\n",
                         W - R + 12, ly, W - R + 36, ly, s.colour);
        o += fmt::format("<text x=\"{}\" y=\"{}\">{}</text>\n", W - R + 42, ly + 4, s.name);
    }
    return o + "</svg>\n";
}

std::string bar_plot(const std::string& title, const std::vector<Series>& bars) {
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

void write(const std::filesystem::path& path, const std::string& text) {
    std::ofstream f(path, std::ios::binary);
    f << text;
    if (!f) throw std::runtime_error("cannot write " + path.string());
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: ctess_report OUT_DIR [MACHINE_NAME]\n");
        return 1;
    }
    const std::filesystem::path dir = argv[1];
    const std::string machine = argc > 2 ? argv[2] : "unnamed machine";
    try {
        std::filesystem::create_directories(dir);
        // The factor sets of `ctess efficiency` (equal, two high one low, 40 seeded random triples).
        const auto rows = ctess::cli::efficiency_rows(64, 40, 2026);
        std::vector<Factors> sets;
        for (const auto& r : rows) sets.push_back({r.factors[0], r.factors[1], r.factors[2]});

        std::string md = "# ctess quality report: CP against its peers\n\n";
        md += fmt::format(
            "Machine: {}. Written by `bench/ctess_report` (bench/README.md); ratios carry the claims, "
            "absolute times belong to this machine only.\n\n",
            machine);
        md += "Generators: CP (max factor 64, the library's `cp::tessellate`; speed from the runtime's "
              "`CpPatch::emit`), D3D11 `tessellate_tri` with inside = average of the edges, OpenSubdiv "
              "`Bfr::Tessellation` (Loop triangle, rates = ceil of each factor). Lengths and angles are "
              "measured "
              "in the domain's own metric: the equilateral triangle with unit edges.\n\n";

        // Per-set table and group means.
        md += "## Per factor set\n\n| group | factors | generator | triangles | zero-area | vertices | ACMR "
              "16 | "
              "ATVR 16 | ACMR 32 | ATVR 32 | longest edge | smallest angle "
              "|\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
        struct Mean {
            double tri = 0, zero = 0, acmr16 = 0, atvr16 = 0, acmr32 = 0, atvr32 = 0, edge = 0, angle = 180;
            std::size_t n = 0;
        };
        std::map<std::pair<std::string, std::string>, Mean> means;
        std::vector<double> cp_tris(rows.size());
        Pattern p;
        for (std::size_t r = 0; r < rows.size(); ++r) {
            for (const Generator& g : generators) {
                g.pattern(sets[r], p);
                const Quality q = measure(p);
                if (&g == &generators[0]) cp_tris[r] = double(q.triangles);
                md += fmt::format(
                    "| {} | {:.2f}, {:.2f}, {:.2f} | {} | {} | {} | {} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | "
                    "{:.4f} | {:.2f}° |\n",
                    rows[r].group, sets[r][0], sets[r][1], sets[r][2], g.name, q.triangles, q.zero_area,
                    q.vertices, q.acmr16, q.atvr16, q.acmr32, q.atvr32, q.longest_edge, q.smallest_angle);
                Mean& m = means[{rows[r].group, g.name}];
                m.tri += double(q.triangles) / cp_tris[r];
                m.zero += double(q.zero_area);
                m.acmr16 += q.acmr16;
                m.atvr16 += q.atvr16;
                m.acmr32 += q.acmr32;
                m.atvr32 += q.atvr32;
                m.edge = std::max(m.edge, q.longest_edge);
                m.angle = std::min(m.angle, q.smallest_angle);
                ++m.n;
            }
        }
        std::string summary =
            "## Summary per group\n\nTriangles are the mean ratio to CP's on the same set; zero-area "
            "the mean count per patch; cache figures are means; edge and angle the worst over the "
            "group.\n\n| group | generator | triangles / CP | zero-area per patch | ACMR 16 | ATVR 16 | "
            "ACMR 32 | ATVR 32 | longest edge | smallest angle "
            "|\n|---|---|---|---|---|---|---|---|---|---|\n";
        for (const char* group : {"equal", "two high, one low", "random"})
            for (const Generator& g : generators) {
                const Mean& m = means[{group, g.name}];
                const double n = double(m.n);
                summary += fmt::format(
                    "| {} | {} | {:.3f} | {:.2f} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {:.4f} | {:.2f}° |\n",
                    group, g.name, m.tri / n, m.zero / n, m.acmr16 / n, m.atvr16 / n, m.acmr32 / n,
                    m.atvr32 / n, m.edge, m.angle);
            }

        // Triangles against an equal factor.
        std::vector<Series> tri_series, move_series, speed_bars;
        for (const Generator& g : generators) {
            Series s{g.name, g.colour, {}};
            for (int k = 0; k <= 63 * 8; ++k) {
                const float f = 1.0f + k / 8.0f;
                g.pattern({f, f, f}, p);
                s.points.push_back({f, double(p.indices.size() / 3)});
            }
            tri_series.push_back(s);
        }
        write(dir / "triangles.svg", line_plot("Triangles against the factor (all three edges equal)",
                                               "factor", "triangles", tri_series));

        // Movement along sweeps.
        struct Sweep {
            const char* name;
            Factors from, to;
        };
        const Sweep sweeps[] = {{"equal 2 → 16", {2, 2, 2}, {16, 16, 16}},
                                {"one edge 2 → 16 (others 8)", {2, 8, 8}, {16, 8, 8}},
                                {"equal 16 → 64", {16, 16, 16}, {64, 64, 64}}};
        const int steps_per_unit = 16;
        std::string moves = fmt::format(
            "## Vertex movement over factor sweeps\n\nEach sweep takes {} steps per unit "
            "of factor. Vertices keep their identity in the pattern as follows: corners are "
            "corners; on each edge the points are taken in order along the edge, and between "
            "two steps the shorter list is matched to the longer in order, the points that "
            "appear (or vanish) being chosen so that the total move is least (a point that is "
            "inserted is not a move; its slide afterwards is); interior points carry no order, "
            "so the closest pairs within 1.5 / factor (more than one step's move of a "
            "persistent point, less than the point spacing) are matched first, each point once, "
            "and the rest appear or vanish. Path length is the sum of the matched vertices' "
            "moves per unit factor change (domain metric, edge = 1); unmatched counts the "
            "appearances and disappearances over the sweep. The edge rule is exact; the "
            "interior rule approximates identity by nearest match.\n\n| sweep | generator | "
            "path length per unit (all) | ratio "
            "to CP | edge points only | ratio to CP | unmatched |\n|---|---|---|---|---|---|---|\n",
            steps_per_unit);
        for (const Sweep& sw : sweeps) {
            double cp_all = 0, cp_edges = 0;
            for (const Generator& g : generators) {
                const int steps = static_cast<int>(
                    std::lround(steps_per_unit *
                                std::max({std::fabs(sw.to[0] - sw.from[0]), std::fabs(sw.to[1] - sw.from[1]),
                                          std::fabs(sw.to[2] - sw.from[2])})));
                const Movement m = sweep(g, sw.from, sw.to, steps);
                if (&g == &generators[0]) cp_all = m.all, cp_edges = m.edges;
                moves += fmt::format(
                    "| {} | {} | {:.4f} | {:.2f} | {:.4f} | {} | {} |\n", sw.name, g.name, m.all,
                    m.all / cp_all, m.edges,
                    cp_edges > 0 ? fmt::format("{:.2f}", m.edges / cp_edges) : std::string("—"), m.unmatched);
                if (&sw == &sweeps[0]) move_series.push_back({g.name, g.colour, m.cumulative});
            }
        }
        write(dir / "movement.svg", line_plot("Edge-point movement, equal factors 2 → 16: cumulative path",
                                              "factor", "path length (edge = 1)", move_series));

        // Emission speed over the report's factor sets, relative to CP.
        std::string speed =
            "## Emission speed\n\nTriangles per second over all the factor sets above (best of 5 "
            "rounds of 20 passes), relative to CP's runtime `CpPatch::emit`. One run, one core.\n\n"
            "| generator | relative to CP |\n|---|---|\n";
        const double cp_rate = emission_rate(generators[0], sets);
        for (const Generator& g : generators) {
            const double rate = &g == &generators[0] ? cp_rate : emission_rate(g, sets);
            speed += fmt::format("| {} | {:.2f} |\n", g.name, rate / cp_rate);
            speed_bars.push_back({g.name, g.colour, {{0, rate / cp_rate}}});
        }
        write(dir / "speed.svg",
              bar_plot("Emission speed relative to CP (triangles per second)", speed_bars));

        md += "\n" + summary + "\n![triangles](triangles.svg)\n\n" + moves +
              "\n![movement](movement.svg)\n\n" + speed + "\n![speed](speed.svg)\n";
        // Put the summaries first: move the per-set table to the end.
        const std::size_t per_set = md.find("## Per factor set");
        const std::size_t per_set_end = md.find("\n## Summary per group");
        const std::string table = md.substr(per_set, per_set_end - per_set);
        md.erase(per_set, per_set_end - per_set + 1);
        md += "\n" + table;
        write(dir / "report.md", md);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ctess_report: %s\n", e.what());
        return 1;
    }
    return 0;
}
