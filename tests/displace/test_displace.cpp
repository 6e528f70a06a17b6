// Displacement in the mesh pipeline (docs/algorithm.md §8): exact heights and normals on flat patches, factor
// growth, bad options; watertightness at uv seams and hard edges on a cube whose six faces have their own
// uv charts and normals (triangles, quads and a mix), and on Debian's spider.obj (skipped when
// assimp-testmodels is missing): after displacement, output vertices whose undisplaced positions are
// bit-identical have bit-identical displaced positions, and the welded output has exactly the open edges,
// by position, that it has without displacement (none for the closed cube). A control run without the
// adjacency (so without dominant edges) must crack, or the check would prove nothing.
#include <catch2/catch.hpp>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <ctess/runtime.hpp>
#include <ctess/runtime/displace/displace.hpp>
#include <ctess/runtime/models.hpp>

#include "displace_support.hpp"

using namespace ctess;
using namespace displace_test;

namespace {

// A height that differs between the cube's uv charts, so that a point sampled in two charts moves apart.
float ripple(const void*, float u, float v) {
    return std::sin(41.0f * u) * std::cos(23.0f * v) + 2.0f * u;
}

float constant_quarter(const void*, float, float) {
    return 0.25f;
}

float ramp_u(const void*, float u, float) {
    return u;
}

} // namespace

TEST_CASE("displacement on a flat triangle: exact heights along the normal, gradient normals (§8.3)") {
    const rt::MeshView mesh = unit_triangle();
    rt::PipelineOptions options = constant_factor(7.5f, rt::Surface::flat);
    rt::Displacement d;
    d.function = &constant_quarter;
    d.scale = 2.0f; // height = 2 * (0.25 * factor + offset)
    d.factor = 1.0f;
    d.offset = 0.0f;
    options.displacement = &d;
    const Output base = unwelded(mesh, constant_factor(7.5f, rt::Surface::flat));
    const Output flat = unwelded(mesh, options);
    REQUIRE(flat.vertices.size() > 20);
    for (std::size_t i = 0; i < flat.vertices.size(); ++i) {
        const rt::TessVertex& a = base.vertices[i];
        const rt::TessVertex& b = flat.vertices[i];
        CHECK(b.position[0] == a.position[0]);
        CHECK(b.position[1] == a.position[1]);
        CHECK(b.position[2] == 0.5f);
        CHECK(b.normal[0] == 0.0f); // a constant height leaves the normal
        CHECK(b.normal[1] == 0.0f);
        CHECK(b.normal[2] == 1.0f);
    }
    // height = 0.5 * u over uv = xy: the surface z = 0.5 x, whose normal is (-0.5, 0, 1) / |.|.
    d.function = &ramp_u;
    d.scale = 0.5f;
    const Output ramp = unwelded(mesh, options);
    const float inv = 1.0f / std::sqrt(1.25f);
    for (const rt::TessVertex& v : ramp.vertices) {
        CHECK(std::fabs(v.position[2] - 0.5f * v.position[0]) <= 1e-6f);
        CHECK(std::fabs(v.normal[0] + 0.5f * inv) <= 1e-5f);
        CHECK(std::fabs(v.normal[1]) <= 1e-5f);
        CHECK(std::fabs(v.normal[2] - inv) <= 1e-5f);
    }
    // Equal inputs, equal bits.
    const Output again = unwelded(mesh, options);
    REQUIRE(again.vertices.size() == ramp.vertices.size());
    CHECK(std::memcmp(again.vertices.data(), ramp.vertices.data(),
                      ramp.vertices.size() * sizeof(rt::TessVertex)) == 0);
}

