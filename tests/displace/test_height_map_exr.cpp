// OpenEXR height maps (docs/models.md "Height maps"): images written here with OpenEXR's own writer (scan
// lines and tiles, half and float, several compressions, a data window off the origin) must load with exactly
// the texels written; the channel rule (R, else Y, else the first); and bad files: every truncated prefix, a
// 65536 x 65536 or empty data window, an attribute claiming more bytes than the file has, too many samples,
// tiles or chunks, non-finite texels, deep or multi-part flags. Each gives an error naming the input and no
// image.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfTileDescriptionAttribute.h>
#include <OpenEXR/ImfTiledOutputFile.h>

#include <ctess/runtime/models/height_map.hpp>

using namespace ctess;

namespace {

struct ExrChannel {
    std::string name;
    Imf::PixelType type = Imf::HALF;
    std::vector<float> texels; // row-major over the data window
};

// An EXR file in memory from OpenEXR's writer: channels over the data window (x0, y0) .. (x0 + w - 1, y0 + h
// - 1).
std::vector<std::uint8_t> write_exr(int w, int h, const std::vector<ExrChannel>& channels, int x0 = 0,
                                    int y0 = 0, Imf::Compression compression = Imf::ZIP_COMPRESSION,
                                    bool tiled = false) {
    const Imath::Box2i window({x0, y0}, {x0 + w - 1, y0 + h - 1});
    Imf::Header header(window, window);
    header.compression() = compression;
    if (tiled) header.setTileDescription(Imf::TileDescription(4, 4, Imf::ONE_LEVEL));
    // Owned storage per channel, in the channel's own pixel type.
    std::vector<std::vector<half>> halves(channels.size());
    std::vector<std::vector<float>> floats(channels.size());
    Imf::FrameBuffer frame;
    for (std::size_t c = 0; c < channels.size(); ++c) {
        header.channels().insert(channels[c].name, Imf::Channel(channels[c].type));
        const auto& t = channels[c].texels;
        if (channels[c].type == Imf::HALF) {
            halves[c].assign(t.begin(), t.end());
            frame.insert(channels[c].name, Imf::Slice::Make(Imf::HALF, halves[c].data(), window, sizeof(half),
                                                            sizeof(half) * static_cast<std::size_t>(w)));
        } else {
            floats[c] = t;
            frame.insert(channels[c].name,
                         Imf::Slice::Make(Imf::FLOAT, floats[c].data(), window, sizeof(float),
                                          sizeof(float) * static_cast<std::size_t>(w)));
        }
    }
    std::ostringstream bytes;
    {
        Imf::StdOSStream stream;
        if (tiled) {
            Imf::TiledOutputFile file(stream, header);
            file.setFrameBuffer(frame);
            file.writeTiles(0, file.numXTiles() - 1, 0, file.numYTiles() - 1);
        } else {
            Imf::OutputFile file(stream, header);
            file.setFrameBuffer(frame);
            file.writePixels(h);
        }
        const std::string s = stream.str();
        return {s.begin(), s.end()};
    }
}

// Values exact in half: k / 8 for k in [-16, 16).
std::vector<float> eighths(int count, int start) {
    std::vector<float> t(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i)
        t[static_cast<std::size_t>(i)] = static_cast<float>((start + 5 * i) % 32 - 16) / 8.0f;
    return t;
}

// The offset of the value of the header attribute `name` (its int32 size sits just before).
std::size_t attribute_value(const std::vector<std::uint8_t>& file, const std::string& name,
                            const std::string& type) {
    std::string key = name;
    key.push_back('\0');
    key += type;
    key.push_back('\0');
    const auto at = std::search(file.begin(), file.end(), key.begin(), key.end());
    REQUIRE(at != file.end());
    return static_cast<std::size_t>(at - file.begin()) + key.size() + 4;
}

void put_le32(std::vector<std::uint8_t>& file, std::size_t at, std::int32_t value) {
    for (int b = 0; b < 4; ++b)
        file[at + static_cast<std::size_t>(b)] =
            static_cast<std::uint8_t>(static_cast<std::uint32_t>(value) >> (8 * b));
}

} // namespace

