// ctess mesh pipeline (both pattern families: CP and uniform density), GLSL 4.50 compute (Vulkan). Generated from
// shaders/ctess_mesh.comp.glsl by gen/: the generator replaces the constants placeholder below with a block of
// `const` lines taken from the C++ definitions (gen/shaders/shader_layout.hpp and the table blob's layout;
// docs/shaders.md, "Generated constants"), and fills in the pass's workgroup size and entry point. The same steps as
// runtime/include/ctess/runtime/pipeline/mesh_pipeline.hpp, operation for operation; the CP lookups mirror
// runtime/include/ctess/runtime/cp/patch.hpp and cp_search.hpp (docs/shaders.md).
#version 450

{{CONSTANTS}}

layout(local_size_x = {{LOCAL_SIZE}}) in;

// params (rt::gpu::param_word): patch count, surface (0 flat, 1 PN, 2 Phong, 3 PN-AEN), alpha, factor scale, eye xyz,
// mesh vertex count, then the patch range [first, end) that the emit passes cover (hosts may emit in batches), the
// pattern (0 CP, 1 uniform), the quad count (the last patches; their 4 indices each follow the triangles' 3) and the
// quad rule
layout(std430, set = 0, binding = 0) readonly buffer Params { uint params[]; };
layout(std430, set = 0, binding = 1) readonly buffer Tables { uint tables[]; };
layout(std430, set = 0, binding = 2) readonly buffer MeshVertices { float mesh_vertices[]; };
layout(std430, set = 0, binding = 3) readonly buffer MeshIndices { uint mesh_indices[]; };
layout(std430, set = 0, binding = 4) buffer Patches { uint patches[]; };
// Binding 5 is read only by the split pattern's vertex passes: the base weights ctess_split_points wrote.
layout(std430, set = 0, binding = 5) buffer OutVertices { uint out_vertices[]; };
layout(std430, set = 0, binding = 6) writeonly buffer OutIndices { uint out_indices[]; };
layout(std430, set = 0, binding = 7) buffer Weld { uint weld[]; }; // the welded output's area (rt::gpu::weld_word)

uint patch_count() { return params[PARAM_PATCH_COUNT]; }
bool uniform_pattern() { return params[PARAM_PATTERN] == PATTERN_UNIFORM; }
bool split_pattern() { return params[PARAM_PATTERN] == PATTERN_UNIFORM_SPLIT; }

// ---- 64-bit helpers (GLSL 4.50 core has no 64-bit integers): x = (lo, hi) ----
uvec2 mul_wide(uint a, uint b) {
    uint a0 = a & 0xFFFFu, a1 = a >> 16, b0 = b & 0xFFFFu, b1 = b >> 16;
    uint p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint mid = (p00 >> 16) + (p01 & 0xFFFFu) + (p10 & 0xFFFFu);
    return uvec2((p00 & 0xFFFFu) | (mid << 16), p11 + (p01 >> 16) + (p10 >> 16) + (mid >> 16));
}
uvec2 add_wide(uvec2 x, uint y) {
    uint lo = x.x + y;
    return uvec2(lo, x.y + (lo < y ? 1u : 0u));
}

// ---- tables ----
uint table_u16(uint base, uint i) { return (tables[base + (i >> 1)] >> ((i & 1u) * 16u)) & 0xFFFFu; }

// ---- CP line (constexpr/ctess/cp/line.hpp) ----
uint round_half_even_shift(uint n, uint s) {
    if (s == 0u) return n;
    uint q = n >> s, r = n & ((1u << s) - 1u), half_ = 1u << (s - 1u);
    return (r > half_ || (r == half_ && (q & 1u) != 0u)) ? q + 1u : q;
}
// Factor -> (token, t16); NaN and f <= 1 give T0, f >= max the last token at t = 1.
uvec2 line_state(float f) {
    uint bits = floatBitsToUint(f);
    bool nan_ = (bits & 0x7FFFFFFFu) > 0x7F800000u;
    uint f16;
    if (nan_ || f <= 1.0) f16 = LERP_ONE;
    else if (f >= float(MAX_FACTOR)) f16 = MAX_FACTOR << 16;
    else f16 = uint(roundEven(f * float(LERP_ONE)));
    if (f16 <= LERP_ONE) return uvec2(0u, 0u);
    for (uint t = 1u; t < TOKENS; ++t) {
        uint range = tables[TOKEN_RANGE + t];
        uint lo = range & 0xFFFFu, hi = range >> 16;
        // hi - lo is a power of two: its lowest set bit is its log2
        if (f16 <= (hi << 16)) return uvec2(t, round_half_even_shift(f16 - (lo << 16), uint(findLSB(hi - lo))));
    }
    return uvec2(TOKENS - 1u, LERP_ONE);
}

// ---- patch state (CpPatch) ----
struct Edge {
    uint points; // u16 index of interior point 1
    uint t16;
    uint segments;
    uint half_step;
};
struct Patch {
    Edge e[3];
    uint type_;
    bool c0, c1, c2, copies;
    uint column; // column record index (s2 - 1) * shapes + s0 - 1
    uint c;      // u16 index of C_0 in the column pool
    uint gap;    // word index of the pair's first zipper word
    uint head, n0, n1, n2;
    float a, b;
    uint copy_bias, clamp_, e1_offset, unique_, strips, zipper, vertices, triangles;
    uvec2 tri_skip[SETUP_TRI_SKIPS];
    uint tri_skips;
    uvec2 slot_skip[4];
    uint slot_skips;
};

uint col(Patch p, int x) { return table_u16(COLUMN_POOL, p.c + uint(x)); }

uint edge_point(Edge e, uint i) {
    if (i == 0u) return 0u;
    if (i >= e.segments) return FIXED_ONE;
    uint packed = table_u16(POINT, e.points + i - 1u);
    int fin = int(packed & 0xFFu);
    uint slide = packed >> 8;
    int half_ = int(e.half_step);
    int start = slide == 1u ? fin + half_ : slide == 2u ? fin - half_ : fin;
    return uint(start * 65536 + (fin - start) * int(e.t16));
}

void add_triangle_skip(inout Patch p, uint begin, uint end) {
    if (end > begin) {
        p.tri_skip[p.tri_skips] = uvec2(begin, end - begin);
        p.tri_skips += 1u;
    }
}
void add_slot_skip(inout Patch p, uint begin, uint end) {
    p.slot_skip[p.slot_skips] = uvec2(begin, end - begin);
    p.slot_skips += 1u;
}

Patch patch_zero() {
    Patch p;
    for (uint k = 0u; k < 3u; ++k) p.e[k] = Edge(0u, 0u, 0u, 0u);
    p.type_ = 0u;
    p.c0 = false; p.c1 = false; p.c2 = false;
    p.n0 = 0u; p.n1 = 0u; p.n2 = 0u;
    p.tri_skips = 0u;
    p.slot_skips = 0u;
    p.copies = false;
    p.column = 0u; p.c = 0u; p.gap = 0u; p.head = 0u; p.a = 0.0; p.b = 0.0;
    p.copy_bias = 0u; p.clamp_ = 0u; p.e1_offset = 0u; p.unique_ = 0u; p.strips = 0u; p.zipper = 0u;
    p.vertices = 0u; p.triangles = 0u;
    for (uint k = 0u; k < SETUP_TRI_SKIPS; ++k) p.tri_skip[k] = uvec2(0u);
    for (uint k = 0u; k < 4u; ++k) p.slot_skip[k] = uvec2(0u);
    return p;
}

// The column record's pool index, head and first-guess coefficients (Type 2).
void load_column_record(inout Patch p) {
    uint rec = COLUMN_RECORD + 4u * p.column;
    p.c = tables[rec];
    p.head = tables[rec + 1u];
    p.a = uintBitsToFloat(tables[rec + 2u]);
    p.b = uintBitsToFloat(tables[rec + 3u]);
}

// The line of a line state (token, t16) from its token record; T0 reads as T1's shape at t = 0.
Edge line_edge(uvec2 s) {
    uint shape = s.x == 0u ? 1u : s.x;
    uint rec = tables[TOKEN_RECORD + 2u * (shape - 1u)];
    return Edge(rec & 0xFFFFu, s.x == 0u ? 0u : s.y, rec >> 16, tables[TOKEN_RECORD + 2u * (shape - 1u) + 1u]);
}

// The whole setup from the line states: the setup pass runs it once per patch.
Patch patch_setup(uvec2 s0, uvec2 s1, uvec2 s2) {
    Patch p = patch_zero();
    uvec2 s[3] = uvec2[3](s0, s1, s2);
    for (uint k = 0u; k < 3u; ++k) p.e[k] = line_edge(s[k]);
    p.c0 = s0.x == 0u;
    p.c1 = s1.x == 0u;
    p.c2 = s2.x == 0u;
    p.n0 = p.e[0].segments;
    p.n1 = p.e[1].segments;
    p.n2 = p.e[2].segments;
    if (p.c0 && p.c1 && p.c2) {
        p.type_ = 0u;
        p.vertices = 3u;
        p.triangles = 1u;
        return p;
    }
    if (s0.x <= 1u && s2.x <= 1u) { // Type 1: n1 + 7 slots, n1 + 6 triangles before the collapse
        p.type_ = 1u;
        uint dropped_slots = 0u;
        if (p.c0) { add_slot_skip(p, 1u, 3u); dropped_slots += 2u; }
        if (p.c1) { add_slot_skip(p, 4u, 6u); dropped_slots += 2u; }
        if (p.c2) {
            uint end = p.c0 ? 7u + p.n1 : 6u + p.n1;
            add_slot_skip(p, 4u + p.n1, end);
            dropped_slots += end - (4u + p.n1);
        }
        if (p.c0 || p.c2) add_triangle_skip(p, 0u, 1u);
        if (p.c0 || p.c1) add_triangle_skip(p, 1u, 2u);
        if (p.c1 || p.c2) add_triangle_skip(p, 2u, 3u);
        if (p.c0 && p.c2) add_triangle_skip(p, 3u, 4u);
        if (p.c0 && p.c1) add_triangle_skip(p, 4u, 5u);
        if (p.c1 && p.c2) add_triangle_skip(p, p.n1 + 3u, p.n1 + 4u);
        if (p.c0 && p.c2) add_triangle_skip(p, p.n1 + 4u, p.n1 + 5u);
        if (p.c0 && p.c2) add_triangle_skip(p, p.n1 + 5u, p.n1 + 6u);
        uint dropped = 0u;
        for (uint k = 0u; k < p.tri_skips; ++k) dropped += p.tri_skip[k].y;
        p.vertices = p.n1 + 7u - dropped_slots;
        p.triangles = p.n1 + 6u - dropped;
        return p;
    }
    p.type_ = 2u;
    uint sh0 = s0.x == 0u ? 1u : s0.x;
    uint sh1 = s1.x == 0u ? 1u : s1.x;
    uint sh2 = s2.x == 0u ? 1u : s2.x;
    p.column = (sh2 - 1u) * SHAPES + sh0 - 1u;
    load_column_record(p);
    p.gap = GAP_WORD + table_u16(GAP_OFFSET, (sh1 - 1u) * SHAPES + sh0 - 1u);
    uint last0 = edge_point(p.e[0], p.n0 - 1u);
    uint v2 = edge_point(p.e[2], sh2 >= 2u ? p.n2 - 1u : 1u);
    p.clamp_ = min(last0, v2);
    uint ch = col(p, int(p.head));
    p.strips = 2u * ch + 1u - 2u * p.head - p.n2;
    p.zipper = p.n0 + p.n1 - 1u;
    p.e1_offset = p.c0 ? p.n2 : p.c2 ? p.n0 : ch + p.n0 - p.head;
    p.unique_ = p.e1_offset + (p.c1 ? 2u : p.n1 + 1u);
    p.copies = !p.c0 && !p.c2;
    uint c1v = col(p, 1);
    p.copy_bias = p.unique_ + 1u - c1v;
    uint copies = p.copies ? ch - c1v - (p.head - 1u) : 0u;
    uint z = p.strips;
    uint t1_fan = p.c1 ? tables[T1_LAST_FAN + sh0 - 1u] : 0u;
    if (p.c0) {
        add_triangle_skip(p, 0u, 2u * p.n2 - 2u);
        if (p.c1) {
            add_triangle_skip(p, z, z + 2u);
            add_triangle_skip(p, z + 3u, z + 5u);
        } else {
            add_triangle_skip(p, z, z + 1u);
            add_triangle_skip(p, z + p.n1, z + p.n1 + 1u);
        }
    } else if (p.c2) {
        uint r1 = col(p, 2) - c1v;
        add_triangle_skip(p, 0u, r1);
        add_triangle_skip(p, r1 + 1u, p.strips);
        if (p.c1) {
            add_triangle_skip(p, z, z + 1u);
            if (t1_fan == p.zipper - 1u) {
                add_triangle_skip(p, z + p.n0, z + p.n0 + 2u);
            } else {
                add_triangle_skip(p, z + t1_fan, z + t1_fan + 1u);
                add_triangle_skip(p, z + p.zipper - 1u, z + p.zipper);
            }
        } else {
            add_triangle_skip(p, z + p.zipper - 1u, z + p.zipper);
        }
    } else if (p.c1) {
        add_triangle_skip(p, z, z + 1u);
        add_triangle_skip(p, z + t1_fan, z + t1_fan + 1u);
    }
    uint dropped = 0u;
    for (uint k = 0u; k < p.tri_skips; ++k) dropped += p.tri_skip[k].y;
    p.vertices = p.unique_ + copies;
    p.triangles = p.strips + p.zipper - dropped;
    return p;
}

// ---- reverse lookups (cp_search.hpp): y = C_x (vertex), C_x - x (copy), PS_x (strip) ----
const int SEARCH_VERTEX = 0, SEARCH_COPY = 1, SEARCH_STRIP = 2;
int search_y(Patch p, int kind, int x) {
    if (kind == SEARCH_VERTEX) return int(col(p, x));
    if (kind == SEARCH_COPY) return int(col(p, x)) - x;
    return int(col(p, x)) + int(col(p, x + 1)) - 2 * x - int(p.n2);
}
int search_first_guess(float alpha, float beta, float e, uint h) {
    float d = alpha * alpha - 4.0 * beta * e;
    d = d > 0.0 ? d : 0.0;
    float x = 2.0 * e / (alpha + sqrt(d));
    float last = float(h - 1u);
    x = x > 0.0 ? x : 0.0;
    x = x < last ? x : last;
    return int(x);
}
uint search_from(Patch p, int kind, uint h, int e, int x0) {
    int last = int(h) - 1;
    int x = x0 < 0 ? 0 : x0 > last ? last : x0;
    int y0 = search_y(p, kind, x);
    int ahead = search_y(p, kind, x + 1) - y0;
    int behind = y0 - search_y(p, kind, x > 0 ? x - 1 : 0);
    bool forward = e >= y0;
    int step_ = forward ? ahead : behind;
    int den = step_ > 0 ? step_ : 1;
    int num = forward ? e - y0 : (y0 - e) + den - 1;
    int q = num / den;
    int next_ = forward ? x + q : x - q;
    x = next_ < 0 ? 0 : next_ > last ? last : next_;
    uint i = uint(x);
    for (uint k = 1u; k <= SEARCH_WINDOW; ++k) {
        int at = x + int(k);
        if (at <= last && search_y(p, kind, at) <= e) i += 1u;
    }
    return i;
}

// ---- vertices ----
uvec2 e1_point(uint s) { return uvec2(FIXED_ONE - s, s); }
uvec2 column_point(Patch p, uint i, uint j) {
    uint v2 = edge_point(p.e[2], j);
    if (i == 0u) return uvec2(0u, v2);
    uint u = edge_point(p.e[0], i);
    uint top = p.clamp_ > u ? p.clamp_ - u : 0u;
    return uvec2(u, min(v2, top));
}
uvec2 type1_center(uint t0, uint t2) {
    uint a = min(t0, LERP_ONE), c = min(t2, LERP_ONE);
    // x = (a << 32) + (1 - a) c (1 - c);  y = (1 - a)(2^16 (a + c) - a c), all in units of 2^-32
    uvec2 x = mul_wide(LERP_ONE - a, c * (LERP_ONE - c));
    x.y += a;
    uvec2 y;
    if (a == LERP_ONE || c == LERP_ONE) y = uvec2(0u, LERP_ONE - a); // the inner factor is 2^32
    else y = mul_wide(LERP_ONE - a, 0u - (LERP_ONE - a) * (LERP_ONE - c));
    x = add_wide(x, 1u << 24);
    y = add_wide(y, 1u << 24);
    return uvec2((x.y << 7) | (x.x >> 25), (y.y << 7) | (y.x >> 25));
}
uvec2 slot_point(Patch p, uint s) {
    if (s == 0u) return uvec2(0u);
    if (s <= 2u) return uvec2(edge_point(p.e[0], s), 0u);
    if (s <= 3u + p.n1) return e1_point(edge_point(p.e[1], s - 3u));
    if (s == 4u + p.n1) return uvec2(0u, edge_point(p.e[2], 2u));
    if (s == 5u + p.n1) return uvec2(0u, edge_point(p.e[2], 1u));
    return type1_center(p.e[0].t16, p.e[2].t16);
}
uint col_start(Patch p, uint i) { return i <= p.head ? col(p, int(i)) : col(p, int(p.head)) + (i - p.head); }
uvec2 copy_point(Patch p, uint k) {
    int t = int(k + col(p, 1)) - 1;
    uint i = search_from(p, SEARCH_COPY, p.head, t, search_first_guess(p.a - 1.0, p.b, float(t), p.head));
    return column_point(p, i, uint(t - search_y(p, SEARCH_COPY, int(i))));
}
uvec2 type2_vertex(Patch p, uint v) {
    if (v >= p.unique_) return copy_point(p, v - p.unique_);
    if (v >= p.e1_offset) {
        uint b = v - p.e1_offset;
        return e1_point(edge_point(p.e[1], p.c1 ? b * p.n1 : b));
    }
    if (p.c0) return column_point(p, 0u, v);
    if (p.c2) return column_point(p, v, 0u);
    uint ch = col(p, int(p.head));
    if (v >= ch) return column_point(p, p.head + (v - ch), 0u);
    uint i = search_from(p, SEARCH_VERTEX, p.head, int(v), search_first_guess(p.a, p.b, float(v), p.head));
    return column_point(p, i, v - col(p, int(i)));
}
uvec2 patch_vertex(Patch p, uint i) {
    if (i >= p.vertices) return uvec2(0u);
    if (p.type_ == 2u) return type2_vertex(p, i);
    if (p.type_ == 1u) {
        for (uint k = 0u; k < p.slot_skips; ++k) i += i >= p.slot_skip[k].x ? p.slot_skip[k].y : 0u;
        return slot_point(p, i);
    }
    return i == 0u ? uvec2(0u) : i == 1u ? uvec2(FIXED_ONE, 0u) : uvec2(0u, FIXED_ONE);
}

// ---- triangles ----
uint slot_index(Patch p, uint s) {
    if (p.c1 && s == 4u) s = 3u;
    if (p.c1 && s == 5u) s = 3u + p.n1;
    if (p.c2 && s == 5u + p.n1) s = 0u;
    if (p.c2 && s == 4u + p.n1) s = 3u + p.n1;
    if (p.c0 && s == 1u) s = 0u;
    if (p.c0 && s == 2u) s = 3u;
    if (p.c0 && p.c2 && s == 6u + p.n1) s = 0u;
    uint below = 0u;
    for (uint k = 0u; k < p.slot_skips; ++k) below += s > p.slot_skip[k].x ? p.slot_skip[k].y : 0u;
    return s - below;
}
uint hexagon_slot(Patch p, uint k) {
    uint m = p.n1 + 3u;
    k %= m;
    if (k == 0u) return 1u;
    if (k == 1u) return 2u;
    if (k < m - 2u) return 3u + (k - 1u);
    return k == m - 2u ? 4u + p.n1 : 5u + p.n1;
}
uvec3 type1_triangle(Patch p, uint r) {
    uint a, b, c;
    if (r == 0u) { a = 0u; b = 1u; c = 5u + p.n1; }
    else if (r == 1u) { a = 3u; b = 4u; c = 2u; }
    else if (r == 2u) { a = 3u + p.n1; b = 4u + p.n1; c = 2u + p.n1; }
    else { a = hexagon_slot(p, r - 2u); b = 6u + p.n1; c = hexagon_slot(p, r - 3u); }
    return uvec3(slot_index(p, a), slot_index(p, b), slot_index(p, c));
}
uint e1_index(Patch p, uint b) { return p.c1 ? p.e1_offset + (b <= 1u ? 0u : 1u) : p.e1_offset + b; }
uint col_index(Patch p, uint i, uint j) {
    if (p.c2) {
        if (i == 0u) return j == 2u ? e1_index(p, p.n1) : 0u;
        return i;
    }
    if (p.c0) {
        if (i == 2u) return e1_index(p, 0u);
        if (i == 1u) return j;
    }
    return col_start(p, i) + j;
}
uint lhs_index(Patch p, uint a) {
    uint i = p.n0 - 1u - a;
    return col_index(p, i, col_start(p, i + 1u) - col_start(p, i) - 1u);
}
uvec3 type2_triangle(Patch p, uint r) {
    if (r < p.strips) {
        float alpha = 2.0 * p.a - 2.0 * p.b - 2.0;
        float model = float(r) - (p.a - p.b - float(p.n2));
        uint i = search_from(p, SEARCH_STRIP, p.head, int(r), search_first_guess(alpha, 2.0 * p.b, model, p.head));
        uint o = r - uint(search_y(p, SEARCH_STRIP, int(i)));
        uint nb = col(p, int(i) + 2) - col(p, int(i) + 1);
        if (p.copies && i >= 1u) {
            // First vertex A_j of column i >= 1 already provoked a triangle of strip i - 1: use its copy.
            uint a = col(p, int(i)), b = col(p, int(i) + 1);
            uint first = a + p.copy_bias - i;
            if (o < 2u * (nb - 1u)) {
                uint j = o >> 1;
                if ((o & 1u) != 0u) return uvec3(b + j, b + j + 1u, a + j + 1u);
                return uvec3(first + j, b + j, a + j + 1u);
            }
            uint j = o - (nb - 1u);
            return uvec3(first + j, b + nb - 1u, a + j + 1u);
        }
        if (o < 2u * (nb - 1u)) {
            uint j = o >> 1;
            if ((o & 1u) != 0u) return uvec3(col_index(p, i + 1u, j), col_index(p, i + 1u, j + 1u), col_index(p, i, j + 1u));
            return uvec3(col_index(p, i, j), col_index(p, i + 1u, j), col_index(p, i, j + 1u));
        }
        uint j = o - (nb - 1u);
        return uvec3(col_index(p, i, j), col_index(p, i + 1u, nb - 1u), col_index(p, i, j + 1u));
    }
    uint q = r - p.strips;
    uint w = tables[p.gap + q / 16u];
    uint bit = q % 16u;
    uint bits = w & 0xFFFFu;
    uint a = (w >> 16) + uint(bitCount(bits & ((1u << bit) - 1u)));
    uint b = q - a;
    if (((bits >> bit) & 1u) != 0u) return uvec3(lhs_index(p, a + 1u), lhs_index(p, a), e1_index(p, b));
    return uvec3(e1_index(p, b + 1u), lhs_index(p, a), e1_index(p, b));
}
uvec3 patch_triangle(Patch p, uint t) {
    if (t >= p.triangles) return uvec3(0u);
    for (uint k = 0u; k < p.tri_skips; ++k) t += t >= p.tri_skip[k].x ? p.tri_skip[k].y : 0u;
    if (p.type_ == 2u) return type2_triangle(p, t);
    if (p.type_ == 1u) return type1_triangle(p, t);
    return uvec3(0u, 1u, 2u);
}

