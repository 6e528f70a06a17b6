// glTF 2.0 loading (docs/models.md, "glTF"): files written here from bytes in each variant (embedded,
// separate .bin, .glb, quantized), node transforms, primitive modes and the adjacency of a closed model.
// Expected values come from the glTF 2.0 specification's formulas and from the geometry written, never from
// the loader.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

#include "model_files.hpp"

using namespace ctess::models;
using namespace ctess::models::test;

namespace {

// A tetrahedron with outward counter-clockwise faces: 4 positions, 12 u16 indices (72 bytes).
const float tet_positions[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
const std::uint16_t tet_indices[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};

std::string tet_buffer() {
    Bytes b;
    for (const auto& p : tet_positions) b.put({p[0], p[1], p[2]});
    for (std::uint16_t i : tet_indices) b.put(i);
    return b.data;
}

// buffer_json: the "buffers" entry; nodes_json: the "nodes" array; extra: more top-level members.
std::string tet_gltf(const std::string& buffer_json, const std::string& nodes_json = R"([{"mesh":0}])",
                     const std::string& extra = "") {
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":)" + nodes_json +
           R"(,"meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3",)"
           R"("min":[0,0,0],"max":[1,1,1]},{"bufferView":1,"componentType":5123,"count":12,"type":"SCALAR"}],)"
           R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":24}],)"
           R"("buffers":[)" +
           buffer_json + "]" + extra + "}";
}

std::string embedded_tet(const std::string& nodes_json = R"([{"mesh":0}])") {
    return tet_gltf(R"({"byteLength":72,"uri":")" + data_uri(tet_buffer()) + "\"}", nodes_json);
}

void require_tetrahedron(const Model& m) {
    REQUIRE(m.vertex_count() == 4);
    REQUIRE(m.triangle_count() == 4);
    REQUIRE(m.quad_count() == 0);
    REQUIRE_FALSE(m.has_normals);
    REQUIRE_FALSE(m.has_uvs);
    for (std::size_t v = 0; v < 4; ++v)
        for (int c = 0; c < 3; ++c) REQUIRE(vertex(m, v)[c] == tet_positions[v][c]);
    REQUIRE(m.triangles == std::vector<std::uint32_t>(tet_indices, tet_indices + 12));
    const Adjacency adj = build_adjacency(m);
    REQUIRE(open_edge_count(m, adj.position_ids) == 0);
}

// Every face's geometric normal points away from the model's centroid (a convex model): true exactly when the
// winding is counter-clockwise seen from outside.
void require_outward_faces(const Model& m) {
    double centroid[3] = {0, 0, 0};
    for (std::size_t v = 0; v < m.vertex_count(); ++v)
        for (int c = 0; c < 3; ++c) centroid[c] += vertex(m, v)[c] / double(m.vertex_count());
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
        const float *a = vertex(m, m.triangles[3 * t]), *b = vertex(m, m.triangles[3 * t + 1]),
                    *c = vertex(m, m.triangles[3 * t + 2]);
        const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                     e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                             e1[0] * e2[1] - e1[1] * e2[0]};
        double d = 0;
        for (int k = 0; k < 3; ++k) d += n[k] * ((a[k] + b[k] + c[k]) / 3.0 - centroid[k]);
        REQUIRE(d > 0);
    }
}

} // namespace

TEST_CASE("glTF embedded buffer (data URI): positions and indices as written, closed") {
    const LoadResult r = load_model(write_file("tet_embedded.gltf", embedded_tet()));
    INFO(r.error.message);
    REQUIRE(r.ok());
    require_tetrahedron(*r.model);
    require_outward_faces(*r.model);
}

TEST_CASE("glTF separate .bin next to the .gltf") {
    write_file("tet_separate.bin", tet_buffer());
    const LoadResult r = load_model(
        write_file("tet_separate.gltf", tet_gltf(R"({"byteLength":72,"uri":"tet_separate.bin"})")));
    INFO(r.error.message);
    REQUIRE(r.ok());
    require_tetrahedron(*r.model);
}

