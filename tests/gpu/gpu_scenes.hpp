// Test meshes for the GPU pipeline tests, in the mesh pipeline's vertex layout (8 floats: position, normal,
// uv). split_normal_icosphere needs ctess::models linked (meshoptimizer's adjacency).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <utility>
#include <vector>

#include <ctess/runtime/displace/displace.hpp>
#include <ctess/runtime/models/adjacency.hpp>
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>

namespace ctess::gpu_test {

struct Scene {
    std::vector<float> vertices;
    std::vector<std::uint32_t> indices; // 3 per triangle
    std::vector<std::uint32_t> quads;   // 4 per quad (the patches after the triangles)
    // Empty, or 12 per face triangle (the triangles, then each quad's (q0, q1, q2) and (q0, q2, q3)):
    // meshopt_generateTessellationIndexBuffer's layout (rt::MeshView::adjacency), which PN-AEN reads.
    std::vector<std::uint32_t> adjacency;
    rt::PipelineOptions options;

    rt::MeshView view() const {
        rt::MeshView v{vertices.data(), static_cast<std::uint32_t>(vertices.size() / rt::mesh_vertex_floats),
                       indices.data(),  static_cast<std::uint32_t>(indices.size() / 3),
                       quads.data(),    static_cast<std::uint32_t>(quads.size() / 4)};
        if (!adjacency.empty()) v.adjacency = adjacency.data();
        return v;
    }
    std::uint32_t patch_count() const {
        return static_cast<std::uint32_t>(indices.size() / 3 + quads.size() / 4);
    }
};

// The words a host uploads as binding 3 (docs/shaders.md, "Passes and bindings"): the triangles' indices, the
// quads', then the adjacency when the scene has it, then with displacement the map's texels (3 floats each in
// vector mode).
inline std::vector<std::uint32_t> mesh_index_words(const Scene& scene) {
    std::vector<std::uint32_t> words = scene.indices;
    words.insert(words.end(), scene.quads.begin(), scene.quads.end());
    words.insert(words.end(), scene.adjacency.begin(), scene.adjacency.end());
    if (const rt::Displacement* d = scene.options.displacement; d != nullptr && d->map.texels != nullptr) {
        const std::size_t count =
            std::size_t{d->map.width} * d->map.height * (d->mode == rt::DisplacementMode::vector ? 3u : 1u);
        const std::size_t at = words.size();
        words.resize(at + count);
        if (count != 0) std::memcpy(&words[at], d->map.texels, count * 4);
    }
    return words;
}
// The floats a host uploads as binding 2: the mesh vertices, then with displacement its directions, then in
// vector mode its tangents (docs/shaders.md, "Displacement").
inline std::vector<float> mesh_vertex_data(const Scene& scene) {
    std::vector<float> floats = scene.vertices;
    const std::size_t n = scene.vertices.size() / rt::mesh_vertex_floats;
    if (const rt::Displacement* d = scene.options.displacement; d != nullptr) {
        if (d->directions != nullptr) floats.insert(floats.end(), d->directions, d->directions + 3 * n);
        if (d->mode == rt::DisplacementMode::vector && d->tangents != nullptr)
            floats.insert(floats.end(), d->tangents, d->tangents + 4 * n);
    }
    return floats;
}

namespace detail {
inline std::uint32_t hash(std::uint32_t x) { // small integer hash for deterministic jitter
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}
inline float unit(std::uint32_t x) {
    return static_cast<float>(hash(x) >> 8) * (1.0f / 16777216.0f);
}
inline void push_vertex(Scene& s, rt::Vec3 p, rt::Vec3 n, float u, float v) {
    s.vertices.insert(s.vertices.end(), {p.x, p.y, p.z, n.x, n.y, n.z, u, v});
}
} // namespace detail

// A wavy height field over a grid whose column widths grow geometrically by 3 * max_factor overall and whose
// row heights grow by 16, seen from above at a distance: the edge factors cover every octave of [1, max] and
// both clamps (below 1, above max), over cells x cells x 2 patches, while the long thin patches of the wide
// columns keep the output near a million vertices at max 256.
// quad_every > 0: every quad_every-th cell is one quad (a mixed mesh) instead of two triangles.
inline Scene factor_sweep_grid(unsigned max_factor, unsigned cells, rt::Surface surface,
                               unsigned quad_every = 0) {
    Scene s;
    const auto axis = [cells](float growth, std::uint32_t seed) {
        const float ratio = std::pow(growth, 1.0f / static_cast<float>(cells - 1));
        std::vector<float> coord(cells + 1, 0.0f);
        float width = 1.0f;
        for (unsigned i = 0; i < cells; ++i) {
            coord[i + 1] = coord[i] + width * (0.75f + 0.5f * detail::unit(seed + i));
            width *= ratio;
        }
        return coord;
    };
    const std::vector<float> xs = axis(3.0f * static_cast<float>(max_factor), 0);
    const std::vector<float> ys = axis(16.0f, 1000);
    const float extent = xs[cells];
    for (unsigned j = 0; j <= cells; ++j) {
        for (unsigned i = 0; i <= cells; ++i) {
            const float x = xs[i] / extent, y = ys[j] / extent;
            const float h = 0.02f * std::sin(9.0f * x) * std::cos(7.0f * y);
            const rt::Vec3 n = rt::normalize_or_zero({-0.18f * std::cos(9.0f * x) * std::cos(7.0f * y),
                                                      0.14f * std::sin(9.0f * x) * std::sin(7.0f * y), 1.0f});
            detail::push_vertex(s, {x, y, h}, n, x, y);
        }
    }
    for (unsigned j = 0; j < cells; ++j) {
        for (unsigned i = 0; i < cells; ++i) {
            const std::uint32_t a = j * (cells + 1) + i, b = a + 1, c = a + cells + 1, d = c + 1;
            if (quad_every != 0 && (j * cells + i) % quad_every == 0)
                s.quads.insert(s.quads.end(), {a, b, d, c});
            else if ((i + j) % 2 == 0)
                s.indices.insert(s.indices.end(), {a, b, d, a, d, c});
            else
                s.indices.insert(s.indices.end(), {a, b, c, b, d, c});
        }
    }
    // Seen from above at distance about 1.5: the smallest cells (width 1/extent) give factors near 0.5.
    s.options.dice.eye = {0.5f, 0.5f * ys[cells] / extent, 1.5f};
    s.options.dice.dice_rate = 2.0f;
    s.options.dice.projection_scale = 1.0f * 1.5f * extent;
    s.options.surface = {surface, 0.75f};
    return s;
}

// A subdivided icosahedron (closed, every edge shared by two triangles) around the origin, with per-vertex
// normals tilted away from the sphere's so that PN and Phong bend the surface; the eye sits outside it.
inline Scene icosphere(unsigned subdivisions, rt::Surface surface, float dice_rate) {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<rt::Vec3> p = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                               {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    for (auto& v : p) v = rt::normalize_or_zero(v);
    std::vector<std::uint32_t> tri = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                                      4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                                      6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
    for (unsigned level = 0; level < subdivisions; ++level) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            p.push_back(rt::normalize_or_zero(0.5f * (p[a] + p[b])));
            const auto index = static_cast<std::uint32_t>(p.size() - 1);
            mid.emplace(key, index);
            return index;
        };
        std::vector<std::uint32_t> next;
        for (std::size_t k = 0; k < tri.size(); k += 3) {
            const std::uint32_t a = tri[k], b = tri[k + 1], c = tri[k + 2];
            const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
        }
        tri = std::move(next);
    }
    Scene s;
    for (std::uint32_t i = 0; i < p.size(); ++i) {
        const rt::Vec3 tilt = {detail::unit(3 * i) - 0.5f, detail::unit(3 * i + 1) - 0.5f,
                               detail::unit(3 * i + 2) - 0.5f};
        const rt::Vec3 n = rt::normalize_or_zero(p[i] + 0.6f * tilt);
        detail::push_vertex(s, p[i], n, 0.5f + 0.5f * p[i].x, 0.5f + 0.5f * p[i].y);
    }
    s.indices = std::move(tri);
    s.options.dice.eye = {0.3f, 0.4f, 2.2f};
    s.options.dice.dice_rate = dice_rate;
    s.options.dice.projection_scale = 800.0f;
    s.options.surface = {surface, 1.0f};
    return s;
}

