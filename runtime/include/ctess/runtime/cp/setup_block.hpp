// The per-patch setup block of the GPU mesh pipeline: everything a vertex or triangle invocation needs about
// its patch beyond the line states, computed once per patch by the setup pass and stored after the patch
// record (docs/shaders.md, "Patch records"). An emit invocation then reads these words and one column record
// instead of redoing the setup (token records, column record, clamp, strip count, collapse skips).
//
// This is the CPU twin of the shaders' patch_setup (shaders/ctess_mesh.comp.glsl, shaders/ctess_mesh.wgsl):
// the state of CpPatchSetup's constructor (the collapse skips of docs/algorithm.md §2.9 included), written
// out as table indices rather than pointers, so that the block does not depend on where a blob puts its
// sections.
#pragma once
#include <cstdint>

#include <ctess/cp/line.hpp>

#include "patch.hpp"
#include "table_set.hpp"

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

// Reads CpPatchSetup's state (its friend): the provoking layout and counter-clockwise winding the pipeline
// uses.
struct PatchSetupBlockWriter {
    static PatchSetupBlock write(const CpTableSet& tables, const CpPatchSetup& p,
                                 const cp::LineState (&s)[3]) {
        namespace w = setup_word;
        PatchSetupBlock out;
        std::uint32_t* word = out.word;
        for (unsigned k = 0; k < 3; ++k) {
            const unsigned shape = s[k].token == 0 ? 1u : s[k].token;
            const cp::tables::TokenRecord& rec = tables.tokens[shape - 1];
            word[w::token_rec + k] = std::uint32_t{rec.first_point} | std::uint32_t{rec.segments} << 16;
            word[w::half_step + k] = rec.half_step;
        }
        if (p.type_ == 2) {
            const unsigned sh0 = p.c0_ ? 1u : s[0].token, sh2 = p.c2_ ? 1u : s[2].token;
            word[w::column] = (sh2 - 1) * tables.shapes + sh0 - 1;
            word[w::gap] = static_cast<std::uint32_t>(p.gap_ - tables.gap_word);
            word[w::clamp] = p.clamp_;
            word[w::strips] = p.strips_;
            word[w::e1_offset] = p.e1_offset_;
            word[w::unique] = p.unique_;
            word[w::copy_bias] = p.copy_bias_;
        }
        for (unsigned k = 0; k < p.slot_skips_; ++k)
            word[w::slot_skip + k] = p.slot_skip_[k].begin | p.slot_skip_[k].length << 16;
        for (unsigned k = 0; k < p.tri_skips_; ++k) {
            word[w::tri_skip + 2 * k] = p.tri_skip_[k].begin;
            word[w::tri_skip + 2 * k + 1] = p.tri_skip_[k].length;
        }
        const bool copies = p.copy_mask_ != 0;
        word[w::flags] = std::uint32_t{p.type_} | std::uint32_t{p.c0_} << 2 | std::uint32_t{p.c1_} << 3 |
                         std::uint32_t{p.c2_} << 4 | std::uint32_t{copies} << 5 | p.tri_skips_ << 8 |
                         p.slot_skips_ << 12;
        out.vertices = p.vertices_;
        out.triangles = p.triangles_;
        return out;
    }
};

// The block of a patch with clamped line states s0, s1, s2 (cp::clamp_line_state).
inline PatchSetupBlock patch_setup_block(const CpTableSet& tables, cp::LineState s0, cp::LineState s1,
                                         cp::LineState s2) {
    const cp::LineState s[3] = {s0, s1, s2};
    return PatchSetupBlockWriter::write(tables, CpPatchSetup(tables, s0, s1, s2), s);
}

} // namespace ctess::rt
