// load_model: picks the loader by extension, checks the content's magic, reads the file with a bounded
// allocation, and turns every failure into a LoadError (docs/models.md).
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <limits>
#include <new>

#include <ctess/runtime/models/model.hpp>
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>

#include "load_common.hpp"
#include "loaders.hpp"

namespace ctess::models {

static_assert(model_vertex_floats == ctess::rt::mesh_vertex_floats,
              "a Model's vertices feed the mesh pipeline");

namespace detail {

void append_face(Model& model, const std::uint32_t* corners, unsigned corner_count) {
    // The same bound as the glTF loader's indices (2^27): an OBJ of long fans could otherwise ask for
    // billions of triangles from a few GB of text.
    if (model.triangles.size() + model.quads.size() + corner_count > (std::size_t{1} << 27))
        throw LoadFailure{"more than 2^27 face indices"};
    const float* v = model.vertices.data();
    for (unsigned i = 0; i < corner_count; ++i)
        for (unsigned j = i + 1; j < corner_count; ++j)
            if (same_position(v + std::size_t{corners[i]} * model_vertex_floats,
                              v + std::size_t{corners[j]} * model_vertex_floats)) {
                ++model.dropped_degenerate_faces;
                return;
            }
    auto& out = corner_count == 3 ? model.triangles : model.quads;
    out.insert(out.end(), corners, corners + corner_count);
}

void check_model(const Model& model) {
    if (model.triangles.empty() && model.quads.empty()) {
        throw LoadFailure{model.dropped_degenerate_faces != 0
                              ? "no faces left: all " + std::to_string(model.dropped_degenerate_faces) +
                                    " faces are degenerate"
                              : "no triangles or quads (empty model)"};
    }
    for (std::size_t i = 0; i < model.vertices.size(); ++i)
        if (!std::isfinite(model.vertices[i]))
            throw LoadFailure{"vertex " + std::to_string(i / model_vertex_floats) +
                              " has a NaN or infinite attribute"};
}

} // namespace detail

namespace {

constexpr std::uint8_t glb_magic[4] = {'g', 'l', 'T', 'F'};

bool starts_with_glb_magic(std::span<const std::uint8_t> bytes) {
    return bytes.size() >= 4 && std::equal(glb_magic, glb_magic + 4, bytes.begin());
}

// The content check (docs/models.md, "Which loader"): the extension picks the loader, the bytes must agree.
std::string content_problem(std::span<const std::uint8_t> bytes, ModelKind kind) {
    if (bytes.empty()) return "the file is empty";
    switch (kind) {
    case ModelKind::gltf_binary:
        if (!starts_with_glb_magic(bytes))
            return "not a binary glTF file (the first 4 bytes are not \"glTF\")";
        return {};
    case ModelKind::gltf_text: {
        if (starts_with_glb_magic(bytes)) return "a binary glTF (.glb) file with a .gltf name";
        std::size_t i = 0;
        if (bytes.size() >= 3 && bytes[0] == 0xEF && bytes[1] == 0xBB && bytes[2] == 0xBF) i = 3; // UTF-8 BOM
        while (i < bytes.size() && std::isspace(bytes[i])) ++i;
        if (i == bytes.size() || bytes[i] != '{') return "not a glTF JSON file (it does not start with '{')";
        return {};
    }
    case ModelKind::obj:
        if (starts_with_glb_magic(bytes)) return "a binary glTF (.glb) file with an .obj name";
        if (std::find(bytes.begin(), bytes.end(), std::uint8_t{0}) != bytes.end())
            return "not an OBJ text file (it contains NUL bytes)";
        return {};
    }
    return "unknown model kind";
}

LoadResult load_checked(std::span<const std::uint8_t> bytes, ModelKind kind, const std::string& name,
                        const std::string* base_dir, const LoadLimits& limits = {}) {
    return detail::guarded_load<LoadResult>(name, [&] {
        if (std::string problem = content_problem(bytes, kind); !problem.empty())
            throw detail::LoadFailure{problem};
        Model model = kind == ModelKind::obj ? detail::load_obj(bytes, limits)
                                             : detail::load_gltf(bytes, kind, base_dir, limits);
        detail::check_model(model);
        LoadResult result;
        result.model = std::move(model);
        return result;
    });
}

} // namespace

LoadResult load_model_from_memory(std::span<const std::uint8_t> bytes, ModelKind kind,
                                  const std::string& name, const LoadLimits& limits) {
    return load_checked(bytes, kind, name, nullptr, limits);
}

namespace detail {

void past_limit(const LoadLimits& limits, std::size_t bound, const char* of) {
    throw LoadFailure{"more than " + std::to_string(bound) + " " + of + ", past " + limits.what};
}

} // namespace detail

LoadResult load_model(const std::string& path) {
    return detail::guarded_load<LoadResult>(path, [&] {
        std::string ext = std::filesystem::path(path).extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
        LoadResult result;
        ModelKind kind;
        if (ext == ".gltf")
            kind = ModelKind::gltf_text;
        else if (ext == ".glb")
            kind = ModelKind::gltf_binary;
        else if (ext == ".obj")
            kind = ModelKind::obj;
        else {
            result.error.message =
                path + ": unknown model extension '" + ext + "' (expected .gltf, .glb or .obj)";
            return result;
        }
        // tinygltf takes a 32-bit length; the bound also keeps the allocation below what the file can
        // justify.
        std::vector<std::uint8_t> bytes;
        result.error.message =
            detail::read_file_bytes(path, std::numeric_limits<std::uint32_t>::max(), "4 GiB", bytes);
        if (!result.error.message.empty()) return result;
        const std::string base_dir = std::filesystem::path(path).parent_path().string();
        return load_checked(bytes, kind, path, &base_dir);
    });
}

} // namespace ctess::models
