// UniformSplit (docs/algorithm.md §3.5) against golden digests of the code it was optimised from (the
// reference implementation of commit 2407141f, whose outputs these digests were taken from before it was
// removed from the tree). Counts, depth, subpatches, every emitted vertex and index, every leaf (corners,
// depth, pattern, counts) and the longest edge enter one FNV-1a digest per table, layout, winding and
// interior tolerance, over fixed triples
// (clamped and bad input among them) and seeded random ones at every depth (0: within the table, 1 and 2:
// split). The reference clamped factors to N^2; the inputs are clamped to N^2 here as it did, so the digests
// show that every output up to N^2 is unchanged by the deeper splitting above it. A changed digest means a
// changed output: the per-depth case counts and the first triple of each configuration are checked too, so a
// failure says where to look.
#include <ctess/runtime/uniform/split.hpp>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <catch2/catch.hpp>

#include "support/emit_all.hpp"

namespace {

// FNV-1a over 64-bit words (Fowler, Noll and Vo).
struct Digest {
    std::uint64_t h = 14695981039346656037ull;
    void word(std::uint64_t w) {
        for (int b = 0; b < 8; ++b) h = (h ^ ((w >> (8 * b)) & 0xff)) * 1099511628211ull;
    }
    void real(double x) { word(std::bit_cast<std::uint64_t>(x)); }
};

std::vector<std::array<float, 3>> split_cases() {
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
    return cases;
}

// Everything UniformSplit reports about one triple.
void add_split(Digest& d, const ctess::rt::UniformSplit& s) {
    d.word(s.counts().vertices), d.word(s.counts().triangles);
    d.word(s.subpatch_count()), d.word(s.depth());
    for (double f : s.factors()) d.real(f);
    const auto e = ctess::test::emit_all(s);
    for (const auto& p : e.vertices) d.word(std::uint64_t{p.u} << 32 | p.v);
    for (std::uint32_t i : e.indices) d.word(i);
    s.for_each_leaf([&](const auto& leaf) {
        for (const auto& c : leaf.corners)
            d.word(static_cast<std::uint64_t>(c[0])), d.word(static_cast<std::uint64_t>(c[1]));
        d.word(leaf.depth), d.word(leaf.patch.pattern_index());
        d.word(leaf.patch.counts().vertices), d.word(leaf.patch.counts().triangles);
    });
    d.real(s.longest_edge());
}

struct Golden {
    std::uint32_t max_factor;
    bool shared, cw;
    double tolerance;
    std::uint64_t digest;
    std::array<int, 3> by_depth; // how many of the triples reach depth 0, 1, 2
};

// Taken from the reference implementation (commit 2407141f) over split_cases(), then again from f39a511
// without the leaf factors' double bits (its outputs still had 2407141f's digests): the decisions read exact
// squared factors since (§3.5, "Exact factors"), and the same outputs show that they decide as the doubles
// did.
constexpr Golden golden[] = {
#include "uniform_split_golden.inc"
};

} // namespace

TEST_CASE("uniform split: output identical to the reference code's golden digests", "[uniform][split]") {
    const std::vector<std::array<float, 3>> cases = split_cases();
    std::size_t g = 0;
    std::array<int, 3> all_depths{};
    for (const auto* tables : {&ctess::rt::uniform_tables_11, &ctess::rt::uniform_tables_16})
        for (const ctess::Layout layout : {ctess::Layout::provoking, ctess::Layout::shared})
            for (const ctess::Winding winding : {ctess::Winding::ccw, ctess::Winding::cw})
                for (const double tolerance : {ctess::rt::uniform_split_interior_tolerance, 1.2,
                                               ctess::rt::uniform_split_strict_tolerance}) {
                    Digest d;
                    std::array<int, 3> by_depth{};
                    for (const auto& input : cases) {
                        // The reference clamped factors to N^2; clamping above it is the only change since
                        // (§3.5: up to 32768), so the inputs are clamped here as it did (NaN stays NaN).
                        const float top = float(tables->max_factor * tables->max_factor);
                        std::array<float, 3> f = input;
                        for (float& x : f) x = x > top ? top : x;
                        const ctess::rt::UniformSplit s(*tables, f[0], f[1], f[2], {layout, winding},
                                                        tolerance);
                        REQUIRE(s.depth() < 3);
                        ++by_depth[s.depth()];
                        add_split(d, s);
                    }
                    REQUIRE(g < std::size(golden));
                    const Golden& expect = golden[g++];
                    CAPTURE(tables->max_factor, layout == ctess::Layout::shared,
                            winding == ctess::Winding::cw, tolerance);
                    REQUIRE(expect.max_factor == tables->max_factor);
                    REQUIRE(expect.shared == (layout == ctess::Layout::shared));
                    REQUIRE(expect.cw == (winding == ctess::Winding::cw));
                    REQUIRE(expect.tolerance == tolerance);
                    CHECK(by_depth == expect.by_depth);
                    CHECK(d.h == expect.digest);
                    for (int k = 0; k < 3; ++k) all_depths[k] += by_depth[k];
                }
    CHECK(g == std::size(golden));
    CHECK(all_depths[0] > 0);
    CHECK(all_depths[1] > 0);
    CHECK(all_depths[2] > 0);
}
