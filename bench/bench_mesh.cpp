// The CPU mesh pipeline (runtime/include/ctess/runtime/pipeline/mesh_pipeline.hpp) on all cores: a
// 10,000-patch height-field grid seen from a camera above one corner (factors from about 4 to 35), flat
// surface. One iteration is the whole frame: every patch's setup (in parallel, equal patch counts), the
// prefix sum (serial), then every vertex and triangle (in parallel, equal output triangle counts: the patches
// near the eye have far more). The patches are cut into one contiguous range per thread; each thread runs the
// library's setup_patch and emit_mesh_range on its range, so the library stays allocation- and thread-free.
// Counters: triangles per second and the thread count (compare 1 and 2 threads for scaling).
//
// mesh_pipeline/torus100k/*: what `ctess mesh --factor 8` does with a 100,352-face closed mesh (a torus
// written here: no uv or normal seams, every edge shared by two faces), one stage per benchmark on the
// calling thread: setup_patches, emit_mesh (the unwelded pipeline), setup_welded, emit_welded_mesh (what
// ctess mesh runs), and a memcpy of each stage's output bytes, so that the stages can be read against the
// cost of only writing their output. Counter tri/s: the stage's output triangles per second (setup included
// in its own line only). mesh_pipeline/torus100k/emit_welded_mesh_ranges/threads:N: emit_welded_mesh in N
// ranges of patches (welded_range), one per thread.
#include <ctess/core/config.hpp>
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
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
            if (rt::emit_mesh_range(tables(), grid.view(begin, end - begin), options, range, vertices,
                                    indices) != rt::PipelineStatus::ok)
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

// A closed torus of 224 x 224 quads, two triangles each (100,352 faces, 50,176 vertices), radii 3 and 1,
// counter-clockwise seen from outside; the last ring and column wrap to the first (no seam vertices).
struct Torus {
    static constexpr std::uint32_t rings = 224, sides = 224;
    std::vector<float> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<std::uint32_t>
        position_ids; // every vertex its own position, as models::build_adjacency gives
    Torus() {
        constexpr float major = 3.0f, minor = 1.0f, two_pi = 2.0f * std::numbers::pi_v<float>;
        for (std::uint32_t r = 0; r < rings; ++r) {
            const float a = two_pi * static_cast<float>(r) / rings;
            for (std::uint32_t s = 0; s < sides; ++s) {
                const float b = two_pi * static_cast<float>(s) / sides;
                const float nx = std::cos(a) * std::cos(b), ny = std::sin(a) * std::cos(b), nz = std::sin(b);
                const float v[rt::mesh_vertex_floats] = {major * std::cos(a) + minor * nx,
                                                         major * std::sin(a) + minor * ny,
                                                         minor * nz,
                                                         nx,
                                                         ny,
                                                         nz,
                                                         static_cast<float>(r) / rings,
                                                         static_cast<float>(s) / sides};
                vertices.insert(vertices.end(), v, v + rt::mesh_vertex_floats);
            }
        }
        auto at = [](std::uint32_t r, std::uint32_t s) { return (r % rings) * sides + s % sides; };
        for (std::uint32_t r = 0; r < rings; ++r) {
            for (std::uint32_t s = 0; s < sides; ++s) {
                const std::uint32_t a = at(r, s), b = at(r + 1, s), c = at(r + 1, s + 1), d = at(r, s + 1);
                indices.insert(indices.end(), {a, b, c, a, c, d});
            }
        }
        position_ids.resize(vertices.size() / rt::mesh_vertex_floats);
        for (std::uint32_t i = 0; i < position_ids.size(); ++i) position_ids[i] = i;
    }
    rt::MeshView view() const {
        rt::MeshView m;
        m.vertices = vertices.data();
        m.vertex_count = static_cast<std::uint32_t>(position_ids.size());
        m.indices = indices.data();
        m.triangle_count = static_cast<std::uint32_t>(indices.size() / 3);
        m.position_ids = position_ids.data();
        return m;
    }
};

