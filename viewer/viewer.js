// ctess viewer: pattern view (one CP or uniform-density triangle from the generated WGSL on WebGPU, or a D3D11
// pattern, or a uniform pattern split above the table's N, from `ctess serve`'s /api/pattern) and mesh view
// (mesh_view.js). After each redraw, window.ctessViewer holds {mode, factors, max, source, vertices, triangles,
// zeroArea, ratioToD3d11Even, sides, corners, readback} for automation (docs/viewer.md);
// ?view=pattern|mesh&mode=cp&factors=10.3,6,3&max=64 sets the starting state.
import { openDevice, WgslPipeline } from './ctess_gpu.js';
import { MeshView, MESH_NAMES, SURFACE_NAMES } from './mesh_view.js';

const MODES = ['cp', 'd3d11-integer', 'd3d11-pow2', 'd3d11-odd', 'd3d11-even', 'uniform'];
const $ = (id) => document.getElementById(id);
const status = $('status');
const setStatus = (text, error = false) => {
    status.textContent = text;
    status.className = error ? 'error' : '';
};

const query = new URLSearchParams(location.search);
const state = {
    view: query.get('view') === 'mesh' ? 'mesh' : 'pattern',
    mode: MODES.includes(query.get('mode')) ? query.get('mode') : 'cp',
    max: query.get('max') === '256' ? 256 : 64,
    domain: query.get('domain') === 'quad' && query.get('mode') !== 'uniform' ? 'quad' : 'tri', // uniform: tri only
    factors: null,
    sweep: null, // {from, to, start} while playing
    trail: null, // [[u, v], ...]: the domain positions a sweep has drawn; kept when paused, dropped by the next change
};

state.factors = parseFactors(query.get('factors') ?? '', state.domain) ?? (state.domain === 'quad' ? [12, 5, 12, 30] : [10.3, 6, 3]);

// Three factors for a triangle, four for a quad (q0q1, q1q2, q2q3, q3q0), each finite and > 0.
function parseFactors(text, domain = state.domain) {
    const f = text.split(',').map((s) => Number(s.trim()));
    const count = domain === 'quad' ? 4 : 3;
    return f.length === count && f.every((x) => Number.isFinite(x) && x > 0) ? f.map(Math.fround) : null;
}
const factorText = (f) => f.map((x) => String(Number(x.toPrecision(7)))).join(',');

// ---- pattern sources ----
const pipelines = new Map(); // max -> Promise<WgslPipeline>
let device = null;
function pipelineFor(max) {
    if (!pipelines.has(max)) pipelines.set(max, WgslPipeline.load(device, max));
    return pipelines.get(max);
}

// The CLI's JSON for a D3D11 mode (three factors: inside = the largest, as in `ctess pattern`) or uniform.
const apiCache = new Map();
async function apiPattern(mode, factors) {
    const domain = factors.length === 4 ? 'quad' : 'tri';
    const key = `${mode}:${domain}:${factors.join(',')}`;
    if (!apiCache.has(key)) {
        const url = `api/pattern?mode=${mode}&domain=${domain}&factors=${factors.map(String).join(',')}`;
        const p = fetch(url).catch(() => {
            throw new Error('D3D11 and uniform patterns come from `ctess serve` (/api/pattern), which did not answer');
        }).then(async (r) => {
            if (!(r.headers.get('content-type') ?? '').includes('json'))
                throw new Error('D3D11 and uniform patterns come from `ctess serve` (/api/pattern); this server has none');
            const json = await r.json();
            if (!r.ok) throw new Error(json.error ?? `HTTP ${r.status}`);
            return json;
        });
        p.catch(() => apiCache.delete(key));
        apiCache.set(key, p);
        if (apiCache.size > 256) apiCache.delete(apiCache.keys().next().value);
    }
    return apiCache.get(key);
}

// uniform::round_factor (constexpr/ctess/uniform/factor.hpp, docs/algorithm.md §3.4), exactly (f is a float, f +
// 0.5 is exact in a double): nearest integer, halves up, in [1, top]. It shapes the drawing frame (the side lengths
// `ctess pattern --format svg` draws uniform with) and picks the source: integer factors within the table's N run
// on the GPU, larger ones are split by the CLI.
const uniformFactor = (f, top) => (!(f >= 1.5) ? 1 : Math.min(top, Math.floor(f + 0.5)));

