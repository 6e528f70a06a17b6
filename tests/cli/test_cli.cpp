// The ctess CLI, run as a user would: the "done when" numbers, outputs, and every bad-input case.
#include <catch2/catch.hpp>

#include <ctess/cp/pattern.hpp>
#include <ctess/d3d11/tessellator.hpp>
#include <ctess/surface/grid_strip.hpp>
#include <ctess/uniform/pattern.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <utility>
#include <vector>

#include "support/cli_run.hpp"
#include <ctess/analysis/square_mesh_checks.hpp>

namespace {

using ctess::test::ctess_cli;
using ctess::test::Run;

long json_number(const std::string& json, const std::string& key) {
    const std::string tag = "\"" + key + "\": ";
    const auto at = json.find(tag);
    REQUIRE(at != std::string::npos);
    return std::stol(json.substr(at + tag.size()));
}

// The "vertices" array as integers, in order.
std::vector<std::uint32_t> json_vertices(const std::string& json) {
    const auto begin = json.find("\"vertices\": [");
    const auto end = json.find("]],", begin);
    std::vector<std::uint32_t> out;
    std::string body = json.substr(begin + 13, end - begin - 13);
    for (char& c : body)
        if (c == '[' || c == ']' || c == ',') c = ' ';
    std::istringstream in(body);
    for (std::uint32_t x; in >> x;) out.push_back(x);
    return out;
}

// The "triangles" array as integers, in order.
std::vector<std::uint32_t> json_triangles(const std::string& json) {
    const auto begin = json.find("\"triangles\": [");
    const auto end = json.find("]]", begin);
    std::string body = json.substr(begin + 14, end - begin - 14);
    for (char& c : body)
        if (c == '[' || c == ']' || c == ',') c = ' ';
    std::vector<std::uint32_t> out;
    std::istringstream in(body);
    for (std::uint32_t x; in >> x;) out.push_back(x);
    return out;
}

std::string temp_path(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("ctess_test_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

} // namespace

TEST_CASE("d3d11-even 64,64,64,64 gives 3169 vertices and 6144 triangles", "[cli]") {
    const Run r = ctess_cli("pattern --mode d3d11-even --factors 64,64,64,64 --format json");
    REQUIRE(r.exit_code == 0);
    CHECK(json_number(r.out, "fixed_one") == 65536);
    CHECK(json_number(r.out, "vertex_count") == 3169);
    CHECK(json_number(r.out, "triangle_count") == 6144);
    CHECK(json_vertices(r.out).size() == 2 * 3169);
}

TEST_CASE("d3d11-odd 2.5,3.7,5.1,4.2 gives 27 vertices and 37 triangles", "[cli]") {
    const Run r = ctess_cli("pattern --mode d3d11-odd --factors 2.5,3.7,5.1,4.2");
    REQUIRE(r.exit_code == 0);
    CHECK(json_number(r.out, "vertex_count") == 27);
    CHECK(json_number(r.out, "triangle_count") == 37);
}

TEST_CASE("pattern JSON carries the library's exact vertices", "[cli]") {
    using namespace ctess;
    const Run r = ctess_cli("pattern --mode d3d11-even --factors 2.5,3.7,5.1,4.2 --format json");
    REQUIRE(r.exit_code == 0);
    std::vector<d3d11::Point> pts(d3d11::max_tri_counts.vertices);
    std::vector<std::uint32_t> idx(d3d11::max_tri_counts.index_count());
    const auto counts = d3d11::tessellate_tri(pts, idx, {2.5f, 3.7f, 5.1f, 4.2f},
                                              {d3d11::Partitioning::fractional_even, Winding::cw});
    const auto v = json_vertices(r.out);
    REQUIRE(v.size() == 2 * counts.vertices);
    for (std::uint32_t i = 0; i < counts.vertices; ++i) {
        CHECK(v[2 * i] == pts[i].u);
        CHECK(v[2 * i + 1] == pts[i].v);
    }

    const Run c = ctess_cli("pattern --mode cp --factors 16,8,4 --layout shared");
    REQUIRE(c.exit_code == 0);
    CHECK(json_number(c.out, "fixed_one") == (1 << 24));
    cp::PatternOptions opt;
    opt.layout = Layout::shared;
    const auto cc = cp::pattern_counts(16, 8, 4, opt);
    CHECK(json_number(c.out, "vertex_count") == cc.vertices);
    CHECK(json_number(c.out, "triangle_count") == cc.triangles);
}

TEST_CASE("svg and obj outputs are written", "[cli]") {
    const std::string svg = temp_path("p.svg");
    REQUIRE(
        ctess_cli("pattern --mode cp --factors 10.3,6,3 --format svg --provoking --out " + svg).exit_code ==
        0);
    std::ifstream in(svg);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(text.rfind("<svg", 0) == 0);
    CHECK(text.find("</svg>") != std::string::npos);
    CHECK(text.find("factors (10.3, 6, 3)") != std::string::npos);
    std::filesystem::remove(svg);

    const Run obj = ctess_cli("pattern --mode d3d11-integer --factors 3,3,3,3 --format obj");
    REQUIRE(obj.exit_code == 0);
    const auto faces = std::count(obj.out.begin(), obj.out.end(), 'f');
    CHECK(faces >= 13); // 13 triangles at integer 3 (algorithm.md §5.5), plus the 'f' letters of comments
}

TEST_CASE("line, sweep and animate run", "[cli]") {
    const Run line = ctess_cli("line --mode cp --factor 1.5");
    REQUIRE(line.exit_code == 0);
    CHECK(line.out.find("4 points") != std::string::npos);
    CHECK(line.out.find("4194304") != std::string::npos); // 0.25 in units of 2^-24

    const Run even = ctess_cli("line --mode d3d11-even --factor 10.3 --format json");
    REQUIRE(even.exit_code == 0);
    CHECK(even.out.find(
              "[0, 6390, 12780, 19170, 19989, 26379, 32768, 39157, 45547, 46366, 52756, 59146, 65536]") !=
          std::string::npos); // docs/algorithm.md §5.2

    const std::string svg = temp_path("sweep.svg");
    REQUIRE(ctess_cli("sweep --mode d3d11-even --from 4 --to 8 --steps 50 --svg " + svg).exit_code == 0);
    CHECK(std::filesystem::file_size(svg) > 1000);
    std::filesystem::remove(svg);

    const std::string dir = temp_path("anim");
    REQUIRE(ctess_cli("animate --mode cp --from 1,1,1 --to 4,4,4 --frames 5 --out " + dir).exit_code == 0);
    CHECK(std::filesystem::exists(dir + "/frame_004.svg"));
    CHECK(std::filesystem::exists(dir + "/index.html"));
    std::filesystem::remove_all(dir);
}

TEST_CASE("bad arguments give a clear message and exit code 2", "[cli][bad_input]") {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"", "usage"},
        {"frobnicate", "unknown command"},
        {"pattern --mode cp", "missing required option '--factors'"},
        {"pattern --mode cp --factors nan,2,3", "must be finite and greater than 0"},
        {"pattern --mode cp --factors inf,2,3", "must be finite and greater than 0"},
        {"pattern --mode cp --factors -inf,2,3", "must be finite and greater than 0"},
        {"pattern --mode d3d11-even --factors -1,2,3,4", "must be finite and greater than 0"},
        {"pattern --mode d3d11-even --factors 0,2,3,4", "must be finite and greater than 0"},
        {"pattern --mode cp --factors 1e39,2,3", "out of the float range"},
        {"pattern --mode cp --factors abc,2,3", "is not a number"},
        {"pattern --mode cp --factors 1,,3", "is not a number"},
        {"pattern --mode cp --factors 2x,2,3", "is not a number"},
        {"pattern --mode cp --factors 1", "expected 2 to 6 comma-separated values"},
        {"pattern --mode cp --factors 1,2", "cp takes three edge factors"},
        {"pattern --mode cp --factors 1,2,3,4", "cp takes three edge factors"},
        {"pattern --mode d3d11-odd --factors 1,2", "tri domain takes"},
        {"pattern --mode bogus --factors 1,2,3", "is not one of"},
        {"pattern --mode cp --factors 1,2,3 --format png", "is not one of"},
        {"pattern --mode cp --factors 1,2,3 --winding left", "is not one of"},
        {"pattern --mode cp --factors 1,2,3 --max 128", "is not one of"},
        {"pattern --mode cp --factors 1,2,3 --bogus 1", "unknown option"},
        {"pattern --mode cp --factors 1,2,3 --factors 1,2,3", "given twice"},
        {"pattern --mode cp --factors", "needs a value"},
        {"pattern --mode cp --domain quad --factors 1,2,3", "a cp quad takes four edge factors"},
        {"pattern --mode cp --domain iso --factors 1,2", "tessellates tri and quad"},
        {"pattern --mode cp --factors 1,2,3 --column-rule fancy", "is not one of"},
        {"pattern --mode d3d11-odd --factors 1,2,3 --layout shared", "cp mode only"},
        {"line --mode cp --factor -2", "must be finite and greater than 0"},
        {"line --mode cp --factor 3 extra", "unexpected argument"},
        {"sweep --mode cp --from 4 --to 2 --svg x.svg", "--to must be greater"},
        {"sweep --mode cp --from 1 --to 2 --steps 1 --svg x.svg", "outside [2, 20000]"},
        {"sweep --mode cp --from 1 --to 2 --steps -5 --svg x.svg", "not a whole number"},
        {"animate --mode cp --from 1,1,1 --to 2,2 --frames 3 --out d", "expected 3 comma-separated"},
    };
    for (const auto& [args, message] : cases) {
        INFO("ctess " << args);
        const Run r = ctess_cli(args);
        CHECK(r.exit_code == 2);
        CHECK(r.out.find(message) != std::string::npos);
    }
    // An unwritable output path is an error too (exit 1), not a crash.
    const Run r = ctess_cli("pattern --mode cp --factors 2,2,2 --format svg --out /nonexistent-dir/x.svg");
    CHECK(r.exit_code == 1);
    CHECK(r.out.find("cannot write") != std::string::npos);
}

