// `ctess mesh --displace FILE | --displace-gltf` as a user runs it (docs/cli.md, "Models"; docs/algorithm.md
// §8): a closed cube with split normals and uv seams stays closed after displacement for every surface, the
// displacement moves it, --displace-grow adds triangles; a glTF's own KHR_materials_displacement image
// embedded as a data: uri is read with the file's factor and offset (exact heights on a flat triangle); bad
// images and bad options fail with nothing written.
#include "mesh_cli_support.hpp"
#include "support/cli_run.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <stb/stb_image_write.h>

using ctess::test::ctess_cli;
using ctess::test::mixed_cube_obj;
using ctess::test::Run;
using ctess::test::write_file;

namespace {

std::string scratch(const std::string& name) {
    return ctess::test::scratch_path("ctess_test_cli_displace", name);
}

nlohmann::json stats(const std::string& args) {
    return ctess::test::mesh_stats(args);
}

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

void append_bytes(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(size));
}

// A grey PNG of w x h texels from a function of the texel.
template <class F>
std::string png(int w, int h, F texel) {
    std::vector<std::uint8_t> t(static_cast<std::size_t>(w * h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) t[static_cast<std::size_t>(y * w + x)] = texel(x, y);
    std::string out;
    REQUIRE(stbi_write_png_to_func(&append_bytes, &out, w, h, 1, t.data(), w) != 0);
    return out;
}

std::string base64(const std::string& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t n = static_cast<std::uint8_t>(bytes[i]) << 16;
        if (i + 1 < bytes.size())
            n |= static_cast<std::uint32_t>(static_cast<std::uint8_t>(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) n |= static_cast<std::uint8_t>(bytes[i + 2]);
        out += digits[(n >> 18) & 63];
        out += digits[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[n & 63] : '=';
    }
    return out;
}

// The z coordinates of an OBJ's vertices.
std::vector<double> obj_z(const std::string& path) {
    std::istringstream in(read_file(path));
    std::vector<double> z;
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("v ", 0) == 0) {
            double x, y, w;
            std::istringstream(line.substr(2)) >> x >> y >> w;
            z.push_back(w);
        }
    return z;
}

} // namespace

TEST_CASE("ctess mesh --displace: a closed model with split normals and uv seams stays closed",
          "[cli][mesh][displace]") {
    const std::string in = scratch("cube.obj");
    write_file(in, mixed_cube_obj());
    const std::string map = scratch("ripple.png");
    write_file(map,
               png(32, 32, [](int x, int y) { return static_cast<std::uint8_t>((x * 37 + y * 91) % 256); }));
    for (const char* surface : {"flat", "pn", "pn-aen", "phong"})
        for (const char* pattern : {"cp", "uniform", "d3d11-even", "d3d11-odd"}) {
            const std::string common =
                std::string("--in ") + in + " --factor 6 --surface " + surface + " --pattern " + pattern;
            const nlohmann::json s = stats(common + " --displace " + map + " --displace-scale 0.05");
            CHECK(s["input_open_edges"] == 0);
            CHECK(s["output_open_edges"] == 0);
            const nlohmann::json grown =
                stats(common + " --displace " + map + " --displace-scale 0.05 --displace-grow");
            CHECK(grown["output_open_edges"] == 0);
            // The map's bound: 0.05 * 253 / 255 (its largest texel), used only with --displace-grow.
            CHECK(s["displacement"]["width"] == 32);
            CHECK(std::fabs(s["displacement"]["bound"].get<double>() - 0.05 * 253.0 / 255.0) < 1e-6);
            CHECK(s["displacement"]["factor_bound"] == 0);
            CHECK(grown["displacement"]["factor_bound"] == grown["displacement"]["bound"]);
            // Every factor grows (unit edges 6 -> 6.6): CP adds points; a uniform pattern may keep its count
            // ((7, 6, 7) has the 36 triangles of (6, 6, 6)).
            if (std::string(pattern) == "cp")
                CHECK(grown["output_triangles"].get<long>() > s["output_triangles"].get<long>());
            else
                CHECK(grown["output_triangles"].get<long>() >= s["output_triangles"].get<long>());
        }
    // The displacement moves the surface: the outputs differ from the undisplaced one.
    const std::string plain = scratch("plain.obj"), moved = scratch("moved.obj");
    REQUIRE(ctess_cli("mesh --in " + in + " --factor 4 --out " + plain).exit_code == 0);
    REQUIRE(ctess_cli("mesh --in " + in + " --factor 4 --displace " + map + " --displace-scale 0.05 --out " +
                      moved)
                .exit_code == 0);
    CHECK(obj_z(plain).size() == obj_z(moved).size());
    CHECK(obj_z(plain) != obj_z(moved));
}

