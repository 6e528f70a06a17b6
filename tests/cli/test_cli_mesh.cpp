// `ctess mesh` as a user runs it (docs/cli.md, "ctess mesh"): real models from Debian's assimp-testmodels
// where installed, and small models written here. A closed model stays closed (every output edge in two
// triangles, by exact position) for every pattern, surface and factor mode; an open model's boundary is its
// input boundary subdivided; PN-AEN closes the cracks plain PN opens at split normals; outputs read back; bad
// input fails with nothing written.
#include "mesh_cli_support.hpp"
#include "support/cli_run.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

using ctess::test::ctess_cli;
using ctess::test::mixed_cube_obj;
using ctess::test::Run;
using ctess::test::write_file;

namespace {

const std::string assimp_models = "/usr/share/assimp/models";

std::string scratch(const std::string& name) {
    return ctess::test::scratch_path("ctess_test_cli_mesh", name);
}

nlohmann::json stats(const std::string& args) {
    return ctess::test::mesh_stats(args);
}

} // namespace

TEST_CASE("ctess mesh: a closed mixed model with split normals stays closed for every pattern, surface and "
          "factor mode",
          "[cli][mesh]") {
    const std::string in = scratch("mixed_cube.obj");
    write_file(in, mixed_cube_obj());
    for (const char* pattern : {"cp", "uniform", "d3d11-integer", "d3d11-pow2", "d3d11-odd", "d3d11-even"})
        for (const char* surface : {"flat", "pn", "pn-aen", "phong"})
            for (const char* factors :
                 {"--factor 5.5", "--edge-length 0.07", "--dice-rate 2 --camera 2.5,1.7,3.1"}) {
                const nlohmann::json s = stats(std::string("--in ") + in + " --pattern " + pattern +
                                               " --surface " + surface + " " + factors);
                CHECK(s["input_triangles"] == 4);
                CHECK(s["input_quads"] == 4);
                CHECK(s["input_open_edges"] == 0);
                CHECK(s["output_triangles"].get<long>() > 8);
                CHECK(s["output_open_edges"] == 0);
            }
}

TEST_CASE("ctess mesh: an open model's boundary is its input boundary, subdivided", "[cli][mesh]") {
    // A 2 x 1 strip of quads: 6 boundary edges. An edge of uniform factor F has F segments, and a CP edge at
    // a power of two F too (§1: the top of a token's range), so the output has 6 F open edges and 4 F^2
    // triangles.
    const std::string in = scratch("strip.obj");
    write_file(in, "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nf 1 2 5 4\nf 2 3 6 5\n");
    for (const std::string pattern : {"cp", "uniform"})
        for (const int f : {1, pattern == "cp" ? 2 : 3, 8}) {
            const nlohmann::json s =
                stats(std::string("--in ") + in + " --pattern " + pattern + " --factor " + std::to_string(f));
            CHECK(s["input_open_edges"] == 6);
            CHECK(s["output_open_edges"] == 6 * f);
            CHECK(s["output_triangles"] == 2 * 2 * f * f);
        }
}

TEST_CASE("ctess mesh: uniform density above N splits (§7.5): closed stays closed, nothing clamped",
          "[cli][mesh]") {
    const std::string in = scratch("mixed_cube_split.obj");
    write_file(in, mixed_cube_obj());
    for (const char* surface : {"flat", "pn-aen"})
        for (const char* factors : {"--factor 40", "--edge-length 0.01"}) {
            const nlohmann::json s =
                stats(std::string("--in ") + in + " --pattern uniform --surface " + surface + " " + factors);
            CHECK(s["clamped_edges"] == 0);
            CHECK(s["output_open_edges"] == 0);
            // Clamped to N = 16 a face would have at most 16^2 triangles (a quad 2 x 16^2).
            CHECK(s["output_triangles"].get<long>() > 12 * 16 * 16);
        }
    // An edge of factor 100 splits into ceil(100 / 16) = 7 pieces of factor 100 / 7, each diced at 14
    // (§3.5): 98 segments on each of the strip's 6 boundary edges.
    const std::string strip = scratch("strip_split.obj");
    write_file(strip, "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nv 1 1 0\nv 2 1 0\nf 1 2 5 4\nf 2 3 6 5\n");
    const nlohmann::json s = stats("--in " + strip + " --pattern uniform --factor 100");
    CHECK(s["output_open_edges"] == 6 * 98);
    CHECK(s["clamped_edges"] == 0);
}

