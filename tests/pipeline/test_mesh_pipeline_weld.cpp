// Quads in the mesh pipeline and its welded, indexed output (mesh_pipeline.hpp, docs/algorithm.md §7):
// the factor modes, clamp reporting, the quad rule's edge lengths, and the weld checked against an
// independent weld of the unwelded output (exact position and attribute bits) on closed and open models
// built here: a triangle torus, an all-quad torus, a mixed torus, an octahedron sphere, a torus with a uv
// seam and an open mixed grid.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <unordered_map>
#include <utility>
#include <vector>

#include <ctess/runtime/pipeline/mesh_pipeline.hpp>
#include <ctess/runtime/uniform/table_set.hpp>

using namespace ctess;

namespace {

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
Model torus(unsigned nu, unsigned nv, Faces faces, bool seam = false) {
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
Model octasphere(unsigned levels) {
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
Model open_grid(unsigned n) {
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

const rt::UniformTableSet& uniform_set() {
    return rt::uniform_tables;
}

Output unwelded(const rt::MeshView& mesh, const rt::PipelineOptions& options) {
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

Output welded(const rt::MeshView& mesh, const rt::PipelineOptions& options) {
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
Key key_of(const rt::TessVertex& v, bool attributes) {
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
std::vector<std::uint32_t> weld_ids(const std::vector<rt::TessVertex>& vertices, bool attributes) {
    std::unordered_map<Key, std::uint32_t, KeyHash> ids;
    std::vector<std::uint32_t> out(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i)
        out[i] = ids.emplace(key_of(vertices[i], attributes), static_cast<std::uint32_t>(ids.size()))
                     .first->second;
    return out;
}

// Triangles as key triples (rotated so the smallest key is first, winding kept), those with two equal keys
// (two coincident corners) left out, sorted.
std::vector<std::array<Key, 3>> key_triangles(const Output& o) {
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
EdgeCounts directed_edges(const std::vector<std::uint32_t>& indices, const std::vector<std::uint32_t>& id) {
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

std::uint64_t reversed(std::uint64_t e) {
    return e >> 32 | e << 32;
}

std::vector<std::uint32_t> identity(std::size_t n) {
    std::vector<std::uint32_t> id(n);
    for (std::size_t i = 0; i < n; ++i) id[i] = static_cast<std::uint32_t>(i);
    return id;
}

// Closed and 2-manifold, consistently oriented: every directed edge once, and its reverse once.
bool closed_manifold(const EdgeCounts& edges) {
    for (std::size_t i = 0; i < edges.size(); ++i) {
        if (i > 0 && edges[i] == edges[i - 1]) return false;
        if (!std::binary_search(edges.begin(), edges.end(), reversed(edges[i]))) return false;
    }
    return true;
}

// Boundary edges (directed edges without a reverse); false when an edge is used more than once.
bool boundary(const EdgeCounts& edges, std::vector<std::pair<std::uint32_t, std::uint32_t>>& out) {
    for (std::size_t i = 0; i < edges.size(); ++i) {
        if (i > 0 && edges[i] == edges[i - 1]) return false;
        if (!std::binary_search(edges.begin(), edges.end(), reversed(edges[i])))
            out.emplace_back(static_cast<std::uint32_t>(edges[i] >> 32),
                             static_cast<std::uint32_t>(edges[i]));
    }
    return true;
}

// The input mesh's boundary edges (directed, as the faces list them).
std::vector<std::pair<std::uint32_t, std::uint32_t>> input_boundary(const Model& m) {
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
void check_boundary_subdivided(const Model& m, const Output& w) {
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
void check_weld_matches(const rt::MeshView& mesh, const rt::PipelineOptions& options, const Output& u,
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

rt::PipelineOptions camera(rt::Pattern pattern, rt::Vec3 eye, float dice_rate,
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
std::array<double, 3> longest_edge_stats(const Output& o, const rt::DiceOptions& dice) {
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

} // namespace

TEST_CASE("factor modes (docs/algorithm.md §7.1): constant, edge length / L and camera, per edge") {
    Model m;
    m.add(0, 0, 0, 0, 0, 1, 0, 0);
    m.add(3, 0, 0, 0, 0, 1, 1, 0);
    m.add(3, 4, 0, 0, 0, 1, 1, 1);
    m.triangles = {0, 1, 2};
    const rt::MeshView mesh = m.view();
    rt::PipelineOptions o;
    o.dice.mode = rt::FactorMode::constant;
    o.dice.constant_factor = 7.5f;
    rt::PatchRecord rec = rt::setup_patch(rt::cp_tables_64, mesh, 0, o);
    CHECK(rec.factor[0] == 7.5f);
    CHECK(rec.factor[1] == 7.5f);
    CHECK(rec.factor[2] == 7.5f);
    // Edge lengths 3, 4 and 5, L = 0.5: factors 6, 8 and 10 exactly.
    o.dice.mode = rt::FactorMode::edge_length;
    o.dice.target_edge_length = 0.5f;
    rec = rt::setup_patch(rt::cp_tables_64, mesh, 0, o);
    CHECK(rec.factor[0] == 6.0f);
    CHECK(rec.factor[1] == 8.0f);
    CHECK(rec.factor[2] == 10.0f);
    // Bad targets: 0 gives +inf (clamped to max), NaN gives NaN (factor 1); both run.
    o.dice.target_edge_length = 0.0f;
    CHECK(std::isinf(rt::setup_patch(rt::cp_tables_64, mesh, 0, o).factor[0]));
    o.dice.target_edge_length = std::nanf("");
    CHECK(std::isnan(rt::setup_patch(rt::cp_tables_64, mesh, 0, o).factor[0]));
    // A mode outside the enum gives NaN (factor 1), never UB.
    o.dice.mode = static_cast<rt::FactorMode>(9);
    CHECK(std::isnan(rt::setup_patch(rt::cp_tables_64, mesh, 0, o).factor[0]));
    // The camera mode is the default and keeps its formula: 3 * 1000 / 2 / distance 10 at the midpoint.
    rt::PipelineOptions c;
    c.dice.eye = {1.5f, 0.0f, 10.0f};
    c.dice.projection_scale = 1000.0f;
    c.dice.dice_rate = 2.0f;
    CHECK(rt::setup_patch(rt::cp_tables_64, mesh, 0, c).factor[0] == Approx(150.0f));
}

TEST_CASE("clamped factors are reported (PipelineTotals::clamped_edges), once per patch edge") {
    const Model m = torus(8, 4, Faces::mixed);
    const rt::MeshView mesh = m.view();
    const std::uint32_t patch_edges = 3 * mesh.triangle_count + 4 * mesh.quad_count;
    rt::PipelineOptions o;
    o.dice.mode = rt::FactorMode::constant;
    o.dice.constant_factor = 64.0f; // the CP tables' max: not a clamp
    CHECK(unwelded(mesh, o).clamped_edges == 0);
    o.dice.constant_factor = 64.5f;
    CHECK(unwelded(mesh, o).clamped_edges == patch_edges);
    CHECK(welded(mesh, o).clamped_edges == patch_edges);
    // Uniform: N + 0.4 rounds to N (no clamp), N + 0.6 to N + 1 (clamped); a uniform quad's diagonal counts.
    const auto n = static_cast<float>(uniform_set().max_factor);
    o.pattern = rt::Pattern::uniform;
    o.dice.constant_factor = n + 0.4f;
    CHECK(unwelded(mesh, o).clamped_edges == 0);
    o.dice.constant_factor = n + 0.6f;
    CHECK(unwelded(mesh, o).clamped_edges == patch_edges + mesh.quad_count);
    CHECK(welded(mesh, o).clamped_edges == patch_edges + mesh.quad_count);
}

TEST_CASE("quad records (§7.3): kind word, 192 bytes, counts of both halves, bad input") {
    STATIC_REQUIRE(sizeof(rt::PatchRecord) == 192);
    const Model m = torus(6, 4, Faces::mixed);
    const rt::MeshView mesh = m.view();
    rt::PipelineOptions o;
    o.dice.mode = rt::FactorMode::constant;
    o.dice.constant_factor = 5.0f;
    std::vector<rt::PatchRecord> rec(mesh.patch_count());
    rt::PipelineTotals totals;
    REQUIRE(rt::setup_patches(rt::cp_tables_64, mesh, o, rec, totals) == rt::PipelineStatus::ok);
    for (std::uint32_t p = 0; p < rec.size(); ++p) {
        CHECK(rec[p].kind == (p < mesh.triangle_count ? rt::patch_kind_triangle : rt::patch_kind_quad));
        if (p >= mesh.triangle_count) {
            // Two CP halves of (5, 5, 5): each the (5, 5, 5) triangle's counts.
            const Counts half = rt::CpPatch(rt::cp_tables_64, 5.0f, 5.0f, 5.0f).counts();
            CHECK(rec[p].vertex_count == 2 * half.vertices);
            CHECK(rec[p].triangle_count == 2 * half.triangles);
        }
    }
    // A tampered quad record is refused, and nothing is written.
    std::vector<rt::TessVertex> v(totals.vertices);
    std::vector<std::uint32_t> idx(3 * std::size_t{totals.triangles}, 77u);
    auto bad = rec;
    bad.back().rotation = 4;
    CHECK(rt::emit_mesh(rt::cp_tables_64, mesh, o, bad, v, idx) == rt::PipelineStatus::bad_patch_record);
    bad = rec;
    bad.back().setup[rt::quad_setup_word::b_token] += 1;
    CHECK(rt::emit_mesh(rt::cp_tables_64, mesh, o, bad, v, idx) == rt::PipelineStatus::bad_patch_record);
    CHECK(std::all_of(idx.begin(), idx.end(), [](std::uint32_t i) { return i == 77u; }));
    // A surface value outside the enum is refused.
    rt::PipelineOptions bad_surface = o;
    bad_surface.surface.surface = static_cast<rt::Surface>(9);
    CHECK(rt::setup_patches(rt::cp_tables_64, mesh, bad_surface, rec, totals) ==
          rt::PipelineStatus::bad_option);
    rt::PipelineOptions rule = o;
    rule.quad_rule = static_cast<rt::QuadRule>(7);
    CHECK(rt::setup_patches(rt::cp_tables_64, mesh, rule, rec, totals) == rt::PipelineStatus::bad_option);
    // A quad with an index past the vertices is culled; the rest is unchanged.
    Model culled = m;
    culled.quads[1] = 100000;
    const rt::MeshView cm = culled.view();
    REQUIRE(rt::setup_patches(rt::cp_tables_64, cm, o, rec, totals) == rt::PipelineStatus::ok);
    CHECK(rec[mesh.triangle_count].vertex_count == 0);
    CHECK(rec[mesh.triangle_count].triangle_count == 0);
    const Output w = welded(cm, o);
    CHECK(w.status == rt::PipelineStatus::ok);
}

TEST_CASE("quads and triangles are watertight where they meet (§7.3): exact bits on shared edges") {
    // The unwelded output welded by position bits alone is closed and 2-manifold: every shared edge's points
    // are the same bits on both sides, triangle or quad, CP or uniform.
    // Every surface: quads evaluate their edges by evaluate_surface's own edge rule (§6.2, §7.3).
    for (const rt::Pattern pattern : {rt::Pattern::cp, rt::Pattern::uniform}) {
        for (const Faces faces : {Faces::quads, Faces::mixed}) {
            for (const rt::Surface surface :
                 {rt::Surface::flat, rt::Surface::pn_triangles, rt::Surface::phong, rt::Surface::pn_aen}) {
                const Model m = torus(12, 5, faces);
                rt::PipelineOptions o = camera(pattern, {0.5f, -9.0f, 3.0f}, 2.0f, 250.0f);
                o.surface.surface = surface;
                const Output u = unwelded(m.view(), o);
                REQUIRE(u.status == rt::PipelineStatus::ok);
                INFO("surface " << static_cast<int>(surface));
                CHECK(closed_manifold(directed_edges(u.indices, weld_ids(u.vertices, false))));
            }
        }
    }
}

TEST_CASE("quad rule (§7.2): q0q1 on the longer pair bounds the longest output edge") {
    // An all-quad torus whose quads list the short pair first (the user's case). Longest output edge per
    // triangle in DiceRate units: with the rule the p99 stays near the triangles' (below 2.5); as labelled
    // it does not.
    const Model m = torus(48, 6, Faces::quads);
    for (const rt::Pattern pattern : {rt::Pattern::cp}) {
        rt::PipelineOptions o = camera(pattern, {0.5f, -9.0f, 3.0f}, 2.0f);
        const auto rule = longest_edge_stats(unwelded(m.view(), o), o.dice);
        o.quad_rule = rt::QuadRule::as_labelled;
        const auto labelled = longest_edge_stats(unwelded(m.view(), o), o.dice);
        CHECK(rule[1] < 2.5);
        CHECK(labelled[1] > 2.0 * rule[1]);
    }
    // The rule is the quad's own data: any cyclic relabelling of the quads gives the same output bits.
    Model turned = m;
    for (std::size_t q = 0; q < turned.quads.size(); q += 4)
        std::rotate(turned.quads.begin() + static_cast<std::ptrdiff_t>(q),
                    turned.quads.begin() + static_cast<std::ptrdiff_t>(q + 1),
                    turned.quads.begin() + static_cast<std::ptrdiff_t>(q + 4));
    const rt::PipelineOptions o = camera(rt::Pattern::cp, {0.5f, -9.0f, 3.0f}, 2.0f, 250.0f);
    CHECK(key_triangles(unwelded(m.view(), o)) == key_triangles(unwelded(turned.view(), o)));
}

TEST_CASE("welded output (§7.4): equals the unwelded output welded by bits, closed models stay closed") {
    const std::vector<std::pair<const char*, Model>> models = {
        {"triangle torus", torus(8, 4, Faces::triangles)},
        {"quad torus", torus(8, 4, Faces::quads)},
        {"mixed torus", torus(8, 4, Faces::mixed)},
        {"octasphere", octasphere(1)},
    };
    std::mt19937 rng(19);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (const auto& [name, m] : models) {
        for (const rt::Pattern pattern : {rt::Pattern::cp, rt::Pattern::uniform}) {
            for (int trial = 0; trial < 6; ++trial) {
                rt::PipelineOptions o =
                    camera(pattern, {8.0f * unit(rng) - 4.0f, -6.0f - 6.0f * unit(rng), 4.0f * unit(rng)},
                           0.5f + 6.0f * unit(rng));
                if (trial % 3 == 1) {
                    o.dice.mode = rt::FactorMode::constant;
                    o.dice.constant_factor = 1.0f + 8.0f * unit(rng);
                } else if (trial % 3 == 2) {
                    o.dice.mode = rt::FactorMode::edge_length;
                    o.dice.target_edge_length = 0.3f + 0.6f * unit(rng);
                }
                o.weld.keep_degenerate = trial % 4 == 3;
                INFO(name << " pattern " << static_cast<int>(pattern) << " trial " << trial);
                const rt::MeshView mesh = m.view();
                const Output u = unwelded(mesh, o), w = welded(mesh, o);
                check_weld_matches(mesh, o, u, w);
                CHECK(closed_manifold(directed_edges(w.indices, identity(w.vertices.size()))));
            }
        }
    }
}

TEST_CASE("welded output: a uv seam keeps its own vertices; open boundaries are the input's, subdivided") {
    for (const rt::Pattern pattern : {rt::Pattern::cp, rt::Pattern::uniform}) {
        for (const Faces faces : {Faces::triangles, Faces::quads, Faces::mixed}) {
            const Model m = torus(8, 4, faces, true);
            const rt::PipelineOptions o = camera(pattern, {0.5f, -9.0f, 3.0f}, 2.0f, 250.0f);
            const Output u = unwelded(m.view(), o), w = welded(m.view(), o);
            check_weld_matches(m.view(), o, u, w);
            // By index the seam is a boundary (as in the input), subdivided; by position it is closed.
            check_boundary_subdivided(m, w);
            CHECK(closed_manifold(directed_edges(w.indices, weld_ids(w.vertices, false))));
        }
        const Model g = open_grid(6);
        const rt::PipelineOptions o = camera(pattern, {1.0f, 0.5f, 4.0f}, 3.0f);
        const Output u = unwelded(g.view(), o), w = welded(g.view(), o);
        check_weld_matches(g.view(), o, u, w);
        check_boundary_subdivided(g, w);
    }
}

TEST_CASE("welded output: degenerate triangles are dropped unless kept; spans and tampered tables refused") {
    const Model m = torus(12, 5, Faces::mixed);
    const rt::MeshView mesh = m.view();
    rt::PipelineOptions o = camera(rt::Pattern::cp, {0.5f, -9.0f, 3.0f}, 2.0f);
    o.dice.mode = rt::FactorMode::constant;
    o.dice.constant_factor = 2.0f; // CP lines at f = 2 have a zero-length middle segment (§1.2)
    const Output drop = welded(mesh, o);
    o.weld.keep_degenerate = true;
    const Output keep = welded(mesh, o);
    REQUIRE(drop.status == rt::PipelineStatus::ok);
    REQUIRE(keep.status == rt::PipelineStatus::ok);
    // Kept: exactly the unwelded triangle count (the shared layout has the provoking layout's triangles).
    CHECK(keep.indices.size() == unwelded(mesh, o).indices.size());
    CHECK(drop.indices.size() < keep.indices.size());
    CHECK(drop.vertices.size() == keep.vertices.size());

    std::vector<rt::WeldedEdge> edges(rt::weld_edge_capacity(mesh));
    std::vector<rt::WeldedPatch> patches(mesh.patch_count());
    rt::WeldedTotals totals{1, 2, 3, 4};
    std::vector<rt::WeldedEdge> short_edges(edges.size() - 1);
    CHECK(rt::setup_welded(rt::cp_tables_64, mesh, o, short_edges, patches, totals) ==
          rt::PipelineStatus::span_too_small);
    CHECK(totals.vertices == 1);
    REQUIRE(rt::setup_welded(rt::cp_tables_64, mesh, o, edges, patches, totals) == rt::PipelineStatus::ok);
    edges.resize(totals.edges);
    std::vector<rt::TessVertex> v(totals.vertices);
    std::vector<std::uint32_t> idx(3 * std::size_t{totals.triangles}, 77u);
    std::vector<std::uint32_t> short_idx(idx.size() - 1);
    CHECK(rt::emit_welded_mesh(rt::cp_tables_64, mesh, o, edges, patches, v, short_idx) ==
          rt::PipelineStatus::span_too_small);
    auto bad_edges = edges;
    bad_edges[3].vertex_count += 1;
    CHECK(rt::emit_welded_mesh(rt::cp_tables_64, mesh, o, bad_edges, patches, v, idx) ==
          rt::PipelineStatus::bad_patch_record);
    bad_edges = edges;
    std::swap(bad_edges[1], bad_edges[2]);
    CHECK(rt::emit_welded_mesh(rt::cp_tables_64, mesh, o, bad_edges, patches, v, idx) ==
          rt::PipelineStatus::bad_patch_record);
    CHECK(rt::emit_welded_mesh(rt::cp_tables_64, mesh, o, std::span(edges).first(edges.size() - 1), patches,
                               v, idx) == rt::PipelineStatus::bad_patch_record);
    auto bad_patches = patches;
    bad_patches[5].triangle_count += 1;
    CHECK(rt::emit_welded_mesh(rt::cp_tables_64, mesh, o, edges, bad_patches, v, idx) ==
          rt::PipelineStatus::bad_patch_record);
    CHECK(std::all_of(idx.begin(), idx.end(), [](std::uint32_t i) { return i == 77u; }));
    CHECK(rt::emit_welded_mesh(rt::cp_tables_64, mesh, o, edges, patches, v, idx) == rt::PipelineStatus::ok);
}

// Figures for docs/algorithm.md §7 (run by hand: test_mesh_pipeline_weld "[figures]").
TEST_CASE("figures: longest output edge, zero-area fraction, weld ratio", "[.][figures]") {
    const rt::Vec3 eye{0.5f, -9.0f, 3.0f};
    const Model quads = torus(48, 6, Faces::quads), tris = torus(48, 6, Faces::triangles);
    for (const rt::QuadRule rule : {rt::QuadRule::as_labelled, rt::QuadRule::longer_pair}) {
        rt::PipelineOptions o = camera(rt::Pattern::cp, eye, 2.0f);
        o.quad_rule = rule;
        const auto s = longest_edge_stats(unwelded(quads.view(), o), o.dice);
        std::printf("quad torus 48x6 CP, %s: longest edge p50 %.2f p99 %.2f max %.2f\n",
                    rule == rt::QuadRule::as_labelled ? "as labelled" : "longer pair", s[0], s[1], s[2]);
    }
    for (const rt::Pattern pattern : {rt::Pattern::cp, rt::Pattern::uniform}) {
        const char* name = pattern == rt::Pattern::cp ? "CP" : "uniform";
        rt::PipelineOptions o = camera(pattern, eye, 2.0f);
        const auto t = longest_edge_stats(unwelded(tris.view(), o), o.dice);
        const auto q = longest_edge_stats(unwelded(quads.view(), o), o.dice);
        std::printf("%s triangle torus: p50 %.2f p99 %.2f max %.2f; quad torus: p50 %.2f p99 %.2f max %.2f\n",
                    name, t[0], t[1], t[2], q[0], q[1], q[2]);
        for (const auto* m : {&tris, &quads}) {
            const Output u = unwelded(m->view(), o), w = welded(m->view(), o);
            std::size_t coincident = 0, zero_area = 0;
            for (std::size_t i = 0; i < u.indices.size(); i += 3) {
                const rt::TessVertex& a = u.vertices[u.indices[i]];
                const rt::TessVertex& b = u.vertices[u.indices[i + 1]];
                const rt::TessVertex& c = u.vertices[u.indices[i + 2]];
                const bool co = !std::memcmp(a.position, b.position, 12) ||
                                !std::memcmp(b.position, c.position, 12) ||
                                !std::memcmp(a.position, c.position, 12);
                const double e1[3] = {double(b.position[0]) - a.position[0],
                                      double(b.position[1]) - a.position[1],
                                      double(b.position[2]) - a.position[2]};
                const double e2[3] = {double(c.position[0]) - a.position[0],
                                      double(c.position[1]) - a.position[1],
                                      double(c.position[2]) - a.position[2]};
                const double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2],
                             cz = e1[0] * e2[1] - e1[1] * e2[0];
                coincident += co;
                zero_area += (cx * cx + cy * cy + cz * cz) < 1e-20;
            }
            const double n = static_cast<double>(u.indices.size() / 3);
            std::printf(
                "  %s %s: %zu triangles, %zu (%.2f%%) with coincident corners, %.2f%% zero area; welded %zu "
                "triangles; vertices %zu unwelded / %zu welded = %.2f\n",
                name, m == &tris ? "triangle torus" : "quad torus", u.indices.size() / 3, coincident,
                100.0 * static_cast<double>(coincident) / n, 100.0 * static_cast<double>(zero_area) / n,
                w.indices.size() / 3, u.vertices.size(), w.vertices.size(),
                static_cast<double>(u.vertices.size()) / static_cast<double>(w.vertices.size()));
        }
    }
}
