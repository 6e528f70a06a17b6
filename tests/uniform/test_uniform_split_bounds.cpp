// UniformSplit::emit() never writes past a span (docs/algorithm.md §3.5): spans sized exactly by counts() are
// filled slot for slot with nothing written around them, and the walk's own checks (emit_checked, without
// emit()'s comparison with counts()) refuse spans one vertex or one triangle short, or shorter, without a
// write past them. Also built with -O2 -ffast-math (test_uniform_split_fast_math): counts() and emit() must
// agree whatever the caller's flags, and a NaN factor must still give 1 (uniform) and T0 (CP).
#include <ctess/runtime/cp/line_state.hpp>
#include <ctess/runtime/uniform/split.hpp>

#include <array>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

using ctess::Layout;
using ctess::PatchOptions;
using ctess::Winding;
using ctess::rt::UniformSplit;
using Point = UniformSplit::point_type;

namespace {

// n slots inside guard zones of `guard` slots on each side, every slot preset to a sentinel no output has
// (coordinates are at most 65534^2 < 2^32 - 1, vertex numbers below the count).
template <class T>
struct Guarded {
    std::vector<T> storage;
    std::size_t guard, size;
    T sentinel;
    Guarded(std::size_t n, T s) : storage(n + 2 * (n + 64), s), guard(n + 64), size(n), sentinel(s) {}
    std::span<T> span() { return {storage.data() + guard, size}; }
    bool guards_intact() const {
        for (std::size_t i = 0; i < storage.size(); ++i)
            if ((i < guard || i >= guard + size) && !(storage[i] == sentinel)) return false;
        return true;
    }
    bool all_written() const {
        for (std::size_t i = guard; i < guard + size; ++i)
            if (storage[i] == sentinel) return false;
        return true;
    }
};

const Point no_point{0xFFFFFFFFu, 0xFFFFFFFFu};
constexpr std::uint32_t no_index = 0xFFFFFFFFu;

// Triples at depth 0, 1 and 2 for both tables, with halves at the rounding boundary and the triples an
// icosahedron mesh overflowed with under -ffast-math.
std::vector<std::array<float, 3>> triples(std::uint32_t n) {
    std::vector<std::array<float, 3>> cases = {{5, 7, 9},
                                               {40, 30, 25},
                                               {176, 176, 176},
                                               {256, 256, 256},
                                               {17, 1, 16},
                                               {255.5f, 17, 200},
                                               {217.37f, 216.76f, 146.46f},
                                               {26.75f, 40.13f, 217.18f},
                                               {71, 104, 217},
                                               {250.68f, 184.88f, 217.37f}};
    constexpr float nan_f = std::numeric_limits<float>::quiet_NaN();
    constexpr float inf_f = std::numeric_limits<float>::infinity();
    for (const std::array<float, 3>& f :
         {std::array<float, 3>{nan_f, 300, 1e30f}, {-inf_f, inf_f, 40}, {nan_f, 5, 5}})
        cases.push_back(f);
    std::uint32_t state = 7 + n;
    for (int k = 0; k < 40; ++k) {
        std::array<float, 3> f{};
        for (float& x : f)
            x = static_cast<float>(1 + (state = state * 1664525u + 1013904223u) % (100 * n * n)) / 100.0f;
        cases.push_back(f);
    }
    return cases;
}

} // namespace