// A pattern with the source that drew it: 'wgsl' (the generated WGSL on WebGPU) or 'api' (ctess serve).
async function computePattern(mode, factors, max) {
    if (mode === 'cp') {
        const p = await (await pipelineFor(max)).pattern(factors);
        return { one: 1 << 24, uv: p.uv, indices: p.indices, vertices: p.vertexCount, triangles: p.triangleCount, sides: null, source: 'wgsl' };
    }
    if (mode === 'uniform') {
        // The pipeline clamps at the table's N and does not split (docs/shaders.md); above N the CLI splits.
        const pipeline = await pipelineFor(max);
        const n = (await pipeline.uniformTables()).maxFactor;
        const sides = factors.map((f) => uniformFactor(f, n * n));
        if (sides.every((s) => s <= n)) {
            const p = await pipeline.pattern(factors, 'uniform');
            return { one: 1 << 24, uv: p.uv, indices: p.indices, vertices: p.vertexCount, triangles: p.triangleCount, sides, source: 'wgsl' };
        }
    }
    const json = await apiPattern(mode, factors);
    // Uniform factors go up to N² (split above the table's N, docs/algorithm.md §3.5); fixed_one is then 65534²,
    // which still fits a Uint32Array.
    const top = json.max_tess_factor ** 2;
    return {
        one: json.fixed_one, uv: Uint32Array.from(json.vertices.flat()), indices: Uint32Array.from(json.triangles.flat()),
        vertices: json.vertex_count, triangles: json.triangle_count,
        sides: mode === 'uniform' ? factors.map((f) => uniformFactor(f, top)) : null, source: 'api',
        splitAbove: mode === 'uniform' ? json.max_tess_factor : null, // the table's N
    };
}

// ---- drawing (the layout and marks of tools/ctess/svg_writer.cpp's pattern SVG) ----
const canvas = $('pattern-canvas');
const ctx = canvas.getContext('2d');
const MARGIN = 50;
// Triangles equilateral with (0,0) bottom left, (1,0) bottom right, (0,1) top; quads square, (0,0) bottom left.
// Uniform density, like `ctess pattern --format svg`, is drawn with its integer factors as side lengths
// (e0 = v0v1 at the bottom), when they make a Euclidean triangle, so that equal intrinsic lengths look equal;
// such a frame is centred in the canvas. v1 = (ux, 0), v2 = (vx, vy) and v0 at x0, all over the width.
function frameFor(domain, sides) {
    const roomX = canvas.width - 2 * MARGIN, roomY = canvas.height - 2 * MARGIN;
    if (domain === 'quad') return { square: true, side: Math.min(roomX, roomY), left: MARGIN, bottom: canvas.height - MARGIN };
    const f = { square: false, ux: 1, vx: 0.5, vy: Math.sqrt(3) / 2, x0: 0 };
    const [a, b, c] = sides ?? [];
    const shaped = sides !== null && a < b + c && b < a + c && c < a + b;
    if (shaped) {
        const x2 = (a * a + c * c - b * b) / (2 * a), y2 = Math.sqrt(Math.max(0, c * c - x2 * x2));
        const lo = Math.min(0, x2), width = Math.max(a, x2) - lo;
        Object.assign(f, { ux: a / width, vx: x2 / width, vy: y2 / width, x0: -lo / width });
    }
    f.side = Math.min(roomX, roomY / f.vy);
    f.left = MARGIN + (roomX - f.side) / 2;
    f.bottom = canvas.height - MARGIN - (shaped ? (roomY - f.side * f.vy) / 2 : 0);
    return f;
}
let frame = frameFor(state.domain, null);
const toX = (u, v) => frame.left + frame.side * (frame.square ? u : frame.x0 + u * frame.ux + v * frame.vx);
const toY = (v) => frame.bottom - frame.side * (frame.square ? v : v * frame.vy);

function doubledArea(uv, a, b, c, one) {
    const bx = uv[2 * b] - uv[2 * a], by = uv[2 * b + 1] - uv[2 * a + 1];
    const cx = uv[2 * c] - uv[2 * a], cy = uv[2 * c + 1] - uv[2 * a + 1];
    // exact below 2^26 (products below 2^53); split uniform patches (one = 65534²) need BigInt
    return one < 2 ** 26 ? bx * cy - by * cx : Number(BigInt(bx) * BigInt(cy) - BigInt(by) * BigInt(cx));
}
// Labels stay inside the canvas whatever the frame's shape.
function label(text, x, y, align = 'left') {
    const w = ctx.measureText(text).width, left = align === 'right' ? x - w : x;
    ctx.fillText(text, Math.min(Math.max(left, 4), canvas.width - 4 - w), y);
}

