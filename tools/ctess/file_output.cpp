#include "file_output.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/core.h>

namespace ctess::cli {

namespace {

[[noreturn]] void fail(const std::string& what, const std::string& path, int error) {
    throw std::runtime_error(fmt::format("cannot {} '{}': {}", what, path, std::strerror(error)));
}

// Writes all of text to fd, then closes it; returns 0 or the first errno.
int write_and_close(int fd, const std::string& text) {
    int error = 0;
    for (std::size_t done = 0; done < text.size() && error == 0;) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0)
            error = n < 0 ? errno : EIO;
        else
            done += static_cast<std::size_t>(n);
    }
    if (::close(fd) != 0 && error == 0) error = errno;
    return error;
}

// A device, pipe or socket cannot be replaced by a rename: it is written in place.
bool is_special_file(const std::string& path) {
    struct stat st {};
    return ::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode);
}

} // namespace

void write_text(const std::string& path, const std::string& text) {
    if (path == "-") {
        if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
            fail("write", "standard output", errno);
        return;
    }
    if (is_special_file(path)) {
        const int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
        if (fd < 0) fail("write", path, errno);
        if (const int error = write_and_close(fd, text)) fail("write", path, error);
        return;
    }
    // A symbolic link is written through: the rename replaces the file it points to, not the link.
    std::string target = path;
    struct stat entry {};
    if (::lstat(path.c_str(), &entry) == 0 && S_ISLNK(entry.st_mode)) {
        char* resolved = ::realpath(path.c_str(), nullptr);
        if (resolved == nullptr) fail("resolve the symbolic link", path, errno);
        target = resolved;
        std::free(resolved);
    }
    // The temporary has a unique name in the target's directory, so the rename stays within one file system.
    // It takes the replaced file's permission bits, or the default mode (0666 less the umask) for a new file.
    struct stat existing {};
    const bool replacing = ::stat(target.c_str(), &existing) == 0;
    std::string temp;
    int fd = -1;
    for (unsigned attempt = 0; fd < 0; ++attempt) {
        temp = fmt::format("{}.tmp-{}-{}", target, ::getpid(), attempt);
        fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd < 0 && (errno != EEXIST || attempt == 100)) fail("write", path, errno);
    }
    if (replacing && ::fchmod(fd, existing.st_mode & 07777) != 0) {
        const int error = errno;
        ::close(fd);
        ::unlink(temp.c_str());
        fail("write", path, error);
    }
    if (const int error = write_and_close(fd, text)) {
        ::unlink(temp.c_str());
        fail("write", path, error);
    }
    if (std::rename(temp.c_str(), target.c_str()) != 0) {
        const int error = errno;
        ::unlink(temp.c_str());
        fail("write", path, error);
    }
}

void make_directory(const std::string& path) {
    std::error_code ec;
    std::filesystem::create_directories(path, ec);
    if (ec || !std::filesystem::is_directory(path))
        throw std::runtime_error(fmt::format("cannot create directory '{}': {}", path,
                                             ec ? ec.message() : std::string("not a directory")));
}

void finish_standard_output() {
    errno = 0;
    const bool flushed = std::fflush(stdout) == 0 && !std::ferror(stdout);
    const int flush_error = errno;
    if (std::fclose(stdout) != 0 || !flushed)
        fail("write", "standard output", flush_error ? flush_error : errno ? errno : EIO);
}

} // namespace ctess::cli