TEST_CASE("finite out-of-range factors are clamped as documented", "[cli][bad_input]") {
    // CP clamps to [1, max]; D3D11 clamps edges to its partitioning's range.
    const Run big = ctess_cli("pattern --mode cp --factors 1000,1000,1000 --max 64 --layout shared");
    REQUIRE(big.exit_code == 0);
    CHECK(json_number(big.out, "triangle_count") == 64 * 64);
    const Run small = ctess_cli("pattern --mode cp --factors 0.25,0.5,1e-30 --layout shared");
    REQUIRE(small.exit_code == 0);
    CHECK(json_number(small.out, "triangle_count") == 1);
    const Run d3d = ctess_cli("pattern --mode d3d11-even --factors 1e30,1e30,1e30,1e30");
    REQUIRE(d3d.exit_code == 0);
    CHECK(json_number(d3d.out, "triangle_count") == 6144);
}

TEST_CASE("a cp quad tiles the unit square and welds its diagonal", "[cli]") {
    for (const char* layout : {"shared", "provoking"}) {
        INFO(layout);
        const Run r = ctess_cli(
            std::string("pattern --mode cp --domain quad --factors 12,5,12,30 --winding ccw --layout ") +
            layout);
        REQUIRE(r.exit_code == 0);
        const auto v = json_vertices(r.out);
        const auto t = json_triangles(r.out);
        REQUIRE(t.size() % 3 == 0);
        std::int64_t doubled = 0;
        for (std::size_t i = 0; i < t.size(); i += 3) {
            const std::int64_t ax = v[2 * t[i]], ay = v[2 * t[i] + 1];
            const std::int64_t bx = v[2 * t[i + 1]], by = v[2 * t[i + 1] + 1];
            const std::int64_t cx = v[2 * t[i + 2]], cy = v[2 * t[i + 2] + 1];
            const std::int64_t a = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
            CHECK(a >= 0);
            doubled += a;
        }
        CHECK(doubled == 2 * (std::int64_t{1} << 48)); // the unit square, in units of 2^-24
        // Welded: the diagonal's points appear once (shared), or once per half (provoking).
        std::size_t on_diagonal = 0;
        for (std::size_t i = 0; i < v.size(); i += 2) on_diagonal += v[i] + v[i + 1] == (1u << 24);
        std::uint32_t line[300];
        const unsigned n = ctess::cp::edge_points(12.0f, 64, line);
        CHECK(on_diagonal == (std::string(layout) == "shared" ? n : 2 * n));
    }
}