TEST_CASE("displacement grows edge factors by its bound (§8.4), bad displacement options are refused") {
    const rt::MeshView mesh = unit_triangle();
    rt::PipelineOptions options = constant_factor(4.0f, rt::Surface::flat);
    rt::Displacement d;
    d.function = &constant_quarter;
    options.displacement = &d;
    std::vector<rt::PatchRecord> patches(1);
    rt::PipelineTotals totals;
    REQUIRE(rt::setup_patches(rt::cp_tables, mesh, options, patches, totals) == rt::PipelineStatus::ok);
    CHECK(patches[0].factor[0] == 4.0f); // factor_bound 0: unchanged
    d.factor_bound = 0.5f;               // edge E0 has length 1: 4 * (1 + 2 * 0.5 / 1) = 8
    REQUIRE(rt::setup_patches(rt::cp_tables, mesh, options, patches, totals) == rt::PipelineStatus::ok);
    CHECK(patches[0].factor[0] == 8.0f);
    CHECK(patches[0].factor[2] == 8.0f);
    CHECK(patches[0].factor[1] > 4.0f);
    CHECK(patches[0].factor[1] < 8.0f); // the diagonal is longer: grown less
    for (int bad = 0; bad < 6; ++bad) {
        rt::Displacement b;
        const float nan = std::nanf("");
        if (bad == 0) b.scale = nan;
        if (bad == 1) b.factor = std::numeric_limits<float>::infinity();
        if (bad == 2) b.offset = nan;
        if (bad == 3) b.factor_bound = -1.0f;
        if (bad == 4) b.normal_step = 0.0f;
        if (bad == 5) b.normal_step = 0.75f;
        options.displacement = &b;
        INFO("bad option " << bad);
        CHECK_FALSE(rt::displacement_valid(b));
        CHECK(rt::setup_patches(rt::cp_tables, mesh, options, patches, totals) ==
              rt::PipelineStatus::bad_option);
    }
}

TEST_CASE("welded_directions: one direction per position, the normalised sum of its normals") {
    const models::Model cube = chart_cube(0);
    const models::Adjacency adjacency = models::build_adjacency(cube);
    const rt::MeshView mesh = view_of(cube, &adjacency);
    std::vector<float> directions(3 * cube.vertex_count());
    REQUIRE(rt::welded_directions(mesh, directions));
    const float c = 1.0f / std::sqrt(3.0f);
    for (std::size_t v = 0; v < cube.vertex_count(); ++v)
        for (unsigned k = 0; k < 3; ++k) {
            // Every cube corner holds three face normals: the direction is the corner's diagonal.
            const float expected = cube.vertices[8 * v + k] > 0 ? c : -c;
            CHECK(std::fabs(directions[3 * v + k] - expected) <= 1e-6f);
        }
    std::vector<float> short_span(3 * cube.vertex_count() - 1);
    CHECK_FALSE(rt::welded_directions(mesh, short_span));
    std::vector<std::uint32_t> bad_ids = adjacency.position_ids;
    bad_ids[3] = static_cast<std::uint32_t>(cube.vertex_count());
    rt::MeshView bad = mesh;
    bad.position_ids = bad_ids.data();
    CHECK_FALSE(rt::welded_directions(bad, directions));
}

TEST_CASE("watertight at uv seams and hard edges (§8.2): the chart cube, triangles, quads and mixed, CP and "
          "uniform") {
    for (int faces = 0; faces < 3; ++faces) {
        const models::Model cube = chart_cube(faces);
        const models::Adjacency adjacency = models::build_adjacency(cube);
        REQUIRE(models::open_edge_count(cube, adjacency.position_ids) == 0);
        const rt::MeshView mesh = view_of(cube, &adjacency);
        std::vector<float> directions(3 * cube.vertex_count());
        REQUIRE(rt::welded_directions(mesh, directions));
        rt::Displacement d;
        d.function = &ripple;
        d.scale = 0.2f;
        d.directions = directions.data();
        check_displaced_seams(mesh, d, faces, [](const Output& base, const Output& moved) {
            // It moved: the displaced and undisplaced positions differ somewhere.
            bool any = false;
            for (std::size_t i = 0; i < base.vertices.size() && !any; ++i)
                any = key_of(base.vertices[i]) != key_of(moved.vertices[i]);
            CHECK(any);
        });
        // The control: without adjacency every edge samples its own chart, and the seams crack.
        rt::MeshView no_adjacency = mesh;
        no_adjacency.adjacency = nullptr;
        rt::PipelineOptions options = constant_factor(5.5f, rt::Surface::flat);
        const Output base = unwelded(no_adjacency, options);
        options.displacement = &d;
        CHECK(check_pairs(base, unwelded(no_adjacency, options)).mismatched > 0);
        CHECK(open_edges_by_position(welded(no_adjacency, options)) > 0);
    }
}

