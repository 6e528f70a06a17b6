// Bare-metal Cortex-M4 program for the flash footprint: calls every runtime entry point on one table set
// (CTESS_ARM_PROBE_MAX) with inputs the compiler cannot see, so that nothing is optimised away.
#include <cstdint>

#ifdef CTESS_ARM_PROBE_MAX
#include "cp_runtime_probe.hpp"

namespace {
volatile float factor[3] = {32.0f, 32.0f, 32.0f};
volatile std::uint32_t sink;
ctess::DomainPoint vertex_buffer[CTESS_ARM_PROBE_MAX * CTESS_ARM_PROBE_MAX + 2];
std::uint32_t index_buffer[3 * CTESS_ARM_PROBE_MAX * CTESS_ARM_PROBE_MAX];
} // namespace

int main() {
#if CTESS_ARM_PROBE_MAX == 64
    const ctess::rt::CpTableSet& t = ctess::rt::cp_tables_64;
#else
    const ctess::rt::CpTableSet& t = ctess::rt::cp_tables_256;
#endif
    const float f0 = factor[0], f1 = factor[1], f2 = factor[2];
    namespace probe = ctess::rt::probe;
    sink = probe::counts(t, f0, f1, f2).vertices + probe::vertex(t, f0, f1, f2, 5).u +
           probe::triangle(t, f0, f1, f2, 7)[0];
    sink = probe::emit(t, f0, f1, f2, vertex_buffer, index_buffer) ? 1u : 0u;
    return 0;
}
#endif