// --- ctess strip and ctess surface (docs/surfaces.md) ---

namespace {

// The numbers of the JSON array that follows "key": [ up to its closing bracket (nested arrays flattened).
std::vector<double> json_array(const std::string& json, const std::string& key) {
    const std::string tag = "\"" + key + "\": [";
    const auto begin = json.find(tag);
    REQUIRE(begin != std::string::npos);
    std::size_t end = begin + tag.size();
    for (int depth = 1; depth > 0; ++end) depth += json[end] == '[' ? 1 : json[end] == ']' ? -1 : 0;
    std::string body = json.substr(begin + tag.size(), end - begin - tag.size() - 1);
    for (char& c : body)
        if (c == '[' || c == ']' || c == ',') c = ' ';
    std::vector<double> out;
    std::istringstream in(body);
    for (double x; in >> x;) out.push_back(x);
    return out;
}

} // namespace

TEST_CASE("strip prints the library's single strip, starting with Cayzac 2007's", "[cli][surfaces]") {
    const Run r = ctess_cli("strip --segments 3,4 --format json");
    REQUIRE(r.exit_code == 0);
    CHECK(json_number(r.out, "u_segments") == 3);
    CHECK(json_number(r.out, "v_segments") == 4);
    const auto indices = json_array(r.out, "indices");
    const std::vector<double> seed = {0, 4, 1, 5, 2, 6, 3, 7, 11, 7, 10, 6, 9, 5, 8, 4, 8, 12};
    REQUIRE(indices.size() == 32);
    for (std::size_t i = 0; i < seed.size(); ++i) CHECK(indices[i] == seed[i]);

    const Run big = ctess_cli("strip --segments 37,5");
    REQUIRE(big.exit_code == 0);
    std::vector<std::uint32_t> expect(ctess::grid::strip_index_count(37, 5));
    REQUIRE(ctess::grid::fill_strip_indices(expect, 37, 5));
    const auto got = json_array(big.out, "indices");
    REQUIRE(got.size() == expect.size());
    for (std::size_t i = 0; i < got.size(); ++i) CHECK(got[i] == expect[i]);
}

