// A small Vulkan compute host for the GPU tests: one device (lavapipe in ctest, VK_DRIVER_FILES),
// host-visible storage buffers, compute pipelines from SPIR-V files with the ctess pipeline's descriptor
// layout (bindings 0..6 of set 0, all storage buffers), and a submit-and-wait of a list of dispatches with
// barriers between them. Errors throw std::runtime_error with the failing call, so a missing driver fails the
// test.
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace ctess::gpu_test {

// A whole file as little-endian u32 words (SPIR-V, table blobs, results); throws if it cannot be read.
std::vector<std::uint32_t> read_words(const std::string& path);

class VkCompute {
  public:
    static constexpr std::uint32_t bindings = 7;

    VkCompute();
    ~VkCompute();
    VkCompute(const VkCompute&) = delete;
    VkCompute& operator=(const VkCompute&) = delete;

    std::string device_name() const { return device_name_; }

    struct Buffer {
        VkBuffer buffer = VK_NULL_HANDLE;
        VkDeviceMemory memory = VK_NULL_HANDLE;
        void* mapped = nullptr;
        std::size_t bytes = 0;
    };
    // A zero-filled host-visible, host-coherent storage buffer (at least 16 bytes).
    std::size_t create_buffer(std::size_t bytes);
    void upload(std::size_t buffer, const void* data, std::size_t bytes);
    const void* mapped(std::size_t buffer) const { return buffers_.at(buffer).mapped; }

    std::size_t create_pipeline(const std::string& spirv_path);

    struct Dispatch {
        std::size_t pipeline;
        std::uint32_t groups;
    };
    // Binds buffers[0..6] to bindings 0..6, runs the dispatches in order with a compute barrier between them,
    // waits, and returns the wall time from submit to the fence in milliseconds.
    double run(std::span<const std::size_t> buffers, std::span<const Dispatch> dispatches);

  private:
    VkInstance instance_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    std::uint32_t queue_family_ = 0;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
    VkCommandPool command_pool_ = VK_NULL_HANDLE;
    std::string device_name_;
    std::vector<Buffer> buffers_;
    std::vector<VkPipeline> pipelines_;
    std::vector<VkShaderModule> modules_;
};

} // namespace ctess::gpu_test
