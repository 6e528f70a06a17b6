// Vector (tangent-space RGB) displacement (docs/algorithm.md §8.7): exact offsets on flat patches whose frame
// is known (uv = xy, and a mirrored chart for the handedness), uv_tangents against Lengyel's rule, the
// displaced normals, the vector bound; watertightness at uv seams and hard edges on the chart cube and on
// Debian's spider.obj, with two controls that must crack (no dominant edges; frames from each vertex's own
// tangent instead of the dominant vertex's); and the bad inputs, each with its documented result.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <stb/stb_image_write.h>

#include <ctess/runtime.hpp>
#include <ctess/runtime/displace/displace.hpp>
#include <ctess/runtime/gpu/shader_interface.hpp>
#include <ctess/runtime/models.hpp>

#include "displace_support.hpp"

using namespace ctess;
using namespace displace_test;

namespace {

// The unit square in z = 0, normal +z, as one quad (quad = true) or two triangles; uv = (x, y), or with
// mirrored = true uv = (1 - x, y) (T = -x, and the handedness -1 keeps B = +y).
struct FlatSquare {
    std::vector<float> vertices;
    std::vector<std::uint32_t> triangles, quads;
    rt::MeshView view() const {
        return {vertices.data(),  static_cast<std::uint32_t>(vertices.size() / 8),
                triangles.data(), static_cast<std::uint32_t>(triangles.size() / 3),
                quads.data(),     static_cast<std::uint32_t>(quads.size() / 4)};
    }
};

FlatSquare flat_square(bool quad, bool mirrored) {
    FlatSquare s;
    const float xy[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const auto& p : xy) {
        const float vertex[8] = {p[0], p[1], 0, 0, 0, 1, mirrored ? 1.0f - p[0] : p[0], p[1]};
        s.vertices.insert(s.vertices.end(), vertex, vertex + 8);
    }
    if (quad)
        s.quads = {0, 1, 2, 3};
    else
        s.triangles = {0, 1, 2, 0, 2, 3};
    return s;
}

// A vector texel that differs between the cube's uv charts in all three channels.
rt::Vec3 vector_ripple(const void*, float u, float v) {
    return {std::sin(17.0f * v) + u, std::cos(29.0f * u) * v,
            std::sin(41.0f * u) * std::cos(23.0f * v) + 2.0f * u};
}

rt::Vec3 constant_vector(const void*, float, float) {
    return {0.5f, -0.25f, 0.75f};
}

rt::Vec3 ramp_normal(const void*, float u, float) {
    return {0.0f, 0.0f, u};
}

rt::Vec3 ramp_tangent(const void*, float u, float) {
    return {u, 0.0f, 0.0f};
}

// A ripple as a height, and the same as a vector (0, 0, h): the scalar mode's twin.
float height_ripple(const void*, float u, float v) {
    return std::sin(41.0f * u) * std::cos(23.0f * v) + 2.0f * u;
}
rt::Vec3 normal_ripple(const void*, float u, float v) {
    return {0.0f, 0.0f, height_ripple(nullptr, u, v)};
}

} // namespace

