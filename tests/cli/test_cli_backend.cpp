// `ctess mesh --unwelded --backend cpu|vulkan|webgpu` (docs/cli.md, "GPU backends") on Debian's
// assimp-testmodels: every backend writes the same file, byte for byte, for the flat surface; for PN the same
// faces and vertex counts, every exact word (records, barycentrics, indices: `--stats`' checksums) equal, and
// positions, normals and uvs within the GPU tests' bound (tests/gpu/pipeline_output.hpp's compare:
// |gpu - cpu| <= 1e-5 max(1, |cpu|) per component; docs/shaders.md, "Bit-exactness"). Vulkan runs on lavapipe
// (VK_DRIVER_FILES), WebGPU on Dawn's OpenGL ES backend in node (CTESS_DAWN_BACKEND=opengles), set per run.
// A backend without a device, node or npm `webgpu` fails the case, as the GPU tests do (lavapipe and `npm ci`
// are part of the test setup, README). Then the refusals: each with a non-zero exit, a message naming the
// cause and no file.
#include "mesh_cli_support.hpp"
#include "support/cli_run.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

using ctess::test::ctess_cli;
using ctess::test::Run;

namespace {

const std::string spider = "/usr/share/assimp/models/OBJ/spider.obj"; // 1,312 triangles, uv seams
const std::string box = "/usr/share/assimp/models/OBJ/box.obj";       // 6 quads

std::string scratch(const std::string& name) {
    return ctess::test::scratch_path("ctess_test_cli_backend", name);
}

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// `ctess mesh [--unwelded] --backend B --stats --out OUT ARGS`: its stats.
nlohmann::json run_mesh(const std::string& backend, const std::string& args, const std::string& out,
                        bool unwelded) {
    std::filesystem::remove(out);
    // Vulkan on lavapipe, Dawn on its GLES backend (the one the GPU tests use), and no leak check in ctess
    // under the asan-ubsan preset: lavapipe leaks 128 bytes in a module the loader has unloaded by exit
    // (tests/gpu/test_gpu.cpp).
    const Run r = ctess::test::run_shell(
        "VK_DRIVER_FILES=" CTESS_LAVAPIPE_ICD " CTESS_DAWN_BACKEND=opengles "
        "ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 " CTESS_CLI " mesh " +
        std::string(unwelded ? "--unwelded " : "") + "--backend " + backend + " --stats --out " + out + " " +
        args + " 2>&1");
    INFO(backend << " " << args << "\n" << r.out);
    REQUIRE(r.exit_code == 0);
    return nlohmann::json::parse(r.out);
}
nlohmann::json run_backend(const std::string& backend, const std::string& args, const std::string& out) {
    return run_mesh(backend, args, out, true);
}

// A binary PLY as ctess writes it (docs/cli.md, "Models"): 8 floats per vertex, triangles as 3 indices.
struct Ply {
    std::vector<float> vertices;
    std::vector<std::uint32_t> triangles;
};

Ply read_ply(const std::string& path) {
    const std::string bytes = read_bytes(path);
    const std::size_t body = bytes.find("end_header\n");
    REQUIRE(body != std::string::npos);
    std::istringstream header(bytes.substr(0, body));
    std::size_t vertex_count = 0, face_count = 0;
    for (std::string line; std::getline(header, line);) {
        std::sscanf(line.c_str(), "element vertex %zu", &vertex_count);
        std::sscanf(line.c_str(), "element face %zu", &face_count);
    }
    const std::size_t at = body + 11;
    REQUIRE(bytes.size() == at + 32 * vertex_count + 13 * face_count);
    Ply ply;
    ply.vertices.resize(8 * vertex_count);
    std::memcpy(ply.vertices.data(), bytes.data() + at, 32 * vertex_count);
    ply.triangles.resize(3 * face_count);
    std::size_t bad_counts = 0;
    for (std::size_t f = 0; f < face_count; ++f) {
        const char* face = bytes.data() + at + 32 * vertex_count + 13 * f;
        bad_counts += face[0] != 3;
        std::memcpy(&ply.triangles[3 * f], face + 1, 12);
    }
    CHECK(bad_counts == 0);
    return ply;
}

// The GPU against the CPU: the same faces, and every float within the GPU tests' bound.
void check_within_bound(const std::string& cpu_file, const std::string& gpu_file) {
    const Ply cpu = read_ply(cpu_file), gpu = read_ply(gpu_file);
    REQUIRE(cpu.vertices.size() == gpu.vertices.size());
    CHECK(cpu.triangles == gpu.triangles);
    std::size_t outside = 0, differing = 0;
    double largest = 0;
    for (std::size_t k = 0; k < cpu.vertices.size(); ++k) {
        const double a = cpu.vertices[k], b = gpu.vertices[k];
        const double err = std::fabs(a - b) / std::fmax(1.0, std::fabs(a));
        largest = std::fmax(largest, err);
        differing += a != b;
        outside += !(err <= 1e-5);
    }
    INFO("largest relative difference " << largest << ", " << differing << " of " << cpu.vertices.size()
                                        << " floats differ");
    CHECK(outside == 0);
}

void check_same_checksums(const nlohmann::json& cpu, const nlohmann::json& gpu) {
    CHECK(cpu["unwelded"]["shader_pipeline"] == true);
    CHECK(gpu["unwelded"]["checksum"] == cpu["unwelded"]["checksum"]);
    // The shaders' exact words are what --stats' gpu block predicts from the CPU (docs/cli.md, "Models"),
    // where the block's uniform pattern (the viewer's, clamped to N) clamps nothing; above N both split.
    if (cpu["gpu"]["clamped_edges"] == 0) CHECK(gpu["unwelded"]["checksum"] == cpu["gpu"]["checksum"]);
    CHECK(gpu["output_vertices"] == cpu["output_vertices"]);
    CHECK(gpu["output_triangles"] == cpu["output_triangles"]);
    CHECK(gpu["output_open_edges"] == cpu["output_open_edges"]);
}

// One model through the CPU and a GPU backend: the same stats and exact words, and the same file byte for
// byte (flat) or the same faces with every float within the bound (PN).
nlohmann::json check_against_cpu(const std::string& backend, const std::string& args, const std::string& name,
                                 const std::string& extension, bool exact) {
    const std::string cpu_file = scratch(name + "_cpu." + extension),
                      gpu_file = scratch(name + "_" + backend + "." + extension);
    const nlohmann::json cpu = run_backend("cpu", args, cpu_file);
    const nlohmann::json gpu = run_backend(backend, args, gpu_file);
    CHECK(gpu["backend"] == backend);
    check_same_checksums(cpu, gpu);
    const std::string cpu_bytes = read_bytes(cpu_file);
    CHECK(cpu_bytes.size() > 50000); // not a trivial file
    if (exact)
        CHECK((cpu_bytes == read_bytes(gpu_file)));
    else
        check_within_bound(cpu_file, gpu_file);
    return cpu;
}

} // namespace

