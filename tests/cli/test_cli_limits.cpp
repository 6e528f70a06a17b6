// The CLI's bounded work and loud failures (docs/cli.md, "Limits" and "Errors and bad input"): every
// command's work is bounded before it starts, every output is checked through close, and a failed write never
// leaves a half-written file behind.
#include "cli/serve_process.hpp"
#include <catch2/catch.hpp>

#include <arpa/inet.h>
#include <cctype>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <netinet/in.h>
#include <poll.h>
#include <string>
#include <string_view>
#include <sys/socket.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "json_escape.hpp"
#include "support/cli_run.hpp"

namespace {

using ctess::test::ctess_cli;
using ctess::test::Run;
using ctess::test::run_shell;

std::string temp_path(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("ctess_limits_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace

TEST_CASE("sweep to huge factors finishes with a bounded chart", "[cli][limits]") {
    // The tick loop used to add the step to f; above about 1e18 f + 128 == f and it never ended.
    for (const char* to : {"1e9", "1e15", "1e30", "3.4028235e38"}) {
        INFO("--to " << to);
        const std::string svg = temp_path("sweep_huge.svg");
        const Run r = ctess_cli(std::string("sweep --mode cp --from 1 --to ") + to + " --svg " + svg);
        REQUIRE(r.exit_code == 0);
        const std::string text = read_file(svg);
        CHECK(text.size() < 2'000'000);
        // At most 17 grid lines: 16 intervals of a power-of-two step.
        std::size_t ticks = 0;
        for (std::size_t at = 0; (at = text.find("stroke=\"#e3e6ea\"", at)) != std::string::npos; ++at)
            ++ticks;
        CHECK(ticks <= 17 + 5); // vertical ticks + the five horizontal lines
        std::filesystem::remove(svg);
    }
}

TEST_CASE("work past a command's limit is refused before it starts, naming the limit", "[cli][limits]") {
    const std::string dir = temp_path("anim_limit");
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"sweep --mode cp --from 1 --to 300 --max 256 --steps 20000 --svg " + dir + ".svg",
         "would draw 5140000 path segments; the limit is 2000000"},
        {"animate --mode cp --max 256 --from 256,256,256 --to 256,256,256 --frames 1000 --out " + dir,
         "the limit is 512 MiB"},
        {"efficiency --random 100001", "--random: 100001 is outside [1, 100000]"},
        {"animate --mode cp --from 1,1,1 --to 2,2,2 --frames 1001 --out " + dir, "outside [2, 1000]"},
    };
    for (const auto& [args, message] : cases) {
        INFO("ctess " << args);
        const Run r = ctess_cli(args);
        CHECK(r.exit_code == 2);
        CHECK(contains(r.out, message));
    }
    // Refused before anything was written.
    CHECK_FALSE(std::filesystem::exists(dir));
    CHECK_FALSE(std::filesystem::exists(dir + ".svg"));
}

TEST_CASE("a full output exits 1 with the OS reason", "[cli][limits]") {
    const Run file = ctess_cli("pattern --factors 4,4,4 --out /dev/full");
    CHECK(file.exit_code == 1);
    CHECK(contains(file.out, "cannot write '/dev/full': No space left on device"));
    // Standard output on a full device: the JSON written with fwrite, the line command's fmt::print, the main
    // usage text; stderr goes to the pipe, stdout to /dev/full.
    for (const char* args :
         {"pattern --factors 4,4,4", "line --factor 4", "efficiency", "--help", "sweep --help"}) {
        INFO("ctess " << args);
        const Run r = run_shell(std::string(CTESS_CLI) + " " + args + " 2>&1 >/dev/full");
        CHECK(r.exit_code == 1);
        CHECK(contains(r.out, "cannot write 'standard output': No space left on device"));
    }
    const Run missing = ctess_cli("pattern --factors 4,4,4 --format svg --out /nonexistent-dir/x.svg");
    CHECK(missing.exit_code == 1);
    CHECK(contains(missing.out, "cannot write '/nonexistent-dir/x.svg': No such file or directory"));
}

TEST_CASE("a failed write leaves the previous file intact and no temporary behind", "[cli][limits]") {
    const std::string dir = temp_path("atomic");
    std::filesystem::create_directories(dir);
    const std::string out = dir + "/p.svg";
    { std::ofstream(out) << "previous content\n"; }
    // A 4 KiB file-size limit (SIGXFSZ ignored, so write() fails with EFBIG) stops the SVG part-way.
    const Run r = run_shell("trap '' XFSZ; ulimit -f 4; " + std::string(CTESS_CLI) +
                            " pattern --factors 16,16,16 --format svg --out " + out + " 2>&1");
    CHECK(r.exit_code == 1);
    CHECK(contains(r.out, "cannot write '" + out + "': File too large"));
    CHECK(read_file(out) == "previous content\n");
    CHECK(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()) ==
          1);
    // Without the limit the file is replaced whole.
    REQUIRE(ctess_cli("pattern --factors 16,16,16 --format svg --out " + out).exit_code == 0);
    CHECK(contains(read_file(out), "</svg>"));
    std::filesystem::remove_all(dir);
}

