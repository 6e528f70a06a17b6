// Where the CLI finds the files it ships beside itself (the viewer, the generated shaders and the WebGPU host
// module), shared by `ctess serve` (cmd_serve.cpp) and `ctess mesh --backend` (cmd_mesh.cpp).
#pragma once
#include <string>

namespace ctess::cli {

// An installed ctess (cmake --install) finds `name` in <prefix>/share/ctess/, beside its own bin/; a ctess
// run from its build tree uses build_dir (the source's viewer/, the build's shaders/).
std::string installed_or_build_dir(const std::string& name, const std::string& build_dir);

} // namespace ctess::cli
