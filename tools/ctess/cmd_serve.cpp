// ctess serve: the browser viewer (viewer/) with the build's generated shaders and table blobs, on 127.0.0.1
// only, plus /api/pattern, which answers a `pattern` request with the same JSON as `ctess pattern --format
// json` (the viewer's D3D11 and uniform modes and its ratio to D3D11 fractional_even come from there;
// docs/viewer.md).
#include "cli_args.hpp"
#include "commands.hpp"
#include "install_dirs.hpp"
#include "json_escape.hpp"
#include "mesh.hpp"
#include "mesh_formats.hpp"
#include "model_upload.hpp"
#include "serve_loop.hpp"

#include <httplib.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <mutex>
#include <span>
#include <string_view>

#include <fmt/core.h>

namespace ctess::cli {

namespace {

// A request's query as a command's arguments (`ctess COMMAND --key value` for each of `keys` present), so
// that an endpoint validates exactly as the CLI does.
Args query_args(const httplib::Request& req, const char* command, const std::vector<std::string>& keys) {
    std::vector<std::string> words = {"ctess", command};
    for (const std::string& key : keys)
        if (req.has_param(key)) {
            words.push_back("--" + key);
            words.push_back(req.get_param_value(key));
        }
    std::vector<char*> argv;
    for (auto& w : words) argv.push_back(w.data());
    return Args(static_cast<int>(argv.size()), argv.data(), 2, keys);
}

// /api/tessellate's options: `ctess mesh`'s, with displace naming the map (none, map, model).
const std::vector<std::string> tessellate_keys = {
    "pattern",    "surface",  "quad-rule",      "dice-rate",       "camera",           "fov",
    "resolution", "displace", "displace-scale", "displace-offset", "displace-address", "displace-grow"};

std::string pattern_json(const httplib::Request& req) {
    const Args args =
        query_args(req, "pattern", {"mode", "domain", "factors", "winding", "max", "layout", "column-rule"});
    const PatternRequest r = pattern_request_from(args, "factors");
    return mesh_to_json(tessellate(r), r);
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

// Compression is chosen by cost (docs/cli.md, "Viewer server"): httplib 0.11 picks br whenever the client
// lists it, at brotli's default quality 11 (over 100x the CPU of the answer itself on a 5.7 MB pattern), and
// gzip at zlib's default level. So br is never offered to httplib, gzip only when the client accepts it, and
// nothing above kMaxCompressedBody: the server is on loopback, where bytes cost less than CPU.
constexpr std::size_t kMaxCompressedBody = 256 * 1024;

// Whether an Accept-Encoding value accepts gzip (a `gzip` or `*` coding without q=0; RFC 9110 §12.5.3).
bool accepts_gzip(std::string_view value) {
    bool star = false;
    while (!value.empty()) {
        const std::size_t comma = value.find(',');
        std::string_view item = value.substr(0, comma);
        value = comma == std::string_view::npos ? std::string_view() : value.substr(comma + 1);
        const std::size_t semi = item.find(';');
        std::string_view coding = item.substr(0, semi);
        while (!coding.empty() && (coding.front() == ' ' || coding.front() == '\t')) coding.remove_prefix(1);
        while (!coding.empty() && (coding.back() == ' ' || coding.back() == '\t')) coding.remove_suffix(1);
        std::string lower(coding);
        for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (lower != "gzip" && lower != "*") continue;
        std::string params(semi == std::string_view::npos ? std::string_view() : item.substr(semi + 1));
        params.erase(std::remove(params.begin(), params.end(), ' '), params.end());
        const std::size_t q = params.find("q=");
        // A weight of all zeros refuses the coding; any other weight accepts it.
        const bool accepted =
            q == std::string::npos || params.substr(q + 2).find_first_not_of("0.") != std::string::npos;
        if (lower == "gzip") return accepted; // an explicit gzip overrides `*`
        star = accepted;
    }
    return star;
}

// httplib decides the coding from the request's Accept-Encoding when it writes the response; the request
// object is httplib's own non-const one (the same hook the Range handling below uses).
void set_accepted_coding(const httplib::Request& req, bool gzip) {
    auto& headers = const_cast<httplib::Request&>(req).headers;
    headers.erase("Accept-Encoding");
    if (gzip) headers.emplace("Accept-Encoding", "gzip");
}

// Called with the response's body: above the bound it goes out uncompressed.
void bound_compression(const httplib::Request& req, const httplib::Response& res) {
    if (res.body.size() > kMaxCompressedBody) set_accepted_coding(req, false);
}

// POST /api/model, /api/height-map and /api/vector-map (?name=FILE): the body is the file's bytes, the answer
// the library's reading of it in model_upload.hpp's container, or 400 and {"error": "..."} naming the
// problem. The loop has bounded the body (ServeLimits::max_upload_body) and the number of uploads at once.
template <class Answer>
void answer_upload(const httplib::Request& req, httplib::Response& res, Answer answer) {
    try {
        const std::string name = req.get_param_value("name");
        if (name.empty())
            throw std::runtime_error("give the file's name: ?name=FILE (its extension picks the reader)");
        const auto* bytes = reinterpret_cast<const std::uint8_t*>(req.body.data());
        // Moved into the body (set_content would copy it): a model's answer can be tens of MB.
        res.body = answer(std::span<const std::uint8_t>(bytes, req.body.size()), name);
        res.set_header("Content-Type", "application/octet-stream");
    } catch (const std::exception& e) {
        res.status = 400;
        res.set_content(fmt::format("{{\"error\": \"{}\"}}\n", json_escape(e.what())), "application/json");
    }
    bound_compression(req, res);
}

httplib::Server::HandlerResponse refuse(httplib::Response& res, int status, const std::string& why) {
    res.status = status;
    res.set_content(why, "text/plain");
    return httplib::Server::HandlerResponse::Handled;
}

} // namespace

int run_serve(int argc, char** argv) {
    const Args args(argc, argv, 2, {"port", "viewer", "shaders"});
    const unsigned port = parse_unsigned(args.get_or("port", "8765"), "--port", 0, 65535);
    const std::string viewer = args.get_or("viewer", installed_or_build_dir("viewer", CTESS_VIEWER_DIR));
    const std::string shaders = args.get_or("shaders", installed_or_build_dir("shaders", CTESS_SHADER_DIR));

    BoundedServer server;
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
        set_accepted_coding(req, accepts_gzip(req.get_header_value("Accept-Encoding")));
        auto& ranges = const_cast<httplib::Request&>(req).ranges;
        const bool many_ranges = ranges.size() > 1 && req.path.rfind("/api/", 0) != 0;
        const std::string origin = req.get_header_value("Origin");
        const std::string_view origin_view = origin;
        const char* foreign = foreign_request(req.method, req.get_header_value("Host"),
                                              req.has_header("Origin") ? &origin_view : nullptr);
        if (many_ranges || req.path.rfind("/api/", 0) == 0 || foreign) ranges.clear();
        if (foreign) return refuse(res, 403, fmt::format("ctess serve: {}\n", foreign));
        if (!is_safe_path(req.path)) return refuse(res, 400, "ctess serve: bad path\n");
        if (many_ranges) return refuse(res, 416, "ctess serve: at most one byte range\n");
        // An upload's body is the file's bytes whatever Content-Type the client sent: httplib would parse a
        // form-urlencoded body into parameters (and refuse one past 8 KiB with an empty 413) and decode a
        // multipart one. The request is httplib's own non-const object, as for the ranges above.
        if (upload_target(req.method, req.path)) {
            auto& headers = const_cast<httplib::Request&>(req).headers;
            headers.erase("Content-Type");
            headers.emplace("Content-Type", "application/octet-stream");
        }
        return httplib::Server::HandlerResponse::Unhandled;
    });
    server.set_file_request_handler(bound_compression);
    server.Get("/api/pattern", [](const httplib::Request& req, httplib::Response& res) {
        try {
            res.set_content(pattern_json(req), "application/json");
        } catch (const std::exception& e) {
            res.status = 400;
            res.set_content(fmt::format("{{\"error\": \"{}\"}}\n", json_escape(e.what())),
                            "application/json");
        }
        bound_compression(req, res);
    });