// ---- mesh input ----
vec3 mesh_position(uint v) {
    uint o = v * MESH_VERTEX_FLOATS;
    return vec3(mesh_vertices[o], mesh_vertices[o + 1u], mesh_vertices[o + 2u]);
}
struct Corner {
    vec3 position;
    vec3 normal;
    vec2 uv;
    uint index;
};
Corner mesh_corner(uint v) {
    uint o = v * MESH_VERTEX_FLOATS;
    Corner c;
    c.position = vec3(mesh_vertices[o], mesh_vertices[o + 1u], mesh_vertices[o + 2u]);
    c.normal = vec3(mesh_vertices[o + 3u], mesh_vertices[o + 4u], mesh_vertices[o + 5u]);
    c.uv = vec2(mesh_vertices[o + 6u], mesh_vertices[o + 7u]);
    c.index = v;
    return c;
}
bool base_triangle(uint t, out uvec3 w) {
    w = uvec3(mesh_indices[3u * t], mesh_indices[3u * t + 1u], mesh_indices[3u * t + 2u]);
    uint n = params[PARAM_MESH_VERTEX_COUNT];
    return w.x < n && w.y < n && w.z < n;
}
// Patches are the base triangles, then the PARAM_QUAD_COUNT quads (4 indices each after the triangles' 3).
uint triangle_count() { return patch_count() - params[PARAM_QUAD_COUNT]; }
bool base_quad(uint q, out uint w[4]) {
    uint o = 3u * triangle_count() + 4u * q;
    uint n = params[PARAM_MESH_VERTEX_COUNT];
    bool inside = true;
    for (uint k = 0u; k < 4u; ++k) {
        w[k] = mesh_indices[o + k];
        inside = inside && w[k] < n;
    }
    return inside;
}

// ---- tess factors (tess_factor.hpp): precise, so that no multiply-add is fused ----
float dot3(vec3 a, vec3 b) {
    precise float r = a.x * b.x + a.y * b.y + a.z * b.z;
    return r;
}
float edge_tess_factor(vec3 a, vec3 b, vec3 eye, float factor_scale) {
    precise vec3 d = b - a;
    precise vec3 m = 0.5 * (a + b);
    precise vec3 e = m - eye;
    precise float len2 = dot3(d, d);
    precise float dist2 = dot3(e, e);
    precise float f = sqrt(len2 * (1.0 / dist2)) * factor_scale;
    return f;
}

// ---- surface (surface_eval.hpp) ----
vec3 normalize_or_zero(vec3 a) {
    float len2 = dot3(a, a);
    if (!(len2 > 0.0)) return vec3(0.0);
    return (1.0 / sqrt(len2)) * a;
}
// PN edge control point b_ij from position pi, normal ni and the far end pj (eval.cpp's pn_control).
vec3 pn_control(vec3 pi, vec3 ni, vec3 pj) {
    float w = dot3(pj - pi, ni);
    return (1.0 / 3.0) * ((2.0 * pi + pj) - w * ni);
}
vec3 pn_edge_point(Corner i, Corner j) { return pn_control(i.position, i.normal, j.position); }
vec3 pn_edge_normal(Corner i, Corner j) {
    vec3 d = j.position - i.position;
    float len2 = dot3(d, d);
    float v = len2 > 0.0 ? 2.0 * dot3(d, i.normal + j.normal) * (1.0 / len2) : 0.0;
    return normalize_or_zero((i.normal + j.normal) - v * d);
}
vec3 phong_project(vec3 q, Corner i) { return q - dot3(q - i.position, i.normal) * i.normal; }
vec3 blend(vec3 flat_, vec3 curved, float alpha) { return (1.0 - alpha) * flat_ + alpha * curved; }

struct SurfacePoint {
    vec3 position;
    vec3 normal;
    vec2 uv;
};
// The PN cubic at weights (w0, w1, w2) from its six edge control points b = {b210, b120, b021, b012, b102, b201}
// (eval.cpp's pn_cubic; Vlachos et al. 2001): position pn and the quadratic normal field nn. PN and PN-AEN differ
// only in b.
void pn_cubic(Corner c0, Corner c1, Corner c2, vec3 b[6], float w0, float w1, float w2, out vec3 pn, out vec3 nn) {
    vec3 e = (1.0 / 6.0) * (((b[0] + b[1]) + (b[2] + b[3])) + (b[4] + b[5]));
    vec3 v = (1.0 / 3.0) * ((c0.position + c1.position) + c2.position);
    vec3 b111 = e + 0.5 * (e - v);
    float q0 = w0 * w0, q1 = w1 * w1, q2 = w2 * w2;
    pn = (q0 * w0) * c0.position + (q1 * w1) * c1.position + (q2 * w2) * c2.position + (3.0 * q0 * w1) * b[0] +
         (3.0 * q1 * w0) * b[1] + (3.0 * q1 * w2) * b[2] + (3.0 * q2 * w1) * b[3] + (3.0 * q2 * w0) * b[4] +
         (3.0 * q0 * w2) * b[5] + (6.0 * w0 * w1 * w2) * b111;
    nn = q0 * c0.normal + q1 * c1.normal + q2 * c2.normal + (w0 * w1) * pn_edge_normal(c0, c1) +
         (w1 * w2) * pn_edge_normal(c1, c2) + (w2 * w0) * pn_edge_normal(c2, c0);
}
SurfacePoint edge_surface(Corner a, Corner b, float s, float t, uint surface, float alpha) {
    SurfacePoint o;
    vec3 flat_p = s * a.position + t * b.position;
    vec3 flat_n = s * a.normal + t * b.normal;
    o.uv = vec2(s * a.uv.x + t * b.uv.x, s * a.uv.y + t * b.uv.y);
    vec3 pos = flat_p, n = flat_n;
    if (surface == SURFACE_PN) {
        vec3 bab = pn_edge_point(a, b), bba = pn_edge_point(b, a);
        float s2 = s * s, t2 = t * t;
        vec3 pn = (s2 * s) * a.position + (3.0 * s2 * t) * bab + (3.0 * s * t2) * bba + (t2 * t) * b.position;
        vec3 nn = s2 * a.normal + t2 * b.normal + (s * t) * pn_edge_normal(a, b);
        pos = blend(flat_p, pn, alpha);
        n = blend(flat_n, nn, alpha);
    } else if (surface == SURFACE_PHONG) {
        vec3 ph = (s * s) * a.position + (t * t) * b.position +
                  (s * t) * (phong_project(b.position, a) + phong_project(a.position, b));
        pos = blend(flat_p, ph, alpha);
    }
    o.position = pos;
    o.normal = normalize_or_zero(n);
    return o;
}
SurfacePoint interior_surface(Corner c0, Corner c1, Corner c2, float w0, float w1, float w2, uint surface, float alpha) {
    SurfacePoint o;
    vec3 flat_p = w0 * c0.position + w1 * c1.position + w2 * c2.position;
    vec3 flat_n = w0 * c0.normal + w1 * c1.normal + w2 * c2.normal;
    o.uv = vec2(w0 * c0.uv.x + w1 * c1.uv.x + w2 * c2.uv.x, w0 * c0.uv.y + w1 * c1.uv.y + w2 * c2.uv.y);
    vec3 pos = flat_p, n = flat_n;
    if (surface == SURFACE_PN) {
        vec3 b[6] = vec3[6](pn_edge_point(c0, c1), pn_edge_point(c1, c0), pn_edge_point(c1, c2),
                            pn_edge_point(c2, c1), pn_edge_point(c2, c0), pn_edge_point(c0, c2));
        vec3 pn, nn;
        pn_cubic(c0, c1, c2, b, w0, w1, w2, pn, nn);
        pos = blend(flat_p, pn, alpha);
        n = blend(flat_n, nn, alpha);
    } else if (surface == SURFACE_PHONG) {
        vec3 ph = (w0 * w0) * c0.position + (w1 * w1) * c1.position + (w2 * w2) * c2.position +
                  (w0 * w1) * (phong_project(c1.position, c0) + phong_project(c0.position, c1)) +
                  (w1 * w2) * (phong_project(c2.position, c1) + phong_project(c1.position, c2)) +
                  (w2 * w0) * (phong_project(c0.position, c2) + phong_project(c2.position, c0));
        pos = blend(flat_p, ph, alpha);
    }
    o.position = pos;
    o.normal = normalize_or_zero(n);
    return o;
}
float fixed_weight(uint w) { return float(w) * (1.0 / float(FIXED_ONE)); }
SurfacePoint evaluate_surface(Corner c[3], uint w[3], uint surface, float alpha) {
    for (uint k = 0u; k < 3u; ++k) {
        if (w[k] == FIXED_ONE) {
            SurfacePoint o;
            o.position = c[k].position;
            o.normal = normalize_or_zero(c[k].normal);
            o.uv = c[k].uv;
            return o;
        }
    }
    for (uint k = 0u; k < 3u; ++k) {
        if (w[k] != 0u) continue;
        uint i = (k + 1u) % 3u, j = (k + 2u) % 3u;
        bool i_first = c[i].index < c[j].index || (c[i].index == c[j].index && i < j);
        uint a = i_first ? i : j, b = i_first ? j : i;
        return edge_surface(c[a], c[b], fixed_weight(w[a]), fixed_weight(w[b]), surface, alpha);
    }
    return interior_surface(c[0], c[1], c[2], fixed_weight(w[0]), fixed_weight(w[1]), fixed_weight(w[2]), surface, alpha);
}

// ---- PN-AEN (eval.cpp's evaluate_surface_aen, docs/algorithm.md §6.1; McDonald and Kilgard 2010) ----
// The neighbour's normals on edge e (corner e -> e + 1) of base triangle t, as mesh_pipeline.cpp's adjacent_edge
// reads them: binding 3 holds, after the 3 x T triangle and 4 x Q quad indices, 12 words per face triangle in
// meshopt_generateTessellationIndexBuffer's layout, whose words 3 + 2e and 4 + 2e are the neighbour's two vertices
// on edge e. Each is paired with the own corner of bit-identical position (either order). A boundary, an index
// >= the mesh vertex count, words past the end of binding 3 or positions matching in neither order: the own
// normals.
bool same_bits(vec3 a, vec3 b) { return floatBitsToUint(a) == floatBitsToUint(b); }
void adjacent_normals(uint t, uint e, Corner from_, Corner to_, out vec3 at_from, out vec3 at_to) {
    at_from = from_.normal;
    at_to = to_.normal;
    // With displacement, binding 3 holds the adjacency only when its flag says so (the texels follow).
    if ((params[PARAM_DISPLACEMENT_FLAGS] & (DISPLACEMENT_ON | DISPLACEMENT_ADJACENCY)) == DISPLACEMENT_ON) return;
    uint at = 3u * triangle_count() + 4u * params[PARAM_QUAD_COUNT] + 12u * t + 3u + 2u * e;
    if (at + 1u >= uint(mesh_indices.length())) return;
    uint i = mesh_indices[at], j = mesh_indices[at + 1u];
    uint n = params[PARAM_MESH_VERTEX_COUNT];
    if (i >= n || j >= n) return;
    Corner v0 = mesh_corner(i), v1 = mesh_corner(j);
    if (same_bits(v0.position, from_.position) && same_bits(v1.position, to_.position)) {
        at_from = v0.normal;
        at_to = v1.normal;
    } else if (same_bits(v1.position, from_.position) && same_bits(v0.position, to_.position)) {
        at_from = v1.normal;
        at_to = v0.normal;
    }
}
// The mean of the PN control points built with both sides' normals: either side gets the same bits (x + y = y + x).
vec3 aen_control(vec3 pi, vec3 ni, vec3 ni_adj, vec3 pj) {
    return 0.5 * (pn_control(pi, ni, pj) + pn_control(pi, ni_adj, pj));
}
// Positions ordered by their bits as unsigned integers, x then y then z (split-normal sides differ in index).
bool position_before(vec3 a, vec3 b) {
    uvec3 ka = floatBitsToUint(a), kb = floatBitsToUint(b);
    for (uint k = 0u; k < 3u; ++k)
        if (ka[k] != kb[k]) return ka[k] < kb[k];
    return false;
}
bool aen_first(Corner a, uint wa, Corner b, uint wb) {
    if (same_bits(a.position, b.position)) return wa >= wb;
    return position_before(a.position, b.position);
}
// x + 0.0f of the CPU (-0.0 becomes +0.0) on the bits: a shader compiler may fold an add of zero away.
vec3 without_negative_zero(vec3 p) {
    uvec3 b = floatBitsToUint(p);
    return uintBitsToFloat(mix(b, uvec3(0u), equal(b, uvec3(0x80000000u))));
}
// A PN-AEN edge point: a first (aen_first), t measured from a; a_adj, b_adj the neighbour's normals at a and b.
SurfacePoint aen_edge_surface(Corner a, vec3 a_adj, Corner b, vec3 b_adj, float s, float t, float alpha) {
    SurfacePoint o;
    vec3 flat_p = s * a.position + t * b.position;
    vec3 flat_n = s * a.normal + t * b.normal;
    o.uv = vec2(s * a.uv.x + t * b.uv.x, s * a.uv.y + t * b.uv.y);
    vec3 bab = aen_control(a.position, a.normal, a_adj, b.position);
    vec3 bba = aen_control(b.position, b.normal, b_adj, a.position);
    float s2 = s * s, t2 = t * t;
    vec3 pn = (s2 * s) * a.position + (3.0 * s2 * t) * bab + (3.0 * s * t2) * bba + (t2 * t) * b.position;
    vec3 nn = s2 * a.normal + t2 * b.normal + (s * t) * pn_edge_normal(a, b);
    o.position = without_negative_zero(blend(flat_p, pn, alpha));
    o.normal = normalize_or_zero(blend(flat_n, nn, alpha));
    return o;
}
// adj_from[e], adj_to[e]: the neighbour's normals at corners e and e + 1 (adjacent_normals).
SurfacePoint evaluate_surface_aen(Corner c[3], vec3 adj_from[3], vec3 adj_to[3], uint w[3], float alpha) {
    for (uint k = 0u; k < 3u; ++k) {
        if (w[k] == FIXED_ONE) {
            SurfacePoint o;
            o.position = without_negative_zero(c[k].position);
            o.normal = normalize_or_zero(c[k].normal);
            o.uv = c[k].uv;
            return o;
        }
    }
    for (uint k = 0u; k < 3u; ++k) {
        if (w[k] != 0u) continue;
        uint i = (k + 1u) % 3u, j = (k + 2u) % 3u; // the edge opposite corner k is edge i: c[i] -> c[j]
        if (aen_first(c[i], w[i], c[j], w[j]))
            return aen_edge_surface(c[i], adj_from[i], c[j], adj_to[i], fixed_weight(w[i]), fixed_weight(w[j]), alpha);
        return aen_edge_surface(c[j], adj_to[i], c[i], adj_from[i], fixed_weight(w[j]), fixed_weight(w[i]), alpha);
    }
    float w0 = fixed_weight(w[0]), w1 = fixed_weight(w[1]), w2 = fixed_weight(w[2]);
    SurfacePoint o;
    vec3 flat_p = w0 * c[0].position + w1 * c[1].position + w2 * c[2].position;
    vec3 flat_n = w0 * c[0].normal + w1 * c[1].normal + w2 * c[2].normal;
    o.uv = vec2(w0 * c[0].uv.x + w1 * c[1].uv.x + w2 * c[2].uv.x, w0 * c[0].uv.y + w1 * c[1].uv.y + w2 * c[2].uv.y);
    vec3 b[6] = vec3[6](aen_control(c[0].position, c[0].normal, adj_from[0], c[1].position),
                        aen_control(c[1].position, c[1].normal, adj_to[0], c[0].position),
                        aen_control(c[1].position, c[1].normal, adj_from[1], c[2].position),
                        aen_control(c[2].position, c[2].normal, adj_to[1], c[1].position),
                        aen_control(c[2].position, c[2].normal, adj_from[2], c[0].position),
                        aen_control(c[0].position, c[0].normal, adj_to[2], c[2].position));
    vec3 pn, nn;
    pn_cubic(c[0], c[1], c[2], b, w0, w1, w2, pn, nn);
    o.position = without_negative_zero(blend(flat_p, pn, alpha));
    o.normal = normalize_or_zero(blend(flat_n, nn, alpha));
    return o;
}

