// Runs the CP mesh pipeline on Vulkan (the generated GLSL as SPIR-V) and on Dawn (the generated WGSL, through
// node), with every output as the GPU buffers lay it out (pipeline_output.hpp).
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <ctess/runtime/cp_table_set.hpp>

#include "pipeline_output.hpp"
#include "vk_compute.hpp"

namespace ctess::gpu_test {

// The record size the generated shaders in dir use (their layout.json).
std::uint32_t layout_patch_words(const std::string& dir, unsigned max_factor);
PipelineOutput run_vulkan(VkCompute& vk, const std::string& shader_dir, unsigned max_factor,
                          const Scene& scene);
// Writes the scene next to out_dir, runs `node run_wgsl.mjs`, reads the result back. Throws on failure.
PipelineOutput run_dawn(const std::string& node, const std::string& script, const std::string& shader_dir,
                        unsigned max_factor, const Scene& scene, const std::string& work_file);

} // namespace ctess::gpu_test
