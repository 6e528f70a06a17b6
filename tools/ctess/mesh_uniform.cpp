// The uniform-density mode of `ctess pattern` (docs/algorithm.md §3): the configured table's pattern through
// ctess::rt::UniformPatch. Only parses the request and calls the library.
#include "cli_args.hpp"
#include "commands.hpp"
#include "mesh.hpp"

#include <ctess/runtime/uniform/patch.hpp>
#include <ctess/runtime/uniform/split.hpp>

#include <fmt/core.h>

namespace ctess::cli {

Mesh tessellate_uniform(const PatternRequest& r) {
    if (r.domain != "tri") throw UsageError("--domain: the uniform mode tessellates the tri domain");
    if (r.factors.size() != 3)
        throw UsageError(fmt::format("--factors: uniform takes three edge factors f0,f1,f2, got {} values",
                                     r.factors.size()));
    const PatchOptions options{r.provoking_layout ? Layout::provoking : Layout::shared,
                               r.ccw ? Winding::ccw : Winding::cw};
    Mesh mesh;
    mesh.uniform.table_max = rt::uniform_tables.max_factor;
    const std::uint32_t n = rt::uniform_tables.max_factor;
    // The library splits up to factor 32,768 (a billion triangles); the CLI writes text, so it takes the
    // patterns up to uniform_cli_max_factor (at most 262,144 triangles, docs/cli.md).
    for (const float f : r.factors)
        if (!(f < uniform_cli_max_factor + 0.5f))
            throw UsageError(
                fmt::format("--factors: the uniform mode writes factors up to {} ({} rounds above "
                            "it); larger patterns are the library's (UniformSplit, up to 32768)",
                            uniform_cli_max_factor, f));
    const bool above = !uniform::within_table(r.factors[0], n) || !uniform::within_table(r.factors[1], n) ||
                       !uniform::within_table(r.factors[2], n);
    if (above) { // split with the table's own patterns (§3.5), welded in the shared layout
        const rt::UniformSplit split(rt::uniform_tables, r.factors[0], r.factors[1], r.factors[2], options);
        for (int i = 0; i < 3; ++i) mesh.uniform.factors[i] = static_cast<std::uint32_t>(split.factors()[i]);
        mesh.uniform.subpatches = split.subpatch_count();
        mesh.uniform.depth = split.depth();
        emit_patch(mesh, split);
        return mesh;
    }
    const rt::UniformPatch patch(rt::uniform_tables, r.factors[0], r.factors[1], r.factors[2], options);
    for (int i = 0; i < 3; ++i)
        mesh.uniform.factors[i] = rt::uniform_factor(r.factors[i], mesh.uniform.table_max);
    emit_patch(mesh, patch);
    return mesh;
}

} // namespace ctess::cli
