// The uniform triforce grid of the unit domain triangle: N segments per edge, vertices (i/N, j/N) with i + j
// <= N, N^2 counter-clockwise triangles. An independent reference mesh for the CP and D3D11 tests.
#pragma once
#include <cstdint>
#include <vector>

#include <ctess/core/domain_point.hpp>

namespace ctess::test {

struct TriforceGrid {
    std::vector<DomainPoint> vertices;
    std::vector<std::uint32_t> indices;
};

// `one` must be divisible by n so that every vertex is exact.
inline TriforceGrid triforce_grid(std::uint32_t n, std::uint32_t one) {
    TriforceGrid g;
    const std::uint32_t step = one / n;
    auto index = [n](std::uint32_t i, std::uint32_t j) {
        // Row j holds n + 1 - j vertices; rows below j hold sum_{r<j} (n + 1 - r).
        return j * (n + 1) - j * (j - 1) / 2 + i;
    };
    for (std::uint32_t j = 0; j <= n; ++j)
        for (std::uint32_t i = 0; i + j <= n; ++i) g.vertices.push_back({i * step, j * step});
    for (std::uint32_t j = 0; j < n; ++j)
        for (std::uint32_t i = 0; i + j < n; ++i) {
            g.indices.insert(g.indices.end(), {index(i, j), index(i + 1, j), index(i, j + 1)}); // upward
            if (i + j + 1 < n)
                g.indices.insert(g.indices.end(), {index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)});
        }
    return g;
}

// The n + 1 uniform edge parameters k * one / n.
inline std::vector<std::uint32_t> uniform_params(std::uint32_t n, std::uint32_t one) {
    std::vector<std::uint32_t> p;
    for (std::uint32_t k = 0; k <= n; ++k) p.push_back(k * (one / n));
    return p;
}

} // namespace ctess::test
