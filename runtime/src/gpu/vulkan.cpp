#include <ctess/runtime/gpu/vulkan.hpp>

#include <ctess/runtime/uniform/split.hpp>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <fstream>
#include <utility>

namespace ctess::vulkan {

namespace {

void check(VkResult r, const char* what) {
    if (r != VK_SUCCESS) {
        std::string why = what;
        why += " failed with VkResult ";
        why += std::to_string(static_cast<int>(r));
        throw Error(why, r);
    }
}

// A zeroed Vulkan struct with its type set (aggregate init would trip -Wmissing-field-initializers).
template <class T>
T vk_struct(VkStructureType type) {
    T value{};
    value.sType = type;
    return value;
}

std::vector<std::uint32_t> read_words(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) throw Error("cannot read " + path + " (are the shaders generated and installed?)");
    const std::streamoff bytes = in.tellg();
    if (bytes <= 0 || bytes % 4 != 0) throw Error(path + " is empty or not whole u32 words");
    std::vector<std::uint32_t> words(static_cast<std::size_t>(bytes) / 4);
    in.seekg(0);
    in.read(reinterpret_cast<char*>(words.data()), static_cast<std::streamsize>(bytes));
    if (!in) throw Error("cannot read " + path);
    return words;
}

constexpr const char* pass_suffix[MeshPipeline::passes] = {"_patch_setup.spv",
                                                           "_prefix_sum.spv",
                                                           "_emit_vertices.spv",
                                                           "_emit_triangles.spv",
                                                           "_emit_quad_vertices.spv",
                                                           "_emit_quad_triangles.spv",
                                                           "_emit_displaced_vertices.spv",
                                                           "_emit_displaced_quad_vertices.spv",
                                                           "_emit_vector_displaced_vertices.spv",
                                                           "_emit_vector_displaced_quad_vertices.spv",
                                                           "_split_roots.spv",
                                                           "_split_count.spv",
                                                           "_split_scan.spv",
                                                           "_split_expand.spv",
                                                           "_split_records.spv",
                                                           "_split_points.spv",
                                                           "_weld_edges.spv",
                                                           "_weld_edge_scan.spv",
                                                           "_weld_count.spv",
                                                           "_weld_writers.spv",
                                                           "_weld_scan.spv",
                                                           "_weld_triangles.spv",
                                                           "_weld_lone_vertices.spv",
                                                           "_weld_keys.spv",
                                                           "_weld_sort_step.spv",
                                                           "_weld_rank_blocks.spv",
                                                           "_weld_rank_scan.spv",
                                                           "_weld_rank_write.spv",
                                                           "_weld_keep.spv",
                                                           "_weld_owner_counts.spv",
                                                           "_weld_sorted_triangles.spv",
                                                           "_weld_sort_local.spv"};
// The split passes' indices in pass_suffix.
constexpr unsigned split_roots_pass = 10, split_count_pass = 11, split_scan_pass = 12, split_expand_pass = 13,
                   split_records_pass = 14, split_points_pass = 15;
// The weld passes' (docs/shaders.md, "Welded output").
constexpr unsigned weld_edges_pass = 16, weld_edge_scan_pass = 17, weld_count_pass = 18,
                   weld_writers_pass = 19, weld_scan_pass = 20, weld_triangles_pass = 21,
                   weld_lone_vertices_pass = 22;
// The weld by one sort over the mesh: its passes.
constexpr unsigned weld_keys_pass = 23, weld_sort_step_pass = 24, weld_rank_blocks_pass = 25,
                   weld_rank_scan_pass = 26, weld_rank_write_pass = 27, weld_keep_pass = 28,
                   weld_owner_counts_pass = 29, weld_sorted_triangles_pass = 30, weld_sort_local_pass = 31;

// Writes one u32 of buffer between compute passes (vkCmdFillBuffer), ordered after the passes before it and
// before the ones after it.
void fill_word(VkCommandBuffer cmd, VkBuffer buffer, VkDeviceSize offset, std::uint32_t value) {
    auto before = vk_struct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    before.srcAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    before.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1,
                         &before, 0, nullptr, 0, nullptr);
    vkCmdFillBuffer(cmd, buffer, offset, 4, value);
    auto after = vk_struct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    after.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    after.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1,
                         &after, 0, nullptr, 0, nullptr);
}

// The vertex pass of kind 0 (base triangles) or 1 (quads): undisplaced, displaced or vector-displaced.
unsigned vertex_pass(unsigned kind, bool displaced, bool vector) {
    return !displaced ? 2 + 2 * kind : vector ? 8 + kind : 6 + kind;
}

// Workgroups of count items at most per invocation's group of size, at least 1, at most max_workgroups.
std::uint32_t grid_workgroups(std::uint64_t items, std::uint32_t size, std::uint32_t max_workgroups) {
    const std::uint64_t groups = items / size + (items % size != 0);
    return static_cast<std::uint32_t>(
        std::max<std::uint64_t>(1, std::min<std::uint64_t>(groups, max_workgroups)));
}

void compute_barrier(VkCommandBuffer cmd) {
    auto barrier = vk_struct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0,
                         1, &barrier, 0, nullptr, 0, nullptr);
}
// The same, and the dispatch words a pass wrote read by the next indirect dispatch.
void indirect_barrier(VkCommandBuffer cmd) {
    auto barrier = vk_struct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask =
        VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT, 0, 1,
                         &barrier, 0, nullptr, 0, nullptr);
}

} // namespace

std::string shader_file(const std::string& shader_dir, unsigned max_factor, const std::string& suffix) {
    return shader_dir + "/ctess_mesh_" + std::to_string(max_factor) + suffix;
}

std::vector<std::uint32_t> load_table_blob(const std::string& shader_dir, unsigned max_factor,
                                           rt::Pattern pattern) {
    return read_words(shader_file(shader_dir, max_factor,
                                  pattern == rt::Pattern::uniform ? ".uniform.tables.bin" : ".tables.bin"));
}

// ---- MeshPipeline ----

MeshPipeline::MeshPipeline(VkDevice device, const std::string& shader_dir, unsigned max_factor,
                           Creation creation)
    : device_(device), max_factor_(max_factor), shader_dir_(shader_dir) {
    if (max_factor != 64 && max_factor != 256)
        throw Error("the shaders exist for max factor 64 and 256 only");
    try {
        VkDescriptorSetLayoutBinding b[rt::gpu::binding::count]{};
        for (std::uint32_t i = 0; i < rt::gpu::binding::count; ++i) {
            b[i].binding = i;
            b[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
            b[i].descriptorCount = 1;
            b[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
        }
        auto dsl =
            vk_struct<VkDescriptorSetLayoutCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO);
        dsl.bindingCount = rt::gpu::binding::count;
        dsl.pBindings = b;
        check(vkCreateDescriptorSetLayout(device_, &dsl, nullptr, &set_layout_),
              "vkCreateDescriptorSetLayout");
        auto pl = vk_struct<VkPipelineLayoutCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO);
        pl.setLayoutCount = 1;
        pl.pSetLayouts = &set_layout_;
        check(vkCreatePipelineLayout(device_, &pl, nullptr, &pipeline_layout_), "vkCreatePipelineLayout");
        // Every SPIR-V file is read now (whole u32 words), so a missing or damaged one is an error of the
        // constructor in either mode.
        for (unsigned k = 0; k < passes; ++k) read_words(shader_file(shader_dir, max_factor, pass_suffix[k]));
        if (creation == Creation::all_now)
            for (unsigned k = 0; k < passes; ++k) pipeline(k);
        else
            for (unsigned k = 0; k < 2; ++k) pipeline(k); // the counting passes, which every use needs
    } catch (...) {
        destroy();
        throw;
    }
}

