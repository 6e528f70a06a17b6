// The one C++ source of every constant the generated shaders, their hosts and the viewer share
// (docs/shaders.md, "Generated constants"): record and vertex layouts, setup block words, params words,
// pattern and surface codes, workgroup sizes, dispatch limits and the fixed-point units. Each value is taken
// from its C++ definition (PatchRecord, setup_word, TessVertex, Pattern, ...) or, for the few that exist only
// on the GPU side (params words, the prefix sum's workgroup), defined here and checked against the C++ that
// depends on them.
//
// ctess_gen_shaders writes every entry as a `const` line into both shader languages (the {{CONSTANTS}}
// placeholder of shaders/ctess_mesh.*) and into <name>.layout.json under "constants"; the C++ GPU host
// (tests/gpu) includes this header, and the JS hosts (tests/gpu/run_wgsl.mjs, viewer/ctess_gpu.js) read the
// layout.json. tests/gpu/test_shader_layout.cpp fails when a generated file or a source drifts from it.
#pragma once
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>

#include <ctess/cp/line.hpp>
#include <ctess/runtime/cp/setup_block.hpp>
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>
#include <ctess/runtime/surface/eval.hpp>
#include <ctess/runtime/uniform/pipeline_words.hpp>
#include <ctess/uniform/factor.hpp>
#include <ctess/uniform/quantise.hpp>

