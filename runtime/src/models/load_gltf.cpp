// glTF 2.0 (.gltf with embedded or external buffers, .glb) through tinygltf (Debian's shared libtinygltf,
// with nlohmann-json; docs/models.md). tinygltf parses the JSON and the buffers; everything read from them
// here is bounds-checked first, because tinygltf 2.7 does not check accessors against their buffer views.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>

#include <tiny_gltf.h>

#include "load_common.hpp"
#include "loaders.hpp"

namespace ctess::models::detail {
namespace {

// Output bounds (docs/models.md, "Bad files"): node instancing can multiply a small file's geometry, so the
// expansion is capped before each primitive's vertices are allocated.
constexpr std::size_t max_model_vertices = std::size_t{1} << 26;
constexpr std::size_t max_model_indices = std::size_t{1} << 27;

using Matrix = std::array<double, 16>; // column-major, as glTF's node.matrix

Matrix identity() {
    return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
}

Matrix multiply(const Matrix& a, const Matrix& b) {
    Matrix c{};
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row)
            for (int k = 0; k < 4; ++k) c[col * 4 + row] += a[k * 4 + row] * b[col * 4 + k];
    return c;
}

// glTF 2.0 §5.25 (node): matrix, or T * R * S with R from a unit quaternion (x, y, z, w).
Matrix local_matrix(const tinygltf::Node& node, int index) {
    const std::string where = "node " + std::to_string(index);
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) throw LoadFailure{where + ": matrix does not have 16 numbers"};
        Matrix m;
        std::copy(node.matrix.begin(), node.matrix.end(), m.begin());
        return m;
    }
    if (!node.translation.empty() && node.translation.size() != 3)
        throw LoadFailure{where + ": translation does not have 3 numbers"};
    if (!node.rotation.empty() && node.rotation.size() != 4)
        throw LoadFailure{where + ": rotation does not have 4 numbers"};
    if (!node.scale.empty() && node.scale.size() != 3)
        throw LoadFailure{where + ": scale does not have 3 numbers"};
    const double x = node.rotation.empty() ? 0 : node.rotation[0],
                 y = node.rotation.empty() ? 0 : node.rotation[1];
    const double z = node.rotation.empty() ? 0 : node.rotation[2],
                 w = node.rotation.empty() ? 1 : node.rotation[3];
    const double sx = node.scale.empty() ? 1 : node.scale[0], sy = node.scale.empty() ? 1 : node.scale[1];
    const double sz = node.scale.empty() ? 1 : node.scale[2];
    Matrix m = {(1 - 2 * (y * y + z * z)) * sx,
                (2 * (x * y + z * w)) * sx,
                (2 * (x * z - y * w)) * sx,
                0,
                (2 * (x * y - z * w)) * sy,
                (1 - 2 * (x * x + z * z)) * sy,
                (2 * (y * z + x * w)) * sy,
                0,
                (2 * (x * z + y * w)) * sz,
                (2 * (y * z - x * w)) * sz,
                (1 - 2 * (x * x + y * y)) * sz,
                0,
                0,
                0,
                0,
                1};
    if (!node.translation.empty()) {
        m[12] = node.translation[0];
        m[13] = node.translation[1];
        m[14] = node.translation[2];
    }
    return m;
}

// The upper 3x3's cofactor matrix: det * inverse-transpose, the normal transform up to a scale (normals are
// renormalised), with the sign of det applied so that mirrored nodes keep outward normals.
std::array<double, 9> normal_matrix(const Matrix& m, double& det) {
    auto a = [&](int row, int col) { return m[col * 4 + row]; };
    std::array<double, 9> c; // row-major
    c[0] = a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1);
    c[1] = a(1, 2) * a(2, 0) - a(1, 0) * a(2, 2);
    c[2] = a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0);
    c[3] = a(0, 2) * a(2, 1) - a(0, 1) * a(2, 2);
    c[4] = a(0, 0) * a(2, 2) - a(0, 2) * a(2, 0);
    c[5] = a(0, 1) * a(2, 0) - a(0, 0) * a(2, 1);
    c[6] = a(0, 1) * a(1, 2) - a(0, 2) * a(1, 1);
    c[7] = a(0, 2) * a(1, 0) - a(0, 0) * a(1, 2);
    c[8] = a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0);
    det = a(0, 0) * c[0] + a(0, 1) * c[1] + a(0, 2) * c[2];
    if (det < 0)
        for (double& v : c) v = -v;
    return c;
}

