// D3D11 edge point placement (docs/algorithm.md §5.2): the verified 1-D vectors, the reference's constant
// tables, exact mirror symmetry, continuity of the fractional modes, and bad factors.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <vector>

#include <ctess/d3d11/edge.hpp>
#include <ctess/d3d11/stitch.hpp>

namespace {

using namespace ctess::d3d11;

constexpr Partitioning all_modes[] = {Partitioning::integer, Partitioning::pow2, Partitioning::fractional_odd,
                                      Partitioning::fractional_even};

std::vector<std::uint32_t> points_of(Partitioning mode, float f) {
    std::vector<std::uint32_t> out(max_edge_points + 1, 0xdeadbeef);
    const unsigned n = edge_points(mode, f, out.data());
    REQUIRE(n <= max_edge_points);
    REQUIRE(out[n] == 0xdeadbeef); // nothing written past N
    REQUIRE(edge_points(mode, f, nullptr) == n);
    out.resize(n);
    return out;
}

// Constant evaluation: an algorithm.md §5.2 vector and a count.
constexpr std::array<std::uint32_t, 6> odd_3_5 = [] {
    std::array<std::uint32_t, 6> p{};
    edge_points(Partitioning::fractional_odd, 3.5f, p.data());
    return p;
}();
static_assert(odd_3_5 == std::array<std::uint32_t, 6>{0, 19661, 22937, 42599, 45875, 65536});
static_assert(edge_points(Partitioning::fractional_even, 10.3f, nullptr) == 13);
static_assert(edge_points(Partitioning::integer, -1.0f, nullptr) == 0);
static_assert(fixed_reciprocal(3) == 0x5555 && remove_msb(6) == 2);
static_assert(ruler_final_position(4) == 17);

// Independent of the implementation: segments from the 16.16 factor by exact rational rounding
// (docs/algorithm.md §5.5).
std::uint32_t expected_segments(Partitioning mode, float f) {
    const auto range = factor_range(mode);
    float c = std::isnan(f) ? range.lo : std::min(range.hi, std::max(range.lo, f));
    if (mode == Partitioning::integer || mode == Partitioning::pow2) c = std::ceil(c);
    const auto fx =
        static_cast<std::uint64_t>(std::nearbyint(static_cast<double>(c) * 65536.0)); // ties to even
    const std::uint64_t whole = (fx + 65535) / 65536;                                 // ceil
    switch (mode) {
    case Partitioning::fractional_even:
        return static_cast<std::uint32_t>(whole + (whole & 1)); // next even
    case Partitioning::fractional_odd:
        return static_cast<std::uint32_t>(whole + 1 - (whole & 1)); // next odd
    default:
        return static_cast<std::uint32_t>(whole);
    }
}

// Symmetric Hausdorff distance between two point sets on the line, in 1/65536.
std::uint32_t hausdorff(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b) {
    const auto one_way = [](const std::vector<std::uint32_t>& x, const std::vector<std::uint32_t>& y) {
        std::uint32_t worst = 0;
        for (const std::uint32_t p : x) {
            std::uint32_t best = 0xffffffffu;
            for (const std::uint32_t q : y) best = std::min(best, p > q ? p - q : q - p);
            worst = std::max(worst, best);
        }
        return worst;
    };
    return std::max(one_way(a, b), one_way(b, a));
}

// Factors 0.5 .. 66 in steps of 1/256, and every integer +- 2^-17 and +- 2^-16.
std::vector<float> dense_sweep() {
    std::vector<float> f;
    for (int k = 128; k <= 66 * 256; ++k) f.push_back(static_cast<float>(k) / 256.0f);
    for (int k = 1; k <= 66; ++k)
        for (const float d : {-1.0f / 65536.0f, -1.0f / 131072.0f, 1.0f / 131072.0f, 1.0f / 65536.0f})
            f.push_back(static_cast<float>(k) + d);
    return f;
}

} // namespace

