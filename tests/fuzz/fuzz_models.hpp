// The property every models fuzzer checks (tests/fuzz/fuzz_models_*.cpp).
#pragma once
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include <ctess/runtime/models.hpp>

#include "fuzz_input.hpp"

namespace ctess::fuzz {

inline void check_model_load(const std::uint8_t* data, std::size_t size, models::ModelKind kind) {
    const models::LoadResult r =
        models::load_model_from_memory(std::span<const std::uint8_t>(data, size), kind);
    CTESS_FUZZ_CHECK(r.ok() != !r.error.message.empty());
    if (!r.ok()) return;
    const models::Model& m = *r.model;
    CTESS_FUZZ_CHECK(m.vertices.size() % models::model_vertex_floats == 0);
    CTESS_FUZZ_CHECK(m.triangles.size() % 3 == 0 && m.quads.size() % 4 == 0);
    CTESS_FUZZ_CHECK(m.triangle_count() + m.quad_count() > 0);
    for (float v : m.vertices) CTESS_FUZZ_CHECK(std::isfinite(v));
    for (std::uint32_t i : m.triangles) CTESS_FUZZ_CHECK(i < m.vertex_count());
    for (std::uint32_t i : m.quads) CTESS_FUZZ_CHECK(i < m.vertex_count());
    const models::Adjacency adj = models::build_adjacency(m);
    CTESS_FUZZ_CHECK(adj.position_ids.size() == m.vertex_count());
    CTESS_FUZZ_CHECK(adj.tessellation_indices.size() == (m.triangle_count() + 2 * m.quad_count()) * 12);
    for (std::uint32_t i : adj.tessellation_indices) CTESS_FUZZ_CHECK(i < m.vertex_count());
    CTESS_FUZZ_CHECK(models::open_edge_count(m, adj.position_ids) <=
                     3 * m.triangle_count() + 4 * m.quad_count());
}

} // namespace ctess::fuzz
