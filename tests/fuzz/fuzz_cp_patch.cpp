// libFuzzer target: ctess::rt::CpPatch through its public API, against the procedural cp::tessellate.
// Input: table set, layout and winding, three edges given as float bit patterns or as raw line states (any
// token, any lerp), then index queries and span sizes. The CpPatchSetup emit path and cp_counts are checked
// too. Properties: counts, every vertex and triangle, and emit into exact spans equal the procedural pattern;
// out-of-range queries give {0, 0} and {0, 0, 0}; emit into a short or empty span returns false and writes
// nothing.
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <ctess/cp/pattern.hpp>
#include <ctess/runtime/cp/patch.hpp>

#include "fuzz_input.hpp"

using namespace ctess;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Input in(data, size);
    const std::uint8_t mode = in.byte();
    const rt::CpTableSet& tables = (mode & 1) ? rt::cp_tables_256 : rt::cp_tables_64;
    const unsigned max = tables.max_factor;
    cp::LineState s[3];
    float f[3] = {};
    const bool raw_states = mode & 2; // any token and lerp: the runtime clamps them as cp::clamp_line_state
    for (unsigned k = 0; k < 3; ++k) {
        if (raw_states) {
            s[k] = cp::LineState{in.u32(), in.u32()};
        } else {
            f[k] = in.float_bits();
            s[k] = cp::line_state(f[k], max); // what the float constructor must do
        }
    }
    const PatchOptions patch_options{(mode & 4) ? Layout::shared : Layout::provoking,
                                     (mode & 8) ? Winding::cw : Winding::ccw};
    const rt::CpPatch patch = raw_states ? rt::CpPatch(tables, s[0], s[1], s[2], patch_options)
                                         : rt::CpPatch(tables, f[0], f[1], f[2], patch_options);

    cp::PatternOptions options{{}, max};
    options.layout = patch_options.layout;
    options.winding = patch_options.winding;
    const Counts ref = cp::tessellate({}, {}, s[0], s[1], s[2], options);
    CTESS_FUZZ_CHECK(patch.vertex_count() == ref.vertices && patch.triangle_count() == ref.triangles);
    CTESS_FUZZ_CHECK(rt::cp_counts(tables, s[0], s[1], s[2], patch_options) == ref);
    std::vector<DomainPoint> ref_v(ref.vertices);
    std::vector<std::uint32_t> ref_i(3 * std::size_t{ref.triangles});
    cp::tessellate(ref_v, ref_i, s[0], s[1], s[2], options);

    // Random access, in range and out of range.
    for (unsigned q = 0; q < 8 && !in.empty(); ++q) {
        const std::uint32_t i = (q & 1) ? in.u32() : in.u32() % (ref.vertices + 2);
        const DomainPoint p = patch.vertex(i);
        CTESS_FUZZ_CHECK(i < ref.vertices ? p == ref_v[i] : p == DomainPoint{});
        const std::uint32_t t = (q & 1) ? in.u32() : in.u32() % (ref.triangles + 2);
        const rt::CpTriangle tri = patch.triangle(t);
        for (unsigned k = 0; k < 3; ++k)
            CTESS_FUZZ_CHECK(tri[k] == (t < ref.triangles ? ref_i[3 * std::size_t{t} + k] : 0u));
    }

    // emit: exact spans equal the reference; a short or empty span writes nothing.
    std::vector<DomainPoint> v(ref.vertices + 1, DomainPoint{7, 7});
    std::vector<std::uint32_t> idx(ref_i.size() + 1, 7u);
    const std::uint8_t spans = in.byte() % 4;
    const std::size_t nv = spans == 1 ? (ref.vertices ? ref.vertices - 1 : 0) : spans == 3 ? 0 : ref.vertices;
    const std::size_t ni = spans == 2   ? (ref_i.empty() ? 0 : ref_i.size() - 1 - in.byte() % ref_i.size())
                           : spans == 3 ? 0
                                        : ref_i.size();
    const bool fits = nv >= ref.vertices && ni >= ref_i.size();
    const bool ok = patch.emit(std::span(v.data(), nv), std::span(idx.data(), ni));
    CTESS_FUZZ_CHECK(ok == fits);
    for (std::size_t k = 0; k < ref.vertices; ++k)
        CTESS_FUZZ_CHECK(v[k] == (ok ? ref_v[k] : DomainPoint{7, 7}));
    for (std::size_t k = 0; k < ref_i.size(); ++k) CTESS_FUZZ_CHECK(idx[k] == (ok ? ref_i[k] : 7u));
    CTESS_FUZZ_CHECK(v.back() == (DomainPoint{7, 7}) && idx.back() == 7u); // never past the span

    // The emit-only setup writes the same.
    if (fits) {
        const rt::CpPatchSetup setup(tables, s[0], s[1], s[2], patch_options);
        std::vector<DomainPoint> v2(ref.vertices);
        std::vector<std::uint32_t> idx2(ref_i.size());
        CTESS_FUZZ_CHECK(setup.emit(v2, idx2));
        CTESS_FUZZ_CHECK(v2 == ref_v && idx2 == ref_i);
    }
    return 0;
}
