// The mesh pipeline on Vulkan (ctess::vulkan; docs/shaders.md, "Hosts"): the generated SPIR-V of
// share/ctess/shaders (ctess_SHADER_DIR) as eight compute pipelines, in two layers.
//
// MeshPipeline is for a renderer: it creates the pipelines on your VkDevice and records the passes into your
// command buffer; you own the buffers (device-local or not), the descriptor set and the synchronisation
// around the passes (record_counts and record_emit put barriers only between their own dispatches and before
// record_emit; see there).
//
//   ctess::vulkan::MeshPipeline pipeline(device, ctess_shader_dir, 64);
//   // descriptor set of pipeline.set_layout(): the eight buffers of rt::gpu::binding, params from
//   // rt::gpu::pipeline_params, the patches buffer rt::gpu::patch_buffer_words(n) words
//   pipeline.record_counts(cmd, set, n);   // setup + prefix sum; read the totals after the records,
//   ...                                    // size the outputs, bind them
//   pipeline.record_emit(cmd, set, t, q);  // vertices + triangles of the t triangles and q quads
//
// Runner is the whole round trip on host-visible buffers, for tools and tests (tests/gpu, the consumer
// example in docs/shaders.md): its own instance and device (the loader's first device with a compute queue;
// lavapipe where VK_DRIVER_FILES names it), counts, then outputs sized from the totals, read back; by default
// it creates each emit pass on its first use (MeshPipeline::Creation::on_first_use).
//
//   ctess::vulkan::Runner gpu(ctess_shader_dir, 64);
//   const ctess::vulkan::Output out = gpu.tessellate(mesh, options);   // out.vertices, out.indices
//
// Errors (no Vulkan device, a missing SPIR-V or blob file, a failing call, a mesh past the pipeline's limits
// or with options the shaders do not run: rt::gpu::gpu_options_status) throw ctess::vulkan::Error, whose
// message names the call or the file. Nothing is written to the outputs then.
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include <ctess/runtime/gpu/shader_interface.hpp>
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>

namespace ctess::vulkan {

class Error : public std::runtime_error {
  public:
    explicit Error(const std::string& what, VkResult result = VK_SUCCESS)
        : std::runtime_error(what), result_(result) {}
    VkResult result() const noexcept { return result_; } // VK_SUCCESS when no Vulkan call failed
  private:
    VkResult result_;
};

// The generated files of one maximum factor (64 or 256) in shader_dir (docs/shaders.md, "Build outputs").
std::string shader_file(const std::string& shader_dir, unsigned max_factor, const std::string& suffix);
// The table blob a pattern needs, as u32 words: ctess_mesh_<max>.tables.bin for CP,
// ctess_mesh_<max>.uniform.tables.bin for uniform density (the CP sections, then the uniform ones).
std::vector<std::uint32_t> load_table_blob(const std::string& shader_dir, unsigned max_factor,
                                           rt::Pattern pattern);

// The compute pipelines (patch setup, prefix sum, emit vertices and triangles of the base triangles and
// of the quads, displaced vertices of both, vector-displaced vertices of both) on a device, with the
// descriptor set layout of rt::gpu::binding (eight storage buffers, compute stage). Move-only; destroys what
// it created, so destroy it before the device. Creation::all_now (the default) creates every pipeline in the
// constructor; on_first_use creates the two counting passes there and each emit pass when a record_emit first
// needs it, so a host that never displaces or never sees a quad never compiles those passes (the driver's
// compile of a displaced pass is the slow one), at the price of a compile inside that record_emit; either way
// every SPIR-V file is read by the constructor. With on_first_use, record_emit throws Error if the driver
// fails to create a pass; the command buffer then holds the passes recorded before it (reset it). Not for use
// from two threads at once.
class MeshPipeline {
  public:
    enum class Creation { all_now, on_first_use };
    MeshPipeline(VkDevice device, const std::string& shader_dir, unsigned max_factor,
                 Creation creation = Creation::all_now);
    ~MeshPipeline();
    MeshPipeline(MeshPipeline&& other) noexcept;
    MeshPipeline& operator=(MeshPipeline&& other) noexcept;
    MeshPipeline(const MeshPipeline&) = delete;
    MeshPipeline& operator=(const MeshPipeline&) = delete;

    VkDescriptorSetLayout set_layout() const noexcept { return set_layout_; }
    VkPipelineLayout pipeline_layout() const noexcept { return pipeline_layout_; }
    unsigned max_factor() const noexcept { return max_factor_; }

