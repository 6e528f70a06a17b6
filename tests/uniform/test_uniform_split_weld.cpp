// The shared (welded) layout of a split uniform patch (docs/algorithm.md §3.5): the library's output equals
// an independent weld (a std::map of exact positions) of the provoking layout's triangles, vertex for vertex
// and triangle for triangle (as position triples, orientation kept); its vertex count is Euler's 1 + (T + B)
// / 2 on a disk; no position twice; every index in range; a short span writes nothing.
#include <ctess/runtime/uniform/split.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <vector>

#include <catch2/catch.hpp>

#include "support/emit_all.hpp"

using ctess::Layout;
using ctess::PatchOptions;
using ctess::Winding;
using ctess::rt::UniformSplit;
using ctess::test::emit_all;
using ctess::uniform::SplitPoint;

namespace {

using Position = std::pair<std::uint32_t, std::uint32_t>;
using Triple = std::array<Position, 3>;

Position position(SplitPoint p) {
    return {p.u, p.v};
}

// A triangle's positions rotated so the smallest comes first: the same cyclic order, so the same orientation.
Triple canonical(Position a, Position b, Position c) {
    Triple t{a, b, c};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
}

std::multiset<Triple> triangles_of(const ctess::test::BasicEmitted<SplitPoint>& e) {
    std::multiset<Triple> out;
    for (std::size_t t = 0; t < e.indices.size(); t += 3)
        out.insert(canonical(position(e.vertices[e.indices[t]]), position(e.vertices[e.indices[t + 1]]),
                             position(e.vertices[e.indices[t + 2]])));
    return out;
}

std::vector<std::array<float, 3>> triples_above(std::uint32_t n) {
    constexpr float nan_f = std::numeric_limits<float>::quiet_NaN();
    constexpr float inf_f = std::numeric_limits<float>::infinity();
    std::vector<std::array<float, 3>> cases = {
        {40, 30, 25},        {40, 30, 20},        {176, 176, 176},    {256, 256, 256},      {121, 121, 121},
        {17, 1, 16},         {100, 3, 99},        {250, 9, 250},      {255.4f, 17, 200},    {193, 160, 254},
        {222, 193, 192},     {93, 231, 142},      {256, 256, 210},    {1e9f, 5, 200},       {inf_f, 5, 200},
        {nan_f, 300, 1e30f}, {-inf_f, inf_f, 40}, {12.5f, 11.5f, 40}, {1e30f, 1e30f, 1e30f}};
    // Factors above N^2 clamp to N^2 here, to keep the emitted size small (1e30 would give 32768: a billion
    // triangles); thin triples below reach the deeper levels (test_uniform_split_deep covers them in full).
    const float top = float(n * n);
    for (auto& f : cases)
        for (float& x : f) x = x > top ? top : x;
    cases.push_back({float(n * n * 3), 20, float(n * n * 3 - 10)});
    cases.push_back({float(n * n * n), 1, float(n * n * n)});
    std::uint32_t state = 1001 + n;
    for (int k = 0; k < 40; ++k) {
        std::array<float, 3> f{};
        for (float& x : f) x = static_cast<float>(1 + (state = state * 1664525u + 1013904223u) % (n * n));
        cases.push_back(f);
    }
    return cases;
}

} // namespace

