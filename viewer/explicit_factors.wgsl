// Appended by the viewer to the generated ctess_mesh_<max>.wgsl: a patch-setup entry point whose edge factors
// are given (params words PARAMS_WORDS + 3t .. PARAMS_WORDS + 3t + 2, float bits, for patch t: after the generated
// module's params) instead of projected from a mesh; one workgroup per patch. Every layout name here is one of
// the module's generated constants (docs/shaders.md, "Generated constants"). Everything after the factors is the
// generated module's own code: for CP line_state, patch_setup and store_setup_block, for the uniform pattern
// store_uniform_record, the record its setup pass writes (uniform_factor, uniform_setup). The generated prefix sum
// and emit passes run unchanged on the records it writes (rotation 0, so the output barycentrics are the
// pattern's u, v).
const EXPLICIT_FACTORS: u32 = PARAMS_WORDS;
@compute @workgroup_size(1)
fn viewer_explicit_setup(@builtin(workgroup_id) wid: vec3<u32>) {
    let t = wid.x;
    if (t >= patch_count()) { return; }
    let rec = t * PATCH_WORDS;
    let given = EXPLICIT_FACTORS + 3u * t;
    for (var k = 0u; k < PATCH_WORDS; k++) { patches[rec + k] = 0u; }
    if (uniform_pattern()) {
        store_uniform_record(rec, array<f32, 3>(bitcast<f32>(params[given]), bitcast<f32>(params[given + 1u]),
                                                bitcast<f32>(params[given + 2u])));
        return;
    }
    var s: array<vec2<u32>, 3>;
    for (var k = 0u; k < 3u; k++) { s[k] = line_state(bitcast<f32>(params[given + k])); }
    let p = patch_setup(s[0], s[1], s[2]);
    for (var k = 0u; k < 3u; k++) {
        patches[rec + REC_TOKEN + k] = s[k].x;
        patches[rec + REC_T16 + k] = s[k].y;
        patches[rec + REC_FACTOR + k] = params[given + k];
    }
    patches[rec + REC_VERTEX_COUNT] = p.vertices;
    patches[rec + REC_TRIANGLE_COUNT] = p.triangles;
    store_setup_block(rec, p);
}
