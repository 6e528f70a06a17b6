// The bounded connection loop of `ctess serve` (serve_loop.hpp; docs/cli.md, "Viewer server").
#include "serve_loop.hpp"

#include <algorithm>
#include <arpa/inet.h>
#include <cctype>
#include <cerrno>
#include <condition_variable>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fcntl.h>
#include <list>
#include <mutex>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <string_view>
#include <sys/resource.h>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>
#include <unordered_map>
#include <vector>

namespace ctess::cli {

namespace {

using Clock = std::chrono::steady_clock;

// One request as httplib reads it: exactly the buffered bytes of this request (a pipelined next request stays
// with the loop), and writes that give up at the response's deadline. The deadline starts at the first write,
// so a model that takes longer than it to prepare is still sent.
class RequestStream final : public httplib::Stream {
  public:
    RequestStream(int fd, const std::string& request, std::string peer_ip, int peer_port, int local_port,
                  std::chrono::milliseconds write_deadline)
        : fd_(fd), request_(request), peer_ip_(std::move(peer_ip)), peer_port_(peer_port),
          local_port_(local_port), write_deadline_(write_deadline) {}

    bool is_readable() const override { return read_at_ < request_.size(); }
    bool is_writable() const override { return !failed_ && Clock::now() < deadline(); }

    ssize_t read(char* ptr, size_t size) override {
        const std::size_t n = std::min(size, request_.size() - read_at_);
        std::memcpy(ptr, request_.data() + read_at_, n);
        read_at_ += n;
        return static_cast<ssize_t>(n);
    }

    ssize_t write(const char* ptr, size_t size) override {
        for (std::size_t sent = 0; sent < size && !failed_;) {
            const ssize_t n = ::send(fd_, ptr + sent, size - sent, MSG_NOSIGNAL);
            if (n > 0) {
                sent += static_cast<std::size_t>(n);
                continue;
            }
            if (n < 0 && errno == EINTR) continue;
            const auto left =
                std::chrono::duration_cast<std::chrono::milliseconds>(deadline() - Clock::now()).count();
            pollfd p{fd_, POLLOUT, 0};
            if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK) && left > 0 &&
                ::poll(&p, 1, static_cast<int>(left)) > 0)
                continue;
            failed_ = true; // the client went away or did not read the response in time
        }
        return failed_ ? -1 : static_cast<ssize_t>(size);
    }

    void get_remote_ip_and_port(std::string& ip, int& port) const override {
        ip = peer_ip_;
        port = peer_port_;
    }
    void get_local_ip_and_port(std::string& ip, int& port) const override {
        ip = "127.0.0.1";
        port = local_port_;
    }
    socket_t socket() const override { return fd_; }

    bool failed() const { return failed_; }

  private:
    int fd_;
    const std::string& request_;
    std::size_t read_at_ = 0;
    std::string peer_ip_;
    int peer_port_;
    int local_port_;
    Clock::time_point deadline() const {
        if (!writing_) deadline_ = Clock::now() + write_deadline_;
        writing_ = true;
        return deadline_;
    }

    std::chrono::milliseconds write_deadline_;
    mutable Clock::time_point deadline_;
    mutable bool writing_ = false;
    bool failed_ = false;
};

