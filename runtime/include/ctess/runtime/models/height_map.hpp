// Height maps for displacement (docs/models.md, "Height maps"): PNG (8 or 16 bits per channel, any channel
// count: the first channel, red or grey, is the height) and the other formats stb_image reads, decoded by
// Debian's stb_image (libstb-dev) into floats in [0, 1] (c / 255, c / 65535, as glTF's normalized texels);
// Radiance .hdr keeps its linear floats. OpenEXR images (by magic number) go through Debian's OpenEXR when
// the build has it: the R channel, else Y, else the first, as floats, every texel finite. Loading never
// throws: a missing, truncated or unreadable file, a 0 x 0 image or one past the size limit gives a LoadError
// naming the file and no image. The size is checked from the header (stbi_info) BEFORE anything is decoded,
// so a header claiming 65536 x 65536 allocates nothing.
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <ctess/runtime/displace/height_map.hpp>
#include <ctess/runtime/models/model.hpp>

namespace ctess::models {

// The largest image side and texel count a height map may have (16384 x 16384 = 2^28 texels, 1 GiB of floats
// is past the texel limit: at most 2^26 texels, 256 MiB; a vector map's three channels 768 MiB). Decoding
// needs more at its peak: stb_image's own buffer (up to 1 GiB of floats for a 4-channel .hdr), or for OpenEXR
// one chunk of the unused channels. An OpenEXR file's channels count together (2^26 samples in all), so an
// RGBA EXR has at most 2^24 texels.
inline constexpr std::uint32_t max_height_map_side = 16384;
inline constexpr std::uint64_t max_height_map_texels = std::uint64_t{1} << 26;

struct HeightImage {
    std::uint32_t width = 0, height = 0;
    std::uint32_t channels = 1; // floats per texel: 1 (load_height_map) or 3 (load_vector_map: r, g, b)
    std::vector<float> texels;  // width * height * channels, row-major, the file's first row first (v = 0)
    // A view for the pipeline (rt::Displacement::map); valid while this image lives.
    rt::HeightMap view(rt::AddressMode address = rt::AddressMode::repeat) const {
        return {texels.data(), width, height, address, channels};
    }
};

struct HeightMapResult {
    std::optional<HeightImage> image;
    LoadError error; // empty message when image is set
    bool ok() const { return image.has_value(); }
    explicit operator bool() const { return ok(); }
};

HeightMapResult load_height_map(const std::string& path);
// The same from encoded bytes (a glTF's embedded image); `name` is what error messages call the input.
HeightMapResult load_height_map_from_memory(std::span<const std::uint8_t> bytes,
                                            const std::string& name = "<memory>");

// A vector displacement map (docs/models.md, "Vector maps"; docs/algorithm.md §8.7): the same formats,
// limits and errors, but the image keeps red, green and blue (channels = 3; an alpha channel is dropped),
// each normalised as above (a PNG's texels lie in [0, 1]: the usual signed encoding 0.5 = zero wants
// Displacement::offset -0.5, --displace-offset -0.5). A grey or grey + alpha image is an error (it has no x
// and y), not a grey vector.
HeightMapResult load_vector_map(const std::string& path);
HeightMapResult load_vector_map_from_memory(std::span<const std::uint8_t> bytes,
                                            const std::string& name = "<memory>");

} // namespace ctess::models