TEST_CASE("d3d11 line: verified 1-D vectors (docs/algorithm.md §5.2)", "[d3d11][line]") {
    using V = std::vector<std::uint32_t>;
    const auto even = Partitioning::fractional_even;
    const auto odd = Partitioning::fractional_odd;
    REQUIRE(points_of(even, 2.0f) == V{0, 32768, 65536});
    REQUIRE(points_of(even, 2.5f) == V{0, 28672, 32768, 36864, 65536});
    REQUIRE(points_of(even, 3.0f) == V{0, 24576, 32768, 40960, 65536});
    REQUIRE(points_of(even, 5.0f) == V{0, 13654, 19115, 32768, 46421, 51882, 65536});
    REQUIRE(points_of(even, 6.0f) == V{0, 10923, 21846, 32768, 43690, 54613, 65536});
    REQUIRE(points_of(even, 10.3f) ==
            V{0, 6390, 12780, 19170, 19989, 26379, 32768, 39157, 45547, 46366, 52756, 59146, 65536});
    REQUIRE(points_of(odd, 1.0f) == V{0, 65536});
    REQUIRE(points_of(odd, 1.5f) == V{0, 5461, 60075, 65536});
    REQUIRE(points_of(odd, 3.0f) == V{0, 21845, 43691, 65536});
    REQUIRE(points_of(odd, 3.5f) == V{0, 19661, 22937, 42599, 45875, 65536});
    REQUIRE(points_of(odd, 4.0f) == V{0, 17476, 24030, 41506, 48060, 65536});
}

TEST_CASE("d3d11 line: coincident points just above an integer (docs/algorithm.md §5.2)", "[d3d11][line]") {
    // Even 4 + 2^-16 already has 6 segments and 0.25 twice; odd 3 + 2^-16 has 5 and 1/3 twice.
    const auto e = points_of(Partitioning::fractional_even, 4.0f + 1.0f / 65536.0f);
    REQUIRE(e.size() == 7);
    REQUIRE(std::count(e.begin(), e.end(), 16384u) == 2);
    REQUIRE(points_of(Partitioning::fractional_even, 4.0f).size() == 5);
    const auto o = points_of(Partitioning::fractional_odd, 3.0f + 1.0f / 65536.0f);
    REQUIRE(o.size() == 6);
    REQUIRE(std::count(o.begin(), o.end(), 21845u) == 2);
}

TEST_CASE("d3d11 line: reference constant tables", "[d3d11][line]") {
    // The reference's 16.16 reciprocal table, entries 1..64.
    constexpr std::uint32_t reciprocal[65] = {
        0,      0x10000, 0x8000, 0x5555, 0x4000, 0x3333, 0x2aab, 0x2492, 0x2000, 0x1c72, 0x199a,
        0x1746, 0x1555,  0x13b1, 0x1249, 0x1111, 0x1000, 0xf0f,  0xe39,  0xd79,  0xccd,  0xc31,
        0xba3,  0xb21,   0xaab,  0xa3d,  0x9d9,  0x97b,  0x925,  0x8d4,  0x889,  0x842,  0x800,
        0x7c2,  0x788,   0x750,  0x71c,  0x6eb,  0x6bd,  0x690,  0x666,  0x63e,  0x618,  0x5f4,
        0x5d1,  0x5b0,   0x591,  0x572,  0x555,  0x539,  0x51f,  0x505,  0x4ec,  0x4d5,  0x4be,
        0x4a8,  0x492,   0x47e,  0x46a,  0x457,  0x444,  0x432,  0x421,  0x410,  0x400};
    for (std::uint32_t n = 1; n <= 64; ++n) {
        INFO("n = " << n);
        REQUIRE(fixed_reciprocal(n) == reciprocal[n]);
    }
    // The ruler-function final positions (docs/algorithm.md §5.4, from the reference tessellator).
    constexpr std::uint32_t ruler[33] = {0, 32, 16, 8,  17, 4,  18, 9,  19, 2,  20, 10, 21, 5,  22, 11, 23,
                                         1, 24, 12, 25, 6,  26, 13, 27, 3,  28, 14, 29, 7,  30, 15, 31};
    for (std::uint32_t i = 0; i < 33; ++i) REQUIRE(ruler_final_position(i) == ruler[i]);
}

