// Bad input to the runtime has the documented results (runtime/include/ctess/runtime/cp/patch.hpp): factors
// and line states are clamped like the generator's, out-of-range indices give {0, 0} / {0, 0, 0}, and emit()
// refuses spans that are too small without writing to them.
#include <ctess/runtime/cp/patch.hpp>

#include <cstdint>
#include <limits>
#include <vector>

#include <catch2/catch.hpp>

using ctess::DomainPoint;
using ctess::rt::CpPatch;
using ctess::rt::CpTableSet;

namespace {

constexpr float nan_f = std::numeric_limits<float>::quiet_NaN();
constexpr float inf_f = std::numeric_limits<float>::infinity();
constexpr float denormal_f = std::numeric_limits<float>::denorm_min();

bool same_patch(const CpPatch& a, const CpPatch& b) {
    if (a.vertex_count() != b.vertex_count() || a.triangle_count() != b.triangle_count()) return false;
    for (std::uint32_t v = 0; v < a.vertex_count(); ++v)
        if (!(a.vertex(v) == b.vertex(v))) return false;
    for (std::uint32_t t = 0; t < a.triangle_count(); ++t)
        if (a.triangle(t) != b.triangle(t)) return false;
    return true;
}

} // namespace

TEST_CASE("runtime bad input: factors at or below 1, NaN and -inf give the base triangle",
          "[runtime][bad_input]") {
    for (const CpTableSet* t : {&ctess::rt::cp_tables_64, &ctess::rt::cp_tables_256}) {
        for (float f : {nan_f, -inf_f, -5.0f, 0.0f, -0.0f, denormal_f, 0.5f, 1.0f}) {
            INFO("max " << t->max_factor << " f = " << f);
            const CpPatch p(*t, f, f, f);
            REQUIRE(p.vertex_count() == 3);
            REQUIRE(p.triangle_count() == 1);
            CHECK(p.vertex(0) == DomainPoint{0, 0});
            CHECK(p.vertex(1) == DomainPoint{ctess::cp::fixed_one, 0});
            CHECK(p.vertex(2) == DomainPoint{0, ctess::cp::fixed_one});
            CHECK(p.triangle(0) == ctess::rt::CpTriangle{0, 1, 2});
            CHECK(same_patch(p, CpPatch(*t, 1.0f, f, 1.0f)));
        }
    }
}

TEST_CASE("runtime bad input: +inf and huge factors clamp to the maximum (the triforce M)",
          "[runtime][bad_input]") {
    for (const CpTableSet* t : {&ctess::rt::cp_tables_64, &ctess::rt::cp_tables_256}) {
        const std::uint32_t m = t->max_factor;
        for (float f : {inf_f, 1e30f, static_cast<float>(m) + 1.0f, static_cast<float>(m)}) {
            INFO("max " << m << " f = " << f);
            const CpPatch p(*t, f, f, f);
            // Triforce M: M^2 triangles; (M+1)(M+2)/2 unique vertices plus one copy per doubled interior
            // point.
            CHECK(p.triangle_count() == m * m);
            CHECK(p.vertex_count() == m * m + 2);
        }
        const CpPatch mixed(*t, inf_f, nan_f, 1e9f);
        CHECK(same_patch(mixed, CpPatch(*t, static_cast<float>(m), 1.0f, static_cast<float>(m))));
    }
}

TEST_CASE("runtime bad input: line states past the last token or lerp are clamped", "[runtime][bad_input]") {
    const CpTableSet& t = ctess::rt::cp_tables_64;
    const unsigned last = ctess::cp::token_count(64) - 1;
    const CpPatch past(t, {99, 7}, {last + 1, 0}, {1000000, 123456});
    const CpPatch top(t, {last, 65536}, {last, 65536}, {last, 65536});
    CHECK(same_patch(past, top));
    const CpPatch lerp(t, {5, 70000}, {6, 4000000000u}, {0, 999});
    const CpPatch lerp_clamped(t, {5, 65536}, {6, 65536}, {0, 0});
    CHECK(same_patch(lerp, lerp_clamped));
}

