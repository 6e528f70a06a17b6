// UniformPatch (docs/algorithm.md §3.4) on the bulk factor sets within N = 16, both layouts: emit(), and the
// same patch written element by element through vertex(i) and triangle(p) (what emit() did before its bulk
// path). UniformSplit is timed in its own file, so that these instantiations do not change how the compiler
// inlines vertex(i) and triangle(p) into it.
#include <ctess/core/domain_point.hpp>
#include <ctess/runtime/uniform/patch.hpp>

#include <cstdint>
#include <span>

#include <benchmark/benchmark.h>

#include "bench_uniform.hpp"

namespace {

// UniformPatch emitted through random access, one call per element.
struct ByElement : ctess::rt::UniformPatch {
    using UniformPatch::UniformPatch;
    bool emit(std::span<ctess::uniform::Point> vertices, std::span<std::uint32_t> indices) const noexcept {
        const ctess::Counts n = counts();
        if (vertices.size() < n.vertices || indices.size() < n.index_count()) return false;
        for (std::uint32_t i = 0; i < n.vertices; ++i) vertices[i] = vertex(i);
        for (std::uint32_t p = 0; p < n.triangles; ++p) {
            const ctess::rt::UniformTriangle t = triangle(p);
            indices[3 * p] = t[0], indices[3 * p + 1] = t[1], indices[3 * p + 2] = t[2];
        }
        return true;
    }
};

using ctess::Layout;
using ctess::bench::uniform_emit;
using ctess::bench::uniform_factor_sets;
using ctess::rt::UniformPatch;

} // namespace

BENCHMARK(uniform_emit<UniformPatch, Layout::provoking>)
    ->Name("uniform/emit")
    ->Apply(uniform_factor_sets<true>);
BENCHMARK(uniform_emit<UniformPatch, Layout::shared>)
    ->Name("uniform/emit_shared")
    ->Apply(uniform_factor_sets<true>);
BENCHMARK(uniform_emit<ByElement, Layout::provoking>)
    ->Name("uniform/emit_by_element")
    ->Apply(uniform_factor_sets<true>);
BENCHMARK(uniform_emit<ByElement, Layout::shared>)
    ->Name("uniform/emit_by_element_shared")
    ->Apply(uniform_factor_sets<true>);
