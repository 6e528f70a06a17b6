// CP efficiency against D3D11 fractional_even: the targets on seeded random triples, and the exact
// 2/3 ratio of triforce (N^2) against D3D11's picture-frame rings (1.5 N^2) at equal powers of two.
#include <catch2/catch.hpp>

#include "efficiency.hpp"

TEST_CASE("mean CP / D3D11 fractional_even ratio meets the targets", "[cp_efficiency]") {
    for (unsigned max : {64u, 256u}) {
        for (std::uint32_t seed : {2026u, 7u, 123456u}) {
            const auto rows = ctess::cli::efficiency_rows(max, 40, seed);
            const auto s = ctess::cli::summarize(rows);
            INFO("max " << max << " seed " << seed);
            REQUIRE(s.random_count == 40);
            CHECK(s.mean_ratio_max <= 0.35);
            CHECK(s.mean_ratio_avg <= 0.65);
            CHECK(s.mean_nondegenerate_ratio_max <= s.mean_ratio_max);
        }
    }
}

TEST_CASE("equal powers of two: CP is exactly 2/3 of D3D11 fractional_even", "[cp_efficiency]") {
    for (const auto& r : ctess::cli::efficiency_rows(64, 1, 1)) {
        if (r.group != "equal") continue;
        const float f = r.factors[0];
        if (f != 4 && f != 8 && f != 16 && f != 32 && f != 64) continue;
        const auto n = static_cast<std::uint32_t>(f);
        CHECK(r.cp_triangles == n * n); // triforce
        CHECK(r.cp_nondegenerate == n * n);
        CHECK(r.d3d_max == 3 * n * n / 2); // spec 4.6: floor(3 S^2 / 2) for uniform even S
        CHECK(3 * r.cp_triangles == 2 * r.d3d_max);
    }
}
