// Grid triangle strips (Cayzac 2007): the post's strip, exhaustive cell coverage and winding for every grid
// up to 64 x 64, the triangle-list conversion, grid evaluation, and bad sizes.
#include <catch2/catch.hpp>

#include <ctess/analysis/signed_area.hpp>
#include <ctess/surface/grid_eval.hpp>
#include <ctess/surface/grid_strip.hpp>

#include <array>
#include <cstdint>
#include <vector>

using namespace ctess::grid;

namespace {

struct GridPoint {
    std::int64_t x, y;
};

GridPoint grid_point(std::uint32_t index, std::uint32_t u_segments) {
    return {index % (u_segments + 1), index / (u_segments + 1)};
}

} // namespace

TEST_CASE("the 3 x 4 strip starts with Cayzac 2007's sequence", "[grid]") {
    constexpr std::array<std::uint32_t, 24> seed = {0, 4, 1, 5, 2, 6,  3, 7,  11, 7,  10, 6,
                                                    9, 5, 8, 4, 8, 12, 9, 13, 10, 14, 11, 15};
    STATIC_REQUIRE(strip_index_count(3, 4) == 32); // the post's 3 x 4 strip has 32 indices
    constexpr auto strip = [] {
        std::array<std::uint32_t, 32> s{};
        fill_strip_indices(s, 3, 4);
        return s;
    }();
    STATIC_REQUIRE(strip[8] == 11);
    for (std::size_t i = 0; i < seed.size(); ++i) CHECK(strip[i] == seed[i]);
    CHECK(grid_counts(3, 4) == ctess::Counts{20, 24});
}

TEST_CASE("every cell of every grid up to 64 x 64 is covered by two strip triangles of one winding",
          "[grid]") {
    for (std::uint32_t U = 1; U <= 64; ++U) {
        for (std::uint32_t V = 1; V <= 64; ++V) {
            const std::uint32_t n = strip_index_count(U, V);
            REQUIRE(n == 2 * (U + 1) * V);
            std::vector<std::uint32_t> strip(n);
            REQUIRE(fill_strip_indices(strip, U, V));
            const std::uint32_t vertex_count = grid_counts(U, V).vertices;
            for (std::uint32_t s : strip) REQUIRE(s < vertex_count);

            std::vector<int> per_cell(U * V, 0);
            std::vector<std::uint32_t> kept; // the non-degenerate strip triangles, with strip winding
            std::uint32_t degenerate = 0;
            for (std::uint32_t k = 0; k + 2 < n; ++k) {
                const std::uint32_t i0 = (k & 1u) ? strip[k + 1] : strip[k];
                const std::uint32_t i1 = (k & 1u) ? strip[k] : strip[k + 1];
                const std::uint32_t i2 = strip[k + 2];
                const GridPoint a = grid_point(i0, U), b = grid_point(i1, U), c = grid_point(i2, U);
                // Twice the signed area in grid units (positive = counter-clockwise with v up).
                const auto area = ctess::analysis::signed_area2(a, b, c);
                REQUIRE((area == 0) == strip_triangle_is_turnaround(k, U));
                if (area == 0) {
                    ++degenerate;
                    continue;
                }
                REQUIRE(area == -1); // half a cell, clockwise with v up
                const std::int64_t x0 = std::min({a.x, b.x, c.x}), y0 = std::min({a.y, b.y, c.y});
                REQUIRE(std::max({a.x, b.x, c.x}) == x0 + 1);
                REQUIRE(std::max({a.y, b.y, c.y}) == y0 + 1);
                ++per_cell[y0 * U + x0];
                kept.insert(kept.end(), {i0, i1, i2});
            }
            CHECK(degenerate == 2 * (V - 1));
            for (int c : per_cell) REQUIRE(c == 2);

            std::vector<std::uint32_t> list(3 * grid_counts(U, V).triangles);
            REQUIRE(fill_triangle_list(list, U, V));
            REQUIRE(list == kept);
        }
    }
}

TEST_CASE("bad grid sizes and short spans write nothing", "[grid]") {
    std::array<std::uint32_t, 64> buf{};
    buf.fill(7u);
    CHECK_FALSE(fill_strip_indices(buf, 0, 3));
    CHECK_FALSE(fill_strip_indices(buf, 3, 0));
    CHECK_FALSE(fill_strip_indices(buf, max_segments + 1, 1));
    CHECK_FALSE(fill_strip_indices(std::span(buf).first(31), 3, 4)); // needs 32
    CHECK_FALSE(fill_triangle_list(std::span(buf).first(3 * 24 - 1), 3, 4));
    for (std::uint32_t b : buf) CHECK(b == 7u);
    CHECK(grid_counts(0, 5) == ctess::Counts{});
    CHECK(strip_index_count(max_segments + 1, 2) == 0);
    CHECK(strip_index_count(max_segments, max_segments) == 2u * (max_segments + 1) * max_segments);
    CHECK(fill_strip_indices(std::span(buf).first(32), 3, 4));
}

TEST_CASE("grid evaluation calls f at exact grid parameters, in strip vertex order", "[grid]") {
    struct UV {
        float u = -1.0f, v = -1.0f;
    };
    constexpr auto uv_grid = [] {
        std::array<UV, 20> g{};
        evaluate_grid(std::span<UV>(g), 3, 4, [](float u, float v) { return UV{u, v}; });
        return g;
    }();
    STATIC_REQUIRE(uv_grid[0].u == 0.0f);
    STATIC_REQUIRE(uv_grid[19].u == 1.0f);
    STATIC_REQUIRE(uv_grid[19].v == 1.0f);
    for (std::uint32_t y = 0; y <= 4; ++y) {
        for (std::uint32_t x = 0; x <= 3; ++x) {
            CHECK(uv_grid[y * 4 + x].u == static_cast<float>(x) / 3.0f);
            CHECK(uv_grid[y * 4 + x].v == static_cast<float>(y) / 4.0f);
        }
    }
    std::array<UV, 19> short_buffer{};
    CHECK_FALSE(evaluate_grid(std::span<UV>(short_buffer), 3, 4, [](float u, float v) { return UV{u, v}; }));
    CHECK(short_buffer[0].u == -1.0f);
}