// ---- displacement (displace.cpp and height_map.cpp, docs/algorithm.md §8) ----
// Operation for operation as the CPU's, which is compiled with -ffp-contract=off: every expression is `precise`, so
// that no multiply-add is fused. Params: PARAM_DISPLACEMENT_* and PARAM_HEIGHT_MAP_*; the directions (3 floats per
// mesh vertex) follow the mesh vertices in binding 2, the texels (f32 bits, row-major, row 0 at v = 0) follow the
// indices and the adjacency in binding 3 (docs/shaders.md, "Displacement").
bool displacement_on() { return (params[PARAM_DISPLACEMENT_FLAGS] & DISPLACEMENT_ON) != 0u; }
bool displacement_adjacency() { return (params[PARAM_DISPLACEMENT_FLAGS] & DISPLACEMENT_ADJACENCY) != 0u; }
// Vector displacement (§8.7): RGB texels (3 floats each) and the tangents after the directions in binding 2.
bool displacement_vector_mode() { return (params[PARAM_DISPLACEMENT_FLAGS] & DISPLACEMENT_VECTOR) != 0u; }
float param_float(uint w) { return uintBitsToFloat(params[w]); }
bool finite_bits(float f) { return (floatBitsToUint(f) & 0x7FFFFFFFu) < 0x7F800000u; }
// Binding 3's adjacency starts after the indices; its texels after the adjacency when the host uploaded it.
uint adjacency_base() { return 3u * triangle_count() + 4u * params[PARAM_QUAD_COUNT]; }
uint texel_base() {
    return adjacency_base() + (displacement_adjacency() ? 12u * (triangle_count() + 2u * params[PARAM_QUAD_COUNT]) : 0u);
}
// A texel past the end of binding 3 (a host that uploaded fewer) reads 0: never out of bounds.
float texel(uint i) {
    uint at = texel_base() + i;
    return at < uint(mesh_indices.length()) ? uintBitsToFloat(mesh_indices[at]) : 0.0;
}
// height_map.cpp's texel_coordinate: the integer part (in [-1, n - 1]) and the fraction.
int texel_coordinate(float u, uint n, bool repeat_, out float fraction) {
    precise float x = repeat_ ? u - floor(u) : (u < 0.0 ? 0.0 : u > 1.0 ? 1.0 : u);
    precise float y = x * float(n) - 0.5;
    float base = floor(y);
    precise float f = y - base;
    fraction = f;
    return int(base);
}
uint texel_address(int i, uint n, bool repeat_) {
    if (repeat_) return i < 0 ? n - 1u : uint(i) >= n ? uint(i) - n : uint(i);
    return i < 0 ? 0u : uint(i) >= n ? n - 1u : uint(i);
}
// height_map.cpp's footprint: the four texels (x0, y0), (x1, y0), (x0, y1), (x1, y1) as texel numbers and the
// weights' fractions; false for an empty map or a NaN or infinite coordinate. An address mode other than repeat
// reads as clamp.
bool texel_footprint(float u, float v, out uvec4 at, out vec2 fraction) {
    uint width = params[PARAM_HEIGHT_MAP_WIDTH], height = params[PARAM_HEIGHT_MAP_HEIGHT];
    if (width == 0u || height == 0u) return false;
    if (!finite_bits(u) || !finite_bits(v)) return false;
    bool repeat_ = params[PARAM_HEIGHT_MAP_ADDRESS] == ADDRESS_REPEAT;
    float fx, fy;
    int i0 = texel_coordinate(u, width, repeat_, fx);
    int j0 = texel_coordinate(v, height, repeat_, fy);
    uint x0 = texel_address(i0, width, repeat_), x1 = texel_address(i0 + 1, width, repeat_);
    uint row0 = texel_address(j0, height, repeat_) * width, row1 = texel_address(j0 + 1, height, repeat_) * width;
    at = uvec4(row0 + x0, row0 + x1, row1 + x0, row1 + x1);
    fraction = vec2(fx, fy);
    return true;
}
// Channel `channel` of texels of `channels` floats (height_map.cpp's blend): the operations of the one-channel sample.
float texel_blend(uvec4 at, vec2 f, uint channels, uint channel) {
    precise float top = (1.0 - f.x) * texel(channels * at.x + channel) + f.x * texel(channels * at.y + channel);
    precise float bottom = (1.0 - f.x) * texel(channels * at.z + channel) + f.x * texel(channels * at.w + channel);
    precise float h = (1.0 - f.y) * top + f.y * bottom;
    return h;
}
// sample_bilinear: texel centres at ((i + 0.5) / width, (j + 0.5) / height); an empty map or a NaN or infinite
// coordinate gives 0.
float sample_bilinear(float u, float v) {
    uvec4 at;
    vec2 f;
    if (!texel_footprint(u, v, at, f)) return 0.0;
    return texel_blend(at, f, 1u, 0u);
}
// sample_bilinear_rgb (§8.7): channels 0, 1, 2 of 3-float texels, each by sample_bilinear's operations; an empty
// map or a NaN or infinite coordinate gives (0, 0, 0).
vec3 sample_bilinear_rgb(float u, float v) {
    uvec4 at;
    vec2 f;
    if (!texel_footprint(u, v, at, f)) return vec3(0.0);
    return vec3(texel_blend(at, f, 3u, 0u), texel_blend(at, f, 3u, 1u), texel_blend(at, f, 3u, 2u));
}
// scale * (texel * factor + offset)
float displacement_height(float u, float v) {
    float t = sample_bilinear(u, v);
    precise float h = param_float(PARAM_DISPLACEMENT_SCALE) * (t * param_float(PARAM_DISPLACEMENT_FACTOR) +
                                                               param_float(PARAM_DISPLACEMENT_OFFSET));
    return h;
}
// Vector mode's displacement_vector (§8.7): scale * (texel * factor + offset) per channel.
vec3 displacement_vector(float u, float v) {
    vec3 t = sample_bilinear_rgb(u, v);
    float scale = param_float(PARAM_DISPLACEMENT_SCALE), factor = param_float(PARAM_DISPLACEMENT_FACTOR);
    float offset = param_float(PARAM_DISPLACEMENT_OFFSET);
    precise vec3 r = vec3(scale * (t.x * factor + offset), scale * (t.y * factor + offset), scale * (t.z * factor + offset));
    return r;
}
// displaced_edge_factor (§8.4): the factor of edge a -> b grown by the bound, as if displacement lengthened it
// at both ends.
float displaced_edge_factor(float factor, vec3 a, vec3 b) {
    float bound = param_float(PARAM_DISPLACEMENT_FACTOR_BOUND);
    if (!displacement_on() || !(bound > 0.0)) return factor;
    precise vec3 e = b - a;
    precise float len = sqrt(dot3(e, e));
    if (!(len > 0.0)) return factor;
    precise float grown = factor * (1.0 + 2.0 * bound / len);
    return grown;
}
vec3 cross3(vec3 a, vec3 b) {
    precise vec3 c = vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
    return c;
}
vec3 scaled(float s, vec3 a) {
    precise vec3 r = s * a;
    return r;
}
// What one patch's displacement reads (DisplacementPatch): per corner the dominant vertex's uv and direction (and
// in vector mode its tangent and bitangent), per edge the dominant edge's uvs at both ends (xy, zw), the own
// corners' positions and uvs; 3 or 4 corners.
struct DisplacementPatch {
    uint corners;
    vec2 corner_uv[4];
    vec3 direction[4];
    vec3 tangent[4];
    vec3 bitangent[4];
    vec4 edge_uv[4];
    vec3 position[4];
    vec2 own_uv[4];
};
vec2 mesh_uv(uint v) { return vec2(mesh_vertices[v * MESH_VERTEX_FLOATS + 6u], mesh_vertices[v * MESH_VERTEX_FLOATS + 7u]); }
// A corner's dominant vertex (§8.2): adjacency slot 9 + corner where the host uploaded the adjacency, else the
// vertex itself; one outside the mesh or at another position: the vertex itself.
uint dominant_vertex(uint v, uint face, uint slot) {
    uint d = v;
    if (displacement_adjacency()) d = mesh_indices[adjacency_base() + 12u * face + 9u + slot];
    return d < params[PARAM_MESH_VERTEX_COUNT] && same_bits(mesh_position(d), mesh_position(v)) ? d : v;
}
// Displacement::directions (after the mesh vertices), or the vertex normal, normalised.
vec3 vertex_direction(uint v) {
    uint o = v * MESH_VERTEX_FLOATS + 3u;
    if ((params[PARAM_DISPLACEMENT_FLAGS] & DISPLACEMENT_DIRECTIONS) != 0u)
        o = params[PARAM_MESH_VERTEX_COUNT] * MESH_VERTEX_FLOATS + 3u * v;
    return normalize_or_zero(vec3(mesh_vertices[o], mesh_vertices[o + 1u], mesh_vertices[o + 2u]));
}
// Displacement::tangents (vector mode, glTF TANGENT's layout): 4 floats per mesh vertex after the mesh vertices and
// the directions in binding 2. A tangent past the end of binding 2 (a host that uploaded fewer) reads (0, 0, 0, 1).
vec4 vertex_tangent(uint v) {
    uint n = params[PARAM_MESH_VERTEX_COUNT];
    uint o = n * MESH_VERTEX_FLOATS + ((params[PARAM_DISPLACEMENT_FLAGS] & DISPLACEMENT_DIRECTIONS) != 0u ? 3u * n : 0u) + 4u * v;
    if (o + 3u >= uint(mesh_vertices.length())) return vec4(0.0, 0.0, 0.0, 1.0);
    return vec4(mesh_vertices[o], mesh_vertices[o + 1u], mesh_vertices[o + 2u], mesh_vertices[o + 3u]);
}
// displacement_patch: a patch of `corners` (3 or 4) vertices w, corner k at slot corner_slot[k] of adjacency face
// corner_face[k], edge k (corner k -> k + 1) at edge slot edge_slot[k] of face edge_face[k] (PatchFaces).
// faces false: no neighbours (each corner its own dominant vertex, each edge its own dominant edge).
DisplacementPatch displacement_patch(uint corners, uint w[4], uint corner_face[4], uint corner_slot[4], uint edge_face[4],
                                     uint edge_slot[4], bool vector_, bool faces) {
    DisplacementPatch dp;
    dp.corners = corners;
    uint n = params[PARAM_MESH_VERTEX_COUNT];
    for (uint k = 0u; k < corners; ++k) {
        uint dom = faces ? dominant_vertex(w[k], corner_face[k], corner_slot[k]) : w[k];
        dp.position[k] = mesh_position(w[k]);
        dp.own_uv[k] = mesh_uv(w[k]);
        dp.corner_uv[k] = mesh_uv(dom);
        dp.direction[k] = vertex_direction(dom);
        if (vector_) {
            // The dominant vertex's frame (§8.7): T made orthogonal to the direction N, B = cross(N, T) w.
            vec4 t = vertex_tangent(dom);
            vec3 nd = dp.direction[k];
            precise vec3 ortho = t.xyz - scaled(dot3(t.xyz, nd), nd);
            dp.tangent[k] = normalize_or_zero(ortho);
            dp.bitangent[k] = scaled(t.w < 0.0 ? -1.0 : 1.0, cross3(nd, dp.tangent[k]));
        }
    }
    // The dominant edge: of the own edge and the neighbour's (slots 3-8, paired by position), the one whose
    // vertices, taken in position order, are lexicographically smaller; the neighbour picks the same one.
    for (uint k = 0u; k < corners; ++k) {
        uint a = w[k], b = w[(k + 1u) % corners];
        uvec2 pick = uvec2(a, b);
        if (faces && displacement_adjacency()) {
            uint at = adjacency_base() + 12u * edge_face[k] + 3u + 2u * edge_slot[k];
            uint c = mesh_indices[at], e = mesh_indices[at + 1u];
            if (c < n && e < n) {
                if (!same_bits(mesh_position(c), mesh_position(a))) { uint x = c; c = e; e = x; }
                if (same_bits(mesh_position(c), mesh_position(a)) && same_bits(mesh_position(e), mesh_position(b))) {
                    bool a_first = !position_before(mesh_position(b), mesh_position(a));
                    uvec2 own_key = a_first ? uvec2(a, b) : uvec2(b, a);
                    uvec2 adj_key = a_first ? uvec2(c, e) : uvec2(e, c);
                    if (adj_key.x < own_key.x || (adj_key.x == own_key.x && adj_key.y < own_key.y)) pick = uvec2(c, e);
                }
            }
        }
        dp.edge_uv[k] = vec4(mesh_uv(pick.x), mesh_uv(pick.y));
    }
    return dp;
}
// bend_normal (§8.3): the normal bent by the height's central differences hu, hv along the tangents tu, tv.
void bend_normal(inout SurfacePoint p, vec3 tu, vec3 tv, float hu, float hv) {
    vec3 n = normalize_or_zero(p.normal);
    if (!(dot3(n, n) > 0.0)) return;
    precise vec3 pu = tu - scaled(dot3(tu, n), n);
    precise vec3 pv = tv - scaled(dot3(tv, n), n);
    float j = dot3(cross3(pu, pv), n);
    if (!(j != 0.0) || !finite_bits(hu) || !finite_bits(hv)) return;
    precise vec3 m = (scaled(j, n) + scaled(hv, cross3(pu, n))) + scaled(hu, cross3(n, pv));
    vec3 bent = normalize_or_zero(scaled(j < 0.0 ? -1.0 : 1.0, m));
    if (dot3(bent, bent) > 0.0) p.normal = bent;
}
// The own uv at triangle parameter (a, b) = (w1, w2), and at quad parameter (s, t) (bilinear).
vec2 tri_own_uv(DisplacementPatch dp, float a, float b) {
    precise float c = (1.0 - a) - b;
    precise float u = (c * dp.own_uv[0].x + a * dp.own_uv[1].x) + b * dp.own_uv[2].x;
    precise float v = (c * dp.own_uv[0].y + a * dp.own_uv[1].y) + b * dp.own_uv[2].y;
    return vec2(u, v);
}
vec2 quad_own_uv(DisplacementPatch dp, float s, float t) {
    precise float w[4] = float[4]((1.0 - s) * (1.0 - t), s * (1.0 - t), s * t, (1.0 - s) * t);
    precise float u = ((w[0] * dp.own_uv[0].x + w[1] * dp.own_uv[1].x) + w[2] * dp.own_uv[2].x) + w[3] * dp.own_uv[3].x;
    precise float v = ((w[0] * dp.own_uv[0].y + w[1] * dp.own_uv[1].y) + w[2] * dp.own_uv[2].y) + w[3] * dp.own_uv[3].y;
    return vec2(u, v);
}
// The height at the own uv of triangle parameter (a, b) = (w1, w2).
float tri_uv_height(DisplacementPatch dp, float a, float b) {
    vec2 uv = tri_own_uv(dp, a, b);
    return displacement_height(uv.x, uv.y);
}
void move_point(inout SurfacePoint p, float height, vec3 direction) {
    precise vec3 moved = p.position + scaled(height, direction);
    p.position = moved;
}
// ---- vector displacement (displace.cpp's vector mode, docs/algorithm.md §8.7) ----
// A tangent frame: t along +u, b, n the displacement direction.
struct Frame {
    vec3 t, b, n;
};
// Position + x T + y B + z N, the offset summed first (the same operations from every face).
void move_vector(inout SurfacePoint p, vec3 moved_by, Frame f) {
    precise vec3 offset = (scaled(moved_by.x, f.t) + scaled(moved_by.y, f.b)) + scaled(moved_by.z, f.n);
    precise vec3 moved = p.position + offset;
    p.position = moved;
}
// interpolated_frame: the frame field at weights w of corners corner[0..count-1], each axis summed from zero in
// corner order and normalised as the directions are (zero stays zero).
Frame interpolated_frame(DisplacementPatch dp, uint corner[4], float w[4], uint count) {
    precise vec3 t = vec3(0.0), b = vec3(0.0), d = vec3(0.0);
    for (uint k = 0u; k < count; ++k) {
        t = t + scaled(w[k], dp.tangent[corner[k]]);
        b = b + scaled(w[k], dp.bitangent[corner[k]]);
        d = d + scaled(w[k], dp.direction[corner[k]]);
    }
    return Frame(normalize_or_zero(t), normalize_or_zero(b), normalize_or_zero(d));
}
// bend_normal_vector: S_u x S_v = (t_u' + D_u) x (t_v' + D_v), D_u = Vu.x T + Vu.y B + Vu.z N from the vector's
// central differences vu, vv in the point's frame (its derivatives left out, as bend_normal leaves out dN).
void bend_normal_vector(inout SurfacePoint p, vec3 tu, vec3 tv, vec3 vu, vec3 vv, Frame f) {
    vec3 n = normalize_or_zero(p.normal);
    if (!(dot3(n, n) > 0.0)) return;
    precise vec3 pu = tu - scaled(dot3(tu, n), n);
    precise vec3 pv = tv - scaled(dot3(tv, n), n);
    float j = dot3(cross3(pu, pv), n);
    precise vec3 du = (scaled(vu.x, f.t) + scaled(vu.y, f.b)) + scaled(vu.z, f.n);
    precise vec3 dv = (scaled(vv.x, f.t) + scaled(vv.y, f.b)) + scaled(vv.z, f.n);
    if (!(j != 0.0) || !finite_bits(dot3(du, du)) || !finite_bits(dot3(dv, dv))) return;
    precise vec3 su = pu + du;
    precise vec3 sv = pv + dv;
    vec3 bent = normalize_or_zero(scaled(j < 0.0 ? -1.0 : 1.0, cross3(su, sv)));
    if (dot3(bent, bent) > 0.0) p.normal = bent;
}
// (plus - minus) / (2 step), as 1 / (2 step) times the difference.
vec3 vector_difference(vec3 plus, vec3 minus, float step_) {
    precise float inv = 1.0 / (2.0 * step_);
    precise vec3 r = scaled(inv, plus - minus);
    return r;
}
vec3 tri_uv_vector(DisplacementPatch dp, float a, float b) {
    vec2 uv = tri_own_uv(dp, a, b);
    return displacement_vector(uv.x, uv.y);
}
vec3 quad_uv_vector(DisplacementPatch dp, float s, float t) {
    vec2 uv = quad_own_uv(dp, s, t);
    return displacement_vector(uv.x, uv.y);
}
// A point on patch edge k with weights wa at corner k and wb at corner k + 1: the dominant edge's uvs and the
// dominant directions interpolated from the endpoint first in position order (equal positions: the larger weight).
// vector_: vector mode (§8.7), a constant of the entry point, so that each pass carries one mode's code.
void displace_edge(DisplacementPatch dp, uint k, uint wa, uint wb, inout SurfacePoint p, bool vector_) {
    uint a = k, b = (k + 1u) % dp.corners;
    vec2 uv_a = dp.edge_uv[k].xy, uv_b = dp.edge_uv[k].zw;
    if (wa == FIXED_ONE || wb == FIXED_ONE) {
        uint c = wa == FIXED_ONE ? a : b;
        if (vector_)
            move_vector(p, displacement_vector(dp.corner_uv[c].x, dp.corner_uv[c].y),
                        Frame(dp.tangent[c], dp.bitangent[c], dp.direction[c]));
        else
            move_point(p, displacement_height(dp.corner_uv[c].x, dp.corner_uv[c].y), dp.direction[c]);
        return;
    }
    bool swap_ = position_before(dp.position[b], dp.position[a]) ||
                 (!position_before(dp.position[a], dp.position[b]) && wb > wa);
    if (swap_) {
        uint x = a; a = b; b = x;
        vec2 y = uv_a; uv_a = uv_b; uv_b = y;
        uint z = wa; wa = wb; wb = z;
    }
    float ta = fixed_weight(wa), tb = fixed_weight(wb);
    precise float u = ta * uv_a.x + tb * uv_b.x;
    precise float v = ta * uv_a.y + tb * uv_b.y;
    if (vector_) {
        move_vector(p, displacement_vector(u, v), interpolated_frame(dp, uint[4](a, b, 0u, 0u), float[4](ta, tb, 0.0, 0.0), 2u));
        return;
    }
    precise vec3 dir = scaled(ta, dp.direction[a]) + scaled(tb, dp.direction[b]);
    move_point(p, displacement_height(u, v), normalize_or_zero(dir));
}
// Vector mode's triangle point (displace_triangle_vector, §8.7): the normal from the vector's differences in the own
// parameters, then the position as displace_triangle_point's (corners and edges through displace_edge, the interior
// in the frame interpolated by the barycentric weights).
void displace_triangle_vector(DisplacementPatch dp, uint w[3], float a, float b, inout SurfacePoint p) {
    float step_ = param_float(PARAM_DISPLACEMENT_NORMAL_STEP);
    Frame frame = interpolated_frame(dp, uint[4](0u, 1u, 2u, 0u), float[4](fixed_weight(w[0]), a, b, 0.0), 3u);
    precise float a_plus = a + step_, a_minus = a - step_, b_plus = b + step_, b_minus = b - step_;
    vec3 vu = vector_difference(tri_uv_vector(dp, a_plus, b), tri_uv_vector(dp, a_minus, b), step_);
    vec3 vv = vector_difference(tri_uv_vector(dp, a, b_plus), tri_uv_vector(dp, a, b_minus), step_);
    precise vec3 tu = dp.position[1] - dp.position[0];
    precise vec3 tv = dp.position[2] - dp.position[0];
    bend_normal_vector(p, tu, tv, vu, vv, frame);
    for (uint k = 0u; k < 3u; ++k) {
        if (w[(k + 2u) % 3u] == 0u || w[k] == FIXED_ONE) {
            if (w[k] == FIXED_ONE) displace_edge(dp, k, FIXED_ONE, 0u, p, true);
            else displace_edge(dp, k, w[k], w[(k + 1u) % 3u], p, true);
            return;
        }
    }
    move_vector(p, displacement_vector(p.uv.x, p.uv.y), frame);
}
// Vector mode's quad point on the boundary goes through displace_edge: a corner (both coordinates at a bound), else edge k from
// q_k with parameter r measured from q_k (t = 0, s = 1, t = 1, s = 0). False for an interior point.
bool displace_quad_boundary(DisplacementPatch dp, uint s, uint t, inout SurfacePoint p) {
    if ((s == 0u || s == FIXED_ONE) && (t == 0u || t == FIXED_ONE)) {
        uint c = t == 0u ? (s == 0u ? 0u : 1u) : (s == FIXED_ONE ? 2u : 3u);
        displace_edge(dp, c, FIXED_ONE, 0u, p, true);
        return true;
    }
    bool on_edge[4] = bool[4](t == 0u, s == FIXED_ONE, t == FIXED_ONE, s == 0u);
    uint r[4] = uint[4](s, t, FIXED_ONE - s, FIXED_ONE - t);
    for (uint k = 0u; k < 4u; ++k) {
        if (on_edge[k]) {
            displace_edge(dp, k, FIXED_ONE - r[k], r[k], p, true);
            return true;
        }
    }
    return false;
}
// Vector mode's quad point (displace_quad_vector, §8.7).
void displace_quad_vector(DisplacementPatch dp, uint s, uint t, float fs, float ft, inout SurfacePoint p) {
    float step_ = param_float(PARAM_DISPLACEMENT_NORMAL_STEP);
    precise float w[4] = float[4]((1.0 - fs) * (1.0 - ft), fs * (1.0 - ft), fs * ft, (1.0 - fs) * ft);
    Frame frame = interpolated_frame(dp, uint[4](0u, 1u, 2u, 3u), w, 4u);
    precise float s_plus = fs + step_, s_minus = fs - step_, t_plus = ft + step_, t_minus = ft - step_;
    vec3 vu = vector_difference(quad_uv_vector(dp, s_plus, ft), quad_uv_vector(dp, s_minus, ft), step_);
    vec3 vv = vector_difference(quad_uv_vector(dp, fs, t_plus), quad_uv_vector(dp, fs, t_minus), step_);
    precise vec3 ts = scaled(1.0 - ft, dp.position[1] - dp.position[0]) + scaled(ft, dp.position[2] - dp.position[3]);
    precise vec3 tt = scaled(1.0 - fs, dp.position[3] - dp.position[0]) + scaled(fs, dp.position[2] - dp.position[1]);
    bend_normal_vector(p, ts, tt, vu, vv, frame);
    if (displace_quad_boundary(dp, s, t, p)) return;
    move_vector(p, displacement_vector(p.uv.x, p.uv.y), frame);
}
// displace_triangle_point: p is the surface point of base weights w (units of FIXED_ONE).
void displace_triangle_point(DisplacementPatch dp, uint w[3], inout SurfacePoint p) {
    float a = fixed_weight(w[1]), b = fixed_weight(w[2]);
    float step_ = param_float(PARAM_DISPLACEMENT_NORMAL_STEP);
    precise float hu = (tri_uv_height(dp, a + step_, b) - tri_uv_height(dp, a - step_, b)) / (2.0 * step_);
    precise float hv = (tri_uv_height(dp, a, b + step_) - tri_uv_height(dp, a, b - step_)) / (2.0 * step_);
    precise vec3 tu = dp.position[1] - dp.position[0];
    precise vec3 tv = dp.position[2] - dp.position[0];
    bend_normal(p, tu, tv, hu, hv);
    // A corner, an edge point (edge k has zero weight at corner k + 2) or an interior point.
    for (uint k = 0u; k < 3u; ++k) {
        if (w[(k + 2u) % 3u] == 0u || w[k] == FIXED_ONE) {
            if (w[k] == FIXED_ONE) displace_edge(dp, k, FIXED_ONE, 0u, p, false);
            else displace_edge(dp, k, w[k], w[(k + 1u) % 3u], p, false);
            return;
        }
    }
    precise vec3 dir = (scaled(fixed_weight(w[0]), dp.direction[0]) + scaled(a, dp.direction[1])) + scaled(b, dp.direction[2]);
    move_point(p, displacement_height(p.uv.x, p.uv.y), normalize_or_zero(dir));
}
// The height at the own uv of quad parameter (s, t), bilinear.
float quad_uv_height(DisplacementPatch dp, float s, float t) {
    vec2 uv = quad_own_uv(dp, s, t);
    return displacement_height(uv.x, uv.y);
}
// displace_quad_point: p is the surface point of quad point (s, t) of the unit square (units of FIXED_ONE).
void displace_quad_point(DisplacementPatch dp, uint s, uint t, inout SurfacePoint p) {
    float fs = fixed_weight(s), ft = fixed_weight(t);
    float step_ = param_float(PARAM_DISPLACEMENT_NORMAL_STEP);
    precise float hu = (quad_uv_height(dp, fs + step_, ft) - quad_uv_height(dp, fs - step_, ft)) / (2.0 * step_);
    precise float hv = (quad_uv_height(dp, fs, ft + step_) - quad_uv_height(dp, fs, ft - step_)) / (2.0 * step_);
    precise vec3 ts = scaled(1.0 - ft, dp.position[1] - dp.position[0]) + scaled(ft, dp.position[2] - dp.position[3]);
    precise vec3 tt = scaled(1.0 - fs, dp.position[3] - dp.position[0]) + scaled(fs, dp.position[2] - dp.position[1]);
    bend_normal(p, ts, tt, hu, hv);
    // Corners, then edge k from q_k with parameter r measured from q_k (t = 0, s = 1, t = 1, s = 0), then the
    // interior.
    if ((s == 0u || s == FIXED_ONE) && (t == 0u || t == FIXED_ONE)) {
        uint c = t == 0u ? (s == 0u ? 0u : 1u) : (s == FIXED_ONE ? 2u : 3u);
        displace_edge(dp, c, FIXED_ONE, 0u, p, false);
        return;
    }
    bool on_edge[4] = bool[4](t == 0u, s == FIXED_ONE, t == FIXED_ONE, s == 0u);
    uint r[4] = uint[4](s, t, FIXED_ONE - s, FIXED_ONE - t);
    for (uint k = 0u; k < 4u; ++k) {
        if (on_edge[k]) {
            displace_edge(dp, k, FIXED_ONE - r[k], r[k], p, false);
            return;
        }
    }
    precise float w[4] = float[4]((1.0 - fs) * (1.0 - ft), fs * (1.0 - ft), fs * ft, (1.0 - fs) * ft);
    precise vec3 dir = ((scaled(w[0], dp.direction[0]) + scaled(w[1], dp.direction[1])) + scaled(w[2], dp.direction[2])) +
                       scaled(w[3], dp.direction[3]);
    move_point(p, displacement_height(p.uv.x, p.uv.y), normalize_or_zero(dir));
}

