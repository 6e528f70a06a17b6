// A displacement texture as the displacement reads it (docs/algorithm.md §8.1): a view of width x height
// texels of `channels` floats each (1: a height map; 3: an RGB vector map, §8.7), row-major, row 0 at v = 0
// (glTF's texture coordinate origin, the image's first row), sampled bilinearly at LOD 0. The view owns
// nothing; models::load_height_map (and load_vector_map) decode image files into an owning HeightImage whose
// view() is this.
#pragma once
#include <cstdint>

namespace ctess::rt {

// What a coordinate outside [0, 1] reads.
enum class AddressMode : std::uint8_t {
    repeat = 0, // the texture tiles (glTF samplers' default wrapS / wrapT, 10497 REPEAT): the default here
    clamp = 1,  // the edge texels extend (GL's CLAMP_TO_EDGE)
};

struct HeightMap {
    const float* texels = nullptr; // width * height * channels floats, row-major, a texel's channels adjacent
    std::uint32_t width = 0, height = 0;
    AddressMode address = AddressMode::repeat;
    std::uint32_t channels = 1; // floats per texel: 1 (height) or 3 (RGB vector, §8.7); 0 reads as empty
};

// The bilinear sample at (u, v), texel centres at ((i + 0.5) / width, (j + 0.5) / height), as a GPU samples
// LOD 0 with linear filtering. Out of line in ctess::runtime_core with -ffp-contract=off -fno-fast-math, so
// both sides of a shared edge get the same bits whatever the caller's flags. Bad input gives a documented
// value and never reads outside the texels: an empty map (null texels, zero width or height) gives 0, a NaN
// or infinite coordinate gives 0, an address mode outside the enum reads as clamp. A map of several
// channels reads its first (channels 0 is empty).
float sample_bilinear(const HeightMap& map, float u, float v);

// The same bilinear sample of channels 0, 1, 2 (an RGB vector map, §8.7), each by sample_bilinear's
// operations. A map of fewer than 3 channels, an empty map, or a NaN or infinite coordinate gives {0, 0, 0}.
struct Texel3 {
    float x = 0.0f, y = 0.0f, z = 0.0f;
};
Texel3 sample_bilinear_rgb(const HeightMap& map, float u, float v);

// The smallest and largest texel value over every channel (both 0 for an empty map; NaN values are
// skipped).
struct TexelRange {
    float min = 0.0f, max = 0.0f;
};
TexelRange texel_range(const HeightMap& map);

} // namespace ctess::rt