TEST_CASE("uniform split shared: equals an independent weld of the provoking output",
          "[uniform][split][weld]") {
    const std::uint64_t one = ctess::rt::uniform_split_fixed_one;
    std::uint32_t depth_two = 0;
    // Both interior dice tolerances (§3.5): the default 1.433 N and the strict N.
    for (const double tolerance :
         {ctess::rt::uniform_split_interior_tolerance, ctess::rt::uniform_split_strict_tolerance})
        for (const auto* set : {&ctess::rt::uniform_tables_11, &ctess::rt::uniform_tables_16})
            for (const Winding winding : {Winding::ccw, Winding::cw})
                for (const auto& f : triples_above(set->max_factor)) {
                    INFO("N " << set->max_factor << " tolerance " << tolerance << " factors " << f[0] << ","
                              << f[1] << "," << f[2] << " winding "
                              << (winding == Winding::ccw ? "ccw" : "cw"));
                    const UniformSplit shared(*set, f[0], f[1], f[2], PatchOptions{Layout::shared, winding},
                                              tolerance);
                    const UniformSplit provoking(*set, f[0], f[1], f[2],
                                                 PatchOptions{Layout::provoking, winding}, tolerance);
                    depth_two += shared.depth() == 2;
                    const auto s = emit_all(shared), p = emit_all(provoking);

                    // The independent weld: one number per exact position the provoking triangles use.
                    std::map<Position, std::uint32_t> weld;
                    for (const std::uint32_t i : p.indices) weld.emplace(position(p.vertices[i]), 0u);
                    REQUIRE(shared.counts().vertices == weld.size());
                    REQUIRE(shared.counts().triangles == provoking.counts().triangles);

                    // No position twice, and the same positions.
                    std::set<Position> out;
                    for (const SplitPoint& d : s.vertices) out.insert(position(d));
                    REQUIRE(out.size() == s.vertices.size());
                    REQUIRE(std::equal(out.begin(), out.end(), weld.begin(), weld.end(),
                                       [](const Position& a, const auto& b) { return a == b.first; }));

                    // Every index in range; the same triangles with the same orientation.
                    for (const std::uint32_t i : s.indices) REQUIRE(i < s.vertices.size());
                    REQUIRE(triangles_of(s) == triangles_of(p));

                    // Euler on a disk: V = 1 + (T + B) / 2, B the boundary points (one per boundary segment).
                    std::uint64_t boundary = 0;
                    for (const Position& q : out)
                        boundary += q.second == 0 || q.first == 0 || std::uint64_t{q.first} + q.second == one;
                    CHECK(shared.counts().vertices == 1 + (shared.counts().triangles + boundary) / 2);
                    CHECK((shared.counts().triangles + boundary) % 2 == 0);
                }
    CHECK(depth_two >= 20); // the cases reach depth 2 at both N and both tolerances
}

TEST_CASE("uniform split shared: welded counts for a few triples", "[uniform][split][weld]") {
    // Far fewer vertices than the subpatches' own vertices; 256^3 at N = 16 is the regular grid of 65536
    // triangles, welded to its (256 + 1)(256 + 2) / 2 positions.
    const UniformSplit grid(ctess::rt::uniform_tables_16, 256, 256, 256, {Layout::shared, Winding::ccw});
    CHECK(grid.counts() == ctess::Counts{257u * 258u / 2u, 65536u});
    const UniformSplit grid11(ctess::rt::uniform_tables_11, 121, 121, 121, {Layout::shared, Winding::ccw});
    CHECK(grid11.counts() == ctess::Counts{122u * 123u / 2u, 121u * 121u});
}

TEST_CASE("uniform split shared: below the table it is UniformPatch's shared layout, scaled",
          "[uniform][split][weld]") {
    const auto& set = ctess::rt::uniform_tables_16;
    const PatchOptions options{Layout::shared, Winding::cw};
    const UniformSplit s(set, 11, 9, 6, options);
    const ctess::rt::UniformPatch p(set, 11, 9, 6, options);
    REQUIRE(s.counts() == p.counts());
    const auto e = emit_all(s);
    const auto q = emit_all(p);
    for (std::uint32_t i = 0; i < p.counts().vertices; ++i)
        REQUIRE(e.vertices[i] == ctess::exact_convert<ctess::units::split>(q.vertices[i]));
    REQUIRE(e.indices == q.indices);
}

TEST_CASE("uniform split shared: emit refuses small spans and writes nothing",
          "[uniform][split][weld][bad_input]") {
    for (const auto* set : {&ctess::rt::uniform_tables_11, &ctess::rt::uniform_tables_16}) {
        const UniformSplit s(*set, 176, 40, 100, {Layout::shared, Winding::ccw});
        const ctess::Counts n = s.counts();
        for (const bool short_vertices : {true, false}) {
            std::vector<SplitPoint> v(n.vertices - (short_vertices ? 1 : 0), SplitPoint{7, 7});
            std::vector<std::uint32_t> idx(n.index_count() - (short_vertices ? 0 : 1), 7u);
            CHECK_FALSE(s.emit(v, idx));
            CHECK(std::all_of(v.begin(), v.end(), [](SplitPoint d) { return d == SplitPoint{7, 7}; }));
            CHECK(std::all_of(idx.begin(), idx.end(), [](std::uint32_t i) { return i == 7u; }));
        }
        // Spans larger than needed: only the first counts() entries are written.
        std::vector<SplitPoint> v(n.vertices + 1, SplitPoint{7, 7});
        std::vector<std::uint32_t> idx(n.index_count() + 1, 7u);
        REQUIRE(s.emit(v, idx));
        CHECK(v.back() == SplitPoint{7, 7});
        CHECK(idx.back() == 7u);
    }
}
