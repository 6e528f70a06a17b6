// The mesh pipeline on the CPU: per-edge tessellation factors (tess_factor.hpp), the orientation rule per
// base triangle (cp_orientation.hpp), per-patch counts and their exclusive prefix sum, then every output
// vertex (exact barycentrics, then position, normal and uv by surface_eval.hpp) and every output triangle
// (CP: indices in provoking-vertex order). The generated GLSL and WGSL shaders run the same steps with the
// same formulas and the same record layouts; this is the reference they are tested against.
//
// Pattern families (PipelineOptions::pattern): CP (docs/algorithm.md §2, the default); uniform density
// (§3, uniform_pipeline_patch.hpp): each base triangle gets UniformPatch's pattern of its three edge factors,
// rounded and clamped to [1, N] of the uniform tables, with its barycentrics converted exactly to 2^-24 base
// weights (the shaders' pattern); uniform density split at any factor up to 32,768 (§7.5, CPU only); or the
// D3D11 tessellator's patterns (§7.6, CPU only). The uniform patterns need the overloads that take a
// UniformTableSet as well; the CP-only overloads refuse them (PipelineStatus::no_uniform_tables).
//
// Counts first, then fills (as OpenSubdiv's Bfr::Tessellation). CP and clamped uniform allocate nothing; the
// split and D3D11 patterns have no O(1) random access and keep one patch's output at a time. The factors,
// setup and emit are out of line in ctess::runtime_core (src/pipeline/mesh_pipeline.cpp), compiled with
// contraction and fast-math off, so that the counts and every shared edge's points are the same whatever
// the caller's flags (docs/api.md, "Crack-free evaluation").
//
//   std::vector<PatchRecord> patches(mesh.patch_count());
//   PipelineTotals totals;
//   if (setup_patches(cp_tables_64, mesh, options, patches, totals) != PipelineStatus::ok) ...
//   std::vector<TessVertex> vertices(totals.vertices);
//   std::vector<std::uint32_t> indices(3 * std::size_t{totals.triangles});
//   emit_mesh(cp_tables_64, mesh, options, patches, vertices, indices);
//
// Quads (MeshView::quad_indices, docs/algorithm.md §7.2-7.3): each is two triangle halves of the patch's
// pattern along a diagonal chosen by PipelineOptions::quad_rule (CP) or the shorter diagonal (the others);
// quads are evaluated with every surface (evaluate_quad_surface inside, the exact edge rule of
// evaluate_surface on their edges), so a mixed mesh is watertight where triangles meet quads. PN-AEN reads
// MeshView::adjacency (docs/algorithm.md §6.1); the GPU shaders run triangles and quads with the flat, PN,
// PN-AEN and Phong surfaces, and read the adjacency after the triangle and quad indices (docs/shaders.md,
// "PN-AEN"). A welded, indexed output: setup_welded / emit_welded_mesh at the end of this header.
//
// Bad input: a base triangle or quad with a vertex index >= vertex_count is culled (no vertices, no
// triangles); factors follow tess_factor.hpp and CpPatch's clamping (NaN/inf positions give NaN/inf factors:
// T0 or the maximum). Every other failure is a PipelineStatus other than ok, and pipeline_status_message()
// says why: spans that are too small, a mesh past the GPU pipeline's limits (totals are summed in 64 bits and
// checked against max_pipeline_patches/vertices/triangles, so they never wrap), or patch records that
// setup_patches did not produce. On a failure emit_mesh writes nothing and setup_patches leaves totals
// unchanged.
#pragma once
#include <cstdint>
#include <span>

#include <ctess/cp/line.hpp>
#include <ctess/cp/orientation.hpp>

#include "tess_factor.hpp"
#include <ctess/runtime/cp/patch.hpp>
#include <ctess/runtime/cp/setup_block.hpp>
#include <ctess/runtime/cp/table_set.hpp>
#include <ctess/runtime/surface/eval.hpp>
#include <ctess/runtime/uniform/pipeline_words.hpp>

