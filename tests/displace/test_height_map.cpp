// Height maps (docs/algorithm.md §8.1, docs/models.md "Height maps"): bilinear sampling at LOD 0 against an
// independent double-precision reference at power-of-two fractions (where every weight and sum is exact),
// both address modes, bad coordinates; and the PNG loader on images written here (stb_image_write for 8 bits,
// a minimal encoder on zlib for 16 bits and for headers no writer would produce: 0 x 0, 65536 x 65536).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <stb/stb_image_write.h>
#include <zlib.h>

#include <ctess/runtime/displace/displace.hpp>
#include <ctess/runtime/models/height_map.hpp>

using namespace ctess;

namespace {

// The reference: texel centres at (i + 0.5) / n, the address mode applied to integer indices, in doubles.
double reference_sample(const std::vector<float>& t, int w, int h, rt::AddressMode mode, double u, double v) {
    auto coordinate = [&](double x, int n, long& i0, double& f) {
        if (mode == rt::AddressMode::repeat)
            x -= std::floor(x);
        else
            x = std::min(1.0, std::max(0.0, x));
        const double p = x * n - 0.5;
        i0 = static_cast<long>(std::floor(p));
        f = p - std::floor(p);
    };
    auto wrap = [&](long i, int n) {
        if (mode == rt::AddressMode::repeat) return static_cast<int>(((i % n) + n) % n);
        return static_cast<int>(std::min<long>(n - 1, std::max<long>(0, i)));
    };
    long i0, j0;
    double fx, fy;
    coordinate(u, w, i0, fx);
    coordinate(v, h, j0, fy);
    auto at = [&](long i, long j) {
        return static_cast<double>(t[static_cast<std::size_t>(wrap(j, h) * w + wrap(i, w))]);
    };
    return (1 - fy) * ((1 - fx) * at(i0, j0) + fx * at(i0 + 1, j0)) +
           fy * ((1 - fx) * at(i0, j0 + 1) + fx * at(i0 + 1, j0 + 1));
}

// A PNG from raw scanlines (filter byte 0 per row), through zlib: what a 16-bit file or an impossible header
// needs and stb_image_write cannot write.
std::vector<std::uint8_t> encode_png(std::uint32_t w, std::uint32_t h, int bit_depth, int colour_type,
                                     const std::vector<std::uint8_t>& raw) {
    std::vector<std::uint8_t> out = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
    auto be32 = [](std::vector<std::uint8_t>& o, std::uint32_t x) {
        for (int s = 24; s >= 0; s -= 8) o.push_back(static_cast<std::uint8_t>(x >> s));
    };
    auto chunk = [&](const char* type, const std::vector<std::uint8_t>& data) {
        be32(out, static_cast<std::uint32_t>(data.size()));
        std::vector<std::uint8_t> body(type, type + 4);
        body.insert(body.end(), data.begin(), data.end());
        out.insert(out.end(), body.begin(), body.end());
        be32(out, static_cast<std::uint32_t>(crc32(0, body.data(), static_cast<uInt>(body.size()))));
    };
    std::vector<std::uint8_t> ihdr;
    be32(ihdr, w);
    be32(ihdr, h);
    ihdr.insert(ihdr.end(),
                {static_cast<std::uint8_t>(bit_depth), static_cast<std::uint8_t>(colour_type), 0, 0, 0});
    chunk("IHDR", ihdr);
    uLongf size = compressBound(static_cast<uLong>(raw.size()));
    std::vector<std::uint8_t> z(size);
    REQUIRE(compress(z.data(), &size, raw.data(), static_cast<uLong>(raw.size())) == Z_OK);
    z.resize(size);
    chunk("IDAT", z);
    chunk("IEND", {});
    return out;
}

struct TempDir {
    std::filesystem::path path;
    TempDir() {
        path = std::filesystem::temp_directory_path() /
               ("ctess_height_map_" + std::to_string(reinterpret_cast<std::uintptr_t>(this)) + "_" +
                std::to_string(std::rand()));
        std::filesystem::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path, ec);
    }
    std::string write(const std::string& name, const std::vector<std::uint8_t>& bytes) const {
        const std::string p = (path / name).string();
        std::ofstream(p, std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
        return p;
    }
};

void append_bytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(context);
    out->insert(out->end(), static_cast<std::uint8_t*>(data), static_cast<std::uint8_t*>(data) + size);
}

} // namespace

TEST_CASE("sample_bilinear: exact at power-of-two fractions against a double reference, both address modes") {
    const int w = 4, h = 2;
    const std::vector<float> t = {0, 3, 5, 6, 10, 20, 40, 80};
    for (const rt::AddressMode mode : {rt::AddressMode::repeat, rt::AddressMode::clamp}) {
        const rt::HeightMap map{t.data(), w, h, mode};
        for (int i = -80; i <= 160; ++i)
            for (int j = -40; j <= 80; ++j) {
                const float u = static_cast<float>(i) / 32.0f, v = static_cast<float>(j) / 16.0f;
                INFO("u " << u << " v " << v << " mode " << static_cast<int>(mode));
                REQUIRE(static_cast<double>(rt::sample_bilinear(map, u, v)) ==
                        reference_sample(t, w, h, mode, u, v));
            }
    }
}

