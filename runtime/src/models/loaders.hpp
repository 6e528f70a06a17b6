// The two loaders behind load_model (runtime/src/models/load_gltf.cpp, load_obj.cpp). Both throw
// detail::LoadFailure; load_model catches it.
#pragma once
#include <cstdint>
#include <span>
#include <string>

#include <ctess/runtime/models/model.hpp>

namespace ctess::models::detail {

// base_dir: where a .gltf's external buffers and images are; nullptr: none may be opened.
Model load_gltf(std::span<const std::uint8_t> bytes, ModelKind kind, const std::string* base_dir,
                const LoadLimits& limits);
Model load_obj(std::span<const std::uint8_t> bytes, const LoadLimits& limits);

// The LoadFailure for a model past a caller's limit (LoadLimits::what).
[[noreturn]] void past_limit(const LoadLimits& limits, std::size_t bound, const char* of);

} // namespace ctess::models::detail
