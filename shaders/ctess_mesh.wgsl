// ctess mesh pipeline (both pattern families: CP and uniform density), WGSL compute. Generated from
// shaders/ctess_mesh.wgsl by gen/: the generator replaces the constants placeholder below with a block of `const`
// lines taken from the C++ definitions (gen/shaders/shader_layout.hpp and the table blob's layout; docs/shaders.md,
// "Generated constants"), so no layout number is written by hand here. Twenty-three entry points, the same steps
// as runtime/include/ctess/runtime/pipeline/mesh_pipeline.hpp and as shaders/ctess_mesh.comp.glsl, operation for
// operation; the CP lookups mirror runtime/include/ctess/runtime/cp/patch.hpp and cp_search.hpp (docs/shaders.md).

{{CONSTANTS}}

// params (rt::gpu::param_word): patch count, surface (0 flat, 1 PN, 2 Phong, 3 PN-AEN), alpha, factor scale, eye xyz,
// mesh vertex count, then the patch range [first, end) that the emit passes cover (hosts may emit in batches), the
// pattern (0 CP, 1 uniform), the quad count (the last patches; their 4 indices each follow the triangles' 3) and the
// quad rule
@group(0) @binding(0) var<storage, read> params: array<u32>;
@group(0) @binding(1) var<storage, read> tables: array<u32>;
@group(0) @binding(2) var<storage, read> mesh_vertices: array<f32>;
@group(0) @binding(3) var<storage, read> mesh_indices: array<u32>;
@group(0) @binding(4) var<storage, read_write> patches: array<u32>;
@group(0) @binding(5) var<storage, read_write> out_vertices: array<u32>;
@group(0) @binding(6) var<storage, read_write> out_indices: array<u32>;
// The welded output's area (rt::gpu::weld_word). WGSL atomics need atomic<u32>: weld_atomic is the same binding
// for ctess_weld_writers' atomicMax, the only entry point that uses it (one entry point may not use both).
@group(0) @binding(7) var<storage, read_write> weld: array<u32>;
@group(0) @binding(7) var<storage, read_write> weld_atomic: array<atomic<u32>>;

fn patch_count() -> u32 { return params[PARAM_PATCH_COUNT]; }
fn uniform_pattern() -> bool { return params[PARAM_PATTERN] == PATTERN_UNIFORM; }
fn split_pattern() -> bool { return params[PARAM_PATTERN] == PATTERN_UNIFORM_SPLIT; }

// ---- 64-bit helpers: x = (lo, hi) ----
fn mul_wide(a: u32, b: u32) -> vec2<u32> {
    let a0 = a & 0xFFFFu; let a1 = a >> 16u; let b0 = b & 0xFFFFu; let b1 = b >> 16u;
    let p00 = a0 * b0; let p01 = a0 * b1; let p10 = a1 * b0; let p11 = a1 * b1;
    let mid = (p00 >> 16u) + (p01 & 0xFFFFu) + (p10 & 0xFFFFu);
    return vec2<u32>((p00 & 0xFFFFu) | (mid << 16u), p11 + (p01 >> 16u) + (p10 >> 16u) + (mid >> 16u));
}
fn add_wide(x: vec2<u32>, y: u32) -> vec2<u32> {
    let lo = x.x + y;
    return vec2<u32>(lo, x.y + select(0u, 1u, lo < y));
}

// ---- tables ----
fn table_u16(base: u32, i: u32) -> u32 { return (tables[base + (i >> 1u)] >> ((i & 1u) * 16u)) & 0xFFFFu; }

// ---- CP line (constexpr/ctess/cp/line.hpp) ----
fn round_half_even_shift(n: u32, s: u32) -> u32 {
    if (s == 0u) { return n; }
    let q = n >> s; let r = n & ((1u << s) - 1u); let half_ = 1u << (s - 1u);
    return select(q, q + 1u, r > half_ || (r == half_ && (q & 1u) != 0u));
}
fn is_nan_bits(f: f32) -> bool { return (bitcast<u32>(f) & 0x7FFFFFFFu) > 0x7F800000u; }
// Factor -> (token, t16); NaN and f <= 1 give T0, f >= max the last token at t = 1.
fn line_state(f: f32) -> vec2<u32> {
    var f16: u32;
    if (is_nan_bits(f) || f <= 1.0) { f16 = LERP_ONE; }
    else if (f >= f32(MAX_FACTOR)) { f16 = MAX_FACTOR << 16u; }
    else { f16 = u32(round(f * f32(LERP_ONE))); }
    if (f16 <= LERP_ONE) { return vec2<u32>(0u, 0u); }
    for (var t = 1u; t < TOKENS; t++) {
        let range = tables[TOKEN_RANGE + t];
        let lo = range & 0xFFFFu; let hi = range >> 16u;
        if (f16 <= (hi << 16u)) { return vec2<u32>(t, round_half_even_shift(f16 - (lo << 16u), firstTrailingBit(hi - lo))); }
    }
    return vec2<u32>(TOKENS - 1u, LERP_ONE);
}

// ---- patch state (CpPatch) ----
struct Edge {
    points: u32, // u16 index of interior point 1
    t16: u32,
    segments: u32,
    half_step: u32,
}
struct Patch {
    e: array<Edge, 3>,
    type_: u32,
    c0: bool, c1: bool, c2: bool, copies: bool,
    column: u32, // column record index (s2 - 1) * shapes + s0 - 1
    c: u32,      // u16 index of C_0 in the column pool
    gap: u32,    // word index of the pair's first zipper word
    head: u32, n0: u32, n1: u32, n2: u32,
    a: f32, b: f32,
    copy_bias: u32, clamp_: u32, e1_offset: u32, unique_: u32, strips: u32, zipper: u32, vertices: u32, triangles: u32,
    tri_skip: array<vec2<u32>, SETUP_TRI_SKIPS>,
    tri_skips: u32,
    slot_skip: array<vec2<u32>, 4>,
    slot_skips: u32,
}

fn col(p: ptr<function, Patch>, x: i32) -> u32 { return table_u16(COLUMN_POOL, (*p).c + u32(x)); }

fn edge_point(e: Edge, i: u32) -> u32 {
    if (i == 0u) { return 0u; }
    if (i >= e.segments) { return FIXED_ONE; }
    let packed = table_u16(POINT, e.points + i - 1u);
    let fin = i32(packed & 0xFFu);
    let slide = packed >> 8u;
    let half_ = i32(e.half_step);
    let start = select(select(fin, fin - half_, slide == 2u), fin + half_, slide == 1u);
    return u32(start * 65536 + (fin - start) * i32(e.t16));
}

fn add_triangle_skip(p: ptr<function, Patch>, begin: u32, end: u32) {
    if (end > begin) {
        (*p).tri_skip[(*p).tri_skips] = vec2<u32>(begin, end - begin);
        (*p).tri_skips += 1u;
    }
}
fn add_slot_skip(p: ptr<function, Patch>, begin: u32, end: u32) {
    (*p).slot_skip[(*p).slot_skips] = vec2<u32>(begin, end - begin);
    (*p).slot_skips += 1u;
}

// The column record's pool index, head and first-guess coefficients (Type 2).
fn load_column_record(p: ptr<function, Patch>) {
    let rec = COLUMN_RECORD + 4u * (*p).column;
    (*p).c = tables[rec];
    (*p).head = tables[rec + 1u];
    (*p).a = bitcast<f32>(tables[rec + 2u]);
    (*p).b = bitcast<f32>(tables[rec + 3u]);
}

// The line of a line state (token, t16) from its token record; T0 reads as T1's shape at t = 0.
fn line_edge(s: vec2<u32>) -> Edge {
    let shape = select(s.x, 1u, s.x == 0u);
    let rec = tables[TOKEN_RECORD + 2u * (shape - 1u)];
    return Edge(rec & 0xFFFFu, select(s.y, 0u, s.x == 0u), rec >> 16u, tables[TOKEN_RECORD + 2u * (shape - 1u) + 1u]);
}

// The whole setup from the line states: the setup pass runs it once per patch.
fn patch_setup(s0: vec2<u32>, s1: vec2<u32>, s2: vec2<u32>) -> Patch {
    var p: Patch; // zero-initialised
    var s = array<vec2<u32>, 3>(s0, s1, s2);
    for (var k = 0u; k < 3u; k++) { p.e[k] = line_edge(s[k]); }
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
        var dropped_slots = 0u;
        if (p.c0) { add_slot_skip(&p, 1u, 3u); dropped_slots += 2u; }
        if (p.c1) { add_slot_skip(&p, 4u, 6u); dropped_slots += 2u; }
        if (p.c2) {
            let end = select(6u + p.n1, 7u + p.n1, p.c0);
            add_slot_skip(&p, 4u + p.n1, end);
            dropped_slots += end - (4u + p.n1);
        }
        if (p.c0 || p.c2) { add_triangle_skip(&p, 0u, 1u); }
        if (p.c0 || p.c1) { add_triangle_skip(&p, 1u, 2u); }
        if (p.c1 || p.c2) { add_triangle_skip(&p, 2u, 3u); }
        if (p.c0 && p.c2) { add_triangle_skip(&p, 3u, 4u); }
        if (p.c0 && p.c1) { add_triangle_skip(&p, 4u, 5u); }
        if (p.c1 && p.c2) { add_triangle_skip(&p, p.n1 + 3u, p.n1 + 4u); }
        if (p.c0 && p.c2) { add_triangle_skip(&p, p.n1 + 4u, p.n1 + 5u); }
        if (p.c0 && p.c2) { add_triangle_skip(&p, p.n1 + 5u, p.n1 + 6u); }
        var dropped = 0u;
        for (var k = 0u; k < p.tri_skips; k++) { dropped += p.tri_skip[k].y; }
        p.vertices = p.n1 + 7u - dropped_slots;
        p.triangles = p.n1 + 6u - dropped;
        return p;
    }
    p.type_ = 2u;
    let sh0 = select(s0.x, 1u, s0.x == 0u);
    let sh1 = select(s1.x, 1u, s1.x == 0u);
    let sh2 = select(s2.x, 1u, s2.x == 0u);
    p.column = (sh2 - 1u) * SHAPES + sh0 - 1u;
    load_column_record(&p);
    p.gap = GAP_WORD + table_u16(GAP_OFFSET, (sh1 - 1u) * SHAPES + sh0 - 1u);
    let last0 = edge_point(p.e[0], p.n0 - 1u);
    let v2 = edge_point(p.e[2], select(1u, p.n2 - 1u, sh2 >= 2u));
    p.clamp_ = min(last0, v2);
    let ch = col(&p, i32(p.head));
    p.strips = 2u * ch + 1u - 2u * p.head - p.n2;
    p.zipper = p.n0 + p.n1 - 1u;
    p.e1_offset = select(select(ch + p.n0 - p.head, p.n0, p.c2), p.n2, p.c0);
    p.unique_ = p.e1_offset + select(p.n1 + 1u, 2u, p.c1);
    p.copies = !p.c0 && !p.c2;
    let c1v = col(&p, 1);
    p.copy_bias = p.unique_ + 1u - c1v;
    let copies = select(0u, ch - c1v - (p.head - 1u), p.copies);
    let z = p.strips;
    let t1_fan = select(0u, tables[T1_LAST_FAN + sh0 - 1u], p.c1);
    if (p.c0) {
        add_triangle_skip(&p, 0u, 2u * p.n2 - 2u);
        if (p.c1) {
            add_triangle_skip(&p, z, z + 2u);
            add_triangle_skip(&p, z + 3u, z + 5u);
        } else {
            add_triangle_skip(&p, z, z + 1u);
            add_triangle_skip(&p, z + p.n1, z + p.n1 + 1u);
        }
    } else if (p.c2) {
        let r1 = col(&p, 2) - c1v;
        add_triangle_skip(&p, 0u, r1);
        add_triangle_skip(&p, r1 + 1u, p.strips);
        if (p.c1) {
            add_triangle_skip(&p, z, z + 1u);
            if (t1_fan == p.zipper - 1u) {
                add_triangle_skip(&p, z + p.n0, z + p.n0 + 2u);
            } else {
                add_triangle_skip(&p, z + t1_fan, z + t1_fan + 1u);
                add_triangle_skip(&p, z + p.zipper - 1u, z + p.zipper);
            }
        } else {
            add_triangle_skip(&p, z + p.zipper - 1u, z + p.zipper);
        }
    } else if (p.c1) {
        add_triangle_skip(&p, z, z + 1u);
        add_triangle_skip(&p, z + t1_fan, z + t1_fan + 1u);
    }
    var dropped = 0u;
    for (var k = 0u; k < p.tri_skips; k++) { dropped += p.tri_skip[k].y; }
    p.vertices = p.unique_ + copies;
    p.triangles = p.strips + p.zipper - dropped;
    return p;
}

// ---- reverse lookups (cp_search.hpp): y = C_x (vertex), C_x - x (copy), PS_x (strip) ----
const SEARCH_VERTEX: i32 = 0;
const SEARCH_COPY: i32 = 1;
const SEARCH_STRIP: i32 = 2;
fn search_y(p: ptr<function, Patch>, kind: i32, x: i32) -> i32 {
    if (kind == SEARCH_VERTEX) { return i32(col(p, x)); }
    if (kind == SEARCH_COPY) { return i32(col(p, x)) - x; }
    return i32(col(p, x)) + i32(col(p, x + 1)) - 2 * x - i32((*p).n2);
}
fn search_first_guess(alpha: f32, beta: f32, e: f32, h: u32) -> i32 {
    var d = alpha * alpha - 4.0 * beta * e;
    d = select(0.0, d, d > 0.0);
    var x = 2.0 * e / (alpha + sqrt(d));
    let last = f32(h - 1u);
    x = select(0.0, x, x > 0.0);
    x = select(last, x, x < last);
    return i32(x);
}
fn search_from(p: ptr<function, Patch>, kind: i32, h: u32, e: i32, x0: i32) -> u32 {
    let last = i32(h) - 1;
    var x = select(select(x0, last, x0 > last), 0, x0 < 0);
    let y0 = search_y(p, kind, x);
    let ahead = search_y(p, kind, x + 1) - y0;
    let behind = y0 - search_y(p, kind, select(0, x - 1, x > 0));
    let forward = e >= y0;
    let step_ = select(behind, ahead, forward);
    let den = select(1, step_, step_ > 0);
    let num = select((y0 - e) + den - 1, e - y0, forward);
    let q = num / den;
    let next_ = select(x - q, x + q, forward);
    x = select(select(next_, last, next_ > last), 0, next_ < 0);
    var i = u32(x);
    for (var k = 1u; k <= SEARCH_WINDOW; k++) {
        let at = x + i32(k);
        if (at <= last) {
            if (search_y(p, kind, at) <= e) { i += 1u; }
        }
    }
    return i;
}

// ---- vertices ----
fn e1_point(s: u32) -> vec2<u32> { return vec2<u32>(FIXED_ONE - s, s); }
fn column_point(p: ptr<function, Patch>, i: u32, j: u32) -> vec2<u32> {
    let v2 = edge_point((*p).e[2], j);
    if (i == 0u) { return vec2<u32>(0u, v2); }
    let u = edge_point((*p).e[0], i);
    let top = select(0u, (*p).clamp_ - u, (*p).clamp_ > u);
    return vec2<u32>(u, min(v2, top));
}
fn type1_center(t0: u32, t2: u32) -> vec2<u32> {
    let a = min(t0, LERP_ONE); let c = min(t2, LERP_ONE);
    // x = (a << 32) + (1 - a) c (1 - c);  y = (1 - a)(2^16 (a + c) - a c), all in units of 2^-32
    var x = mul_wide(LERP_ONE - a, c * (LERP_ONE - c));
    x.y += a;
    var y: vec2<u32>;
    if (a == LERP_ONE || c == LERP_ONE) { y = vec2<u32>(0u, LERP_ONE - a); } // the inner factor is 2^32
    else { y = mul_wide(LERP_ONE - a, 0u - (LERP_ONE - a) * (LERP_ONE - c)); }
    x = add_wide(x, 1u << 24u);
    y = add_wide(y, 1u << 24u);
    return vec2<u32>((x.y << 7u) | (x.x >> 25u), (y.y << 7u) | (y.x >> 25u));
}
fn slot_point(p: ptr<function, Patch>, s: u32) -> vec2<u32> {
    let n1 = (*p).n1;
    if (s == 0u) { return vec2<u32>(0u); }
    if (s <= 2u) { return vec2<u32>(edge_point((*p).e[0], s), 0u); }
    if (s <= 3u + n1) { return e1_point(edge_point((*p).e[1], s - 3u)); }
    if (s == 4u + n1) { return vec2<u32>(0u, edge_point((*p).e[2], 2u)); }
    if (s == 5u + n1) { return vec2<u32>(0u, edge_point((*p).e[2], 1u)); }
    return type1_center((*p).e[0].t16, (*p).e[2].t16);
}
fn col_start(p: ptr<function, Patch>, i: u32) -> u32 {
    if (i <= (*p).head) { return col(p, i32(i)); }
    return col(p, i32((*p).head)) + (i - (*p).head);
}
fn copy_point(p: ptr<function, Patch>, k: u32) -> vec2<u32> {
    let t = i32(k + col(p, 1)) - 1;
    let i = search_from(p, SEARCH_COPY, (*p).head, t, search_first_guess((*p).a - 1.0, (*p).b, f32(t), (*p).head));
    return column_point(p, i, u32(t - search_y(p, SEARCH_COPY, i32(i))));
}
fn type2_vertex(p: ptr<function, Patch>, v: u32) -> vec2<u32> {
    if (v >= (*p).unique_) { return copy_point(p, v - (*p).unique_); }
    if (v >= (*p).e1_offset) {
        let b = v - (*p).e1_offset;
        return e1_point(edge_point((*p).e[1], select(b, b * (*p).n1, (*p).c1)));
    }
    if ((*p).c0) { return column_point(p, 0u, v); }
    if ((*p).c2) { return column_point(p, v, 0u); }
    let ch = col(p, i32((*p).head));
    if (v >= ch) { return column_point(p, (*p).head + (v - ch), 0u); }
    let i = search_from(p, SEARCH_VERTEX, (*p).head, i32(v), search_first_guess((*p).a, (*p).b, f32(v), (*p).head));
    return column_point(p, i, v - col(p, i32(i)));
}
fn patch_vertex(p: ptr<function, Patch>, index: u32) -> vec2<u32> {
    var i = index;
    if (i >= (*p).vertices) { return vec2<u32>(0u); }
    if ((*p).type_ == 2u) { return type2_vertex(p, i); }
    if ((*p).type_ == 1u) {
        for (var k = 0u; k < (*p).slot_skips; k++) {
            if (i >= (*p).slot_skip[k].x) { i += (*p).slot_skip[k].y; }
        }
        return slot_point(p, i);
    }
    if (i == 0u) { return vec2<u32>(0u); }
    if (i == 1u) { return vec2<u32>(FIXED_ONE, 0u); }
    return vec2<u32>(0u, FIXED_ONE);
}

// ---- triangles ----
fn slot_index(p: ptr<function, Patch>, slot: u32) -> u32 {
    let n1 = (*p).n1;
    let c0 = (*p).c0; let c1 = (*p).c1; let c2 = (*p).c2;
    var s = slot;
    if (c1 && s == 4u) { s = 3u; }
    if (c1 && s == 5u) { s = 3u + n1; }
    if (c2 && s == 5u + n1) { s = 0u; }
    if (c2 && s == 4u + n1) { s = 3u + n1; }
    if (c0 && s == 1u) { s = 0u; }
    if (c0 && s == 2u) { s = 3u; }
    if (c0 && c2 && s == 6u + n1) { s = 0u; }
    var below = 0u;
    for (var k = 0u; k < (*p).slot_skips; k++) {
        if (s > (*p).slot_skip[k].x) { below += (*p).slot_skip[k].y; }
    }
    return s - below;
}
fn hexagon_slot(p: ptr<function, Patch>, index: u32) -> u32 {
    let n1 = (*p).n1;
    let m = n1 + 3u;
    let k = index % m;
    if (k == 0u) { return 1u; }
    if (k == 1u) { return 2u; }
    if (k < m - 2u) { return 3u + (k - 1u); }
    return select(5u + n1, 4u + n1, k == m - 2u);
}
fn type1_triangle(p: ptr<function, Patch>, r: u32) -> vec3<u32> {
    let n1 = (*p).n1;
    var a: u32; var b: u32; var c: u32;
    if (r == 0u) { a = 0u; b = 1u; c = 5u + n1; }
    else if (r == 1u) { a = 3u; b = 4u; c = 2u; }
    else if (r == 2u) { a = 3u + n1; b = 4u + n1; c = 2u + n1; }
    else { a = hexagon_slot(p, r - 2u); b = 6u + n1; c = hexagon_slot(p, r - 3u); }
    return vec3<u32>(slot_index(p, a), slot_index(p, b), slot_index(p, c));
}
fn e1_index(p: ptr<function, Patch>, b: u32) -> u32 {
    if ((*p).c1) { return (*p).e1_offset + select(1u, 0u, b <= 1u); }
    return (*p).e1_offset + b;
}
fn col_index(p: ptr<function, Patch>, i: u32, j: u32) -> u32 {
    if ((*p).c2) {
        if (i == 0u) { return select(0u, e1_index(p, (*p).n1), j == 2u); }
        return i;
    }
    if ((*p).c0) {
        if (i == 2u) { return e1_index(p, 0u); }
        if (i == 1u) { return j; }
    }
    return col_start(p, i) + j;
}
fn lhs_index(p: ptr<function, Patch>, a: u32) -> u32 {
    let i = (*p).n0 - 1u - a;
    return col_index(p, i, col_start(p, i + 1u) - col_start(p, i) - 1u);
}
fn type2_triangle(p: ptr<function, Patch>, r: u32) -> vec3<u32> {
    if (r < (*p).strips) {
        let alpha = 2.0 * (*p).a - 2.0 * (*p).b - 2.0;
        let model = f32(r) - ((*p).a - (*p).b - f32((*p).n2));
        let i = search_from(p, SEARCH_STRIP, (*p).head, i32(r), search_first_guess(alpha, 2.0 * (*p).b, model, (*p).head));
        let o = r - u32(search_y(p, SEARCH_STRIP, i32(i)));
        let nb = col(p, i32(i) + 2) - col(p, i32(i) + 1);
        if ((*p).copies && i >= 1u) {
            // First vertex A_j of column i >= 1 already provoked a triangle of strip i - 1: use its copy.
            let a = col(p, i32(i)); let b = col(p, i32(i) + 1);
            let first = a + (*p).copy_bias - i;
            if (o < 2u * (nb - 1u)) {
                let j = o >> 1u;
                if ((o & 1u) != 0u) { return vec3<u32>(b + j, b + j + 1u, a + j + 1u); }
                return vec3<u32>(first + j, b + j, a + j + 1u);
            }
            let j = o - (nb - 1u);
            return vec3<u32>(first + j, b + nb - 1u, a + j + 1u);
        }
        if (o < 2u * (nb - 1u)) {
            let j = o >> 1u;
            if ((o & 1u) != 0u) {
                return vec3<u32>(col_index(p, i + 1u, j), col_index(p, i + 1u, j + 1u), col_index(p, i, j + 1u));
            }
            return vec3<u32>(col_index(p, i, j), col_index(p, i + 1u, j), col_index(p, i, j + 1u));
        }
        let j = o - (nb - 1u);
        return vec3<u32>(col_index(p, i, j), col_index(p, i + 1u, nb - 1u), col_index(p, i, j + 1u));
    }
    let q = r - (*p).strips;
    let w = tables[(*p).gap + q / 16u];
    let bit = q % 16u;
    let bits = w & 0xFFFFu;
    let a = (w >> 16u) + countOneBits(bits & ((1u << bit) - 1u));
    let b = q - a;
    if (((bits >> bit) & 1u) != 0u) { return vec3<u32>(lhs_index(p, a + 1u), lhs_index(p, a), e1_index(p, b)); }
    return vec3<u32>(e1_index(p, b + 1u), lhs_index(p, a), e1_index(p, b));
}
fn patch_triangle(p: ptr<function, Patch>, index: u32) -> vec3<u32> {
    var t = index;
    if (t >= (*p).triangles) { return vec3<u32>(0u); }
    for (var k = 0u; k < (*p).tri_skips; k++) {
        if (t >= (*p).tri_skip[k].x) { t += (*p).tri_skip[k].y; }
    }
    if ((*p).type_ == 2u) { return type2_triangle(p, t); }
    if ((*p).type_ == 1u) { return type1_triangle(p, t); }
    return vec3<u32>(0u, 1u, 2u);
}

