// Exact integer checks on a tessellation of the unit domain triangle, for any algorithm (CP, D3D11).
//
// Positions are ctess::DomainPoint {u, v} in units of `one`: the point v0 + u(v1-v0) + v(v2-v0). The domain
// triangle is (0,0), (one,0), (0,one); its boundary loop runs e0 = v0->v1 (v = 0), e1 = v1->v2 (u + v = one,
// parameter s = v from v1) and e2 = v0->v2 (u = 0, walked back from v2 to v0). Coordinates are below 2^25, so
// doubled areas fit in int64 and their sum in int128.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <ctess/core/domain_point.hpp>

namespace ctess::test {

__extension__ using int128 = __int128;

// Joins text and numbers (appending avoids g++ 12's false -Wrestrict on "literal" + std::string at -O3).
namespace detail {
inline void append_text(std::string& s, const std::string& part) {
    s += part;
}
inline void append_text(std::string& s, const char* part) {
    s += part;
}
template <class Number>
requires std::is_arithmetic_v<Number>
void append_text(std::string& s, Number part) {
    s += std::to_string(part);
}
} // namespace detail
template <class... Parts>
std::string cat(const Parts&... parts) {
    std::string s;
    (detail::append_text(s, parts), ...);
    return s;
}

// Twice the signed area, positive for counter-clockwise (u, v).
template <class Unit>
constexpr std::int64_t signed_area2(FixedPoint<Unit> a, FixedPoint<Unit> b, FixedPoint<Unit> c) {
    const std::int64_t bu = std::int64_t{b.u} - a.u, bv = std::int64_t{b.v} - a.v;
    const std::int64_t cu = std::int64_t{c.u} - a.u, cv = std::int64_t{c.v} - a.v;
    return bu * cv - bv * cu;
}

// One position as a sortable key (u high, v low).
template <class Unit>
constexpr std::uint64_t position_key(FixedPoint<Unit> p) {
    return (std::uint64_t{p.u} << 32) | p.v;
}

// A triangle as three exact positions, in emitted (winding) order.
using PositionTriangle = std::array<DomainPoint, 3>;

// Rotates the triangle (keeping the winding) so that its smallest position comes first.
constexpr PositionTriangle canonical_rotation(PositionTriangle t) {
    std::size_t first = 0;
    for (std::size_t i = 1; i < 3; ++i)
        if (position_key(t[i]) < position_key(t[first])) first = i;
    return {t[first], t[(first + 1) % 3], t[(first + 2) % 3]};
}

constexpr bool position_triangle_less(const PositionTriangle& a, const PositionTriangle& b) {
    for (std::size_t i = 0; i < 3; ++i)
        if (position_key(a[i]) != position_key(b[i])) return position_key(a[i]) < position_key(b[i]);
    return false;
}

// The checks work in any unit (`one` is their argument) on (u, v) pairs carried as DomainPoint; points of
// another FixedPoint type enter through check_points, which copies their coordinates unchanged.
template <class Unit>
std::vector<DomainPoint> check_points(std::span<const FixedPoint<Unit>> points) {
    std::vector<DomainPoint> out(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) out[i] = {points[i].u, points[i].v};
    return out;
}
template <class Unit>
std::vector<DomainPoint> check_points(const std::vector<FixedPoint<Unit>>& points) {
    return check_points(std::span<const FixedPoint<Unit>>(points));
}
template <class Unit>
DomainPoint check_point(FixedPoint<Unit> p) {
    return {p.u, p.v};
}

struct MeshView {
    std::span<const DomainPoint> vertices;
    std::span<const std::uint32_t> indices; // 3 per triangle
    std::size_t triangle_count() const { return indices.size() / 3; }
    PositionTriangle triangle(std::size_t t) const {
        return {vertices[indices[3 * t]], vertices[indices[3 * t + 1]], vertices[indices[3 * t + 2]]};
    }
};

// Every index refers to a vertex, and every vertex is referenced.
inline bool indices_in_range(const MeshView& m) {
    return std::all_of(m.indices.begin(), m.indices.end(),
                       [&](std::uint32_t i) { return i < m.vertices.size(); });
}
inline std::size_t unreferenced_vertex_count(const MeshView& m) {
    std::vector<char> used(m.vertices.size(), 0);
    for (std::uint32_t i : m.indices)
        if (i < used.size()) used[i] = 1;
    return static_cast<std::size_t>(std::count(used.begin(), used.end(), 0));
}

// Every vertex lies in the closed domain triangle.
inline bool vertices_in_domain(const MeshView& m, std::uint32_t one) {
    return std::all_of(m.vertices.begin(), m.vertices.end(),
                       [&](DomainPoint p) { return std::uint64_t{p.u} + p.v <= one; });
}

struct AreaStats {
    std::size_t triangles = 0;
    std::size_t inverted = 0;   // negative area
    std::size_t degenerate = 0; // zero area
    std::size_t fins = 0;       // zero area with three distinct positions: a T-junction in disguise
    int128 area2_sum = 0;
    // Exact tiling of the unit domain triangle: the doubled areas sum to one^2.
    bool covers(std::uint32_t one) const { return area2_sum == int128{one} * one; }
};

inline AreaStats area_stats(const MeshView& m) {
    AreaStats s;
    s.triangles = m.triangle_count();
    for (std::size_t t = 0; t < s.triangles; ++t) {
        const PositionTriangle p = m.triangle(t);
        const std::int64_t a2 = signed_area2(p[0], p[1], p[2]);
        s.area2_sum += a2;
        if (a2 < 0) ++s.inverted;
        if (a2 == 0) {
            ++s.degenerate;
            if (!(p[0] == p[1]) && !(p[1] == p[2]) && !(p[0] == p[2])) ++s.fins;
        }
    }
    return s;
}

// The multiset of non-degenerate triangles as canonically rotated position triples, sorted. Two meshes with
// equal multisets describe the same piecewise-linear surface: this is the exact pop comparison.
inline std::vector<PositionTriangle> surface_triangles(const MeshView& m) {
    std::vector<PositionTriangle> out;
    out.reserve(m.triangle_count());
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
        const PositionTriangle p = m.triangle(t);
        if (signed_area2(p[0], p[1], p[2]) != 0) out.push_back(canonical_rotation(p));
    }
    std::sort(out.begin(), out.end(), position_triangle_less);
    return out;
}