    // The last model and the last map uploaded, for /api/tessellate: one of each (a new upload replaces it,
    // bounding memory), numbered so that a page whose upload was replaced is told to upload again.
    struct Held {
        std::mutex mutex;
        std::uint64_t next_id = 1;
        std::uint64_t model_id = 0, map_id = 0;
        std::shared_ptr<const HeldModel> model;
        std::shared_ptr<const HeldMap> map;
    };
    Held held;
    server.Post("/api/model", [&held](const httplib::Request& req, httplib::Response& res) {
        answer_upload(req, res, [&held](std::span<const std::uint8_t> bytes, const std::string& name) {
            std::shared_ptr<const HeldModel> model = load_uploaded_model(bytes, name);
            std::uint64_t id = 0;
            {
                const std::lock_guard lock(held.mutex);
                id = held.model_id = held.next_id++;
                held.model = model;
            }
            return model_answer(*model, id);
        });
    });
    for (const bool vector : {false, true})
        server.Post(vector ? "/api/vector-map" : "/api/height-map",
                    [&held, vector](const httplib::Request& req, httplib::Response& res) {
                        answer_upload(
                            req, res, [&](std::span<const std::uint8_t> bytes, const std::string& name) {
                                std::shared_ptr<const HeldMap> map = load_uploaded_map(bytes, name, vector);
                                std::uint64_t id = 0;
                                {
                                    const std::lock_guard lock(held.mutex);
                                    id = held.map_id = held.next_id++;
                                    held.map = map;
                                }
                                return map_answer(*map, id);
                            });
                    });
    server.Get("/api/tessellate", [&held](const httplib::Request& req, httplib::Response& res) {
        try {
            const auto id_of = [&](const char* key) {
                return req.has_param(key)
                           ? std::uint64_t{parse_unsigned(req.get_param_value(key), key, 1, 0xFFFFFFFFu)}
                           : std::uint64_t{0};
            };
            const std::uint64_t model_id = id_of("model"), map_id = id_of("map");
            std::shared_ptr<const HeldModel> model;
            std::shared_ptr<const HeldMap> map;
            {
                const std::lock_guard lock(held.mutex);
                if (model_id != 0 && model_id == held.model_id) model = held.model;
                if (map_id != 0 && map_id == held.map_id) map = held.map;
            }
            if (!model)
                throw std::runtime_error(
                    "the model is no longer held (another upload replaced it): upload it again");
            if (map_id != 0 && !map)
                throw std::runtime_error(
                    "the map is no longer held (another upload replaced it): upload it again");
            res.body = tessellate_answer(*model, map.get(), query_args(req, "mesh", tessellate_keys));
            res.set_header("Content-Type", "application/octet-stream");
        } catch (const std::exception& e) {
            res.status = 400;
            res.set_content(fmt::format("{{\"error\": \"{}\"}}\n", json_escape(e.what())),
                            "application/json");
        }
        bound_compression(req, res);
    });

    const char* host = "127.0.0.1"; // loopback only: the viewer is a local tool
    const int bound = server.bind_and_listen(host, port);
    if (bound < 0) throw std::runtime_error(fmt::format("cannot listen on {}:{}", host, port));
    fmt::print("ctess serve: http://{}:{}/ (viewer {}, shaders {}; Ctrl-C stops)\n", host, bound, viewer,
               shaders);
    std::fflush(stdout);
    return server.serve_forever() ? 0 : 1;
}

} // namespace ctess::cli
