// The uniform-density mode of `ctess pattern` (docs/algorithm.md §6): the configured table's pattern through
// ctess::rt::UniformPatch. Only parses the request and calls the library.
#include "cli_args.hpp"
#include "mesh.hpp"

#include <ctess/runtime/uniform_patch.hpp>

#include <fmt/core.h>

namespace ctess::cli {

Mesh tessellate_uniform(const PatternRequest& r) {
    if (r.domain != "tri") throw UsageError("--domain: the uniform mode tessellates the tri domain");
    if (r.factors.size() != 3)
        throw UsageError(fmt::format("--factors: uniform takes three edge factors f0,f1,f2, got {} values",
                                     r.factors.size()));
    const PatchOptions options{Layout::shared, r.ccw ? Winding::ccw : Winding::cw};
    const rt::UniformPatch patch(rt::uniform_tables, r.factors[0], r.factors[1], r.factors[2], options);
    Mesh mesh;
    mesh.fixed_one = uniform::fixed_one;
    mesh.vertices.resize(patch.counts().vertices);
    mesh.indices.resize(patch.counts().index_count());
    patch.emit(mesh.vertices, mesh.indices);
    return mesh;
}

} // namespace ctess::cli