TEST_CASE("uniform split emit: exact spans are filled slot for slot, nothing written around them",
          "[uniform][split][bounds]") {
    for (const auto* set : {&ctess::rt::uniform_tables_11, &ctess::rt::uniform_tables_16})
        for (const double tolerance :
             {ctess::rt::uniform_split_interior_tolerance, ctess::rt::uniform_split_strict_tolerance})
            for (const Layout layout : {Layout::provoking, Layout::shared})
                for (const auto& f : triples(set->max_factor)) {
                    INFO("N " << set->max_factor << " tolerance " << tolerance << " shared "
                              << (layout == Layout::shared) << " factors " << f[0] << "," << f[1] << ","
                              << f[2]);
                    const UniformSplit split(*set, f[0], f[1], f[2], PatchOptions{layout, Winding::ccw},
                                             tolerance);
                    const ctess::Counts n = split.counts();
                    Guarded<Point> v(n.vertices, no_point);
                    Guarded<std::uint32_t> i(n.index_count(), no_index);
                    REQUIRE(split.emit(v.span(), i.span()));
                    REQUIRE(v.guards_intact());
                    REQUIRE(i.guards_intact());
                    REQUIRE(v.all_written());
                    REQUIRE(i.all_written());
                    for (const std::uint32_t x : i.span()) REQUIRE(x < n.vertices);
                }
}

TEST_CASE("uniform split emit: the walk checks every write against the spans, not against counts()",
          "[uniform][split][bounds]") {
    for (const auto* set : {&ctess::rt::uniform_tables_11, &ctess::rt::uniform_tables_16})
        for (const Layout layout : {Layout::provoking, Layout::shared})
            for (const auto& f : triples(set->max_factor)) {
                const UniformSplit split(*set, f[0], f[1], f[2], PatchOptions{layout, Winding::ccw});
                const ctess::Counts n = split.counts();
                // (vertices, indices) short of counts(): one vertex, one triangle, half, everything.
                const std::array<std::pair<std::uint32_t, std::uint32_t>, 6> shortfalls{
                    {{1, 0},
                     {0, 3},
                     {1, 3},
                     {n.vertices / 2, 0},
                     {0, n.index_count() / 2 + 1},
                     {n.vertices, n.index_count()}}};
                for (const auto& [dv, di] : shortfalls) {
                    INFO("N " << set->max_factor << " shared " << (layout == Layout::shared) << " factors "
                              << f[0] << "," << f[1] << "," << f[2] << " short by " << dv << ", " << di);
                    Guarded<Point> v(n.vertices - dv, no_point);
                    Guarded<std::uint32_t> i(n.index_count() - di, no_index);
                    REQUIRE_FALSE(ctess::rt::uniform_split_detail::emit_checked(split, v.span(), i.span()));
                    REQUIRE(v.guards_intact());
                    REQUIRE(i.guards_intact());
                }
                // Exact spans: the walk and counts() agree.
                Guarded<Point> v(n.vertices, no_point);
                Guarded<std::uint32_t> i(n.index_count(), no_index);
                REQUIRE(ctess::rt::uniform_split_detail::emit_checked(split, v.span(), i.span()));
                REQUIRE(v.all_written());
                REQUIRE(i.all_written());
            }
}

TEST_CASE("float factors: NaN gives 1 (CP: T0) and infinities clamp, whatever the flags",
          "[uniform][split][bounds]") {
    constexpr float nan_f = std::numeric_limits<float>::quiet_NaN();
    constexpr float inf_f = std::numeric_limits<float>::infinity();
    volatile float nan_v = nan_f, inf_v = inf_f; // read at run time, not folded
    CHECK(ctess::rt::uniform_factor(nan_v, 16) == 1);
    CHECK(ctess::rt::uniform_factor(-nan_v, 16) == 1);
    CHECK(ctess::rt::uniform_factor(inf_v, 16) == 16);
    CHECK(ctess::rt::uniform_factor(-inf_v, 16) == 1);
    const UniformSplit split(ctess::rt::uniform_tables_16, nan_v, inf_v, -inf_v);
    CHECK(split.factors() == std::array<double, 3>{1, 32768, 1}); // uniform_split_max_factor
    CHECK(ctess::rt::line_state(nan_v, 64) == ctess::cp::LineState{0, 0});
    CHECK(ctess::rt::line_state(-nan_v, 64) == ctess::cp::LineState{0, 0});
    CHECK(ctess::rt::line_state(inf_v, 64) == ctess::rt::line_state(64.0f, 64));
}