TEST_CASE("sample_bilinear: texel centres, the edges under each mode, bad coordinates and empty maps") {
    const std::vector<float> t = {0, 1, 2, 3}; // 2 x 2
    const rt::HeightMap repeat{t.data(), 2, 2, rt::AddressMode::repeat};
    const rt::HeightMap clamp{t.data(), 2, 2, rt::AddressMode::clamp};
    CHECK(rt::sample_bilinear(repeat, 0.25f, 0.25f) == 0.0f); // texel centres read one texel
    CHECK(rt::sample_bilinear(repeat, 0.75f, 0.75f) == 3.0f);
    CHECK(rt::sample_bilinear(repeat, 0.5f, 0.5f) == 1.5f);  // the mean of the four
    CHECK(rt::sample_bilinear(repeat, 0.0f, 0.25f) == 0.5f); // wraps to texel 1
    CHECK(rt::sample_bilinear(clamp, 0.0f, 0.25f) == 0.0f);  // the edge texel extends
    CHECK(rt::sample_bilinear(repeat, 1.25f, 0.25f) == 0.0f);
    CHECK(rt::sample_bilinear(clamp, 7.0f, 0.25f) == 1.0f);
    CHECK(rt::sample_bilinear(repeat, -0.75f, 0.25f) == 0.0f);
    // Huge coordinates stay in range (repeat reduces first: a float that large is an integer, u - floor = 0).
    CHECK(rt::sample_bilinear(repeat, 1e30f, 0.25f) == 0.5f);
    CHECK(rt::sample_bilinear(clamp, -1e30f, 0.25f) == 0.0f);
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    CHECK(rt::sample_bilinear(repeat, nan, 0.5f) == 0.0f);
    CHECK(rt::sample_bilinear(clamp, 0.5f, inf) == 0.0f);
    CHECK(rt::sample_bilinear(rt::HeightMap{}, 0.5f, 0.5f) == 0.0f);
    CHECK(rt::sample_bilinear(rt::HeightMap{t.data(), 0, 2, rt::AddressMode::repeat}, 0.5f, 0.5f) == 0.0f);
    // An address mode outside the enum reads as clamp.
    const rt::HeightMap odd{t.data(), 2, 2, static_cast<rt::AddressMode>(7)};
    CHECK(rt::sample_bilinear(odd, 0.0f, 0.25f) == 0.0f);
    // The texel range, and the bound it gives: height = scale * (texel * factor + offset).
    const rt::TexelRange r = rt::texel_range(repeat);
    CHECK(r.min == 0.0f);
    CHECK(r.max == 3.0f);
    rt::Displacement d;
    d.map = repeat;
    d.scale = 0.5f;
    d.factor = 2.0f;
    d.offset = -4.0f; // heights -2 .. 1
    CHECK(rt::displacement_bound(d) == 2.0f);
    CHECK(rt::displacement_height(d, 0.75f, 0.75f) == 1.0f);
}

TEST_CASE(
    "load_height_map: 8-bit grey and RGB PNGs, and 16-bit PNGs, as c / 255 and c / 65535, first channel") {
    TempDir dir;
    // 3 x 2 grey, 8 bits, written by stb_image_write.
    const std::uint8_t grey[6] = {0, 51, 255, 17, 128, 1};
    std::vector<std::uint8_t> png;
    REQUIRE(stbi_write_png_to_func(&append_bytes, &png, 3, 2, 1, grey, 3) != 0);
    const models::HeightMapResult a = models::load_height_map(dir.write("grey.png", png));
    REQUIRE(a.ok());
    REQUIRE(a.error.message.empty());
    CHECK(a.image->width == 3);
    CHECK(a.image->height == 2);
    for (int i = 0; i < 6; ++i)
        CHECK(a.image->texels[static_cast<std::size_t>(i)] == static_cast<float>(grey[i]) / 255.0f);
    // RGB: the red channel is the height.
    const std::uint8_t rgb[6] = {10, 200, 30, 250, 0, 0}; // 2 x 1
    png.clear();
    REQUIRE(stbi_write_png_to_func(&append_bytes, &png, 2, 1, 3, rgb, 6) != 0);
    const models::HeightMapResult b = models::load_height_map_from_memory(png, "rgb");
    REQUIRE(b.ok());
    CHECK(b.image->texels == std::vector<float>{10.0f / 255.0f, 250.0f / 255.0f});
    // 16 bits, grey: big-endian samples.
    const std::uint16_t deep[4] = {0, 1, 65535, 40000}; // 2 x 2
    std::vector<std::uint8_t> raw;
    for (int row = 0; row < 2; ++row) {
        raw.push_back(0);
        for (int i = 0; i < 2; ++i) {
            raw.push_back(static_cast<std::uint8_t>(deep[row * 2 + i] >> 8));
            raw.push_back(static_cast<std::uint8_t>(deep[row * 2 + i] & 0xFF));
        }
    }
    const models::HeightMapResult c =
        models::load_height_map(dir.write("deep.png", encode_png(2, 2, 16, 0, raw)));
    REQUIRE(c.ok());
    for (int i = 0; i < 4; ++i)
        CHECK(c.image->texels[static_cast<std::size_t>(i)] == static_cast<float>(deep[i]) / 65535.0f);
    // The view samples the image, row 0 at v = 0.
    const rt::HeightMap view = c.image->view(rt::AddressMode::clamp);
    CHECK(rt::sample_bilinear(view, 0.75f, 0.25f) == 1.0f / 65535.0f);
    CHECK(rt::sample_bilinear(view, 0.25f, 0.75f) == 1.0f);
}