function drawPattern(p, trail) {
    ctx.fillStyle = 'white';
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    const x = (i) => toX(p.uv[2 * i] / p.one, p.uv[2 * i + 1] / p.one), y = (i) => toY(p.uv[2 * i + 1] / p.one);
    let zero = 0;
    ctx.lineJoin = 'round';
    for (let t = 0; t < p.triangles; t++) {
        const [a, b, c] = [p.indices[3 * t], p.indices[3 * t + 1], p.indices[3 * t + 2]];
        ctx.beginPath();
        ctx.moveTo(x(a), y(a));
        ctx.lineTo(x(b), y(b));
        ctx.lineTo(x(c), y(c));
        ctx.closePath();
        if (doubledArea(p.uv, a, b, c, p.one) === 0) {
            zero++;
            ctx.strokeStyle = '#d62728';
            ctx.lineWidth = 1.6;
        } else {
            ctx.fillStyle = t % 2 ? '#dbe7f4' : '#eaf1f9';
            ctx.fill();
            ctx.strokeStyle = '#27445f';
            ctx.lineWidth = 0.8;
        }
        ctx.stroke();
    }
    ctx.fillStyle = '#9a7fd1';
    for (const [u, v] of trail) ctx.fillRect(toX(u, v) - 1, toY(v) - 1, 2, 2);
    const dotR = p.vertices > 2000 ? 0.9 : p.vertices > 300 ? 1.6 : 2.4;
    ctx.fillStyle = '#e07b00';
    if (p.triangles < 20000)
        for (let t = 0; t < p.triangles; t++) {
            const [a, b, c] = [p.indices[3 * t], p.indices[3 * t + 1], p.indices[3 * t + 2]];
            const cx = (x(a) + x(b) + x(c)) / 3, cy = (y(a) + y(b) + y(c)) / 3;
            ctx.beginPath();
            ctx.arc(0.65 * x(a) + 0.35 * cx, 0.65 * y(a) + 0.35 * cy, dotR * 0.9, 0, 2 * Math.PI);
            ctx.fill();
        }
    ctx.fillStyle = '#1b2838';
    for (let i = 0; i < p.vertices; i++) {
        ctx.beginPath();
        ctx.arc(x(i), y(i), dotR, 0, 2 * Math.PI);
        ctx.fill();
    }
    ctx.font = '15px DejaVu Sans, sans-serif';
    const cp = !state.mode.startsWith('d3d11'); // CP's names for CP and uniform, as in the CLI's SVGs
    // uniform: the integer the factor rounds to, where it differs
    const f = (k) => String(Number(state.factors[k].toPrecision(7))) +
                     (p.sides && p.sides[k] !== state.factors[k] ? ` → ${p.sides[k]}` : '');
    if (state.domain === 'quad') {
        const corner = cp ? ['q0', 'q1', 'q2', 'q3'] : ['(0,0)', 'u = 1', '(1,1)', 'v = 1'];
        ctx.fillText(corner[0], toX(0, 0) - 26, toY(0) + 18);
        ctx.fillText(corner[1], toX(1, 0) + 6, toY(0) + 18);
        ctx.fillText(corner[2], toX(1, 1) + 6, toY(1) - 6);
        ctx.fillText(corner[3], toX(0, 1) - 26, toY(1) - 6);
        ctx.fillStyle = '#2a6f3a';
        ctx.font = 'bold 14px DejaVu Sans, sans-serif';
        ctx.fillText(`f0 = ${f(0)}`, toX(0.5, 0) - 30, toY(0) + 34);
        ctx.fillText(`f2 = ${f(2)}`, toX(0.5, 1) - 30, toY(1) - 12);
        ctx.save();
        ctx.translate(toX(1, 0.5) + 16, toY(0.5) - 24);
        ctx.rotate(Math.PI / 2);
        ctx.fillText(`f1 = ${f(1)}`, 0, 0);
        ctx.restore();
        ctx.save();
        ctx.translate(toX(0, 0.5) - 16, toY(0.5) + 24);
        ctx.rotate(-Math.PI / 2);
        ctx.fillText(`f3 = ${f(3)}`, 0, 0);
        ctx.restore();
        return zero;
    }
    ctx.fillText(cp ? 'v0' : 'W', toX(0, 0) - 26, toY(0) + 18);
    ctx.fillText(cp ? 'v1' : 'U', toX(1, 0) + 8, toY(0) + 18);
    ctx.fillText(cp ? 'v2' : 'V', toX(0, 1) - 8, toY(1) - 10);
    // Edge labels as in the SVGs: CP e0 = v0v1 (bottom), e1 = v1v2, e2 = v2v0; D3D11 Veq0 bottom, Ueq0 left, Weq0 right.
    ctx.fillStyle = '#2a6f3a';
    ctx.font = 'bold 14px DejaVu Sans, sans-serif';
    label(cp ? `e0 = ${f(0)}` : `Veq0 = ${f(1)}`, toX(0.5, 0) - 40, toY(0) + 34);
    label(cp ? `e1 = ${f(1)}` : `Weq0 = ${f(2)}`, toX(0.5, 0.5) + 14, toY(0.5));
    label(cp ? `e2 = ${f(2)}` : `Ueq0 = ${f(0)}`, toX(0, 0.5) - 14, toY(0.5), 'right');
    return zero;
}