TEST_CASE("ctess mesh --out .glb and .ply (streamed to the file): a failed write keeps the previous file, no "
          "temporary",
          "[cli][limits]") {
    for (const std::string format : {"glb", "ply"}) {
        INFO(format);
        const std::string dir = temp_path("atomic_" + format);
        std::filesystem::create_directories(dir);
        const std::string model = dir + "/tetra.obj";
        {
            std::ofstream(model)
                << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
        }
        const std::string out = dir + "/t." + format;
        { std::ofstream(out) << "previous content\n"; }
        // About 50 KB of output at factor 16 against a 4 KiB file-size limit: write() fails with EFBIG
        // part-way.
        const std::string mesh = std::string(CTESS_CLI) + " mesh --in " + model + " --factor 16 --out ";
        const Run r = run_shell("trap '' XFSZ; ulimit -f 4; " + mesh + out + " 2>&1");
        CHECK(r.exit_code == 1);
        CHECK(contains(r.out, "cannot write '" + out + "': File too large"));
        CHECK(read_file(out) == "previous content\n");
        CHECK(std::distance(std::filesystem::directory_iterator(dir),
                            std::filesystem::directory_iterator()) == 2);
        // A device is written in place: a full one is the OS reason.
        const std::string full = dir + "/full." + format;
        std::filesystem::create_symlink("/dev/full", full);
        const Run f = run_shell(mesh + full + " 2>&1");
        CHECK(f.exit_code == 1);
        CHECK(contains(f.out, "No space left on device"));
        // Without the limit the file is replaced whole: its header and its stated length.
        REQUIRE(run_shell(mesh + out).exit_code == 0);
        const std::string file = read_file(out);
        if (format == "glb") {
            REQUIRE(file.size() > 12);
            CHECK(file.substr(0, 4) == "glTF");
            std::uint32_t length = 0;
            std::memcpy(&length, file.data() + 8, 4);
            CHECK(length == file.size());
        } else {
            // 32 bytes a vertex, 13 a face, after the header's element counts.
            const std::size_t end = file.find("end_header\n");
            REQUIRE(end != std::string::npos);
            const std::size_t v = file.find("element vertex "), t = file.find("element face ");
            REQUIRE((v != std::string::npos && t != std::string::npos));
            const std::size_t vertices = std::stoul(file.substr(v + 15)),
                              faces = std::stoul(file.substr(t + 13));
            CHECK(vertices > 0);
            CHECK(file.size() == end + 11 + 32 * vertices + 13 * faces);
        }
        std::filesystem::remove_all(dir);
    }
}

TEST_CASE("ctess <command> --help prints that command's usage", "[cli]") {
    for (const char* command : {"pattern", "line", "sweep", "animate", "efficiency"}) {
        INFO(command);
        for (const char* flag : {"--help", "-h"}) {
            const Run r = ctess_cli(std::string(command) + " --mode cp " + flag);
            CHECK(r.exit_code == 0);
            CHECK(r.out.starts_with(std::string("usage: ctess ") + command + " "));
            CHECK_FALSE(contains(r.out, "commands:")); // only this command's lines
        }
    }
    const Run pattern = ctess_cli("pattern --help");
    CHECK(contains(pattern.out, "[--column-rule minimal|staircase]")); // its continuation lines too
    const Run unknown = ctess_cli("frobnicate --help");
    CHECK(unknown.exit_code == 2);
    CHECK(contains(unknown.out, "unknown command"));
}

