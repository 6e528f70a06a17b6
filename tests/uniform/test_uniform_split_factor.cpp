// The exact squared factors of uniform splitting (constexpr/ctess/uniform/split_factor.hpp, docs/algorithm.md
// §3.5, "Exact factors"): the portable 128-bit steps against the compiler's __int128, the square root and the
// rounding exhaustively near every threshold, every root edge's pieces against the exact rational rounding,
// and the interior rule's symmetry.
#include <ctess/uniform/split_factor.hpp>

#include <array>
#include <cstdint>

#include <catch2/catch.hpp>

namespace {

using namespace ctess::uniform;

std::uint64_t next(std::uint64_t& state) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return state ^ (state >> 29);
}

#if defined(__SIZEOF_INT128__)
__extension__ typedef __int128 int128; // the compiler's, without -Wpedantic's complaint
__extension__ typedef unsigned __int128 uint128;

// The same formula in the compiler's 128-bit integers: an independent evaluation.
SquaredFactor segment_reference(const std::array<SquaredFactor, 3>& s, std::int64_t du, std::int64_t dv) {
    const std::int64_t dw = -du - dv;
    const int128 q = -static_cast<int128>(s[2]) * (dv * dw) - static_cast<int128>(s[0]) * (dw * du) -
                     static_cast<int128>(s[1]) * (du * dv);
    if (q <= 0) return 0;
    return static_cast<SquaredFactor>(q / (static_cast<int128>(fixed_one) * fixed_one));
}
#endif

} // namespace

TEST_CASE("split factor: floor(2f) exactly, at run time and in constant expressions",
          "[uniform][split][factor]") {
    static_assert(floor_twice_factor(0) == 0 && floor_twice_factor(squared_factor_max) == 65536 &&
                  floor_twice_factor(squared_factor_max - 1) == 65535);
    static_assert(floor_twice_factor(std::uint64_t{1} << 30) == 1 && floor_twice_factor((1u << 30) - 1) == 0);
    // Every m: m^2 2^30 itself, one below it, and the largest value below the next one.
    for (std::uint64_t m = 1; m <= 65536; ++m) {
        const std::uint64_t at = m * m << 30;
        REQUIRE(floor_twice_factor(at) == m);
        REQUIRE(floor_twice_factor(at - 1) == m - 1);
        if (m < 65536) REQUIRE(floor_twice_factor(((m + 1) * (m + 1) << 30) - 1) == m);
    }
    std::uint64_t state = 7;
    for (int k = 0; k < 200000; ++k) {
        const std::uint64_t s = next(state) % (squared_factor_max + 1);
        const std::uint64_t m = floor_twice_factor(s);
        REQUIRE((m * m << 30) <= s);
        REQUIRE(((m + 1) * (m + 1) << 30) > s);
    }
}

TEST_CASE("split factor: rounding and the dice limit at every half-integer up to 32768",
          "[uniform][split][factor]") {
    // f = k - 1/2 exactly is s = (2k - 1)^2 2^30; one unit below it must round down.
    for (std::uint64_t k = 1; k <= 32768; ++k) {
        const std::uint64_t s = (2 * k - 1) * (2 * k - 1) << 30;
        REQUIRE(rounded_factor(s) == k);
        REQUIRE(rounded_factor(s - 1) == k - 1);
        REQUIRE(rounded_factor(squared_factor(static_cast<std::uint32_t>(k))) == k);
        for (std::uint32_t n : {11u, 16u, 255u}) { // the leaves' clamped rounding, without a square root
            const auto clamped = [n](std::uint64_t x) { return x < 1 ? 1 : x > n ? n : x; };
            REQUIRE(rounded_factor_within(s, n) == clamped(k));
            REQUIRE(rounded_factor_within(s - 1, n) == clamped(k - 1));
        }
    }
    for (std::uint32_t n : {11u, 16u}) {
        const std::uint64_t half_past = std::uint64_t{2 * n + 1} * (2 * n + 1) << 30;
        CHECK(below_half_past(half_past - 1, n));
        CHECK_FALSE(below_half_past(half_past, n));
        // The interior limit: f < n * tolerance, rounded up to whole units of 2^-32 in f^2.
        CHECK(interior_limit_squared(n, 1.0) == squared_factor(n));
        const double x = n * 1.433;
        CHECK(static_cast<double>(interior_limit_squared(n, 1.433)) >= x * x * 4294967296.0);
        CHECK(static_cast<double>(interior_limit_squared(n, 1.433) - 1) < x * x * 4294967296.0);
    }
}