const SOURCE_NAMES = { wgsl: 'the generated WGSL on WebGPU', api: 'ctess serve (/api/pattern)' };

// ---- redraw loop: the latest state wins; window.ctessViewer is set after every redraw ----
let busy = false, pending = false;
async function redraw() {
    if (!device) return; // controls moved before WebGPU is up: the first redraw uses the latest state
    if (busy) { pending = true; return; }
    busy = true;
    try {
        do {
            pending = false;
            if (state.view === 'pattern') await redrawPattern();
            else {
                const m = await meshView.redraw(state.max);
                const name = (mode) => (mode === 'uniform' ? `uniform density, factors clamped to [1, ${m.uniformMax}]`
                                        : mode === 'uniform-split' ? `uniform density, split above ${m.uniformMax}`
                                        : mode.startsWith('d3d11') ? mode : 'CP');
                setStatus(`mesh · ${m.model ? m.model.name : m.mesh} · ${name(m.mode)}${m.compare ? ` | ${name(m.compare.mode)}` : ''} · ` +
                          `${m.surface}${m.displacement ? ' displaced' : ''} · DiceRate ${m.diceRate} px · max ${m.max} · computed by the generated WGSL on WebGPU`);
                syncUrl();
            }
        } while (pending);
    } catch (e) {
        setStatus(`Error: ${e.message}`, true);
        console.error(e);
    } finally {
        busy = false;
    }
}

async function redrawPattern() {
    const { mode, max, domain } = state;
    const factors = state.factors.slice();
    const t0 = performance.now();
    const p = await computePattern(mode, factors, max);
    const t1 = performance.now();
    let ratio = null;
    try {
        const even = await apiPattern('d3d11-even', factors);
        ratio = p.triangles / even.triangle_count;
    } catch { /* no /api/pattern (page opened without ctess serve): no ratio */ }
    // The trail keeps domain positions, drawn in the current frame (a uniform frame changes with the factors).
    if (state.sweep) {
        for (let i = 0; i < p.vertices; i++) state.trail.push([p.uv[2 * i] / p.one, p.uv[2 * i + 1] / p.one]);
        if (state.trail.length > 400000) state.trail.splice(0, 200000);
    }
    frame = frameFor(domain, p.sides);
    const t2 = performance.now();
    const zero = drawPattern(p, state.trail ?? []);
    const ms = { compute: t1 - t0, ratio: t2 - t1, draw: performance.now() - t2 };
    $('count-vertices').textContent = p.vertices;
    $('count-triangles').textContent = p.triangles;
    $('count-zero').textContent = zero;
    $('count-ratio').textContent = ratio === null ? 'n/a (needs ctess serve)' : `${ratio.toFixed(3)}×`;
    $('count-source').textContent = { wgsl: 'WGSL on WebGPU', api: 'ctess serve' }[p.source];
    window.ctessViewer = {
        view: 'pattern', mode, domain, factors, max, source: p.source, vertices: p.vertices, triangles: p.triangles, zeroArea: zero,
        ratioToD3d11Even: ratio, ms, sides: p.sides, trail: state.trail,
        corners: (domain === 'quad' ? [[0, 0], [1, 0], [1, 1], [0, 1]] : [[0, 0], [1, 0], [0, 1]]).map(([u, v]) => [toX(u, v), toY(v)]),
        readback: { one: p.one, uv: Array.from(p.uv), indices: Array.from(p.indices) },
    };
    setStatus(`${mode} · ${domain} · factors ${factorText(factors)}` +
              (p.sides ? ` · integer factors ${p.sides.join(',')} (pops at each step)` : ` · max ${max}`) +
              (p.splitAbove ? ` · split above N = ${p.splitAbove}` : '') + ` · computed by ${SOURCE_NAMES[p.source]}`);
}