// --- `ctess serve` on loopback: the server is started on a free port and stopped by each test ---

namespace {

// `ctess serve --port 0` on a free port, stopped when it goes out of scope (cli/serve_process.hpp).
using Server = ctess::test::ServeProcess;

struct Reply {
    int status = 0;
    std::string head, body;
};

// One raw HTTP/1.1 request to 127.0.0.1:port (Connection: close), reading at most `limit` bytes, each read
// bounded by a 10 s timeout.
Reply http(int port, const std::string& request, std::size_t limit = 64u << 20) {
    const int s = ctess::test::connect_loopback(port);
    REQUIRE(s >= 0);
    for (std::size_t sent = 0; sent < request.size();) {
        const ssize_t n = ::send(s, request.data() + sent, request.size() - sent, MSG_NOSIGNAL);
        REQUIRE(n > 0);
        sent += static_cast<std::size_t>(n);
    }
    std::string all;
    char buf[65536];
    ssize_t n = 0;
    while (all.size() < limit && (n = ::recv(s, buf, sizeof buf, 0)) > 0)
        all.append(buf, static_cast<std::size_t>(n));
    ::close(s);
    Reply r;
    const std::size_t end = all.find("\r\n\r\n");
    r.head = all.substr(0, end);
    if (end != std::string::npos) r.body = all.substr(end + 4);
    if (all.rfind("HTTP/1.1 ", 0) == 0) r.status = std::atoi(all.c_str() + 9);
    return r;
}

std::string get(const std::string& target, const std::string& host, const std::string& extra = "") {
    return "GET " + target + " HTTP/1.1\r\nHost: " + host + "\r\n" + extra + "Connection: close\r\n\r\n";
}

// A strict JSON check (RFC 8259 grammar, strings with only the escapes JSON allows and no raw control
// characters) that also lists the top-level object's keys.
struct JsonCheck {
    std::string_view s;
    std::size_t i = 0;
    std::vector<std::string> keys;

    explicit JsonCheck(std::string_view text) : s(text) {}

    void ws() {
        while (i < s.size() && (s[i] == ' ' || s[i] == '\n' || s[i] == '\r' || s[i] == '\t')) ++i;
    }
    bool lit(std::string_view w) {
        if (s.substr(i, w.size()) != w) return false;
        i += w.size();
        return true;
    }
    bool string(std::string* out) {
        if (!lit("\"")) return false;
        while (i < s.size() && s[i] != '"') {
            const unsigned char c = static_cast<unsigned char>(s[i]);
            if (c < 0x20) return false;
            if (c == '\\') {
                if (++i >= s.size()) return false;
                if (s[i] == 'u') {
                    for (int k = 1; k <= 4; ++k)
                        if (i + k >= s.size() || !std::isxdigit(static_cast<unsigned char>(s[i + k])))
                            return false;
                    i += 4;
                } else if (std::string_view("\"\\/bfnrt").find(s[i]) == std::string_view::npos) {
                    return false;
                }
            }
            if (out) *out += s[i];
            ++i;
        }
        return lit("\"");
    }
    bool value(int depth) {
        ws();
        if (i >= s.size()) return false;
        if (s[i] == '{' || s[i] == '[') {
            const char close = s[i] == '{' ? '}' : ']';
            ++i;
            ws();
            if (lit(std::string_view(&close, 1))) return true;
            do {
                ws();
                if (close == '}') {
                    std::string key;
                    if (!string(&key)) return false;
                    if (depth == 0) keys.push_back(key);
                    ws();
                    if (!lit(":")) return false;
                }
                if (!value(depth + 1)) return false;
                ws();
            } while (lit(","));
            return lit(std::string_view(&close, 1));
        }
        if (s[i] == '"') return string(nullptr);
        if (lit("true") || lit("false") || lit("null")) return true;
        const std::size_t start = i;
        while (i < s.size() && std::string_view("+-.eE0123456789").find(s[i]) != std::string_view::npos) ++i;
        return i > start;
    }
    bool document() {
        if (!value(0)) return false;
        ws();
        return i == s.size();
    }
};

} // namespace

