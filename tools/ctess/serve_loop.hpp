// The connection loop under `ctess serve` (docs/cli.md, "Viewer server"): one poll() thread reads every
// connection's request until it is whole, and only whole requests reach the worker threads, so a slow or idle
// client holds a buffer, never a worker. httplib (0.11.4) still parses, routes and writes each request,
// through its protected Server::process_request; what it could not bound (a byte every few seconds keeps its
// read timeout alive, 8 workers, backlog 5, pipelined requests dropped) is done here.
#pragma once

#include <httplib.h>

#include <chrono>
#include <cstddef>
#include <string>
#include <string_view>

namespace ctess::cli {

// Every bound the loop enforces; docs/cli.md lists them with the figures they give.
struct ServeLimits {
    std::size_t max_connections = 512;    // open at once; a new one closes the longest-waiting non-busy one
    std::size_t max_request_head = 16384; // request line and headers, bytes (431 beyond)
    std::size_t max_request_body = 65536; // Content-Length bytes (413 beyond; chunked bodies get 501)
    // POST /api/model, /api/height-map and /api/vector-map (upload_target): their bodies may be this large
    // (413 beyond), and at most max_uploads of them are buffered or being answered at once (503 beyond), so
    // uploads bound memory.
    std::size_t max_upload_body = std::size_t{64} << 20;
    std::size_t max_uploads = 2;
    std::chrono::milliseconds request_deadline{10000}; // a whole request must arrive within this (408/close)
    std::chrono::milliseconds write_deadline{10000};   // the client must take a whole response within this
    unsigned file_workers = 4;                         // static files and refusals
    unsigned api_workers = 3;     // /api/ answers above small factors, so they cannot queue ahead of files
    std::size_t max_queued = 256; // whole requests waiting for a worker, per lane (503 beyond)
    std::size_t max_requests_per_connection = 1000;
    int listen_backlog = 1024; // the kernel caps it at net.core.somaxconn
};

// Whether a request line's method and target are an upload (POST /api/model, /api/height-map or
// /api/vector-map, any query).
bool upload_target(std::string_view method, std::string_view target);

// The server's Host and Origin rule (docs/cli.md, "Viewer server"), shared by the loop (uploads, before
// their bodies are buffered) and cmd_serve.cpp's pre-routing handler (every request): Host must be a loopback
// name with an optional port, and a request other than GET or HEAD that carries an Origin must come from a
// loopback http origin, so a DNS-rebound page on another name cannot read or post. `origin` is nullptr when
// the request has none. Returns nullptr when allowed, else why it is refused (ASCII, no quotes).
const char* foreign_request(std::string_view method, std::string_view host, const std::string_view* origin);

// Whether a buffered request (its request line may still be partial) is for an /api/ target, whose refusals
// are JSON.
bool api_request(std::string_view in);

// An httplib::Server whose routes are set as usual, served by the loop above instead of httplib's listen().
class BoundedServer : public httplib::Server {
  public:
    // The Keep-Alive header httplib writes states the loop's bounds.
    explicit BoundedServer(ServeLimits limits = {}) : limits_(limits) {
        set_keep_alive_max_count(limits.max_requests_per_connection);
        set_keep_alive_timeout(
            std::chrono::duration_cast<std::chrono::seconds>(limits.request_deadline).count());
    }

    // Binds and listens on host:port (port 0: a free port); returns the bound port, or -1.
    int bind_and_listen(const std::string& host, unsigned port);

    // Serves until the process is signalled. Returns false only before serving (no listening socket, no wake
    // pipe); once the workers run it never returns, and a failure of the loop itself ends the process (exit
    // 1).
    bool serve_forever();

    const ServeLimits& limits() const { return limits_; }

  private:
    friend struct ServeWorker;
    // One whole request, answered by httplib on this thread; returns whether the connection stays open.
    bool answer(int fd, const std::string& request, bool last, const std::string& peer_ip, int peer_port);

    ServeLimits limits_;
    int listen_fd_ = -1;
    int port_ = 0;
};

} // namespace ctess::cli
