// Writers for a tessellated patch: JSON (schema in docs/cli.md), Wavefront OBJ, and an SVG picture.
#pragma once
#include <string>

#include "mesh.hpp"

namespace ctess::cli {

std::string mesh_to_json(const Mesh& mesh, const PatternRequest& request);
std::string mesh_to_obj(const Mesh& mesh, const PatternRequest& request);
struct SvgOptions {
    bool show_provoking = false; // mark each triangle's first vertex
    std::string caption;         // extra line under the title (animate uses it for the frame number)
};
std::string mesh_to_svg(const Mesh& mesh, const PatternRequest& request, const SvgOptions& options = {});
std::string factors_text(const std::vector<float>& factors);

} // namespace ctess::cli