TEST_CASE("ctess mesh --displace-gltf: the model's own embedded displacement image, factor and offset",
          "[cli][mesh][displace]") {
    // One flat triangle (normals +z, uvs = xy), its material's KHR_materials_displacement texture a 4 x 4 PNG
    // of 255 in a data: uri, factor 0.5, offset 0.1: every output vertex at z = 1 * 0.5 + 0.1.
    std::string buffer;
    const float data[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    buffer.assign(reinterpret_cast<const char*>(data), sizeof data);
    const std::string image = png(4, 4, [](int, int) { return std::uint8_t{255}; });
    const std::string gltf =
        R"({"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_materials_displacement"],
  "buffers": [{"byteLength": 96, "uri": "data:application/octet-stream;base64,)" +
        base64(buffer) + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 72, "byteLength": 24}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"}],
  "images": [{"uri": "data:image/png;base64,)" +
        base64(image) + R"("}],
  "textures": [{"source": 0}],
  "materials": [{"extensions": {"KHR_materials_displacement": {"displacementTexture": {"index": 0},
                 "displacementFactor": 0.5, "displacementOffset": 0.1}}}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "material": 0}]}],
  "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
    const std::string in = scratch("displaced.gltf"), out = scratch("displaced.obj");
    write_file(in, gltf);
    const Run r = ctess_cli("mesh --in " + in + " --factor 5 --displace-gltf --out " + out);
    INFO(r.out);
    REQUIRE(r.exit_code == 0);
    const std::vector<double> z = obj_z(out);
    REQUIRE(z.size() > 10);
    for (const double v : z) CHECK(std::fabs(v - 0.6) <= 1e-6);
    // --displace-offset overrides the file's offset.
    REQUIRE(ctess_cli("mesh --in " + in + " --factor 5 --displace-gltf --displace-offset 0 --out " + out)
                .exit_code == 0);
    for (const double v : obj_z(out)) CHECK(std::fabs(v - 0.5) <= 1e-6);
}

TEST_CASE("ctess mesh --displace: bad images and options are a clear error and write nothing",
          "[cli][mesh][displace][bad_input]") {
    const std::string out = scratch("never.obj");
    std::filesystem::remove(out);
    const std::string cube = scratch("cube_errors.obj");
    write_file(cube, mixed_cube_obj());
    const std::string good = png(8, 8, [](int x, int) { return static_cast<std::uint8_t>(x * 30); });
    const std::string truncated = scratch("truncated.png"), empty = scratch("empty.png"),
                      text = scratch("text.png");
    write_file(truncated, good.substr(0, good.size() / 2));
    write_file(empty, "");
    write_file(text, "this is not an image at all");
    const std::string base = "--in " + cube + " --factor 3 --out " + out;
    const std::vector<ctess::test::RefusedCase> cases = {
        {base + " --displace /nonexistent/height.png", 1, "/nonexistent/height.png: no such file"},
        {base + " --displace " + truncated, 1, truncated},
        {base + " --displace " + empty, 1, "empty"},
        {base + " --displace " + text, 1, "not an image"},
        {base + " --displace-gltf", 1, "no KHR_materials_displacement texture"},
        {base + " --displace " + truncated + " --displace-gltf", 2, "one of --displace"},
        {base + " --displace-scale 2", 2, "go with --displace"},
        {base + " --displace-grow", 2, "go with --displace"},
        {base + " --displace " + truncated + " --displace-scale nan", 2, "--displace-scale"},
        {base + " --displace " + truncated + " --displace-offset inf", 2, "--displace-offset"},
        {base + " --displace " + truncated + " --displace-address mirror", 2, "--displace-address"},
    };
    ctess::test::check_refused(cases, out);
}

namespace {

// An RGB PNG of w x h texels from a function of the texel giving its three channels.
template <class F>
std::string rgb_png(int w, int h, F texel) {
    std::vector<std::uint8_t> t;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c) t.push_back(texel(x, y, c));
    std::string out;
    REQUIRE(stbi_write_png_to_func(&append_bytes, &out, w, h, 3, t.data(), 3 * w) != 0);
    return out;
}

} // namespace

