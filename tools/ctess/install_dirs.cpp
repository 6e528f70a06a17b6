// The CLI's installed or build-tree folders (install_dirs.hpp).
#include "install_dirs.hpp"

#include <filesystem>
#include <system_error>

namespace ctess::cli {

std::string installed_or_build_dir(const std::string& name, const std::string& build_dir) {
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const std::filesystem::path installed = exe.parent_path().parent_path() / "share" / "ctess" / name;
        if (std::filesystem::is_directory(installed, ec)) return installed.string();
    }
    return build_dir;
}

} // namespace ctess::cli