// ---- quad surfaces (evaluate_quad_surface, docs/algorithm.md §6.2, §7.3) ----
// A point strictly inside quad q0 q1 q2 q3 at (s, t) of its unit square: bilinear (flat, zeros as +0), Phong
// (the bilinear point projected onto the corner tangent planes, blended bilinearly) or the PN bicubic patch
// whose boundary is the PN triangles' edge curves, with the biquadratic normal field.
// PN-AEN (aen): the PN patch on PN-AEN edge control points, adj_from[k], adj_to[k] the neighbour's normals on edge k.
SurfacePoint quad_interior(Corner q[4], vec3 adj_from[4], vec3 adj_to[4], bool aen, uint s, uint t, uint surface,
                           float alpha) {
    float fs = fixed_weight(s), ft = fixed_weight(t);
    float gs = fixed_weight(FIXED_ONE - s), gt = fixed_weight(FIXED_ONE - t);
    float w[4] = float[4](gs * gt, fs * gt, fs * ft, gs * ft);
    vec3 flat_p = vec3(0.0), flat_n = vec3(0.0);
    vec2 uv = vec2(0.0);
    for (uint k = 0u; k < 4u; ++k) {
        flat_p = flat_p + w[k] * q[k].position;
        flat_n = flat_n + w[k] * q[k].normal;
        uv.x += w[k] * q[k].uv.x;
        uv.y += w[k] * q[k].uv.y;
    }
    SurfacePoint o;
    o.uv = uv;
    if (surface == SURFACE_PHONG) {
        vec3 ph = vec3(0.0);
        for (uint k = 0u; k < 4u; ++k) ph = ph + w[k] * phong_project(flat_p, q[k]);
        o.position = blend(flat_p, ph, alpha);
        o.normal = normalize_or_zero(flat_n);
        return o;
    }
    if (surface != SURFACE_PN && !aen) {
        o.position = without_negative_zero(flat_p);
        o.normal = without_negative_zero(normalize_or_zero(flat_n));
        o.uv = without_negative_zero(vec3(uv, 0.0)).xy;
        return o;
    }
    // The Bezier net b[i][j] (i along s, j along t) at b[4 * i + j].
    vec3 b[16];
    b[0] = q[0].position; b[12] = q[1].position; b[15] = q[2].position; b[3] = q[3].position;
    if (aen) {
        b[4] = aen_control(q[0].position, q[0].normal, adj_from[0], q[1].position);
        b[8] = aen_control(q[1].position, q[1].normal, adj_to[0], q[0].position);
        b[13] = aen_control(q[1].position, q[1].normal, adj_from[1], q[2].position);
        b[14] = aen_control(q[2].position, q[2].normal, adj_to[1], q[1].position);
        b[11] = aen_control(q[2].position, q[2].normal, adj_from[2], q[3].position);
        b[7] = aen_control(q[3].position, q[3].normal, adj_to[2], q[2].position);
        b[2] = aen_control(q[3].position, q[3].normal, adj_from[3], q[0].position);
        b[1] = aen_control(q[0].position, q[0].normal, adj_to[3], q[3].position);
    } else {
        b[4] = pn_control(q[0].position, q[0].normal, q[1].position);
        b[8] = pn_control(q[1].position, q[1].normal, q[0].position);
        b[13] = pn_control(q[1].position, q[1].normal, q[2].position);
        b[14] = pn_control(q[2].position, q[2].normal, q[1].position);
        b[11] = pn_control(q[2].position, q[2].normal, q[3].position);
        b[7] = pn_control(q[3].position, q[3].normal, q[2].position);
        b[2] = pn_control(q[3].position, q[3].normal, q[0].position);
        b[1] = pn_control(q[0].position, q[0].normal, q[3].position);
    }
    vec3 twist = (1.0 / 9.0) * ((q[0].position + q[2].position) - (q[1].position + q[3].position));
    b[5] = ((b[4] + b[1]) - q[0].position) + twist;
    b[9] = ((b[8] + b[13]) - q[1].position) - twist;
    b[10] = ((b[11] + b[14]) - q[2].position) + twist;
    b[6] = ((b[7] + b[2]) - q[3].position) - twist;
    float bs[4] = float[4](gs * gs * gs, 3.0 * gs * gs * fs, 3.0 * gs * fs * fs, fs * fs * fs);
    float bt[4] = float[4](gt * gt * gt, 3.0 * gt * gt * ft, 3.0 * gt * ft * ft, ft * ft * ft);
    vec3 pn = vec3(0.0);
    for (uint j = 0u; j < 4u; ++j) {
        vec3 row = vec3(0.0);
        for (uint i = 0u; i < 4u; ++i) row = row + bs[i] * b[4u * i + j];
        pn = pn + bt[j] * row;
    }
    vec3 m[4] = vec3[4](0.5 * pn_edge_normal(q[0], q[1]), 0.5 * pn_edge_normal(q[1], q[2]),
                        0.5 * pn_edge_normal(q[2], q[3]), 0.5 * pn_edge_normal(q[3], q[0]));
    // nq[i][j] at nq[3 * i + j]
    vec3 nq[9] = vec3[9](q[0].normal, m[3], q[3].normal, m[0], 0.25 * ((m[0] + m[1]) + (m[2] + m[3])), m[2],
                         q[1].normal, m[1], q[2].normal);
    float cs[3] = float[3](gs * gs, 2.0 * gs * fs, fs * fs);
    float ct[3] = float[3](gt * gt, 2.0 * gt * ft, ft * ft);
    vec3 nn = vec3(0.0);
    for (uint j = 0u; j < 3u; ++j) {
        vec3 row = vec3(0.0);
        for (uint i = 0u; i < 3u; ++i) row = row + cs[i] * nq[3u * i + j];
        nn = nn + ct[j] * row;
    }
    o.position = blend(flat_p, pn, alpha);
    if (aen) o.position = without_negative_zero(o.position);
    o.normal = normalize_or_zero(blend(flat_n, nn, alpha));
    return o;
}
// ---- uniform-density pattern (uniform_patch.hpp, uniform_pipeline_patch.hpp) ----
// uniform::round_factor (constexpr/ctess/uniform/factor.hpp, docs/algorithm.md §3.4) line for line, on the float's
// bits with integers only: NaN, negatives and anything below 1.5 give 1, +inf and from UNIFORM_MAX_FACTOR - 0.5
// on give UNIFORM_MAX_FACTOR, else the nearest integer, halves up (UNIFORM_ROUND_FROM_BITS = 1.5f and
// F32_INFINITY_BITS are generated from that function's checks).
uint round_factor(float f, uint max_factor) {
    uint bits = floatBitsToUint(f);
    if (bits < UNIFORM_ROUND_FROM_BITS || bits > F32_INFINITY_BITS) return 1u;
    uint exponent = (bits >> 23) - 127u; // f in [2^exponent, 2^(exponent + 1)), exponent >= 0
    if (exponent >= 23u) return max_factor;
    uint mantissa = (bits & 0x7FFFFFu) | 0x800000u; // f = mantissa * 2^(exponent - 23)
    uint shift = 23u - exponent;
    uint rounded = (mantissa + (1u << (shift - 1u))) >> shift; // halves up, exact
    return min(rounded, max_factor);
}
// The table's factor (Pattern::uniform), or the split's up to SPLIT_MAX_FACTOR (Pattern::uniform_split).
uint uniform_factor(float f) { return round_factor(f, split_pattern() ? SPLIT_MAX_FACTOR : UNIFORM_MAX_FACTOR); }
uint uniform_edge_parameter(uint i, uint f) {
    uint small_ = min(i, f - i);
    uint q = (2u * small_ * UNIFORM_ONE + f) / (2u * f);
    return i <= f - i ? q : UNIFORM_ONE - q;
}
uint uniform_pattern_index(uint f0, uint f1, uint f2) { return (f0 - 1u) * f0 * (f0 + 1u) / 6u + (f1 - 1u) * f1 / 2u + (f2 - 1u); }
// A 65534-unit weight in units of 2^-24: nearest, never a tie, so mirror-exact.
uint uniform_to_fixed(uint w) { return 256u * w + (512u * w + 32767u) / UNIFORM_ONE; }
// The uniform setup words from the integer factors of base edges E0, E1, E2 (UniformPatch's constructor).
// Returns the counts; words: pattern index, f0 | f1 << 8 | f2 << 16, corner sources | flip << 12.
uvec2 uniform_setup(uint f[3], out uvec3 words) {
    uint order[3] = uint[3](0u, 1u, 2u);
    uint tmp;
    if (f[order[1]] > f[order[0]]) { tmp = order[0]; order[0] = order[1]; order[1] = tmp; }
    if (f[order[2]] > f[order[1]]) { tmp = order[1]; order[1] = order[2]; order[2] = tmp; }
    if (f[order[1]] > f[order[0]]) { tmp = order[0]; order[0] = order[1]; order[1] = tmp; }
    uint s0 = f[order[0]], s1 = f[order[1]], s2 = f[order[2]];
    uint opposite[3] = uint[3](2u, 0u, 1u);
    uint target_[3] = uint[3](opposite[order[1]], opposite[order[2]], opposite[order[0]]);
    uint source[3];
    for (uint c = 0u; c < 3u; ++c) source[target_[c]] = c;
    bool flip = (target_[1] + 3u - target_[0]) % 3u != 1u;
    uint index = uniform_pattern_index(s0, s1, s2);
    uint first = tables[UNIFORM_OFFSET + index], next = tables[UNIFORM_OFFSET + index + 1u];
    words = uvec3(index, s0 | (s1 << 8) | (s2 << 16), source[0] | (source[1] << 4) | (source[2] << 8) | (flip ? 4096u : 0u));
    return uvec2(s0 + s1 + s2 + (next & 0xFFFFu) - (first & 0xFFFFu), (next >> 16) - (first >> 16));
}
// Vertex i as base weights (w1, w2), units of 2^-24.
// The uniform setup words of a record (pattern index, sorted factors, corner sources).
uvec3 uniform_words(uint rec) {
    return uvec3(patches[rec + SETUP + USETUP_PATTERN], patches[rec + SETUP + USETUP_SORTED], patches[rec + SETUP + USETUP_CORNERS]);
}
// Vertex i in the pattern's own weights (w1, w2), units of 65534 (UniformPatch::vertex).
uvec2 uniform_local(uvec3 words, uint i) {
    uint index = words.x, sorted = words.y, corners = words.z;
    uint f0 = sorted & 255u, f1 = (sorted >> 8) & 255u, f2 = sorted >> 16;
    uvec2 c;
    if (i < f0) c = uvec2(uniform_edge_parameter(i, f0), 0u);
    else if (i < f0 + f1) { uint v = uniform_edge_parameter(i - f0, f1); c = uvec2(UNIFORM_ONE - v, v); }
    else if (i < f0 + f1 + f2) c = uvec2(0u, uniform_edge_parameter(f2 - (i - f0 - f1), f2));
    else {
        uint word = tables[UNIFORM_INTERIOR + (tables[UNIFORM_OFFSET + index] & 0xFFFFu) + i - (f0 + f1 + f2)];
        c = uvec2(word & 0xFFFFu, word >> 16);
    }
    uint weight[3] = uint[3](UNIFORM_ONE - c.x - c.y, c.x, c.y);
    return uvec2(weight[(corners >> 4) & 3u], weight[(corners >> 8) & 3u]);
}
uvec2 uniform_vertex(uvec3 words, uint i) {
    uvec2 c = uniform_local(words, i);
    return uvec2(uniform_to_fixed(c.x), uniform_to_fixed(c.y));
}
uint uniform_index_byte(uint b) { return (tables[UNIFORM_TRIANGLE + (b >> 2)] >> ((b & 3u) * 8u)) & 255u; }
uvec3 uniform_triangle(uvec3 words, uint p) {
    uint b = 3u * ((tables[UNIFORM_OFFSET + words.x] >> 16) + p);
    uvec3 t = uvec3(uniform_index_byte(b), uniform_index_byte(b + 1u), uniform_index_byte(b + 2u));
    return (words.z & 4096u) != 0u ? t.xzy : t;
}

// ---- uniform splitting (Pattern::uniform_split; docs/shaders.md, "Splitting"; docs/algorithm.md §3.5) ----
// UniformSplit's decisions on the exact squared factors of constexpr/ctess/uniform/split_factor.hpp, in 32-bit
// words: a square s = f^2 2^32 as uvec2 (lo, hi), a product below 2^96 as uvec3 (low word first).
bool less64(uvec2 a, uvec2 b) { return a.y != b.y ? a.y < b.y : a.x < b.x; }
uvec3 add96(uvec3 a, uvec3 b) {
    uint x = a.x + b.x;
    uint y = a.y + b.y;
    uint carry = y < a.y ? 1u : 0u;
    uint y1 = y + (x < a.x ? 1u : 0u);
    carry += y1 < y ? 1u : 0u;
    return uvec3(x, y1, a.z + b.z + carry);
}
bool less96(uvec3 a, uvec3 b) { return a.z != b.z ? a.z < b.z : a.y != b.y ? a.y < b.y : a.x < b.x; }
uvec3 sub96(uvec3 a, uvec3 b) { // a >= b
    uint x = a.x - b.x;
    uint y = a.y - b.y;
    uint borrow = a.y < b.y ? 1u : 0u;
    uint y1 = y - (a.x < b.x ? 1u : 0u);
    borrow += y < y1 ? 1u : 0u;
    return uvec3(x, y1, a.z - b.z - borrow);
}
uvec3 mul96(uvec2 s, uint c) { // s c, s < 2^64
    uvec2 lo = mul_wide(s.x, c), hi = mul_wide(s.y, c);
    uint mid = lo.y + hi.x;
    return uvec3(lo.x, mid, hi.y + (mid < lo.y ? 1u : 0u));
}
// floor(x / 65534) in 16-bit digits from the top: every step's dividend is below 65534 x 2^16 + 2^16 < 2^32.
uint div_digit(inout uint r, uint digit) {
    uint n = (r << 16) | digit;
    uint q = n / UNIFORM_ONE;
    r = n - q * UNIFORM_ONE;
    return q;
}
uvec3 div96_unit(uvec3 x) {
    uint r = 0u;
    uint zh = div_digit(r, x.z >> 16), zl = div_digit(r, x.z & 0xFFFFu);
    uint yh = div_digit(r, x.y >> 16), yl = div_digit(r, x.y & 0xFFFFu);
    uint xh = div_digit(r, x.x >> 16), xl = div_digit(r, x.x & 0xFFFFu);
    return uvec3((xh << 16) | xl, (yh << 16) | yl, (zh << 16) | zl);
}
// segment_squared_factor: floor(max(0, q) / 65534^2), q = -s2 dv dw - s0 dw du - s1 du dv, dw = -du - dv.
uvec2 segment_squared(uvec2 s[3], int du, int dv) {
    int dw = -du - dv;
    int a[3] = int[3](dw, du, dv), b[3] = int[3](du, dv, dw); // coefficient k is -a[k] b[k]
    uvec3 positive = uvec3(0u), negative = uvec3(0u);
    for (uint k = 0u; k < 3u; ++k) {
        uint magnitude = uint(abs(a[k])) * uint(abs(b[k])); // at most 65534^2 < 2^32
        uvec3 term = mul96(s[k], magnitude);
        if ((a[k] < 0) == (b[k] < 0)) negative = add96(negative, term);
        else positive = add96(positive, term);
    }
    if (!less96(negative, positive)) return uvec2(0u);
    return div96_unit(div96_unit(sub96(positive, negative))).xy; // below 2^64
}
// floor(2f): the largest m with m^2 2^30 <= s (at most 65536), from a float guess corrected exactly.
bool twice_fits(uvec2 s, uint m) {
    uvec2 square = mul_wide(m, m);
    return !less64(s, uvec2(square.x << 30, (square.y << 30) | (square.x >> 2)));
}
uint floor_twice_factor(uvec2 s) {
    float guess = sqrt(float(s.y) * 4294967296.0 + float(s.x)) * (1.0 / 32768.0);
    uint m = guess >= 65536.0 ? 65536u : uint(max(guess, 0.0));
    while (m > 0u && !twice_fits(s, m)) --m;
    while (m < 65536u && twice_fits(s, m + 1u)) ++m;
    return m;
}
uint rounded_split_factor(uvec2 s) { return (floor_twice_factor(s) + 1u) / 2u; }
// (2k - 1)^2 2^30: f rounds to k or more from this square on.
uvec2 half_below_squared(uint k) {
    uint v = (2u * k - 1u) * (2u * k - 1u);
    return uvec2(v << 30, v >> 2);
}
// A leaf's factor: rounded, clamped to [1, UNIFORM_MAX_FACTOR], by a binary search of the squares.
uint leaf_factor(uvec2 s) {
    uint low = 1u, high = UNIFORM_MAX_FACTOR;
    while (low < high) {
        uint mid = (low + high + 1u) / 2u;
        if (less64(s, half_below_squared(mid))) high = mid - 1u;
        else low = mid;
    }
    return low;
}
// A split node's pieces of an edge (UniformSplit edge_pieces): whole within the dice limit (f < N + 1/2 at
// depth 0 and on the root's boundary, else below the interior limit), else ceil(round(f) / N) clamped to [1, N].
uint edge_pieces(uvec2 s, uint depth, bool boundary) {
    uint n = UNIFORM_MAX_FACTOR;
    bool whole = depth == 0u || boundary ? less64(s, half_below_squared(n + 1u))
                                         : less64(s, uvec2(SPLIT_INTERIOR_LIMIT_LO, SPLIT_INTERIOR_LIMIT_HI));
    if (whole) return 1u;
    return clamp((rounded_split_factor(s) + n - 1u) / n, 1u, n);
}
// uniform_split_depth_limit(N, largest root factor): one level more than its edges need, in [2, bound].
uint split_depth_limit(uint largest) {
    uint reach = UNIFORM_MAX_FACTOR, levels = 0u;
    for (; reach < largest; ++levels) reach *= UNIFORM_MAX_FACTOR;
    return max(min(levels + 1u, SPLIT_DEPTH_BOUND), 2u);
}

// A node of the split area (rt::gpu::split_node_word): corners on the root in units of SPLIT_FIXED_ONE.
struct SplitNode {
    uint patch_, info;
    uvec2 corner[3];
    uvec2 squared[3];
};
uint split_area() { return patch_count() * PATCH_WORDS + TOTALS_WORDS; }
uint split_header(uint w) { return split_area() + w; }
// Node i of the region of `level` (the levels alternate between two regions of PARAM_SPLIT_CAPACITY nodes).
uint split_node(uint level, uint i) {
    return split_area() + SPLIT_HEADER_WORDS + ((level & 1u) * params[PARAM_SPLIT_CAPACITY] + i) * NODE_WORDS;
}
SplitNode load_node(uint n) {
    SplitNode s;
    s.patch_ = patches[n + NODE_PATCH];
    s.info = patches[n + NODE_INFO];
    for (uint k = 0u; k < 3u; ++k) {
        s.corner[k] = uvec2(patches[n + NODE_CORNER + 2u * k], patches[n + NODE_CORNER + 2u * k + 1u]);
        s.squared[k] = uvec2(patches[n + NODE_SQUARED + 2u * k], patches[n + NODE_SQUARED + 2u * k + 1u]);
    }
    return s;
}
void store_node(uint n, SplitNode s) {
    patches[n + NODE_PATCH] = s.patch_;
    patches[n + NODE_INFO] = s.info;
    for (uint k = 0u; k < 3u; ++k) {
        patches[n + NODE_CORNER + 2u * k] = s.corner[k].x;
        patches[n + NODE_CORNER + 2u * k + 1u] = s.corner[k].y;
        patches[n + NODE_SQUARED + 2u * k] = s.squared[k].x;
        patches[n + NODE_SQUARED + 2u * k + 1u] = s.squared[k].y;
    }
}
// The root edges a point lies on: bit 0 e0 (v = 0), bit 1 e1 (u + v = 65534^2), bit 2 e2 (u = 0).
uint root_edges_of(uvec2 p) {
    return (p.y == 0u ? 1u : 0u) | (p.x + p.y == SPLIT_FIXED_ONE ? 2u : 0u) | (p.x == 0u ? 4u : 0u);
}
bool split_edge_on_boundary(SplitNode s, uint e) {
    uint a = e == 2u ? 0u : e, b = e == 0u ? 1u : 2u;
    return (root_edges_of(s.corner[a]) & root_edges_of(s.corner[b])) != 0u;
}
// The point of node s at local (u, v) (units of 65534) on the root: the exact sum over the corners divided by
// 65534, rounded half up, ties on a root edge to even (UniformSplit map and map32: each corner is 65534 a + b,
// so the sum is 65534 (w a0 + u a1 + v a2) + (w b0 + u b1 + v b2), both parts below 2^32).
uvec2 split_map(SplitNode s, uvec2 d) {
    uint w = UNIFORM_ONE - d.x - d.y;
    uint edges = (w == 0u ? 7u : root_edges_of(s.corner[0])) & (d.x == 0u ? 7u : root_edges_of(s.corner[1])) &
                 (d.y == 0u ? 7u : root_edges_of(s.corner[2]));
    uvec2 r;
    for (uint k = 0u; k < 2u; ++k) {
        uint c0 = s.corner[0][k], c1 = s.corner[1][k], c2 = s.corner[2][k];
        uint a0 = c0 / UNIFORM_ONE, a1 = c1 / UNIFORM_ONE, a2 = c2 / UNIFORM_ONE;
        uint q = w * a0 + d.x * a1 + d.y * a2;
        uint b = w * (c0 - a0 * UNIFORM_ONE) + d.x * (c1 - a1 * UNIFORM_ONE) + d.y * (c2 - a2 * UNIFORM_ONE);
        q += b / UNIFORM_ONE;
        uint rest = b % UNIFORM_ONE, half_ = UNIFORM_ONE / 2u;
        r[k] = q + (rest > half_ || (rest == half_ && (edges == 0u || (q & 1u) != 0u)) ? 1u : 0u);
    }
    return r;
}
// to_base_weights: a root coordinate to 2^-24 units, (c 2^24 + 65534^2 / 2) / 65534^2 (no ties).
uint split_base_weight(uint c) {
    uint x = min(c, SPLIT_FIXED_ONE);
    uvec2 n = add_wide(uvec2(x << 24, x >> 8), SPLIT_FIXED_ONE / 2u);
    return div96_unit(div96_unit(uvec3(n, 0u))).x;
}
int pattern_corner(uvec2 p) {
    return p == uvec2(0u) ? 0 : p == uvec2(UNIFORM_ONE, 0u) ? 1 : p == uvec2(0u, UNIFORM_ONE) ? 2 : -1;
}
// A child edge from a to b (pattern points of s): a whole edge of s keeps its square, any other is measured in
// s's metric (UniformSplit child_edge_factor).
uvec2 child_squared(SplitNode s, uvec2 a, uvec2 b) {
    int ca = pattern_corner(a), cb = pattern_corner(b);
    if (ca >= 0 && cb >= 0 && ca != cb) {
        int lo = min(ca, cb), hi = max(ca, cb);
        return s.squared[lo == 0 && hi == 1 ? 0 : lo == 1 && hi == 2 ? 1 : 2];
    }
    return segment_squared(s.squared, int(b.x) - int(a.x), int(b.y) - int(a.y));
}
// The indirect dispatch of a pass over n items: SPLIT_GROUP invocations a workgroup, at most
// MAX_DISPATCH_WORKGROUPS (the passes stride over the rest).
void split_dispatch(uint n) {
    patches[split_header(SPLIT_DISPATCH)] = max(1u, min((n + SPLIT_GROUP - 1u) / SPLIT_GROUP, MAX_DISPATCH_WORKGROUPS));
    patches[split_header(SPLIT_DISPATCH + 1u)] = 1u;
    patches[split_header(SPLIT_DISPATCH + 2u)] = 1u;
}
uint split_stride() { return gl_NumWorkGroups.x * gl_WorkGroupSize.x; }