TEST_CASE("uv_tangents: Lengyel's tangent and handedness on flat charts, bad input writes nothing") {
    for (const bool quad : {false, true})
        for (const bool mirrored : {false, true}) {
            INFO("quad " << quad << " mirrored " << mirrored);
            const FlatSquare s = flat_square(quad, mirrored);
            std::vector<float> t(16, 7.0f);
            REQUIRE(rt::uv_tangents(s.view(), t));
            for (unsigned v = 0; v < 4; ++v) {
                CHECK(t[4 * v] == (mirrored ? -1.0f : 1.0f));
                CHECK(t[4 * v + 1] == 0.0f);
                CHECK(t[4 * v + 2] == 0.0f);
                // cross(N, T) = (0, +-1, 0) against dP/dv = +y: +1, or -1 in the mirrored chart.
                CHECK(t[4 * v + 3] == (mirrored ? -1.0f : 1.0f));
            }
        }
    FlatSquare s = flat_square(false, false);
    std::vector<float> t(16, 7.0f);
    CHECK_FALSE(rt::uv_tangents(s.view(), std::span<float>(t.data(), 15))); // too short
    s.triangles[4] = 4;                                                     // out of range
    CHECK_FALSE(rt::uv_tangents(s.view(), t));
    CHECK(t == std::vector<float>(16, 7.0f));
    // Every uv equal (zero uv area) or NaN: no usable tangent, (0, 0, 0, 1).
    for (const float uv : {0.25f, std::numeric_limits<float>::quiet_NaN()}) {
        FlatSquare z = flat_square(false, false);
        for (unsigned v = 0; v < 4; ++v) z.vertices[8 * v + 6] = z.vertices[8 * v + 7] = uv;
        REQUIRE(rt::uv_tangents(z.view(), t));
        CHECK(t == std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1});
    }
}

TEST_CASE("vector displacement on a flat square: exact offsets in the known frame, normals (§8.7)") {
    // One RGB texel (0.5, 0.25, 1): every bilinear sample is exactly it (power-of-two values, §8.1), and
    // scale 0.5 * (texel * 2 + 0.5) = (0.75, 0.5, 1.25), exact in float.
    const float texel[3] = {0.5f, 0.25f, 1.0f};
    rt::Displacement d;
    d.mode = rt::DisplacementMode::vector;
    d.map = {texel, 1, 1, rt::AddressMode::clamp, 3};
    d.scale = 0.5f;
    d.factor = 2.0f;
    d.offset = 0.5f;
    for (const bool quad : {false, true})
        for (const bool mirrored : {false, true})
            for (const rt::Pattern pattern : {rt::Pattern::cp, rt::Pattern::uniform}) {
                INFO("quad " << quad << " mirrored " << mirrored << " pattern " << static_cast<int>(pattern));
                const FlatSquare s = flat_square(quad, mirrored);
                std::vector<float> tangents(16);
                REQUIRE(rt::uv_tangents(s.view(), tangents));
                d.tangents = tangents.data();
                rt::PipelineOptions options = constant_factor(6.5f, rt::Surface::flat);
                options.pattern = pattern;
                const Output base = unwelded(s.view(), options);
                options.displacement = &d;
                const Output moved = unwelded(s.view(), options);
                REQUIRE(moved.vertices.size() == base.vertices.size());
                REQUIRE(moved.vertices.size() > 20);
                // T = +x (mirrored: -x), B = +y in both charts, N = +z.
                const float dx = mirrored ? -0.75f : 0.75f;
                std::size_t exact = 0;
                for (std::size_t i = 0; i < moved.vertices.size(); ++i) {
                    const rt::TessVertex& a = base.vertices[i];
                    const rt::TessVertex& b = moved.vertices[i];
                    exact += b.position[0] == a.position[0] + dx && b.position[1] == a.position[1] + 0.5f &&
                             b.position[2] == 1.25f && b.normal[0] == 0.0f && b.normal[1] == 0.0f &&
                             b.normal[2] == 1.0f;
                }
                CHECK(exact == moved.vertices.size());
            }
    // Gradients: (0, 0, 0.5 u) is a height ramp (normal (-0.5, 0, 1) / |.|, as §8.3's scalar case);
    // (0.5 u, 0, 0) slides the plane along itself (normal stays +z, x grows by half).
    const FlatSquare s = flat_square(false, false);
    std::vector<float> tangents(16);
    REQUIRE(rt::uv_tangents(s.view(), tangents));
    rt::Displacement f;
    f.mode = rt::DisplacementMode::vector;
    f.tangents = tangents.data();
    f.scale = 0.5f;
    rt::PipelineOptions options = constant_factor(5.0f, rt::Surface::flat);
    const Output base = unwelded(s.view(), options);
    options.displacement = &f;
    f.vector_function = &ramp_normal;
    const Output ramp = unwelded(s.view(), options);
    const float inv = 1.0f / std::sqrt(1.25f);
    for (const rt::TessVertex& v : ramp.vertices) {
        CHECK(std::fabs(v.position[2] - 0.5f * v.position[0]) <= 1e-6f);
        CHECK(std::fabs(v.normal[0] + 0.5f * inv) <= 1e-5f);
        CHECK(std::fabs(v.normal[1]) <= 1e-5f);
        CHECK(std::fabs(v.normal[2] - inv) <= 1e-5f);
    }
    f.vector_function = &ramp_tangent;
    const Output slide = unwelded(s.view(), options);
    for (std::size_t i = 0; i < slide.vertices.size(); ++i) {
        CHECK(std::fabs(slide.vertices[i].position[0] - 1.5f * base.vertices[i].position[0]) <= 1e-6f);
        CHECK(slide.vertices[i].position[1] == base.vertices[i].position[1]);
        CHECK(slide.vertices[i].position[2] == 0.0f);
        CHECK(std::fabs(slide.vertices[i].normal[0]) <= 1e-6f);
        CHECK(std::fabs(slide.vertices[i].normal[2] - 1.0f) <= 1e-6f);
    }
    // Equal inputs, equal bits.
    const Output again = unwelded(s.view(), options);
    CHECK(std::memcmp(again.vertices.data(), slide.vertices.data(),
                      slide.vertices.size() * sizeof(rt::TessVertex)) == 0);
}