TEST_CASE("load_height_map: bad images give an error naming the file and no image") {
    TempDir dir;
    auto refused = [](const models::HeightMapResult& r, const std::string& name, const std::string& words) {
        INFO(r.error.message);
        CHECK_FALSE(r.ok());
        CHECK(r.error.message.rfind(name + ": ", 0) == 0);
        CHECK(r.error.message.find(words) != std::string::npos);
    };
    refused(models::load_height_map((dir.path / "missing.png").string()), (dir.path / "missing.png").string(),
            "no such file");
    refused(models::load_height_map(dir.path.string()), dir.path.string(), "no such file"); // a directory
    refused(models::load_height_map(dir.write("empty.png", {})), (dir.path / "empty.png").string(), "empty");
    const std::vector<std::uint8_t> not_image = {'G', 'I', 'F', '8', '7', 'b', 0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
    refused(models::load_height_map_from_memory(not_image, "magic"), "magic", "not an image");
    const std::vector<std::uint8_t> text = {'h', 'e', 'l', 'l', 'o', ' ', 'p', 'n', 'g'};
    refused(models::load_height_map_from_memory(text, "text"), "text", "not an image");
    // 0 x 0 and 65536 x 65536 headers (the latter with one row of data: refused before any decoding).
    refused(models::load_height_map_from_memory(encode_png(0, 0, 8, 0, {0}), "zero"), "zero",
            "empty (0 x 0)");
    refused(models::load_height_map_from_memory(encode_png(65536, 65536, 8, 0, {0, 0}), "huge"), "huge",
            "65536 x 65536");
    refused(models::load_height_map_from_memory(encode_png(20000, 1, 8, 0, {0, 0}), "wide"), "wide",
            "past the height map limit");
    // A 2 x 1 PNG whose second IDAT chunk claims 1 GiB in a 74-byte file (found by fuzz_height_map):
    // stb_image allocated the claim before reading it; refused first.
    const std::vector<std::uint8_t> claim = {
        0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44,
        0x52, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x08, 0x00, 0x00, 0x00, 0x00, 0x07,
        0x4d, 0x8e, 0xbb, 0x00, 0x00, 0x00, 0x12, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0x60,
        0x60, 0x98, 0xe3, 0xc0, 0xa0, 0xac, 0xb1, 0x3f, 0x03, 0x00, 0x08, 0xb8, 0x02, 0x4f, 0x96,
        0x74, 0x35, 0x0b, 0x40, 0x00, 0x00, 0x00, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x82};
    refused(models::load_height_map_from_memory(claim, "claim"), "claim", "runs past the end of the file");
    // Every truncation of a valid PNG.
    std::vector<std::uint8_t> png;
    std::vector<std::uint8_t> texels(16 * 16);
    for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = static_cast<std::uint8_t>(i * 7);
    REQUIRE(stbi_write_png_to_func(&append_bytes, &png, 16, 16, 1, texels.data(), 16) != 0);
    REQUIRE(models::load_height_map_from_memory(png, "whole").ok());
    std::size_t refused_prefixes = 0;
    for (std::size_t n = 0; n + 12 < png.size(); ++n) { // short of the IEND chunk's 12 bytes
        const models::HeightMapResult r =
            models::load_height_map_from_memory(std::span<const std::uint8_t>(png.data(), n), "cut");
        if (!r.ok()) {
            ++refused_prefixes;
            CHECK(r.error.message.rfind("cut: ", 0) == 0);
        } else {
            // stb_image accepts a file whose image data is complete; then every texel must be the file's.
            CHECK(r.image->texels.size() == texels.size());
            for (std::size_t i = 0; i < texels.size(); ++i)
                CHECK(r.image->texels[i] == static_cast<float>(texels[i]) / 255.0f);
        }
    }
    CHECK(refused_prefixes > 0);
}
