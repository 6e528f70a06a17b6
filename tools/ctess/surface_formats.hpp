// Writers for ctess surface and ctess strip: JSON (schema in docs/cli.md), OBJ with normals, the SVG of the
// parameter-domain triangulation, a shaded SVG view of the surface, and the comparison report.
#pragma once
#include <cstdint>
#include <span>
#include <string>

#include "surface_mesh.hpp"

namespace ctess::cli {

std::string surface_to_json(const SurfaceMesh& mesh, const SurfaceRequest& request);
std::string surface_to_obj(const SurfaceMesh& mesh, const SurfaceRequest& request);
std::string surface_to_param_svg(const SurfaceMesh& mesh, const SurfaceRequest& request);
std::string surface_to_shaded_svg(const SurfaceMesh& mesh, const SurfaceRequest& request);
std::string surface_stats_json(const SurfaceMesh& mesh, const SurfaceRequest& request,
                               const UniformComparison& uniform);
std::string strip_to_json(std::uint32_t u_segments, std::uint32_t v_segments,
                          std::span<const std::uint32_t> indices);

} // namespace ctess::cli
