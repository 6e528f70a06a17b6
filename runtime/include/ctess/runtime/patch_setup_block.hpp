// The per-patch setup block of the GPU mesh pipeline: everything a vertex or triangle invocation needs about
// its patch beyond the line states, computed once per patch by the setup pass and stored after the patch
// record (docs/shaders.md, "Patch records"). An emit invocation then reads these words and one column record
// instead of redoing the setup (token records, column record, clamp, strip count, collapse skips).
//
// This is the CPU twin of the shaders' patch_setup (shaders/ctess_cp.comp.glsl, shaders/ctess_cp.wgsl): the
// same steps as CpPatch's constructor (docs/algorithm.md §2.9 for the collapse skips), written out as table
// indices rather than pointers, so that the block does not depend on where a blob puts its sections. Its
// counts are tested against CpPatch's for every line-state triple.
#pragma once
#include <cstdint>

#include <ctess/cp_edge_line.hpp>
#include <ctess/cp_line.hpp>

#include "cp_table_set.hpp"

namespace ctess::rt {

// Word indices inside the block. Skips are runs of dropped raw triangles or slots (begin, length).
namespace setup_word {
inline constexpr unsigned flags = 0;     // type | c0 << 2 | c1 << 3 | c2 << 4 | copies << 5 |
                                         // triangle skips << 8 | slot skips << 12
inline constexpr unsigned token_rec = 1; // 3 words, edge k: first_point | segments << 16
inline constexpr unsigned half_step = 4; // 3 words
inline constexpr unsigned column = 7;    // Type 2: column record index (s2 - 1) * shapes + s0 - 1
inline constexpr unsigned gap = 8;       // Type 2: first zipper word, relative to the gap words
inline constexpr unsigned clamp = 9;     // Type 2: K
inline constexpr unsigned strips = 10;
inline constexpr unsigned e1_offset = 11;
inline constexpr unsigned unique = 12;
inline constexpr unsigned copy_bias = 13;
inline constexpr unsigned slot_skip = 14; // 2 words: begin | length << 16 (Type 1: at most two)
inline constexpr unsigned tri_skip = 16;  // 8 pairs: begin, length
inline constexpr unsigned words = 32;
} // namespace setup_word

struct PatchSetupBlock {
    std::uint32_t word[setup_word::words] = {};
    std::uint32_t vertices = 0; // not stored: the record holds the counts
    std::uint32_t triangles = 0;
};

namespace detail {

struct SetupEdge {
    std::uint32_t points, t16, segments, half_step;
};

// Point i of a CP edge (the shaders' edge_point, CpPatch::point).
inline std::uint32_t setup_edge_point(const CpTableSet& tables, const SetupEdge& e, std::uint32_t i) {
    if (i == 0) return 0;
    if (i >= e.segments) return cp::fixed_one;
    const std::uint32_t packed = tables.points[e.points + i - 1];
    const int fin = static_cast<int>(packed & cp::tables::point_final_mask);
    const std::uint32_t slide = packed >> cp::tables::point_slide_shift;
    const int half = static_cast<int>(e.half_step);
    const int start = slide == 1 ? fin + half : slide == 2 ? fin - half : fin;
    return static_cast<std::uint32_t>(start * 65536 + (fin - start) * static_cast<int>(e.t16));
}

} // namespace detail

// The block of a patch with clamped line states s0, s1, s2 (cp::clamp_line_state).
inline PatchSetupBlock patch_setup_block(const CpTableSet& tables, cp::LineState s0, cp::LineState s1,
                                         cp::LineState s2) {
    namespace w = setup_word;
    PatchSetupBlock out;
    std::uint32_t* word = out.word;
    const cp::LineState s[3] = {s0, s1, s2};
    detail::SetupEdge e[3];
    for (unsigned k = 0; k < 3; ++k) {
        const unsigned shape = s[k].token == 0 ? 1u : s[k].token;
        const cp::tables::TokenRecord& rec = tables.tokens[shape - 1];
        e[k] = {rec.first_point, s[k].token == 0 ? 0u : s[k].t16, rec.segments, rec.half_step};
        word[w::token_rec + k] = std::uint32_t{rec.first_point} | std::uint32_t{rec.segments} << 16;
        word[w::half_step + k] = rec.half_step;
    }
    const bool c0 = s0.token == 0, c1 = s1.token == 0, c2 = s2.token == 0;
    const std::uint32_t n0 = e[0].segments, n1 = e[1].segments, n2 = e[2].segments;
    unsigned tri_skips = 0, slot_skips = 0;
    auto skip_triangles = [&](std::uint32_t begin, std::uint32_t end) {
        if (end <= begin) return;
        word[w::tri_skip + 2 * tri_skips] = begin;
        word[w::tri_skip + 2 * tri_skips + 1] = end - begin;
        ++tri_skips;
    };
    auto dropped_triangles = [&] {
        std::uint32_t dropped = 0;
        for (unsigned k = 0; k < tri_skips; ++k) dropped += word[w::tri_skip + 2 * k + 1];
        return dropped;
    };
    unsigned type = 0;
    bool copies = false;
    if (c0 && c1 && c2) {
        out.vertices = 3;
        out.triangles = 1;
    } else if (s0.token <= 1 && s2.token <= 1) { // Type 1: n1 + 7 slots, n1 + 6 triangles before the collapse
        type = 1;
        std::uint32_t dropped_slots = 0;
        auto skip_slots = [&](std::uint32_t begin, std::uint32_t end) {
            word[w::slot_skip + slot_skips++] = begin | (end - begin) << 16;
            dropped_slots += end - begin;
        };
        if (c0) skip_slots(1, 3);
        if (c1) skip_slots(4, 6);
        if (c2) skip_slots(4 + n1, c0 ? 7 + n1 : 6 + n1);
        auto drop = [&](bool when, std::uint32_t at) {
            if (when) skip_triangles(at, at + 1);
        };
        drop(c0 || c2, 0);
        drop(c0 || c1, 1);
        drop(c1 || c2, 2);
        drop(c0 && c2, 3);
        drop(c0 && c1, 4);
        drop(c1 && c2, n1 + 3);
        drop(c0 && c2, n1 + 4);
        drop(c0 && c2, n1 + 5);
        out.vertices = n1 + 7 - dropped_slots;
        out.triangles = n1 + 6 - dropped_triangles();
    } else {
        type = 2;
        const unsigned shapes = tables.shapes;
        const unsigned sh0 = c0 ? 1u : s0.token, sh1 = c1 ? 1u : s1.token, sh2 = c2 ? 1u : s2.token;
        const CpColumnChunk& chunk = tables.column_chunks[tables.chunk_of_shape2[sh2 - 1]];
        const cp::tables::ColumnRecord& rec = chunk.records[(sh2 - chunk.first_shape2) * shapes + sh0 - 1];
        const std::uint16_t* col = chunk.pool + rec.offset;
        const std::uint32_t head = rec.head;
        word[w::column] = (sh2 - 1) * shapes + sh0 - 1;
        word[w::gap] = tables.gap_offset[(sh1 - 1) * shapes + sh0 - 1];
        const std::uint32_t last0 = detail::setup_edge_point(tables, e[0], n0 - 1);
        const std::uint32_t v2 = detail::setup_edge_point(tables, e[2], sh2 >= 2 ? n2 - 1 : 1u);
        word[w::clamp] = last0 < v2 ? last0 : v2;
        const std::uint32_t ch = col[head];
        const std::uint32_t strips = 2 * ch + 1 - 2 * head - n2;
        const std::uint32_t zipper = n0 + n1 - 1;
        const std::uint32_t e1_offset = c0 ? n2 : c2 ? n0 : ch + n0 - head;
        const std::uint32_t unique = e1_offset + (c1 ? 2u : n1 + 1);
        copies = !c0 && !c2;
        word[w::strips] = strips;
        word[w::e1_offset] = e1_offset;
        word[w::unique] = unique;
        word[w::copy_bias] = unique + 1u - col[1];
        const std::uint32_t copy_count = copies ? ch - col[1] - (head - 1) : 0u;
        const std::uint32_t z = strips;
        const std::uint32_t t1_fan = c1 ? tables.t1_last_fan[sh0 - 1] : 0u;
        if (c0) {
            skip_triangles(0, 2 * n2 - 2);
            if (c1) {
                skip_triangles(z, z + 2);
                skip_triangles(z + 3, z + 5);
            } else {
                skip_triangles(z, z + 1);
                skip_triangles(z + n1, z + n1 + 1);
            }
        } else if (c2) {
            const std::uint32_t r1 = col[2] - col[1];
            skip_triangles(0, r1);
            skip_triangles(r1 + 1, strips);
            if (c1) {
                skip_triangles(z, z + 1);
                if (t1_fan == zipper - 1) {
                    skip_triangles(z + n0, z + n0 + 2);
                } else {
                    skip_triangles(z + t1_fan, z + t1_fan + 1);
                    skip_triangles(z + zipper - 1, z + zipper);
                }
            } else {
                skip_triangles(z + zipper - 1, z + zipper);
            }
        } else if (c1) {
            skip_triangles(z, z + 1);
            skip_triangles(z + t1_fan, z + t1_fan + 1);
        }
        out.vertices = unique + copy_count;
        out.triangles = strips + zipper - dropped_triangles();
    }
    word[w::flags] = type | std::uint32_t{c0} << 2 | std::uint32_t{c1} << 3 | std::uint32_t{c2} << 4 |
                     std::uint32_t{copies} << 5 | tri_skips << 8 | slot_skips << 12;
    return out;
}

} // namespace ctess::rt
