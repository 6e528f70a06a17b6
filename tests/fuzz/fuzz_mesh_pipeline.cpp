// libFuzzer target: the CPU mesh pipeline (runtime/include/ctess/runtime/pipeline/mesh_pipeline.hpp) on small
// arbitrary meshes: vertex floats as any bit pattern (NaN, inf, zero-area triangles), indices in and out of
// range, any dice and surface options, every pattern (CP, uniform clamped and split, the D3D11 partitionings,
// and one value outside the enum, which must be bad_option), optionally a base triangle repeated tens of
// thousands of times (totals past the limits), then patch records tampered with before emit. Properties:
// setup_patches is ok or a limit; ok totals equal the records' sums; emit_mesh on untouched records is ok,
// every index names an emitted vertex of its own patch and every barycentric lies in the base triangle; on
// tampered records it is ok or bad_patch_record, and on any failure nothing is written. Then quads, arbitrary
// position ids and PN-AEN adjacency indices (in and out of range) through the welded output (setup_welded,
// emit_welded_mesh): ok or a limit, every index names a written vertex, and the counts are what emit wrote;
// two ranges of patches cut at a fuzzed patch write the same bytes.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <ctess/runtime/pipeline/mesh_pipeline.hpp>
#include <ctess/runtime/uniform/table_set.hpp>

#include "fuzz_input.hpp"

