// UniformSplit (docs/algorithm.md §3.5) against the code it was optimised from: the reference copy of commit
// 2407141f (tests/support/uniform_split_reference.hpp). Counts, depth, subpatches, every emitted vertex and
// index, every leaf and the longest edge must be identical, for both tables, both layouts, both windings and
// three interior tolerances, on fixed triples (clamped and bad input among them) and seeded random ones, at
// every depth (0: within the table, 1 and 2: split).
#include <ctess/runtime/uniform/split.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <catch2/catch.hpp>

#include "support/emit_all.hpp"
#include "support/uniform_split_reference.hpp"

namespace {

struct LeafRecord {
    std::array<double, 3> factors;
    std::array<std::array<std::int64_t, 2>, 3> corners;
    std::uint32_t depth, pattern;
    ctess::Counts counts;
    bool operator==(const LeafRecord&) const = default;
};

template <class Split>
std::vector<LeafRecord> leaves(const Split& s) {
    std::vector<LeafRecord> out;
    s.for_each_leaf([&](const auto& leaf) {
        out.push_back(
            {leaf.factors, leaf.corners, leaf.depth, leaf.patch.pattern_index(), leaf.patch.counts()});
    });
    return out;
}

bool same_points(const std::vector<ctess::DomainPoint>& a, const std::vector<ctess::DomainPoint>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].u != b[i].u || a[i].v != b[i].v) return false;
    return true;
}

} // namespace

TEST_CASE("uniform split: output identical to the reference code", "[uniform][split]") {
    constexpr float inf = std::numeric_limits<float>::infinity(),
                    nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<std::array<float, 3>> cases = {
        {40, 30, 20},  {193, 160, 254},   {100, 3, 99},    {256, 256, 256},
        {32, 32, 32},  {64, 64, 64},      {32, 12, 20},    {17, 1, 16},
        {16, 16, 17},  {255.4f, 17, 200}, {250, 9, 250},   {121, 121, 122},
        {inf, 5, 300}, {nan, 40, -3},     {1e9f, 1e9f, 2}, {33.5f, 64.49f, 31.51f},
        {16, 9, 11},   {8, 8, 8},         {11, 7, 3},      {1, 1, 1}};
    std::uint32_t state = 20261124u;
    for (int k = 0; k < 120; ++k) {
        std::array<float, 3> f{};
        for (float& x : f) x = static_cast<float>((state = state * 1664525u + 1013904223u) % 30000u) / 100.0f;
        cases.push_back(f);
    }
    std::array<int, 3> by_depth{}; // the cases compared at each depth: every depth must be reached
    for (const auto* tables : {&ctess::rt::uniform_tables_11, &ctess::rt::uniform_tables_16})
        for (const ctess::Layout layout : {ctess::Layout::provoking, ctess::Layout::shared})
            for (const ctess::Winding winding : {ctess::Winding::ccw, ctess::Winding::cw})
                for (const double tolerance : {ctess::rt::uniform_split_interior_tolerance, 1.2,
                                               ctess::rt::uniform_split_strict_tolerance})
                    for (const auto& f : cases) {
                        CAPTURE(tables->max_factor, layout == ctess::Layout::shared,
                                winding == ctess::Winding::cw, tolerance, f[0], f[1], f[2]);
                        const ctess::PatchOptions options{layout, winding};
                        const ctess::rt::UniformSplit now(*tables, f[0], f[1], f[2], options, tolerance);
                        const ctess::rt::reference::UniformSplit then(*tables, f[0], f[1], f[2], options,
                                                                      tolerance);
                        REQUIRE(now.counts() == then.counts());
                        REQUIRE(now.subpatch_count() == then.subpatch_count());
                        REQUIRE(now.depth() == then.depth());
                        ++by_depth[now.depth() < 3 ? now.depth() : 0];
                        REQUIRE(now.factors() == then.factors());
                        const ctess::test::Emitted a = ctess::test::emit_all(now),
                                                   b = ctess::test::emit_all(then);
                        REQUIRE(same_points(a.vertices, b.vertices));
                        REQUIRE(a.indices == b.indices);
                        REQUIRE(leaves(now) == leaves(then));
                        REQUIRE(now.longest_edge() == then.longest_edge());
                    }
    CHECK(by_depth[0] > 0);
    CHECK(by_depth[1] > 0);
    CHECK(by_depth[2] > 0);
}