// ---- controls ----
function showFactors() {
    $('f3-label').hidden = state.domain !== 'quad';
    $('domain').value = state.domain;
    for (let k = 0; k < state.factors.length; k++) {
        $(`f${k}`).max = String(state.max);
        $(`f${k}`).value = String(state.factors[k]);
        $(`f${k}-value`).textContent = String(Number(state.factors[k].toPrecision(7)));
    }
    $('factors').value = factorText(state.factors);
    $('mode').value = state.mode;
    $('domain-quad').disabled = state.mode === 'uniform'; // the uniform family tessellates triangles only
    $('max').value = String(state.max);
}
function syncUrl() {
    const q = new URLSearchParams({ view: state.view, mode: state.mode, domain: state.domain, factors: factorText(state.factors), max: state.max });
    if (state.view === 'mesh') {
        q.set('mesh', $('mesh-kind').value);
        q.set('pattern', $('mesh-pattern').value);
        q.set('surface', $('surface').value);
        q.set('dice', $('dice').value);
        if ($('compare').checked) q.set('compare', $('compare-pattern').value);
        if (!$('wireframe').checked) q.set('wireframe', '0');
        if (meshView.cameraPinned && meshView.camera) {
            q.set('camera', meshView.camera.eye.join(','));
            q.set('target', meshView.camera.target.join(','));
        }
    }
    history.replaceState(null, '', `?${q}`);
}
function changed() {
    if (!state.sweep) state.trail = null;
    showFactors();
    syncUrl();
    redraw();
}
for (let k = 0; k < 4; k++)
    $(`f${k}`).addEventListener('input', (e) => {
        state.factors[k] = Math.fround(Number(e.target.value));
        changed();
    });
$('factors').addEventListener('change', (e) => {
    const f = parseFactors(e.target.value);
    if (!f) return setStatus(state.domain === 'quad' ? 'Factors: four numbers > 0, e.g. 12,5,12,30' : 'Factors: three numbers > 0, e.g. 10.3,6,3', true);
    state.factors = f;
    changed();
});
function setDomain(domain) {
    state.domain = domain;
    state.factors = state.domain === 'quad' ? [...state.factors.slice(0, 3), state.factors[0]] : state.factors.slice(0, 3);
    state.sweep = state.trail = null;
    $('play').textContent = 'play';
    $('sweep-from').value = state.domain === 'quad' ? '1,1,1,1' : '1,1,1';
    $('sweep-to').value = state.domain === 'quad' ? '8,8,8,8' : '8,8,8';
}
$('mode').addEventListener('change', (e) => {
    state.mode = e.target.value;
    if (state.mode === 'uniform' && state.domain === 'quad') setDomain('tri');
    changed();
});
$('domain').addEventListener('change', (e) => {
    setDomain(e.target.value);
    changed();
});
$('max').addEventListener('change', (e) => {
    state.max = Number(e.target.value);
    state.factors = state.factors.map((f) => Math.min(f, state.max));
    changed();
});
for (const radio of document.querySelectorAll('input[name=view]'))
    radio.addEventListener('change', (e) => {
        state.view = e.target.value;
        $('pattern-view').hidden = state.view !== 'pattern';
        $('mesh-view').hidden = state.view !== 'mesh';
        syncUrl();
        redraw();
    });