// Every triangle, degenerate ones included (e.g. to compare two index layouts of the same mesh).
inline std::vector<PositionTriangle> all_triangles(const MeshView& m) {
    std::vector<PositionTriangle> out(m.triangle_count());
    for (std::size_t t = 0; t < out.size(); ++t) out[t] = canonical_rotation(m.triangle(t));
    std::sort(out.begin(), out.end(), position_triangle_less);
    return out;
}

using DirectedEdge = std::pair<std::uint64_t, std::uint64_t>; // position keys, from -> to

// The boundary loop of the domain as directed position edges between consecutive distinct points. Each list
// holds an edge's parameters (units of one, sorted, endpoints included): e0 and e2 from v0, e1 from v1.
inline std::vector<DirectedEdge> boundary_loop_edges(std::span<const std::uint32_t> e0,
                                                     std::span<const std::uint32_t> e1,
                                                     std::span<const std::uint32_t> e2, std::uint32_t one) {
    std::vector<DirectedEdge> out;
    auto add_chain = [&](std::span<const std::uint32_t> params, auto to_point, bool reversed) {
        std::vector<std::uint64_t> keys;
        for (std::uint32_t p : params) keys.push_back(position_key(to_point(p)));
        if (reversed) std::reverse(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
        for (std::size_t i = 0; i + 1 < keys.size(); ++i) out.emplace_back(keys[i], keys[i + 1]);
    };
    add_chain(
        e0,
        [](std::uint32_t p) {
            return DomainPoint{p, 0};
        },
        false);
    add_chain(
        e1,
        [one](std::uint32_t s) {
            return DomainPoint{one - s, s};
        },
        false);
    add_chain(
        e2,
        [](std::uint32_t p) {
            return DomainPoint{0, p};
        },
        true);
    std::sort(out.begin(), out.end());
    return out;
}

// Conformity of the non-degenerate triangles on exact positions: each directed edge is used at most once,
// every edge used in one direction only is a boundary-loop edge and every boundary-loop edge is used, and the
// Euler characteristic V - E + F of the non-degenerate triangles is 1 (a disk). Zero-area triangles are left
// out: with no fins they all have two coincident corners, so their edges cancel among themselves.
struct SurfaceTopology {
    bool edges_unique = true;     // no directed position edge used twice
    bool boundary_matches = true; // unpaired edges == the boundary loop
    long long euler = 0;
    std::size_t unpaired = 0;
    std::size_t expected_boundary = 0;
};

// Directed edges over dense ids [0, id_count): whether each is used once, how many have their reverse, and
// the ones that do not (sorted). Linear time: adjacency lists by source, each sorted (they are short).
using IdEdge = std::pair<std::uint32_t, std::uint32_t>;
struct EdgeCensus {
    bool unique = true;
    std::size_t paired = 0;
    std::vector<IdEdge> unpaired;
};

inline EdgeCensus edge_census(std::size_t id_count, std::span<const IdEdge> edges) {
    std::vector<std::uint32_t> first(id_count + 1, 0);
    for (const IdEdge& e : edges) ++first[e.first + 1];
    for (std::size_t i = 0; i < id_count; ++i) first[i + 1] += first[i];
    std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
    std::vector<std::uint32_t> targets(edges.size());
    for (const IdEdge& e : edges) targets[next[e.first]++] = e.second;
    EdgeCensus r;
    for (std::size_t i = 0; i < id_count; ++i) {
        const auto b = targets.begin() + first[i], e = targets.begin() + first[i + 1];
        std::sort(b, e);
        if (std::adjacent_find(b, e) != e) r.unique = false;
    }
    for (const IdEdge& e : edges) {
        const auto b = targets.begin() + first[e.second], end = targets.begin() + first[e.second + 1];
        if (std::binary_search(b, end, e.first))
            ++r.paired;
        else
            r.unpaired.push_back(e);
    }
    std::sort(r.unpaired.begin(), r.unpaired.end());
    return r;
}

// Dense ids of the distinct positions: id_of_vertex[i] is vertex i's id, keys[id] its position key (sorted).
struct Weld {
    std::vector<std::uint32_t> id_of_vertex;
    std::vector<std::uint64_t> keys;
};

inline Weld weld_positions(std::span<const DomainPoint> vertices) {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> order(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i)
        order[i] = {position_key(vertices[i]), static_cast<std::uint32_t>(i)};
    std::sort(order.begin(), order.end());
    Weld w;
    w.id_of_vertex.resize(vertices.size());
    for (const auto& [key, index] : order) {
        if (w.keys.empty() || w.keys.back() != key) w.keys.push_back(key);
        w.id_of_vertex[index] = static_cast<std::uint32_t>(w.keys.size() - 1);
    }
    return w;
}

inline SurfaceTopology surface_topology(const MeshView& m, std::span<const DirectedEdge> boundary) {
    if (!indices_in_range(m)) return {false, false, 0, 0, boundary.size()};
    const Weld w = weld_positions(m.vertices);
    std::vector<IdEdge> edges;
    edges.reserve(m.indices.size());
    std::vector<char> used(w.keys.size(), 0);
    std::size_t faces = 0;
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
        const PositionTriangle p = m.triangle(t);
        if (signed_area2(p[0], p[1], p[2]) == 0) continue;
        ++faces;
        for (std::size_t i = 0; i < 3; ++i) {
            const std::uint32_t a = w.id_of_vertex[m.indices[3 * t + i]];
            edges.emplace_back(a, w.id_of_vertex[m.indices[3 * t + (i + 1) % 3]]);
            used[a] = 1;
        }
    }
    const EdgeCensus c = edge_census(w.keys.size(), edges);
    std::vector<DirectedEdge> open;
    for (const IdEdge& e : c.unpaired) open.emplace_back(w.keys[e.first], w.keys[e.second]);
    std::sort(open.begin(), open.end());

    SurfaceTopology r;
    r.edges_unique = c.unique;
    r.unpaired = open.size();
    r.expected_boundary = boundary.size();
    r.boundary_matches = std::equal(open.begin(), open.end(), boundary.begin(), boundary.end());
    const auto undirected = static_cast<long long>(c.paired / 2 + open.size());
    const auto vertices = static_cast<long long>(std::count(used.begin(), used.end(), 1));
    r.euler = vertices - undirected + static_cast<long long>(faces);
    return r;
}

