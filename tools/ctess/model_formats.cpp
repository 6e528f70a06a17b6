#include "model_formats.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <sstream>
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

template <class T>
void append_bytes(std::string& out, const T& value) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T)); // little-endian host (x86-64, AArch64): PLY and glTF are LE
    out.append(bytes, sizeof(T));
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

std::string mesh_to_ply(const OutputMesh& mesh, std::string_view comment) {
    std::string out = fmt::format("ply\nformat binary_little_endian 1.0\ncomment {}\nelement vertex {}\n"
                                  "property float x\nproperty float y\nproperty float z\n"
                                  "property float nx\nproperty float ny\nproperty float nz\n"
                                  "property float s\nproperty float t\nelement face {}\n"
                                  "property list uchar uint vertex_indices\nend_header\n",
                                  one_line(comment), mesh.vertex_count(), mesh.triangle_count());
    out.reserve(out.size() + mesh.vertices.size() * 4 + mesh.triangle_count() * 13);
    for (const float f : mesh.vertices) append_bytes(out, f);
    for (std::size_t t = 0; t < mesh.triangles.size(); t += 3) {
        out.push_back(3);
        for (int k = 0; k < 3; ++k) append_bytes(out, mesh.triangles[t + k]);
    }
    return out;
}

std::string mesh_to_glb(const OutputMesh& mesh, std::string_view comment) {
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
    std::string bytes;
    bytes.reserve(n * 32 + mesh.triangles.size() * 4);
    std::vector<double> lo(3, std::numeric_limits<double>::infinity()),
        hi(3, -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) {
            const float f = mesh.vertices[8 * i + k];
            append_bytes(bytes, f);
            lo[k] = std::min<double>(lo[k], f);
            hi[k] = std::max<double>(hi[k], f);
        }
    for (std::size_t i = 0; i < n; ++i)
        for (int k = 3; k < 6; ++k) append_bytes(bytes, mesh.vertices[8 * i + k]);
    for (std::size_t i = 0; i < n; ++i)
        for (int k = 6; k < 8; ++k) append_bytes(bytes, mesh.vertices[8 * i + k]);
    for (const std::uint32_t index : mesh.triangles) append_bytes(bytes, index);
    buffer.data.assign(bytes.begin(), bytes.end());
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

    std::ostringstream stream;
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToStream(&model, stream, false, true))
        throw std::runtime_error("tinygltf could not write the binary glTF");
    return stream.str();
}

} // namespace ctess::cli
