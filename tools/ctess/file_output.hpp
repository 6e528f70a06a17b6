// Writing the CLI's output files, with a clear error when a path cannot be written.
#pragma once
#include <string>

namespace ctess::cli {

// Writes text to path ("-" = standard output); throws std::runtime_error with the path on failure.
void write_text(const std::string& path, const std::string& text);
// Creates the directory (and parents) if needed; throws on failure.
void make_directory(const std::string& path);

} // namespace ctess::cli
