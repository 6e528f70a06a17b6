// Out-of-line wrappers of the runtime (see cp_runtime_probe.cpp).
#pragma once
#include <cstdint>
#include <span>

#include <ctess/runtime/cp/patch.hpp>

namespace ctess::rt::probe {

Counts counts(const CpTableSet& tables, float f0, float f1, float f2) noexcept;
DomainPoint vertex(const CpTableSet& tables, float f0, float f1, float f2, std::uint32_t i) noexcept;
CpTriangle triangle(const CpTableSet& tables, float f0, float f1, float f2, std::uint32_t p) noexcept;
bool emit(const CpTableSet& tables, float f0, float f1, float f2, std::span<DomainPoint> vertices,
          std::span<std::uint32_t> indices) noexcept;

} // namespace ctess::rt::probe
