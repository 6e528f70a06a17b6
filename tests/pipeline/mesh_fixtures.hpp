// Models and checks shared by the mesh pipeline tests (tests/pipeline/): closed and open models built here
// (a triangle, quad or mixed torus, optionally with a uv seam; an octahedron sphere; an open mixed grid), the
// unwelded and welded pipeline runs, an independent weld by exact bits, closedness and boundary checks.
#pragma once
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

#include <ctess/runtime/pipeline/mesh_pipeline.hpp>
#include <ctess/runtime/uniform/table_set.hpp>

namespace pipeline_fixtures {

using namespace ctess;

constexpr float two_pi = 6.28318530717958647692f;

struct Model {
    std::vector<float> vertices; // rt::mesh_vertex_floats per vertex
    std::vector<std::uint32_t> triangles, quads;

    std::uint32_t add(float x, float y, float z, float nx, float ny, float nz, float u, float v) {
        const float f[8] = {x, y, z, nx, ny, nz, u, v};
        vertices.insert(vertices.end(), f, f + 8);
        return static_cast<std::uint32_t>(vertices.size() / 8 - 1);
    }
    rt::MeshView view() const {
        return {vertices.data(),  static_cast<std::uint32_t>(vertices.size() / 8),
                triangles.data(), static_cast<std::uint32_t>(triangles.size() / 3),
                quads.data(),     static_cast<std::uint32_t>(quads.size() / 4)};
    }
};

enum class Faces { triangles, quads, mixed };

// A torus of nu x nv cells (major radius 3, minor 1). The cell's first edge runs along u (around the major
// circle), which with nu much larger than nv is the short pair of the quad. seam: a last column that repeats
// the first column's positions bit for bit with u = 1 (a uv seam: different indices at one position).
inline Model torus(unsigned nu, unsigned nv, Faces faces, bool seam = false) {
    Model m;
    const unsigned columns = seam ? nu + 1 : nu;
    for (unsigned i = 0; i < columns; ++i) {
        for (unsigned j = 0; j < nv; ++j) {
            if (i == nu) { // the seam column: column 0's position and normal, u = 1
                const float* p = &m.vertices[std::size_t{j} * 8];
                m.add(p[0], p[1], p[2], p[3], p[4], p[5], 1.0f, p[7]);
                continue;
            }
            const float u = two_pi * static_cast<float>(i) / static_cast<float>(nu);
            const float v = two_pi * static_cast<float>(j) / static_cast<float>(nv);
            const float ring = 3.0f + std::cos(v);
            m.add(ring * std::cos(u), ring * std::sin(u), std::sin(v), std::cos(v) * std::cos(u),
                  std::cos(v) * std::sin(u), std::sin(v), static_cast<float>(i) / static_cast<float>(nu),
                  static_cast<float>(j) / static_cast<float>(nv));
        }
    }
    auto id = [&](unsigned i, unsigned j) {
        const unsigned column = seam ? i : i % nu;
        return static_cast<std::uint32_t>(column * nv + j % nv);
    };
    for (unsigned i = 0; i < nu; ++i) {
        for (unsigned j = 0; j < nv; ++j) {
            const std::uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            const bool as_quad = faces == Faces::quads || (faces == Faces::mixed && (i + j) % 3 != 0);
            if (as_quad) {
                m.quads.insert(m.quads.end(), {a, b, c, d});
            } else {
                m.triangles.insert(m.triangles.end(), {a, b, c, a, c, d});
            }
        }
    }
    return m;
}

// An octahedron subdivided `levels` times, projected to the unit sphere: closed, triangles only.
inline Model octasphere(unsigned levels) {
    Model m;
    auto add_unit = [&](float x, float y, float z) {
        const float l = std::sqrt(x * x + y * y + z * z);
        return m.add(x / l, y / l, z / l, x / l, y / l, z / l, 0.5f + 0.5f * x / l, 0.5f + 0.5f * y / l);
    };
    add_unit(1, 0, 0);
    add_unit(-1, 0, 0);
    add_unit(0, 1, 0);
    add_unit(0, -1, 0);
    add_unit(0, 0, 1);
    add_unit(0, 0, -1);
    m.triangles = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    for (unsigned l = 0; l < levels; ++l) {
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
        auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            const float* p = &m.vertices[std::size_t{a} * 8];
            const float* q = &m.vertices[std::size_t{b} * 8];
            const std::uint32_t v = add_unit(p[0] + q[0], p[1] + q[1], p[2] + q[2]);
            mid[key] = v;
            return v;
        };
        std::vector<std::uint32_t> next;
        for (std::size_t t = 0; t < m.triangles.size(); t += 3) {
            const std::uint32_t a = m.triangles[t], b = m.triangles[t + 1], c = m.triangles[t + 2];
            const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
            next.insert(next.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
        }
        m.triangles = next;
    }
    return m;
}

// An open n x n grid in the z = 0 plane, every third cell as two triangles, the rest quads.
inline Model open_grid(unsigned n) {
    Model m;
    for (unsigned i = 0; i <= n; ++i)
        for (unsigned j = 0; j <= n; ++j)
            m.add(static_cast<float>(i) * 0.5f, static_cast<float>(j) * 0.25f, 0.0f, 0.0f, 0.0f, 1.0f,
                  static_cast<float>(i), static_cast<float>(j));
    auto id = [&](unsigned i, unsigned j) { return static_cast<std::uint32_t>(i * (n + 1) + j); };
    for (unsigned i = 0; i < n; ++i)
        for (unsigned j = 0; j < n; ++j) {
            const std::uint32_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            if ((i + j) % 3 == 0)
                m.triangles.insert(m.triangles.end(), {a, b, c, a, c, d});
            else
                m.quads.insert(m.quads.end(), {a, b, c, d});
        }
    return m;
}

struct Output {
    rt::PipelineStatus status = rt::PipelineStatus::ok;
    std::vector<rt::TessVertex> vertices;
    std::vector<std::uint32_t> indices;
    std::uint32_t clamped_edges = 0;
    std::vector<rt::WeldedEdge> edges;
};

inline const rt::UniformTableSet& uniform_set() {
    return rt::uniform_tables;
}

inline Output unwelded(const rt::MeshView& mesh, const rt::PipelineOptions& options) {
    Output out;
    std::vector<rt::PatchRecord> patches(mesh.patch_count());
    rt::PipelineTotals totals;
    out.status = rt::setup_patches(rt::cp_tables_64, uniform_set(), mesh, options, patches, totals);
    if (out.status != rt::PipelineStatus::ok) return out;
    out.clamped_edges = totals.clamped_edges;
    out.vertices.resize(totals.vertices);
    out.indices.resize(3 * std::size_t{totals.triangles});
    out.status =
        rt::emit_mesh(rt::cp_tables_64, uniform_set(), mesh, options, patches, out.vertices, out.indices);
    return out;
}

inline Output welded(const rt::MeshView& mesh, const rt::PipelineOptions& options) {
    Output out;
    out.edges.resize(rt::weld_edge_capacity(mesh));
    std::vector<rt::WeldedPatch> patches(mesh.patch_count());
    rt::WeldedTotals totals;
    out.status = rt::setup_welded(rt::cp_tables_64, uniform_set(), mesh, options, out.edges, patches, totals);
    if (out.status != rt::PipelineStatus::ok) return out;
    out.clamped_edges = totals.clamped_edges;
    out.edges.resize(totals.edges);
    out.vertices.resize(totals.vertices);
    out.indices.resize(3 * std::size_t{totals.triangles});
    out.status = rt::emit_welded_mesh(rt::cp_tables_64, uniform_set(), mesh, options, out.edges, patches,
                                      out.vertices, out.indices);
    return out;
}

// A vertex's exact bits: position only, or position, normal and uv.
using Key = std::array<std::uint32_t, 8>;
inline Key key_of(const rt::TessVertex& v, bool attributes) {
    Key k{};
    std::memcpy(k.data(), v.position, 12);
    if (attributes) {
        std::memcpy(k.data() + 3, v.normal, 12);
        std::memcpy(k.data() + 6, v.uv, 8);
    }
    return k;
}

struct KeyHash {
    std::size_t operator()(const Key& k) const {
        std::uint64_t h = 1469598103934665603ull;
        for (std::uint32_t w : k) h = (h ^ w) * 1099511628211ull;
        return static_cast<std::size_t>(h);
    }
};

// The independent weld: one id per distinct key, in order of first appearance.
inline std::vector<std::uint32_t> weld_ids(const std::vector<rt::TessVertex>& vertices, bool attributes) {
    std::unordered_map<Key, std::uint32_t, KeyHash> ids;
    std::vector<std::uint32_t> out(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i)
        out[i] = ids.emplace(key_of(vertices[i], attributes), static_cast<std::uint32_t>(ids.size()))
                     .first->second;
    return out;
}

// Triangles as key triples (rotated so the smallest key is first, winding kept), those with two equal keys
// (two coincident corners) left out, sorted.
inline std::vector<std::array<Key, 3>> key_triangles(const Output& o) {
    std::vector<std::array<Key, 3>> out;
    for (std::size_t t = 0; t + 2 < o.indices.size(); t += 3) {
        std::array<Key, 3> k;
        for (unsigned c = 0; c < 3; ++c) k[c] = key_of(o.vertices[o.indices[t + c]], true);
        if (k[0] == k[1] || k[1] == k[2] || k[0] == k[2]) continue;
        const auto first = std::min_element(k.begin(), k.end()) - k.begin();
        std::rotate(k.begin(), k.begin() + first, k.end());
        out.push_back(k);
    }
    std::sort(out.begin(), out.end());
    return out;
}

// Directed edges (a << 32 | b) of the triangles under an id map, sorted; triangles with a repeated id are
// left out.
using EdgeCounts = std::vector<std::uint64_t>;
inline EdgeCounts directed_edges(const std::vector<std::uint32_t>& indices,
                                 const std::vector<std::uint32_t>& id) {
    EdgeCounts edges;
    edges.reserve(indices.size());
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint64_t a = id[indices[t]], b = id[indices[t + 1]], c = id[indices[t + 2]];
        if (a == b || b == c || a == c) continue;
        edges.insert(edges.end(), {a << 32 | b, b << 32 | c, c << 32 | a});
    }
    std::sort(edges.begin(), edges.end());
    return edges;
}