// One accessor's elements, bounds-checked against its buffer view and buffer.
struct AccessorView {
    const std::uint8_t* data = nullptr;
    std::size_t count = 0, stride = 0;
    int component_type = 0, components = 0;
    bool normalized = false;
};

AccessorView view_accessor(const tinygltf::Model& g, int index, const std::string& what) {
    const std::string where = what + " (accessor " + std::to_string(index) + ")";
    if (index < 0 || static_cast<std::size_t>(index) >= g.accessors.size())
        throw LoadFailure{what + ": accessor " + std::to_string(index) + " does not exist"};
    const tinygltf::Accessor& acc = g.accessors[static_cast<std::size_t>(index)];
    if (acc.sparse.isSparse) throw LoadFailure{where + ": sparse accessors are not supported"};
    if (acc.bufferView < 0 || static_cast<std::size_t>(acc.bufferView) >= g.bufferViews.size())
        throw LoadFailure{where + ": no valid bufferView"};
    const tinygltf::BufferView& bv = g.bufferViews[static_cast<std::size_t>(acc.bufferView)];
    if (bv.extensions.count("EXT_meshopt_compression"))
        throw LoadFailure{where +
                          ": its buffer view uses EXT_meshopt_compression, which ctess does not decode"};
    if (bv.buffer < 0 || static_cast<std::size_t>(bv.buffer) >= g.buffers.size())
        throw LoadFailure{where + ": the buffer view's buffer does not exist"};
    const std::vector<unsigned char>& buffer = g.buffers[static_cast<std::size_t>(bv.buffer)].data;
    if (bv.byteOffset > buffer.size() || bv.byteLength > buffer.size() - bv.byteOffset)
        throw LoadFailure{where + ": the buffer view runs past the end of its buffer"};
    const int component_size =
        tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(acc.componentType));
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(acc.type));
    if (component_size <= 0 || components <= 0) throw LoadFailure{where + ": unknown component type or type"};
    const std::size_t element =
        static_cast<std::size_t>(component_size) * static_cast<std::size_t>(components);
    const std::size_t stride = bv.byteStride != 0 ? bv.byteStride : element;
    if (stride < element) throw LoadFailure{where + ": byteStride is smaller than one element"};
    if (acc.count != 0 && (acc.byteOffset > bv.byteLength || element > bv.byteLength - acc.byteOffset ||
                           acc.count - 1 > (bv.byteLength - acc.byteOffset - element) / stride))
        throw LoadFailure{where + ": " + std::to_string(acc.count) +
                          " elements run past the end of the buffer view"};
    AccessorView v;
    v.data = acc.count == 0 ? buffer.data() : buffer.data() + bv.byteOffset + acc.byteOffset;
    v.count = acc.count;
    v.stride = stride;
    v.component_type = acc.componentType;
    v.components = components;
    v.normalized = acc.normalized;
    return v;
}

// glTF 2.0 §3.11 (animation, normalized integers) and KHR_mesh_quantization: c / 255, c / 65535 for unsigned,
// max(c / 127, -1), max(c / 32767, -1) for signed; the plain value when not normalized.
float read_component(const AccessorView& v, std::size_t element, int component) {
    const std::uint8_t* p = v.data + element * v.stride;
    switch (v.component_type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float f;
        std::memcpy(&f, p + 4 * component, 4);
        return f;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
        const float c = p[component];
        return v.normalized ? c / 255.0f : c;
    }
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const float c = static_cast<std::int8_t>(p[component]);
        return v.normalized ? std::max(c / 127.0f, -1.0f) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t u;
        std::memcpy(&u, p + 2 * component, 2);
        return v.normalized ? static_cast<float>(u) / 65535.0f : static_cast<float>(u);
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        std::int16_t s;
        std::memcpy(&s, p + 2 * component, 2);
        return v.normalized ? std::max(static_cast<float>(s) / 32767.0f, -1.0f) : static_cast<float>(s);
    }
    default:
        return 0; // excluded by check_attribute
    }
}

