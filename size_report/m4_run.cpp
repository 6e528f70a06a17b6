// The runtime run, not just linked (issue #22): one program compiled for the Cortex-M4 image (run under QEMU,
// mps2-an386) and for the host. For a fixed set of factor triples it builds CpPatch, UniformPatch and
// UniformSplit in both layouts, emits each patch, checks vertex(i) and triangle(p) against the emitted
// buffers, and prints one line per case: the counts and an FNV-1a digest of the emitted vertices and indices.
// It then runs verify_tables on the CP tables. tests/embedded compares the two outputs byte for byte, so the
// target's results must equal the host's bit for bit.
//
// Lines starting with '#' are informational and ignored by the comparison: on the target, each case's stack
// high-water mark (the stack painted with a pattern before the call and scanned after) and the instructions
// it executed (SysTick ticks under `qemu -icount shift=0`, see README.md "Running on a Cortex-M4").
//
// Exit status 0 only if every emit succeeded, random access matched the emitted buffers and the tables
// verified. Build with CTESS_M4_RUN_MAX = 64 (uniform tables N = 11) or 256 (N = 16).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <span>

#include <ctess/runtime/cp/patch.hpp>
#include <ctess/runtime/cp/table_integrity.hpp>
#include <ctess/runtime/uniform/patch.hpp>
#include <ctess/runtime/uniform/split.hpp>
#include <ctess/runtime/uniform/table_set.hpp>

#ifndef CTESS_M4_RUN_MAX
#error "CTESS_M4_RUN_MAX (64 or 256) must be defined"
#endif

