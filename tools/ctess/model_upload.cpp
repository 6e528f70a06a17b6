// `ctess serve`'s model and height-map answers (model_upload.hpp): the library loads and prepares, this
// writes the container.
#include "model_upload.hpp"

#include "json_escape.hpp"
#include "mesh_options.hpp"
#include "model_prep.hpp"

#include <ctess/runtime/displace/displace.hpp>
#include <ctess/runtime/displace/height_map.hpp>
#include <ctess/runtime/models/height_map.hpp>

#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <fmt/core.h>

namespace ctess::cli {

namespace {

struct Section {
    const char* name;
    const char* type; // "f32" or "u32"
    const void* data;
    std::size_t count; // 4-byte elements
};

// The container (model_upload.hpp): magic, version, header length, the JSON header padded to 4 bytes, then
// the sections. `scalars` is the header's members before "sections", each followed by ", ".
std::string container(const std::string& scalars, std::span<const Section> sections) {
    // The offsets depend on the header's length, which depends on the offsets' digits: lay the header out
    // with the offsets the previous pass gave until it stops growing (two passes in practice).
    std::string header;
    std::size_t header_bytes = 0;
    for (int pass = 0; pass < 8; ++pass) {
        std::size_t offset = 12 + header_bytes;
        header = "{" + scalars + "\"sections\": [";
        for (std::size_t i = 0; i < sections.size(); ++i) {
            header +=
                fmt::format("{}{{\"name\": \"{}\", \"type\": \"{}\", \"offset\": {}, \"count\": {}}}",
                            i ? ", " : "", sections[i].name, sections[i].type, offset, sections[i].count);
            offset += 4 * sections[i].count;
        }
        header += "]}";
        const std::size_t padded = (header.size() + 3) / 4 * 4;
        if (padded == header_bytes) break;
        header_bytes = padded;
    }
    header.resize(header_bytes, ' ');
    std::size_t total = 12 + header.size();
    for (const Section& s : sections) total += 4 * s.count;
    std::string out;
    out.reserve(total);
    const auto word = [&](std::uint32_t w) {
        for (unsigned b = 0; b < 4; ++b) out.push_back(static_cast<char>((w >> (8 * b)) & 0xFFu));
    };
    out += "CTMD";
    word(1);
    word(static_cast<std::uint32_t>(header.size()));
    out += header;
    // The host is little-endian (x86-64, AArch64): the arrays are copied as they are in memory.
    static_assert(std::endian::native == std::endian::little, "the container is little-endian");
    for (const Section& s : sections) out.append(static_cast<const char*>(s.data), 4 * s.count);
    return out;
}

// JSON has no NaN or infinity: such a number is written as null.
std::string json_number(float f) {
    return std::isfinite(f) ? fmt::format("{}", f) : std::string("null");
}

} // namespace

std::shared_ptr<const HeldModel> load_uploaded_model(std::span<const std::uint8_t> bytes,
                                                     const std::string& name) {
    const std::optional<models::ModelKind> kind = model_kind_of(name);
    if (!kind) throw std::runtime_error(name + ": the name must end in .glb, .gltf or .obj");
    const models::LoadLimits limits{max_upload_vertices, max_upload_faces,
                                    "the viewer's limit of 2^22 vertices and 2^23 faces"};
    models::LoadResult loaded = models::load_model_from_memory(bytes, *kind, name, limits);
    if (!loaded) {
        // One upload holds one file: a .gltf whose buffers are separate files cannot come with it.
        std::string message = loaded.error.message;
        if (*kind == models::ModelKind::gltf_text &&
            (message.find("not found") != std::string::npos || message.find("external") != std::string::npos))
            message +=
                " (an upload is one file: a .gltf must embed its buffers as data: URIs; or upload the .glb)";
        throw std::runtime_error(message);
    }
    auto held = std::make_shared<HeldModel>();
    held->name = name;
    held->prepared = prepare_model(std::move(*loaded.model), name);
    held->directions = displacement_directions(held->prepared, name);
    const models::Model& m = held->prepared.model;
    // Vector displacement's frame (docs/algorithm.md §8.7), as `ctess mesh --displace-vector` picks it; a
    // model without uvs has none (the CLI refuses it).
    if (m.has_uvs || m.has_tangents) held->tangents = displacement_tangents(held->prepared, name);
    // The file's KHR_materials_displacement image, decoded as `ctess mesh --displace-gltf` decodes it, so
    // that the viewer displaces by it. A failed decode is reported in the answer, not as a failed upload: the
    // model itself is fine.
    const models::Model::Displacement& d = m.displacement;
    if (d.present && d.image_uri.empty() && !d.image_bytes.empty()) {
        models::HeightMapResult decoded =
            models::load_height_map_from_memory(d.image_bytes, name + " (embedded displacement image)");
        if (decoded)
            held->image = std::move(*decoded.image);
        else
            held->image_error = decoded.error.message;
    }
    return held;
}

std::string model_answer(const HeldModel& held, std::uint64_t id) {
    const std::string& name = held.name;
    const PreparedModel& prepared = held.prepared;
    const std::vector<float>& directions = held.directions;
    const DisplacementTangents& tangents = held.tangents;
    const models::HeightImage& image = held.image;
    const models::Model& m = prepared.model;
    const models::Model::Displacement& d = m.displacement;
    std::string displacement = "null";
    if (d.present) {
        std::string image_fields;
        if (!d.image_uri.empty()) {
            image_fields =
                fmt::format("\"embedded_image\": false, \"image_uri\": \"{}\"", json_escape(d.image_uri));
        } else if (!d.image_bytes.empty()) {
            if (held.image_error.empty()) {
                const rt::TexelRange range = rt::texel_range(image.view());
                image_fields =
                    fmt::format("\"embedded_image\": true, \"width\": {}, \"height\": {}, \"texel_min\": {}, "
                                "\"texel_max\": {}",
                                image.width, image.height, json_number(range.min), json_number(range.max));
            } else {
                image_fields = fmt::format("\"embedded_image\": true, \"image_error\": \"{}\"",
                                           json_escape(held.image_error));
            }
        } else {
            image_fields = "\"embedded_image\": false";
        }
        displacement = fmt::format("{{\"factor\": {}, \"offset\": {}, {}}}", json_number(d.factor),
                                   json_number(d.offset), image_fields);
    }
    const std::string scalars = fmt::format(
        "\"id\": {}, \"name\": \"{}\", \"vertex_count\": {}, \"triangle_count\": {}, \"quad_count\": {}, "
        "\"has_normals\": {}, "
        "\"has_uvs\": {}, \"dropped_degenerate_faces\": {}, \"open_edges\": {}, \"displacement\": {}, "
        "\"tangent_source\": \"{}\", ",
        id, json_escape(name), m.vertex_count(), m.triangle_count(), m.quad_count(), m.has_normals, m.has_uvs,
        m.dropped_degenerate_faces, prepared.open_edges, displacement, tangents.source);
    const models::Adjacency& a = prepared.adjacency;
    const Section sections[] = {
        {"vertices", "f32", m.vertices.data(), m.vertices.size()},
        {"triangles", "u32", m.triangles.data(), m.triangles.size()},
        {"quads", "u32", m.quads.data(), m.quads.size()},
        {"position_ids", "u32", a.position_ids.data(), a.position_ids.size()},
        {"adjacency", "u32", a.tessellation_indices.data(), a.tessellation_indices.size()},
        {"directions", "f32", directions.data(), directions.size()},
        {"displacement_texels", "f32", image.texels.data(), image.texels.size()},
        {"tangents", "f32", tangents.tangents.data(), tangents.tangents.size()},
    };
    return container(scalars, sections);
}

std::shared_ptr<const HeldMap> load_uploaded_map(std::span<const std::uint8_t> bytes, const std::string& name,
                                                 bool vector) {
    models::HeightMapResult loaded = vector ? models::load_vector_map_from_memory(bytes, name)
                                            : models::load_height_map_from_memory(bytes, name);
    if (!loaded) throw std::runtime_error(loaded.error.message);
    auto held = std::make_shared<HeldMap>();
    held->name = name;
    held->image = std::move(*loaded.image);
    return held;
}

std::string map_answer(const HeldMap& held, std::uint64_t id) {
    const models::HeightImage& image = held.image;
    std::string scalars =
        fmt::format("\"id\": {}, \"name\": \"{}\", \"width\": {}, \"height\": {}, \"channels\": {}, ", id,
                    json_escape(held.name), image.width, image.height, image.channels);
    if (image.channels == 1) {
        const rt::TexelRange range = rt::texel_range(image.view());
        scalars += fmt::format("\"texel_min\": {}, \"texel_max\": {}, ", json_number(range.min),
                               json_number(range.max));
    }
    const Section sections[] = {{"texels", "f32", image.texels.data(), image.texels.size()}};
    return container(scalars, sections);
}

std::string tessellate_answer(const HeldModel& model, const HeldMap* map, const Args& args) {
    rt::PipelineOptions options = pipeline_options_from(args);
    if (options.dice.mode != rt::FactorMode::camera)
        throw UsageError("give dice-rate, camera, fov and resolution (the viewer's camera)");
    if (options.pattern == rt::Pattern::cp || options.pattern == rt::Pattern::uniform_split)
        throw UsageError(
            "cp and uniform run on the GPU (the generated WGSL); this answers the D3D11 patterns");
    // Displacement as `ctess mesh` builds it (docs/algorithm.md §8): `map` is the uploaded map, or the
    // model's own image (null with displace=model), with the model's factor then.
    const std::string source = args.get_or("displace", "none");
    rt::Displacement displacement;
    if (source != "none") {
        const bool own = source == "model";
        if (!own && source != "map") throw UsageError("displace must be none, map or model");
        if (own && model.image.texels.empty())
            throw std::runtime_error(model.name + ": no embedded displacement image to displace by");
        if (!own && map == nullptr)
            throw std::runtime_error("no height or vector map is held: upload it again");
        const models::HeightImage& image = own ? model.image : map->image;
        const std::string address =
            choice(args.get_or("displace-address", "repeat"), {"repeat", "clamp"}, "displace-address");
        displacement.map = image.view(address == "repeat" ? rt::AddressMode::repeat : rt::AddressMode::clamp);
        const auto number = [&](const char* key, float fallback) {
            const float f = args.has(key) ? parse_float(args.get(key), key) : fallback;
            if (!std::isfinite(f)) throw UsageError(std::string(key) + " must be a finite number");
            return f;
        };
        displacement.scale = number("displace-scale", 1.0f);
        displacement.factor = own ? model.prepared.model.displacement.factor : 1.0f;
        displacement.offset =
            number("displace-offset", own ? model.prepared.model.displacement.offset : 0.0f);
        displacement.directions = model.directions.data();
        if (image.channels == 3) {
            if (model.tangents.tangents.empty())
                throw std::runtime_error(model.name +
                                         ": vector displacement needs tangents (the model has no uvs)");
            displacement.mode = rt::DisplacementMode::vector;
            displacement.tangents = model.tangents.tangents.data();
        }
        if (args.get_or("displace-grow", "0") == "1")
            displacement.factor_bound = rt::displacement_bound(displacement);
        options.displacement = &displacement;
    }
    const UnweldedOutput out = unwelded_output(rt::cp_tables_64, rt::uniform_tables, model.prepared.view(),
                                               options, model.name, max_tessellate_triangles);
    static_assert(sizeof(rt::PatchRecord) % 4 == 0 && sizeof(rt::TessVertex) % 4 == 0);
    const std::string scalars =
        fmt::format("\"vertices\": {}, \"triangles\": {}, \"clamped_edges\": {}, ", out.totals.vertices,
                    out.totals.triangles, out.totals.clamped_edges);
    const Section sections[] = {
        {"records", "u32", out.records.data(), out.records.size() * sizeof(rt::PatchRecord) / 4},
        {"vertices", "u32", out.vertices.data(), out.vertices.size() * sizeof(rt::TessVertex) / 4},
        {"indices", "u32", out.indices.data(), out.indices.size()},
    };
    return container(scalars, sections);
}

} // namespace ctess::cli
