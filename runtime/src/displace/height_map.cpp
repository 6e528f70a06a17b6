// Bilinear sampling at LOD 0 (height_map.hpp), compiled with -ffp-contract=off -fno-fast-math
// (runtime/CMakeLists.txt): a point on a shared edge samples the same uv from both faces and must get the
// same bits (docs/algorithm.md §8.1).
#include <ctess/runtime/displace/height_map.hpp>

#include <cmath>
#include <cstdint>

namespace ctess::rt {

namespace {

// Texel index i of a row of n (n >= 1) under the address mode; i may be -1 or n.
std::uint32_t address(std::int64_t i, std::uint32_t n, AddressMode mode) {
    if (mode == AddressMode::repeat) {
        const std::int64_t m = i % n;
        return static_cast<std::uint32_t>(m < 0 ? m + n : m);
    }
    return static_cast<std::uint32_t>(i < 0 ? 0 : i >= n ? n - 1 : i);
}

// The texel coordinate of u along n texels: the integer part i0 (in [-1, n - 1]) and the fraction. repeat
// first reduces u to [0, 1] and clamp clamps it there, so huge coordinates never overflow the integer.
void texel_coordinate(float u, std::uint32_t n, AddressMode mode, std::int64_t& i0, float& fraction) {
    float x = mode == AddressMode::repeat ? u - std::floor(u) : (u < 0.0f ? 0.0f : u > 1.0f ? 1.0f : u);
    x = x * static_cast<float>(n) - 0.5f;
    const float base = std::floor(x);
    i0 = static_cast<std::int64_t>(base);
    fraction = x - base;
}

// The four texels' offsets (in floats, channel 0) and the weights' fractions of a bilinear sample; false
// for an empty map or a NaN or infinite coordinate.
struct Footprint {
    std::size_t t00 = 0, t10 = 0, t01 = 0, t11 = 0; // (x0, y0), (x1, y0), (x0, y1), (x1, y1)
    float fx = 0.0f, fy = 0.0f;
};

bool footprint(const HeightMap& map, float u, float v, Footprint& f) {
    if (map.texels == nullptr || map.width == 0 || map.height == 0 || map.channels == 0) return false;
    if (!std::isfinite(u) || !std::isfinite(v)) return false;
    const AddressMode mode = map.address == AddressMode::repeat ? AddressMode::repeat : AddressMode::clamp;
    std::int64_t i0 = 0, j0 = 0;
    texel_coordinate(u, map.width, mode, i0, f.fx);
    texel_coordinate(v, map.height, mode, j0, f.fy);
    const std::uint32_t x0 = address(i0, map.width, mode), x1 = address(i0 + 1, map.width, mode);
    const std::uint32_t y0 = address(j0, map.height, mode), y1 = address(j0 + 1, map.height, mode);
    const std::size_t row0 = std::size_t{y0} * map.width, row1 = std::size_t{y1} * map.width;
    const std::size_t c = map.channels;
    f.t00 = (row0 + x0) * c;
    f.t10 = (row0 + x1) * c;
    f.t01 = (row1 + x0) * c;
    f.t11 = (row1 + x1) * c;
    return true;
}

// Channel `channel` of the footprint: the operations of the single-channel sample (§8.1).
float blend(const float* texels, const Footprint& f, unsigned channel) {
    const float top = (1.0f - f.fx) * texels[f.t00 + channel] + f.fx * texels[f.t10 + channel];
    const float bottom = (1.0f - f.fx) * texels[f.t01 + channel] + f.fx * texels[f.t11 + channel];
    return (1.0f - f.fy) * top + f.fy * bottom;
}

} // namespace

float sample_bilinear(const HeightMap& map, float u, float v) {
    Footprint f;
    if (!footprint(map, u, v, f)) return 0.0f;
    return blend(map.texels, f, 0);
}

Texel3 sample_bilinear_rgb(const HeightMap& map, float u, float v) {
    Footprint f;
    if (map.channels < 3 || !footprint(map, u, v, f)) return {};
    return {blend(map.texels, f, 0), blend(map.texels, f, 1), blend(map.texels, f, 2)};
}

TexelRange texel_range(const HeightMap& map) {
    TexelRange r;
    if (map.texels == nullptr || map.width == 0 || map.height == 0) return r;
    bool first = true;
    const std::size_t n = std::size_t{map.width} * map.height * map.channels;
    for (std::size_t i = 0; i < n; ++i) {
        const float t = map.texels[i];
        if (std::isnan(t)) continue;
        if (first || t < r.min) r.min = t;
        if (first || t > r.max) r.max = t;
        first = false;
    }
    return r;
}

} // namespace ctess::rt
