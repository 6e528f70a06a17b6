// The one counts type of every triangle pattern in ctess (CP, D3D11 tri and quad, uniform density, the
// runtime patches, the mesh pipeline): how many vertices and triangles a pattern has, so the caller can size
// its buffers before the fill (count, then fill, as OpenSubdiv's Bfr::Tessellation). Indices are
// 3 * triangles.
#pragma once
#include <cstdint>

namespace ctess {

struct Counts {
    std::uint32_t vertices = 0;
    std::uint32_t triangles = 0;
    constexpr std::uint32_t index_count() const { return 3 * triangles; }
    friend constexpr bool operator==(const Counts&, const Counts&) = default;
};

} // namespace ctess
