// Writing the CLI's output files: every write is checked through flush and close, a failure names the path
// and the OS reason, and a regular file is written to a temporary next to it and renamed into place, so that
// a failed write never leaves a half-written file that looks complete.
#pragma once
#include <functional>
#include <ostream>
#include <string>

namespace ctess::cli {

// Writes text to path ("-" = standard output); throws std::runtime_error with the path and strerror on
// failure. A regular (or new) file is replaced atomically; a device or pipe (/dev/null, /dev/full, a FIFO) is
// written in place.
void write_text(const std::string& path, const std::string& text);
// The same for a file written by fill through a stream (not "-"): a writer that streams puts its bytes into
// the file without building them in memory first. An exception from fill removes the temporary and passes on.
void write_stream(const std::string& path, const std::function<void(std::ostream&)>& fill);
// Creates the directory (and parents) if needed; throws on failure.
void make_directory(const std::string& path);
// Flushes and checks standard output; throws std::runtime_error with strerror on failure (a full disk, a
// closed pipe). main() calls it before returning 0.
void finish_standard_output();

} // namespace ctess::cli
