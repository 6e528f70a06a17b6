// ctess_report: the quality report of CP against its peers (D3D11 fractional_even / fractional_odd / integer,
// OpenSubdiv's Bfr::Tessellation, ctess's uniform density) on the same edge factors. Writes
// OUT_DIR/report.md and three SVG plots.
//
//   ./build/release/bench/ctess_report OUT_DIR [MACHINE_NAME]
//
// Generators are rows of one table (`generators` below): adding one is a function that fills a Pattern, an
// emit function and one row. Every generator works in its own domain coordinates, converted
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
#include <stdexcept>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/core.h>
#include <meshoptimizer.h>
#include <opensubdiv/bfr/parameterization.h>
#include <opensubdiv/bfr/tessellation.h>
#include <opensubdiv/sdc/types.h>

#include <ctess/cp/pattern.hpp>
#include <ctess/d3d11/tessellator.hpp>
#include <ctess/runtime/cp/patch.hpp>
#include <ctess/runtime/uniform/patch.hpp>
#include <ctess/runtime/uniform/split.hpp>

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
    const ctess::Counts n = ctess::cp::tessellate(v, i, f[0], f[1], f[2], opt);
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
    static std::vector<ctess::d3d11::Point> v(ctess::d3d11::max_tri_counts.vertices);
    static std::vector<std::uint32_t> i(ctess::d3d11::max_tri_counts.index_count());
    const ctess::d3d11::TessOptions opt{P, ctess::Winding::ccw};
    const float inside = (f[0] + f[1] + f[2]) / 3.0f;
    const ctess::Counts n = ctess::d3d11::tessellate_tri(v, i, {f[0], f[1], f[2], inside}, opt);
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
        // Points of the edge u + v = 1 come as floats whose sum misses 1 by a rounding residue: snap it, so
        // that they count as edge points (the movement measure classifies points by w = 0).
        const double w = 1.0 - u - v;
        out.w[k] = {std::fabs(w) < 1e-6 ? 0.0 : w, u, v};
    }
    out.indices.assign(facets.begin(), facets.end());
}

// Uniform density (docs/algorithm.md §3): integer factors (each rounded, halves up). The configured table's
// UniformPatch when every factor fits the table (at most N after rounding), UniformSplit (§3.5) above it.
bool uniform_fits(const Factors& f) {
    const std::uint32_t n = ctess::rt::uniform_tables.max_factor;
    return ctess::uniform::within_table(f[0], n) && ctess::uniform::within_table(f[1], n) &&
           ctess::uniform::within_table(f[2], n);
}
// Emits a uniform patch into v and i (grown as needed) and returns its counts.
template <class Patch>
ctess::Counts uniform_emit_into(const Patch& patch, std::vector<typename Patch::point_type>& v,
                                std::vector<std::uint32_t>& i) {
    const ctess::Counts n = patch.counts();
    if (v.size() < n.vertices) v.resize(n.vertices);
    if (i.size() < n.index_count()) i.resize(n.index_count());
    if (!patch.emit(v, i)) throw std::runtime_error("uniform emit refused its buffers");
    return n;
}
// The barycentric weights of points in units of Point::one.
template <class Point>
void uniform_weights(std::span<const Point> v, Pattern& out) {
    const double one = Point::one;
    out.w.resize(v.size());
    for (std::size_t k = 0; k < v.size(); ++k)
        out.w[k] = {(one - v[k].u - v[k].v) / one, v[k].u / one, v[k].v / one};
}
void uniform_pattern(const Factors& f, Pattern& out) {
    static std::vector<ctess::uniform::Point> v;
    static std::vector<ctess::uniform::SplitPoint> vs;
    static std::vector<std::uint32_t> i;
    ctess::Counts n;
    if (uniform_fits(f)) {
        n = uniform_emit_into(ctess::rt::UniformPatch(ctess::rt::uniform_tables, f[0], f[1], f[2]), v, i);
        uniform_weights(std::span<const ctess::uniform::Point>(v.data(), n.vertices), out);
    } else {
        n = uniform_emit_into(ctess::rt::UniformSplit(ctess::rt::uniform_tables, f[0], f[1], f[2]), vs, i);
        uniform_weights(std::span<const ctess::uniform::SplitPoint>(vs.data(), n.vertices), out);
    }
    out.indices.assign(i.begin(), i.begin() + n.index_count());
}