TEST_CASE("strip refuses bad segment counts, naming the limit", "[cli][surfaces]") {
    for (const char* bad : {"0,3", "3,1025", "3", "3,4,5", "a,2", "-1,2"}) {
        INFO(bad);
        const Run r = ctess_cli(std::string("strip --segments ") + bad);
        CHECK(r.exit_code == 2);
        CHECK(r.out.find("--segments") != std::string::npos);
    }
    CHECK(ctess_cli("strip --segments 3,1025").out.find("[1, 1024]") != std::string::npos);
    CHECK(ctess_cli("strip --segments 3,4 --format svg").exit_code == 2);
}

TEST_CASE("surface JSON is a conforming triangulation of the square with unit normals", "[cli][surfaces]") {
    for (const char* name : {"sphere", "torus", "ripple"}) {
        INFO(name);
        const Run r = ctess_cli(std::string("surface --name ") + name + " --max-level 12 --format json");
        REQUIRE(r.exit_code == 0);
        CHECK(json_number(r.out, "fixed_one") == 65536);
        const auto params = json_array(r.out, "params");
        const auto vertices = json_array(r.out, "vertices");
        const auto normals = json_array(r.out, "normals");
        const auto triangles = json_array(r.out, "triangles");
        REQUIRE(params.size() / 2 == static_cast<std::size_t>(json_number(r.out, "vertex_count")));
        REQUIRE(triangles.size() / 3 == static_cast<std::size_t>(json_number(r.out, "triangle_count")));
        REQUIRE(vertices.size() == 3 * params.size() / 2);
        REQUIRE(normals.size() == vertices.size());
        std::vector<ctess::analysis::SquarePoint> sq;
        for (std::size_t i = 0; i < params.size(); i += 2)
            sq.push_back({static_cast<std::int64_t>(params[i]), static_cast<std::int64_t>(params[i + 1])});
        const std::vector<std::uint32_t> tri(triangles.begin(), triangles.end());
        CHECK(ctess::analysis::square_mesh_violation(sq, tri, 65536) == "");
        for (std::size_t i = 0; i < normals.size(); i += 3) {
            const double len2 =
                normals[i] * normals[i] + normals[i + 1] * normals[i + 1] + normals[i + 2] * normals[i + 2];
            CHECK(std::abs(len2 - 1.0) < 1e-5);
        }
    }
}

TEST_CASE("surface writes OBJ with normals, both SVG views and the uniform-grid comparison",
          "[cli][surfaces]") {
    const Run obj = ctess_cli("surface --name torus --max-level 10 --format obj");
    REQUIRE(obj.exit_code == 0);
    std::istringstream lines(obj.out);
    std::size_t v = 0, vn = 0, f = 0;
    for (std::string line; std::getline(lines, line);) {
        v += line.rfind("v ", 0) == 0;
        vn += line.rfind("vn ", 0) == 0;
        f += line.rfind("f ", 0) == 0;
    }
    CHECK(v > 0);
    CHECK(vn == v);
    CHECK(f > 0);

    for (const char* view : {"param", "shaded"}) {
        const std::string svg = temp_path(std::string("surface_") + view + ".svg");
        REQUIRE(ctess_cli(std::string("surface --name ripple --max-level 10 --format svg --view ") + view +
                          " --out " + svg)
                    .exit_code == 0);
        std::ifstream in(svg);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        CHECK(text.rfind("<svg", 0) == 0);
        CHECK(text.find("</svg>") != std::string::npos);
        CHECK(text.find("ripple") != std::string::npos);
        std::filesystem::remove(svg);
    }

    const Run stats = ctess_cli("surface --name sphere --max-level 12 --format stats");
    REQUIRE(stats.exit_code == 0);
    CHECK(stats.out.find("\"reached\": true") != std::string::npos);
    CHECK(json_number(stats.out, "triangles") > 0);
}