    // Points the eight bindings of set at buffers (whole ranges), in rt::gpu::binding order. Every binding
    // must be valid in every pass: bind 16-byte placeholders as outputs for record_counts. Binding 3's range
    // is read to its end by PN-AEN (arrayLength): give its exact words.
    void write_descriptor_set(VkDescriptorSet set, const VkBuffer (&buffers)[rt::gpu::binding::count]) const;
    // The same with ranges (sub-allocated buffers).
    void write_descriptor_set(VkDescriptorSet set,
                              const VkDescriptorBufferInfo (&ranges)[rt::gpu::binding::count]) const;

    // Records the setup pass and the prefix sum over patch_count patches (the params' patch count), with a
    // compute-to-compute barrier between them and one after; the totals then follow the records in binding 4.
    // Before it, make the params and mesh uploads visible to the compute stage; to read the totals on the
    // host, add a compute-to-host (or -transfer) barrier after it.
    void record_counts(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t patch_count,
                       std::uint32_t max_workgroups = rt::max_dispatch_workgroups) const;
    // Records the emit passes for the params' patch range [first, end), which holds triangle_patches base
    // triangles and quad_patches quads (a pass with none is skipped), with a barrier before (for the counts);
    // to draw the outputs, add a compute-to-vertex-input (and index-read) barrier after it. displaced: the
    // params displace (rt::gpu::displacement_flag::on); the vertices then come from the displaced passes (the
    // others write no vertex for such params; docs/shaders.md, "Displacement"). vector: the params displace
    // by a vector map (rt::gpu::displacement_flag::vector, docs/algorithm.md §8.7), whose vertices come from
    // the vector-displaced passes (the height passes write none for such params, and the reverse).
    void record_emit(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t triangle_patches,
                     std::uint32_t quad_patches, std::uint32_t max_workgroups = rt::max_dispatch_workgroups,
                     bool displaced = false, bool vector = false) const;

    // Pattern::uniform_split (docs/shaders.md, "Splitting"). record_split_counts records the setup pass, the
    // roots, the split levels (rt::uniform_split_max_depth of them, the bound of any shipped table; each a
    // count, a scan and an expand pass, the count and expand passes dispatched indirectly from binding 4),
    // the leaves' count and scan, their records and the prefix sum. patches is binding 4's buffer, created
    // with VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, at patches_offset (a multiple of 4),
    // rt::gpu::split_buffer_words( patch_count, the params' split capacity) words; roots =
    // rt::gpu::split_roots(triangles, quads). After it the split header (rt::gpu::split_word at
    // rt::gpu::split_area_word(patch_count)) says whether the capacity held (overflow, needed) and, in
    // parents, how many leaves record_split_emit draws.
    void record_split_counts(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t patch_count,
                             std::uint32_t roots, VkBuffer patches, VkDeviceSize patches_offset,
                             std::uint32_t max_workgroups = rt::max_dispatch_workgroups) const;
    // The emit passes over the leaves (a workgroup per leaf, at most max_workgroups): the leaves' points,
    // then the vertices and triangles of the triangles when triangles is true, of the quads when quads is
    // true, for the params' patch range.
    void record_split_emit(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t leaves, bool triangles,
                           bool quads, std::uint32_t max_workgroups = rt::max_dispatch_workgroups,
                           bool displaced = false, bool vector = false) const;

