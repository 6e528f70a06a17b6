// ctess mesh: a model file in (glTF 2.0 or OBJ: triangles, quads, n-gons), the mesh pipeline over every face
// at the chosen factors and surface, one welded indexed mesh out (OBJ, PLY or binary glTF), written to a
// temporary file and renamed (docs/cli.md, "ctess mesh"). The library does the work: ctess::models loads and
// finds the adjacency, the pipeline (setup_welded, emit_welded_mesh) tessellates and welds; this file parses
// options, times the stages and writes. `--unwelded` writes the pipeline's unwelded output instead (every
// patch's own vertices, as the generated shaders write them), from the CPU or, with `--backend
// vulkan|webgpu`, from the shaders themselves (docs/cli.md, "GPU backends"; mesh_backend.hpp).
#include "cli_args.hpp"
#include "commands.hpp"
#include "file_output.hpp"
#include "install_dirs.hpp"
#include "json_escape.hpp"
#include "mesh_backend.hpp"
#include "mesh_options.hpp"
#include "model_formats.hpp"
#include "model_prep.hpp"

#include <ctess/runtime/cp/table_set.hpp>
#include <ctess/runtime/displace/displace.hpp>
#include <ctess/runtime/gpu/shader_interface.hpp>
#include <ctess/runtime/models/adjacency.hpp>
#include <ctess/runtime/models/height_map.hpp>
#include <ctess/runtime/models/model.hpp>
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>
#include <ctess/runtime/uniform/table_set.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <memory>
#include <new>
#include <numbers>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include <fmt/core.h>

