// UniformSplit (docs/algorithm.md §3.5) on the bulk factor sets above N = 16, both layouts (its shared layout
// welds the subpatches), construction included; also at the large factor sets (256 and 4,096).
#include <ctess/runtime/uniform/split.hpp>

#include <benchmark/benchmark.h>

#include "bench_uniform.hpp"

namespace {

using ctess::Layout;
using ctess::bench::uniform_emit;
using ctess::bench::uniform_factor_sets;
using ctess::rt::UniformSplit;

} // namespace

BENCHMARK(uniform_emit<UniformSplit, Layout::provoking>)
    ->Name("uniform/split_emit")
    ->Apply(uniform_factor_sets<false>)
    ->Apply(ctess::bench::large_factor_sets);
BENCHMARK(uniform_emit<UniformSplit, Layout::shared>)
    ->Name("uniform/split_emit_shared")
    ->Apply(uniform_factor_sets<false>)
    ->Apply(ctess::bench::large_factor_sets);