TEST_CASE("runtime bad input: out-of-range vertex and triangle indices give zeros", "[runtime][bad_input]") {
    for (const CpTableSet* t : {&ctess::rt::cp_tables_64, &ctess::rt::cp_tables_256}) {
        for (const CpPatch& p : {CpPatch(*t, 1.0f, 1.0f, 1.0f), CpPatch(*t, 1.5f, 20.0f, 1.2f),
                                 CpPatch(*t, 40.0f, 1.0f, 2.5f), CpPatch(*t, 33.0f, 17.0f, 60.0f)}) {
            for (std::uint32_t i : {p.vertex_count(), p.vertex_count() + 1, 0xFFFFFFFFu})
                CHECK(p.vertex(i) == DomainPoint{0, 0});
            for (std::uint32_t i : {p.triangle_count(), p.triangle_count() + 7, 0xFFFFFFFFu})
                CHECK(p.triangle(i) == ctess::rt::CpTriangle{0, 0, 0});
            // In range, the last elements are real: a non-degenerate index triple.
            const auto last = p.triangle(p.triangle_count() - 1);
            CHECK((last[0] != last[1] && last[1] != last[2] && last[0] != last[2]));
        }
    }
}

namespace {

// emit() with a span one element short returns false and writes nothing; with exact spans it writes.
template <class Patch>
void check_refuses_small_spans(const Patch& p) {
    const std::uint32_t nv = p.vertex_count(), nt = p.triangle_count();
    const DomainPoint sentinel{0xDEADu, 0xBEEFu};
    std::vector<DomainPoint> v(nv, sentinel);
    std::vector<std::uint32_t> i(3 * nt, 0xABCDu);
    CHECK_FALSE(p.emit(std::span(v.data(), nv - 1), std::span(i)));
    CHECK_FALSE(p.emit(std::span(v), std::span(i.data(), 3 * nt - 1)));
    CHECK_FALSE(p.emit({}, {}));
    for (const DomainPoint& x : v) REQUIRE(x == sentinel);
    for (std::uint32_t x : i) REQUIRE(x == 0xABCDu);
    CHECK(p.emit(v, i));
    CHECK(i[0] != 0xABCDu);
}

} // namespace

TEST_CASE("runtime bad input: emit refuses spans that are too small and leaves them untouched",
          "[runtime][bad_input]") {
    check_refuses_small_spans(CpPatch(ctess::rt::cp_tables_64, 12.0f, 7.0f, 9.0f));
}

TEST_CASE("runtime bad input: CpPatchSetup::emit refuses small spans in every layout and winding",
          "[runtime][bad_input]") {
    using ctess::Layout;
    using ctess::Winding;
    for (const ctess::PatchOptions o : {ctess::PatchOptions{Layout::provoking, Winding::cw},
                                        ctess::PatchOptions{Layout::shared, Winding::ccw},
                                        ctess::PatchOptions{Layout::shared, Winding::cw}}) {
        // A plain patch (the fast path) and one with a T0 edge (the collapse path).
        for (const float f1 : {7.0f, 1.0f})
            check_refuses_small_spans(ctess::rt::CpPatchSetup(ctess::rt::cp_tables_64, 12.0f, f1, 9.0f, o));
    }
}

TEST_CASE("runtime bad input: cp_counts clamps factors as CpPatch does", "[runtime][bad_input]") {
    for (const CpTableSet* t : {&ctess::rt::cp_tables_64, &ctess::rt::cp_tables_256}) {
        const float m = static_cast<float>(t->max_factor);
        for (const ctess::Layout layout : {ctess::Layout::provoking, ctess::Layout::shared}) {
            const ctess::PatchOptions o{layout, ctess::Winding::ccw};
            CHECK(ctess::rt::cp_counts(*t, nan_f, -inf_f, -5.0f, o) ==
                  ctess::rt::cp_counts(*t, 1.0f, 1.0f, 1.0f, o));
            CHECK(ctess::rt::cp_counts(*t, inf_f, 1e30f, m + 1.0f, o) == CpPatch(*t, m, m, m, o).counts());
        }
        // The shared layout of the triforce M: (M+1)(M+2)/2 distinct positions, M^2 triangles.
        const std::uint32_t mi = t->max_factor;
        CHECK(ctess::rt::cp_counts(*t, inf_f, inf_f, inf_f, {ctess::Layout::shared, ctess::Winding::ccw}) ==
              ctess::Counts{(mi + 1) * (mi + 2) / 2, mi * mi});
    }
}