namespace ctess::cli {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

float finite_option(const Args& args, const std::string& key, float fallback) {
    if (!args.has(key)) return fallback;
    const float f = parse_float(args.get(key), "--" + key);
    if (!std::isfinite(f)) throw UsageError("--" + key + " must be a finite number");
    return f;
}

// The displacement options (docs/cli.md, "Models"): --displace FILE, --displace-gltf or --displace-vector
// FILE (an RGB tangent-space map, docs/algorithm.md §8.7), with --displace-scale, --displace-offset,
// --displace-address and --displace-grow. Checked before anything is loaded.
struct DisplaceRequest {
    bool on = false, from_gltf = false, vector = false, grow = false;
    std::string file;
    float scale = 1.0f;
    bool has_offset = false;
    float offset = 0.0f;
    rt::AddressMode address = rt::AddressMode::repeat;
};

DisplaceRequest displace_request_from(const Args& args) {
    DisplaceRequest r;
    const int sources =
        int{args.has("displace")} + int{args.has("displace-gltf")} + int{args.has("displace-vector")};
    if (sources > 1)
        throw UsageError("give one of --displace FILE, --displace-gltf and --displace-vector FILE");
    r.on = sources == 1;
    const bool details = args.has("displace-scale") || args.has("displace-offset") ||
                         args.has("displace-address") || args.has("displace-grow");
    if (details && !r.on)
        throw UsageError(
            "--displace-scale, --displace-offset, --displace-address and --displace-grow go with "
            "--displace FILE, --displace-gltf or --displace-vector FILE");
    r.from_gltf = args.has("displace-gltf");
    r.vector = args.has("displace-vector");
    r.file = r.vector ? args.get_or("displace-vector", "") : args.get_or("displace", "");
    if (args.has("displace") && r.file.empty()) throw UsageError("--displace needs a height map file");
    if (r.vector && r.file.empty()) throw UsageError("--displace-vector needs an RGB vector map file");
    r.scale = finite_option(args, "displace-scale", 1.0f);
    r.has_offset = args.has("displace-offset");
    r.offset = finite_option(args, "displace-offset", 0.0f);
    r.address = choice(args.get_or("displace-address", "repeat"), {"repeat", "clamp"},
                       "--displace-address") == "repeat"
                    ? rt::AddressMode::repeat
                    : rt::AddressMode::clamp;
    r.grow = args.has("displace-grow");
    return r;
}

// The height map the request names: the file, or the model's own KHR_materials_displacement image (an
// external file next to the model, or one embedded in it).
models::HeightImage load_displacement_image(const DisplaceRequest& r, const std::string& in,
                                            const models::Model& model) {
    models::HeightMapResult image;
    if (r.vector) {
        image = models::load_vector_map(r.file);
    } else if (!r.from_gltf) {
        image = models::load_height_map(r.file);
    } else {
        const models::Model::Displacement& d = model.displacement;
        if (!d.present || d.texture < 0)
            throw std::runtime_error(
                in + ": --displace-gltf: the model has no KHR_materials_displacement texture");
        if (!d.image_uri.empty())
            image = models::load_height_map((std::filesystem::path(in).parent_path() / d.image_uri).string());
        else if (!d.image_bytes.empty())
            image = models::load_height_map_from_memory(d.image_bytes, in + " (embedded displacement image)");
        else
            throw std::runtime_error(in + ": --displace-gltf: the displacement texture has no image");
    }
    if (!image) throw std::runtime_error(image.error.message);
    return std::move(*image.image);
}

struct StageSeconds {
    double load = 0, adjacency = 0, setup = 0, emit = 0, write = 0;
};

// Open edges of a triangle mesh by exact position (every output edge must be in two triangles).
std::size_t open_edges_by_position(const OutputMesh& mesh) {
    models::Model m;
    m.vertices.assign(mesh.vertices.begin(), mesh.vertices.end());
    m.triangles.assign(mesh.triangles.begin(), mesh.triangles.end());
    return models::open_edge_count(m, models::position_ids(m));
}

// The longest edge of every output triangle in the factor's own unit (DiceRate units for --dice-rate, L for
// --edge-length: rt::edge_factor of the edge), as median, 99th percentile and maximum. Constant factors have
// no length unit: empty.
struct EdgeQuantiles {
    bool present = false;
    double median = 0, p99 = 0, max = 0;
};

EdgeQuantiles longest_edges(const OutputMesh& mesh, const rt::DiceOptions& dice) {
    EdgeQuantiles q;
    if (dice.mode == rt::FactorMode::constant || mesh.triangles.empty()) return q;
    const auto position = [&](std::uint32_t v) {
        const float* p = &mesh.vertices[8 * std::size_t{v}];
        return rt::Vec3{p[0], p[1], p[2]};
    };
    std::vector<double> longest(mesh.triangle_count());
    for (std::size_t t = 0; t < longest.size(); ++t) {
        double l = 0;
        for (int k = 0; k < 3; ++k)
            l = std::max<double>(l, rt::edge_factor(position(mesh.triangles[3 * t + k]),
                                                    position(mesh.triangles[3 * t + (k + 1) % 3]), dice));
        longest[t] = l;
    }
    std::sort(longest.begin(), longest.end());
    const auto at = [&](double f) {
        return longest[static_cast<std::size_t>(f * static_cast<double>(longest.size() - 1))];
    };
    q.present = true;
    q.median = at(0.5);
    q.p99 = at(0.99);
    q.max = longest.back();
    return q;
}

// FNV-1a (32 bits) over the little-endian bytes of 32-bit words: the checksum the viewer computes over the
// GPU's output buffers too (docs/cli.md, "Models": `gpu`).
std::uint32_t fnv1a_words(std::uint32_t hash, std::span<const std::uint32_t> words) {
    for (const std::uint32_t w : words)
        for (unsigned byte = 0; byte < 4; ++byte) {
            hash ^= (w >> (8 * byte)) & 0xFFu;
            hash *= 16777619u;
        }
    return hash;
}
constexpr std::uint32_t fnv1a_basis = 2166136261u;

// What the generated shaders write for these options, which a GPU host can match bit for bit: the unwelded
// pipeline's counts (setup_patches, emit_mesh: every patch's own vertices, docs/shaders.md) and checksums of
// its exact words, the patch records (48 words each, without the totals), each vertex's base weights (u, v)
// and the indices. Positions, normals and uvs are left out: they agree with the GPU's within a bound only
// (docs/shaders.md, "Bit-exactness"). The viewer takes the camera factor mode. The shaders run the cp and
// uniform patterns; their uniform pattern clamps factors to [1, N] where `ctess mesh --pattern uniform`
// splits (docs/algorithm.md §7.5), and this block is the clamped one. The D3D11 patterns have no shader: the
// viewer draws them from `ctess serve`'s /api/tessellate, which returns this same output.
struct OutputChecksums {
    std::uint32_t records = fnv1a_basis, barycentrics = fnv1a_basis, indices = fnv1a_basis;
};

OutputChecksums output_checksums(const UnweldedOutput& output) {
    OutputChecksums c;
    for (const rt::PatchRecord& r : output.records) {
        std::uint32_t words[sizeof(rt::PatchRecord) / 4];
        std::memcpy(words, &r, sizeof words);
        c.records = fnv1a_words(c.records, words);
    }
    for (const rt::TessVertex& v : output.vertices)
        c.barycentrics = fnv1a_words(c.barycentrics, {{v.u, v.v}});
    c.indices = fnv1a_words(c.indices, output.indices);
    return c;
}

std::string checksums_json(const OutputChecksums& c) {
    return fmt::format("{{\"records\": \"{:08x}\", \"barycentrics\": \"{:08x}\", \"indices\": \"{:08x}\"}}",
                       c.records, c.barycentrics, c.indices);
}

struct GpuReference {
    bool present = false;
    std::uint64_t patches = 0;
    rt::PipelineTotals totals;
    std::uint32_t factor_scale_bits = 0;
    OutputChecksums checksums;
    double seconds = 0;
};

GpuReference gpu_reference(const rt::CpTableSet& cp, const rt::UniformTableSet& uniform,
                           const rt::MeshView& view, rt::PipelineOptions options, const std::string& in) {
    GpuReference g;
    if (options.dice.mode != rt::FactorMode::camera) return g;
    const auto start = Clock::now();
    if (options.pattern == rt::Pattern::uniform_split) options.pattern = rt::Pattern::uniform;
    const UnweldedOutput output = unwelded_output(cp, uniform, view, options, in, 0xFFFFFFFFu / 3);
    g.totals = output.totals;
    g.checksums = output_checksums(output);
    g.present = true;
    g.patches = view.patch_count();
    const float scale = options.dice.factor_scale();
    std::memcpy(&g.factor_scale_bits, &scale, 4);
    g.seconds = seconds_since(start);
    return g;
}

void check_triangle_limit(const std::string& in, std::uint32_t triangles, unsigned max_triangles) {
    if (triangles > max_triangles)
        throw std::runtime_error(
            fmt::format("{}: the tessellated model would have {} triangles, above the limit "
                        "of {} (--max-triangles; lower the factor or raise the limit)",
                        in, triangles, max_triangles));
}

// --backend and what goes with it (docs/cli.md, "GPU backends"), checked before anything is loaded.
struct BackendRequest {
    std::string name = "cpu";
    bool unwelded = false;
    GpuRun run;
};

BackendRequest backend_request_from(const Args& args, unsigned max) {
    BackendRequest r;
    r.name = choice(args.get_or("backend", "cpu"), {"cpu", "vulkan", "webgpu"}, "--backend");
    r.unwelded = args.has("unwelded");
    if (r.unwelded && args.has("keep-degenerate"))
        throw UsageError("--keep-degenerate goes with the welded output (--unwelded keeps every triangle)");
    if (args.has("shaders") && r.name == "cpu")
        throw UsageError("--shaders goes with --backend vulkan or webgpu");
    if (args.has("backend-timeout") && r.name != "webgpu")
        throw UsageError("--backend-timeout goes with --backend webgpu");
    r.run.shader_dir = args.get_or("shaders", installed_or_build_dir("shaders", CTESS_SHADER_DIR));
    r.run.max_factor = max;
    if (args.has("backend-timeout")) {
        const float t = parse_float(args.get("backend-timeout"), "--backend-timeout");
        if (!(t > 0 && t <= 86400))
            throw UsageError("--backend-timeout must be a number of seconds in (0, 86400]");
        r.run.timeout_seconds = t;
    }
    return r;
}

// What --unwelded runs. Where the generated shaders run the options (rt::gpu::gpu_options_status), it is
// their pipeline, so that every backend writes the same file: shared edges ordered by vertex index (the
// shaders take no position ids, docs/shaders.md "Hosts"; docs/algorithm.md §7.3), uniform density split at
// any factor leaf by leaf (§7.5). Elsewhere (the D3D11 patterns, --factor, --edge-length) it is the
// library's unwelded output as `ctess serve`'s /api/tessellate computes it, on the CPU only.
struct UnweldedPlan {
    rt::MeshView view;
    rt::PipelineOptions options;
    bool shaders = false;
    rt::PipelineStatus gpu_status = rt::PipelineStatus::ok;
};

UnweldedPlan unwelded_plan(const rt::MeshView& view, const rt::PipelineOptions& options) {
    UnweldedPlan plan{view, options};
    rt::MeshView gpu_view = view;
    gpu_view.position_ids = nullptr;
    const rt::PipelineOptions gpu_options = options;
    plan.gpu_status = rt::gpu::gpu_options_status(gpu_view, gpu_options);
    if (plan.gpu_status == rt::PipelineStatus::ok) {
        plan.view = gpu_view;
        plan.options = gpu_options;
        plan.shaders = true;
    }
    return plan;
}

// A GPU backend asked for options the shaders do not run: the reason, as the user typed the options.
[[noreturn]] void refuse_gpu_options(const std::string& backend, const std::string& pattern,
                                     const rt::PipelineOptions& options, rt::PipelineStatus status,
                                     bool unwelded) {
    if (status != rt::PipelineStatus::bad_option)
        throw std::runtime_error(
            fmt::format("--backend {}: {}", backend, rt::pipeline_status_message(status)));
    const std::string reason =
        pattern != "cp" && pattern != "uniform"
            ? "--pattern " + pattern + " has no shader (the D3D11 tessellator runs on the CPU only)"
        : options.dice.mode != rt::FactorMode::camera
            ? std::string("the shaders take camera factors only (--dice-rate with --camera), not --factor or "
                          "--edge-length")
            : std::string(rt::pipeline_status_message(status));
    throw UsageError(fmt::format("--backend {}: the GPU pipeline does not run these options: {} "
                                 "(rt::gpu::gpu_options_status; docs/shaders.md, \"Hosts\"). {}",
                                 backend, reason,
                                 unwelded ? "--backend cpu --unwelded writes their unwelded output"
                                          : "--backend cpu writes their welded output"));
}

// Runs work(k) for k < threads, k = 0 on the calling thread: std::jthread joins on unwinding too, and an
// exception in a thread (no memory) is rethrown here once every thread has joined.
template <class Work>
void on_threads(unsigned threads, Work&& work) {
    std::vector<std::exception_ptr> error(threads);
    const auto guarded = [&](unsigned k) noexcept {
        try {
            work(k);
        } catch (...) {
            error[k] = std::current_exception();
        }
    };
    {
        std::vector<std::jthread> pool;
        pool.reserve(threads - 1);
        for (unsigned k = 1; k < threads; ++k) pool.emplace_back(guarded, k);
        guarded(0);
    }
    for (const std::exception_ptr& e : error)
        if (e) std::rethrow_exception(e);
}

// emit_welded_mesh in `threads` ranges of patches (rt::welded_range), one thread each: the same output as one
// call (docs/algorithm.md §7.4, "Ranges"); one thread is the call without a range. The first failure is the
// answer.
rt::PipelineStatus emit_welded_threads(const rt::CpTableSet& cp, const rt::UniformTableSet& uniform,
                                       const rt::MeshView& view, const rt::PipelineOptions& options,
                                       std::span<const rt::WeldedEdge> edges,
                                       std::span<const rt::WeldedPatch> patches,
                                       std::span<rt::TessVertex> vertices, std::span<std::uint32_t> indices,
                                       unsigned threads) {
    if (threads <= 1)
        return rt::emit_welded_mesh(cp, uniform, view, options, edges, patches, vertices, indices);
    std::vector<rt::PipelineStatus> status(threads, rt::PipelineStatus::ok);
    on_threads(threads, [&](unsigned k) {
        status[k] = rt::emit_welded_mesh(cp, uniform, view, options, edges, patches,
                                         rt::welded_range(view, patches, k, threads), vertices, indices);
    });
    for (const rt::PipelineStatus s : status)
        if (s != rt::PipelineStatus::ok) return s;
    return rt::PipelineStatus::ok;
}

// The welded vertices before the mesh's layout takes them: malloc'd and not zeroed (the emit writes every
// one, first touching the pages on its own threads; a zeroing pass took longer than the emit itself).
struct FreeDeleter {
    void operator()(void* p) const noexcept { std::free(p); }
};
std::unique_ptr<rt::TessVertex[], FreeDeleter> unzeroed_vertices(std::size_t count) {
    void* p = std::malloc(std::max<std::size_t>(count, 1) * sizeof(rt::TessVertex));
    if (p == nullptr) throw std::bad_alloc();
    return std::unique_ptr<rt::TessVertex[], FreeDeleter>(static_cast<rt::TessVertex*>(p));
}

} // namespace