TEST_CASE("json_escape escapes quotes, backslashes and controls, and replaces invalid UTF-8",
          "[cli][serve]") {
    using ctess::cli::json_escape;
    CHECK(json_escape("plain") == "plain");
    CHECK(json_escape("a\"b\\c") == "a\\\"b\\\\c");
    CHECK(json_escape(std::string("\n\t\x01\x7f", 4)) == "\\u000a\\u0009\\u0001\\u007f");
    CHECK(json_escape(std::string("\0", 1)) == "\\u0000");
    CHECK(json_escape("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80") ==
          "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80");
    CHECK(json_escape("\xff") == "\\ufffd");
    CHECK(json_escape("\xc3") == "\\ufffd");                                  // truncated
    CHECK(json_escape("\xc0\xaf") == "\\ufffd\\ufffd");                       // overlong
    CHECK(json_escape("\xed\xa0\x80") == "\\ufffd\\ufffd\\ufffd");            // surrogate
    CHECK(json_escape("\xf4\x90\x80\x80") == "\\ufffd\\ufffd\\ufffd\\ufffd"); // past U+10FFFF
}

TEST_CASE("serve: a hostile /api/pattern query gives valid JSON with only the error key", "[cli][serve]") {
    const Server server;
    REQUIRE(server.port > 0);
    const std::string host = "127.0.0.1:" + std::to_string(server.port);
    for (const char* mode : {"x%22,%22vertex_count%22:1,%22e%22:%22", "a%5C", "a%0Ab%00c", "%FF%C3%28",
                             "%22%7D%7B%22x%22:%22"}) {
        INFO("mode=" << mode);
        const Reply r =
            http(server.port, get(std::string("/api/pattern?mode=") + mode + "&factors=4,4,4", host));
        CHECK(r.status == 400);
        JsonCheck json{r.body};
        CHECK(json.document());
        CHECK(json.keys == std::vector<std::string>{"error"});
    }
    const Reply ok = http(server.port, get("/api/pattern?mode=cp&factors=4,4,4", host));
    CHECK(ok.status == 200);
    CHECK(JsonCheck{ok.body}.document());
}

TEST_CASE("serve: only loopback Host values are answered", "[cli][serve]") {
    const Server server;
    REQUIRE(server.port > 0);
    const std::string port = std::to_string(server.port);
    for (const std::string& host :
         std::vector<std::string>{"evil.example", "evil.example:" + port, "127.0.0.1.evil.example",
                                  "localhost.evil.example:" + port, "127.0.0.1:" + port + "@evil", ""}) {
        INFO("Host: " << host);
        CHECK(http(server.port, get("/", host)).status == 403);
    }
    for (const std::string& host :
         std::vector<std::string>{"127.0.0.1:" + port, "127.0.0.1", "localhost:" + port, "[::1]:" + port}) {
        INFO("Host: " << host);
        CHECK(http(server.port, get("/", host)).status == 200);
    }
    // A non-GET request with a foreign Origin is refused even with a loopback Host.
    const std::string post =
        "POST /api/pattern HTTP/1.1\r\nHost: 127.0.0.1:" + port +
        "\r\nOrigin: http://evil.example\r\nContent-Length: 0\r\nConnection: close\r\n\r\n";
    CHECK(http(server.port, post).status == 403);
}

TEST_CASE("serve: paths with NUL or .. are refused before a file is looked up", "[cli][serve]") {
    const Server server;
    REQUIRE(server.port > 0);
    const std::string host = "127.0.0.1:" + std::to_string(server.port);
    const Reply js = http(server.port, get("/viewer.js", host));
    CHECK(js.status == 200);
    CHECK(contains(js.head, "Content-Type: text/javascript"));
    for (const char* path :
         {"/viewer.js%00.html", "/viewer.js%00", "/../CMakeLists.txt", "/shaders/%2E%2E/x"}) {
        INFO(path);
        const Reply r = http(server.port, get(path, host));
        CHECK((r.status == 400 || r.status == 404));
        CHECK(!contains(r.head, "text/html"));
    }
}