TEST_CASE("watertight on a real model with seams and split normals: spider.obj, a noise height map") {
    const std::string path = "/usr/share/assimp/models/OBJ/spider.obj";
    const models::LoadResult loaded = models::load_model(path);
    if (!loaded.ok()) {
        WARN("skipped: " << path << " is not installed (Debian assimp-testmodels): " << loaded.error.message);
        return;
    }
    const models::Model& model = *loaded.model;
    const models::Adjacency adjacency = models::build_adjacency(model);
    const rt::MeshView mesh = view_of(model, &adjacency);
    // meshoptimizer's dominant corner is a function of the position: every corner at one position names the
    // same vertex (docs/algorithm.md §8.2 relies on it).
    std::map<std::uint32_t, std::uint32_t> dominant;
    for (std::size_t f = 0; f < adjacency.tessellation_indices.size() / 12; ++f)
        for (unsigned k = 0; k < 3; ++k) {
            const std::uint32_t v = adjacency.tessellation_indices[12 * f + k];
            const std::uint32_t dom = adjacency.tessellation_indices[12 * f + 9 + k];
            const auto [it, inserted] = dominant.emplace(adjacency.position_ids[v], dom);
            CHECK(it->second == dom);
            CHECK(std::memcmp(&model.vertices[8 * std::size_t{v}], &model.vertices[8 * std::size_t{dom}],
                              12) == 0);
        }
    std::vector<float> directions(3 * model.vertex_count());
    REQUIRE(rt::welded_directions(mesh, directions));
    std::vector<float> texels(64 * 64);
    std::uint32_t state = 12345;
    for (float& t : texels) {
        state = state * 1664525u + 1013904223u;
        t = static_cast<float>(state >> 8) / 16777216.0f;
    }
    rt::Displacement d;
    d.map = {texels.data(), 64, 64, rt::AddressMode::repeat};
    d.scale = 2.0f;
    d.offset = -0.5f;
    d.directions = directions.data();
    for (const rt::Surface surface : {rt::Surface::flat, rt::Surface::pn_aen}) {
        INFO("surface " << static_cast<int>(surface));
        rt::PipelineOptions options = constant_factor(3.5f, surface);
        const Output base = unwelded(mesh, options);
        const std::size_t open_before = open_edges_by_position(welded(mesh, options));
        options.displacement = &d;
        const PairCheck pairs = check_pairs(base, unwelded(mesh, options));
        CHECK(pairs.shared > 0);
        CHECK(pairs.mismatched == 0);
        CHECK(open_edges_by_position(welded(mesh, options)) == open_before);
    }
    // Grown factors (§8.4): the same, against an undisplaced run with the same factors (a zero height).
    rt::Displacement zero;
    zero.scale = 0.0f;
    zero.factor_bound = d.factor_bound = rt::displacement_bound(d);
    // Texels in [0, 1): heights 2 * (texel - 0.5) in [-1, 1), the bound the smallest texel's |height|.
    const rt::TexelRange range = rt::texel_range(d.map);
    REQUIRE(d.factor_bound == std::fabs(2.0f * (range.min - 0.5f)));
    REQUIRE(d.factor_bound > 0.99f);
    check_grown_seams(mesh, d, zero);
}