TEST_CASE("ctess mesh: real closed models stay closed (assimp-testmodels)", "[cli][mesh][real]") {
    const std::vector<std::string> closed = {
        "OBJ/box.obj", "OBJ/testmixed.obj", "glTF2/BoxTextured-glTF/BoxTextured.gltf",
        "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", "glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf"};
    for (const std::string& name : closed) {
        const std::string in = assimp_models + "/" + name;
        if (!std::filesystem::exists(in)) {
            WARN("assimp-testmodels not installed: " << in << " skipped");
            continue;
        }
        for (const char* pattern : {"cp", "uniform"})
            for (const char* surface : {"flat", "pn-aen"}) {
                const nlohmann::json s = stats("--in " + in + " --pattern " + pattern + " --surface " +
                                               surface + " --edge-length 0.05");
                INFO(name << " " << pattern << " " << surface);
                CHECK(s["input_open_edges"] == 0);
                CHECK(s["output_open_edges"] == 0);
                CHECK(s["output_triangles"].get<long>() > 1000);
            }
    }
}

TEST_CASE("ctess mesh: PN-AEN closes the cracks plain PN opens at split normals (spider.obj)",
          "[cli][mesh][real]") {
    const std::string in = assimp_models + "/OBJ/spider.obj";
    if (!std::filesystem::exists(in)) {
        WARN("assimp-testmodels not installed: spider.obj skipped");
        return;
    }
    // An open model (its boundary is open in every mode); PN cracks on top of that, PN-AEN does not.
    const std::string common = " --in " + in + " --dice-rate 2 --camera 0,0,400";
    const long flat = stats(common + " --surface flat")["output_open_edges"];
    const long pn = stats(common + " --surface pn")["output_open_edges"];
    const long aen = stats(common + " --surface pn-aen")["output_open_edges"];
    CHECK(pn > flat + 100);
    CHECK(aen == flat);
}

TEST_CASE("ctess mesh --threads: the welded file of 2 and 3 threads is the one thread's, byte for byte",
          "[cli][mesh][real]") {
    // WusonOBJ (quads and triangles, seams) and spider.obj (open, split normals), with CP, uniform splitting
    // above N, PN and PN-AEN.
    // A mixed cube written here runs wherever assimp-testmodels is missing.
    const std::string cube = scratch("mixed_cube_threads.obj");
    write_file(cube, mixed_cube_obj());
    std::vector<std::pair<std::string, std::string>> runs = {
        {cube, " --factor 40 --pattern uniform --surface pn-aen"},
        {assimp_models + "/OBJ/WusonOBJ.obj", " --factor 12 --surface pn"},
        {assimp_models + "/OBJ/spider.obj", " --dice-rate 1 --camera 0,0,300 --pattern uniform"},
    };
    for (const auto& [in, options] : runs) {
        if (!std::filesystem::exists(in)) {
            WARN("assimp-testmodels not installed: " << in << " skipped");
            continue;
        }
        std::string one;
        for (const char* threads : {"1", "2", "3"}) {
            const std::string out = scratch(std::string("threads_") + threads + ".glb");
            std::filesystem::remove(out);
            const nlohmann::json s =
                stats("--in " + in + options + " --out " + out + " --threads " + threads);
            INFO(in << options << " --threads " << threads);
            CHECK(s["threads"] == std::stoi(threads));
            std::ifstream file(out, std::ios::binary);
            const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
            REQUIRE(bytes.size() > 1000);
            if (one.empty())
                one = bytes;
            else
                CHECK(bytes == one);
        }
    }
}

