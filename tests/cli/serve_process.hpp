// `ctess serve` in a child process on a free loopback port, and a raw HTTP/1.1 client for the serve tests
// (test_serve_bounds.cpp, test_serve_load.cpp). Raw sockets, so a test controls every byte and every pause.
#pragma once
#include <catch2/catch.hpp>

#include <arpa/inet.h>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <netinet/in.h>
#include <poll.h>
#include <string>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

namespace ctess::test {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// `ctess serve --port 0`, stopped (SIGTERM) when this goes out of scope; port is 0 if it did not start.
struct ServeProcess {
    pid_t pid = -1;
    int port = 0;
    std::string shaders;

    ServeProcess() {
        shaders = (std::filesystem::temp_directory_path() /
                   ("ctess_serve_" + std::to_string(::getpid()) + "_shaders"))
                      .string();
        std::filesystem::create_directories(shaders);
        int fds[2];
        REQUIRE(::pipe(fds) == 0);
        pid = ::fork();
        REQUIRE(pid >= 0);
        if (pid == 0) {
            ::dup2(fds[1], 1);
            ::close(fds[0]);
            ::close(fds[1]);
            ::execl(CTESS_CLI, "ctess", "serve", "--port", "0", "--shaders", shaders.c_str(), nullptr);
            ::_exit(127);
        }
        ::close(fds[1]);
        // The first line names the bound port; wait at most 10 s for it.
        std::string line;
        pollfd p{fds[0], POLLIN, 0};
        while (line.find('\n') == std::string::npos && ::poll(&p, 1, 10'000) > 0) {
            char buf[256];
            const ssize_t n = ::read(fds[0], buf, sizeof buf);
            if (n <= 0) break;
            line.append(buf, static_cast<std::size_t>(n));
        }
        ::close(fds[0]);
        const std::size_t at = line.find("127.0.0.1:");
        if (at != std::string::npos) port = std::atoi(line.c_str() + at + 10);
    }
    ~ServeProcess() {
        if (pid > 0) {
            ::kill(pid, SIGCONT); // a test may have stopped it
            ::kill(pid, SIGTERM);
            ::waitpid(pid, nullptr, 0);
        }
        std::filesystem::remove_all(shaders);
    }
    ServeProcess(const ServeProcess&) = delete;
    ServeProcess& operator=(const ServeProcess&) = delete;

    // Still running (not exited, not killed)?
    bool alive() const { return pid > 0 && ::waitpid(pid, nullptr, WNOHANG) == 0; }

    // The server's peak resident set (VmHWM), in KiB; 0 if unreadable.
    long peak_rss_kib() const { return status_kib("VmHWM:"); }
    // Its resident set now (VmRSS), in KiB.
    long rss_kib() const { return status_kib("VmRSS:"); }

    long status_kib(const std::string& field) const {
        std::ifstream status("/proc/" + std::to_string(pid) + "/status");
        std::string key;
        while (status >> key) {
            if (key == field) {
                long kib = 0;
                status >> kib;
                return kib;
            }
            std::getline(status, key);
        }
        return 0;
    }
};

// A TCP connection to 127.0.0.1:port (blocking, each send/recv bounded by `timeout_s`); -1 if refused.
inline int connect_loopback(int port, int timeout_s = 10) {
    const int s = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (s < 0) return -1;
    timeval tv{timeout_s, 0};
    ::setsockopt(s, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
    ::setsockopt(s, SOL_SOCKET, SO_SNDTIMEO, &tv, sizeof tv);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<std::uint16_t>(port));
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(s, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
        ::close(s);
        return -1;
    }
    return s;
}

inline bool send_all(int s, const std::string& bytes) {
    for (std::size_t sent = 0; sent < bytes.size();) {
        const ssize_t n = ::send(s, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
        if (n <= 0) return false;
        sent += static_cast<std::size_t>(n);
    }
    return true;
}

// Everything the peer sends until it closes (or a recv times out, or `limit` bytes).
inline std::string recv_all(int s, std::size_t limit = 64u << 20) {
    std::string all;
    char buf[65536];
    ssize_t n = 0;
    while (all.size() < limit && (n = ::recv(s, buf, sizeof buf, 0)) > 0)
        all.append(buf, static_cast<std::size_t>(n));
    return all;
}

struct Reply {
    int status = 0;
    std::string head, body;
};

inline Reply parse_reply(const std::string& all) {
    Reply r;
    const std::size_t end = all.find("\r\n\r\n");
    r.head = all.substr(0, end);
    if (end != std::string::npos) r.body = all.substr(end + 4);
    if (all.rfind("HTTP/1.1 ", 0) == 0) r.status = std::atoi(all.c_str() + 9);
    return r;
}

// One reply on a kept-alive connection: its head, then Content-Length bytes of body.
inline Reply recv_reply(int s) {
    std::string all;
    char buf[65536];
    for (;;) {
        const std::size_t end = all.find("\r\n\r\n");
        if (end != std::string::npos) {
            const std::size_t at = all.find("Content-Length: ");
            const std::size_t length = at < end ? std::strtoul(all.c_str() + at + 16, nullptr, 10) : 0;
            if (all.size() >= end + 4 + length) return parse_reply(all);
        }
        const ssize_t n = ::recv(s, buf, sizeof buf, 0);
        if (n <= 0) return parse_reply(all);
        all.append(buf, static_cast<std::size_t>(n));
    }
}

// One request on its own connection (the request should say Connection: close).
inline Reply http(int port, const std::string& request, int timeout_s = 10) {
    const int s = connect_loopback(port, timeout_s);
    if (s < 0) return {};
    // A refused request may be cut short by the server: read its answer even if the rest could not be sent.
    send_all(s, request);
    const Reply r = parse_reply(recv_all(s));
    ::close(s);
    return r;
}

inline std::string get(const std::string& target, int port, const std::string& extra = "",
                       const char* connection = "close") {
    return "GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n" + extra +
           "Connection: " + connection + "\r\n\r\n";
}

inline bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace ctess::test