// ---- mesh input ----
fn mesh_position(v: u32) -> vec3<f32> {
    let o = v * MESH_VERTEX_FLOATS;
    return vec3<f32>(mesh_vertices[o], mesh_vertices[o + 1u], mesh_vertices[o + 2u]);
}
struct Corner {
    position: vec3<f32>,
    normal: vec3<f32>,
    uv: vec2<f32>,
    index: u32,
}
fn mesh_corner(v: u32) -> Corner {
    let o = v * MESH_VERTEX_FLOATS;
    return Corner(vec3<f32>(mesh_vertices[o], mesh_vertices[o + 1u], mesh_vertices[o + 2u]),
                  vec3<f32>(mesh_vertices[o + 3u], mesh_vertices[o + 4u], mesh_vertices[o + 5u]),
                  vec2<f32>(mesh_vertices[o + 6u], mesh_vertices[o + 7u]), v);
}
fn base_triangle(t: u32) -> vec3<u32> {
    return vec3<u32>(mesh_indices[3u * t], mesh_indices[3u * t + 1u], mesh_indices[3u * t + 2u]);
}
fn base_triangle_valid(w: vec3<u32>) -> bool {
    let n = params[PARAM_MESH_VERTEX_COUNT];
    return w.x < n && w.y < n && w.z < n;
}
// Patches are the base triangles, then the PARAM_QUAD_COUNT quads (4 indices each after the triangles' 3).
fn triangle_count() -> u32 { return patch_count() - params[PARAM_QUAD_COUNT]; }
fn base_quad(q: u32) -> vec4<u32> {
    let o = 3u * triangle_count() + 4u * q;
    return vec4<u32>(mesh_indices[o], mesh_indices[o + 1u], mesh_indices[o + 2u], mesh_indices[o + 3u]);
}
fn base_quad_valid(w: vec4<u32>) -> bool {
    let n = params[PARAM_MESH_VERTEX_COUNT];
    return w.x < n && w.y < n && w.z < n && w.w < n;
}

// ---- tess factors (tess_factor.hpp) ----
fn dot3(a: vec3<f32>, b: vec3<f32>) -> f32 { return a.x * b.x + a.y * b.y + a.z * b.z; }
fn edge_tess_factor(a: vec3<f32>, b: vec3<f32>, eye: vec3<f32>, factor_scale: f32) -> f32 {
    let d = b - a;
    let m = 0.5 * (a + b);
    let e = m - eye;
    let len2 = dot3(d, d);
    let dist2 = dot3(e, e);
    return sqrt(len2 * (1.0 / dist2)) * factor_scale;
}

// ---- surface (surface_eval.hpp) ----
fn normalize_or_zero(a: vec3<f32>) -> vec3<f32> {
    let len2 = dot3(a, a);
    if (!(len2 > 0.0)) { return vec3<f32>(0.0); }
    return (1.0 / sqrt(len2)) * a;
}
// PN edge control point b_ij from position pi, normal ni and the far end pj (eval.cpp's pn_control).
fn pn_control(pi: vec3<f32>, ni: vec3<f32>, pj: vec3<f32>) -> vec3<f32> {
    let w = dot3(pj - pi, ni);
    return (1.0 / 3.0) * ((2.0 * pi + pj) - w * ni);
}
fn pn_edge_point(i: Corner, j: Corner) -> vec3<f32> { return pn_control(i.position, i.normal, j.position); }
fn pn_edge_normal(i: Corner, j: Corner) -> vec3<f32> {
    let d = j.position - i.position;
    let len2 = dot3(d, d);
    var v = 0.0;
    if (len2 > 0.0) { v = 2.0 * dot3(d, i.normal + j.normal) * (1.0 / len2); }
    return normalize_or_zero((i.normal + j.normal) - v * d);
}
fn phong_project(q: vec3<f32>, i: Corner) -> vec3<f32> { return q - dot3(q - i.position, i.normal) * i.normal; }
fn blend(flat_: vec3<f32>, curved: vec3<f32>, alpha: f32) -> vec3<f32> { return (1.0 - alpha) * flat_ + alpha * curved; }