TEST_CASE("glTF external buffers are found next to the .gltf only, never in the current directory") {
    const std::filesystem::path scratch = scratch_dir();
    std::filesystem::create_directories(scratch / "sub");
    write_file("cwd_only.bin", tet_buffer());
    write_file("sub/cwd_only.gltf", tet_gltf(R"({"byteLength":72,"uri":"cwd_only.bin"})"));
    const std::filesystem::path cwd = std::filesystem::current_path();
    std::filesystem::current_path(scratch);
    const LoadResult r = load_model("sub/cwd_only.gltf");
    std::filesystem::current_path(cwd);
    REQUIRE_FALSE(r.ok());
    REQUIRE(r.error.message.find("cwd_only.bin") != std::string::npos);
}

TEST_CASE("glTF from memory never opens an external buffer") {
    write_file("tet_separate.bin", tet_buffer());
    const LoadResult r =
        load_bytes(tet_gltf(R"({"byteLength":72,"uri":"tet_separate.bin"})"), ModelKind::gltf_text);
    REQUIRE_FALSE(r.ok());
    REQUIRE(r.error.message.find("tet_separate.bin") != std::string::npos);
}

TEST_CASE("glTF binary .glb with its BIN chunk") {
    const std::string bytes = glb(tet_gltf(R"({"byteLength":72})"), tet_buffer());
    const LoadResult r = load_model(write_file("tet.glb", bytes));
    INFO(r.error.message);
    REQUIRE(r.ok());
    require_tetrahedron(*r.model);
    const LoadResult m = load_bytes(bytes, ModelKind::gltf_binary);
    REQUIRE(m.ok());
    REQUIRE(m.model->vertices == r.model->vertices);
}

TEST_CASE("glTF KHR_mesh_quantization: integer attributes read by the spec's normalisation rules") {
    // One triangle: POSITION u16 unnormalised (stride 8: 4-byte aligned), NORMAL i8 normalised (stride 4),
    // TEXCOORD_0 u16 normalised.
    Bytes b;
    b.put<std::uint16_t>({0, 0, 0, 0, 3, 0, 0, 0, 0, 5, 0, 0});       // positions (0,0,0) (3,0,0) (0,5,0)
    b.put<std::int8_t>({0, 0, 127, 0, 0, -128, 0, 0, -127, 0, 0, 0}); // normals, 1 byte padding each
    b.put<std::uint16_t>({0, 65535, 65535, 32768, 0, 0});             // uvs
    b.put<std::uint16_t>({0, 1, 2, 0});                               // indices (+ padding)
    const std::string json =
        R"({"asset":{"version":"2.0"},"extensionsUsed":["KHR_mesh_quantization"],)"
        R"("extensionsRequired":["KHR_mesh_quantization"],"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1,"TEXCOORD_0":2},"indices":3}]}],)"
        R"("accessors":[{"bufferView":0,"componentType":5123,"count":3,"type":"VEC3"},)"
        R"({"bufferView":1,"componentType":5120,"normalized":true,"count":3,"type":"VEC3"},)"
        R"({"bufferView":2,"componentType":5123,"normalized":true,"count":3,"type":"VEC2"},)"
        R"({"bufferView":3,"componentType":5123,"count":3,"type":"SCALAR"}],)"
        R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":24,"byteStride":8},)"
        R"({"buffer":0,"byteOffset":24,"byteLength":12,"byteStride":4},)"
        R"({"buffer":0,"byteOffset":36,"byteLength":12},{"buffer":0,"byteOffset":48,"byteLength":6}],)"
        R"("buffers":[{"byteLength":56}]})";
    const LoadResult r = load_bytes(glb(json, b.data), ModelKind::gltf_binary);
    INFO(r.error.message);
    REQUIRE(r.ok());
    const Model& m = *r.model;
    REQUIRE(m.vertex_count() == 3);
    REQUIRE(m.has_normals);
    REQUIRE(m.has_uvs);
    const float expected[3][8] = {{0, 0, 0, 0, 0, 1, 0, 1},
                                  {3, 0, 0, 0, -1, 0, 1, 32768.0f / 65535.0f}, // -128 clamps to -1
                                  {0, 5, 0, -1, 0, 0, 0, 0}};
    for (std::size_t v = 0; v < 3; ++v)
        for (int k = 0; k < 8; ++k) REQUIRE(vertex(m, v)[k] == Approx(expected[v][k]).margin(1e-7));
}