using namespace ctess;
using rt::PipelineStatus;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Input in(data, size);
    const std::uint8_t mode = in.byte();
    const rt::CpTableSet& tables = (mode & 1) ? rt::cp_tables_256 : rt::cp_tables_64;
    rt::PipelineOptions options;
    options.dice.eye = {in.float_bits(), in.float_bits(), in.float_bits()};
    if (mode & 2) options.dice.projection_scale = in.float_bits();
    if (mode & 4) options.dice.dice_rate = in.float_bits();
    const unsigned surface_value = in.byte() % 5u; // 4 is past the enum
    options.surface.surface = static_cast<rt::Surface>(surface_value);
    options.surface.alpha = (mode & 8) ? in.float_bits() : 0.75f;
    const auto pattern_value = in.byte() % 8u; // 7 is past the enum
    options.pattern = static_cast<rt::Pattern>(pattern_value);
    const unsigned quad_rule_value = (mode & 8) ? in.byte() % 3u : 0u; // 2 is past the enum
    options.quad_rule = static_cast<rt::QuadRule>(quad_rule_value);
    const bool bad_option = pattern_value > 6 || surface_value > 3 || quad_rule_value > 1;
    // A split patch of factor 32,768 takes a walk of millions of leaves to count: no repeated patches.
    const bool split = options.pattern == rt::Pattern::uniform_split;
    const rt::UniformTableSet& uniform = rt::uniform_tables;

    const unsigned vertex_count = in.byte() % 9;
    std::vector<float> vertices(std::size_t{vertex_count} * rt::mesh_vertex_floats);
    for (float& x : vertices) x = (mode & 16) ? in.float_bits() : static_cast<float>(in.byte()) - 128.0f;
    std::vector<std::uint32_t> indices(3 * static_cast<std::size_t>(in.byte() % 9));
    for (std::uint32_t& i : indices) i = (mode & 32) ? in.u32() : in.byte() % (vertex_count + 1);
    if ((mode & 0xC0) == 0xC0 && !split &&
        indices.size() >= 3) { // repeat the first base triangle: up to 65,536 patches
        const std::size_t copies = 1 + (in.byte() | std::size_t{in.byte()} << 8);
        indices.resize(3 * copies);
        for (std::size_t t = 1; t < copies; ++t) std::copy_n(indices.begin(), 3, indices.begin() + 3 * t);
    }
    const rt::MeshView mesh{vertices.data(), vertex_count, indices.data(),
                            static_cast<std::uint32_t>(indices.size() / 3)};

    std::vector<rt::PatchRecord> records(mesh.triangle_count);
    rt::PipelineTotals totals{1234, 5678};
    const PipelineStatus setup = rt::setup_patches(tables, uniform, mesh, options, records, totals);
    if (bad_option) {
        CTESS_FUZZ_CHECK(setup == PipelineStatus::bad_option);
        return 0;
    }
    if (setup != PipelineStatus::ok) {
        CTESS_FUZZ_CHECK(setup == PipelineStatus::too_many_vertices ||
                         setup == PipelineStatus::too_many_triangles);
        CTESS_FUZZ_CHECK(totals.vertices == 1234 && totals.triangles == 5678);
        return 0;
    }
    std::uint64_t sum_v = 0, sum_t = 0;
    for (const rt::PatchRecord& r : records) sum_v += r.vertex_count, sum_t += r.triangle_count;
    CTESS_FUZZ_CHECK(sum_v == totals.vertices && sum_t == totals.triangles);
    if (sum_v > (1u << 18)) return 0; // a valid mesh too large to emit quickly under the sanitizers

    // Tamper: overwrite a few record bytes.
    const bool tampered = (mode & 64) && !records.empty();
    std::vector<rt::PatchRecord> used = records;
    if (tampered) {
        auto* bytes = reinterpret_cast<std::uint8_t*>(used.data());
        const std::size_t n = used.size() * sizeof(rt::PatchRecord);
        for (unsigned k = 0; k < 4; ++k) {
            const std::uint32_t at = in.u32();
            bytes[at % n] = in.byte();
        }
    }
    std::vector<rt::TessVertex> out_v(totals.vertices + 4);
    std::vector<std::uint32_t> out_i(3 * std::size_t{totals.triangles} + 4, 0xA5A5A5A5u);
    rt::TessVertex marker;
    marker.u = 0xA5A5A5A5u;
    std::fill(out_v.begin(), out_v.end(), marker);
    const PipelineStatus emit = rt::emit_mesh(tables, uniform, mesh, options, used, out_v, out_i);
    if (!tampered) CTESS_FUZZ_CHECK(emit == PipelineStatus::ok);
    if (emit != PipelineStatus::ok) {
        CTESS_FUZZ_CHECK(emit == PipelineStatus::bad_patch_record || emit == PipelineStatus::span_too_small ||
                         emit == PipelineStatus::too_many_vertices ||
                         emit == PipelineStatus::too_many_triangles);
        for (const rt::TessVertex& v : out_v) CTESS_FUZZ_CHECK(v.u == 0xA5A5A5A5u);
        for (std::uint32_t i : out_i) CTESS_FUZZ_CHECK(i == 0xA5A5A5A5u);
        return 0;
    }
    for (std::size_t t = 0; t < used.size(); ++t) {
        const rt::PatchRecord& r = used[t];
        for (std::uint32_t i = 0; i < r.vertex_count; ++i) {
            const rt::TessVertex& v = out_v[r.first_vertex + i];
            CTESS_FUZZ_CHECK(std::uint64_t{v.u} + v.v <= cp::fixed_one);
        }
        for (std::uint32_t k = 0; k < 3 * r.triangle_count; ++k) {
            const std::uint32_t i = out_i[3 * std::size_t{r.first_triangle} + k];
            CTESS_FUZZ_CHECK(i >= r.first_vertex && i < r.first_vertex + r.vertex_count);
        }
    }

    // The welded output of a mixed mesh: the triangles above (at most 8), up to 6 quads, position ids and
    // adjacency from the input bytes.
    if (mesh.triangle_count > 8) return 0;
    std::vector<std::uint32_t> quads(4 * static_cast<std::size_t>(in.byte() % 7));
    for (std::uint32_t& i : quads) i = (mode & 32) ? in.u32() : in.byte() % (vertex_count + 1);
    std::vector<std::uint32_t> position_ids(vertex_count);
    for (std::uint32_t& i : position_ids) i = in.byte() % (vertex_count + 1);
    std::vector<std::uint32_t> adjacency(12 * (mesh.triangle_count + 2 * (quads.size() / 4)));
    for (std::uint32_t& i : adjacency) i = (mode & 128) ? in.u32() : in.byte() % (vertex_count + 1);
    rt::MeshView mixed = mesh;
    mixed.quad_indices = quads.data();
    mixed.quad_count = static_cast<std::uint32_t>(quads.size() / 4);
    mixed.position_ids = position_ids.data();
    mixed.adjacency = adjacency.data();
    options.weld.keep_degenerate = (mode & 4) != 0;
    // The weld keeps one patch's output in scratch: skip meshes whose unwelded output is large (the quads are
    // new here), as above.
    {
        std::vector<rt::PatchRecord> mixed_records(mixed.patch_count());
        rt::PipelineTotals mixed_totals;
        if (rt::setup_patches(tables, uniform, mixed, options, mixed_records, mixed_totals) !=
                PipelineStatus::ok ||
            mixed_totals.vertices > (1u << 18))
            return 0;
    }
    std::vector<rt::WeldedEdge> edges(rt::weld_edge_capacity(mixed));
    std::vector<rt::WeldedPatch> patches(mixed.patch_count());
    rt::WeldedTotals welded;
    const PipelineStatus ws = rt::setup_welded(tables, uniform, mixed, options, edges, patches, welded);
    if (ws != PipelineStatus::ok) {
        CTESS_FUZZ_CHECK(ws == PipelineStatus::too_many_vertices || ws == PipelineStatus::too_many_triangles);
        return 0;
    }
    if (welded.vertices > (1u << 18)) return 0;
    edges.resize(welded.edges);
    std::vector<rt::TessVertex> wv(welded.vertices);
    std::vector<std::uint32_t> wi(3 * std::size_t{welded.triangles}, 0xA5A5A5A5u);
    CTESS_FUZZ_CHECK(rt::emit_welded_mesh(tables, uniform, mixed, options, edges, patches, wv, wi) ==
                     PipelineStatus::ok);
    for (const std::uint32_t i : wi) CTESS_FUZZ_CHECK(i < welded.vertices);
    // The same output in two ranges of patches cut at a fuzzed patch, the later range first (§7.4, "Ranges").
    const auto patch_count = static_cast<std::uint32_t>(mixed.patch_count());
    if (patch_count == 0) return 0; // no ranges: bad_range (tests/pipeline)
    const std::uint32_t cut = in.byte() % (patch_count + 1);
    std::vector<rt::TessVertex> fresh(welded.vertices); // value-initialised, as wv was
    std::vector<std::uint32_t> ri(wi.size(), 0xA5A5A5A5u);
    for (const rt::WeldedRange r : {rt::WeldedRange{cut, patch_count}, rt::WeldedRange{0, cut}})
        CTESS_FUZZ_CHECK(rt::emit_welded_mesh(tables, uniform, mixed, options, edges, patches, r, fresh,
                                              ri) == PipelineStatus::ok);
    CTESS_FUZZ_CHECK(ri == wi);
    CTESS_FUZZ_CHECK(wv.empty() ||
                     std::memcmp(fresh.data(), wv.data(), wv.size() * sizeof(rt::TessVertex)) == 0);
    return 0;
}