TEST_CASE("serve: many byte ranges cannot multiply a response", "[cli][serve]") {
    const Server server;
    REQUIRE(server.port > 0);
    const std::string host = "127.0.0.1:" + std::to_string(server.port);
    std::string ranges = "Range: bytes=0-10";
    for (int k = 1; k < 700; ++k) ranges += ",0-10";
    ranges += "\r\n";
    const std::string api = "/api/pattern?mode=uniform&factors=256,256,256";
    const Reply whole = http(server.port, get(api, host));
    REQUIRE(whole.status == 200);
    // Read at most a little past the whole answer: the old server sent about 700 copies.
    const Reply many = http(server.port, get(api, host, ranges), 2 * whole.body.size() + 65536);
    CHECK(many.status == 200);
    CHECK(many.body.size() <= whole.body.size());
    const Reply one = http(server.port, get(api, host, "Range: bytes=0-10\r\n"));
    CHECK(one.status == 200); // generated answers ignore Range
    CHECK(one.body == whole.body);
    // A static file takes one range; more than one is refused.
    const Reply file_one = http(server.port, get("/viewer.js", host, "Range: bytes=0-10\r\n"));
    CHECK(file_one.status == 206);
    CHECK(file_one.body.size() == 11);
    const Reply file_many = http(server.port, get("/viewer.js", host, ranges), 1 << 20);
    CHECK(file_many.status == 416);
    CHECK(file_many.body.size() < 200);
}

TEST_CASE("surface writes a non-finite --angle or --distance as JSON null", "[cli][limits]") {
    for (const char* option : {"--angle inf", "--distance inf"}) {
        for (const char* format : {"json", "stats"}) {
            INFO(option << " --format " << format);
            const Run r = ctess_cli(std::string("surface --name sphere --max-level 6 ") + option +
                                    " --format " + format);
            CHECK(r.exit_code == 0);
            CHECK_FALSE(contains(r.out, "inf"));
            CHECK_FALSE(contains(r.out, "nan"));
            CHECK(contains(r.out, option[2] == 'a' ? "\"angle\": null" : "\"distance\": null"));
        }
    }
    CHECK(contains(ctess_cli("surface --name sphere --max-level 6").out, "\"distance\": 0.05,"));
}

TEST_CASE("--out writes through a symbolic link and keeps the replaced file's permissions", "[cli][limits]") {
    namespace fs = std::filesystem;
    const fs::path dir = fs::path(CTESS_TEST_BINARY_DIR) / ("cli_out_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path target = dir / "target.json";
    const fs::path link = dir / "link.json";
    { std::ofstream(target) << "previous\n"; }
    fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write);
    fs::create_symlink("target.json", link);
    REQUIRE(ctess_cli("pattern --factors 4,4,4 --out " + link.string()).exit_code == 0);
    CHECK(fs::is_symlink(link));
    CHECK(fs::read_symlink(link) == "target.json");
    CHECK(contains(read_file(target.string()), "\"triangle_count\""));
    CHECK((fs::status(target).permissions() & fs::perms::all) ==
          (fs::perms::owner_read | fs::perms::owner_write));
    // A plain file keeps its bits too; a new file gets the default mode.
    fs::permissions(target, fs::perms::owner_all | fs::perms::group_read, fs::perm_options::replace);
    REQUIRE(ctess_cli("pattern --factors 3,3,3 --out " + target.string()).exit_code == 0);
    CHECK((fs::status(target).permissions() & fs::perms::all) ==
          (fs::perms::owner_all | fs::perms::group_read));
    // A dangling link is refused and left alone.
    const fs::path dangling = dir / "dangling.json";
    fs::create_symlink("missing/x.json", dangling);
    const Run r = ctess_cli("pattern --factors 4,4,4 --out " + dangling.string());
    CHECK(r.exit_code == 1);
    CHECK(contains(r.out, "cannot resolve the symbolic link '" + dangling.string() + "'"));
    CHECK(fs::is_symlink(dangling));
    CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 3);
    fs::remove_all(dir);
}

TEST_CASE("animate bounds every frame, not only the two ends", "[cli][limits]") {
    const std::string dir = temp_path("anim_middle");
    const Run big =
        ctess_cli("animate --mode cp --max 256 --from 1,1,256 --to 256,256,1 --frames 1000 --out " + dir);
    CHECK(big.exit_code == 2);
    CHECK(contains(big.out, "the limit is 512 MiB"));
    CHECK_FALSE(std::filesystem::exists(dir));
    const Run small = ctess_cli("animate --mode cp --from 1,1,4 --to 4,4,1 --frames 3 --out " + dir);
    CHECK(small.exit_code == 0);
    CHECK(std::filesystem::exists(dir + "/frame_002.svg"));
    CHECK(std::filesystem::exists(dir + "/index.html"));
    std::filesystem::remove_all(dir);
}
