// Uniform-density patterns (docs/algorithm.md §3): the checked-in pattern data of gen/uniform_gen, read in
// constant expressions. A pattern exists for every sorted factor triple f0 >= f1 >= f2 in [1, 16], on the
// edges e0 = v0 -> v1 (v = 0), e1 = v1 -> v2 (u + v = 1) and e2 = v0 -> v2 (u = 0). Its vertices use the
// canonical numbering: the f0 + f1 + f2 boundary vertices counter-clockwise (v0, e0's points, v1, e1's
// points, v2, e2's points back to v0), then the interior vertices of the data. Coordinates are exact
// integers (u, v) in units of fixed_one = 65534.
#pragma once
#include <array>
#include <cstdint>

#include <ctess/core/domain_point.hpp>
#include <ctess/uniform/patterns_data.hpp>
#include <ctess/uniform/quantise.hpp>

namespace ctess::uniform {

inline constexpr unsigned data_max_factor = data::max_factor;

// Patterns whose factors are all at most n.
constexpr unsigned pattern_count(unsigned n) {
    return n * (n + 1) * (n + 2) / 6;
}

// The O(1) index of a sorted triple f0 >= f1 >= f2 >= 1 (patterns are stored f0 = 1..N, f1 = 1..f0,
// f2 = 1..f1, so the triples of a smaller maximum are a prefix).
constexpr unsigned pattern_index(unsigned f0, unsigned f1, unsigned f2) {
    return (f0 - 1) * f0 * (f0 + 1) / 6 + (f1 - 1) * f1 / 2 + (f2 - 1);
}

// Triangles of a pattern with the given boundary and interior vertex counts (Euler on a disk).
constexpr unsigned triangle_count(unsigned boundary, unsigned interior) {
    return 2 * interior + boundary - 2;
}

// Canonical boundary vertex k < f0 + f1 + f2 of the triple (f0, f1, f2).
constexpr Point boundary_vertex(unsigned f0, unsigned f1, unsigned f2, unsigned k) {
    if (k < f0) return {edge_parameter(k, f0), 0};
    k -= f0;
    if (k < f1) {
        const std::uint32_t v = edge_parameter(k, f1);
        return {fixed_one - v, v};
    }
    k -= f1;
    return {0, edge_parameter(f2 - k, f2)}; // from v2 back towards v0
}

// Prefix sums of the data: where each pattern's interior vertices and triangles start.
struct PatternOffsets {
    std::array<std::uint32_t, data::pattern_count + 1> interior{};
    std::array<std::uint32_t, data::pattern_count + 1> triangle{};
};

constexpr PatternOffsets build_pattern_offsets() {
    PatternOffsets o;
    for (unsigned p = 0; p < data::pattern_count; ++p) {
        const data::PatternRecord& r = data::patterns[p];
        o.interior[p + 1] = o.interior[p] + r.interior;
        o.triangle[p + 1] = o.triangle[p] + triangle_count(r.f0 + r.f1 + r.f2, r.interior);
    }
    return o;
}

inline constexpr PatternOffsets pattern_offsets = build_pattern_offsets();

static_assert(sizeof(data::interior) / sizeof(data::interior[0]) == pattern_offsets.interior.back(),
              "uniform pattern data: interior vertex count mismatch");
static_assert(sizeof(data::triangles) / sizeof(data::triangles[0]) == pattern_offsets.triangle.back(),
              "uniform pattern data: triangle count mismatch");

// One pattern of the sorted triple (f0, f1, f2), 1 <= f2 <= f1 <= f0 <= data_max_factor.
struct Pattern {
    unsigned f0 = 1, f1 = 1, f2 = 1;
    unsigned index = 0;

    constexpr unsigned boundary_count() const { return f0 + f1 + f2; }
    constexpr unsigned interior_count() const { return data::patterns[index].interior; }
    constexpr unsigned vertex_count() const { return boundary_count() + interior_count(); }
    constexpr unsigned triangle_count() const {
        return pattern_offsets.triangle[index + 1] - pattern_offsets.triangle[index];
    }
    constexpr Point vertex(unsigned k) const {
        if (k < boundary_count()) return boundary_vertex(f0, f1, f2, k);
        const data::InteriorVertex& q =
            data::interior[pattern_offsets.interior[index] + k - boundary_count()];
        return {q.u, q.v};
    }
    // Counter-clockwise in the (u, v) plane.
    constexpr std::array<unsigned, 3> triangle(unsigned t) const {
        const data::TriangleRecord& r = data::triangles[pattern_offsets.triangle[index] + t];
        return {r.i0, r.i1, r.i2};
    }
};

constexpr Pattern pattern(unsigned f0, unsigned f1, unsigned f2) {
    return {f0, f1, f2, pattern_index(f0, f1, f2)};
}

} // namespace ctess::uniform