namespace ctess::rt {

inline constexpr unsigned mesh_vertex_floats = 8; // position xyz, normal xyz, uv

// Patches are the base triangles first (patch t = triangle t), then the quads (patch triangle_count + q =
// quad q), on the GPU too (binding 3 holds the triangles' indices, then the quads').
struct MeshView {
    const float* vertices = nullptr; // mesh_vertex_floats per vertex
    std::uint32_t vertex_count = 0;
    const std::uint32_t* indices = nullptr; // 3 per base triangle, counter-clockwise
    std::uint32_t triangle_count = 0;
    const std::uint32_t* quad_indices = nullptr; // 4 per quad q0 q1 q2 q3, counter-clockwise
    std::uint32_t quad_count = 0;
    // Optional (null: none), each as long as stated (as indices holds 3 x triangle_count). position_ids:
    // vertex_count entries, the first vertex with the same position
    // (models::Adjacency::position_ids); shared edges are then ordered by position, so the two sides of a uv
    // or normal seam evaluate an edge point with the same operations (without them, by vertex index).
    const std::uint32_t* position_ids = nullptr;
    // adjacency: 12 x (triangle_count + 2 x quad_count) entries, meshopt_generateTessellationIndexBuffer's
    // layout (models::Adjacency::tessellation_indices): the base triangles, then each quad's (q0, q1, q2) and
    // (q0, q2, q3). Read by Surface::pn_aen; without it PN-AEN treats every edge as a boundary.
    const std::uint32_t* adjacency = nullptr;
    std::uint64_t patch_count() const { return std::uint64_t{triangle_count} + quad_count; }
};

// The pattern family of every patch; the shaders read it as params word 10 (docs/shaders.md).
enum class Pattern : std::uint32_t {
    cp = 0,
    uniform = 1, // uniform density, factors rounded and clamped to the table's N (the shaders' pass)
    // Uniform density at any factor up to 32,768 (uniform_split_max_factor): patches above N split with the
    // table's own patterns (UniformSplit, docs/algorithm.md §3.5, §7.5); the same output as uniform up to N.
    // Its records carry no setup block; the shaders split too (docs/shaders.md, "Splitting").
    uniform_split = 2,
    // The D3D11 tessellator's triangle domain (docs/algorithm.md §5, §7.6) with the partitioning named, CPU
    // only: the fixed-function patterns ctess is measured against, on the same mesh and factors.
    d3d11_integer = 3,
    d3d11_pow2 = 4,
    d3d11_fractional_odd = 5,
    d3d11_fractional_even = 6,
};

// Which quad edge becomes q0q1, the edge whose factor the CP diagonal takes (docs/algorithm.md §7.2).
enum class QuadRule : std::uint32_t {
    longer_pair = 0, // q0q1 = the longer edge of the opposite pair with the larger summed length (default)
    as_labelled = 1, // q0q1 = the quad's first edge, as the mesh lists it
};

// The welded output (emit_welded_mesh, docs/algorithm.md §7.4).
struct WeldOptions {
    // false (default): a triangle whose welded corners repeat an index is dropped (it has zero area). true:
    // kept, so the triangle list is the same at every factor of a token triple (fixed topology, popless).
    bool keep_degenerate = false;
};

struct Displacement; // displace/displace.hpp

struct PipelineOptions {
    DiceOptions dice{};
    SurfaceOptions surface{};
    Pattern pattern = Pattern::cp;
    QuadRule quad_rule = QuadRule::longer_pair;
    WeldOptions weld{};
    // Displacement (displace/displace.hpp, docs/algorithm.md §8): null, the default, is none. Applied to
    // every output vertex of emit_mesh and emit_welded_mesh; its factor_bound also grows the edge factors.
    const Displacement* displacement = nullptr;
};

// A quad record (docs/algorithm.md §7.3) has kind == patch_kind_quad (the shaders write the same words). Its
// rotation (0-3) is the quad rule's: pattern corner q_k is the mesh quad's corner (k + rotation) % 4. It is
// two halves, A = (q0, q1, q3) and B = (q2, q3, q1), both with the diagonal q1q3 as e1 and rotation 0: A's
// line states (CP) or uniform factors are token/t16 as a triangle's, B's are setup[quad_setup_word::b_token
// + k] and setup[quad_setup_word::b_t16 + k]; counts and offsets are A's and B's together (A first).
// factor[k] holds the mesh quad's edges Q0..Q2 (Qk = corner k -> k + 1), the setup word q3_factor Q3's bits.
inline constexpr std::uint32_t patch_kind_triangle = 0;
inline constexpr std::uint32_t patch_kind_quad = 1;
namespace quad_setup_word {
inline constexpr unsigned b_token = 0;   // 3 words
inline constexpr unsigned b_t16 = 3;     // 3 words (0 for uniform)
inline constexpr unsigned q3_factor = 6; // float bits
} // namespace quad_setup_word

// One base triangle (patch). 48 words: the GPU's patch buffer uses this layout. Words 16-47 are the setup
// block the GPU's emit passes read instead of redoing the patch setup (patch_setup_block.hpp). A uniform
// patch has rotation 0, token[k] = uniform_factor(k), the integer factor of base edge Ek, t16 zero, and the
// uniform setup words (uniform_pipeline_patch.hpp).
struct PatchRecord {
    std::uint32_t rotation = 0;  // cp::Rotation::shift: pattern vertex v_k is base vertex (k + rotation) % 3
    std::uint32_t token[3] = {}; // pattern edges e0, e1, e2: CP line state
    std::uint32_t t16[3] = {};
    std::uint32_t vertex_count = 0;
    std::uint32_t triangle_count = 0;
    std::uint32_t first_vertex = 0; // exclusive prefix sums over the patches
    std::uint32_t first_triangle = 0;
    float factor[3] = {};                     // base edges E0 = w0w1, E1 = w1w2, E2 = w2w0, before clamping
    std::uint32_t kind = patch_kind_triangle; // patch_kind_triangle or patch_kind_quad
    std::uint32_t reserved = 0;
    std::uint32_t setup[setup_word::words] = {};