VkPipeline MeshPipeline::pipeline(unsigned k) const {
    if (pipelines_[k] != VK_NULL_HANDLE) return pipelines_[k];
    if (modules_[k] == VK_NULL_HANDLE) { // kept from an earlier call whose pipeline creation failed
        const std::vector<std::uint32_t> code =
            read_words(shader_file(shader_dir_, max_factor_, pass_suffix[k]));
        auto smci = vk_struct<VkShaderModuleCreateInfo>(VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO);
        smci.codeSize = code.size() * 4;
        smci.pCode = code.data();
        check(vkCreateShaderModule(device_, &smci, nullptr, &modules_[k]), "vkCreateShaderModule");
    }
    auto cpci = vk_struct<VkComputePipelineCreateInfo>(VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO);
    cpci.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    cpci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    cpci.stage.module = modules_[k];
    cpci.stage.pName = "main"; // one entry point per GLSL file (docs/shaders.md)
    cpci.layout = pipeline_layout_;
    check(vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &cpci, nullptr, &pipelines_[k]),
          "vkCreateComputePipelines");
    return pipelines_[k];
}

void MeshPipeline::destroy() noexcept {
    if (device_ == VK_NULL_HANDLE) return;
    for (VkPipeline& p : pipelines_) {
        if (p != VK_NULL_HANDLE) vkDestroyPipeline(device_, p, nullptr);
        p = VK_NULL_HANDLE;
    }
    for (VkShaderModule& m : modules_) {
        if (m != VK_NULL_HANDLE) vkDestroyShaderModule(device_, m, nullptr);
        m = VK_NULL_HANDLE;
    }
    if (pipeline_layout_ != VK_NULL_HANDLE) vkDestroyPipelineLayout(device_, pipeline_layout_, nullptr);
    if (set_layout_ != VK_NULL_HANDLE) vkDestroyDescriptorSetLayout(device_, set_layout_, nullptr);
    pipeline_layout_ = VK_NULL_HANDLE;
    set_layout_ = VK_NULL_HANDLE;
}

MeshPipeline::~MeshPipeline() {
    destroy();
}

MeshPipeline::MeshPipeline(MeshPipeline&& other) noexcept {
    *this = std::move(other);
}

MeshPipeline& MeshPipeline::operator=(MeshPipeline&& other) noexcept {
    if (this == &other) return *this;
    destroy();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    max_factor_ = other.max_factor_;
    shader_dir_ = std::move(other.shader_dir_);
    set_layout_ = std::exchange(other.set_layout_, VK_NULL_HANDLE);
    pipeline_layout_ = std::exchange(other.pipeline_layout_, VK_NULL_HANDLE);
    for (unsigned k = 0; k < passes; ++k) {
        modules_[k] = std::exchange(other.modules_[k], VK_NULL_HANDLE);
        pipelines_[k] = std::exchange(other.pipelines_[k], VK_NULL_HANDLE);
    }
    return *this;
}

void MeshPipeline::write_descriptor_set(VkDescriptorSet set,
                                        const VkBuffer (&buffers)[rt::gpu::binding::count]) const {
    VkDescriptorBufferInfo ranges[rt::gpu::binding::count];
    for (std::uint32_t i = 0; i < rt::gpu::binding::count; ++i) ranges[i] = {buffers[i], 0, VK_WHOLE_SIZE};
    write_descriptor_set(set, ranges);
}

void MeshPipeline::write_descriptor_set(
    VkDescriptorSet set, const VkDescriptorBufferInfo (&ranges)[rt::gpu::binding::count]) const {
    VkWriteDescriptorSet writes[rt::gpu::binding::count];
    for (std::uint32_t i = 0; i < rt::gpu::binding::count; ++i) {
        writes[i] = vk_struct<VkWriteDescriptorSet>(VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET);
        writes[i].dstSet = set;
        writes[i].dstBinding = i;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        writes[i].pBufferInfo = &ranges[i];
    }
    vkUpdateDescriptorSets(device_, rt::gpu::binding::count, writes, 0, nullptr);
}

void MeshPipeline::record_counts(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t patch_count,
                                 std::uint32_t max_workgroups) const {
    if (max_workgroups == 0) max_workgroups = 1;
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &set, 0, nullptr);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(0));
    // An empty mesh still runs one setup workgroup (it writes nothing) so the prefix sum's totals are
    // written.
    const std::uint32_t groups = rt::gpu::setup_workgroups(patch_count, max_workgroups);
    vkCmdDispatch(cmd, groups > 0 ? groups : 1, 1, 1);
    compute_barrier(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(1));
    vkCmdDispatch(cmd, 1, 1, 1);
    compute_barrier(cmd);
}

void MeshPipeline::record_emit(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t triangle_patches,
                               std::uint32_t quad_patches, std::uint32_t max_workgroups, bool displaced,
                               bool vector) const {
    if (triangle_patches == 0 && quad_patches == 0) return;
    if (max_workgroups == 0) max_workgroups = 1;
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &set, 0, nullptr);
    compute_barrier(cmd);
    // Vertices, then triangles, of the triangles (passes 2, 3) and of the quads (4, 5); displaced vertices
    // from their own passes (6, 7; vector displacement 8, 9), so that undisplaced meshes run no displacement
    // code and each displaced pass one mode's (docs/shaders.md).
    const std::uint32_t count[2] = {triangle_patches, quad_patches};
    for (unsigned kind = 0; kind < 2; ++kind) {
        if (count[kind] == 0) continue;
        const std::uint32_t groups = rt::gpu::emit_workgroups(count[kind], max_workgroups);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE,
                          pipeline(vertex_pass(kind, displaced, vector)));
        vkCmdDispatch(cmd, groups, 1, 1);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(3 + 2 * kind));
        vkCmdDispatch(cmd, groups, 1, 1);
    }
}

void MeshPipeline::record_split_counts(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t patch_count,
                                       std::uint32_t roots, VkBuffer patches, VkDeviceSize patches_offset,
                                       std::uint32_t max_workgroups) const {
    if (max_workgroups == 0) max_workgroups = 1;
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &set, 0, nullptr);
    const std::uint32_t groups = rt::gpu::setup_workgroups(patch_count, max_workgroups);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(0));
    vkCmdDispatch(cmd, groups > 0 ? groups : 1, 1, 1);
    compute_barrier(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(split_roots_pass));
    vkCmdDispatch(cmd, grid_workgroups(roots, rt::gpu::split_workgroup, max_workgroups), 1, 1);
    indirect_barrier(cmd);
    const VkDeviceSize dispatch =
        patches_offset + 4 * (rt::gpu::split_area_word(patch_count) + rt::gpu::split_word::dispatch);
    // The levels, then the leaves' count and scan: every node at the bound's depth is a leaf. The bound of
    // the deepest shipped table (N = 11: 4), whichever table the shaders were built with: a level past a
    // table's own bound copies its leaves (an extra level costs little; too few would leave split nodes as
    // leaves).
    const std::uint32_t levels = rt::uniform_split_max_depth;
    for (std::uint32_t level = 0; level <= levels; ++level) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(split_count_pass));
        vkCmdDispatchIndirect(cmd, patches, dispatch);
        compute_barrier(cmd);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(split_scan_pass));
        vkCmdDispatch(cmd, 1, 1, 1);
        indirect_barrier(cmd);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE,
                          pipeline(level < levels ? split_expand_pass : split_records_pass));
        vkCmdDispatchIndirect(cmd, patches, dispatch);
        compute_barrier(cmd);
    }
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(1));
    vkCmdDispatch(cmd, 1, 1, 1);
    compute_barrier(cmd);
}