int run_mesh(int argc, char** argv) {
    const Args args(argc, argv, 2,
                    {"in",
                     "out",
                     "pattern",
                     "max",
                     "factor",
                     "edge-length",
                     "dice-rate",
                     "camera",
                     "fov",
                     "resolution",
                     "surface",
                     "quad-rule",
                     "max-triangles",
                     "displace",
                     "displace-scale",
                     "displace-offset",
                     "displace-address",
                     "displace-vector",
                     "backend",
                     "backend-timeout",
                     "shaders",
                     "threads"},
                    {"stats", "keep-degenerate", "displace-gltf", "displace-grow", "unwelded"});
    const std::string in = args.get("in");
    const std::string out = args.get_or("out", "");
    const bool stats = args.has("stats");
    if (out.empty() && !stats) throw UsageError("give --out FILE (.obj, .ply or .glb), --stats, or both");
    const std::string format = out.empty() ? "" : extension_of(out);
    if (!out.empty() && format != "obj" && format != "ply" && format != "glb")
        throw UsageError("--out must end in .obj, .ply or .glb");
    const std::string pattern = args.get_or("pattern", "cp");
    rt::PipelineOptions options = pipeline_options_from(args);
    if (pattern != "cp" && args.has("max")) throw UsageError("--max applies to --pattern cp only");
    const unsigned max = max_factor_from(args);
    options.weld.keep_degenerate = args.has("keep-degenerate");
    // The output is held in memory (about 32 bytes per triangle) before it is written: a bound the user can
    // raise, so that a factor typed too large is an error, not an allocation the machine cannot give.
    const unsigned max_triangles =
        args.has("max-triangles")
            ? parse_unsigned(args.get("max-triangles"), "--max-triangles", 1, 0xFFFFFFFFu / 3)
            : mesh_cli_default_max_triangles;
    const DisplaceRequest displace = displace_request_from(args);
    const BackendRequest backend = backend_request_from(args, max);
    // The welded emit in ranges of patches, one thread each (docs/cli.md, "Threads").
    const unsigned threads =
        args.has("threads") ? parse_unsigned(args.get("threads"), "--threads", 1, 64) : 1;
    if (args.has("threads") && (backend.unwelded || backend.name != "cpu"))
        throw UsageError("--threads goes with the CPU's welded output (emit_welded_mesh in ranges), not "
                         "--unwelded or a GPU backend");
    // The options alone, before the model is loaded: a pattern or factor mode the shaders lack.
    if (backend.name != "cpu")
        if (const UnweldedPlan early = unwelded_plan(rt::MeshView{}, options); !early.shaders)
            refuse_gpu_options(backend.name, pattern, options, early.gpu_status, backend.unwelded);
    StageSeconds seconds;
    auto start = Clock::now();
    models::LoadResult loaded = models::load_model(in);
    if (!loaded) throw std::runtime_error(loaded.error.message);
    seconds.load = seconds_since(start);

    start = Clock::now();
    const PreparedModel prepared = prepare_model(std::move(*loaded.model), in);
    const models::Model& model = prepared.model;
    const std::size_t input_open_edges = prepared.open_edges;
    const rt::MeshView view = prepared.view();
    seconds.adjacency = seconds_since(start);

    // Displacement (docs/algorithm.md §8): the height map, one direction per position, the options.
    models::HeightImage height_image;
    std::vector<float> directions, tangents;
    std::string tangent_source = "none"; // --stats: vector mode's frame from the model's TANGENT or the uvs
    rt::Displacement displacement;
    if (displace.on) {
        start = Clock::now();
        // Tangent space needs uvs: without them every tangent would be zero and x, y would be lost.
        if (displace.vector && !model.has_uvs)
            throw std::runtime_error(in + ": --displace-vector: the model has no texture coordinates (the "
                                          "tangent frame comes from their gradients)");
        height_image = load_displacement_image(displace, in, model);
        directions = displacement_directions(prepared, in);
        displacement.map = height_image.view(displace.address);
        displacement.scale = displace.scale;
        displacement.factor = displace.from_gltf ? model.displacement.factor : 1.0f;
        displacement.offset =
            displace.has_offset || !displace.from_gltf ? displace.offset : model.displacement.offset;
        displacement.directions = directions.data();
        if (displace.vector) {
            // One frame per position, from the dominant vertex's tangent (docs/algorithm.md §8.7): the
            // model's own (glTF TANGENT) when every primitive has them, else from the uv gradients.
            DisplacementTangents frame = displacement_tangents(prepared, in);
            tangents = std::move(frame.tangents);
            tangent_source = frame.source;
            displacement.mode = rt::DisplacementMode::vector;
            displacement.tangents = tangents.data();
        }
        if (displace.grow) displacement.factor_bound = rt::displacement_bound(displacement);
        options.displacement = &displacement;
        seconds.load += seconds_since(start);
    }

    const rt::CpTableSet& cp = max == 64 ? rt::cp_tables_64 : rt::cp_tables_256;
    const rt::UniformTableSet& uniform = rt::uniform_tables;
    OutputMesh mesh;
    std::uint64_t clamped_edges = 0;
    // --unwelded: what the backend wrote, with its device and the checksums of its exact words.
    std::string device;
    OutputChecksums checksums;
    bool shader_pipeline = false;
    // Into the mesh's layout (position, normal, uv), in `slices` parts, one thread each.
    const auto copy_vertices = [&mesh](std::span<const rt::TessVertex> vertices, unsigned slices = 1) {
        mesh.vertices.resize(8 * vertices.size());
        const std::size_t n = vertices.size();
        on_threads(slices, [&](unsigned k) {
            for (std::size_t i = n * k / slices; i < n * (k + 1) / slices; ++i) {
                float* v = &mesh.vertices[8 * i];
                const rt::TessVertex& t = vertices[i];
                v[0] = t.position[0], v[1] = t.position[1], v[2] = t.position[2];
                v[3] = t.normal[0], v[4] = t.normal[1], v[5] = t.normal[2];
                v[6] = t.uv[0], v[7] = t.uv[1];
            }
        });
    };
    if (backend.unwelded) {
        const UnweldedPlan plan = unwelded_plan(view, options);
        if (backend.name != "cpu" && !plan.shaders)
            refuse_gpu_options(backend.name, pattern, options, plan.gpu_status, backend.unwelded);
        shader_pipeline = plan.shaders;
        // The counts on the CPU first, whatever the backend: the limit before any output is allocated, and
        // clamped_edges (the shaders do not count them).
        start = Clock::now();
        UnweldedOutput counted; // the records and totals; the CPU backend emits from them
        counted.records.resize(plan.view.patch_count());
        const rt::PipelineStatus st =
            rt::setup_patches(cp, uniform, plan.view, plan.options, counted.records, counted.totals);
        if (st != rt::PipelineStatus::ok)
            throw std::runtime_error(fmt::format("{}: {}", in, rt::pipeline_status_message(st)));
        check_triangle_limit(in, counted.totals.triangles, max_triangles);
        clamped_edges = counted.totals.clamped_edges;
        seconds.setup = seconds_since(start);
        start = Clock::now();
        UnweldedOutput output;
        if (backend.name == "cpu") {
            output = std::move(counted);
            emit_unwelded(cp, uniform, plan.view, plan.options, in, output);
            device = "ctess CPU pipeline";
        } else {
            output = backend.name == "vulkan" ? vulkan_output(backend.run, plan.view, plan.options, device)
                                              : webgpu_output(backend.run, plan.view, plan.options, device);
            // The records are exact on the GPU (docs/shaders.md, "Bit-exactness"): a GPU result whose records
            // or totals are not the CPU's (a pass that did not run, a short read) is an error, never a file.
            if (output.totals.vertices != counted.totals.vertices ||
                output.totals.triangles != counted.totals.triangles ||
                output.records.size() != counted.records.size() ||
                (!counted.records.empty() &&
                 std::memcmp(output.records.data(), counted.records.data(),
                             counted.records.size() * sizeof(rt::PatchRecord)) != 0))
                throw std::runtime_error(fmt::format(
                    "--backend {}: the GPU's patch records or totals ({} vertices, {} triangles) differ from "
                    "the CPU's count ({} vertices, {} triangles)",
                    backend.name, output.totals.vertices, output.totals.triangles, counted.totals.vertices,
                    counted.totals.triangles));
        }
        checksums = output_checksums(output);
        copy_vertices(output.vertices);
        mesh.triangles.assign(output.indices.begin(), output.indices.end());
        seconds.emit = seconds_since(start);
    } else {
        start = Clock::now();
        // The unwelded counts first: they come from the patterns' counts alone, where the weld walks every
        // patch's output, so a factor typed too large is refused before any patch is tessellated. The welded
        // output has at most as many triangles.
        {
            std::vector<rt::PatchRecord> records(view.patch_count());
            rt::PipelineTotals unwelded;
            const rt::PipelineStatus counted =
                rt::setup_patches(cp, uniform, view, options, records, unwelded);
            if (counted != rt::PipelineStatus::ok)
                throw std::runtime_error(fmt::format("{}: {}", in, rt::pipeline_status_message(counted)));
            check_triangle_limit(in, unwelded.triangles, max_triangles);
            clamped_edges = unwelded.clamped_edges;
        }
        if (backend.name != "cpu") {
            // The shaders' weld of the model as they see it (vertex indices order shared edges: no position
            // ids, as --unwelded's plan): the CPU's welded faces exactly, floats within the bound
            // (docs/cli.md, "GPU backends").
            const UnweldedPlan plan = unwelded_plan(view, options);
            if (!plan.shaders)
                refuse_gpu_options(backend.name, pattern, options, plan.gpu_status, backend.unwelded);
            shader_pipeline = true;
            seconds.setup = seconds_since(start);
            start = Clock::now();
            WeldedGpuOutput output = backend.name == "vulkan"
                                         ? vulkan_welded_output(backend.run, plan.view, plan.options, device)
                                         : webgpu_welded_output(backend.run, plan.view, plan.options, device);
            check_triangle_limit(in, output.totals.triangles, max_triangles);
            copy_vertices(output.vertices);
            mesh.triangles.assign(output.indices.begin(), output.indices.end());
            seconds.emit = seconds_since(start);
        }
    }
    if (!backend.unwelded && backend.name == "cpu") {
        std::vector<rt::WeldedEdge> edges(rt::weld_edge_capacity(view));
        std::vector<rt::WeldedPatch> patches(view.patch_count());
        rt::WeldedTotals totals;
        rt::PipelineStatus status = rt::setup_welded(cp, uniform, view, options, edges, patches, totals);
        if (status != rt::PipelineStatus::ok)
            throw std::runtime_error(fmt::format("{}: {}", in, rt::pipeline_status_message(status)));
        check_triangle_limit(in, totals.triangles, max_triangles);
        edges.resize(totals.edges);
        clamped_edges = totals.clamped_edges;
        seconds.setup = seconds_since(start);

        start = Clock::now();
        const auto storage = unzeroed_vertices(totals.vertices);
        const std::span<rt::TessVertex> vertices(storage.get(), totals.vertices);
        mesh.triangles.resize(3 * std::size_t{totals.triangles});
        status = emit_welded_threads(cp, uniform, view, options, edges, patches, vertices, mesh.triangles,
                                     threads);
        if (status != rt::PipelineStatus::ok)
            throw std::runtime_error(fmt::format("{}: {}", in, rt::pipeline_status_message(status)));
        copy_vertices(vertices, threads);
        seconds.emit = seconds_since(start);
    }

    if (!out.empty()) {
        start = Clock::now();
        const std::string comment = fmt::format("ctess mesh --in {} --pattern {}", in, pattern);
        if (format == "glb")
            write_stream(out, [&](std::ostream& stream) { write_glb(mesh, comment, stream); });
        else if (format == "ply")
            write_stream(out, [&](std::ostream& stream) { write_ply(mesh, comment, stream); });
        else
            write_text(out, mesh_to_obj(mesh, comment));
        seconds.write = seconds_since(start);
    }
    if (stats) {
        const std::size_t output_open_edges = open_edges_by_position(mesh);
        const double total = seconds.load + seconds.adjacency + seconds.setup + seconds.emit + seconds.write;
        std::string text = "{\n";
        text += fmt::format("  \"input\": \"{}\",\n  \"pattern\": \"{}\",\n", json_escape(in), pattern);
        text += fmt::format("  \"input_vertices\": {},\n  \"input_triangles\": {},\n  \"input_quads\": {},\n",
                            model.vertex_count(), model.triangle_count(), model.quad_count());
        text += fmt::format("  \"dropped_degenerate_faces\": {},\n  \"input_open_edges\": {},\n",
                            model.dropped_degenerate_faces, input_open_edges);
        text += fmt::format(
            "  \"output_vertices\": {},\n  \"output_triangles\": {},\n  \"output_open_edges\": {},\n",
            mesh.vertex_count(), mesh.triangle_count(), output_open_edges);
        text += fmt::format("  \"clamped_edges\": {},\n", clamped_edges);
        text += fmt::format("  \"output\": \"{}\",\n  \"backend\": \"{}\",\n  \"threads\": {},\n",
                            backend.unwelded ? "unwelded" : "welded", backend.name, threads);
        if (backend.unwelded)
            text += fmt::format(
                "  \"unwelded\": {{\"shader_pipeline\": {}, \"device\": \"{}\", \"checksum\": {}}},\n",
                shader_pipeline, json_escape(device), checksums_json(checksums));
        else if (backend.name != "cpu")
            text += fmt::format("  \"welded\": {{\"shader_pipeline\": true, \"device\": \"{}\"}},\n",
                                json_escape(device));
        if (displace.on)
            text +=
                fmt::format("  \"displacement\": {{\"mode\": \"{}\", \"tangents\": \"{}\", \"channels\": {}, "
                            "\"width\": {}, \"height\": {}, \"bound\": {}, \"factor_bound\": {}}},\n",
                            displace.vector ? "vector" : "scalar", tangent_source, height_image.channels,
                            height_image.width, height_image.height, rt::displacement_bound(displacement),
                            displacement.factor_bound);
        if (const GpuReference g = gpu_reference(cp, uniform, view, options, in); g.present)
            text +=
                fmt::format("  \"gpu\": {{\"pattern\": \"{}\", \"patches\": {}, \"vertices\": {}, "
                            "\"triangles\": {}, \"clamped_edges\": {}, \"factor_scale_bits\": {}, "
                            "\"checksum\": {}, \"seconds\": {:.6f}}},\n",
                            pattern, g.patches, g.totals.vertices, g.totals.triangles, g.totals.clamped_edges,
                            g.factor_scale_bits, checksums_json(g.checksums), g.seconds);
        if (const EdgeQuantiles q = longest_edges(mesh, options.dice); q.present)
            text +=
                fmt::format("  \"longest_edge\": {{\"unit\": \"{}\", \"median\": {:.4f}, \"p99\": {:.4f}, "
                            "\"max\": {:.4f}}},\n",
                            options.dice.mode == rt::FactorMode::camera ? "dice_rate" : "edge_length",
                            q.median, q.p99, q.max);
        text +=
            fmt::format("  \"seconds\": {{\"load\": {:.6f}, \"adjacency\": {:.6f}, \"setup\": {:.6f}, "
                        "\"emit_and_weld\": {:.6f}, \"write\": {:.6f}, \"total\": {:.6f}}}\n",
                        seconds.load, seconds.adjacency, seconds.setup, seconds.emit, seconds.write, total);
        text += "}\n";
        write_text("-", text);
    }
    return 0;
}

} // namespace ctess::cli