// The index mesh itself (degenerate triangles included) is a topological disk: no triangle repeats an index,
// each directed index edge is used at most once, the edges used in one direction only form one closed loop,
// and V - E + F = 1 over the referenced vertices. Only meaningful for layouts with one vertex per mesh
// vertex.
struct IndexTopology {
    bool no_repeated_index = true;
    bool edges_unique = true;
    bool single_boundary_loop = true;
    long long euler = 0;
};

inline IndexTopology index_topology(const MeshView& m) {
    IndexTopology r;
    if (!indices_in_range(m)) return {false, false, false, 0};
    std::vector<IdEdge> edges;
    edges.reserve(m.indices.size());
    std::vector<char> used(m.vertices.size(), 0);
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
        const std::uint32_t* i = &m.indices[3 * t];
        if (i[0] == i[1] || i[1] == i[2] || i[0] == i[2]) r.no_repeated_index = false;
        for (std::size_t k = 0; k < 3; ++k) {
            edges.emplace_back(i[k], i[(k + 1) % 3]);
            used[i[k]] = 1;
        }
    }
    const EdgeCensus c = edge_census(m.vertices.size(), edges);
    r.edges_unique = c.unique;
    const std::vector<IdEdge>& boundary = c.unpaired; // sorted by source
    // One closed loop: every boundary vertex has exactly one outgoing boundary edge, and walking from the
    // first edge returns to it after visiting all of them.
    r.single_boundary_loop = !boundary.empty();
    for (std::size_t k = 1; k < boundary.size(); ++k)
        if (boundary[k].first == boundary[k - 1].first) r.single_boundary_loop = false;
    if (r.single_boundary_loop) {
        std::size_t steps = 0;
        std::uint32_t at = boundary.front().first;
        do {
            auto it = std::lower_bound(boundary.begin(), boundary.end(), IdEdge{at, 0});
            if (it == boundary.end() || it->first != at) {
                r.single_boundary_loop = false;
                break;
            }
            at = it->second;
            ++steps;
        } while (at != boundary.front().first && steps <= boundary.size());
        if (steps != boundary.size()) r.single_boundary_loop = false;
    }
    const auto undirected = static_cast<long long>(c.paired / 2 + boundary.size());
    const auto vertices = static_cast<long long>(std::count(used.begin(), used.end(), 1));
    r.euler = vertices - undirected + static_cast<long long>(m.triangle_count());
    return r;
}

