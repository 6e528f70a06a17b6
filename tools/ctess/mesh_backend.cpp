// `ctess mesh`'s GPU backends (mesh_backend.hpp).
#include "mesh_backend.hpp"

#include <ctess/runtime/gpu/shader_interface.hpp>

#if CTESS_HAVE_VULKAN
#include <ctess/runtime/gpu/vulkan.hpp>
#endif

#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <span>
#include <stdexcept>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/core.h>

extern char** environ;

namespace ctess::cli {

namespace {

// The shaders' output is used only once it has the sizes mesh implies and every index names a vertex, so a
// driver's or a child's bad result cannot reach the writers.
bool indices_within(const std::vector<std::uint32_t>& indices, std::size_t vertices) {
    for (const std::uint32_t i : indices)
        if (i >= vertices) return false;
    return true;
}

void check_output(const UnweldedOutput& out, const rt::MeshView& mesh, const char* backend) {
    const bool sized = out.records.size() == mesh.patch_count() &&
                       out.vertices.size() == out.totals.vertices &&
                       out.indices.size() == 3 * std::size_t{out.totals.triangles};
    if (!sized || !indices_within(out.indices, out.vertices.size()))
        throw std::runtime_error(fmt::format(
            "--backend {}: the GPU's output is malformed ({} records for {} "
            "patches, {} vertices, {} indices, or an index past the vertices)",
            backend, out.records.size(), mesh.patch_count(), out.vertices.size(), out.indices.size()));
}

void check_welded_output(const WeldedGpuOutput& out, const rt::MeshView& mesh, const char* backend) {
    const bool sized = out.patches.size() == mesh.patch_count() && out.edges.size() == out.totals.edges &&
                       out.vertices.size() == out.totals.vertices &&
                       out.indices.size() == 3 * std::size_t{out.totals.triangles};
    if (!sized || !indices_within(out.indices, out.vertices.size()))
        throw std::runtime_error(fmt::format(
            "--backend {}: the GPU's welded output is malformed ({} records for "
            "{} patches, {} vertices, {} indices, or an index past the vertices)",
            backend, out.patches.size(), mesh.patch_count(), out.vertices.size(), out.indices.size()));
}

// A scratch folder under the system's temporary directory, removed with everything in it at scope exit.
class ScratchDir {
  public:
    ScratchDir() {
        std::string pattern = (std::filesystem::temp_directory_path() / "ctess-mesh-XXXXXX").string();
        if (mkdtemp(pattern.data()) == nullptr)
            throw std::runtime_error(
                fmt::format("--backend webgpu: cannot create a temporary folder: {}", std::strerror(errno)));
        path_ = pattern;
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    std::string file(const char* name) const { return (path_ / name).string(); }

  private:
    std::filesystem::path path_;
};

void append_words(std::vector<std::uint32_t>& words, const void* data, std::size_t count) {
    const std::size_t at = words.size();
    words.resize(at + count);
    if (count != 0) std::memcpy(words.data() + at, data, 4 * count);
}

// The job file of ctess_mesh_node.mjs (its header comment has the layout): what vulkan::Runner uploads, in
// the same order (docs/shaders.md, "Passes and bindings", "Displacement").
std::vector<std::uint32_t> webgpu_job(const GpuRun& run, const rt::MeshView& mesh,
                                      const rt::PipelineOptions& options, bool welded) {
    namespace pw = rt::gpu::param_word;
    const auto params =
        welded ? rt::gpu::weld_params(mesh, options) : rt::gpu::pipeline_params(mesh, options);
    const rt::Displacement* d = options.displacement;
    const std::uint32_t flags = params[pw::displacement_flags];
    const bool displaced = (flags & rt::gpu::displacement_flag::on) != 0;
    // PN-AEN reads binding 3 to its end (arrayLength): the adjacency only where the params need it.
    const bool adjacency =
        mesh.adjacency != nullptr && (displaced ? (flags & rt::gpu::displacement_flag::adjacency) != 0
                                                : options.surface.surface == rt::Surface::pn_aen);
    const std::size_t vertex_floats = std::size_t{mesh.vertex_count} * rt::mesh_vertex_floats;
    const std::size_t triangle_words = 3 * std::size_t{mesh.triangle_count};
    const std::size_t quad_words = 4 * std::size_t{mesh.quad_count};
    const std::size_t adjacency_words =
        adjacency ? 12 * (std::size_t{mesh.triangle_count} + 2 * std::size_t{mesh.quad_count}) : 0;
    const std::size_t texel_floats = displaced ? std::size_t{params[pw::height_map_width]} *
                                                     params[pw::height_map_height] * rt::gpu::texel_floats(*d)
                                               : 0;
    const std::size_t direction_floats = displaced && (flags & rt::gpu::displacement_flag::directions) != 0
                                             ? 3 * std::size_t{mesh.vertex_count}
                                             : 0;
    const std::size_t tangent_floats = displaced && (flags & rt::gpu::displacement_flag::vector) != 0
                                           ? 4 * std::size_t{mesh.vertex_count}
                                           : 0;
    const std::size_t sizes[] = {
        params.size(), vertex_floats,    triangle_words + quad_words + adjacency_words,
        texel_floats,  direction_floats, tangent_floats};
    std::vector<std::uint32_t> job = {0x4E4D5443u, 1u, run.max_factor};
    for (const std::size_t s : sizes) {
        if (s > 0xFFFFFFFFu) throw std::runtime_error("--backend webgpu: the model is too large for one job");
        job.push_back(static_cast<std::uint32_t>(s));
    }
    append_words(job, params.data(), params.size());
    append_words(job, mesh.vertices, vertex_floats);
    append_words(job, mesh.indices, triangle_words);
    append_words(job, mesh.quad_indices, quad_words);
    append_words(job, mesh.adjacency, adjacency_words);
    if (texel_floats != 0) append_words(job, d->map.texels, texel_floats);
    if (direction_floats != 0) append_words(job, d->directions, direction_floats);
    if (tangent_floats != 0) append_words(job, d->tangents, tangent_floats);
    return job;
}

std::string read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The last lines of node's output, for an error message.
std::string log_tail(const std::string& path) {
    std::string text = read_file(path);
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    if (text.size() > 2000) text = "..." + text.substr(text.size() - 2000);
    return text.empty() ? "(no output)" : text;
}

// The signal that interrupted run_child's wait (SIGINT, SIGTERM, SIGHUP), or 0.
volatile std::sig_atomic_t interrupted_by = 0;
extern "C" void note_interrupt(int signal_number) {
    interrupted_by = signal_number;
}

// For run_child's lifetime: SIGINT, SIGTERM and SIGHUP only noted (the wait loop then kills the child's group
// and throws, so the scratch folder is removed; the signal is raised again after that, in ctess's main), and
// SIGCHLD at its default (an ignored SIGCHLD, inherited from a parent, makes waitpid fail). Restored after.
class ChildSignals {
  public:
    ChildSignals() {
        interrupted_by = 0;
        struct sigaction note {};
        note.sa_handler = note_interrupt;
        sigemptyset(&note.sa_mask);
        for (unsigned k = 0; k < 3; ++k) sigaction(stops[k], &note, &saved_[k]);
        struct sigaction default_action {};
        default_action.sa_handler = SIG_DFL;
        sigemptyset(&default_action.sa_mask);
        sigaction(SIGCHLD, &default_action, &saved_child_);
    }
    ~ChildSignals() {
        for (unsigned k = 0; k < 3; ++k) sigaction(stops[k], &saved_[k], nullptr);
        sigaction(SIGCHLD, &saved_child_, nullptr);
    }
    ChildSignals(const ChildSignals&) = delete;
    ChildSignals& operator=(const ChildSignals&) = delete;
    static constexpr int stops[3] = {SIGINT, SIGTERM, SIGHUP};

