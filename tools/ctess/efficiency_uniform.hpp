// The uniform-density efficiency report (docs/algorithm.md §3): uniform triangle counts against D3D11
// integer partitioning (inside = max of the edges and inside = average) and against CP, over every sorted
// triple of the configured table (seed 001 reports 69 % of D3D11's uniform topology).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace ctess::cli {

struct UniformEfficiencyRow {
    std::array<std::uint32_t, 3> factors{};
    std::uint32_t uniform = 0, d3d_max = 0, d3d_avg = 0, cp = 0;
};

std::vector<UniformEfficiencyRow> uniform_efficiency_rows(unsigned cp_max_factor);

// Splitting above the table (§3.5): subpatches against binary longest-edge splitting to the same dice limit,
// and final triangles against D3D11 integer partitioning.
struct UniformSplitRow {
    std::array<float, 3> factors{};
    std::uint64_t subpatches = 0, binary_subpatches = 0, triangles = 0, d3d_max = 0;
};
std::vector<UniformSplitRow> uniform_split_rows();
std::string uniform_split_markdown(const std::vector<UniformSplitRow>& rows);
std::string uniform_efficiency_markdown(const std::vector<UniformEfficiencyRow>& rows);
std::string uniform_efficiency_json(const std::vector<UniformEfficiencyRow>& rows);

} // namespace ctess::cli