TEST_CASE("vector displacement (0, 0, h) moves every point as the scalar mode's height h") {
    const models::Model cube = chart_cube(2);
    const models::Adjacency adjacency = models::build_adjacency(cube);
    const rt::MeshView mesh = view_of(cube, &adjacency);
    std::vector<float> directions(3 * cube.vertex_count()), tangents(4 * cube.vertex_count());
    REQUIRE(rt::welded_directions(mesh, directions));
    REQUIRE(rt::uv_tangents(mesh, tangents));
    rt::Displacement scalar;
    scalar.function = &height_ripple;
    scalar.scale = 0.2f;
    scalar.directions = directions.data();
    rt::Displacement vector = scalar;
    vector.function = nullptr;
    vector.mode = rt::DisplacementMode::vector;
    vector.vector_function = &normal_ripple;
    vector.tangents = tangents.data();
    for (const rt::Surface surface : {rt::Surface::flat, rt::Surface::pn_aen}) {
        INFO("surface " << static_cast<int>(surface));
        rt::PipelineOptions options = constant_factor(4.5f, surface);
        options.displacement = &scalar;
        const Output a = unwelded(mesh, options);
        options.displacement = &vector;
        const Output b = unwelded(mesh, options);
        REQUIRE(a.vertices.size() == b.vertices.size());
        std::size_t equal = 0;
        for (std::size_t i = 0; i < a.vertices.size(); ++i)
            equal += a.vertices[i].position[0] == b.vertices[i].position[0] &&
                     a.vertices[i].position[1] == b.vertices[i].position[1] &&
                     a.vertices[i].position[2] == b.vertices[i].position[2];
        CHECK(equal == a.vertices.size());
    }
}