TEST_CASE("surface refuses bad thresholds, levels and names with a clear error", "[cli][surfaces]") {
    const std::pair<const char*, const char*> cases[] = {
        {"--angle nan", "angle threshold"},
        {"--angle -1", "angle threshold"},
        {"--distance nan", "distance threshold"},
        {"--distance -0.1", "distance threshold"},
        {"--min-level 9 --max-level 5", "min_level <= max_level"},
        {"--max-level 19", "[0, 18]"},
        {"--format obj --view shaded", "--view"},
    };
    for (const auto& [args, message] : cases) {
        INFO(args);
        const Run r = ctess_cli(std::string("surface --name sphere ") + args);
        CHECK(r.exit_code == 2);
        CHECK(r.out.find(message) != std::string::npos);
    }
    const Run cube = ctess_cli("surface --name cube");
    CHECK(cube.exit_code == 2);
    CHECK(cube.out.find("sphere, torus, ripple") != std::string::npos);
}

// --- uniform density (docs/algorithm.md §3) ---

TEST_CASE("cli: pattern --mode uniform is the stored pattern, in any factor order", "[cli][uniform]") {
    const auto p = ctess::uniform::pattern(11, 9, 6);
    for (const char* factors : {"11,9,6", "6,11,9", "9,6,11", "10.6,9.4,6"}) {
        INFO(factors);
        const Run r =
            ctess_cli(std::string("pattern --mode uniform --factors ") + factors + " --format json");
        REQUIRE(r.exit_code == 0);
        CHECK(json_number(r.out, "fixed_one") == 65534);
        CHECK(json_number(r.out, "vertex_count") == long(p.vertex_count()));
        CHECK(json_number(r.out, "triangle_count") == long(p.triangle_count()));
        CHECK(json_number(r.out, "degenerate_triangle_count") == 0);
    }
    const Run svg = ctess_cli("pattern --mode uniform --factors 11,9,6 --format svg");
    REQUIRE(svg.exit_code == 0);
    CHECK(svg.out.find("<svg") != std::string::npos);
    const Run obj = ctess_cli("pattern --mode uniform --factors 11,9,6 --format obj");
    REQUIRE(obj.exit_code == 0);
    CHECK(obj.out.find("\nf ") != std::string::npos);
}

TEST_CASE("cli: pattern --mode uniform --layout provoking appends the fewest copies", "[cli][uniform]") {
    // 11, 9, 6 has more triangles than vertices: one vertex per triangle, every first index its own.
    const auto p = ctess::uniform::pattern(11, 9, 6);
    REQUIRE(p.triangle_count() > p.vertex_count());
    const Run r = ctess_cli("pattern --mode uniform --factors 6,11,9 --format json --layout provoking");
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("\"layout\": \"provoking\"") != std::string::npos);
    CHECK(json_number(r.out, "vertex_count") == long(p.triangle_count()));
    CHECK(json_number(r.out, "triangle_count") == long(p.triangle_count()));
    CHECK(json_number(r.out, "degenerate_triangle_count") == 0);
    const Run shared = ctess_cli("pattern --mode uniform --factors 6,11,9 --format json");
    CHECK(json_number(shared.out, "vertex_count") == long(p.vertex_count()));
}

TEST_CASE("cli: pattern --mode uniform above the table splits (units 65534^2, welded when shared)",
          "[cli][uniform]") {
    const Run shared = ctess_cli("pattern --mode uniform --factors 40,30,20 --format json");
    const Run separate =
        ctess_cli("pattern --mode uniform --factors 40,30,20 --format json --layout provoking");
    REQUIRE(shared.exit_code == 0);
    REQUIRE(separate.exit_code == 0);
    CHECK(json_number(shared.out, "fixed_one") == 4294705156L);
    CHECK(json_number(shared.out, "degenerate_triangle_count") == 0);
    CHECK(json_number(shared.out, "triangle_count") == json_number(separate.out, "triangle_count"));
    CHECK(json_number(shared.out, "vertex_count") < json_number(separate.out, "vertex_count"));
}

