// The provoking vertices of a uniform-density pattern (docs/algorithm.md §3.4): each triangle is rotated
// (winding kept) so that its first vertex is one no other triangle starts with, wherever a maximum matching
// of triangles to their vertices allows; the rest need a copy of their first vertex. A matching saturates the
// smaller side in every stored pattern, so a pattern needs max(T - V, 0) copies, the fewest possible (every
// triangle's first index is its own: V + copies >= T).
#pragma once
#include <array>
#include <cstdint>

#include <ctess/uniform/pattern.hpp>

namespace ctess::uniform {

// Upper bounds of one pattern (the largest stored pattern has 153 vertices and 256 triangles).
inline constexpr unsigned provoking_max_vertices = 256;
inline constexpr unsigned provoking_max_triangles = 512;

// The fewest copies a pattern can need: every triangle needs a first vertex of its own.
constexpr unsigned provoking_copy_bound(unsigned vertices, unsigned triangles) {
    return triangles > vertices ? triangles - vertices : 0u;
}

struct ProvokingChoice {
    // rotation[t]: the corner of the stored triangle t that goes first (0, 1 or 2).
    std::array<std::uint8_t, provoking_max_triangles> rotation{};
    // copied[t]: triangle t's first vertex also starts another triangle, so it gets a copy.
    std::array<bool, provoking_max_triangles> copied{};
    unsigned copies = 0;
};

namespace detail {

struct ProvokingMatching {
    std::array<std::array<std::uint8_t, 3>, provoking_max_triangles> tri{};
    std::array<int, provoking_max_vertices> owner{}; // the triangle that starts with vertex v, or -1
    std::array<unsigned, provoking_max_vertices> seen{};
    std::array<std::uint8_t, provoking_max_triangles> rotation{};
    unsigned stamp = 0;

    // Kuhn's augmenting path from triangle t (depth at most the vertex count).
    constexpr bool augment(unsigned t) {
        for (std::uint8_t k = 0; k < 3; ++k) {
            const unsigned v = tri[t][k];
            if (seen[v] == stamp) continue;
            seen[v] = stamp;
            if (owner[v] < 0 || augment(static_cast<unsigned>(owner[v]))) {
                owner[v] = static_cast<int>(t);
                rotation[t] = k;
                return true;
            }
        }
        return false;
    }
};

} // namespace detail

// A maximum matching of the pattern's triangles to their own first vertices: greedily in triangle order,
// each triangle's stored first corner first (most triangles keep their rotation), then augmenting paths.
constexpr ProvokingChoice provoking_choice(const Pattern& p) {
    detail::ProvokingMatching m;
    const unsigned vertices = p.vertex_count(), triangles = p.triangle_count();
    for (unsigned v = 0; v < vertices; ++v) m.owner[v] = -1;
    std::array<bool, provoking_max_triangles> matched{};
    unsigned matches = 0;
    for (unsigned t = 0; t < triangles; ++t) {
        const auto c = p.triangle(t);
        m.tri[t] = {static_cast<std::uint8_t>(c[0]), static_cast<std::uint8_t>(c[1]),
                    static_cast<std::uint8_t>(c[2])};
        for (std::uint8_t k = 0; k < 3 && !matched[t]; ++k)
            if (m.owner[c[k]] < 0) {
                m.owner[c[k]] = static_cast<int>(t);
                m.rotation[t] = k;
                matched[t] = true;
                ++matches;
            }
    }
    for (unsigned t = 0; t < triangles && matches < vertices; ++t) {
        if (matched[t]) continue;
        ++m.stamp;
        if (m.augment(t)) matched[t] = true, ++matches;
    }
    ProvokingChoice out;
    for (unsigned t = 0; t < triangles; ++t) {
        out.rotation[t] = matched[t] ? m.rotation[t] : std::uint8_t{0};
        out.copied[t] = !matched[t];
        out.copies += matched[t] ? 0u : 1u;
    }
    return out;
}

} // namespace ctess::uniform