TEST_CASE("d3d11 line: point count is the rounded segment count + 1 (docs/algorithm.md §5.5)",
          "[d3d11][line]") {
    for (const Partitioning mode : all_modes) {
        for (const float f : dense_sweep()) {
            INFO("mode " << static_cast<int>(mode) << " f " << f);
            REQUIRE(edge_points(mode, f, nullptr) == expected_segments(mode, f) + 1);
        }
    }
}

TEST_CASE("d3d11 line: mirror exactness and monotonicity over a dense sweep", "[d3d11][line]") {
    for (const Partitioning mode : all_modes) {
        for (const float f : dense_sweep()) {
            INFO("mode " << static_cast<int>(mode) << " f " << f);
            const auto p = points_of(mode, f);
            REQUIRE(p.size() >= 2);
            REQUIRE(p.front() == 0);
            REQUIRE(p.back() == fixed_one);
            for (std::size_t i = 0; i < p.size(); ++i) REQUIRE(p[i] + p[p.size() - 1 - i] == fixed_one);
            // Monotone up to the reciprocal table's rounding: at most 32 (index) x 1/2 (unit) = 16 units
            // back.
            for (std::size_t i = 0; i + 1 < p.size(); ++i) REQUIRE(p[i + 1] + 16 >= p[i]);
        }
    }
}

TEST_CASE("d3d11 line: the reference is not strictly monotone (reciprocal rounding)", "[d3d11][line]") {
    // Even 30 + 2^-16: point 15 still sits on the 30-segment partition at 15 x 0x889 (the table's 1/30) =
    // 32775, past the exact midpoint 32768; its mirror is 32761. Bit-exactness means we keep this.
    const auto p = points_of(Partitioning::fractional_even, 30.0f + 1.0f / 65536.0f);
    REQUIRE(p.size() == 33);
    REQUIRE(p[15] == 15 * 0x889);
    REQUIRE(p[16] == 32768);
    REQUIRE(p[17] == 65536 - 15 * 0x889);
    // Even 6 + 2^-16: 3 x 0x2aab (1/6) = 32769, then 32768, 32767 (this makes sliver triangles invert
    // slightly).
    const auto q = points_of(Partitioning::fractional_even, 6.0f + 1.0f / 65536.0f);
    REQUIRE(q.size() == 9);
    REQUIRE(q[3] == 3 * 0x2aab);
    REQUIRE(q[4] == 32768);
    REQUIRE(q[5] == 65536 - 3 * 0x2aab);
}

TEST_CASE("d3d11 line: pow2 places points exactly like integer", "[d3d11][line]") {
    for (const float f : dense_sweep())
        REQUIRE(points_of(Partitioning::pow2, f) == points_of(Partitioning::integer, f));
}