    // A uniform patch's integer factor of base edge Ek, kept in token[k] (the shaders read the same word).
    constexpr std::uint32_t uniform_factor(unsigned k) const noexcept { return token[k]; }
    constexpr void set_uniform_factor(unsigned k, std::uint32_t f) noexcept { token[k] = f; }
};
static_assert(sizeof(PatchRecord) == 192);

// One output vertex. 10 words: the GPU's vertex buffer uses this layout.
struct TessVertex {
    std::uint32_t u = 0, v = 0; // base weights of w1 and w2, units of 2^-24 (w0 = 2^24 - u - v)
    float position[3] = {};
    float normal[3] = {};
    float uv[2] = {};
};
static_assert(sizeof(TessVertex) == 40);

struct PipelineTotals {
    std::uint32_t vertices = 0;
    std::uint32_t triangles = 0;
    // Patch edges whose factor was above the pattern's maximum and was clamped to it (CP: the tables'
    // max_factor; uniform: N; uniform_split: 32,768; D3D11: 64, 63 for fractional_odd). Counted once per
    // patch and edge, so an edge shared by two faces counts twice; a CP quad counts its 4 edges, a uniform
    // quad its diagonal too. Non-zero means the output is coarser than the factors asked for.
    std::uint32_t clamped_edges = 0;
};

enum class PipelineStatus : std::uint8_t {
    ok,
    span_too_small,     // the patches, vertices or indices span is shorter than the counts need
    too_many_patches,   // more base triangles than max_pipeline_patches
    too_many_vertices,  // total vertices past max_pipeline_vertices
    too_many_triangles, // total triangles past max_pipeline_triangles
    bad_patch_record,   // a record setup_patches did not produce (tampered counts, offsets or rotation)
    no_uniform_tables,  // a uniform pattern through an overload without a UniformTableSet
    bad_option,         // a Pattern, QuadRule or Surface value outside its enum, or an invalid Displacement
    bad_range,          // a WeldedRange outside the mesh's patches, or any range of a mesh without patches
};

// The limits of one pipeline run, set by the shaders (docs/shaders.md): the patch setup pass is one
// dimension of workgroups of 64, at most 65,535 of them (the smallest maxComputeWorkGroupCount Vulkan and
// WebGPU guarantee); the emit passes address vertex and index words with 32-bit integers.
inline constexpr std::uint32_t max_dispatch_workgroups = 65535;
inline constexpr std::uint32_t patch_setup_workgroup = 64;
inline constexpr std::uint64_t max_pipeline_patches =
    std::uint64_t{max_dispatch_workgroups} * patch_setup_workgroup;
inline constexpr std::uint64_t max_pipeline_vertices = 0xFFFFFFFFu / (sizeof(TessVertex) / 4); // 429,496,729
inline constexpr std::uint64_t max_pipeline_triangles = 0xFFFFFFFFu / 3; // 1,431,655,765

constexpr const char* pipeline_status_message(PipelineStatus status) {
    switch (status) {
    case PipelineStatus::ok:
        return "ok";
    case PipelineStatus::span_too_small:
        return "an output span is smaller than the counts need";
    case PipelineStatus::too_many_patches:
        return "the mesh has more base triangles than the patch setup dispatch allows (65,535 x 64)";
    case PipelineStatus::too_many_vertices:
        return "the mesh needs more output vertices than 32-bit vertex words can address (429,496,729)";
    case PipelineStatus::too_many_triangles:
        return "the mesh needs more output triangles than 32-bit index words can address (1,431,655,765)";
    case PipelineStatus::bad_patch_record:
        return "a patch record was not produced by setup_patches";
    case PipelineStatus::no_uniform_tables:
        return "the uniform pattern needs a UniformTableSet (the overloads that take one)";
    case PipelineStatus::bad_option:
        return "an option (pattern, quad rule, surface) is outside its enum";
    case PipelineStatus::bad_range:
        return "a range of patches lies outside the mesh's patches (a mesh without patches has no ranges)";
    }
    return "unknown status";
}

// Checks a run's size against the limits, in 64 bits (the GPU host code calls it on the totals too).
constexpr PipelineStatus check_pipeline_size(std::uint64_t patches, std::uint64_t vertices,
                                             std::uint64_t triangles) {
    if (patches > max_pipeline_patches) return PipelineStatus::too_many_patches;
    if (vertices > max_pipeline_vertices) return PipelineStatus::too_many_vertices;
    if (triangles > max_pipeline_triangles) return PipelineStatus::too_many_triangles;
    return PipelineStatus::ok;
}

// Patch t's rotation, line states, counts and setup block (first_vertex and first_triangle are left 0). The
// CP pattern, whatever options.pattern says.
PatchRecord setup_patch(const CpTableSet& tables, const MeshView& mesh, std::uint32_t t,
                        const PipelineOptions& options);

// The pipeline's uniform patches: one vertex per position (the shaders have no provoking copies for uniform),
// counter-clockwise as the base triangles.
inline constexpr PatchOptions uniform_pipeline_options{Layout::shared, Winding::ccw};

// Patch t's uniform record: rotation 0, uniform_factor(k) = the rounded and clamped factor of base edge Ek,
// counts and the uniform setup words.
PatchRecord setup_uniform_patch(const UniformTableSet& tables, const MeshView& mesh, std::uint32_t t,
                                const PipelineOptions& options);

// Every patch's record, with the exclusive prefix sums and the totals. Stops at the first patch that takes a
// total past its limit (the records before it are written, totals is left unchanged).
PipelineStatus setup_patches(const CpTableSet& tables, const MeshView& mesh, const PipelineOptions& options,
                             std::span<PatchRecord> patches, PipelineTotals& totals);
// The same with the uniform tables, for PipelineOptions::pattern = Pattern::uniform.
PipelineStatus setup_patches(const CpTableSet& tables, const UniformTableSet& uniform, const MeshView& mesh,
                             const PipelineOptions& options, std::span<PatchRecord> patches,
                             PipelineTotals& totals);

inline CpPatch patch_of(const CpTableSet& tables, const PatchRecord& rec) {
    return CpPatch(tables, cp::LineState{rec.token[0], rec.t16[0]}, cp::LineState{rec.token[1], rec.t16[1]},
                   cp::LineState{rec.token[2], rec.t16[2]});
}

inline UniformPatch uniform_patch_of(const UniformTableSet& tables, const PatchRecord& rec) {
    return UniformPatch(tables, {rec.uniform_factor(0), rec.uniform_factor(1), rec.uniform_factor(2)},
                        uniform_pipeline_options);
}

// Vertex i of a patch: exact base weights, then the surface.
TessVertex patch_vertex(const CpPatch& patch, const PatchRecord& rec, const SurfaceCorner (&corner)[3],
                        std::uint32_t i, const SurfaceOptions& surface);

// Every vertex and triangle of the mesh, at the records' offsets. Checks every record first (its counts are
// its pattern's counts, its offsets the exclusive prefix sums, a culled patch is empty) and the spans; on
// any failure writes nothing.
PipelineStatus emit_mesh(const CpTableSet& tables, const MeshView& mesh, const PipelineOptions& options,
                         std::span<const PatchRecord> patches, std::span<TessVertex> vertices,
                         std::span<std::uint32_t> indices);
// The same with the uniform tables, for PipelineOptions::pattern = Pattern::uniform.
PipelineStatus emit_mesh(const CpTableSet& tables, const UniformTableSet& uniform, const MeshView& mesh,
                         const PipelineOptions& options, std::span<const PatchRecord> patches,
                         std::span<TessVertex> vertices, std::span<std::uint32_t> indices);
// Patches [a, b) of a mesh into the whole mesh's spans, so that threads can each emit a range at once
// (bench/bench_mesh.cpp, mesh_pipeline/grid10k). range is a MeshView of those faces: indices from triangle a
// on, quad_indices from the range's first quad on, and adjacency from the range's first entry on (12 per
// triangle, then 24 per quad after all the mesh's triangles: adjacency + 12 a while a is a triangle,
// adjacency + 12 T + 24 (a - T) past the T triangles); patches are the range's records, whose offsets run on
// from the first one's. Checked as emit_mesh checks a mesh, the spans against the range's end.
PipelineStatus emit_mesh_range(const CpTableSet& tables, const MeshView& range,
                               const PipelineOptions& options, std::span<const PatchRecord> patches,
                               std::span<TessVertex> vertices, std::span<std::uint32_t> indices);
PipelineStatus emit_mesh_range(const CpTableSet& tables, const UniformTableSet& uniform,
                               const MeshView& range, const PipelineOptions& options,
                               std::span<const PatchRecord> patches, std::span<TessVertex> vertices,
                               std::span<std::uint32_t> indices);

// --- One welded, indexed mesh (docs/algorithm.md §7.4) ---
//
// Every output position once where the input shares a vertex index: output vertex v < mesh.vertex_count is
// input vertex v (its corner value: position, normalised normal, uv), then the points inside each mesh edge
// (edges keyed by their two vertex indices, lower first, sorted; numbered by prefix sums over that list),
// then each patch's interior points (prefix sums over the patches). Edge points at one parameter are one
// vertex even where the line has coincident points (a zero-length segment), and interior slots at one exact
// domain point (a quad's diagonal, points born on a neighbour) are one vertex of the patch. A position
// reached by different input indices (a uv or normal seam) keeps one vertex per index, as the input does.
// Vertices are TessVertex; u and v are the patch's base weights (a quad's unit square) for interior points
// and 0 for corners and edge points, which belong to no one patch.
//
//   std::vector<rt::WeldedEdge> edges(rt::weld_edge_capacity(mesh));
//   std::vector<rt::WeldedPatch> patches(mesh.patch_count());
//   rt::WeldedTotals totals;
//   if (rt::setup_welded(cp_tables_64, mesh, options, edges, patches, totals) != PipelineStatus::ok) ...
//   edges.resize(totals.edges);
//   std::vector<TessVertex> vertices(totals.vertices);
//   std::vector<std::uint32_t> indices(3 * std::size_t{totals.triangles});
//   rt::emit_welded_mesh(cp_tables_64, mesh, options, edges, patches, vertices, indices);
//
// The patterns are the unwelded pipeline's (setup_patches), in the shared layout: the same triangles, with
// the triangles whose welded corners repeat an index dropped unless options.weld.keep_degenerate. Culled
// faces (an index >= vertex_count) add nothing. setup_welded counts the unwelded output first and refuses a
// mesh whose unwelded counts pass the pipeline's limits, before any pattern is generated. setup_welded and
// emit_welded_mesh keep in scratch one patch's slot map and interior points (about 36 bytes per slot), for
// the split and D3D11 patterns its whole output (8 bytes per point, 12 per triangle), one index per mesh
// vertex into the edge list, and a cache of patch shapes: a pattern's weld in local ids, made once and
// reused by every patch with the same pattern words and distinct corners (32 of up to 4,096 ids, about
// 5 MB at most, plus one larger; docs/algorithm.md §7.4). emit_welded_mesh checks the edge list and the
// patch records against the mesh first (bad_patch_record) and writes nothing on any failure; it then writes
// the patches last to first, each corner and edge point once (one bit per point), with the value of the
// last patch that reaches it.

// One mesh edge of the welded output: its endpoints (lo < hi, or lo == hi for a degenerate face) and its
// interior points' vertex range.
struct WeldedEdge {
    std::uint32_t lo = 0, hi = 0;
    std::uint32_t first_vertex = 0;
    std::uint32_t vertex_count = 0; // distinct interior points of the edge's line
};

// One patch of the welded output: its interior vertices and its kept triangles.
struct WeldedPatch {
    std::uint32_t first_vertex = 0;
    std::uint32_t vertex_count = 0;
    std::uint32_t first_triangle = 0;
    std::uint32_t triangle_count = 0;
};

struct WeldedTotals {
    std::uint32_t vertices = 0;      // output vertices: the mesh's, the edges' and the patches' interiors
    std::uint32_t triangles = 0;     // output triangles (kept ones)
    std::uint32_t edges = 0;         // distinct mesh edges: the first entries of the edges span
    std::uint32_t clamped_edges = 0; // as PipelineTotals::clamped_edges
};

// The edges span setup_welded needs: 3 per base triangle and 4 per quad (before duplicates are removed).
constexpr std::uint64_t weld_edge_capacity(const MeshView& mesh) {
    return 3 * std::uint64_t{mesh.triangle_count} + 4 * std::uint64_t{mesh.quad_count};
}

// The mesh's edges as setup_welded lists them: each face's (culled faces none, a quad's four), keyed lo < hi
// (lo == hi for a degenerate face), sorted and distinct at the front of edges (weld_edge_capacity entries),
// first_vertex and vertex_count 0. Returns how many. A function of the indices alone, so a GPU host computes
// it once per mesh (docs/shaders.md, "Welded output"). 0 when edges is too small.
std::uint32_t weld_edge_list(const MeshView& mesh, std::span<WeldedEdge> edges);

// Counts: the sorted distinct edges (totals.edges of them, at the front of edges), every patch's counts and
// offsets, and the totals. On a failure totals is left unchanged.
PipelineStatus setup_welded(const CpTableSet& tables, const MeshView& mesh, const PipelineOptions& options,
                            std::span<WeldedEdge> edges, std::span<WeldedPatch> patches,
                            WeldedTotals& totals);
PipelineStatus setup_welded(const CpTableSet& tables, const UniformTableSet& uniform, const MeshView& mesh,
                            const PipelineOptions& options, std::span<WeldedEdge> edges,
                            std::span<WeldedPatch> patches, WeldedTotals& totals);

// Fills: the welded vertices and triangle indices at the offsets setup_welded gave, with the same options.
PipelineStatus emit_welded_mesh(const CpTableSet& tables, const MeshView& mesh,
                                const PipelineOptions& options, std::span<const WeldedEdge> edges,
                                std::span<const WeldedPatch> patches, std::span<TessVertex> vertices,
                                std::span<std::uint32_t> indices);
PipelineStatus emit_welded_mesh(const CpTableSet& tables, const UniformTableSet& uniform,
                                const MeshView& mesh, const PipelineOptions& options,
                                std::span<const WeldedEdge> edges, std::span<const WeldedPatch> patches,
                                std::span<TessVertex> vertices, std::span<std::uint32_t> indices);

// --- The welded output in ranges of patches, for a caller's threads (docs/algorithm.md §7.4, "Ranges") ---
//
// emit_welded_mesh for the patches [first_patch, end_patch) only: their interior vertices and triangles, and
// the corners and edge points whose last patch (the one emit_welded_mesh takes each value from) lies in the
// range; the range that holds the last patch also writes the mesh vertices no face reaches. Ranges that
// cover the patches once, called one after another or at once on several threads (the inputs are only
// read), write exactly what one emit_welded_mesh call writes, and no two of them write the same word. The
// library starts no thread:
//
//   std::vector<std::thread> threads;
//   for (std::uint32_t k = 0; k < 2; ++k)
//       threads.emplace_back([&, k] {
//           status[k] = rt::emit_welded_mesh(cp_tables_64, mesh, options, edges, patches,
//                                            rt::welded_range(mesh, patches, k, 2), vertices, indices);
//       });
//
// Each call checks the edge list, the offsets of every record and the counts of its own records, and
// writes nothing on a failure (bad_range for a range outside the patches, and for any range of a mesh
// without patches, whose vertices only the call without a range writes); a failed call leaves the other
// ranges' output in place, so a caller discards the mesh when any range fails. Each call also marks, before
// writing, the corners and edge points that patches after its range reach (one bit per corner and edge
// point, as emit_welded_mesh's marks).
struct WeldedRange {
    std::uint32_t first_patch = 0;
    std::uint32_t end_patch = 0; // one past the last patch
};

// Part `part` of `parts` consecutive ranges of the mesh's patches with about equal output triangles, from the
// records' first_triangle (parts 0 is taken as 1; a part past the last gives an empty range at the end).
WeldedRange welded_range(const MeshView& mesh, std::span<const WeldedPatch> patches, std::uint32_t part,
                         std::uint32_t parts);

PipelineStatus emit_welded_mesh(const CpTableSet& tables, const MeshView& mesh,
                                const PipelineOptions& options, std::span<const WeldedEdge> edges,
                                std::span<const WeldedPatch> patches, WeldedRange range,
                                std::span<TessVertex> vertices, std::span<std::uint32_t> indices);
PipelineStatus emit_welded_mesh(const CpTableSet& tables, const UniformTableSet& uniform,
                                const MeshView& mesh, const PipelineOptions& options,
                                std::span<const WeldedEdge> edges, std::span<const WeldedPatch> patches,
                                WeldedRange range, std::span<TessVertex> vertices,
                                std::span<std::uint32_t> indices);

} // namespace ctess::rt
