// Height maps through Debian's stb_image and, for OpenEXR files, the C core of Debian's OpenEXR
// (height_map.hpp, docs/models.md "Height maps"): the header is read first (stbi_info_from_memory,
// exr_start_read) and the size limits checked before any texel is decoded.
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
#include <OpenEXR/openexr.h>
#include <cmath>
#include <cstring>
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
// OpenEXR through its C core (OpenEXRCore, openexr.h), which validates what it reads against the size of the
// input: the C++ library of 3.1 reconstructs a damaged chunk table and then reads uninitialised memory (found
// by fuzz_height_map). Chunk reconstruction is off, so a damaged or incomplete file is an error.
struct ExrInput {
    std::span<const std::uint8_t> bytes;
    std::string last_error; // the core's last message
};

std::int64_t exr_read(exr_const_context_t, void* user, void* buffer, std::uint64_t size, std::uint64_t offset,
                      exr_stream_error_func_ptr_t) {
    const auto& bytes = static_cast<ExrInput*>(user)->bytes;
    if (offset >= bytes.size()) return 0;
    const std::uint64_t n = std::min<std::uint64_t>(size, bytes.size() - offset);
    std::memcpy(buffer, bytes.data() + offset, static_cast<std::size_t>(n));
    return static_cast<std::int64_t>(n);
}

std::int64_t exr_size(exr_const_context_t, void* user) {
    return static_cast<std::int64_t>(static_cast<ExrInput*>(user)->bytes.size());
}

// The core reports through this callback; the user data is reached through the context.
// Called from C frames, so nothing may escape it: a failed copy of the message leaves the previous one.
void exr_error(exr_const_context_t ctxt, exr_result_t code, const char* message) noexcept {
    void* user = nullptr;
    if (exr_get_user_data(ctxt, &user) != EXR_ERR_SUCCESS || user == nullptr) return;
    try {
        static_cast<ExrInput*>(user)->last_error =
            message != nullptr ? message : exr_get_default_error_message(code);
    } catch (...) {
    }
}