    // The welded output (Pattern::cp and Pattern::uniform; docs/shaders.md, "Welded output"). After
    // record_counts, record_weld_counts records the weld's counting passes: each edge's points and the
    // edges' prefix sums, each patch's weld (slots mapped, interior points sorted and ranked, kept
    // triangles), each shared id's writer, and the patches' prefix sums. Binding 7 then holds setup_welded's
    // edges, patch records and totals (rt::gpu::weld_word); before it the host writes the header's edges and
    // slots words and the edges' lo and hi (rt::weld_edge_list); binding 7 is
    // rt::gpu::weld_buffer_words(edges, patch_count, mesh_vertices, slots) words, slots the unwelded vertex
    // total. The params set rt::gpu::weld_flag::on (rt::gpu::weld_params).
    // The count pass runs a patch per workgroup, in batches of max_workgroups whose first patch it writes
    // into binding 7's header between dispatches (vkCmdFillBuffer): binding 7 is weld at weld_offset, created
    // with VK_BUFFER_USAGE_TRANSFER_DST_BIT. Every patch must have at most rt::gpu::weld_max_patch_slots
    // unwelded vertices (record_sorted_weld_counts welds the others).
    void record_weld_counts(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t patch_count,
                            std::uint32_t edges, std::uint32_t mesh_vertices, std::uint32_t slots,
                            VkBuffer weld, VkDeviceSize weld_offset,
                            std::uint32_t max_workgroups = rt::max_dispatch_workgroups) const;
    // The welded vertices (the vertex passes, each slot writing the id it owns) and kept triangles of the
    // params' patch range [first_patch, first_patch + triangle_patches + quad_patches), which holds
    // triangle_patches base triangles and quad_patches quads, and the mesh vertices no face reaches; the
    // outputs sized from binding 7's totals. The triangles run in batches as record_weld_counts' count pass.
    void record_weld_emit(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t first_patch,
                          std::uint32_t triangle_patches, std::uint32_t quad_patches,
                          std::uint32_t mesh_vertices, VkBuffer weld, VkDeviceSize weld_offset,
                          std::uint32_t max_workgroups = rt::max_dispatch_workgroups, bool displaced = false,
                          bool vector = false) const;

    // The weld by one sort over the mesh (rt::gpu::weld_flag::sorted in the params; docs/shaders.md, "Welded
    // output", "One sort"), which Pattern::uniform_split always takes and the other patterns when a patch has
    // more than rt::gpu::weld_max_patch_slots slots: after record_counts (record_split_counts), each slot's
    // record, a bitonic sort (one dispatch in workgroup memory, then per stage of the network past
    // rt::gpu::weld_sort_chunk its larger steps and one more in workgroup memory, each after the host writes
    // its stage and step into binding 7's header), the distinct keys ranked, the kept triangles flagged and
    // ranked, each edge's and patch's counts, the prefix sums and each id's writer; binding 7 then holds what
    // record_weld_counts leaves there. Binding 7 is rt::gpu::weld_sorted_buffer_words(edges, patch_count,
    // mesh_vertices, slots, triangles) words (slots and triangles the unwelded totals), with the header's
    // edges, slots and sort_records (rt::gpu::weld_sort_records(slots, triangles)) words and the edges' lo
    // and hi written by the host. items: the split header's parents (the leaves) for the split pattern, else
    // patch_count.
    void record_sorted_weld_counts(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t patch_count,
                                   std::uint32_t edges, std::uint32_t mesh_vertices, std::uint32_t slots,
                                   std::uint32_t triangles, std::uint32_t items, VkBuffer weld,
                                   VkDeviceSize weld_offset,
                                   std::uint32_t max_workgroups = rt::max_dispatch_workgroups) const;
    // The welded vertices and kept triangles of the params' patch range after record_sorted_weld_counts, and
    // the mesh vertices no face reaches. triangle_items and quad_items: the range's base triangles and quads,
    // or for the split pattern the leaves (0 where the range has no patch of that kind).
    void record_sorted_weld_emit(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t triangle_items,
                                 std::uint32_t quad_items, std::uint32_t mesh_vertices,
                                 std::uint32_t max_workgroups = rt::max_dispatch_workgroups,
                                 bool displaced = false, bool vector = false) const;

    static constexpr unsigned passes = 32;