TEST_CASE(
    "ctess mesh --displace-vector: an RGB tangent-space map keeps the cube closed, and --stats reports it",
    "[cli][mesh][displace]") {
    const std::string in = scratch("cube_vector.obj");
    write_file(in, mixed_cube_obj());
    const std::string map = scratch("vector.png");
    write_file(map, rgb_png(16, 16, [](int x, int y, int c) {
                   return static_cast<std::uint8_t>((x * 37 + y * 91 + c * 101) % 256);
               }));
    for (const char* surface : {"flat", "pn-aen"})
        for (const char* pattern : {"cp", "uniform", "d3d11-even"}) {
            const std::string common = std::string("--in ") + in + " --factor 5 --surface " + surface +
                                       " --pattern " + pattern + " --displace-vector " + map +
                                       " --displace-scale 0.1 --displace-offset -0.5";
            const nlohmann::json s = stats(common);
            CHECK(s["output_open_edges"] == 0);
            CHECK(s["displacement"]["mode"] == "vector");
            CHECK(s["displacement"]["tangents"] == "uv"); // an OBJ has no TANGENT
            CHECK(s["displacement"]["channels"] == 3);
            CHECK(s["displacement"]["width"] == 16);
            // The longest texel vector, 0.1 * |texel - 0.5|, at most 0.1 * sqrt(3) / 2.
            const double bound = s["displacement"]["bound"].get<double>();
            CHECK(bound > 0.05);
            CHECK(bound <= 0.1 * std::sqrt(3.0) / 2.0 + 1e-6);
            const nlohmann::json grown = stats(common + " --displace-grow");
            CHECK(grown["output_open_edges"] == 0);
            CHECK(grown["displacement"]["factor_bound"] == grown["displacement"]["bound"]);
            CHECK(grown["output_triangles"].get<long>() >= s["output_triangles"].get<long>());
        }
    // The shaders displace by vectors too (docs/shaders.md, "Displacement"): with camera factors the gpu
    // block is there, and without factor growth its exact words are the undisplaced run's (displacement moves
    // positions only); grown factors give more triangles.
    const std::string camera =
        std::string("--in ") + in + " --dice-rate 30 --camera 2.5,1.7,3.1"; // none clamped
    const nlohmann::json plain_gpu = stats(camera);
    const nlohmann::json vector_gpu = stats(camera + " --displace-vector " + map + " --displace-scale 0.1");
    REQUIRE(plain_gpu.contains("gpu"));
    REQUIRE(vector_gpu.contains("gpu"));
    CHECK(vector_gpu["gpu"]["checksum"] == plain_gpu["gpu"]["checksum"]);
    const nlohmann::json grown_gpu =
        stats(camera + " --displace-vector " + map + " --displace-scale 0.1 --displace-grow");
    REQUIRE(grown_gpu.contains("gpu"));
    CHECK(grown_gpu["gpu"]["triangles"].get<long>() > plain_gpu["gpu"]["triangles"].get<long>());
    // The scalar mode reports its own mode and one channel.
    const std::string grey = scratch("grey_for_mode.png");
    write_file(grey, png(4, 4, [](int x, int) { return static_cast<std::uint8_t>(x * 60); }));
    const nlohmann::json scalar = stats("--in " + in + " --factor 2 --displace " + grey);
    CHECK(scalar["displacement"]["mode"] == "scalar");
    CHECK(scalar["displacement"]["tangents"] == "none");
    CHECK(scalar["displacement"]["channels"] == 1);
    // It moves the surface, differently from the scalar map of its red channel.
    const std::string plain = scratch("vector_plain.obj"), moved = scratch("vector_moved.obj");
    REQUIRE(ctess_cli("mesh --in " + in + " --factor 3 --out " + plain).exit_code == 0);
    REQUIRE(ctess_cli("mesh --in " + in + " --factor 3 --displace-vector " + map +
                      " --displace-scale 0.1 --displace-offset -0.5 --out " + moved)
                .exit_code == 0);
    CHECK(obj_z(plain).size() == obj_z(moved).size());
    CHECK(obj_z(plain) != obj_z(moved));
}