// Each GPU process compiles its pipelines (lavapipe and Dawn's GLES on llvmpipe: seconds each with Mesa's
// shader cache, tens of seconds without; a quad pass more), so each backend runs few models.
TEST_CASE("ctess mesh --unwelded: vulkan writes the CPU's file (flat, byte for byte) and its faces and exact "
          "words (PN), on lavapipe",
          "[cli][mesh][vulkan]") {
    // Quads (box.obj: 6) through uniform density split above N (613,572 triangles), flat, as binary glTF: the
    // same bytes.
    const nlohmann::json box_stats = check_against_cpu(
        "vulkan", "--in " + box + " --dice-rate 1 --camera 1,2,3 --pattern uniform", "box", "glb", true);
    CHECK(box_stats["gpu"]["clamped_edges"] > 0); // the factors are above N: split, not clamped
    // CP and PN on spider.obj's triangles and uv seams: the exact words, and the floats within the bound.
    check_against_cpu("vulkan", "--in " + spider + " --dice-rate 2 --camera 0,0,400 --surface pn",
                      "spider_pn", "ply", false);
}

TEST_CASE("ctess mesh --unwelded: webgpu (Dawn in node) writes the CPU's file, byte for byte (flat)",
          "[cli][mesh][webgpu]") {
    // One node process (its pipelines compile cold, on the CPU): CP, flat, spider.obj as OBJ text.
    check_against_cpu("webgpu", "--in " + spider + " --dice-rate 2 --camera 0,0,400", "spider", "obj", true);
}

