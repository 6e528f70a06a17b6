#include "file_output.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <ostream>
#include <stdexcept>
#include <streambuf>
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

// Writes size bytes to fd; returns 0 or the first errno.
int write_all(int fd, const char* data, std::size_t size) {
    for (std::size_t done = 0; done < size;) {
        const ssize_t n = ::write(fd, data + done, size - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return n < 0 ? errno : EIO;
        done += static_cast<std::size_t>(n);
    }
    return 0;
}

// An output stream buffer over a file descriptor (a writer that streams, such as tinygltf's, writes straight
// to the file instead of into a string first); error() is the first failed write's errno.
class FdBuffer : public std::streambuf {
  public:
    explicit FdBuffer(int fd) : fd_(fd) { setp(buffer_, buffer_ + sizeof buffer_); }
    int error() const { return error_; }

  protected:
    int_type overflow(int_type c) override {
        if (sync() != 0) return traits_type::eof();
        if (!traits_type::eq_int_type(c, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(c);
            pbump(1);
        }
        return traits_type::not_eof(c);
    }
    std::streamsize xsputn(const char* data, std::streamsize size) override {
        if (size < static_cast<std::streamsize>(sizeof buffer_)) return std::streambuf::xsputn(data, size);
        if (sync() != 0) return 0; // a large block goes straight through
        if ((error_ = write_all(fd_, data, static_cast<std::size_t>(size))) != 0) return 0;
        return size;
    }
    int sync() override {
        if (error_ == 0) error_ = write_all(fd_, pbase(), static_cast<std::size_t>(pptr() - pbase()));
        setp(buffer_, buffer_ + sizeof buffer_);
        return error_ == 0 ? 0 : -1;
    }

  private:
    int fd_;
    int error_ = 0;
    char buffer_[1 << 16];
};

// Runs fill on a stream over fd, flushes it and closes fd; returns 0 or the first errno (EIO when the
// stream failed without one).
int fill_and_close(int fd, const std::function<void(std::ostream&)>& fill) {
    int error = 0;
    try {
        FdBuffer buffer(fd);
        std::ostream stream(&buffer);
        fill(stream);
        stream.flush();
        error = buffer.error() != 0 ? buffer.error() : !stream ? EIO : 0;
    } catch (...) {
        ::close(fd);
        throw;
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
    write_stream(path, [&text](std::ostream& out) {
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
    });
}

void write_stream(const std::string& path, const std::function<void(std::ostream&)>& fill) {
    if (is_special_file(path)) {
        const int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
        if (fd < 0) fail("write", path, errno);
        if (const int error = fill_and_close(fd, fill)) fail("write", path, error);
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
    int written = 0;
    try {
        written = fill_and_close(fd, fill); // closes fd, also when fill throws
    } catch (...) {
        ::unlink(temp.c_str());
        throw;
    }
    if (written != 0) {
        ::unlink(temp.c_str());
        fail("write", path, written);
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