bool iequals(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

// Whether a target may cost more than a small file: /api/ requests, except patterns whose factors are all
// numbers up to 32 (their answers are at most a few tens of KB). The costly lane has its own workers, so a
// queue of large patterns never delays a small one.
bool costly_target(std::string_view target) {
    if (target.substr(0, 5) != "/api/") return false;
    const std::size_t query = target.find('?');
    if (query == std::string_view::npos) return true;
    std::string_view factors;
    for (std::string_view rest = target.substr(query + 1); !rest.empty();) {
        const std::size_t amp = rest.find('&');
        const std::string_view param = rest.substr(0, amp);
        rest = amp == std::string_view::npos ? std::string_view() : rest.substr(amp + 1);
        if (param.substr(0, 8) == "factors=") factors = param.substr(8);
    }
    if (factors.empty()) return true;
    // Tokens end at ',' or its escape "%2C".
    std::string token;
    for (std::size_t at = 0; at <= factors.size(); ++at) {
        const bool comma = at < factors.size() && factors[at] == ',';
        const bool escaped = factors.substr(at, 3) == "%2C" || factors.substr(at, 3) == "%2c";
        if (at < factors.size() && !comma && !escaped) {
            token += factors[at];
            continue;
        }
        char* stop = nullptr;
        const double value = token.empty() ? 0 : std::strtod(token.c_str(), &stop);
        if (token.empty() || *stop != '\0' || !(value <= 32)) return true;
        token.clear();
        if (escaped) at += 2;
    }
    return false;
}

// What the loop learns from a buffered request before a worker sees it.
struct Framing {
    enum class Kind { incomplete, whole, refuse } kind = Kind::incomplete;
    std::size_t size = 0;         // head and body bytes, when whole
    int status = 0;               // when refused
    bool api = false;             // costly_target: the /api/ lane
    bool json = false;            // an /api/ target: a refusal is {"error": ...}
    bool upload = false;          // upload_target: the larger body bound, one of the upload slots
    const char* why = "";         // when refused for a reason the status does not say
    bool expect_continue = false; // Expect: 100-continue
};

// Finds where the first buffered request ends (RFC 9112 §6: Content-Length frames a request body; a request
// with Transfer-Encoding is refused, as nothing here takes a body that large). A Content-Encoding is refused
// too: httplib would decompress the body into memory without a bound (203 bytes of brotli became 268 MB). An
// upload's Host and Origin are checked here, before its body is buffered or it takes a slot.
Framing frame_request(std::string_view in, const ServeLimits& limits) {
    Framing f;
    const std::size_t head_end = in.find("\r\n\r\n");
    if (head_end == std::string_view::npos || head_end + 4 > limits.max_request_head) {
        if (in.size() >= limits.max_request_head) f = {Framing::Kind::refuse, 0, 431, false};
        return f;
    }
    const std::string_view head = in.substr(0, head_end + 2);
    const std::size_t line_end = head.find("\r\n");
    const std::string_view line = head.substr(0, line_end);
    const std::size_t sp = line.find(' ');
    if (sp != std::string_view::npos) {
        std::string_view target = line.substr(sp + 1);
        target = target.substr(0, target.find(' '));
        f.upload = upload_target(line.substr(0, sp), target);
        f.api = costly_target(target) || f.upload; // an upload's factors= query does not make it cheap
        f.json = target.substr(0, 5) == "/api/";
    }
    const auto refused = [&](int status, const char* why = "") {
        Framing r = f;
        r.kind = Framing::Kind::refuse;
        r.status = status;
        r.why = why;
        return r;
    };
    std::size_t body = 0;
    bool has_length = false;
    std::string_view host, origin;
    bool has_host = false, has_origin = false;
    for (std::size_t at = line_end + 2; at < head.size();) {
        const std::size_t end = head.find("\r\n", at);
        const std::string_view field = head.substr(at, end - at);
        at = end + 2;
        const std::size_t colon = field.find(':');
        if (colon == std::string_view::npos) continue; // httplib answers malformed lines itself
        const std::string_view name = field.substr(0, colon);
        const std::string_view value = trim(field.substr(colon + 1));
        if (iequals(name, "Transfer-Encoding")) return refused(501);
        if (iequals(name, "Content-Encoding")) return refused(415, "request bodies are taken uncompressed");
        if (iequals(name, "Expect") && iequals(value, "100-continue")) f.expect_continue = true;
        // The first of each, as httplib's get_header_value reads them.
        if (iequals(name, "Host") && !has_host) {
            has_host = true;
            host = value;
        }
        if (iequals(name, "Origin") && !has_origin) {
            has_origin = true;
            origin = value;
        }
        if (!iequals(name, "Content-Length")) continue;
        if (has_length || value.empty() || value.size() > 9 ||
            value.find_first_not_of("0123456789") != std::string_view::npos)
            return refused(400);
        has_length = true;
        body = static_cast<std::size_t>(std::stoul(std::string(value)));
    }
    if (f.upload)
        if (const char* why = foreign_request(line.substr(0, sp), host, has_origin ? &origin : nullptr))
            return refused(403, why);
    if (body > (f.upload ? limits.max_upload_body : limits.max_request_body)) return refused(413);
    f.size = head_end + 4 + body;
    f.kind = in.size() >= f.size ? Framing::Kind::whole : Framing::Kind::incomplete;
    return f;
}

const char* reason(int status) {
    switch (status) {
    case 400:
        return "Bad Request";
    case 408:
        return "Request Timeout";
    case 403:
        return "Forbidden";
    case 413:
        return "Content Too Large";
    case 415:
        return "Unsupported Media Type";
    case 431:
        return "Request Header Fields Too Large";
    case 501:
        return "Not Implemented";
    default:
        return "Service Unavailable";
    }
}

// The loop's own refusals: small enough for the socket buffer, sent once without waiting, then the socket
// is closed. An /api/ target gets {"error": "..."} as the endpoints' own errors (docs/cli.md), with `detail`
// (ASCII, no quotes) saying which bound it passed.
void refuse_and_close(int fd, int status, bool json = false, const std::string& detail = "") {
    const std::string text =
        std::string("ctess serve: ") + reason(status) + (detail.empty() ? "" : ": " + detail);
    const std::string body = json ? "{\"error\": \"" + text + "\"}\n" : text + "\n";
    const std::string reply = "HTTP/1.1 " + std::to_string(status) + " " + reason(status) +
                              "\r\nContent-Type: " + (json ? "application/json" : "text/plain") +
                              "\r\nContent-Length: " + std::to_string(body.size()) +
                              "\r\nConnection: close\r\n\r\n" + body;
    [[maybe_unused]] const ssize_t n = ::send(fd, reply.data(), reply.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
    ::shutdown(fd, SHUT_WR);
    // Unread input makes close() send a reset, which can discard the answer before the client reads it.
    char drain[16384];
    for (int k = 0; k < 16 && ::recv(fd, drain, sizeof drain, MSG_DONTWAIT) > 0; ++k) {
    }
    ::close(fd);
}

} // namespace

bool api_request(std::string_view in) {
    const std::size_t sp = in.find(' ');
    return sp != std::string_view::npos && in.substr(sp + 1, 5) == "/api/";
}

namespace {

bool is_loopback_authority(std::string_view a) {
    for (const std::string_view name : {"127.0.0.1", "localhost", "[::1]"}) {
        if (a.substr(0, name.size()) != name) continue;
        const std::string_view rest = a.substr(name.size());
        if (rest.empty()) return true;
        if (rest[0] != ':' || rest.size() < 2 || rest.size() > 6) return false;
        return rest.substr(1).find_first_not_of("0123456789") == std::string_view::npos;
    }
    return false;
}

bool is_loopback_origin(std::string_view origin) {
    constexpr std::string_view scheme = "http://";
    return origin.substr(0, scheme.size()) == scheme && is_loopback_authority(origin.substr(scheme.size()));
}

} // namespace

const char* foreign_request(std::string_view method, std::string_view host, const std::string_view* origin) {
    if (!is_loopback_authority(host)) return "Host must be 127.0.0.1, localhost or [::1]";
    if (method != "GET" && method != "HEAD" && origin && !is_loopback_origin(*origin))
        return "Origin must be a loopback http origin";
    return nullptr;
}

bool upload_target(std::string_view method, std::string_view target) {
    const std::string_view path = target.substr(0, target.find('?'));
    return method == "POST" &&
           (path == "/api/model" || path == "/api/height-map" || path == "/api/vector-map");
}

// A worker lane: a bounded queue of whole requests and its threads.
struct ServeWorker {
    struct Job {
        int fd;
        std::string request;
        bool last;
        std::string peer_ip;
        int peer_port;
    };
    struct Done {
        int fd;
        bool keep_open;
    };

    BoundedServer& server;
    std::mutex& done_mutex;
    std::vector<Done>& done;
    int wake_fd;
    std::mutex mutex;
    std::condition_variable ready;
    std::deque<Job> jobs;
    std::vector<std::thread> threads;

    ServeWorker(BoundedServer& s, std::mutex& dm, std::vector<Done>& d, int wake, unsigned count)
        : server(s), done_mutex(dm), done(d), wake_fd(wake) {
        for (unsigned i = 0; i < count; ++i) threads.emplace_back([this] { run(); });
    }
    ServeWorker(const ServeWorker&) = delete;
    ServeWorker& operator=(const ServeWorker&) = delete;

    bool push(Job job) {
        {
            const std::lock_guard<std::mutex> lock(mutex);
            if (jobs.size() >= server.limits().max_queued) return false;
            jobs.push_back(std::move(job));
        }
        ready.notify_one();
        return true;
    }

    void run() {
        for (;;) {
            Job job;
            {
                std::unique_lock<std::mutex> lock(mutex);
                ready.wait(lock, [this] { return !jobs.empty(); });
                job = std::move(jobs.front());
                jobs.pop_front();
            }
            const bool keep = server.answer(job.fd, job.request, job.last, job.peer_ip, job.peer_port);
            {
                const std::lock_guard<std::mutex> lock(done_mutex);
                done.push_back({job.fd, keep});
            }
            const char byte = 1;
            [[maybe_unused]] const ssize_t n = ::write(wake_fd, &byte, 1);
        }
    }
};

bool BoundedServer::answer(int fd, const std::string& request, bool last, const std::string& peer_ip,
                           int peer_port) {
    RequestStream stream(fd, request, peer_ip, peer_port, port_, limits_.write_deadline);
    bool closed = false;
    const bool ok = process_request(stream, last, closed, nullptr);
    return ok && !closed && !last && !stream.failed();
}

int BoundedServer::bind_and_listen(const std::string& host, unsigned port) {
    listen_fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
    if (listen_fd_ < 0) return -1;
    // SO_REUSEADDR only: SO_REUSEPORT would let a second server share a busy port.
    int yes = 1;
    ::setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<std::uint16_t>(port));
    if (::inet_pton(AF_INET, host.c_str(), &addr.sin_addr) != 1 ||
        ::bind(listen_fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 ||
        ::listen(listen_fd_, limits_.listen_backlog) != 0) {
        ::close(listen_fd_);
        listen_fd_ = -1;
        return -1;
    }
    socklen_t len = sizeof addr;
    ::getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&addr), &len);
    port_ = ntohs(addr.sin_port);
    return port_;
}

