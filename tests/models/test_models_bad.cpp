// Bad files (docs/models.md, "Bad files"): each gives an error naming the file and the problem, and no model.
// The files are written here from bytes.
#include <catch2/catch.hpp>

#include "model_files.hpp"

using namespace ctess::models;
using namespace ctess::models::test;

namespace {

void require_error(const LoadResult& r, const std::string& name, const std::string& problem) {
    INFO(r.error.message);
    REQUIRE_FALSE(r.ok());
    REQUIRE_FALSE(r.model.has_value());
    REQUIRE(r.error.message.rfind(name + ": ", 0) == 0);
    REQUIRE(r.error.message.find(problem) != std::string::npos);
}

const float tri_positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};

// One triangle in a .glb; the accessor's count, the index values and the header's length can be overridden.
std::string triangle_glb(std::uint16_t third_index = 2, const std::string& count = "3",
                         const std::string& node = R"({"mesh":0})") {
    Bytes b;
    for (float f : tri_positions) b.put(f);
    b.put<std::uint16_t>({0, 1, third_index, 0});
    const std::string json =
        R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],"nodes":[)" + node +
        R"(],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1}]}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":)" +
        count +
        R"(,"type":"VEC3"},)"
        R"({"bufferView":1,"componentType":5123,"count":3,"type":"SCALAR"}],)"
        R"("bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":6}],)"
        R"("buffers":[{"byteLength":44}]})";
    return glb(json, b.data);
}

} // namespace

TEST_CASE("bad file: missing, unknown extension, empty") {
    const std::string missing = (scratch_dir() / "does_not_exist.obj").string();
    require_error(load_model(missing), missing, "no such file");
    const std::string ply = write_file("model.ply", "ply\n");
    require_error(load_model(ply), ply, "unknown model extension");
    for (const char* name : {"empty.obj", "empty.gltf", "empty.glb"}) {
        const std::string path = write_file(name, "");
        require_error(load_model(path), path, "empty");
    }
}

TEST_CASE("bad file: wrong magic, or content that does not match the extension") {
    std::string bytes = triangle_glb();
    REQUIRE(load_bytes(bytes, ModelKind::gltf_binary).ok());
    const std::string as_gltf = write_file("binary.gltf", bytes);
    require_error(load_model(as_gltf), as_gltf, "binary glTF");
    const std::string as_obj = write_file("binary.obj", bytes);
    require_error(load_model(as_obj), as_obj, "binary glTF");
    bytes[3] = 'X';
    const std::string bad_magic = write_file("bad_magic.glb", bytes);
    require_error(load_model(bad_magic), bad_magic, "\"glTF\"");
    const std::string text_glb = write_file("text.glb", R"({"asset":{"version":"2.0"}})");
    require_error(load_model(text_glb), text_glb, "\"glTF\"");
    const std::string not_json = write_file("not_json.gltf", "v 0 0 0\n");
    require_error(load_model(not_json), not_json, "'{'");
}

TEST_CASE("bad file: every truncation of a .glb is an error") {
    const std::string bytes = triangle_glb();
    for (std::size_t n = 0; n < bytes.size(); ++n) {
        INFO("length " << n);
        const LoadResult r = load_bytes(bytes.substr(0, n), ModelKind::gltf_binary);
        REQUIRE_FALSE(r.ok());
        REQUIRE_FALSE(r.error.message.empty());
    }
}

TEST_CASE("bad file: a .glb whose BIN chunk runs past the end is refused (tinygltf would read past it)") {
    // The file ends 8 bytes early and its header says so; the BIN chunk still claims its 44 bytes, which
    // tinygltf's own check lets through (it forgets the chunk's 8-byte header) and then copies.
    std::string bytes = triangle_glb();
    bytes.resize(bytes.size() - 8);
    const auto total = static_cast<std::uint32_t>(bytes.size());
    std::memcpy(&bytes[8], &total, 4);
    require_error(load_bytes(bytes, ModelKind::gltf_binary), "test", "second chunk runs past the end");
    // One byte short of the whole chunk, too; the whole file loads.
    bytes = triangle_glb();
    bytes.pop_back();
    const auto short_total = static_cast<std::uint32_t>(bytes.size());
    std::memcpy(&bytes[8], &short_total, 4);
    require_error(load_bytes(bytes, ModelKind::gltf_binary), "test", "second chunk runs past the end");
    CHECK(load_bytes(triangle_glb(), ModelKind::gltf_binary).ok());
}