void check_attribute(const AccessorView& v, int components, const std::string& what) {
    if (v.components != components)
        throw LoadFailure{what + ": expected " + std::to_string(components) + " components per element"};
    switch (v.component_type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return;
    default:
        throw LoadFailure{what + ": component type " + std::to_string(v.component_type) + " is not allowed"};
    }
}

std::uint32_t read_index(const AccessorView& v, std::size_t i) {
    const std::uint8_t* p = v.data + i * v.stride;
    switch (v.component_type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return p[0];
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t u;
        std::memcpy(&u, p, 2);
        return u;
    }
    default: {
        std::uint32_t u;
        std::memcpy(&u, p, 4);
        return u;
    }
    }
}

class GltfReader {
  public:
    GltfReader(const tinygltf::Model& gltf, Model& model, const LoadLimits& limits)
        : g_(gltf), model_(model), limits_(limits) {}

    void read_scene() {
        // The default scene, else the first; with no scenes at all (a dangling "scene" included), every mesh
        // untransformed.
        int scene = g_.defaultScene;
        if (!g_.scenes.empty() && static_cast<std::size_t>(scene) >= g_.scenes.size() && scene >= 0)
            throw LoadFailure{"the default scene " + std::to_string(scene) + " does not exist"};
        if (scene < 0 && !g_.scenes.empty()) scene = 0;
        if (g_.scenes.empty()) {
            for (std::size_t m = 0; m < g_.meshes.size(); ++m) read_mesh(static_cast<int>(m), identity());
            return;
        }
        std::vector<bool> visited(g_.nodes.size(), false);
        std::vector<std::pair<int, Matrix>> stack;
        for (int root : g_.scenes[static_cast<std::size_t>(scene)].nodes)
            stack.emplace_back(root, identity());
        while (!stack.empty()) {
            auto [index, parent] = stack.back();
            stack.pop_back();
            if (index < 0 || static_cast<std::size_t>(index) >= g_.nodes.size())
                throw LoadFailure{"node " + std::to_string(index) + " does not exist"};
            // A node reached twice is a cycle or a node with two parents; both are invalid (glTF 2.0 §3.5.3).
            if (visited[static_cast<std::size_t>(index)])
                throw LoadFailure{"node " + std::to_string(index) +
                                  " is reached twice (a cycle or two parents)"};
            visited[static_cast<std::size_t>(index)] = true;
            const tinygltf::Node& node = g_.nodes[static_cast<std::size_t>(index)];
            const Matrix world = multiply(parent, local_matrix(node, index));
            for (double e : world)
                if (!std::isfinite(e))
                    throw LoadFailure{"node " + std::to_string(index) + ": non-finite transform"};
            if (node.mesh >= 0) read_mesh(node.mesh, world);
            for (int child : node.children) stack.emplace_back(child, world);
        }
    }