  private:
    struct sigaction saved_[3] = {}, saved_child_ = {};
};

// Runs argv (argv[0] looked up on PATH, no shell), stdin from /dev/null, stdout and stderr into log, in a
// process group of its own; kills that whole group (node and anything it started, e.g. a version manager's
// shim) once timeout_seconds have passed or when ctess gets SIGINT, SIGTERM or SIGHUP. Returns the exit
// status, -1 when the timeout killed it, -2 when a signal did. Throws Interrupted after an interrupt.
int run_child(const std::vector<std::string>& args, const std::string& log, double timeout_seconds) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const ChildSignals signals;
    posix_spawn_file_actions_t actions;
    posix_spawnattr_t attr;
    posix_spawn_file_actions_init(&actions);
    posix_spawnattr_init(&attr);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    sigset_t empty; // the default signal mask and dispositions, whatever ctess's are
    sigemptyset(&empty);
    posix_spawnattr_setsigmask(&attr, &empty);
    sigset_t defaults;
    sigemptyset(&defaults);
    for (const int k : ChildSignals::stops) sigaddset(&defaults, k);
    sigaddset(&defaults, SIGCHLD);
    posix_spawnattr_setsigdefault(&attr, &defaults);
    posix_spawnattr_setpgroup(&attr, 0);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETPGROUP);
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, argv[0], &actions, &attr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    if (spawned == ENOENT)
        throw std::runtime_error(
            fmt::format("--backend webgpu: '{}' is not on PATH: install Node.js (Debian: apt-get install "
                        "nodejs) and the npm package webgpu (npm install webgpu)",
                        args[0]));
    if (spawned != 0)
        throw std::runtime_error(
            fmt::format("--backend webgpu: cannot start '{}': {}", args[0], std::strerror(spawned)));
    const auto kill_group = [pid] {
        kill(-pid, SIGKILL);
        int status = 0;
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
    };
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_seconds);
    for (auto pause = std::chrono::milliseconds(1);;
         pause = std::min(2 * pause, std::chrono::milliseconds(50))) {
        int status = 0;
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) {
            kill(-pid, SIGKILL); // whatever node left running in its group
            return WIFEXITED(status) ? WEXITSTATUS(status) : -2;
        }
        if (done < 0 && errno != EINTR) {
            const int error = errno;
            kill_group();
            throw std::runtime_error(fmt::format("--backend webgpu: waitpid: {}", std::strerror(error)));
        }
        if (interrupted_by != 0) {
            kill_group();
            throw Interrupted(interrupted_by);
        }
        if (std::chrono::steady_clock::now() >= deadline) {
            kill_group();
            return -1;
        }
        std::this_thread::sleep_for(pause);
    }
}

} // namespace