// Pass: the roots of level 0, one per base triangle, two per quad (halves A and B), in patch order, from the
// records' rounded factors (a culled patch's are 0: a culled root).
void ctess_split_roots() {
    uint triangles = triangle_count(), roots = triangles + 2u * params[PARAM_QUAD_COUNT];
    uint capacity = params[PARAM_SPLIT_CAPACITY];
    if (gl_GlobalInvocationID.x == 0u) {
        patches[split_header(SPLIT_LEVEL)] = 0u;
        patches[split_header(SPLIT_NODES)] = min(roots, capacity);
        patches[split_header(SPLIT_PARENTS)] = 0u;
        patches[split_header(SPLIT_NEEDED)] = roots;
        patches[split_header(SPLIT_OVERFLOW)] = roots > capacity ? 1u : 0u;
        split_dispatch(min(roots, capacity));
    }
    for (uint r = gl_GlobalInvocationID.x; r < min(roots, capacity); r += split_stride()) {
        uint t = r < triangles ? r : triangles + (r - triangles) / 2u;
        uint half_ = r < triangles ? 0u : (r - triangles) & 1u;
        uint rec = t * PATCH_WORDS;
        SplitNode s;
        s.patch_ = t;
        uint largest = 0u;
        for (uint k = 0u; k < 3u; ++k) {
            uint f = patches[rec + (half_ == 0u ? REC_TOKEN : SETUP + QSETUP_B_TOKEN) + k];
            s.squared[k] = uvec2(0u, f * f); // f^2 2^32
            largest = max(largest, f);
        }
        s.info = (split_depth_limit(largest) << NODE_LIMIT_SHIFT) | (half_ << NODE_HALF_SHIFT) | (largest == 0u ? NODE_CULLED : 0u);
        s.corner[0] = uvec2(0u);
        s.corner[1] = uvec2(SPLIT_FIXED_ONE, 0u);
        s.corner[2] = uvec2(0u, SPLIT_FIXED_ONE);
        store_node(split_node(0u, r), s);
    }
}

// Pass: decides every node of the current level. A leaf (every edge whole, or the depth limit): its pattern
// from its factors rounded to [1, N], its counts, one child (itself). A split node: the pattern of its pieces,
// whose triangles are its children.
void ctess_split_count() {
    uint level = patches[split_header(SPLIT_LEVEL)], nodes = patches[split_header(SPLIT_NODES)];
    for (uint i = gl_GlobalInvocationID.x; i < nodes; i += split_stride()) {
        uint n = split_node(level, i);
        SplitNode s = load_node(n);
        uvec2 counts = uvec2(0u);
        uvec3 words = uvec3(0u);
        uint children = 0u;
        if ((s.info & NODE_CULLED) == 0u) {
            uint depth = s.info & NODE_DEPTH_MASK;
            uint pieces[3] = uint[3](1u, 1u, 1u);
            if (depth < ((s.info >> NODE_LIMIT_SHIFT) & NODE_DEPTH_MASK))
                for (uint e = 0u; e < 3u; ++e) pieces[e] = edge_pieces(s.squared[e], depth, split_edge_on_boundary(s, e));
            if (pieces[0] == 1u && pieces[1] == 1u && pieces[2] == 1u) {
                uint r[3] = uint[3](leaf_factor(s.squared[0]), leaf_factor(s.squared[1]), leaf_factor(s.squared[2]));
                counts = uniform_setup(r, words);
                children = 1u;
                patches[n + NODE_INFO] = s.info | NODE_LEAF;
            } else {
                children = uniform_setup(pieces, words).y;
            }
        }
        patches[n + NODE_CHILDREN] = children;
        patches[n + NODE_PATTERN] = words.x;
        patches[n + NODE_PATTERN + 1u] = words.y;
        patches[n + NODE_PATTERN + 2u] = words.z;
        patches[n + NODE_VERTICES] = counts.x;
        patches[n + NODE_TRIANGLES] = counts.y;
    }
}

// Pass, one workgroup of SCAN_GROUP: exclusive prefix sums of the level's children and counts (the children's
// slots in the next level, a leaf's first vertex and triangle), then the header moves to the next level: its
// nodes are the children, at most PARAM_SPLIT_CAPACITY (beyond it SPLIT_OVERFLOW and no node).
shared uvec3 split_sum[SCAN_GROUP];
shared uint split_wrapped;
void ctess_split_scan() {
    uint level = patches[split_header(SPLIT_LEVEL)], n = patches[split_header(SPLIT_NODES)];
    uint lane = gl_LocalInvocationID.x;
    if (lane == 0u) split_wrapped = 0u;
    uint per = (n + (SCAN_GROUP - 1u)) / SCAN_GROUP;
    uint begin = min(n, lane * per), end = min(n, begin + per);
    uvec3 sum = uvec3(0u);
    bool wrapped = false; // the children's count past 32 bits: an overflow, never a wrapped level
    for (uint i = begin; i < end; ++i) {
        uint node = split_node(level, i);
        uint children = patches[node + NODE_CHILDREN];
        wrapped = wrapped || sum.x + children < sum.x;
        sum += uvec3(children, patches[node + NODE_VERTICES], patches[node + NODE_TRIANGLES]);
    }
    split_sum[lane] = sum;
    barrier();
    for (uint d = 1u; d < SCAN_GROUP; d <<= 1) {
        uvec3 add = lane >= d ? split_sum[lane - d] : uvec3(0u);
        barrier();
        wrapped = wrapped || split_sum[lane].x + add.x < add.x;
        split_sum[lane] += add;
        barrier();
    }
    if (wrapped) atomicOr(split_wrapped, 1u);
    uvec3 base = split_sum[lane] - sum;
    for (uint i = begin; i < end; ++i) {
        uint node = split_node(level, i);
        patches[node + NODE_FIRST_CHILD] = base.x;
        patches[node + NODE_FIRST_VERTEX] = base.y;
        patches[node + NODE_FIRST_TRIANGLE] = base.z;
        base += uvec3(patches[node + NODE_CHILDREN], patches[node + NODE_VERTICES], patches[node + NODE_TRIANGLES]);
    }
    // Every lane has read the header and written its nodes before the header moves on.
    memoryBarrierBuffer();
    barrier();
    if (lane == SCAN_GROUP - 1u) {
        uint children = split_wrapped != 0u ? 0xFFFFFFFFu : split_sum[SCAN_GROUP - 1u].x;
        uint capacity = params[PARAM_SPLIT_CAPACITY];
        bool over = children > capacity || patches[split_header(SPLIT_OVERFLOW)] != 0u;
        patches[split_header(SPLIT_NEEDED)] = max(patches[split_header(SPLIT_NEEDED)], children);
        patches[split_header(SPLIT_OVERFLOW)] = over ? 1u : 0u;
        patches[split_header(SPLIT_LEVEL)] = level + 1u;
        patches[split_header(SPLIT_PARENTS)] = n;
        patches[split_header(SPLIT_NODES)] = over ? 0u : children;
        split_dispatch(over ? 0u : children);
    }
}

// Pass: child slot j of the next level from its parent (the last node whose first child is at most j): a leaf
// is copied, a split node's child k is its split pattern's triangle k, its corners mapped on the root and its
// edges' squares from the parent's (UniformSplit child).
void ctess_split_expand() {
    uint level = patches[split_header(SPLIT_LEVEL)], nodes = patches[split_header(SPLIT_NODES)];
    uint parents = patches[split_header(SPLIT_PARENTS)];
    for (uint j = gl_GlobalInvocationID.x; j < nodes; j += split_stride()) {
        uint low = 0u, high = parents - 1u;
        while (low < high) {
            uint mid = (low + high + 1u) / 2u;
            if (patches[split_node(level - 1u, mid) + NODE_FIRST_CHILD] <= j) low = mid;
            else high = mid - 1u;
        }
        uint p = split_node(level - 1u, low);
        SplitNode s = load_node(p);
        SplitNode c = s;
        c.info = s.info & ~NODE_LEAF;
        if ((s.info & NODE_LEAF) == 0u) {
            uvec3 words = uvec3(patches[p + NODE_PATTERN], patches[p + NODE_PATTERN + 1u], patches[p + NODE_PATTERN + 2u]);
            uvec3 tri = uniform_triangle(words, j - patches[p + NODE_FIRST_CHILD]);
            uvec2 a = uniform_local(words, tri.x), b = uniform_local(words, tri.y), d = uniform_local(words, tri.z);
            c.info = (s.info & ~(NODE_LEAF | NODE_DEPTH_MASK)) | ((s.info & NODE_DEPTH_MASK) + 1u);
            c.corner[0] = split_map(s, a);
            c.corner[1] = split_map(s, b);
            c.corner[2] = split_map(s, d);
            c.squared[0] = child_squared(s, a, b);
            c.squared[1] = child_squared(s, b, d);
            c.squared[2] = child_squared(s, a, d);
        }
        store_node(split_node(level, j), c);
    }
}

// The leaves after the last scan: the region of the level before the header's, as many as its parents.
uint split_leaves() { return patches[split_header(SPLIT_PARENTS)]; }
uint split_leaf(uint i) { return split_node(patches[split_header(SPLIT_LEVEL)] - 1u, i); }
// The first leaf of a patch t or after it (the leaves lie in patch order): the emit passes' range of leaves.
uint split_first_leaf(uint t) {
    uint low = 0u, high = split_leaves();
    while (low < high) {
        uint mid = (low + high) / 2u;
        if (patches[split_leaf(mid) + NODE_PATCH] < t) low = mid + 1u;
        else high = mid;
    }
    return low;
}
// The leaves of the patches in [first, end): no search at the ends of the mesh.
uint split_range_start(uint first) { return first == 0u ? 0u : split_first_leaf(first); }
uint split_range_end(uint end) { return end >= patch_count() ? split_leaves() : split_first_leaf(end); }

// Pass: each patch's counts from its leaves (they lie together, in patch order): the last leaf of a patch
// writes the record's counts, from the first one's prefix sums to its own end.
void ctess_split_records() {
    uint leaves = split_leaves();
    for (uint i = gl_GlobalInvocationID.x; i < leaves; i += split_stride()) {
        uint n = split_leaf(i), t = patches[n + NODE_PATCH];
        if (i + 1u < leaves && patches[split_leaf(i + 1u) + NODE_PATCH] == t) continue;
        uint low = 0u, high = i;
        while (low < high) {
            uint mid = (low + high) / 2u;
            if (patches[split_leaf(mid) + NODE_PATCH] < t) low = mid + 1u;
            else high = mid;
        }
        uint f = split_leaf(low), rec = t * PATCH_WORDS;
        patches[rec + REC_VERTEX_COUNT] = patches[n + NODE_FIRST_VERTEX] + patches[n + NODE_VERTICES] - patches[f + NODE_FIRST_VERTEX];
        patches[rec + REC_TRIANGLE_COUNT] = patches[n + NODE_FIRST_TRIANGLE] + patches[n + NODE_TRIANGLES] - patches[f + NODE_FIRST_TRIANGLE];
    }
}
// A leaf's vertex i as the pipeline's base weights (2^-24): its pattern's point mapped on the root, then
// to_base_weights.
uvec2 split_vertex(SplitNode s, uvec3 words, uint i) {
    uvec2 p = split_map(s, uniform_local(words, i));
    return uvec2(split_base_weight(p.x), split_base_weight(p.y));
}
// An emit pass's work items over the patches [first_patch, end): those patches, or the split pattern's leaves
// of them. item_patch: an item's patch, and its leaf node (0 for a patch).
uvec2 emit_items(bool split_, uint first_patch, uint end) {
    return split_ ? uvec2(split_range_start(first_patch), split_range_end(end)) : uvec2(first_patch, end);
}
uint item_patch(bool split_, uint item, out uint leaf) {
    leaf = split_ ? split_leaf(item) : 0u;
    return split_ ? patches[leaf + NODE_PATCH] : item;
}

// ---- patch records (PatchRecord) ----
uint smallest_edge_rotation(float l[3]) {
    uint smallest = 0u;
    for (uint k = 1u; k < 3u; ++k) {
        bool nan_k = (floatBitsToUint(l[k]) & 0x7FFFFFFFu) > 0x7F800000u;
        bool nan_s = (floatBitsToUint(l[smallest]) & 0x7FFFFFFFu) > 0x7F800000u;
        if (nan_k) continue;
        if (nan_s || l[k] < l[smallest]) smallest = k;
    }
    return (smallest + 1u) % 3u;
}
// The setup block (rt::setup_word's word order, runtime/include/ctess/runtime/cp/setup_block.hpp): written once by the setup pass, read by every emit
// invocation instead of redoing patch_setup.
void store_setup_block(uint rec, Patch p) {
    uint b = rec + SETUP;
    patches[b + SETUP_FLAGS] = p.type_ | (p.c0 ? 4u : 0u) | (p.c1 ? 8u : 0u) | (p.c2 ? 16u : 0u) | (p.copies ? 32u : 0u) |
                 (p.tri_skips << 8) | (p.slot_skips << 12);
    for (uint k = 0u; k < 3u; ++k) {
        patches[b + SETUP_TOKEN_REC + k] = p.e[k].points | (p.e[k].segments << 16);
        patches[b + SETUP_HALF_STEP + k] = p.e[k].half_step;
    }
    patches[b + SETUP_COLUMN] = p.column;
    patches[b + SETUP_GAP] = p.type_ == 2u ? p.gap - GAP_WORD : 0u;
    patches[b + SETUP_CLAMP] = p.clamp_;
    patches[b + SETUP_STRIPS] = p.strips;
    patches[b + SETUP_E1_OFFSET] = p.e1_offset;
    patches[b + SETUP_UNIQUE] = p.unique_;
    patches[b + SETUP_COPY_BIAS] = p.copy_bias;
    for (uint k = 0u; k < SETUP_SLOT_SKIPS; ++k) patches[b + SETUP_SLOT_SKIP + k] = p.slot_skip[k].x | (p.slot_skip[k].y << 16);
    for (uint k = 0u; k < 8u; ++k) {
        patches[b + SETUP_TRI_SKIP + 2u * k] = p.tri_skip[k].x;
        patches[b + (SETUP_TRI_SKIP + 1u) + 2u * k] = p.tri_skip[k].y;
    }
}
Patch record_patch(uint rec) {
    Patch p = patch_zero();
    uint b = rec + SETUP;
    uint flags = patches[b + SETUP_FLAGS];
    for (uint k = 0u; k < 3u; ++k) {
        uint tr = patches[b + SETUP_TOKEN_REC + k];
        p.e[k].points = tr & 0xFFFFu;
        p.e[k].segments = tr >> 16;
        p.e[k].half_step = patches[b + SETUP_HALF_STEP + k];
        p.e[k].t16 = patches[rec + REC_TOKEN + k] == 0u ? 0u : patches[rec + REC_T16 + k];
    }
    p.type_ = flags & 3u;
    p.c0 = (flags & 4u) != 0u;
    p.c1 = (flags & 8u) != 0u;
    p.c2 = (flags & 16u) != 0u;
    p.copies = (flags & 32u) != 0u;
    p.tri_skips = (flags >> 8) & 15u;
    p.slot_skips = (flags >> 12) & 15u;
    p.n0 = p.e[0].segments;
    p.n1 = p.e[1].segments;
    p.n2 = p.e[2].segments;
    p.vertices = patches[rec + REC_VERTEX_COUNT];
    p.triangles = patches[rec + REC_TRIANGLE_COUNT];
    if (p.type_ == 2u) {
        p.column = patches[b + SETUP_COLUMN];
        load_column_record(p);
        p.gap = GAP_WORD + patches[b + SETUP_GAP];
        p.clamp_ = patches[b + SETUP_CLAMP];
        p.strips = patches[b + SETUP_STRIPS];
        p.zipper = p.n0 + p.n1 - 1u;
        p.e1_offset = patches[b + SETUP_E1_OFFSET];
        p.unique_ = patches[b + SETUP_UNIQUE];
        p.copy_bias = patches[b + SETUP_COPY_BIAS];
    }
    for (uint k = 0u; k < p.slot_skips; ++k) {
        uint w = patches[b + SETUP_SLOT_SKIP + k];
        p.slot_skip[k] = uvec2(w & 0xFFFFu, w >> 16);
    }
    for (uint k = 0u; k < p.tri_skips; ++k) p.tri_skip[k] = uvec2(patches[b + SETUP_TRI_SKIP + 2u * k], patches[b + (SETUP_TRI_SKIP + 1u) + 2u * k]);
    return p;
}