TEST_CASE("cli: pattern --mode uniform above the table, shared = the provoking triangles welded by position",
          "[cli][uniform]") {
    // The library welds (docs/algorithm.md §3.5): each position once, the same triangles as position pairs.
    const Run shared = ctess_cli("pattern --mode uniform --factors 40,30,25 --format json");
    const Run separate =
        ctess_cli("pattern --mode uniform --factors 40,30,25 --format json --layout provoking");
    REQUIRE(shared.exit_code == 0);
    REQUIRE(separate.exit_code == 0);
    const std::vector<std::uint32_t> sv = json_vertices(shared.out), pv = json_vertices(separate.out);
    const std::vector<std::uint32_t> st = json_triangles(shared.out), pt = json_triangles(separate.out);
    using Position = std::pair<std::uint32_t, std::uint32_t>;
    std::set<Position> shared_positions, provoking_positions;
    for (std::size_t i = 0; i < sv.size(); i += 2) shared_positions.insert({sv[i], sv[i + 1]});
    for (std::size_t i = 0; i < pv.size(); i += 2) provoking_positions.insert({pv[i], pv[i + 1]});
    CHECK(shared_positions.size() == sv.size() / 2);
    CHECK(shared_positions == provoking_positions);
    CHECK(json_number(shared.out, "vertex_count") == 364); // = 1 + (T + B) / 2 with T = 631, B = 95
    REQUIRE(st.size() == pt.size());
    for (std::size_t k = 0; k < st.size(); ++k)
        REQUIRE(Position{sv[2 * st[k]], sv[2 * st[k] + 1]} == Position{pv[2 * pt[k]], pv[2 * pt[k] + 1]});
}

TEST_CASE("cli: pattern --mode uniform bad input is a usage error", "[cli][uniform][bad_input]") {
    for (const char* args :
         {"--factors 1,2", "--factors 1,2,3,4", "--factors 3,3,3 --domain quad", "--factors 3,3,3 --max 64",
          "--factors 3,3,3 --column-rule staircase", "--factors 3,-1,3", "--factors 3,nan,3"}) {
        INFO(args);
        const Run r = ctess_cli(std::string("pattern --mode uniform ") + args);
        CHECK(r.exit_code != 0);
        CHECK(r.out.find("error") != std::string::npos);
    }
}

TEST_CASE("cli: efficiency --family uniform totals the stored patterns", "[cli][uniform]") {
    unsigned total = 0;
    for (unsigned a = 1; a <= 11; ++a)
        for (unsigned b = 1; b <= a; ++b)
            for (unsigned c = 1; c <= b; ++c) total += ctess::uniform::pattern(a, b, c).triangle_count();
    const Run r = ctess_cli("efficiency --family uniform");
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("| a <= 11 | 286 | " + std::to_string(total) + " |") != std::string::npos);
    CHECK(r.out.find("binary longest-edge") != std::string::npos);
    // Both interior dice tolerances of the split (docs/algorithm.md §3.5), in text and JSON.
    CHECK(r.out.find("| 1.433 N |") != std::string::npos);
    CHECK(r.out.find("| 1.000 N |") != std::string::npos);
    const Run j = ctess_cli("efficiency --family uniform --format json");
    REQUIRE(j.exit_code == 0);
    CHECK(j.out.find("\"interior_tolerance\": 1.433") != std::string::npos);
    CHECK(j.out.find("\"interior_tolerance\": 1.000") != std::string::npos);
    CHECK(j.out.find("\"longest_edge_mean_of_maxima\"") != std::string::npos);
}

// --- uniform: factors, bad input, limits and options (docs/cli.md "Modes", "Errors and bad input") ---------

namespace {

// The "uniform_factors" array of a uniform pattern's JSON.
std::vector<long> json_uniform_factors(const std::string& json) {
    const auto at = json.find("\"uniform_factors\": [");
    REQUIRE(at != std::string::npos);
    std::string body = json.substr(at + 20, json.find(']', at) - at - 20);
    for (char& c : body)
        if (c == ',') c = ' ';
    std::vector<long> out;
    std::istringstream in(body);
    for (long x; in >> x;) out.push_back(x);
    return out;
}

// docs/algorithm.md §3.2, written out independently: on an edge with f segments the smaller coordinate of
// point i is i / f rounded half up in units of 65534, the larger is 65534 minus the other one.
std::uint32_t spec_edge_parameter(std::uint32_t i, std::uint32_t f) {
    const std::uint32_t small = std::min(i, f - i);
    const std::uint32_t q = (2 * small * 65534 + f) / (2 * f);
    return i <= f - i ? q : 65534 - q;
}

} // namespace

