// The ctess subcommands. Each parses its own options and returns the process exit code.
#pragma once

namespace ctess::cli {

int run_line(int argc, char** argv);
int run_pattern(int argc, char** argv);
int run_sweep(int argc, char** argv);
int run_animate(int argc, char** argv);
int run_efficiency(int argc, char** argv);

} // namespace ctess::cli