TEST_CASE("vector displacement is watertight at uv seams and hard edges (§8.7): the chart cube") {
    for (int faces = 0; faces < 3; ++faces) {
        const models::Model cube = chart_cube(faces);
        const models::Adjacency adjacency = models::build_adjacency(cube);
        const rt::MeshView mesh = view_of(cube, &adjacency);
        std::vector<float> directions(3 * cube.vertex_count()), tangents(4 * cube.vertex_count());
        REQUIRE(rt::welded_directions(mesh, directions));
        REQUIRE(rt::uv_tangents(mesh, tangents));
        rt::Displacement d;
        d.mode = rt::DisplacementMode::vector;
        d.vector_function = &vector_ripple;
        d.scale = 0.2f;
        d.directions = directions.data();
        d.tangents = tangents.data();
        check_displaced_seams(mesh, d, faces, [](const Output&, const Output&) {});
        // Control 1: without adjacency every edge samples its own chart, and the seams crack.
        rt::MeshView no_adjacency = mesh;
        no_adjacency.adjacency = nullptr;
        rt::PipelineOptions options = constant_factor(5.5f, rt::Surface::flat);
        Output base = unwelded(no_adjacency, options);
        options.displacement = &d;
        CHECK(check_pairs(base, unwelded(no_adjacency, options)).mismatched > 0);
        // Control 2: a vector that is the same everywhere (no uv can differ), but each vertex's own tangent
        // (no dominant vertex: neither adjacency nor position ids): the frames of the faces meeting at an
        // edge differ, and the seams crack; with the dominant rule the same vector closes.
        rt::Displacement constant = d;
        constant.vector_function = &constant_vector;
        rt::MeshView own_frames = no_adjacency;
        own_frames.position_ids = nullptr;
        options.displacement = nullptr;
        base = unwelded(own_frames, options);
        options.displacement = &constant;
        CHECK(check_pairs(base, unwelded(own_frames, options)).mismatched > 0);
        CHECK(open_edges_by_position(welded(own_frames, options)) > 0);
        options.displacement = nullptr;
        base = unwelded(mesh, options);
        options.displacement = &constant;
        CHECK(check_pairs(base, unwelded(mesh, options)).mismatched == 0);
        CHECK(open_edges_by_position(welded(mesh, options)) == 0);
    }
}

TEST_CASE("vector displacement is watertight on spider.obj: an RGB noise map, grown factors") {
    const std::string path = "/usr/share/assimp/models/OBJ/spider.obj";
    const models::LoadResult loaded = models::load_model(path);
    if (!loaded.ok()) {
        WARN("skipped: " << path << " is not installed (Debian assimp-testmodels): " << loaded.error.message);
        return;
    }
    const models::Model& model = *loaded.model;
    const models::Adjacency adjacency = models::build_adjacency(model);
    const rt::MeshView mesh = view_of(model, &adjacency);
    std::vector<float> directions(3 * model.vertex_count()), tangents(4 * model.vertex_count());
    REQUIRE(rt::welded_directions(mesh, directions));
    REQUIRE(rt::uv_tangents(mesh, tangents));
    std::vector<float> texels(64 * 64 * 3);
    std::uint32_t state = 54321;
    for (float& t : texels) {
        state = state * 1664525u + 1013904223u;
        t = static_cast<float>(state >> 8) / 16777216.0f;
    }
    rt::Displacement d;
    d.mode = rt::DisplacementMode::vector;
    d.map = {texels.data(), 64, 64, rt::AddressMode::repeat, 3};
    d.scale = 2.0f;
    d.offset = -0.5f;
    d.directions = directions.data();
    d.tangents = tangents.data();
    REQUIRE(rt::displacement_valid(d));
    for (const rt::Surface surface : {rt::Surface::flat, rt::Surface::pn_aen}) {
        INFO("surface " << static_cast<int>(surface));
        rt::PipelineOptions options = constant_factor(3.5f, surface);
        const Output base = unwelded(mesh, options);
        const std::size_t open_before = open_edges_by_position(welded(mesh, options));
        options.displacement = &d;
        const Output moved = unwelded(mesh, options);
        const PairCheck pairs = check_pairs(base, moved);
        CHECK(pairs.shared > 0);
        CHECK(pairs.mismatched == 0);
        CHECK(open_edges_by_position(welded(mesh, options)) == open_before);
        // The tangential channels move points too: some point moves off its direction's line.
        bool sideways = false;
        for (std::size_t i = 0; i < base.vertices.size() && !sideways; ++i) {
            const rt::Vec3 move{moved.vertices[i].position[0] - base.vertices[i].position[0],
                                moved.vertices[i].position[1] - base.vertices[i].position[1],
                                moved.vertices[i].position[2] - base.vertices[i].position[2]};
            const rt::Vec3 n{base.vertices[i].normal[0], base.vertices[i].normal[1],
                             base.vertices[i].normal[2]};
            const rt::Vec3 off = move - rt::dot(move, n) * n;
            sideways = rt::dot(off, off) > 0.01f;
        }
        CHECK(sideways);
    }
    // Grown factors (§8.4) by the vector bound: the texels' vectors 2 * (t - 0.5) reach nearly sqrt(3).
    d.factor_bound = rt::displacement_bound(d);
    CHECK(d.factor_bound > 1.5f);
    CHECK(d.factor_bound <= std::sqrt(3.0f) * (1.0f + 1e-6f));
    rt::Displacement zero = d;
    zero.scale = 0.0f;
    check_grown_seams(mesh, d, zero);
}