TEST_CASE("bad file: sizes claiming 2 GB are refused before allocating") {
    std::string header = triangle_glb();
    const std::uint32_t huge = 0x80000000u;
    std::memcpy(&header[8], &huge, 4); // the GLB header's total length
    require_error(load_bytes(header, ModelKind::gltf_binary), "test", "");
    // An accessor whose count would need 24 GB of positions.
    require_error(load_bytes(triangle_glb(2, "2000000000"), ModelKind::gltf_binary), "test",
                  "run past the end of the buffer view");
    // A buffer claiming 2 GB over a 3-byte data URI.
    const std::string json = R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":2000000000,"uri":")" +
                             data_uri("abc") + R"("}]})";
    require_error(load_bytes(json, ModelKind::gltf_text), "test", "");
}

TEST_CASE("bad file: indices out of range") {
    require_error(load_bytes(triangle_glb(3), ModelKind::gltf_binary), "test",
                  "index 3 at position 2 is out of range");
    require_error(load_bytes("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", ModelKind::obj), "test",
                  "position index 9 is out of range");
    require_error(load_bytes("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//1\n", ModelKind::obj),
                  "test", "normal index 2 is out of range");
}

TEST_CASE("bad file: NaN or infinite attributes") {
    std::string bytes = triangle_glb();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::size_t bin = bytes.size() - 44; // the BIN chunk's data is the last 44 bytes
    std::memcpy(&bytes[bin + 4], &nan, 4);
    require_error(load_bytes(bytes, ModelKind::gltf_binary), "test",
                  "vertex 0 has a NaN or infinite attribute");
    // OBJ numbers tinyobjloader would read as 0 without a word, or as infinity.
    require_error(load_bytes("v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n", ModelKind::obj), "test",
                  "line 2: '1e999' is not a finite number");
    require_error(load_bytes("v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", ModelKind::obj), "test",
                  "line 1: 'nan' is not a finite number");
    require_error(load_bytes("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 abc\nf 1/1 2/1 3/1\n", ModelKind::obj),
                  "test", "line 4: 'abc' is not a finite number");
    // Signs and exponents that strtod reads are numbers.
    REQUIRE(load_bytes("v +0 -0 1e-60\nv 1E0 0 0\r\nv 0 1.5e-0 0\nf 1 2 3\n", ModelKind::obj).ok());
    require_error(load_bytes("v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n", ModelKind::obj), "test",
                  "line 2: '1e39' is not a finite number");
}

TEST_CASE("bad file: a node transform that takes a finite position past the float range is an error") {
    // 1 x 1e39 has no float value; the loader refuses it instead of converting (undefined behaviour).
    require_error(
        load_bytes(triangle_glb(2, "3", R"({"mesh":0,"scale":[1e39,1e39,1e39]})"), ModelKind::gltf_binary),
        "test", "outside the float range after its node transform");
    REQUIRE(load_bytes(triangle_glb(2, "3", R"({"mesh":0,"scale":[1e30,1e30,1e30]})"), ModelKind::gltf_binary)
                .ok());
}

TEST_CASE("bad file: a model whose faces are all degenerate, or with none, is an error") {
    require_error(load_bytes("v 0 0 0\nv 1 0 0\nf 1 2 2\nf 1 1 1\n", ModelKind::obj), "test",
                  "all 2 faces are degenerate");
    require_error(load_bytes(triangle_glb(1), ModelKind::gltf_binary), "test", "all 1 faces are degenerate");
    require_error(load_bytes("v 0 0 0\nv 1 0 0\nl 1 2\n", ModelKind::obj), "test", "empty model");
    require_error(load_bytes(R"({"asset":{"version":"2.0"}})", ModelKind::gltf_text), "test", "empty model");
}

TEST_CASE("bad file: node cycles and line primitives") {
    std::string json = R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],)"
                       R"("nodes":[{"children":[1]},{"children":[0]}]})";
    require_error(load_bytes(json, ModelKind::gltf_text), "test", "reached twice");
    Bytes b;
    for (float f : tri_positions) b.put(f);
    json = R"({"asset":{"version":"2.0"},"meshes":[{"primitives":[{"attributes":{"POSITION":0},"mode":1}]}],)"
           R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],)"
           R"("bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"byteLength":36}]})";
    require_error(load_bytes(glb(json, b.data), ModelKind::gltf_binary), "test", "mode 1 is points or lines");
}