// ctess mesh --factor 8 --surface flat: one constant factor on every edge.
rt::PipelineOptions torus_options() {
    rt::PipelineOptions options;
    options.dice.mode = rt::FactorMode::constant;
    options.dice.constant_factor = 8.0f;
    return options;
}

// One torus and the buffers of both pipelines, made once for every torus benchmark.
struct TorusRun {
    Torus torus;
    rt::MeshView mesh = torus.view();
    rt::PipelineOptions options = torus_options();
    std::vector<rt::PatchRecord> patches;
    rt::PipelineTotals totals;
    std::vector<rt::TessVertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<rt::WeldedEdge> edges;
    std::vector<rt::WeldedPatch> welded_patches;
    rt::WeldedTotals welded_totals;
    std::vector<rt::TessVertex> welded_vertices;
    std::vector<std::uint32_t> welded_indices;
    bool ok = true;
    TorusRun()
        : patches(mesh.patch_count()), edges(rt::weld_edge_capacity(mesh)),
          welded_patches(mesh.patch_count()) {
        ok = rt::setup_patches(tables(), mesh, options, patches, totals) == rt::PipelineStatus::ok &&
             rt::setup_welded(tables(), mesh, options, edges, welded_patches, welded_totals) ==
                 rt::PipelineStatus::ok;
        vertices.resize(totals.vertices);
        indices.resize(3 * std::size_t{totals.triangles});
        welded_vertices.resize(welded_totals.vertices);
        welded_indices.resize(3 * std::size_t{welded_totals.triangles});
        ok = ok &&
             rt::emit_mesh(tables(), mesh, options, patches, vertices, indices) == rt::PipelineStatus::ok &&
             rt::emit_welded_mesh(tables(), mesh, options, std::span(edges).first(welded_totals.edges),
                                  welded_patches, welded_vertices, welded_indices) == rt::PipelineStatus::ok;
    }
    std::size_t output_bytes() const {
        return vertices.size() * sizeof(rt::TessVertex) + indices.size() * sizeof(std::uint32_t);
    }
    std::size_t welded_output_bytes() const {
        return welded_vertices.size() * sizeof(rt::TessVertex) +
               welded_indices.size() * sizeof(std::uint32_t);
    }
};

TorusRun& torus_run() {
    static TorusRun run; // about 280 MB of output buffers, made on first use
    return run;
}

void torus_counters(benchmark::State& state, std::uint32_t triangles, std::size_t bytes) {
    state.counters["tri/s"] =
        benchmark::Counter(static_cast<double>(triangles) * static_cast<double>(state.iterations()),
                           benchmark::Counter::kIsRate);
    state.counters["tris"] = static_cast<double>(triangles);
    state.counters["out_bytes"] = static_cast<double>(bytes);
}

enum class TorusStage {
    setup_patches,
    emit_mesh,
    memcpy_mesh,
    setup_welded,
    emit_welded_mesh,
    memcpy_welded
};

