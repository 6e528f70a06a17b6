// ctess: command-line front end to the ctess tessellators (patterns, lines, sweeps, animations).
#include "cli_args.hpp"
#include "commands.hpp"

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
  efficiency [--max 64|256] [--random n] [--seed s] [--format markdown|json] [--out FILE]
  serve    [--port N] [--viewer DIR] [--shaders DIR]   the browser viewer on 127.0.0.1 (docs/viewer.md)

pattern modes: cp, d3d11-integer, d3d11-pow2, d3d11-odd, d3d11-even
line modes:    the pattern modes plus pow2-subdivision, one-at-a-time, even-spacing
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
        return 0;
    }
    try {
        if (command == "pattern") return ctess::cli::run_pattern(argc, argv);
        if (command == "line") return ctess::cli::run_line(argc, argv);
        if (command == "sweep") return ctess::cli::run_sweep(argc, argv);
        if (command == "animate") return ctess::cli::run_animate(argc, argv);
        if (command == "efficiency") return ctess::cli::run_efficiency(argc, argv);
        if (command == "serve") return ctess::cli::run_serve(argc, argv);
        fmt::print(stderr, "ctess: unknown command '{}'\n\n{}", command, kUsage);
        return 2;
    } catch (const ctess::cli::UsageError& e) {
        fmt::print(stderr, "ctess {}: error: {}\n(run 'ctess --help' for usage)\n", command, e.what());
        return 2;
    } catch (const std::exception& e) {
        fmt::print(stderr, "ctess {}: error: {}\n", command, e.what());
        return 1;
    }
}
