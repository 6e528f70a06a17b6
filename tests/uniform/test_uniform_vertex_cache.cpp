// The uniform patterns' triangle order for the post-transform vertex cache (docs/algorithm.md §3.1), measured
// with meshoptimizer's analyzer (16-entry FIFO): ATVR (vertex shader runs per vertex) near 1, and within 5 %
// of what meshoptimizer's own reordering of the same triangles reaches.
#include <ctess/uniform/pattern.hpp>

#include <meshoptimizer.h>

#include <vector>

#include <catch2/catch.hpp>

TEST_CASE("uniform: triangle order keeps ATVR near 1 (meshoptimizer, cache 16)", "[uniform][cache]") {
    for (unsigned n : {11u, 16u}) {
        double ours = 0, reference = 0;
        unsigned count = 0;
        for (unsigned a = 1; a <= n; ++a)
            for (unsigned b = 1; b <= a; ++b)
                for (unsigned c = 1; c <= b; ++c) {
                    const auto p = ctess::uniform::pattern(a, b, c);
                    std::vector<unsigned> idx;
                    for (unsigned t = 0; t < p.triangle_count(); ++t)
                        for (unsigned k : p.triangle(t)) idx.push_back(k);
                    ours +=
                        meshopt_analyzeVertexCache(idx.data(), idx.size(), p.vertex_count(), 16, 0, 0).atvr;
                    std::vector<unsigned> opt(idx.size());
                    meshopt_optimizeVertexCache(opt.data(), idx.data(), idx.size(), p.vertex_count());
                    reference +=
                        meshopt_analyzeVertexCache(opt.data(), opt.size(), p.vertex_count(), 16, 0, 0).atvr;
                    ++count;
                }
        INFO("N = " << n << ": mean ATVR " << ours / count << ", meshoptimizer " << reference / count);
        CHECK(ours / count <= 1.06);
        CHECK(ours / count <= 1.05 * reference / count);
    }
}