// ---- quads (docs/algorithm.md §7.2, §7.3): two triangle halves along a diagonal ----
vec3 mesh_eye() {
    return vec3(uintBitsToFloat(params[PARAM_EYE]), uintBitsToFloat(params[PARAM_EYE + 1u]), uintBitsToFloat(params[PARAM_EYE + 2u]));
}
// The factor and squared length of mesh edge (i, j), endpoints in mesh-index order (both faces get the same bits).
float mesh_edge_factor(uint i, uint j) {
    vec3 a = mesh_position(min(i, j)), b = mesh_position(max(i, j));
    return displaced_edge_factor(edge_tess_factor(a, b, mesh_eye(), uintBitsToFloat(params[PARAM_FACTOR_SCALE])), a, b);
}
float mesh_edge_length2(uint i, uint j) {
    precise vec3 d = mesh_position(max(i, j)) - mesh_position(min(i, j));
    return dot3(d, d);
}
// The quad rule: CP makes q0q1 the longer edge of the opposite pair with the larger summed length (the diagonal
// takes its factor); uniform density splits along the shorter diagonal. Ties and NaN keep the labelled order.
uint cp_quad_rotation(float length2[4]) {
    if (params[PARAM_QUAD_RULE] == QUAD_RULE_AS_LABELLED) return 0u;
    float len[4];
    for (uint k = 0u; k < 4u; ++k) len[k] = sqrt(length2[k]);
    uint first = len[1] + len[3] > len[0] + len[2] ? 1u : 0u;
    return len[first + 2u] > len[first] ? first + 2u : first;
}
uint uniform_quad_rotation(uint w[4]) {
    if (params[PARAM_QUAD_RULE] == QUAD_RULE_AS_LABELLED) return 0u;
    return mesh_edge_length2(w[0], w[2]) < mesh_edge_length2(w[1], w[3]) ? 1u : 0u;
}
uvec2 saturating_add(uvec2 a, uvec2 b) {
    uvec2 sum = a + b;
    return uvec2(sum.x < a.x ? 0xFFFFFFFFu : sum.x, sum.y < a.y ? 0xFFFFFFFFu : sum.y);
}
// A quad's record (rt::PatchRecord with kind PATCH_KIND_QUAD): rotation = the quad rule's, half A = (q0, q1, q3)'s
// line states (or uniform factors) as tokens, half B = (q2, q3, q1)'s in the setup words, the counts of both
// halves together, factors Q0..Q2 and Q3's bits in the setup words. No CP setup block: the emit passes set up
// each half themselves.
void setup_one_quad(uint t) {
    uint rec = t * PATCH_WORDS;
    patches[rec + REC_KIND] = PATCH_KIND_QUAD;
    uint w[4];
    if (!base_quad(t - triangle_count(), w)) return;
    float f[4], length2[4];
    for (uint k = 0u; k < 4u; ++k) {
        f[k] = mesh_edge_factor(w[k], w[(k + 1u) % 4u]);
        length2[k] = mesh_edge_length2(w[k], w[(k + 1u) % 4u]);
    }
    for (uint k = 0u; k < 3u; ++k) patches[rec + REC_FACTOR + k] = floatBitsToUint(f[k]);
    patches[rec + SETUP + QSETUP_Q3_FACTOR] = floatBitsToUint(f[3]);
    bool uniform_ = uniform_pattern() || split_pattern();
    uint r;
    float diagonal;
    if (uniform_) {
        r = uniform_quad_rotation(w);
        diagonal = mesh_edge_factor(w[(1u + r) % 4u], w[(3u + r) % 4u]);
    } else {
        r = cp_quad_rotation(length2);
        diagonal = f[r];
    }
    patches[rec + REC_ROTATION] = r;
    float fa[3] = float[3](f[r], diagonal, f[(r + 3u) % 4u]);
    float fb[3] = float[3](f[(r + 2u) % 4u], diagonal, f[(r + 1u) % 4u]);
    uvec2 counts;
    if (uniform_) {
        uint ia[3], ib[3];
        for (uint k = 0u; k < 3u; ++k) {
            ia[k] = uniform_factor(fa[k]);
            ib[k] = uniform_factor(fb[k]);
            patches[rec + REC_TOKEN + k] = ia[k];
            patches[rec + SETUP + QSETUP_B_TOKEN + k] = ib[k];
        }
        uvec3 words;
        // A split quad's counts come from its halves' leaves (ctess_split_records).
        counts = split_pattern() ? uvec2(0u) : saturating_add(uniform_setup(ia, words), uniform_setup(ib, words));
    } else {
        // One loop over the halves: one copy of patch_setup in the compiled pass, not two.
        counts = uvec2(0u);
        for (uint side = 0u; side < 2u; ++side) {
            uvec2 st[3];
            for (uint k = 0u; k < 3u; ++k) {
                st[k] = line_state(side == 0u ? fa[k] : fb[k]);
                patches[rec + (side == 0u ? REC_TOKEN : SETUP + QSETUP_B_TOKEN) + k] = st[k].x;
                patches[rec + (side == 0u ? REC_T16 : SETUP + QSETUP_B_T16) + k] = st[k].y;
            }
            Patch half_patch = patch_setup(st[0], st[1], st[2]);
            counts = saturating_add(counts, uvec2(half_patch.vertices, half_patch.triangles));
        }
    }
    patches[rec + REC_VERTEX_COUNT] = counts.x;
    patches[rec + REC_TRIANGLE_COUNT] = counts.y;
}
// The line states of quad half h (A = 0 from the tokens, B = 1 from the setup words).
uvec2 quad_half_state(uint rec, uint h, uint k) {
    if (h == 0u) return uvec2(patches[rec + REC_TOKEN + k], patches[rec + REC_T16 + k]);
    return uvec2(patches[rec + SETUP + QSETUP_B_TOKEN + k], patches[rec + SETUP + QSETUP_B_T16 + k]);
}
// Both halves of a quad record, as the emit passes need them: the CP patches (CP) or the uniform setup words of
// half A (index 0) and B (1); returns half A's vertex and triangle counts.
uvec2 quad_halves(uint rec, out Patch halves[2], out uvec3 words[2]) {
    uvec2 counts_a;
    for (uint side = 0u; side < 2u; ++side) { // one copy of patch_setup in the compiled pass
        uvec2 s0 = quad_half_state(rec, side, 0u), s1 = quad_half_state(rec, side, 1u), s2 = quad_half_state(rec, side, 2u);
        uvec2 counts;
        if (uniform_pattern()) {
            uint f[3] = uint[3](s0.x, s1.x, s2.x);
            counts = uniform_setup(f, words[side]);
            halves[side] = patch_zero();
        } else {
            halves[side] = patch_setup(s0, s1, s2);
            counts = uvec2(halves[side].vertices, halves[side].triangles);
            words[side] = uvec3(0u);
        }
        if (side == 0u) counts_a = counts;
    }
    return counts_a;
}
void store_vertex(uint o, uint u, uint v, SurfacePoint sp) {
    out_vertices[o + VERTEX_U] = u;
    out_vertices[o + VERTEX_V] = v;
    out_vertices[o + VERTEX_POSITION] = floatBitsToUint(sp.position.x);
    out_vertices[o + (VERTEX_POSITION + 1u)] = floatBitsToUint(sp.position.y);
    out_vertices[o + (VERTEX_POSITION + 2u)] = floatBitsToUint(sp.position.z);
    out_vertices[o + VERTEX_NORMAL] = floatBitsToUint(sp.normal.x);
    out_vertices[o + (VERTEX_NORMAL + 1u)] = floatBitsToUint(sp.normal.y);
    out_vertices[o + (VERTEX_NORMAL + 2u)] = floatBitsToUint(sp.normal.z);
    out_vertices[o + VERTEX_UV] = floatBitsToUint(sp.uv.x);
    out_vertices[o + (VERTEX_UV + 1u)] = floatBitsToUint(sp.uv.y);
}
// Pass 1, one invocation per patch: factors, rotation, line states, counts and the setup block (quads: setup_one_quad).
void setup_one_patch(uint t) {
    uint rec = t * PATCH_WORDS;
    for (uint k = 0u; k < PATCH_WORDS; ++k) patches[rec + k] = 0u;
    if (t >= triangle_count()) {
        setup_one_quad(t);
        return;
    }
    uvec3 w;
    if (!base_triangle(t, w)) return;
    uint wv[3] = uint[3](w.x, w.y, w.z);
    float scale = uintBitsToFloat(params[PARAM_FACTOR_SCALE]);
    vec3 eye = mesh_eye();
    float factor[3], length2[3];
    for (uint k = 0u; k < 3u; ++k) {
        uint i = wv[k], j = wv[(k + 1u) % 3u];
        vec3 a = mesh_position(min(i, j)), b = mesh_position(max(i, j));
        factor[k] = displaced_edge_factor(edge_tess_factor(a, b, eye, scale), a, b); // grown by the bound (§8.4)
        precise vec3 d = b - a;
        length2[k] = dot3(d, d);
    }
    if (uniform_pattern() || split_pattern()) {
        uint f[3];
        for (uint k = 0u; k < 3u; ++k) {
            f[k] = uniform_factor(factor[k]);
            patches[rec + REC_TOKEN + k] = f[k];
            patches[rec + REC_FACTOR + k] = floatBitsToUint(factor[k]);
        }
        if (split_pattern()) return; // no setup words; the counts come from the leaves (ctess_split_records)
        uvec3 words;
        uvec2 counts = uniform_setup(f, words);
        patches[rec + REC_VERTEX_COUNT] = counts.x;
        patches[rec + REC_TRIANGLE_COUNT] = counts.y;
        patches[rec + SETUP + USETUP_PATTERN] = words.x;
        patches[rec + SETUP + USETUP_SORTED] = words.y;
        patches[rec + SETUP + USETUP_CORNERS] = words.z;
        return;
    }
    uint rot = smallest_edge_rotation(length2);
    uvec2 s[3];
    for (uint k = 0u; k < 3u; ++k) s[k] = line_state(factor[(k + rot) % 3u]);
    Patch p = patch_setup(s[0], s[1], s[2]);
    patches[rec + REC_ROTATION] = rot;
    for (uint k = 0u; k < 3u; ++k) {
        patches[rec + REC_TOKEN + k] = s[k].x;
        patches[rec + REC_T16 + k] = s[k].y;
        patches[rec + REC_FACTOR + k] = floatBitsToUint(factor[k]);
    }
    patches[rec + REC_VERTEX_COUNT] = p.vertices;
    patches[rec + REC_TRIANGLE_COUNT] = p.triangles;
    store_setup_block(rec, p);
}
// Grid-stride: a host may dispatch fewer workgroups than patches / SETUP_GROUP (at most MAX_DISPATCH_WORKGROUPS).
void ctess_patch_setup() {
    uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint t = gl_GlobalInvocationID.x; t < patch_count(); t += stride) setup_one_patch(t);
}

// Pass 2, one workgroup of SCAN_GROUP = 128 (WebGPU compatibility mode allows at most 128 invocations): exclusive prefix sums of the counts; the totals follow the records.
// Totals that do not fit in u32 (indices are u32) are written as TOTALS_OVERFLOW, both of them: hosts refuse them.
shared uvec2 scan_sum[SCAN_GROUP];
shared uint scan_overflow;
void ctess_prefix_sum() {
    uint n = patch_count();
    uint lane = gl_LocalInvocationID.x;
    if (lane == 0u) scan_overflow = 0u;
    bool overflow = false;
    uint per = (n + (SCAN_GROUP - 1u)) / SCAN_GROUP;
    uint begin = min(n, lane * per), end = min(n, begin + per);
    uvec2 sum = uvec2(0u);
    for (uint t = begin; t < end; ++t) {
        uvec2 count = uvec2(patches[t * PATCH_WORDS + REC_VERTEX_COUNT], patches[t * PATCH_WORDS + REC_TRIANGLE_COUNT]);
        sum += count;
        overflow = overflow || sum.x < count.x || sum.y < count.y || sum.x == TOTALS_OVERFLOW || sum.y == TOTALS_OVERFLOW;
    }
    scan_sum[lane] = sum;
    barrier();
    for (uint d = 1u; d < SCAN_GROUP; d <<= 1) {
        uvec2 add = lane >= d ? scan_sum[lane - d] : uvec2(0u);
        barrier();
        uvec2 before = scan_sum[lane];
        uvec2 after = before + add;
        overflow = overflow || after.x < before.x || after.y < before.y || after.x == TOTALS_OVERFLOW || after.y == TOTALS_OVERFLOW;
        scan_sum[lane] = after;
        barrier();
    }
    if (overflow) atomicOr(scan_overflow, 1u);
    barrier();
    uvec2 base = scan_sum[lane] - sum;
    for (uint t = begin; t < end; ++t) {
        uint rec = t * PATCH_WORDS;
        patches[rec + REC_FIRST_VERTEX] = base.x;
        patches[rec + REC_FIRST_TRIANGLE] = base.y;
        base += uvec2(patches[rec + REC_VERTEX_COUNT], patches[rec + REC_TRIANGLE_COUNT]);
    }
    if (lane == SCAN_GROUP - 1u) {
        bool too_large = scan_overflow != 0u;
        patches[n * PATCH_WORDS] = too_large ? TOTALS_OVERFLOW : scan_sum[SCAN_GROUP - 1u].x;
        patches[n * PATCH_WORDS + 1u] = too_large ? TOTALS_OVERFLOW : scan_sum[SCAN_GROUP - 1u].y;
    }
}

// ---- the welded output (docs/shaders.md, "Welded output"; docs/algorithm.md §7.4; Pattern::cp and uniform) ----
// Binding 7 (rt::gpu::weld_word): the header, the mesh's edges (rt::WeldedEdge, lo and hi from the host, sorted and
// distinct), a rt::WeldedPatch per patch, then a writer word per shared id, a map word per slot (unwelded vertex)
// and WELD_SORT_WORDS per slot. Ids as setup_welded numbers them: a corner is its mesh vertex, an edge point the
// edge's first id plus the rank of its parameter from the lower index, an interior point the patch's first id plus
// the rank of its exact domain point among the patch's distinct interior points.
bool weld_on() { return (params[PARAM_WELD] & WELD_ON) != 0u; }
// The weld by one sort over the mesh (ctess_weld_keys and after): the split pattern's, and any other's with a
// patch past WELD_MAX_PATCH_SLOTS.
bool weld_sorted() { return split_pattern() || (params[PARAM_WELD] & WELD_SORTED) != 0u; }
uint weld_edge_count() { return weld[WELD_EDGES]; }
uint weld_edge(uint e) { return WELD_HEADER_WORDS + e * WELD_EDGE_WORDS; }
uint weld_patch(uint t) { return weld_edge(weld_edge_count()) + t * WELD_PATCH_WORDS; }
uint weld_writer(uint id) { return weld_patch(patch_count()) + id; }
uint weld_map(uint s) { return weld_writer(params[PARAM_MESH_VERTEX_COUNT] + weld[WELD_SLOTS]) + s; }
uint weld_sort(uint s) { return weld_map(weld[WELD_SLOTS]) + WELD_SORT_WORDS * s; }

// Edge (a, b) of the sorted list (a binary search); a missing edge (a list the host did not make with
// rt::weld_edge_list) sets WELD_MISSING_EDGE and gives edge 0.
uint weld_find_edge(uint a, uint b) {
    uint lo_ = min(a, b), hi_ = max(a, b), first = 0u, count = weld_edge_count();
    while (count > 0u) {
        uint half_ = count / 2u, m = weld_edge(first + half_);
        if (weld[m + WEDGE_LO] < lo_ || (weld[m + WEDGE_LO] == lo_ && weld[m + WEDGE_HI] < hi_)) {
            first += half_ + 1u;
            count -= half_ + 1u;
        } else {
            count = half_;
        }
    }
    uint m = weld_edge(first);
    if (first >= weld_edge_count() || weld[m + WEDGE_LO] != lo_ || weld[m + WEDGE_HI] != hi_) {
        atomicOr(weld[WELD_STATUS], WELD_MISSING_EDGE);
        return 0u;
    }
    return first;
}

// The distinct interior parameters below x of the line of an edge of factor f (x = FIXED_ONE: all of them), as
// EdgeParams (mesh_pipeline.cpp): CP line points rise with their index (ties where a segment has zero length),
// uniform ones strictly.
uint line_rank(float f, uint x) {
    if (uniform_pattern()) {
        uint n = uniform_factor(f), lo_ = 1u, hi_ = n; // the first i in [1, n) whose parameter is >= x
        while (lo_ < hi_) {
            uint mid = (lo_ + hi_) / 2u;
            if (uniform_to_fixed(uniform_edge_parameter(mid, n)) < x) lo_ = mid + 1u;
            else hi_ = mid;
        }
        return lo_ - 1u;
    }
    uvec2 s = line_state(f);
    if (s.x == 0u) return 0u;
    Edge e = line_edge(s);
    uint rank = 0u, previous = 0u;
    for (uint i = 1u; i < e.segments; ++i) {
        uint point = edge_point(e, i);
        if (point >= x) break;
        if (point != previous) ++rank;
        previous = point;
    }
    return rank;
}

// Patch t as the weld reads it: its mesh corners, rotation and pattern halves; false for a culled patch.
struct WeldPatch {
    bool quad;
    uint rot;
    uint w[4];
    Patch halves[2];
    uvec3 words[2];
    uvec2 counts_a; // half A's vertices and triangles (a base triangle's all)
    uint vertices, triangles, first;
};
bool weld_load(uint t, out WeldPatch wp) {
    uint rec = t * PATCH_WORDS;
    wp.vertices = patches[rec + REC_VERTEX_COUNT];
    wp.triangles = patches[rec + REC_TRIANGLE_COUNT];
    wp.first = patches[rec + REC_FIRST_VERTEX];
    wp.rot = patches[rec + REC_ROTATION];
    wp.quad = t >= triangle_count();
    wp.w = uint[4](0u, 0u, 0u, 0u);
    if (wp.vertices == 0u) return false;
    if (wp.quad) {
        if (!base_quad(t - triangle_count(), wp.w)) return false;
        wp.counts_a = quad_halves(rec, wp.halves, wp.words);
        return true;
    }
    uvec3 w;
    if (!base_triangle(t, w)) return false;
    wp.w = uint[4](w.x, w.y, w.z, 0u);
    wp.halves[0] = uniform_pattern() ? patch_zero() : record_patch(rec);
    wp.words[0] = uniform_words(rec);
    wp.halves[1] = wp.halves[0];
    wp.words[1] = wp.words[0];
    wp.counts_a = uvec2(wp.vertices, wp.triangles);
    return true;
}

// Where the point d of half `side` lies, as slot_place (mesh_pipeline.cpp): 0 a corner (its mesh vertex in
// place.x), else 1 on the first mesh edge whose weight is zero (a quad half's diagonal is inside): its mesh
// vertices in place.xy and its parameter from the lower index in place.z, else 2 inside, with its domain point in
// key (a triangle's base weights (w1, w2), a quad's unit square). key is (~0, ~0) but inside.
uint weld_place(WeldPatch wp, uint side, uvec2 d, out uvec3 place, out uvec2 key) {
    key = uvec2(0xFFFFFFFFu);
    place = uvec3(0u);
    uint a, b, x;
    if (wp.quad) {
        if (side == 1u) d = uvec2(FIXED_ONE - d.x, FIXED_ONE - d.y); // half B: cp::quad_point
        bool on_edge[4] = bool[4](d.y == 0u, d.x == FIXED_ONE, d.y == FIXED_ONE, d.x == 0u);
        uint r[4] = uint[4](d.x, d.y, FIXED_ONE - d.x, FIXED_ONE - d.y); // from q_k along edge k
        uint k = 4u;
        for (uint e = 0u; e < 4u && k == 4u; ++e) if (on_edge[e]) k = e;
        if (k == 4u) {
            key = d;
            return 2u;
        }
        a = wp.w[(k + wp.rot) % 4u];
        b = wp.w[(k + 1u + wp.rot) % 4u];
        if (r[k] == 0u || r[k] == FIXED_ONE) {
            place.x = r[k] == 0u ? a : b;
            return 0u;
        }
        x = a <= b ? r[k] : FIXED_ONE - r[k];
    } else {
        uint pw[3] = uint[3](FIXED_ONE - d.x - d.y, d.x, d.y), w3[3];
        for (uint k = 0u; k < 3u; ++k) w3[(k + wp.rot) % 3u] = pw[k];
        for (uint c = 0u; c < 3u; ++c) {
            if (w3[c] == FIXED_ONE) {
                place.x = wp.w[c];
                return 0u;
            }
        }
        uint j = w3[0] == 0u ? 0u : w3[1] == 0u ? 1u : w3[2] == 0u ? 2u : 3u;
        if (j == 3u) {
            key = uvec2(w3[1], w3[2]);
            return 2u;
        }
        uint i1 = (j + 1u) % 3u, i2 = (j + 2u) % 3u;
        a = wp.w[i1];
        b = wp.w[i2];
        x = a <= b ? w3[i2] : w3[i1];
    }
    place = uvec3(a, b, x);
    return 1u;
}

// Slot i's pattern point and its half (half B's slots after half A's).
uvec2 weld_slot_point(WeldPatch wp, uint i, out uint side) {
    side = i < wp.counts_a.x ? 0u : 1u;
    uint local = side == 0u ? i : i - wp.counts_a.x;
    return uniform_pattern() ? uniform_vertex(wp.words[side], local) : patch_vertex(side == 0u ? wp.halves[0] : wp.halves[1], local);
}

// Slot i's shared id (a corner's mesh vertex, an edge point's id), or WELD_INTERIOR with its domain point in key;
// shared slots get key (~0, ~0), which sorts last.
uint weld_slot(WeldPatch wp, uint i, out uvec2 key) {
    uint side;
    uvec2 d = weld_slot_point(wp, i, side);
    uvec3 place;
    uint kind = weld_place(wp, side, d, place, key);
    if (kind == 0u) return place.x;
    if (kind == 2u) return WELD_INTERIOR;
    return weld[weld_edge(weld_find_edge(place.x, place.y)) + WEDGE_FIRST_VERTEX] +
           line_rank(mesh_edge_factor(place.x, place.y), place.z);
}

// Pattern triangle k's slots (half B's after half A's vertices).
uvec3 weld_triangle_slots(WeldPatch wp, uint k) {
    uint side = k < wp.counts_a.y ? 0u : 1u;
    uint local = side == 0u ? k : k - wp.counts_a.y;
    uvec3 tri = uniform_pattern() ? uniform_triangle(wp.words[side], local) : patch_triangle(side == 0u ? wp.halves[0] : wp.halves[1], local);
    return tri + uvec3(side == 0u ? 0u : wp.counts_a.x);
}
// A map word as an id within the patch's weld (interior ranks keep WELD_INTERIOR), for comparisons.
uint weld_local_id(uint m) { return (m & WELD_INTERIOR) != 0u ? m & ~WELD_REPRESENTATIVE : m; }
// A map word as an output id, interior ranks after the patch's first interior id.
uint weld_output_id(uint m, uint first_interior) {
    return (m & WELD_INTERIOR) != 0u ? first_interior + (m & WELD_RANK_MASK) : m;
}
bool weld_kept(uvec3 ids) {
    return (params[PARAM_WELD] & WELD_KEEP_DEGENERATE) != 0u || (ids.x != ids.y && ids.y != ids.z && ids.x != ids.z);
}

// Weld pass 1, grid-stride: clears the writer words and counts each edge's distinct interior points.
void ctess_weld_edges() {
    uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    uint ids = params[PARAM_MESH_VERTEX_COUNT] + weld[WELD_SLOTS];
    for (uint id = gl_GlobalInvocationID.x; id < ids; id += stride) weld[weld_writer(id)] = 0u;
    // The weld by one sort counts from the ranks (ctess_weld_owner_counts): its owners' words start at 0.
    bool sorted_ = weld_sorted();
    for (uint e = gl_GlobalInvocationID.x; e < weld_edge_count(); e += stride) {
        uint m = weld_edge(e);
        weld[m + WEDGE_VERTEX_COUNT] = sorted_ ? 0u : line_rank(mesh_edge_factor(weld[m + WEDGE_LO], weld[m + WEDGE_HI]), FIXED_ONE);
    }
    if (!sorted_) return;
    for (uint t = gl_GlobalInvocationID.x; t < patch_count(); t += stride) {
        for (uint k = 0u; k < WELD_PATCH_WORDS; ++k) weld[weld_patch(t) + k] = 0u;
    }
}

// Exclusive prefix sums in one workgroup of SCAN_GROUP over n records of `stride` words from base: the counts at
// count_word (.y too when two) into first_word, from start. Returns the end; sets WELD_OVERFLOW past 2^31.
uvec2 weld_prefix(uint base, uint stride, uint n, uvec2 count_word, uvec2 first_word, bool two, uvec2 start) {
    uint lane = gl_LocalInvocationID.x;
    if (lane == 0u) scan_overflow = 0u;
    bool overflow = false;
    uint per = (n + (SCAN_GROUP - 1u)) / SCAN_GROUP;
    uint begin = min(n, lane * per), end = min(n, begin + per);
    uvec2 sum = uvec2(0u);
    for (uint t = begin; t < end; ++t) {
        uint r = base + t * stride;
        uvec2 count = uvec2(weld[r + count_word.x], two ? weld[r + count_word.y] : 0u);
        sum += count;
        overflow = overflow || sum.x < count.x || sum.y < count.y;
    }
    scan_sum[lane] = sum;
    barrier();
    for (uint d = 1u; d < SCAN_GROUP; d <<= 1) {
        uvec2 add = lane >= d ? scan_sum[lane - d] : uvec2(0u);
        barrier();
        uvec2 before = scan_sum[lane];
        uvec2 after = before + add;
        overflow = overflow || after.x < before.x || after.y < before.y;
        scan_sum[lane] = after;
        barrier();
    }
    uvec2 total = scan_sum[SCAN_GROUP - 1u], end_ = start + total;
    overflow = overflow || end_.x < start.x || end_.y < start.y || end_.x >= WELD_INTERIOR || end_.y >= WELD_INTERIOR;
    if (overflow) atomicOr(scan_overflow, 1u);
    uvec2 at = start + scan_sum[lane] - sum;
    for (uint t = begin; t < end; ++t) {
        uint r = base + t * stride;
        weld[r + first_word.x] = at.x;
        at.x += weld[r + count_word.x];
        if (two) {
            weld[r + first_word.y] = at.y;
            at.y += weld[r + count_word.y];
        }
    }
    barrier();
    if (lane == 0u && scan_overflow != 0u) weld[WELD_STATUS] |= WELD_OVERFLOW;
    return end_;
}

// Weld pass 2, one workgroup: the edges' first ids, after the mesh vertices.
void ctess_weld_edge_scan() {
    uvec2 end_ = weld_prefix(weld_edge(0u), WELD_EDGE_WORDS, weld_edge_count(), uvec2(WEDGE_VERTEX_COUNT, 0u),
                             uvec2(WEDGE_FIRST_VERTEX, 0u), false, uvec2(params[PARAM_MESH_VERTEX_COUNT], 0u));
    if (gl_LocalInvocationID.x == 0u) weld[WELD_SHARED] = end_.x;
}

