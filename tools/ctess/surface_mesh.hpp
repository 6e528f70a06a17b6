// An adaptively tessellated built-in surface as the CLI handles it (ctess surface): the request, the mesh
// copied out of the library's workspace, and the comparison with a uniform grid of the same chord error.
#pragma once
#include <ctess/runtime/surface/adaptive.hpp>
#include <ctess/surface/conforming_bintree.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace ctess::cli {

// The deepest level the CLI accepts: its worst case is 2^19 triangles and a 32 MiB node workspace.
inline constexpr unsigned surface_cli_max_level = 18;
// The largest uniform grid the comparison tries (segments per direction).
inline constexpr std::uint32_t comparison_max_segments = 2048;

struct SurfaceRequest {
    std::string name = "sphere"; // sphere, torus, ripple
    rt::AdaptiveOptions options;
};

struct SurfaceMesh {
    std::vector<adaptive::ParamPoint> params;
    std::vector<rt::SurfaceVertex> vertices;
    std::vector<std::uint32_t> triangles; // counter-clockwise in (u, v)
    std::vector<std::uint32_t> levels;    // per triangle
    float chord_error = 0.0f;             // max_chord_error of chord_error.hpp
};

struct UniformComparison {
    std::uint32_t segments = 0; // N of the smallest N x N grid tried whose error is <= the adaptive one
    std::uint32_t triangles = 0;
    float chord_error = 0.0f;
    bool reached = false; // false: no grid up to comparison_max_segments reached it
};

const std::vector<std::string>& surface_names();
// Tessellates; a status other than ok is an error (UsageError for bad options) naming the problem.
SurfaceMesh tessellate_surface(const SurfaceRequest& request);
// Scans N = 1, 2, ..., 32, then N growing by 4% (at least 1) up to comparison_max_segments.
UniformComparison compare_with_uniform_grid(const SurfaceRequest& request, float target_error);

} // namespace ctess::cli