// The scene's PN-AEN adjacency from models::build_adjacency (meshoptimizer), as `ctess mesh` computes it.
inline void add_adjacency(Scene& s) {
    models::Model model;
    model.vertices = s.vertices;
    model.triangles = s.indices;
    model.quads = s.quads;
    s.adjacency = models::build_adjacency(model).tessellation_indices;
}

// icosphere() cut into the 20 regions of its base icosahedron's faces, each region with its own copies of its
// vertices: along a region border one position carries two vertices, always with different uvs (a uv seam)
// and, where either region is odd, with different normals (a hard edge: odd regions tilt their normals their
// own way). Closed by position; adjacency from models::build_adjacency (meshoptimizer), as `ctess mesh`
// computes it.
// hard_edges false: the normals stay shared (uv seams only).
inline Scene split_normal_icosphere(unsigned subdivisions, rt::Surface surface, float dice_rate,
                                    bool hard_edges = true) {
    const Scene smooth = icosphere(subdivisions, surface, dice_rate);
    Scene s;
    s.options = smooth.options;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> copy; // (vertex, region) -> new vertex
    for (std::size_t k = 0; k < smooth.indices.size(); ++k) {
        // Subdivision puts a face's four children in a row: triangle t lies in base face t / 4^subdivisions.
        const auto region = static_cast<std::uint32_t>((k / 3) >> (2 * subdivisions));
        const std::uint32_t v = smooth.indices[k];
        const auto [it, fresh] = copy.try_emplace({v, region}, static_cast<std::uint32_t>(copy.size()));
        s.indices.push_back(it->second);
        if (!fresh) continue;
        const float* a = &smooth.vertices[std::size_t{v} * rt::mesh_vertex_floats];
        rt::Vec3 n = {a[3], a[4], a[5]};
        if (hard_edges && region % 2 == 1) {
            const std::uint32_t seed = 1000 + 3 * (v * 20 + region);
            n = rt::normalize_or_zero(n + 0.5f * rt::Vec3{detail::unit(seed) - 0.5f,
                                                          detail::unit(seed + 1) - 0.5f,
                                                          detail::unit(seed + 2) - 0.5f});
        }
        detail::push_vertex(s, {a[0], a[1], a[2]}, n, a[6] + 0.05f * static_cast<float>(region), a[7]);
    }
    add_adjacency(s);
    return s;
}