inline std::uint64_t reversed(std::uint64_t e) {
    return e >> 32 | e << 32;
}

inline std::vector<std::uint32_t> identity(std::size_t n) {
    std::vector<std::uint32_t> id(n);
    for (std::size_t i = 0; i < n; ++i) id[i] = static_cast<std::uint32_t>(i);
    return id;
}

// Closed and 2-manifold, consistently oriented: every directed edge once, and its reverse once.
inline bool closed_manifold(const EdgeCounts& edges) {
    for (std::size_t i = 0; i < edges.size(); ++i) {
        if (i > 0 && edges[i] == edges[i - 1]) return false;
        if (!std::binary_search(edges.begin(), edges.end(), reversed(edges[i]))) return false;
    }
    return true;
}

// Boundary edges (directed edges without a reverse); false when an edge is used more than once.
inline bool boundary(const EdgeCounts& edges, std::vector<std::pair<std::uint32_t, std::uint32_t>>& out) {
    for (std::size_t i = 0; i < edges.size(); ++i) {
        if (i > 0 && edges[i] == edges[i - 1]) return false;
        if (!std::binary_search(edges.begin(), edges.end(), reversed(edges[i])))
            out.emplace_back(static_cast<std::uint32_t>(edges[i] >> 32),
                             static_cast<std::uint32_t>(edges[i]));
    }
    return true;
}

