// The one C++ source of every constant the generated shaders, their hosts and the viewer share
// (docs/shaders.md, "Generated constants"): record and vertex layouts, setup block words, params words,
// pattern and surface codes, workgroup sizes, dispatch limits and the fixed-point units. Each value is taken
// from its C++ definition (PatchRecord, setup_word, TessVertex, Pattern, ...) or, for the few that exist only
// on the GPU side (params words, workgroup sizes), from the hosts' header
// <ctess/runtime/gpu/shader_interface.hpp>.
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
#include <ctess/runtime/gpu/shader_interface.hpp>
#include <ctess/runtime/pipeline/mesh_pipeline.hpp>
#include <ctess/runtime/surface/eval.hpp>
#include <ctess/runtime/uniform/pipeline_words.hpp>
#include <ctess/runtime/uniform/split.hpp>
#include <ctess/uniform/factor.hpp>
#include <ctess/uniform/quantise.hpp>
#include <ctess/uniform/split_factor.hpp>

namespace ctess::gen {

// The params words, workgroup sizes and totals are the hosts' (<ctess/runtime/gpu/shader_interface.hpp>).
namespace param_word = rt::gpu::param_word;
using rt::gpu::emit_workgroup;
using rt::gpu::scan_workgroup;
using rt::gpu::setup_workgroup;
using rt::gpu::split_workgroup;
using rt::gpu::totals_overflow;
using rt::gpu::totals_words;

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

// Splitting (docs/shaders.md, "Splitting"): the interior dice limit of the pipeline's tolerance (the default)
// as the exact square the shaders compare with (uniform/split_factor.hpp), for the configured table.
inline constexpr std::uint64_t split_interior_limit =
    uniform::interior_limit_squared(CTESS_UNIFORM_MAX_FACTOR, rt::uniform_split_interior_tolerance);
static_assert(rt::uniform_split_fixed_one == std::uint64_t{uniform::fixed_one} * uniform::fixed_one);

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
    ShaderConstant{"REC_KIND", CTESS_WORD_OF(rt::PatchRecord, kind), "rt::PatchRecord::kind"},
    ShaderConstant{"SETUP", CTESS_WORD_OF(rt::PatchRecord, setup), "rt::PatchRecord::setup"},
    ShaderConstant{"PATCH_KIND_QUAD", rt::patch_kind_quad, "rt::patch_kind_quad"},
    // a quad record's setup words (rt::quad_setup_word), relative to SETUP
    ShaderConstant{"QSETUP_B_TOKEN", rt::quad_setup_word::b_token, "rt::quad_setup_word::b_token"},
    ShaderConstant{"QSETUP_B_T16", rt::quad_setup_word::b_t16, "rt::quad_setup_word::b_t16"},
    ShaderConstant{"QSETUP_Q3_FACTOR", rt::quad_setup_word::q3_factor, "rt::quad_setup_word::q3_factor"},
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
    // the bindings (set 0 / group 0, every one a storage buffer; the first READ_ONLY_BINDINGS are read-only)
    ShaderConstant{"BINDINGS", rt::gpu::binding::count, "rt::gpu::binding::count"},
    ShaderConstant{"READ_ONLY_BINDINGS", rt::gpu::binding::patches, "rt::gpu::binding::patches"},
    // the params buffer
    ShaderConstant{"PARAM_PATCH_COUNT", param_word::patch_count, "rt::gpu::param_word::patch_count"},
    ShaderConstant{"PARAM_SURFACE", param_word::surface, "rt::gpu::param_word::surface"},
    ShaderConstant{"PARAM_ALPHA", param_word::alpha, "rt::gpu::param_word::alpha"},
    ShaderConstant{"PARAM_FACTOR_SCALE", param_word::factor_scale, "rt::gpu::param_word::factor_scale"},
    ShaderConstant{"PARAM_EYE", param_word::eye, "rt::gpu::param_word::eye"},
    ShaderConstant{"PARAM_MESH_VERTEX_COUNT", param_word::mesh_vertex_count,
                   "rt::gpu::param_word::mesh_vertex_count"},
    ShaderConstant{"PARAM_FIRST_PATCH", param_word::first_patch, "rt::gpu::param_word::first_patch"},
    ShaderConstant{"PARAM_END_PATCH", param_word::end_patch, "rt::gpu::param_word::end_patch"},
    ShaderConstant{"PARAM_PATTERN", param_word::pattern, "rt::gpu::param_word::pattern"},
    ShaderConstant{"PARAM_QUAD_COUNT", param_word::quad_count, "rt::gpu::param_word::quad_count"},
    ShaderConstant{"PARAM_QUAD_RULE", param_word::quad_rule, "rt::gpu::param_word::quad_rule"},
    ShaderConstant{"PARAM_DISPLACEMENT_FLAGS", param_word::displacement_flags,
                   "rt::gpu::param_word::displacement_flags"},
    ShaderConstant{"PARAM_DISPLACEMENT_SCALE", param_word::displacement_scale,
                   "rt::gpu::param_word::displacement_scale"},
    ShaderConstant{"PARAM_DISPLACEMENT_FACTOR", param_word::displacement_factor,
                   "rt::gpu::param_word::displacement_factor"},
    ShaderConstant{"PARAM_DISPLACEMENT_OFFSET", param_word::displacement_offset,
                   "rt::gpu::param_word::displacement_offset"},
    ShaderConstant{"PARAM_DISPLACEMENT_NORMAL_STEP", param_word::displacement_normal_step,
                   "rt::gpu::param_word::displacement_normal_step"},
    ShaderConstant{"PARAM_DISPLACEMENT_FACTOR_BOUND", param_word::displacement_factor_bound,
                   "rt::gpu::param_word::displacement_factor_bound"},
    ShaderConstant{"PARAM_HEIGHT_MAP_WIDTH", param_word::height_map_width,
                   "rt::gpu::param_word::height_map_width"},
    ShaderConstant{"PARAM_HEIGHT_MAP_HEIGHT", param_word::height_map_height,
                   "rt::gpu::param_word::height_map_height"},
    ShaderConstant{"PARAM_HEIGHT_MAP_ADDRESS", param_word::height_map_address,
                   "rt::gpu::param_word::height_map_address"},
    ShaderConstant{"PARAM_SPLIT_CAPACITY", param_word::split_capacity, "rt::gpu::param_word::split_capacity"},
    ShaderConstant{"PARAM_WELD", param_word::weld, "rt::gpu::param_word::weld"},
    ShaderConstant{"PARAMS_WORDS", param_word::words, "rt::gpu::param_word::words"},
    // the displacement flags (params word PARAM_DISPLACEMENT_FLAGS) and the height map's address modes
    ShaderConstant{"DISPLACEMENT_ON", rt::gpu::displacement_flag::on, "rt::gpu::displacement_flag::on"},
    ShaderConstant{"DISPLACEMENT_DIRECTIONS", rt::gpu::displacement_flag::directions,
                   "rt::gpu::displacement_flag::directions"},
    ShaderConstant{"DISPLACEMENT_ADJACENCY", rt::gpu::displacement_flag::adjacency,
                   "rt::gpu::displacement_flag::adjacency"},
    ShaderConstant{"DISPLACEMENT_VECTOR", rt::gpu::displacement_flag::vector,
                   "rt::gpu::displacement_flag::vector"},
    ShaderConstant{"ADDRESS_REPEAT", static_cast<std::uint32_t>(rt::AddressMode::repeat),
                   "rt::AddressMode::repeat"},
    ShaderConstant{"ADDRESS_CLAMP", static_cast<std::uint32_t>(rt::AddressMode::clamp),
                   "rt::AddressMode::clamp"},
    // option codes
    ShaderConstant{"PATTERN_CP", static_cast<std::uint32_t>(rt::Pattern::cp), "rt::Pattern::cp"},
    ShaderConstant{"PATTERN_UNIFORM", static_cast<std::uint32_t>(rt::Pattern::uniform),
                   "rt::Pattern::uniform"},
    ShaderConstant{"PATTERN_UNIFORM_SPLIT", static_cast<std::uint32_t>(rt::Pattern::uniform_split),
                   "rt::Pattern::uniform_split"},
    ShaderConstant{"QUAD_RULE_LONGER_PAIR", static_cast<std::uint32_t>(rt::QuadRule::longer_pair),
                   "rt::QuadRule::longer_pair"},
    ShaderConstant{"QUAD_RULE_AS_LABELLED", static_cast<std::uint32_t>(rt::QuadRule::as_labelled),
                   "rt::QuadRule::as_labelled"},
    ShaderConstant{"SURFACE_FLAT", static_cast<std::uint32_t>(rt::Surface::flat), "rt::Surface::flat"},
    ShaderConstant{"SURFACE_PN", static_cast<std::uint32_t>(rt::Surface::pn_triangles),
                   "rt::Surface::pn_triangles"},
    ShaderConstant{"SURFACE_PHONG", static_cast<std::uint32_t>(rt::Surface::phong), "rt::Surface::phong"},
    ShaderConstant{"SURFACE_PN_AEN", static_cast<std::uint32_t>(rt::Surface::pn_aen), "rt::Surface::pn_aen"},
    // workgroups, dispatch limits and the totals
    ShaderConstant{"SETUP_GROUP", setup_workgroup, "rt::patch_setup_workgroup"},
    ShaderConstant{"SCAN_GROUP", scan_workgroup, "rt::gpu::scan_workgroup"},
    ShaderConstant{"EMIT_GROUP", emit_workgroup, "rt::gpu::emit_workgroup"},
    ShaderConstant{"MAX_DISPATCH_WORKGROUPS", rt::max_dispatch_workgroups, "rt::max_dispatch_workgroups"},
    ShaderConstant{"TOTALS_WORDS", totals_words, "rt::gpu::totals_words"},
    ShaderConstant{"TOTALS_OVERFLOW", totals_overflow, "rt::gpu::totals_overflow"},
    // splitting (rt::gpu::split_word, rt::gpu::split_node_word, uniform/split_factor.hpp)
    ShaderConstant{"SPLIT_GROUP", rt::gpu::split_workgroup, "rt::gpu::split_workgroup"},
    ShaderConstant{"SPLIT_LEVEL", rt::gpu::split_word::level, "rt::gpu::split_word::level"},
    ShaderConstant{"SPLIT_NODES", rt::gpu::split_word::nodes, "rt::gpu::split_word::nodes"},
    ShaderConstant{"SPLIT_PARENTS", rt::gpu::split_word::parents, "rt::gpu::split_word::parents"},
    ShaderConstant{"SPLIT_DISPATCH", rt::gpu::split_word::dispatch, "rt::gpu::split_word::dispatch"},
    ShaderConstant{"SPLIT_NEEDED", rt::gpu::split_word::needed, "rt::gpu::split_word::needed"},
    ShaderConstant{"SPLIT_OVERFLOW", rt::gpu::split_word::overflow, "rt::gpu::split_word::overflow"},
    ShaderConstant{"SPLIT_HEADER_WORDS", rt::gpu::split_word::header_words,
                   "rt::gpu::split_word::header_words"},
    ShaderConstant{"NODE_PATCH", rt::gpu::split_node_word::patch, "rt::gpu::split_node_word::patch"},
    ShaderConstant{"NODE_INFO", rt::gpu::split_node_word::info, "rt::gpu::split_node_word::info"},
    ShaderConstant{"NODE_CORNER", rt::gpu::split_node_word::corner, "rt::gpu::split_node_word::corner"},
    ShaderConstant{"NODE_SQUARED", rt::gpu::split_node_word::squared, "rt::gpu::split_node_word::squared"},
    ShaderConstant{"NODE_CHILDREN", rt::gpu::split_node_word::children, "rt::gpu::split_node_word::children"},
    ShaderConstant{"NODE_PATTERN", rt::gpu::split_node_word::pattern, "rt::gpu::split_node_word::pattern"},
    ShaderConstant{"NODE_VERTICES", rt::gpu::split_node_word::vertices, "rt::gpu::split_node_word::vertices"},
    ShaderConstant{"NODE_TRIANGLES", rt::gpu::split_node_word::triangles,
                   "rt::gpu::split_node_word::triangles"},
    ShaderConstant{"NODE_FIRST_CHILD", rt::gpu::split_node_word::first_child,
                   "rt::gpu::split_node_word::first_child"},
    ShaderConstant{"NODE_FIRST_VERTEX", rt::gpu::split_node_word::first_vertex,
                   "rt::gpu::split_node_word::first_vertex"},
    ShaderConstant{"NODE_FIRST_TRIANGLE", rt::gpu::split_node_word::first_triangle,
                   "rt::gpu::split_node_word::first_triangle"},
    ShaderConstant{"NODE_WORDS", rt::gpu::split_node_word::words, "rt::gpu::split_node_word::words"},
    ShaderConstant{"NODE_DEPTH_MASK", rt::gpu::split_node_info::depth_mask,
                   "rt::gpu::split_node_info::depth_mask"},
    ShaderConstant{"NODE_LIMIT_SHIFT", rt::gpu::split_node_info::limit_shift,
                   "rt::gpu::split_node_info::limit_shift"},
    ShaderConstant{"NODE_HALF_SHIFT", rt::gpu::split_node_info::half_shift,
                   "rt::gpu::split_node_info::half_shift"},
    ShaderConstant{"NODE_LEAF", rt::gpu::split_node_info::leaf, "rt::gpu::split_node_info::leaf"},
    ShaderConstant{"NODE_CULLED", rt::gpu::split_node_info::culled, "rt::gpu::split_node_info::culled"},
    ShaderConstant{"SPLIT_MAX_FACTOR", rt::uniform_split_max_factor, "rt::uniform_split_max_factor"},
    ShaderConstant{"SPLIT_DEPTH_BOUND", rt::uniform_split_depth_bound(CTESS_UNIFORM_MAX_FACTOR),
                   "rt::uniform_split_depth_bound(N)"},
    ShaderConstant{"SPLIT_FIXED_ONE", static_cast<std::uint32_t>(rt::uniform_split_fixed_one),
                   "rt::uniform_split_fixed_one (65534^2)"},
    ShaderConstant{"SPLIT_INTERIOR_LIMIT_LO", static_cast<std::uint32_t>(split_interior_limit),
                   "uniform::interior_limit_squared(N, rt::uniform_split_interior_tolerance), low word"},
    ShaderConstant{"SPLIT_INTERIOR_LIMIT_HI", static_cast<std::uint32_t>(split_interior_limit >> 32),
                   "uniform::interior_limit_squared(N, rt::uniform_split_interior_tolerance), high word"},
    // the welded output (rt::gpu::weld_word, rt::WeldedEdge, rt::WeldedPatch)
    ShaderConstant{"WELD_ON", rt::gpu::weld_flag::on, "rt::gpu::weld_flag::on"},
    ShaderConstant{"WELD_SORTED", rt::gpu::weld_flag::sorted, "rt::gpu::weld_flag::sorted"},
    ShaderConstant{"WELD_KEEP_DEGENERATE", rt::gpu::weld_flag::keep_degenerate,
                   "rt::gpu::weld_flag::keep_degenerate"},
    ShaderConstant{"WELD_EDGES", rt::gpu::weld_word::edges, "rt::gpu::weld_word::edges"},
    ShaderConstant{"WELD_SLOTS", rt::gpu::weld_word::slots, "rt::gpu::weld_word::slots"},
    ShaderConstant{"WELD_SHARED", rt::gpu::weld_word::shared, "rt::gpu::weld_word::shared"},
    ShaderConstant{"WELD_VERTICES", rt::gpu::weld_word::vertices, "rt::gpu::weld_word::vertices"},
    ShaderConstant{"WELD_TRIANGLES", rt::gpu::weld_word::triangles, "rt::gpu::weld_word::triangles"},
    ShaderConstant{"WELD_STATUS", rt::gpu::weld_word::status, "rt::gpu::weld_word::status"},
    ShaderConstant{"WELD_HEADER_WORDS", rt::gpu::weld_word::header_words, "rt::gpu::weld_word::header_words"},
    ShaderConstant{"WELD_OVERFLOW", rt::gpu::weld_status::overflow, "rt::gpu::weld_status::overflow"},
    ShaderConstant{"WELD_MISSING_EDGE", rt::gpu::weld_status::missing_edge,
                   "rt::gpu::weld_status::missing_edge"},
    ShaderConstant{"WELD_INTERIOR", rt::gpu::weld_map::interior, "rt::gpu::weld_map::interior"},
    ShaderConstant{"WELD_REPRESENTATIVE", rt::gpu::weld_map::representative,
                   "rt::gpu::weld_map::representative"},
    ShaderConstant{"WELD_RANK_MASK", rt::gpu::weld_map::rank_mask, "rt::gpu::weld_map::rank_mask"},
    ShaderConstant{"WELD_EDGE_WORDS", rt::gpu::weld_edge_words, "sizeof(rt::WeldedEdge) / 4"},
    ShaderConstant{"WEDGE_LO", CTESS_WORD_OF(rt::WeldedEdge, lo), "rt::WeldedEdge::lo"},
    ShaderConstant{"WEDGE_HI", CTESS_WORD_OF(rt::WeldedEdge, hi), "rt::WeldedEdge::hi"},
    ShaderConstant{"WEDGE_FIRST_VERTEX", CTESS_WORD_OF(rt::WeldedEdge, first_vertex),
                   "rt::WeldedEdge::first_vertex"},
    ShaderConstant{"WEDGE_VERTEX_COUNT", CTESS_WORD_OF(rt::WeldedEdge, vertex_count),
                   "rt::WeldedEdge::vertex_count"},
    ShaderConstant{"WELD_PATCH_WORDS", rt::gpu::weld_patch_words, "sizeof(rt::WeldedPatch) / 4"},
    ShaderConstant{"WPATCH_FIRST_VERTEX", CTESS_WORD_OF(rt::WeldedPatch, first_vertex),
                   "rt::WeldedPatch::first_vertex"},
    ShaderConstant{"WPATCH_VERTEX_COUNT", CTESS_WORD_OF(rt::WeldedPatch, vertex_count),
                   "rt::WeldedPatch::vertex_count"},
    ShaderConstant{"WPATCH_FIRST_TRIANGLE", CTESS_WORD_OF(rt::WeldedPatch, first_triangle),
                   "rt::WeldedPatch::first_triangle"},
    ShaderConstant{"WPATCH_TRIANGLE_COUNT", CTESS_WORD_OF(rt::WeldedPatch, triangle_count),
                   "rt::WeldedPatch::triangle_count"},
    ShaderConstant{"WELD_SORT_WORDS", rt::gpu::weld_sort_words, "rt::gpu::weld_sort_words"},
    ShaderConstant{"WELD_COUNTED_RANKS", rt::gpu::weld_counted_ranks, "rt::gpu::weld_counted_ranks"},
    ShaderConstant{"WELD_MAX_PATCH_SLOTS", rt::gpu::weld_max_patch_slots, "rt::gpu::weld_max_patch_slots"},
    ShaderConstant{"WELD_FIRST_PATCH", rt::gpu::weld_word::first_patch, "rt::gpu::weld_word::first_patch"},
    ShaderConstant{"WELD_SORT_RECORDS", rt::gpu::weld_word::sort_records, "rt::gpu::weld_word::sort_records"},
    ShaderConstant{"WELD_SORT_STAGE", rt::gpu::weld_word::sort_stage, "rt::gpu::weld_word::sort_stage"},
    ShaderConstant{"WELD_SORT_STEP", rt::gpu::weld_word::sort_step, "rt::gpu::weld_word::sort_step"},
    ShaderConstant{"WELD_RANK_MODE", rt::gpu::weld_word::rank_mode, "rt::gpu::weld_word::rank_mode"},
    ShaderConstant{"WELD_RANKED", rt::gpu::weld_word::ranked, "rt::gpu::weld_word::ranked"},
    ShaderConstant{"WELD_RANK_KEYS", rt::gpu::weld_rank_mode::keys, "rt::gpu::weld_rank_mode::keys"},
    ShaderConstant{"WELD_RANK_TRIANGLES", rt::gpu::weld_rank_mode::triangles,
                   "rt::gpu::weld_rank_mode::triangles"},
    ShaderConstant{"WELD_RECORD_WORDS", rt::gpu::weld_record_words, "rt::gpu::weld_record_words"},
    ShaderConstant{"WELD_RANK_BLOCK", rt::gpu::weld_rank_block, "rt::gpu::weld_rank_block"},
    ShaderConstant{"WELD_SORT_CHUNK", rt::gpu::weld_sort_chunk, "rt::gpu::weld_sort_chunk"},
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
static_assert(rt::quad_setup_word::b_t16 == rt::quad_setup_word::b_token + 3 &&
              rt::quad_setup_word::q3_factor < rt::setup_word::words);
static_assert(rt::max_pipeline_patches == std::uint64_t{rt::max_dispatch_workgroups} * setup_workgroup);

} // namespace ctess::gen