TEST_CASE("ctess mesh: OBJ and glTF outputs read back as the same closed mesh, PLY is sized by its header",
          "[cli][mesh]") {
    const std::string in = scratch("mixed_cube_out.obj");
    write_file(in, mixed_cube_obj());
    for (const char* ext : {"obj", "glb"}) {
        const std::string out = scratch(std::string("cube_out.") + ext);
        std::filesystem::remove(out);
        const nlohmann::json s = stats("--in " + in + " --factor 4 --surface pn-aen --out " + out);
        // Read back at factor 1: every output triangle is an input triangle of the second run.
        const nlohmann::json back = stats("--in " + out + " --factor 1");
        INFO(ext);
        CHECK(back["input_triangles"] == s["output_triangles"]);
        CHECK(back["input_open_edges"] == 0);
        CHECK(back["output_open_edges"] == 0);
    }
    const std::string ply = scratch("cube_out.ply");
    const nlohmann::json s = stats("--in " + in + " --factor 4 --out " + ply);
    std::ifstream file(ply, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    const auto header_end = bytes.find("end_header\n");
    REQUIRE(header_end != std::string::npos);
    const std::size_t v = s["output_vertices"], t = s["output_triangles"];
    CHECK(bytes.find("element vertex " + std::to_string(v) + "\n") != std::string::npos);
    CHECK(bytes.find("element face " + std::to_string(t) + "\n") != std::string::npos);
    CHECK(bytes.size() == header_end + 11 + 32 * v + 13 * t); // 8 floats per vertex; count byte + 3 uint32
}

TEST_CASE("ctess mesh: bad input is a clear error and writes nothing", "[cli][mesh][bad_input]") {
    const std::string out = scratch("never.obj");
    std::filesystem::remove(out);
    const std::string cube = scratch("cube_for_errors.obj");
    write_file(cube, mixed_cube_obj());
    const std::string truncated = scratch("truncated.glb");
    write_file(truncated, std::string("glTF\x02\x00\x00\x00\xff\xff\xff\x7f", 12));
    const std::vector<ctess::test::RefusedCase> cases = {
        {"--in /nonexistent/model.obj --factor 2 --out " + out, 1, "/nonexistent/model.obj"},
        {"--in " + truncated + " --factor 2 --out " + out, 1, truncated},
        {"--in " + cube + " --factor 2 --out " + scratch("never.stl"), 2, ".obj, .ply or .glb"},
        {"--in " + cube + " --factor 2 --edge-length 1 --out " + out, 2, "exactly one of"},
        {"--in " + cube + " --out " + out, 2, "exactly one of"},
        {"--in " + cube + " --factor nan --out " + out, 2, "--factor"},
        {"--in " + cube + " --factor -1 --out " + out, 2, "--factor"},
        {"--in " + cube + " --dice-rate 2 --out " + out, 2, "--camera"},
        {"--in " + cube + " --dice-rate 2 --camera 1,2 --out " + out, 2, "--camera"},
        {"--in " + cube + " --factor 2 --surface smooth --out " + out, 2, "--surface"},
        {"--in " + cube + " --factor 2 --pattern d3d11-quad --out " + out, 2, "--pattern"},
        {"--in " + cube + " --factor 2", 2, "--out"},
        // 4 quads and 4 triangles at factor 64: 4 x 2 x 4096 + 4 x 4096 = 49,152 triangles, above a limit of
        // 1,000.
        {"--in " + cube + " --factor 64 --max-triangles 1000 --out " + out, 1,
         "49152 triangles, above the limit of 1000"},
        {"--in " + cube + " --factor 2 --max-triangles 0 --out " + out, 2, "--max-triangles"},
        {"--in " + cube + " --factor 2 --threads 0 --out " + out, 2, "--threads"},
        {"--in " + cube + " --factor 2 --threads 65 --out " + out, 2, "--threads"},
        {"--in " + cube + " --factor 2 --threads 2 --unwelded --out " + out, 2, "--threads"},
    };
    ctess::test::check_refused(cases, out);
}

TEST_CASE("ctess mesh --stats: the gpu block is the unwelded pipeline's, for the viewer's camera only",
          "[cli][mesh]") {
    const std::string in = scratch("mixed_cube_gpu.obj");
    write_file(in, mixed_cube_obj());
    const std::string camera = " --dice-rate 3 --camera 2.5,1.7,3.1 --fov 45 --resolution 640,600";
    const nlohmann::json cp = stats("--in " + in + camera);
    REQUIRE(cp.contains("gpu"));
    const nlohmann::json& g = cp["gpu"];
    CHECK(g["pattern"] == "cp");
    CHECK(g["patches"] == 8); // 4 triangles and 4 quads, one patch each
    // Every patch keeps its own corner and edge points: at least as many vertices and triangles as the weld.
    CHECK(g["vertices"].get<long>() > cp["output_vertices"].get<long>());
    CHECK(g["triangles"].get<long>() >= cp["output_triangles"].get<long>());
    // The factor scale the shaders get: 600 / (2 tan(22.5 deg)) / 3 as a float.
    const float scale = static_cast<float>(600 / (2 * std::tan(22.5 * 3.14159265358979323846 / 180))) / 3.0f;
    std::uint32_t bits = 0;
    std::memcpy(&bits, &scale, 4);
    CHECK(g["factor_scale_bits"] == bits);
    // Records, barycentrics and indices do not depend on the surface (positions, left out, do).
    for (const char* surface : {"pn", "pn-aen", "phong"}) {
        const nlohmann::json other = stats("--in " + in + camera + " --surface " + surface);
        CHECK(other["gpu"]["checksum"] == g["checksum"]);
        CHECK(other["gpu"]["triangles"] == g["triangles"]);
    }
    // Another camera, other factors: other records.
    const nlohmann::json moved = stats("--in " + in + " --dice-rate 3 --camera 2.5,1.7,3.2");
    CHECK(moved["gpu"]["checksum"]["records"] != g["checksum"]["records"]);
    // Uniform: the shaders clamp to N = 16 where `ctess mesh` splits. A close camera asks for more.
    const nlohmann::json uniform =
        stats("--in " + in + " --pattern uniform --dice-rate 1 --camera 0.5,0.5,1.6");
    CHECK(uniform["gpu"]["pattern"] == "uniform");
    CHECK(uniform["clamped_edges"] == 0);
    CHECK(uniform["gpu"]["clamped_edges"].get<long>() > 0);
    CHECK(uniform["gpu"]["triangles"].get<long>() < uniform["output_triangles"].get<long>());
    // D3D11 patterns: the unwelded output `ctess serve` gives the viewer (no shader runs them); unwelded, so
    // at least the welded triangles. No block for the CPU's factor modes.
    const nlohmann::json d3d11 = stats("--in " + in + " --pattern d3d11-even" + camera);
    CHECK(d3d11["gpu"]["pattern"] == "d3d11-even");
    CHECK(d3d11["gpu"]["triangles"].get<long>() >= d3d11["output_triangles"].get<long>());
    CHECK(d3d11["gpu"]["vertices"].get<long>() > d3d11["output_vertices"].get<long>());
    CHECK_FALSE(stats("--in " + in + " --factor 4").contains("gpu"));
    CHECK_FALSE(stats("--in " + in + " --edge-length 0.1").contains("gpu"));
}

TEST_CASE("ctess mesh --stats: the gpu block's checksums are FNV-1a over the words, checked by hand",
          "[cli][mesh]") {
    // One triangle far from the camera: every factor clamps to 1, so the output is the triangle itself (Type
    // 0: v0, v1, v2 and the triangle (0, 1, 2), docs/algorithm.md §2.11). Its edges E0 = 1, E1 = sqrt 2, E2 =
    // 1: the smallest, E0 (the tie to the lower index), goes on the pattern's e2, so the rotation is 1 and
    // v0, v1, v2 are base corners w1, w2, w0 (§2.13), base weights (u, v) = (2^24, 0), (0, 2^24), (0, 0).
    const std::string in = scratch("one_triangle_gpu.obj");
    write_file(in, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const nlohmann::json s = stats("--in " + in + " --dice-rate 64 --camera 0,0,1000");
    REQUIRE(s.contains("gpu"));
    CHECK(s["gpu"]["vertices"] == 3);
    CHECK(s["gpu"]["triangles"] == 1);
    // FNV-1a 32 (offset basis 2166136261, prime 16777619) over the little-endian bytes of the words.
    const auto fnv1a = [](std::initializer_list<std::uint32_t> words) {
        std::uint32_t h = 2166136261u;
        for (const std::uint32_t w : words)
            for (int b = 0; b < 32; b += 8) h = (h ^ ((w >> b) & 0xFFu)) * 16777619u;
        char hex[9];
        std::snprintf(hex, sizeof hex, "%08x", h);
        return std::string(hex);
    };
    constexpr std::uint32_t one = 1u << 24;
    CHECK(s["gpu"]["checksum"]["barycentrics"] == fnv1a({one, 0, 0, one, 0, 0}));
    CHECK(s["gpu"]["checksum"]["indices"] == fnv1a({0, 1, 2}));
}
