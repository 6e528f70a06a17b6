// A consumer of the installed Vulkan host (ctess::vulkan, docs/shaders.md "Hosts"), built as a user's project
// is: an octahedron tessellated by the installed SPIR-V on the loader's device (lavapipe in ctest), then
// checked against the CPU pipeline: equal counts, records, barycentrics and indices, positions within the
// shaders' documented bound; then welded on the GPU, against the CPU's weld and closed by index. Lines
// between "example" marks are the docs' example. Exit 0 when they agree.
#include <ctess/runtime.hpp>
#include <ctess/runtime/gpu/vulkan.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <utility>
#include <vector>

// The GPU's welded output of mesh with options against the CPU's weld, and the closed octahedron closed by
// index (every edge in two triangles); 0 when they agree.
int check_welded(const ctess::rt::MeshView& mesh, const ctess::rt::PipelineOptions& options,
                 std::uint32_t& welded_vertices) {
    ctess::vulkan::WeldedOutput welded;
    try {
        ctess::vulkan::Runner gpu(CTESS_SHADER_DIR, 64);
        welded = gpu.tessellate_welded(mesh, options);
    } catch (const ctess::vulkan::Error& e) {
        std::fprintf(stderr, "vulkan_mesh: welded: %s\n", e.what());
        return 1;
    }
    std::vector<ctess::rt::WeldedEdge> edges(ctess::rt::weld_edge_capacity(mesh));
    std::vector<ctess::rt::WeldedPatch> weld_patches(8);
    ctess::rt::WeldedTotals weld_totals;
    if (ctess::rt::setup_welded(ctess::rt::cp_tables_64, ctess::rt::uniform_tables, mesh, options, edges,
                                weld_patches, weld_totals) != ctess::rt::PipelineStatus::ok)
        return 2;
    edges.resize(weld_totals.edges);
    std::vector<ctess::rt::TessVertex> weld_vertices(weld_totals.vertices);
    std::vector<std::uint32_t> weld_indices(3 * std::size_t{weld_totals.triangles});
    if (ctess::rt::emit_welded_mesh(ctess::rt::cp_tables_64, ctess::rt::uniform_tables, mesh, options, edges,
                                    weld_patches, weld_vertices,
                                    weld_indices) != ctess::rt::PipelineStatus::ok)
        return 2;
    std::size_t open_or_shared = 0;
    {
        std::vector<std::pair<std::uint32_t, std::uint32_t>> keys;
        for (std::size_t t = 0; t < welded.indices.size(); t += 3)
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t a = welded.indices[t + k], b = welded.indices[t + (k + 1) % 3];
                keys.emplace_back(a < b ? a : b, a < b ? b : a);
            }
        std::sort(keys.begin(), keys.end());
        for (std::size_t i = 0; i < keys.size();) {
            std::size_t j = i;
            while (j < keys.size() && keys[j] == keys[i]) ++j;
            open_or_shared += j - i != 2;
            i = j;
        }
    }
    if (welded.totals.vertices != weld_totals.vertices || welded.totals.triangles != weld_totals.triangles ||
        welded.indices != weld_indices || weld_totals.vertices < 100 || open_or_shared != 0) {
        std::fprintf(stderr, "vulkan_mesh: the welded output differs from the CPU's or is not closed (%s)\n",
                     options.pattern == ctess::rt::Pattern::cp ? "cp" : "uniform split");
        return 5;
    }
    welded_vertices = welded.totals.vertices;
    return 0;
}

int main() {
    // An octahedron: 6 vertices (position, normal, uv: rt::mesh_vertex_floats each), 8 triangles.
    std::vector<float> vertices;
    const float axes[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const auto& a : axes)
        vertices.insert(vertices.end(), {a[0], a[1], a[2], a[0], a[1], a[2], 0.5f, 0.5f});
    const std::vector<std::uint32_t> indices = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                                                2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
    // example: tessellate on the GPU
    const ctess::rt::MeshView mesh{vertices.data(), 6, indices.data(), 8};
    ctess::rt::PipelineOptions options;
    options.surface.surface = ctess::rt::Surface::pn_triangles;
    options.dice.eye = {0.5f, 1.0f, 4.0f}; // camera; factors from DiceRate (2 pixels per segment)
    options.dice.projection_scale = 400.0f;
    ctess::vulkan::Output out;
    try {
        ctess::vulkan::Runner gpu(CTESS_SHADER_DIR, 64); // ctess_SHADER_DIR of find_package(ctess)
        out = gpu.tessellate(mesh, options);
        std::printf("%s: %u vertices, %u triangles\n", gpu.device_name().c_str(), out.totals.vertices,
                    out.totals.triangles);
    } catch (const ctess::vulkan::Error& e) {
        std::fprintf(stderr, "vulkan_mesh: %s\n", e.what());
        return 1;
    }
    // end of example

    std::vector<ctess::rt::PatchRecord> patches(8);
    ctess::rt::PipelineTotals totals;
    if (ctess::rt::setup_patches(ctess::rt::cp_tables_64, mesh, options, patches, totals) !=
        ctess::rt::PipelineStatus::ok)
        return 2;
    std::vector<ctess::rt::TessVertex> cpu_vertices(totals.vertices);
    std::vector<std::uint32_t> cpu_indices(3 * std::size_t{totals.triangles});
    if (ctess::rt::emit_mesh(ctess::rt::cp_tables_64, mesh, options, patches, cpu_vertices, cpu_indices) !=
        ctess::rt::PipelineStatus::ok)
        return 2;
    if (totals.vertices < 100 || out.totals.vertices != totals.vertices ||
        out.totals.triangles != totals.triangles || out.indices != cpu_indices ||
        std::memcmp(out.patches.data(), patches.data(), sizeof(patches[0]) * 8) != 0) {
        std::fprintf(stderr, "vulkan_mesh: counts, records or indices differ from the CPU's\n");
        return 3;
    }
    for (std::size_t v = 0; v < cpu_vertices.size(); ++v) {
        const ctess::rt::TessVertex &a = cpu_vertices[v], &b = out.vertices[v];
        bool same = a.u == b.u && a.v == b.v;
        for (int k = 0; k < 3; ++k) same = same && std::fabs(a.position[k] - b.position[k]) <= 1e-5f;
        if (!same) {
            std::fprintf(stderr, "vulkan_mesh: vertex %zu differs from the CPU's\n", v);
            return 4;
        }
    }
    // The welded output on the GPU (docs/shaders.md, "Welded output"): CP, and uniform density split above N
    // (welded by one sort over the mesh), each the CPU's weld and closed by index.
    ctess::rt::PipelineOptions split = options;
    split.pattern = ctess::rt::Pattern::uniform_split; // factors of about 64, above N = 16: the patches split
    std::uint32_t welded_vertices[2] = {};
    for (int k = 0; k < 2; ++k)
        if (const int failed = check_welded(mesh, k == 0 ? options : split, welded_vertices[k]))
            return failed;
    std::printf("vulkan_mesh: the GPU output equals the CPU's, unwelded and welded (%u vertices; split %u)\n",
                welded_vertices[0], welded_vertices[1]);
    return 0;
}
