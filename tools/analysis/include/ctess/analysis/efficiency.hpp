// The CP efficiency report: CP triangle counts against D3D11 fractional_even on the same edges (inside = max
// of the edges and inside = average), over a fixed family of factor sets that the quality report shares.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ctess::analysis {

// One factor set of the efficiency family: its group ("equal", "two high, one low", "random") and the edge
// factors (e0, e1, e2).
struct FactorSet {
    std::string group;
    std::array<float, 3> factors{};
};

// Equal factors, two-high-one-low triples and `random_count` seeded random triples in [2, 64], the same
// triples on every standard library.
std::vector<FactorSet> efficiency_factor_sets(unsigned random_count, std::uint32_t seed);

struct EfficiencyRow {
    std::string group; // "equal", "two high, one low", "random"
    std::array<float, 3> factors{};
    std::uint32_t cp_triangles = 0;
    std::uint32_t cp_nondegenerate = 0;
    std::uint32_t cp_rotated_triangles = 0; // smallest factor put on e2 (the orientation rule)
    std::uint32_t d3d_max = 0;              // fractional_even, inside = max of the edges
    std::uint32_t d3d_avg = 0;              // fractional_even, inside = average of the edges
};

struct EfficiencySummary {
    std::size_t random_count = 0;
    double mean_ratio_max = 0, mean_ratio_avg = 0; // CP triangles / D3D11, random rows
    double mean_nondegenerate_ratio_max = 0, mean_nondegenerate_ratio_avg = 0;
    double mean_rotated_ratio_max = 0, mean_rotated_ratio_avg = 0;
};

// One row: CP (as given and oriented by cp::smallest_edge_rotation) against D3D11 fractional_even.
EfficiencyRow efficiency_row(const std::array<float, 3>& factors, unsigned max_factor,
                             const std::string& group = "custom");
// One row per set of efficiency_factor_sets(random_count, seed).
std::vector<EfficiencyRow> efficiency_rows(unsigned max_factor, unsigned random_count, std::uint32_t seed);
EfficiencySummary summarize(const std::vector<EfficiencyRow>& rows);
std::string efficiency_markdown(const std::vector<EfficiencyRow>& rows, const EfficiencySummary& s,
                                unsigned max);
std::string efficiency_json(const std::vector<EfficiencyRow>& rows, const EfficiencySummary& s, unsigned max);

} // namespace ctess::analysis