TEST_CASE("vector displacement: the map's bound and RGB sampling (§8.7)") {
    // Texel vectors (3, 4, 0) and (0, 0, -6), a NaN texel skipped: the bound is the longest, 6.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float texels[9] = {3, 4, 0, 0, 0, -6, nan, 0, 0};
    rt::Displacement d;
    d.mode = rt::DisplacementMode::vector;
    d.map = {texels, 3, 1, rt::AddressMode::clamp, 3};
    CHECK(rt::displacement_bound(d) == 6.0f);
    d.scale = 0.5f;
    d.offset = 1.0f; // 0.5 * (t + 1): (2, 2.5, 0.5) and (0.5, 0.5, -2.5)
    CHECK(rt::displacement_bound(d) == std::sqrt(2.0f * 2.0f + 2.5f * 2.5f + 0.5f * 0.5f));
    // Components whose squares overflow float (an EXR texel can be this large): texel (3e20, 4e20, 0) at
    // scale 0.5 is (1.5e20, 2e20, 0), of length 2.5e20, which a float dot product would make inf.
    const float large[3] = {3e20f, 4e20f, 0.0f};
    rt::Displacement big = d;
    big.offset = 0.0f;
    big.map = {large, 1, 1, rt::AddressMode::clamp, 3};
    CHECK(rt::displacement_bound(big) ==
          static_cast<float>(std::sqrt(double{1.5e20f} * 1.5e20f + double{2e20f} * 2e20f)));
    CHECK(std::isfinite(rt::displacement_bound(big)));
    d.vector_function = &constant_vector; // a function's bound is the caller's
    CHECK(rt::displacement_bound(d) == 0.0f);
    // Channels: each of R, G, B samples as a one-channel map of it would (the same operations).
    std::vector<float> rgb(4 * 2 * 3), channel[3];
    for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<float>(i * 7 % 11) / 8.0f;
    for (unsigned c = 0; c < 3; ++c)
        for (std::size_t i = 0; i < 8; ++i) channel[c].push_back(rgb[3 * i + c]);
    for (const rt::AddressMode mode : {rt::AddressMode::repeat, rt::AddressMode::clamp})
        for (float u = -1.25f; u <= 2.0f; u += 0.0625f)
            for (float v = -0.5f; v <= 1.5f; v += 0.375f) {
                const rt::Texel3 s = rt::sample_bilinear_rgb({rgb.data(), 4, 2, mode, 3}, u, v);
                CHECK(s.x == rt::sample_bilinear({channel[0].data(), 4, 2, mode}, u, v));
                CHECK(s.y == rt::sample_bilinear({channel[1].data(), 4, 2, mode}, u, v));
                CHECK(s.z == rt::sample_bilinear({channel[2].data(), 4, 2, mode}, u, v));
                // The scalar sample of the RGB map reads its first channel.
                CHECK(rt::sample_bilinear({rgb.data(), 4, 2, mode, 3}, u, v) == s.x);
            }
    // Fewer than 3 channels, no channels, an empty map, a NaN coordinate: {0, 0, 0} (and 0 for the scalar).
    const rt::Texel3 one =
        rt::sample_bilinear_rgb({rgb.data(), 4, 2, rt::AddressMode::repeat, 1}, 0.3f, 0.3f);
    CHECK((one.x == 0.0f && one.y == 0.0f && one.z == 0.0f));
    CHECK(rt::sample_bilinear({rgb.data(), 4, 2, rt::AddressMode::repeat, 0}, 0.3f, 0.3f) == 0.0f);
    const rt::Texel3 empty = rt::sample_bilinear_rgb({nullptr, 4, 2, rt::AddressMode::repeat, 3}, 0.3f, 0.3f);
    CHECK((empty.x == 0.0f && empty.y == 0.0f && empty.z == 0.0f));
    const rt::Texel3 bad = rt::sample_bilinear_rgb({rgb.data(), 4, 2, rt::AddressMode::repeat, 3}, nan, 0.3f);
    CHECK((bad.x == 0.0f && bad.y == 0.0f && bad.z == 0.0f));
}

