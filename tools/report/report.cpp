// ctess_report: the quality report of CP against its peers (D3D11 fractional_even / fractional_odd / integer,
// OpenSubdiv's Bfr::Tessellation, ctess's uniform density) on the same edge factors. Writes
// OUT_DIR/report.md and three SVG plots.
//
//   ./build/release/tools/report/ctess_report OUT_DIR [MACHINE_NAME]
//
// Generators are rows of one table (`generators` below): adding one is a function that fills a Pattern, an
// emit function and one row. Every generator works in its own domain coordinates, converted
// to barycentric weights (w0, w1, w2); lengths and angles use the domain's own metric, the equilateral
// triangle with unit edges. Each section of report.md is one function (`..._section` below); the factor sets,
// the movement metrics and the signed area come from the analysis library (ctess/analysis/). Exit status 0,
// or 1 with a message.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <span>
#include <stdexcept>
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

#include <ctess/analysis/efficiency.hpp>
#include <ctess/analysis/movement.hpp>
#include <ctess/analysis/signed_area.hpp>

#include "svg_plot.hpp"

namespace {

using namespace ctess::report;
using ctess::analysis::Factors;

using ctess::analysis::Pattern;

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
    return ctess::d3d11::tessellate_tri(v, i, {f[0], f[1], f[2], (f[0] + f[1] + f[2]) / 3.0f}, opt).triangles;
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

using ctess::analysis::dist;
using ctess::analysis::Movement;
using ctess::analysis::Point2;
using ctess::analysis::to_metric;

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
        const double area2 = ctess::analysis::signed_area2(a, b, c);
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

// ---- the report's sections, in the order they are computed ----

// The factor sets of `ctess efficiency` (equal, two high one low, 40 seeded random triples) and the
// configured uniform table's N, which every section reads.
constexpr unsigned random_sets = 40;
struct Inputs {
    std::vector<ctess::analysis::FactorSet> sets;
    unsigned uniform_max = 0;
    std::size_t split_sets = 0; // the sets uniform density splits (a factor above N after rounding)
};
Inputs inputs() {
    Inputs in{ctess::analysis::efficiency_factor_sets(random_sets, 2026),
              ctess::rt::uniform_tables.max_factor, 0};
    for (const auto& s : in.sets) in.split_sets += uniform_fits(s.factors) ? 0 : 1;
    return in;
}

// The speed anchor's row.
std::size_t osd_row() {
    std::size_t osd = 0;
    while (std::string(generators[osd].name) != "OpenSubdiv") ++osd;
    return osd;
}

// Title, machine and the generators as measured.
std::string intro_section(const std::string& machine, const Inputs& in) {
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
        in.uniform_max, in.split_sets, in.sets.size());
    return md;
}

// Per-generator sums over a group of factor sets, for the summary and the headline.
struct Mean {
    double tri = 0, tri_ratio = 0, zero = 0, acmr16 = 0, atvr16 = 0, acmr32 = 0, atvr32 = 0, edge = 0,
           angle = 180;
    std::size_t n = 0;
    void add(const Quality& q, double cp_triangles) {
        tri += double(q.triangles);
        tri_ratio += double(q.triangles) / cp_triangles;
        zero += double(q.zero_area);
        acmr16 += q.acmr16;
        atvr16 += q.atvr16;
        acmr32 += q.acmr32;
        atvr32 += q.atvr32;
        edge = std::max(edge, q.longest_edge);
        angle = std::min(angle, q.smallest_angle);
        ++n;
    }
};
using Means = std::map<std::pair<std::string, std::string>, Mean>; // by group and generator
const Mean& mean_of(const Means& means, const std::string& group, const char* generator) {
    static const Mean none;
    const auto it = means.find({group, generator});
    return it == means.end() ? none : it->second;
}

// The table of every factor set and generator (placed last in the report); fills the group means.
std::string per_set_section(const Inputs& in, Means& means) {
    std::string md =
        "## Per factor set\n\n| group | factors | generator | triangles | zero-area | vertices | ACMR "
        "16 | "
        "ATVR 16 | ACMR 32 | ATVR 32 | longest edge | smallest angle "
        "|\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    Pattern p;
    for (const auto& set : in.sets) {
        const Factors& f = set.factors;
        double cp_triangles = 0;
        for (const Generator& g : generators) {
            g.pattern(f, p);
            const Quality q = measure(p);
            if (&g == &generators[0]) cp_triangles = double(q.triangles);
            md += fmt::format(
                "| {} | {:.2f}, {:.2f}, {:.2f} | {} | {} | {} | {} | {:.3f} | {:.3f} | {:.3f} | {:.3f} | "
                "{:.4f} | {:.2f}° |\n",
                set.group, f[0], f[1], f[2], g.name, q.triangles, q.zero_area, q.vertices, q.acmr16, q.atvr16,
                q.acmr32, q.atvr32, q.longest_edge, q.smallest_angle);
            means[{set.group, g.name}].add(q, cp_triangles);
        }
    }
    return md;
}