  private:
    void read_mesh(int mesh_index, const Matrix& world) {
        if (static_cast<std::size_t>(mesh_index) >= g_.meshes.size())
            throw LoadFailure{"mesh " + std::to_string(mesh_index) + " does not exist"};
        const tinygltf::Mesh& mesh = g_.meshes[static_cast<std::size_t>(mesh_index)];
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p)
            read_primitive(mesh.primitives[p],
                           "mesh " + std::to_string(mesh_index) + " primitive " + std::to_string(p), world);
    }

    void read_primitive(const tinygltf::Primitive& prim, const std::string& where, const Matrix& world) {
        if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            prim.mode != TINYGLTF_MODE_TRIANGLE_FAN)
            throw LoadFailure{where + ": mode " + std::to_string(prim.mode) +
                              " is points or lines; only triangles, strips and fans are read"};
        const bool draco = prim.extensions.count("KHR_draco_mesh_compression") != 0;
        const std::string suffix =
            draco ? " (the primitive uses KHR_draco_mesh_compression, which ctess does not "
                    "decode, and has no uncompressed fallback)"
                  : "";
        const auto position_it = prim.attributes.find("POSITION");
        if (position_it == prim.attributes.end())
            throw LoadFailure{where + ": no POSITION attribute" + suffix};
        AccessorView positions, normals, uvs, tangents;
        try {
            positions = view_accessor(g_, position_it->second, where + " POSITION");
        } catch (const LoadFailure& f) {
            throw LoadFailure{f.problem + suffix};
        }
        check_attribute(positions, 3, where + " POSITION");
        const auto normal_it = prim.attributes.find("NORMAL");
        const bool has_normals = normal_it != prim.attributes.end();
        if (has_normals) {
            normals = view_accessor(g_, normal_it->second, where + " NORMAL");
            check_attribute(normals, 3, where + " NORMAL");
            if (normals.count != positions.count)
                throw LoadFailure{where + ": NORMAL and POSITION counts differ"};
        }
        const auto uv_it = prim.attributes.find("TEXCOORD_0");
        const bool has_uvs = uv_it != prim.attributes.end();
        if (has_uvs) {
            uvs = view_accessor(g_, uv_it->second, where + " TEXCOORD_0");
            check_attribute(uvs, 2, where + " TEXCOORD_0");
            if (uvs.count != positions.count)
                throw LoadFailure{where + ": TEXCOORD_0 and POSITION counts differ"};
        }
        // TANGENT (vector displacement's frame, docs/algorithm.md §8.7): kept only when every primitive has
        // it.
        const auto tangent_it = prim.attributes.find("TANGENT");
        const bool has_tangents = tangent_it != prim.attributes.end();
        if (has_tangents) {
            tangents = view_accessor(g_, tangent_it->second, where + " TANGENT");
            check_attribute(tangents, 4, where + " TANGENT");
            if (tangents.count != positions.count)
                throw LoadFailure{where + ": TANGENT and POSITION counts differ"};
        }
        first_primitive_ ? (model_.has_normals = has_normals, model_.has_uvs = has_uvs)
                         : (model_.has_normals &= has_normals, model_.has_uvs &= has_uvs);
        model_.has_tangents = (first_primitive_ || model_.has_tangents) && has_tangents;
        first_primitive_ = false;

        // The caller's limits, from the accessors' counts before anything of this instance is allocated: the
        // faces are at most those of an all-distinct corner list.
        const std::size_t base_vertices = model_.vertex_count();
        if (positions.count > limits_.max_vertices - std::min(base_vertices, limits_.max_vertices))
            past_limit(limits_, limits_.max_vertices, "vertices");
        const std::size_t corner_count =
            prim.indices >= 0 && static_cast<std::size_t>(prim.indices) < g_.accessors.size()
                ? g_.accessors[static_cast<std::size_t>(prim.indices)].count
                : positions.count;
        const std::size_t most_faces = prim.mode == TINYGLTF_MODE_TRIANGLES ? corner_count / 3
                                       : corner_count >= 3                  ? corner_count - 2
                                                                            : 0;
        const std::size_t faces = model_.triangle_count() + model_.quad_count();
        if (most_faces > limits_.max_faces - std::min(faces, limits_.max_faces))
            past_limit(limits_, limits_.max_faces, "faces");

        // Corner list: the index accessor's values, or 0..count-1 for a non-indexed primitive.
        std::vector<std::uint32_t> corners;
        if (prim.indices >= 0) {
            const AccessorView idx = view_accessor(g_, prim.indices, where + " indices");
            if (idx.components != 1 || (idx.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                        idx.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                        idx.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
                throw LoadFailure{where + ": indices must be unsigned byte, short or int scalars"};
            if (idx.count > max_model_indices) throw LoadFailure{where + ": too many indices"};
            corners.resize(idx.count);
            for (std::size_t i = 0; i < idx.count; ++i) {
                corners[i] = read_index(idx, i);
                if (corners[i] >= positions.count)
                    throw LoadFailure{where + ": index " + std::to_string(corners[i]) + " at position " +
                                      std::to_string(i) + " is out of range (" +
                                      std::to_string(positions.count) + " vertices)"};
            }
        } else {
            if (positions.count > max_model_indices) throw LoadFailure{where + ": too many vertices"};
            corners.resize(positions.count);
            for (std::size_t i = 0; i < positions.count; ++i) corners[i] = static_cast<std::uint32_t>(i);
        }

        const std::size_t base = model_.vertex_count();
        if (positions.count > max_model_vertices - base)
            throw LoadFailure{"more than " + std::to_string(max_model_vertices) + " vertices"};
        double det = 0;
        const std::array<double, 9> nm = normal_matrix(world, det);
        model_.vertices.resize((base + positions.count) * model_vertex_floats, 0.0f);
        for (std::size_t i = 0; i < positions.count; ++i) {
            float* out = model_.vertices.data() + (base + i) * model_vertex_floats;
            double p[3];
            for (int c = 0; c < 3; ++c) p[c] = read_component(positions, i, c);
            for (int r = 0; r < 3; ++r) {
                const double d = world[r] * p[0] + world[4 + r] * p[1] + world[8 + r] * p[2] + world[12 + r];
                // A finite double past the float range has no float value (converting it is undefined
                // behaviour); NaN and infinities convert, and the model check names them.
                if (std::isfinite(d) && std::fabs(d) > static_cast<double>(std::numeric_limits<float>::max()))
                    throw LoadFailure{"vertex " + std::to_string(i) +
                                      " is outside the float range after its node transform"};
                out[r] = canonical_zero(static_cast<float>(d));
            }
            if (has_normals) {
                double n[3], t[3];
                for (int c = 0; c < 3; ++c) n[c] = read_component(normals, i, c);
                for (int r = 0; r < 3; ++r)
                    t[r] = nm[3 * r] * n[0] + nm[3 * r + 1] * n[1] + nm[3 * r + 2] * n[2];
                const double len = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
                for (int r = 0; r < 3; ++r) out[3 + r] = len > 0 ? static_cast<float>(t[r] / len) : 0.0f;
            }
            if (has_uvs)
                for (int c = 0; c < 2; ++c) out[6 + c] = read_component(uvs, i, c);
        }
        // Tangents lie in the surface, so they transform as positions' differences (the upper 3x3); a mirror
        // flips the handedness. Dropped as soon as one primitive lacks them.
        if (!model_.has_tangents) {
            model_.tangents.clear();
        } else {
            model_.tangents.resize((base + positions.count) * 4, 0.0f);
            for (std::size_t i = 0; i < positions.count; ++i) {
                float* out = model_.tangents.data() + (base + i) * 4;
                double t[3], m[3];
                for (int c = 0; c < 3; ++c) t[c] = read_component(tangents, i, c);
                for (int r = 0; r < 3; ++r)
                    m[r] = world[r] * t[0] + world[4 + r] * t[1] + world[8 + r] * t[2];
                const double len = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
                const bool usable = len > 0 && std::isfinite(len); // else (0, 0, 0): no tangent there
                for (int r = 0; r < 3; ++r) out[r] = usable ? static_cast<float>(m[r] / len) : 0.0f;
                const float w = read_component(tangents, i, 3);
                out[3] = (w < 0.0f) != (det < 0) ? -1.0f : 1.0f;
            }
        }

        // Triangles from the corner list (glTF 2.0 §3.7.2.1, primitive modes); a mirrored node (det < 0)
        // reverses the winding so that front faces stay counter-clockwise.
        const bool mirrored = det < 0;
        auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
            std::uint32_t tri[3] = {static_cast<std::uint32_t>(base + a),
                                    static_cast<std::uint32_t>(base + b),
                                    static_cast<std::uint32_t>(base + c)};
            if (mirrored) std::swap(tri[1], tri[2]);
            if (model_.triangles.size() >= max_model_indices) throw LoadFailure{"too many triangles"};
            append_face(model_, tri, 3);
        };
        const std::size_t n = corners.size();
        if (prim.mode == TINYGLTF_MODE_TRIANGLES) {
            for (std::size_t i = 0; i + 2 < n; i += 3) emit(corners[i], corners[i + 1], corners[i + 2]);
        } else if (prim.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            for (std::size_t i = 0; i + 2 < n; ++i)
                emit(corners[i], corners[i + 1 + i % 2], corners[i + 2 - i % 2]);
        } else {
            for (std::size_t i = 1; i + 1 < n; ++i) emit(corners[i], corners[i + 1], corners[0]);
        }
        read_displacement(prim.material);
    }

    // KHR_materials_displacement as proposed in KhronosGroup/glTF#948, in the shape of the ratified
    // KHR_materials_* extensions: {"displacementTexture": {"index": t}, "displacementFactor": f,
    // "displacementOffset": o}.
    void read_displacement(int material) {
        if (model_.displacement.present || material < 0 ||
            static_cast<std::size_t>(material) >= g_.materials.size())
            return;
        const auto& ext = g_.materials[static_cast<std::size_t>(material)].extensions;
        const auto it = ext.find("KHR_materials_displacement");
        if (it == ext.end() || !it->second.IsObject()) return;
        const tinygltf::Value& d = it->second;
        Model::Displacement out;
        out.present = true;
        if (d.Has("displacementFactor") && d.Get("displacementFactor").IsNumber())
            out.factor = static_cast<float>(d.Get("displacementFactor").GetNumberAsDouble());
        if (d.Has("displacementOffset") && d.Get("displacementOffset").IsNumber())
            out.offset = static_cast<float>(d.Get("displacementOffset").GetNumberAsDouble());
        if (d.Has("displacementTexture") && d.Get("displacementTexture").Has("index") &&
            d.Get("displacementTexture").Get("index").IsInt()) {
            const int t = d.Get("displacementTexture").Get("index").GetNumberAsInt();
            if (t >= 0 && static_cast<std::size_t>(t) < g_.textures.size()) {
                out.texture = t;
                const int source = g_.textures[static_cast<std::size_t>(t)].source;
                if (source >= 0 && static_cast<std::size_t>(source) < g_.images.size()) {
                    const tinygltf::Image& image = g_.images[static_cast<std::size_t>(source)];
                    if (!image.uri.empty() && image.uri.rfind("data:", 0) != 0)
                        out.image_uri = image.uri;
                    else // a data: uri or a buffer view: keep_image_bytes kept the encoded bytes
                        out.image_bytes.assign(image.image.begin(), image.image.end());
                }
            }
        }
        if (!std::isfinite(out.factor) || !std::isfinite(out.offset))
            throw LoadFailure{"KHR_materials_displacement: non-finite factor or offset"};
        model_.displacement = std::move(out);
    }

    const tinygltf::Model& g_;
    Model& model_;
    const LoadLimits& limits_;
    bool first_primitive_ = true;
};