TEST_CASE(
    "vector displacement: bad options are refused (bad_option), the GPU takes a vector map, not a function") {
    const FlatSquare s = flat_square(true, false);
    std::vector<float> tangents(16);
    REQUIRE(rt::uv_tangents(s.view(), tangents));
    const float rgb[3] = {0.5f, 0.5f, 0.5f}, grey[1] = {0.5f};
    rt::Displacement good;
    good.mode = rt::DisplacementMode::vector;
    good.map = {rgb, 1, 1, rt::AddressMode::repeat, 3};
    good.tangents = tangents.data();
    REQUIRE(rt::displacement_valid(good));
    rt::PipelineOptions options = constant_factor(3.0f, rt::Surface::flat);
    std::vector<rt::PatchRecord> patches(1);
    rt::PipelineTotals totals;
    options.displacement = &good;
    REQUIRE(rt::setup_patches(rt::cp_tables, s.view(), options, patches, totals) == rt::PipelineStatus::ok);
    for (int bad = 0; bad < 8; ++bad) {
        rt::Displacement b = good;
        if (bad == 0) b.scale = std::nanf("");
        if (bad == 1) b.tangents = nullptr;                                        // no frame
        if (bad == 2) b.map = {grey, 1, 1, rt::AddressMode::repeat, 1};            // a grey map as vectors
        if (bad == 3) b.map.channels = 4;                                          // wrong channel count
        if (bad == 4) b.function = [](const void*, float, float) { return 1.0f; }; // a height in vector mode
        if (bad == 5) b.mode = static_cast<rt::DisplacementMode>(7);
        if (bad == 6) b.mode = rt::DisplacementMode::scalar; // an RGB map as heights
        if (bad == 7) {                                      // a vector function in scalar mode
            b.mode = rt::DisplacementMode::scalar;
            b.map = {grey, 1, 1, rt::AddressMode::repeat, 1};
            b.vector_function = &constant_vector;
        }
        INFO("bad option " << bad);
        CHECK_FALSE(rt::displacement_valid(b));
        options.displacement = &b;
        CHECK(rt::setup_patches(rt::cp_tables, s.view(), options, patches, totals) ==
              rt::PipelineStatus::bad_option);
    }
    // A scalar map of one channel and an empty map in either mode stay valid (an empty map reads 0, §8.1).
    rt::Displacement scalar;
    scalar.map = {grey, 1, 1, rt::AddressMode::repeat, 1};
    CHECK(rt::displacement_valid(scalar));
    rt::Displacement empty = good;
    empty.map = {};
    CHECK(rt::displacement_valid(empty));
    // The shaders run vector mode from an RGB map (docs/shaders.md, "Vector displacement"); a VectorFunction
    // is CPU code, and gpu_options_status refuses it.
    rt::PipelineOptions gpu;
    gpu.dice.mode = rt::FactorMode::camera;
    gpu.displacement = &scalar;
    CHECK(rt::gpu::gpu_options_status(s.view(), gpu) == rt::PipelineStatus::ok);
    gpu.displacement = &good;
    CHECK(rt::gpu::gpu_options_status(s.view(), gpu) == rt::PipelineStatus::ok);
    rt::Displacement function = good;
    function.map = {};
    function.vector_function = &constant_vector;
    REQUIRE(rt::displacement_valid(function));
    gpu.displacement = &function;
    CHECK(rt::gpu::gpu_options_status(s.view(), gpu) == rt::PipelineStatus::bad_option);
}

