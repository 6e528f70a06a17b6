// The ctess subcommands. Each parses its own options and returns the process exit code.
#pragma once
#include <string>

#include "line_modes.hpp"

#include "cli_args.hpp"
#include "mesh.hpp"

namespace ctess::cli {

// Option parsers shared by several commands (UsageError on bad values).
LineMode line_mode_from(const std::string& name); // --mode for line/sweep
unsigned max_factor_from(const Args& args);       // --max, default: the build's
PatternRequest pattern_request_from(const Args& args,
                                    const std::string& factors_key); // pattern/animate options

int run_line(int argc, char** argv);
int run_pattern(int argc, char** argv);
int run_sweep(int argc, char** argv);
int run_animate(int argc, char** argv);
int run_efficiency(int argc, char** argv);
int run_serve(int argc, char** argv);
int run_mesh(int argc, char** argv); // a model file tessellated and welded (cmd_mesh.cpp)

// The largest uniform factor `ctess pattern` (and /api/pattern) writes: at most 262,144 triangles.
inline constexpr unsigned uniform_cli_max_factor = 512;

// The most triangles `ctess mesh` writes unless --max-triangles says otherwise (about 4 GiB in memory).
inline constexpr unsigned mesh_cli_default_max_triangles = 1u << 27;

// The largest grid `ctess strip` prints (segments per direction): 2,099,200 indices at most.
inline constexpr unsigned strip_cli_max_segments = 1024;
int run_strip(int argc, char** argv);
int run_surface(int argc, char** argv);

} // namespace ctess::cli