namespace ctess::gen {

// The params buffer (binding 0), one u32 word each; floats as their bits (docs/shaders.md, "Passes and
// bindings").
namespace param_word {
inline constexpr std::uint32_t patch_count = 0;
inline constexpr std::uint32_t surface = 1;      // rt::Surface
inline constexpr std::uint32_t alpha = 2;        // float
inline constexpr std::uint32_t factor_scale = 3; // float, DiceOptions::factor_scale()
inline constexpr std::uint32_t eye = 4;          // 3 floats
inline constexpr std::uint32_t mesh_vertex_count = 7;
inline constexpr std::uint32_t first_patch = 8; // the emit passes' patch range [first, end)
inline constexpr std::uint32_t end_patch = 9;
inline constexpr std::uint32_t pattern = 10; // rt::Pattern
inline constexpr std::uint32_t words = 11;
} // namespace param_word

// Workgroup sizes. The setup pass's is the C++ limit's (rt::max_pipeline_patches counts in it); the prefix
// sum is one workgroup of 128 (WebGPU compatibility mode allows at most 128 invocations); the emit passes
// loop over a patch's vertices and triangles in steps of their workgroup.
inline constexpr std::uint32_t setup_workgroup = rt::patch_setup_workgroup;
inline constexpr std::uint32_t scan_workgroup = 128;
inline constexpr std::uint32_t emit_workgroup = 64;
// The prefix sum writes both totals as this marker when they do not fit in u32 (hosts refuse them).
inline constexpr std::uint32_t totals_overflow = 0xFFFFFFFFu;
inline constexpr std::uint32_t totals_words = 2; // after the last record: total vertices, total triangles

// The thresholds of uniform::round_factor (constexpr/ctess/uniform/factor.hpp), the one rounding rule of
// uniform factors, which the shaders' uniform_factor runs line for line on the float's bits: below 1.5f (and
// every negative float) gives 1, above +inf (NaN) gives 1. Checked against the function on both sides.
inline constexpr std::uint32_t uniform_round_from_bits = std::bit_cast<std::uint32_t>(1.5f);
inline constexpr std::uint32_t f32_infinity_bits =
    std::bit_cast<std::uint32_t>(std::numeric_limits<float>::infinity());
static_assert(uniform::round_factor(std::bit_cast<float>(uniform_round_from_bits), 16) == 2 &&
              uniform::round_factor(std::bit_cast<float>(uniform_round_from_bits - 1), 16) == 1);
static_assert(uniform::round_factor(std::bit_cast<float>(f32_infinity_bits), 16) == 16 &&
              uniform::round_factor(std::bit_cast<float>(f32_infinity_bits + 1), 16) == 1);
static_assert(rt::uniform_factor(3.4999998f, 16) ==
              uniform::round_factor(3.4999998f, 16)); // the C++ callers' rule

#define CTESS_WORD_OF(type, member) static_cast<std::uint32_t>(offsetof(type, member) / 4)

struct ShaderConstant {
    const char* name; // the shaders' name (upper case)
    std::uint32_t value;
    const char* source; // the C++ definition, for the generated comment
};

// Every u32 constant the generator injects, in the order of the generated block.
inline constexpr std::array shader_constants = {
    // fixed-point units
    ShaderConstant{"FIXED_ONE", cp::fixed_one, "cp::fixed_one (2^24)"},
    ShaderConstant{"LERP_ONE", cp::lerp_one, "cp::lerp_one (t16 = 1)"},
    ShaderConstant{"UNIFORM_ONE", uniform::fixed_one, "uniform::fixed_one (16-bit barycentric 1.0)"},
    // the patch record (rt::PatchRecord)
    ShaderConstant{"PATCH_WORDS", sizeof(rt::PatchRecord) / 4, "sizeof(rt::PatchRecord) / 4"},
    ShaderConstant{"REC_ROTATION", CTESS_WORD_OF(rt::PatchRecord, rotation), "rt::PatchRecord::rotation"},
    ShaderConstant{"REC_TOKEN", CTESS_WORD_OF(rt::PatchRecord, token), "rt::PatchRecord::token[3]"},
    ShaderConstant{"REC_T16", CTESS_WORD_OF(rt::PatchRecord, t16), "rt::PatchRecord::t16[3]"},
    ShaderConstant{"REC_VERTEX_COUNT", CTESS_WORD_OF(rt::PatchRecord, vertex_count),
                   "rt::PatchRecord::vertex_count"},
    ShaderConstant{"REC_TRIANGLE_COUNT", CTESS_WORD_OF(rt::PatchRecord, triangle_count),
                   "rt::PatchRecord::triangle_count"},
    ShaderConstant{"REC_FIRST_VERTEX", CTESS_WORD_OF(rt::PatchRecord, first_vertex),
                   "rt::PatchRecord::first_vertex"},
    ShaderConstant{"REC_FIRST_TRIANGLE", CTESS_WORD_OF(rt::PatchRecord, first_triangle),
                   "rt::PatchRecord::first_triangle"},
    ShaderConstant{"REC_FACTOR", CTESS_WORD_OF(rt::PatchRecord, factor), "rt::PatchRecord::factor[3]"},
    ShaderConstant{"SETUP", CTESS_WORD_OF(rt::PatchRecord, setup), "rt::PatchRecord::setup"},
    // the CP setup block (rt::setup_word), relative to SETUP
    ShaderConstant{"SETUP_WORDS", rt::setup_word::words, "rt::setup_word::words"},
    ShaderConstant{"SETUP_FLAGS", rt::setup_word::flags, "rt::setup_word::flags"},
    ShaderConstant{"SETUP_TOKEN_REC", rt::setup_word::token_rec, "rt::setup_word::token_rec"},
    ShaderConstant{"SETUP_HALF_STEP", rt::setup_word::half_step, "rt::setup_word::half_step"},
    ShaderConstant{"SETUP_COLUMN", rt::setup_word::column, "rt::setup_word::column"},
    ShaderConstant{"SETUP_GAP", rt::setup_word::gap, "rt::setup_word::gap"},
    ShaderConstant{"SETUP_CLAMP", rt::setup_word::clamp, "rt::setup_word::clamp"},
    ShaderConstant{"SETUP_STRIPS", rt::setup_word::strips, "rt::setup_word::strips"},
    ShaderConstant{"SETUP_E1_OFFSET", rt::setup_word::e1_offset, "rt::setup_word::e1_offset"},
    ShaderConstant{"SETUP_UNIQUE", rt::setup_word::unique, "rt::setup_word::unique"},
    ShaderConstant{"SETUP_COPY_BIAS", rt::setup_word::copy_bias, "rt::setup_word::copy_bias"},
    ShaderConstant{"SETUP_SLOT_SKIP", rt::setup_word::slot_skip, "rt::setup_word::slot_skip"},
    ShaderConstant{"SETUP_SLOT_SKIPS", rt::setup_word::tri_skip - rt::setup_word::slot_skip,
                   "rt::setup_word::tri_skip - slot_skip (slot skip words)"},
    ShaderConstant{"SETUP_TRI_SKIP", rt::setup_word::tri_skip, "rt::setup_word::tri_skip"},
    ShaderConstant{"SETUP_TRI_SKIPS", (rt::setup_word::words - rt::setup_word::tri_skip) / 2,
                   "(rt::setup_word::words - tri_skip) / 2 (triangle skip pairs)"},
    // the uniform setup words (rt::uniform_setup_word), relative to SETUP
    ShaderConstant{"USETUP_PATTERN", rt::uniform_setup_word::pattern, "rt::uniform_setup_word::pattern"},
    ShaderConstant{"USETUP_SORTED", rt::uniform_setup_word::sorted, "rt::uniform_setup_word::sorted"},
    ShaderConstant{"USETUP_CORNERS", rt::uniform_setup_word::corners, "rt::uniform_setup_word::corners"},
    // the output vertex (rt::TessVertex) and the mesh input
    ShaderConstant{"VERTEX_WORDS", sizeof(rt::TessVertex) / 4, "sizeof(rt::TessVertex) / 4"},
    ShaderConstant{"VERTEX_U", CTESS_WORD_OF(rt::TessVertex, u), "rt::TessVertex::u"},
    ShaderConstant{"VERTEX_V", CTESS_WORD_OF(rt::TessVertex, v), "rt::TessVertex::v"},
    ShaderConstant{"VERTEX_POSITION", CTESS_WORD_OF(rt::TessVertex, position), "rt::TessVertex::position"},
    ShaderConstant{"VERTEX_NORMAL", CTESS_WORD_OF(rt::TessVertex, normal), "rt::TessVertex::normal"},
    ShaderConstant{"VERTEX_UV", CTESS_WORD_OF(rt::TessVertex, uv), "rt::TessVertex::uv"},
    ShaderConstant{"MESH_VERTEX_FLOATS", rt::mesh_vertex_floats, "rt::mesh_vertex_floats"},
    // the params buffer
    ShaderConstant{"PARAM_PATCH_COUNT", param_word::patch_count, "gen::param_word::patch_count"},
    ShaderConstant{"PARAM_SURFACE", param_word::surface, "gen::param_word::surface"},
    ShaderConstant{"PARAM_ALPHA", param_word::alpha, "gen::param_word::alpha"},
    ShaderConstant{"PARAM_FACTOR_SCALE", param_word::factor_scale, "gen::param_word::factor_scale"},
    ShaderConstant{"PARAM_EYE", param_word::eye, "gen::param_word::eye"},
    ShaderConstant{"PARAM_MESH_VERTEX_COUNT", param_word::mesh_vertex_count,
                   "gen::param_word::mesh_vertex_count"},
    ShaderConstant{"PARAM_FIRST_PATCH", param_word::first_patch, "gen::param_word::first_patch"},
    ShaderConstant{"PARAM_END_PATCH", param_word::end_patch, "gen::param_word::end_patch"},
    ShaderConstant{"PARAM_PATTERN", param_word::pattern, "gen::param_word::pattern"},
    ShaderConstant{"PARAMS_WORDS", param_word::words, "gen::param_word::words"},
    // option codes
    ShaderConstant{"PATTERN_CP", static_cast<std::uint32_t>(rt::Pattern::cp), "rt::Pattern::cp"},
    ShaderConstant{"PATTERN_UNIFORM", static_cast<std::uint32_t>(rt::Pattern::uniform),
                   "rt::Pattern::uniform"},
    ShaderConstant{"SURFACE_FLAT", static_cast<std::uint32_t>(rt::Surface::flat), "rt::Surface::flat"},
    ShaderConstant{"SURFACE_PN", static_cast<std::uint32_t>(rt::Surface::pn_triangles),
                   "rt::Surface::pn_triangles"},
    ShaderConstant{"SURFACE_PHONG", static_cast<std::uint32_t>(rt::Surface::phong), "rt::Surface::phong"},
    ShaderConstant{"SURFACE_PN_AEN", static_cast<std::uint32_t>(rt::Surface::pn_aen), "rt::Surface::pn_aen"},
    // workgroups, dispatch limits and the totals
    ShaderConstant{"SETUP_GROUP", setup_workgroup, "rt::patch_setup_workgroup"},
    ShaderConstant{"SCAN_GROUP", scan_workgroup, "gen::scan_workgroup"},
    ShaderConstant{"EMIT_GROUP", emit_workgroup, "gen::emit_workgroup"},
    ShaderConstant{"MAX_DISPATCH_WORKGROUPS", rt::max_dispatch_workgroups, "rt::max_dispatch_workgroups"},
    ShaderConstant{"TOTALS_WORDS", totals_words, "gen::totals_words"},
    ShaderConstant{"TOTALS_OVERFLOW", totals_overflow, "gen::totals_overflow"},
    // the uniform-factor rule (the shaders' uniform_factor)
    ShaderConstant{"UNIFORM_ROUND_FROM_BITS", uniform_round_from_bits, "uniform::round_factor: 1.5f"},
    ShaderConstant{"F32_INFINITY_BITS", f32_infinity_bits, "uniform::round_factor: +inf"},
};

#undef CTESS_WORD_OF

// The layout checks the generated names rely on.
static_assert(sizeof(rt::PatchRecord) % 4 == 0 && sizeof(rt::TessVertex) % 4 == 0);
static_assert(offsetof(rt::PatchRecord, t16) == offsetof(rt::PatchRecord, token) + 12);
static_assert(offsetof(rt::PatchRecord, triangle_count) == offsetof(rt::PatchRecord, vertex_count) + 4);
static_assert(offsetof(rt::PatchRecord, first_triangle) == offsetof(rt::PatchRecord, first_vertex) + 4);
static_assert(offsetof(rt::PatchRecord, setup) + 4 * rt::setup_word::words == sizeof(rt::PatchRecord));
static_assert(rt::max_pipeline_patches == std::uint64_t{rt::max_dispatch_workgroups} * setup_workgroup);
static_assert(param_word::eye + 3 == param_word::mesh_vertex_count &&
              param_word::pattern + 1 == param_word::words);

} // namespace ctess::gen
