// Wavefront OBJ through tinyobjloader (Debian's libtinyobjloader, docs/models.md). tinyobjloader parses the
// text and resolves negative (relative) indices; it does not check indices against the attribute arrays, so
// every index is checked here before use.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <string_view>
#include <unordered_map>

#include <tiny_obj_loader.h>

#include "load_common.hpp"
#include "loaders.hpp"

namespace ctess::models::detail {
namespace {

struct CornerKey {
    int position, normal, uv;
    bool operator==(const CornerKey&) const = default;
};
struct CornerKeyHash {
    std::size_t operator()(const CornerKey& k) const {
        std::size_t h = static_cast<std::uint32_t>(k.position);
        h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k.normal);
        return h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k.uv);
    }
};

void check_index(int index, std::size_t count, const char* what, std::size_t face) {
    if (index < 0 || static_cast<std::size_t>(index) >= count)
        throw LoadFailure{std::string("face ") + std::to_string(face + 1) + ": " + what + " index " +
                          std::to_string(index + 1) + " is out of range (" + std::to_string(count) +
                          " defined)"};
}

// tinyobjloader reads a number it cannot parse ("nan", "abc") as 0 without a word: every number of the v, vn
// and vt lines is checked here first, so that such a file is an error rather than a silently moved vertex
// (docs/models.md, "Bad files").
void check_attribute_numbers(std::string_view text) {
    std::size_t line_number = 0;
    while (!text.empty()) {
        ++line_number;
        const std::size_t end = std::min(text.find('\n'), text.size());
        std::string_view line = text.substr(0, end);
        text.remove_prefix(std::min(end + 1, text.size()));
        auto next_token = [&line]() {
            const std::size_t start = std::min(line.find_first_not_of(" \t\r"), line.size());
            line.remove_prefix(start);
            const std::size_t stop = std::min(line.find_first_of(" \t\r"), line.size());
            const std::string_view token = line.substr(0, stop);
            line.remove_prefix(stop);
            return token;
        };
        const std::string_view keyword = next_token();
        if (keyword != "v" && keyword != "vn" && keyword != "vt") continue;
        for (std::string_view token = next_token(); !token.empty(); token = next_token()) {
            std::string_view digits = token;
            if (digits.size() > 1 && digits[0] == '+') digits.remove_prefix(1); // strtod's leading '+'
            // Read as a double: a float underflow (|x| < 1e-45) is a legitimate 0; a float overflow is not.
            double value = 0;
            const auto [rest, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
            if (ec != std::errc{} || rest != digits.data() + digits.size() || !std::isfinite(value) ||
                std::abs(value) > std::numeric_limits<float>::max())
                throw LoadFailure{"line " + std::to_string(line_number) + ": '" + std::string(token) +
                                  "' is not a finite number"};
        }
    }
}

} // namespace

Model load_obj(std::span<const std::uint8_t> bytes, const LoadLimits& limits) {
    tinyobj::ObjReaderConfig config;
    config.triangulate = false; // quads stay quads; n-gons are fanned below
    config.vertex_color = false;
    const std::string text(bytes.begin(), bytes.end());
    check_attribute_numbers(text);
    tinyobj::ObjReader reader;
    // Materials are not read: an mtllib line only gives tinyobjloader a warning.
    if (!reader.ParseFromString(text, std::string{}, config)) {
        std::string err = reader.Error();
        while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
        throw LoadFailure{"OBJ parse error: " + (err.empty() ? std::string{"unknown"} : err)};
    }
    const tinyobj::attrib_t& attrib = reader.GetAttrib();
    const std::size_t position_count = attrib.vertices.size() / 3;
    const std::size_t normal_count = attrib.normals.size() / 3;
    const std::size_t uv_count = attrib.texcoords.size() / 2;

    Model model;
    model.has_normals = model.has_uvs = true;
    std::unordered_map<CornerKey, std::uint32_t, CornerKeyHash> vertex_of;
    std::vector<std::uint32_t> face;
    std::size_t face_number = 0; // over all shapes, for error messages
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const tinyobj::mesh_t& mesh = shape.mesh;
        std::size_t first = 0;
        for (std::size_t f = 0; f < mesh.num_face_vertices.size(); ++f, ++face_number) {
            const std::size_t corner_count = mesh.num_face_vertices[f];
            if (corner_count > mesh.indices.size() - first)
                throw LoadFailure{"face " + std::to_string(face_number + 1) +
                                  " has more corners than indices"};
            face.clear();
            for (std::size_t c = 0; c < corner_count; ++c) {
                const tinyobj::index_t& idx = mesh.indices[first + c];
                check_index(idx.vertex_index, position_count, "position", face_number);
                if (idx.normal_index >= 0) check_index(idx.normal_index, normal_count, "normal", face_number);
                if (idx.texcoord_index >= 0) check_index(idx.texcoord_index, uv_count, "uv", face_number);
                model.has_normals &= idx.normal_index >= 0;
                model.has_uvs &= idx.texcoord_index >= 0;
                // One output vertex per distinct (position, normal, uv) triple: seams keep their split
                // normals and uvs.
                const CornerKey key{idx.vertex_index, idx.normal_index, idx.texcoord_index};
                auto [it, inserted] =
                    vertex_of.try_emplace(key, static_cast<std::uint32_t>(model.vertex_count()));
                if (inserted) {
                    if (model.vertex_count() >= std::numeric_limits<std::uint32_t>::max())
                        throw LoadFailure{"more than 2^32 - 1 vertices"};
                    if (model.vertex_count() >= limits.max_vertices)
                        past_limit(limits, limits.max_vertices, "vertices");
                    const auto p = static_cast<std::size_t>(idx.vertex_index);
                    float v[model_vertex_floats] = {canonical_zero(attrib.vertices[3 * p]),
                                                    canonical_zero(attrib.vertices[3 * p + 1]),
                                                    canonical_zero(attrib.vertices[3 * p + 2])};
                    if (idx.normal_index >= 0)
                        for (int k = 0; k < 3; ++k)
                            v[3 + k] = attrib.normals[3 * static_cast<std::size_t>(idx.normal_index) + k];
                    if (idx.texcoord_index >= 0)
                        for (int k = 0; k < 2; ++k)
                            v[6 + k] = attrib.texcoords[2 * static_cast<std::size_t>(idx.texcoord_index) + k];
                    model.vertices.insert(model.vertices.end(), v, v + model_vertex_floats);
                }
                face.push_back(it->second);
            }
            first += corner_count;
            if (corner_count >= 3 &&
                model.triangle_count() + model.quad_count() + (corner_count <= 4 ? 1 : corner_count - 2) >
                    limits.max_faces)
                past_limit(limits, limits.max_faces, "faces");
            if (corner_count < 3) {
                ++model.dropped_degenerate_faces;
            } else if (corner_count <= 4) {
                append_face(model, face.data(), static_cast<unsigned>(corner_count));
            } else {
                // n-gons: a fan from the first corner (docs/models.md, "OBJ"), exact for the convex
                // polygons that exporters write.
                for (std::size_t c = 1; c + 1 < corner_count; ++c) {
                    const std::uint32_t tri[3] = {face[0], face[c], face[c + 1]};
                    append_face(model, tri, 3);
                }
            }
        }
        if (first != mesh.indices.size())
            throw LoadFailure{"a face has more than 255 corners (tinyobjloader's limit)"};
    }
    if (model.vertices.empty()) model.has_normals = model.has_uvs = false;
    return model;
}

} // namespace ctess::models::detail