TEST_CASE("cli: uniform factors are rounded to the nearest integer, halves up, above N the patch splits",
          "[cli][uniform]") {
    struct Case {
        std::string factors;
        std::vector<long> used; // one table pattern each
    };
    const Run n_run = ctess_cli("pattern --mode uniform --factors 1,1,1");
    REQUIRE(n_run.exit_code == 0);
    const long n = json_number(n_run.out, "max_tess_factor"); // the table's N
    REQUIRE((n == 16 || n == 11));
    const std::string below = std::to_string(n) + ".49", half = std::to_string(n) + ".5";
    for (const Case& c : {Case{"10.6,9.4,6", {11, 9, 6}}, Case{"2.5,1.49,1.5", {3, 1, 2}},
                          Case{"0.2,1e-30,1", {1, 1, 1}}, Case{below + ",3,3", {n, 3, 3}}}) {
        INFO(c.factors);
        const Run r = ctess_cli("pattern --mode uniform --format json --factors " + c.factors);
        REQUIRE(r.exit_code == 0);
        CHECK(json_uniform_factors(r.out) == c.used);
        CHECK(json_number(r.out, "subpatch_count") == 1);
        CHECK(json_number(r.out, "split_depth") == 0);
        CHECK(json_number(r.out, "fixed_one") == 65534);
    }
    const Run split = ctess_cli("pattern --mode uniform --format json --factors " + half + ",3,3");
    REQUIRE(split.exit_code == 0);
    CHECK(json_uniform_factors(split.out) == std::vector<long>{n + 1, 3, 3});
    CHECK(json_number(split.out, "subpatch_count") > 1);
    CHECK(json_number(split.out, "split_depth") >= 1);
    CHECK(json_number(split.out, "fixed_one") == 4294705156L); // 65534^2
    CHECK(json_number(split.out, "max_tess_factor") == n);     // N, not the factor accepted
}

TEST_CASE("cli: uniform nan, inf, -inf, 0 and negative factors are exit 2 with no output",
          "[cli][uniform][bad_input]") {
    const std::string file = temp_path("uniform_bad.json");
    for (const char* bad : {"inf", "-inf", "0", "-1", "nan", "-0"}) {
        for (const std::string& factors : {std::string(bad) + ",3,3", "3,3," + std::string(bad)}) {
            INFO(factors);
            std::filesystem::remove(file);
            const Run to_file = ctess_cli("pattern --mode uniform --factors " + factors + " --out " + file);
            CHECK(to_file.exit_code == 2);
            CHECK(to_file.out.find("finite and greater than 0") != std::string::npos);
            CHECK_FALSE(std::filesystem::exists(file));
            const Run to_stdout = ctess::test::run_shell(std::string(CTESS_CLI) +
                                                         " pattern --mode uniform --format svg --factors " +
                                                         factors + " 2>/dev/null");
            CHECK(to_stdout.exit_code == 2);
            CHECK(to_stdout.out.empty());
        }
    }
}

TEST_CASE("cli: uniform factors above 512 are refused, 512 splits within the output bound",
          "[cli][uniform]") {
    // docs/cli.md "Uniform factors": the library splits to 32,768; the CLI writes at most factor 512.
    for (const char* huge : {"1e30", "3e38", "513", "512.5", "3.4028235e38"}) {
        INFO(huge);
        const std::string h(huge);
        const Run r = ctess_cli("pattern --mode uniform --format json --factors " + h + ",3,3");
        CHECK(r.exit_code == 2);
        CHECK(r.out.find("up to 512") != std::string::npos); // the error, and no pattern
        CHECK(r.out.find("\"vertices\"") == std::string::npos);
    }
    const Run top = ctess_cli("pattern --mode uniform --format json --factors 512.49,512,512");
    REQUIRE(top.exit_code == 0);
    CHECK(json_uniform_factors(top.out) == std::vector<long>{512, 512, 512});
    CHECK(json_number(top.out, "triangle_count") == 512L * 512L); // T^2 triangles at equal factors T (§3.5)
    CHECK(json_number(top.out, "split_depth") >= 2);
    CHECK(json_number(top.out, "subpatch_count") > 1);
    CHECK(json_number(top.out, "degenerate_triangle_count") == 0);
}

