// Test helpers for tests/models/: files written from bytes into the build folder, base64 for data URIs, GLB
// containers built by hand (glTF 2.0 §4.4, binary glTF layout), and packed little-endian buffers.
#pragma once
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <ctess/runtime/models.hpp>

namespace ctess::models::test {

inline std::filesystem::path scratch_dir() {
    const std::filesystem::path dir = std::filesystem::path(CTESS_TEST_BINARY_DIR) / "models_scratch";
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::string write_file(const std::string& name, const std::string& bytes) {
    const std::filesystem::path path = scratch_dir() / name;
    std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return path.string();
}

inline std::string bytes_of(const std::vector<std::uint8_t>& v) {
    return std::string(v.begin(), v.end());
}

// Appends values as little-endian bytes (x86_64 and every glTF buffer are little-endian).
struct Bytes {
    std::string data;
    template <class T>
    Bytes& put(T value) {
        char b[sizeof(T)];
        std::memcpy(b, &value, sizeof(T));
        data.append(b, sizeof(T));
        return *this;
    }
    template <class T>
    Bytes& put(std::initializer_list<T> values) {
        for (T v : values) put(v);
        return *this;
    }
};

inline std::string base64(const std::string& in) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < in.size(); i += 3) {
        const unsigned n =
            (std::uint8_t(in[i]) << 16) | (std::uint8_t(in[i + 1]) << 8) | std::uint8_t(in[i + 2]);
        for (int k = 18; k >= 0; k -= 6) out += alphabet[(n >> k) & 63];
    }
    if (i + 1 == in.size()) {
        const unsigned n = std::uint8_t(in[i]) << 16;
        out += alphabet[(n >> 18) & 63];
        out += alphabet[(n >> 12) & 63];
        out += "==";
    } else if (i + 2 == in.size()) {
        const unsigned n = (std::uint8_t(in[i]) << 16) | (std::uint8_t(in[i + 1]) << 8);
        for (int k = 18; k >= 6; k -= 6) out += alphabet[(n >> k) & 63];
        out += "=";
    }
    return out;
}

inline std::string data_uri(const std::string& bytes) {
    return "data:application/octet-stream;base64," + base64(bytes);
}

// A GLB: 12-byte header, a JSON chunk padded with spaces, a BIN chunk padded with zeros.
inline std::string glb(std::string json, std::string bin) {
    while (json.size() % 4) json += ' ';
    while (bin.size() % 4) bin += '\0';
    Bytes out;
    const auto total = static_cast<std::uint32_t>(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size()));
    out.data = "glTF";
    out.put<std::uint32_t>(2).put<std::uint32_t>(total);
    out.put<std::uint32_t>(static_cast<std::uint32_t>(json.size())).put<std::uint32_t>(0x4E4F534Au);
    out.data += json;
    if (!bin.empty()) {
        out.put<std::uint32_t>(static_cast<std::uint32_t>(bin.size())).put<std::uint32_t>(0x004E4942u);
        out.data += bin;
    }
    return out.data;
}

inline LoadResult load_bytes(const std::string& bytes, ModelKind kind) {
    return load_model_from_memory(
        std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()),
        kind, "test");
}

inline const float* vertex(const Model& m, std::size_t i) {
    return m.vertices.data() + i * model_vertex_floats;
}

} // namespace ctess::models::test