// File access for tinygltf: only below the model's folder (or nothing at all for in-memory loads), no shell
// expansion of paths (tinygltf's default ExpandFilePath runs wordexp), no writes.
struct FileAccess {
    const std::string* base_dir = nullptr;
};

// tinygltf looks in the model's folder, then in ".": only the first is allowed, so that a model never picks
// up a file from the current directory.
bool allowed(const std::string& path, const FileAccess* access) {
    if (access->base_dir == nullptr) return false;
    const std::string& dir = *access->base_dir;
    return dir.empty() || path.rfind(dir.back() == '/' ? dir : dir + "/", 0) == 0;
}

bool file_exists(const std::string& path, void* user) {
    const auto* access = static_cast<const FileAccess*>(user);
    if (!allowed(path, access)) return false;
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
}

std::string expand_file_path(const std::string& path, void*) {
    return path;
}

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
    const auto* access = static_cast<const FileAccess*>(user);
    if (!allowed(path, access)) return false;
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec || size > std::numeric_limits<std::uint32_t>::max()) {
        if (err) *err += "cannot read " + path;
        return false;
    }
    out->resize(static_cast<std::size_t>(size));
    std::ifstream in(path, std::ios::binary);
    return static_cast<bool>(
        in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size)));
}

bool write_whole_file(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
    return false;
}

