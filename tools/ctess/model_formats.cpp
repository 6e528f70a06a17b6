#include "model_formats.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>
#include <span>
#include <stdexcept>

#include <fmt/core.h>
#include <tiny_gltf.h>

namespace ctess::cli {

namespace {

std::string one_line(std::string_view text) {
    std::string s(text);
    std::replace_if(
        s.begin(), s.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    return s;
}

// The files' binary parts are written with memcpy of whole values and runs of values: the host is
// little-endian (x86-64, AArch64), as PLY's binary_little_endian and glTF are.
static_assert(std::endian::native == std::endian::little);

// Floats `first` to `first + count - 1` of every 8-float vertex, packed, from `to` on (a glTF accessor's
// data).
unsigned char* copy_columns(std::span<const float> vertices, std::size_t first, std::size_t count,
                            unsigned char* to) {
    for (std::size_t i = 0; i < vertices.size() / 8; ++i, to += 4 * count)
        std::memcpy(to, &vertices[8 * i + first], 4 * count);
    return to;
}

} // namespace

std::string mesh_to_obj(const OutputMesh& mesh, std::string_view comment) {
    std::string out = fmt::format("# {}\n# {} vertices, {} triangles\n", one_line(comment),
                                  mesh.vertex_count(), mesh.triangle_count());
    const float* v = mesh.vertices.data();
    for (std::size_t i = 0; i < mesh.vertex_count(); ++i)
        out += fmt::format("v {:.9g} {:.9g} {:.9g}\n", v[8 * i], v[8 * i + 1], v[8 * i + 2]);
    for (std::size_t i = 0; i < mesh.vertex_count(); ++i)
        out += fmt::format("vn {:.9g} {:.9g} {:.9g}\n", v[8 * i + 3], v[8 * i + 4], v[8 * i + 5]);
    for (std::size_t i = 0; i < mesh.vertex_count(); ++i)
        out += fmt::format("vt {:.9g} {:.9g}\n", v[8 * i + 6], v[8 * i + 7]);
    for (std::size_t t = 0; t < mesh.triangles.size(); t += 3)
        out += fmt::format("f {0}/{0}/{0} {1}/{1}/{1} {2}/{2}/{2}\n", mesh.triangles[t] + 1,
                           mesh.triangles[t + 1] + 1, mesh.triangles[t + 2] + 1);
    return out;
}

void write_ply(const OutputMesh& mesh, std::string_view comment, std::ostream& out) {
    const std::string header =
        fmt::format("ply\nformat binary_little_endian 1.0\ncomment {}\nelement vertex {}\n"
                    "property float x\nproperty float y\nproperty float z\n"
                    "property float nx\nproperty float ny\nproperty float nz\n"
                    "property float s\nproperty float t\nelement face {}\n"
                    "property list uchar uint vertex_indices\nend_header\n",
                    one_line(comment), mesh.vertex_count(), mesh.triangle_count());
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    // The vertices as they are (x y z nx ny nz s t, float32), one write; then per face a count byte and three
    // uint32, in blocks.
    out.write(reinterpret_cast<const char*>(mesh.vertices.data()),
              static_cast<std::streamsize>(mesh.vertices.size() * 4));
    constexpr std::size_t block = 4096;
    char faces[13 * block];
    for (std::size_t t = 0; t < mesh.triangle_count(); t += block) {
        const std::size_t count = std::min(block, mesh.triangle_count() - t);
        for (std::size_t k = 0; k < count; ++k) {
            faces[13 * k] = 3;
            std::memcpy(&faces[13 * k + 1], &mesh.triangles[3 * (t + k)], 12);
        }
        out.write(faces, static_cast<std::streamsize>(13 * count));
    }
}

void write_glb(const OutputMesh& mesh, std::string_view comment, std::ostream& out) {
    // One buffer: positions, normals, uvs (each tightly packed, as glTF accessors with min/max on POSITION),
    // then the indices. glTF requires POSITION's min and max.
    const std::size_t n = mesh.vertex_count();
    if (n == 0 || mesh.triangles.empty())
        throw std::runtime_error("the tessellated model is empty: nothing to write");
    // GLB chunk lengths are 32-bit: a larger buffer would be written with wrapped lengths.
    if (n * 32 + mesh.triangles.size() * 4 > 0xFFFF0000u)
        throw std::runtime_error(
            "the tessellated model needs more than 4 GiB, past binary glTF's 32-bit lengths: "
            "write .ply or .obj");
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = one_line(comment);
    tinygltf::Buffer buffer;
    buffer.data.resize(n * 32 + mesh.triangles.size() * 4);
    std::vector<double> lo(3, std::numeric_limits<double>::infinity()),
        hi(3, -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) {
            const float f = mesh.vertices[8 * i + k];
            lo[k] = std::min<double>(lo[k], f);
            hi[k] = std::max<double>(hi[k], f);
        }
    unsigned char* to = buffer.data.data();
    to = copy_columns(mesh.vertices, 0, 3, to); // positions
    to = copy_columns(mesh.vertices, 3, 3, to); // normals
    to = copy_columns(mesh.vertices, 6, 2, to); // uvs
    std::memcpy(to, mesh.triangles.data(), mesh.triangles.size() * 4);
    model.buffers.push_back(std::move(buffer));

    const auto add_view = [&](std::size_t offset, std::size_t length, int target) {
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = offset;
        view.byteLength = length;
        view.target = target;
        model.bufferViews.push_back(view);
        return static_cast<int>(model.bufferViews.size() - 1);
    };
    const auto add_accessor = [&](int view, int component, std::size_t count, int type) {
        tinygltf::Accessor accessor;
        accessor.bufferView = view;
        accessor.componentType = component;
        accessor.count = count;
        accessor.type = type;
        model.accessors.push_back(accessor);
        return static_cast<int>(model.accessors.size() - 1);
    };
    const int position = add_accessor(add_view(0, n * 12, TINYGLTF_TARGET_ARRAY_BUFFER),
                                      TINYGLTF_COMPONENT_TYPE_FLOAT, n, TINYGLTF_TYPE_VEC3);
    model.accessors[static_cast<std::size_t>(position)].minValues = lo;
    model.accessors[static_cast<std::size_t>(position)].maxValues = hi;
    const int normal = add_accessor(add_view(n * 12, n * 12, TINYGLTF_TARGET_ARRAY_BUFFER),
                                    TINYGLTF_COMPONENT_TYPE_FLOAT, n, TINYGLTF_TYPE_VEC3);
    const int uv = add_accessor(add_view(n * 24, n * 8, TINYGLTF_TARGET_ARRAY_BUFFER),
                                TINYGLTF_COMPONENT_TYPE_FLOAT, n, TINYGLTF_TYPE_VEC2);
    const int indices =
        add_accessor(add_view(n * 32, mesh.triangles.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, mesh.triangles.size(), TINYGLTF_TYPE_SCALAR);
    tinygltf::Primitive primitive;
    primitive.attributes = {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}};
    primitive.indices = indices;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh gltf_mesh;
    gltf_mesh.primitives.push_back(primitive);
    model.meshes.push_back(gltf_mesh);
    tinygltf::Node node;
    node.mesh = 0;
    model.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes.push_back(0);
    model.scenes.push_back(scene);
    model.defaultScene = 0;

    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, out, false, true))
        throw std::runtime_error("tinygltf could not write the binary glTF");
}

} // namespace ctess::cli
