// Appended by the viewer to the generated ctess_cp_<max>.wgsl: a patch-setup entry point whose edge factors
// are given (params words 10 + 3t .. 12 + 3t, float bits, for patch t) instead of projected from a mesh; one
// workgroup per patch. Everything after the factors is the generated module's own code (line_state,
// patch_setup, store_setup_block), and the generated prefix sum and emit passes run unchanged on the records it writes
// (rotation 0, so the output barycentrics are the pattern's own u, v).
@compute @workgroup_size(1)
fn viewer_explicit_setup(@builtin(workgroup_id) wid: vec3<u32>) {
    let t = wid.x;
    if (t >= patch_count()) { return; }
    let rec = t * PATCH_WORDS;
    var s: array<vec2<u32>, 3>;
    for (var k = 0u; k < 3u; k++) { s[k] = line_state(bitcast<f32>(params[10u + 3u * t + k])); }
    let p = patch_setup(s[0], s[1], s[2]);
    for (var k = 0u; k < PATCH_WORDS; k++) { patches[rec + k] = 0u; }
    for (var k = 0u; k < 3u; k++) {
        patches[rec + 1u + k] = s[k].x;
        patches[rec + 4u + k] = s[k].y;
        patches[rec + 11u + k] = params[10u + 3u * t + k];
    }
    patches[rec + 7u] = p.vertices;
    patches[rec + 8u] = p.triangles;
    store_setup_block(rec, p);
}