// The welded output (docs/cli.md, "GPU backends"): the shaders weld the model without position ids, so the
// faces are the CPU weld's exactly and the floats within the bound (on spider.obj, flat, byte for byte).
TEST_CASE("ctess mesh --backend vulkan (welded): the CPU's welded faces exactly, floats within the bound",
          "[cli][mesh][vulkan]") {
    for (const std::string surface : {"flat", "pn"}) {
        const std::string args = "--in " + spider + " --dice-rate 2 --camera 0,0,400 --surface " + surface;
        const std::string cpu_file = scratch("welded_" + surface + "_cpu.ply"),
                          gpu_file = scratch("welded_" + surface + "_vulkan.ply");
        const nlohmann::json cpu = run_mesh("cpu", args, cpu_file, false);
        const nlohmann::json gpu = run_mesh("vulkan", args, gpu_file, false);
        CHECK(cpu["output"] == "welded");
        CHECK(gpu["output"] == "welded");
        CHECK(gpu["welded"]["shader_pipeline"] == true);
        CHECK(gpu["output_vertices"] == cpu["output_vertices"]);
        CHECK(gpu["output_triangles"] == cpu["output_triangles"]);
        // PN on a uv seam: without position ids the shaders order a seam's edge by vertex index, so its two
        // sides may differ by an ulp (docs/shaders.md, "Hosts"); flat is exact either way.
        if (surface == "flat") CHECK(gpu["output_open_edges"] == cpu["output_open_edges"]);
        CHECK(cpu["output_triangles"].get<long>() > 100000);
        check_within_bound(cpu_file, gpu_file);
        if (surface == "flat") CHECK((read_bytes(cpu_file) == read_bytes(gpu_file)));
    }
}

// Uniform density split above N (--pattern uniform) welded by the shaders' sort over the mesh: box.obj's
// quads, flat, as binary glTF, the CPU's bytes.
TEST_CASE("ctess mesh --backend vulkan|webgpu --pattern uniform (welded): the CPU's file byte for byte",
          "[cli][mesh][vulkan][webgpu]") {
    const std::string args = "--in " + box + " --dice-rate 2 --camera 1,2,3 --pattern uniform";
    const std::string cpu_file = scratch("welded_split_cpu.glb");
    const nlohmann::json cpu = run_mesh("cpu", args, cpu_file, false);
    const std::string cpu_bytes = read_bytes(cpu_file);
    CHECK(cpu_bytes.size() > 1000000);
    CHECK(cpu["output_open_edges"] == 0);
    for (const std::string backend : {"vulkan", "webgpu"}) {
        const std::string gpu_file = scratch("welded_split_" + backend + ".glb");
        const nlohmann::json gpu = run_mesh(backend, args, gpu_file, false);
        CHECK(gpu["output"] == "welded");
        CHECK(gpu["welded"]["shader_pipeline"] == true);
        CHECK(gpu["output_triangles"] == cpu["output_triangles"]);
        CHECK(gpu["output_open_edges"] == 0);
        CHECK((cpu_bytes == read_bytes(gpu_file)));
    }
}

TEST_CASE("ctess mesh --backend webgpu (welded): the CPU's file byte for byte (box.obj's quads, flat)",
          "[cli][mesh][webgpu]") {
    const std::string args = "--in " + box + " --dice-rate 1 --camera 1,2,3";
    const std::string cpu_file = scratch("welded_box_cpu.glb"), gpu_file = scratch("welded_box_webgpu.glb");
    const nlohmann::json cpu = run_mesh("cpu", args, cpu_file, false);
    const nlohmann::json gpu = run_mesh("webgpu", args, gpu_file, false);
    CHECK(gpu["output"] == "welded");
    CHECK(gpu["welded"]["shader_pipeline"] == true);
    CHECK(gpu["output_triangles"] == cpu["output_triangles"]);
    CHECK(cpu["output_open_edges"] == 0); // closed by position across its 24 vertices' uv seams
    CHECK(gpu["output_open_edges"] == 0);
    const std::string cpu_bytes = read_bytes(cpu_file);
    CHECK(cpu_bytes.size() > 1000000);
    CHECK((cpu_bytes == read_bytes(gpu_file)));
}

