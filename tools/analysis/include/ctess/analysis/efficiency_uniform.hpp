// The uniform-density efficiency report (docs/algorithm.md §3): uniform triangle counts against D3D11
// integer partitioning (inside = max of the edges and inside = average) and against CP, over every sorted
// triple of the configured table (Karis 2026 reports 69 % of D3D11's uniform topology).
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ctess::analysis {

struct UniformEfficiencyRow {
    std::array<std::uint32_t, 3> factors{};
    std::uint32_t uniform = 0, d3d_max = 0, d3d_avg = 0, cp = 0;
};

std::vector<UniformEfficiencyRow> uniform_efficiency_rows(unsigned cp_max_factor);

// Splitting above the table (§3.5) with one interior dice tolerance: subpatches against binary longest-edge
// splitting to the same dice limit, final triangles against D3D11 integer partitioning, and the output's
// longest edge in the root's intrinsic metric (on the triples that form a real triangle).
struct UniformSplitRow {
    std::array<float, 3> factors{};
    std::uint64_t subpatches = 0, binary_subpatches = 0, triangles = 0, d3d_max = 0;
    bool real_triangle = false;
    double longest_edge = 0;
};
std::vector<UniformSplitRow> uniform_split_rows(double interior_tolerance);

struct UniformSplitSummary {
    double tolerance = 0;
    std::size_t triples = 0, with_d3d = 0, real_triangles = 0;
    double subpatch_ratio = 0, triangle_ratio = 0, longest_max = 0, longest_mean = 0;
    std::size_t longest_above_table = 0; // real-triangle triples whose longest edge is above 1.433
};
UniformSplitSummary summarize_uniform_split(const std::vector<UniformSplitRow>& rows,
                                            double interior_tolerance);
// The summaries for the default tolerance (1.433) and the strict one (1).
std::vector<UniformSplitSummary> uniform_split_summaries();

std::string uniform_split_markdown(const std::vector<UniformSplitSummary>& summaries);
std::string uniform_efficiency_markdown(const std::vector<UniformEfficiencyRow>& rows);
std::string uniform_efficiency_json(const std::vector<UniformEfficiencyRow>& rows,
                                    const std::vector<UniformSplitSummary>& split);

} // namespace ctess::analysis