namespace {

void append_bytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    out->insert(out->end(), static_cast<std::uint8_t*>(data), static_cast<std::uint8_t*>(data) + size);
}

std::vector<std::uint8_t> png(int w, int h, int channels, const std::vector<std::uint8_t>& texels) {
    std::vector<std::uint8_t> out;
    REQUIRE(stbi_write_png_to_func(&append_bytes, &out, w, h, channels, texels.data(), w * channels) != 0);
    return out;
}

} // namespace

TEST_CASE("load_vector_map: RGB and RGBA keep red, green, blue, grey is an error (docs/models.md)") {
    // 2 x 1 RGB: (0, 51, 255), (255, 102, 0); RGBA adds alpha, which is dropped.
    const std::vector<std::uint8_t> rgb = {0, 51, 255, 255, 102, 0};
    const std::vector<float> expected = {0.0f, 51.0f / 255.0f, 1.0f, 1.0f, 102.0f / 255.0f, 0.0f};
    const models::HeightMapResult a = models::load_vector_map_from_memory(png(2, 1, 3, rgb), "rgb");
    INFO(a.error.message);
    REQUIRE(a.ok());
    CHECK(a.image->channels == 3);
    CHECK(a.image->width == 2);
    CHECK(a.image->texels == expected);
    CHECK(a.image->view().channels == 3);
    const models::HeightMapResult b =
        models::load_vector_map_from_memory(png(2, 1, 4, {0, 51, 255, 9, 255, 102, 0, 200}), "rgba");
    REQUIRE(b.ok());
    CHECK(b.image->texels == expected);
    // The same RGB file as a height map keeps red only, one channel.
    const models::HeightMapResult h = models::load_height_map_from_memory(png(2, 1, 3, rgb), "rgb");
    REQUIRE(h.ok());
    CHECK(h.image->channels == 1);
    CHECK(h.image->texels == std::vector<float>{0.0f, 1.0f});
    // Grey and grey + alpha have no x and y: an error naming the file, no image.
    for (const int channels : {1, 2}) {
        const models::HeightMapResult g = models::load_vector_map_from_memory(
            png(2, 1, channels, std::vector<std::uint8_t>(2 * static_cast<std::size_t>(channels), 128)),
            "grey");
        CHECK_FALSE(g.ok());
        CHECK(g.error.message.find("grey") != std::string::npos);
        CHECK(g.error.message.rfind("grey:", 0) == 0);
    }
    // The height map's errors hold: empty bytes, a missing file.
    CHECK_FALSE(models::load_vector_map_from_memory({}, "nothing").ok());
    const models::HeightMapResult missing = models::load_vector_map("/nonexistent/ctess/vector.png");
    CHECK_FALSE(missing.ok());
    CHECK(missing.error.message.find("/nonexistent/ctess/vector.png") != std::string::npos);
}