TEST_CASE("load_height_map: OpenEXR scan lines and tiles, half and float, load exactly the texels written") {
    // 37 rows: several chunks of ZIP's 16 and PIZ's 32 lines and of the 4 x 4 tiles, each with a partial last
    // one.
    const int w = 7, h = 37;
    const std::vector<float> red = eighths(w * h, 3), green = eighths(w * h, 11);
    struct Variant {
        const char* what;
        Imf::PixelType type;
        Imf::Compression compression;
        bool tiled;
        int x0, y0;
    };
    const Variant variants[] = {
        {"half, ZIP", Imf::HALF, Imf::ZIP_COMPRESSION, false, 0, 0},
        {"half, PIZ", Imf::HALF, Imf::PIZ_COMPRESSION, false, 0, 0},
        {"float, none", Imf::FLOAT, Imf::NO_COMPRESSION, false, 0, 0},
        {"float, RLE, window at (-3, 12)", Imf::FLOAT, Imf::RLE_COMPRESSION, false, -3, 12},
        {"half, tiled 4 x 4, ZIPS", Imf::HALF, Imf::ZIPS_COMPRESSION, true, 0, 0},
        {"float, tiled, window at (5, -2)", Imf::FLOAT, Imf::ZIP_COMPRESSION, true, 5, -2},
    };
    for (const Variant& v : variants) {
        INFO(v.what);
        // G before R in the file's (alphabetical) order: the height is R all the same.
        const auto file =
            write_exr(w, h, {{"G", v.type, green}, {"R", v.type, red}}, v.x0, v.y0, v.compression, v.tiled);
        const auto result = models::load_height_map_from_memory(file, "test.exr");
        INFO(result.error.message);
        REQUIRE(result.ok());
        CHECK(result.image->width == static_cast<std::uint32_t>(w));
        CHECK(result.image->height == static_cast<std::uint32_t>(h));
        CHECK(result.image->texels == red); // the data window's first row first
    }
}

TEST_CASE("load_height_map: the OpenEXR channel is R, else Y, else the file's first") {
    const std::vector<float> a = eighths(6, 1), b = eighths(6, 7), c = eighths(6, 13);
    const auto texels_of = [](const std::vector<std::uint8_t>& file) {
        const auto result = models::load_height_map_from_memory(file, "test.exr");
        INFO(result.error.message);
        REQUIRE(result.ok());
        return result.image->texels;
    };
    CHECK(texels_of(write_exr(3, 2, {{"B", Imf::HALF, a}, {"Y", Imf::HALF, b}, {"Z", Imf::HALF, c}})) == b);
    CHECK(texels_of(write_exr(3, 2, {{"R", Imf::HALF, a}, {"Y", Imf::HALF, b}})) == a);
    CHECK(texels_of(write_exr(3, 2, {{"height", Imf::FLOAT, c}, {"mask", Imf::FLOAT, a}})) == c);
}

TEST_CASE(
    "load_vector_map: an OpenEXR vector map is its R, G and B, interleaved, without all three, an error") {
    const int w = 5, h = 3;
    const std::vector<float> r = eighths(w * h, 1), g = eighths(w * h, 9), b = eighths(w * h, 17);
    for (const bool tiled : {false, true}) {
        INFO("tiled " << tiled);
        const auto file = write_exr(
            w, h, {{"A", Imf::HALF, g}, {"B", Imf::FLOAT, b}, {"G", Imf::HALF, g}, {"R", Imf::HALF, r}}, 2,
            -1, Imf::PIZ_COMPRESSION, tiled);
        const auto result = models::load_vector_map_from_memory(file, "vector.exr");
        INFO(result.error.message);
        REQUIRE(result.ok());
        CHECK(result.image->channels == 3);
        REQUIRE(result.image->texels.size() == 3u * w * h);
        for (std::size_t i = 0; i < r.size(); ++i) {
            CHECK(result.image->texels[3 * i] == r[i]);
            CHECK(result.image->texels[3 * i + 1] == g[i]);
            CHECK(result.image->texels[3 * i + 2] == b[i]);
        }
        // As a height map the same file is its R channel.
        const auto height = models::load_height_map_from_memory(file, "vector.exr");
        REQUIRE(height.ok());
        CHECK(height.image->texels == r);
    }
    const auto grey = models::load_vector_map_from_memory(write_exr(w, h, {{"Y", Imf::HALF, r}}), "grey.exr");
    CHECK_FALSE(grey.ok());
    CHECK(grey.error.message ==
          "grey.exr: the OpenEXR image has no R, G and B channels; a vector displacement "
          "map needs them");
    auto nan = b;
    nan[7] = std::numeric_limits<float>::quiet_NaN();
    const auto bad = models::load_vector_map_from_memory(
        write_exr(w, h, {{"B", Imf::FLOAT, nan}, {"G", Imf::FLOAT, g}, {"R", Imf::FLOAT, r}}), "nan.exr");
    CHECK_FALSE(bad.ok());
    CHECK(bad.error.message == "nan.exr: the OpenEXR texel (2, 1) is not finite");
}

TEST_CASE("load_height_map: an OpenEXR file from disk, by path") {
    const auto dir = std::filesystem::temp_directory_path() / "ctess_test_height_exr";
    std::filesystem::create_directories(dir);
    const auto path = (dir / "height.exr").string();
    const std::vector<float> red = eighths(12, 5);
    const auto file = write_exr(4, 3, {{"R", Imf::HALF, red}});
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(file.data()), static_cast<std::streamsize>(file.size()));
    const auto result = models::load_height_map(path);
    INFO(result.error.message);
    REQUIRE(result.ok());
    CHECK(result.image->texels == red);
    std::filesystem::remove_all(dir);
}