// Emission only (what a renderer calls per patch), for the speed column: returns the triangle count. CP: the
// fastest bulk path of the runtime, CpPatchSetup (counts and emit, no random-access buckets) in the shared
// layout (bench/README.md).
std::uint32_t cp_emit(const Factors& f) {
    static std::vector<ctess::DomainPoint> v(ctess::cp::max_pattern_counts(64).vertices);
    static std::vector<std::uint32_t> i(3 * ctess::cp::max_pattern_counts(64).triangles);
    const ctess::rt::CpPatchSetup patch(ctess::rt::cp_tables_64, f[0], f[1], f[2], {ctess::Layout::shared});
    if (!patch.emit(v, i)) throw std::runtime_error("CP emit refused its buffers");
    return patch.triangle_count();
}
std::uint32_t uniform_emit(const Factors& f) {
    static std::vector<ctess::uniform::Point> v;
    static std::vector<ctess::uniform::SplitPoint> vs;
    static std::vector<std::uint32_t> i;
    if (uniform_fits(f))
        return uniform_emit_into(ctess::rt::UniformPatch(ctess::rt::uniform_tables, f[0], f[1], f[2]), v, i)
            .triangles;
    return uniform_emit_into(ctess::rt::UniformSplit(ctess::rt::uniform_tables, f[0], f[1], f[2]), vs, i)
        .triangles;
}
template <ctess::d3d11::Partitioning P>
std::uint32_t d3d11_emit(const Factors& f) {
    static std::vector<ctess::d3d11::Point> v(ctess::d3d11::max_tri_counts.vertices);
    static std::vector<std::uint32_t> i(ctess::d3d11::max_tri_counts.index_count());
    const ctess::d3d11::TessOptions opt{P, ctess::Winding::ccw};
    return ctess::d3d11::tessellate_tri(v, i, {f[0], f[1], f[2], (f[0] + f[1] + f[2]) / 3.0f},
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
    const char* dash; // SVG stroke-dasharray of its plot lines, "" for solid
    void (*pattern)(const Factors&, Pattern&);
    std::uint32_t (*emit)(const Factors&);
};

// The hook: one row per generator.
const Generator generators[] = {
    {"CP", "#d62728", "", cp_pattern, cp_emit},
    {"D3D11 fractional_even", "#1f77b4", "", d3d11_pattern<ctess::d3d11::Partitioning::fractional_even>,
     d3d11_emit<ctess::d3d11::Partitioning::fractional_even>},
    {"D3D11 fractional_odd", "#2ca02c", "", d3d11_pattern<ctess::d3d11::Partitioning::fractional_odd>,
     d3d11_emit<ctess::d3d11::Partitioning::fractional_odd>},
    {"D3D11 integer", "#9467bd", "", d3d11_pattern<ctess::d3d11::Partitioning::integer>,
     d3d11_emit<ctess::d3d11::Partitioning::integer>},
    {"OpenSubdiv", "#ff7f0e", "8 5", osd_pattern, osd_emit},
    {"uniform density", "#17becf", "", uniform_pattern, uniform_emit},
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
    std::vector<Point2> all; // every position once: corners, edge points, interior
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
    // A position counts once: CP's provoking copies and UniformSplit's per-subpatch vertices repeat points
    // bit for bit.
    for (auto& e : out.edge) {
        std::sort(e.begin(), e.end());
        e.erase(std::unique(e.begin(), e.end()), e.end());
    }
    auto less = [](Point2 a, Point2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
    auto same = [](Point2 a, Point2 b) { return a.x == b.x && a.y == b.y; };
    std::sort(out.interior.begin(), out.interior.end(), less);
    out.interior.erase(std::unique(out.interior.begin(), out.interior.end(), same), out.interior.end());
    out.all.assign(out.corner.begin(), out.corner.end());
    for (int k = 0; k < 3; ++k)
        for (double t : out.edge[k]) {
            std::array<double, 3> w{};
            w[(k + 1) % 3] = t;
            w[(k + 2) % 3] = 1 - t;
            out.all.push_back(to_metric(w));
        }
    out.all.insert(out.all.end(), out.interior.begin(), out.interior.end());
    return out;
}

// Edge points keep their identity in order: between two steps, the points of the shorter list are matched to
// the longer list's in order, choosing the points that appear (or disappear) so that the total move is
// least.
struct Moves {
    double total = 0;          // path length (parameter = length along the unit edge)
    double largest = 0;        // the largest single move
    std::size_t unmatched = 0; // points that appear or vanish
    double pop = 0;            // for each of those, the distance to the other step's nearest point, summed
    double largest_pop = 0;
    void add_pop(double d) {
        pop += d;
        largest_pop = std::max(largest_pop, d);
    }
};
Moves edge_moves(const std::vector<double>& a, const std::vector<double>& b) {
    const std::vector<double>& s = a.size() <= b.size() ? a : b;
    const std::vector<double>& l = a.size() <= b.size() ? b : a;
    const std::size_t n = s.size(), m = l.size(), w = m + 1;
    // cost[i * w + j]: the least total move matching s[0, i) into l[0, j).
    std::vector<double> cost((n + 1) * w, 1e300);
    std::fill(cost.begin(), cost.begin() + w, 0.0);
    for (std::size_t i = 1; i <= n; ++i)
        for (std::size_t j = 1; j <= m; ++j)
            cost[i * w + j] =
                std::min(cost[i * w + j - 1], cost[(i - 1) * w + j - 1] + std::fabs(s[i - 1] - l[j - 1]));
    Moves out{cost[n * w + m], 0, m - n};
    std::vector<bool> matched(m);
    for (std::size_t i = n, j = m; i > 0;) { // walk the least matching back for its largest move
        if (cost[i * w + j] == cost[i * w + j - 1]) {
            --j;
            continue;
        }
        out.largest = std::max(out.largest, std::fabs(s[i - 1] - l[j - 1]));
        matched[j - 1] = true;
        --i, --j;
    }
    for (std::size_t j = 0; j < m;
         ++j) { // an unmatched point pops from (or into) the nearest point or corner
        if (matched[j]) continue;
        double d = std::min(l[j], 1 - l[j]);
        for (double x : s) d = std::min(d, std::fabs(x - l[j]));
        out.add_pop(d);
    }
    return out;
}

// Interior points have no order to keep: the closest pairs (within r, a bound on one step's move) are matched
// first, each point at most once; the rest appear or vanish.
// An unmatched point pops from (or into) the nearest point of the other step (all_b for a, all_a for b).
Moves interior_moves(const std::vector<Point2>& a, const std::vector<Point2>& b, double r,
                     const std::vector<Point2>& all_a, const std::vector<Point2>& all_b) {
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
    Moves out;
    std::size_t matched = 0;
    for (const auto& [d, i, j] : pairs) {
        if (used_a[i] || used_b[j]) continue;
        used_a[i] = used_b[j] = true;
        out.total += d;
        out.largest = std::max(out.largest, d);
        ++matched;
    }
    out.unmatched = a.size() + b.size() - 2 * matched;
    auto pops = [&](const std::vector<Point2>& from, const std::vector<bool>& used,
                    const std::vector<Point2>& other) {
        for (std::size_t i = 0; i < from.size(); ++i) {
            if (used[i]) continue;
            double d = 1e300;
            for (const Point2& q : other) d = std::min(d, dist(from[i], q));
            out.add_pop(d);
        }
    };
    pops(a, used_a, all_b);
    pops(b, used_b, all_a);
    return out;
}

struct Movement {
    double all = 0, edges = 0;       // path length per unit factor change
    double largest = 0;              // the largest move of one vertex in one step
    std::size_t unmatched = 0;       // vertices without a partner in the next step (appear or disappear)
    double pop = 0, largest_pop = 0; // per unit factor change; the largest single one
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
    double total = 0, edges = 0, pop = 0;
    m.cumulative.push_back({from[0], 0});
    for (int s = 1; s <= steps; ++s) {
        g.pattern(at(s), p);
        Places next = places(p);
        for (int k = 0; k < 3; ++k) {
            total += dist(prev.corner[k], next.corner[k]);
            const Moves e = edge_moves(prev.edge[k], next.edge[k]);
            edges += e.total;
            total += e.total;
            m.largest = std::max(m.largest, e.largest);
            m.unmatched += e.unmatched;
            pop += e.pop;
            m.largest_pop = std::max(m.largest_pop, e.largest_pop);
        }
        // A persistent point moves less than the point spacing (1 / factor) per step.
        const Factors f = at(s);
        const double r = 1.5 / std::max({1.0f, f[0], f[1], f[2]});
        const Moves in = interior_moves(prev.interior, next.interior, r, prev.all, next.all);
        total += in.total;
        m.largest = std::max(m.largest, in.largest);
        m.unmatched += in.unmatched;
        pop += in.pop;
        m.largest_pop = std::max(m.largest_pop, in.largest_pop);
        m.cumulative.push_back({at(s)[0], edges});
        prev = std::move(next);
    }
    double span = 0;
    for (int k = 0; k < 3; ++k) span = std::max(span, double(std::fabs(to[k] - from[k])));
    m.all = total / span;
    m.edges = edges / span;
    m.pop = pop / span;
    return m;
}

// Triangles per second of each generator's `emit` over the factor sets: short rounds (a few passes), the
// generators taking turns within a round (so that a shared machine's load changes reach all of them alike),
// the best round of each kept.
constexpr int speed_rounds = 40, speed_passes = 5;
std::vector<double> emission_rates(const std::vector<Factors>& sets) {
    std::vector<double> best(std::size(generators), 0.0);
    for (int round = 0; round < speed_rounds; ++round)
        for (std::size_t g = 0; g < best.size(); ++g) {
            std::uint64_t triangles = 0;
            const auto start = std::chrono::steady_clock::now();
            for (int pass = 0; pass < speed_passes; ++pass)
                for (const Factors& f : sets) triangles += generators[g].emit(f);
            const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            best[g] = std::max(best[g], double(triangles) / s);
        }
    return best;
}

// ---- SVG ----

struct Series {
    std::string name, colour, dash;
    std::vector<std::pair<double, double>> points;
};

// Axis ticks at multiples of 1, 2, 2.5 or 5 times a power of ten, about `count` of them over [lo, hi].
std::vector<double> ticks(double lo, double hi, int count) {
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

std::string line_plot(const std::string& title, const std::string& xlabel, const std::string& ylabel,
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
    const std::size_t n_gen = std::size(generators);
    std::size_t osd = 0; // the speed anchor's row
    while (std::string(generators[osd].name) != "OpenSubdiv") ++osd;
    try {
        std::filesystem::create_directories(dir);
        // The factor sets of `ctess efficiency` (equal, two high one low, 40 seeded random triples).
        const auto rows = ctess::cli::efficiency_rows(64, 40, 2026);
        std::vector<Factors> sets;
        for (const auto& r : rows) sets.push_back({r.factors[0], r.factors[1], r.factors[2]});
        const unsigned un = ctess::rt::uniform_tables.max_factor;
        std::size_t split_sets = 0;
        for (const Factors& f : sets) split_sets += uniform_fits(f) ? 0 : 1;

        std::string md = "# ctess quality report: CP against its peers\n\n";
        md += fmt::format(
            "Machine: {}. Written by `bench/ctess_report` in one run (bench/README.md); ratios carry the "
            "claims, absolute times belong to this machine only.\n\n",
            machine);
        md += fmt::format(
            "Generators: **CP** (max factor 64; pattern from the library's `cp::tessellate`, provoking "
            "layout; "
            "speed from the runtime's fastest bulk path, `ctess::rt::CpPatchSetup` + `emit()` in the shared "
            "layout, which builds no random-access buckets), **D3D11** `tessellate_tri` with inside = "
            "average "
            "of the edges, **OpenSubdiv** `Bfr::Tessellation` (Loop triangle, rates = ceil of each factor), "
            "and ctess's **uniform density** (docs/algorithm.md §3; the configured table, N = {0}): integer "
            "factors, each rounded to the nearest integer (halves up); `ctess::rt::UniformPatch` when every "
            "rounded factor is at most {0}, `ctess::rt::UniformSplit` (§3.5) when one is above, so that "
            "every "
            "factor set is covered ({1} of the {2} sets below, and the plots above {0}.5, go through the "
            "split). UniformSplit runs in its default provoking layout, which writes each subpatch's own "
            "vertices (positions shared bit for bit; `Layout::shared` welds them, §3.5): its vertex counts "
            "and cache figures are of that output as emitted. Lengths and angles "
            "are measured in the domain's own metric: the equilateral triangle with unit edges (not the "
            "intrinsic metric that uniform density optimises).\n\n",
            un, split_sets, sets.size());

        // Per-set table and group means.
        md += "## Per factor set\n\n| group | factors | generator | triangles | zero-area | vertices | ACMR "
              "16 | "
              "ATVR 16 | ACMR 32 | ATVR 32 | longest edge | smallest angle "
              "|\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
        struct Mean {
            double tri = 0, tri_ratio = 0, zero = 0, acmr16 = 0, atvr16 = 0, acmr32 = 0, atvr32 = 0, edge = 0,
                   angle = 180;
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
                m.tri += double(q.triangles);
                m.tri_ratio += double(q.triangles) / cp_tris[r];
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
            "## Summary per group\n\nTriangles: the mean per patch, and the mean of the ratio to CP's on the "
            "same set; zero-area the mean count per patch; cache figures are means; edge and angle the worst "
            "over the group.\n\n| group | generator | triangles | triangles / CP | zero-area per patch | "
            "ACMR 16 | ATVR 16 | ACMR 32 | ATVR 32 | longest edge | smallest angle "
            "|\n|---|---|---|---|---|---|---|---|---|---|---|\n";
        for (const char* group : {"equal", "two high, one low", "random"})
            for (const Generator& g : generators) {
                const Mean& m = means[{group, g.name}];
                const double n = double(m.n);
                summary += fmt::format("| {} | {} | {:.1f} | {:.3f} | {:.2f} | {:.3f} | {:.3f} | {:.3f} | "
                                       "{:.3f} | {:.4f} | {:.2f}° |\n",
                                       group, g.name, m.tri / n, m.tri_ratio / n, m.zero / n, m.acmr16 / n,
                                       m.atvr16 / n, m.acmr32 / n, m.atvr32 / n, m.edge, m.angle);
            }

        // Triangles against an equal factor.
        std::vector<Series> tri_series, move_series, speed_bars;
        for (const Generator& g : generators) {
            Series s{g.name, g.colour, g.dash, {}};
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
            "corners; each position counts once (CP's provoking copies and UniformSplit's per-subpatch "
            "vertices repeat positions bit for bit); on each edge the points are taken in order along the "
            "edge, and between two steps the shorter list is matched to the longer in order, the points that "
            "appear (or vanish) being chosen so that the total move is least (a point that is "
            "inserted is not a move; its slide afterwards is); interior points carry no order, "
            "so the closest pairs within 1.5 / factor (more than one step's move of a "
            "persistent point, less than the point spacing) are matched first, each point once, "
            "and the rest appear or vanish. Path length is the sum of the matched vertices' "
            "moves per unit factor change (domain metric, edge = 1); largest step is the longest move of one "
            "matched vertex in one step (1/{} of a unit); unmatched counts the "
            "appearances and disappearances over the sweep. The edge rule is exact; the "
            "interior rule approximates identity by nearest match.\n\n"
            "**Pops.** A vertex without a partner in the next step (unmatched: it appears or vanishes) is "
            "charged the distance to the nearest vertex of the other step: zero when it splits off, or "
            "merges "
            "into, a vertex at the same place (CP's collapsed T0 edges, D3D11's fractional point pairs), a "
            "jump otherwise. Pop per unit is the sum of those distances per unit factor change, largest pop "
            "the largest one; for an interior point it is a lower bound of the jump a viewer sees (the "
            "nearest new vertex need not be where the old one went). A point that splits off in place is "
            "compared with its partner one step earlier, so a popless pattern's pop is of the size of one "
            "step's move (it shrinks with the step); an integer pattern's pop is a jump, whatever the "
            "step.\n\n"
            "**Integer generators.** D3D11 integer, OpenSubdiv (integer rates, the ceil of each factor, as "
            "driven here) and uniform density take integer factors: their pattern is constant between "
            "integer "
            "crossings (D3D11 integer and OpenSubdiv round up, uniform density to nearest) and changes at "
            "once "
            "at a crossing. The same matching measures them: their path length is the sum of those jumps for "
            "the vertices that stay within the matching radius (no slide in between), and the vertices that "
            "jump further, which for uniform density is most of the interior (its interior is re-placed for "
            "every triple, §3.1), count as unmatched and show in the pop columns instead. Read path length "
            "and pop together for them. Uniform density's (n, n, n) pattern is the regular n² grid, as is "
            "OpenSubdiv's: on the equal 2 → 16 sweep their rows coincide (the jumps are the same, at "
            "different factors).\n\n"
            "| sweep | generator | path length per unit (all) | ratio to CP | edge points only | ratio to CP "
            "| "
            "largest step | unmatched | pop per unit | largest pop "
            "|\n|---|---|---|---|---|---|---|---|---|---|\n",
            steps_per_unit, steps_per_unit);
        std::vector<std::vector<Movement>> movement(std::size(sweeps));
        for (std::size_t w = 0; w < std::size(sweeps); ++w) {
            const Sweep& sw = sweeps[w];
            const int steps = static_cast<int>(std::lround(
                steps_per_unit * std::max({std::fabs(sw.to[0] - sw.from[0]), std::fabs(sw.to[1] - sw.from[1]),
                                           std::fabs(sw.to[2] - sw.from[2])})));
            for (const Generator& g : generators) movement[w].push_back(sweep(g, sw.from, sw.to, steps));
            const Movement& cp = movement[w][0];
            for (std::size_t g = 0; g < n_gen; ++g) {
                const Movement& m = movement[w][g];
                moves += fmt::format(
                    "| {} | {} | {:.4f} | {:.2f} | {:.4f} | {} | {:.4f} | {} | {:.4f} | {:.4f} |\n", sw.name,
                    generators[g].name, m.all, m.all / cp.all, m.edges,
                    cp.edges > 0 ? fmt::format("{:.2f}", m.edges / cp.edges) : std::string("—"), m.largest,
                    m.unmatched, m.pop, m.largest_pop);
                if (w == 0)
                    move_series.push_back(
                        {generators[g].name, generators[g].colour, generators[g].dash, m.cumulative});
            }
        }
        write(dir / "movement.svg", line_plot("Edge-point movement, equal factors 2 → 16", "factor",
                                              "cumulative path (edge = 1)", move_series));

        // Emission speed over the report's factor sets, relative to OpenSubdiv and to CP.
        const std::vector<double> rates = emission_rates(sets);
        std::vector<Factors> small_sets; // the sets uniform density dices without splitting
        for (const Factors& f : sets)
            if (uniform_fits(f)) small_sets.push_back(f);
        const std::vector<double> small_rates = emission_rates(small_sets);
        std::string speed = fmt::format(
            "## Emission speed\n\nTriangles per second of each generator's whole-patch emission (setup "
            "included, into buffers made once) over all the factor sets above, one core: {} rounds of {} "
            "passes, the generators taking turns within each round, the best round of each kept; one run. "
            "CP times `CpPatchSetup` + `emit()` (shared layout), uniform density `UniformPatch::emit` or "
            "`UniformSplit::emit` as above (construction included: UniformSplit counts in its "
            "constructor). The last column repeats the measurement (same rounds, right after) on the {} sets "
            "whose factors are all at most {} after rounding, where uniform density needs no split.\n\n"
            "| generator | relative to OpenSubdiv | relative to CP | relative to OpenSubdiv, the {} sets "
            "without "
            "a split |\n|---|---|---|---|\n",
            speed_rounds, speed_passes, small_sets.size(), un, small_sets.size());
        for (std::size_t g = 0; g < n_gen; ++g) {
            speed +=
                fmt::format("| {} | {:.2f} | {:.2f} | {:.2f} |\n", generators[g].name, rates[g] / rates[osd],
                            rates[g] / rates[0], small_rates[g] / small_rates[osd]);
            speed_bars.push_back(
                {generators[g].name, generators[g].colour, "", {{0, rates[g] / rates[osd]}}});
        }
        write(dir / "speed.svg",
              bar_plot("Emission speed relative to OpenSubdiv (triangles per second)", speed_bars));

        // The headline: one row per generator, every ratio from this run.
        std::string head =
            "## Headline\n\nTriangles and zero-area on the random set (40 triples); movement is the path "
            "length of all matched vertices per unit factor over each sweep, as a ratio to CP's; pop is the "
            "distance jumped by vertices that appear or vanish, per unit factor (about one step's move for a "
            "pattern that splits points off in place, a jump for one that pops; see the movement section for "
            "both); emission speed relative to OpenSubdiv.\n\n| generator | "
            "triangles / CP | zero-area per patch | movement / CP: equal 2 → 16 | one edge 2 → 16 | equal 16 "
            "→ "
            "64 | pop per unit: equal 2 → 16 | one edge 2 → 16 | equal 16 → 64 | emission / OpenSubdiv "
            "|\n|---|---|---|---|---|---|---|---|---|---|\n";
        for (std::size_t g = 0; g < n_gen; ++g) {
            const Mean& m = means[{"random", generators[g].name}];
            head += fmt::format(
                "| {} | {:.3f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.4f} | {:.4f} | {:.4f} | {:.2f} |\n",
                generators[g].name, m.tri_ratio / double(m.n), m.zero / double(m.n),
                movement[0][g].all / movement[0][0].all, movement[1][g].all / movement[1][0].all,
                movement[2][g].all / movement[2][0].all, movement[0][g].pop, movement[1][g].pop,
                movement[2][g].pop, rates[g] / rates[osd]);
        }

        md += "\n" + head + "\n" + summary +
              "\n![triangles](triangles.svg)\n\nUniform density's count above 16 comes from UniformSplit and "
              "is not monotone in the factor: the split pattern and the rounded factors of the subpatches "
              "change at different factors (docs/algorithm.md §3.5).\n\n" +
              moves + "\n![movement](movement.svg)\n\n" + speed + "\n![speed](speed.svg)\n";
        // Put the summaries first: move the per-set table to the end.
        const std::size_t per_set = md.find("## Per factor set");
        const std::size_t per_set_end = md.find("\n## Headline");
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
