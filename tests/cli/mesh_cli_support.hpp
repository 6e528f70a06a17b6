// What the `ctess mesh` CLI tests share (test_cli_mesh.cpp, test_cli_displace.cpp): a scratch folder per test
// binary, writing a file, `ctess mesh --stats` parsed as JSON, and a small closed mixed model with split
// normals and uv seams.
#pragma once
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "support/cli_run.hpp"

namespace ctess::test {

// folder/name under the system's temporary directory, the folder created.
inline std::string scratch_path(const std::string& folder, const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / folder;
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

inline void write_file(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out << bytes;
}

// `ctess mesh --stats ARGS`, which must succeed, as JSON.
inline nlohmann::json mesh_stats(const std::string& args) {
    const Run r = ctess_cli("mesh --stats " + args);
    INFO(args << "\n" << r.out);
    REQUIRE(r.exit_code == 0);
    return nlohmann::json::parse(r.out);
}

// A command that must be refused: its exit code, a part of its message, and no file at out afterwards.
struct RefusedCase {
    std::string args; // after `ctess mesh`
    int exit_code;
    std::string message;
};

inline void check_refused(const std::vector<RefusedCase>& cases, const std::string& out) {
    for (const RefusedCase& c : cases) {
        const Run r = ctess_cli("mesh " + c.args);
        INFO(c.args << "\n" << r.out);
        CHECK(r.exit_code == c.exit_code);
        CHECK(r.out.find(c.message) != std::string::npos);
        CHECK_FALSE(std::filesystem::exists(out));
    }
}

// A closed mixed model: a unit cube whose four sides are quads and whose top and bottom are two triangles
// each, with one normal per face (split normals on every edge) and every face on the same uv square (uv seams
// everywhere: each shared edge is sampled at different uvs by its two faces).
inline std::string mixed_cube_obj() {
    std::string s = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";
    s += "vn 0 -1 0\nvn 1 0 0\nvn 0 1 0\nvn -1 0 0\nvn 0 0 -1\nvn 0 0 1\n";
    s += "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
    s += "f 1/1/1 2/2/1 6/3/1 5/4/1\nf 2/1/2 3/2/2 7/3/2 6/4/2\nf 3/1/3 4/2/3 8/3/3 7/4/3\nf 4/1/4 1/2/4 "
         "5/3/4 8/4/4\n";
    s += "f 1/1/5 4/4/5 3/3/5\nf 1/1/5 3/3/5 2/2/5\nf 5/1/6 6/2/6 7/3/6\nf 5/1/6 7/3/6 8/4/6\n";
    return s;
}

} // namespace ctess::test