template <TorusStage stage>
void torus_stage(benchmark::State& state) {
    TorusRun& run = torus_run();
    if (!run.ok) {
        state.SkipWithError("the pipeline refused the torus");
        return;
    }
    bool ok = true;
    const bool welded = stage == TorusStage::setup_welded || stage == TorusStage::emit_welded_mesh ||
                        stage == TorusStage::memcpy_welded;
    const std::size_t bytes = welded ? run.welded_output_bytes() : run.output_bytes();
    // The memcpy's source: a copy of the stage's output (its vertices, then its indices) in one buffer.
    std::vector<unsigned char> source, target;
    if constexpr (stage == TorusStage::memcpy_mesh || stage == TorusStage::memcpy_welded) {
        source.resize(bytes), target.resize(bytes);
        const auto& v = welded ? run.welded_vertices : run.vertices;
        const auto& i = welded ? run.welded_indices : run.indices;
        std::memcpy(source.data(), v.data(), v.size() * sizeof(rt::TessVertex));
        std::memcpy(source.data() + v.size() * sizeof(rt::TessVertex), i.data(),
                    i.size() * sizeof(std::uint32_t));
        std::memcpy(target.data(), source.data(),
                    bytes); // every page of the target touched before the timing
    }
    for (auto _ : state) {
        if constexpr (stage == TorusStage::setup_patches) {
            rt::PipelineTotals totals;
            ok = ok && rt::setup_patches(tables(), run.mesh, run.options, run.patches, totals) ==
                           rt::PipelineStatus::ok;
        } else if constexpr (stage == TorusStage::emit_mesh) {
            ok = ok && rt::emit_mesh(tables(), run.mesh, run.options, run.patches, run.vertices,
                                     run.indices) == rt::PipelineStatus::ok;
        } else if constexpr (stage == TorusStage::setup_welded) {
            rt::WeldedTotals totals;
            ok = ok && rt::setup_welded(tables(), run.mesh, run.options, run.edges, run.welded_patches,
                                        totals) == rt::PipelineStatus::ok;
        } else if constexpr (stage == TorusStage::emit_welded_mesh) {
            ok = ok &&
                 rt::emit_welded_mesh(tables(), run.mesh, run.options,
                                      std::span(run.edges).first(run.welded_totals.edges), run.welded_patches,
                                      run.welded_vertices, run.welded_indices) == rt::PipelineStatus::ok;
        } else {
            std::memcpy(target.data(), source.data(), bytes);
        }
        benchmark::ClobberMemory();
    }
    if (!ok) state.SkipWithError("the pipeline refused its own buffers");
    torus_counters(state, welded ? run.welded_totals.triangles : run.totals.triangles, bytes);
}

// emit_welded_mesh on N threads: one range of patches each (welded_range, equal output triangles), the
// calling thread takes range 0. Real time.
void torus_welded_ranges(benchmark::State& state) {
    TorusRun& run = torus_run();
    if (!run.ok) {
        state.SkipWithError("the pipeline refused the torus");
        return;
    }
    const auto threads = static_cast<std::uint32_t>(state.range(0));
    // Range k starts where welded_range's part k starts (part `threads` is the empty range at the end).
    const auto bound = [&](std::uint32_t k) {
        return rt::welded_range(run.mesh, run.welded_patches, k, threads).first_patch;
    };
    std::atomic<bool> ok = true;
    for (auto _ : state) {
        in_parallel(threads, bound, [&](std::uint32_t first, std::uint32_t end) {
            if (rt::emit_welded_mesh(tables(), run.mesh, run.options,
                                     std::span(run.edges).first(run.welded_totals.edges), run.welded_patches,
                                     rt::WeldedRange{first, end}, run.welded_vertices,
                                     run.welded_indices) != rt::PipelineStatus::ok)
                ok = false;
        });
        benchmark::ClobberMemory();
    }
    if (!ok) state.SkipWithError("the pipeline refused its own buffers");
    torus_counters(state, run.welded_totals.triangles, run.welded_output_bytes());
}

} // namespace

// One core: each stage on the calling thread.
BENCHMARK(torus_stage<TorusStage::setup_patches>)
    ->Name("mesh_pipeline/torus100k/setup_patches")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(torus_stage<TorusStage::emit_mesh>)
    ->Name("mesh_pipeline/torus100k/emit_mesh")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(torus_stage<TorusStage::memcpy_mesh>)
    ->Name("mesh_pipeline/torus100k/memcpy_mesh")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(torus_stage<TorusStage::setup_welded>)
    ->Name("mesh_pipeline/torus100k/setup_welded")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(torus_stage<TorusStage::emit_welded_mesh>)
    ->Name("mesh_pipeline/torus100k/emit_welded_mesh")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(torus_stage<TorusStage::memcpy_welded>)
    ->Name("mesh_pipeline/torus100k/memcpy_welded")
    ->Unit(benchmark::kMillisecond);
// emit_welded_mesh in ranges on 1 and 2 threads (real time).
BENCHMARK(torus_welded_ranges)
    ->Name("mesh_pipeline/torus100k/emit_welded_mesh_ranges")
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// Real time: the threads' CPU time is not the main thread's.
BENCHMARK(mesh_pipeline)
    ->Name("mesh_pipeline/grid10k")
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