void MeshPipeline::record_split_emit(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t leaves,
                                     bool triangles, bool quads, std::uint32_t max_workgroups, bool displaced,
                                     bool vector) const {
    if (leaves == 0 || (!triangles && !quads)) return;
    if (max_workgroups == 0) max_workgroups = 1;
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &set, 0, nullptr);
    compute_barrier(cmd);
    const std::uint32_t groups = std::min(leaves, max_workgroups);
    // The leaves' base weights first, read by the vertex passes (docs/shaders.md, "Splitting").
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(split_points_pass));
    vkCmdDispatch(cmd, groups, 1, 1);
    compute_barrier(cmd);
    for (unsigned kind = 0; kind < 2; ++kind) {
        if (!(kind == 0 ? triangles : quads)) continue;
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE,
                          pipeline(vertex_pass(kind, displaced, vector)));
        vkCmdDispatch(cmd, groups, 1, 1);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(3 + 2 * kind));
        vkCmdDispatch(cmd, groups, 1, 1);
    }
}

void MeshPipeline::record_weld_counts(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t patch_count,
                                      std::uint32_t edges, std::uint32_t mesh_vertices, std::uint32_t slots,
                                      VkBuffer weld, VkDeviceSize weld_offset,
                                      std::uint32_t max_workgroups) const {
    if (max_workgroups == 0) max_workgroups = 1;
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &set, 0, nullptr);
    compute_barrier(cmd); // after record_counts
    const std::uint32_t group = rt::gpu::emit_workgroup;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(weld_edges_pass));
    vkCmdDispatch(cmd,
                  grid_workgroups(std::max<std::uint64_t>(edges, std::uint64_t{mesh_vertices} + slots), group,
                                  max_workgroups),
                  1, 1);
    compute_barrier(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(weld_edge_scan_pass));
    vkCmdDispatch(cmd, 1, 1, 1);
    compute_barrier(cmd);
    // A patch per workgroup, in batches of at most max_workgroups from the header's first-patch word.
    const VkDeviceSize first_word = weld_offset + 4 * rt::gpu::weld_word::first_patch;
    for (std::uint32_t first = 0; first < patch_count; first += max_workgroups) {
        fill_word(cmd, weld, first_word, first);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(weld_count_pass));
        vkCmdDispatch(cmd, std::min(max_workgroups, patch_count - first), 1, 1);
    }
    compute_barrier(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(weld_writers_pass));
    vkCmdDispatch(cmd, grid_workgroups(slots, group, max_workgroups), 1, 1);
    compute_barrier(cmd);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(weld_scan_pass));
    vkCmdDispatch(cmd, 1, 1, 1);
    compute_barrier(cmd);
}

// The welded output's vertex passes: items[0] workgroups' worth of base triangles (or split leaves), items[1]
// of quads, each slot writing the id it owns.
void MeshPipeline::record_weld_vertices(VkCommandBuffer cmd, const std::array<std::uint32_t, 2>& items,
                                        std::uint32_t max_workgroups, bool displaced, bool vector) const {
    for (unsigned kind = 0; kind < 2; ++kind) {
        if (items[kind] == 0) continue;
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE,
                          pipeline(vertex_pass(kind, displaced, vector)));
        vkCmdDispatch(cmd, rt::gpu::emit_workgroups(items[kind], max_workgroups), 1, 1);
    }
}

void MeshPipeline::record_weld_emit(VkCommandBuffer cmd, VkDescriptorSet set, std::uint32_t first_patch,
                                    std::uint32_t triangle_patches, std::uint32_t quad_patches,
                                    std::uint32_t mesh_vertices, VkBuffer weld, VkDeviceSize weld_offset,
                                    std::uint32_t max_workgroups, bool displaced, bool vector) const {
    if (max_workgroups == 0) max_workgroups = 1;
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &set, 0, nullptr);
    compute_barrier(cmd);
    record_weld_vertices(cmd, {triangle_patches, quad_patches}, max_workgroups, displaced, vector);
    // The triangles a patch per workgroup, in batches from the header's first-patch word (as the count pass).
    const std::uint32_t end = first_patch + triangle_patches + quad_patches;
    for (std::uint32_t first = first_patch; first < end; first += max_workgroups) {
        fill_word(cmd, weld, weld_offset + 4 * rt::gpu::weld_word::first_patch, first);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(weld_triangles_pass));
        vkCmdDispatch(cmd, std::min(max_workgroups, end - first), 1, 1);
    }
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(weld_lone_vertices_pass));
    vkCmdDispatch(cmd, grid_workgroups(mesh_vertices, rt::gpu::emit_workgroup, max_workgroups), 1, 1);
}

