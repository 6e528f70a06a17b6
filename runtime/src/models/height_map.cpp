// Height maps through Debian's stb_image and, for OpenEXR files, Debian's OpenEXR (height_map.hpp,
// docs/models.md "Height maps"): the header is read first (stbi_info_from_memory; for EXR, a bounds-checked
// walk of the header) and the size limits checked before any texel is decoded.
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

#if CTESS_HAVE_OPENEXR
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIO.h>
#include <OpenEXR/ImfInputFile.h>
#include <cmath>
#include <cstring>
#include <stdexcept>
#endif

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

// Empty, or why a w x h image is refused (0 x 0, past the side or texel limit).
std::string size_problem(std::uint64_t w, std::uint64_t h) {
    if (w == 0 || h == 0) return "the image is empty (" + std::to_string(w) + " x " + std::to_string(h) + ")";
    if (w > max_height_map_side || h > max_height_map_side || w * h > max_height_map_texels)
        return "the image is " + std::to_string(w) + " x " + std::to_string(h) +
               ", past the height map limit (sides up to 16384, 2^26 texels)";
    return {};
}

// OpenEXR's magic number, 20000630 little-endian (the OpenEXR file layout document).
bool is_exr(std::span<const std::uint8_t> bytes) {
    return bytes.size() >= 4 && bytes[0] == 0x76 && bytes[1] == 0x2f && bytes[2] == 0x31 && bytes[3] == 0x01;
}

#if CTESS_HAVE_OPENEXR
// The encoded bytes as OpenEXR's input stream; a read past the end throws, as IStream::read must.
class ByteStream final : public Imf::IStream {
  public:
    explicit ByteStream(std::span<const std::uint8_t> bytes) : Imf::IStream("<memory>"), bytes_(bytes) {}
    bool read(char c[], int n) override {
        if (n < 0 || static_cast<std::uint64_t>(n) > bytes_.size() - at_)
            throw std::runtime_error("truncated OpenEXR file");
        std::memcpy(c, bytes_.data() + at_, static_cast<std::size_t>(n));
        at_ += static_cast<std::uint64_t>(n);
        return at_ < bytes_.size();
    }
    std::uint64_t tellg() override { return at_; }
    void seekg(std::uint64_t pos) override {
        if (pos > bytes_.size()) throw std::runtime_error("truncated OpenEXR file");
        at_ = pos;
    }

  private:
    std::span<const std::uint8_t> bytes_;
    std::uint64_t at_ = 0;
};

// What the header walk finds: the data window's size, the channel count and the tiling.
struct ExrHeaderFacts {
    std::int64_t width = 0, height = 0;
    bool found_window = false;
    std::uint64_t channels = 0;
    bool tiled = false;
    std::uint32_t tile_width = 0, tile_height = 0;
};