TEST_CASE("load_height_map: bad OpenEXR files give an error naming the input and no image") {
    const std::vector<float> red = eighths(35, 2);
    const auto good = write_exr(7, 5, {{"R", Imf::HALF, red}});
    const auto refused = [](const std::vector<std::uint8_t>& file, const std::string& reason) {
        const auto result = models::load_height_map_from_memory(file, "bad.exr");
        INFO(result.error.message);
        CHECK_FALSE(result.ok());
        CHECK(result.error.message.rfind("bad.exr: ", 0) == 0);
        if (!reason.empty()) CHECK(result.error.message.find(reason) != std::string::npos);
    };

    SECTION("every truncated prefix, scan lines and tiles: refused, or (the pixels complete) every texel") {
        const auto tiled = write_exr(7, 5, {{"R", Imf::HALF, red}}, 0, 0, Imf::ZIP_COMPRESSION, true);
        for (const auto* file : {&good, &tiled})
            for (std::size_t n = 1; n < file->size(); ++n) {
                INFO("prefix of " << n << " bytes of " << file->size());
                const std::vector<std::uint8_t> prefix(file->begin(),
                                                       file->begin() + static_cast<std::ptrdiff_t>(n));
                const auto result = models::load_height_map_from_memory(prefix, "bad.exr");
                if (result.ok())
                    CHECK(result.image->texels == red);
                else
                    CHECK(result.error.message.rfind("bad.exr: ", 0) == 0);
            }
    }
    SECTION("DWAA and DWAB, which the OpenEXR 3.1 core cannot decode, are refused by name") {
        refused(write_exr(7, 5, {{"R", Imf::HALF, red}}, 0, 0, Imf::DWAA_COMPRESSION),
                "DWAA-compressed OpenEXR images are not read");
        refused(write_exr(7, 5, {{"R", Imf::FLOAT, red}}, 0, 0, Imf::DWAB_COMPRESSION),
                "DWAB-compressed OpenEXR images are not read");
    }
    SECTION("a 65536 x 65536 data window is refused after the header, before any chunk is read") {
        auto file = good;
        const std::size_t at = attribute_value(file, "dataWindow", "box2i");
        put_le32(file, at + 8, 65535);
        put_le32(file, at + 12, 65535);
        refused(file, "65536 x 65536, past the height map limit");
    }
    SECTION("a data window within the texel limit whose channels together pass 2^26 samples") {
        auto file = write_exr(7, 5, {{"G", Imf::HALF, red}, {"R", Imf::HALF, red}});
        const std::size_t at = attribute_value(file, "dataWindow", "box2i");
        put_le32(file, at + 8, 16383); // 16384 x 4096 = 2^26 texels, times 2 channels
        put_le32(file, at + 12, 4095);
        refused(file, "16384 x 4096 texels of 2 channels, past the limit of 2^26 samples");
    }
    SECTION("tiles too large or too many: refused before any chunk is read") {
        const auto tiled = write_exr(7, 5, {{"R", Imf::HALF, red}}, 0, 0, Imf::ZIP_COMPRESSION, true);
        REQUIRE(models::load_height_map_from_memory(tiled).ok());
        auto huge_tile = tiled;
        put_le32(huge_tile, attribute_value(huge_tile, "tiles", "tiledesc") + 4, 0x0a000004);
        refused(huge_tile, "the OpenEXR tiles are 4 x 167772164, outside the limits");
        auto many_tiles = tiled; // 4 x 4 tiles over 16384 x 4096: 2^22 tiles
        const std::size_t at = attribute_value(many_tiles, "dataWindow", "box2i");
        put_le32(many_tiles, at + 8, 16383);
        put_le32(many_tiles, at + 12, 4095);
        refused(many_tiles, "the OpenEXR image has 4194304 chunks, past the limit of 2^20");
    }
    SECTION("an empty data window (max below min)") {
        auto file = good;
        const std::size_t at = attribute_value(file, "dataWindow", "box2i");
        put_le32(file, at + 8, -1);
        refused(file, "OpenEXR cannot read the header (Invalid data window");
    }
    SECTION("an attribute claiming more bytes than the file holds") {
        auto file = good;
        put_le32(file, attribute_value(file, "compression", "compression") - 4, 0x7fffff00);
        refused(file, "OpenEXR cannot");
    }
    SECTION("non-finite texels") {
        for (const float bad :
             {std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()}) {
            auto texels = red;
            texels[9] = bad;
            refused(write_exr(7, 5, {{"R", Imf::FLOAT, texels}}), "texel (2, 1) is not finite");
        }
    }
    SECTION("deep or multi-part flags, another version") {
        for (const std::uint8_t flag : {std::uint8_t{0x08}, std::uint8_t{0x10}}) {
            auto file = good;
            file[5] = static_cast<std::uint8_t>(file[5] | flag);
            refused(file, "OpenEXR cannot read the header");
        }
        auto file = good;
        file[4] = 3;
        refused(file, "OpenEXR cannot read the header (File is of an unsupported version");
    }
    SECTION("the magic alone") {
        refused({0x76, 0x2f, 0x31, 0x01}, "OpenEXR cannot read the header");
    }
}