// The input mesh's boundary edges (directed, as the faces list them).
inline std::vector<std::pair<std::uint32_t, std::uint32_t>> input_boundary(const Model& m) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, unsigned> edges;
    for (std::size_t t = 0; t < m.triangles.size(); t += 3)
        for (unsigned k = 0; k < 3; ++k) ++edges[{m.triangles[t + k], m.triangles[t + (k + 1) % 3]}];
    for (std::size_t q = 0; q < m.quads.size(); q += 4)
        for (unsigned k = 0; k < 4; ++k) ++edges[{m.quads[q + k], m.quads[q + (k + 1) % 4]}];
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
    for (const auto& [e, n] : edges)
        if (!edges.count({e.second, e.first})) out.push_back(e);
    return out;
}

// The welded output's boundary is the input's, subdivided: as many segments as the input boundary edges have
// points plus one, each segment between two points of one input boundary edge (its corners and its edge
// points).
inline void check_boundary_subdivided(const Model& m, const Output& w) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
    REQUIRE(boundary(directed_edges(w.indices, identity(w.vertices.size())), out));
    const auto in = input_boundary(m);
    std::size_t segments = 0;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> points;
    for (const auto& [a, b] : in) {
        const rt::WeldedEdge key{std::min(a, b), std::max(a, b), 0, 0};
        const auto it =
            std::lower_bound(w.edges.begin(), w.edges.end(), key, [](const auto& x, const auto& y) {
                return x.lo != y.lo ? x.lo < y.lo : x.hi < y.hi;
            });
        REQUIRE(it != w.edges.end());
        REQUIRE((it->lo == key.lo && it->hi == key.hi));
        segments += it->vertex_count + 1;
        auto& p = points[{a, b}];
        p = {a, b};
        for (std::uint32_t i = 0; i < it->vertex_count; ++i) p.push_back(it->first_vertex + i);
    }
    CHECK(out.size() == segments);
    for (const auto& [a, b] : out) {
        bool found = false;
        for (const auto& [e, p] : points)
            found = found || (std::count(p.begin(), p.end(), a) && std::count(p.begin(), p.end(), b));
        CHECK(found);
    }
}