  private:
    void destroy() noexcept;
    VkPipeline pipeline(unsigned pass) const; // created on its first call
    void record_weld_vertices(VkCommandBuffer cmd, const std::array<std::uint32_t, 2>& items,
                              std::uint32_t max_workgroups, bool displaced, bool vector) const;
    VkDevice device_ = VK_NULL_HANDLE;
    unsigned max_factor_ = 0;
    std::string shader_dir_;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
    mutable VkShaderModule modules_[passes] = {};
    mutable VkPipeline pipelines_[passes] = {}; // setup, prefix sum, emit vertices and triangles, of quads,
                                                // displaced vertices of triangles and of quads,
                                                // vector-displaced vertices of both, then the six split
                                                // passes (roots, count, scan, expand, records, points),
                                                // then the seven weld passes and the
                                                // nine of the weld by one sort
};

// What Runner::tessellate reads back: the unwelded output as rt::emit_mesh writes it (docs/shaders.md).
struct Output {
    std::vector<rt::PatchRecord> patches; // one per patch: the base triangles, then the quads
    rt::PipelineTotals totals;            // vertices and triangles (clamped_edges is not counted on the GPU)
    std::vector<rt::TessVertex> vertices; // totals.vertices
    std::vector<std::uint32_t> indices;   // 3 x totals.triangles
    double milliseconds = 0.0;            // submit to fence, both submissions
    double counts_milliseconds = 0.0; // of which the first: patch setup and prefix sum (split: the levels)
    std::uint32_t split_leaves = 0;   // Pattern::uniform_split: the leaves drawn
    std::uint32_t split_capacity = 0; // and the nodes per split region the run took (after any regrowth)
};

// What Runner::tessellate_welded reads back: rt::setup_welded's and rt::emit_welded_mesh's outputs.
struct WeldedOutput {
    std::vector<rt::WeldedEdge> edges;    // totals.edges, as setup_welded's list
    std::vector<rt::WeldedPatch> patches; // one per patch
    rt::WeldedTotals totals;              // clamped_edges is not counted on the GPU
    std::vector<rt::TessVertex> vertices; // totals.vertices
    std::vector<std::uint32_t> indices;   // 3 x totals.triangles
    double milliseconds = 0.0;            // submit to fence, all three submissions
    double counts_milliseconds = 0.0;     // of which the first two: the unwelded counts and the weld's
};

struct RunOptions {
    std::uint32_t max_workgroups = rt::max_dispatch_workgroups; // per dispatch; the passes stride over more
    bool counts_only = false; // setup and prefix sum only: patches and totals, no outputs
    // Pattern::uniform_split: the nodes of each split region to start with (0: 65,536, or max_split_capacity
    // if smaller, and at least the roots). A level that needs more is run again with what it needed (at least
    // twice the nodes), growing the regions up to max_split_capacity nodes (0: as many as the device's
    // storage range allows); past it tessellate throws Error naming the nodes needed. Never a dropped patch.
    std::uint32_t split_capacity = 0;
    std::uint32_t max_split_capacity = 0;
};

class Runner {
  public:
    // creation: on first use by default, so a run creates only the passes its mesh and params use.
    Runner(const std::string& shader_dir, unsigned max_factor,
           MeshPipeline::Creation creation = MeshPipeline::Creation::on_first_use);
    ~Runner();
    Runner(const Runner&) = delete;
    Runner& operator=(const Runner&) = delete;

    std::string device_name() const;

    // The mesh pipeline on mesh's patches with options (rt::gpu::gpu_options_status must be ok). The
    // totals are recounted from the records in 64 bits and checked against rt::check_pipeline_size before
    // the outputs are allocated.
    Output tessellate(const rt::MeshView& mesh, const rt::PipelineOptions& options, RunOptions run = {});
    // The same with the params words given (a host that sets them itself, e.g. tests of the params' range).
    // Params that displace (rt::gpu::displacement_flag::on) need displacement: its map (whose width x height
    // must be the params', an empty map 0 x 0; 3 floats a texel in vector mode) and, when the params' flags
    // name them, its directions and the mesh's adjacency are uploaded, and in vector mode (whose flag must
    // match Displacement::mode) its tangents (docs/shaders.md, "Displacement"); a HeightFunction or a
    // VectorFunction throws.
    Output tessellate(const rt::MeshView& mesh,
                      const std::array<std::uint32_t, rt::gpu::param_word::words>& params,
                      RunOptions run = {}, const rt::Displacement* displacement = nullptr);

    // The welded output of mesh with options (rt::gpu::gpu_weld_status must be ok: Pattern::cp, uniform or
    // uniform_split), bit for bit rt::setup_welded's and rt::emit_welded_mesh's (positions and normals
    // within the bound of docs/shaders.md where the evaluation is not exact). The edge list is
    // rt::weld_edge_list's, computed here; the welded totals are checked against rt::check_pipeline_size
    // before the outputs are allocated. run.counts_only and the split options do not apply.
    WeldedOutput tessellate_welded(const rt::MeshView& mesh, const rt::PipelineOptions& options,
                                   RunOptions run = {});

  private:
    Output run_pipeline(const rt::MeshView& mesh,
                        const std::array<std::uint32_t, rt::gpu::param_word::words>& params, RunOptions run,
                        const rt::Displacement* displacement, WeldedOutput* welded);
    struct Device;
    std::unique_ptr<Device> device_;
    std::string shader_dir_;
    unsigned max_factor_;
};

} // namespace ctess::vulkan
