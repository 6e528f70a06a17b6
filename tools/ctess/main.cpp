// ctess: command-line front end to the ctess tessellators (patterns, lines, sweeps, animations).
#include "cli_args.hpp"
#include "command_usage.hpp"
#include "commands.hpp"
#include "file_output.hpp"
#include "mesh_backend.hpp"

#include <csignal>
#include <cstdio>
#include <exception>
#include <string>

#include <fmt/core.h>

namespace {

constexpr const char* kUsage = R"(usage: ctess <command> [options]

commands:
  pattern  --mode M --factors a,b,c[,inside] [--domain tri|quad|iso] [--winding cw|ccw]
           [--format json|svg|obj] [--out FILE] [--max 64|256] [--layout provoking|shared] [--provoking]
           [--column-rule minimal|staircase]
  line     --mode M --factor f [--max 64|256] [--format text|json]
  sweep    --mode M --from a --to b [--steps n] --svg out.svg [--max 64|256]
  animate  --mode M --from a,b,c --to d,e,f --frames n --out DIR [pattern options]
  efficiency [--family cp|uniform] [--max 64|256] [--random n] [--seed s] [--format markdown|json]
           [--out FILE]   (--random and --seed: cp only)
  strip    --segments U,V [--format json] [--out FILE]            (U, V in [1, 1024])
  surface  --name sphere|torus|ripple [--angle deg] [--distance rel] [--min-level n] [--max-level n]
           [--format json|obj|svg|stats] [--view param|shaded] [--out FILE]   (levels in [0, 18])
  mesh     --in MODEL(.gltf|.glb|.obj) (--out OUT(.obj|.ply|.glb) | --stats) [--pattern cp|uniform|d3d11-*]
           (--factor F | --edge-length L | --dice-rate PX --camera X,Y,Z [--fov DEG] [--resolution W,H])
           [--surface flat|pn|pn-aen|phong] [--max 64|256] [--quad-rule longer-pair|as-labelled]
           [--keep-degenerate] [--max-triangles N] [--threads N] [--stats]
           [--displace HEIGHT.png | --displace-gltf | --displace-vector RGB.png] [--displace-scale S]
           [--displace-offset O]
           [--displace-address repeat|clamp] [--displace-grow]
           [--unwelded] [--backend cpu|vulkan|webgpu [--shaders DIR] [--backend-timeout S]]
  serve    [--port N] [--viewer DIR] [--shaders DIR]   the browser viewer on 127.0.0.1 (docs/viewer.md)

pattern modes: cp, d3d11-integer, d3d11-pow2, d3d11-odd, d3d11-even, uniform (tri, three factors)
line modes:    cp and the d3d11 modes plus pow2-subdivision, one-at-a-time, even-spacing
Factors must be finite and > 0. See docs/cli.md for the JSON schema and every option.
)";

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fputs(kUsage, stderr);
        return 2;
    }
    const std::string command = argv[1];
    if (command == "--help" || command == "-h" || command == "help") {
        std::fputs(kUsage, stdout);
        try {
            ctess::cli::finish_standard_output();
        } catch (const std::exception& e) {
            fmt::print(stderr, "ctess: error: {}\n", e.what());
            return 1;
        }
        return 0;
    }
    try {
        int status = -1;
        if (const std::string usage = ctess::cli::command_usage(kUsage, command);
            !usage.empty() && ctess::cli::asks_for_help(argc, argv)) {
            std::fputs(usage.c_str(), stdout);
            status = 0;
        }
        if (status < 0 && command == "pattern") status = ctess::cli::run_pattern(argc, argv);
        if (status < 0 && command == "line") status = ctess::cli::run_line(argc, argv);
        if (status < 0 && command == "sweep") status = ctess::cli::run_sweep(argc, argv);
        if (status < 0 && command == "animate") status = ctess::cli::run_animate(argc, argv);
        if (status < 0 && command == "efficiency") status = ctess::cli::run_efficiency(argc, argv);
        if (status < 0 && command == "strip") status = ctess::cli::run_strip(argc, argv);
        if (status < 0 && command == "surface") status = ctess::cli::run_surface(argc, argv);
        if (status < 0 && command == "serve") status = ctess::cli::run_serve(argc, argv);
        if (status < 0 && command == "mesh") status = ctess::cli::run_mesh(argc, argv);
        if (status < 0) {
            fmt::print(stderr, "ctess: unknown command '{}'\n\n{}", command, kUsage);
            return 2;
        }
        ctess::cli::finish_standard_output(); // a full disk or a closed pipe is an error, not exit 0
        return status;
    } catch (const ctess::cli::Interrupted& e) {
        // Cleaned up by now (node's group killed, its scratch folder removed): die of the signal itself.
        fmt::print(stderr, "ctess {}: {}\n", command, e.what());
        std::signal(e.signal_number(), SIG_DFL);
        std::raise(e.signal_number());
        return 128 + e.signal_number();
    } catch (const ctess::cli::UsageError& e) {
        fmt::print(stderr, "ctess {}: error: {}\n(run 'ctess --help' for usage)\n", command, e.what());
        return 2;
    } catch (const std::exception& e) {
        fmt::print(stderr, "ctess {}: error: {}\n", command, e.what());
        return 1;
    }
}
