// ctess serve: the browser viewer (viewer/) with the build's generated shaders and table blobs, on 127.0.0.1
// only, plus /api/pattern, which answers a `pattern` request with the same JSON as `ctess pattern --format
// json` (the viewer's D3D11 and uniform modes and its ratio to D3D11 fractional_even come from there;
// docs/viewer.md).
#include "cli_args.hpp"
#include "commands.hpp"
#include "json_escape.hpp"
#include "mesh.hpp"
#include "mesh_formats.hpp"

#include <httplib.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <string_view>

#include <fmt/core.h>

namespace ctess::cli {

namespace {

// The query's keys become `pattern` options, so the endpoint validates exactly as the CLI does.
std::string pattern_json(const httplib::Request& req) {
    std::vector<std::string> words = {"ctess", "pattern"};
    for (const char* key : {"mode", "domain", "factors", "winding", "max", "layout", "column-rule"})
        if (req.has_param(key)) {
            words.push_back(std::string("--") + key);
            words.push_back(req.get_param_value(key));
        }
    std::vector<char*> argv;
    for (auto& w : words) argv.push_back(w.data());
    const Args args(static_cast<int>(argv.size()), argv.data(), 2,
                    {"mode", "domain", "factors", "winding", "max", "layout", "column-rule"});
    const PatternRequest r = pattern_request_from(args, "factors");
    return mesh_to_json(tessellate(r), r);
}

// A loopback name with an optional port: `127.0.0.1`, `localhost` or `[::1]`. Any other Host (or Origin) is
// refused, so a DNS-rebound page on another name cannot read the server's answers.
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

// A decoded path with NUL (the file would be found by the name before it, its type taken from the name after
// it) or a `..` segment is refused before the file handler sees it.
bool is_safe_path(std::string_view path) {
    if (path.find('\0') != std::string_view::npos) return false;
    for (std::size_t at = 0; at <= path.size();) {
        const std::size_t end = std::min(path.find('/', at), path.size());
        if (path.substr(at, end - at) == "..") return false;
        at = end + 1;
    }
    return true;
}

httplib::Server::HandlerResponse refuse(httplib::Response& res, int status, const char* why) {
    res.status = status;
    res.set_content(why, "text/plain");
    return httplib::Server::HandlerResponse::Handled;
}

} // namespace

int run_serve(int argc, char** argv) {
    const Args args(argc, argv, 2, {"port", "viewer", "shaders"});
    const unsigned port = parse_unsigned(args.get_or("port", "8765"), "--port", 0, 65535);
    const std::string viewer = args.get_or("viewer", CTESS_VIEWER_DIR);
    const std::string shaders = args.get_or("shaders", CTESS_SHADER_DIR);

    httplib::Server server;
    // SO_REUSEADDR only: httplib's default adds SO_REUSEPORT, which lets a second server share a busy port.
    server.set_socket_options([](socket_t sock) {
        int yes = 1;
        setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof(yes));
    });
    if (!server.set_mount_point("/shaders", shaders))
        throw std::runtime_error("--shaders: cannot serve '" + shaders + "' (not a directory)");
    if (!server.set_mount_point("/", viewer))
        throw std::runtime_error("--viewer: cannot serve '" + viewer + "' (not a directory)");
    server.set_file_extension_and_mimetype_mapping("wgsl", "text/plain");
    server.set_file_extension_and_mimetype_mapping("mjs", "text/javascript");
    server.set_pre_routing_handler([](const httplib::Request& req, httplib::Response& res) {
        // httplib parsed Range before routing and applies it to any body (a refusal's too): a generated
        // answer ignores it, and a file takes at most one range, so many overlapping ranges cannot multiply
        // the response. The request is httplib's own non-const object; clearing its parsed ranges is the only
        // hook 0.11 gives.
        auto& ranges = const_cast<httplib::Request&>(req).ranges;
        const bool many_ranges = ranges.size() > 1 && req.path.rfind("/api/", 0) != 0;
        if (many_ranges || req.path.rfind("/api/", 0) == 0 ||
            !is_loopback_authority(req.get_header_value("Host")))
            ranges.clear();
        if (!is_loopback_authority(req.get_header_value("Host")))
            return refuse(res, 403, "ctess serve: Host must be 127.0.0.1, localhost or [::1]\n");
        if (req.method != "GET" && req.method != "HEAD" && req.has_header("Origin") &&
            !is_loopback_origin(req.get_header_value("Origin")))
            return refuse(res, 403, "ctess serve: Origin must be a loopback http origin\n");
        if (!is_safe_path(req.path)) return refuse(res, 400, "ctess serve: bad path\n");
        if (many_ranges) return refuse(res, 416, "ctess serve: at most one byte range\n");
        return httplib::Server::HandlerResponse::Unhandled;
    });
    server.Get("/api/pattern", [](const httplib::Request& req, httplib::Response& res) {
        try {
            res.set_content(pattern_json(req), "application/json");
        } catch (const std::exception& e) {
            res.status = 400;
            res.set_content(fmt::format("{{\"error\": \"{}\"}}\n", json_escape(e.what())),
                            "application/json");
        }
    });

    const char* host = "127.0.0.1"; // loopback only: the viewer is a local tool
    const int bound = port == 0
                          ? server.bind_to_any_port(host)
                          : (server.bind_to_port(host, static_cast<int>(port)) ? static_cast<int>(port) : -1);
    if (bound < 0) throw std::runtime_error(fmt::format("cannot listen on {}:{}", host, port));
    fmt::print("ctess serve: http://{}:{}/ (viewer {}, shaders {}; Ctrl-C stops)\n", host, bound, viewer,
               shaders);
    std::fflush(stdout);
    return server.listen_after_bind() ? 0 : 1;
}

} // namespace ctess::cli