TEST_CASE("glTF node transforms: T * R * S down the hierarchy, normals by the inverse transpose") {
    // Parent: translation (10,0,0), scale (2,1,1); child: 90 degrees about z. p' = T S R p.
    const double h = std::sqrt(0.5);
    const std::string nodes = R"([{"translation":[10,0,0],"scale":[2,1,1],"children":[1]},)"
                              R"({"rotation":[0,0,)" +
                              std::to_string(h) + "," + std::to_string(h) + R"(],"mesh":0}])";
    const LoadResult r = load_model(write_file("tet_transformed.gltf", embedded_tet(nodes)));
    INFO(r.error.message);
    REQUIRE(r.ok());
    const float expected[4][3] = {{10, 0, 0}, {10, 1, 0}, {8, 0, 0}, {10, 0, 1}};
    for (std::size_t v = 0; v < 4; ++v)
        for (int c = 0; c < 3; ++c) REQUIRE(vertex(*r.model, v)[c] == Approx(expected[v][c]).margin(1e-5));
    require_outward_faces(*r.model);

    // A normal (1,1,0)/sqrt2 under scale (2,1,1): the inverse transpose diag(1/2,1,1) gives (1,2,0)/sqrt5.
    Bytes b;
    b.put({0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f});
    for (int i = 0; i < 3; ++i) b.put({float(h), float(h), 0.f});
    const std::string json =
        R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[{"scale":[2,1,1],"mesh":0}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0,"NORMAL":1}}]}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"},)"
        R"({"bufferView":0,"byteOffset":36,"componentType":5126,"count":3,"type":"VEC3"}],)"
        R"("bufferViews":[{"buffer":0,"byteLength":72}],"buffers":[{"byteLength":72}]})";
    const LoadResult n = load_bytes(glb(json, b.data), ModelKind::gltf_binary);
    INFO(n.error.message);
    REQUIRE(n.ok());
    for (std::size_t v = 0; v < 3; ++v) {
        REQUIRE(vertex(*n.model, v)[3] == Approx(1 / std::sqrt(5.0)));
        REQUIRE(vertex(*n.model, v)[4] == Approx(2 / std::sqrt(5.0)));
        REQUIRE(vertex(*n.model, v)[5] == Approx(0).margin(1e-7));
    }
    REQUIRE(vertex(*n.model, 1)[0] == 2.0f);
}

TEST_CASE("glTF mirrored node (negative determinant) keeps faces counter-clockwise from outside") {
    const LoadResult r =
        load_model(write_file("tet_mirrored.gltf", embedded_tet(R"([{"scale":[-1,1,1],"mesh":0}])")));
    INFO(r.error.message);
    REQUIRE(r.ok());
    REQUIRE(vertex(*r.model, 1)[0] == -1.0f);
    require_outward_faces(*r.model);
    const LoadResult matrix = load_model(write_file(
        "tet_matrix.gltf", embedded_tet(R"([{"matrix":[1,0,0,0, 0,1,0,0, 0,0,-3,0, 1,2,3,1],"mesh":0}])")));
    REQUIRE(matrix.ok());
    REQUIRE(vertex(*matrix.model, 3)[2] == 0.0f); // (0,0,1) -> (1,2,0)
    REQUIRE(vertex(*matrix.model, 3)[0] == 1.0f);
    require_outward_faces(*matrix.model);
}