TEST_CASE("ctess mesh --backend: refusals exit non-zero with the reason and write nothing", "[cli][mesh]") {
    const std::string out = scratch("refused.ply");
    std::filesystem::remove(out);
    const std::string in = "--in " + box + " --dice-rate 3 --camera 1,2,3 --out " + out;
    ctess::test::check_refused(
        {
            {in + " --backend vulkan --threads 2", 2, "--threads goes with the CPU's welded output"},
            {in + " --unwelded --backend metal", 2, "--backend: 'metal' is not one of: cpu, vulkan, webgpu"},
            {in + " --unwelded --keep-degenerate", 2, "--keep-degenerate goes with the welded output"},
            {in + " --unwelded --shaders /tmp", 2, "--shaders goes with --backend vulkan or webgpu"},
            {in + " --unwelded --backend vulkan --backend-timeout 5", 2,
             "--backend-timeout goes with --backend webgpu"},
            {in + " --unwelded --backend webgpu --backend-timeout 0", 2, "--backend-timeout must be"},
            {in + " --unwelded --backend webgpu --backend-timeout nan", 2, "--backend-timeout"},
            {in + " --unwelded --backend vulkan --pattern d3d11-even", 2,
             "--pattern d3d11-even has no shader"},
            {"--in " + box + " --factor 3 --out " + out + " --unwelded --backend webgpu", 2,
             "the shaders take camera factors only"},
            {in + " --unwelded --backend webgpu --shaders /nonexistent", 1,
             "no '/nonexistent/ctess_mesh_node.mjs'"},
            // Vulkan: the missing SPIR-V file, or the missing device where there is none.
            {in + " --unwelded --backend vulkan --shaders /nonexistent", 1, "--backend vulkan: "},
        },
        out);
    // The CPU runs what the shaders do not, unwelded: D3D11 and constant factors.
    const nlohmann::json d3d11 =
        ctess::test::mesh_stats("--in " + box + " --factor 3 --pattern d3d11-even --unwelded");
    CHECK(d3d11["output"] == "unwelded");
    CHECK(d3d11["unwelded"]["shader_pipeline"] == false);
    CHECK(d3d11["output_triangles"].get<long>() > 6 * 2);
}

TEST_CASE("ctess mesh --backend webgpu: no node, no npm webgpu and a run past --backend-timeout are errors",
          "[cli][mesh]") {
    const std::string out = scratch("webgpu_refused.ply");
    std::filesystem::remove(out);
    const std::string args =
        "mesh --in " + box + " --dice-rate 3 --camera 1,2,3 --unwelded --backend webgpu --out " + out;
    // No node on PATH (the shell finds ctess by its absolute path).
    Run r = ctess::test::run_shell("PATH=/nonexistent " + std::string(CTESS_CLI) + " " + args + " 2>&1");
    CHECK(r.exit_code == 1);
    CHECK(r.out.find("'node' is not on PATH: install Node.js") != std::string::npos);
    // The module outside any node_modules tree (and NODE_PATH unset): the npm package is named.
    const std::filesystem::path lone = std::filesystem::temp_directory_path() / "ctess_test_cli_backend_lone";
    std::filesystem::create_directories(lone);
    for (const char* module : {"ctess_mesh_node.mjs", "ctess_webgpu.mjs"})
        std::filesystem::copy_file(std::filesystem::path(CTESS_SHADER_DIR) / module, lone / module,
                                   std::filesystem::copy_options::overwrite_existing);
    r = ctess::test::run_shell("cd / && env -u NODE_PATH " + std::string(CTESS_CLI) + " " + args +
                               " --shaders " + lone.string() + " 2>&1");
    CHECK(r.exit_code == 1);
    CHECK(r.out.find("the npm package 'webgpu' (Dawn for Node) is not installed") != std::string::npos);
    // A run past the timeout is killed: an error naming the option, at once.
    r = ctess_cli(args + " --backend-timeout 0.01");
    CHECK(r.exit_code == 1);
    CHECK(r.out.find("node did not finish within 0.01 s (--backend-timeout); it was killed") !=
          std::string::npos);
    CHECK_FALSE(std::filesystem::exists(out));
}