bool have_vulkan_backend() {
    return CTESS_HAVE_VULKAN != 0;
}

namespace {

#if CTESS_HAVE_VULKAN
// A Runner on the loader's first device, its name in `device`, and run(runner)'s output; Vulkan's errors
// named as the backend's.
template <class Run>
auto with_vulkan(const GpuRun& run, std::string& device, Run&& tessellate) {
    try {
        vulkan::Runner runner(run.shader_dir, run.max_factor);
        device = runner.device_name();
        return tessellate(runner);
    } catch (const vulkan::Error& e) {
        throw std::runtime_error(fmt::format("--backend vulkan: {}", e.what()));
    }
}
#else
[[noreturn]] void no_vulkan() {
    throw std::runtime_error(
        "--backend vulkan: this ctess was built without Vulkan (install Debian libvulkan-dev "
        "and rebuild; ctess::vulkan)");
}
#endif

} // namespace

UnweldedOutput vulkan_output([[maybe_unused]] const GpuRun& run, [[maybe_unused]] const rt::MeshView& mesh,
                             [[maybe_unused]] const rt::PipelineOptions& options,
                             [[maybe_unused]] std::string& device) {
#if CTESS_HAVE_VULKAN
    UnweldedOutput out = with_vulkan(run, device, [&](vulkan::Runner& runner) {
        vulkan::Output gpu = runner.tessellate(mesh, options);
        return UnweldedOutput{gpu.totals, std::move(gpu.patches), std::move(gpu.vertices),
                              std::move(gpu.indices)};
    });
    check_output(out, mesh, "vulkan");
    return out;
#else
    no_vulkan();
#endif
}

