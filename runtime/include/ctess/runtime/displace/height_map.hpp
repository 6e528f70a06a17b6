// A height texture as the displacement reads it (docs/algorithm.md §8.1): a view of width x height float
// texels, row-major, row 0 at v = 0 (glTF's texture coordinate origin, the image's first row), sampled
// bilinearly at LOD 0. The view owns nothing; models::load_height_map decodes PNG files into an owning
// HeightImage whose view() is this.
#pragma once
#include <cstdint>

namespace ctess::rt {

// What a coordinate outside [0, 1] reads.
enum class AddressMode : std::uint8_t {
    repeat = 0, // the texture tiles (glTF samplers' default wrapS / wrapT, 10497 REPEAT): the default here
    clamp = 1,  // the edge texels extend (GL's CLAMP_TO_EDGE)
};

struct HeightMap {
    const float* texels = nullptr; // width * height floats, row-major
    std::uint32_t width = 0, height = 0;
    AddressMode address = AddressMode::repeat;
};

// The bilinear sample at (u, v), texel centres at ((i + 0.5) / width, (j + 0.5) / height), as a GPU samples
// LOD 0 with linear filtering. Out of line in ctess::runtime_core with -ffp-contract=off -fno-fast-math, so
// both sides of a shared edge get the same bits whatever the caller's flags. Bad input gives a documented
// value and never reads outside the texels: an empty map (null texels, zero width or height) gives 0, a NaN
// or infinite coordinate gives 0, an address mode outside the enum reads as clamp.
float sample_bilinear(const HeightMap& map, float u, float v);

// The smallest and largest texel (both 0 for an empty map; NaN texels are skipped).
struct TexelRange {
    float min = 0.0f, max = 0.0f;
};
TexelRange texel_range(const HeightMap& map);

} // namespace ctess::rt
