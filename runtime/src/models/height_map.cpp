// Height maps through Debian's stb_image (height_map.hpp, docs/models.md "Height maps"): the header is read
// first (stbi_info_from_memory) and the size limits checked before any texel is decoded.
#include <ctess/runtime/models/height_map.hpp>

#include "load_common.hpp"

#include <algorithm>
#include <climits>
#include <filesystem>
#include <fstream>
#include <memory>
#include <new>
#include <type_traits>

#include <stb/stb_image.h>

namespace ctess::models {

namespace {

std::string stb_reason() {
    const char* r = stbi_failure_reason();
    return r != nullptr ? r : "unknown";
}

// Encoded files past this size are refused before they are read (a 2^26-texel image compresses far below).
constexpr std::uintmax_t max_height_file_bytes = std::uintmax_t{1} << 30;

template <class T>
struct StbFree {
    void operator()(T* p) const { stbi_image_free(p); }
};

// wanted: 1 (a height map: the first channel) or 3 (a vector map: red, green, blue; docs/models.md).
HeightMapResult decode(std::span<const std::uint8_t> bytes, const std::string& name, unsigned wanted) {
    HeightMapResult result;
    auto fail = [&](const std::string& problem) {
        result.error.message = name + ": " + problem;
        return result;
    };
    if (bytes.empty()) return fail("the file is empty");
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) return fail("larger than 2 GiB");
    const int length = static_cast<int>(bytes.size());
    auto size_problem = [](std::uint64_t w, std::uint64_t h) -> std::string {
        if (w == 0 || h == 0)
            return "the image is empty (" + std::to_string(w) + " x " + std::to_string(h) + ")";
        if (w > max_height_map_side || h > max_height_map_side || w * h > max_height_map_texels)
            return "the image is " + std::to_string(w) + " x " + std::to_string(h) +
                   ", past the height map limit (sides up to 16384, 2^26 texels)";
        return {};
    };
    // A PNG's size is read from its IHDR here first: stb_image refuses very large headers itself but names
    // no size ("unknown image type").
    constexpr std::uint8_t png_signature[8] = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
    if (bytes.size() >= 24 && std::equal(png_signature, png_signature + 8, bytes.begin()) &&
        std::equal(bytes.begin() + 12, bytes.begin() + 16, "IHDR")) {
        auto be32 = [&](std::size_t at) {
            return std::uint32_t{bytes[at]} << 24 | std::uint32_t{bytes[at + 1]} << 16 |
                   std::uint32_t{bytes[at + 2]} << 8 | bytes[at + 3];
        };
        if (std::string problem = size_problem(be32(16), be32(20)); !problem.empty()) return fail(problem);
    }
    int w = 0, h = 0, channels = 0;
    if (stbi_info_from_memory(bytes.data(), length, &w, &h, &channels) == 0)
        return fail("not an image stb_image can read (" + stb_reason() + ")");
    if (std::string problem = size_problem(w < 0 ? 0 : static_cast<std::uint64_t>(w),
                                           h < 0 ? 0 : static_cast<std::uint64_t>(h));
        !problem.empty())
        return fail(problem);
    // A vector map needs three colour channels: grey (1) or grey + alpha (2) would give no x and y.
    if (wanted == 3 && channels < 3)
        return fail("the image has " + std::to_string(channels) + (channels == 1 ? " channel" : " channels") +
                    " (grey); a vector displacement map needs red, green and blue");
    HeightImage image;
    image.channels = wanted;
    image.width = static_cast<std::uint32_t>(w);
    image.height = static_cast<std::uint32_t>(h);
    const std::size_t count = std::size_t{image.width} * image.height;
    int decoded_w = 0, decoded_h = 0, decoded_channels = 0;
    // The first `wanted` channels of what stb_image decoded, divided by the format's largest value (1 for
    // .hdr floats).
    bool decoded = false;
    const auto first_channel = [&](auto* raw, float divisor) {
        using T = std::remove_pointer_t<decltype(raw)>;
        const std::unique_ptr<T, StbFree<T>> data(raw);
        if (!data || decoded_w != w || decoded_h != h || decoded_channels < static_cast<int>(wanted)) return;
        image.texels.resize(count * wanted);
        for (std::size_t i = 0; i < count; ++i)
            for (std::size_t c = 0; c < wanted; ++c)
                image.texels[i * wanted + c] =
                    static_cast<float>(data.get()[i * static_cast<std::size_t>(decoded_channels) + c]) /
                    divisor;
        decoded = true;
    };
    if (stbi_is_hdr_from_memory(bytes.data(), length))
        first_channel(
            stbi_loadf_from_memory(bytes.data(), length, &decoded_w, &decoded_h, &decoded_channels, 0), 1.0f);
    else if (stbi_is_16_bit_from_memory(bytes.data(), length))
        first_channel(
            stbi_load_16_from_memory(bytes.data(), length, &decoded_w, &decoded_h, &decoded_channels, 0),
            65535.0f);
    else
        first_channel(
            stbi_load_from_memory(bytes.data(), length, &decoded_w, &decoded_h, &decoded_channels, 0),
            255.0f);
    if (!decoded) return fail("cannot decode the image (" + stb_reason() + ")");
    result.image = std::move(image);
    return result;
}

HeightMapResult load_from_memory(std::span<const std::uint8_t> bytes, const std::string& name,
                                 unsigned wanted) {
    return detail::guarded_load<HeightMapResult>(name, [&] { return decode(bytes, name, wanted); });
}

HeightMapResult load_file(const std::string& path, unsigned wanted) {
    return detail::guarded_load<HeightMapResult>(path, [&] {
        HeightMapResult result;
        std::vector<std::uint8_t> bytes;
        result.error.message = detail::read_file_bytes(path, max_height_file_bytes, "1 GiB", bytes);
        return result.error.message.empty() ? decode(bytes, path, wanted) : result;
    });
}

} // namespace

HeightMapResult load_height_map_from_memory(std::span<const std::uint8_t> bytes, const std::string& name) {
    return load_from_memory(bytes, name, 1);
}

HeightMapResult load_height_map(const std::string& path) {
    return load_file(path, 1);
}

HeightMapResult load_vector_map_from_memory(std::span<const std::uint8_t> bytes, const std::string& name) {
    return load_from_memory(bytes, name, 3);
}

HeightMapResult load_vector_map(const std::string& path) {
    return load_file(path, 3);
}

} // namespace ctess::models
