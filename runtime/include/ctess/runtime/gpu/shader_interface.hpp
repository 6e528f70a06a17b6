// What a host of the generated mesh pipeline shaders (docs/shaders.md) binds and writes: the eight storage
// bindings, the params words, the workgroup sizes and the totals after the patch records. The shaders get
// these numbers from gen/shaders/shader_layout.hpp, which takes them from here, so the C++ hosts
// (<ctess/runtime/gpu/vulkan.hpp>), the JS host (ctess_webgpu.mjs, through layout.json) and the shaders share
// one source. No GPU API here: a host for any API includes this header.
//
//   const auto params = ctess::rt::gpu::pipeline_params(mesh, options); // binding 0
//   // binding 4: patch_buffer_words(mesh.patch_count()) words; the prefix sum writes the totals after the
//   // records: totals_words(...) below reads them back.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include <ctess/runtime/displace/displace.hpp>
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>

namespace ctess::rt::gpu {

// Set 0 (Vulkan) / group 0 (WebGPU), every binding a storage buffer (docs/shaders.md, "Passes and bindings").
namespace binding {
inline constexpr std::uint32_t params = 0;        // param_word::words u32, read
inline constexpr std::uint32_t tables = 1;        // the table blob, read
inline constexpr std::uint32_t mesh_vertices = 2; // mesh_vertex_floats floats per vertex, read
inline constexpr std::uint32_t mesh_indices = 3;  // 3 per base triangle, then 4 per quad, read
inline constexpr std::uint32_t patches = 4;       // PatchRecord per patch, then the totals, read/write
inline constexpr std::uint32_t out_vertices = 5;  // TessVertex per output vertex, written
inline constexpr std::uint32_t out_indices = 6;   // 3 per output triangle, written
inline constexpr std::uint32_t weld =
    7; // the welded output's edges, records and scratch (weld_word), read/write
inline constexpr std::uint32_t count = 8;
} // namespace binding

// The params buffer (binding 0), one u32 word each; floats as their bits.
namespace param_word {
inline constexpr std::uint32_t patch_count = 0;  // base triangles + quads (MeshView::patch_count)
inline constexpr std::uint32_t surface = 1;      // rt::Surface
inline constexpr std::uint32_t alpha = 2;        // float
inline constexpr std::uint32_t factor_scale = 3; // float, DiceOptions::factor_scale()
inline constexpr std::uint32_t eye = 4;          // 3 floats
inline constexpr std::uint32_t mesh_vertex_count = 7;
inline constexpr std::uint32_t first_patch = 8; // the emit passes' patch range [first, end)
inline constexpr std::uint32_t end_patch = 9;
inline constexpr std::uint32_t pattern = 10;    // rt::Pattern
inline constexpr std::uint32_t quad_count = 11; // the last quad_count patches are quads
inline constexpr std::uint32_t quad_rule = 12;  // rt::QuadRule
// Displacement (docs/shaders.md, "Displacement"; docs/algorithm.md §8): the displacement_flag bits, then
// rt::Displacement's numbers (floats as bits) and the height map's size and rt::AddressMode. The directions
// (3 floats per mesh vertex), then in vector mode the tangents (4 per mesh vertex), follow the mesh vertices
// in binding 2; the texels (f32 bits, row-major; 3 floats each in vector mode) the indices and the adjacency
// in binding 3.
inline constexpr std::uint32_t displacement_flags = 13;
inline constexpr std::uint32_t displacement_scale = 14;
inline constexpr std::uint32_t displacement_factor = 15;
inline constexpr std::uint32_t displacement_offset = 16;
inline constexpr std::uint32_t displacement_normal_step = 17;
inline constexpr std::uint32_t displacement_factor_bound = 18;
inline constexpr std::uint32_t height_map_width = 19; // 0 with height 0: an empty map (height 0)
inline constexpr std::uint32_t height_map_height = 20;
inline constexpr std::uint32_t height_map_address = 21; // rt::AddressMode; other values read as clamp
// Pattern::uniform_split (docs/shaders.md, "Splitting"): the nodes each of the split area's two regions holds
// (split_capacity below); 0 for the other patterns.
inline constexpr std::uint32_t split_capacity = 22;
// The welded output (docs/shaders.md, "Welded output"): the weld_flag bits; 0 for the unwelded output.
inline constexpr std::uint32_t weld = 23;
inline constexpr std::uint32_t words = 24;
} // namespace param_word
static_assert(param_word::eye + 3 == param_word::mesh_vertex_count &&
              param_word::weld + 1 == param_word::words);

// The bits of param_word::weld.
namespace weld_flag {
inline constexpr std::uint32_t on = 1;              // the vertex passes write the welded layout (binding 7)
inline constexpr std::uint32_t keep_degenerate = 2; // WeldOptions::keep_degenerate
// The weld by one sort over the mesh (weld_rank_mode and the passes after ctess_weld_keys), which
// Pattern::uniform_split always takes and the other patterns take when a patch has more than
// weld_max_patch_slots slots; without it, each patch's weld runs in one workgroup.
inline constexpr std::uint32_t sorted = 4;
} // namespace weld_flag

// The bits of param_word::displacement_flags.
namespace displacement_flag {
inline constexpr std::uint32_t on = 1;         // displace (the other displacement words are read only then)
inline constexpr std::uint32_t directions = 2; // binding 2 holds the directions after the mesh vertices
inline constexpr std::uint32_t adjacency = 4;  // binding 3 holds the adjacency (12 per face triangle)
// DisplacementMode::vector (docs/algorithm.md §8.7): the texels are RGB (3 floats each) and binding 2 holds
// the tangents (4 floats per mesh vertex) after the mesh vertices and the directions.
inline constexpr std::uint32_t vector = 8;
} // namespace displacement_flag

// Floats per texel of a displacement in binding 3 (docs/shaders.md, "Displacement"): 1 for a height, 3 for an
// RGB vector (DisplacementMode::vector).
inline std::uint32_t texel_floats(const Displacement& d) {
    return d.mode == DisplacementMode::vector ? 3u : 1u;
}

// Workgroup sizes. The setup pass's is the C++ limit's (rt::max_pipeline_patches counts in it); the prefix
// sum is one workgroup of 128 (WebGPU compatibility mode allows at most 128 invocations); the emit passes run
// a workgroup per patch and loop over its vertices and triangles in steps of their workgroup.
inline constexpr std::uint32_t setup_workgroup = patch_setup_workgroup;
inline constexpr std::uint32_t scan_workgroup = 128;
inline constexpr std::uint32_t emit_workgroup = 64;
// After the last record: total vertices, total triangles. The prefix sum writes both as totals_overflow when
// they do not fit in u32; hosts recount the records' counts in 64 bits and refuse such a mesh.
inline constexpr std::uint32_t totals_words = 2;
inline constexpr std::uint32_t totals_overflow = 0xFFFFFFFFu;

inline constexpr std::uint32_t patch_words = sizeof(PatchRecord) / 4;
inline constexpr std::uint32_t vertex_words = sizeof(TessVertex) / 4;

// Words of binding 4 for patch_count patches: the records, then the totals.
constexpr std::uint64_t patch_buffer_words(std::uint64_t patch_count) {
    return patch_count * patch_words + totals_words;
}

// Splitting on the GPU (Pattern::uniform_split; docs/shaders.md, "Splitting"; docs/algorithm.md §3.5): after
// the totals binding 4 holds the split area, a header, then two regions of split_capacity nodes each. Level 0
// is the roots (one per base triangle, two per quad: halves A and B), in patch order. Each level's count pass
// decides every node (a leaf: its pattern and counts; a split node: its split pattern and children), the scan
// numbers the children (prefix sums), and the expand pass writes them into the other region, a leaf as
// itself, so that after split_depth_bound levels the last region holds every leaf in the CPU's walk order.
// A level past the capacity sets split_word::overflow and writes nothing more: the host refuses the run or
// runs it again with split_word::needed nodes (never a dropped patch).
namespace split_word {                       // relative to split_area_word(patch_count)
inline constexpr std::uint32_t level = 0;    // the level the next count pass decides
inline constexpr std::uint32_t nodes = 1;    // the nodes of that level
inline constexpr std::uint32_t parents = 2;  // the nodes of the level before (the expand pass's parents)
inline constexpr std::uint32_t dispatch = 3; // 3 words: the indirect dispatch of the next count or expand
inline constexpr std::uint32_t needed =
    6; // the most nodes a level asked for (at least the capacity on overflow)
inline constexpr std::uint32_t overflow = 7; // 1 when a level asked for more nodes than split_capacity
inline constexpr std::uint32_t header_words = 8;
} // namespace split_word
// A node's words (split_node_word::words each). Corners in units of uniform_split_fixed_one (65534^2) on the
// root, squared factors as uniform::SquaredFactor (low word first), pattern words as
// rt::uniform_setup_word's.
namespace split_node_word {
inline constexpr std::uint32_t patch = 0;     // the patch (record index)
inline constexpr std::uint32_t info = 1;      // split_node_info bits
inline constexpr std::uint32_t corner = 2;    // 6 words: x0 y0 x1 y1 x2 y2
inline constexpr std::uint32_t squared = 8;   // 6 words: s0 s1 s2, two words each
inline constexpr std::uint32_t children = 14; // 1 for a leaf, its split pattern's triangles for a split node
inline constexpr std::uint32_t pattern = 15; // 3 words: the leaf's pattern, or the split node's split pattern
inline constexpr std::uint32_t vertices = 18; // a leaf's counts (0 for a split node)
inline constexpr std::uint32_t triangles = 19;
inline constexpr std::uint32_t first_child = 20; // the scan's exclusive prefix sums
inline constexpr std::uint32_t first_vertex = 21;
inline constexpr std::uint32_t first_triangle = 22;
inline constexpr std::uint32_t words = 24;
} // namespace split_node_word
// The bits of split_node_word::info.
namespace split_node_info {
inline constexpr std::uint32_t depth_mask = 15; // the node's depth (the root's is 0)
inline constexpr std::uint32_t limit_shift = 4; // its patch's depth limit (uniform_split_depth_limit), 4 bits
inline constexpr std::uint32_t half_shift = 8;  // a quad's half (0: A, 1: B)
inline constexpr std::uint32_t leaf = 1u << 9;  // set by the count pass on a leaf
inline constexpr std::uint32_t culled = 1u << 10; // a root of a culled patch: no children, no leaf
} // namespace split_node_info
inline constexpr std::uint32_t split_workgroup = 64; // the roots, count, expand and records passes

constexpr std::uint64_t split_area_word(std::uint64_t patch_count) {
    return patch_buffer_words(patch_count);
}
// Words of binding 4 with the split area for capacity nodes per region.
constexpr std::uint64_t split_buffer_words(std::uint64_t patch_count, std::uint64_t capacity) {
    return split_area_word(patch_count) + split_word::header_words + 2 * capacity * split_node_word::words;
}
// The roots of level 0: one per base triangle, two per quad.
constexpr std::uint64_t split_roots(std::uint64_t triangles, std::uint64_t quads) {
    return triangles + 2 * quads;
}

// The welded output on the GPU (Pattern::cp and Pattern::uniform; docs/shaders.md, "Welded output";
// docs/algorithm.md §7.4): binding 7 holds a header, the mesh's edges as rt::WeldedEdge (the host writes lo
// and hi, sorted and distinct: rt::weld_edge_list; the passes fill the rest), one rt::WeldedPatch per patch,
// then scratch: one writer word per shared id (mesh vertices, then at most one edge point per unwelded
// vertex), one map word per unwelded vertex (slot) and weld_sort_words per slot for the sort of each patch's
// points. Every count and offset is setup_welded's, bit for bit.
namespace weld_word {
inline constexpr std::uint32_t edges = 0;     // the edges in the list (host)
inline constexpr std::uint32_t slots = 1;     // the unwelded vertices the scratch holds (host: the totals')
inline constexpr std::uint32_t shared = 2;    // mesh vertices + edge points: the patches' first interior id
inline constexpr std::uint32_t vertices = 3;  // WeldedTotals::vertices
inline constexpr std::uint32_t triangles = 4; // WeldedTotals::triangles
inline constexpr std::uint32_t status = 5;    // weld_status bits; 0 when the passes' output is whole
// The first patch of a batch of the count and triangle passes (one patch per workgroup; the host writes it
// before each dispatch).
inline constexpr std::uint32_t first_patch = 6;
// The weld by one sort (weld_flag::sorted, docs/shaders.md "Welded output"): the sort's records (host:
// weld_sort_records), the bitonic stage and step of ctess_weld_sort_step, and which list the
// rank passes scan (weld_rank_mode; the host writes these three before each dispatch), and the rank scan's
// total.
inline constexpr std::uint32_t sort_records = 7;
inline constexpr std::uint32_t sort_stage = 8;
inline constexpr std::uint32_t sort_step = 9;
inline constexpr std::uint32_t rank_mode = 10;
inline constexpr std::uint32_t ranked = 11;
inline constexpr std::uint32_t header_words = 12;
} // namespace weld_word
// What the rank passes scan: the sorted records' distinct keys (weld ids), or the kept triangles.
namespace weld_rank_mode {
inline constexpr std::uint32_t keys = 0;
inline constexpr std::uint32_t triangles = 1;
} // namespace weld_rank_mode
namespace weld_status {
inline constexpr std::uint32_t overflow = 1;     // a total past 2^31 (ids) or 2^32
inline constexpr std::uint32_t missing_edge = 2; // a patch edge not in the host's list
} // namespace weld_status
// A slot's map word: a shared id (below 2^31), or weld_map::interior | the rank of the slot's domain point
// among the patch's distinct interior points, with weld_map::representative on the first slot of each point.
namespace weld_map {
inline constexpr std::uint32_t interior = 1u << 31;
inline constexpr std::uint32_t representative = 1u << 30;
inline constexpr std::uint32_t rank_mask = representative - 1;
} // namespace weld_map
inline constexpr std::uint32_t weld_edge_words = sizeof(WeldedEdge) / 4;
inline constexpr std::uint32_t weld_patch_words = sizeof(WeldedPatch) / 4;
// ctess_weld_rank_write writes an owner's first id and its end into two neighbouring words.
static_assert(offsetof(WeldedEdge, vertex_count) == offsetof(WeldedEdge, first_vertex) + 4 &&
              offsetof(WeldedPatch, vertex_count) == offsetof(WeldedPatch, first_vertex) + 4);
inline constexpr std::uint32_t weld_sort_words = 3; // a slot's domain point (u, v) and its index in the patch
// Patches of at most this many slots rank their interior points by counting (O(n) per slot, two barriers)
// instead of the bitonic sort (a barrier per stage); both give the same ranks.
inline constexpr std::uint32_t weld_counted_ranks = 128;
// The most slots (unwelded vertices) a patch may have for the weld of each patch in one workgroup: its sort
// runs in one workgroup, and past this an invocation's loops could pass llvmpipe's 65,535 iterations, so a
// mesh with a larger patch is welded by one sort over the mesh (weld_flag::sorted). Max 64 never reaches it
// (4,290 at most); at max 256 the largest patches do.
inline constexpr std::uint32_t weld_max_patch_slots = 16384;

// Words of binding 7 for a weld of edges edges, patch_count patches, mesh_vertices mesh vertices and slots
// unwelded vertices.
constexpr std::uint64_t weld_buffer_words(std::uint64_t edges, std::uint64_t patch_count,
                                          std::uint64_t mesh_vertices, std::uint64_t slots) {
    return weld_word::header_words + edges * weld_edge_words + patch_count * weld_patch_words +
           mesh_vertices + slots * (2 + weld_sort_words);
}

// The weld by one sort over the whole mesh (weld_flag::sorted; a split patch can have millions of slots):
// every slot's record (owner, key, slot; weld_record_words) sorted by a bitonic network of global steps, the
// distinct keys ranked by a scan in blocks of weld_rank_block items, and the kept triangles ranked the same
// way.
inline constexpr std::uint32_t weld_record_words = 4;
// Records sorted together in workgroup memory by ctess_weld_sort_local (8 KB): every stage up to it at once,
// and each later stage's steps below it (docs/shaders.md, "One sort over the mesh").
inline constexpr std::uint32_t weld_sort_chunk = 512;
inline constexpr std::uint32_t weld_rank_block = 4096; // items per workgroup of the rank passes (64 x 64)
// The sort's records: the slots, or more where the triangles' flags (one word each, weld_record_words to a
// record) need the room afterwards. The network treats the records past them as +inf (ctess_weld_sort_step).
constexpr std::uint64_t weld_sort_records(std::uint64_t slots, std::uint64_t triangles) {
    const std::uint64_t flags = (triangles + weld_record_words - 1) / weld_record_words;
    return slots > flags ? slots : flags > 0 ? flags : 1;
}
// The bitonic network's width for n records: a power of two, at least n and weld_sort_chunk.
constexpr std::uint64_t weld_sort_width(std::uint64_t n) {
    std::uint64_t width = weld_sort_chunk;
    while (width < n) width *= 2;
    return width;
}
constexpr std::uint64_t weld_rank_blocks(std::uint64_t slots, std::uint64_t triangles) {
    const std::uint64_t records = weld_sort_records(slots, triangles);
    return ((records > triangles ? records : triangles) + weld_rank_block - 1) / weld_rank_block;
}
// Words of binding 7 for the weld by one sort: the header, edges and patches as weld_buffer_words, a writer
// word per id, a map word and two words of base weights per slot, the sort's records and two words per rank
// block.
constexpr std::uint64_t weld_sorted_buffer_words(std::uint64_t edges, std::uint64_t patch_count,
                                                 std::uint64_t mesh_vertices, std::uint64_t slots,
                                                 std::uint64_t triangles) {
    return weld_word::header_words + edges * weld_edge_words + patch_count * weld_patch_words +
           mesh_vertices + slots * 4 + weld_record_words * weld_sort_records(slots, triangles) +
           2 * weld_rank_blocks(slots, triangles);
}

// Workgroups of each pass for patch_count patches, at most max_workgroups per dispatch (the passes stride
// over the rest; rt::max_dispatch_workgroups is the one-dispatch limit every Vulkan and WebGPU device
// allows).
constexpr std::uint32_t setup_workgroups(std::uint32_t patch_count,
                                         std::uint32_t max_workgroups = max_dispatch_workgroups) {
    const std::uint32_t groups = patch_count / setup_workgroup + (patch_count % setup_workgroup != 0);
    return groups < max_workgroups ? groups : max_workgroups;
}
constexpr std::uint32_t emit_workgroups(std::uint32_t patch_count,
                                        std::uint32_t max_workgroups = max_dispatch_workgroups) {
    return patch_count < max_workgroups ? patch_count : max_workgroups;
}

// The params of a run over mesh's patches (base triangles, then quads) with options (the D3D11 patterns are
// CPU only: a host refuses them, see gpu_options_status), the emit range covering every patch; split_capacity
// nodes per split region for Pattern::uniform_split.
// Binding 3 then holds mesh.indices (3 per triangle) followed by mesh.quad_indices (4 per quad) and, for
// PN-AEN or displacement, mesh.adjacency (12 per face triangle: the triangles, then each quad's two;
// docs/shaders.md, "PN-AEN"), then with displacement the map's texels (texel_floats each); binding 2 holds
// the mesh vertices, then with displacement and Displacement::directions the directions, then in vector mode
// Displacement::tangents (docs/shaders.md, "Displacement").
inline std::array<std::uint32_t, param_word::words>
pipeline_params(const MeshView& mesh, const PipelineOptions& options, std::uint32_t split_capacity = 0) {
    const auto bits = [](float f) {
        std::uint32_t u;
        std::memcpy(&u, &f, 4);
        return u;
    };
    std::array<std::uint32_t, param_word::words> p{};
    const auto patches = static_cast<std::uint32_t>(mesh.patch_count()); // gpu_options_status checks the size
    p[param_word::patch_count] = patches;
    p[param_word::surface] = static_cast<std::uint32_t>(options.surface.surface);
    p[param_word::alpha] = bits(options.surface.alpha);
    p[param_word::factor_scale] = bits(options.dice.factor_scale());
    p[param_word::eye] = bits(options.dice.eye.x);
    p[param_word::eye + 1] = bits(options.dice.eye.y);
    p[param_word::eye + 2] = bits(options.dice.eye.z);
    p[param_word::mesh_vertex_count] = mesh.vertex_count;
    p[param_word::first_patch] = 0;
    p[param_word::end_patch] = patches;
    p[param_word::pattern] = static_cast<std::uint32_t>(options.pattern);
    p[param_word::quad_count] = mesh.quad_count;
    p[param_word::quad_rule] = static_cast<std::uint32_t>(options.quad_rule);
    p[param_word::split_capacity] = options.pattern == Pattern::uniform_split ? split_capacity : 0u;
    p[param_word::weld] = 0; // the unwelded output; a welded run sets weld_flag::on (weld_params)
    if (const Displacement* d = options.displacement; d != nullptr) {
        const bool empty = d->map.texels == nullptr || d->map.width == 0 || d->map.height == 0;
        p[param_word::displacement_flags] =
            displacement_flag::on | (d->directions != nullptr ? displacement_flag::directions : 0u) |
            (mesh.adjacency != nullptr ? displacement_flag::adjacency : 0u) |
            (d->mode == DisplacementMode::vector ? displacement_flag::vector : 0u);
        p[param_word::displacement_scale] = bits(d->scale);
        p[param_word::displacement_factor] = bits(d->factor);
        p[param_word::displacement_offset] = bits(d->offset);
        p[param_word::displacement_normal_step] = bits(d->normal_step);
        p[param_word::displacement_factor_bound] = bits(d->factor_bound);
        p[param_word::height_map_width] = empty ? 0u : d->map.width; // an empty map samples 0 (§8.1)
        p[param_word::height_map_height] = empty ? 0u : d->map.height;
        p[param_word::height_map_address] = static_cast<std::uint32_t>(d->map.address);
    }
    return p;
}

// Whether the shaders run mesh with options: ok, or bad_option for what they do not run (the D3D11
// patterns, factors other than FactorMode::camera, MeshView::position_ids: the shaders order shared
// edges by vertex index, so a seam between different indices would not get the CPU's bits; displacement by a
// HeightFunction or a VectorFunction, which are CPU code) and for a QuadRule outside its enum, a
// Displacement that displacement_valid refuses (as the CPU pipeline does: among others vector mode without
// tangents, a map whose channel count is not the mode's), or too_many_patches. Both displacement modes run
// (scalar heights, docs/algorithm.md §8.6; RGB vectors in tangent space, §8.7).
inline PipelineStatus gpu_options_status(const MeshView& mesh, const PipelineOptions& options) {
    if (mesh.position_ids != nullptr) return PipelineStatus::bad_option;
    if (const Displacement* d = options.displacement; d != nullptr)
        if (d->function != nullptr || d->vector_function != nullptr || !displacement_valid(*d))
            return PipelineStatus::bad_option;
    if (options.quad_rule != QuadRule::longer_pair && options.quad_rule != QuadRule::as_labelled)
        return PipelineStatus::bad_option;
    if (options.dice.mode != FactorMode::camera) return PipelineStatus::bad_option;
    if (options.pattern != Pattern::cp && options.pattern != Pattern::uniform &&
        options.pattern != Pattern::uniform_split)
        return PipelineStatus::bad_option;
    const Surface surface = options.surface.surface;
    if (surface != Surface::flat && surface != Surface::pn_triangles && surface != Surface::phong &&
        surface != Surface::pn_aen)
        return PipelineStatus::bad_option;
    return check_pipeline_size(mesh.patch_count(), 0, 0);
}

// Whether the shaders weld mesh with options (the welded output, docs/shaders.md "Welded output"): as
// gpu_options_status (Pattern::cp, uniform and uniform_split).
inline PipelineStatus gpu_weld_status(const MeshView& mesh, const PipelineOptions& options) {
    return gpu_options_status(mesh, options);
}

// The params of a welded run: pipeline_params with weld_flag::on and options.weld's keep_degenerate.
inline std::array<std::uint32_t, param_word::words> weld_params(const MeshView& mesh,
                                                                const PipelineOptions& options) {
    std::array<std::uint32_t, param_word::words> p = pipeline_params(mesh, options);
    p[param_word::weld] = weld_flag::on | (options.weld.keep_degenerate ? weld_flag::keep_degenerate : 0u);
    return p;
}

} // namespace ctess::rt::gpu
