// Real files from Debian's assimp-testmodels (/usr/share/assimp/models), when installed; skipped otherwise.
// Expected counts come from the files themselves, read here independently: accessor counts from the glTF JSON
// (nlohmann-json), face lines from the OBJ text.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "model_files.hpp"

using namespace ctess::models;

namespace {

const std::filesystem::path assimp_models = "/usr/share/assimp/models";

std::string read_text(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The glTF JSON: the whole .gltf, or a .glb's first chunk.
nlohmann::json gltf_json(const std::filesystem::path& p) {
    std::string bytes = read_text(p);
    if (p.extension() == ".glb") {
        std::uint32_t length;
        std::memcpy(&length, bytes.data() + 12, 4);
        bytes = bytes.substr(20, length);
    }
    return nlohmann::json::parse(bytes);
}

struct Expected {
    std::size_t vertices = 0, triangles = 0, quads = 0;
};

// Sum over the default scene's node tree: POSITION counts and index counts / 3 (TRIANGLES primitives only).
Expected gltf_expected(const nlohmann::json& j) {
    Expected e;
    std::function<void(std::size_t)> visit = [&](std::size_t node) {
        const auto& n = j["nodes"][node];
        if (n.contains("mesh"))
            for (const auto& prim : j["meshes"][n["mesh"].get<std::size_t>()]["primitives"]) {
                e.vertices += j["accessors"][prim["attributes"]["POSITION"].get<std::size_t>()]["count"]
                                  .get<std::size_t>();
                e.triangles +=
                    j["accessors"][prim["indices"].get<std::size_t>()]["count"].get<std::size_t>() / 3;
            }
        if (n.contains("children"))
            for (const auto& c : n["children"]) visit(c.get<std::size_t>());
    };
    for (const auto& root : j["scenes"][j.value("scene", 0)]["nodes"]) visit(root.get<std::size_t>());
    return e;
}

// Face lines: 3 corners a triangle, 4 a quad, n > 4 the n - 2 triangles of a fan.
Expected obj_expected(const std::string& text) {
    Expected e;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string word;
        if (!(words >> word) || word != "f") continue;
        std::size_t corners = 0;
        while (words >> word) ++corners;
        if (corners == 4)
            ++e.quads;
        else if (corners >= 3)
            e.triangles += corners - 2;
    }
    return e;
}

} // namespace

TEST_CASE("assimp-testmodels glTF samples: counts from the JSON, closed boxes") {
    if (!std::filesystem::exists(assimp_models / "glTF2")) {
        WARN("assimp-testmodels is not installed: skipped");
        return;
    }
    const std::map<std::string, bool> files = {
        // path, closed
        {"glTF2/BoxTextured-glTF/BoxTextured.gltf", true},
        {"glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf", true},
        {"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", true},
        {"glTF2/BoxTexcoords-glTF/boxTexcoords.gltf", true},
        {"glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf", true},
        {"glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", false},
        {"glTF2/ClearCoat-glTF/ClearCoatTest.gltf", false},
    };
    for (const auto& [file, closed] : files) {
        const std::filesystem::path path = assimp_models / file;
        INFO(file);
        const LoadResult r = load_model(path.string());
        INFO(r.error.message);
        REQUIRE(r.ok());
        const Expected e = gltf_expected(gltf_json(path));
        REQUIRE(r.model->vertex_count() == e.vertices);
        REQUIRE(r.model->triangle_count() + r.model->dropped_degenerate_faces == e.triangles);
        const Adjacency adj = build_adjacency(*r.model);
        REQUIRE(adj.tessellation_indices.size() == r.model->triangle_count() * 12);
        if (closed) REQUIRE(open_edge_count(*r.model, adj.position_ids) == 0);
    }
}

TEST_CASE("assimp-testmodels OBJ files: face counts from the text, closed boxes") {
    if (!std::filesystem::exists(assimp_models / "OBJ")) {
        WARN("assimp-testmodels is not installed: skipped");
        return;
    }
    const std::map<std::string, bool> files = {
        {"OBJ/box.obj", true},
        {"OBJ/testmixed.obj", true},
        {"OBJ/cube_usemtl.obj", true},
        {"OBJ/regr_3429812.obj", false},
        {"OBJ/WusonOBJ.obj", false},
        {"OBJ/spider.obj", false},
        {"OBJ/concave_polygon.obj", false},
    };
    for (const auto& [file, closed] : files) {
        const std::filesystem::path path = assimp_models / file;
        INFO(file);
        const LoadResult r = load_model(path.string());
        INFO(r.error.message);
        REQUIRE(r.ok());
        const Expected e = obj_expected(read_text(path));
        REQUIRE(r.model->triangle_count() + r.model->quad_count() + r.model->dropped_degenerate_faces ==
                e.triangles + e.quads);
        REQUIRE(r.model->quad_count() <= e.quads);
        const Adjacency adj = build_adjacency(*r.model);
        if (closed) REQUIRE(open_edge_count(*r.model, adj.position_ids) == 0);
    }
}

TEST_CASE("assimp-testmodels broken files give errors naming the file and the problem") {
    if (!std::filesystem::exists(assimp_models / "glTF2")) {
        WARN("assimp-testmodels is not installed: skipped");
        return;
    }
    const std::map<std::string, std::string> files = {
        {"glTF2/IndexOutOfRange/IndexOutOfRange.gltf", "out of range"},
        {"glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf", "out of range"},
        {"glTF2/MissingBin/BoxTextured.gltf", "BoxTextured0.bin"},
        {"glTF2/RecursiveNodes/RecursiveNodes.gltf", "reached twice"},
        {"glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", "NaN or infinite"},
        {"glTF2/draco/2CylinderEngine.gltf", "uses the glTF extension KHR_draco_mesh_compression"},
        {"glTF2/BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf", "KHR_technique_webgl"},
        {"OBJ/box_UTF16BE.obj", "NUL bytes"},
        {"OBJ/box_longline.obj", "more than 255 corners"},
        {"OBJ/point_cloud.obj", "empty model"},
        {"OBJ/number_formats.obj", "line 11: '3.1+e2' is not a finite number"},
    };
    for (const auto& [file, problem] : files) {
        const std::string path = (assimp_models / file).string();
        const LoadResult r = load_model(path);
        INFO(file << ": " << r.error.message);
        REQUIRE_FALSE(r.ok());
        REQUIRE(r.error.message.rfind(path + ": ", 0) == 0);
        REQUIRE(r.error.message.find(problem) != std::string::npos);
    }
}
