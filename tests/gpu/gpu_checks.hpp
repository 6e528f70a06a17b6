// Checks on pipeline outputs shared by the CPU and GPU tests: watertightness across shared edges, and the
// spread of the edge factors over [1, max].
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <set>
#include <tuple>
#include <vector>

#include <ctess/runtime/uniform/split.hpp>

#include "pipeline_output.hpp"

namespace ctess::gpu_test {

// The pattern's name in the tests' and the benchmark's lines.
inline const char* pattern_name(rt::Pattern p) {
    return p == rt::Pattern::cp ? "CP" : p == rt::Pattern::uniform ? "uniform" : "uniform split";
}

// Splitting (docs/shaders.md, "Splitting"): how many leaves of each depth a CPU output of
// Pattern::uniform_split has, from its records' factors (each quad half is a split of its own).
inline std::array<std::uint32_t, 5> split_depths(const Scene& scene, const PipelineOutput& cpu) {
    std::array<std::uint32_t, 5> by_depth{};
    const std::size_t triangles = scene.indices.size() / 3;
    const auto* records = reinterpret_cast<const rt::PatchRecord*>(cpu.patches.data());
    for (std::size_t p = 0; p < scene.patch_count(); ++p)
        for (unsigned half = 0; half < (p < triangles ? 1u : 2u); ++half) {
            const auto factor = [&](unsigned k) {
                return static_cast<float>(half == 0 ? records[p].uniform_factor(k)
                                                    : records[p].setup[rt::quad_setup_word::b_token + k]);
            };
            if (factor(0) == 0) continue; // culled
            rt::UniformSplit(rt::uniform_tables, factor(0), factor(1), factor(2),
                             rt::uniform_pipeline_options)
                .for_each_leaf([&](const rt::UniformSplit::Leaf& leaf) { ++by_depth[leaf.depth]; });
        }
    return by_depth;
}

struct CrackReport {
    std::size_t shared_edges = 0;        // base edges used by exactly two patches
    std::size_t edge_points = 0;         // edge points compared across them (corners included)
    std::size_t position_mismatches = 0; // same edge point, different position bits
    std::size_t unmatched_points = 0;    // an edge point that the other side of the edge does not have
};

// Each vertex's position id: the first vertex with a bit-identical position (models::Adjacency::position_ids'
// rule), so that the two sides of a seam (different vertices at one position) name the same edge.
inline std::vector<std::uint32_t> position_ids(const Scene& scene) {
    using Position = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>;
    std::map<Position, std::uint32_t> first;
    std::vector<std::uint32_t> ids(scene.vertices.size() / rt::mesh_vertex_floats);
    for (std::uint32_t v = 0; v < ids.size(); ++v) {
        std::uint32_t p[3];
        std::memcpy(p, &scene.vertices[std::size_t{v} * rt::mesh_vertex_floats], sizeof p);
        ids[v] = first.try_emplace({p[0], p[1], p[2]}, v).first->second;
    }
    return ids;
}

// Every vertex with a zero base weight lies on a base edge: key it by (lower position id, higher position id,
// parameter from the lower one) and require both patches of the edge to produce the same keys with the same
// position bits. Without duplicated positions the ids are the mesh indices.
inline CrackReport crack_check(const Scene& scene, const PipelineOutput& out) {
    const std::vector<std::uint32_t> id = position_ids(scene);
    using Key = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>;
    using Position = std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>;
    std::map<Key, std::vector<std::pair<std::uint32_t, Position>>> points; // key -> (patch, position bits)
    std::map<std::pair<std::uint32_t, std::uint32_t>, unsigned> edge_users;
    CrackReport r;
    const std::uint32_t n = scene.patch_count();
    for (std::uint32_t t = 0; t < n; ++t) {
        const std::uint32_t* rec = &out.patches[std::size_t{t} * patch_words];
        const std::uint32_t w[3] = {id[scene.indices[3 * t]], id[scene.indices[3 * t + 1]],
                                    id[scene.indices[3 * t + 2]]};
        for (unsigned k = 0; k < 3; ++k) ++edge_users[std::minmax(w[k], w[(k + 1) % 3])];
        std::map<Key, Position> mine; // the provoking-layout copies repeat points within a patch
        for (std::uint32_t i = 0; i < rec[7]; ++i) {
            const std::uint32_t* v = &out.vertices[(std::size_t{rec[9]} + i) * vertex_words];
            const std::uint32_t bw[3] = {(1u << 24) - v[0] - v[1], v[0], v[1]};
            for (unsigned k = 0; k < 3; ++k) {
                if (bw[k] != 0) continue;
                const unsigned a = (k + 1) % 3, b = (k + 2) % 3;
                const bool a_low = w[a] < w[b];
                const Key key{a_low ? w[a] : w[b], a_low ? w[b] : w[a], a_low ? bw[b] : bw[a]};
                const Position pos{v[2], v[3], v[4]};
                const auto [it, fresh] = mine.try_emplace(key, pos);
                if (!fresh && it->second != pos) ++r.position_mismatches; // copies must agree too
            }
        }
        for (const auto& [key, pos] : mine) points[key].emplace_back(t, pos);
    }
    for (const auto& [edge, users] : edge_users)
        if (users == 2) ++r.shared_edges;
    for (const auto& [key, seen] : points) {
        if (edge_users[{std::get<0>(key), std::get<1>(key)}] != 2) continue;
        ++r.edge_points;
        if (seen.size() != 2) {
            ++r.unmatched_points;
            continue;
        }
        if (seen[0].second != seen[1].second) ++r.position_mismatches;
    }
    return r;
}

// Base edge factors (from the patch records) per octave: [0] below 1, [k] in [2^(k-1), 2^k), last: >= max.
inline std::vector<std::size_t> factor_octaves(const PipelineOutput& out, std::uint32_t patches,
                                               unsigned max_factor) {
    unsigned octaves = 0;
    while ((1u << octaves) < max_factor) ++octaves;
    std::vector<std::size_t> bins(octaves + 2, 0);
    for (std::uint32_t t = 0; t < patches; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            float f;
            std::memcpy(&f, &out.patches[std::size_t{t} * patch_words + 11 + k], 4);
            std::size_t bin = 0;
            if (f >= static_cast<float>(max_factor))
                bin = octaves + 1;
            else if (f >= 1.0f)
                bin = 1 + static_cast<std::size_t>(std::floor(std::log2(f)));
            ++bins[bin];
        }
    }
    return bins;
}

} // namespace ctess::gpu_test