bool BoundedServer::serve_forever() {
    if (listen_fd_ < 0) return false;
    std::signal(SIGPIPE, SIG_IGN); // sends use MSG_NOSIGNAL; this covers anything httplib writes itself
    int wake[2];
    if (::pipe2(wake, O_CLOEXEC | O_NONBLOCK) != 0) return false;

    // Every open connection needs a descriptor: raise the soft limit toward the cap, or lower the cap to fit
    // (an accept that fails for lack of descriptors would leave the listening socket readable forever).
    constexpr rlim_t spare_fds = 64;
    rlimit files_limit{};
    if (::getrlimit(RLIMIT_NOFILE, &files_limit) == 0) {
        const rlim_t wanted = limits_.max_connections + spare_fds;
        if (files_limit.rlim_cur < wanted) {
            files_limit.rlim_cur = std::min(wanted, files_limit.rlim_max);
            ::setrlimit(RLIMIT_NOFILE, &files_limit);
            ::getrlimit(RLIMIT_NOFILE, &files_limit);
        }
        if (files_limit.rlim_cur < wanted)
            limits_.max_connections =
                files_limit.rlim_cur > 2 * spare_fds ? files_limit.rlim_cur - spare_fds : 16;
    }

    // The lanes and what they share live until the process ends (it ends by a signal, with workers blocked in
    // their queues), so they are never destroyed under a running worker.
    std::mutex& done_mutex = *new std::mutex;
    std::vector<ServeWorker::Done>& done = *new std::vector<ServeWorker::Done>;
    ServeWorker& files = *new ServeWorker(*this, done_mutex, done, wake[1], limits_.file_workers);
    ServeWorker& api = *new ServeWorker(*this, done_mutex, done, wake[1], limits_.api_workers);

    struct Connection {
        std::string in; // received and not yet answered: may hold the start of a pipelined request
        Clock::time_point deadline;
        std::list<int>::iterator waiting; // position in `order` while not busy
        bool busy = false;
        std::size_t answered = 0;
        std::string peer_ip;
        int peer_port = 0;
        bool upload = false;    // holds an upload slot: its request is being buffered or answered
        bool continued = false; // 100 Continue sent for the request being buffered
    };
    std::unordered_map<int, Connection> connections;
    std::size_t uploads = 0; // upload slots held
    std::list<int> order; // non-busy connections, longest-waiting first: the one a new connection displaces

    const auto release_upload = [&](Connection& c) {
        if (c.upload) --uploads;
        c.upload = false;
    };
    const auto close_connection = [&](int fd, int status, bool json = false, const std::string& detail = "") {
        Connection& c = connections.at(fd);
        if (!c.busy) order.erase(c.waiting);
        release_upload(c);
        if (status)
            refuse_and_close(fd, status, json, detail);
        else
            ::close(fd);
        connections.erase(fd);
    };
    const auto start_waiting = [&](int fd, Connection& c) {
        c.busy = false;
        c.deadline = Clock::now() + limits_.request_deadline;
        c.waiting = order.insert(order.end(), fd);
    };
    // Hands the first buffered request to its lane once it is whole.
    const auto dispatch = [&](int fd) {
        Connection& c = connections.at(fd);
        const Framing f = frame_request(c.in, limits_);
        if (f.kind == Framing::Kind::refuse) {
            const std::size_t limit = f.upload ? limits_.max_upload_body : limits_.max_request_body;
            return close_connection(
                fd, f.status, f.json,
                f.status == 413 ? "the body is larger than " + std::to_string(limit) + " bytes" : f.why);
        }
        // An upload takes a slot as soon as its head says so, before its body is buffered.
        if (f.upload && !c.upload) {
            if (uploads >= limits_.max_uploads)
                return close_connection(fd, 503, f.json,
                                        std::to_string(uploads) + " uploads are in progress, try again");
            c.upload = true;
            ++uploads;
        }
        if (f.kind == Framing::Kind::incomplete) {
            // The body's size is known: one allocation of it, where growing by doubling could reach twice.
            if (f.size > c.in.capacity()) c.in.reserve(f.size);
            // The head passed every check here (an upload holds its slot): a client waiting for 100 Continue
            // (curl does, a second, for bodies over 1 MiB) may send the body now. httplib writes its own 100
            // once the request is whole; clients skip a second interim answer.
            if (f.expect_continue && !c.continued && f.size > 0 && c.in.find("\r\n\r\n") + 4 == c.in.size()) {
                constexpr std::string_view go = "HTTP/1.1 100 Continue\r\n\r\n";
                [[maybe_unused]] const ssize_t n =
                    ::send(fd, go.data(), go.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
                c.continued = true;
            }
            return;
        }
        c.continued = false;
        const bool last = c.answered + 1 >= limits_.max_requests_per_connection;
        ServeWorker::Job job{fd, {}, last, c.peer_ip, c.peer_port};
        if (c.in.size() == f.size) {
            job.request = std::move(c.in); // no copy of an upload; its buffer goes with the job
            c.in = std::string();
        } else {
            job.request = c.in.substr(0, f.size);
            c.in.erase(0, f.size);
            // A kept-alive connection must not keep an upload's buffer: only the next request's bytes stay.
            if (c.in.capacity() > 2 * limits_.max_request_head + limits_.max_request_body)
                c.in = std::string(c.in);
        }
        if (!(f.api ? api : files).push(std::move(job))) return close_connection(fd, 503);
        ++c.answered;
        order.erase(c.waiting);
        c.busy = true;
    };

    std::vector<pollfd> polled;
    std::vector<char> buf(std::size_t{1} << 16); // one receive; uploads arrive in these steps
    for (;;) {
        polled.clear();
        polled.push_back({listen_fd_, POLLIN, 0});
        polled.push_back({wake[0], POLLIN, 0});
        Clock::time_point next = Clock::now() + std::chrono::seconds(1);
        for (const auto& [fd, c] : connections)
            if (!c.busy) {
                polled.push_back({fd, POLLIN, 0});
                next = std::min(next, c.deadline);
            }
        const auto wait =
            std::chrono::duration_cast<std::chrono::milliseconds>(next - Clock::now()).count() + 1;
        if (::poll(polled.data(), polled.size(), static_cast<int>(std::max<long long>(wait, 0))) < 0 &&
            errno != EINTR) {
            // Workers may be inside a handler that holds this server: returning would let the caller destroy
            // it under them. The loop failing ends the process.
            std::perror("ctess serve: poll");
            std::fflush(nullptr);
            std::_Exit(1);
        }

        // Answered requests: the connection waits for its next request, which may already be buffered.
        if (polled[1].revents) {
            char drain[256];
            while (::read(wake[0], drain, sizeof drain) > 0) {
            }
            std::vector<ServeWorker::Done> finished;
            {
                const std::lock_guard<std::mutex> lock(done_mutex);
                finished.swap(done);
            }
            for (const auto& d : finished) {
                Connection& c = connections.at(d.fd);
                release_upload(c);
                start_waiting(d.fd, c);
                if (!d.keep_open)
                    close_connection(d.fd, 0);
                else
                    dispatch(d.fd);
            }
        }

        for (std::size_t i = 2; i < polled.size(); ++i) {
            if (!polled[i].revents) continue;
            const int fd = polled[i].fd;
            const auto it = connections.find(fd);
            if (it == connections.end() || it->second.busy) continue;
            Connection& c = it->second;
            // One byte past the bound, so that frame_request sees a request too large and refuses it.
            const std::size_t limit =
                limits_.max_request_head + (c.upload ? limits_.max_upload_body : limits_.max_request_body);
            const std::size_t room = limit > c.in.size() ? limit - c.in.size() : 0;
            const ssize_t n = ::recv(fd, buf.data(), std::min(buf.size(), room + 1), 0);
            if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
                close_connection(fd, 0);
                continue;
            }
            if (n > 0) c.in.append(buf.data(), static_cast<std::size_t>(n));
            dispatch(fd);
        }

        // Whole requests must arrive by their deadline, however slowly the bytes came: an idle connection
        // is closed, a partial request gets 408.
        const auto now = Clock::now();
        std::vector<int> late;
        for (const auto& [fd, c] : connections)
            if (!c.busy && c.deadline <= now) late.push_back(fd);
        for (const int fd : late) {
            const std::string_view in = connections.at(fd).in;
            close_connection(fd, in.empty() ? 0 : 408, api_request(in));
        }

        if (polled[0].revents) {
            for (;;) {
                sockaddr_in peer{};
                socklen_t len = sizeof peer;
                const int fd = ::accept4(listen_fd_, reinterpret_cast<sockaddr*>(&peer), &len,
                                         SOCK_CLOEXEC | SOCK_NONBLOCK);
                if (fd < 0) break; // EAGAIN, or out of descriptors: the rest wait in the backlog
                if (connections.size() >= limits_.max_connections) {
                    if (order.empty()) {
                        refuse_and_close(fd, 503);
                        continue;
                    }
                    close_connection(order.front(), 503);
                }
                int one = 1;
                ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
                char ip[INET_ADDRSTRLEN] = {};
                ::inet_ntop(AF_INET, &peer.sin_addr, ip, sizeof ip);
                Connection& c = connections[fd];
                c.peer_ip = ip;
                c.peer_port = ntohs(peer.sin_port);
                start_waiting(fd, c);
            }
        }
    }
}

} // namespace ctess::cli
