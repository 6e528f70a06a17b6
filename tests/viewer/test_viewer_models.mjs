// The viewer opens the user's model (docs/viewer.md, "Your model"): headless chromium (WebGPU on SwiftShader)
// uploads two models from Debian's assimp-testmodels that ctess did not make, one with mixed triangles and quads
// (OBJ/regr_3429812.obj: a quad and two triangles) through the file picker and one with uv and normal seams
// (glTF2/BoxTextured-glTF-Binary/BoxTextured.glb: 24 vertices at 8 positions) by drag and drop, plus a height
// map, sets the camera exactly (URL and JS hook) and the DiceRate, and compares the page's counts and the
// checksums of its output buffers (window.ctessViewer, and window.ctessViewerChecksum on request) with `ctess mesh --stats`'s
// `gpu` block for the same options: CP and uniform side by side (and uniform split above N against `--unwelded`),
// PN-AEN, Phong with displacement, and the seamed
// model given its own KHR_materials_displacement image with factors grown by its bound, beside D3D11 fractional_even
// (computed by ctess serve on the CPU), then an RGB vector map. The built-in
// quad torus displaced by the map stays closed and moves by at most the height bound. A .gltf whose buffer is a
// separate file is refused with the server's message on the page.
//   node tests/viewer/test_viewer_models.mjs path/to/ctess    exit 0 pass, 1 fail, 77 skipped (no chromium/models)
import { spawn, execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { chromium } from 'playwright-core';

const ctess = process.argv[2];
const browserPath = process.env.CTESS_CHROMIUM ?? '/usr/bin/chromium';
const models = process.env.CTESS_ASSIMP_MODELS ?? '/usr/share/assimp/models';
const mixed = `${models}/OBJ/regr_3429812.obj`, seams = `${models}/glTF2/BoxTextured-glTF-Binary/BoxTextured.glb`;
const heightMap = `${models}/glTF2/BoxTextured-glTF/CesiumLogoFlat.png`, external = `${models}/glTF2/BoxTextured-glTF/BoxTextured.gltf`;
for (const [path, what] of [[browserPath, "Debian's chromium"], [mixed, 'assimp-testmodels'], [seams, 'assimp-testmodels'],
                            [heightMap, 'assimp-testmodels'], [external, 'assimp-testmodels']])
    if (!existsSync(path)) {
        console.log(`SKIPPED: ${path} not found; install ${what} (./.ci/install-deps) to run the viewer's model test`);
        process.exit(77);
    }
const started = Date.now();
let failures = 0, compared = 0;
const check = (ok, what) => {
    if (!ok) { failures++; console.log(`FAIL ${what}`); }
    return ok;
};

const server = spawn(ctess, ['serve', '--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
const base = await new Promise((resolve, reject) => {
    let out = '';
    server.stdout.on('data', (d) => {
        out += d;
        const m = out.match(/http:\/\/127\.0\.0\.1:(\d+)\//);
        if (m) resolve(m[0]);
    });
    server.on('exit', (code) => reject(new Error(`ctess serve exited with ${code}: ${out}`)));
});
process.on('exit', () => server.kill());

// The canvas the viewer draws (640 x 600) and its field of view (45 degrees) are the CLI's --resolution and --fov.
const cliStats = (file, { pattern, surface, dice, eye, displace, unwelded }) => JSON.parse(execFileSync(ctess, [
    'mesh', '--in', file, '--stats', ...(unwelded ? ['--unwelded'] : []), '--pattern', pattern, '--surface', surface,
    '--dice-rate', String(dice),
    '--camera', eye.join(','), '--fov', '45', '--resolution', '640,600',
    ...(displace ? [...(displace.gltf ? ['--displace-gltf'] : [displace.vector ? '--displace-vector' : '--displace', displace.file]),
                    '--displace-scale', String(displace.scale),
                    ...(displace.offset !== undefined ? ['--displace-offset', String(displace.offset)] : []),
                    ...(displace.grow ? ['--displace-grow'] : [])] : []),
], { encoding: 'utf8' }));

const flags = ['--no-sandbox', '--disable-quic', '--disable-background-networking', '--disable-component-update', '--disable-sync',
               '--no-first-run', '--use-angle=vulkan', '--enable-features=Vulkan', '--use-vulkan=swiftshader', '--enable-unsafe-webgpu'];
const browser = await chromium.launch({ executablePath: browserPath, headless: true, args: flags });
const page = await browser.newPage({ viewport: { width: 1400, height: 800 } });
page.on('pageerror', (e) => check(false, `page error: ${e.message}`));
async function viewerState(pred, arg) {
    try {
        await page.waitForFunction(pred, arg, { timeout: 120000 });
    } catch (e) {
        const shown = await page.evaluate(() => `status "${document.getElementById('status').textContent}", ` +
                                                `state ${JSON.stringify({ ...(window.ctessViewer ?? {}), readback: null })}`);
        throw new Error(`${e.message}\nwaiting for ${JSON.stringify(arg)}; the page shows ${shown}`);
    }
    return page.evaluate(() => ({ ...window.ctessViewer, readback: null }));
}

// The page's two sides against the CLI: the counts and each checksum, and the factor scale bits (what makes the
// factors equal). sides: [[pattern, side], ...].
async function sameAsCli(state, file, options, sides) {
    for (const [pattern, side] of sides) {
        const what = `${file.split('/').pop()} ${pattern} ${options.surface}${options.displace ? ' displaced' : ''} DiceRate ${options.dice}`;
        const ref = cliStats(file, { ...options, pattern }).gpu;
        const counts = side === 0 ? state : state.compare;
        const sum = counts?.checksum;
        const onRequest = await page.evaluate((s) => window.ctessViewerChecksum(s), side);
        check(JSON.stringify(onRequest) === JSON.stringify(sum), `${what}: ctessViewerChecksum ${JSON.stringify(onRequest)}, ctessViewer ${JSON.stringify(sum)}`);
        let ok = check(ref && counts?.mode === pattern, `${what}: the CLI has no gpu block, or the page shows ${counts?.mode}`);
        ok &&= check(state.factorScaleBits === ref.factor_scale_bits, `${what}: factor scale bits ${state.factorScaleBits}, CLI ${ref.factor_scale_bits}`);
        ok &&= check(state.patches === ref.patches && counts.vertices === ref.vertices && counts.triangles === ref.triangles,
                     `${what}: ${state.patches} patches, ${counts.vertices}/${counts.triangles}; CLI ${ref.patches}, ${ref.vertices}/${ref.triangles}`);
        ok &&= check(JSON.stringify(sum) === JSON.stringify(ref.checksum), `${what}: checksums ${JSON.stringify(sum)}, CLI ${JSON.stringify(ref.checksum)}`);
        if (ok) compared++;
        console.log(`${what}: ${counts.vertices} vertices, ${counts.triangles} triangles, checksums ${Object.values(sum ?? {}).join('/')} ` +
                    `${ok ? '=' : '!='} the CLI's`);
    }
}
const sameVector = (a, b) => a.length === b.length && a.every((x, k) => x === Math.fround(b[k]));

// ---- the mixed model through the file picker, camera and options from the URL; CP | uniform, PN-AEN ----
const mixedEye = [0.07, 0.98, 0.13], mixedTarget = [0.0457, 0.963, 0.0959];
await page.goto(`${base}?view=mesh&surface=pn-aen&dice=8&pattern=cp&compare=uniform&camera=${mixedEye}&target=${mixedTarget}`);
await viewerState(() => window.ctessViewer?.view === 'mesh');
await page.setInputFiles('#model-file', mixed);
let state = await viewerState(() => window.ctessViewer?.model?.name === 'regr_3429812.obj');
check(state.mesh === 'model' && state.quads === 1 && state.patches === 3 && state.surface === 'pn-aen' && state.diceRate === 8,
      `mixed model: mesh ${state.mesh}, ${state.patches} patches, ${state.quads} quads, ${state.surface}, DiceRate ${state.diceRate}`);
check(sameVector(state.camera.eye, mixedEye) && sameVector(state.camera.target, mixedTarget) && state.camera.fov === 45 &&
      state.resolution.join() === '640,600', `mixed model: camera ${JSON.stringify(state.camera)}, resolution ${state.resolution}`);
await sameAsCli(state, mixed, { surface: 'pn-aen', dice: 8, eye: mixedEye }, [['cp', 0], ['uniform', 1]]);

// ---- a height map, Phong, displacement scale and offset; one side ----
await page.setInputFiles('#height-file', heightMap);
await page.uncheck('#compare');
await page.selectOption('#surface', 'phong');
await page.fill('#displace-scale', '0.004');
await page.fill('#displace-offset', '-0.5');
state = await viewerState(() => window.ctessViewer?.displacement?.scale === Math.fround(0.004) &&
                                window.ctessViewer.displacement.offset === -0.5 && window.ctessViewer.surface === 'phong' && !window.ctessViewer.compare);
check(state.displacement.width === 211 && state.displacement.height === 211, `height map: ${JSON.stringify(state.displacement)}`);
await sameAsCli(state, mixed, { surface: 'phong', dice: 8, eye: mixedEye, displace: { file: heightMap, scale: 0.004, offset: -0.5 } }, [['cp', 0]]);

// ---- the built-in quad torus displaced by the same map: still closed, every point moved by at most the bound ----
// (Its vertices are shared across the uv seam and it has no adjacency: each vertex moves along its own normal.)
const C = (await (await fetch(`${base}shaders/ctess_mesh_64.layout.json`)).json()).constants;
const torusPositions = () => page.evaluate((C) => {
    const { vertices, indices } = window.ctessViewer.readback;
    const p = [];
    for (let i = 0; i < vertices.length; i += C.VERTEX_WORDS) p.push(...new Float32Array(vertices.slice(i + C.VERTEX_POSITION, i + C.VERTEX_POSITION + 3).buffer));
    // Welded by position bits, CP's zero-area triangles left out: every edge used once each way.
    const id = new Map(), key = (i) => `${vertices[i * C.VERTEX_WORDS + C.VERTEX_POSITION]},${vertices[i * C.VERTEX_WORDS + C.VERTEX_POSITION + 1]},${vertices[i * C.VERTEX_WORDS + C.VERTEX_POSITION + 2]}`;
    const directed = new Map();
    for (let t = 0; t < indices.length; t += 3) {
        const w = [0, 1, 2].map((k) => { const s = key(indices[t + k]); if (!id.has(s)) id.set(s, id.size); return id.get(s); });
        if (w[0] === w[1] || w[1] === w[2] || w[2] === w[0]) continue;
        for (let k = 0; k < 3; k++) directed.set(`${w[k]},${w[(k + 1) % 3]}`, (directed.get(`${w[k]},${w[(k + 1) % 3]}`) ?? 0) + 1);
    }
    let unpaired = 0;
    for (const [e, n] of directed) { const [a, b] = e.split(','); if (n !== 1 || directed.get(`${b},${a}`) !== 1) unpaired++; }
    return { positions: p, unpaired };
}, C);
await page.evaluate(() => window.ctessViewerSetCamera([2.4, 1.8, 3.2], [0, 0, 0]));
await page.selectOption('#mesh-kind', 'torus');
const displacedTorus = await viewerState(() => window.ctessViewer?.mesh === 'torus' && window.ctessViewer.displacement &&
                                                   window.ctessViewer.camera.eye[0] === Math.fround(2.4));
const moved = await torusPositions();
await page.uncheck('#displace');
const plainTorus = await viewerState(() => window.ctessViewer?.mesh === 'torus' && !window.ctessViewer.displacement);
const still = await torusPositions();
// |height| <= scale * max |texel + offset| (factor 1), 0.004 * 0.5 with texels in [0, 1]; plus the positions'
// float rounding (they are about 1.4 in size).
const bound = 0.004 * 0.5 + 1e-6;
let largest = 0;
for (let i = 0; i < still.positions.length; i += 3)
    largest = Math.max(largest, Math.hypot(...[0, 1, 2].map((k) => moved.positions[i + k] - still.positions[i + k])));
check(displacedTorus.vertices === plainTorus.vertices && displacedTorus.triangles === plainTorus.triangles &&
      JSON.stringify(displacedTorus.checksum) === JSON.stringify(plainTorus.checksum),
      `displaced torus: ${displacedTorus.vertices}/${displacedTorus.triangles}, plain ${plainTorus.vertices}/${plainTorus.triangles}`);
check(moved.unpaired === 0 && still.unpaired === 0 && largest > 0 && largest <= bound,
      `displaced torus: ${moved.unpaired} unpaired edges (plain ${still.unpaired}), largest move ${largest}, bound ${bound}`);
console.log(`displaced torus: closed, ${displacedTorus.triangles} triangles, largest move ${largest.toFixed(5)} (bound ${bound.toFixed(5)})`);
await page.selectOption('#mesh-kind', 'model');

// ---- the seamed model dropped on the canvas, the camera through the JS hook; CP | uniform again ----
const seamsEye = [2.2, 1.6, 2.9];
await page.selectOption('#surface', 'pn-aen');
await page.check('#compare');
const dropped = await page.evaluateHandle(([name, bytes]) => {
    const transfer = new DataTransfer();
    transfer.items.add(new File([new Uint8Array(bytes)], name));
    return transfer;
}, ['BoxTextured.glb', [...readFileSync(seams)]]);
await page.dispatchEvent('#mesh-canvas', 'drop', { dataTransfer: dropped });
await viewerState(() => window.ctessViewer?.model?.name === 'BoxTextured.glb');
await page.evaluate((eye) => window.ctessViewerSetCamera(eye, [0, 0, 0]), seamsEye);
await page.locator('#dice').fill('20');
state = await viewerState((eye) => window.ctessViewer?.model?.name === 'BoxTextured.glb' && window.ctessViewer.diceRate === 20 &&
                                   window.ctessViewer.camera.eye.every((x, k) => x === Math.fround(eye[k])) && window.ctessViewer.compare &&
                                   !window.ctessViewer.displacement && window.ctessViewer.surface === 'pn-aen', seamsEye);
check(state.model.vertex_count === 24 && state.model.open_edges === 0 && state.quads === 0 && page.url().includes('camera=2.2'),
      `seamed model: ${JSON.stringify(state.model)}, URL ${page.url()}`);
await sameAsCli(state, seams, { surface: 'pn-aen', dice: 20, eye: seamsEye }, [['cp', 0], ['uniform', 1]]);

// ---- uniform density split above N beside it (docs/shaders.md, "Splitting"): the CLI's --unwelded --pattern
// uniform runs the same passes, so its counts and checksums are the page's ----
await page.selectOption('#compare-pattern', 'uniform-split');
await page.locator('#dice').fill('2');
state = await viewerState(() => window.ctessViewer?.compare?.mode === 'uniform-split' && window.ctessViewer.diceRate === 2);
{
    const ref = cliStats(seams, { surface: 'pn-aen', dice: 2, eye: seamsEye, pattern: 'uniform', unwelded: true });
    const sum = await page.evaluate(() => window.ctessViewerChecksum(1));
    const what = `BoxTextured.glb uniform split pn-aen DiceRate 2`;
    let ok = check(state.factorScaleBits === ref.gpu.factor_scale_bits, `${what}: factor scale bits ${state.factorScaleBits}, CLI ${ref.gpu.factor_scale_bits}`);
    ok &&= check(ref.gpu.clamped_edges > 0, `${what}: the factors do not pass N (the CLI's clamped uniform clamps ${ref.gpu.clamped_edges} edges)`);
    const shown = await page.textContent('#status');
    ok &&= check(shown.includes('CP | uniform density, split above'), `${what}: the status says "${shown}"`);
    ok &&= check(state.compare.vertices === ref.output_vertices && state.compare.triangles === ref.output_triangles,
                 `${what}: ${state.compare.vertices}/${state.compare.triangles}; CLI ${ref.output_vertices}/${ref.output_triangles}`);
    ok &&= check(JSON.stringify(sum) === JSON.stringify(ref.unwelded.checksum), `${what}: checksums ${JSON.stringify(sum)}, CLI ${JSON.stringify(ref.unwelded.checksum)}`);
    if (ok) compared++;
    console.log(`${what}: ${state.compare.triangles} triangles (clamped to N: ${ref.gpu.triangles}) ${ok ? '=' : '!='} the CLI's`);
}
await page.selectOption('#compare-pattern', 'uniform');
await page.locator('#dice').fill('20');
await viewerState(() => window.ctessViewer?.compare?.mode === 'uniform' && window.ctessViewer.diceRate === 20);

// ---- the model's own KHR_materials_displacement image, factors grown by its bound (--displace-gltf --displace-grow) ----
// BoxTextured.glb with the extension added to its material, pointing at its own embedded texture (CesiumLogoFlat,
// 211 x 211): the GLB's JSON chunk rewritten, its binary chunk kept.
const withDisplacement = (() => {
    const glb = readFileSync(seams), jsonLength = glb.readUInt32LE(12);
    const gltf = JSON.parse(glb.subarray(20, 20 + jsonLength).toString('utf8'));
    gltf.extensionsUsed = [...(gltf.extensionsUsed ?? []), 'KHR_materials_displacement'];
    gltf.materials[0].extensions = { ...(gltf.materials[0].extensions ?? {}),
                                     KHR_materials_displacement: { displacementTexture: { index: 0 }, displacementFactor: 0.5, displacementOffset: -0.25 } };
    let json = Buffer.from(JSON.stringify(gltf), 'utf8');
    json = Buffer.concat([json, Buffer.alloc((4 - (json.length % 4)) % 4, 0x20)]);
    const rest = glb.subarray(20 + jsonLength), header = Buffer.alloc(20);
    header.write('glTF', 0, 'latin1');
    header.writeUInt32LE(2, 4);
    header.writeUInt32LE(20 + json.length + rest.length, 8);
    header.writeUInt32LE(json.length, 12);
    header.write('JSON', 16, 'latin1');
    const dir = mkdtempSync(`${tmpdir()}/ctess-viewer-`), file = `${dir}/BoxDisplaced.glb`;
    writeFileSync(file, Buffer.concat([header, json, rest]));
    process.on('exit', () => rmSync(dir, { recursive: true, force: true }));
    return file;
})();
await page.uncheck('#compare');
await page.fill('#displace-scale', '0.2');
await page.setInputFiles('#model-file', withDisplacement);
const ungrown = await viewerState(() => window.ctessViewer?.model?.name === 'BoxDisplaced.glb' && window.ctessViewer.displacement?.fromModel &&
                                         window.ctessViewer.displacement.factorBound === 0 && !window.ctessViewer.compare);
check(ungrown.displacement.factor === 0.5 && ungrown.displacement.offset === -0.25 && ungrown.displacement.width === 211 &&
      ungrown.model.displacement?.embedded_image === true, `glTF displacement: ${JSON.stringify(ungrown.displacement)}, header ${JSON.stringify(ungrown.model.displacement)}`);
await page.check('#displace-grow');
state = await viewerState(() => window.ctessViewer?.displacement?.factorBound > 0);
// The bound: |0.2 · (texel · 0.5 − 0.25)| at the map's extreme texels, as rt::displacement_bound computes it.
check(state.triangles > ungrown.triangles, `grown factors: ${state.triangles} triangles, ungrown ${ungrown.triangles} (bound ${state.displacement.factorBound})`);
await sameAsCli(state, withDisplacement, { surface: 'pn-aen', dice: 20, eye: seamsEye, displace: { gltf: true, scale: 0.2, grow: true } }, [['cp', 0]]);

// ---- D3D11 fractional_even beside it: no shader runs it, ctess serve's /api/tessellate computes it on the CPU ----
await page.selectOption('#compare-pattern', 'd3d11-even');
await page.check('#compare');
state = await viewerState(() => window.ctessViewer?.compare?.mode === 'd3d11-even' && window.ctessViewer.displacement?.factorBound > 0);
await sameAsCli(state, withDisplacement, { surface: 'pn-aen', dice: 20, eye: seamsEye, displace: { gltf: true, scale: 0.2, grow: true } },
                [['d3d11-even', 1]]);
await page.uncheck('#compare');

// ---- the same map as an RGB vector map in the box's tangent frame (from its uvs), grown: --displace-vector ----
await page.fill('#displace-offset', '0');
await page.setInputFiles('#vector-file', heightMap);
state = await viewerState(() => window.ctessViewer?.displacement?.vector && window.ctessViewer.displacement.offset === 0 &&
                                window.ctessViewer.displacement.factorBound > 0 && !window.ctessViewer.compare);
check(state.model.tangent_source === 'uv' && state.displacement.width === 211 && !state.displacement.fromModel,
      `vector map: ${JSON.stringify(state.displacement)}, tangents from ${state.model.tangent_source}`);
await sameAsCli(state, withDisplacement, { surface: 'pn-aen', dice: 20, eye: seamsEye,
                                           displace: { vector: true, file: heightMap, scale: 0.2, offset: 0, grow: true } }, [['cp', 0]]);
await page.uncheck('#displace-grow');
await viewerState(() => window.ctessViewer?.displacement?.factorBound === 0); // the redraw done before the next upload

// ---- a .gltf whose buffer is a separate file cannot come in one upload: the page shows why ----
await page.setInputFiles('#model-file', external);
state = await viewerState(() => window.ctessViewer?.uploadError);
const status = await page.textContent('#status');
check(/BoxTextured0\.bin/.test(state.uploadError) && /data: URIs/.test(status) && (await page.getAttribute('#status', 'class')) === 'error',
      `external .gltf: "${state.uploadError}", status "${status}"`);
await browser.close();

console.log(`${compared} model views equal ctess mesh --stats; ${failures} failures; ${((Date.now() - started) / 1000).toFixed(1)} s`);
process.exit(failures ? 1 : 0);