// wanted = 1: the R channel, else Y (luminance), else the file's first channel (alphabetical); wanted = 3 (a
// vector map): R, G and B, interleaved. Decoded to floats (half and uint converted); every texel must be
// finite, as the pipeline's height bound is taken over them (§8.4). Before any chunk is read, the data window
// is held to the height map's limits and the buffers the core sizes to bounds of their own: all channels
// together 2^26 samples, tiles 1 to 16384 a side and 2^26 samples each, 2^20 chunks.
HeightMapResult decode_exr(std::span<const std::uint8_t> bytes, const std::string& name, unsigned wanted) {
    HeightMapResult result;
    ExrInput input{bytes, {}};
    auto fail = [&](const std::string& problem) {
        result.error.message = name + ": " + problem;
        return result;
    };
    auto core_fail = [&](const char* what, exr_result_t code) {
        return fail(std::string("OpenEXR cannot ") + what + " (" +
                    (input.last_error.empty() ? exr_get_default_error_message(code) : input.last_error) +
                    ")");
    };
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = exr_error;
    init.user_data = &input;
    init.read_fn = exr_read;
    init.size_fn = exr_size;
    init.flags = EXR_CONTEXT_FLAG_DISABLE_CHUNK_RECONSTRUCTION;
    exr_context_t ctxt = nullptr;
    const exr_result_t opened = exr_start_read(&ctxt, name.c_str(), &init);
    const std::unique_ptr<exr_context_t, void (*)(exr_context_t*)> closer(&ctxt, [](exr_context_t* c) {
        if (*c != nullptr) exr_finish(c);
    });
    if (opened != EXR_ERR_SUCCESS) return core_fail("read the header", opened);
    int parts = 0;
    exr_storage_t storage = EXR_STORAGE_LAST_TYPE;
    exr_attr_box2i_t window{};
    const exr_attr_chlist_t* channels = nullptr;
    if (exr_get_count(ctxt, &parts) != EXR_ERR_SUCCESS || parts != 1)
        return fail("a multi-part OpenEXR file (only single-part images are read)");
    if (exr_get_storage(ctxt, 0, &storage) != EXR_ERR_SUCCESS ||
        (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED))
        return fail("a deep OpenEXR image (only flat scan-line or tiled images are read)");
    // OpenEXR 3.1's core cannot decode DWA (openexr issues #1384, #1591): refused by name, not as damage.
    exr_compression_t compression = EXR_COMPRESSION_LAST_TYPE;
    if (const exr_result_t r = exr_get_compression(ctxt, 0, &compression); r != EXR_ERR_SUCCESS)
        return core_fail("read the compression", r);
    if (compression == EXR_COMPRESSION_DWAA || compression == EXR_COMPRESSION_DWAB)
        return fail(std::string(compression == EXR_COMPRESSION_DWAA ? "DWAA" : "DWAB") +
                    "-compressed OpenEXR images are not read (the OpenEXR 3.1 core cannot decode them); save "
                    "it with ZIP, PIZ or no compression");
    if (const exr_result_t r = exr_get_data_window(ctxt, 0, &window); r != EXR_ERR_SUCCESS)
        return core_fail("read the data window", r);
    if (const exr_result_t r = exr_get_channels(ctxt, 0, &channels);
        r != EXR_ERR_SUCCESS || channels == nullptr)
        return core_fail("read the channels", r);
    const std::int64_t w64 = std::int64_t{window.max.x} - window.min.x + 1,
                       h64 = std::int64_t{window.max.y} - window.min.y + 1;
    if (std::string problem = size_problem(w64 > 0 ? static_cast<std::uint64_t>(w64) : 0,
                                           h64 > 0 ? static_cast<std::uint64_t>(h64) : 0);
        !problem.empty())
        return fail(problem);
    const std::uint64_t w = static_cast<std::uint64_t>(w64), h = static_cast<std::uint64_t>(h64);
    const auto channel_count = static_cast<std::uint64_t>(channels->num_channels);
    if (channel_count == 0) return fail("the OpenEXR image has no channels");
    if (w * h * channel_count > max_height_map_texels)
        return fail("the OpenEXR image holds " + std::to_string(w) + " x " + std::to_string(h) +
                    " texels of " + std::to_string(channel_count) +
                    " channels, past the limit of 2^26 samples");
    std::uint32_t tile_w = 0, tile_h = 0;
    if (storage == EXR_STORAGE_TILED) {
        exr_tile_level_mode_t level = EXR_TILE_LAST_TYPE;
        exr_tile_round_mode_t round = EXR_TILE_ROUND_LAST_TYPE;
        if (const exr_result_t r = exr_get_tile_descriptor(ctxt, 0, &tile_w, &tile_h, &level, &round);
            r != EXR_ERR_SUCCESS)
            return core_fail("read the tiles", r);
        const std::uint64_t tw = tile_w, th = tile_h;
        if (tw == 0 || th == 0 || tw > max_height_map_side || th > max_height_map_side ||
            tw * th * channel_count > max_height_map_texels)
            return fail("the OpenEXR tiles are " + std::to_string(tw) + " x " + std::to_string(th) +
                        ", outside the limits (sides 1 to 16384, at most 2^26 samples a tile)");
    }
    std::int32_t chunks = 0;
    if (const exr_result_t r = exr_get_chunk_count(ctxt, 0, &chunks); r != EXR_ERR_SUCCESS || chunks <= 0)
        return core_fail("count the chunks", r);
    if (chunks > (1 << 20))
        return fail("the OpenEXR image has " + std::to_string(chunks) + " chunks, past the limit of 2^20");

    // The channels wanted, by their index in the (alphabetical) channel list.
    const auto find = [&](const char* wanted_name) {
        for (int c = 0; c < channels->num_channels; ++c)
            if (channels->entries[c].name.str != nullptr &&
                std::strcmp(channels->entries[c].name.str, wanted_name) == 0)
                return c;
        return -1;
    };
    std::vector<int> picked;
    if (wanted == 3) {
        for (const char* c : {"R", "G", "B"}) picked.push_back(find(c));
        if (std::find(picked.begin(), picked.end(), -1) != picked.end())
            return fail("the OpenEXR image has no R, G and B channels; a vector displacement map needs them");
    } else {
        const int r = find("R"), y = find("Y");
        picked.push_back(r >= 0 ? r : y >= 0 ? y : 0);
    }
    for (const int c : picked)
        if (channels->entries[c].x_sampling != 1 || channels->entries[c].y_sampling != 1)
            return fail(std::string("the OpenEXR channel '") + channels->entries[c].name.str +
                        "' is subsampled");

    HeightImage image;
    image.channels = wanted;
    image.width = static_cast<std::uint32_t>(w);
    image.height = static_cast<std::uint32_t>(h);
    // Every chunk's info (its place, read from the chunk table and the chunk's own leader) is read and
    // checked first, then the image is allocated and the chunks decoded: a file with a damaged chunk
    // allocates nothing.
    std::int32_t lines = 0;
    if (storage == EXR_STORAGE_SCANLINE) {
        if (const exr_result_t r = exr_get_scanlines_per_chunk(ctxt, 0, &lines);
            r != EXR_ERR_SUCCESS || lines <= 0)
            return core_fail("read the chunk height", r);
    }
    const auto for_each_chunk = [&](auto&& per_chunk) -> exr_result_t {
        const bool tiled = storage == EXR_STORAGE_TILED;
        const std::uint64_t across = tiled ? (w + tile_w - 1) / tile_w : 1,
                            down = tiled ? (h + tile_h - 1) / tile_h
                                         : (h + static_cast<std::uint64_t>(lines) - 1) /
                                               static_cast<std::uint64_t>(lines);
        for (std::uint64_t j = 0; j < down; ++j)
            for (std::uint64_t i = 0; i < across; ++i) {
                exr_chunk_info_t chunk{};
                exr_result_t r =
                    tiled
                        ? exr_read_tile_chunk_info(ctxt, 0, static_cast<int>(i), static_cast<int>(j), 0, 0,
                                                   &chunk)
                        : exr_read_scanline_chunk_info(
                              ctxt, 0, static_cast<int>(window.min.y + static_cast<std::int64_t>(j) * lines),
                              &chunk);
                // The chunk's place in the image: a scan-line chunk names its first line, a tile its column
                // and row (openexr_chunkio.h); it must lie inside the image.
                const std::int64_t x0 = tiled ? std::int64_t{chunk.start_x} * tile_w : 0,
                                   y0 = tiled ? std::int64_t{chunk.start_y} * tile_h
                                              : chunk.start_y - std::int64_t{window.min.y};
                if (r == EXR_ERR_SUCCESS &&
                    (x0 < 0 || y0 < 0 || chunk.width < 0 || chunk.height < 0 ||
                     static_cast<std::uint64_t>(x0) + static_cast<std::uint64_t>(chunk.width) > w ||
                     static_cast<std::uint64_t>(y0) + static_cast<std::uint64_t>(chunk.height) > h))
                    r = EXR_ERR_BAD_CHUNK_LEADER;
                if (r == EXR_ERR_SUCCESS)
                    r = per_chunk(chunk, static_cast<std::uint64_t>(x0), static_cast<std::uint64_t>(y0));
                if (r != EXR_ERR_SUCCESS) return r;
            }
        return EXR_ERR_SUCCESS;
    };
    if (const exr_result_t r = for_each_chunk(
            [](const exr_chunk_info_t&, std::uint64_t, std::uint64_t) { return EXR_ERR_SUCCESS; });
        r != EXR_ERR_SUCCESS)
        return core_fail("read the chunk table", r);
    image.texels.assign(w * h * wanted, 0.0f);
    // One chunk at a time into the image, each with its own decoder: its picked channels as floats at the
    // chunk's place.
    std::vector<float> scratch;
    const auto decode_chunk = [&](const exr_chunk_info_t& chunk, std::uint64_t x0,
                                  std::uint64_t y0) -> exr_result_t {
        exr_decode_pipeline_t decoder{}; // all zero, as EXR_DECODE_PIPELINE_INITIALIZER
        exr_result_t r = exr_decoding_initialize(ctxt, 0, &chunk, &decoder);
        if (r != EXR_ERR_SUCCESS) return r;
        // Every channel gets a destination: OpenEXR 3.1's unpacker can crash on a skipped (null) one, so the
        // channels not wanted go to one scratch plane of the chunk's size.
        scratch.resize(static_cast<std::size_t>(chunk.width) * static_cast<std::size_t>(chunk.height));
        for (int c = 0; c < decoder.channel_count; ++c) {
            exr_coding_channel_info_t& out = decoder.channels[c];
            out.decode_to_ptr = reinterpret_cast<std::uint8_t*>(scratch.data());
            out.user_pixel_stride = sizeof(float);
            out.user_line_stride =
                static_cast<std::int32_t>(sizeof(float) * static_cast<std::size_t>(chunk.width));
            out.user_data_type = EXR_PIXEL_FLOAT;
            out.user_bytes_per_element = sizeof(float);
        }
        for (unsigned k = 0; k < wanted; ++k) {
            exr_coding_channel_info_t& out = decoder.channels[picked[k]];
            out.decode_to_ptr =
                reinterpret_cast<std::uint8_t*>(image.texels.data() + (y0 * w + x0) * wanted + k);
            out.user_pixel_stride = static_cast<std::int32_t>(sizeof(float) * wanted);
            out.user_line_stride = static_cast<std::int32_t>(sizeof(float) * wanted * w);
        }
        r = exr_decoding_choose_default_routines(ctxt, 0, &decoder);
        if (r == EXR_ERR_SUCCESS) r = exr_decoding_run(ctxt, 0, &decoder);
        exr_decoding_destroy(ctxt, &decoder);
        return r;
    };
    if (const exr_result_t r = for_each_chunk(decode_chunk); r != EXR_ERR_SUCCESS)
        return core_fail("decode the image", r);
    for (std::size_t i = 0; i < image.texels.size(); ++i)
        if (!std::isfinite(image.texels[i]))
            return fail("the OpenEXR texel (" + std::to_string(i / wanted % image.width) + ", " +
                        std::to_string(i / wanted / image.width) + ") is not finite");
    result.image = std::move(image);
    return result;
}
#else
HeightMapResult decode_exr(std::span<const std::uint8_t>, const std::string& name, unsigned) {
    HeightMapResult result;
    result.error.message = name +
                           ": an OpenEXR image, and this build of ctess::models has no OpenEXR (Debian "
                           "libopenexr-dev)";
    return result;
}
#endif

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
    if (is_exr(bytes)) return decode_exr(bytes, name, wanted);
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
        // Every chunk (length, type, data, CRC) inside the file, up to IEND: stb_image allocates an IDAT
        // chunk's claimed length before reading it (a 74-byte file claiming 1 GiB asked for 2 GiB,
        // fuzz_height_map), so no claim may pass the bytes there are.
        for (std::size_t at = 8; at + 8 <= bytes.size();) {
            const std::uint64_t next = at + std::uint64_t{12} + be32(at);
            if (next > bytes.size())
                return fail("a PNG chunk runs past the end of the file (truncated or corrupt)");
            if (std::equal(bytes.begin() + static_cast<std::ptrdiff_t>(at + 4),
                           bytes.begin() + static_cast<std::ptrdiff_t>(at + 8), "IEND"))
                break;
            at = static_cast<std::size_t>(next);
        }
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
        const T* in = data.get();
        float* out = image.texels.data();
        const auto stride = static_cast<std::size_t>(decoded_channels);
        // One loop per channel count, so that each texel costs no inner loop (the fuzz build traces every
        // comparison).
        if (wanted == 1) {
            for (std::size_t i = 0; i < count; ++i) out[i] = static_cast<float>(in[i * stride]) / divisor;
        } else {
            for (std::size_t i = 0; i < count; ++i) {
                out[3 * i] = static_cast<float>(in[i * stride]) / divisor;
                out[3 * i + 1] = static_cast<float>(in[i * stride + 1]) / divisor;
                out[3 * i + 2] = static_cast<float>(in[i * stride + 2]) / divisor;
            }
        }
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
