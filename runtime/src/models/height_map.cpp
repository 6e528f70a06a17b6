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

HeightMapResult decode(std::span<const std::uint8_t> bytes, const std::string& name) {
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
    HeightImage image;
    image.width = static_cast<std::uint32_t>(w);
    image.height = static_cast<std::uint32_t>(h);
    const std::size_t count = std::size_t{image.width} * image.height;
    int dw = 0, dh = 0, dc = 0;
    if (stbi_is_hdr_from_memory(bytes.data(), length)) {
        std::unique_ptr<float, StbFree<float>> data(
            stbi_loadf_from_memory(bytes.data(), length, &dw, &dh, &dc, 0));
        if (!data || dw != w || dh != h || dc <= 0)
            return fail("cannot decode the image (" + stb_reason() + ")");
        image.texels.resize(count);
        for (std::size_t i = 0; i < count; ++i)
            image.texels[i] = data.get()[i * static_cast<std::size_t>(dc)];
    } else if (stbi_is_16_bit_from_memory(bytes.data(), length)) {
        std::unique_ptr<stbi_us, StbFree<stbi_us>> data(
            stbi_load_16_from_memory(bytes.data(), length, &dw, &dh, &dc, 0));
        if (!data || dw != w || dh != h || dc <= 0)
            return fail("cannot decode the image (" + stb_reason() + ")");
        image.texels.resize(count);
        for (std::size_t i = 0; i < count; ++i)
            image.texels[i] = static_cast<float>(data.get()[i * static_cast<std::size_t>(dc)]) / 65535.0f;
    } else {
        std::unique_ptr<stbi_uc, StbFree<stbi_uc>> data(
            stbi_load_from_memory(bytes.data(), length, &dw, &dh, &dc, 0));
        if (!data || dw != w || dh != h || dc <= 0)
            return fail("cannot decode the image (" + stb_reason() + ")");
        image.texels.resize(count);
        for (std::size_t i = 0; i < count; ++i)
            image.texels[i] = static_cast<float>(data.get()[i * static_cast<std::size_t>(dc)]) / 255.0f;
    }
    result.image = std::move(image);
    return result;
}

} // namespace

HeightMapResult load_height_map_from_memory(std::span<const std::uint8_t> bytes, const std::string& name) {
    try {
        return decode(bytes, name);
    } catch (const std::bad_alloc&) {
        HeightMapResult r;
        r.error.message = name + ": out of memory";
        return r;
    }
}

HeightMapResult load_height_map(const std::string& path) {
    HeightMapResult result;
    try {
        std::vector<std::uint8_t> bytes;
        result.error.message = detail::read_file_bytes(path, max_height_file_bytes, "1 GiB", bytes);
        if (!result.error.message.empty()) return result;
        return decode(bytes, path);
    } catch (const std::bad_alloc&) {
        result.error.message = path + ": out of memory";
    } catch (const std::exception& e) {
        result.error.message = path + ": " + e.what();
    }
    return result;
}

} // namespace ctess::models