TEST_CASE("split factor: every piece of every root edge rounds as its exact rational length",
          "[uniform][split][factor]") {
    // A piece between parameters a < b of a root edge of factor t has length t (b - a) / 65534; it rounds
    // (halves up) to floor((2 t (b - a) + 65534) / (2 x 65534)). The squares floor f^2 2^32 and still round
    // alike: every threshold is a multiple of the unit.
    std::uint64_t checked = 0;
    for (std::uint32_t t = 1; t <= 32768; ++t) {
        const SquaredFactor s = squared_factor(t);
        for (std::uint32_t k = 2; k <= 16; ++k)
            for (std::uint32_t p = 0; p < k; ++p) {
                const std::uint32_t a = edge_parameter(p, k), b = edge_parameter(p + 1, k);
                const std::uint64_t exact = (2 * std::uint64_t{t} * (b - a) + fixed_one) / (2 * fixed_one);
                const SquaredFactor piece = piece_squared_factor(s, a, b);
                if (rounded_factor(piece) != exact) FAIL("t " << t << " k " << k << " p " << p);
                // The mirrored piece (k - 1 - p) has the same span (symmetric quantisation, §3.2).
                if (piece_squared_factor(s, edge_parameter(k - 1 - p, k), edge_parameter(k - p, k)) != piece)
                    FAIL("mirror t " << t << " k " << k << " p " << p);
                ++checked;
            }
    }
    CHECK(checked == 32768ull * 135);
}

TEST_CASE("split factor: the interior rule in portable words equals 128-bit integers, either direction",
          "[uniform][split][factor]") {
    std::uint64_t state = 20261127;
    for (int k = 0; k < 300000; ++k) {
        std::array<SquaredFactor, 3> s{};
        for (SquaredFactor& x : s) x = next(state) % (squared_factor_max + 1);
        if (k % 5 == 0) s[k % 3] = squared_factor_max; // the largest squares
        // A segment between two points of the pattern triangle (u, v >= 0, u + v <= 65534).
        const auto point = [&] {
            const std::int64_t u = static_cast<std::int64_t>(next(state) % (fixed_one + 1));
            const std::int64_t v = static_cast<std::int64_t>(next(state) % (fixed_one + 1 - u));
            return std::array<std::int64_t, 2>{u, v};
        };
        const auto a = point(), b = point();
        const std::int64_t du = b[0] - a[0], dv = b[1] - a[1];
        const SquaredFactor q = segment_squared_factor(s, du, dv);
        REQUIRE(q == segment_squared_factor(s, -du, -dv));
        REQUIRE(q <= std::max({s[0], s[1], s[2]})); // never longer than the longest side
#if defined(__SIZEOF_INT128__)
        REQUIRE(q == segment_reference(s, du, dv));
#endif
    }
}

#if defined(__SIZEOF_INT128__)
TEST_CASE("split factor: the portable product in 32-bit halves equals the compiler's 128-bit product",
          "[uniform][split][factor]") {
    // The Cortex-M4 build has no __int128 and multiplies in halves.
    namespace d = split_factor_detail;
    std::uint64_t state = 3;
    for (int k = 0; k < 1000000; ++k) {
        const std::uint64_t a = next(state), b = k % 4 == 0 ? ~std::uint64_t{0} - k : next(state);
        const d::Wide p = d::multiply_in_halves(a, b);
        const uint128 expect = static_cast<uint128>(a) * b;
        REQUIRE(p.lo == static_cast<std::uint64_t>(expect));
        REQUIRE(p.hi == static_cast<std::uint64_t>(expect >> 64));
    }
}
#endif
