// Out-of-line entry points that pull in every part of the runtime. They are built with the embedded flags
// (-fno-exceptions -fno-rtti) in every configuration, which proves that the runtime compiles that way, and
// they are what size_report links for the Cortex-M4 flash footprint.
#include "cp_runtime_probe.hpp"

namespace ctess::rt::probe {

Counts counts(const CpTableSet& tables, float f0, float f1, float f2) noexcept {
    return cp_counts(tables, f0, f1, f2);
}

DomainPoint vertex(const CpTableSet& tables, float f0, float f1, float f2, std::uint32_t i) noexcept {
    return CpPatch(tables, f0, f1, f2).vertex(i);
}

CpTriangle triangle(const CpTableSet& tables, float f0, float f1, float f2, std::uint32_t p) noexcept {
    return CpPatch(tables, f0, f1, f2).triangle(p);
}

bool emit(const CpTableSet& tables, float f0, float f1, float f2, std::span<DomainPoint> vertices,
          std::span<std::uint32_t> indices) noexcept {
    return CpPatch(tables, f0, f1, f2).emit(vertices, indices);
}

} // namespace ctess::rt::probe