// The group means of every generator.
std::string summary_section(const Means& means) {
    std::string md =
        "## Summary per group\n\nTriangles: the mean per patch, and the mean of the ratio to CP's on the "
        "same set; zero-area the mean count per patch; cache figures are means; edge and angle the worst "
        "over the group.\n\n| group | generator | triangles | triangles / CP | zero-area per patch | "
        "ACMR 16 | ATVR 16 | ACMR 32 | ATVR 32 | longest edge | smallest angle "
        "|\n|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const char* group : {"equal", "two high, one low", "random"})
        for (const Generator& g : generators) {
            const Mean& m = mean_of(means, group, g.name);
            const double n = double(m.n);
            md += fmt::format("| {} | {} | {:.1f} | {:.3f} | {:.2f} | {:.3f} | {:.3f} | {:.3f} | "
                              "{:.3f} | {:.4f} | {:.2f}° |\n",
                              group, g.name, m.tri / n, m.tri_ratio / n, m.zero / n, m.acmr16 / n,
                              m.atvr16 / n, m.acmr32 / n, m.atvr32 / n, m.edge, m.angle);
        }
    return md;
}

// triangles.svg: triangles against an equal factor; returns the section's text.
std::string triangles_section(const std::filesystem::path& dir, const Inputs& in) {
    std::vector<Series> tri_series;
    Pattern p;
    for (const Generator& g : generators) {
        Series s{g.name, g.colour, g.dash, {}};
        for (int k = 0; k <= 63 * 8; ++k) {
            const float f = 1.0f + k / 8.0f;
            g.pattern({f, f, f}, p);
            s.points.push_back({f, double(p.indices.size() / 3)});
        }
        tri_series.push_back(s);
    }
    write(dir / "triangles.svg", line_plot("Triangles against the factor (all three edges equal)", "factor",
                                           "triangles", tri_series));
    return fmt::format(
        "\n![triangles](triangles.svg)\n\nUniform density's count above {} comes from UniformSplit and "
        "is not monotone in the factor: the split pattern and the rounded factors of the subpatches "
        "change at different factors (docs/algorithm.md §3.5).\n\n",
        in.uniform_max);
}

// Movement along sweeps (movement.svg), measured by the analysis library; `movement` gets one row per sweep,
// one entry per generator.
struct Sweep {
    const char* name;
    Factors from, to;
};
const Sweep sweeps[] = {{"equal 2 → 16", {2, 2, 2}, {16, 16, 16}},
                        {"one edge 2 → 16 (others 8)", {2, 8, 8}, {16, 8, 8}},
                        {"equal 16 → 64", {16, 16, 16}, {64, 64, 64}}};
constexpr int steps_per_unit = 16;

std::string movement_section(const std::filesystem::path& dir, std::vector<std::vector<Movement>>& movement) {
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
    std::vector<Series> move_series;
    movement.assign(std::size(sweeps), {});
    for (std::size_t w = 0; w < std::size(sweeps); ++w) {
        const Sweep& sw = sweeps[w];
        const int steps = static_cast<int>(std::lround(
            steps_per_unit * std::max({std::fabs(sw.to[0] - sw.from[0]), std::fabs(sw.to[1] - sw.from[1]),
                                       std::fabs(sw.to[2] - sw.from[2])})));
        for (const Generator& g : generators)
            movement[w].push_back(ctess::analysis::sweep(g.pattern, sw.from, sw.to, steps));
        const Movement& cp = movement[w][0];
        for (std::size_t g = 0; g < std::size(generators); ++g) {
            const Movement& m = movement[w][g];
            moves +=
                fmt::format("| {} | {} | {:.4f} | {:.2f} | {:.4f} | {} | {:.4f} | {} | {:.4f} | {:.4f} |\n",
                            sw.name, generators[g].name, m.all, m.all / cp.all, m.edges,
                            cp.edges > 0 ? fmt::format("{:.2f}", m.edges / cp.edges) : std::string("—"),
                            m.largest, m.unmatched, m.pop, m.largest_pop);
            if (w == 0)
                move_series.push_back(
                    {generators[g].name, generators[g].colour, generators[g].dash, m.cumulative});
        }
    }
    write(dir / "movement.svg", line_plot("Edge-point movement, equal factors 2 → 16", "factor",
                                          "cumulative path (edge = 1)", move_series));
    return moves + "\n![movement](movement.svg)\n\n";
}