TEST_CASE("cli: uniform 11,9,6 JSON vertices are the quantised boundary points (docs/algorithm.md §3.2) and "
          "the pattern data",
          "[cli][uniform]") {
    const Run r = ctess_cli("pattern --mode uniform --factors 11,9,6 --format json");
    REQUIRE(r.exit_code == 0);
    const std::vector<std::uint32_t> v = json_vertices(r.out);
    // Boundary, counter-clockwise from v0 (docs/algorithm.md §3.1): e0's points, v1, e1's points, v2, e2's.
    std::vector<std::uint32_t> boundary = {0, 0};
    for (std::uint32_t i = 1; i < 11; ++i) boundary.insert(boundary.end(), {spec_edge_parameter(i, 11), 0});
    boundary.insert(boundary.end(), {65534, 0});
    for (std::uint32_t i = 1; i < 9; ++i) {
        const std::uint32_t p = spec_edge_parameter(i, 9);
        boundary.insert(boundary.end(), {65534 - p, p});
    }
    boundary.insert(boundary.end(), {0, 65534});
    for (std::uint32_t i = 1; i < 6; ++i) boundary.insert(boundary.end(), {0, spec_edge_parameter(6 - i, 6)});
    REQUIRE(v.size() >= boundary.size());
    CHECK(std::vector<std::uint32_t>(v.begin(), v.begin() + long(boundary.size())) == boundary);
    // Every vertex, in order: the constexpr data's canonical numbering (the sorted triple needs no corner
    // map).
    const auto p = ctess::uniform::pattern(11, 9, 6);
    std::vector<std::uint32_t> expected;
    for (unsigned k = 0; k < p.vertex_count(); ++k)
        expected.insert(expected.end(), {p.vertex(k).u, p.vertex(k).v});
    CHECK(v == expected);
    // 6,11,9: canonical v2 (opposite the largest) goes to output v0, v0 to v1, v1 to v2 (§3.4), so a
    // canonical (u, v) with w = 65534 - u - v lands at (w, u).
    const Run rotated = ctess_cli("pattern --mode uniform --factors 6,11,9 --format json");
    REQUIRE(rotated.exit_code == 0);
    const std::vector<std::uint32_t> rv = json_vertices(rotated.out);
    using Position = std::pair<std::uint32_t, std::uint32_t>;
    std::set<Position> got, mapped;
    for (std::size_t i = 0; i + 1 < rv.size(); i += 2) got.insert({rv[i], rv[i + 1]});
    for (unsigned k = 0; k < p.vertex_count(); ++k)
        mapped.insert({65534 - p.vertex(k).u - p.vertex(k).v, p.vertex(k).u});
    CHECK(got == mapped);
    CHECK(json_uniform_factors(rotated.out) == std::vector<long>{6, 11, 9});
}

TEST_CASE("cli: options that do not apply to uniform are exit 2", "[cli][uniform][bad_input]") {
    for (const char* args :
         {"pattern --mode uniform --factors 3,3,3 --domain quad",
          "pattern --mode uniform --factors 3,3,3 --domain iso",
          "pattern --mode uniform --factors 3,3,3 --max 64",
          "pattern --mode uniform --factors 3,3,3 --column-rule minimal",
          "pattern --mode uniform --factors 3,3,3,3", "efficiency --family uniform --random 5",
          "efficiency --family uniform --seed 1", "line --mode uniform --factor 3",
          "sweep --mode uniform --from 1 --to 3 --svg /dev/null"}) {
        INFO(args);
        const Run r = ctess::test::run_shell(std::string(CTESS_CLI) + " " + args + " 2>/dev/null");
        CHECK(r.exit_code == 2);
        CHECK(r.out.empty());
    }
    const Run help = ctess_cli("--help");
    CHECK(help.out.find("d3d11-even, uniform") != std::string::npos);
    const Run efficiency_help = ctess_cli("efficiency --help");
    CHECK(efficiency_help.out.find("--family cp|uniform") != std::string::npos);
}

TEST_CASE("cli: a split uniform SVG names N and the subpatches", "[cli][uniform]") {
    const Run r = ctess_cli("pattern --mode uniform --factors 40,30,20 --format svg");
    REQUIRE(r.exit_code == 0);
    const Run json = ctess_cli("pattern --mode uniform --factors 40,30,20 --format json");
    const std::string label =
        "uniform density, N = " + std::to_string(json_number(json.out, "max_tess_factor")) +
        " · split into " + std::to_string(json_number(json.out, "subpatch_count")) + " subpatches, depth " +
        std::to_string(json_number(json.out, "split_depth"));
    CHECK(r.out.find(label) != std::string::npos);
    CHECK(r.out.find("max factor") == std::string::npos);
    const Run rounded = ctess_cli("pattern --mode uniform --factors 10.6,9.4,6 --format svg");
    CHECK(rounded.out.find("used (11, 9, 6) · one table pattern") != std::string::npos);
}