void MeshPipeline::record_sorted_weld_counts(VkCommandBuffer cmd, VkDescriptorSet set,
                                             std::uint32_t patch_count, std::uint32_t edges,
                                             std::uint32_t mesh_vertices, std::uint32_t slots,
                                             std::uint32_t triangles, std::uint32_t items, VkBuffer weld,
                                             VkDeviceSize weld_offset, std::uint32_t max_workgroups) const {
    if (max_workgroups == 0) max_workgroups = 1;
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &set, 0, nullptr);
    compute_barrier(cmd); // after record_counts or record_split_counts
    const std::uint32_t group = rt::gpu::emit_workgroup;
    const auto dispatch = [&](unsigned pass, std::uint32_t workgroups) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(pass));
        vkCmdDispatch(cmd, std::max(workgroups, 1u), 1, 1);
        compute_barrier(cmd);
    };
    const auto word = [&](std::uint32_t w, std::uint32_t value) {
        fill_word(cmd, weld, weld_offset + 4 * VkDeviceSize{w}, value);
    };
    dispatch(weld_edges_pass, grid_workgroups(std::max<std::uint64_t>(
                                                  {edges, patch_count, std::uint64_t{mesh_vertices} + slots}),
                                              group, max_workgroups));
    const std::uint64_t records = rt::gpu::weld_sort_records(slots, triangles);
    dispatch(weld_keys_pass, std::max(std::min(items, max_workgroups),
                                      grid_workgroups(records - slots, group, max_workgroups)));
    // The bitonic network: the stages up to a chunk in workgroup memory, then each larger stage's steps of a
    // chunk or more over binding 7 and the rest in workgroup memory again.
    const std::uint32_t chunks =
        grid_workgroups(records, rt::gpu::weld_sort_chunk, max_workgroups); // the last one padded
    word(rt::gpu::weld_word::sort_stage, 0);
    dispatch(weld_sort_local_pass, chunks);
    const std::uint64_t width = rt::gpu::weld_sort_width(records);
    for (std::uint64_t stage = 2 * std::uint64_t{rt::gpu::weld_sort_chunk}; stage <= width; stage *= 2) {
        word(rt::gpu::weld_word::sort_stage, static_cast<std::uint32_t>(stage));
        for (std::uint64_t step = stage / 2; step >= rt::gpu::weld_sort_chunk; step /= 2) {
            word(rt::gpu::weld_word::sort_step, static_cast<std::uint32_t>(step));
            dispatch(weld_sort_step_pass, grid_workgroups(records, group, max_workgroups));
        }
        dispatch(weld_sort_local_pass, chunks);
    }
    const auto rank = [&](std::uint32_t mode, std::uint64_t ranked) {
        word(rt::gpu::weld_word::rank_mode, mode);
        const std::uint32_t blocks = grid_workgroups(ranked, rt::gpu::weld_rank_block, max_workgroups);
        dispatch(weld_rank_blocks_pass, blocks);
        dispatch(weld_rank_scan_pass, 1);
        dispatch(weld_rank_write_pass, blocks);
    };
    rank(rt::gpu::weld_rank_mode::keys, records);
    dispatch(weld_keep_pass, std::min(items, max_workgroups));
    rank(rt::gpu::weld_rank_mode::triangles, triangles);
    dispatch(weld_owner_counts_pass,
             grid_workgroups(std::max<std::uint64_t>(edges, patch_count), group, max_workgroups));
    dispatch(weld_edge_scan_pass, 1);
    dispatch(weld_scan_pass, 1);
    dispatch(weld_writers_pass, grid_workgroups(slots, group, max_workgroups));
}

void MeshPipeline::record_sorted_weld_emit(VkCommandBuffer cmd, VkDescriptorSet set,
                                           std::uint32_t triangle_items, std::uint32_t quad_items,
                                           std::uint32_t mesh_vertices, std::uint32_t max_workgroups,
                                           bool displaced, bool vector) const {
    if (max_workgroups == 0) max_workgroups = 1;
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &set, 0, nullptr);
    compute_barrier(cmd);
    record_weld_vertices(cmd, {triangle_items, quad_items}, max_workgroups, displaced, vector);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(weld_sorted_triangles_pass));
    vkCmdDispatch(cmd, std::max(std::min(triangle_items + quad_items, max_workgroups), 1u), 1, 1);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline(weld_lone_vertices_pass));
    vkCmdDispatch(cmd, grid_workgroups(mesh_vertices, rt::gpu::emit_workgroup, max_workgroups), 1, 1);
}

// ---- Runner ----

struct Runner::Device {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    std::uint32_t queue_family = 0;
    VkCommandPool command_pool = VK_NULL_HANDLE;
    VkDescriptorPool descriptor_pool = VK_NULL_HANDLE;
    std::string name;
    VkPhysicalDeviceLimits limits{};
    std::unique_ptr<MeshPipeline> pipeline;
    std::vector<std::uint32_t> tables[2]; // CP blob, uniform blob (loaded on first use)

    struct Buffer {
        VkBuffer buffer = VK_NULL_HANDLE;
        VkDeviceMemory memory = VK_NULL_HANDLE;
        void* mapped = nullptr;
    };

    Device() {
        try {
            init();
        } catch (...) {
            release(); // a constructor that throws runs no destructor
            throw;
        }
    }

