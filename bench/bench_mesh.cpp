// The CPU mesh pipeline (runtime/include/ctess/runtime/pipeline/mesh_pipeline.hpp) on all cores: a
// 10,000-patch height-field grid seen from a camera above one corner (factors from about 4 to 35), flat
// surface. One iteration is the whole frame: every patch's setup (in parallel, equal patch counts), the
// prefix sum (serial), then every vertex and triangle (in parallel, equal output triangle counts: the patches
// near the eye have far more). The patches are cut into one contiguous range per thread; each thread runs the
// library's own per-patch functions on its range, so the library stays allocation- and thread-free. Counters:
// triangles per second and the thread count (compare 1 and 2 threads for scaling).
#include <ctess/core/config.hpp>
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <thread>
#include <vector>

#include <benchmark/benchmark.h>

namespace {

namespace rt = ctess::rt;

const rt::CpTableSet& tables() {
    return ctess::max_tess_factor == 256 ? rt::cp_tables_256 : rt::cp_tables_64;
}

// A (columns x rows)-quad grid on [0, 10] x [0, 20] with a gentle wave, two triangles per quad.
struct Grid {
    static constexpr std::uint32_t columns = 50, rows = 100; // 10,000 triangles
    std::vector<float> vertices;
    std::vector<std::uint32_t> indices;
    Grid() {
        for (std::uint32_t y = 0; y <= rows; ++y) {
            for (std::uint32_t x = 0; x <= columns; ++x) {
                const float px = 10.0f * static_cast<float>(x) / columns,
                            py = 20.0f * static_cast<float>(y) / rows;
                const float v[rt::mesh_vertex_floats] = {
                    px, py, 0.2f * std::sin(px) * std::cos(py), 0.0f, 0.0f, 1.0f, px / 10.0f, py / 20.0f};
                vertices.insert(vertices.end(), v, v + rt::mesh_vertex_floats);
            }
        }
        for (std::uint32_t y = 0; y < rows; ++y) {
            for (std::uint32_t x = 0; x < columns; ++x) {
                const std::uint32_t a = y * (columns + 1) + x, b = a + 1, c = a + columns + 1, d = c + 1;
                indices.insert(indices.end(), {a, b, d, a, d, c});
            }
        }
    }
    rt::MeshView view(std::uint32_t first, std::uint32_t count) const {
        return {vertices.data(), static_cast<std::uint32_t>(vertices.size() / rt::mesh_vertex_floats),
                indices.data() + 3 * std::size_t{first}, count};
    }
    std::uint32_t triangle_count() const { return static_cast<std::uint32_t>(indices.size() / 3); }
};

// Range k of the threads is [bound(k), bound(k + 1)); the calling thread takes range 0.
template <class Bound, class Work>
void in_parallel(unsigned threads, Bound&& bound, Work&& work) {
    std::vector<std::thread> pool;
    for (unsigned k = 1; k < threads; ++k) pool.emplace_back([&, k] { work(bound(k), bound(k + 1)); });
    work(bound(0), bound(1));
    for (std::thread& t : pool) t.join();
}

void mesh_pipeline(benchmark::State& state) {
    const unsigned threads = static_cast<unsigned>(state.range(0));
    const Grid grid;
    const rt::MeshView mesh = grid.view(0, grid.triangle_count());
    rt::PipelineOptions options;
    options.dice.eye = {-2.0f, -2.0f, 3.0f};
    std::vector<rt::PatchRecord> patches(mesh.triangle_count);
    rt::PipelineTotals totals;
    if (rt::setup_patches(tables(), mesh, options, patches, totals) != rt::PipelineStatus::ok) {
        state.SkipWithError("setup_patches refused the grid");
        return;
    }
    std::vector<rt::TessVertex> vertices(totals.vertices);
    std::vector<std::uint32_t> indices(3 * std::size_t{totals.triangles});
    std::atomic<bool> ok = true;
    for (auto _ : state) {
        // Setup costs the same per patch: equal patch counts.
        const std::uint32_t n = mesh.triangle_count;
        auto by_patches = [&](unsigned k) {
            return static_cast<std::uint32_t>(std::uint64_t{n} * k / threads);
        };
        in_parallel(threads, by_patches, [&](std::uint32_t begin, std::uint32_t end) {
            for (std::uint32_t t = begin; t < end; ++t)
                patches[t] = rt::setup_patch(tables(), mesh, t, options);
        });
        std::uint32_t v = 0, p = 0;
        for (rt::PatchRecord& rec : patches) {
            rec.first_vertex = v, rec.first_triangle = p;
            v += rec.vertex_count, p += rec.triangle_count;
        }
        if (v != totals.vertices || p != totals.triangles) ok = false;
        // Emission costs per output triangle, and the patches near the eye have far more: equal triangle
        // counts, found in the prefix sums.
        auto by_triangles = [&](unsigned k) {
            if (k == threads) return n;
            const std::uint32_t target = static_cast<std::uint32_t>(std::uint64_t{p} * k / threads);
            const auto it = std::lower_bound(
                patches.begin(), patches.end(), target,
                [](const rt::PatchRecord& r, std::uint32_t x) { return r.first_triangle < x; });
            return static_cast<std::uint32_t>(it - patches.begin());
        };
        in_parallel(threads, by_triangles, [&](std::uint32_t begin, std::uint32_t end) {
            const std::span<const rt::PatchRecord> range(patches.data() + begin, end - begin);
            if (rt::emit_mesh(tables(), grid.view(begin, end - begin), options, range, vertices, indices) !=
                rt::PipelineStatus::ok)
                ok = false;
        });
        benchmark::ClobberMemory();
    }
    if (!ok) state.SkipWithError("the pipeline refused its own buffers");
    state.counters["tri/s"] =
        benchmark::Counter(static_cast<double>(totals.triangles) * static_cast<double>(state.iterations()),
                           benchmark::Counter::kIsRate);
    state.counters["tris"] = static_cast<double>(totals.triangles);
    state.counters["patches"] = static_cast<double>(mesh.triangle_count);
}

} // namespace

// Real time: the threads' CPU time is not the main thread's.
BENCHMARK(mesh_pipeline)
    ->Name("mesh_pipeline/grid10k")
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