TEST_CASE("glTF TRIANGLE_STRIP and TRIANGLE_FAN become triangles by the spec's formulas") {
    Bytes b;
    b.put({0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 1.f, 1.f, 0.f});
    for (int mode : {5, 6}) {
        const std::string json =
            R"({"asset":{"version":"2.0"},"meshes":[{"primitives":[{"attributes":{"POSITION":0},"mode":)" +
            std::to_string(mode) +
            R"(}]}],"accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"}],)"
            R"("bufferViews":[{"buffer":0,"byteLength":48}],"buffers":[{"byteLength":48}]})";
        const LoadResult r = load_bytes(glb(json, b.data), ModelKind::gltf_binary);
        INFO(r.error.message);
        REQUIRE(r.ok()); // no scene: every mesh is read
        // Strip: triangle i is (i, i+1+i%2, i+2-i%2); fan: (i+1, i+2, 0).
        const std::vector<std::uint32_t> expected = mode == 5 ? std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2}
                                                              : std::vector<std::uint32_t>{1, 2, 0, 2, 3, 0};
        REQUIRE(r.model->triangles == expected);
    }
}

TEST_CASE("glTF KHR_materials_displacement is read where present") {
    const std::string extra =
        R"(,"materials":[{"extensions":{"KHR_materials_displacement":{"displacementTexture":{"index":0},)"
        R"("displacementFactor":0.25,"displacementOffset":-0.5}}}],"textures":[{"source":0}],)"
        R"("images":[{"uri":"height.png"}])";
    std::string json =
        tet_gltf(R"({"byteLength":72,"uri":")" + data_uri(tet_buffer()) + "\"}", R"([{"mesh":0}])", extra);
    json.replace(json.find(R"("indices":1)"), 11, R"("indices":1,"material":0)");
    const LoadResult r = load_model(write_file("tet_displaced.gltf", json));
    INFO(r.error.message);
    REQUIRE(r.ok());
    REQUIRE(r.model->displacement.present);
    REQUIRE(r.model->displacement.texture == 0);
    REQUIRE(r.model->displacement.image_uri == "height.png");
    REQUIRE(r.model->displacement.factor == 0.25f);
    REQUIRE(r.model->displacement.offset == -0.5f);
    const LoadResult plain = load_bytes(embedded_tet(), ModelKind::gltf_text);
    REQUIRE_FALSE(plain.model->displacement.present);
}

TEST_CASE("glTF required extensions that are not supported are refused by name") {
    for (const char* ext :
         {"KHR_draco_mesh_compression", "EXT_meshopt_compression", "KHR_texture_transform"}) {
        const std::string extra = std::string(R"(,"extensionsRequired":[")") + ext + "\"]";
        const LoadResult r =
            load_bytes(tet_gltf(R"({"byteLength":72,"uri":")" + data_uri(tet_buffer()) + "\"}",
                                R"([{"mesh":0}])", extra),
                       ModelKind::gltf_text);
        REQUIRE_FALSE(r.ok());
        REQUIRE(r.error.message.find(ext) != std::string::npos);
        REQUIRE_FALSE(r.model.has_value());
    }
}

TEST_CASE("adjacency of the tetrahedron: 12 indices per triangle whose edges and corners match positions") {
    const LoadResult r = load_bytes(embedded_tet(), ModelKind::gltf_text);
    REQUIRE(r.ok());
    const Model& m = *r.model;
    const Adjacency adj = build_adjacency(m);
    REQUIRE(adj.position_ids == std::vector<std::uint32_t>{0, 1, 2, 3});
    REQUIRE(adj.tessellation_indices.size() == m.triangle_count() * 12);
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
        const std::uint32_t* p = adj.tessellation_indices.data() + 12 * t;
        for (int k = 0; k < 3; ++k) REQUIRE(p[k] == m.triangles[3 * t + k]);
        // Closed model: edge k's adjacent edge joins the same two positions, in the other triangle's order.
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = p[k], b = p[(k + 1) % 3], x = p[3 + 2 * k], y = p[4 + 2 * k];
            REQUIRE(((x == a && y == b) || (x == b && y == a)));
        }
        for (int k = 0; k < 3; ++k)
            REQUIRE(p[9 + k] == p[k]); // no seams: a corner is its own dominant vertex
    }
}
