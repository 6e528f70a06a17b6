// One source for every shared constant (docs/shaders.md, "Generated constants"): the generated shaders and
// layout.json files must hold gen/shaders/shader_layout.hpp's values (taken from the C++ definitions), and
// the shader templates, the JS hosts and the viewer must not restate them by hand. A constant that drifts, a
// stale generated file or a hand-written copy fails here.
#include <catch2/catch.hpp>

#include <cstddef>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <ctess/runtime/pipeline/mesh_pipeline.hpp>

#include "shader_layout.hpp"

namespace {

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    INFO(path);
    REQUIRE(in);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string shader(unsigned max, const std::string& suffix) {
    return slurp(std::string(CTESS_SHADER_DIR) + "/ctess_mesh_" + std::to_string(max) + suffix);
}

std::string source(const char* path) {
    return slurp(std::string(CTESS_SOURCE_DIR) + "/" + path);
}

bool contains(const std::string& text, const std::string& what) {
    return text.find(what) != std::string::npos;
}

// The first match of a pattern in text, or "" (for the failure message).
std::string first_match(const std::string& text, const char* pattern) {
    std::smatch m;
    return std::regex_search(text, m, std::regex(pattern)) ? m.str() : std::string();
}

const char* pass_names[] = {"patch_setup",    "prefix_sum",         "emit_vertices",
                            "emit_triangles", "emit_quad_vertices", "emit_quad_triangles"};

} // namespace

TEST_CASE("the shared constants are the C++ definitions") {
    namespace g = ctess::gen;
    namespace rt = ctess::rt;
    // The table is built from the definitions; these pin the ones a reader of the shaders relies on.
    STATIC_REQUIRE(sizeof(rt::PatchRecord) / 4 == 48);
    STATIC_REQUIRE(offsetof(rt::PatchRecord, setup) / 4 == 16);
    STATIC_REQUIRE(sizeof(rt::TessVertex) / 4 == 10);
    STATIC_REQUIRE(g::setup_workgroup == rt::patch_setup_workgroup);
    for (const g::ShaderConstant& c : g::shader_constants) {
        INFO(c.name);
        std::size_t same = 0;
        for (const g::ShaderConstant& d : g::shader_constants) same += std::string(c.name) == d.name;
        CHECK(same == 1);
    }
}

TEST_CASE("layout.json and the generated shaders hold every constant's value") {
    for (unsigned max : {64u, 256u}) {
        INFO("max " << max);
        const std::string json = shader(max, ".layout.json");
        const std::string wgsl = shader(max, ".wgsl");
        for (const ctess::gen::ShaderConstant& c : ctess::gen::shader_constants) {
            INFO(c.name << " = " << c.value << " (" << c.source << ")");
            const std::string name = c.name, value = std::to_string(c.value);
            const std::string entry = "\"" + name + "\": " + value;
            CHECK((contains(json, entry + ",") || contains(json, entry + "\n")));
            CHECK(contains(wgsl, "const " + name + ": u32 = " + value + "u;"));
            for (const char* pass : pass_names)
                CHECK(contains(shader(max, std::string("_") + pass + ".comp"),
                               "const uint " + name + " = " + value + "u;"));
        }
        CHECK(contains(json, "\"patch_words\": " + std::to_string(sizeof(ctess::rt::PatchRecord) / 4)));
        CHECK(contains(json, "\"max_patches\": " + std::to_string(ctess::rt::max_pipeline_patches)));
        CHECK(contains(json, "\"max_vertices\": " + std::to_string(ctess::rt::max_pipeline_vertices)));
        CHECK(contains(json, "\"max_triangles\": " + std::to_string(ctess::rt::max_pipeline_triangles)));
        const unsigned sizes[] = {ctess::gen::setup_workgroup, ctess::gen::scan_workgroup,
                                  ctess::gen::emit_workgroup,  ctess::gen::emit_workgroup,
                                  ctess::gen::emit_workgroup,  ctess::gen::emit_workgroup};
        for (std::size_t k = 0; k < std::size(pass_names); ++k) {
            INFO(pass_names[k]);
            CHECK(contains(json, std::string("\"name\": \"") + pass_names[k] + "\", \"entry\": \"ctess_" +
                                     pass_names[k] + "\", \"workgroup_size\": " + std::to_string(sizes[k])));
            CHECK(contains(shader(max, std::string("_") + pass_names[k] + ".comp"),
                           "layout(local_size_x = " + std::to_string(sizes[k]) + ") in;"));
        }
    }
}

TEST_CASE("the shader templates restate no generated constant") {
    for (const char* path : {"shaders/ctess_mesh.wgsl", "shaders/ctess_mesh.comp.glsl"}) {
        INFO(path);
        const std::string text = source(path);
        CHECK(contains(text, "{{CONSTANTS}}"));
        for (const ctess::gen::ShaderConstant& c : ctess::gen::shader_constants) {
            INFO(c.name);
            CHECK(first_match(text, (std::string("const\\s+(uint\\s+)?") + c.name + "\\b").c_str()).empty());
        }
        // The literal forms the constants replaced: params, record, setup block and vertex words, workgroups.
        for (const char* literal :
             {R"(params\[\d+)", R"(patches\[rec \+ \d+u)", R"(patches\[b \+ \d+u)", R"(patches\[(rec|b)\])",
              R"(t \* PATCH_WORDS \+ \d+u\])", R"(out_vertices\[o( \+ \d+u)?\])", R"(workgroup_size\(\d+)",
              R"(\b(48|128|65534|16777216)u\b)", R"(const (uint )?UNIFORM_MAX_FACTOR)", R"(>= 1\.5\b)",
              R"(0x3FC00000)"}) {
            INFO(literal);
            CHECK(first_match(text, literal) == "");
        }
    }
}

TEST_CASE("the JS hosts and the viewer take their layout from layout.json") {
    for (const char* path : {"shaders/ctess_webgpu.mjs", "tests/gpu/run_wgsl.mjs", "viewer/ctess_gpu.js",
                             "viewer/mesh_view.js", "viewer/explicit_factors.wgsl",
                             "tests/viewer/test_viewer.mjs", "tests/viewer/test_viewer_models.mjs"}) {
        INFO(path);
        const std::string text = source(path);
        CHECK(!contains(text, "ctess_cp"));
        // Hand-written record, vertex, params and limit numbers.
        for (const char* literal :
             {R"(\* 48\b)", R"(\b65535\b)", R"(\b0xFFFFFFFF / (3|10)\b)", R"(\+ (7|8|9|10|11)\])",
              R"(\+ (7|8|9|10|11)u\])", R"(params\[\d+\])", R"(VERTEX_WORDS = 10)", R"(\+= 10\b)",
              R"(\* 10\b)", R"(/ 64\b)", R"(EXPLICIT_FACTORS: u32 = \d)", R"(PerShaderStage < \d)",
              R"(i < \d \?)"}) {
            INFO(literal);
            CHECK(first_match(text, literal) == "");
        }
    }
}