namespace {

#if CTESS_M4_RUN_MAX == 64
const ctess::rt::CpTableSet& cp_tables = ctess::rt::cp_tables_64;
const ctess::rt::UniformTableSet& uniform_tables = ctess::rt::uniform_tables_11;
constexpr std::uint32_t uniform_max = 11;
#elif CTESS_M4_RUN_MAX == 256
const ctess::rt::CpTableSet& cp_tables = ctess::rt::cp_tables_256;
const ctess::rt::UniformTableSet& uniform_tables = ctess::rt::uniform_tables_16;
constexpr std::uint32_t uniform_max = 16;
#else
#error "CTESS_M4_RUN_MAX must be 64 or 256"
#endif
constexpr std::uint32_t cp_max = CTESS_M4_RUN_MAX;

// Output buffers, sized for the largest patch each runtime can give (checked: a case that does not fit fails
// the run). CP: at most max^2 + 2 vertices and 3 max^2 indices (the size probe's bound, arm_probe_main.cpp);
// UniformSplit runs its cases with factors clamped to N^2 here (the library splits to 32,768, a billion
// triangles: the deeper splits are tested on the host, tests/uniform/test_uniform_split_deep.cpp), and its
// largest output, at (N^2, N^2, N^2), has N^4 vertices and triangles.
constexpr std::uint32_t cp_vertex_capacity = cp_max * cp_max + 2;
constexpr std::uint32_t split_vertex_capacity = uniform_max * uniform_max * uniform_max * uniform_max;
constexpr std::uint32_t index_capacity =
    3 * (cp_max * cp_max > split_vertex_capacity ? cp_max * cp_max : split_vertex_capacity);
constexpr std::uint32_t uniform_vertex_capacity = 1024;
ctess::DomainPoint cp_vertices[cp_vertex_capacity];
ctess::uniform::Point uniform_vertices[uniform_vertex_capacity];
ctess::uniform::SplitPoint split_vertices[split_vertex_capacity];
std::uint32_t indices[index_capacity]; // shared: one patch at a time

// Factor bit patterns, so that NaN, infinities and negative zero are exact and the printed triples are the
// same bits on both sides.
constexpr std::uint32_t nan_bits = 0x7FC00000u, inf_bits = 0x7F800000u, minus_inf_bits = 0xFF800000u,
                        minus_zero_bits = 0x80000000u, denormal_bits = 0x00000001u;

float from_bits(std::uint32_t b) {
    float f;
    std::memcpy(&f, &b, sizeof f);
    return f;
}
std::uint32_t to_bits(float f) {
    std::uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b;
}

struct Triple {
    float f[3];
};
// T0 (factor 1) edges, integers, fractional factors, both tables' maxima and beyond, and every clamp: NaN,
// +-inf, zero, -0, negatives and a denormal (docs/algorithm.md §2: factors clamp to [1, max]).
const Triple cases[] = {
    {{1, 1, 1}},
    {{1, 1, 5}},
    {{1, 7, 1}},
    {{9, 1, 1}},
    {{1, 12, 12}},
    {{2, 2, 2}},
    {{3, 4, 5}},
    {{8, 8, 8}},
    {{5, 9, 3}},
    {{16, 9, 11}},
    {{2.5f, 3.25f, 7.75f}},
    {{5.5f, 5.5f, 5.5f}},
    {{1.01f, 1.99f, 2.01f}},
    {{31.9f, 0.5f, 17.3f}},
    {{10.5f, 11.5f, 16.49f}},
    {{32, 32, 32}},
    {{64, 64, 64}},
    {{64, 1, 64}},
    {{63.9f, 64, 2.2f}},
    {{121, 121, 121}},
    {{100, 47.5f, 256}},
    {{256, 256, 256}},
    {{1000, 3, 3}},
    {{from_bits(nan_bits), 4, 6}},
    {{from_bits(inf_bits), from_bits(inf_bits), from_bits(inf_bits)}},
    {{from_bits(minus_inf_bits), 20, from_bits(nan_bits)}},
    {{-5, 0, from_bits(minus_zero_bits)}},
    {{from_bits(denormal_bits), -1e30f, 7}},
    {{3e38f, 13, 0.999f}},
    {{17, 23, 29}},
};
constexpr unsigned case_count = sizeof cases / sizeof cases[0];

// FNV-1a, 64-bit, over each 32-bit value's bytes in little-endian order (values, not object bytes: the digest
// is the same on every target).
struct Fnv1a {
    std::uint64_t h = 0xcbf29ce484222325u;
    void add(std::uint32_t x) {
        for (int k = 0; k < 4; ++k) h = (h ^ ((x >> (8 * k)) & 0xFFu)) * 0x100000001b3u;
    }
};

// What one case of one runtime gives: counts, digests and whether everything was consistent.
struct CaseResult {
    std::uint32_t vertices = 0, triangles = 0;
    bool emitted = false;
    bool random_access_ok = true; // vertex(i), triangle(p) equal the emitted buffers
};

template <class Point>
std::uint64_t digest_points(const Point* p, std::uint32_t n) {
    Fnv1a d;
    for (std::uint32_t i = 0; i < n; ++i) d.add(p[i].u), d.add(p[i].v);
    return d.h;
}
std::uint64_t digest_indices(std::uint32_t n) {
    Fnv1a d;
    for (std::uint32_t i = 0; i < n; ++i) d.add(indices[i]);
    return d.h;
}

// The measured units: a patch built and emitted (Phase::emit), or built and queried for every vertex(i) and
// triangle(p), each compared with the emitted buffers (Phase::lookups). Out of line, so that the patch lives
// in their frames and the stack measurement covers it.
enum class Phase { emit, lookups };
struct Job {
    const Triple* triple;
    ctess::PatchOptions options;
    Phase phase;
    CaseResult* result;
};

template <class Patch, class Point>
void emit_patch(const Patch& patch, std::span<Point> vertices, CaseResult& result) {
    const ctess::Counts n = patch.counts();
    result.vertices = n.vertices;
    result.triangles = n.triangles;
    if (n.vertices > vertices.size() || 3u * n.triangles > index_capacity) return; // emitted stays false
    result.emitted = patch.emit(vertices, std::span<std::uint32_t>(indices, index_capacity));
}

template <class Patch, class Point>
void check_lookups(const Patch& patch, std::span<const Point> vertices, CaseResult& result) {
    const ctess::Counts n = patch.counts();
    bool ok = result.emitted && n.vertices == result.vertices && n.triangles == result.triangles;
    for (std::uint32_t i = 0; ok && i < n.vertices; ++i)
        if (!(patch.vertex(i) == vertices[i])) ok = false;
    for (std::uint32_t p = 0; ok && p < n.triangles; ++p) {
        const auto t = patch.triangle(p);
        if (t[0] != indices[3 * p] || t[1] != indices[3 * p + 1] || t[2] != indices[3 * p + 2]) ok = false;
    }
    // Out of range gives the documented zeros (cp/patch.hpp, uniform/patch.hpp).
    const auto past = patch.triangle(n.triangles);
    if (!(patch.vertex(n.vertices) == Point{}) || past[0] != 0 || past[1] != 0 || past[2] != 0) ok = false;
    result.random_access_ok = ok;
}

__attribute__((noinline)) void run_cp(void* context) {
    const Job& job = *static_cast<const Job*>(context);
    const ctess::rt::CpPatch patch(cp_tables, job.triple->f[0], job.triple->f[1], job.triple->f[2],
                                   job.options);
    if (job.phase == Phase::emit)
        emit_patch(patch, std::span<ctess::DomainPoint>(cp_vertices), *job.result);
    else
        check_lookups(patch, std::span<const ctess::DomainPoint>(cp_vertices), *job.result);
}

__attribute__((noinline)) void run_uniform(void* context) {
    const Job& job = *static_cast<const Job*>(context);
    const ctess::rt::UniformPatch patch(uniform_tables, job.triple->f[0], job.triple->f[1], job.triple->f[2],
                                        job.options);
    if (job.phase == Phase::emit)
        emit_patch(patch, std::span<ctess::uniform::Point>(uniform_vertices), *job.result);
    else
        check_lookups(patch, std::span<const ctess::uniform::Point>(uniform_vertices), *job.result);
}

// UniformSplit has no random access: its lookups phase is empty.
__attribute__((noinline)) void run_split(void* context) {
    const Job& job = *static_cast<const Job*>(context);
    if (job.phase != Phase::emit) return;
    constexpr float top = static_cast<float>(uniform_max * uniform_max);
    const auto clamp = [](float f) { return f > top ? top : f; }; // NaN and -inf pass: the library's cases
    const ctess::rt::UniformSplit split(uniform_tables, clamp(job.triple->f[0]), clamp(job.triple->f[1]),
                                        clamp(job.triple->f[2]), job.options);
    emit_patch(split, std::span<ctess::uniform::SplitPoint>(split_vertices), *job.result);
}

// Target-only measurements. The stack: paint stack_paint_bytes below the current stack pointer, call, and
// find the lowest word that changed. Instructions: with `-icount shift=0` QEMU advances virtual time 1 ns per
// instruction, and SysTick (processor clock, 25 MHz on mps2-an386) counts one tick per 40 ns: ticks x 40
// instructions, to within 40 per reading.
struct Measure {
    std::uint32_t stack_bytes = 0;
    std::uint32_t ticks = 0;
    bool valid = false;
};

#if defined(__arm__) && !defined(__linux__)
// The stack is where newlib's rdimon start-up puts it (semihosting SYS_HEAPINFO; under QEMU 7.2 the top of
// the mps2-an386's 16 MiB PSRAM, 0x22000000): far more than the painted 48 KiB, which bounds what can be
// measured.
constexpr std::uint32_t stack_paint_bytes = 48 * 1024;
constexpr std::uint32_t paint = 0xA5C3E1F7u;
volatile std::uint32_t* const syst_csr = reinterpret_cast<volatile std::uint32_t*>(0xE000E010u);
volatile std::uint32_t* const syst_rvr = reinterpret_cast<volatile std::uint32_t*>(0xE000E014u);
volatile std::uint32_t* const syst_cvr = reinterpret_cast<volatile std::uint32_t*>(0xE000E018u);

void start_systick() {
    *syst_rvr = 0x00FFFFFFu; // the 24-bit maximum
    *syst_cvr = 0;
    *syst_csr = 0x5u; // enable, processor clock, no interrupt
}

__attribute__((noinline)) Measure measure(void (*run)(void*), void* context) {
    std::uint32_t sp;
    asm volatile("mov %0, sp" : "=r"(sp));
    volatile std::uint32_t* const top = reinterpret_cast<volatile std::uint32_t*>(sp & ~3u);
    volatile std::uint32_t* const bottom = top - stack_paint_bytes / 4;
    for (volatile std::uint32_t* p = bottom; p < top; ++p) *p = paint;
    *syst_cvr = 0;   // restart the count from the reload value
    (void)*syst_csr; // clears COUNTFLAG
    const std::uint32_t start = *syst_cvr;
    run(context);
    const std::uint32_t end = *syst_cvr;
    const bool wrapped = (*syst_csr & 0x10000u) != 0;
    volatile std::uint32_t* p = bottom;
    while (p < top && *p == paint) ++p;
    Measure m;
    m.stack_bytes = static_cast<std::uint32_t>(top - p) * 4u;
    m.ticks = ((start == 0 ? 0x00FFFFFFu : start) - end) & 0x00FFFFFFu;
    m.valid = !wrapped && p != bottom; // p == bottom: the call may have gone past the painted area
    return m;
}

// A loop of a known instruction count (4 per iteration), measured like a patch: checks the ticks x 40 scale.
__attribute__((noinline)) void calibration_loop(void*) {
    std::uint32_t n = 100'000;
    asm volatile("1:\n\tsubs %0, %0, #1\n\tnop\n\tnop\n\tbne 1b" : "+r"(n) : : "cc");
}
void print_target_notes() {
    std::uint32_t sp;
    asm volatile("mov %0, sp" : "=r"(sp));
    std::printf("# stack pointer in main: 0x%08lx\n", static_cast<unsigned long>(sp));
    const Measure m = measure(calibration_loop, nullptr);
    std::printf("# calibration: a loop of 400000 instructions: %lu ticks ~ %lu instructions\n",
                static_cast<unsigned long>(m.ticks), static_cast<unsigned long>(m.ticks * 40u));
}
#else
void print_target_notes() {}
void start_systick() {}
Measure measure(void (*run)(void*), void* context) {
    run(context);
    return {};
}
#endif

// printf's %lu and %lx on every target (uint32_t is unsigned long on arm-none-eabi, unsigned int on the
// host).
unsigned long ul(std::uint64_t x) {
    return static_cast<unsigned long>(x);
}

struct Runtime {
    const char* name;
    void (*run)(void*);
    bool lookups;                                           // vertex(i) and triangle(p)
    std::uint64_t (*vertex_digest)(std::uint32_t vertices); // of its emitted vertex buffer
};

} // namespace

