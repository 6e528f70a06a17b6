// ctess_gpu_bench: times the GPU mesh pipeline on lavapipe (Vulkan) and Dawn (WebGPU on GLES/llvmpipe), for
// one or more shader builds in the same run, on the 1,152-patch factor sweep and a 50 k-patch grid; with
// --split, uniform density clamped to N beside split (docs/shaders.md, "Splitting") on scenes whose deepest
// leaves are at depth 0, 1 and 2, for the first build; with --weld, the welded output beside the unwelded one
// on both (docs/shaders.md, "Welded output"). Not a test: docs/shaders.md quotes its output.
//
//   ctess_gpu_bench [--split | --weld] LABEL=SHADER_DIR [LABEL=SHADER_DIR ...]
//
// Each build runs each scene once to warm the driver's shader cache, then `repeats` times; the median of the
// submit-to-completion times is printed. Every build's vertices and indices must equal the CPU pipeline's
// (records are compared only when the build's record size is the CPU's). Exit status 0, or 1 with a message.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include <ctess/runtime/cp/table_set.hpp>

#include "gpu_checks.hpp"
#include "gpu_pipeline.hpp"

using namespace ctess;
using namespace ctess::gpu_test;

namespace {

struct Build {
    std::string label, dir;
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

bool same_output(PipelineOutput cpu, PipelineOutput gpu) {
    if (cpu.patches.size() != gpu.patches.size()) { // another record size: compare the outputs only
        cpu.patches.clear();
        gpu.patches.clear();
    }
    const Comparison c = compare(cpu, gpu);
    if (!c.equal())
        std::fprintf(stderr, "ctess_gpu_bench: output differs from the CPU: %s\n",
                     c.first_difference.c_str());
    return c.equal();
}

// The uniform pattern clamped to N beside split, on scenes whose deepest leaves are at depth 0, 1 and 2: per
// backend the median times (lavapipe: the counting submission, with the split passes, and the emit one apart)
// and the split run's time relative to the clamped one's, per output triangle too.
int split_table(const Build& build, vulkan::Runner& runner, int repeats) {
    struct Case {
        const char* name;
        Scene scene;
    };
    std::vector<Case> cases;
    for (const float dice : {12.0f, 6.0f}) { // deepest leaves at depth 0 and 1
        Scene grid = factor_sweep_grid(64, 158, rt::Surface::pn_triangles);
        grid.options.dice.dice_rate = dice;
        cases.push_back(
            {dice == 12.0f ? "50 k-patch grid, DiceRate 12" : "50 k-patch grid, DiceRate 6", grid});
    }
    // Depth 2 needs factors above N^2 = 256: on 50 k patches, tens of millions of triangles.
    cases.push_back({"288-patch sweep to 1,800", factor_sweep_grid(600, 12, rt::Surface::pn_triangles)});
    std::printf("\n| scene | depth of the deepest leaf | backend | pattern | patches | leaves | triangles | "
                "median ms (of "
                "%d) | counting, ms | emit, ms | split / clamped time | per triangle |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|---|\n",
                repeats);
    for (Case& c : cases) {
        PipelineOutput cpu[2];
        std::uint32_t deepest = 0, leaves = 0;
        for (int k = 0; k < 2; ++k) {
            c.scene.options.pattern = k == 0 ? rt::Pattern::uniform : rt::Pattern::uniform_split;
            cpu[k] = run_cpu(rt::cp_tables_64, c.scene);
        }
        const std::array<std::uint32_t, 5> depths = split_depths(c.scene, cpu[1]);
        for (std::uint32_t d = 0; d < depths.size(); ++d)
            if (depths[d] != 0) deepest = d, leaves += depths[d];
        for (const char* backend : {"lavapipe", "Dawn"}) {
            std::vector<double> ms[2], counts_ms[2];
            for (int r = -1; r < repeats; ++r)
                for (int k = 0; k < 2; ++k) {
                    c.scene.options.pattern = k == 0 ? rt::Pattern::uniform : rt::Pattern::uniform_split;
                    const PipelineOutput gpu = backend[0] == 'l'
                                                   ? run_vulkan(runner, c.scene)
                                                   : run_dawn(CTESS_NODE, CTESS_RUN_WGSL, build.dir, 64,
                                                              {{&c.scene, std::string(CTESS_WORK_DIR) +
                                                                              "/bench_split_" + build.label}})
                                                         .front();
                    if (r < 0 && !same_output(cpu[k], gpu)) return 1;
                    if (r >= 0)
                        ms[k].push_back(gpu.milliseconds), counts_ms[k].push_back(gpu.counts_milliseconds);
                }
            for (int k = 0; k < 2; ++k) {
                const double t = median(ms[k]), counting = median(counts_ms[k]);
                char parts[64] = "— | —";
                if (counting >= 0) std::snprintf(parts, sizeof parts, "%.1f | %.1f", counting, t - counting);
                char ratio[64] = "1 | 1";
                if (k == 1)
                    std::snprintf(ratio, sizeof ratio, "%.2f | %.2f", t / median(ms[0]),
                                  (t / cpu[1].total_triangles()) /
                                      (median(ms[0]) / cpu[0].total_triangles()));
                std::printf("| %s | %u | %s | %s | %u | %u | %u | %.1f | %s | %s |\n", c.name, deepest,
                            backend, k == 0 ? "uniform (clamped to N)" : "uniform split",
                            c.scene.patch_count(), k == 0 ? c.scene.patch_count() : leaves,
                            cpu[k].total_triangles(), t, parts, ratio);
            }
            std::fflush(stdout);
        }
    }
    return 0;
}

// The welded output (docs/shaders.md, "Welded output") beside the unwelded one, CP, uniform and uniform split
// (the sort over the mesh; at DiceRate 12 its output is the clamped pattern's, at 6 it splits once), on
// lavapipe and Dawn: median times of the whole run and of its counting submissions, the welded run relative
// to the unwelded, and the CPU's single-threaded setup_welded + emit_welded_mesh on the same scene. Every
// welded output must equal the CPU's.
int weld_table(const Build& build, vulkan::Runner& runner, int repeats) {
    struct Case {
        const char* name;
        Scene scene;
    };
    Scene big = factor_sweep_grid(64, 158, rt::Surface::pn_triangles);
    big.options.dice.dice_rate = 12.0f;
    Scene deeper = big; // uniform split: leaves at depth 1
    deeper.options.dice.dice_rate = 6.0f;
    std::vector<Case> cases = {
        {"1,152-patch sweep, PN", factor_sweep_grid(64, 24, rt::Surface::pn_triangles)},
        {"50 k-patch grid, PN, DiceRate 12", big},
        {"50 k-patch grid, PN, DiceRate 6", deeper}};
    std::printf(
        "\n| scene | pattern | output | vertices | triangles | backend | median ms (of %d) | counting, ms | "
        "welded / unwelded | CPU ms (one thread) |\n|---|---|---|---|---|---|---|---|---|---|\n",
        repeats);
    const std::string work = std::string(CTESS_WORK_DIR) + "/bench_weld_" + build.label;
    for (Case& c : cases)
        for (const rt::Pattern pattern : {rt::Pattern::cp, rt::Pattern::uniform, rt::Pattern::uniform_split})
            for (const char* backend : {"lavapipe", "Dawn"}) {
                // The split pattern is welded by one sort over the mesh ("One sort over the mesh").
                if (c.scene.options.dice.dice_rate == 6.0f && pattern != rt::Pattern::uniform_split) continue;
                c.scene.options.pattern = pattern;
                PipelineOutput cpu[2];
                std::vector<double> ms[2], counts_ms[2], cpu_ms[2];
                for (int r = -1; r < repeats; ++r)
                    for (int k = 0; k < 2; ++k) { // unwelded, welded
                        const PipelineOutput reference = k == 0 ? run_cpu(rt::cp_tables_64, c.scene)
                                                                : run_cpu_welded(rt::cp_tables_64, c.scene);
                        PipelineOutput gpu;
                        if (backend[0] == 'l')
                            gpu = k == 0 ? run_vulkan(runner, c.scene) : run_vulkan_welded(runner, c.scene);
                        else
                            gpu = (k == 0 ? run_dawn : run_dawn_welded)(CTESS_NODE, CTESS_RUN_WGSL, build.dir,
                                                                        64, {{&c.scene, work}}, RunLimits{})
                                      .front();
                        if (r < 0) {
                            cpu[k] = reference;
                            if (!same_output(reference, gpu)) return 1;
                            continue;
                        }
                        ms[k].push_back(gpu.milliseconds);
                        counts_ms[k].push_back(gpu.counts_milliseconds);
                        cpu_ms[k].push_back(reference.milliseconds);
                    }
                for (int k = 0; k < 2; ++k) {
                    char ratio[32] = "1", counting[32] = "—";
                    if (k == 1) std::snprintf(ratio, sizeof ratio, "%.2f", median(ms[1]) / median(ms[0]));
                    if (median(counts_ms[k]) >= 0)
                        std::snprintf(counting, sizeof counting, "%.1f", median(counts_ms[k]));
                    std::printf("| %s | %s | %s | %u | %u | %s | %.1f | %s | %s | %.1f |\n", c.name,
                                pattern_name(pattern), k == 0 ? "unwelded" : "welded",
                                cpu[k].total_vertices(), cpu[k].total_triangles(), backend, median(ms[k]),
                                counting, ratio, median(cpu_ms[k]));
                }
                std::fflush(stdout);
            }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<Build> builds;
    bool split_only = false, weld_only = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--split" || arg == "--weld") {
            (arg == "--split" ? split_only : weld_only) = true;
            continue;
        }
        const std::size_t eq = arg.find('=');
        if (eq == std::string::npos) {
            std::fprintf(stderr, "usage: ctess_gpu_bench LABEL=SHADER_DIR [LABEL=SHADER_DIR ...]\n");
            return 1;
        }
        builds.push_back({arg.substr(0, eq), arg.substr(eq + 1)});
    }
    if (builds.empty()) {
        std::fprintf(stderr, "usage: ctess_gpu_bench LABEL=SHADER_DIR [LABEL=SHADER_DIR ...]\n");
        return 1;
    }
    struct Named {
        const char* name;
        Scene scene;
    };
    // The 50 k-patch grid: 19 MB of vertices.
    Scene big = factor_sweep_grid(64, 158, rt::Surface::pn_triangles);
    big.options.dice.dice_rate = 12.0f;
    const Named scenes[] = {{"1,152-patch sweep, PN", factor_sweep_grid(64, 24, rt::Surface::pn_triangles)},
                            {"50 k-patch grid, PN", big}};
    constexpr int repeats = 3;
    try {
        std::vector<std::unique_ptr<vulkan::Runner>> runners;
        for (const Build& b : builds) runners.push_back(std::make_unique<vulkan::Runner>(b.dir, 64));
        if (split_only) return split_table(builds.front(), *runners.front(), repeats);
        if (weld_only) return weld_table(builds.front(), *runners.front(), repeats);
        std::printf(
            "| scene | patches | vertices | triangles | backend | build | median ms (of %d) | of which "
            "setup + prefix sum, ms | emit passes, ms |\n"
            "|---|---|---|---|---|---|---|---|---|\n",
            repeats);
        for (const Named& s : scenes) {
            const PipelineOutput cpu = run_cpu(rt::cp_tables_64, s.scene);
            for (const char* backend : {"lavapipe", "Dawn"}) {
                // Builds alternate inside each repeat, so that drift of the machine hits them alike.
                std::vector<std::vector<double>> ms(builds.size()), counts_ms(builds.size()),
                    emit_ms(builds.size());
                for (int r = -1; r < repeats; ++r) {
                    for (std::size_t b = 0; b < builds.size(); ++b) {
                        const PipelineOutput gpu =
                            backend[0] == 'l'
                                ? run_vulkan(*runners[b], s.scene)
                                : run_dawn(
                                      CTESS_NODE, CTESS_RUN_WGSL, builds[b].dir, 64,
                                      {{&s.scene, std::string(CTESS_WORK_DIR) + "/bench_" + builds[b].label}})
                                      .front();
                        if (r < 0 && !same_output(cpu, gpu)) return 1;
                        if (r >= 0) ms[b].push_back(gpu.milliseconds);
                        if (r >= 0) counts_ms[b].push_back(gpu.counts_milliseconds);
                        if (r >= 0) emit_ms[b].push_back(gpu.milliseconds - gpu.counts_milliseconds);
                    }
                }
                for (std::size_t b = 0; b < builds.size(); ++b) {
                    // The split is Vulkan's two submissions (Dawn's run reports the whole only).
                    char split[64] = "— | —";
                    if (median(counts_ms[b]) >= 0)
                        std::snprintf(split, sizeof split, "%.1f | %.1f", median(counts_ms[b]),
                                      median(emit_ms[b]));
                    std::printf("| %s | %u | %u | %u | %s | %s | %.1f | %s |\n", s.name,
                                s.scene.patch_count(), cpu.total_vertices(), cpu.total_triangles(), backend,
                                builds[b].label.c_str(), median(ms[b]), split);
                }
                std::fflush(stdout);
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ctess_gpu_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
