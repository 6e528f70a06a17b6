// Writers for `ctess mesh` (docs/cli.md): a tessellated model as Wavefront OBJ (text, 9 significant digits,
// which round-trips every float), binary little-endian PLY, or binary glTF 2.0 (.glb, through tinygltf).
#pragma once
#include <cstdint>
#include <memory>
#include <new>
#include <ostream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace ctess::cli {

// An allocator whose resize() leaves new floats and integers unwritten (default-initialised), so that the
// tessellator writes the output's pages first, on its own threads, instead of after a zeroing pass (which
// took as long as the emit). Every element is written before it is read: the welded emit fills every vertex
// and index, copy_vertices every float (cmd_mesh.cpp).
template <class T>
struct UnzeroedAllocator : std::allocator<T> {
    using value_type = T;
    UnzeroedAllocator() = default;
    template <class U>
    UnzeroedAllocator(const UnzeroedAllocator<U>&) noexcept {}
    // Value-initialisation (resize) becomes default-initialisation; every other construction is
    // std::allocator_traits' own.
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
};

// One indexed triangle mesh: 8 floats per vertex (position xyz, normal xyz, uv), 3 indices per triangle,
// counter-clockwise. The layout of models::Model and the pipeline's vertex attributes.
struct OutputMesh {
    std::vector<float, UnzeroedAllocator<float>> vertices;
    std::vector<std::uint32_t, UnzeroedAllocator<std::uint32_t>> triangles;
    std::size_t vertex_count() const { return vertices.size() / 8; }
    std::size_t triangle_count() const { return triangles.size() / 3; }
};

// `comment` becomes the file's comment (OBJ, PLY) or asset.generator (glTF); one line, no newlines.
std::string mesh_to_obj(const OutputMesh& mesh, std::string_view comment);
// PLY is written to a stream (write_stream) too: its binary blocks go to the file as they are, without a copy
// of the whole file in memory first.
void write_ply(const OutputMesh& mesh, std::string_view comment, std::ostream& out);
// The .glb is written to a stream (write_stream: into the file, without a copy of it in memory).
void write_glb(const OutputMesh& mesh, std::string_view comment, std::ostream& out);

} // namespace ctess::cli