namespace {

std::string base64(const std::vector<std::uint8_t>& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t n = std::uint32_t{bytes[i]} << 16;
        if (i + 1 < bytes.size()) n |= std::uint32_t{bytes[i + 1]} << 8;
        if (i + 2 < bytes.size()) n |= bytes[i + 2];
        out += digits[(n >> 18) & 63];
        out += digits[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[n & 63] : '=';
    }
    return out;
}

// A .gltf of the right triangle (0,0,0), (1,0,0), (0,1,0), normal +z, uv = xy, TANGENT (0, 1, 0, 1) (a frame
// uv_tangents would not give: it would say +x), under `node` (its JSON); with a second primitive without
// TANGENT when `second` is set.
models::LoadResult tangent_gltf(const std::string& node, bool second) {
    const float data[] = {0, 0, 0, 1, 0, 0, 0, 1, 0,           // POSITION
                          0, 0, 1, 0, 0, 1, 0, 0, 1,           // NORMAL
                          0, 0, 1, 0, 0, 1,                    // TEXCOORD_0
                          0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1}; // TANGENT
    std::vector<std::uint8_t> bytes(sizeof data);
    std::memcpy(bytes.data(), data, sizeof data);
    const std::string attributes = R"("POSITION":0,"NORMAL":1,"TEXCOORD_0":2)";
    const std::string json =
        R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":144,"uri":"data:application/octet-stream;base64,)" +
        base64(bytes) +
        R"("}],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":36},)"
        R"({"buffer":0,"byteOffset":72,"byteLength":24},{"buffer":0,"byteOffset":96,"byteLength":48}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},)"
        R"({"bufferView":1,"componentType":5126,"count":3,"type":"VEC3"},)"
        R"({"bufferView":2,"componentType":5126,"count":3,"type":"VEC2"},)"
        R"({"bufferView":3,"componentType":5126,"count":3,"type":"VEC4"}],)"
        R"("meshes":[{"primitives":[{"attributes":{)" +
        attributes + R"(,"TANGENT":3}})" +
        (second ? R"(,{"attributes":{)" + attributes + "}}" : std::string()) + R"(]}],"nodes":[)" + node +
        R"(],"scenes":[{"nodes":[0]}],"scene":0})";
    return models::load_model_from_memory(
        std::span(reinterpret_cast<const std::uint8_t*>(json.data()), json.size()),
        models::ModelKind::gltf_text, "tangents.gltf");
}

} // namespace

TEST_CASE("glTF TANGENT: read, transformed, and used as the vector displacement's frame (§8.7)") {
    const models::LoadResult plain = tangent_gltf(R"({"mesh":0})", false);
    INFO(plain.error.message);
    REQUIRE(plain.ok());
    const models::Model& m = *plain.model;
    REQUIRE(m.has_tangents);
    CHECK(m.tangents == std::vector<float>{0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1});
    // A mirroring node (x -> -x): the tangent (0, 1, 0) stays, the handedness flips.
    const models::LoadResult mirrored = tangent_gltf(R"({"mesh":0,"scale":[-1,1,1]})", false);
    REQUIRE(mirrored.ok());
    CHECK(mirrored.model->tangents == std::vector<float>{0, 1, 0, -1, 0, 1, 0, -1, 0, 1, 0, -1});
    // A primitive without TANGENT: none kept (as has_normals).
    const models::LoadResult mixed = tangent_gltf(R"({"mesh":0})", true);
    REQUIRE(mixed.ok());
    CHECK_FALSE(mixed.model->has_tangents);
    CHECK(mixed.model->tangents.empty());
    // The file's frame: T = +y, B = cross(N, T) = -x; the vector (0.75, 0.5, 1.25) moves by (-0.5,
    // 0.75, 1.25).
    const float texel[3] = {0.5f, 0.25f, 1.0f};
    rt::Displacement d;
    d.mode = rt::DisplacementMode::vector;
    d.map = {texel, 1, 1, rt::AddressMode::clamp, 3};
    d.scale = 0.5f;
    d.factor = 2.0f;
    d.offset = 0.5f;
    d.tangents = m.tangents.data();
    const rt::MeshView mesh = view_of(m, nullptr);
    rt::PipelineOptions options = constant_factor(4.5f, rt::Surface::flat);
    const Output base = unwelded(mesh, options);
    options.displacement = &d;
    const Output moved = unwelded(mesh, options);
    REQUIRE(moved.vertices.size() == base.vertices.size());
    std::size_t exact = 0;
    for (std::size_t i = 0; i < moved.vertices.size(); ++i)
        exact += moved.vertices[i].position[0] == base.vertices[i].position[0] - 0.5f &&
                 moved.vertices[i].position[1] == base.vertices[i].position[1] + 0.75f &&
                 moved.vertices[i].position[2] == 1.25f;
    CHECK(exact == moved.vertices.size());
}
