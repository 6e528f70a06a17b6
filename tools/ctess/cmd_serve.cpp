// ctess serve: the browser viewer (viewer/) with the build's generated shaders and table blobs, on 127.0.0.1
// only, plus /api/pattern, which answers a `pattern` request with the same JSON as `ctess pattern --format
// json` (the viewer's D3D11 and uniform modes and its ratio to D3D11 fractional_even come from there;
// docs/viewer.md).
#include "cli_args.hpp"
#include "commands.hpp"
#include "mesh.hpp"
#include "mesh_formats.hpp"

#include <httplib.h>

#include <cstdio>
#include <exception>

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
    server.Get("/api/pattern", [](const httplib::Request& req, httplib::Response& res) {
        try {
            res.set_content(pattern_json(req), "application/json");
        } catch (const std::exception& e) {
            res.status = 400;
            res.set_content(fmt::format("{{\"error\": \"{}\"}}\n", e.what()), "application/json");
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