// Distinct parameters of the vertices lying on each domain edge: e0 (v = 0) by u, e1 (u + v = one) by s = v,
// and e2 (u = 0) by v. Sorted. Compare with the distinct line points of each edge.
struct EdgeVertexParams {
    std::vector<std::uint32_t> e0, e1, e2;
};

inline EdgeVertexParams edge_vertex_params(const MeshView& m, std::uint32_t one) {
    EdgeVertexParams r;
    for (DomainPoint p : m.vertices) {
        if (p.v == 0) r.e0.push_back(p.u);
        if (std::uint64_t{p.u} + p.v == one) r.e1.push_back(p.v);
        if (p.u == 0) r.e2.push_back(p.v);
    }
    for (auto* list : {&r.e0, &r.e1, &r.e2}) {
        std::sort(list->begin(), list->end());
        list->erase(std::unique(list->begin(), list->end()), list->end());
    }
    return r;
}

// The first index of every triangle is unique across the mesh (a flat-shading provoking vertex per triangle).
inline bool unique_first_index(const MeshView& m) {
    std::vector<char> seen(m.vertices.size(), 0);
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
        const std::uint32_t i = m.indices[3 * t];
        if (i >= seen.size() || seen[i] != 0) return false;
        seen[i] = 1;
    }
    return true;
}

// All checks that make a mesh a valid, watertight tessellation of the domain with the given edge parameters.
// failures is empty when valid, else a short description of every failed check; area holds the area counts.
struct ValidityReport {
    AreaStats area;
    std::string failures;
    bool ok() const { return failures.empty(); }
};

inline ValidityReport check_valid_tessellation(const MeshView& m, std::uint32_t one,
                                               std::span<const std::uint32_t> e0,
                                               std::span<const std::uint32_t> e1,
                                               std::span<const std::uint32_t> e2) {
    ValidityReport r;
    auto fail = [&](const std::string& what) { r.failures += cat(what, "; "); };
    if (m.indices.size() % 3 != 0) fail("index count not a multiple of 3");
    if (!indices_in_range(m)) {
        fail("index out of range");
        return r;
    }
    if (unreferenced_vertex_count(m) != 0) fail(cat("unreferenced vertices: ", unreferenced_vertex_count(m)));
    if (!vertices_in_domain(m, one)) fail("vertex outside the domain");
    r.area = area_stats(m);
    if (r.area.inverted != 0) fail(cat("inverted: ", r.area.inverted));
    if (r.area.fins != 0) fail(cat("fins: ", r.area.fins));
    if (!r.area.covers(one)) fail("coverage != 1/2");

    auto distinct = [](std::span<const std::uint32_t> p) {
        std::vector<std::uint32_t> d(p.begin(), p.end());
        std::sort(d.begin(), d.end());
        d.erase(std::unique(d.begin(), d.end()), d.end());
        return d;
    };
    const EdgeVertexParams on_edges = edge_vertex_params(m, one);
    if (on_edges.e0 != distinct(e0)) fail("e0 vertices != line points");
    if (on_edges.e1 != distinct(e1)) fail("e1 vertices != line points");
    if (on_edges.e2 != distinct(e2)) fail("e2 vertices != line points");

    const std::vector<DirectedEdge> loop = boundary_loop_edges(e0, e1, e2, one);
    const SurfaceTopology topo = surface_topology(m, loop);
    if (!topo.edges_unique) fail("a directed position edge is used twice");
    if (!topo.boundary_matches)
        fail(cat("open edges (", topo.unpaired, ") != boundary loop (", topo.expected_boundary, ")"));
    if (topo.euler != 1) fail(cat("Euler characteristic ", topo.euler));
    return r;
}

} // namespace ctess::test
