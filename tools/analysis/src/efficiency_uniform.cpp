#include <ctess/analysis/efficiency_uniform.hpp>

#include <ctess/cp/pattern.hpp>
#include <ctess/d3d11/tessellator.hpp>
#include <ctess/runtime/uniform/patch.hpp>
#include <ctess/runtime/uniform/split.hpp>
#include <ctess/uniform/metric.hpp>

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

namespace ctess::analysis {

namespace {

std::uint32_t d3d_integer_triangles(const std::array<float, 3>& f, float inside) {
    const d3d11::TessOptions opt{d3d11::Partitioning::integer, d3d11::Winding::cw};
    return d3d11::tessellate_tri({}, {}, {f[0], f[1], f[2], inside}, opt).triangles;
}

struct Totals {
    std::uint64_t uniform = 0, d3d_max = 0, d3d_avg = 0, cp = 0;
    double ratio_max = 0, ratio_avg = 0, ratio_cp = 0;
    std::size_t count = 0;
};

Totals totals(const std::vector<UniformEfficiencyRow>& rows, unsigned up_to) {
    Totals t;
    for (const auto& r : rows) {
        if (r.factors[0] > up_to) continue;
        t.uniform += r.uniform, t.d3d_max += r.d3d_max, t.d3d_avg += r.d3d_avg, t.cp += r.cp;
        t.ratio_max += double(r.uniform) / r.d3d_max;
        t.ratio_avg += double(r.uniform) / r.d3d_avg;
        t.ratio_cp += double(r.uniform) / r.cp;
        ++t.count;
    }
    if (t.count != 0)
        t.ratio_max /= double(t.count), t.ratio_avg /= double(t.count), t.ratio_cp /= double(t.count);
    return t;
}

// Binary (longest-edge) splitting, the comparison of Karis 2026: halve the longest edge (factor T / 2 on each
// half, the median's intrinsic length on the new edge) until every factor is at most n, with the same
// tolerance as UniformSplit for edges inside the root (inside[i]); returns the leaves.
std::uint64_t binary_split_leaves(std::array<double, 3> f, std::array<bool, 3> inside, double n,
                                  double tolerance, int depth = 0) {
    bool fits = true;
    for (int i = 0; i < 3; ++i) fits = fits && f[i] < (inside[i] ? n * tolerance : n + 0.5);
    if (fits || depth > 40) return 1;
    const int k = f[0] >= f[1] && f[0] >= f[2] ? 0 : f[1] >= f[2] ? 1 : 2;
    const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    const double a = f[k], b = f[k1], c = f[k2];
    const double median = 0.5 * std::sqrt(std::max(0.0, 2 * b * b + 2 * c * c - a * a));
    return binary_split_leaves({a / 2, b, median}, {inside[k], inside[k1], true}, n, tolerance, depth + 1) +
           binary_split_leaves({a / 2, c, median}, {inside[k], inside[k2], true}, n, tolerance, depth + 1);
}

} // namespace

std::vector<UniformSplitRow> uniform_split_rows(double interior_tolerance) {
    std::vector<UniformSplitRow> rows;
    const unsigned n = rt::uniform_tables.max_factor;
    std::uint32_t state = 2026u; // a fixed linear congruential sequence: the same triples everywhere
    auto next = [&]() {
        state = state * 1664525u + 1013904223u;
        return state >> 8;
    };
    for (int i = 0; i < 200; ++i) {
        std::array<float, 3> f{};
        const unsigned top = i < 100 ? 64u : n * n; // half within D3D11's range
        for (float& x : f) x = float(n + 1 + next() % (top - n));
        UniformSplitRow r;
        r.factors = f;
        const rt::UniformSplit split(rt::uniform_tables, f[0], f[1], f[2], {}, interior_tolerance);
        r.subpatches = split.subpatch_count();
        r.triangles = split.counts().triangles;
        r.binary_subpatches =
            binary_split_leaves({f[0], f[1], f[2]}, {false, false, false}, n, split.interior_tolerance());
        r.real_triangle = uniform::is_real_triangle(split.factors());
        r.longest_edge = split.longest_edge();
        if (f[0] <= 64 && f[1] <= 64 && f[2] <= 64)
            r.d3d_max = d3d_integer_triangles(f, std::max({f[0], f[1], f[2]}));
        rows.push_back(r);
    }
    return rows;
}

UniformSplitSummary summarize_uniform_split(const std::vector<UniformSplitRow>& rows,
                                            double interior_tolerance) {
    UniformSplitSummary t;
    t.tolerance = interior_tolerance;
    t.triples = rows.size();
    double sub = 0, bin = 0, tri = 0, d3d = 0;
    for (const auto& r : rows) {
        sub += double(r.subpatches), bin += double(r.binary_subpatches);
        if (r.d3d_max != 0) tri += double(r.triangles), d3d += double(r.d3d_max), ++t.with_d3d;
        if (!r.real_triangle) continue;
        ++t.real_triangles;
        t.longest_max = std::max(t.longest_max, r.longest_edge);
        t.longest_mean += r.longest_edge;
        t.longest_above_table += r.longest_edge > rt::uniform_split_interior_tolerance;
    }
    t.subpatch_ratio = bin != 0 ? sub / bin : 0.0;
    t.triangle_ratio = d3d != 0 ? tri / d3d : 0.0;
    if (t.real_triangles != 0) t.longest_mean /= double(t.real_triangles);
    return t;
}

std::vector<UniformSplitSummary> uniform_split_summaries() {
    std::vector<UniformSplitSummary> out;
    for (double tolerance : {rt::uniform_split_interior_tolerance, rt::uniform_split_strict_tolerance})
        out.push_back(summarize_uniform_split(uniform_split_rows(tolerance), tolerance));
    return out;
}

std::string uniform_split_markdown(const std::vector<UniformSplitSummary>& summaries) {
    if (summaries.empty()) return {};
    const UniformSplitSummary& first = summaries.front();
    const unsigned n = rt::uniform_tables.max_factor;
    std::string out =
        fmt::format("\nSplitting above the table: {} seeded random triples above {}, half up to 64, half up "
                    "to {}; {} form "
                    "a real triangle (a < b + c), {} are degenerate\n\n",
                    first.triples, n, n * n, first.real_triangles, first.triples - first.real_triangles);
    out += fmt::format(
        "| interior dice tolerance | subpatches / binary longest-edge (same dice limit; Karis 2026: "
        "0.68) | triangles / D3D11 integer (inside = max; {} triples <= 64) | longest edge: max | "
        "mean of per-patch maxima | patches above 1.433 |\n|---|---|---|---|---|---|\n",
        first.with_d3d);
    for (const auto& s : summaries)
        out += fmt::format("| {:.3f} N | {:.3f} | {:.3f} | {:.3f} | {:.3f} | {} of {} |\n", s.tolerance,
                           s.subpatch_ratio, s.triangle_ratio, s.longest_max, s.longest_mean,
                           s.longest_above_table, s.real_triangles);
    out += "\nLongest edges in the root patch's intrinsic metric (rounded root factors as side lengths), "
           "over the "
           "real-triangle triples; the table's own longest edge is 1.433.\n";
    return out;
}

std::vector<UniformEfficiencyRow> uniform_efficiency_rows(unsigned cp_max_factor) {
    std::vector<UniformEfficiencyRow> rows;
    const unsigned n = rt::uniform_tables.max_factor;
    cp::PatternOptions cp_options;
    cp_options.max_factor = cp_max_factor;
    for (std::uint32_t a = 1; a <= n; ++a)
        for (std::uint32_t b = 1; b <= a; ++b)
            for (std::uint32_t c = 1; c <= b; ++c) {
                UniformEfficiencyRow r;
                r.factors = {a, b, c};
                const std::array<float, 3> f{float(a), float(b), float(c)};
                r.uniform = rt::UniformPatch(rt::uniform_tables, r.factors).counts().triangles;
                r.d3d_max = d3d_integer_triangles(f, f[0]);
                r.d3d_avg = d3d_integer_triangles(f, (f[0] + f[1] + f[2]) / 3.0f);
                r.cp = cp::pattern_counts(f[0], f[1], f[2], cp_options).triangles;
                rows.push_back(r);
            }
    return rows;
}

std::string uniform_efficiency_markdown(const std::vector<UniformEfficiencyRow>& rows) {
    const unsigned n = rt::uniform_tables.max_factor;
    std::string out = fmt::format("Uniform density (table max {}) against D3D11 integer and CP, every sorted "
                                  "triple a >= b >= c\n\n",
                                  n);
    out += "| triples | count | uniform triangles | D3D11 integer (inside max) | mean ratio | D3D11 integer "
           "(inside avg) | mean ratio | CP | mean ratio |\n|---|---|---|---|---|---|---|---|---|\n";
    for (unsigned up_to : {11u, n}) {
        if (up_to > n || (up_to == n && n == 11 && out.find("a <= 11 |") != std::string::npos)) continue;
        const Totals t = totals(rows, up_to);
        out +=
            fmt::format("| a <= {} | {} | {} | {} | {:.3f} | {} | {:.3f} | {} | {:.3f} |\n", up_to, t.count,
                        t.uniform, t.d3d_max, t.ratio_max, t.d3d_avg, t.ratio_avg, t.cp, t.ratio_cp);
    }
    out += "\nSelected triples:\n\n| factors | uniform | D3D11 (max) | D3D11 (avg) | CP "
           "|\n|---|---|---|---|---|\n";
    for (const auto& r : rows) {
        const auto& f = r.factors;
        const bool pick = (f[0] == f[1] && f[1] == f[2]) || (f[0] == 11 && f[1] == 9 && f[2] == 6) ||
                          (f[1] == f[0] && f[2] == 1 && f[0] % 4 == 0) ||
                          (f[0] == n && f[1] == n / 2 && f[2] == 2);
        if (pick)
            out += fmt::format("| {}, {}, {} | {} | {} | {} | {} |\n", f[0], f[1], f[2], r.uniform, r.d3d_max,
                               r.d3d_avg, r.cp);
    }
    return out;
}

std::string uniform_efficiency_json(const std::vector<UniformEfficiencyRow>& rows,
                                    const std::vector<UniformSplitSummary>& split) {
    const Totals t = totals(rows, rt::uniform_tables.max_factor);
    std::string out = fmt::format("{{\"uniform_max_factor\": {}, \"rows\": [", rt::uniform_tables.max_factor);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const auto& r = rows[i];
        out += fmt::format("{}\n  {{\"factors\": [{}, {}, {}], \"uniform_triangles\": {}, "
                           "\"d3d11_integer_inside_max\": {}, \"d3d11_integer_inside_avg\": {}, "
                           "\"cp_triangles\": {}}}",
                           i ? "," : "", r.factors[0], r.factors[1], r.factors[2], r.uniform, r.d3d_max,
                           r.d3d_avg, r.cp);
    }
    out += fmt::format("\n], \"mean_ratio_inside_max\": {:.6f}, \"mean_ratio_inside_avg\": {:.6f}, "
                       "\"mean_ratio_cp\": {:.6f}, \"split\": [",
                       t.ratio_max, t.ratio_avg, t.ratio_cp);
    for (std::size_t i = 0; i < split.size(); ++i) {
        const auto& s = split[i];
        out +=
            fmt::format("{}\n  {{\"interior_tolerance\": {:.3f}, \"triples\": {}, \"real_triangles\": {}, "
                        "\"subpatches_over_binary\": {:.6f}, \"d3d11_triples\": {}, "
                        "\"triangles_over_d3d11_integer_inside_max\": {:.6f}, \"longest_edge_max\": {:.6f}, "
                        "\"longest_edge_mean_of_maxima\": {:.6f}, \"longest_edge_above_1_433\": {}}}",
                        i ? "," : "", s.tolerance, s.triples, s.real_triangles, s.subpatch_ratio, s.with_d3d,
                        s.triangle_ratio, s.longest_max, s.longest_mean, s.longest_above_table);
    }
    out += "\n]}\n";
    return out;
}

} // namespace ctess::analysis