// Weld pass 3, a workgroup per patch: every slot's map word (its shared id, or its interior rank after a sort of
// the patch's points by (u, v, slot)), the patch's distinct interior points and kept triangles.
shared uint weld_lane[EMIT_GROUP];
shared uint weld_kept_count;
shared uint weld_distinct;
// The inclusive prefix sum of each lane's value in weld_lane; every lane must call it.
uint weld_lane_sum(uint value) {
    uint lane = gl_LocalInvocationID.x;
    weld_lane[lane] = value;
    barrier();
    for (uint d = 1u; d < EMIT_GROUP; d <<= 1) {
        uint add = lane >= d ? weld_lane[lane - d] : 0u;
        barrier();
        weld_lane[lane] += add;
        barrier();
    }
    return weld_lane[lane];
}
uint weld_lane_scan(bool flag) { return weld_lane_sum(flag ? 1u : 0u); }
bool weld_sort_less(uint a, uint b) {
    uvec3 x = uvec3(weld[a], weld[a + 1u], weld[a + 2u]), y = uvec3(weld[b], weld[b + 1u], weld[b + 2u]);
    return x.x != y.x ? x.x < y.x : x.y != y.y ? x.y < y.y : x.z < y.z;
}
// One patch per workgroup: the host dispatches batches from WELD_FIRST_PATCH, so that no invocation loops over
// several patches (llvmpipe ends every loop of an invocation after 65,535 iterations in all, without an error).
void ctess_weld_count() {
    uint lane = gl_LocalInvocationID.x;
    uint first_patch = weld[WELD_FIRST_PATCH], end = min(patch_count(), first_patch + gl_NumWorkGroups.x);
    for (uint t = first_patch + gl_WorkGroupID.x; t < end; t += gl_NumWorkGroups.x) {
        uint wpw = weld_patch(t);
        WeldPatch wp;
        if (!weld_load(t, wp)) {
            if (lane == 0u) {
                weld[wpw + WPATCH_VERTEX_COUNT] = 0u;
                weld[wpw + WPATCH_TRIANGLE_COUNT] = 0u;
            }
            continue;
        }
        uint n = wp.vertices;
        for (uint i = lane; i < n; i += EMIT_GROUP) {
            uvec2 key;
            uint id = weld_slot(wp, i, key), o = weld_sort(wp.first + i);
            weld[weld_map(wp.first + i)] = id;
            weld[o] = key.x;
            weld[o + 1u] = key.y;
            weld[o + 2u] = i;
        }
        if (lane == 0u) weld_distinct = 0u;
        memoryBarrierBuffer();
        barrier();
        uint distinct = 0u;
        if (n <= WELD_COUNTED_RANKS) {
            // A small patch ranks by counting: a slot is its point's first when no earlier slot has the point, and
            // its rank counts the first slots of smaller points (the sort's numbering, with two barriers where the
            // sort takes one per stage: a software adapter pays for each).
            for (uint i = lane; i < n; i += EMIT_GROUP) {
                uint o = weld_sort(wp.first + i);
                bool first = weld[o] != 0xFFFFFFFFu;
                for (uint j = 0u; j < i && first; ++j) {
                    uint oj = weld_sort(wp.first + j);
                    first = weld[oj] != weld[o] || weld[oj + 1u] != weld[o + 1u];
                }
                weld[o + 2u] = first ? 1u : 0u;
            }
            memoryBarrierBuffer();
            barrier();
            uint firsts = 0u;
            for (uint i = lane; i < n; i += EMIT_GROUP) {
                uint o = weld_sort(wp.first + i);
                if (weld[o] == 0xFFFFFFFFu) continue;
                uint rank = 0u;
                for (uint j = 0u; j < n; ++j) {
                    uint oj = weld_sort(wp.first + j);
                    if (weld[oj + 2u] != 0u && (weld[oj] < weld[o] || (weld[oj] == weld[o] && weld[oj + 1u] < weld[o + 1u]))) ++rank;
                }
                bool first = weld[o + 2u] != 0u;
                if (first) ++firsts;
                weld[weld_map(wp.first + i)] = WELD_INTERIOR | rank | (first ? WELD_REPRESENTATIVE : 0u);
            }
            atomicAdd(weld_distinct, firsts);
            barrier();
            distinct = weld_distinct;
        } else {
            // A bitonic sort, every comparator ascending (each block's first stage compares mirrored pairs), with the
            // entries past n taken as +inf: a comparator that reaches past n is skipped.
            uint size = 1u;
            while (size < n) size <<= 1;
            for (uint k = 2u; k <= size; k <<= 1) {
                for (uint j = k >> 1; j > 0u; j >>= 1) {
                    for (uint q = lane; q < size / 2u; q += EMIT_GROUP) {
                        uint i = (q / j) * 2u * j + q % j;
                        uint partner = j == (k >> 1) ? i ^ (k - 1u) : i + j;
                        if (partner >= n) continue;
                        uint oa = weld_sort(wp.first + i), ob = weld_sort(wp.first + partner);
                        if (weld_sort_less(ob, oa)) {
                            for (uint w = 0u; w < WELD_SORT_WORDS; ++w) {
                                uint x = weld[oa + w];
                                weld[oa + w] = weld[ob + w];
                                weld[ob + w] = x;
                            }
                        }
                    }
                    memoryBarrierBuffer();
                    barrier();
                }
            }
            // The interior entries (first after the sort) numbered by distinct point.
            for (uint base_ = 0u; base_ < n; base_ += EMIT_GROUP) {
                uint j = base_ + lane, o = weld_sort(wp.first + min(j, n - 1u));
                bool interior = j < n && weld[o] != 0xFFFFFFFFu;
                bool fresh = interior && (j == 0u || weld[o - WELD_SORT_WORDS] != weld[o] || weld[o - WELD_SORT_WORDS + 1u] != weld[o + 1u]);
                uint rank = distinct + weld_lane_scan(fresh) - 1u;
                if (interior) weld[weld_map(wp.first + weld[o + 2u])] = WELD_INTERIOR | rank | (fresh ? WELD_REPRESENTATIVE : 0u);
                distinct += weld_lane[EMIT_GROUP - 1u];
                barrier();
            }
        }
        if (lane == 0u) weld_kept_count = 0u;
        memoryBarrierBuffer();
        barrier();
        uint kept = 0u;
        for (uint k = lane; k < wp.triangles; k += EMIT_GROUP) {
            uvec3 s = weld_triangle_slots(wp, k) + uvec3(wp.first);
            uvec3 ids = uvec3(weld_local_id(weld[weld_map(s.x)]), weld_local_id(weld[weld_map(s.y)]), weld_local_id(weld[weld_map(s.z)]));
            if (weld_kept(ids)) ++kept;
        }
        atomicAdd(weld_kept_count, kept);
        barrier();
        if (lane == 0u) {
            weld[wpw + WPATCH_VERTEX_COUNT] = distinct;
            weld[wpw + WPATCH_TRIANGLE_COUNT] = weld_kept_count;
        }
        barrier();
    }
}

// Weld pass 4, grid-stride over the slots: each shared id's writer, the last slot that reaches it (as the CPU's
// patches last to first, and within a patch its last slot). atomicMax: the result does not depend on the order.
void ctess_weld_writers() {
    uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    // The weld by one sort has ids in its map words (interior ones marked): every id gets a writer.
    bool sorted_ = weld_sorted();
    for (uint s = gl_GlobalInvocationID.x; s < weld[WELD_SLOTS]; s += stride) {
        uint m = weld[weld_map(s)];
        if (sorted_) atomicMax(weld[weld_writer(m & ~WELD_INTERIOR)], s + 1u);
        else if ((m & WELD_INTERIOR) == 0u) atomicMax(weld[weld_writer(m)], s + 1u);
    }
}

// Weld pass 5, one workgroup: the patches' first interior ids (after the shared ones) and first triangles, and the
// totals.
void ctess_weld_scan() {
    uvec2 end_ = weld_prefix(weld_patch(0u), WELD_PATCH_WORDS, patch_count(), uvec2(WPATCH_VERTEX_COUNT, WPATCH_TRIANGLE_COUNT),
                             uvec2(WPATCH_FIRST_VERTEX, WPATCH_FIRST_TRIANGLE), true, uvec2(weld[WELD_SHARED], 0u));
    if (gl_LocalInvocationID.x == 0u) {
        weld[WELD_VERTICES] = end_.x;
        weld[WELD_TRIANGLES] = end_.y;
    }
}

// Weld emit, a workgroup per patch of the emit range (triangles and quads): the kept triangles in pattern order.
// One patch per workgroup, batches from WELD_FIRST_PATCH as ctess_weld_count's, within the params' emit range.
void ctess_weld_triangles() {
    uint lane = gl_LocalInvocationID.x;
    uint first_patch = max(weld[WELD_FIRST_PATCH], params[PARAM_FIRST_PATCH]);
    uint end = min(min(params[PARAM_END_PATCH], patch_count()), weld[WELD_FIRST_PATCH] + gl_NumWorkGroups.x);
    for (uint t = first_patch + gl_WorkGroupID.x; t < end; t += gl_NumWorkGroups.x) {
        WeldPatch wp;
        if (!weld_load(t, wp)) continue;
        uint wpw = weld_patch(t);
        uint first_interior = weld[wpw + WPATCH_FIRST_VERTEX], written = weld[wpw + WPATCH_FIRST_TRIANGLE];
        for (uint base_ = 0u; base_ < wp.triangles; base_ += EMIT_GROUP) {
            uint k = base_ + lane;
            uvec3 ids = uvec3(0u);
            bool keep = false;
            if (k < wp.triangles) {
                uvec3 s = weld_triangle_slots(wp, k) + uvec3(wp.first);
                ids = uvec3(weld_output_id(weld[weld_map(s.x)], first_interior), weld_output_id(weld[weld_map(s.y)], first_interior),
                            weld_output_id(weld[weld_map(s.z)], first_interior));
                keep = weld_kept(ids);
            }
            uint before = weld_lane_scan(keep);
            if (keep) {
                uint o = 3u * (written + before - 1u);
                out_indices[o] = ids.x;
                out_indices[o + 1u] = ids.y;
                out_indices[o + 2u] = ids.z;
            }
            written += weld_lane[EMIT_GROUP - 1u];
            barrier();
        }
    }
}

// Weld emit, grid-stride over the mesh vertices: each one no face reaches (no writer) as its corner value, as
// emit_welded_mesh (a corner of its own, displaced with itself as the dominant vertex and no neighbours).
void ctess_weld_lone_vertices() {
    uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    uint surface = params[PARAM_SURFACE];
    float alpha = uintBitsToFloat(params[PARAM_ALPHA]);
    bool vector_ = displacement_vector_mode();
    for (uint v = gl_GlobalInvocationID.x; v < params[PARAM_MESH_VERTEX_COUNT]; v += stride) {
        if (weld[weld_writer(v)] != 0u) continue;
        Corner c = mesh_corner(v);
        Corner tri[3] = Corner[3](c, c, c);
        uint w3[3] = uint[3](FIXED_ONE, 0u, 0u);
        vec3 normals[3] = vec3[3](c.normal, c.normal, c.normal);
        SurfacePoint sp = surface == SURFACE_PN_AEN ? evaluate_surface_aen(tri, normals, normals, w3, alpha) : evaluate_surface(tri, w3, surface, alpha);
        if (displacement_on()) {
            uint own[4] = uint[4](v, v, v, 0u), none[4] = uint[4](0u, 0u, 0u, 0u);
            DisplacementPatch dp = displacement_patch(3u, own, none, none, none, none, vector_, false);
            if (vector_) displace_triangle_vector(dp, w3, 0.0, 0.0, sp);
            else displace_triangle_point(dp, w3, sp);
        }
        store_vertex(v * VERTEX_WORDS, 0u, 0u, sp);
    }
}

// ---- the weld by one sort over the mesh (docs/shaders.md, "Welded output", "One sort"; WELD_SORTED) ----
// A split patch can have millions of slots, and any patch past WELD_MAX_PATCH_SLOTS is past one workgroup's sort,
// so every slot of the mesh gets a record (owner, key, slot): a mesh edge's points are owned by the edge (owner e)
// and keyed by their parameter from the lower index, a patch's interior points by the patch (owner edges + t) and
// their domain point; corners and the padding have owner ~0 and sort last. Sorted, the distinct (owner, key) pairs
// in order are setup_welded's ids after the mesh vertices: edges in list order, each by rank of its parameter,
// then the patches' interiors, each by rank of its domain point. Binding 7 after the map words: two words of base
// weights per slot (the split pattern's leaves), the records (WELD_SORT_RECORDS, a power of two) and two words per
// rank block. A slot's map word is its id, with WELD_INTERIOR on interior points.
uint weld_weights(uint s) { return weld_map(weld[WELD_SLOTS]) + 2u * s; }
uint weld_record(uint i) { return weld_weights(weld[WELD_SLOTS]) + WELD_RECORD_WORDS * i; }
uint weld_block(uint b) { return weld_record(weld[WELD_SORT_RECORDS]) + 2u * b; }
uvec4 weld_load_record(uint i) {
    uint o = weld_record(i);
    return uvec4(weld[o], weld[o + 1u], weld[o + 2u], weld[o + 3u]);
}
void weld_store_record(uint i, uvec4 r) {
    uint o = weld_record(i);
    weld[o] = r.x;
    weld[o + 1u] = r.y;
    weld[o + 2u] = r.z;
    weld[o + 3u] = r.w;
}
bool weld_record_less(uvec4 a, uvec4 b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z != b.z ? a.z < b.z : a.w < b.w;
}
// Patch t's corners and rotation as weld_load reads them; false for a culled patch.
bool weld_corners(uint t, out WeldPatch wp) {
    wp.quad = t >= triangle_count();
    wp.rot = patches[t * PATCH_WORDS + REC_ROTATION];
    wp.w = uint[4](0u, 0u, 0u, 0u);
    if (wp.quad) return base_quad(t - triangle_count(), wp.w);
    uvec3 w;
    if (!base_triangle(t, w)) return false;
    wp.w = uint[4](w.x, w.y, w.z, 0u);
    return true;
}
// Slot s of patch t, at point d of half `side`: its map word (a corner's mesh vertex) or its record.
void weld_key(WeldPatch wp, uint t, uint side, uvec2 d, uint s) {
    uvec3 place;
    uvec2 key;
    uint kind = weld_place(wp, side, d, place, key);
    uvec4 r = uvec4(0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu, s);
    if (kind == 0u) weld[weld_map(s)] = place.x;
    else if (kind == 1u) r.xyz = uvec3(weld_find_edge(place.x, place.y), place.z, 0u);
    else r.xyz = uvec3(weld_edge_count() + t, key);
    weld_store_record(s, r);
}
// The sorted weld's work items: the split pattern's leaves, or the patches.
uint weld_items() { return split_pattern() ? split_leaves() : patch_count(); }

// Sorted weld pass 1 (after the counts, instead of ctess_weld_count), a workgroup per leaf or patch: each slot's
// map word (a corner's mesh vertex) or record, a split leaf's base weights; the padding records.
void ctess_weld_keys() {
    uint slots = weld[WELD_SLOTS], stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint i = slots + gl_GlobalInvocationID.x; i < weld[WELD_SORT_RECORDS]; i += stride) weld_store_record(i, uvec4(0xFFFFFFFFu));
    bool split_ = split_pattern();
    for (uint item = gl_WorkGroupID.x; item < weld_items(); item += gl_NumWorkGroups.x) {
        WeldPatch wp;
        if (!split_) {
            if (!weld_load(item, wp)) continue;
            for (uint i = gl_LocalInvocationID.x; i < wp.vertices; i += gl_WorkGroupSize.x) {
                uint side;
                uvec2 d = weld_slot_point(wp, i, side);
                weld_key(wp, item, side, d, wp.first + i);
            }
            continue;
        }
        uint leaf = split_leaf(item), t = patches[leaf + NODE_PATCH];
        uint first = patches[leaf + NODE_FIRST_VERTEX], count = patches[leaf + NODE_VERTICES];
        if (count == 0u || !weld_corners(t, wp)) continue;
        SplitNode s = load_node(leaf);
        uvec3 words = uvec3(patches[leaf + NODE_PATTERN], patches[leaf + NODE_PATTERN + 1u], patches[leaf + NODE_PATTERN + 2u]);
        uint side = wp.quad ? (patches[leaf + NODE_INFO] >> NODE_HALF_SHIFT) & 1u : 0u;
        for (uint i = gl_LocalInvocationID.x; i < count; i += gl_WorkGroupSize.x) {
            uvec2 d = split_vertex(s, words, i);
            uint o = weld_weights(first + i);
            weld[o] = d.x;
            weld[o + 1u] = d.y;
            weld_key(wp, t, side, d, first + i);
        }
    }
}

// The bitonic network with every comparator ascending (docs/shaders.md, "One sort over the mesh"): the first step
// of a stage compares each block's halves mirrored (p with p ^ (stage - 1)), the others p with p + step. A record
// past the count then acts as +inf and never moves, so the records need no padding to a power of two.
uint weld_sort_partner(uint p, uint stage, uint step_) { return step_ * 2u == stage ? p ^ (stage - 1u) : p + step_; }

// Sorted weld pass 2, one compare-exchange step (stage WELD_SORT_STAGE, step WELD_SORT_STEP, written by the host
// before each dispatch; steps of at least WELD_SORT_CHUNK, the smaller ones in ctess_weld_sort_local), grid-stride
// over the records: no invocation loops long.
void ctess_weld_sort_step() {
    uint n = weld[WELD_SORT_RECORDS], stage = weld[WELD_SORT_STAGE], step_ = weld[WELD_SORT_STEP];
    for (uint p = gl_GlobalInvocationID.x; p < n; p += gl_NumWorkGroups.x * gl_WorkGroupSize.x) {
        uint q = weld_sort_partner(p, stage, step_);
        if ((p & step_) != 0u || q >= n) continue;
        uvec4 a = weld_load_record(p), b = weld_load_record(q);
        if (weld_record_less(b, a)) {
            weld_store_record(p, b);
            weld_store_record(q, a);
        }
    }
}

// Sorted weld pass 2b, a workgroup per chunk of WELD_SORT_CHUNK records in workgroup memory (the last one padded
// with +inf): with WELD_SORT_STAGE 0 every stage up to the chunk (each chunk sorted), else the steps below the
// chunk of that stage (the host runs the larger steps with ctess_weld_sort_step): the same network, a dispatch for
// what would be up to log2(WELD_SORT_CHUNK) + 1 of them.
shared uvec4 weld_chunk[WELD_SORT_CHUNK];
void ctess_weld_sort_local() {
    uint lane = gl_LocalInvocationID.x, n = weld[WELD_SORT_RECORDS], stage = weld[WELD_SORT_STAGE];
    for (uint chunk = gl_WorkGroupID.x; chunk * WELD_SORT_CHUNK < n; chunk += gl_NumWorkGroups.x) {
        uint base_ = chunk * WELD_SORT_CHUNK;
        for (uint i = lane; i < WELD_SORT_CHUNK; i += EMIT_GROUP)
            weld_chunk[i] = base_ + i < n ? weld_load_record(base_ + i) : uvec4(0xFFFFFFFFu);
        for (uint s = stage == 0u ? 2u : stage; s <= (stage == 0u ? WELD_SORT_CHUNK : stage); s <<= 1) {
            for (uint step_ = min(s, WELD_SORT_CHUNK) / 2u; step_ > 0u; step_ >>= 1) {
                barrier();
                for (uint i = lane; i < WELD_SORT_CHUNK / 2u; i += EMIT_GROUP) {
                    uint low = i & (step_ - 1u), p = ((i - low) << 1u) | low, q = weld_sort_partner(p, s, step_);
                    uvec4 a = weld_chunk[p], b = weld_chunk[q];
                    if (weld_record_less(b, a)) {
                        weld_chunk[p] = b;
                        weld_chunk[q] = a;
                    }
                }
            }
        }
        barrier();
        for (uint i = lane; i < WELD_SORT_CHUNK && base_ + i < n; i += EMIT_GROUP) weld_store_record(base_ + i, weld_chunk[i]);
        barrier();
    }
}

// The rank passes' items: the sorted records (WELD_RANK_KEYS: flagged where a distinct (owner, key) starts) or
// the unwelded triangles (WELD_RANK_TRIANGLES: flagged where kept, one word each over the records' area).
uint weld_rank_items() {
    return weld[WELD_RANK_MODE] == WELD_RANK_KEYS ? weld[WELD_SORT_RECORDS] : patches[patch_count() * PATCH_WORDS + 1u];
}
bool weld_rank_flag(uint i, uint items) {
    if (i >= items) return false;
    if (weld[WELD_RANK_MODE] != WELD_RANK_KEYS) return weld[weld_record(0u) + i] != 0u;
    uvec4 r = weld_load_record(i);
    if (r.x == 0xFFFFFFFFu) return false;
    return i == 0u || weld_load_record(i - 1u).xyz != r.xyz;
}

// Sorted weld rank pass 1, a workgroup per block of WELD_RANK_BLOCK items: the block's flags counted.
void ctess_weld_rank_blocks() {
    uint lane = gl_LocalInvocationID.x, items = weld_rank_items();
    uint blocks = (items + WELD_RANK_BLOCK - 1u) / WELD_RANK_BLOCK;
    for (uint b = gl_WorkGroupID.x; b < blocks; b += gl_NumWorkGroups.x) {
        uint count = 0u;
        for (uint c = 0u; c < WELD_RANK_BLOCK; c += EMIT_GROUP)
            if (weld_rank_flag(b * WELD_RANK_BLOCK + c + lane, items)) ++count;
        weld_lane_sum(count);
        if (lane == 0u) weld[weld_block(b)] = weld_lane[EMIT_GROUP - 1u];
        barrier();
    }
}

// Sorted weld rank pass 2, one workgroup: the blocks' first ranks; the total in WELD_RANKED.
void ctess_weld_rank_scan() {
    uint items = weld_rank_items();
    uvec2 end_ = weld_prefix(weld_block(0u), 2u, (items + WELD_RANK_BLOCK - 1u) / WELD_RANK_BLOCK, uvec2(0u), uvec2(1u, 0u), false, uvec2(0u));
    if (gl_LocalInvocationID.x == 0u) weld[WELD_RANKED] = end_.x;
}