    void init() {
        auto app = vk_struct<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
        app.pApplicationName = "ctess";
        app.apiVersion = VK_API_VERSION_1_1;
        auto ici = vk_struct<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
        ici.pApplicationInfo = &app;
        check(vkCreateInstance(&ici, nullptr, &instance),
              "vkCreateInstance (no Vulkan driver? Debian: mesa-vulkan-drivers)");
        std::uint32_t count = 0;
        check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
        if (count == 0) throw Error("no Vulkan device (Debian's mesa-vulkan-drivers gives lavapipe)");
        std::vector<VkPhysicalDevice> devices(count);
        check(vkEnumeratePhysicalDevices(instance, &count, devices.data()), "vkEnumeratePhysicalDevices");
        queue_family = UINT32_MAX;
        for (VkPhysicalDevice candidate : devices) {
            std::uint32_t families = 0;
            vkGetPhysicalDeviceQueueFamilyProperties(candidate, &families, nullptr);
            std::vector<VkQueueFamilyProperties> qf(families);
            vkGetPhysicalDeviceQueueFamilyProperties(candidate, &families, qf.data());
            for (std::uint32_t i = 0; i < families && queue_family == UINT32_MAX; ++i) {
                if (qf[i].queueFlags & VK_QUEUE_COMPUTE_BIT) {
                    physical = candidate;
                    queue_family = i;
                }
            }
            if (queue_family != UINT32_MAX) break;
        }
        if (queue_family == UINT32_MAX) throw Error("no Vulkan device with a compute queue");
        VkPhysicalDeviceProperties props;
        vkGetPhysicalDeviceProperties(physical, &props);
        name = props.deviceName;
        limits = props.limits;
        const float priority = 1.0f;
        auto qci = vk_struct<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
        qci.queueFamilyIndex = queue_family;
        qci.queueCount = 1;
        qci.pQueuePriorities = &priority;
        auto dci = vk_struct<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO);
        dci.queueCreateInfoCount = 1;
        dci.pQueueCreateInfos = &qci;
        check(vkCreateDevice(physical, &dci, nullptr, &device), "vkCreateDevice");
        vkGetDeviceQueue(device, queue_family, 0, &queue);
        auto cp = vk_struct<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
        cp.queueFamilyIndex = queue_family;
        check(vkCreateCommandPool(device, &cp, nullptr, &command_pool), "vkCreateCommandPool");
        VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3 * rt::gpu::binding::count};
        auto dpci = vk_struct<VkDescriptorPoolCreateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO);
        dpci.maxSets = 3; // counts, weld counts, emit
        dpci.poolSizeCount = 1;
        dpci.pPoolSizes = &size;
        check(vkCreateDescriptorPool(device, &dpci, nullptr, &descriptor_pool), "vkCreateDescriptorPool");
    }

    ~Device() { release(); }

    void release() noexcept {
        pipeline.reset();
        if (device != VK_NULL_HANDLE) {
            vkDeviceWaitIdle(device);
            if (descriptor_pool != VK_NULL_HANDLE) vkDestroyDescriptorPool(device, descriptor_pool, nullptr);
            if (command_pool != VK_NULL_HANDLE) vkDestroyCommandPool(device, command_pool, nullptr);
            vkDestroyDevice(device, nullptr);
        }
        if (instance != VK_NULL_HANDLE) vkDestroyInstance(instance, nullptr);
        device = VK_NULL_HANDLE;
        instance = VK_NULL_HANDLE;
    }

    // A zero-filled host-visible, host-coherent storage buffer of at least 16 bytes.
    Buffer create_buffer(std::uint64_t bytes) {
        Buffer b;
        bytes = bytes < 16 ? 16 : bytes;
        // Every buffer is one whole storage binding: the device's range limit (2^27 bytes guaranteed).
        if (bytes > limits.maxStorageBufferRange)
            throw Error("a binding of " + std::to_string(bytes) +
                        " bytes is past this device's maxStorageBufferRange (" +
                        std::to_string(limits.maxStorageBufferRange) + ")");
        auto bci = vk_struct<VkBufferCreateInfo>(VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO);
        bci.size = bytes;
        bci.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                    VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        bci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
        check(vkCreateBuffer(device, &bci, nullptr, &b.buffer), "vkCreateBuffer");
        VkMemoryRequirements req;
        vkGetBufferMemoryRequirements(device, b.buffer, &req);
        VkPhysicalDeviceMemoryProperties mp;
        vkGetPhysicalDeviceMemoryProperties(physical, &mp);
        const VkMemoryPropertyFlags want =
            VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        std::uint32_t type = UINT32_MAX;
        for (std::uint32_t i = 0; i < mp.memoryTypeCount && type == UINT32_MAX; ++i)
            if ((req.memoryTypeBits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want)
                type = i;
        if (type == UINT32_MAX) {
            vkDestroyBuffer(device, b.buffer, nullptr);
            throw Error("no host-visible, host-coherent memory type");
        }
        auto mai = vk_struct<VkMemoryAllocateInfo>(VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO);
        mai.allocationSize = req.size;
        mai.memoryTypeIndex = type;
        if (const VkResult r = vkAllocateMemory(device, &mai, nullptr, &b.memory); r != VK_SUCCESS) {
            vkDestroyBuffer(device, b.buffer, nullptr);
            check(r, "vkAllocateMemory");
        }
        VkResult r = vkBindBufferMemory(device, b.buffer, b.memory, 0);
        if (r == VK_SUCCESS) r = vkMapMemory(device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped);
        if (r != VK_SUCCESS) {
            destroy(b);
            check(r, "vkBindBufferMemory / vkMapMemory");
        }
        std::memset(b.mapped, 0, static_cast<std::size_t>(bytes));
        return b;
    }

    void destroy(Buffer& b) noexcept {
        if (b.buffer != VK_NULL_HANDLE) vkDestroyBuffer(device, b.buffer, nullptr);
        if (b.memory != VK_NULL_HANDLE) vkFreeMemory(device, b.memory, nullptr);
        b = {};
    }

    // Records what `record` records into a one-time command buffer, submits it and waits; milliseconds.
    template <class Record>
    double submit(Record&& record) {
        auto cbai = vk_struct<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
        cbai.commandPool = command_pool;
        cbai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        cbai.commandBufferCount = 1;
        VkCommandBuffer cmd;
        check(vkAllocateCommandBuffers(device, &cbai, &cmd), "vkAllocateCommandBuffers");
        VkFence fence = VK_NULL_HANDLE;
        try {
            auto begin = vk_struct<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
            begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
            check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
            record(cmd);
            auto host = vk_struct<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
            host.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
            host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
            vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                                 &host, 0, nullptr, 0, nullptr);
            check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
            auto fci = vk_struct<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
            check(vkCreateFence(device, &fci, nullptr, &fence), "vkCreateFence");
            auto si = vk_struct<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
            si.commandBufferCount = 1;
            si.pCommandBuffers = &cmd;
            const auto start = std::chrono::steady_clock::now();
            check(vkQueueSubmit(queue, 1, &si, fence), "vkQueueSubmit");
            check(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
            const auto stop = std::chrono::steady_clock::now();
            vkDestroyFence(device, fence, nullptr);
            vkFreeCommandBuffers(device, command_pool, 1, &cmd);
            return std::chrono::duration<double, std::milli>(stop - start).count();
        } catch (...) {
            if (fence != VK_NULL_HANDLE) vkDestroyFence(device, fence, nullptr);
            vkDeviceWaitIdle(device);
            vkFreeCommandBuffers(device, command_pool, 1, &cmd);
            throw;
        }
    }
};

Runner::Runner(const std::string& shader_dir, unsigned max_factor, MeshPipeline::Creation creation)
    : device_(std::make_unique<Device>()), shader_dir_(shader_dir), max_factor_(max_factor) {
    device_->pipeline = std::make_unique<MeshPipeline>(device_->device, shader_dir, max_factor, creation);
}

Runner::~Runner() = default;

std::string Runner::device_name() const {
    return device_->name;
}

Output Runner::tessellate(const rt::MeshView& mesh, const rt::PipelineOptions& options, RunOptions run) {
    if (const rt::PipelineStatus st = rt::gpu::gpu_options_status(mesh, options);
        st != rt::PipelineStatus::ok) {
        throw Error(
            st == rt::PipelineStatus::bad_option
                ? "the shaders run the cp or uniform pattern and camera factors, without position_ids, and "
                  "displace by a valid height or vector map only (not a HeightFunction or VectorFunction) "
                  "(docs/shaders.md, \"Hosts\")"
                : rt::pipeline_status_message(st));
    }
    return tessellate(mesh, rt::gpu::pipeline_params(mesh, options), run, options.displacement);
}

Output Runner::tessellate(const rt::MeshView& mesh,
                          const std::array<std::uint32_t, rt::gpu::param_word::words>& params, RunOptions run,
                          const rt::Displacement* displacement) {
    if ((params[rt::gpu::param_word::weld] & rt::gpu::weld_flag::on) != 0)
        throw Error("the params weld: run them with tessellate_welded");
    return run_pipeline(mesh, params, run, displacement, nullptr);
}

WeldedOutput Runner::tessellate_welded(const rt::MeshView& mesh, const rt::PipelineOptions& options,
                                       RunOptions run) {
    if (const rt::PipelineStatus st = rt::gpu::gpu_weld_status(mesh, options); st != rt::PipelineStatus::ok) {
        throw Error(st == rt::PipelineStatus::bad_option
                        ? "the shaders weld the cp, uniform and uniform_split patterns with camera "
                          "factors, without position_ids, displacing by a valid height or vector map only "
                          "(docs/shaders.md, \"Welded output\")"
                        : rt::pipeline_status_message(st));
    }
    run.counts_only = false;
    WeldedOutput welded;
    run_pipeline(mesh, rt::gpu::weld_params(mesh, options), run, options.displacement, &welded);
    return welded;
}