// Continuity, formulated exactly: a point moves at most 1/4 of the factor change (it lerps between partitions
// at most 1/2 apart while the half factor moves at half speed), and a point born at a re-indexing lands on an
// existing one up to the reciprocal table's error (index <= 32 times 1/2 unit = 16 units; e.g. 7 at even 30).
// So the Hausdorff distance between the point sets at f and f + h is at most 65536 * h / 4 + 16 + 2 (in
// 1/65536; 2 units of rounding), for every step of a sweep. Integer partitioning breaks this by hundreds.
TEST_CASE("d3d11 line: fractional modes are continuous, integer mode jumps", "[d3d11][line]") {
    const auto bound = [](float h) { return static_cast<std::uint32_t>(65536.0f * h / 4.0f) + 18; };
    const float coarse = 1.0f / 256.0f;
    const float fine = 1.0f / 65536.0f;
    std::uint32_t integer_worst = 0;
    for (const Partitioning mode : all_modes) {
        const bool fractional = mode == Partitioning::fractional_odd || mode == Partitioning::fractional_even;
        std::uint32_t worst = 0;
        // Coarse sweep over the whole range, 1/256 steps.
        for (int k = 256; k < 66 * 256; ++k) {
            const float f = static_cast<float>(k) / 256.0f;
            const std::uint32_t d = hausdorff(points_of(mode, f), points_of(mode, f + coarse));
            if (fractional) {
                INFO("mode " << static_cast<int>(mode) << " f " << f << " distance " << d);
                REQUIRE(d <= bound(coarse));
            }
            worst = std::max(worst, d);
        }
        // Fine steps across every integer, where re-indexing happens.
        for (int k = 1; k <= 65; ++k) {
            for (int s = -4; s < 4; ++s) {
                const float f = static_cast<float>(k) + static_cast<float>(s) * fine;
                const std::uint32_t d = hausdorff(points_of(mode, f), points_of(mode, f + fine));
                if (fractional) {
                    INFO("mode " << static_cast<int>(mode) << " f " << f << " distance " << d);
                    REQUIRE(d <= bound(fine));
                }
                worst = std::max(worst, d);
            }
        }
        if (mode == Partitioning::integer) integer_worst = worst;
    }
    // Integer partitioning jumps at integers: 3 -> 3 + 2^-16 goes from thirds to quarters, and the midpoint
    // 1/2 is 1/6 away from both thirds.
    REQUIRE(hausdorff(points_of(Partitioning::integer, 3.0f),
                      points_of(Partitioning::integer, 3.0f + fine)) == 32768 - 21845);
    REQUIRE(integer_worst > bound(coarse));
}

TEST_CASE("d3d11 line: bad factors cull or clamp (docs/algorithm.md §5.1)", "[d3d11][line]") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const float denorm = std::numeric_limits<float>::denorm_min();
    for (const Partitioning mode : all_modes) {
        INFO("mode " << static_cast<int>(mode));
        // NaN, zero, negative zero, negatives and -inf cull.
        for (const float f : {nan, 0.0f, -0.0f, -1.0f, -1e30f, -inf, -denorm})
            REQUIRE(edge_points(mode, f, nullptr) == 0);
        const auto range = factor_range(mode);
        // A positive denormal or tiny factor does not cull: it clamps to the lower bound.
        REQUIRE(points_of(mode, denorm) == points_of(mode, range.lo));
        REQUIRE(points_of(mode, 1e-30f) == points_of(mode, range.lo));
        REQUIRE(points_of(mode, 0.25f) == points_of(mode, range.lo));
        // +inf and huge clamp to the upper bound.
        REQUIRE(points_of(mode, inf) == points_of(mode, range.hi));
        REQUIRE(points_of(mode, 1e30f) == points_of(mode, range.hi));
        REQUIRE(points_of(mode, 1000.0f) == points_of(mode, range.hi));
    }
    // The bounds themselves: integer 1 -> one segment, even 2 -> 2, odd 63 -> 63, 64 -> 64 segments.
    REQUIRE(points_of(Partitioning::integer, 1e-30f).size() == 2);
    REQUIRE(points_of(Partitioning::fractional_even, 1e-30f) == std::vector<std::uint32_t>{0, 32768, 65536});
    REQUIRE(points_of(Partitioning::fractional_odd, 1e30f).size() == 64);
    REQUIRE(points_of(Partitioning::fractional_even, 1e30f).size() == 65);
    REQUIRE(points_of(Partitioning::integer, 1e30f).size() == 65);
    // Uniform 64: i/64 exactly.
    const auto p64 = points_of(Partitioning::integer, 64.0f);
    for (std::uint32_t i = 0; i <= 64; ++i) REQUIRE(p64[i] == i * 1024);
}