TEST_CASE("a .glb's displacement image in a buffer view reaches the height map loader (docs/models.md)") {
    // One triangle and a 2 x 1 grey PNG (texels 0 and 255), both in the BIN chunk.
    const std::uint8_t png_bytes[] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A, 0, 0, 0, 13, 'I', 'H', 'D',
                                      'R',  0,   0,   0,   2,    0,    0,    0,    1, 8, 0, 0,  0,   0};
    // The rest by hand: IHDR's CRC, one row (filter 0, texels 0 and 255) as a stored (uncompressed) zlib
    // block in IDAT, then IEND.
    std::vector<std::uint8_t> png(png_bytes, png_bytes + sizeof png_bytes);
    auto be32 = [&](std::uint32_t x) {
        for (int s = 24; s >= 0; s -= 8) png.push_back(static_cast<std::uint8_t>(x >> s));
    };
    auto crc = [](const std::uint8_t* p, std::size_t n) {
        std::uint32_t c = 0xFFFFFFFFu;
        for (std::size_t i = 0; i < n; ++i) {
            c ^= p[i];
            for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
        }
        return c ^ 0xFFFFFFFFu;
    };
    be32(crc(png.data() + 12, 17));
    const std::uint8_t row[3] = {0, 0, 255};
    // zlib: header 78 01, one stored block (final, length 3), the row, Adler-32.
    std::vector<std::uint8_t> z = {0x78, 0x01, 0x01, 3, 0, 0xFC, 0xFF, row[0], row[1], row[2]};
    std::uint32_t a = 1, b = 0;
    for (const std::uint8_t x : row) {
        a = (a + x) % 65521;
        b = (b + a) % 65521;
    }
    for (int s = 24; s >= 0; s -= 8) z.push_back(static_cast<std::uint8_t>(((b << 16) | a) >> s));
    be32(static_cast<std::uint32_t>(z.size()));
    const std::size_t idat = png.size();
    png.insert(png.end(), {'I', 'D', 'A', 'T'});
    png.insert(png.end(), z.begin(), z.end());
    be32(crc(png.data() + idat, png.size() - idat));
    be32(0);
    const std::size_t iend = png.size();
    png.insert(png.end(), {'I', 'E', 'N', 'D'});
    be32(crc(png.data() + iend, 4));
    const models::HeightMapResult direct = models::load_height_map_from_memory(png, "hand-made");
    INFO(direct.error.message);
    REQUIRE(direct.ok());
    REQUIRE(direct.image->texels == std::vector<float>{0.0f, 1.0f});

    std::vector<std::uint8_t> bin(36);
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::memcpy(bin.data(), positions, 36);
    bin.insert(bin.end(), png.begin(), png.end());
    while (bin.size() % 4 != 0) bin.push_back(0);
    std::string json =
        R"({"asset":{"version":"2.0"},"extensionsUsed":["KHR_materials_displacement"],"buffers":[{"byteLength":)" +
        std::to_string(bin.size()) + R"(}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},)" +
        R"({"buffer":0,"byteOffset":36,"byteLength":)" + std::to_string(png.size()) +
        R"(}],"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],)" +
        R"("images":[{"bufferView":1,"mimeType":"image/png"}],"textures":[{"source":0}],)" +
        R"("materials":[{"extensions":{"KHR_materials_displacement":{"displacementTexture":{"index":0},)" +
        R"("displacementFactor":2,"displacementOffset":-1}}}],)" +
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],"nodes":[{"mesh":0}],)" +
        R"("scenes":[{"nodes":[0]}],"scene":0})";
    while (json.size() % 4 != 0) json.push_back(' ');
    std::vector<std::uint8_t> glb = {'g', 'l', 'T', 'F', 2, 0, 0, 0, 0, 0, 0, 0};
    auto le32 = [&](std::uint32_t x) {
        for (int s = 0; s < 32; s += 8) glb.push_back(static_cast<std::uint8_t>(x >> s));
    };
    le32(static_cast<std::uint32_t>(json.size()));
    glb.insert(glb.end(), {'J', 'S', 'O', 'N'});
    glb.insert(glb.end(), json.begin(), json.end());
    le32(static_cast<std::uint32_t>(bin.size()));
    glb.insert(glb.end(), {'B', 'I', 'N', 0});
    glb.insert(glb.end(), bin.begin(), bin.end());
    const auto total = static_cast<std::uint32_t>(glb.size());
    for (int k = 0; k < 4; ++k)
        glb[8 + static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(total >> (8 * k));
    const models::LoadResult loaded =
        models::load_model_from_memory(glb, models::ModelKind::gltf_binary, "embedded.glb");
    INFO(loaded.error.message);
    REQUIRE(loaded.ok());
    const models::Model::Displacement& d = loaded.model->displacement;
    CHECK(d.present);
    CHECK(d.texture == 0);
    CHECK(d.image_uri.empty());
    CHECK(d.factor == 2.0f);
    CHECK(d.offset == -1.0f);
    CHECK(d.image_bytes == png);
}
