// `ctess serve` answers every client within a bound, however others behave (docs/cli.md, "Viewer server"):
// regressions for issue #23 items 2 (br cost) and 3 (slow clients, idle connections, backlog, pipelining).
#include "cli/serve_process.hpp"

#include <atomic>
#include <fcntl.h>
#include <thread>
#include <vector>

using namespace ctess::test;

namespace {

const char* const large_api = "/api/pattern?mode=cp&max=256&domain=quad&factors=256,256,256,256";
const char* const small_api = "/api/pattern?mode=cp&factors=4,4,4";

int count_of(const std::string& text, const std::string& part) {
    int n = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

} // namespace

TEST_CASE("serve: br is never chosen, gzip only up to 256 KiB, whatever the client accepts", "[cli][serve]") {
    const ServeProcess server;
    REQUIRE(server.port > 0);
    const int port = server.port;
    // The large pattern is about 5.7 MB of JSON; brotli quality 11 took 5-11 s on it, no coding about 0.1 s.
    const auto t0 = Clock::now();
    const Reply large = http(port, get(large_api, port, "Accept-Encoding: br, gzip, deflate\r\n"));
    const double large_s = seconds_since(t0);
    REQUIRE(large.status == 200);
    CHECK_FALSE(has(large.head, "Content-Encoding"));
    CHECK(large.body.size() > 256 * 1024);
    CHECK(large.body.rfind("{", 0) == 0);
    CHECK(large_s < 3.0);

    const Reply br_only = http(port, get(small_api, port, "Accept-Encoding: br\r\n"));
    CHECK(br_only.status == 200);
    CHECK_FALSE(has(br_only.head, "Content-Encoding"));
    CHECK(br_only.body.rfind("{", 0) == 0);

    const Reply gzip = http(port, get(small_api, port, "Accept-Encoding: br, gzip\r\n"));
    CHECK(gzip.status == 200);
    CHECK(has(gzip.head, "Content-Encoding: gzip"));
    CHECK(gzip.body.rfind("\x1f\x8b", 0) == 0); // the gzip magic (RFC 1952 §2.3.1)

    for (const char* refused : {"gzip;q=0", "gzip; q=0.000, br", "identity", "*;q=0", "gzip;q=0, *"}) {
        INFO("Accept-Encoding: " << refused);
        const Reply r =
            http(port, get("/viewer.js", port, std::string("Accept-Encoding: ") + refused + "\r\n"));
        CHECK(r.status == 200);
        CHECK_FALSE(has(r.head, "Content-Encoding"));
    }
    for (const char* accepted : {"gzip;q=0.5, br;q=1", "br, *", "GZIP"}) {
        INFO("Accept-Encoding: " << accepted);
        const Reply r =
            http(port, get("/viewer.js", port, std::string("Accept-Encoding: ") + accepted + "\r\n"));
        CHECK(has(r.head, "Content-Encoding: gzip"));
    }
}

TEST_CASE("serve: slow senders and 600 idle connections do not delay another client", "[cli][serve]") {
    const ServeProcess server;
    REQUIRE(server.port > 0);
    const int port = server.port;
    // 20 clients that send a request a byte every 0.5 s (the old server's 8 workers were held by 8 of
    // them)...
    std::atomic<bool> stop{false};
    std::vector<std::thread> slow;
    for (int k = 0; k < 20; ++k)
        slow.emplace_back([&, port] {
            const int s = connect_loopback(port);
            const std::string request = get("/index.html", port);
            for (std::size_t i = 0; s >= 0 && i < request.size() && !stop; ++i) {
                if (::send(s, &request[i], 1, MSG_NOSIGNAL) != 1) break;
                for (int t = 0; t < 5 && !stop; ++t)
                    std::this_thread::sleep_for(std::chrono::milliseconds(100));
            }
            if (s >= 0) ::close(s);
        });
    // ...and more idle connections than the server keeps open (512).
    std::vector<int> idle;
    for (int k = 0; k < 600; ++k) idle.push_back(connect_loopback(port));
    std::this_thread::sleep_for(std::chrono::milliseconds(500));

    double worst = 0;
    for (int k = 0; k < 20; ++k) {
        const auto t0 = Clock::now();
        const Reply r = http(port, get(k % 2 ? "/viewer.css" : small_api, port));
        worst = std::max(worst, seconds_since(t0));
        CHECK(r.status == 200);
        CHECK_FALSE(r.body.empty());
    }
    stop = true;
    for (auto& t : slow) t.join();
    for (const int s : idle)
        if (s >= 0) ::close(s);
    WARN("slowest of 20 requests among 20 slow and 600 idle clients: " << worst << " s");
    CHECK(worst < 1.0);
    CHECK(server.alive());
}

TEST_CASE("serve: the listen backlog holds 200 connections while the server is not accepting",
          "[cli][serve]") {
    const ServeProcess server;
    REQUIRE(server.port > 0);
    // Stopped, the server accepts nothing: the kernel completes handshakes into the backlog only (it was 5).
    REQUIRE(::kill(server.pid, SIGSTOP) == 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<std::uint16_t>(server.port));
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    std::vector<pollfd> pending;
    for (int k = 0; k < 200; ++k) {
        const int s = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
        REQUIRE(s >= 0);
        ::connect(s, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
        pending.push_back({s, POLLOUT, 0});
    }
    int connected = 0;
    const auto t0 = Clock::now();
    while (connected < 200 && seconds_since(t0) < 0.5) {
        ::poll(pending.data(), pending.size(), 50);
        connected = 0;
        for (const auto& p : pending) {
            int err = 1;
            socklen_t len = sizeof err;
            if ((p.revents & POLLOUT) && ::getsockopt(p.fd, SOL_SOCKET, SO_ERROR, &err, &len) == 0 &&
                err == 0)
                ++connected;
        }
    }
    ::kill(server.pid, SIGCONT);
    for (const auto& p : pending) ::close(p.fd);
    CHECK(connected == 200);
    CHECK(http(server.port, get("/viewer.css", server.port)).status == 200);
}

TEST_CASE("serve: pipelined requests are all answered, in order", "[cli][serve]") {
    const ServeProcess server;
    REQUIRE(server.port > 0);
    const int port = server.port;
    const int s = connect_loopback(port);
    REQUIRE(s >= 0);
    // Three requests in one write (the old server answered the first and dropped the rest).
    REQUIRE(send_all(s, get("/viewer.css", port, "", "keep-alive") + get(small_api, port, "", "keep-alive") +
                            get("/index.html", port)));
    const std::string all = recv_all(s);
    ::close(s);
    CHECK(count_of(all, "HTTP/1.1 200 OK\r\n") == 3);
    const std::size_t css = all.find("Content-Type: text/css");
    const std::size_t json = all.find("Content-Type: application/json");
    const std::size_t html = all.find("Content-Type: text/html");
    CHECK(css < json);
    CHECK(json < html);
    CHECK(html != std::string::npos);
}

TEST_CASE("serve: oversized heads and bodies, and chunked bodies, get 431, 413 and 501", "[cli][serve]") {
    const ServeProcess server;
    REQUIRE(server.port > 0);
    const int port = server.port;
    CHECK(http(port, get("/viewer.css", port, "X-Pad: " + std::string(20000, 'a') + "\r\n")).status == 431);
    CHECK(http(port, get("/viewer.css", port, "Content-Length: 100000\r\n")).status == 413);
    CHECK(http(port, get("/viewer.css", port, "Content-Length: 1\r\nContent-Length: 1\r\n") + "xx").status ==
          400);
    CHECK(http(port, get("/viewer.css", port, "Content-Length: -1\r\n")).status == 400);
    CHECK(http(port, get("/viewer.css", port, "Transfer-Encoding: chunked\r\n") + "0\r\n\r\n").status == 501);
    // A body within the bound is read and the request answered.
    CHECK(http(port, get("/viewer.css", port, "Content-Length: 5\r\n") + "hello").status == 200);
    CHECK(server.alive());
}
