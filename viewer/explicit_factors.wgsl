// Appended by the viewer to the generated ctess_cp_<max>.wgsl: a patch-setup entry point for one patch whose
// three edge factors are given (params words 10-12, float bits) instead of projected from a mesh. Everything
// after the factors is the generated module's own code (line_state, patch_setup), and the generated prefix
// sum and emit passes run unchanged on the record it writes (rotation 0, so the output barycentrics are the
// pattern's own u, v).
@compute @workgroup_size(1)
fn viewer_explicit_setup() {
    var s: array<vec2<u32>, 3>;
    for (var k = 0u; k < 3u; k++) { s[k] = line_state(bitcast<f32>(params[10u + k])); }
    let p = patch_setup(s[0], s[1], s[2]);
    for (var k = 0u; k < PATCH_WORDS; k++) { patches[k] = 0u; }
    for (var k = 0u; k < 3u; k++) {
        patches[1u + k] = s[k].x;
        patches[4u + k] = s[k].y;
        patches[11u + k] = params[10u + k];
    }
    patches[7u] = p.vertices;
    patches[8u] = p.triangles;
}