// Emission speed over the report's factor sets, relative to OpenSubdiv and to CP (speed.svg); `rates` gets
// each generator's triangles per second.
std::string speed_section(const std::filesystem::path& dir, const Inputs& in, std::vector<double>& rates) {
    std::vector<Factors> sets, small_sets; // all, and the sets uniform density dices without splitting
    for (const auto& s : in.sets) sets.push_back(s.factors);
    rates = emission_rates(sets);
    for (const Factors& f : sets)
        if (uniform_fits(f)) small_sets.push_back(f);
    const std::vector<double> small_rates = emission_rates(small_sets);
    const std::size_t osd = osd_row();
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
        speed_rounds, speed_passes, small_sets.size(), in.uniform_max, small_sets.size());
    std::vector<Series> speed_bars;
    for (std::size_t g = 0; g < std::size(generators); ++g) {
        speed += fmt::format("| {} | {:.2f} | {:.2f} | {:.2f} |\n", generators[g].name, rates[g] / rates[osd],
                             rates[g] / rates[0], small_rates[g] / small_rates[osd]);
        speed_bars.push_back({generators[g].name, generators[g].colour, "", {{0, rates[g] / rates[osd]}}});
    }
    write(dir / "speed.svg",
          bar_plot("Emission speed relative to OpenSubdiv (triangles per second)", speed_bars));
    return speed + "\n![speed](speed.svg)\n";
}

// The headline: one row per generator, every ratio from this run.
std::string headline_section(const Means& means, const std::vector<std::vector<Movement>>& movement,
                             const std::vector<double>& rates) {
    const std::size_t osd = osd_row();
    std::string head = fmt::format(
        "## Headline\n\nTriangles and zero-area on the random set ({} triples); movement is the path "
        "length of all matched vertices per unit factor over each sweep, as a ratio to CP's; pop is the "
        "distance jumped by vertices that appear or vanish, per unit factor (about one step's move for a "
        "pattern that splits points off in place, a jump for one that pops; see the movement section for "
        "both); emission speed relative to OpenSubdiv.\n\n| generator | "
        "triangles / CP | zero-area per patch | movement / CP: equal 2 → 16 | one edge 2 → 16 | equal 16 "
        "→ "
        "64 | pop per unit: equal 2 → 16 | one edge 2 → 16 | equal 16 → 64 | emission / OpenSubdiv "
        "|\n|---|---|---|---|---|---|---|---|---|---|\n",
        random_sets);
    for (std::size_t g = 0; g < std::size(generators); ++g) {
        const Mean& m = mean_of(means, "random", generators[g].name);
        head += fmt::format(
            "| {} | {:.3f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.4f} | {:.4f} | {:.4f} | {:.2f} |\n",
            generators[g].name, m.tri_ratio / double(m.n), m.zero / double(m.n),
            movement[0][g].all / movement[0][0].all, movement[1][g].all / movement[1][0].all,
            movement[2][g].all / movement[2][0].all, movement[0][g].pop, movement[1][g].pop,
            movement[2][g].pop, rates[g] / rates[osd]);
    }
    return head;
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
        const Inputs in = inputs();
        Means means;
        const std::string per_set = per_set_section(in, means);
        const std::string summary = summary_section(means);
        const std::string triangles = triangles_section(dir, in);
        std::vector<std::vector<Movement>> movement;
        const std::string moves = movement_section(dir, movement);
        std::vector<double> rates;
        const std::string speed = speed_section(dir, in, rates);
        const std::string head = headline_section(means, movement, rates);
        // The summaries first, the per-set table last.
        write(dir / "report.md", intro_section(machine, in) + head + "\n" + summary + triangles + moves +
                                     speed + "\n" + per_set);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ctess_report: %s\n", e.what());
        return 1;
    }
    return 0;
}