// Sweep: factors move from one triple to the other and back (4 s each way); every vertex position visited
// stays drawn (until the next change after a pause), so a point that moves leaves a path and a point that pops
// leaves a gap.
$('play').addEventListener('click', () => {
    if (state.sweep) {
        state.sweep = null;
        $('play').textContent = 'play';
        return;
    }
    const from = parseFactors($('sweep-from').value), to = parseFactors($('sweep-to').value);
    if (!from || !to) return setStatus(`Sweep: ${state.factors.length} numbers > 0 in each field`, true);
    state.sweep = { from, to, start: performance.now() };
    state.trail = [];
    $('play').textContent = 'pause';
    const step = async () => {
        if (!state.sweep) return;
        const s = state.sweep;
        const phase = ((performance.now() - s.start) / 4000) % 2, t = phase < 1 ? phase : 2 - phase;
        state.factors = s.from.map((a, k) => Math.fround(a + (s.to[k] - a) * t));
        showFactors();
        await redraw();
        requestAnimationFrame(step);
    };
    step();
});

const meshView = new MeshView({
    canvas: $('mesh-canvas'), canvasB: $('mesh-canvas-b'), compareFigure: $('compare-figure'), captionA: $('caption-a'),
    captionB: $('caption-b'), kind: $('mesh-kind'), kindModel: $('mesh-kind-model'), pattern: $('mesh-pattern'),
    compare: $('compare'), comparePattern: $('compare-pattern'), surface: $('surface'), dice: $('dice'),
    diceValue: $('dice-value'), wireframe: $('wireframe'), displace: $('displace'), displaceScale: $('displace-scale'),
    displaceOffset: $('displace-offset'), displaceAddress: $('displace-address'), displaceGrow: $('displace-grow'),
    displaceInfo: $('displace-info'), modelFile: $('model-file'),
    heightFile: $('height-file'), vectorFile: $('vector-file'), dropZone: $('drop-zone'), modelInfo: $('model-info'), patches: $('mesh-patches'),
    vertices: $('mesh-vertices'), triangles: $('mesh-triangles'), frameTime: $('frame-time'),
}, () => pipelineFor(state.max), redraw, setStatus);
// Automation (docs/viewer.md): the camera exactly (float32 eye and target, world units), and the checksums of a
// side's output buffers (0: the left canvas, 1: the side-by-side one), as `ctess mesh --stats` reports them.
window.ctessViewerSetCamera = (eye, target) => meshView.setCamera(eye, target);
window.ctessViewerChecksum = (side = 0) => meshView.checksum(side);

// ---- start ----
const numbers = (text, count) => {
    const v = (text ?? '').split(',').map(Number);
    return v.length === count && v.every(Number.isFinite) ? v : null;
};
if (MESH_NAMES.includes(query.get('mesh'))) $('mesh-kind').value = query.get('mesh');
if (['cp', 'uniform', 'uniform-split'].includes(query.get('pattern'))) $('mesh-pattern').value = query.get('pattern');
if (SURFACE_NAMES.includes(query.get('surface'))) $('surface').value = query.get('surface');
if (Number(query.get('dice')) > 0) $('dice').value = query.get('dice');
if (['cp', 'uniform', 'uniform-split'].includes(query.get('compare'))) {
    $('compare').checked = true;
    $('compare-pattern').value = query.get('compare');
}
if (query.get('wireframe') === '0') $('wireframe').checked = false;
if (numbers(query.get('camera'), 3)) meshView.setCamera(numbers(query.get('camera'), 3), numbers(query.get('target'), 3) ?? [0, 0, 0]);
for (const id of ['mesh-kind', 'mesh-pattern', 'surface', 'dice', 'compare', 'compare-pattern', 'wireframe'])
    $(id).addEventListener('change', syncUrl);
if (state.domain === 'quad') {
    $('sweep-from').value = '1,1,1,1';
    $('sweep-to').value = '8,8,8,8';
}
showFactors();
document.querySelector(`input[name=view][value=${state.view}]`).checked = true;
$('pattern-view').hidden = state.view !== 'pattern';
$('mesh-view').hidden = state.view !== 'mesh';
try {
    const opened = await openDevice();
    device = opened.device;
    device.lost.then((info) => setStatus(`WebGPU device lost: ${info.message}`, true));
    meshView.attach(device);
    await redraw();
} catch (e) {
    setStatus(`WebGPU is unavailable, so the viewer cannot run: ${e.message}`, true);
    window.ctessViewer = { error: e.message };
}
