// OBJ loading (docs/models.md, "OBJ"): triangles, quads, n-gons fanned from the first corner, one output
// vertex per distinct (position, normal, uv) triple, and the seams that split vertices joined again by the
// adjacency's position ids.
#include <catch2/catch.hpp>

#include <set>

#include "model_files.hpp"

using namespace ctess::models;
using namespace ctess::models::test;

namespace {

LoadResult load_obj_text(const std::string& text) {
    return load_bytes(text, ModelKind::obj);
}

const char* cube_positions = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";

} // namespace

TEST_CASE("OBJ cube of quads with per-face normals: 24 vertices, 8 positions, closed") {
    const std::string text = std::string(cube_positions) +
                             "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 0 1 0\nvn -1 0 0\nvn 1 0 0\n"
                             "f 1//1 4//1 3//1 2//1\nf 5//2 6//2 7//2 8//2\nf 1//3 2//3 6//3 5//3\n"
                             "f 4//4 8//4 7//4 3//4\nf 1//5 5//5 8//5 4//5\nf 2//6 3//6 7//6 6//6\n";
    const LoadResult r = load_model(write_file("cube.obj", text));
    INFO(r.error.message);
    REQUIRE(r.ok());
    const Model& m = *r.model;
    REQUIRE(m.vertex_count() == 24);
    REQUIRE(m.quad_count() == 6);
    REQUIRE(m.triangle_count() == 0);
    REQUIRE(m.has_normals);
    REQUIRE_FALSE(m.has_uvs);
    // Each quad's corners carry its face normal, and lie on the face's plane (normal . p == 0 or 1).
    for (std::size_t q = 0; q < 6; ++q) {
        const float* n0 = vertex(m, m.quads[4 * q]) + 3;
        for (int c = 0; c < 4; ++c) {
            const float* v = vertex(m, m.quads[4 * q + c]);
            for (int k = 0; k < 3; ++k) REQUIRE(v[3 + k] == n0[k]);
            REQUIRE(v[6] == 0.0f);
        }
    }
    const Adjacency adj = build_adjacency(m);
    REQUIRE(std::set<std::uint32_t>(adj.position_ids.begin(), adj.position_ids.end()).size() == 8);
    REQUIRE(open_edge_count(m, adj.position_ids) == 0);
    REQUIRE(adj.tessellation_indices.size() == 6 * 2 * 12); // each quad as two triangles
    // Without position ids joining the seams, every edge would be open.
    std::vector<std::uint32_t> own(m.vertex_count());
    for (std::uint32_t i = 0; i < own.size(); ++i) own[i] = i;
    REQUIRE(open_edge_count(m, own) == 24);
}

TEST_CASE("OBJ triangles, quads and n-gons: n-gons fan from the first corner") {
    const std::string text = "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 2 0\nv -1 1 0\n"
                             "f 1 2 3\nf 1 2 3 4\nf 1 2 3 4 5\nf 1 2 3 4 5 6\n";
    const LoadResult r = load_obj_text(text);
    INFO(r.error.message);
    REQUIRE(r.ok());
    const Model& m = *r.model;
    REQUIRE(m.vertex_count() == 6); // no normals or uvs: one vertex per position
    REQUIRE(m.quads == std::vector<std::uint32_t>{0, 1, 2, 3});
    REQUIRE(m.triangles == std::vector<std::uint32_t>{0, 1, 2,                              // triangle
                                                      0, 1, 2, 0, 2, 3, 0, 3, 4,            // pentagon
                                                      0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5}); // hexagon
    REQUIRE_FALSE(m.has_normals);
    REQUIRE_FALSE(m.has_uvs);
}

TEST_CASE("OBJ uv seam: one vertex per distinct (position, normal, uv) triple") {
    const std::string text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                             "vt 0 0\nvt 1 0\nvt 1 1\nvt 0.5 0\nvt 0 1\n"
                             "f 1/1 2/2 3/3\nf 1/4 3/3 4/5\n";
    const LoadResult r = load_obj_text(text);
    INFO(r.error.message);
    REQUIRE(r.ok());
    const Model& m = *r.model;
    REQUIRE(m.vertex_count() == 5); // position 1 appears with two uvs
    REQUIRE(m.has_uvs);
    REQUIRE(m.triangles == std::vector<std::uint32_t>{0, 1, 2, 3, 2, 4});
    REQUIRE(vertex(m, 3)[6] == 0.5f);
    REQUIRE(vertex(m, 0)[6] == 0.0f);
    const Adjacency adj = build_adjacency(m);
    REQUIRE(adj.position_ids == std::vector<std::uint32_t>{0, 1, 2, 0, 4});
    REQUIRE(open_edge_count(m, adj.position_ids) == 4); // a square of two triangles: the diagonal is shared
}

TEST_CASE("OBJ negative (relative) indices and partial normals") {
    const LoadResult r =
        load_obj_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf -3//1 -2//1 -1//1\nv 0 0 1\nf 1 2 4\n");
    INFO(r.error.message);
    REQUIRE(r.ok());
    const Model& m = *r.model;
    REQUIRE(m.triangles == std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5});
    REQUIRE(vertex(m, 0)[5] == 1.0f);
    REQUIRE_FALSE(m.has_normals); // the second face has none: zeros written
    REQUIRE(vertex(m, 5)[5] == 0.0f);
    REQUIRE(vertex(m, 5)[2] == 1.0f);
}

TEST_CASE("OBJ degenerate faces are dropped and counted") {
    const LoadResult r =
        load_obj_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 1 0\nf 1 2 3\nf 1 1 2\nf 1 3 4\nf 1 2 3 4\n");
    INFO(r.error.message);
    REQUIRE(r.ok());
    REQUIRE(r.model->triangle_count() == 1);
    REQUIRE(r.model->quad_count() == 0);
    REQUIRE(r.model->dropped_degenerate_faces == 3); // repeated index, repeated position (3 and 4), in a quad
}
