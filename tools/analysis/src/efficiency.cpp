#include <ctess/analysis/efficiency.hpp>
#include <ctess/analysis/signed_area.hpp>

#include <ctess/cp/orientation.hpp>
#include <ctess/cp/pattern.hpp>
#include <ctess/d3d11/tessellator.hpp>

#include <algorithm>
#include <random>

#include <fmt/core.h>

namespace ctess::analysis {

namespace {

std::uint32_t d3d_even_triangles(const std::array<float, 3>& f, float inside) {
    const d3d11::TessOptions opt{d3d11::Partitioning::fractional_even, Winding::cw};
    return d3d11::tessellate_tri({}, {}, {f[0], f[1], f[2], inside}, opt).triangles;
}

// CP's pattern for the factors as given (counter-clockwise, shared layout): its triangles and how many of
// them have zero area.
struct CpCount {
    std::uint32_t triangles = 0, zero_area = 0;
};
CpCount cp_count(const std::array<float, 3>& f, unsigned max) {
    cp::PatternOptions opt;
    opt.max_factor = max;
    opt.layout = Layout::shared;
    opt.winding = Winding::ccw;
    const Counts n = cp::pattern_counts(f[0], f[1], f[2], opt);
    std::vector<DomainPoint> v(n.vertices);
    std::vector<std::uint32_t> idx(n.index_count());
    cp::tessellate(v, idx, f[0], f[1], f[2], opt);
    CpCount c{n.triangles, 0};
    for (std::size_t k = 0; k < idx.size(); k += 3)
        c.zero_area += signed_area2(v[idx[k]], v[idx[k + 1]], v[idx[k + 2]]) == 0;
    return c;
}

} // namespace

std::vector<FactorSet> efficiency_factor_sets(unsigned random_count, std::uint32_t seed) {
    std::vector<FactorSet> sets;
    for (float f : {2.0f, 4.0f, 5.0f, 8.0f, 10.3f, 16.0f, 24.0f, 32.0f, 48.0f, 64.0f})
        sets.push_back({"equal", {f, f, f}});
    const std::array<std::array<float, 3>, 8> two_high = {{{64, 64, 2},
                                                           {64, 2, 64},
                                                           {2, 64, 64},
                                                           {32, 32, 8},
                                                           {8, 32, 32},
                                                           {48, 40, 3},
                                                           {20, 24, 1.5f},
                                                           {16, 16, 4}}};
    for (const auto& f : two_high) sets.push_back({"two high, one low", f});
    std::mt19937 rng(seed);
    for (unsigned i = 0; i < random_count; ++i) {
        std::array<float, 3> f{};
        // 2 + 62 * k / 2^24 with a 24-bit k: the same triples on every standard library.
        for (float& x : f) x = 2.0f + 62.0f * static_cast<float>(rng() >> 8) / 16777216.0f;
        sets.push_back({"random", f});
    }
    return sets;
}

EfficiencyRow efficiency_row(const std::array<float, 3>& f, unsigned max, const std::string& group) {
    EfficiencyRow row;
    row.group = group;
    row.factors = f;
    const CpCount cp_as_given = cp_count(f, max);
    row.cp_triangles = cp_as_given.triangles;
    row.cp_nondegenerate = cp_as_given.triangles - cp_as_given.zero_area;
    cp::PatternOptions opt;
    opt.max_factor = max;
    // The orientation rule (docs/algorithm.md §2.13) with the factors as the measure: the smallest on e2.
    const std::array<float, 3> r = cp::rotate_factors(cp::smallest_edge_rotation(f[0], f[1], f[2]), f);
    row.cp_rotated_triangles = cp::pattern_counts(r[0], r[1], r[2], opt).triangles;
    row.d3d_max = d3d_even_triangles(f, std::max({f[0], f[1], f[2]}));
    row.d3d_avg = d3d_even_triangles(f, (f[0] + f[1] + f[2]) / 3.0f);
    return row;
}

std::vector<EfficiencyRow> efficiency_rows(unsigned max, unsigned random_count, std::uint32_t seed) {
    std::vector<EfficiencyRow> rows;
    for (const FactorSet& set : efficiency_factor_sets(random_count, seed))
        rows.push_back(efficiency_row(set.factors, max, set.group));
    return rows;
}

EfficiencySummary summarize(const std::vector<EfficiencyRow>& rows) {
    EfficiencySummary s;
    for (const auto& r : rows) {
        if (r.group != "random") continue;
        ++s.random_count;
        s.mean_ratio_max += double(r.cp_triangles) / r.d3d_max;
        s.mean_ratio_avg += double(r.cp_triangles) / r.d3d_avg;
        s.mean_nondegenerate_ratio_max += double(r.cp_nondegenerate) / r.d3d_max;
        s.mean_nondegenerate_ratio_avg += double(r.cp_nondegenerate) / r.d3d_avg;
        s.mean_rotated_ratio_max += double(r.cp_rotated_triangles) / r.d3d_max;
        s.mean_rotated_ratio_avg += double(r.cp_rotated_triangles) / r.d3d_avg;
    }
    if (s.random_count != 0) {
        const double n = double(s.random_count);
        for (double* m :
             {&s.mean_ratio_max, &s.mean_ratio_avg, &s.mean_nondegenerate_ratio_max,
              &s.mean_nondegenerate_ratio_avg, &s.mean_rotated_ratio_max, &s.mean_rotated_ratio_avg})
            *m /= n;
    }
    return s;
}

std::string efficiency_markdown(const std::vector<EfficiencyRow>& rows, const EfficiencySummary& s,
                                unsigned max) {
    std::string out =
        fmt::format("CP (max factor {}) against D3D11 fractional_even on the same edges\n\n", max);
    out += "| group | factors (e0, e1, e2) | CP triangles | non-degenerate | CP, smallest on e2 | D3D11 "
           "(inside max) "
           "| ratio | D3D11 (inside avg) | ratio |\n|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& r : rows)
        out += fmt::format("| {} | {:.2f}, {:.2f}, {:.2f} | {} | {} | {} | {} | {:.3f} | {} | {:.3f} |\n",
                           r.group, r.factors[0], r.factors[1], r.factors[2], r.cp_triangles,
                           r.cp_nondegenerate, r.cp_rotated_triangles, r.d3d_max,
                           double(r.cp_triangles) / r.d3d_max, r.d3d_avg, double(r.cp_triangles) / r.d3d_avg);
    out += fmt::format("\nMean over the {} random triples in [2, 64]:\n", s.random_count);
    out += fmt::format("- CP / D3D11 (inside = max): {:.3f} (target <= 0.35); non-degenerate only {:.3f}; "
                       "smallest edge on e2 {:.3f}\n",
                       s.mean_ratio_max, s.mean_nondegenerate_ratio_max, s.mean_rotated_ratio_max);
    out +=
        fmt::format("- CP / D3D11 (inside = average): {:.3f} (target <= 0.65); non-degenerate only {:.3f}; "
                    "smallest edge on e2 {:.3f}\n",
                    s.mean_ratio_avg, s.mean_nondegenerate_ratio_avg, s.mean_rotated_ratio_avg);
    return out;
}

std::string efficiency_json(const std::vector<EfficiencyRow>& rows, const EfficiencySummary& s,
                            unsigned max) {
    std::string out = fmt::format("{{\"max_tess_factor\": {}, \"rows\": [", max);
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const auto& r = rows[i];
        out += fmt::format(
            "{}\n  {{\"group\": \"{}\", \"factors\": [{}, {}, {}], \"cp_triangles\": {}, "
            "\"cp_nondegenerate\": {}, \"cp_rotated_triangles\": {}, \"d3d11_even_inside_max\": {}, "
            "\"d3d11_even_inside_avg\": {}}}",
            i ? "," : "", r.group, r.factors[0], r.factors[1], r.factors[2], r.cp_triangles,
            r.cp_nondegenerate, r.cp_rotated_triangles, r.d3d_max, r.d3d_avg);
    }
    out += fmt::format(
        "\n], \"random_count\": {}, \"mean_ratio_inside_max\": {:.6f}, \"mean_ratio_inside_avg\": {:.6f}, "
        "\"mean_nondegenerate_ratio_inside_max\": {:.6f}, \"mean_nondegenerate_ratio_inside_avg\": "
        "{:.6f}}}\n",
        s.random_count, s.mean_ratio_max, s.mean_ratio_avg, s.mean_nondegenerate_ratio_max,
        s.mean_nondegenerate_ratio_avg);
    return out;
}

} // namespace ctess::analysis
