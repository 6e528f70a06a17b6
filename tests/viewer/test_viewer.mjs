// Loads viewer/ from `ctess serve` in headless chromium (WebGPU on SwiftShader, --enable-unsafe-webgpu) and
// checks, against `ctess pattern --format json` (the CPU), bit for bit: the counts in window.ctessViewer and
// the read-back vertices (u, v) and triangles, for CP (generated WGSL, max 64 and 256), the D3D11 modes and
// uniform density (D3D11 and split uniform patterns through /api/pattern; uniform patterns within the table's N
// from the generated WGSL, max 64 and 256, in 2^-24 units: each point the nearest to the CLI's, the triangles the
// CLI's with their winding). Also: the URL sets the state, a slider changes the counts, a uniform sweep visits
// only the CLI's patterns, the canvases are not blank, the mesh view's triangle count follows the DiceRate and
// its read-back is closed (CP and uniform; uniform patch by patch against the CLI), bad /api/pattern input gets a
// 400, a busy port is an error, and without WebGPU the page says so.
//   node tests/viewer/test_viewer.mjs path/to/ctess        exit 0 pass, 1 fail, 77 skipped (no chromium)
import { spawn, execFileSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { chromium } from 'playwright-core';

const ctess = process.argv[2];
const browserPath = process.env.CTESS_CHROMIUM ?? '/usr/bin/chromium';
if (!existsSync(browserPath)) {
    console.log(`SKIPPED: ${browserPath} not found; install Debian's chromium (./.ci/install-deps) to run the viewer test`);
    process.exit(77);
}
const started = Date.now();
let failures = 0;
const check = (ok, what) => {
    if (!ok) { failures++; console.log(`FAIL ${what}`); }
    return ok;
};

// ---- the server, on 127.0.0.1 and a free port ----
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
const stop = () => server.kill();
process.on('exit', stop);
check(/^http:\/\/127\.0\.0\.1:/.test(base), `serve listens on ${base}`);
// The generated constants (record, vertex and fixed-point layouts; docs/shaders.md, "Generated constants"), as
// served to the viewer.
const C = (await (await fetch(`${base}shaders/ctess_mesh_64.layout.json`)).json()).constants;

// ---- a busy port and an impossible port are errors, not a second server or a hang ----
const exitOf = (args) => {
    try {
        execFileSync(ctess, args, { stdio: 'pipe', timeout: 20000 });
        return 0;
    } catch (e) {
        return e.status ?? `killed (${e.signal})`;
    }
};
check(exitOf(['serve', '--port', base.match(/:(\d+)\//)[1]]) === 1, 'serve on a busy port must exit 1');
check(exitOf(['serve', '--port', '70000']) === 2, 'serve --port 70000 must exit 2');

const cli = (mode, factors, max) => JSON.parse(execFileSync(ctess, ['pattern', '--mode', mode, '--factors',
    factors.join(','), '--domain', factors.length === 4 ? 'quad' : 'tri', ...(mode === 'cp' ? ['--max', String(max)] : []), '--format', 'json'], { encoding: 'utf8', maxBuffer: 1 << 28 }));

// Uniform patterns within the table's N come from the generated WGSL (2^-24 units), split ones from
// /api/pattern (the CLI's JSON, bit for bit): the CLI's fixed_one says which (65534 unsplit, 65534² split).
const UNIFORM_ONE = C.UNIFORM_ONE, PIPELINE_ONE = C.FIXED_ONE;
// The pipeline's weight for the CLI's w / 65534: the nearest multiple of 2^-24 (docs/shaders.md), exact in BigInt.
// Never a tie: 2^24·w is even, so its remainder by 65534 is never 32767.
function pipelineUnits(w) {
    const scaled = BigInt(w) * BigInt(PIPELINE_ONE), q = scaled / BigInt(UNIFORM_ONE), r = scaled % BigInt(UNIFORM_ONE);
    return Number(2n * r > BigInt(UNIFORM_ONE) ? q + 1n : q);
}
// A uniform pattern read back from the GPU (uv in 2^-24, indices from 0) against the CLI's JSON: every GPU
// vertex is the nearest 2^-24 point of exactly one CLI vertex (|2(g·65534 − w·2^24)| < 65534, cross-multiplied in
// BigInt), one to one; the triangles, as position triples, are the CLI's with the same winding (each rotated to
// start at its smallest vertex index in the CLI's numbering). Returns an error message or null; sameOrder says
// whether the vertex and triangle order are the CLI's too.
function uniformMismatch(uv, indices, ref) {
    if (uv.length !== 2 * ref.vertex_count || indices.length !== 3 * ref.triangle_count)
        return `${uv.length / 2} vertices, ${indices.length / 3} triangles; CLI ${ref.vertex_count}, ${ref.triangle_count}`;
    const cliAt = new Map();
    ref.vertices.forEach(([u, v], i) => cliAt.set(`${pipelineUnits(u)},${pipelineUnits(v)}`, i));
    if (cliAt.size !== ref.vertex_count) return 'two CLI vertices round to one 2^-24 point';
    const toCli = [];
    for (let i = 0; i < uv.length / 2; i++) {
        const c = cliAt.get(`${uv[2 * i]},${uv[2 * i + 1]}`);
        if (c === undefined) return `GPU vertex ${i} (${uv[2 * i]}, ${uv[2 * i + 1]}) is no CLI vertex`;
        for (let k = 0; k < 2; k++) {
            const gap = 2n * (BigInt(uv[2 * i + k]) * BigInt(UNIFORM_ONE) - BigInt(ref.vertices[c][k]) * BigInt(PIPELINE_ONE));
            if (gap >= BigInt(UNIFORM_ONE) || -gap >= BigInt(UNIFORM_ONE)) return `GPU vertex ${i}: not the nearest 2^-24 point`;
        }
        toCli.push(c);
    }
    if (new Set(toCli).size !== toCli.length) return 'two GPU vertices at one CLI vertex';
    const rotated = (t) => {
        const k = t.indexOf(Math.min(...t));
        return `${t[k]},${t[(k + 1) % 3]},${t[(k + 2) % 3]}`;
    };
    const expected = new Map();
    for (const t of ref.triangles) expected.set(rotated(t), (expected.get(rotated(t)) ?? 0) + 1);
    for (let t = 0; t < indices.length; t += 3) {
        const key = rotated([toCli[indices[t]], toCli[indices[t + 1]], toCli[indices[t + 2]]]);
        if (!expected.get(key)) return `GPU triangle ${t / 3} (CLI vertices ${key}) is not the CLI's (or not with its winding)`;
        expected.set(key, expected.get(key) - 1);
    }
    return null;
}
const sameOrder = (uv, indices, ref) => ref.vertices.every(([u, v], i) => uv[2 * i] === pipelineUnits(u) && uv[2 * i + 1] === pipelineUnits(v)) &&
                                        ref.triangles.flat().every((x, i) => indices[i] === x);
let uniformFromWgsl = 0, uniformSameOrder = 0;

function sameAsCli(state, mode, factors, max) {
    const ref = cli(mode, factors, max);
    const what = `${mode} ${factors.join(',')} max ${max}`;
    if (mode === 'uniform') {
        const split = ref.fixed_one !== UNIFORM_ONE;
        if (!check(state.source === (split ? 'api' : 'wgsl'), `${what}: drawn by ${state.source}, CLI fixed_one ${ref.fixed_one}`)) return null;
        if (!split) {
            let ok = check(state.mode === mode && state.max === max && state.factors.every((f, k) => f === Math.fround(factors[k])),
                           `${what}: state says ${state.mode} max ${state.max} factors ${state.factors}`);
            ok &&= check(state.readback.one === PIPELINE_ONE && state.zeroArea === ref.degenerate_triangle_count &&
                         state.vertices === ref.vertex_count && state.triangles === ref.triangle_count,
                         `${what}: one ${state.readback.one}, counts ${state.vertices}/${state.triangles}/${state.zeroArea}, ` +
                         `CLI ${ref.vertex_count}/${ref.triangle_count}/${ref.degenerate_triangle_count}`);
            const wrong = ok && uniformMismatch(state.readback.uv, state.readback.indices, ref);
            ok &&= check(!wrong, `${what} from WGSL: ${wrong}`);
            uniformFromWgsl += ok;
            uniformSameOrder += ok && sameOrder(state.readback.uv, state.readback.indices, ref);
            return ok ? ref : null;
        }
    }
    let ok = check(state.mode === mode && state.max === max, `${what}: state says ${state.mode} max ${state.max}`);
    ok &&= check(state.factors.every((f, k) => f === Math.fround(factors[k])), `${what}: factors ${state.factors}`);
    ok &&= check(state.vertices === ref.vertex_count && state.triangles === ref.triangle_count,
                 `${what}: counts ${state.vertices}/${state.triangles}, CLI ${ref.vertex_count}/${ref.triangle_count}`);
    ok &&= check(state.zeroArea === ref.degenerate_triangle_count, `${what}: zero-area ${state.zeroArea}, CLI ${ref.degenerate_triangle_count}`);
    const uv = ref.vertices.flat(), idx = ref.triangles.flat();
    ok &&= check(state.readback.one === ref.fixed_one, `${what}: fixed one`);
    const badV = uv.findIndex((x, i) => state.readback.uv[i] !== x);
    ok &&= check(state.readback.uv.length === uv.length && badV < 0, `${what}: vertex word ${badV} differs`);
    const badT = idx.findIndex((x, i) => state.readback.indices[i] !== x);
    ok &&= check(state.readback.indices.length === idx.length && badT < 0, `${what}: index ${badT} differs`);
    return ok ? ref : null;
}

// Headless WebGPU canvases need Vulkan compositing on SwiftShader: with the default (GL) compositor the
// device is lost at the first present ("A valid external Instance reference no longer exists").
const flags = ['--no-sandbox', '--disable-quic', '--disable-background-networking', '--disable-component-update',
               '--disable-sync', '--no-first-run', '--use-angle=vulkan', '--enable-features=Vulkan', '--use-vulkan=swiftshader'];
const browser = await chromium.launch({ executablePath: browserPath, headless: true, args: [...flags, '--enable-unsafe-webgpu'] });
const page = await browser.newPage({ viewport: { width: 1000, height: 720 } });
page.on('pageerror', (e) => check(false, `page error: ${e.message}`));
// Waits for a redraw that satisfies pred; on a timeout, says what the page shows.
async function viewerState(pred, arg) {
    try {
        await page.waitForFunction(pred, arg, { timeout: 120000 });
    } catch (e) {
        const shown = await page.evaluate(() => {
            const { readback, trail, ...rest } = window.ctessViewer ?? {};
            return `status "${document.getElementById('status').textContent}", state ${JSON.stringify(rest)}`;
        });
        throw new Error(`${e.message}\nwaiting for ${JSON.stringify(arg)}; the page shows ${shown}`);
    }
    // the mesh view's read-back stays in the page (weldCheck reads it there)
    return page.evaluate(() => (window.ctessViewer.view === 'mesh' ? { ...window.ctessViewer, readback: null } : window.ctessViewer));
}
const factorsMatch = ({ mode, factors, max }) => {
    const v = window.ctessViewer;
    return v && v.mode === mode && v.max === max && v.factors.length === factors.length &&
           v.factors.every((f, k) => f === Math.fround(factors[k]));
};
// A new state through the exact-factors field (as a person types it).
async function typeFactors(factors) {
    await page.fill('#factors', factors.join(','));
    await page.dispatchEvent('#factors', 'change');
}

// The uniform table's N, as the CLI reports it (16 by default, 11 with CTESS_UNIFORM_MAX_FACTOR=11).
const UNIFORM_N = cli('uniform', [1, 1, 1]).max_tess_factor;

// ---- CP and D3D11 patterns: the first from the URL, then through the mode and max selectors and the
// exact-factors field, on one page (each page load compiles the WGSL again: about 7 s on SwiftShader) ----
const cases = [
    ['cp', 64, [[10.3, 6, 3], [1, 1, 1], [1.5, 1.25, 1.01], [2, 2, 2], [16, 8, 4], [8, 16, 4], [33.7, 2.2, 64],
                [64, 64, 64], [100, 0.5, 7.77], [5.5, 5.5, 5.5], [63.99, 12.125, 40.5]]],
    ['d3d11-integer', 64, [[3, 4, 5], [7.2, 1, 13]]],
    ['d3d11-pow2', 64, [[3, 4, 5]]],
    ['d3d11-odd', 64, [[2.5, 3.7, 5.1], [64, 1, 1]]],
    ['d3d11-even', 64, [[8, 16, 4], [10.3, 6, 3], [2, 2, 2]]],
    ['cp', 256, [[10.3, 6, 3], [256, 256, 256], [150.5, 3, 40.25], [1, 256, 17.25], [70, 70.5, 71]]],
    ['cp', 64, [[12, 5, 12, 30], [8, 8, 8, 8], [1, 1, 1, 1], [2.5, 40, 1.5, 6.25]]], // quads
    ['d3d11-even', 64, [[12, 5, 12, 30]]],
    // uniform density: in order, out of order and its rotations, rounded (11, 6, 3; 3, 3, 7), non-Euclidean, clamped to
    // 1, (N, N, N), just under and at N + 0.5, split above the table's N (16 or 11; fixed_one 65534²), split and
    // clamped to N² (256 for N = 16); within N from the generated WGSL (max 64 and 256 modules), above it from the API
    ['uniform', 64, [[11, 9, 6], [1, 1, 1], [3, 11, 7], [7, 3, 11], [11, 7, 3], [10.5, 6.49, 2.5], [2.5, 3.49, 7],
                     [11, 4, 2], [0.3, 1, 1], [UNIFORM_N, UNIFORM_N, UNIFORM_N], [UNIFORM_N + 0.49, 2, 3], [UNIFORM_N + 0.5, 2, 3],
                     [40, 30, 20], [300, 2, 299]]],
    ['uniform', 256, [[1, 1, 1], [11, 9, 6], [9, 6, 11], [UNIFORM_N, UNIFORM_N, UNIFORM_N], [3.49, 2.5, UNIFORM_N - 0.5], [20, 5, 5]]],
];
let compared = 0;
await page.goto(`${base}?mode=cp&max=64&factors=10.3,6,3`);
await viewerState(() => window.ctessViewer);
for (const [mode, max, triples] of cases) {
    await page.selectOption('#mode', mode);
    await page.selectOption('#max', String(max));
    await page.selectOption('#domain', triples[0].length === 4 ? 'quad' : 'tri');
    for (const factors of triples) {
        await typeFactors(factors);
        const t0 = Date.now();
        const state = await viewerState(factorsMatch, { mode, factors, max });
        if (sameAsCli(state, mode, factors, max)) compared++;
        console.log(`${mode} max ${max} factors ${factors}: ${state.vertices} vertices, ${state.triangles} ` +
                    `triangles, ${Date.now() - t0} ms (page: ${JSON.stringify(state.ms, (k, v) => (typeof v === "number" ? Math.round(v) : v))})`);
    }
}
const listed = cases.reduce((n, c) => n + c[2].length, 0);
check(compared === listed, `only ${compared} of ${listed} patterns matched`);

let state;
// ---- uniform density (docs/algorithm.md §3): integer factors, drawn with them as side lengths ----
const uniformStart = Date.now();
await page.selectOption('#mode', 'uniform');
await page.selectOption('#max', '64');
check(await page.$eval('#domain-quad', (o) => o.disabled), 'uniform: the quad domain must be disabled');
const corners = (s) => s.corners.map((c, k) => Math.hypot(c[0] - s.corners[(k + 1) % 3][0], c[1] - s.corners[(k + 1) % 3][1]));
const sameRatios = (lengths, sides) => lengths.every((l, k) => Math.abs(l / lengths[0] - sides[k] / sides[0]) < 1e-9);
// halves round up (§3.4): 10.5, 6.49, 2.5 is drawn and tessellated as 11, 6, 3
await typeFactors([10.5, 6.49, 2.5]);
state = await viewerState(factorsMatch, { mode: 'uniform', factors: [10.5, 6.49, 2.5], max: 64 });
const rounded = cli('uniform', [11, 6, 3]);
check(String(state.sides) === '11,6,3' && state.triangles === rounded.triangle_count && state.vertices === rounded.vertex_count,
      `uniform 10.5,6.49,2.5: sides ${state.sides}, ${state.vertices}/${state.triangles}; 11,6,3 has ${rounded.vertex_count}/${rounded.triangle_count}`);
// e0 = v0v1, e1 = v1v2, e2 = v2v0 on the canvas in the ratio 11 : 9 : 6; a non-Euclidean 11, 4, 2 equilateral
await typeFactors([11, 9, 6]);
state = await viewerState(factorsMatch, { mode: 'uniform', factors: [11, 9, 6], max: 64 });
check(sameRatios(corners(state), [11, 9, 6]), `uniform 11,9,6 drawn with sides ${corners(state)}`);
const at11 = state;
await typeFactors([11, 4, 2]);
state = await viewerState(factorsMatch, { mode: 'uniform', factors: [11, 4, 2], max: 64 });
check(sameRatios(corners(state), [1, 1, 1]), `uniform 11,4,2 (non-Euclidean) drawn with sides ${corners(state)}`);
await typeFactors([40, 30, 20]);
state = await viewerState(factorsMatch, { mode: 'uniform', factors: [40, 30, 20], max: 64 });
check(state.readback.one === 65534 ** 2 && state.source === 'api', `uniform 40,30,20 (split): fixed one ${state.readback.one}, from ${state.source}`);
check(state.ratioToD3d11Even === state.triangles / cli('d3d11-even', [40, 30, 20]).triangle_count, `uniform ratio ${state.ratioToD3d11Even}`);
// the e0 slider: 11 -> 11.3 rounds to the same pattern, 14 gives the CLI's 14, 9, 6
await typeFactors([11, 9, 6]);
await viewerState(factorsMatch, { mode: 'uniform', factors: [11, 9, 6], max: 64 });
await page.locator('#f0').fill('11.3');
state = await viewerState(factorsMatch, { mode: 'uniform', factors: [11.3, 9, 6], max: 64 });
check(state.triangles === at11.triangles && String(state.readback.uv) === String(at11.readback.uv),
      `uniform slider 11 -> 11.3: ${state.triangles} triangles, ${at11.triangles} at 11`);
await page.locator('#f0').fill('14');
state = await viewerState(factorsMatch, { mode: 'uniform', factors: [14, 9, 6], max: 64 });
check(state.triangles !== at11.triangles, `uniform slider 11 -> 14: still ${state.triangles} triangles`);
sameAsCli(state, 'uniform', [14, 9, 6], 64) && compared++;
// a sweep 10,9,6 -> 11,9,6 pops: the positions it has drawn are exactly those of the CLI's two patterns (drawn
// from the WGSL's 2^-24 units: each the nearest such point to the CLI's; both within N = 11 or 16)
await page.fill('#sweep-from', '10,9,6');
await page.fill('#sweep-to', '11,9,6');
await page.click('#play');
state = await viewerState(() => window.ctessViewer?.trail && window.ctessViewer.factors[0] >= 10.5);
await page.click('#play');
const expected = new Set(), drawn = new Set(state.trail.map(([u, v]) => `${u},${v}`));
for (const f of [[10, 9, 6], [11, 9, 6]]) {
    const ref = cli('uniform', f);
    for (const [u, v] of ref.vertices) expected.add(`${pipelineUnits(u) / PIPELINE_ONE},${pipelineUnits(v) / PIPELINE_ONE}`);
}
check(drawn.size === expected.size && [...drawn].every((p) => expected.has(p)),
      `uniform sweep: ${drawn.size} positions drawn, ${expected.size} in the CLI's 10,9,6 and 11,9,6`);
console.log(`uniform sweep 10,9,6 -> 11,9,6: ${state.trail.length} points drawn at ${drawn.size} positions; ` +
            `uniform checks after the sets: ${((Date.now() - uniformStart) / 1000).toFixed(1)} s; ${uniformFromWgsl} uniform ` +
            `patterns from WGSL equal the CLI's (${uniformSameOrder} in the CLI's vertex and triangle order too)`);

// ---- the ratio to D3D11 fractional_even on the same edges ----
await page.selectOption('#mode', 'cp');
await page.selectOption('#max', '64');
await page.selectOption('#domain', 'tri');
await typeFactors([16, 8, 4]);
state = await viewerState(factorsMatch, { mode: 'cp', factors: [16, 8, 4], max: 64 });
const even = cli('d3d11-even', [16, 8, 4], 64);
check(state.ratioToD3d11Even === state.triangles / even.triangle_count,
      `ratio ${state.ratioToD3d11Even}, expected ${state.triangles}/${even.triangle_count}`);

// ---- a slider: e0 from 16 to 40 changes the counts to the CLI's for 40,8,4 ----
await page.locator('#f0').fill('40');
state = await viewerState(factorsMatch, { mode: 'cp', factors: [40, 8, 4], max: 64 });
const before = cli('cp', [16, 8, 4], 64);
check(state.triangles > before.triangle_count, `slider: ${state.triangles} triangles at e0 = 40, ${before.triangle_count} at 16`);
sameAsCli(state, 'cp', [40, 8, 4], 64) && compared++;

// ---- the canvases are not blank: pixel statistics of real screenshots, decoded by the browser ----
async function pixelStats(selector) {
    const png = (await page.locator(selector).screenshot()).toString('base64');
    return page.evaluate(async (b64) => {
        const bitmap = await createImageBitmap(await (await fetch(`data:image/png;base64,${b64}`)).blob());
        const c = new OffscreenCanvas(bitmap.width, bitmap.height).getContext('2d');
        c.drawImage(bitmap, 0, 0);
        const d = c.getImageData(0, 0, bitmap.width, bitmap.height).data;
        let ink = 0;
        const colours = new Set();
        for (let i = 0; i < d.length; i += 4) {
            if (d[i] < 240 || d[i + 1] < 240 || d[i + 2] < 240) ink++;
            colours.add((d[i] << 16) | (d[i + 1] << 8) | d[i + 2]);
        }
        return { ink: ink / (d.length / 4), colours: colours.size };
    }, png);
}
let stats = await pixelStats('#pattern-canvas');
console.log(`pattern canvas: ${(100 * stats.ink).toFixed(1)}% ink, ${stats.colours} colours`);
check(stats.ink > 0.2 && stats.colours > 20, 'pattern canvas looks blank');

// ---- mesh view: more triangles at a smaller DiceRate, shaded pixels on the canvas ----
await page.check('input[name=view][value=mesh]');
const coarse = await viewerState(() => window.ctessViewer?.view === 'mesh');
await page.locator('#dice').fill('6');
const fine = await viewerState(() => window.ctessViewer?.view === 'mesh' && window.ctessViewer.diceRate === 6);
check(coarse.triangles >= 20 && fine.triangles > 2 * coarse.triangles,
      `mesh: ${coarse.triangles} triangles at DiceRate ${coarse.diceRate}, ${fine.triangles} at 6`);
// The factors come from the base mesh alone, so Phong and flat evaluation give PN's counts exactly.
for (const [value, name] of [['phong', 'phong'], ['flat', 'flat']]) {
    await page.selectOption('#surface', value);
    const other = await viewerState((n) => window.ctessViewer?.surface === n, name);
    check(other.vertices === fine.vertices && other.triangles === fine.triangles,
          `mesh ${name}: ${other.vertices}/${other.triangles}, PN ${fine.vertices}/${fine.triangles}`);
}
await page.selectOption('#surface', 'pn');
await viewerState(() => window.ctessViewer?.surface === 'pn');
stats = await pixelStats('#mesh-canvas');
console.log(`mesh canvas: ${(100 * stats.ink).toFixed(1)}% ink, ${stats.colours} colours; ` +
            `${coarse.triangles} -> ${fine.triangles} triangles`);
check(stats.ink > 0.1 && stats.colours > 50, 'mesh canvas looks blank');

// ---- the mesh view's read-back is a closed, consistently oriented surface (no cracks) ----
// Welds the output vertices by their position bits, drops CP's zero-area triangles (two corners at one point,
// docs/algorithm.md §2.9) and counts directed edges: every edge of a closed, consistently oriented surface
// without T-junctions or cracks is used exactly twice, once each way. Euler's V - E + F is then 2 for the
// icosphere and 0 for the torus.
async function weldCheck() {
    return page.evaluate((C) => {
        const { vertices, indices } = window.ctessViewer.readback;
        const id = new Map();
        const point = (i) => {
            const o = i * C.VERTEX_WORDS + C.VERTEX_POSITION;
            const key = `${vertices[o]},${vertices[o + 1]},${vertices[o + 2]}`;
            if (!id.has(key)) id.set(key, id.size);
            return id.get(key);
        };
        const directed = new Map();
        let faces = 0;
        for (let t = 0; t < indices.length; t += 3) {
            const w = [point(indices[t]), point(indices[t + 1]), point(indices[t + 2])];
            if (w[0] === w[1] || w[1] === w[2] || w[2] === w[0]) continue;
            faces++;
            for (let k = 0; k < 3; k++) {
                const key = `${w[k]},${w[(k + 1) % 3]}`;
                directed.set(key, (directed.get(key) ?? 0) + 1);
            }
        }
        let unpaired = 0;
        for (const [key, n] of directed) {
            const [a, b] = key.split(',');
            if (n !== 1 || directed.get(`${b},${a}`) !== 1) unpaired++;
        }
        return { points: id.size, edges: directed.size / 2, faces, unpaired, euler: id.size - directed.size / 2 + faces };
    }, C);
}
const meshStart = Date.now();
const weldIco = await weldCheck();
check(weldIco.unpaired === 0 && weldIco.euler === 2, `mesh icosahedron: ${JSON.stringify(weldIco)}`);
// the quad mesh: a 12 x 8 torus, two triangles per quad, counts that follow the DiceRate
await page.selectOption('#mesh-kind', 'torus');
const torusFine = await viewerState(() => window.ctessViewer?.mesh === 'torus');
const weldFine = await weldCheck();
check(torusFine.patches === 96 && torusFine.quads === 96 && torusFine.diceRate === 6 && page.url().includes('mesh=torus'),
      `torus: ${torusFine.patches} patches at DiceRate ${torusFine.diceRate}, URL ${page.url()}`);
check(weldFine.unpaired === 0 && weldFine.euler === 0 && weldFine.points > 96, `torus at DiceRate 6: ${JSON.stringify(weldFine)}`);
stats = await pixelStats('#mesh-canvas');
check(stats.ink > 0.1 && stats.colours > 50, `torus canvas looks blank: ${JSON.stringify(stats)}`);
await page.locator('#dice').fill('24');
const torusCoarse = await viewerState(() => window.ctessViewer?.mesh === 'torus' && window.ctessViewer.diceRate === 24);
const weldCoarse = await weldCheck();
check(torusCoarse.triangles >= 192 && torusFine.triangles > 2 * torusCoarse.triangles,
      `torus: ${torusCoarse.triangles} triangles at DiceRate 24, ${torusFine.triangles} at 6`);
check(weldCoarse.unpaired === 0 && weldCoarse.euler === 0, `torus at DiceRate 24: ${JSON.stringify(weldCoarse)}`);
// flat evaluation: PN's counts, and its shared edges are bit for bit too
await page.selectOption('#surface', 'flat');
const torusFlat = await viewerState(() => window.ctessViewer?.mesh === 'torus' && window.ctessViewer.surface === 'flat');
const weldFlat = await weldCheck();
check(torusFlat.triangles === torusCoarse.triangles && torusFlat.vertices === torusCoarse.vertices &&
      weldFlat.unpaired === 0 && weldFlat.euler === 0, `torus flat: ${torusFlat.triangles} triangles, ${JSON.stringify(weldFlat)}`);
console.log(`mesh welded: icosahedron ${weldIco.points} points, ${weldIco.edges} edges, ${weldIco.faces} faces; torus ` +
            `${torusCoarse.triangles} -> ${torusFine.triangles} triangles (DiceRate 24 -> 6), ${weldFine.points} points, ` +
            `${weldFine.edges} edges, ${weldFine.faces} faces at 6; canvas ${(100 * stats.ink).toFixed(1)}% ink, ` +
            `${stats.colours} colours; ${((Date.now() - meshStart) / 1000).toFixed(1)} s`);

// ---- the mesh view with the uniform pattern (params word 10 = 1, the uniform blob) ----
// No CPU mesh pipeline is reachable from here (the CLI has no mesh command), so each patch stands in for it: its
// integer factors are uniform::round_factor of the factor bits the setup pass computed (nearest, halves up,
// clamped to [1, N]: mirrored below exactly, in double arithmetic), and its counts, (u, v) and triangles are the CLI's
// pattern for those factors (uniformMismatch); the totals are the sums. Then the surface is closed, as for CP.
const uniformFactorRef = (f, n) => (!(f >= 1.5) ? 1 : Math.min(n, Math.floor(f + 0.5)));
const cliUniform = new Map(); // 'a,b,c' -> the CLI's JSON
async function uniformMeshAgainstCli(state) {
    const { records, uv, indices } = await page.evaluate((C) => {
        const { vertices, indices, records } = window.ctessViewer.readback;
        const pairs = [];
        for (let i = 0; i < vertices.length; i += C.VERTEX_WORDS) pairs.push(vertices[i + C.VERTEX_U], vertices[i + C.VERTEX_V]);
        return { records: Array.from(records), uv: pairs, indices: Array.from(indices) };
    }, C);
    const factor = new Float32Array(new Uint32Array(records).buffer);
    const wanted = [];
    let clamped = 0, vertices = 0, triangles = 0;
    // Quad records (the torus) hold two halves (docs/shaders.md, "Quads"): their clamped edges are counted from
    // the four edge factors (Q3's in the setup words); their patterns are checked by the closedness test only.
    // Meshes loaded from files are compared with `ctess mesh --stats` below, quads included.
    const quadPatches = [];
    for (let t = 0; t < state.patches; t++) {
        const rec = t * C.PATCH_WORDS;
        if (records[rec + C.REC_KIND] !== C.PATCH_KIND_QUAD) continue;
        quadPatches.push(t);
        const q3 = new Float32Array(Uint32Array.of(records[rec + C.SETUP + C.QSETUP_Q3_FACTOR]).buffer)[0];
        clamped += [factor[rec + C.REC_FACTOR], factor[rec + C.REC_FACTOR + 1], factor[rec + C.REC_FACTOR + 2], q3]
            .filter((f) => f >= UNIFORM_N + 0.5).length;
    }
    if (quadPatches.length) return { clamped, distinct: null };
    for (let t = 0; t < state.patches; t++) {
        const rec = t * C.PATCH_WORDS, f = [0, 1, 2].map((k) => uniformFactorRef(factor[rec + C.REC_FACTOR + k], UNIFORM_N));
        clamped += [0, 1, 2].filter((k) => factor[rec + C.REC_FACTOR + k] >= UNIFORM_N + 0.5).length;
        const token = rec + C.REC_TOKEN;
        if (!check(f.every((x, k) => records[token + k] === x), `uniform mesh patch ${t}: integer factors ${records.slice(token, token + 3)}, expected ${f}`)) return null;
        wanted.push(f.join(','));
    }
    for (const key of wanted) if (!cliUniform.has(key)) cliUniform.set(key, cli('uniform', key.split(',').map(Number)));
    for (let t = 0; t < state.patches; t++) {
        const rec = t * C.PATCH_WORDS, ref = cliUniform.get(wanted[t]);
        const [count, tcount, first, tfirst] = [records[rec + C.REC_VERTEX_COUNT], records[rec + C.REC_TRIANGLE_COUNT],
                                                records[rec + C.REC_FIRST_VERTEX], records[rec + C.REC_FIRST_TRIANGLE]];
        const wrong = count !== ref.vertex_count || tcount !== ref.triangle_count ? `counts ${count}/${tcount}` :
            uniformMismatch(uv.slice(2 * first, 2 * (first + count)), indices.slice(3 * tfirst, 3 * (tfirst + tcount)).map((i) => i - first), ref);
        if (!check(!wrong, `uniform mesh patch ${t} (factors ${wanted[t]}): ${wrong}`)) return null;
        vertices += count;
        triangles += tcount;
    }
    check(vertices === state.vertices && triangles === state.triangles,
          `uniform mesh: ${state.vertices}/${state.triangles}, the patches' CLI patterns sum to ${vertices}/${triangles}`);
    return { clamped, distinct: new Set(wanted).size };
}
const uniformMeshStart = Date.now();
await page.selectOption('#mesh-pattern', 'uniform');
const torusUniform = await viewerState(() => window.ctessViewer?.mode === 'uniform' && window.ctessViewer.mesh === 'torus');
check(torusUniform.uniformMax === UNIFORM_N && page.url().includes('pattern=uniform'), `uniform mesh: N ${torusUniform.uniformMax}, URL ${page.url()}`);
const weldUniform = await weldCheck();
check(weldUniform.unpaired === 0 && weldUniform.euler === 0 && weldUniform.faces === torusUniform.triangles,
      `uniform torus (flat, DiceRate 24): ${torusUniform.triangles} triangles, ${JSON.stringify(weldUniform)}`);
const torusUniformCli = await uniformMeshAgainstCli(torusUniform);
// DiceRate 6, PN: factors above N are clamped (the pipeline does not split)
await page.selectOption('#surface', 'pn');
await page.locator('#dice').fill('6');
const torusUniformFine = await viewerState(() => window.ctessViewer?.mode === 'uniform' && window.ctessViewer.diceRate === 6 && window.ctessViewer.surface === 'pn');
const weldUniformFine = await weldCheck();
check(weldUniformFine.unpaired === 0 && weldUniformFine.euler === 0 && weldUniformFine.faces === torusUniformFine.triangles,
      `uniform torus (PN, DiceRate 6): ${JSON.stringify(weldUniformFine)}`);
const torusUniformFineCli = await uniformMeshAgainstCli(torusUniformFine);
check(torusUniformFineCli?.clamped > 0, `uniform torus at DiceRate 6: no factor above N = ${UNIFORM_N} (nothing clamped)`);
// the icosphere (80 triangles), PN at DiceRate 6: a closed sphere, V - E + F = 2
await page.selectOption('#mesh-kind', 'ico1');
const icoUniform = await viewerState(() => window.ctessViewer?.mode === 'uniform' && window.ctessViewer.mesh === 'ico1');
const weldIcoUniform = await weldCheck();
check(weldIcoUniform.unpaired === 0 && weldIcoUniform.euler === 2 && weldIcoUniform.faces === icoUniform.triangles,
      `uniform icosphere (PN, DiceRate 6): ${JSON.stringify(weldIcoUniform)}`);
const icoUniformCli = await uniformMeshAgainstCli(icoUniform);
stats = await pixelStats('#mesh-canvas');
check(stats.ink > 0.1 && stats.colours > 50, `uniform icosphere canvas looks blank: ${JSON.stringify(stats)}`);
console.log(`uniform mesh: torus ${torusUniform.triangles} triangles at DiceRate 24 (CP ${torusCoarse.triangles}), ` +
            `${torusUniformFine.triangles} at 6 (CP ${torusFine.triangles}; ${torusUniformFineCli?.clamped} patch edges clamped to ${UNIFORM_N}); ` +
            `icosphere ${icoUniform.triangles} at 6; distinct patterns ${torusUniformCli?.distinct} / ${torusUniformFineCli?.distinct} / ` +
            `${icoUniformCli?.distinct}; ${((Date.now() - uniformMeshStart) / 1000).toFixed(1)} s`);
// ---- the URL sets a D3D11 state too ----
await page.goto(`${base}?mode=d3d11-odd&factors=2.5,3.7,5.1`);
state = await viewerState(factorsMatch, { mode: 'd3d11-odd', factors: [2.5, 3.7, 5.1], max: 64 });
sameAsCli(state, 'd3d11-odd', [2.5, 3.7, 5.1], 64) && compared++;
// and uniform (a quad in the URL falls back to the triangle: uniform tessellates triangles only)
await page.goto(`${base}?mode=uniform&domain=quad&factors=11,9,6`);
state = await viewerState(factorsMatch, { mode: 'uniform', factors: [11, 9, 6], max: 64 });
check(state.domain === 'tri', `uniform from the URL: domain ${state.domain}`);
sameAsCli(state, 'uniform', [11, 9, 6], 64) && compared++;
await browser.close();

// ---- bad input to /api/pattern is a 400 with the CLI's message ----
for (const q of ['mode=bogus&factors=1,2,3', 'mode=d3d11-even&factors=nan,2,3', 'mode=cp&factors=1,2', 'mode=cp&factors=1,2,3&max=100',
                 'mode=uniform&domain=quad&factors=1,2,3,4', 'mode=uniform&factors=1,2,3&max=64', 'mode=uniform&factors=1,inf,3']) {
    const r = await fetch(`${base}api/pattern?${q}`);
    const body = await r.json();
    check(r.status === 400 && typeof body.error === 'string', `api ${q}: status ${r.status}`);
}

// ---- without WebGPU the page says so ----
const plain = await chromium.launch({ executablePath: browserPath, headless: true, args: flags });
const page2 = await plain.newPage();
await page2.goto(base);
await page2.waitForFunction(() => window.ctessViewer, null, { timeout: 60000 });
const message = await page2.textContent('#status');
check(/WebGPU is unavailable/.test(message), `no-WebGPU message: "${message}"`);
await plain.close();

console.log(`${compared} patterns equal the CLI's bit for bit; ${failures} failures; ${((Date.now() - started) / 1000).toFixed(1)} s`);
process.exit(failures ? 1 : 0);
