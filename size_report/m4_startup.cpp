// Startup of the runnable Cortex-M4 image (m4_run.cpp under QEMU's mps2-an386): a two-entry vector table
// (initial stack pointer, reset handler) placed first in flash by m4_run.ld. The reset handler enables the
// FPU (the image is built for -mfloat-abi=hard, and an FP instruction with the coprocessor off faults) and
// enters newlib's semihosting start-up (rdimon.specs), which zeroes .bss, calls main and passes its return
// value to the host as QEMU's exit status. .data needs no copy: m4_run.ld places it in RAM, and QEMU loads it
// there.
#include <cstdint>

extern "C" {
[[noreturn]] void _mainCRTStartup();
extern std::uint32_t __StackTop;
[[noreturn]] void ctess_m4_reset();
}

extern "C" [[noreturn]] void ctess_m4_reset() {
    volatile std::uint32_t* const cpacr = reinterpret_cast<volatile std::uint32_t*>(0xE000ED88u);
    *cpacr |= 0xFu << 20; // CP10 and CP11 full access
    asm volatile("dsb\n\tisb" ::: "memory");
    _mainCRTStartup();
}

__attribute__((section(".vectors"), used))
const void* const ctess_m4_vectors[2] = {&__StackTop, reinterpret_cast<const void*>(&ctess_m4_reset)};