// Walks the (first) header's attributes, each name, type, int32 size and value, checking every size against
// the bytes left, and reads the data window. OpenEXR allocates an attribute's claimed size before reading it,
// so a damaged size is refused here first; the decode itself is OpenEXR's.
std::string walk_exr_header(std::span<const std::uint8_t> bytes, ExrHeaderFacts& facts) {
    if (bytes.size() < 8) return "truncated OpenEXR file";
    const std::uint32_t flags = bytes[5] | std::uint32_t{bytes[6]} << 8 | std::uint32_t{bytes[7]} << 16;
    if (bytes[4] != 2) return "OpenEXR version " + std::to_string(bytes[4]) + " (2 is read)";
    if ((flags & 0x18u) != 0)
        return "a deep or multi-part OpenEXR file (only single-part flat images are read)";
    auto le32 = [&](std::size_t at) {
        return static_cast<std::int32_t>(std::uint32_t{bytes[at]} | std::uint32_t{bytes[at + 1]} << 8 |
                                         std::uint32_t{bytes[at + 2]} << 16 |
                                         std::uint32_t{bytes[at + 3]} << 24);
    };
    std::size_t at = 8;
    const auto read_name = [&](std::string& out) {
        const auto begin = bytes.begin() + static_cast<std::ptrdiff_t>(at);
        const auto end = std::find(begin, bytes.end(), std::uint8_t{0});
        if (end == bytes.end()) return false;
        out.assign(begin, end);
        at += out.size() + 1;
        return true;
    };
    for (std::string name, type;;) {
        if (at >= bytes.size()) return "truncated OpenEXR file";
        if (bytes[at] == 0) break; // the header's end
        if (!read_name(name) || !read_name(type) || bytes.size() - at < 4) return "truncated OpenEXR file";
        const std::int32_t size = le32(at);
        at += 4;
        if (size < 0 || static_cast<std::uint64_t>(size) > bytes.size() - at)
            return "the OpenEXR attribute '" + name + "' claims " + std::to_string(size) +
                   " bytes, past the end of the file";
        const std::size_t value = at, value_end = at + static_cast<std::size_t>(size);
        if (name == "dataWindow" && type == "box2i" && size == 16) {
            const std::int64_t x0 = le32(value), y0 = le32(value + 4), x1 = le32(value + 8),
                               y1 = le32(value + 12);
            facts.width = x1 >= x0 ? x1 - x0 + 1 : 0;
            facts.height = y1 >= y0 ? y1 - y0 + 1 : 0;
            facts.found_window = true;
        } else if (name == "channels" && type == "chlist") {
            // Entries: a name, then 16 bytes (type, pLinear, reserved, x and y sampling); a 0 ends the list.
            facts.channels = 0;
            for (std::size_t c = value; c < value_end && bytes[c] != 0; ++facts.channels) {
                while (c < value_end && bytes[c] != 0) ++c;
                c += 17;
            }
        } else if (name == "tiles" && type == "tiledesc" && size == 9) {
            facts.tile_width = static_cast<std::uint32_t>(le32(value));
            facts.tile_height = static_cast<std::uint32_t>(le32(value + 4));
        }
        at = value_end;
    }
    if (!facts.found_window) return "the OpenEXR header has no dataWindow";
    facts.tiled = (flags & 0x02u) != 0;
    return {};
}

// OpenEXR sizes its buffers by every channel of the file, and a tiled file's offset table by its tile count:
// these bounds keep each below the height map's own texel limit (max_height_map_texels samples, 2^20 tiles)
// whatever the header claims. Empty, or why the file is refused.
std::string exr_buffer_problem(const ExrHeaderFacts& f) {
    const auto w = static_cast<std::uint64_t>(f.width), h = static_cast<std::uint64_t>(f.height);
    if (f.channels == 0) return "the OpenEXR image has no channels";
    if (w * h * f.channels > max_height_map_texels)
        return "the OpenEXR image holds " + std::to_string(w) + " x " + std::to_string(h) + " texels of " +
               std::to_string(f.channels) + " channels, past the limit of 2^26 samples";
    if (!f.tiled) return {};
    const std::uint64_t tw = f.tile_width, th = f.tile_height;
    if (tw == 0 || th == 0 || tw > max_height_map_side || th > max_height_map_side ||
        tw * th * f.channels > max_height_map_texels ||
        ((w + tw - 1) / tw) * ((h + th - 1) / th) > (1u << 20))
        return "the OpenEXR tiles are " + std::to_string(tw) + " x " + std::to_string(th) +
               ", outside the limits (sides 1 to 16384, at most 2^26 samples a tile and 2^20 tiles)";
    return {};
}

