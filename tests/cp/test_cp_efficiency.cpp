// CP efficiency against D3D11 fractional_even: the targets on seeded random triples, and the exact
// 2/3 ratio of triforce (N^2) against D3D11's picture-frame rings (1.5 N^2) at equal powers of two.
#include <catch2/catch.hpp>

#include <ctess/analysis/efficiency.hpp>
#include <ctess/analysis/signed_area.hpp>
#include <ctess/cp/pattern.hpp>

#include <cstdint>
#include <vector>

TEST_CASE("mean CP / D3D11 fractional_even ratio meets the targets", "[cp_efficiency]") {
    for (unsigned max : {64u, 256u}) {
        for (std::uint32_t seed : {2026u, 7u, 123456u}) {
            const auto rows = ctess::analysis::efficiency_rows(max, 40, seed);
            const auto s = ctess::analysis::summarize(rows);
            INFO("max " << max << " seed " << seed);
            REQUIRE(s.random_count == 40);
            CHECK(s.mean_ratio_max <= 0.35);
            CHECK(s.mean_ratio_avg <= 0.65);
            CHECK(s.mean_nondegenerate_ratio_max <= 0.35);
        }
    }
}

TEST_CASE("efficiency rows count CP's zero-area triangles as the pattern has them", "[cp_efficiency]") {
    // The analysis library's counts against the procedural pattern, tessellated and measured here: exact
    // integer areas.
    std::size_t degenerate_rows = 0;
    for (const auto& r : ctess::analysis::efficiency_rows(64, 40, 2026)) {
        ctess::cp::PatternOptions opt;
        opt.layout = ctess::Layout::shared;
        const auto n = ctess::cp::pattern_counts(r.factors[0], r.factors[1], r.factors[2], opt);
        std::vector<ctess::DomainPoint> v(n.vertices);
        std::vector<std::uint32_t> t(3 * std::size_t{n.triangles});
        ctess::cp::tessellate(v, t, r.factors[0], r.factors[1], r.factors[2], opt);
        std::uint32_t zero_area = 0;
        for (std::size_t k = 0; k < t.size(); k += 3) {
            const auto cross = ctess::analysis::signed_area2(v[t[k]], v[t[k + 1]], v[t[k + 2]]);
            zero_area += cross == 0;
            CHECK(cross >= 0); // counter-clockwise or degenerate, never folded
        }
        INFO(r.group << " " << r.factors[0] << "," << r.factors[1] << "," << r.factors[2]);
        CHECK(r.cp_triangles == n.triangles);
        CHECK(r.cp_nondegenerate == n.triangles - zero_area);
        degenerate_rows += zero_area != 0;
    }
    CHECK(degenerate_rows > 0); // the set includes factors whose patterns have zero-area triangles
}

TEST_CASE("efficiency orients with the library's rule: factors 5,2,2 become 2,5,2", "[cp_efficiency]") {
    // smallest_edge_rotation: ties go to the lowest edge index, so E1 (2) goes to e2, and e0 gets E2.
    const ctess::cp::PatternOptions opt;
    const auto oriented = ctess::cp::pattern_counts(2, 5, 2, opt).triangles;
    const auto unoriented = ctess::cp::pattern_counts(5, 2, 2, opt).triangles;
    REQUIRE(oriented != unoriented);
    REQUIRE(ctess::analysis::efficiency_row({5, 2, 2}, 64).cp_rotated_triangles == oriented);
}

TEST_CASE("equal powers of two: CP is exactly 2/3 of D3D11 fractional_even", "[cp_efficiency]") {
    unsigned checked = 0;
    for (const auto& r : ctess::analysis::efficiency_rows(64, 1, 1)) {
        if (r.group != "equal") continue;
        const float f = r.factors[0];
        if (f != 4 && f != 8 && f != 16 && f != 32 && f != 64) continue;
        const auto n = static_cast<std::uint32_t>(f);
        CHECK(r.cp_triangles == n * n); // triforce
        CHECK(r.cp_nondegenerate == n * n);
        CHECK(r.d3d_max == 3 * n * n / 2); // docs/algorithm.md §5.5: floor(3 S^2 / 2) for uniform even S
        CHECK(3 * r.cp_triangles == 2 * r.d3d_max);
        ++checked;
    }
    REQUIRE(checked == 5); // 4, 8, 16, 32, 64
}