WeldedGpuOutput vulkan_welded_output([[maybe_unused]] const GpuRun& run,
                                     [[maybe_unused]] const rt::MeshView& mesh,
                                     [[maybe_unused]] const rt::PipelineOptions& options,
                                     [[maybe_unused]] std::string& device) {
#if CTESS_HAVE_VULKAN
    WeldedGpuOutput out = with_vulkan(run, device, [&](vulkan::Runner& runner) {
        vulkan::WeldedOutput gpu = runner.tessellate_welded(mesh, options);
        return WeldedGpuOutput{gpu.totals, std::move(gpu.edges), std::move(gpu.patches),
                               std::move(gpu.vertices), std::move(gpu.indices)};
    });
    check_welded_output(out, mesh, "vulkan");
    return out;
#else
    no_vulkan();
#endif
}

namespace {

// node's result file (ctess_mesh_node.mjs's header comment) as words, after the run: the header checked.
struct NodeResult {
    std::vector<std::uint32_t> words;
    std::uint64_t record_words = 0, vertex_words = 0, index_words = 0, name_bytes = 0;
};

NodeResult run_node_job(const GpuRun& run, const rt::MeshView& mesh, const rt::PipelineOptions& options,
                        bool welded);

} // namespace

WeldedGpuOutput webgpu_welded_output(const GpuRun& run, const rt::MeshView& mesh,
                                     const rt::PipelineOptions& options, std::string& device) {
    const NodeResult r = run_node_job(run, mesh, options, true);
    constexpr std::uint32_t per_vertex = sizeof(rt::TessVertex) / 4;
    const std::uint64_t patch_words = 4 * std::uint64_t{mesh.patch_count()};
    // The records: the edges (4 words each), the patches' (4 each), then the totals' vertices, triangles and
    // edges.
    if (r.record_words < patch_words + 3 || (r.record_words - patch_words - 3) % 4 != 0 ||
        r.vertex_words % per_vertex != 0 || r.index_words % 3 != 0)
        throw std::runtime_error("--backend webgpu: the welded result file of node is malformed");
    WeldedGpuOutput out;
    const std::uint32_t* at = r.words.data() + 7;
    const std::uint64_t edges = (r.record_words - patch_words - 3) / 4;
    out.edges.resize(static_cast<std::size_t>(edges));
    if (edges != 0) std::memcpy(static_cast<void*>(out.edges.data()), at, 16 * edges);
    at += 4 * edges;
    out.patches.resize(mesh.patch_count());
    if (patch_words != 0) std::memcpy(static_cast<void*>(out.patches.data()), at, 4 * patch_words);
    at += patch_words;
    out.totals = {at[0], at[1], at[2], 0};
    at += 3;
    out.vertices.resize(static_cast<std::size_t>(r.vertex_words / per_vertex));
    if (r.vertex_words != 0) std::memcpy(static_cast<void*>(out.vertices.data()), at, 4 * r.vertex_words);
    at += r.vertex_words;
    out.indices.assign(at, at + r.index_words);
    at += r.index_words;
    device.assign(reinterpret_cast<const char*>(at), r.name_bytes);
    check_welded_output(out, mesh, "webgpu");
    return out;
}