// Sorted weld rank pass 3, a workgroup per block: each item's rank. Keys: every slot's map word (the mesh vertices,
// then the rank of its (owner, key)), and each owner's first id and end (its first and last records) in its
// WeldedEdge or WeldedPatch, for ctess_weld_owner_counts. Triangles: each triangle's exclusive rank among the kept
// ones, with WELD_INTERIOR on a dropped one.
void ctess_weld_rank_write() {
    uint lane = gl_LocalInvocationID.x, items = weld_rank_items(), mode = weld[WELD_RANK_MODE];
    uint blocks = (items + WELD_RANK_BLOCK - 1u) / WELD_RANK_BLOCK, base_id = params[PARAM_MESH_VERTEX_COUNT];
    for (uint b = gl_WorkGroupID.x; b < blocks; b += gl_NumWorkGroups.x) {
        uint before = weld[weld_block(b) + 1u];
        for (uint c = 0u; c < WELD_RANK_BLOCK; c += EMIT_GROUP) {
            uint i = b * WELD_RANK_BLOCK + c + lane;
            bool flag = weld_rank_flag(i, items);
            uint rank = before + weld_lane_scan(flag) - 1u; // the last flagged item up to i
            if (i < items && mode != WELD_RANK_KEYS) {
                weld[weld_record(0u) + i] = flag ? rank : (rank + 1u) | WELD_INTERIOR;
            } else if (i < items) {
                uvec4 r = weld_load_record(i);
                if (r.x != 0xFFFFFFFFu) {
                    uint id = base_id + rank, edges = weld_edge_count();
                    weld[weld_map(r.w)] = id | (r.x >= edges ? WELD_INTERIOR : 0u);
                    uint owner = r.x < edges ? weld_edge(r.x) + WEDGE_FIRST_VERTEX : weld_patch(r.x - edges) + WPATCH_FIRST_VERTEX;
                    // WEDGE_VERTEX_COUNT and WPATCH_VERTEX_COUNT follow the first-vertex words.
                    if (i == 0u || weld_load_record(i - 1u).x != r.x) weld[owner] = id;
                    if (i + 1u == items || weld_load_record(i + 1u).x != r.x) weld[owner + 1u] = id + 1u;
                }
            }
            before += weld_lane[EMIT_GROUP - 1u];
            barrier();
        }
    }
}

// Triangle k of a sorted weld's item (a leaf, or a patch wp): its slots and its unwelded index.
uvec4 weld_item_triangle(bool split_, uint item, WeldPatch wp, uint k) {
    if (!split_) return uvec4(weld_triangle_slots(wp, k) + uvec3(wp.first), patches[item * PATCH_WORDS + REC_FIRST_TRIANGLE] + k);
    uint leaf = split_leaf(item);
    uvec3 words = uvec3(patches[leaf + NODE_PATTERN], patches[leaf + NODE_PATTERN + 1u], patches[leaf + NODE_PATTERN + 2u]);
    return uvec4(uniform_triangle(words, k) + uvec3(patches[leaf + NODE_FIRST_VERTEX]), patches[leaf + NODE_FIRST_TRIANGLE] + k);
}
// A sorted weld's item's triangles; false for a culled patch.
bool weld_item_load(bool split_, uint item, out WeldPatch wp, out uint triangles) {
    triangles = 0u;
    if (split_) {
        triangles = patches[split_leaf(item) + NODE_TRIANGLES];
        return true;
    }
    if (!weld_load(item, wp)) return false;
    triangles = wp.triangles;
    return true;
}

// Sorted weld pass, a workgroup per leaf or patch: each triangle's kept flag (its welded corners distinct, or
// keep_degenerate) over the records' area, for the triangles' ranks.
void ctess_weld_keep() {
    uint flags = weld_record(0u);
    bool split_ = split_pattern();
    for (uint item = gl_WorkGroupID.x; item < weld_items(); item += gl_NumWorkGroups.x) {
        WeldPatch wp;
        uint triangles;
        if (!weld_item_load(split_, item, wp, triangles)) continue;
        for (uint k = gl_LocalInvocationID.x; k < triangles; k += gl_WorkGroupSize.x) {
            uvec4 s = weld_item_triangle(split_, item, wp, k);
            uvec3 ids = uvec3(weld[weld_map(s.x)], weld[weld_map(s.y)], weld[weld_map(s.z)]) & uvec3(~WELD_INTERIOR);
            weld[flags + s.w] = weld_kept(ids) ? 1u : 0u;
        }
    }
}

// Sorted weld pass, grid-stride over the edges and patches: each one's counts from the ranks. An owner's
// vertex_count word holds its end id when it has points (ctess_weld_rank_write), else 0; a patch's kept
// triangles are the ranks at its first unwelded triangle and after its last.
void ctess_weld_owner_counts() {
    uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x, edges = weld_edge_count(), flags = weld_record(0u);
    uint triangles = patches[patch_count() * PATCH_WORDS + 1u];
    for (uint e = gl_GlobalInvocationID.x; e < edges; e += stride) {
        uint m = weld_edge(e), end_ = weld[m + WEDGE_VERTEX_COUNT];
        weld[m + WEDGE_VERTEX_COUNT] = end_ == 0u ? 0u : end_ - weld[m + WEDGE_FIRST_VERTEX];
    }
    for (uint t = gl_GlobalInvocationID.x; t < patch_count(); t += stride) {
        uint m = weld_patch(t), end_ = weld[m + WPATCH_VERTEX_COUNT];
        weld[m + WPATCH_VERTEX_COUNT] = end_ == 0u ? 0u : end_ - weld[m + WPATCH_FIRST_VERTEX];
        uint rec = t * PATCH_WORDS, first = patches[rec + REC_FIRST_TRIANGLE], count = patches[rec + REC_TRIANGLE_COUNT];
        uint at = first < triangles ? weld[flags + first] & ~WELD_INTERIOR : weld[WELD_RANKED];
        uint after = first + count < triangles ? weld[flags + first + count] & ~WELD_INTERIOR : weld[WELD_RANKED];
        weld[m + WPATCH_TRIANGLE_COUNT] = count == 0u ? 0u : after - at;
    }
}

// Sorted weld emit, a workgroup per leaf or patch of the emit range: its kept triangles at their ranks.
void ctess_weld_sorted_triangles() {
    uint flags = weld_record(0u), first_patch = params[PARAM_FIRST_PATCH], end = min(params[PARAM_END_PATCH], patch_count());
    bool split_ = split_pattern();
    uvec2 items = emit_items(split_, first_patch, end);
    for (uint item = items.x + gl_WorkGroupID.x; item < items.y; item += gl_NumWorkGroups.x) {
        uint leaf;
        uint t = item_patch(split_, item, leaf);
        WeldPatch wp;
        uint triangles;
        if (t < first_patch || t >= end || !weld_item_load(split_, item, wp, triangles)) continue;
        for (uint k = gl_LocalInvocationID.x; k < triangles; k += gl_WorkGroupSize.x) {
            uvec4 s = weld_item_triangle(split_, item, wp, k);
            uint rank = weld[flags + s.w];
            if ((rank & WELD_INTERIOR) != 0u) continue;
            uint o = 3u * rank;
            out_indices[o] = weld[weld_map(s.x)] & ~WELD_INTERIOR;
            out_indices[o + 1u] = weld[weld_map(s.y)] & ~WELD_INTERIOR;
            out_indices[o + 2u] = weld[weld_map(s.z)] & ~WELD_INTERIOR;
        }
    }
}

// Passes 3 and 4 (vertices), a workgroup per patch (looping when there are more patches than workgroups): every
// output vertex of the emit range's triangles (quad_pass false: ctess_emit_vertices) or quads (true:
// ctess_emit_quad_vertices). Separate entry points, so that a triangle pipeline carries no quad code: a software
// adapter runs an untaken workgroup-uniform branch at full cost (docs/shaders.md, "Quads"). One call site of each
// pattern and surface function, so that a compiler that inlines everything keeps one copy of each.
void emit_vertices(bool quad_pass, bool displaced, bool vector_) {
    uint first_patch = quad_pass ? max(params[PARAM_FIRST_PATCH], triangle_count()) : params[PARAM_FIRST_PATCH];
    uint end = min(params[PARAM_END_PATCH], quad_pass ? patch_count() : triangle_count());
    float alpha = uintBitsToFloat(params[PARAM_ALPHA]);
    uint surface = params[PARAM_SURFACE];
    bool aen = surface == SURFACE_PN_AEN;
    bool uniform_ = uniform_pattern();
    // Displacement runs in its own entry points (a software adapter runs an untaken branch at full cost); the
    // others write no vertex when the params displace, rather than undisplaced ones.
    // Vector displacement (§8.7) has its own entry points too (vector_); each displaced pass writes no vertex for
    // the other mode's params.
    bool displace = displaced;
    if (displacement_on() != displaced) return;
    if (displaced && displacement_vector_mode() != vector_) return;
    // Split (docs/shaders.md, "Splitting"): a workgroup per leaf of the patches in [first_patch, end) instead of
    // per patch; a leaf's vertices are its pattern's, mapped on the root.
    bool split_ = split_pattern();
    // Welded (docs/shaders.md, "Welded output"): each slot writes its weld id's vertex when it is the id's writer
    // (the first slot of an interior point, the writer word's slot of a shared one), with u = v = 0 for shared ids.
    bool weld_ = weld_on(), sorted_ = weld_ && weld_sorted();
    uvec2 items = emit_items(split_, first_patch, end);
    for (uint item = items.x + gl_WorkGroupID.x; item < items.y; item += gl_NumWorkGroups.x) {
        uint leaf;
        uint t = item_patch(split_, item, leaf);
        if (t < first_patch || t >= end) continue;
        uint rec = t * PATCH_WORDS;
        uint count = split_ ? patches[leaf + NODE_VERTICES] : patches[rec + REC_VERTEX_COUNT];
        if (count == 0u) continue;
        uint first_interior = weld_ && !sorted_ ? weld[weld_patch(t) + WPATCH_FIRST_VERTEX] : 0u;
        bool quad = quad_pass;
        uint rot = patches[rec + REC_ROTATION];
        // The corners in pattern order for a quad (q_k = mesh corner (k + rotation) % 4), in base order for a
        // triangle; adj_from[k], adj_to[k]: the neighbour's normals on edge k (the own ones unless PN-AEN).
        Corner q[4];
        vec3 adj_from[4], adj_to[4];
        Patch halves[2];
        uvec3 words[2];
        uint vertices_a = count;
        DisplacementPatch dp;
        if (quad) {
            uint w[4];
            if (!base_quad(t - triangle_count(), w)) continue;
            for (uint k = 0u; k < 4u; ++k) q[k] = mesh_corner(w[(k + rot) % 4u]);
            // Pattern edge k is mesh edge m = (k + rotation) % 4: edge 0 or 1 of face triangle (q0, q1, q2)
            // (adjacency block triangle_count + 2 quad) for m < 2, edge 1 or 2 of (q0, q2, q3) (the next) after.
            uint face = triangle_count() + 2u * (t - triangle_count());
            for (uint k = 0u; k < 4u; ++k) {
                uint m = (k + rot) % 4u;
                adj_from[k] = q[k].normal;
                adj_to[k] = q[(k + 1u) % 4u].normal;
                if (aen) adjacent_normals(face + (m >= 2u ? 1u : 0u), m >= 2u ? m - 1u : m, q[k], q[(k + 1u) % 4u], adj_from[k], adj_to[k]);
            }
            if (split_) vertices_a = ((patches[leaf + NODE_INFO] >> NODE_HALF_SHIFT) & 1u) == 0u ? count : 0u;
            else vertices_a = quad_halves(rec, halves, words).x;
            if (displace) {
                // Mesh corners q0, q1, q2 are slots 0-2 of face (q0, q1, q2), q3 slot 2 of (q0, q2, q3); mesh edges
                // 0 and 1 are edges 0 and 1 of the first, 2 and 3 edges 1 and 2 of the second (mesh_pipeline.cpp).
                uint wp[4], corner_face[4], corner_slot[4], edge_face[4], edge_slot[4];
                for (uint k = 0u; k < 4u; ++k) {
                    uint m = (k + rot) % 4u;
                    wp[k] = w[m];
                    corner_face[k] = face + (m == 3u ? 1u : 0u);
                    corner_slot[k] = m == 3u ? 2u : m;
                    edge_face[k] = face + (m >= 2u ? 1u : 0u);
                    edge_slot[k] = m >= 2u ? m - 1u : m;
                }
                dp = displacement_patch(4u, wp, corner_face, corner_slot, edge_face, edge_slot, vector_, true);
            }
        } else {
            uvec3 w;
            if (!base_triangle(t, w)) continue;
            q[0] = mesh_corner(w.x);
            q[1] = mesh_corner(w.y);
            q[2] = mesh_corner(w.z);
            q[3] = q[0];
            for (uint e = 0u; e < 3u; ++e) {
                adj_from[e] = q[e].normal;
                adj_to[e] = q[(e + 1u) % 3u].normal;
                if (aen) adjacent_normals(t, e, q[e], q[(e + 1u) % 3u], adj_from[e], adj_to[e]);
            }
            halves[0] = uniform_ || split_ ? patch_zero() : record_patch(rec);
            words[0] = uniform_words(rec);
            if (displace)
                dp = displacement_patch(3u, uint[4](w.x, w.y, w.z, 0u), uint[4](t, t, t, t), uint[4](0u, 1u, 2u, 0u),
                                        uint[4](t, t, t, t), uint[4](0u, 1u, 2u, 0u), vector_, true);
        }
        uint first = split_ ? patches[leaf + NODE_FIRST_VERTEX] : patches[rec + REC_FIRST_VERTEX];
        for (uint i = gl_LocalInvocationID.x; i < count; i += gl_WorkGroupSize.x) {
            uint side = i < vertices_a ? 0u : 1u;
            uint local = side == 0u ? i : i - vertices_a;
            uint o = (first + i) * VERTEX_WORDS;
            bool shared_id = false;
            if (weld_) {
                uint m = weld[weld_map(first + i)];
                shared_id = (m & WELD_INTERIOR) == 0u;
                if (sorted_) {
                    // The weld by one sort has ids in its map words (ctess_weld_keys), each written by its writer.
                    if (weld[weld_writer(m & ~WELD_INTERIOR)] != first + i + 1u) continue;
                    o = (m & ~WELD_INTERIOR) * VERTEX_WORDS;
                } else {
                    if (shared_id ? weld[weld_writer(m)] != first + i + 1u : (m & WELD_REPRESENTATIVE) == 0u) continue;
                    o = weld_output_id(m, first_interior) * VERTEX_WORDS;
                }
            }
            // A split leaf's base weights are ctess_split_points' (its map into the root stays out of this pass),
            // welded ctess_weld_keys' in binding 7.
            uint sw = weld_ && split_ ? weld_weights(first + i) : 0u;
            uvec2 d = !split_ ? (uniform_ ? uniform_vertex(words[side], local) : patch_vertex(side == 0u ? halves[0] : halves[1], local))
                      : weld_ ? uvec2(weld[sw], weld[sw + 1u]) : uvec2(out_vertices[o + VERTEX_U], out_vertices[o + VERTEX_V]);
            // The surface's triangle and weights: a triangle's own (to_base_point: pattern weights (1 - u - v, u,
            // v) move to base vertices (k + rot) % 3), or for a point on quad edge k the triangle (q_k, q_k+1,
            // q_k+2) with weights (1 - r, r, 0), the operations the neighbour across the edge runs (quad_vertex on
            // the CPU); a point inside a quad goes to quad_interior.
            Corner tri[3] = Corner[3](q[0], q[1], q[2]);
            uint w3[3];
            vec3 from3[3] = vec3[3](adj_from[0], adj_from[1], adj_from[2]);
            vec3 to3[3] = vec3[3](adj_to[0], adj_to[1], adj_to[2]);
            bool inner = false;
            uvec2 out_uv;
            if (quad) {
                if (side == 1u) d = uvec2(FIXED_ONE - d.x, FIXED_ONE - d.y); // half B: cp::quad_point
                out_uv = d;
                bool on_edge[4] = bool[4](d.y == 0u, d.x == FIXED_ONE, d.y == FIXED_ONE, d.x == 0u);
                uint r[4] = uint[4](d.x, d.y, FIXED_ONE - d.x, FIXED_ONE - d.y);
                uint k = 4u;
                for (uint e = 0u; e < 4u && k == 4u; ++e) if (on_edge[e]) k = e;
                inner = k == 4u;
                if (!inner) {
                    tri = Corner[3](q[k], q[(k + 1u) % 4u], q[(k + 2u) % 4u]);
                    w3 = uint[3](FIXED_ONE - r[k], r[k], 0u);
                    // Edge k's neighbours; the triangle's other two edges are its own boundary.
                    from3 = vec3[3](adj_from[k], tri[1].normal, tri[2].normal);
                    to3 = vec3[3](adj_to[k], tri[2].normal, tri[0].normal);
                }
            } else {
                uint pw[3] = uint[3](FIXED_ONE - d.x - d.y, d.x, d.y);
                for (uint k = 0u; k < 3u; ++k) w3[(k + rot) % 3u] = pw[k];
                out_uv = uvec2(w3[1], w3[2]);
            }
            SurfacePoint sp;
            if (inner) sp = quad_interior(q, adj_from, adj_to, aen, out_uv.x, out_uv.y, surface, alpha);
            else if (aen) sp = evaluate_surface_aen(tri, from3, to3, w3, alpha);
            else sp = evaluate_surface(tri, w3, surface, alpha);
            // §8: after the surface, as mesh_pipeline.cpp (a quad's every point by its square point).
            if (displace && vector_ && quad) displace_quad_vector(dp, out_uv.x, out_uv.y, fixed_weight(out_uv.x), fixed_weight(out_uv.y), sp);
            else if (displace && vector_) displace_triangle_vector(dp, w3, fixed_weight(w3[1]), fixed_weight(w3[2]), sp);
            else if (displace && quad) displace_quad_point(dp, out_uv.x, out_uv.y, sp);
            else if (displace) displace_triangle_point(dp, w3, sp);
            store_vertex(o, shared_id ? 0u : out_uv.x, shared_id ? 0u : out_uv.y, sp);
        }
    }
}

// Split pattern, before the vertex passes: every leaf vertex's base weights (its pattern's point mapped on the
// root, to_base_weights) into the output vertex's first two words, a workgroup per leaf of the emit range. The
// vertex passes read them there, so that the other patterns' vertex passes carry no split code (a software
// adapter runs an untaken branch at full cost).
void ctess_split_points() {
    if (!split_pattern()) return;
    uint last = split_range_end(min(params[PARAM_END_PATCH], patch_count()));
    for (uint item = split_range_start(params[PARAM_FIRST_PATCH]) + gl_WorkGroupID.x; item < last;
         item += gl_NumWorkGroups.x) {
        // The leaf's node and pattern once, not per vertex (a vertex store may alias them for the compiler).
        uint leaf = split_leaf(item), first = patches[leaf + NODE_FIRST_VERTEX], count = patches[leaf + NODE_VERTICES];
        SplitNode s = load_node(leaf);
        uvec3 words = uvec3(patches[leaf + NODE_PATTERN], patches[leaf + NODE_PATTERN + 1u], patches[leaf + NODE_PATTERN + 2u]);
        for (uint i = gl_LocalInvocationID.x; i < count; i += gl_WorkGroupSize.x) {
            uvec2 d = split_vertex(s, words, i);
            out_vertices[(first + i) * VERTEX_WORDS + VERTEX_U] = d.x;
            out_vertices[(first + i) * VERTEX_WORDS + VERTEX_V] = d.y;
        }
    }
}

void ctess_emit_vertices() { emit_vertices(false, false, false); }
void ctess_emit_quad_vertices() { emit_vertices(true, false, false); }
void ctess_emit_displaced_vertices() { emit_vertices(false, true, false); }
void ctess_emit_displaced_quad_vertices() { emit_vertices(true, true, false); }
void ctess_emit_vector_displaced_vertices() { emit_vertices(false, true, true); }
void ctess_emit_vector_displaced_quad_vertices() { emit_vertices(true, true, true); }

// Passes 5 and 6 (triangles), as 3 and 4: every output triangle, in provoking-vertex order, as mesh-wide indices
// (a quad's half B after A, its indices after A's vertices).
void emit_triangles(bool quad_pass) {
    uint first_patch = quad_pass ? max(params[PARAM_FIRST_PATCH], triangle_count()) : params[PARAM_FIRST_PATCH];
    uint end = min(params[PARAM_END_PATCH], quad_pass ? patch_count() : triangle_count());
    bool uniform_ = uniform_pattern();
    // Split: a workgroup per leaf, its pattern's triangles after its own first vertex (as emit_vertices).
    bool split_ = split_pattern();
    uvec2 items = emit_items(split_, first_patch, end);
    for (uint item = items.x + gl_WorkGroupID.x; item < items.y; item += gl_NumWorkGroups.x) {
        uint leaf;
        uint t = item_patch(split_, item, leaf);
        if (t < first_patch || t >= end) continue;
        uint rec = t * PATCH_WORDS;
        uint count = split_ ? patches[leaf + NODE_TRIANGLES] : patches[rec + REC_TRIANGLE_COUNT];
        if (count == 0u) continue;
        Patch halves[2];
        uvec3 words[2];
        uvec2 counts_a = uvec2(0u, count);
        if (split_) {
            words[0] = uvec3(patches[leaf + NODE_PATTERN], patches[leaf + NODE_PATTERN + 1u], patches[leaf + NODE_PATTERN + 2u]);
            halves[0] = patch_zero();
        } else if (quad_pass) {
            counts_a = quad_halves(rec, halves, words);
        } else {
            halves[0] = uniform_ ? patch_zero() : record_patch(rec);
            words[0] = uniform_words(rec);
        }
        uint vfirst = split_ ? patches[leaf + NODE_FIRST_VERTEX] : patches[rec + REC_FIRST_VERTEX];
        uint tfirst = split_ ? patches[leaf + NODE_FIRST_TRIANGLE] : patches[rec + REC_FIRST_TRIANGLE];
        for (uint i = gl_LocalInvocationID.x; i < count; i += gl_WorkGroupSize.x) {
            uint side = i < counts_a.y ? 0u : 1u;
            uint local = side == 0u ? i : i - counts_a.y;
            uvec3 tri = uniform_ || split_ ? uniform_triangle(words[side], local) : patch_triangle(side == 0u ? halves[0] : halves[1], local);
            tri += uvec3(vfirst + (side == 0u ? 0u : counts_a.x));
            uint o = 3u * (tfirst + i);
            out_indices[o] = tri.x;
            out_indices[o + 1u] = tri.y;
            out_indices[o + 2u] = tri.z;
        }
    }
}

void ctess_emit_triangles() { emit_triangles(false); }
void ctess_emit_quad_triangles() { emit_triangles(true); }

void main() { {{ENTRY}}(); }