TEST_CASE("ctess mesh --displace-vector: grey maps, models without uvs and bad combinations are errors",
          "[cli][mesh][displace][bad_input]") {
    const std::string out = scratch("never_vector.obj");
    std::filesystem::remove(out);
    const std::string cube = scratch("cube_vector_errors.obj");
    write_file(cube, mixed_cube_obj());
    const std::string grey = scratch("grey_vector.png"), rgb = scratch("rgb_vector.png");
    write_file(grey, png(4, 4, [](int x, int) { return static_cast<std::uint8_t>(x * 60); }));
    write_file(rgb, rgb_png(4, 4, [](int x, int, int c) { return static_cast<std::uint8_t>(x * 60 + c); }));
    // A triangle without texture coordinates: no tangent frame.
    const std::string no_uv = scratch("no_uv.obj");
    write_file(no_uv, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string base = "--in " + cube + " --factor 3 --out " + out;
    const std::vector<ctess::test::RefusedCase> cases = {
        {base + " --displace-vector " + grey, 1, "a vector displacement map needs red, green and blue"},
        {base + " --displace-vector /nonexistent/vector.png", 1, "/nonexistent/vector.png: no such file"},
        {"--in " + no_uv + " --factor 3 --out " + out + " --displace-vector " + rgb, 1,
         "no texture coordinates"},
        {base + " --displace " + grey + " --displace-vector " + rgb, 2, "one of --displace"},
        {base + " --displace-gltf --displace-vector " + rgb, 2, "one of --displace"},
        {base + " --displace-vector " + rgb + " --displace-scale nan", 2, "--displace-scale"},
        {base + " --displace-vector=", 2, "--displace-vector"},
    };
    ctess::test::check_refused(cases, out);
}

TEST_CASE("ctess mesh --displace-vector: a glTF's own TANGENT is the frame (--stats says so)",
          "[cli][mesh][displace]") {
    // One flat triangle (normal +z, uv = xy) with TANGENT (0, 1, 0, 1): T = +y, B = cross(N, T) = -x, where
    // tangents from the uvs would say T = +x. A one-texel RGB map (255, 0, 255) at scale 0.5: the vector
    // (0.5, 0, 0.5) moves every point by 0.5 T + 0.5 N = (0, 0.5, 0.5).
    std::string buffer;
    const float data[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 0, 0, 1,
                          0, 0, 1, 0, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1};
    buffer.assign(reinterpret_cast<const char*>(data), sizeof data);
    const std::string gltf =
        R"({"asset": {"version": "2.0"},
  "buffers": [{"byteLength": 144, "uri": "data:application/octet-stream;base64,)" +
        base64(buffer) + R"("}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 36},
                  {"buffer": 0, "byteOffset": 72, "byteLength": 24}, {"buffer": 0, "byteOffset": 96, "byteLength": 48}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"},
                {"bufferView": 3, "componentType": 5126, "count": 3, "type": "VEC4"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2, "TANGENT": 3}}]}],
  "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
    const std::string in = scratch("tangents.gltf"), map = scratch("magenta.png");
    write_file(in, gltf);
    write_file(map,
               rgb_png(1, 1, [](int, int, int c) { return static_cast<std::uint8_t>(c == 1 ? 0 : 255); }));
    const std::string args = "--in " + in + " --factor 4 --displace-vector " + map + " --displace-scale 0.5";
    const nlohmann::json s = stats(args);
    CHECK(s["displacement"]["tangents"] == "model");
    const std::string plain = scratch("tangents_plain.obj"), moved = scratch("tangents_moved.obj");
    REQUIRE(ctess_cli("mesh --in " + in + " --factor 4 --out " + plain).exit_code == 0);
    REQUIRE(ctess_cli("mesh " + args + " --out " + moved).exit_code == 0);
    // x, y, z of every OBJ vertex, in order.
    auto positions = [](const std::string& path) {
        std::istringstream text(read_file(path));
        std::vector<double> p;
        std::string line;
        while (std::getline(text, line))
            if (line.rfind("v ", 0) == 0) {
                double x, y, z;
                std::istringstream(line.substr(2)) >> x >> y >> z;
                p.insert(p.end(), {x, y, z});
            }
        return p;
    };
    const std::vector<double> a = positions(plain), b = positions(moved);
    REQUIRE(a.size() == b.size());
    REQUIRE(a.size() > 30);
    for (std::size_t i = 0; i < a.size(); i += 3) {
        CHECK(std::fabs(b[i] - a[i]) <= 1e-6);
        CHECK(std::fabs(b[i + 1] - a[i + 1] - 0.5) <= 1e-6);
        CHECK(std::fabs(b[i + 2] - 0.5) <= 1e-6);
    }
}
