#include <ctess/analysis/mesh_checks.hpp>

#include <algorithm>

namespace ctess::analysis {

bool indices_in_range(const MeshView& m) {
    return std::all_of(m.indices.begin(), m.indices.end(),
                       [&](std::uint32_t i) { return i < m.vertices.size(); });
}

std::size_t unreferenced_vertex_count(const MeshView& m) {
    std::vector<char> used(m.vertices.size(), 0);
    for (std::uint32_t i : m.indices)
        if (i < used.size()) used[i] = 1;
    return static_cast<std::size_t>(std::count(used.begin(), used.end(), 0));
}

bool vertices_in_domain(const MeshView& m, std::uint32_t one) {
    return std::all_of(m.vertices.begin(), m.vertices.end(),
                       [&](DomainPoint p) { return std::uint64_t{p.u} + p.v <= one; });
}

AreaStats area_stats(const MeshView& m) {
    AreaStats s;
    s.triangles = m.triangle_count();
    for (std::size_t t = 0; t < s.triangles; ++t) {
        const PositionTriangle p = m.triangle(t);
        const int128 a2 = signed_area2(p[0], p[1], p[2]);
        s.area2_sum += a2;
        if (a2 < 0) ++s.inverted;
        if (a2 == 0) {
            ++s.degenerate;
            if (!(p[0] == p[1]) && !(p[1] == p[2]) && !(p[0] == p[2])) ++s.fins;
        }
    }
    return s;
}

std::vector<PositionTriangle> surface_triangles(const MeshView& m) {
    std::vector<PositionTriangle> out;
    out.reserve(m.triangle_count());
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
        const PositionTriangle p = m.triangle(t);
        if (signed_area2(p[0], p[1], p[2]) != 0) out.push_back(canonical_rotation(p));
    }
    std::sort(out.begin(), out.end(), position_triangle_less);
    return out;
}

std::vector<PositionTriangle> all_triangles(const MeshView& m) {
    std::vector<PositionTriangle> out(m.triangle_count());
    for (std::size_t t = 0; t < out.size(); ++t) out[t] = canonical_rotation(m.triangle(t));
    std::sort(out.begin(), out.end(), position_triangle_less);
    return out;
}

std::vector<DirectedEdge> boundary_loop_edges(std::span<const std::uint32_t> e0,
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

EdgeCensus edge_census(std::size_t id_count, std::span<const IdEdge> edges) {
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

Weld weld_positions(std::span<const DomainPoint> vertices) {
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

SurfaceTopology surface_topology(const MeshView& m, std::span<const DirectedEdge> boundary) {
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

namespace {

// One closed loop: every boundary vertex has exactly one outgoing boundary edge, and walking from the first
// edge returns to it after visiting all of them. `boundary` is sorted by source.
bool is_single_loop(const std::vector<IdEdge>& boundary) {
    if (boundary.empty()) return false;
    for (std::size_t k = 1; k < boundary.size(); ++k)
        if (boundary[k].first == boundary[k - 1].first) return false;
    std::size_t steps = 0;
    std::uint32_t at = boundary.front().first;
    do {
        auto it = std::lower_bound(boundary.begin(), boundary.end(), IdEdge{at, 0});
        if (it == boundary.end() || it->first != at) return false;
        at = it->second;
        ++steps;
    } while (at != boundary.front().first && steps <= boundary.size());
    return steps == boundary.size();
}

} // namespace

IndexTopology index_topology(const MeshView& m) {
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
    r.single_boundary_loop = is_single_loop(c.unpaired);
    const auto undirected = static_cast<long long>(c.paired / 2 + c.unpaired.size());
    const auto vertices = static_cast<long long>(std::count(used.begin(), used.end(), 1));
    r.euler = vertices - undirected + static_cast<long long>(m.triangle_count());
    return r;
}

EdgeVertexParams edge_vertex_params(const MeshView& m, std::uint32_t one) {
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

bool unique_first_index(const MeshView& m) {
    std::vector<char> seen(m.vertices.size(), 0);
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
        const std::uint32_t i = m.indices[3 * t];
        if (i >= seen.size() || seen[i] != 0) return false;
        seen[i] = 1;
    }
    return true;
}

namespace {

std::vector<std::uint32_t> distinct(std::span<const std::uint32_t> p) {
    std::vector<std::uint32_t> d(p.begin(), p.end());
    std::sort(d.begin(), d.end());
    d.erase(std::unique(d.begin(), d.end()), d.end());
    return d;
}

// The failures of the domain's edges and of the position topology (check_valid_tessellation).
void check_boundary(const MeshView& m, std::uint32_t one, std::span<const std::uint32_t> e0,
                    std::span<const std::uint32_t> e1, std::span<const std::uint32_t> e2,
                    std::string& failures) {
    const EdgeVertexParams on_edges = edge_vertex_params(m, one);
    if (on_edges.e0 != distinct(e0)) failures += "e0 vertices != line points; ";
    if (on_edges.e1 != distinct(e1)) failures += "e1 vertices != line points; ";
    if (on_edges.e2 != distinct(e2)) failures += "e2 vertices != line points; ";

    const std::vector<DirectedEdge> loop = boundary_loop_edges(e0, e1, e2, one);
    const SurfaceTopology topo = surface_topology(m, loop);
    if (!topo.edges_unique) failures += "a directed position edge is used twice; ";
    if (!topo.boundary_matches) {
        failures += "open edges (";
        failures += std::to_string(topo.unpaired);
        failures += ") != boundary loop (";
        failures += std::to_string(topo.expected_boundary);
        failures += "); ";
    }
    if (topo.euler != 1) {
        failures += "Euler characteristic ";
        failures += std::to_string(topo.euler);
        failures += "; ";
    }
}

// Appends "what count; " (appending avoids g++ 12's false -Wrestrict on "literal" + std::string at -O3).
void fail_count(std::string& failures, const char* what, std::size_t count) {
    failures += what;
    failures += std::to_string(count);
    failures += "; ";
}

} // namespace

ValidityReport check_valid_tessellation(const MeshView& m, std::uint32_t one,
                                        std::span<const std::uint32_t> e0, std::span<const std::uint32_t> e1,
                                        std::span<const std::uint32_t> e2) {
    ValidityReport r;
    if (m.indices.size() % 3 != 0) r.failures += "index count not a multiple of 3; ";
    if (!indices_in_range(m)) {
        r.failures += "index out of range; ";
        return r;
    }
    if (unreferenced_vertex_count(m) != 0)
        fail_count(r.failures, "unreferenced vertices: ", unreferenced_vertex_count(m));
    if (!vertices_in_domain(m, one)) r.failures += "vertex outside the domain; ";
    r.area = area_stats(m);
    if (r.area.inverted != 0) fail_count(r.failures, "inverted: ", r.area.inverted);
    if (r.area.fins != 0) fail_count(r.failures, "fins: ", r.area.fins);
    if (!r.area.covers(one)) r.failures += "coverage != 1/2; ";
    check_boundary(m, one, e0, e1, e2, r.failures);
    return r;
}

} // namespace ctess::analysis
