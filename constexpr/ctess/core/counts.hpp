// The one counts type of every triangle pattern in ctess (CP, D3D11 tri and quad, uniform density, the
// runtime patches, the mesh pipeline): how many vertices and triangles a pattern has, so the caller can size
// its buffers before the fill (count, then fill, as OpenSubdiv's Bfr::Tessellation). Indices are
// 3 * triangles.
#pragma once
#include <cstddef>
#include <cstdint>

namespace ctess {

struct Counts {
    std::uint32_t vertices = 0;
    std::uint32_t triangles = 0;
    constexpr std::uint32_t index_count() const { return 3 * triangles; }
    friend constexpr bool operator==(const Counts&, const Counts&) = default;
};

// Whether buffers of these sizes hold a pattern of counts n: what every fill that takes spans checks before
// it writes anything (docs/api.md, "Sized outputs").
constexpr bool fits(Counts n, std::size_t vertices, std::size_t indices) {
    return n.vertices <= vertices && n.index_count() <= indices;
}

} // namespace ctess