int main() {
    start_systick();
    const Runtime runtimes[] = {
        {"cp", run_cp, true, [](std::uint32_t n) { return digest_points(cp_vertices, n); }},
        {"uniform", run_uniform, true, [](std::uint32_t n) { return digest_points(uniform_vertices, n); }},
        {"split", run_split, false, [](std::uint32_t n) { return digest_points(split_vertices, n); }}};
    const ctess::Layout layouts[] = {ctess::Layout::provoking, ctess::Layout::shared};
    bool all_ok = true;
    print_target_notes();
    std::printf("ctess m4 run: cp max %lu, uniform N %lu, %u cases\n", ul(cp_max), ul(uniform_max),
                case_count);
    for (const Runtime& runtime : runtimes) {
        // The per-lookup figure of the largest patch, where the patch's construction weighs least.
        std::uint32_t worst_stack = 0, worst_emit = 0, largest_queries = 0, largest_per_query = 0;
        bool measured = true;
        for (const ctess::Layout layout : layouts) {
            for (unsigned c = 0; c < case_count; ++c) {
                CaseResult r;
                Job job{&cases[c], {layout}, Phase::emit, &r};
                const Measure emit = measure(runtime.run, &job);
                const std::uint64_t vd = r.emitted ? runtime.vertex_digest(r.vertices) : 0;
                const std::uint64_t id = r.emitted ? digest_indices(3 * r.triangles) : 0;
                job.phase = Phase::lookups;
                const Measure lookups = measure(runtime.run, &job);
                const bool ok = r.emitted && r.random_access_ok;
                all_ok = all_ok && ok;
                const char* layout_name = layout == ctess::Layout::shared ? "shared" : "provoking";
                std::printf("%s %s %02u f=%08lx,%08lx,%08lx v=%lu t=%lu vd=%08lx%08lx id=%08lx%08lx %s\n",
                            runtime.name, layout_name, c, ul(to_bits(cases[c].f[0])),
                            ul(to_bits(cases[c].f[1])), ul(to_bits(cases[c].f[2])), ul(r.vertices),
                            ul(r.triangles), ul(vd >> 32), ul(vd & 0xFFFFFFFFu), ul(id >> 32),
                            ul(id & 0xFFFFFFFFu),
                            !r.emitted            ? "FAIL(emit)"
                            : !r.random_access_ok ? "FAIL(random access)"
                                                  : "ok");
                measured = measured && emit.valid && lookups.valid;
                if (!emit.valid || !lookups.valid) continue;
                const std::uint32_t queries = r.vertices + r.triangles;
                const std::uint32_t per_query =
                    runtime.lookups && queries ? lookups.ticks * 40u / queries : 0;
                std::printf("# %s %s %02u: emit ~ %lu instructions, stack %lu B", runtime.name, layout_name,
                            c, ul(emit.ticks * 40u), ul(emit.stack_bytes));
                if (runtime.lookups)
                    std::printf("; lookups ~ %lu instructions (~ %lu per vertex or triangle), stack %lu B",
                                ul(lookups.ticks * 40u), ul(per_query), ul(lookups.stack_bytes));
                std::printf("\n");
                worst_stack = std::max({worst_stack, emit.stack_bytes, lookups.stack_bytes});
                worst_emit = std::max(worst_emit, emit.ticks * 40u);
                if (queries > largest_queries) largest_queries = queries, largest_per_query = per_query;
            }
        }
        if (measured) {
            std::printf("# %s: stack high-water %lu B; most instructions to build and emit a patch ~ %lu",
                        runtime.name, ul(worst_stack), ul(worst_emit));
            if (runtime.lookups)
                std::printf("; ~ %lu per vertex(i) or triangle(p) at the largest patch (%lu of them)",
                            ul(largest_per_query), ul(largest_queries));
            std::printf("\n");
        }
    }
    ctess::rt::TableCheckResult check;
    const Measure verify = measure(
        [](void* c) { *static_cast<ctess::rt::TableCheckResult*>(c) = ctess::rt::verify_tables(cp_tables); },
        &check);
    if (verify.valid)
        std::printf("# verify_tables: ~ %lu instructions, stack %lu B\n", ul(verify.ticks * 40u),
                    ul(verify.stack_bytes));
    std::printf("verify_tables cp_tables_%lu: %s\n", ul(cp_max), check ? "ok" : "FAIL");
    all_ok = all_ok && static_cast<bool>(check);
    std::printf("result: %s\n", all_ok ? "pass" : "FAIL");
    return all_ok ? 0 : 1;
}