namespace {

NodeResult run_node_job(const GpuRun& run, const rt::MeshView& mesh, const rt::PipelineOptions& options,
                        bool welded) {
    // Absolute, so that a shader folder named like an option (`-x`) is never read by node as one.
    const std::string module =
        std::filesystem::absolute(std::filesystem::path(run.shader_dir) / "ctess_mesh_node.mjs").string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(module, ec))
        throw std::runtime_error(
            fmt::format("--backend webgpu: no '{}' (the shader folder: --shaders DIR)", module));
    const ScratchDir scratch;
    const std::string job_file = scratch.file("job.bin"), result_file = scratch.file("result.bin"),
                      log_file = scratch.file("node.log");
    {
        const std::vector<std::uint32_t> job = webgpu_job(run, mesh, options, welded);
        std::ofstream job_out(job_file, std::ios::binary);
        job_out.write(reinterpret_cast<const char*>(job.data()),
                      static_cast<std::streamsize>(4 * job.size()));
        if (!job_out.flush())
            throw std::runtime_error(fmt::format("--backend webgpu: cannot write '{}'", job_file));
    }
    const int status = run_child({"node", module, job_file, result_file}, log_file, run.timeout_seconds);
    if (status == -1)
        throw std::runtime_error(fmt::format("--backend webgpu: node did not finish within {:g} s "
                                             "(--backend-timeout); it was killed. Its output:\n{}",
                                             run.timeout_seconds, log_tail(log_file)));
    if (status != 0)
        throw std::runtime_error(fmt::format("--backend webgpu: node {}: {}",
                                             status == -2 ? "was killed by a signal"
                                                          : fmt::format("exited with status {}", status),
                                             log_tail(log_file)));
    // The result (ctess_mesh_node.mjs's header comment), every size checked against the file's.
    const std::string bytes = read_file(result_file);
    std::vector<std::uint32_t> words(bytes.size() / 4);
    if (!words.empty()) std::memcpy(words.data(), bytes.data(), 4 * words.size());
    const auto malformed = [&] {
        return std::runtime_error(fmt::format("--backend webgpu: the result file of node is malformed "
                                              "({} bytes)",
                                              bytes.size()));
    };
    if (bytes.size() % 4 != 0 || words.size() < 7 || words[0] != 0x524D5443u || words[1] != 1u)
        throw malformed();
    const std::uint64_t record_words = words[2], vertex_words = words[3], index_words = words[4],
                        name_bytes = words[6];
    const std::uint64_t expected = 7 + record_words + vertex_words + index_words + (name_bytes + 3) / 4;
    if (expected != words.size()) throw malformed();
    return {std::move(words), record_words, vertex_words, index_words, name_bytes};
}

} // namespace

UnweldedOutput webgpu_output(const GpuRun& run, const rt::MeshView& mesh, const rt::PipelineOptions& options,
                             std::string& device) {
    const NodeResult r = run_node_job(run, mesh, options, false);
    constexpr std::uint32_t per_vertex = sizeof(rt::TessVertex) / 4;
    const std::uint64_t record_words = r.record_words, vertex_words = r.vertex_words,
                        index_words = r.index_words, name_bytes = r.name_bytes;
    if (record_words != rt::gpu::patch_buffer_words(mesh.patch_count()) || vertex_words % per_vertex != 0 ||
        index_words % 3 != 0)
        throw std::runtime_error(fmt::format("--backend webgpu: the result file of node is malformed "
                                             "({} bytes)",
                                             4 * r.words.size()));
    UnweldedOutput out;
    const std::uint32_t* at = r.words.data() + 7;
    out.records.resize(mesh.patch_count());
    std::memcpy(static_cast<void*>(out.records.data()), at, sizeof(rt::PatchRecord) * out.records.size());
    at += record_words;
    out.totals.vertices = static_cast<std::uint32_t>(vertex_words / per_vertex);
    out.totals.triangles = static_cast<std::uint32_t>(index_words / 3);
    out.vertices.resize(out.totals.vertices);
    std::memcpy(static_cast<void*>(out.vertices.data()), at, 4 * vertex_words);
    at += vertex_words;
    out.indices.assign(at, at + index_words);
    at += index_words;
    device.assign(reinterpret_cast<const char*>(at), name_bytes);
    check_output(out, mesh, "webgpu");
    return out;
}

} // namespace ctess::cli