// A `node` that starts a child and hangs (as a version manager's shim would): ctess must stop both and remove
// its scratch folder, on a timeout and on SIGTERM, and must not depend on the SIGCHLD disposition it
// inherits.
TEST_CASE(
    "ctess mesh --backend webgpu: a timeout or SIGTERM stops node's whole process group and removes the "
    "scratch folder",
    "[cli][mesh][bad-input]") {
    const std::filesystem::path fake = std::filesystem::temp_directory_path() / "ctess_test_cli_backend_node";
    const std::filesystem::path tmp = std::filesystem::temp_directory_path() / "ctess_test_cli_backend_tmp";
    std::filesystem::remove_all(tmp);
    std::filesystem::create_directories(fake);
    std::filesystem::create_directories(tmp);
    {
        std::ofstream node(fake / "node");
        // Exits at once where CTESS_TEST_NODE_EXIT is set; otherwise marks that it started, then hangs.
        node << "#!/bin/sh\n[ -n \"$CTESS_TEST_NODE_EXIT\" ] && exit 0\ntouch \"$CTESS_TEST_NODE_MARK\"\n"
                "sleep 41.7 &\nsleep 41.7\n";
    }
    std::filesystem::permissions(fake / "node", std::filesystem::perms::owner_all);
    const std::string out = scratch("webgpu_stopped.obj");
    std::filesystem::remove(out);
    const std::filesystem::path mark = fake / "started";
    std::filesystem::remove(mark);
    const std::string env = "TMPDIR=" + tmp.string() + " PATH=" + fake.string() + ":$PATH " +
                            "CTESS_TEST_NODE_MARK=" + mark.string() + " ";
    const std::string run = env + CTESS_CLI + " mesh --in " + box +
                            " --dice-rate 3 --camera 1,2,3 --unwelded --backend webgpu --out " + out;
    // [p]: the pattern does not match the shell that runs pgrep.
    const auto sleepers = [] { return ctess::test::run_shell("pgrep -f 'slee[p] 41.7' | wc -l").out; };
    Run r = ctess::test::run_shell(run + " --backend-timeout 0.5 2>&1");
    CHECK(r.exit_code == 1);
    CHECK(r.out.find("it was killed") != std::string::npos);
    CHECK(sleepers() == "0\n"); // the shim's child too
    CHECK(std::filesystem::is_empty(tmp));
    // With SIGCHLD ignored by the parent (inherited across exec) the system reaps node itself; the wait must
    // still see it end (and then find no result), not fail with "No child processes".
    r = ctess::test::run_shell(
        env + "CTESS_TEST_NODE_EXIT=1 env --ignore-signal=CHLD " + CTESS_CLI + " mesh --in " + box +
        " --dice-rate 3 --camera 1,2,3 --unwelded --backend webgpu --out " + out + " 2>&1");
    CHECK(r.exit_code == 1);
    CHECK(r.out.find("the result file of node is malformed") != std::string::npos);
    CHECK(r.out.find("waitpid") == std::string::npos);
    CHECK(std::filesystem::is_empty(tmp));
    // SIGTERM once node has started: node's group stopped, the folder removed, ctess dies of SIGTERM (143).
    std::filesystem::remove(mark);
    r = ctess::test::run_shell(
        "(" + run + " 2>&1 & p=$!; i=0; while [ ! -e " + mark.string() +
        " ] && [ $i -lt 600 ]; do sleep 0.1; i=$((i+1)); done; kill -TERM $p; wait $p; "
        "echo \"status $?\")");
    CHECK(r.out.find("interrupted; node was stopped") != std::string::npos);
    CHECK(r.out.find("status 143") != std::string::npos);
    CHECK(sleepers() == "0\n");
    CHECK(std::filesystem::is_empty(tmp));
    CHECK_FALSE(std::filesystem::exists(out));
    std::filesystem::remove_all(tmp);
}