// The R channel, else Y (luminance), else the first channel of the file, as floats (OpenEXR converts half
// and uint); every texel must be finite, as the pipeline's height bound is taken over them (§8.4).
HeightMapResult decode_exr(std::span<const std::uint8_t> bytes, const std::string& name) {
    HeightMapResult result;
    auto fail = [&](const std::string& problem) {
        result.error.message = name + ": " + problem;
        return result;
    };
    ExrHeaderFacts facts;
    if (std::string problem = walk_exr_header(bytes, facts); !problem.empty()) return fail(problem);
    if (std::string problem =
            size_problem(static_cast<std::uint64_t>(facts.width), static_cast<std::uint64_t>(facts.height));
        !problem.empty())
        return fail(problem);
    if (std::string problem = exr_buffer_problem(facts); !problem.empty()) return fail(problem);
    ByteStream stream(bytes);
    Imf::InputFile file(stream);
    const Imath::Box2i window = file.header().dataWindow();
    const Imf::ChannelList& channels = file.header().channels();
    const char* channel = channels.findChannel("R") != nullptr   ? "R"
                          : channels.findChannel("Y") != nullptr ? "Y"
                          : channels.begin() != channels.end()   ? channels.begin().name()
                                                                 : nullptr;
    if (channel == nullptr) return fail("the OpenEXR image has no channels");
    const Imf::Channel& picked = channels[channel];
    if (picked.xSampling != 1 || picked.ySampling != 1)
        return fail(std::string("the OpenEXR channel '") + channel + "' is subsampled");
    HeightImage image;
    image.width = static_cast<std::uint32_t>(facts.width);
    image.height = static_cast<std::uint32_t>(facts.height);
    image.texels.assign(std::size_t{image.width} * image.height, 0.0f);
    Imf::FrameBuffer frame;
    frame.insert(channel, Imf::Slice::Make(Imf::FLOAT, image.texels.data(), window, sizeof(float),
                                           sizeof(float) * std::size_t{image.width}));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    for (std::size_t i = 0; i < image.texels.size(); ++i)
        if (!std::isfinite(image.texels[i]))
            return fail("the OpenEXR texel (" + std::to_string(i % image.width) + ", " +
                        std::to_string(i / image.width) + ") is not finite");
    result.image = std::move(image);
    return result;
}
#else
HeightMapResult decode_exr(std::span<const std::uint8_t>, const std::string& name) {
    HeightMapResult result;
    result.error.message = name +
                           ": an OpenEXR image, and this build of ctess::models has no OpenEXR (Debian "
                           "libopenexr-dev)";
    return result;
}
#endif

HeightMapResult decode(std::span<const std::uint8_t> bytes, const std::string& name) {
    HeightMapResult result;
    auto fail = [&](const std::string& problem) {
        result.error.message = name + ": " + problem;
        return result;
    };
    if (bytes.empty()) return fail("the file is empty");
    if (bytes.size() > static_cast<std::size_t>(INT_MAX)) return fail("larger than 2 GiB");
    const int length = static_cast<int>(bytes.size());
    if (is_exr(bytes)) return decode_exr(bytes, name);
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
    int decoded_w = 0, decoded_h = 0, decoded_channels = 0;
    // The first channel of what stb_image decoded, divided by the format's largest value (1 for .hdr floats).
    bool decoded = false;
    const auto first_channel = [&](auto* raw, float divisor) {
        using T = std::remove_pointer_t<decltype(raw)>;
        const std::unique_ptr<T, StbFree<T>> data(raw);
        if (!data || decoded_w != w || decoded_h != h || decoded_channels <= 0) return;
        image.texels.resize(count);
        for (std::size_t i = 0; i < count; ++i)
            image.texels[i] =
                static_cast<float>(data.get()[i * static_cast<std::size_t>(decoded_channels)]) / divisor;
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

} // namespace

HeightMapResult load_height_map_from_memory(std::span<const std::uint8_t> bytes, const std::string& name) {
    return detail::guarded_load<HeightMapResult>(name, [&] { return decode(bytes, name); });
}

HeightMapResult load_height_map(const std::string& path) {
    return detail::guarded_load<HeightMapResult>(path, [&] {
        HeightMapResult result;
        std::vector<std::uint8_t> bytes;
        result.error.message = detail::read_file_bytes(path, max_height_file_bytes, "1 GiB", bytes);
        return result.error.message.empty() ? decode(bytes, path) : result;
    });
}

} // namespace ctess::models