// The properties every weld must have: the same non-degenerate triangles as the unwelded output (as exact
// key triples), no two triangles naming a repeated vertex unless asked, and every vertex used.
inline void check_weld_matches(const rt::MeshView& mesh, const rt::PipelineOptions& options, const Output& u,
                               const Output& w) {
    REQUIRE(u.status == rt::PipelineStatus::ok);
    REQUIRE(w.status == rt::PipelineStatus::ok);
    CHECK(key_triangles(u) == key_triangles(w));
    CHECK(u.clamped_edges == w.clamped_edges);
    std::vector<bool> used(w.vertices.size(), false);
    std::size_t repeated = 0;
    for (std::size_t t = 0; t < w.indices.size(); t += 3) {
        for (unsigned c = 0; c < 3; ++c) used[w.indices[t + c]] = true;
        repeated += w.indices[t] == w.indices[t + 1] || w.indices[t + 1] == w.indices[t + 2] ||
                    w.indices[t] == w.indices[t + 2];
    }
    if (!options.weld.keep_degenerate) CHECK(repeated == 0);
    // Mesh vertices may be unused (none here); every edge and interior point is used.
    for (std::size_t v = mesh.vertex_count; v < used.size(); ++v) {
        if (!used[v]) {
            FAIL_CHECK("welded vertex " << v << " is not used");
            break;
        }
    }
    // Every output position once: the welded vertices are exactly the unwelded output's distinct keys.
    const auto wu = weld_ids(u.vertices, true), ww = weld_ids(w.vertices, true);
    CHECK(*std::max_element(wu.begin(), wu.end()) == *std::max_element(ww.begin(), ww.end()));
    CHECK(*std::max_element(ww.begin(), ww.end()) + 1 == w.vertices.size());
}

inline rt::PipelineOptions camera(rt::Pattern pattern, rt::Vec3 eye, float dice_rate,
                                  float projection_scale = 1000.0f) {
    rt::PipelineOptions o;
    o.pattern = pattern;
    o.dice.eye = eye;
    o.dice.projection_scale = projection_scale;
    o.dice.dice_rate = dice_rate;
    return o;
}

// The longest output edge of every non-degenerate triangle in DiceRate units (pixels / dice_rate, the edge
// projected as the factor formula projects it, tess_factor.hpp): p50, p99, max.
inline std::array<double, 3> longest_edge_stats(const Output& o, const rt::DiceOptions& dice) {
    std::vector<double> longest;
    for (std::size_t t = 0; t < o.indices.size(); t += 3) {
        double l = 0;
        bool degenerate = false;
        for (unsigned k = 0; k < 3; ++k) {
            const rt::TessVertex& a = o.vertices[o.indices[t + k]];
            const rt::TessVertex& b = o.vertices[o.indices[t + (k + 1) % 3]];
            const rt::Vec3 pa{a.position[0], a.position[1], a.position[2]};
            const rt::Vec3 pb{b.position[0], b.position[1], b.position[2]};
            if (std::memcmp(a.position, b.position, 12) == 0) degenerate = true;
            l = std::max(l, static_cast<double>(rt::edge_tess_factor(pa, pb, dice.eye, dice.factor_scale())));
        }
        if (!degenerate) longest.push_back(l);
    }
    std::sort(longest.begin(), longest.end());
    auto at = [&](double q) {
        return longest[static_cast<std::size_t>(q * static_cast<double>(longest.size() - 1))];
    };
    return {at(0.5), at(0.99), longest.back()};
}

} // namespace pipeline_fixtures
