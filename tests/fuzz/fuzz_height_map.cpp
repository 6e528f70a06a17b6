// libFuzzer: ctess::models::load_height_map_from_memory on arbitrary bytes (PNG and what stb_image reads,
// OpenEXR).
// Any input gives an image or an error (never a crash, a hang or a sanitizer report); an image keeps the
// loader's promises (docs/models.md, "Height maps"): sides in [1, 16384], at most 2^26 texels, width * height
// texels, finite, in [0, 1] unless the file is a Radiance .hdr or an OpenEXR image (linear floats); and the
// pipeline's sampler reads it finitely (docs/algorithm.md §8.1). The same bytes as a vector map
// (load_vector_map_from_memory, §8.7): an image only where the height map loads too, of the same size, with 3
// channels in the same range, sampled finitely.
#include <cmath>
#include <cstdint>
#include <cstring>

#include <ctess/runtime/displace/displace.hpp>
#include <ctess/runtime/models/height_map.hpp>

#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace ctess;
    const models::HeightMapResult r =
        models::load_height_map_from_memory(std::span<const std::uint8_t>(data, size));
    CTESS_FUZZ_CHECK(r.ok() != !r.error.message.empty());
    const bool hdr = size >= 2 && data[0] == '#' && data[1] == '?';
    const bool exr = size >= 4 && data[0] == 0x76 && data[1] == 0x2f && data[2] == 0x31 && data[3] == 0x01;
    const models::HeightMapResult rgb =
        models::load_vector_map_from_memory(std::span<const std::uint8_t>(data, size));
    CTESS_FUZZ_CHECK(rgb.ok() != !rgb.error.message.empty());
    if (rgb.ok()) {
        const models::HeightImage& image = *rgb.image;
        CTESS_FUZZ_CHECK(r.ok() && r.image->width == image.width && r.image->height == image.height);
        CTESS_FUZZ_CHECK(image.channels == 3);
        CTESS_FUZZ_CHECK(image.texels.size() == 3 * std::size_t{image.width} * image.height);
        for (const float t : image.texels) {
            CTESS_FUZZ_CHECK(std::isfinite(t));
            if (!hdr && !exr) CTESS_FUZZ_CHECK(t >= 0.0f && t <= 1.0f);
        }
        for (const float u : {-1.5f, 0.0f, 0.37f, 1.0f, 2.25f}) {
            const rt::Texel3 s = rt::sample_bilinear_rgb(image.view(), u, 1.0f - u);
            CTESS_FUZZ_CHECK(std::isfinite(s.x) && std::isfinite(s.y) && std::isfinite(s.z));
        }
    }
    if (!r.ok()) return 0;
    const models::HeightImage& image = *r.image;
    CTESS_FUZZ_CHECK(image.width >= 1 && image.width <= models::max_height_map_side);
    CTESS_FUZZ_CHECK(image.height >= 1 && image.height <= models::max_height_map_side);
    CTESS_FUZZ_CHECK(std::uint64_t{image.width} * image.height <= models::max_height_map_texels);
    CTESS_FUZZ_CHECK(image.texels.size() == std::size_t{image.width} * image.height);
    for (const float t : image.texels) {
        CTESS_FUZZ_CHECK(std::isfinite(t));
        if (!hdr && !exr) CTESS_FUZZ_CHECK(t >= 0.0f && t <= 1.0f);
    }
    for (const rt::AddressMode mode : {rt::AddressMode::repeat, rt::AddressMode::clamp}) {
        const rt::HeightMap map = image.view(mode);
        for (const float u : {-1.5f, 0.0f, 0.37f, 1.0f, 2.25f})
            CTESS_FUZZ_CHECK(std::isfinite(rt::sample_bilinear(map, u, 1.0f - u)));
    }
    return 0;
}