Output Runner::run_pipeline(const rt::MeshView& mesh,
                            const std::array<std::uint32_t, rt::gpu::param_word::words>& params,
                            RunOptions run, const rt::Displacement* displacement, WeldedOutput* welded) {
    namespace pw = rt::gpu::param_word;
    namespace flag = rt::gpu::displacement_flag;
    const std::uint32_t n = params[pw::patch_count];
    const std::uint32_t quads = params[pw::quad_count];
    // Displacement (docs/shaders.md, "Displacement"): the params must describe the data given.
    const std::uint32_t disp = params[pw::displacement_flags];
    const bool displace = (disp & flag::on) != 0;
    const bool vector = displace && (disp & flag::vector) != 0;
    const std::uint64_t texel_count =
        std::uint64_t{params[pw::height_map_width]} * params[pw::height_map_height];
    if (displace) {
        if (displacement == nullptr) throw Error("the params displace but no rt::Displacement is given");
        if (displacement->function != nullptr)
            throw Error("a HeightFunction is CPU code: the shaders displace by a height map only");
        if (displacement->vector_function != nullptr)
            throw Error("a VectorFunction is CPU code: the shaders displace by a vector map only");
        if (!rt::displacement_valid(*displacement))
            throw Error(
                "the Displacement is not valid (rt::displacement_valid: finite numbers, factor_bound >= 0, "
                "normal_step in (0, 0.5], a map of the mode's channels, tangents in vector mode)");
        // Vector mode (docs/algorithm.md §8.7) reads RGB texels and tangents: the params' flag must say so.
        if (vector != (displacement->mode == rt::DisplacementMode::vector))
            throw Error(vector ? "the params name vector displacement but the Displacement is scalar"
                               : "the Displacement is vector mode but the params lack its flag "
                                 "(rt::gpu::displacement_flag::vector)");
        const rt::HeightMap& map = displacement->map;
        const bool empty = map.texels == nullptr || map.width == 0 || map.height == 0;
        if ((empty ? 0 : std::uint64_t{map.width} * map.height) != texel_count)
            throw Error("the height map's texel count (" + std::to_string(map.width) + " x " +
                        std::to_string(map.height) + ") does not match the params' width x height (" +
                        std::to_string(params[pw::height_map_width]) + " x " +
                        std::to_string(params[pw::height_map_height]) + ")");
        if ((disp & flag::directions) != 0 && displacement->directions == nullptr)
            throw Error("the params name displacement directions but Displacement::directions is null");
        if ((disp & flag::adjacency) != 0 && mesh.adjacency == nullptr)
            throw Error("the params name an adjacency but MeshView::adjacency is null");
    }
    if (quads > n || quads > mesh.quad_count || n - quads > mesh.triangle_count ||
        params[pw::mesh_vertex_count] > mesh.vertex_count)
        throw Error("the params name more triangles, quads or mesh vertices than the mesh has");
    if (params[pw::first_patch] > params[pw::end_patch] || params[pw::end_patch] > n)
        throw Error("the params' emit range [first, end) is not inside [0, patch count]");
    if (const rt::PipelineStatus st = rt::check_pipeline_size(n, 0, 0); st != rt::PipelineStatus::ok)
        throw Error(rt::pipeline_status_message(st));
    const bool split = params[pw::pattern] == static_cast<std::uint32_t>(rt::Pattern::uniform_split);
    const bool uniform = split || params[pw::pattern] == static_cast<std::uint32_t>(rt::Pattern::uniform);
    std::vector<std::uint32_t>& tables = device_->tables[uniform ? 1 : 0];
    if (tables.empty())
        tables = load_table_blob(shader_dir_, max_factor_, uniform ? rt::Pattern::uniform : rt::Pattern::cp);

    Device& d = *device_;
    run.max_workgroups = std::min(run.max_workgroups, d.limits.maxComputeWorkGroupCount[0]);
    std::vector<Device::Buffer> owned;
    struct Release { // frees every buffer and the descriptor sets on every path out
        Device& d;
        std::vector<Device::Buffer>& owned;
        ~Release() {
            for (Device::Buffer& b : owned) d.destroy(b);
            vkResetDescriptorPool(d.device, d.descriptor_pool, 0);
        }
    } release{d, owned};
    owned.reserve(16); // make() never reallocates, so a created buffer is always owned
    const auto make = [&](std::uint64_t bytes, const void* data, std::size_t data_bytes) {
        owned.push_back(d.create_buffer(bytes));
        if (data_bytes != 0) std::memcpy(owned.back().mapped, data, data_bytes);
        return owned.back();
    };
    // Binding 3 (sized and checked before any buffer is made): the triangles' 3 indices each, the quads' 4,
    // then for PN-AEN (and for displacement, when its flag says so) the adjacency's 12 per face triangle
    // (docs/shaders.md, "PN-AEN"; without it every edge is a boundary, as on the CPU), then with displacement
    // the texels.
    const bool aen =
        displace ? (disp & flag::adjacency) != 0
                 : params[pw::surface] == static_cast<std::uint32_t>(rt::Surface::pn_aen) && mesh.adjacency;
    const std::size_t triangle_bytes = std::size_t{n - quads} * 12, quad_bytes = std::size_t{quads} * 16;
    const std::size_t adjacency_bytes = aen ? (std::size_t{n - quads} + 2 * std::size_t{quads}) * 48 : 0;
    const std::uint64_t texel_bytes =
        displace ? 4 * std::uint64_t{rt::gpu::texel_floats(*displacement)} * texel_count : 0;
    const std::uint64_t index_binding = triangle_bytes + quad_bytes + adjacency_bytes + texel_bytes;
    if (index_binding > d.limits.maxStorageBufferRange)
        throw Error("binding 3 (indices, adjacency and " + std::to_string(displace ? texel_count : 0) +
                    (vector ? " RGB" : " height-map") + " texels) would be " + std::to_string(index_binding) +
                    " bytes, past this device's maxStorageBufferRange (" +
                    std::to_string(d.limits.maxStorageBufferRange) + ")");
    // Binding 2: the mesh vertices, then with displacement directions (3 floats per vertex) and in vector
    // mode tangents (4 per vertex) for the params' vertex count, from vertex word params' vertex count x 8 on
    // (vertices past that count are never read).
    const std::size_t vertex_bytes = std::size_t{mesh.vertex_count} * rt::mesh_vertex_floats * 4;
    const std::size_t frame_vertices = params[pw::mesh_vertex_count];
    const bool directions = displace && (disp & flag::directions) != 0;
    const std::size_t direction_bytes = directions ? frame_vertices * 12 : 0;
    const std::size_t tangent_bytes = vector ? frame_vertices * 16 : 0;
    const std::size_t frame_at = frame_vertices * rt::mesh_vertex_floats * 4;
    const std::uint64_t vertex_binding =
        std::max<std::uint64_t>(vertex_bytes, frame_at + direction_bytes + tangent_bytes);
    if (vertex_binding > d.limits.maxStorageBufferRange)
        throw Error("binding 2 (mesh vertices, directions and tangents) would be " +
                    std::to_string(vertex_binding) + " bytes, past this device's maxStorageBufferRange (" +
                    std::to_string(d.limits.maxStorageBufferRange) + ")");
    // Split (docs/shaders.md, "Splitting"): the regions' nodes, from the run's or a default of at least
    // 65,536 and the roots; the params' capacity word is the Runner's.
    const std::uint32_t roots = static_cast<std::uint32_t>(rt::gpu::split_roots(n - quads, quads));
    std::uint32_t capacity = 0;
    if (split) { // a default start never above the run's limit; at least the roots
        capacity = run.split_capacity != 0 ? run.split_capacity : 65536u;
        if (run.split_capacity == 0 && run.max_split_capacity != 0)
            capacity = std::min(capacity, run.max_split_capacity);
        capacity = std::max(capacity, std::max(roots, 1u));
    }
    const Device::Buffer b_params = make(sizeof params, params.data(), sizeof params);
    const Device::Buffer b_tables = make(tables.size() * 4, tables.data(), tables.size() * 4);
    const Device::Buffer b_mesh = make(vertex_binding, mesh.vertices, vertex_bytes);
    if (directions)
        std::memcpy(static_cast<char*>(b_mesh.mapped) + frame_at, displacement->directions, direction_bytes);
    if (vector)
        std::memcpy(static_cast<char*>(b_mesh.mapped) + frame_at + direction_bytes, displacement->tangents,
                    tangent_bytes);
    const Device::Buffer b_indices = make(index_binding, mesh.indices, triangle_bytes);
    auto* index_bytes = static_cast<char*>(b_indices.mapped);
    if (quad_bytes != 0) std::memcpy(index_bytes + triangle_bytes, mesh.quad_indices, quad_bytes);
    if (texel_bytes != 0)
        std::memcpy(index_bytes + triangle_bytes + quad_bytes + adjacency_bytes, displacement->map.texels,
                    static_cast<std::size_t>(texel_bytes));
    if (aen) {
        // The first n - quads triangles' blocks, then the quads' (after all mesh.triangle_count triangles').
        std::memcpy(index_bytes + triangle_bytes + quad_bytes, mesh.adjacency, std::size_t{n - quads} * 48);
        std::memcpy(index_bytes + triangle_bytes + quad_bytes + std::size_t{n - quads} * 48,
                    mesh.adjacency + std::size_t{mesh.triangle_count} * 12, std::size_t{quads} * 96);
    }
    const Device::Buffer b_none = make(16, nullptr, 0);
    Device::Buffer b_patches;
    // The split area's words for a capacity, refused past the device's range with what the run needed.
    const auto split_words = [&](std::uint64_t nodes) {
        const std::uint64_t words = rt::gpu::split_buffer_words(n, nodes);
        if (words * 4 > d.limits.maxStorageBufferRange)
            throw Error("splitting needs " + std::to_string(nodes) +
                        " nodes per region: binding 4 would be " + std::to_string(words * 4) +
                        " bytes, past this device's maxStorageBufferRange (" +
                        std::to_string(d.limits.maxStorageBufferRange) + ")");
        if (run.max_split_capacity != 0 && nodes > run.max_split_capacity)
            throw Error("splitting needs " + std::to_string(nodes) +
                        " nodes per region, past the run's max_split_capacity (" +
                        std::to_string(run.max_split_capacity) + ")");
        return words;
    };

    const auto descriptor_set = [&](VkBuffer vertices, VkBuffer indices, VkBuffer weld) {
        VkDescriptorSetLayout layout = d.pipeline->set_layout();
        auto dsai = vk_struct<VkDescriptorSetAllocateInfo>(VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO);
        dsai.descriptorPool = d.descriptor_pool;
        dsai.descriptorSetCount = 1;
        dsai.pSetLayouts = &layout;
        VkDescriptorSet set;
        check(vkAllocateDescriptorSets(d.device, &dsai, &set), "vkAllocateDescriptorSets");
        const VkBuffer buffers[rt::gpu::binding::count] = {
            b_params.buffer,  b_tables.buffer, b_mesh.buffer, b_indices.buffer,
            b_patches.buffer, vertices,        indices,       weld};
        d.pipeline->write_descriptor_set(set, buffers);
        return set;
    };

    Output out;
    const std::uint32_t* words = nullptr;
    for (;;) { // once, or again with larger split regions until the levels fit them
        const std::uint64_t patch_words = split ? split_words(capacity) : rt::gpu::patch_buffer_words(n);
        b_patches = make(patch_words * 4, nullptr, 0);
        static_cast<std::uint32_t*>(b_params.mapped)[pw::split_capacity] = capacity;
        const VkDescriptorSet counts_set = descriptor_set(b_none.buffer, b_none.buffer, b_none.buffer);
        const double ms = d.submit([&](VkCommandBuffer cmd) {
            if (split)
                d.pipeline->record_split_counts(cmd, counts_set, n, roots, b_patches.buffer, 0,
                                                run.max_workgroups);
            else
                d.pipeline->record_counts(cmd, counts_set, n, run.max_workgroups);
        });
        out.counts_milliseconds += ms;
        words = static_cast<const std::uint32_t*>(b_patches.mapped);
        if (!split) break;
        const std::uint32_t* header = words + rt::gpu::split_area_word(n);
        if (header[rt::gpu::split_word::overflow] == 0) {
            out.split_leaves = header[rt::gpu::split_word::parents];
            out.split_capacity = capacity;
            break;
        }
        // A level asked for more nodes than a region holds: grow to what it asked, at least twice (a deeper
        // level may ask for more again), within the device's range, and run the levels again.
        std::uint64_t grown = std::max<std::uint64_t>(header[rt::gpu::split_word::needed], 2ull * capacity);
        if (run.max_split_capacity != 0 && grown > run.max_split_capacity &&
            capacity < run.max_split_capacity)
            grown = std::max<std::uint64_t>(run.max_split_capacity, header[rt::gpu::split_word::needed]);
        split_words(grown); // throws past the device's range or the run's limit
        capacity = static_cast<std::uint32_t>(grown);
        owned.pop_back(); // b_patches, the last buffer made
        d.destroy(b_patches);
        vkResetDescriptorPool(d.device, d.descriptor_pool, 0);
    }
    out.milliseconds = out.counts_milliseconds;
    out.patches.resize(n);
    if (n != 0)
        std::memcpy(static_cast<void*>(out.patches.data()), words, std::size_t{n} * sizeof(rt::PatchRecord));
    // The shader's u32 totals wrap past 2^32 (it then writes the overflow marker): recount them in 64 bits
    // and refuse a mesh past the pipeline's limits before sizing the outputs, as the CPU pipeline does.
    std::uint64_t sum_v = 0, sum_t = 0;
    for (const rt::PatchRecord& r : out.patches) {
        sum_v += r.vertex_count;
        sum_t += r.triangle_count;
    }
    if (run.counts_only) {
        out.totals.vertices = words[std::size_t{n} * rt::gpu::patch_words];
        out.totals.triangles = words[std::size_t{n} * rt::gpu::patch_words + 1];
        return out;
    }
    if (const rt::PipelineStatus st = rt::check_pipeline_size(n, sum_v, sum_t); st != rt::PipelineStatus::ok)
        throw Error(rt::pipeline_status_message(st));
    out.totals.vertices = words[std::size_t{n} * rt::gpu::patch_words];
    out.totals.triangles = words[std::size_t{n} * rt::gpu::patch_words + 1];
    if (out.totals.vertices != sum_v || out.totals.triangles != sum_t)
        throw Error("the prefix sum's totals differ from the records' counts");
    // The emit range [first, end) split at the first quad.
    const std::uint32_t first = params[pw::first_patch], end = params[pw::end_patch], triangles = n - quads;
    const std::uint32_t triangle_end = std::min(end, triangles), quad_first = std::max(first, triangles);
    const std::uint32_t triangle_patches = triangle_end > first ? triangle_end - first : 0,
                        quad_patches = end > quad_first ? end - quad_first : 0;
    if (welded != nullptr) {
        // The weld (docs/shaders.md, "Welded output"): binding 7 with the mesh's edge list, then the weld's
        // counting passes, then the outputs at the welded totals. A patch's weld runs in one workgroup up to
        // weld_max_patch_slots slots (past it a software driver's loop limit could cut its sort short); the
        // split pattern, and a mesh with a larger patch, are welded by one sort over the mesh.
        bool sorted = split;
        for (std::uint32_t p = 0; p < n && !sorted; ++p)
            sorted = out.patches[p].vertex_count > rt::gpu::weld_max_patch_slots;
        if (sorted) static_cast<std::uint32_t*>(b_params.mapped)[pw::weld] |= rt::gpu::weld_flag::sorted;
        std::vector<rt::WeldedEdge> edges(rt::weld_edge_capacity(mesh));
        const std::uint32_t edge_count = rt::weld_edge_list(mesh, edges);
        const std::uint32_t mesh_vertices = params[pw::mesh_vertex_count];
        const std::uint64_t weld_words =
            sorted ? rt::gpu::weld_sorted_buffer_words(edge_count, n, mesh_vertices, out.totals.vertices,
                                                       out.totals.triangles)
                   : rt::gpu::weld_buffer_words(edge_count, n, mesh_vertices, out.totals.vertices);
        if (weld_words * 4 > d.limits.maxStorageBufferRange)
            throw Error("the weld's binding 7 would be " + std::to_string(weld_words * 4) +
                        " bytes, past this device's maxStorageBufferRange (" +
                        std::to_string(d.limits.maxStorageBufferRange) + ")");
        const Device::Buffer b_weld = make(weld_words * 4, nullptr, 0);
        auto* weld = static_cast<std::uint32_t*>(b_weld.mapped);
        weld[rt::gpu::weld_word::edges] = edge_count;
        weld[rt::gpu::weld_word::slots] = out.totals.vertices;
        weld[rt::gpu::weld_word::sort_records] =
            static_cast<std::uint32_t>(rt::gpu::weld_sort_records(out.totals.vertices, out.totals.triangles));
        if (edge_count != 0)
            std::memcpy(weld + rt::gpu::weld_word::header_words, edges.data(),
                        edge_count * sizeof(rt::WeldedEdge));
        const VkDescriptorSet weld_set = descriptor_set(b_none.buffer, b_none.buffer, b_weld.buffer);
        const double weld_ms = d.submit([&](VkCommandBuffer cmd) {
            if (sorted)
                d.pipeline->record_sorted_weld_counts(
                    cmd, weld_set, n, edge_count, mesh_vertices, out.totals.vertices, out.totals.triangles,
                    split ? out.split_leaves : n, b_weld.buffer, 0, run.max_workgroups);
            else
                d.pipeline->record_weld_counts(cmd, weld_set, n, edge_count, mesh_vertices,
                                               out.totals.vertices, b_weld.buffer, 0, run.max_workgroups);
        });
        welded->counts_milliseconds = out.counts_milliseconds + weld_ms;
        if ((weld[rt::gpu::weld_word::status] & rt::gpu::weld_status::missing_edge) != 0)
            throw Error("the weld met a patch edge missing from the edge list");
        const auto* weld_edges =
            reinterpret_cast<const rt::WeldedEdge*>(weld + rt::gpu::weld_word::header_words);
        const auto* weld_patches = reinterpret_cast<const rt::WeldedPatch*>(weld_edges + edge_count);
        welded->edges.assign(weld_edges, weld_edges + edge_count);
        welded->patches.assign(weld_patches, weld_patches + n);
        // Recounted in 64 bits, as the CPU's setup_welded adds them up.
        std::uint64_t weld_v = mesh_vertices, weld_t = 0;
        for (const rt::WeldedEdge& e : welded->edges) weld_v += e.vertex_count;
        for (const rt::WeldedPatch& wp : welded->patches) {
            weld_v += wp.vertex_count;
            weld_t += wp.triangle_count;
        }
        if (const rt::PipelineStatus st = rt::check_pipeline_size(n, weld_v, weld_t);
            st != rt::PipelineStatus::ok)
            throw Error(rt::pipeline_status_message(st));
        if ((weld[rt::gpu::weld_word::status] & rt::gpu::weld_status::overflow) != 0 ||
            weld[rt::gpu::weld_word::vertices] != weld_v || weld[rt::gpu::weld_word::triangles] != weld_t)
            throw Error("the weld's prefix sums differ from its records' counts");
        welded->totals = {static_cast<std::uint32_t>(weld_v), static_cast<std::uint32_t>(weld_t), edge_count,
                          0};
        const Device::Buffer b_vertices = make(weld_v * sizeof(rt::TessVertex), nullptr, 0);
        const Device::Buffer b_out_indices = make(weld_t * 12, nullptr, 0);
        const VkDescriptorSet emit_set =
            descriptor_set(b_vertices.buffer, b_out_indices.buffer, b_weld.buffer);
        const double emit_ms = d.submit([&](VkCommandBuffer cmd) {
            if (sorted)
                d.pipeline->record_sorted_weld_emit(
                    cmd, emit_set, split ? (triangle_patches != 0 ? out.split_leaves : 0) : triangle_patches,
                    split ? (quad_patches != 0 ? out.split_leaves : 0) : quad_patches, mesh_vertices,
                    run.max_workgroups, displace, vector);
            else
                d.pipeline->record_weld_emit(cmd, emit_set, first, triangle_patches, quad_patches,
                                             mesh_vertices, b_weld.buffer, 0, run.max_workgroups, displace,
                                             vector);
        });
        welded->milliseconds = welded->counts_milliseconds + emit_ms;
        welded->vertices.resize(static_cast<std::size_t>(weld_v));
        if (weld_v != 0)
            std::memcpy(static_cast<void*>(welded->vertices.data()), b_vertices.mapped,
                        welded->vertices.size() * sizeof(rt::TessVertex));
        welded->indices.resize(static_cast<std::size_t>(weld_t) * 3);
        if (weld_t != 0)
            std::memcpy(welded->indices.data(), b_out_indices.mapped, welded->indices.size() * 4);
        return out;
    }

    const Device::Buffer b_vertices =
        make(std::uint64_t{out.totals.vertices} * sizeof(rt::TessVertex), nullptr, 0);
    const Device::Buffer b_out_indices = make(std::uint64_t{out.totals.triangles} * 12, nullptr, 0);
    const VkDescriptorSet emit_set = descriptor_set(b_vertices.buffer, b_out_indices.buffer, b_none.buffer);
    out.milliseconds += d.submit([&](VkCommandBuffer cmd) {
        if (split)
            d.pipeline->record_split_emit(cmd, emit_set, out.split_leaves, triangle_patches != 0,
                                          quad_patches != 0, run.max_workgroups, displace, vector);
        else
            d.pipeline->record_emit(cmd, emit_set, triangle_patches, quad_patches, run.max_workgroups,
                                    displace, vector);
    });
    out.vertices.resize(out.totals.vertices);
    if (!out.vertices.empty())
        std::memcpy(static_cast<void*>(out.vertices.data()), b_vertices.mapped,
                    out.vertices.size() * sizeof(rt::TessVertex));
    out.indices.resize(std::size_t{out.totals.triangles} * 3);
    if (!out.indices.empty()) std::memcpy(out.indices.data(), b_out_indices.mapped, out.indices.size() * 4);
    return out;
}

} // namespace ctess::vulkan