// Images are not decoded here: the encoded bytes are kept in Image::image (tinygltf's pixel vector, unused
// otherwise), so that an embedded displacement image can reach models::load_height_map_from_memory; an
// external image keeps its uri.
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
    if (image != nullptr && bytes != nullptr && size > 0) image->image.assign(bytes, bytes + size);
    return true;
}

// The one check of a .glb's chunks Debian 12's tinygltf (2.7) lacks: it bounds the BIN chunk's data by the
// file without the chunk's 8-byte header, so a BIN chunk whose length runs up to 8 bytes past the end of the
// file is read past it (found by fuzz_models_glb). The GLB layout: a 12-byte header (magic, version, total
// length), then chunks of a 4-byte length, a 4-byte type and the data (glTF 2.0 specification, "GLB File
// Format").
void check_glb_chunks(std::span<const std::uint8_t> bytes) {
    const auto le32 = [&](std::size_t at) {
        return std::uint32_t{bytes[at]} | std::uint32_t{bytes[at + 1]} << 8 |
               std::uint32_t{bytes[at + 2]} << 16 | std::uint32_t{bytes[at + 3]} << 24;
    };
    if (bytes.size() < 20) return; // tinygltf refuses it
    const std::uint64_t end = std::min<std::uint64_t>(le32(8), bytes.size());
    const std::uint64_t bin = 20 + std::uint64_t{le32(12)}; // the second chunk's header
    if (bin + 8 <= end && bin + 8 + le32(static_cast<std::size_t>(bin)) > end)
        throw LoadFailure{"the binary glTF's second chunk runs past the end of the file"};
}

} // namespace