struct SurfacePoint {
    position: vec3<f32>,
    normal: vec3<f32>,
    uv: vec2<f32>,
}
// The PN cubic at weights (w0, w1, w2) from its six edge control points b = {b210, b120, b021, b012, b102, b201}
// (eval.cpp's pn_cubic; Vlachos et al. 2001): the position and the quadratic normal field, in a SurfacePoint whose
// uv is unused. PN and PN-AEN differ only in b.
fn pn_cubic(c0: Corner, c1: Corner, c2: Corner, b: array<vec3<f32>, 6>, w0: f32, w1: f32, w2: f32) -> SurfacePoint {
    let e = (1.0 / 6.0) * (((b[0] + b[1]) + (b[2] + b[3])) + (b[4] + b[5]));
    let v = (1.0 / 3.0) * ((c0.position + c1.position) + c2.position);
    let b111 = e + 0.5 * (e - v);
    let q0 = w0 * w0; let q1 = w1 * w1; let q2 = w2 * w2;
    let pn = (q0 * w0) * c0.position + (q1 * w1) * c1.position + (q2 * w2) * c2.position + (3.0 * q0 * w1) * b[0] +
             (3.0 * q1 * w0) * b[1] + (3.0 * q1 * w2) * b[2] + (3.0 * q2 * w1) * b[3] + (3.0 * q2 * w0) * b[4] +
             (3.0 * q0 * w2) * b[5] + (6.0 * w0 * w1 * w2) * b111;
    let nn = q0 * c0.normal + q1 * c1.normal + q2 * c2.normal + (w0 * w1) * pn_edge_normal(c0, c1) +
             (w1 * w2) * pn_edge_normal(c1, c2) + (w2 * w0) * pn_edge_normal(c2, c0);
    return SurfacePoint(pn, nn, vec2<f32>(0.0));
}
fn edge_surface(a: Corner, b: Corner, s: f32, t: f32, surface: u32, alpha: f32) -> SurfacePoint {
    let flat_p = s * a.position + t * b.position;
    let flat_n = s * a.normal + t * b.normal;
    let uv = vec2<f32>(s * a.uv.x + t * b.uv.x, s * a.uv.y + t * b.uv.y);
    var pos = flat_p;
    var n = flat_n;
    if (surface == SURFACE_PN) {
        let bab = pn_edge_point(a, b); let bba = pn_edge_point(b, a);
        let s2 = s * s; let t2 = t * t;
        let pn = (s2 * s) * a.position + (3.0 * s2 * t) * bab + (3.0 * s * t2) * bba + (t2 * t) * b.position;
        let nn = s2 * a.normal + t2 * b.normal + (s * t) * pn_edge_normal(a, b);
        pos = blend(flat_p, pn, alpha);
        n = blend(flat_n, nn, alpha);
    } else if (surface == SURFACE_PHONG) {
        let ph = (s * s) * a.position + (t * t) * b.position +
                 (s * t) * (phong_project(b.position, a) + phong_project(a.position, b));
        pos = blend(flat_p, ph, alpha);
    }
    return SurfacePoint(pos, normalize_or_zero(n), uv);
}
fn interior_surface(c0: Corner, c1: Corner, c2: Corner, w0: f32, w1: f32, w2: f32, surface: u32, alpha: f32) -> SurfacePoint {
    let flat_p = w0 * c0.position + w1 * c1.position + w2 * c2.position;
    let flat_n = w0 * c0.normal + w1 * c1.normal + w2 * c2.normal;
    let uv = vec2<f32>(w0 * c0.uv.x + w1 * c1.uv.x + w2 * c2.uv.x, w0 * c0.uv.y + w1 * c1.uv.y + w2 * c2.uv.y);
    var pos = flat_p;
    var n = flat_n;
    if (surface == SURFACE_PN) {
        let pn = pn_cubic(c0, c1, c2, array<vec3<f32>, 6>(pn_edge_point(c0, c1), pn_edge_point(c1, c0),
                          pn_edge_point(c1, c2), pn_edge_point(c2, c1), pn_edge_point(c2, c0), pn_edge_point(c0, c2)),
                          w0, w1, w2);
        pos = blend(flat_p, pn.position, alpha);
        n = blend(flat_n, pn.normal, alpha);
    } else if (surface == SURFACE_PHONG) {
        let ph = (w0 * w0) * c0.position + (w1 * w1) * c1.position + (w2 * w2) * c2.position +
                 (w0 * w1) * (phong_project(c1.position, c0) + phong_project(c0.position, c1)) +
                 (w1 * w2) * (phong_project(c2.position, c1) + phong_project(c1.position, c2)) +
                 (w2 * w0) * (phong_project(c0.position, c2) + phong_project(c2.position, c0));
        pos = blend(flat_p, ph, alpha);
    }
    return SurfacePoint(pos, normalize_or_zero(n), uv);
}
fn fixed_weight(w: u32) -> f32 { return f32(w) * (1.0 / f32(FIXED_ONE)); }
fn evaluate_surface(corners: array<Corner, 3>, weights: array<u32, 3>, surface: u32, alpha: f32) -> SurfacePoint {
    var c = corners;
    var w = weights;
    for (var k = 0u; k < 3u; k++) {
        if (w[k] == FIXED_ONE) { return SurfacePoint(c[k].position, normalize_or_zero(c[k].normal), c[k].uv); }
    }
    for (var k = 0u; k < 3u; k++) {
        if (w[k] != 0u) { continue; }
        let i = (k + 1u) % 3u; let j = (k + 2u) % 3u;
        let i_first = c[i].index < c[j].index || (c[i].index == c[j].index && i < j);
        let a = select(j, i, i_first); let b = select(i, j, i_first);
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
// normals (at_from, at_to).
struct EdgeNormals {
    at_from: vec3<f32>,
    at_to: vec3<f32>,
}
fn same_bits(a: vec3<f32>, b: vec3<f32>) -> bool { return all(bitcast<vec3<u32>>(a) == bitcast<vec3<u32>>(b)); }
fn adjacent_normals(t: u32, e: u32, from_: Corner, to_: Corner) -> EdgeNormals {
    let own = EdgeNormals(from_.normal, to_.normal);
    // With displacement, binding 3 holds the adjacency only when its flag says so (the texels follow).
    if ((params[PARAM_DISPLACEMENT_FLAGS] & (DISPLACEMENT_ON | DISPLACEMENT_ADJACENCY)) == DISPLACEMENT_ON) { return own; }
    let at = 3u * triangle_count() + 4u * params[PARAM_QUAD_COUNT] + 12u * t + 3u + 2u * e;
    if (at + 1u >= arrayLength(&mesh_indices)) { return own; }
    let i = mesh_indices[at]; let j = mesh_indices[at + 1u];
    let n = params[PARAM_MESH_VERTEX_COUNT];
    if (i >= n || j >= n) { return own; }
    let v0 = mesh_corner(i); let v1 = mesh_corner(j);
    if (same_bits(v0.position, from_.position) && same_bits(v1.position, to_.position)) {
        return EdgeNormals(v0.normal, v1.normal);
    }
    if (same_bits(v1.position, from_.position) && same_bits(v0.position, to_.position)) {
        return EdgeNormals(v1.normal, v0.normal);
    }
    return own;
}
// The mean of the PN control points built with both sides' normals: either side gets the same bits (x + y = y + x).
fn aen_control(pi: vec3<f32>, ni: vec3<f32>, ni_adj: vec3<f32>, pj: vec3<f32>) -> vec3<f32> {
    return 0.5 * (pn_control(pi, ni, pj) + pn_control(pi, ni_adj, pj));
}
// Positions ordered by their bits as unsigned integers, x then y then z (split-normal sides differ in index).
fn position_before(a: vec3<f32>, b: vec3<f32>) -> bool {
    let ka = bitcast<vec3<u32>>(a); let kb = bitcast<vec3<u32>>(b);
    for (var k = 0u; k < 3u; k++) {
        if (ka[k] != kb[k]) { return ka[k] < kb[k]; }
    }
    return false;
}
fn aen_first(a: Corner, wa: u32, b: Corner, wb: u32) -> bool {
    if (same_bits(a.position, b.position)) { return wa >= wb; }
    return position_before(a.position, b.position);
}
// x + 0.0f of the CPU (-0.0 becomes +0.0) on the bits: a shader compiler may fold an add of zero away.
fn without_negative_zero(p: vec3<f32>) -> vec3<f32> {
    let b = bitcast<vec3<u32>>(p);
    return bitcast<vec3<f32>>(select(b, vec3<u32>(0u), b == vec3<u32>(0x80000000u)));
}
// A PN-AEN edge point: a first (aen_first), t measured from a; a_adj, b_adj the neighbour's normals at a and b.
fn aen_edge_surface(a: Corner, a_adj: vec3<f32>, b: Corner, b_adj: vec3<f32>, s: f32, t: f32, alpha: f32) -> SurfacePoint {
    let flat_p = s * a.position + t * b.position;
    let flat_n = s * a.normal + t * b.normal;
    let uv = vec2<f32>(s * a.uv.x + t * b.uv.x, s * a.uv.y + t * b.uv.y);
    let bab = aen_control(a.position, a.normal, a_adj, b.position);
    let bba = aen_control(b.position, b.normal, b_adj, a.position);
    let s2 = s * s; let t2 = t * t;
    let pn = (s2 * s) * a.position + (3.0 * s2 * t) * bab + (3.0 * s * t2) * bba + (t2 * t) * b.position;
    let nn = s2 * a.normal + t2 * b.normal + (s * t) * pn_edge_normal(a, b);
    return SurfacePoint(without_negative_zero(blend(flat_p, pn, alpha)), normalize_or_zero(blend(flat_n, nn, alpha)), uv);
}
// en[e]: the neighbour's normals on edge e (adjacent_normals).
fn evaluate_surface_aen(corners: array<Corner, 3>, edges: array<EdgeNormals, 3>, weights: array<u32, 3>, alpha: f32) -> SurfacePoint {
    var c = corners;
    var en = edges;
    var w = weights;
    for (var k = 0u; k < 3u; k++) {
        if (w[k] == FIXED_ONE) {
            return SurfacePoint(without_negative_zero(c[k].position), normalize_or_zero(c[k].normal), c[k].uv);
        }
    }
    for (var k = 0u; k < 3u; k++) {
        if (w[k] != 0u) { continue; }
        let i = (k + 1u) % 3u; let j = (k + 2u) % 3u; // the edge opposite corner k is edge i: c[i] -> c[j]
        if (aen_first(c[i], w[i], c[j], w[j])) {
            return aen_edge_surface(c[i], en[i].at_from, c[j], en[i].at_to, fixed_weight(w[i]), fixed_weight(w[j]), alpha);
        }
        return aen_edge_surface(c[j], en[i].at_to, c[i], en[i].at_from, fixed_weight(w[j]), fixed_weight(w[i]), alpha);
    }
    let w0 = fixed_weight(w[0]); let w1 = fixed_weight(w[1]); let w2 = fixed_weight(w[2]);
    let flat_p = w0 * c[0].position + w1 * c[1].position + w2 * c[2].position;
    let flat_n = w0 * c[0].normal + w1 * c[1].normal + w2 * c[2].normal;
    let uv = vec2<f32>(w0 * c[0].uv.x + w1 * c[1].uv.x + w2 * c[2].uv.x, w0 * c[0].uv.y + w1 * c[1].uv.y + w2 * c[2].uv.y);
    let pn = pn_cubic(c[0], c[1], c[2],
                      array<vec3<f32>, 6>(aen_control(c[0].position, c[0].normal, en[0].at_from, c[1].position),
                                          aen_control(c[1].position, c[1].normal, en[0].at_to, c[0].position),
                                          aen_control(c[1].position, c[1].normal, en[1].at_from, c[2].position),
                                          aen_control(c[2].position, c[2].normal, en[1].at_to, c[1].position),
                                          aen_control(c[2].position, c[2].normal, en[2].at_from, c[0].position),
                                          aen_control(c[0].position, c[0].normal, en[2].at_to, c[2].position)),
                      w0, w1, w2);
    return SurfacePoint(without_negative_zero(blend(flat_p, pn.position, alpha)),
                        normalize_or_zero(blend(flat_n, pn.normal, alpha)), uv);
}

// ---- displacement (displace.cpp and height_map.cpp, docs/algorithm.md §8) ----
// Operation for operation as the CPU's (compiled with -ffp-contract=off; WGSL has no `precise`, so a driver may
// fuse: docs/shaders.md, "Displacement", gives the bound). Params: PARAM_DISPLACEMENT_* and PARAM_HEIGHT_MAP_*;
// the directions (3 floats per mesh vertex) follow the mesh vertices in binding 2, the texels (f32 bits,
// row-major, row 0 at v = 0) follow the indices and the adjacency in binding 3.
fn displacement_on() -> bool { return (params[PARAM_DISPLACEMENT_FLAGS] & DISPLACEMENT_ON) != 0u; }
fn displacement_adjacency() -> bool { return (params[PARAM_DISPLACEMENT_FLAGS] & DISPLACEMENT_ADJACENCY) != 0u; }
// Vector displacement (§8.7): RGB texels (3 floats each) and the tangents after the directions in binding 2.
fn displacement_vector_mode() -> bool { return (params[PARAM_DISPLACEMENT_FLAGS] & DISPLACEMENT_VECTOR) != 0u; }
fn param_float(w: u32) -> f32 { return bitcast<f32>(params[w]); }
fn finite_bits(f: f32) -> bool { return (bitcast<u32>(f) & 0x7FFFFFFFu) < 0x7F800000u; }
// Binding 3's adjacency starts after the indices; its texels after the adjacency when the host uploaded it.
fn adjacency_base() -> u32 { return 3u * triangle_count() + 4u * params[PARAM_QUAD_COUNT]; }
fn texel_base() -> u32 {
    return adjacency_base() + select(0u, 12u * (triangle_count() + 2u * params[PARAM_QUAD_COUNT]), displacement_adjacency());
}
// A texel past the end of binding 3 (a host that uploaded fewer) reads 0: never out of bounds.
fn texel(i: u32) -> f32 {
    let at = texel_base() + i;
    if (at >= arrayLength(&mesh_indices)) { return 0.0; }
    return bitcast<f32>(mesh_indices[at]);
}
struct TexelCoordinate {
    base: i32,
    fraction: f32,
}
// height_map.cpp's texel_coordinate: the integer part (in [-1, n - 1]) and the fraction.
fn texel_coordinate(u: f32, n: u32, repeat_: bool) -> TexelCoordinate {
    var x = u - floor(u);
    if (!repeat_) { x = select(select(u, 1.0, u > 1.0), 0.0, u < 0.0); }
    let y = x * f32(n) - 0.5;
    let base = floor(y);
    return TexelCoordinate(i32(base), y - base);
}
fn texel_address(i: i32, n: u32, repeat_: bool) -> u32 {
    if (repeat_) {
        if (i < 0) { return n - 1u; }
        return select(u32(i), u32(i) - n, u32(i) >= n);
    }
    if (i < 0) { return 0u; }
    return select(u32(i), n - 1u, u32(i) >= n);
}
// height_map.cpp's footprint: the four texels (x0, y0), (x1, y0), (x0, y1), (x1, y1) as texel numbers and the
// weights' fractions; ok false for an empty map or a NaN or infinite coordinate. An address mode other than repeat
// reads as clamp.
struct Footprint {
    ok: bool,
    at: vec4<u32>,
    fraction: vec2<f32>,
}
fn texel_footprint(u: f32, v: f32) -> Footprint {
    var f: Footprint;
    let width = params[PARAM_HEIGHT_MAP_WIDTH]; let height = params[PARAM_HEIGHT_MAP_HEIGHT];
    if (width == 0u || height == 0u) { return f; }
    if (!finite_bits(u) || !finite_bits(v)) { return f; }
    let repeat_ = params[PARAM_HEIGHT_MAP_ADDRESS] == ADDRESS_REPEAT;
    let cx = texel_coordinate(u, width, repeat_);
    let cy = texel_coordinate(v, height, repeat_);
    let x0 = texel_address(cx.base, width, repeat_); let x1 = texel_address(cx.base + 1, width, repeat_);
    let row0 = texel_address(cy.base, height, repeat_) * width; let row1 = texel_address(cy.base + 1, height, repeat_) * width;
    f.ok = true;
    f.at = vec4<u32>(row0 + x0, row0 + x1, row1 + x0, row1 + x1);
    f.fraction = vec2<f32>(cx.fraction, cy.fraction);
    return f;
}
// Channel `channel` of texels of `channels` floats (height_map.cpp's blend): the operations of the one-channel sample.
fn texel_blend(f: Footprint, channels: u32, channel: u32) -> f32 {
    let fx = f.fraction.x; let fy = f.fraction.y;
    let top = (1.0 - fx) * texel(channels * f.at.x + channel) + fx * texel(channels * f.at.y + channel);
    let bottom = (1.0 - fx) * texel(channels * f.at.z + channel) + fx * texel(channels * f.at.w + channel);
    return (1.0 - fy) * top + fy * bottom;
}
// sample_bilinear: texel centres at ((i + 0.5) / width, (j + 0.5) / height); an empty map or a NaN or infinite
// coordinate gives 0.
fn sample_bilinear(u: f32, v: f32) -> f32 {
    let f = texel_footprint(u, v);
    if (!f.ok) { return 0.0; }
    return texel_blend(f, 1u, 0u);
}
// sample_bilinear_rgb (§8.7): channels 0, 1, 2 of 3-float texels, each by sample_bilinear's operations; an empty
// map or a NaN or infinite coordinate gives (0, 0, 0).
fn sample_bilinear_rgb(u: f32, v: f32) -> vec3<f32> {
    let f = texel_footprint(u, v);
    if (!f.ok) { return vec3<f32>(0.0); }
    return vec3<f32>(texel_blend(f, 3u, 0u), texel_blend(f, 3u, 1u), texel_blend(f, 3u, 2u));
}
// scale * (texel * factor + offset)
fn displacement_height(u: f32, v: f32) -> f32 {
    let t = sample_bilinear(u, v);
    return param_float(PARAM_DISPLACEMENT_SCALE) * (t * param_float(PARAM_DISPLACEMENT_FACTOR) + param_float(PARAM_DISPLACEMENT_OFFSET));
}
// Vector mode's displacement_vector (§8.7): scale * (texel * factor + offset) per channel.
fn displacement_vector(u: f32, v: f32) -> vec3<f32> {
    let t = sample_bilinear_rgb(u, v);
    let scale = param_float(PARAM_DISPLACEMENT_SCALE); let factor = param_float(PARAM_DISPLACEMENT_FACTOR);
    let offset = param_float(PARAM_DISPLACEMENT_OFFSET);
    return vec3<f32>(scale * (t.x * factor + offset), scale * (t.y * factor + offset), scale * (t.z * factor + offset));
}
// displaced_edge_factor (§8.4): the factor of edge a -> b grown by the bound, as if displacement lengthened it
// at both ends.
fn displaced_edge_factor(factor: f32, a: vec3<f32>, b: vec3<f32>) -> f32 {
    let bound = param_float(PARAM_DISPLACEMENT_FACTOR_BOUND);
    if (!displacement_on() || !(bound > 0.0)) { return factor; }
    let e = b - a;
    let len = sqrt(dot3(e, e));
    if (!(len > 0.0)) { return factor; }
    return factor * (1.0 + 2.0 * bound / len);
}
fn cross3(a: vec3<f32>, b: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
// What one patch's displacement reads (DisplacementPatch): per corner the dominant vertex's uv and direction (and
// in vector mode its tangent and bitangent), per edge the dominant edge's uvs at both ends (xy, zw), the own
// corners' positions and uvs; 3 or 4 corners.
struct DisplacementPatch {
    corners: u32,
    corner_uv: array<vec2<f32>, 4>,
    direction: array<vec3<f32>, 4>,
    tangent: array<vec3<f32>, 4>,
    bitangent: array<vec3<f32>, 4>,
    edge_uv: array<vec4<f32>, 4>,
    position: array<vec3<f32>, 4>,
    own_uv: array<vec2<f32>, 4>,
}
fn mesh_uv(v: u32) -> vec2<f32> { return vec2<f32>(mesh_vertices[v * MESH_VERTEX_FLOATS + 6u], mesh_vertices[v * MESH_VERTEX_FLOATS + 7u]); }
// A corner's dominant vertex (§8.2): adjacency slot 9 + corner where the host uploaded the adjacency, else the
// vertex itself; one outside the mesh or at another position: the vertex itself.
fn dominant_vertex(v: u32, face: u32, slot: u32) -> u32 {
    var d = v;
    if (displacement_adjacency()) { d = mesh_indices[adjacency_base() + 12u * face + 9u + slot]; }
    if (d < params[PARAM_MESH_VERTEX_COUNT] && same_bits(mesh_position(d), mesh_position(v))) { return d; }
    return v;
}
// Displacement::directions (after the mesh vertices), or the vertex normal, normalised.
fn vertex_direction(v: u32) -> vec3<f32> {
    var o = v * MESH_VERTEX_FLOATS + 3u;
    if ((params[PARAM_DISPLACEMENT_FLAGS] & DISPLACEMENT_DIRECTIONS) != 0u) {
        o = params[PARAM_MESH_VERTEX_COUNT] * MESH_VERTEX_FLOATS + 3u * v;
    }
    return normalize_or_zero(vec3<f32>(mesh_vertices[o], mesh_vertices[o + 1u], mesh_vertices[o + 2u]));
}
// Displacement::tangents (vector mode, glTF TANGENT's layout): 4 floats per mesh vertex after the mesh vertices and
// the directions in binding 2. A tangent past the end of binding 2 (a host that uploaded fewer) reads (0, 0, 0, 1).
fn vertex_tangent(v: u32) -> vec4<f32> {
    let n = params[PARAM_MESH_VERTEX_COUNT];
    let o = n * MESH_VERTEX_FLOATS + select(0u, 3u * n, (params[PARAM_DISPLACEMENT_FLAGS] & DISPLACEMENT_DIRECTIONS) != 0u) + 4u * v;
    if (o + 3u >= arrayLength(&mesh_vertices)) { return vec4<f32>(0.0, 0.0, 0.0, 1.0); }
    return vec4<f32>(mesh_vertices[o], mesh_vertices[o + 1u], mesh_vertices[o + 2u], mesh_vertices[o + 3u]);
}
// displacement_patch: a patch of `corners` (3 or 4) vertices w, corner k at slot corner_slot[k] of adjacency face
// corner_face[k], edge k (corner k -> k + 1) at edge slot edge_slot[k] of face edge_face[k] (PatchFaces).
// faces false: no neighbours (each corner its own dominant vertex, each edge its own dominant edge).
fn displacement_patch(corners: u32, w_in: array<u32, 4>, corner_face_in: array<u32, 4>, corner_slot_in: array<u32, 4>,
                      edge_face_in: array<u32, 4>, edge_slot_in: array<u32, 4>, vector_: bool, faces: bool) -> DisplacementPatch {
    var dp: DisplacementPatch;
    dp.corners = corners;
    var w = w_in; var corner_face = corner_face_in; var corner_slot = corner_slot_in;
    var edge_face = edge_face_in; var edge_slot = edge_slot_in;
    let n = params[PARAM_MESH_VERTEX_COUNT];
    for (var k = 0u; k < corners; k++) {
        var dom = w[k];
        if (faces) { dom = dominant_vertex(w[k], corner_face[k], corner_slot[k]); }
        dp.position[k] = mesh_position(w[k]);
        dp.own_uv[k] = mesh_uv(w[k]);
        dp.corner_uv[k] = mesh_uv(dom);
        dp.direction[k] = vertex_direction(dom);
        if (vector_) {
            // The dominant vertex's frame (§8.7): T made orthogonal to the direction N, B = cross(N, T) w.
            let t = vertex_tangent(dom);
            let nd = dp.direction[k];
            dp.tangent[k] = normalize_or_zero(t.xyz - dot3(t.xyz, nd) * nd);
            dp.bitangent[k] = select(1.0, -1.0, t.w < 0.0) * cross3(nd, dp.tangent[k]);
        }
    }
    // The dominant edge: of the own edge and the neighbour's (slots 3-8, paired by position), the one whose
    // vertices, taken in position order, are lexicographically smaller; the neighbour picks the same one.
    for (var k = 0u; k < corners; k++) {
        let a = w[k]; let b = w[(k + 1u) % corners];
        var pick = vec2<u32>(a, b);
        if (faces && displacement_adjacency()) {
            let at = adjacency_base() + 12u * edge_face[k] + 3u + 2u * edge_slot[k];
            var c = mesh_indices[at]; var e = mesh_indices[at + 1u];
            if (c < n && e < n) {
                if (!same_bits(mesh_position(c), mesh_position(a))) { let x = c; c = e; e = x; }
                if (same_bits(mesh_position(c), mesh_position(a)) && same_bits(mesh_position(e), mesh_position(b))) {
                    let a_first = !position_before(mesh_position(b), mesh_position(a));
                    let own_key = select(vec2<u32>(b, a), vec2<u32>(a, b), a_first);
                    let adj_key = select(vec2<u32>(e, c), vec2<u32>(c, e), a_first);
                    if (adj_key.x < own_key.x || (adj_key.x == own_key.x && adj_key.y < own_key.y)) { pick = vec2<u32>(c, e); }
                }
            }
        }
        dp.edge_uv[k] = vec4<f32>(mesh_uv(pick.x), mesh_uv(pick.y));
    }
    return dp;
}
// bend_normal (§8.3): the normal bent by the height's central differences hu, hv along the tangents tu, tv.
fn bend_normal(normal: vec3<f32>, tu: vec3<f32>, tv: vec3<f32>, hu: f32, hv: f32) -> vec3<f32> {
    let n = normalize_or_zero(normal);
    if (!(dot3(n, n) > 0.0)) { return normal; }
    let pu = tu - dot3(tu, n) * n;
    let pv = tv - dot3(tv, n) * n;
    let j = dot3(cross3(pu, pv), n);
    if (!(j != 0.0) || !finite_bits(hu) || !finite_bits(hv)) { return normal; }
    let m = (j * n + hv * cross3(pu, n)) + hu * cross3(n, pv);
    let bent = normalize_or_zero(select(1.0, -1.0, j < 0.0) * m);
    if (dot3(bent, bent) > 0.0) { return bent; }
    return normal;
}
// The own uv at triangle parameter (a, b) = (w1, w2), and at quad parameter (s, t) (bilinear).
fn tri_own_uv(dp: DisplacementPatch, a: f32, b: f32) -> vec2<f32> {
    let c = (1.0 - a) - b;
    return vec2<f32>((c * dp.own_uv[0].x + a * dp.own_uv[1].x) + b * dp.own_uv[2].x,
                     (c * dp.own_uv[0].y + a * dp.own_uv[1].y) + b * dp.own_uv[2].y);
}
fn quad_own_uv(dp: DisplacementPatch, s: f32, t: f32) -> vec2<f32> {
    let w = array<f32, 4>((1.0 - s) * (1.0 - t), s * (1.0 - t), s * t, (1.0 - s) * t);
    return vec2<f32>(((w[0] * dp.own_uv[0].x + w[1] * dp.own_uv[1].x) + w[2] * dp.own_uv[2].x) + w[3] * dp.own_uv[3].x,
                     ((w[0] * dp.own_uv[0].y + w[1] * dp.own_uv[1].y) + w[2] * dp.own_uv[2].y) + w[3] * dp.own_uv[3].y);
}
// The height at the own uv of triangle parameter (a, b) = (w1, w2).
fn tri_uv_height(dp: DisplacementPatch, a: f32, b: f32) -> f32 {
    let uv = tri_own_uv(dp, a, b);
    return displacement_height(uv.x, uv.y);
}
// ---- vector displacement (displace.cpp's vector mode, docs/algorithm.md §8.7) ----
// A tangent frame: t along +u, b, n the displacement direction.
struct Frame {
    t: vec3<f32>,
    b: vec3<f32>,
    n: vec3<f32>,
}
// Position + x T + y B + z N, the offset summed first (the same operations from every face).
fn move_vector(position: vec3<f32>, moved_by: vec3<f32>, f: Frame) -> vec3<f32> {
    return position + ((moved_by.x * f.t + moved_by.y * f.b) + moved_by.z * f.n);
}
// interpolated_frame: the frame field at weights w of corners corner[0..count-1], each axis summed from zero in
// corner order and normalised as the directions are (zero stays zero).
fn interpolated_frame(dp_in: DisplacementPatch, corner_in: array<u32, 4>, w_in: array<f32, 4>, count: u32) -> Frame {
    var dp = dp_in; var corner = corner_in; var w = w_in;
    var t = vec3<f32>(0.0); var b = vec3<f32>(0.0); var d = vec3<f32>(0.0);
    for (var k = 0u; k < count; k++) {
        t = t + w[k] * dp.tangent[corner[k]];
        b = b + w[k] * dp.bitangent[corner[k]];
        d = d + w[k] * dp.direction[corner[k]];
    }
    return Frame(normalize_or_zero(t), normalize_or_zero(b), normalize_or_zero(d));
}
// bend_normal_vector: S_u x S_v = (t_u' + D_u) x (t_v' + D_v), D_u = Vu.x T + Vu.y B + Vu.z N from the vector's
// central differences vu, vv in the point's frame (its derivatives left out, as bend_normal leaves out dN).
fn bend_normal_vector(normal: vec3<f32>, tu: vec3<f32>, tv: vec3<f32>, vu: vec3<f32>, vv: vec3<f32>, f: Frame) -> vec3<f32> {
    let n = normalize_or_zero(normal);
    if (!(dot3(n, n) > 0.0)) { return normal; }
    let pu = tu - dot3(tu, n) * n;
    let pv = tv - dot3(tv, n) * n;
    let j = dot3(cross3(pu, pv), n);
    let du = (vu.x * f.t + vu.y * f.b) + vu.z * f.n;
    let dv = (vv.x * f.t + vv.y * f.b) + vv.z * f.n;
    if (!(j != 0.0) || !finite_bits(dot3(du, du)) || !finite_bits(dot3(dv, dv))) { return normal; }
    let bent = normalize_or_zero(select(1.0, -1.0, j < 0.0) * cross3(pu + du, pv + dv));
    if (dot3(bent, bent) > 0.0) { return bent; }
    return normal;
}
// (plus - minus) / (2 step), as 1 / (2 step) times the difference.
fn vector_difference(plus: vec3<f32>, minus: vec3<f32>, step_: f32) -> vec3<f32> {
    return (1.0 / (2.0 * step_)) * (plus - minus);
}
fn tri_uv_vector(dp: DisplacementPatch, a: f32, b: f32) -> vec3<f32> {
    let uv = tri_own_uv(dp, a, b);
    return displacement_vector(uv.x, uv.y);
}
fn quad_uv_vector(dp: DisplacementPatch, s: f32, t: f32) -> vec3<f32> {
    let uv = quad_own_uv(dp, s, t);
    return displacement_vector(uv.x, uv.y);
}
// A point on patch edge k with weights wa at corner k and wb at corner k + 1: the dominant edge's uvs and the
// dominant directions interpolated from the endpoint first in position order (equal positions: the larger weight).
// Returns the displaced position.
// vector_: vector mode (§8.7), a constant of the entry point, so that each pass carries one mode's code.
fn displace_edge(dp_in: DisplacementPatch, k: u32, wa_in: u32, wb_in: u32, position: vec3<f32>, vector_: bool) -> vec3<f32> {
    var dp = dp_in;
    var a = k; var b = (k + 1u) % dp.corners;
    var wa = wa_in; var wb = wb_in;
    var uv_a = dp.edge_uv[k].xy; var uv_b = dp.edge_uv[k].zw;
    if (wa == FIXED_ONE || wb == FIXED_ONE) {
        let c = select(b, a, wa == FIXED_ONE);
        if (vector_) {
            return move_vector(position, displacement_vector(dp.corner_uv[c].x, dp.corner_uv[c].y),
                               Frame(dp.tangent[c], dp.bitangent[c], dp.direction[c]));
        }
        return position + displacement_height(dp.corner_uv[c].x, dp.corner_uv[c].y) * dp.direction[c];
    }
    let swap_ = position_before(dp.position[b], dp.position[a]) ||
                (!position_before(dp.position[a], dp.position[b]) && wb > wa);
    if (swap_) {
        let x = a; a = b; b = x;
        let y = uv_a; uv_a = uv_b; uv_b = y;
        let z = wa; wa = wb; wb = z;
    }
    let ta = fixed_weight(wa); let tb = fixed_weight(wb);
    let u = ta * uv_a.x + tb * uv_b.x;
    let v = ta * uv_a.y + tb * uv_b.y;
    if (vector_) {
        return move_vector(position, displacement_vector(u, v),
                           interpolated_frame(dp, array<u32, 4>(a, b, 0u, 0u), array<f32, 4>(ta, tb, 0.0, 0.0), 2u));
    }
    let dir = normalize_or_zero(ta * dp.direction[a] + tb * dp.direction[b]);
    return position + displacement_height(u, v) * dir;
}
// Vector mode's triangle point (displace_triangle_vector, §8.7): the normal from the vector's differences in the own
// parameters, then the position as displace_triangle_point's (corners and edges through displace_edge, the interior
// in the frame interpolated by the barycentric weights).
fn displace_triangle_vector(dp: DisplacementPatch, weights: array<u32, 3>, a: f32, b: f32, sp: SurfacePoint) -> SurfacePoint {
    var w = weights;
    var p = sp;
    let step_ = param_float(PARAM_DISPLACEMENT_NORMAL_STEP);
    let frame = interpolated_frame(dp, array<u32, 4>(0u, 1u, 2u, 0u), array<f32, 4>(fixed_weight(w[0]), a, b, 0.0), 3u);
    let vu = vector_difference(tri_uv_vector(dp, a + step_, b), tri_uv_vector(dp, a - step_, b), step_);
    let vv = vector_difference(tri_uv_vector(dp, a, b + step_), tri_uv_vector(dp, a, b - step_), step_);
    p.normal = bend_normal_vector(p.normal, dp.position[1] - dp.position[0], dp.position[2] - dp.position[0], vu, vv, frame);
    for (var k = 0u; k < 3u; k++) {
        if (w[(k + 2u) % 3u] == 0u || w[k] == FIXED_ONE) {
            if (w[k] == FIXED_ONE) {
                p.position = displace_edge(dp, k, FIXED_ONE, 0u, p.position, true);
            } else {
                p.position = displace_edge(dp, k, w[k], w[(k + 1u) % 3u], p.position, true);
            }
            return p;
        }
    }
    p.position = move_vector(p.position, displacement_vector(p.uv.x, p.uv.y), frame);
    return p;
}
// Vector mode's quad point (displace_quad_vector, §8.7): boundary points through displace_edge as
// displace_quad_point's.
fn displace_quad_vector(dp: DisplacementPatch, s: u32, t: u32, fs: f32, ft: f32, sp: SurfacePoint) -> SurfacePoint {
    var p = sp;
    let step_ = param_float(PARAM_DISPLACEMENT_NORMAL_STEP);
    let w = array<f32, 4>((1.0 - fs) * (1.0 - ft), fs * (1.0 - ft), fs * ft, (1.0 - fs) * ft);
    let frame = interpolated_frame(dp, array<u32, 4>(0u, 1u, 2u, 3u), w, 4u);
    let vu = vector_difference(quad_uv_vector(dp, fs + step_, ft), quad_uv_vector(dp, fs - step_, ft), step_);
    let vv = vector_difference(quad_uv_vector(dp, fs, ft + step_), quad_uv_vector(dp, fs, ft - step_), step_);
    let ts = (1.0 - ft) * (dp.position[1] - dp.position[0]) + ft * (dp.position[2] - dp.position[3]);
    let tt = (1.0 - fs) * (dp.position[3] - dp.position[0]) + fs * (dp.position[2] - dp.position[1]);
    p.normal = bend_normal_vector(p.normal, ts, tt, vu, vv, frame);
    if ((s == 0u || s == FIXED_ONE) && (t == 0u || t == FIXED_ONE)) {
        let c = select(select(3u, 2u, s == FIXED_ONE), select(1u, 0u, s == 0u), t == 0u);
        p.position = displace_edge(dp, c, FIXED_ONE, 0u, p.position, true);
        return p;
    }
    var on_edge = array<bool, 4>(t == 0u, s == FIXED_ONE, t == FIXED_ONE, s == 0u);
    var r = array<u32, 4>(s, t, FIXED_ONE - s, FIXED_ONE - t);
    for (var k = 0u; k < 4u; k++) {
        if (on_edge[k]) {
            p.position = displace_edge(dp, k, FIXED_ONE - r[k], r[k], p.position, true);
            return p;
        }
    }
    p.position = move_vector(p.position, displacement_vector(p.uv.x, p.uv.y), frame);
    return p;
}
// displace_triangle_point: sp is the surface point of base weights w (units of FIXED_ONE).
fn displace_triangle_point(dp_in: DisplacementPatch, weights: array<u32, 3>, sp: SurfacePoint) -> SurfacePoint {
    var dp = dp_in;
    var w = weights;
    var p = sp;
    let a = fixed_weight(w[1]); let b = fixed_weight(w[2]);
    let step_ = param_float(PARAM_DISPLACEMENT_NORMAL_STEP);
    let hu = (tri_uv_height(dp, a + step_, b) - tri_uv_height(dp, a - step_, b)) / (2.0 * step_);
    let hv = (tri_uv_height(dp, a, b + step_) - tri_uv_height(dp, a, b - step_)) / (2.0 * step_);
    p.normal = bend_normal(p.normal, dp.position[1] - dp.position[0], dp.position[2] - dp.position[0], hu, hv);
    // A corner, an edge point (edge k has zero weight at corner k + 2) or an interior point.
    for (var k = 0u; k < 3u; k++) {
        if (w[(k + 2u) % 3u] == 0u || w[k] == FIXED_ONE) {
            if (w[k] == FIXED_ONE) {
                p.position = displace_edge(dp, k, FIXED_ONE, 0u, p.position, false);
            } else {
                p.position = displace_edge(dp, k, w[k], w[(k + 1u) % 3u], p.position, false);
            }
            return p;
        }
    }
    let dir = normalize_or_zero((fixed_weight(w[0]) * dp.direction[0] + a * dp.direction[1]) + b * dp.direction[2]);
    p.position = p.position + displacement_height(p.uv.x, p.uv.y) * dir;
    return p;
}
// The height at the own uv of quad parameter (s, t), bilinear.
fn quad_uv_height(dp: DisplacementPatch, s: f32, t: f32) -> f32 {
    let uv = quad_own_uv(dp, s, t);
    return displacement_height(uv.x, uv.y);
}
// displace_quad_point: sp is the surface point of quad point (s, t) of the unit square (units of FIXED_ONE).
fn displace_quad_point(dp_in: DisplacementPatch, s: u32, t: u32, sp: SurfacePoint) -> SurfacePoint {
    var dp = dp_in;
    var p = sp;
    let fs = fixed_weight(s); let ft = fixed_weight(t);
    let step_ = param_float(PARAM_DISPLACEMENT_NORMAL_STEP);
    let hu = (quad_uv_height(dp, fs + step_, ft) - quad_uv_height(dp, fs - step_, ft)) / (2.0 * step_);
    let hv = (quad_uv_height(dp, fs, ft + step_) - quad_uv_height(dp, fs, ft - step_)) / (2.0 * step_);
    let ts = (1.0 - ft) * (dp.position[1] - dp.position[0]) + ft * (dp.position[2] - dp.position[3]);
    let tt = (1.0 - fs) * (dp.position[3] - dp.position[0]) + fs * (dp.position[2] - dp.position[1]);
    p.normal = bend_normal(p.normal, ts, tt, hu, hv);
    // Corners, then edge k from q_k with parameter r measured from q_k (t = 0, s = 1, t = 1, s = 0), then the
    // interior.
    if ((s == 0u || s == FIXED_ONE) && (t == 0u || t == FIXED_ONE)) {
        let c = select(select(3u, 2u, s == FIXED_ONE), select(1u, 0u, s == 0u), t == 0u);
        p.position = displace_edge(dp, c, FIXED_ONE, 0u, p.position, false);
        return p;
    }
    var on_edge = array<bool, 4>(t == 0u, s == FIXED_ONE, t == FIXED_ONE, s == 0u);
    var r = array<u32, 4>(s, t, FIXED_ONE - s, FIXED_ONE - t);
    for (var k = 0u; k < 4u; k++) {
        if (on_edge[k]) {
            p.position = displace_edge(dp, k, FIXED_ONE - r[k], r[k], p.position, false);
            return p;
        }
    }
    let w = array<f32, 4>((1.0 - fs) * (1.0 - ft), fs * (1.0 - ft), fs * ft, (1.0 - fs) * ft);
    let dir = normalize_or_zero(((w[0] * dp.direction[0] + w[1] * dp.direction[1]) + w[2] * dp.direction[2]) + w[3] * dp.direction[3]);
    p.position = p.position + displacement_height(p.uv.x, p.uv.y) * dir;
    return p;
}

// ---- quad surfaces (evaluate_quad_surface, docs/algorithm.md §6.2, §7.3) ----
// A point strictly inside quad q0 q1 q2 q3 at (s, t) of its unit square: bilinear (flat, zeros as +0), Phong
// (the bilinear point projected onto the corner tangent planes, blended bilinearly) or the PN bicubic patch
// whose boundary is the PN triangles' edge curves, with the biquadratic normal field.
// PN-AEN (aen): the PN patch on PN-AEN edge control points, en[k] the neighbour's normals on edge k.
fn quad_interior(corners: array<Corner, 4>, edges: array<EdgeNormals, 4>, aen: bool, s: u32, t: u32, surface: u32,
                 alpha: f32) -> SurfacePoint {
    var q = corners;
    var en = edges;
    let fs = fixed_weight(s); let ft = fixed_weight(t);
    let gs = fixed_weight(FIXED_ONE - s); let gt = fixed_weight(FIXED_ONE - t);
    var w = array<f32, 4>(gs * gt, fs * gt, fs * ft, gs * ft);
    var flat_p = vec3<f32>(0.0); var flat_n = vec3<f32>(0.0); var uv = vec2<f32>(0.0);
    for (var k = 0u; k < 4u; k++) {
        flat_p = flat_p + w[k] * q[k].position;
        flat_n = flat_n + w[k] * q[k].normal;
        uv.x += w[k] * q[k].uv.x;
        uv.y += w[k] * q[k].uv.y;
    }
    if (surface == SURFACE_PHONG) {
        var ph = vec3<f32>(0.0);
        for (var k = 0u; k < 4u; k++) { ph = ph + w[k] * phong_project(flat_p, q[k]); }
        return SurfacePoint(blend(flat_p, ph, alpha), normalize_or_zero(flat_n), uv);
    }
    if (surface != SURFACE_PN && !aen) {
        let uv_zeros = without_negative_zero(vec3<f32>(uv, 0.0));
        return SurfacePoint(without_negative_zero(flat_p), without_negative_zero(normalize_or_zero(flat_n)), uv_zeros.xy);
    }
    // The Bezier net b[i][j] (i along s, j along t) at b[4 * i + j].
    var b: array<vec3<f32>, 16>;
    b[0] = q[0].position; b[12] = q[1].position; b[15] = q[2].position; b[3] = q[3].position;
    if (aen) {
        b[4] = aen_control(q[0].position, q[0].normal, en[0].at_from, q[1].position);
        b[8] = aen_control(q[1].position, q[1].normal, en[0].at_to, q[0].position);
        b[13] = aen_control(q[1].position, q[1].normal, en[1].at_from, q[2].position);
        b[14] = aen_control(q[2].position, q[2].normal, en[1].at_to, q[1].position);
        b[11] = aen_control(q[2].position, q[2].normal, en[2].at_from, q[3].position);
        b[7] = aen_control(q[3].position, q[3].normal, en[2].at_to, q[2].position);
        b[2] = aen_control(q[3].position, q[3].normal, en[3].at_from, q[0].position);
        b[1] = aen_control(q[0].position, q[0].normal, en[3].at_to, q[3].position);
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
    let twist = (1.0 / 9.0) * ((q[0].position + q[2].position) - (q[1].position + q[3].position));
    b[5] = ((b[4] + b[1]) - q[0].position) + twist;
    b[9] = ((b[8] + b[13]) - q[1].position) - twist;
    b[10] = ((b[11] + b[14]) - q[2].position) + twist;
    b[6] = ((b[7] + b[2]) - q[3].position) - twist;
    var bs = array<f32, 4>(gs * gs * gs, 3.0 * gs * gs * fs, 3.0 * gs * fs * fs, fs * fs * fs);
    var bt = array<f32, 4>(gt * gt * gt, 3.0 * gt * gt * ft, 3.0 * gt * ft * ft, ft * ft * ft);
    var pn = vec3<f32>(0.0);
    for (var j = 0u; j < 4u; j++) {
        var row = vec3<f32>(0.0);
        for (var i = 0u; i < 4u; i++) { row = row + bs[i] * b[4u * i + j]; }
        pn = pn + bt[j] * row;
    }
    var m = array<vec3<f32>, 4>(0.5 * pn_edge_normal(q[0], q[1]), 0.5 * pn_edge_normal(q[1], q[2]),
                                0.5 * pn_edge_normal(q[2], q[3]), 0.5 * pn_edge_normal(q[3], q[0]));
    // nq[i][j] at nq[3 * i + j]
    var nq = array<vec3<f32>, 9>(q[0].normal, m[3], q[3].normal, m[0], 0.25 * ((m[0] + m[1]) + (m[2] + m[3])), m[2],
                                 q[1].normal, m[1], q[2].normal);
    var cs = array<f32, 3>(gs * gs, 2.0 * gs * fs, fs * fs);
    var ct = array<f32, 3>(gt * gt, 2.0 * gt * ft, ft * ft);
    var nn = vec3<f32>(0.0);
    for (var j = 0u; j < 3u; j++) {
        var row = vec3<f32>(0.0);
        for (var i = 0u; i < 3u; i++) { row = row + cs[i] * nq[3u * i + j]; }
        nn = nn + ct[j] * row;
    }
    let position = blend(flat_p, pn, alpha);
    return SurfacePoint(select(position, without_negative_zero(position), aen), normalize_or_zero(blend(flat_n, nn, alpha)), uv);
}
// ---- uniform-density pattern (uniform_patch.hpp, uniform_pipeline_patch.hpp) ----
// uniform::round_factor (constexpr/ctess/uniform/factor.hpp, docs/algorithm.md §3.4) line for line, on the float's
// bits with integers only: NaN, negatives and anything below 1.5 give 1, +inf and from UNIFORM_MAX_FACTOR - 0.5
// on give UNIFORM_MAX_FACTOR, else the nearest integer, halves up (UNIFORM_ROUND_FROM_BITS = 1.5f and
// F32_INFINITY_BITS are generated from that function's checks).
fn round_factor(f: f32, max_factor: u32) -> u32 {
    let bits = bitcast<u32>(f);
    if (bits < UNIFORM_ROUND_FROM_BITS || bits > F32_INFINITY_BITS) { return 1u; }
    let exponent = (bits >> 23u) - 127u; // f in [2^exponent, 2^(exponent + 1)), exponent >= 0
    if (exponent >= 23u) { return max_factor; }
    let mantissa = (bits & 0x7FFFFFu) | 0x800000u; // f = mantissa * 2^(exponent - 23)
    let shift = 23u - exponent;
    let rounded = (mantissa + (1u << (shift - 1u))) >> shift; // halves up, exact
    return min(rounded, max_factor);
}
// The table's factor (Pattern::uniform), or the split's up to SPLIT_MAX_FACTOR (Pattern::uniform_split).
fn uniform_factor(f: f32) -> u32 { return round_factor(f, select(UNIFORM_MAX_FACTOR, SPLIT_MAX_FACTOR, split_pattern())); }
fn uniform_edge_parameter(i: u32, f: u32) -> u32 {
    let nearer = min(i, f - i);
    let q = (2u * nearer * UNIFORM_ONE + f) / (2u * f);
    return select(UNIFORM_ONE - q, q, i <= f - i);
}
fn uniform_pattern_index(f0: u32, f1: u32, f2: u32) -> u32 { return (f0 - 1u) * f0 * (f0 + 1u) / 6u + (f1 - 1u) * f1 / 2u + (f2 - 1u); }
// A 65534-unit weight in units of 2^-24: nearest, never a tie, so mirror-exact.
fn uniform_to_fixed(w: u32) -> u32 { return 256u * w + (512u * w + 32767u) / UNIFORM_ONE; }
// The uniform setup words from the integer factors of base edges E0, E1, E2 (UniformPatch's constructor).
// Returns the counts; words: pattern index, f0 | f1 << 8 | f2 << 16, corner sources | flip << 12.
fn uniform_setup(f: array<u32, 3>, words: ptr<function, vec3<u32>>) -> vec2<u32> {
    var order = array<u32, 3>(0u, 1u, 2u);
    var tmp: u32;
    if (f[order[1]] > f[order[0]]) { tmp = order[0]; order[0] = order[1]; order[1] = tmp; }
    if (f[order[2]] > f[order[1]]) { tmp = order[1]; order[1] = order[2]; order[2] = tmp; }
    if (f[order[1]] > f[order[0]]) { tmp = order[0]; order[0] = order[1]; order[1] = tmp; }
    let s0 = f[order[0]]; let s1 = f[order[1]]; let s2 = f[order[2]];
    var opposite = array<u32, 3>(2u, 0u, 1u);
    var target_ = array<u32, 3>(opposite[order[1]], opposite[order[2]], opposite[order[0]]);
    var source: array<u32, 3>;
    for (var c = 0u; c < 3u; c++) { source[target_[c]] = c; }
    let flip = (target_[1] + 3u - target_[0]) % 3u != 1u;
    let index = uniform_pattern_index(s0, s1, s2);
    let first = tables[UNIFORM_OFFSET + index];
    let next = tables[UNIFORM_OFFSET + index + 1u];
    *words = vec3<u32>(index, s0 | (s1 << 8u) | (s2 << 16u), source[0] | (source[1] << 4u) | (source[2] << 8u) | select(0u, 4096u, flip));
    return vec2<u32>(s0 + s1 + s2 + (next & 0xFFFFu) - (first & 0xFFFFu), (next >> 16u) - (first >> 16u));
}
// The uniform setup words of a record (pattern index, sorted factors, corner sources).
fn uniform_words(rec: u32) -> vec3<u32> {
    return vec3<u32>(patches[rec + SETUP + USETUP_PATTERN], patches[rec + SETUP + USETUP_SORTED], patches[rec + SETUP + USETUP_CORNERS]);
}
// Vertex i in the pattern's own weights (w1, w2), units of 65534 (UniformPatch::vertex).
fn uniform_local(words: vec3<u32>, i: u32) -> vec2<u32> {
    let index = words.x;
    let sorted = words.y;
    let corners = words.z;
    let f0 = sorted & 255u; let f1 = (sorted >> 8u) & 255u; let f2 = sorted >> 16u;
    var c: vec2<u32>;
    if (i < f0) {
        c = vec2<u32>(uniform_edge_parameter(i, f0), 0u);
    } else if (i < f0 + f1) {
        let v = uniform_edge_parameter(i - f0, f1);
        c = vec2<u32>(UNIFORM_ONE - v, v);
    } else if (i < f0 + f1 + f2) {
        c = vec2<u32>(0u, uniform_edge_parameter(f2 - (i - f0 - f1), f2));
    } else {
        let word = tables[UNIFORM_INTERIOR + (tables[UNIFORM_OFFSET + index] & 0xFFFFu) + i - (f0 + f1 + f2)];
        c = vec2<u32>(word & 0xFFFFu, word >> 16u);
    }
    var weight = array<u32, 3>(UNIFORM_ONE - c.x - c.y, c.x, c.y);
    return vec2<u32>(weight[(corners >> 4u) & 3u], weight[(corners >> 8u) & 3u]);
}
// Vertex i as base weights (w1, w2), units of 2^-24.
fn uniform_vertex(words: vec3<u32>, i: u32) -> vec2<u32> {
    let c = uniform_local(words, i);
    return vec2<u32>(uniform_to_fixed(c.x), uniform_to_fixed(c.y));
}
fn uniform_index_byte(b: u32) -> u32 { return (tables[UNIFORM_TRIANGLE + (b >> 2u)] >> ((b & 3u) * 8u)) & 255u; }
fn uniform_triangle(words: vec3<u32>, p: u32) -> vec3<u32> {
    let b = 3u * ((tables[UNIFORM_OFFSET + words.x] >> 16u) + p);
    let t = vec3<u32>(uniform_index_byte(b), uniform_index_byte(b + 1u), uniform_index_byte(b + 2u));
    if ((words.z & 4096u) != 0u) { return t.xzy; }
    return t;
}

// The uniform pattern's record (setup pass, pattern 1) from base edges E0, E1, E2's factors, into a zeroed record:
// rotation 0, the integer factors as tokens, the factor bits, the counts and the three setup words. A split
// patch's (pattern 2) has no setup words, and its counts come from its leaves (ctess_split_records).
fn store_uniform_record(rec: u32, factor: array<f32, 3>) {
    var f: array<u32, 3>;
    for (var k = 0u; k < 3u; k++) {
        f[k] = uniform_factor(factor[k]);
        patches[rec + REC_TOKEN + k] = f[k];
        patches[rec + REC_FACTOR + k] = bitcast<u32>(factor[k]);
    }
    if (split_pattern()) { return; }
    var words: vec3<u32>;
    let counts = uniform_setup(f, &words);
    patches[rec + REC_VERTEX_COUNT] = counts.x;
    patches[rec + REC_TRIANGLE_COUNT] = counts.y;
    patches[rec + SETUP + USETUP_PATTERN] = words.x;
    patches[rec + SETUP + USETUP_SORTED] = words.y;
    patches[rec + SETUP + USETUP_CORNERS] = words.z;
}

// ---- patch records (PatchRecord) ----
fn smallest_edge_rotation(lengths: array<f32, 3>) -> u32 {
    var l = lengths;
    var smallest = 0u;
    for (var k = 1u; k < 3u; k++) {
        if (is_nan_bits(l[k])) { continue; }
        if (is_nan_bits(l[smallest]) || l[k] < l[smallest]) { smallest = k; }
    }
    return (smallest + 1u) % 3u;
}
// The setup block (rt::setup_word's word order, runtime/include/ctess/runtime/cp/setup_block.hpp): written once by the setup pass, read by every emit
// invocation instead of redoing patch_setup.
fn store_setup_block(rec: u32, p: Patch) {
    let b = rec + SETUP;
    patches[b + SETUP_FLAGS] = p.type_ | select(0u, 4u, p.c0) | select(0u, 8u, p.c1) | select(0u, 16u, p.c2) |
                 select(0u, 32u, p.copies) | (p.tri_skips << 8u) | (p.slot_skips << 12u);
    for (var k = 0u; k < 3u; k++) {
        patches[b + SETUP_TOKEN_REC + k] = p.e[k].points | (p.e[k].segments << 16u);
        patches[b + SETUP_HALF_STEP + k] = p.e[k].half_step;
    }
    patches[b + SETUP_COLUMN] = p.column;
    patches[b + SETUP_GAP] = select(0u, p.gap - GAP_WORD, p.type_ == 2u);
    patches[b + SETUP_CLAMP] = p.clamp_;
    patches[b + SETUP_STRIPS] = p.strips;
    patches[b + SETUP_E1_OFFSET] = p.e1_offset;
    patches[b + SETUP_UNIQUE] = p.unique_;
    patches[b + SETUP_COPY_BIAS] = p.copy_bias;
    for (var k = 0u; k < SETUP_SLOT_SKIPS; k++) { patches[b + SETUP_SLOT_SKIP + k] = p.slot_skip[k].x | (p.slot_skip[k].y << 16u); }
    for (var k = 0u; k < SETUP_TRI_SKIPS; k++) {
        patches[b + SETUP_TRI_SKIP + 2u * k] = p.tri_skip[k].x;
        patches[b + (SETUP_TRI_SKIP + 1u) + 2u * k] = p.tri_skip[k].y;
    }
}
fn record_patch(rec: u32) -> Patch {
    var p: Patch; // zero-initialised
    let b = rec + SETUP;
    let flags = patches[b + SETUP_FLAGS];
    for (var k = 0u; k < 3u; k++) {
        let tr = patches[b + SETUP_TOKEN_REC + k];
        p.e[k].points = tr & 0xFFFFu;
        p.e[k].segments = tr >> 16u;
        p.e[k].half_step = patches[b + SETUP_HALF_STEP + k];
        p.e[k].t16 = select(patches[rec + REC_T16 + k], 0u, patches[rec + REC_TOKEN + k] == 0u);
    }
    p.type_ = flags & 3u;
    p.c0 = (flags & 4u) != 0u;
    p.c1 = (flags & 8u) != 0u;
    p.c2 = (flags & 16u) != 0u;
    p.copies = (flags & 32u) != 0u;
    p.tri_skips = (flags >> 8u) & 15u;
    p.slot_skips = (flags >> 12u) & 15u;
    p.n0 = p.e[0].segments;
    p.n1 = p.e[1].segments;
    p.n2 = p.e[2].segments;
    p.vertices = patches[rec + REC_VERTEX_COUNT];
    p.triangles = patches[rec + REC_TRIANGLE_COUNT];
    if (p.type_ == 2u) {
        p.column = patches[b + SETUP_COLUMN];
        load_column_record(&p);
        p.gap = GAP_WORD + patches[b + SETUP_GAP];
        p.clamp_ = patches[b + SETUP_CLAMP];
        p.strips = patches[b + SETUP_STRIPS];
        p.zipper = p.n0 + p.n1 - 1u;
        p.e1_offset = patches[b + SETUP_E1_OFFSET];
        p.unique_ = patches[b + SETUP_UNIQUE];
        p.copy_bias = patches[b + SETUP_COPY_BIAS];
    }
    for (var k = 0u; k < p.slot_skips; k++) {
        let w = patches[b + SETUP_SLOT_SKIP + k];
        p.slot_skip[k] = vec2<u32>(w & 0xFFFFu, w >> 16u);
    }
    for (var k = 0u; k < p.tri_skips; k++) { p.tri_skip[k] = vec2<u32>(patches[b + SETUP_TRI_SKIP + 2u * k], patches[b + (SETUP_TRI_SKIP + 1u) + 2u * k]); }
    return p;
}

// Pass 1, one invocation per patch: factors, rotation, line states, counts and the setup block (quads: setup_one_quad).
fn setup_one_patch(t: u32) {
    let rec = t * PATCH_WORDS;
    for (var k = 0u; k < PATCH_WORDS; k++) { patches[rec + k] = 0u; }
    if (t >= triangle_count()) {
        setup_one_quad(t);
        return;
    }
    let w = base_triangle(t);
    if (!base_triangle_valid(w)) { return; }
    var wv = array<u32, 3>(w.x, w.y, w.z);
    let scale = bitcast<f32>(params[PARAM_FACTOR_SCALE]);
    let eye = mesh_eye();
    var factor: array<f32, 3>;
    var length2: array<f32, 3>;
    for (var k = 0u; k < 3u; k++) {
        let i = wv[k]; let j = wv[(k + 1u) % 3u];
        let a = mesh_position(min(i, j)); let b = mesh_position(max(i, j));
        factor[k] = displaced_edge_factor(edge_tess_factor(a, b, eye, scale), a, b); // grown by the bound (§8.4)
        let d = b - a;
        length2[k] = dot3(d, d);
    }
    if (uniform_pattern() || split_pattern()) {
        store_uniform_record(rec, factor);
        return;
    }
    let rot = smallest_edge_rotation(length2);
    var s: array<vec2<u32>, 3>;
    for (var k = 0u; k < 3u; k++) { s[k] = line_state(factor[(k + rot) % 3u]); }
    let p = patch_setup(s[0], s[1], s[2]);
    patches[rec + REC_ROTATION] = rot;
    for (var k = 0u; k < 3u; k++) {
        patches[rec + REC_TOKEN + k] = s[k].x;
        patches[rec + REC_T16 + k] = s[k].y;
        patches[rec + REC_FACTOR + k] = bitcast<u32>(factor[k]);
    }
    patches[rec + REC_VERTEX_COUNT] = p.vertices;
    patches[rec + REC_TRIANGLE_COUNT] = p.triangles;
    store_setup_block(rec, p);
}
// ---- uniform splitting (Pattern::uniform_split; docs/shaders.md, "Splitting"; docs/algorithm.md §3.5) ----
// UniformSplit's decisions on the exact squared factors of constexpr/ctess/uniform/split_factor.hpp, in 32-bit
// words: a square s = f^2 2^32 as vec2<u32> (lo, hi), a product below 2^96 as vec3<u32> (low word first).
fn less64(a: vec2<u32>, b: vec2<u32>) -> bool { return select(a.x < b.x, a.y < b.y, a.y != b.y); }
fn add96(a: vec3<u32>, b: vec3<u32>) -> vec3<u32> {
    let x = a.x + b.x;
    let y = a.y + b.y;
    var carry = select(0u, 1u, y < a.y);
    let y1 = y + select(0u, 1u, x < a.x);
    carry += select(0u, 1u, y1 < y);
    return vec3<u32>(x, y1, a.z + b.z + carry);
}
fn less96(a: vec3<u32>, b: vec3<u32>) -> bool {
    if (a.z != b.z) { return a.z < b.z; }
    return less64(a.xy, b.xy);
}
fn sub96(a: vec3<u32>, b: vec3<u32>) -> vec3<u32> { // a >= b
    let x = a.x - b.x;
    let y = a.y - b.y;
    var borrow = select(0u, 1u, a.y < b.y);
    let y1 = y - select(0u, 1u, a.x < b.x);
    borrow += select(0u, 1u, y < y1);
    return vec3<u32>(x, y1, a.z - b.z - borrow);
}
fn mul96(s: vec2<u32>, c: u32) -> vec3<u32> { // s c, s < 2^64
    let lo = mul_wide(s.x, c);
    let hi = mul_wide(s.y, c);
    let mid = lo.y + hi.x;
    return vec3<u32>(lo.x, mid, hi.y + select(0u, 1u, mid < lo.y));
}
// floor(x / 65534) in 16-bit digits from the top: every step's dividend is below 65534 x 2^16 + 2^16 < 2^32.
fn div_digit(r: ptr<function, u32>, digit: u32) -> u32 {
    let n = (*r << 16u) | digit;
    let q = n / UNIFORM_ONE;
    *r = n - q * UNIFORM_ONE;
    return q;
}
fn div96_unit(x: vec3<u32>) -> vec3<u32> {
    var r = 0u;
    let zh = div_digit(&r, x.z >> 16u); let zl = div_digit(&r, x.z & 0xFFFFu);
    let yh = div_digit(&r, x.y >> 16u); let yl = div_digit(&r, x.y & 0xFFFFu);
    let xh = div_digit(&r, x.x >> 16u); let xl = div_digit(&r, x.x & 0xFFFFu);
    return vec3<u32>((xh << 16u) | xl, (yh << 16u) | yl, (zh << 16u) | zl);
}
// segment_squared_factor: floor(max(0, q) / 65534^2), q = -s2 dv dw - s0 dw du - s1 du dv, dw = -du - dv.
fn segment_squared(s: array<vec2<u32>, 3>, du: i32, dv: i32) -> vec2<u32> {
    let dw = -du - dv;
    var squares = s;
    var a = array<i32, 3>(dw, du, dv); // coefficient k is -a[k] b[k]
    var b = array<i32, 3>(du, dv, dw);
    var positive = vec3<u32>(0u);
    var negative = vec3<u32>(0u);
    for (var k = 0u; k < 3u; k++) {
        let magnitude = u32(abs(a[k])) * u32(abs(b[k])); // at most 65534^2 < 2^32
        let term = mul96(squares[k], magnitude);
        if ((a[k] < 0) == (b[k] < 0)) { negative = add96(negative, term); } else { positive = add96(positive, term); }
    }
    if (!less96(negative, positive)) { return vec2<u32>(0u); }
    return div96_unit(div96_unit(sub96(positive, negative))).xy; // below 2^64
}
// floor(2f): the largest m with m^2 2^30 <= s (at most 65536), from a float guess corrected exactly.
fn twice_fits(s: vec2<u32>, m: u32) -> bool {
    let square = mul_wide(m, m);
    return !less64(s, vec2<u32>(square.x << 30u, (square.y << 30u) | (square.x >> 2u)));
}
fn floor_twice_factor(s: vec2<u32>) -> u32 {
    let guess = sqrt(f32(s.y) * 4294967296.0 + f32(s.x)) * (1.0 / 32768.0);
    var m = select(u32(max(guess, 0.0)), 65536u, guess >= 65536.0);
    while (m > 0u && !twice_fits(s, m)) { m--; }
    while (m < 65536u && twice_fits(s, m + 1u)) { m++; }
    return m;
}
fn rounded_split_factor(s: vec2<u32>) -> u32 { return (floor_twice_factor(s) + 1u) / 2u; }
// (2k - 1)^2 2^30: f rounds to k or more from this square on.
fn half_below_squared(k: u32) -> vec2<u32> {
    let v = (2u * k - 1u) * (2u * k - 1u);
    return vec2<u32>(v << 30u, v >> 2u);
}
// A leaf's factor: rounded, clamped to [1, UNIFORM_MAX_FACTOR], by a binary search of the squares.
fn leaf_factor(s: vec2<u32>) -> u32 {
    var low = 1u;
    var high = UNIFORM_MAX_FACTOR;
    while (low < high) {
        let mid = (low + high + 1u) / 2u;
        if (less64(s, half_below_squared(mid))) { high = mid - 1u; } else { low = mid; }
    }
    return low;
}
// A split node's pieces of an edge (UniformSplit edge_pieces): whole within the dice limit (f < N + 1/2 at
// depth 0 and on the root's boundary, else below the interior limit), else ceil(round(f) / N) clamped to [1, N].
fn edge_pieces(s: vec2<u32>, depth: u32, boundary: bool) -> u32 {
    let n = UNIFORM_MAX_FACTOR;
    var whole: bool;
    if (depth == 0u || boundary) { whole = less64(s, half_below_squared(n + 1u)); }
    else { whole = less64(s, vec2<u32>(SPLIT_INTERIOR_LIMIT_LO, SPLIT_INTERIOR_LIMIT_HI)); }
    if (whole) { return 1u; }
    return clamp((rounded_split_factor(s) + n - 1u) / n, 1u, n);
}
// uniform_split_depth_limit(N, largest root factor): one level more than its edges need, in [2, bound].
fn split_depth_limit(largest: u32) -> u32 {
    var reach = UNIFORM_MAX_FACTOR;
    var levels = 0u;
    for (; reach < largest; levels++) { reach *= UNIFORM_MAX_FACTOR; }
    return max(min(levels + 1u, SPLIT_DEPTH_BOUND), 2u);
}

// A node of the split area (rt::gpu::split_node_word): corners on the root in units of SPLIT_FIXED_ONE.
struct SplitNode {
    patch_: u32,
    info: u32,
    corner: array<vec2<u32>, 3>,
    squared: array<vec2<u32>, 3>,
}
fn split_area() -> u32 { return patch_count() * PATCH_WORDS + TOTALS_WORDS; }
fn split_header(w: u32) -> u32 { return split_area() + w; }
// Node i of the region of `level` (the levels alternate between two regions of PARAM_SPLIT_CAPACITY nodes).
fn split_node(level: u32, i: u32) -> u32 {
    return split_area() + SPLIT_HEADER_WORDS + ((level & 1u) * params[PARAM_SPLIT_CAPACITY] + i) * NODE_WORDS;
}
fn load_node(n: u32) -> SplitNode {
    var s: SplitNode;
    s.patch_ = patches[n + NODE_PATCH];
    s.info = patches[n + NODE_INFO];
    for (var k = 0u; k < 3u; k++) {
        s.corner[k] = vec2<u32>(patches[n + NODE_CORNER + 2u * k], patches[n + NODE_CORNER + 2u * k + 1u]);
        s.squared[k] = vec2<u32>(patches[n + NODE_SQUARED + 2u * k], patches[n + NODE_SQUARED + 2u * k + 1u]);
    }
    return s;
}
fn store_node(n: u32, s: SplitNode) {
    var node = s;
    patches[n + NODE_PATCH] = node.patch_;
    patches[n + NODE_INFO] = node.info;
    for (var k = 0u; k < 3u; k++) {
        patches[n + NODE_CORNER + 2u * k] = node.corner[k].x;
        patches[n + NODE_CORNER + 2u * k + 1u] = node.corner[k].y;
        patches[n + NODE_SQUARED + 2u * k] = node.squared[k].x;
        patches[n + NODE_SQUARED + 2u * k + 1u] = node.squared[k].y;
    }
}
// The root edges a point lies on: bit 0 e0 (v = 0), bit 1 e1 (u + v = 65534^2), bit 2 e2 (u = 0).
fn root_edges_of(p: vec2<u32>) -> u32 {
    return select(0u, 1u, p.y == 0u) | select(0u, 2u, p.x + p.y == SPLIT_FIXED_ONE) | select(0u, 4u, p.x == 0u);
}
fn split_edge_on_boundary(s: SplitNode, e: u32) -> bool {
    var node = s;
    let a = select(e, 0u, e == 2u);
    let b = select(2u, 1u, e == 0u);
    return (root_edges_of(node.corner[a]) & root_edges_of(node.corner[b])) != 0u;
}
// The point of node s at local (u, v) (units of 65534) on the root: the exact sum over the corners divided by
// 65534, rounded half up, ties on a root edge to even (UniformSplit map and map32: each corner is 65534 a + b,
// so the sum is 65534 (w a0 + u a1 + v a2) + (w b0 + u b1 + v b2), both parts below 2^32).
fn split_map(s: SplitNode, d: vec2<u32>) -> vec2<u32> {
    var node = s;
    let w = UNIFORM_ONE - d.x - d.y;
    let edges = select(root_edges_of(node.corner[0]), 7u, w == 0u) & select(root_edges_of(node.corner[1]), 7u, d.x == 0u) &
                select(root_edges_of(node.corner[2]), 7u, d.y == 0u);
    var r: vec2<u32>;
    for (var k = 0u; k < 2u; k++) {
        let c0 = node.corner[0][k]; let c1 = node.corner[1][k]; let c2 = node.corner[2][k];
        let a0 = c0 / UNIFORM_ONE; let a1 = c1 / UNIFORM_ONE; let a2 = c2 / UNIFORM_ONE;
        var q = w * a0 + d.x * a1 + d.y * a2;
        let b = w * (c0 - a0 * UNIFORM_ONE) + d.x * (c1 - a1 * UNIFORM_ONE) + d.y * (c2 - a2 * UNIFORM_ONE);
        q += b / UNIFORM_ONE;
        let rest = b % UNIFORM_ONE;
        let half_ = UNIFORM_ONE / 2u;
        r[k] = q + select(0u, 1u, rest > half_ || (rest == half_ && (edges == 0u || (q & 1u) != 0u)));
    }
    return r;
}
// to_base_weights: a root coordinate to 2^-24 units, (c 2^24 + 65534^2 / 2) / 65534^2 (no ties).
fn split_base_weight(c: u32) -> u32 {
    let x = min(c, SPLIT_FIXED_ONE);
    let n = add_wide(vec2<u32>(x << 24u, x >> 8u), SPLIT_FIXED_ONE / 2u);
    return div96_unit(div96_unit(vec3<u32>(n, 0u))).x;
}
fn pattern_corner(p: vec2<u32>) -> i32 {
    if (all(p == vec2<u32>(0u))) { return 0; }
    if (all(p == vec2<u32>(UNIFORM_ONE, 0u))) { return 1; }
    if (all(p == vec2<u32>(0u, UNIFORM_ONE))) { return 2; }
    return -1;
}
// A child edge from a to b (pattern points of s): a whole edge of s keeps its square, any other is measured in
// s's metric (UniformSplit child_edge_factor).
fn child_squared(s: SplitNode, a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
    var node = s;
    let ca = pattern_corner(a);
    let cb = pattern_corner(b);
    if (ca >= 0 && cb >= 0 && ca != cb) {
        let lo = min(ca, cb);
        let hi = max(ca, cb);
        if (lo == 0 && hi == 1) { return node.squared[0]; }
        if (lo == 1 && hi == 2) { return node.squared[1]; }
        return node.squared[2];
    }
    return segment_squared(node.squared, i32(b.x) - i32(a.x), i32(b.y) - i32(a.y));
}
// The indirect dispatch of a pass over n items: SPLIT_GROUP invocations a workgroup, at most
// MAX_DISPATCH_WORKGROUPS (the passes stride over the rest).
fn split_dispatch(n: u32) {
    patches[split_header(SPLIT_DISPATCH)] = max(1u, min((n + SPLIT_GROUP - 1u) / SPLIT_GROUP, MAX_DISPATCH_WORKGROUPS));
    patches[split_header(SPLIT_DISPATCH + 1u)] = 1u;
    patches[split_header(SPLIT_DISPATCH + 2u)] = 1u;
}

// Pass: the roots of level 0, one per base triangle, two per quad (halves A and B), in patch order, from the
// records' rounded factors (a culled patch's are 0: a culled root).
@compute @workgroup_size(SPLIT_GROUP)
fn ctess_split_roots(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let triangles = triangle_count();
    let roots = triangles + 2u * params[PARAM_QUAD_COUNT];
    let capacity = params[PARAM_SPLIT_CAPACITY];
    if (gid.x == 0u) {
        patches[split_header(SPLIT_LEVEL)] = 0u;
        patches[split_header(SPLIT_NODES)] = min(roots, capacity);
        patches[split_header(SPLIT_PARENTS)] = 0u;
        patches[split_header(SPLIT_NEEDED)] = roots;
        patches[split_header(SPLIT_OVERFLOW)] = select(0u, 1u, roots > capacity);
        split_dispatch(min(roots, capacity));
    }
    for (var r = gid.x; r < min(roots, capacity); r += groups.x * SPLIT_GROUP) {
        let t = select(triangles + (r - triangles) / 2u, r, r < triangles);
        let half_ = select((r - triangles) & 1u, 0u, r < triangles);
        let rec = t * PATCH_WORDS;
        var s: SplitNode;
        s.patch_ = t;
        var largest = 0u;
        for (var k = 0u; k < 3u; k++) {
            let f = patches[rec + select(SETUP + QSETUP_B_TOKEN, REC_TOKEN, half_ == 0u) + k];
            s.squared[k] = vec2<u32>(0u, f * f); // f^2 2^32
            largest = max(largest, f);
        }
        s.info = (split_depth_limit(largest) << NODE_LIMIT_SHIFT) | (half_ << NODE_HALF_SHIFT) | select(0u, NODE_CULLED, largest == 0u);
        s.corner[0] = vec2<u32>(0u);
        s.corner[1] = vec2<u32>(SPLIT_FIXED_ONE, 0u);
        s.corner[2] = vec2<u32>(0u, SPLIT_FIXED_ONE);
        store_node(split_node(0u, r), s);
    }
}

// Pass: decides every node of the current level. A leaf (every edge whole, or the depth limit): its pattern
// from its factors rounded to [1, N], its counts, one child (itself). A split node: the pattern of its pieces,
// whose triangles are its children.
@compute @workgroup_size(SPLIT_GROUP)
fn ctess_split_count(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let level = patches[split_header(SPLIT_LEVEL)];
    let nodes = patches[split_header(SPLIT_NODES)];
    for (var i = gid.x; i < nodes; i += groups.x * SPLIT_GROUP) {
        let n = split_node(level, i);
        var s = load_node(n);
        var counts = vec2<u32>(0u);
        var words = vec3<u32>(0u);
        var children = 0u;
        if ((s.info & NODE_CULLED) == 0u) {
            let depth = s.info & NODE_DEPTH_MASK;
            var pieces = array<u32, 3>(1u, 1u, 1u);
            if (depth < ((s.info >> NODE_LIMIT_SHIFT) & NODE_DEPTH_MASK)) {
                for (var e = 0u; e < 3u; e++) { pieces[e] = edge_pieces(s.squared[e], depth, split_edge_on_boundary(s, e)); }
            }
            if (pieces[0] == 1u && pieces[1] == 1u && pieces[2] == 1u) {
                let r = array<u32, 3>(leaf_factor(s.squared[0]), leaf_factor(s.squared[1]), leaf_factor(s.squared[2]));
                counts = uniform_setup(r, &words);
                children = 1u;
                patches[n + NODE_INFO] = s.info | NODE_LEAF;
            } else {
                children = uniform_setup(pieces, &words).y;
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
var<workgroup> split_sum: array<vec3<u32>, SCAN_GROUP>;
var<workgroup> split_wrapped: atomic<u32>;
@compute @workgroup_size(SCAN_GROUP)
fn ctess_split_scan(@builtin(local_invocation_id) lid: vec3<u32>) {
    let level = patches[split_header(SPLIT_LEVEL)];
    let n = patches[split_header(SPLIT_NODES)];
    let lane = lid.x;
    if (lane == 0u) { atomicStore(&split_wrapped, 0u); }
    let per = (n + (SCAN_GROUP - 1u)) / SCAN_GROUP;
    let begin = min(n, lane * per);
    let end = min(n, begin + per);
    var sum = vec3<u32>(0u);
    var wrapped = false; // the children's count past 32 bits: an overflow, never a wrapped level
    for (var i = begin; i < end; i++) {
        let node = split_node(level, i);
        let children = patches[node + NODE_CHILDREN];
        wrapped = wrapped || sum.x + children < sum.x;
        sum += vec3<u32>(children, patches[node + NODE_VERTICES], patches[node + NODE_TRIANGLES]);
    }
    split_sum[lane] = sum;
    workgroupBarrier();
    for (var d = 1u; d < SCAN_GROUP; d <<= 1u) {
        var add = vec3<u32>(0u);
        if (lane >= d) { add = split_sum[lane - d]; }
        workgroupBarrier();
        wrapped = wrapped || split_sum[lane].x + add.x < add.x;
        split_sum[lane] += add;
        workgroupBarrier();
    }
    if (wrapped) { atomicOr(&split_wrapped, 1u); }
    var base = split_sum[lane] - sum;
    for (var i = begin; i < end; i++) {
        let node = split_node(level, i);
        patches[node + NODE_FIRST_CHILD] = base.x;
        patches[node + NODE_FIRST_VERTEX] = base.y;
        patches[node + NODE_FIRST_TRIANGLE] = base.z;
        base += vec3<u32>(patches[node + NODE_CHILDREN], patches[node + NODE_VERTICES], patches[node + NODE_TRIANGLES]);
    }
    // Every lane has read the header and written its nodes before the header moves on.
    storageBarrier();
    workgroupBarrier();
    if (lane == SCAN_GROUP - 1u) {
        var children = split_sum[SCAN_GROUP - 1u].x;
        if (atomicLoad(&split_wrapped) != 0u) { children = 0xFFFFFFFFu; }
        let over = children > params[PARAM_SPLIT_CAPACITY] || patches[split_header(SPLIT_OVERFLOW)] != 0u;
        patches[split_header(SPLIT_NEEDED)] = max(patches[split_header(SPLIT_NEEDED)], children);
        patches[split_header(SPLIT_OVERFLOW)] = select(0u, 1u, over);
        patches[split_header(SPLIT_LEVEL)] = level + 1u;
        patches[split_header(SPLIT_PARENTS)] = n;
        patches[split_header(SPLIT_NODES)] = select(children, 0u, over);
        split_dispatch(select(children, 0u, over));
    }
}

// Pass: child slot j of the next level from its parent (the last node whose first child is at most j): a leaf
// is copied, a split node's child k is its split pattern's triangle k, its corners mapped on the root and its
// edges' squares from the parent's (UniformSplit child).
@compute @workgroup_size(SPLIT_GROUP)
fn ctess_split_expand(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let level = patches[split_header(SPLIT_LEVEL)];
    let nodes = patches[split_header(SPLIT_NODES)];
    let parents = patches[split_header(SPLIT_PARENTS)];
    for (var j = gid.x; j < nodes; j += groups.x * SPLIT_GROUP) {
        var low = 0u;
        var high = parents - 1u;
        while (low < high) {
            let mid = (low + high + 1u) / 2u;
            if (patches[split_node(level - 1u, mid) + NODE_FIRST_CHILD] <= j) { low = mid; } else { high = mid - 1u; }
        }
        let p = split_node(level - 1u, low);
        let s = load_node(p);
        var c = s;
        c.info = s.info & ~NODE_LEAF;
        if ((s.info & NODE_LEAF) == 0u) {
            let words = vec3<u32>(patches[p + NODE_PATTERN], patches[p + NODE_PATTERN + 1u], patches[p + NODE_PATTERN + 2u]);
            let tri = uniform_triangle(words, j - patches[p + NODE_FIRST_CHILD]);
            let a = uniform_local(words, tri.x);
            let b = uniform_local(words, tri.y);
            let d = uniform_local(words, tri.z);
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
fn split_leaves() -> u32 { return patches[split_header(SPLIT_PARENTS)]; }
fn split_leaf(i: u32) -> u32 { return split_node(patches[split_header(SPLIT_LEVEL)] - 1u, i); }
// The first leaf of a patch t or after it (the leaves lie in patch order): the emit passes' range of leaves.
fn split_first_leaf(t: u32) -> u32 {
    var low = 0u;
    var high = split_leaves();
    while (low < high) {
        let mid = (low + high) / 2u;
        if (patches[split_leaf(mid) + NODE_PATCH] < t) { low = mid + 1u; } else { high = mid; }
    }
    return low;
}
// The leaves of the patches in [first, end): no search at the ends of the mesh.
fn split_range_start(first: u32) -> u32 {
    if (first == 0u) { return 0u; }
    return split_first_leaf(first);
}
fn split_range_end(end: u32) -> u32 {
    if (end >= patch_count()) { return split_leaves(); }
    return split_first_leaf(end);
}

// Pass: each patch's counts from its leaves (they lie together, in patch order): the last leaf of a patch
// writes the record's counts, from the first one's prefix sums to its own end.
@compute @workgroup_size(SPLIT_GROUP)
fn ctess_split_records(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let leaves = split_leaves();
    for (var i = gid.x; i < leaves; i += groups.x * SPLIT_GROUP) {
        let n = split_leaf(i);
        let t = patches[n + NODE_PATCH];
        if (i + 1u < leaves && patches[split_leaf(i + 1u) + NODE_PATCH] == t) { continue; }
        var low = 0u;
        var high = i;
        while (low < high) {
            let mid = (low + high) / 2u;
            if (patches[split_leaf(mid) + NODE_PATCH] < t) { low = mid + 1u; } else { high = mid; }
        }
        let f = split_leaf(low);
        let rec = t * PATCH_WORDS;
        patches[rec + REC_VERTEX_COUNT] = patches[n + NODE_FIRST_VERTEX] + patches[n + NODE_VERTICES] - patches[f + NODE_FIRST_VERTEX];
        patches[rec + REC_TRIANGLE_COUNT] = patches[n + NODE_FIRST_TRIANGLE] + patches[n + NODE_TRIANGLES] - patches[f + NODE_FIRST_TRIANGLE];
    }
}
// A leaf's vertex i as the pipeline's base weights (2^-24): its pattern's point mapped on the root, then
// to_base_weights.
fn split_vertex(s: SplitNode, words: vec3<u32>, i: u32) -> vec2<u32> {
    let p = split_map(s, uniform_local(words, i));
    return vec2<u32>(split_base_weight(p.x), split_base_weight(p.y));
}
// An emit pass's work items over the patches [first_patch, end): those patches, or the split pattern's leaves
// of them. item_patch: an item's patch, and its leaf node (0 for a patch). (Ifs, not select(), which would read
// both sides: the split words exist only in a split run.)
fn emit_items(split_: bool, first_patch: u32, end: u32) -> vec2<u32> {
    if (split_) { return vec2<u32>(split_range_start(first_patch), split_range_end(end)); }
    return vec2<u32>(first_patch, end);
}
fn item_patch(split_: bool, item: u32, leaf: ptr<function, u32>) -> u32 {
    *leaf = 0u;
    if (!split_) { return item; }
    *leaf = split_leaf(item);
    return patches[*leaf + NODE_PATCH];
}

// ---- quads (docs/algorithm.md §7.2, §7.3): two triangle halves along a diagonal ----
fn mesh_eye() -> vec3<f32> {
    return vec3<f32>(bitcast<f32>(params[PARAM_EYE]), bitcast<f32>(params[PARAM_EYE + 1u]), bitcast<f32>(params[PARAM_EYE + 2u]));
}
// The factor and squared length of mesh edge (i, j), endpoints in mesh-index order (both faces get the same bits).
fn mesh_edge_factor(i: u32, j: u32) -> f32 {
    let a = mesh_position(min(i, j)); let b = mesh_position(max(i, j));
    return displaced_edge_factor(edge_tess_factor(a, b, mesh_eye(), bitcast<f32>(params[PARAM_FACTOR_SCALE])), a, b);
}
fn mesh_edge_length2(i: u32, j: u32) -> f32 {
    let d = mesh_position(max(i, j)) - mesh_position(min(i, j));
    return dot3(d, d);
}
// The quad rule: CP makes q0q1 the longer edge of the opposite pair with the larger summed length (the diagonal
// takes its factor); uniform density splits along the shorter diagonal. Ties and NaN keep the labelled order.
fn cp_quad_rotation(length2: array<f32, 4>) -> u32 {
    if (params[PARAM_QUAD_RULE] == QUAD_RULE_AS_LABELLED) { return 0u; }
    var len: array<f32, 4>;
    for (var k = 0u; k < 4u; k++) { len[k] = sqrt(length2[k]); }
    let first = select(0u, 1u, len[1] + len[3] > len[0] + len[2]);
    return select(first, first + 2u, len[first + 2u] > len[first]);
}
fn uniform_quad_rotation(w: array<u32, 4>) -> u32 {
    if (params[PARAM_QUAD_RULE] == QUAD_RULE_AS_LABELLED) { return 0u; }
    return select(0u, 1u, mesh_edge_length2(w[0], w[2]) < mesh_edge_length2(w[1], w[3]));
}
fn saturating_add(a: vec2<u32>, b: vec2<u32>) -> vec2<u32> {
    let sum = a + b;
    return select(sum, vec2<u32>(0xFFFFFFFFu), sum < a);
}
// A quad's record (rt::PatchRecord with kind PATCH_KIND_QUAD): rotation = the quad rule's, half A = (q0, q1, q3)'s
// line states (or uniform factors) as tokens, half B = (q2, q3, q1)'s in the setup words, the counts of both
// halves together, factors Q0..Q2 and Q3's bits in the setup words. No CP setup block: the emit passes set up
// each half themselves.
fn setup_one_quad(t: u32) {
    let rec = t * PATCH_WORDS;
    patches[rec + REC_KIND] = PATCH_KIND_QUAD;
    let wq = base_quad(t - triangle_count());
    if (!base_quad_valid(wq)) { return; }
    var w = array<u32, 4>(wq.x, wq.y, wq.z, wq.w);
    var f: array<f32, 4>;
    var length2: array<f32, 4>;
    for (var k = 0u; k < 4u; k++) {
        f[k] = mesh_edge_factor(w[k], w[(k + 1u) % 4u]);
        length2[k] = mesh_edge_length2(w[k], w[(k + 1u) % 4u]);
    }
    for (var k = 0u; k < 3u; k++) { patches[rec + REC_FACTOR + k] = bitcast<u32>(f[k]); }
    patches[rec + SETUP + QSETUP_Q3_FACTOR] = bitcast<u32>(f[3]);
    let uniform_ = uniform_pattern() || split_pattern();
    var r: u32;
    var diagonal: f32;
    if (uniform_) {
        r = uniform_quad_rotation(w);
        diagonal = mesh_edge_factor(w[(1u + r) % 4u], w[(3u + r) % 4u]);
    } else {
        r = cp_quad_rotation(length2);
        diagonal = f[r];
    }
    patches[rec + REC_ROTATION] = r;
    var fa = array<f32, 3>(f[r], diagonal, f[(r + 3u) % 4u]);
    var fb = array<f32, 3>(f[(r + 2u) % 4u], diagonal, f[(r + 1u) % 4u]);
    var counts: vec2<u32>;
    if (uniform_) {
        var ia: array<u32, 3>;
        var ib: array<u32, 3>;
        for (var k = 0u; k < 3u; k++) {
            ia[k] = uniform_factor(fa[k]);
            ib[k] = uniform_factor(fb[k]);
            patches[rec + REC_TOKEN + k] = ia[k];
            patches[rec + SETUP + QSETUP_B_TOKEN + k] = ib[k];
        }
        var words: vec3<u32>;
        // A split quad's counts come from its halves' leaves (ctess_split_records).
        if (split_pattern()) { counts = vec2<u32>(0u); } else { counts = saturating_add(uniform_setup(ia, &words), uniform_setup(ib, &words)); }
    } else {
        // One loop over the halves: one copy of patch_setup in the compiled pass, not two.
        counts = vec2<u32>(0u);
        for (var side = 0u; side < 2u; side++) {
            var st: array<vec2<u32>, 3>;
            for (var k = 0u; k < 3u; k++) {
                st[k] = line_state(select(fb[k], fa[k], side == 0u));
                patches[rec + select(SETUP + QSETUP_B_TOKEN, REC_TOKEN, side == 0u) + k] = st[k].x;
                patches[rec + select(SETUP + QSETUP_B_T16, REC_T16, side == 0u) + k] = st[k].y;
            }
            let half_patch = patch_setup(st[0], st[1], st[2]);
            counts = saturating_add(counts, vec2<u32>(half_patch.vertices, half_patch.triangles));
        }
    }
    patches[rec + REC_VERTEX_COUNT] = counts.x;
    patches[rec + REC_TRIANGLE_COUNT] = counts.y;
}
// The line states of quad half h (A = 0 from the tokens, B = 1 from the setup words).
fn quad_half_state(rec: u32, h: u32, k: u32) -> vec2<u32> {
    if (h == 0u) { return vec2<u32>(patches[rec + REC_TOKEN + k], patches[rec + REC_T16 + k]); }
    return vec2<u32>(patches[rec + SETUP + QSETUP_B_TOKEN + k], patches[rec + SETUP + QSETUP_B_T16 + k]);
}
// Both halves of a quad record, as the emit passes need them: the CP patches (CP) or the uniform setup words of
// half A (index 0) and B (1); returns half A's vertex and triangle counts.
fn quad_halves(rec: u32, halves: ptr<function, array<Patch, 2>>, words: ptr<function, array<vec3<u32>, 2>>) -> vec2<u32> {
    var counts_a: vec2<u32>;
    for (var side = 0u; side < 2u; side++) { // one copy of patch_setup in the compiled pass
        let s0 = quad_half_state(rec, side, 0u); let s1 = quad_half_state(rec, side, 1u); let s2 = quad_half_state(rec, side, 2u);
        var counts: vec2<u32>;
        if (uniform_pattern()) {
            var w: vec3<u32>;
            counts = uniform_setup(array<u32, 3>(s0.x, s1.x, s2.x), &w);
            (*words)[side] = w;
        } else {
            (*halves)[side] = patch_setup(s0, s1, s2);
            counts = vec2<u32>((*halves)[side].vertices, (*halves)[side].triangles);
        }
        if (side == 0u) { counts_a = counts; }
    }
    return counts_a;
}
fn store_vertex(o: u32, u: u32, v: u32, sp: SurfacePoint) {
    out_vertices[o + VERTEX_U] = u;
    out_vertices[o + VERTEX_V] = v;
    out_vertices[o + VERTEX_POSITION] = bitcast<u32>(sp.position.x);
    out_vertices[o + (VERTEX_POSITION + 1u)] = bitcast<u32>(sp.position.y);
    out_vertices[o + (VERTEX_POSITION + 2u)] = bitcast<u32>(sp.position.z);
    out_vertices[o + VERTEX_NORMAL] = bitcast<u32>(sp.normal.x);
    out_vertices[o + (VERTEX_NORMAL + 1u)] = bitcast<u32>(sp.normal.y);
    out_vertices[o + (VERTEX_NORMAL + 2u)] = bitcast<u32>(sp.normal.z);
    out_vertices[o + VERTEX_UV] = bitcast<u32>(sp.uv.x);
    out_vertices[o + (VERTEX_UV + 1u)] = bitcast<u32>(sp.uv.y);
}
// Grid-stride: a host may dispatch fewer workgroups than patches / SETUP_GROUP (at most MAX_DISPATCH_WORKGROUPS).
@compute @workgroup_size(SETUP_GROUP)
fn ctess_patch_setup(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let stride = groups.x * SETUP_GROUP;
    for (var t = gid.x; t < patch_count(); t += stride) { setup_one_patch(t); }
}

// Pass 2, one workgroup of SCAN_GROUP = 128 (WebGPU compatibility mode allows at most 128 invocations): exclusive prefix sums of the counts; the totals follow the records.
// Totals that do not fit in u32 (indices are u32) are written as TOTALS_OVERFLOW, both of them: hosts refuse them.
var<workgroup> scan_sum: array<vec2<u32>, SCAN_GROUP>;
var<workgroup> scan_overflow: atomic<u32>;
@compute @workgroup_size(SCAN_GROUP)
fn ctess_prefix_sum(@builtin(local_invocation_id) lid: vec3<u32>) {
    let n = patch_count();
    let lane = lid.x;
    if (lane == 0u) { atomicStore(&scan_overflow, 0u); }
    var overflow = false;
    let per = (n + (SCAN_GROUP - 1u)) / SCAN_GROUP;
    let begin = min(n, lane * per);
    let end = min(n, begin + per);
    var sum = vec2<u32>(0u);
    for (var t = begin; t < end; t++) {
        let count = vec2<u32>(patches[t * PATCH_WORDS + REC_VERTEX_COUNT], patches[t * PATCH_WORDS + REC_TRIANGLE_COUNT]);
        sum += count;
        overflow = overflow || sum.x < count.x || sum.y < count.y || sum.x == TOTALS_OVERFLOW || sum.y == TOTALS_OVERFLOW;
    }
    scan_sum[lane] = sum;
    workgroupBarrier();
    for (var d = 1u; d < SCAN_GROUP; d <<= 1u) {
        var add = vec2<u32>(0u);
        if (lane >= d) { add = scan_sum[lane - d]; }
        workgroupBarrier();
        let before = scan_sum[lane];
        let after = before + add;
        overflow = overflow || after.x < before.x || after.y < before.y || after.x == TOTALS_OVERFLOW || after.y == TOTALS_OVERFLOW;
        scan_sum[lane] = after;
        workgroupBarrier();
    }
    if (overflow) { atomicOr(&scan_overflow, 1u); }
    workgroupBarrier();
    var base = scan_sum[lane] - sum;
    for (var t = begin; t < end; t++) {
        let rec = t * PATCH_WORDS;
        patches[rec + REC_FIRST_VERTEX] = base.x;
        patches[rec + REC_FIRST_TRIANGLE] = base.y;
        base += vec2<u32>(patches[rec + REC_VERTEX_COUNT], patches[rec + REC_TRIANGLE_COUNT]);
    }
    if (lane == SCAN_GROUP - 1u) {
        let too_large = atomicLoad(&scan_overflow) != 0u;
        patches[n * PATCH_WORDS] = select(scan_sum[SCAN_GROUP - 1u].x, TOTALS_OVERFLOW, too_large);
        patches[n * PATCH_WORDS + 1u] = select(scan_sum[SCAN_GROUP - 1u].y, TOTALS_OVERFLOW, too_large);
    }
}

// ---- the welded output (docs/shaders.md, "Welded output"; docs/algorithm.md §7.4; Pattern::cp and uniform) ----
// Binding 7 (rt::gpu::weld_word): the header, the mesh's edges (rt::WeldedEdge, lo and hi from the host, sorted and
// distinct), a rt::WeldedPatch per patch, then a writer word per shared id, a map word per slot (unwelded vertex)
// and WELD_SORT_WORDS per slot. Ids as setup_welded numbers them: a corner is its mesh vertex, an edge point the
// edge's first id plus the rank of its parameter from the lower index, an interior point the patch's first id plus
// the rank of its exact domain point among the patch's distinct interior points.
fn weld_on() -> bool { return (params[PARAM_WELD] & WELD_ON) != 0u; }
// The weld by one sort over the mesh (ctess_weld_keys and after): the split pattern's, and any other's with a
// patch past WELD_MAX_PATCH_SLOTS.
fn weld_sorted() -> bool { return split_pattern() || (params[PARAM_WELD] & WELD_SORTED) != 0u; }
fn weld_edge_count() -> u32 { return weld[WELD_EDGES]; }
fn weld_edge(e: u32) -> u32 { return WELD_HEADER_WORDS + e * WELD_EDGE_WORDS; }
fn weld_patch(t: u32) -> u32 { return weld_edge(weld_edge_count()) + t * WELD_PATCH_WORDS; }
fn weld_writer(id: u32) -> u32 { return weld_patch(patch_count()) + id; }
fn weld_map(s: u32) -> u32 { return weld_writer(params[PARAM_MESH_VERTEX_COUNT] + weld[WELD_SLOTS]) + s; }
fn weld_sort(s: u32) -> u32 { return weld_map(weld[WELD_SLOTS]) + WELD_SORT_WORDS * s; }
// A weld_status flag by a plain read-modify-write (the GLSL's atomicOr): these passes use `weld`, and an entry point
// may not use weld_atomic too. The word only gains flags: ctess_weld_count's racing workgroups all set
// WELD_MISSING_EDGE, and WELD_OVERFLOW comes from one lane of a one-workgroup scan, so a lost race still leaves the
// flag set.
fn weld_flag_status(flag: u32) { weld[WELD_STATUS] = weld[WELD_STATUS] | flag; }

// Edge (a, b) of the sorted list (a binary search); a missing edge (a list the host did not make with
// rt::weld_edge_list) sets WELD_MISSING_EDGE and gives edge 0.
fn weld_find_edge(a: u32, b: u32) -> u32 {
    let lo_ = min(a, b);
    let hi_ = max(a, b);
    var first = 0u;
    var count = weld_edge_count();
    while (count > 0u) {
        let half_ = count / 2u;
        let m = weld_edge(first + half_);
        if (weld[m + WEDGE_LO] < lo_ || (weld[m + WEDGE_LO] == lo_ && weld[m + WEDGE_HI] < hi_)) {
            first += half_ + 1u;
            count -= half_ + 1u;
        } else {
            count = half_;
        }
    }
    let m = weld_edge(first);
    if (first >= weld_edge_count() || weld[m + WEDGE_LO] != lo_ || weld[m + WEDGE_HI] != hi_) {
        weld_flag_status(WELD_MISSING_EDGE);
        return 0u;
    }
    return first;
}

// The distinct interior parameters below x of the line of an edge of factor f (x = FIXED_ONE: all of them), as
// EdgeParams (mesh_pipeline.cpp): CP line points rise with their index (ties where a segment has zero length),
// uniform ones strictly.
fn line_rank(f: f32, x: u32) -> u32 {
    if (uniform_pattern()) {
        let n = uniform_factor(f); // the first i in [1, n) whose parameter is >= x
        var lo_ = 1u;
        var hi_ = n;
        while (lo_ < hi_) {
            let mid = (lo_ + hi_) / 2u;
            if (uniform_to_fixed(uniform_edge_parameter(mid, n)) < x) { lo_ = mid + 1u; } else { hi_ = mid; }
        }
        return lo_ - 1u;
    }
    let s = line_state(f);
    if (s.x == 0u) { return 0u; }
    let e = line_edge(s);
    var rank = 0u;
    var previous = 0u;
    for (var i = 1u; i < e.segments; i++) {
        let point = edge_point(e, i);
        if (point >= x) { break; }
        if (point != previous) { rank++; }
        previous = point;
    }
    return rank;
}

// Patch t as the weld reads it: its mesh corners, rotation and pattern halves; false for a culled patch.
struct WeldPatch {
    quad: bool,
    rot: u32,
    w: array<u32, 4>,
    halves: array<Patch, 2>,
    words: array<vec3<u32>, 2>,
    counts_a: vec2<u32>, // half A's vertices and triangles (a base triangle's all)
    vertices: u32,
    triangles: u32,
    first: u32,
}
fn weld_load(t: u32, wp: ptr<function, WeldPatch>) -> bool {
    let rec = t * PATCH_WORDS;
    (*wp).vertices = patches[rec + REC_VERTEX_COUNT];
    (*wp).triangles = patches[rec + REC_TRIANGLE_COUNT];
    (*wp).first = patches[rec + REC_FIRST_VERTEX];
    (*wp).rot = patches[rec + REC_ROTATION];
    (*wp).quad = t >= triangle_count();
    (*wp).w = array<u32, 4>(0u, 0u, 0u, 0u);
    if ((*wp).vertices == 0u) { return false; }
    if ((*wp).quad) {
        let wq = base_quad(t - triangle_count());
        if (!base_quad_valid(wq)) { return false; }
        (*wp).w = array<u32, 4>(wq.x, wq.y, wq.z, wq.w);
        var halves: array<Patch, 2>; // locals: two pointers into *wp would alias (WGSL refuses them)
        var words: array<vec3<u32>, 2>;
        (*wp).counts_a = quad_halves(rec, &halves, &words);
        (*wp).halves = halves;
        (*wp).words = words;
        return true;
    }
    let w = base_triangle(t);
    if (!base_triangle_valid(w)) { return false; }
    (*wp).w = array<u32, 4>(w.x, w.y, w.z, 0u);
    var half_patch: Patch; // zero-initialised: unused by the uniform pattern
    if (!uniform_pattern()) { half_patch = record_patch(rec); }
    (*wp).halves[0] = half_patch;
    (*wp).words[0] = uniform_words(rec);
    (*wp).halves[1] = (*wp).halves[0];
    (*wp).words[1] = (*wp).words[0];
    (*wp).counts_a = vec2<u32>((*wp).vertices, (*wp).triangles);
    return true;
}

// Where the point d of half `side` lies, as slot_place (mesh_pipeline.cpp): 0 a corner (its mesh vertex in
// place.x), else 1 on the first mesh edge whose weight is zero (a quad half's diagonal is inside): its mesh
// vertices in place.xy and its parameter from the lower index in place.z, else 2 inside, with its domain point in
// key (a triangle's base weights (w1, w2), a quad's unit square). key is (~0, ~0) but inside.
fn weld_place(wp: ptr<function, WeldPatch>, side: u32, d_in: vec2<u32>, place: ptr<function, vec3<u32>>,
              key: ptr<function, vec2<u32>>) -> u32 {
    *key = vec2<u32>(0xFFFFFFFFu);
    *place = vec3<u32>(0u);
    var d = d_in;
    let rot = (*wp).rot;
    var a: u32;
    var b: u32;
    var x: u32;
    if ((*wp).quad) {
        if (side == 1u) { d = vec2<u32>(FIXED_ONE - d.x, FIXED_ONE - d.y); } // half B: cp::quad_point
        var on_edge = array<bool, 4>(d.y == 0u, d.x == FIXED_ONE, d.y == FIXED_ONE, d.x == 0u);
        var r = array<u32, 4>(d.x, d.y, FIXED_ONE - d.x, FIXED_ONE - d.y); // from q_k along edge k
        var k = 4u;
        for (var e = 0u; e < 4u && k == 4u; e++) { if (on_edge[e]) { k = e; } }
        if (k == 4u) {
            *key = d;
            return 2u;
        }
        a = (*wp).w[(k + rot) % 4u];
        b = (*wp).w[(k + 1u + rot) % 4u];
        if (r[k] == 0u || r[k] == FIXED_ONE) {
            (*place).x = select(b, a, r[k] == 0u);
            return 0u;
        }
        x = select(FIXED_ONE - r[k], r[k], a <= b);
    } else {
        var pw = array<u32, 3>(FIXED_ONE - d.x - d.y, d.x, d.y);
        var w3: array<u32, 3>;
        for (var k = 0u; k < 3u; k++) { w3[(k + rot) % 3u] = pw[k]; }
        for (var c = 0u; c < 3u; c++) {
            if (w3[c] == FIXED_ONE) {
                (*place).x = (*wp).w[c];
                return 0u;
            }
        }
        var j = 3u;
        if (w3[0] == 0u) { j = 0u; } else if (w3[1] == 0u) { j = 1u; } else if (w3[2] == 0u) { j = 2u; }
        if (j == 3u) {
            *key = vec2<u32>(w3[1], w3[2]);
            return 2u;
        }
        let i1 = (j + 1u) % 3u;
        let i2 = (j + 2u) % 3u;
        a = (*wp).w[i1];
        b = (*wp).w[i2];
        x = select(w3[i1], w3[i2], a <= b);
    }
    *place = vec3<u32>(a, b, x);
    return 1u;
}

// Slot i's pattern point and its half (half B's slots after half A's).
fn weld_slot_point(wp: ptr<function, WeldPatch>, i: u32, side: ptr<function, u32>) -> vec2<u32> {
    let counts_a = (*wp).counts_a;
    *side = select(1u, 0u, i < counts_a.x);
    let local = select(i - counts_a.x, i, *side == 0u);
    if (uniform_pattern()) { return uniform_vertex((*wp).words[*side], local); }
    return patch_vertex(&(*wp).halves[*side], local);
}

// Slot i's shared id (a corner's mesh vertex, an edge point's id), or WELD_INTERIOR with its domain point in key;
// shared slots get key (~0, ~0), which sorts last.
fn weld_slot(wp: ptr<function, WeldPatch>, i: u32, key: ptr<function, vec2<u32>>) -> u32 {
    var side: u32;
    let d = weld_slot_point(wp, i, &side);
    var place: vec3<u32>;
    let kind = weld_place(wp, side, d, &place, key);
    if (kind == 0u) { return place.x; }
    if (kind == 2u) { return WELD_INTERIOR; }
    return weld[weld_edge(weld_find_edge(place.x, place.y)) + WEDGE_FIRST_VERTEX] +
           line_rank(mesh_edge_factor(place.x, place.y), place.z);
}

// Pattern triangle k's slots (half B's after half A's vertices).
fn weld_triangle_slots(wp: ptr<function, WeldPatch>, k: u32) -> vec3<u32> {
    let counts_a = (*wp).counts_a;
    let side = select(1u, 0u, k < counts_a.y);
    let local = select(k - counts_a.y, k, side == 0u);
    var tri: vec3<u32>;
    if (uniform_pattern()) { tri = uniform_triangle((*wp).words[side], local); } else { tri = patch_triangle(&(*wp).halves[side], local); }
    return tri + vec3<u32>(select(counts_a.x, 0u, side == 0u));
}
// A map word as an id within the patch's weld (interior ranks keep WELD_INTERIOR), for comparisons.
fn weld_local_id(m: u32) -> u32 { return select(m, m & ~WELD_REPRESENTATIVE, (m & WELD_INTERIOR) != 0u); }
// A map word as an output id, interior ranks after the patch's first interior id.
fn weld_output_id(m: u32, first_interior: u32) -> u32 {
    return select(m, first_interior + (m & WELD_RANK_MASK), (m & WELD_INTERIOR) != 0u);
}
fn weld_kept(ids: vec3<u32>) -> bool {
    return (params[PARAM_WELD] & WELD_KEEP_DEGENERATE) != 0u || (ids.x != ids.y && ids.y != ids.z && ids.x != ids.z);
}

// Weld pass 1, grid-stride: clears the writer words and counts each edge's distinct interior points.
@compute @workgroup_size(EMIT_GROUP)
fn ctess_weld_edges(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let stride = groups.x * EMIT_GROUP;
    let ids = params[PARAM_MESH_VERTEX_COUNT] + weld[WELD_SLOTS];
    for (var id = gid.x; id < ids; id += stride) { weld[weld_writer(id)] = 0u; }
    // The weld by one sort counts from the ranks (ctess_weld_owner_counts): its owners' words start at 0.
    let sorted_ = weld_sorted();
    for (var e = gid.x; e < weld_edge_count(); e += stride) {
        let m = weld_edge(e);
        var count = 0u;
        if (!sorted_) { count = line_rank(mesh_edge_factor(weld[m + WEDGE_LO], weld[m + WEDGE_HI]), FIXED_ONE); }
        weld[m + WEDGE_VERTEX_COUNT] = count;
    }
    if (!sorted_) { return; }
    for (var t = gid.x; t < patch_count(); t += stride) {
        for (var k = 0u; k < WELD_PATCH_WORDS; k++) { weld[weld_patch(t) + k] = 0u; }
    }
}

// Exclusive prefix sums in one workgroup of SCAN_GROUP over n records of `stride` words from base: the counts at
// count_word (.y too when two) into first_word, from start. Returns the end; sets WELD_OVERFLOW past 2^31.
// (scan_sum and scan_overflow are ctess_prefix_sum's: another entry point, so not shared with it.)
fn weld_prefix(lane: u32, base: u32, stride: u32, n: u32, count_word: vec2<u32>, first_word: vec2<u32>, two: bool,
               start: vec2<u32>) -> vec2<u32> {
    if (lane == 0u) { atomicStore(&scan_overflow, 0u); }
    var overflow = false;
    let per = (n + (SCAN_GROUP - 1u)) / SCAN_GROUP;
    let begin = min(n, lane * per);
    let end = min(n, begin + per);
    var sum = vec2<u32>(0u);
    for (var t = begin; t < end; t++) {
        let r = base + t * stride;
        var count = vec2<u32>(weld[r + count_word.x], 0u);
        if (two) { count.y = weld[r + count_word.y]; }
        sum += count;
        overflow = overflow || sum.x < count.x || sum.y < count.y;
    }
    scan_sum[lane] = sum;
    workgroupBarrier();
    for (var d = 1u; d < SCAN_GROUP; d <<= 1u) {
        var add = vec2<u32>(0u);
        if (lane >= d) { add = scan_sum[lane - d]; }
        workgroupBarrier();
        let before = scan_sum[lane];
        let after = before + add;
        overflow = overflow || after.x < before.x || after.y < before.y;
        scan_sum[lane] = after;
        workgroupBarrier();
    }
    let total = scan_sum[SCAN_GROUP - 1u];
    let end_ = start + total;
    overflow = overflow || end_.x < start.x || end_.y < start.y || end_.x >= WELD_INTERIOR || end_.y >= WELD_INTERIOR;
    if (overflow) { atomicOr(&scan_overflow, 1u); }
    var at = start + scan_sum[lane] - sum;
    for (var t = begin; t < end; t++) {
        let r = base + t * stride;
        weld[r + first_word.x] = at.x;
        at.x += weld[r + count_word.x];
        if (two) {
            weld[r + first_word.y] = at.y;
            at.y += weld[r + count_word.y];
        }
    }
    workgroupBarrier();
    if (lane == 0u && atomicLoad(&scan_overflow) != 0u) { weld_flag_status(WELD_OVERFLOW); }
    return end_;
}

// Weld pass 2, one workgroup: the edges' first ids, after the mesh vertices.
@compute @workgroup_size(SCAN_GROUP)
fn ctess_weld_edge_scan(@builtin(local_invocation_id) lid: vec3<u32>) {
    let end_ = weld_prefix(lid.x, weld_edge(0u), WELD_EDGE_WORDS, weld_edge_count(), vec2<u32>(WEDGE_VERTEX_COUNT, 0u),
                           vec2<u32>(WEDGE_FIRST_VERTEX, 0u), false, vec2<u32>(params[PARAM_MESH_VERTEX_COUNT], 0u));
    if (lid.x == 0u) { weld[WELD_SHARED] = end_.x; }
}

// Weld pass 3, a workgroup per patch: every slot's map word (its shared id, or its interior rank after a sort of
// the patch's points by (u, v, slot)), the patch's distinct interior points and kept triangles.
var<workgroup> weld_lane: array<u32, EMIT_GROUP>;
var<workgroup> weld_kept_count: atomic<u32>;
var<workgroup> weld_distinct: atomic<u32>;
// A patch's count that the workgroup's barriers depend on, through workgroupUniformLoad: values read from a
// read_write binding are not uniform to WGSL's analysis, and a barrier must be in uniform control flow.
var<workgroup> weld_uniform: u32;
var<workgroup> weld_batch: u32; // the batch's first patch (apart from weld_uniform, which the loop rewrites)
// The inclusive prefix sum of each lane's value in weld_lane; every lane must call it.
fn weld_lane_sum(lane: u32, value: u32) -> u32 {
    weld_lane[lane] = value;
    workgroupBarrier();
    for (var d = 1u; d < EMIT_GROUP; d <<= 1u) {
        var add = 0u;
        if (lane >= d) { add = weld_lane[lane - d]; }
        workgroupBarrier();
        weld_lane[lane] += add;
        workgroupBarrier();
    }
    return weld_lane[lane];
}
fn weld_lane_scan(lane: u32, flag: bool) -> u32 { return weld_lane_sum(lane, select(0u, 1u, flag)); }
fn weld_sort_less(a: u32, b: u32) -> bool {
    let x = vec3<u32>(weld[a], weld[a + 1u], weld[a + 2u]);
    let y = vec3<u32>(weld[b], weld[b + 1u], weld[b + 2u]);
    if (x.x != y.x) { return x.x < y.x; }
    if (x.y != y.y) { return x.y < y.y; }
    return x.z < y.z;
}
@compute @workgroup_size(EMIT_GROUP)
fn ctess_weld_count(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>,
                    @builtin(local_invocation_id) lid: vec3<u32>) {
    let lane = lid.x;
    // One patch per workgroup: the host dispatches batches from WELD_FIRST_PATCH, so that no invocation loops over
    // several patches (llvmpipe ends every loop of an invocation after 65,535 iterations in all, without an error).
    if (lane == 0u) { weld_batch = weld[WELD_FIRST_PATCH]; }
    let first_patch = workgroupUniformLoad(&weld_batch);
    let end = min(patch_count(), first_patch + groups.x);
    for (var t = first_patch + wid.x; t < end; t += groups.x) {
        let wpw = weld_patch(t);
        var wp: WeldPatch;
        let loaded = weld_load(t, &wp);
        // The slots, 0 for a culled patch (a loaded one has some), the same for every lane.
        if (lane == 0u) { weld_uniform = select(0u, wp.vertices, loaded); }
        let n = workgroupUniformLoad(&weld_uniform);
        if (n == 0u) {
            if (lane == 0u) {
                weld[wpw + WPATCH_VERTEX_COUNT] = 0u;
                weld[wpw + WPATCH_TRIANGLE_COUNT] = 0u;
            }
            continue;
        }
        for (var i = lane; i < n; i += EMIT_GROUP) {
            var key: vec2<u32>;
            let id = weld_slot(&wp, i, &key);
            let o = weld_sort(wp.first + i);
            weld[weld_map(wp.first + i)] = id;
            weld[o] = key.x;
            weld[o + 1u] = key.y;
            weld[o + 2u] = i;
        }
        if (lane == 0u) { atomicStore(&weld_distinct, 0u); }
        storageBarrier();
        workgroupBarrier();
        var distinct = 0u;
        if (n <= WELD_COUNTED_RANKS) {
            // A small patch ranks by counting: a slot is its point's first when no earlier slot has the point, and
            // its rank counts the first slots of smaller points (the sort's numbering, with two barriers where the
            // sort takes one per stage: a software adapter pays for each).
            for (var i = lane; i < n; i += EMIT_GROUP) {
                let o = weld_sort(wp.first + i);
                var first = weld[o] != 0xFFFFFFFFu;
                for (var j = 0u; j < i && first; j++) {
                    let oj = weld_sort(wp.first + j);
                    first = weld[oj] != weld[o] || weld[oj + 1u] != weld[o + 1u];
                }
                weld[o + 2u] = select(0u, 1u, first);
            }
            storageBarrier();
            workgroupBarrier();
            var firsts = 0u;
            for (var i = lane; i < n; i += EMIT_GROUP) {
                let o = weld_sort(wp.first + i);
                if (weld[o] == 0xFFFFFFFFu) { continue; }
                var rank = 0u;
                for (var j = 0u; j < n; j++) {
                    let oj = weld_sort(wp.first + j);
                    if (weld[oj + 2u] != 0u && (weld[oj] < weld[o] || (weld[oj] == weld[o] && weld[oj + 1u] < weld[o + 1u]))) { rank++; }
                }
                let first = weld[o + 2u] != 0u;
                if (first) { firsts++; }
                weld[weld_map(wp.first + i)] = WELD_INTERIOR | rank | select(0u, WELD_REPRESENTATIVE, first);
            }
            atomicAdd(&weld_distinct, firsts);
            workgroupBarrier();
            distinct = atomicLoad(&weld_distinct);
        } else {
            // A bitonic sort, every comparator ascending (each block's first stage compares mirrored pairs), with the
            // entries past n taken as +inf: a comparator that reaches past n is skipped.
            var size = 1u;
            while (size < n) { size <<= 1u; }
            for (var k = 2u; k <= size; k <<= 1u) {
                for (var j = k >> 1u; j > 0u; j >>= 1u) {
                    for (var q = lane; q < size / 2u; q += EMIT_GROUP) {
                        let i = (q / j) * 2u * j + q % j;
                        let partner = select(i + j, i ^ (k - 1u), j == (k >> 1u));
                        if (partner >= n) { continue; }
                        let oa = weld_sort(wp.first + i);
                        let ob = weld_sort(wp.first + partner);
                        if (weld_sort_less(ob, oa)) {
                            for (var w = 0u; w < WELD_SORT_WORDS; w++) {
                                let x = weld[oa + w];
                                weld[oa + w] = weld[ob + w];
                                weld[ob + w] = x;
                            }
                        }
                    }
                    storageBarrier();
                    workgroupBarrier();
                }
            }
            // The interior entries (first after the sort) numbered by distinct point.
            for (var base_ = 0u; base_ < n; base_ += EMIT_GROUP) {
                let j = base_ + lane;
                let o = weld_sort(wp.first + min(j, n - 1u));
                let interior = j < n && weld[o] != 0xFFFFFFFFu;
                let fresh = interior && (j == 0u || weld[o - WELD_SORT_WORDS] != weld[o] || weld[o - WELD_SORT_WORDS + 1u] != weld[o + 1u]);
                let rank = distinct + weld_lane_scan(lane, fresh) - 1u;
                if (interior) { weld[weld_map(wp.first + weld[o + 2u])] = WELD_INTERIOR | rank | select(0u, WELD_REPRESENTATIVE, fresh); }
                distinct += weld_lane[EMIT_GROUP - 1u];
                workgroupBarrier();
            }
        }
        if (lane == 0u) { atomicStore(&weld_kept_count, 0u); }
        storageBarrier();
        workgroupBarrier();
        var kept = 0u;
        for (var k = lane; k < wp.triangles; k += EMIT_GROUP) {
            let s = weld_triangle_slots(&wp, k) + vec3<u32>(wp.first);
            let ids = vec3<u32>(weld_local_id(weld[weld_map(s.x)]), weld_local_id(weld[weld_map(s.y)]), weld_local_id(weld[weld_map(s.z)]));
            if (weld_kept(ids)) { kept++; }
        }
        atomicAdd(&weld_kept_count, kept);
        workgroupBarrier();
        if (lane == 0u) {
            weld[wpw + WPATCH_VERTEX_COUNT] = distinct;
            weld[wpw + WPATCH_TRIANGLE_COUNT] = atomicLoad(&weld_kept_count);
        }
        workgroupBarrier();
    }
}

// Weld pass 4, grid-stride over the slots: each shared id's writer, the last slot that reaches it (as the CPU's
// patches last to first, and within a patch its last slot). atomicMax: the result does not depend on the order.
// Only weld_atomic here (binding 7 as atomics): weld_writer and weld_map's words from the header's atomically read.
@compute @workgroup_size(EMIT_GROUP)
fn ctess_weld_writers(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let stride = groups.x * EMIT_GROUP;
    let slots = atomicLoad(&weld_atomic[WELD_SLOTS]);
    let writers = weld_edge(atomicLoad(&weld_atomic[WELD_EDGES])) + patch_count() * WELD_PATCH_WORDS; // weld_writer(0)
    let map = writers + params[PARAM_MESH_VERTEX_COUNT] + slots; // weld_map(0)
    // The weld by one sort has ids in its map words (interior ones marked): every id gets a writer.
    let sorted_ = weld_sorted();
    for (var s = gid.x; s < slots; s += stride) {
        let m = atomicLoad(&weld_atomic[map + s]);
        if (sorted_) {
            atomicMax(&weld_atomic[writers + (m & ~WELD_INTERIOR)], s + 1u);
        } else if ((m & WELD_INTERIOR) == 0u) {
            atomicMax(&weld_atomic[writers + m], s + 1u);
        }
    }
}

// Weld pass 5, one workgroup: the patches' first interior ids (after the shared ones) and first triangles, and the
// totals.
@compute @workgroup_size(SCAN_GROUP)
fn ctess_weld_scan(@builtin(local_invocation_id) lid: vec3<u32>) {
    let end_ = weld_prefix(lid.x, weld_patch(0u), WELD_PATCH_WORDS, patch_count(), vec2<u32>(WPATCH_VERTEX_COUNT, WPATCH_TRIANGLE_COUNT),
                           vec2<u32>(WPATCH_FIRST_VERTEX, WPATCH_FIRST_TRIANGLE), true, vec2<u32>(weld[WELD_SHARED], 0u));
    if (lid.x == 0u) {
        weld[WELD_VERTICES] = end_.x;
        weld[WELD_TRIANGLES] = end_.y;
    }
}

// Weld emit, a workgroup per patch of the emit range (triangles and quads): the kept triangles in pattern order.
@compute @workgroup_size(EMIT_GROUP)
fn ctess_weld_triangles(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>,
                        @builtin(local_invocation_id) lid: vec3<u32>) {
    let lane = lid.x;
    // One patch per workgroup, batches from WELD_FIRST_PATCH as ctess_weld_count's, within the params' emit range.
    if (lane == 0u) { weld_batch = weld[WELD_FIRST_PATCH]; }
    let batch = workgroupUniformLoad(&weld_batch);
    let end = min(min(params[PARAM_END_PATCH], patch_count()), batch + groups.x);
    for (var t = max(batch, params[PARAM_FIRST_PATCH]) + wid.x; t < end; t += groups.x) {
        var wp: WeldPatch;
        let loaded = weld_load(t, &wp);
        // The pattern's triangles, 0 for a culled patch, the same for every lane (ctess_weld_count).
        if (lane == 0u) { weld_uniform = select(0u, wp.triangles, loaded); }
        let triangles = workgroupUniformLoad(&weld_uniform);
        if (triangles == 0u) { continue; }
        let wpw = weld_patch(t);
        let first_interior = weld[wpw + WPATCH_FIRST_VERTEX];
        var written = weld[wpw + WPATCH_FIRST_TRIANGLE];
        for (var base_ = 0u; base_ < triangles; base_ += EMIT_GROUP) {
            let k = base_ + lane;
            var ids = vec3<u32>(0u);
            var keep = false;
            if (k < triangles) {
                let s = weld_triangle_slots(&wp, k) + vec3<u32>(wp.first);
                ids = vec3<u32>(weld_output_id(weld[weld_map(s.x)], first_interior), weld_output_id(weld[weld_map(s.y)], first_interior),
                                weld_output_id(weld[weld_map(s.z)], first_interior));
                keep = weld_kept(ids);
            }
            let before = weld_lane_scan(lane, keep);
            if (keep) {
                let o = 3u * (written + before - 1u);
                out_indices[o] = ids.x;
                out_indices[o + 1u] = ids.y;
                out_indices[o + 2u] = ids.z;
            }
            written += weld_lane[EMIT_GROUP - 1u];
            workgroupBarrier();
        }
    }
}

// Weld emit, grid-stride over the mesh vertices: each one no face reaches (no writer) as its corner value, as
// emit_welded_mesh (a corner of its own, displaced with itself as the dominant vertex and no neighbours).
@compute @workgroup_size(EMIT_GROUP)
fn ctess_weld_lone_vertices(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let stride = groups.x * EMIT_GROUP;
    let surface = params[PARAM_SURFACE];
    let alpha = bitcast<f32>(params[PARAM_ALPHA]);
    let vector_ = displacement_vector_mode();
    for (var v = gid.x; v < params[PARAM_MESH_VERTEX_COUNT]; v += stride) {
        if (weld[weld_writer(v)] != 0u) { continue; }
        let c = mesh_corner(v);
        let tri = array<Corner, 3>(c, c, c);
        let w3 = array<u32, 3>(FIXED_ONE, 0u, 0u);
        let own_normals = EdgeNormals(c.normal, c.normal);
        var sp: SurfacePoint;
        if (surface == SURFACE_PN_AEN) {
            sp = evaluate_surface_aen(tri, array<EdgeNormals, 3>(own_normals, own_normals, own_normals), w3, alpha);
        } else {
            sp = evaluate_surface(tri, w3, surface, alpha);
        }
        if (displacement_on()) {
            let own = array<u32, 4>(v, v, v, 0u);
            let no_faces = array<u32, 4>(0u, 0u, 0u, 0u);
            let dp = displacement_patch(3u, own, no_faces, no_faces, no_faces, no_faces, vector_, false);
            if (vector_) { sp = displace_triangle_vector(dp, w3, 0.0, 0.0, sp); } else { sp = displace_triangle_point(dp, w3, sp); }
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
fn weld_weights(s: u32) -> u32 { return weld_map(weld[WELD_SLOTS]) + 2u * s; }
fn weld_record(i: u32) -> u32 { return weld_weights(weld[WELD_SLOTS]) + WELD_RECORD_WORDS * i; }
fn weld_block(b: u32) -> u32 { return weld_record(weld[WELD_SORT_RECORDS]) + 2u * b; }
fn weld_load_record(i: u32) -> vec4<u32> {
    let o = weld_record(i);
    return vec4<u32>(weld[o], weld[o + 1u], weld[o + 2u], weld[o + 3u]);
}
fn weld_store_record(i: u32, r: vec4<u32>) {
    let o = weld_record(i);
    weld[o] = r.x;
    weld[o + 1u] = r.y;
    weld[o + 2u] = r.z;
    weld[o + 3u] = r.w;
}
fn weld_record_less(a: vec4<u32>, b: vec4<u32>) -> bool {
    if (a.x != b.x) { return a.x < b.x; }
    if (a.y != b.y) { return a.y < b.y; }
    if (a.z != b.z) { return a.z < b.z; }
    return a.w < b.w;
}
// Patch t's corners and rotation as weld_load reads them; false for a culled patch.
fn weld_corners(t: u32, wp: ptr<function, WeldPatch>) -> bool {
    (*wp).quad = t >= triangle_count();
    (*wp).rot = patches[t * PATCH_WORDS + REC_ROTATION];
    (*wp).w = array<u32, 4>(0u, 0u, 0u, 0u);
    if ((*wp).quad) {
        let wq = base_quad(t - triangle_count());
        (*wp).w = array<u32, 4>(wq.x, wq.y, wq.z, wq.w);
        return base_quad_valid(wq);
    }
    let w = base_triangle(t);
    if (!base_triangle_valid(w)) { return false; }
    (*wp).w = array<u32, 4>(w.x, w.y, w.z, 0u);
    return true;
}
// Slot s of patch t, at point d of half `side`: its map word (a corner's mesh vertex) or its record.
fn weld_key(wp: ptr<function, WeldPatch>, t: u32, side: u32, d: vec2<u32>, s: u32) {
    var place: vec3<u32>;
    var key: vec2<u32>;
    let kind = weld_place(wp, side, d, &place, &key);
    var r = vec4<u32>(0xFFFFFFFFu, 0xFFFFFFFFu, 0xFFFFFFFFu, s);
    if (kind == 0u) {
        weld[weld_map(s)] = place.x;
    } else if (kind == 1u) {
        r = vec4<u32>(weld_find_edge(place.x, place.y), place.z, 0u, s);
    } else {
        r = vec4<u32>(weld_edge_count() + t, key, s);
    }
    weld_store_record(s, r);
}
// The sorted weld's work items: the split pattern's leaves, or the patches.
fn weld_items() -> u32 {
    if (split_pattern()) { return split_leaves(); }
    return patch_count();
}

// Sorted weld pass 1 (after the counts, instead of ctess_weld_count), a workgroup per leaf or patch: each slot's
// map word (a corner's mesh vertex) or record, a split leaf's base weights; the padding records.
@compute @workgroup_size(EMIT_GROUP)
fn ctess_weld_keys(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>,
                   @builtin(local_invocation_id) lid: vec3<u32>, @builtin(global_invocation_id) gid: vec3<u32>) {
    let slots = weld[WELD_SLOTS];
    let stride = groups.x * EMIT_GROUP;
    for (var i = slots + gid.x; i < weld[WELD_SORT_RECORDS]; i += stride) { weld_store_record(i, vec4<u32>(0xFFFFFFFFu)); }
    let split_ = split_pattern();
    for (var item = wid.x; item < weld_items(); item += groups.x) {
        var wp: WeldPatch;
        if (!split_) {
            if (!weld_load(item, &wp)) { continue; }
            for (var i = lid.x; i < wp.vertices; i += EMIT_GROUP) {
                var side: u32;
                let d = weld_slot_point(&wp, i, &side);
                weld_key(&wp, item, side, d, wp.first + i);
            }
            continue;
        }
        let leaf = split_leaf(item);
        let t = patches[leaf + NODE_PATCH];
        let first = patches[leaf + NODE_FIRST_VERTEX];
        let count = patches[leaf + NODE_VERTICES];
        if (count == 0u || !weld_corners(t, &wp)) { continue; }
        let s = load_node(leaf);
        let words = vec3<u32>(patches[leaf + NODE_PATTERN], patches[leaf + NODE_PATTERN + 1u], patches[leaf + NODE_PATTERN + 2u]);
        let side = select(0u, (patches[leaf + NODE_INFO] >> NODE_HALF_SHIFT) & 1u, wp.quad);
        for (var i = lid.x; i < count; i += EMIT_GROUP) {
            let d = split_vertex(s, words, i);
            let o = weld_weights(first + i);
            weld[o] = d.x;
            weld[o + 1u] = d.y;
            weld_key(&wp, t, side, d, first + i);
        }
    }
}

// The bitonic network with every comparator ascending (docs/shaders.md, "One sort over the mesh"): the first step
// of a stage compares each block's halves mirrored (p with p ^ (stage - 1)), the others p with p + step. A record
// past the count then acts as +inf and never moves, so the records need no padding to a power of two.
fn weld_sort_partner(p: u32, stage: u32, step_: u32) -> u32 {
    if (step_ * 2u == stage) { return p ^ (stage - 1u); }
    return p + step_;
}

// Sorted weld pass 2, one compare-exchange step (stage WELD_SORT_STAGE, step WELD_SORT_STEP, written by the host
// before each dispatch; steps of at least WELD_SORT_CHUNK, the smaller ones in ctess_weld_sort_local), grid-stride
// over the records: no invocation loops long.
@compute @workgroup_size(EMIT_GROUP)
fn ctess_weld_sort_step(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let n = weld[WELD_SORT_RECORDS];
    let stage = weld[WELD_SORT_STAGE];
    let step_ = weld[WELD_SORT_STEP];
    for (var p = gid.x; p < n; p += groups.x * EMIT_GROUP) {
        let q = weld_sort_partner(p, stage, step_);
        if ((p & step_) != 0u || q >= n) { continue; }
        let a = weld_load_record(p);
        let b = weld_load_record(q);
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
var<workgroup> weld_chunk: array<vec4<u32>, WELD_SORT_CHUNK>;
// The records and the stage, the same for every lane: the loops' barriers depend on them (workgroupUniformLoad, as
// ctess_weld_count's weld_uniform), a variable each.
var<workgroup> weld_sort_count: u32;
var<workgroup> weld_sort_stage: u32;
@compute @workgroup_size(EMIT_GROUP)
fn ctess_weld_sort_local(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>,
                         @builtin(local_invocation_id) lid: vec3<u32>) {
    let lane = lid.x;
    if (lane == 0u) {
        weld_sort_count = weld[WELD_SORT_RECORDS];
        weld_sort_stage = weld[WELD_SORT_STAGE];
    }
    let n = workgroupUniformLoad(&weld_sort_count);
    let stage = workgroupUniformLoad(&weld_sort_stage);
    for (var chunk = wid.x; chunk * WELD_SORT_CHUNK < n; chunk += groups.x) {
        let base_ = chunk * WELD_SORT_CHUNK;
        for (var i = lane; i < WELD_SORT_CHUNK; i += EMIT_GROUP) {
            var r = vec4<u32>(0xFFFFFFFFu);
            if (base_ + i < n) { r = weld_load_record(base_ + i); }
            weld_chunk[i] = r;
        }
        for (var s = select(stage, 2u, stage == 0u); s <= select(stage, WELD_SORT_CHUNK, stage == 0u); s <<= 1u) {
            for (var step_ = min(s, WELD_SORT_CHUNK) / 2u; step_ > 0u; step_ >>= 1u) {
                workgroupBarrier();
                for (var i = lane; i < WELD_SORT_CHUNK / 2u; i += EMIT_GROUP) {
                    let low = i & (step_ - 1u);
                    let p = ((i - low) << 1u) | low;
                    let q = weld_sort_partner(p, s, step_);
                    let a = weld_chunk[p];
                    let b = weld_chunk[q];
                    if (weld_record_less(b, a)) {
                        weld_chunk[p] = b;
                        weld_chunk[q] = a;
                    }
                }
            }
        }
        workgroupBarrier();
        for (var i = lane; i < WELD_SORT_CHUNK && base_ + i < n; i += EMIT_GROUP) { weld_store_record(base_ + i, weld_chunk[i]); }
        workgroupBarrier();
    }
}

// The rank passes' items: the sorted records (WELD_RANK_KEYS: flagged where a distinct (owner, key) starts) or
// the unwelded triangles (WELD_RANK_TRIANGLES: flagged where kept, one word each over the records' area).
fn weld_rank_items() -> u32 {
    if (weld[WELD_RANK_MODE] == WELD_RANK_KEYS) { return weld[WELD_SORT_RECORDS]; }
    return patches[patch_count() * PATCH_WORDS + 1u];
}
fn weld_rank_flag(i: u32, items: u32) -> bool {
    if (i >= items) { return false; }
    if (weld[WELD_RANK_MODE] != WELD_RANK_KEYS) { return weld[weld_record(0u) + i] != 0u; }
    let r = weld_load_record(i);
    if (r.x == 0xFFFFFFFFu) { return false; }
    return i == 0u || any(weld_load_record(i - 1u).xyz != r.xyz);
}
// The rank passes' items, the same for every lane: their barriers depend on it (workgroupUniformLoad, as
// ctess_weld_count's weld_uniform).
var<workgroup> weld_rank_count: u32;

// Sorted weld rank pass 1, a workgroup per block of WELD_RANK_BLOCK items: the block's flags counted.
@compute @workgroup_size(EMIT_GROUP)
fn ctess_weld_rank_blocks(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>,
                          @builtin(local_invocation_id) lid: vec3<u32>) {
    let lane = lid.x;
    if (lane == 0u) { weld_rank_count = weld_rank_items(); }
    let items = workgroupUniformLoad(&weld_rank_count);
    let blocks = (items + WELD_RANK_BLOCK - 1u) / WELD_RANK_BLOCK;
    for (var b = wid.x; b < blocks; b += groups.x) {
        var count = 0u;
        for (var c = 0u; c < WELD_RANK_BLOCK; c += EMIT_GROUP) {
            if (weld_rank_flag(b * WELD_RANK_BLOCK + c + lane, items)) { count++; }
        }
        weld_lane_sum(lane, count);
        if (lane == 0u) { weld[weld_block(b)] = weld_lane[EMIT_GROUP - 1u]; }
        workgroupBarrier();
    }
}

// Sorted weld rank pass 2, one workgroup: the blocks' first ranks; the total in WELD_RANKED.
@compute @workgroup_size(SCAN_GROUP)
fn ctess_weld_rank_scan(@builtin(local_invocation_id) lid: vec3<u32>) {
    let items = weld_rank_items();
    let end_ = weld_prefix(lid.x, weld_block(0u), 2u, (items + WELD_RANK_BLOCK - 1u) / WELD_RANK_BLOCK, vec2<u32>(0u),
                           vec2<u32>(1u, 0u), false, vec2<u32>(0u));
    if (lid.x == 0u) { weld[WELD_RANKED] = end_.x; }
}

// Sorted weld rank pass 3, a workgroup per block: each item's rank. Keys: every slot's map word (the mesh vertices,
// then the rank of its (owner, key)), and each owner's first id and end (its first and last records) in its
// WeldedEdge or WeldedPatch, for ctess_weld_owner_counts. Triangles: each triangle's exclusive rank among the kept
// ones, with WELD_INTERIOR on a dropped one.
@compute @workgroup_size(EMIT_GROUP)
fn ctess_weld_rank_write(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>,
                         @builtin(local_invocation_id) lid: vec3<u32>) {
    let lane = lid.x;
    if (lane == 0u) { weld_rank_count = weld_rank_items(); }
    let items = workgroupUniformLoad(&weld_rank_count);
    let mode = weld[WELD_RANK_MODE];
    let blocks = (items + WELD_RANK_BLOCK - 1u) / WELD_RANK_BLOCK;
    let base_id = params[PARAM_MESH_VERTEX_COUNT];
    for (var b = wid.x; b < blocks; b += groups.x) {
        var before = weld[weld_block(b) + 1u];
        for (var c = 0u; c < WELD_RANK_BLOCK; c += EMIT_GROUP) {
            let i = b * WELD_RANK_BLOCK + c + lane;
            let flag = weld_rank_flag(i, items);
            let rank = before + weld_lane_scan(lane, flag) - 1u; // the last flagged item up to i
            if (i < items && mode != WELD_RANK_KEYS) {
                weld[weld_record(0u) + i] = select((rank + 1u) | WELD_INTERIOR, rank, flag);
            } else if (i < items) {
                let r = weld_load_record(i);
                if (r.x != 0xFFFFFFFFu) {
                    let id = base_id + rank;
                    let edges = weld_edge_count();
                    weld[weld_map(r.w)] = id | select(0u, WELD_INTERIOR, r.x >= edges);
                    var owner: u32;
                    if (r.x < edges) { owner = weld_edge(r.x) + WEDGE_FIRST_VERTEX; } else { owner = weld_patch(r.x - edges) + WPATCH_FIRST_VERTEX; }
                    // WEDGE_VERTEX_COUNT and WPATCH_VERTEX_COUNT follow the first-vertex words.
                    if (i == 0u || weld_load_record(i - 1u).x != r.x) { weld[owner] = id; }
                    if (i + 1u == items || weld_load_record(i + 1u).x != r.x) { weld[owner + 1u] = id + 1u; }
                }
            }
            before += weld_lane[EMIT_GROUP - 1u];
            workgroupBarrier();
        }
    }
}

// Triangle k of a sorted weld's item (a leaf, or a patch wp): its slots and its unwelded index.
fn weld_item_triangle(split_: bool, item: u32, wp: ptr<function, WeldPatch>, k: u32) -> vec4<u32> {
    if (!split_) { return vec4<u32>(weld_triangle_slots(wp, k) + vec3<u32>((*wp).first), patches[item * PATCH_WORDS + REC_FIRST_TRIANGLE] + k); }
    let leaf = split_leaf(item);
    let words = vec3<u32>(patches[leaf + NODE_PATTERN], patches[leaf + NODE_PATTERN + 1u], patches[leaf + NODE_PATTERN + 2u]);
    return vec4<u32>(uniform_triangle(words, k) + vec3<u32>(patches[leaf + NODE_FIRST_VERTEX]), patches[leaf + NODE_FIRST_TRIANGLE] + k);
}
// A sorted weld's item's triangles; false for a culled patch.
fn weld_item_load(split_: bool, item: u32, wp: ptr<function, WeldPatch>, triangles: ptr<function, u32>) -> bool {
    *triangles = 0u;
    if (split_) {
        *triangles = patches[split_leaf(item) + NODE_TRIANGLES];
        return true;
    }
    if (!weld_load(item, wp)) { return false; }
    *triangles = (*wp).triangles;
    return true;
}

// Sorted weld pass, a workgroup per leaf or patch: each triangle's kept flag (its welded corners distinct, or
// keep_degenerate) over the records' area, for the triangles' ranks.
@compute @workgroup_size(EMIT_GROUP)
fn ctess_weld_keep(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>,
                   @builtin(local_invocation_id) lid: vec3<u32>) {
    let flags = weld_record(0u);
    let split_ = split_pattern();
    for (var item = wid.x; item < weld_items(); item += groups.x) {
        var wp: WeldPatch;
        var triangles: u32;
        if (!weld_item_load(split_, item, &wp, &triangles)) { continue; }
        for (var k = lid.x; k < triangles; k += EMIT_GROUP) {
            let s = weld_item_triangle(split_, item, &wp, k);
            let ids = vec3<u32>(weld[weld_map(s.x)], weld[weld_map(s.y)], weld[weld_map(s.z)]) & vec3<u32>(~WELD_INTERIOR);
            weld[flags + s.w] = select(0u, 1u, weld_kept(ids));
        }
    }
}

// Sorted weld pass, grid-stride over the edges and patches: each one's counts from the ranks. An owner's
// vertex_count word holds its end id when it has points (ctess_weld_rank_write), else 0; a patch's kept
// triangles are the ranks at its first unwelded triangle and after its last.
@compute @workgroup_size(EMIT_GROUP)
fn ctess_weld_owner_counts(@builtin(global_invocation_id) gid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>) {
    let stride = groups.x * EMIT_GROUP;
    let edges = weld_edge_count();
    let flags = weld_record(0u);
    let triangles = patches[patch_count() * PATCH_WORDS + 1u];
    for (var e = gid.x; e < edges; e += stride) {
        let m = weld_edge(e);
        let end_ = weld[m + WEDGE_VERTEX_COUNT];
        weld[m + WEDGE_VERTEX_COUNT] = select(end_ - weld[m + WEDGE_FIRST_VERTEX], 0u, end_ == 0u);
    }
    for (var t = gid.x; t < patch_count(); t += stride) {
        let m = weld_patch(t);
        let end_ = weld[m + WPATCH_VERTEX_COUNT];
        weld[m + WPATCH_VERTEX_COUNT] = select(end_ - weld[m + WPATCH_FIRST_VERTEX], 0u, end_ == 0u);
        let rec = t * PATCH_WORDS;
        let first = patches[rec + REC_FIRST_TRIANGLE];
        let count = patches[rec + REC_TRIANGLE_COUNT];
        var at = weld[WELD_RANKED];
        if (first < triangles) { at = weld[flags + first] & ~WELD_INTERIOR; }
        var after = weld[WELD_RANKED];
        if (first + count < triangles) { after = weld[flags + first + count] & ~WELD_INTERIOR; }
        weld[m + WPATCH_TRIANGLE_COUNT] = select(after - at, 0u, count == 0u);
    }
}

// Sorted weld emit, a workgroup per leaf or patch of the emit range: its kept triangles at their ranks.
@compute @workgroup_size(EMIT_GROUP)
fn ctess_weld_sorted_triangles(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>,
                               @builtin(local_invocation_id) lid: vec3<u32>) {
    let flags = weld_record(0u);
    let first_patch = params[PARAM_FIRST_PATCH];
    let end = min(params[PARAM_END_PATCH], patch_count());
    let split_ = split_pattern();
    let items = emit_items(split_, first_patch, end);
    for (var item = items.x + wid.x; item < items.y; item += groups.x) {
        var leaf: u32;
        let t = item_patch(split_, item, &leaf);
        var wp: WeldPatch;
        var triangles: u32;
        if (t < first_patch || t >= end || !weld_item_load(split_, item, &wp, &triangles)) { continue; }
        for (var k = lid.x; k < triangles; k += EMIT_GROUP) {
            let s = weld_item_triangle(split_, item, &wp, k);
            let rank = weld[flags + s.w];
            if ((rank & WELD_INTERIOR) != 0u) { continue; }
            let o = 3u * rank;
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
fn emit_vertices(quad_pass: bool, displaced: bool, vector_: bool, wid: vec3<u32>, groups: vec3<u32>, lid: vec3<u32>) {
    let first_patch = select(params[PARAM_FIRST_PATCH], max(params[PARAM_FIRST_PATCH], triangle_count()), quad_pass);
    let end = min(params[PARAM_END_PATCH], select(triangle_count(), patch_count(), quad_pass));
    let alpha = bitcast<f32>(params[PARAM_ALPHA]);
    let surface = params[PARAM_SURFACE];
    let aen = surface == SURFACE_PN_AEN;
    let uniform_ = uniform_pattern();
    // Displacement runs in its own entry points (a software adapter runs an untaken branch at full cost); the
    // others write no vertex when the params displace, rather than undisplaced ones.
    // Vector displacement (§8.7) has its own entry points too (vector_); each displaced pass writes no vertex for
    // the other mode's params.
    let displace = displaced;
    if (displacement_on() != displaced) { return; }
    if (displaced && displacement_vector_mode() != vector_) { return; }
    // Split (docs/shaders.md, "Splitting"): a workgroup per leaf of the patches in [first_patch, end) instead of
    // per patch; a leaf's vertices are its pattern's, mapped on the root.
    let split_ = split_pattern();
    // Welded (docs/shaders.md, "Welded output"): each slot writes its weld id's vertex when it is the id's writer
    // (the first slot of an interior point, the writer word's slot of a shared one), with u = v = 0 for shared ids.
    let weld_ = weld_on();
    let sorted_ = weld_ && weld_sorted();
    let items = emit_items(split_, first_patch, end);
    for (var item = items.x + wid.x; item < items.y; item += groups.x) {
        var leaf: u32;
        let t = item_patch(split_, item, &leaf);
        if (t < first_patch || t >= end) { continue; }
        let rec = t * PATCH_WORDS;
        var count = patches[rec + REC_VERTEX_COUNT];
        if (split_) { count = patches[leaf + NODE_VERTICES]; }
        if (count == 0u) { continue; }
        var first_interior = 0u;
        if (weld_ && !sorted_) { first_interior = weld[weld_patch(t) + WPATCH_FIRST_VERTEX]; }
        let quad = quad_pass;
        let rot = patches[rec + REC_ROTATION];
        // The corners in pattern order for a quad (q_k = mesh corner (k + rotation) % 4), in base order for a
        // triangle; en[k]: the neighbour's normals on edge k (the own ones unless PN-AEN).
        var q: array<Corner, 4>;
        var en: array<EdgeNormals, 4>;
        var halves: array<Patch, 2>;
        var words: array<vec3<u32>, 2>;
        var vertices_a = count;
        var dp: DisplacementPatch;
        if (quad) {
            let wq = base_quad(t - triangle_count());
            if (!base_quad_valid(wq)) { continue; }
            var w = array<u32, 4>(wq.x, wq.y, wq.z, wq.w);
            for (var k = 0u; k < 4u; k++) { q[k] = mesh_corner(w[(k + rot) % 4u]); }
            // Pattern edge k is mesh edge m = (k + rotation) % 4: edge 0 or 1 of face triangle (q0, q1, q2)
            // (adjacency block triangle_count + 2 quad) for m < 2, edge 1 or 2 of (q0, q2, q3) (the next) after.
            let face = triangle_count() + 2u * (t - triangle_count());
            for (var k = 0u; k < 4u; k++) {
                let m = (k + rot) % 4u;
                en[k] = EdgeNormals(q[k].normal, q[(k + 1u) % 4u].normal);
                if (aen) { en[k] = adjacent_normals(face + select(0u, 1u, m >= 2u), select(m, m - 1u, m >= 2u), q[k], q[(k + 1u) % 4u]); }
            }
            if (split_) { vertices_a = select(0u, count, ((patches[leaf + NODE_INFO] >> NODE_HALF_SHIFT) & 1u) == 0u); }
            else { vertices_a = quad_halves(rec, &halves, &words).x; }
            if (displace) {
                // Mesh corners q0, q1, q2 are slots 0-2 of face (q0, q1, q2), q3 slot 2 of (q0, q2, q3); mesh edges
                // 0 and 1 are edges 0 and 1 of the first, 2 and 3 edges 1 and 2 of the second (mesh_pipeline.cpp).
                var wp: array<u32, 4>; var corner_face: array<u32, 4>; var corner_slot: array<u32, 4>;
                var edge_face: array<u32, 4>; var edge_slot: array<u32, 4>;
                for (var k = 0u; k < 4u; k++) {
                    let m = (k + rot) % 4u;
                    wp[k] = w[m];
                    corner_face[k] = face + select(0u, 1u, m == 3u);
                    corner_slot[k] = select(m, 2u, m == 3u);
                    edge_face[k] = face + select(0u, 1u, m >= 2u);
                    edge_slot[k] = select(m, m - 1u, m >= 2u);
                }
                dp = displacement_patch(4u, wp, corner_face, corner_slot, edge_face, edge_slot, vector_, true);
            }
        } else {
            let w = base_triangle(t);
            if (!base_triangle_valid(w)) { continue; }
            q[0] = mesh_corner(w.x);
            q[1] = mesh_corner(w.y);
            q[2] = mesh_corner(w.z);
            q[3] = q[0];
            for (var e = 0u; e < 3u; e++) {
                en[e] = EdgeNormals(q[e].normal, q[(e + 1u) % 3u].normal);
                if (aen) { en[e] = adjacent_normals(t, e, q[e], q[(e + 1u) % 3u]); }
            }
            if (!uniform_ && !split_) { halves[0] = record_patch(rec); }
            words[0] = uniform_words(rec);
            if (displace) {
                dp = displacement_patch(3u, array<u32, 4>(w.x, w.y, w.z, 0u), array<u32, 4>(t, t, t, t),
                                        array<u32, 4>(0u, 1u, 2u, 0u), array<u32, 4>(t, t, t, t), array<u32, 4>(0u, 1u, 2u, 0u),
                                        vector_, true);
            }
        }
        var first = patches[rec + REC_FIRST_VERTEX];
        if (split_) { first = patches[leaf + NODE_FIRST_VERTEX]; }
        for (var i = lid.x; i < count; i += EMIT_GROUP) {
            let side = select(1u, 0u, i < vertices_a);
            let local = select(i - vertices_a, i, side == 0u);
            var o = (first + i) * VERTEX_WORDS;
            var shared_id = false;
            if (weld_) {
                let m = weld[weld_map(first + i)];
                shared_id = (m & WELD_INTERIOR) == 0u;
                if (sorted_) {
                    // The weld by one sort has ids in its map words (ctess_weld_keys), each written by its writer.
                    if (weld[weld_writer(m & ~WELD_INTERIOR)] != first + i + 1u) { continue; }
                    o = (m & ~WELD_INTERIOR) * VERTEX_WORDS;
                } else {
                    if (shared_id) {
                        if (weld[weld_writer(m)] != first + i + 1u) { continue; }
                    } else if ((m & WELD_REPRESENTATIVE) == 0u) {
                        continue;
                    }
                    o = weld_output_id(m, first_interior) * VERTEX_WORDS;
                }
            }
            // A split leaf's base weights are ctess_split_points' (its map into the root stays out of this pass),
            // welded ctess_weld_keys' in binding 7.
            var d: vec2<u32>;
            if (!split_) {
                if (uniform_) { d = uniform_vertex(words[side], local); } else { d = patch_vertex(&halves[side], local); }
            } else if (weld_) {
                let sw = weld_weights(first + i);
                d = vec2<u32>(weld[sw], weld[sw + 1u]);
            } else {
                d = vec2<u32>(out_vertices[o + VERTEX_U], out_vertices[o + VERTEX_V]);
            }
            // The surface's triangle and weights: a triangle's own (to_base_point: pattern weights (1 - u - v, u,
            // v) move to base vertices (k + rot) % 3), or for a point on quad edge k the triangle (q_k, q_k+1,
            // q_k+2) with weights (1 - r, r, 0), the operations the neighbour across the edge runs (quad_vertex on
            // the CPU); a point inside a quad goes to quad_interior.
            var tri = array<Corner, 3>(q[0], q[1], q[2]);
            var w3: array<u32, 3>;
            var en3 = array<EdgeNormals, 3>(en[0], en[1], en[2]);
            var inner = false;
            var out_uv: vec2<u32>;
            if (quad) {
                if (side == 1u) { d = vec2<u32>(FIXED_ONE - d.x, FIXED_ONE - d.y); } // half B: cp::quad_point
                out_uv = d;
                var on_edge = array<bool, 4>(d.y == 0u, d.x == FIXED_ONE, d.y == FIXED_ONE, d.x == 0u);
                var r = array<u32, 4>(d.x, d.y, FIXED_ONE - d.x, FIXED_ONE - d.y);
                var k = 4u;
                for (var e = 0u; e < 4u && k == 4u; e++) { if (on_edge[e]) { k = e; } }
                inner = k == 4u;
                if (!inner) {
                    tri = array<Corner, 3>(q[k], q[(k + 1u) % 4u], q[(k + 2u) % 4u]);
                    w3 = array<u32, 3>(FIXED_ONE - r[k], r[k], 0u);
                    // Edge k's neighbours; the triangle's other two edges are its own boundary.
                    en3 = array<EdgeNormals, 3>(en[k], EdgeNormals(tri[1].normal, tri[2].normal), EdgeNormals(tri[2].normal, tri[0].normal));
                }
            } else {
                var pw = array<u32, 3>(FIXED_ONE - d.x - d.y, d.x, d.y);
                for (var k = 0u; k < 3u; k++) { w3[(k + rot) % 3u] = pw[k]; }
                out_uv = vec2<u32>(w3[1], w3[2]);
            }
            var sp: SurfacePoint;
            if (inner) {
                sp = quad_interior(q, en, aen, out_uv.x, out_uv.y, surface, alpha);
            } else if (aen) {
                sp = evaluate_surface_aen(tri, en3, w3, alpha);
            } else {
                sp = evaluate_surface(tri, w3, surface, alpha);
            }
            // §8: after the surface, as mesh_pipeline.cpp (a quad's every point by its square point).
            if (displace && vector_ && quad) {
                sp = displace_quad_vector(dp, out_uv.x, out_uv.y, fixed_weight(out_uv.x), fixed_weight(out_uv.y), sp);
            } else if (displace && vector_) {
                sp = displace_triangle_vector(dp, w3, fixed_weight(w3[1]), fixed_weight(w3[2]), sp);
            } else if (displace && quad) {
                sp = displace_quad_point(dp, out_uv.x, out_uv.y, sp);
            } else if (displace) {
                sp = displace_triangle_point(dp, w3, sp);
            }
            store_vertex(o, select(out_uv.x, 0u, shared_id), select(out_uv.y, 0u, shared_id), sp);
        }
    }
}

// Split pattern, before the vertex passes: every leaf vertex's base weights (its pattern's point mapped on the
// root, to_base_weights) into the output vertex's first two words, a workgroup per leaf of the emit range. The
// vertex passes read them there, so that the other patterns' vertex passes carry no split code (a software
// adapter runs an untaken branch at full cost).
@compute @workgroup_size(EMIT_GROUP)
fn ctess_split_points(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>,
                      @builtin(local_invocation_id) lid: vec3<u32>) {
    if (!split_pattern()) { return; }
    let end = min(params[PARAM_END_PATCH], patch_count());
    let last = split_range_end(end);
    for (var item = split_range_start(params[PARAM_FIRST_PATCH]) + wid.x; item < last; item += groups.x) {
        // The leaf's node and pattern once, not per vertex (a vertex store may alias them for the compiler).
        let leaf = split_leaf(item);
        let first = patches[leaf + NODE_FIRST_VERTEX];
        let count = patches[leaf + NODE_VERTICES];
        let s = load_node(leaf);
        let words = vec3<u32>(patches[leaf + NODE_PATTERN], patches[leaf + NODE_PATTERN + 1u], patches[leaf + NODE_PATTERN + 2u]);
        for (var i = lid.x; i < count; i += EMIT_GROUP) {
            let d = split_vertex(s, words, i);
            out_vertices[(first + i) * VERTEX_WORDS + VERTEX_U] = d.x;
            out_vertices[(first + i) * VERTEX_WORDS + VERTEX_V] = d.y;
        }
    }
}

@compute @workgroup_size(EMIT_GROUP)
fn ctess_emit_vertices(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>,
                       @builtin(local_invocation_id) lid: vec3<u32>) {
    emit_vertices(false, false, false, wid, groups, lid);
}
@compute @workgroup_size(EMIT_GROUP)
fn ctess_emit_quad_vertices(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>,
                            @builtin(local_invocation_id) lid: vec3<u32>) {
    emit_vertices(true, false, false, wid, groups, lid);
}
@compute @workgroup_size(EMIT_GROUP)
fn ctess_emit_displaced_vertices(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>,
                                 @builtin(local_invocation_id) lid: vec3<u32>) {
    emit_vertices(false, true, false, wid, groups, lid);
}
@compute @workgroup_size(EMIT_GROUP)
fn ctess_emit_displaced_quad_vertices(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>,
                                      @builtin(local_invocation_id) lid: vec3<u32>) {
    emit_vertices(true, true, false, wid, groups, lid);
}
@compute @workgroup_size(EMIT_GROUP)
fn ctess_emit_vector_displaced_vertices(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>,
                                        @builtin(local_invocation_id) lid: vec3<u32>) {
    emit_vertices(false, true, true, wid, groups, lid);
}
@compute @workgroup_size(EMIT_GROUP)
fn ctess_emit_vector_displaced_quad_vertices(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>,
                                             @builtin(local_invocation_id) lid: vec3<u32>) {
    emit_vertices(true, true, true, wid, groups, lid);
}

// Passes 5 and 6 (triangles), as 3 and 4: every output triangle, in provoking-vertex order, as mesh-wide indices
// (a quad's half B after A, its indices after A's vertices).
fn emit_triangles(quad_pass: bool, wid: vec3<u32>, groups: vec3<u32>, lid: vec3<u32>) {
    let first_patch = select(params[PARAM_FIRST_PATCH], max(params[PARAM_FIRST_PATCH], triangle_count()), quad_pass);
    let end = min(params[PARAM_END_PATCH], select(triangle_count(), patch_count(), quad_pass));
    let uniform_ = uniform_pattern();
    // Split: a workgroup per leaf, its pattern's triangles after its own first vertex (as emit_vertices).
    let split_ = split_pattern();
    let items = emit_items(split_, first_patch, end);
    for (var item = items.x + wid.x; item < items.y; item += groups.x) {
        var leaf: u32;
        let t = item_patch(split_, item, &leaf);
        if (t < first_patch || t >= end) { continue; }
        let rec = t * PATCH_WORDS;
        var count = patches[rec + REC_TRIANGLE_COUNT];
        if (split_) { count = patches[leaf + NODE_TRIANGLES]; }
        if (count == 0u) { continue; }
        var halves: array<Patch, 2>;
        var words: array<vec3<u32>, 2>;
        var counts_a = vec2<u32>(0u, count);
        if (split_) {
            words[0] = vec3<u32>(patches[leaf + NODE_PATTERN], patches[leaf + NODE_PATTERN + 1u], patches[leaf + NODE_PATTERN + 2u]);
        } else if (quad_pass) {
            counts_a = quad_halves(rec, &halves, &words);
        } else {
            if (!uniform_) { halves[0] = record_patch(rec); }
            words[0] = uniform_words(rec);
        }
        var vfirst = patches[rec + REC_FIRST_VERTEX];
        var tfirst = patches[rec + REC_FIRST_TRIANGLE];
        if (split_) {
            vfirst = patches[leaf + NODE_FIRST_VERTEX];
            tfirst = patches[leaf + NODE_FIRST_TRIANGLE];
        }
        for (var i = lid.x; i < count; i += EMIT_GROUP) {
            let side = select(1u, 0u, i < counts_a.y);
            let local = select(i - counts_a.y, i, side == 0u);
            var tri: vec3<u32>;
            if (uniform_ || split_) { tri = uniform_triangle(words[side], local); } else { tri = patch_triangle(&halves[side], local); }
            tri += vec3<u32>(vfirst + select(counts_a.x, 0u, side == 0u));
            let o = 3u * (tfirst + i);
            out_indices[o] = tri.x;
            out_indices[o + 1u] = tri.y;
            out_indices[o + 2u] = tri.z;
        }
    }
}
@compute @workgroup_size(EMIT_GROUP)
fn ctess_emit_triangles(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>,
                        @builtin(local_invocation_id) lid: vec3<u32>) {
    emit_triangles(false, wid, groups, lid);
}
@compute @workgroup_size(EMIT_GROUP)
fn ctess_emit_quad_triangles(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) groups: vec3<u32>,
                             @builtin(local_invocation_id) lid: vec3<u32>) {
    emit_triangles(true, wid, groups, lid);
}
