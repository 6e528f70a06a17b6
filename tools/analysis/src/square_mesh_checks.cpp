#include <ctess/analysis/signed_area.hpp>
#include <ctess/analysis/square_mesh_checks.hpp>

#include <map>
#include <set>
#include <utility>

namespace ctess::analysis {

std::string square_mesh_violation(std::span<const SquarePoint> params,
                                  std::span<const std::uint32_t> triangles, std::int64_t one) {
    std::set<std::pair<std::int64_t, std::int64_t>> distinct;
    for (const SquarePoint& v : params) {
        if (v.p < 0 || v.q < 0 || v.p > one || v.q > one) return "vertex outside the square";
        if (!distinct.insert({v.p, v.q}).second) return "two vertices share a parameter";
    }
    int128 area_sum = 0;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (std::size_t t = 0; t + 3 <= triangles.size(); t += 3) {
        const std::uint32_t i[3] = {triangles[t], triangles[t + 1], triangles[t + 2]};
        for (std::uint32_t k : i)
            if (k >= params.size()) return "index out of range";
        const SquarePoint a = params[i[0]], b = params[i[1]], c = params[i[2]];
        const auto area2 = signed_area2(a, b, c);
        if (area2 <= 0) return "a triangle is not counter-clockwise with positive area";
        area_sum += area2;
        for (int e = 0; e < 3; ++e)
            if (++directed[{i[e], i[(e + 1) % 3]}] > 1) return "a directed edge is used twice";
    }
    if (area_sum != 2 * one * one) return "the areas do not sum to the square's";
    for (const auto& [edge, n] : directed) {
        const bool twin = directed.count({edge.second, edge.first}) != 0;
        const SquarePoint a = params[edge.first], b = params[edge.second];
        const bool on_boundary =
            (a.p == b.p && (a.p == 0 || a.p == one)) || (a.q == b.q && (a.q == 0 || a.q == one));
        if (on_boundary == twin)
            return on_boundary ? "a boundary edge is used twice" : "an interior edge is used once";
        (void)n;
    }
    return "";
}

} // namespace ctess::analysis