// A flat grid of cells x cells x 2 patches seen from so close that every edge factor clamps to the maximum:
// the largest output per patch, for the totals' overflow guard.
inline Scene max_factor_grid(unsigned cells) {
    Scene s;
    for (unsigned j = 0; j <= cells; ++j)
        for (unsigned i = 0; i <= cells; ++i) {
            const float x = static_cast<float>(i) / cells, y = static_cast<float>(j) / cells;
            detail::push_vertex(s, {x, y, 0.0f}, {0.0f, 0.0f, 1.0f}, x, y);
        }
    for (unsigned j = 0; j < cells; ++j)
        for (unsigned i = 0; i < cells; ++i) {
            const std::uint32_t a = j * (cells + 1) + i, b = a + 1, c = a + cells + 1, d = c + 1;
            s.indices.insert(s.indices.end(), {a, b, d, a, d, c});
        }
    s.options.dice.eye = {0.5f, 0.5f, 0.01f};
    s.options.dice.projection_scale = 1.0e7f;
    s.options.surface = {rt::Surface::flat, 0.0f};
    return s;
}

// `patches` copies of one large triangle close to the eye: every edge factor is far above 256, so every patch
// is the (max, max, max) pattern. Three shared vertices keep the mesh itself small.
inline Scene repeated_big_triangle(std::uint32_t patches) {
    Scene s;
    const float corners[3][rt::mesh_vertex_floats] = {
        {-100.0f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f},
        {100.0f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f, 1.0f, 0.0f},
        {0.0f, 100.0f, 1.0f, 0.0f, 0.0f, 1.0f, 0.0f, 1.0f},
    };
    s.vertices.assign(&corners[0][0], &corners[0][0] + 3 * rt::mesh_vertex_floats);
    s.indices.resize(3 * std::size_t{patches});
    for (std::size_t t = 0; t < patches; ++t) s.indices[3 * t + 1] = 1, s.indices[3 * t + 2] = 2;
    return s;
}

} // namespace ctess::gpu_test