Model load_gltf(std::span<const std::uint8_t> bytes, ModelKind kind, const std::string* base_dir,
                const LoadLimits& limits) {
    if (bytes.size() > std::numeric_limits<std::uint32_t>::max()) throw LoadFailure{"larger than 4 GiB"};
    if (kind == ModelKind::gltf_binary) check_glb_chunks(bytes);
    FileAccess access{base_dir};
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&file_exists, &expand_file_path, &read_whole_file, &write_whole_file, &access});
    loader.SetImageLoader(&keep_image_bytes, nullptr);
    tinygltf::Model gltf;
    std::string err, warn;
    const auto length = static_cast<unsigned>(bytes.size());
    const std::string dir = base_dir ? *base_dir : std::string{};
    const bool ok = kind == ModelKind::gltf_binary
                        ? loader.LoadBinaryFromMemory(&gltf, &err, &warn, bytes.data(), length, dir)
                        : loader.LoadASCIIFromString(
                              &gltf, &err, &warn, reinterpret_cast<const char*>(bytes.data()), length, dir);
    if (!ok) {
        while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
        // tinygltf rejects a compressed primitive's accessors before the extension can be read: name the
        // extension from the JSON text (a .glb's JSON chunk is in the same bytes).
        const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
        for (const char* ext : {"KHR_draco_mesh_compression", "EXT_meshopt_compression"})
            if (text.find(ext) != std::string_view::npos)
                throw LoadFailure{std::string("uses the glTF extension ") + ext +
                                  " (compressed geometry), which ctess does not decode (tinygltf: " +
                                  (err.empty() ? std::string{"unknown error"} : err) + ")"};
        throw LoadFailure{"glTF parse error: " + (err.empty() ? std::string{"unknown"} : err)};
    }
    for (const std::string& ext : gltf.extensionsRequired)
        if (ext != "KHR_mesh_quantization" && ext != "KHR_materials_displacement")
            throw LoadFailure{"requires the glTF extension " + ext + ", which ctess does not support" +
                              (ext == "KHR_draco_mesh_compression" || ext == "EXT_meshopt_compression"
                                   ? " (compressed geometry is not decoded)"
                                   : "")};
    Model model;
    GltfReader(gltf, model, limits).read_scene();
    return model;
}

} // namespace ctess::models::detail
