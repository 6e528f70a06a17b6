// Mesh view: a built-in icosahedron/icosphere or quad torus, or the user's own model (.glb, .gltf, .obj, loaded
// by `ctess serve` through ctess::models exactly as `ctess mesh` loads and prepares it: /api/model), run through
// the whole generated pipeline with the CP or the uniform-density pattern (projected edge factors over a
// DiceRate; flat, PN, PN-AEN or Phong evaluation; optional displacement by an uploaded height map), drawn shaded
// with its wireframe under an orbit camera, optionally side by side with a second pattern (docs/viewer.md).
import { PATTERN_NAMES } from './ctess_gpu.js';

// The D3D11 patterns (`ctess mesh --pattern` names): no shader runs them, so `ctess serve`'s /api/tessellate
// computes them on the CPU for an uploaded model, exactly as `ctess mesh --stats` reports its `gpu` block.
const D3D11_PATTERNS = ['d3d11-even', 'd3d11-odd', 'd3d11-integer', 'd3d11-pow2'];

const DEFAULT_FOV_DEGREES = 45;
// The meshes below: position xyz, normal xyz, uv per vertex (checked against the pipeline's MESH_VERTEX_FLOATS).
const MESH_VERTEX_FLOATS = 8;
export const SURFACE_NAMES = ['flat', 'pn', 'pn-aen', 'phong'];

// Icosahedron (counter-clockwise seen from outside), optionally split once (each triangle into four).
function icosphere(levels) {
    const t = (1 + Math.sqrt(5)) / 2;
    let p = [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t], [0, -1, -t], [0, 1, -t],
             [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]];
    let f = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2],
             [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11],
             [6, 2, 10], [8, 6, 7], [9, 8, 1]];
    for (let l = 0; l < levels; l++) {
        const mid = new Map(), next = [];
        const m = (a, b) => {
            const key = a < b ? `${a},${b}` : `${b},${a}`;
            if (!mid.has(key)) { mid.set(key, p.length); p.push(p[a].map((x, k) => (x + p[b][k]) / 2)); }
            return mid.get(key);
        };
        for (const [a, b, c] of f) {
            const ab = m(a, b), bc = m(b, c), ca = m(c, a);
            next.push([a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]);
        }
        f = next;
    }
    const vertices = new Float32Array(p.length * MESH_VERTEX_FLOATS);
    p.forEach((q, i) => {
        const n = Math.hypot(...q), u = q.map((x) => x / n);
        vertices.set([u[0], u[1], u[2], u[0], u[1], u[2], 0.5 + Math.atan2(u[2], u[0]) / (2 * Math.PI), 0.5 - Math.asin(u[1]) / Math.PI], i * MESH_VERTEX_FLOATS);
    });
    return { vertices, triangles: new Uint32Array(f.flat()), quads: new Uint32Array(0) };
}

// A torus (major radius 1, minor 0.4) of 12 x 8 quads q0 q1 q2 q3 (counter-clockwise seen from outside), with
// the smooth surface's normals: quad patches on the GPU (docs/shaders.md, "Quads"; docs/algorithm.md §7.2-7.3).
// Vertices are shared across the seams (the factors are per edge of the indexed mesh); uv is (i / 12, j / 8).
const TORUS = { major: 1, minor: 0.4, around: 12, across: 8 };
function torus({ major, minor, around, across }) {
    const vertices = new Float32Array(around * across * MESH_VERTEX_FLOATS);
    const at = (i, j) => (i % around) * across + (j % across);
    for (let i = 0; i < around; i++) {
        for (let j = 0; j < across; j++) {
            const u = (2 * Math.PI * i) / around, v = (2 * Math.PI * j) / across;
            const n = [Math.cos(v) * Math.cos(u), Math.sin(v), Math.cos(v) * Math.sin(u)];
            vertices.set([major * Math.cos(u) + minor * n[0], minor * n[1], major * Math.sin(u) + minor * n[2], ...n,
                          i / around, j / across], at(i, j) * MESH_VERTEX_FLOATS);
        }
    }
    const quads = [];
    for (let i = 0; i < around; i++)
        for (let j = 0; j < across; j++) quads.push(at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j));
    return { vertices, triangles: new Uint32Array(0), quads: new Uint32Array(quads) };
}
const MESHES = { ico0: () => icosphere(0), ico1: () => icosphere(1), torus: () => torus(TORUS) };
export const MESH_NAMES = Object.keys(MESHES);

// `ctess serve`'s upload answers (tools/ctess/model_upload.hpp): "CTMD", version 1, the JSON header's length,
// the header, then little-endian 32-bit sections at the offsets the header gives.
export function parseContainer(buffer) {
    const bytes = new Uint8Array(buffer);
    if (bytes.length < 12 || String.fromCharCode(...bytes.subarray(0, 4)) !== 'CTMD')
        throw new Error('the server answered something other than a ctess container');
    const view = new DataView(buffer);
    if (view.getUint32(4, true) !== 1) throw new Error(`container version ${view.getUint32(4, true)}, this viewer reads 1`);
    const headerBytes = view.getUint32(8, true);
    const header = JSON.parse(new TextDecoder().decode(bytes.subarray(12, 12 + headerBytes)));
    const sections = {};
    for (const s of header.sections) {
        if (s.offset % 4 || s.offset + 4 * s.count > buffer.byteLength) throw new Error(`container section ${s.name} lies outside the answer`);
        sections[s.name] = new (s.type === 'f32' ? Float32Array : Uint32Array)(buffer, s.offset, s.count);
    }
    return { header, sections };
}

// The server's upload limit: ServeLimits::max_upload_body in tools/ctess/serve_loop.hpp (docs/cli.md). A
// larger body is refused from its head and the connection closed, which fetch reports as a network error.
const MAX_UPLOAD_BYTES = 64 * 1024 * 1024;

// POSTs a file to /api/model or /api/height-map; the server's {"error": ...} becomes the thrown message.
async function upload(endpoint, file) {
    if (file.size > MAX_UPLOAD_BYTES) {
        const mib = (file.size / (1024 * 1024)).toFixed(1);
        throw new Error(`${file.name}: ${mib} MiB, past ctess serve's upload limit of 64 MiB`);
    }
    let r;
    try {
        r = await fetch(`api/${endpoint}?name=${encodeURIComponent(file.name)}`, { method: 'POST', body: file });
    } catch {
        throw new Error(`${file.name}: models are loaded by \`ctess serve\`, which did not answer`);
    }
    if (!r.ok) {
        const text = await r.text();
        let message = `HTTP ${r.status}`;
        try { message = JSON.parse(text).error ?? message; } catch { message = `${message}: ${text.trim()}`; }
        throw new Error(message);
    }
    return parseContainer(await r.arrayBuffer());
}

// `ctess mesh --displace-grow`'s bound, rt::displacement_bound for a height map (docs/algorithm.md §8.4): the
// larger |scale · (texel · factor + offset)| at the map's smallest and largest texel, in float32 operation by
// operation as the runtime computes it (no contraction), so that the grown factors are the CLI's.
function heightBound(map, scale, offset) {
    if (!Number.isFinite(map.texelMin) || !Number.isFinite(map.texelMax))
        throw new Error(`${map.name}: no finite texel range, so no displacement bound to grow factors by`);
    const f = Math.fround;
    const at = (texel) => Math.abs(f(scale * f(f(texel * map.factor) + offset)));
    const lo = at(map.texelMin), hi = at(map.texelMax);
    return lo > hi ? lo : hi;
}

// The same for a vector map (§8.7): the longest texel vector, each component in float32, the length in double
// and rounded to float32 once, as rt::displacement_bound computes it.
function vectorBound(map, scale, offset) {
    const f = Math.fround, t = map.texels;
    let bound = 0;
    for (let i = 0; i + 2 < t.length; i += 3) {
        const [x, y, z] = [t[i], t[i + 1], t[i + 2]].map((c) => f(scale * f(f(c * map.factor) + offset)));
        const length = Math.sqrt(x * x + y * y + z * z);
        if (length > bound) bound = length; // NaN compares false: skipped
    }
    return f(bound);
}

// The model as the pipeline takes it, and the box the camera frames.
function withBounds(mesh) {
    const v = mesh.vertices, n = v.length / MESH_VERTEX_FLOATS;
    const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < n; i++)
        for (let k = 0; k < 3; k++) {
            lo[k] = Math.min(lo[k], v[i * MESH_VERTEX_FLOATS + k]);
            hi[k] = Math.max(hi[k], v[i * MESH_VERTEX_FLOATS + k]);
        }
    const center = lo.map((x, k) => (x + hi[k]) / 2);
    const radius = Math.max(1e-6, Math.hypot(...hi.map((x, k) => x - lo[k])) / 2);
    return { ...mesh, patches: mesh.triangles.length / 3 + mesh.quads.length / 4, center, radius };
}

function mul(a, b) { // column-major 4x4
    const r = new Float32Array(16);
    for (let c = 0; c < 4; c++) for (let rI = 0; rI < 4; rI++)
        for (let k = 0; k < 4; k++) r[c * 4 + rI] += a[k * 4 + rI] * b[c * 4 + k];
    return r;
}
function perspective(fovY, aspect, near, far) {
    const f = 1 / Math.tan(fovY / 2), r = new Float32Array(16);
    r[0] = f / aspect; r[5] = f; r[10] = far / (near - far); r[11] = -1; r[14] = (near * far) / (near - far);
    return r;
}
const sub = (a, b) => a.map((x, k) => x - b[k]);
function lookAt(eye, target) {
    const norm = (v) => { const l = Math.hypot(...v); return v.map((x) => x / l); };
    const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    const z = norm(sub(eye, target));
    const x = norm(Math.abs(z[1]) > 0.999 ? cross([0, 0, 1], z) : cross([0, 1, 0], z)), y = cross(z, x);
    const d = (a) => -(a[0] * eye[0] + a[1] * eye[1] + a[2] * eye[2]);
    return new Float32Array([x[0], y[0], z[0], 0, x[1], y[1], z[1], 0, x[2], y[2], z[2], 0, d(x), d(y), d(z), 1]);
}

// The pipeline's output vertex layout (VERTEX_WORDS, VERTEX_POSITION, VERTEX_NORMAL) is the generated module's
// (its layout.json constants, docs/shaders.md), prefixed to the render shader. cam.light.w turns the wireframe on.
const renderWgsl = (C) => ['VERTEX_WORDS', 'VERTEX_POSITION', 'VERTEX_NORMAL'].map((k) => `const ${k}: u32 = ${C[k]}u;`).join('\n') + `
struct Camera { view_proj: mat4x4<f32>, light: vec4<f32> }
@group(0) @binding(0) var<uniform> cam: Camera;
@group(0) @binding(1) var<storage, read> verts: array<f32>;
@group(0) @binding(2) var<storage, read> tris: array<u32>;
struct VOut { @builtin(position) pos: vec4<f32>, @location(0) normal: vec3<f32>, @location(1) bary: vec3<f32> }
@vertex fn vs(@builtin(vertex_index) vi: u32) -> VOut {
    let o = tris[vi] * VERTEX_WORDS;
    var b = vec3<f32>(0.0);
    b[vi % 3u] = 1.0;
    let p = vec3<f32>(verts[o + VERTEX_POSITION], verts[o + VERTEX_POSITION + 1u], verts[o + VERTEX_POSITION + 2u]);
    let n = vec3<f32>(verts[o + VERTEX_NORMAL], verts[o + VERTEX_NORMAL + 1u], verts[o + VERTEX_NORMAL + 2u]);
    return VOut(cam.view_proj * vec4<f32>(p, 1.0), n, b);
}
@fragment fn fs(in: VOut, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    let w = fwidth(in.bary);
    let a = smoothstep(vec3<f32>(0.0), 1.2 * w, in.bary);
    let edge = (1.0 - min(min(a.x, a.y), a.z)) * cam.light.w;
    var n = normalize(in.normal);
    if (!front) { n = -n; }
    let lit = 0.25 + 0.75 * max(dot(n, normalize(cam.light.xyz)), 0.0);
    return vec4<f32>(mix(vec3<f32>(0.55, 0.7, 0.9) * lit, vec3<f32>(0.08, 0.12, 0.2), edge), 1.0);
}`;

// FNV-1a (32 bits) over the little-endian bytes of 32-bit words, as `ctess mesh --stats` computes its `gpu`
// checksums (docs/cli.md, "Models").
export function fnv1a(hash, words, stride = 1, offsets = [0]) {
    for (let i = 0; i + stride <= words.length; i += stride)
        for (const o of offsets) {
            const w = words[i + o];
            for (let b = 0; b < 32; b += 8) hash = Math.imul(hash ^ ((w >>> b) & 255), 16777619) >>> 0;
        }
    return hash;
}
const FNV_BASIS = 2166136261;
const CHECKSUM_EVERY_FRAME = 1 << 22; // output vertices + triangles of one side
const hex = (h) => h.toString(16).padStart(8, '0');

// One canvas: its WebGPU context, depth buffer, camera uniform and the output buffers it last drew.
class Target {
    constructor(canvas) {
        this.canvas = canvas;
    }

    attach(device, format) {
        this.context = this.canvas.getContext('webgpu');
        this.context.configure({ device, format, alphaMode: 'opaque' });
        this.depth = device.createTexture({ size: [this.canvas.width, this.canvas.height], format: 'depth24plus', usage: GPUTextureUsage.RENDER_ATTACHMENT });
        this.uniform = device.createBuffer({ size: 80, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });
    }

    // The buffers of the previous draw are kept until the next one, so checksum() can read them on request.
    replace(out) {
        this.out?.vertices?.destroy();
        this.out?.indices?.destroy();
        this.out = out;
    }
}

export class MeshView {
    constructor(ui, pipelineFor, redraw, setStatus) {
        Object.assign(this, { ui, pipelineFor, requestRedraw: redraw, setStatus });
        this.targets = [new Target(ui.canvas), new Target(ui.canvasB)];
        this.model = null; // the uploaded model (withBounds), once loaded
        this.heightMap = null; // {name, width, height, texels, texelMin, texelMax, factor, fromModel}
        this.camera = null; // {eye, target}: set from the mesh's bounds when null
        this.cameraFor = null; // the mesh the camera was framed for
        this.passSetsSeen = new Set(); // max factor, patterns, displaced, quads: the pass sets drawn so far
        this.cameraPinned = false; // set exactly (setCamera, ?camera=): kept across meshes until the user moves it
        this.fovDegrees = DEFAULT_FOV_DEGREES;
        this.meshCache = new Map();
        for (const canvas of [ui.canvas, ui.canvasB]) this.listenCamera(canvas);
        for (const el of [ui.kind, ui.surface, ui.dice, ui.pattern, ui.compare, ui.comparePattern, ui.wireframe, ui.displace,
                          ui.displaceScale, ui.displaceOffset, ui.displaceAddress, ui.displaceGrow])
            el.addEventListener('input', () => redraw());
        ui.modelFile.addEventListener('change', () => ui.modelFile.files[0] && this.loadModel(ui.modelFile.files[0]));
        ui.heightFile.addEventListener('change', () => ui.heightFile.files[0] && this.loadHeightMap(ui.heightFile.files[0]));
        ui.vectorFile.addEventListener('change', () => ui.vectorFile.files[0] && this.loadHeightMap(ui.vectorFile.files[0], true));
        for (const zone of [ui.dropZone, ui.canvas, ui.canvasB]) {
            zone.addEventListener('dragover', (e) => { e.preventDefault(); zone.classList.add('dragging'); });
            zone.addEventListener('dragleave', () => zone.classList.remove('dragging'));
            zone.addEventListener('drop', (e) => {
                e.preventDefault();
                zone.classList.remove('dragging');
                for (const file of e.dataTransfer.files) {
                    if (/\.(png|exr)$/i.test(file.name) || file.type === 'image/png') this.loadHeightMap(file);
                    else this.loadModel(file);
                }
            });
        }
    }

    // Orbit (drag) and dolly (wheel) around the camera's target; the eye is the state, so a camera set exactly
    // (setCamera, ?camera=) stays exact until the user moves it.
    listenCamera(canvas) {
        let drag = null;
        canvas.addEventListener('pointerdown', (e) => { drag = [e.clientX, e.clientY]; canvas.setPointerCapture(e.pointerId); });
        canvas.addEventListener('pointerup', () => { drag = null; });
        canvas.addEventListener('pointermove', (e) => {
            if (!drag || !this.camera) return;
            const { yaw, pitch, distance } = this.orbit();
            this.cameraPinned = false;
            this.setOrbit(yaw - (e.clientX - drag[0]) * 0.01, Math.max(-1.5, Math.min(1.5, pitch + (e.clientY - drag[1]) * 0.01)), distance);
            drag = [e.clientX, e.clientY];
            this.requestRedraw();
        });
        canvas.addEventListener('wheel', (e) => {
            e.preventDefault();
            if (!this.camera) return;
            const { yaw, pitch, distance } = this.orbit(), r = this.radius ?? 1;
            this.cameraPinned = false;
            this.setOrbit(yaw, pitch, Math.max(0.3 * r, Math.min(60 * r, distance * Math.exp(e.deltaY * 0.001))));
            this.requestRedraw();
        }, { passive: false });
    }

    orbit() {
        const d = sub(this.camera.eye, this.camera.target), distance = Math.hypot(...d);
        return { yaw: Math.atan2(d[0], d[2]), pitch: Math.asin(Math.max(-1, Math.min(1, d[1] / distance))), distance };
    }

    setOrbit(yaw, pitch, distance) {
        const t = this.camera.target;
        this.camera.eye = [t[0] + distance * Math.cos(pitch) * Math.sin(yaw), t[1] + distance * Math.sin(pitch),
                           t[2] + distance * Math.cos(pitch) * Math.cos(yaw)].map(Math.fround);
    }

    // The automation hook (docs/viewer.md): the eye (and optionally the target) exactly, as float32 values.
    setCamera(eye, target) {
        this.camera = { eye: eye.map(Math.fround), target: (target ?? this.camera?.target ?? [0, 0, 0]).map(Math.fround) };
        this.cameraPinned = true;
        this.requestRedraw();
    }

    attach(device) {
        this.device = device;
        this.format = navigator.gpu.getPreferredCanvasFormat();
        for (const t of this.targets) t.attach(device, this.format);
        this.render = null; // made on the first redraw, from the pipeline's vertex layout
    }

    async loadModel(file) {
        try {
            this.setStatus(`Loading ${file.name} through ctess serve…`);
            const { header, sections } = await upload('model', file);
            this.model = withBounds({ name: header.name, header, vertices: sections.vertices, triangles: sections.triangles,
                                      quads: sections.quads, adjacency: sections.adjacency, directions: sections.directions,
                                      tangents: sections.tangents?.length ? sections.tangents : null,
                                      positionIds: sections.position_ids });
            this.ui.kindModel.disabled = false;
            this.ui.kindModel.textContent = `${header.name} (${header.triangle_count} triangles, ${header.quad_count} quads)`;
            this.ui.modelInfo.textContent = `${header.name}: ${header.vertex_count} vertices, ${header.triangle_count} triangles, ` +
                `${header.quad_count} quads, ${header.open_edges} open edges` +
                (header.dropped_degenerate_faces ? `, ${header.dropped_degenerate_faces} degenerate faces dropped` : '') +
                (header.has_normals ? '' : ' (no normals in the file: zeros, so PN and Phong are flat)');
            this.useModelDisplacement(header, sections.displacement_texels);
            this.ui.kind.value = 'model';
            if (!this.cameraPinned) this.camera = null; // frame the new model
            this.ui.kind.dispatchEvent(new Event('change'));
            this.requestRedraw();
        } catch (e) {
            this.setStatus(`Model: ${e.message}`, true);
            window.ctessViewer = { ...(window.ctessViewer ?? {}), uploadError: e.message };
        }
    }

    // A height map, or with `vector` an RGB vector map in tangent space (`ctess mesh --displace-vector`,
    // docs/algorithm.md §8.7).
    async loadHeightMap(file, vector = false) {
        try {
            this.setStatus(`Loading ${file.name} through ctess serve…`);
            const { header, sections } = await upload(vector ? 'vector-map' : 'height-map', file);
            this.setHeightMap({ name: header.name, width: header.width, height: header.height, texels: sections.texels,
                                texelMin: header.texel_min, texelMax: header.texel_max, factor: 1, fromModel: false, vector, id: header.id });
            this.requestRedraw();
        } catch (e) {
            this.setStatus(`Height map: ${e.message}`, true);
            window.ctessViewer = { ...(window.ctessViewer ?? {}), uploadError: e.message };
        }
    }

    setHeightMap(map) {
        this.heightMap = map;
        this.ui.displace.disabled = !map;
        this.ui.displace.checked = !!map;
        this.ui.displaceInfo.textContent = map ? `${map.name}: ${map.width} × ${map.height}` +
            (map.fromModel ? `, the model's KHR_materials_displacement (factor ${map.factor})` : '') +
            (map.vector ? ', an RGB vector map in the tangent frame' : '') : '';
    }

    // The model's own KHR_materials_displacement image, as `ctess mesh --displace-gltf` takes it: its factor,
    // and its offset typed into the offset field (the CLI's default for --displace-offset). A model without
    // one leaves an uploaded height map in place and drops the previous model's.
    useModelDisplacement(header, texels) {
        const d = header.displacement;
        if (d && d.width > 0 && texels) {
            this.setHeightMap({ name: `${header.name} (embedded displacement image)`, width: d.width, height: d.height, texels,
                                texelMin: d.texel_min, texelMax: d.texel_max, factor: Math.fround(d.factor), fromModel: true });
            this.ui.displaceOffset.value = String(d.offset);
        } else if (this.heightMap?.fromModel) {
            this.setHeightMap(null);
        }
        if (d?.image_error) this.setStatus(`Displacement image: ${d.image_error}`, true);
        else if (d && !d.embedded_image)
            this.setStatus(`${header.name}: the displacement image${d.image_uri ? ` ${d.image_uri}` : ''} is not in the file; upload it as a height map`, true);
    }

    mesh(kind) {
        if (kind === 'model' && this.model) return this.model;
        const name = MESHES[kind] ? kind : 'ico0';
        if (!this.meshCache.has(name)) this.meshCache.set(name, withBounds({ name, ...MESHES[name]() }));
        return this.meshCache.get(name);
    }

    // A D3D11 side: `ctess serve` tessellates the held model on the CPU (/api/tessellate, docs/cli.md "Viewer
    // server") with the page's camera and options, and the output goes into buffers shaped as the GPU's.
    async serverOutput(pipeline, mesh, pattern, settings, canvas) {
        if (!mesh.header?.id) throw new Error(`${pattern}: the D3D11 patterns are computed by ctess serve for an uploaded model`);
        const { surface, dice, eye, displacement: d } = settings;
        const query = new URLSearchParams({ model: mesh.header.id, pattern, surface, 'dice-rate': String(Math.fround(dice)),
                                            camera: eye.map(String).join(','), fov: String(this.fovDegrees),
                                            resolution: `${canvas.width},${canvas.height}` });
        if (d) {
            query.set('displace', d.fromModel ? 'model' : 'map');
            if (!d.fromModel) query.set('map', d.mapId);
            for (const [key, value] of [['displace-scale', d.params.scale], ['displace-offset', d.params.offset],
                                        ['displace-address', d.params.address], ['displace-grow', d.grow ? 1 : 0]])
                query.set(key, String(value));
        }
        const started = performance.now();
        const r = await fetch(`api/tessellate?${query}`);
        if (!r.ok) {
            let message = `HTTP ${r.status}`;
            try { message = (await r.json()).error ?? message; } catch { /* keep the status */ }
            throw new Error(`${pattern}: ${message}`);
        }
        const { header, sections } = parseContainer(await r.arrayBuffer());
        const buffer = (words) => {
            const b = this.device.createBuffer({ size: Math.max(16, words.byteLength),
                                                 usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC | GPUBufferUsage.COPY_DST });
            this.device.queue.writeBuffer(b, 0, words);
            return b;
        };
        const patches = new Uint32Array(sections.records.length + pipeline.constants.TOTALS_WORDS);
        patches.set(sections.records);
        return { vertices: buffer(sections.vertices), indices: buffer(sections.indices), vertexCount: header.vertices,
                 triangleCount: header.triangles, patches, milliseconds: performance.now() - started };
    }

    // A CP or uniform side: the generated WGSL's passes on the mesh (ctess_webgpu.mjs).
    gpuOutput(pipeline, mesh, pattern, settings, factorScale) {
        const { surface, eye, displacement } = settings;
        // PN-AEN reads the adjacency after the indices, and displacement its dominant edges and corners; the
        // built-in meshes have none (PN-AEN is then PN with every edge a boundary).
        const adjacency = mesh.adjacency && (surface === 'pn-aen' || displacement) ? mesh.adjacency : null;
        const indices = new Uint32Array(mesh.triangles.length + mesh.quads.length + (adjacency?.length ?? 0));
        indices.set(mesh.triangles);
        indices.set(mesh.quads, mesh.triangles.length);
        if (adjacency) indices.set(adjacency, mesh.triangles.length + mesh.quads.length);
        const params = pipeline.params({ patchCount: mesh.patches, quadCount: mesh.quads.length / 4, surface, alpha: 1, factorScale, eye,
                                         meshVertexCount: mesh.vertices.length / MESH_VERTEX_FLOATS, pattern,
                                         displacement: displacement && { ...displacement.params, directions: !!mesh.directions, adjacency: !!adjacency,
                                                                         vector: displacement.vector } });
        return pipeline.run(params, mesh.vertices, indices, false, 0,
                            displacement ? { texels: displacement.texels, directions: mesh.directions ?? undefined,
                                             tangents: displacement.vector ? mesh.tangents : undefined } : {});
    }

    // One side: the pipeline on the mesh with the pattern, then the draw. Resolves to its counts and timings.
    async drawSide(target, pipeline, mesh, pattern, settings) {
        const { dice, eye, viewProj, wireframe } = settings;
        const projectionScale = Math.fround(target.canvas.height / (2 * Math.tan((this.fovDegrees * Math.PI) / 360)));
        const factorScale = Math.fround(projectionScale / Math.fround(dice));
        const out = D3D11_PATTERNS.includes(pattern) ? await this.serverOutput(pipeline, mesh, pattern, settings, target.canvas)
                                                     : await this.gpuOutput(pipeline, mesh, pattern, settings, factorScale);
        target.replace(out);
        const u = new Float32Array(20);
        u.set(viewProj);
        u.set([eye[0] - settings.target[0] + 1, eye[1] - settings.target[1] + 2, eye[2] - settings.target[2], wireframe ? 1 : 0], 16);
        this.device.queue.writeBuffer(target.uniform, 0, u);
        const bind = this.device.createBindGroup({
            layout: this.render.getBindGroupLayout(0),
            entries: [{ binding: 0, resource: { buffer: target.uniform } }, { binding: 1, resource: { buffer: out.vertices } },
                      { binding: 2, resource: { buffer: out.indices } }],
        });
        const enc = this.device.createCommandEncoder();
        const pass = enc.beginRenderPass({
            colorAttachments: [{ view: target.context.getCurrentTexture().createView(), clearValue: [1, 1, 1, 1], loadOp: 'clear', storeOp: 'store' }],
            depthStencilAttachment: { view: target.depth.createView(), depthClearValue: 1, depthLoadOp: 'clear', depthStoreOp: 'store' },
        });
        pass.setPipeline(this.render);
        pass.setBindGroup(0, bind);
        pass.draw(out.triangleCount * 3);
        pass.end();
        this.device.queue.submit([enc.finish()]);
        return { mode: pattern, vertices: out.vertexCount, triangles: out.triangleCount, computeMs: out.milliseconds,
                 factorScaleBits: new Uint32Array(new Float32Array([factorScale]).buffer)[0] };
    }

    // Checksums of a side's last output, as `ctess mesh --stats` reports them under `gpu`: the patch records (48
    // words each, without the totals), each vertex's (u, v) and the indices.
    async checksum(side = 0) {
        const target = this.targets[side], out = target.out, pipeline = await this.lastPipeline;
        if (!out) return null;
        const C = pipeline.constants, n = out.patches.length - C.TOTALS_WORDS;
        const vertices = await pipeline.read(out.vertices, out.vertexCount * C.VERTEX_WORDS);
        const indices = await pipeline.read(out.indices, out.triangleCount * 3);
        return { records: hex(fnv1a(FNV_BASIS, out.patches.subarray(0, n))),
                 barycentrics: hex(fnv1a(FNV_BASIS, vertices, C.VERTEX_WORDS, [C.VERTEX_U, C.VERTEX_V])),
                 indices: hex(fnv1a(FNV_BASIS, indices)) };
    }

    async redraw(maxFactor) {
        let started = performance.now();
        const kind = this.ui.kind.value === 'model' && this.model ? 'model' : (MESHES[this.ui.kind.value] ? this.ui.kind.value : 'ico0');
        const mesh = this.mesh(kind);
        this.radius = mesh.radius;
        if (!this.camera || (this.cameraFor !== kind && !this.cameraPinned)) {
            // Frame the mesh: the built-in ones as before (distance 4 from the origin), a model at 2.5 radii.
            const target = kind === 'model' ? mesh.center : [0, 0, 0];
            this.camera = { eye: [0, 0, 0], target: target.map(Math.fround) };
            this.setOrbit(0.6, 0.35, kind === 'model' ? 2.5 * mesh.radius : 4);
            this.cameraFor = kind;
        }
        const { eye, target } = this.camera;
        const dice = Number(this.ui.dice.value);
        const surface = SURFACE_NAMES.includes(this.ui.surface.value) ? this.ui.surface.value : 'pn';
        const patterns = [this.ui.pattern.value, this.ui.comparePattern.value]
            .map((p) => (PATTERN_NAMES.includes(p) || D3D11_PATTERNS.includes(p) ? p : 'cp'));
        const compare = this.ui.compare.checked;
        this.ui.compareFigure.hidden = !compare;
        const pipeline = await this.pipelineFor();
        this.lastPipeline = Promise.resolve(pipeline);
        started = performance.now(); // the frame: both sides' passes (a pass's first use compiles it) and draws
        const C = pipeline.constants;
        if (C.MESH_VERTEX_FLOATS !== MESH_VERTEX_FLOATS)
            throw new Error(`the generated pipeline reads ${C.MESH_VERTEX_FLOATS} floats per mesh vertex, the viewer's meshes have ${MESH_VERTEX_FLOATS}`);
        if (!this.render) {
            const module = this.device.createShaderModule({ code: renderWgsl(C) });
            this.render = this.device.createRenderPipeline({
                layout: 'auto',
                vertex: { module, entryPoint: 'vs' },
                fragment: { module, entryPoint: 'fs', targets: [{ format: this.format }] },
                primitive: { topology: 'triangle-list', cullMode: 'none' },
                depthStencil: { format: 'depth24plus', depthWriteEnabled: true, depthCompare: 'less' },
            });
        }
        // Displacement (docs/shaders.md, "Displacement"): an uploaded height map (factor 1, as `ctess mesh
        // --displace FILE`) or the model's own image (its factor, as --displace-gltf), the scale and offset
        // typed (float32, as the CLI parses them).
        const h = this.heightMap, displaced = !!(h && this.ui.displace.checked);
        const [scale, offset] = [this.ui.displaceScale.value, this.ui.displaceOffset.value].map((x) => Math.fround(Number(x)));
        if (displaced && !(Number.isFinite(scale) && Number.isFinite(offset))) throw new Error('displacement: scale and offset must be finite numbers');
        // Vector mode's frame needs the model's tangents (its TANGENT or its uvs'); the built-in meshes have none.
        if (displaced && h.vector && !mesh.tangents)
            throw new Error(`vector displacement needs tangents: ${kind === 'model' ? 'the model has no uvs' : 'upload a model with uvs'}`);
        const grow = displaced && this.ui.displaceGrow.checked;
        const factorBound = grow ? (h.vector ? vectorBound(h, scale, offset) : heightBound(h, scale, offset)) : 0;
        const displacement = displaced ? { texels: h.texels, vector: !!h.vector, mapId: h.id, fromModel: !!h.fromModel, grow,
                                           params: { scale, factor: h.factor, offset, factorBound, width: h.width,
                                                     height: h.height, address: this.ui.displaceAddress.value } } : null;
        const near = Math.max(1e-4 * mesh.radius, Math.hypot(...sub(eye, target)) - 4 * mesh.radius);
        const far = Math.hypot(...sub(eye, target)) + 8 * mesh.radius;
        const canvas = this.targets[0].canvas;
        const fovY = (this.fovDegrees * Math.PI) / 180;
        const viewProj = mul(perspective(fovY, canvas.width / canvas.height, Math.max(near, 1e-3 * far), far), lookAt(eye, target));
        const settings = { surface, dice, eye, target, viewProj, displacement, wireframe: this.ui.wireframe.checked };
        const sides = [await this.drawSide(this.targets[0], pipeline, mesh, patterns[0], settings)];
        if (compare) sides.push(await this.drawSide(this.targets[1], pipeline, mesh, patterns[1], settings));
        else this.targets[1].replace(null);
        await this.device.queue.onSubmittedWorkDone();
        const frameMs = performance.now() - started;
        // The built-in meshes' output words, for the test's watertightness checks (docs/shaders.md's vertex records).
        let readback = null;
        if (kind !== 'model') {
            const out = this.targets[0].out;
            readback = { vertices: await pipeline.read(out.vertices, out.vertexCount * C.VERTEX_WORDS),
                         indices: await pipeline.read(out.indices, out.triangleCount * 3), records: out.patches };
        }
        // The checksums of every side's output (read back after the frame, outside its time), up to a size where
        // reading back each frame stays cheap; beyond it, ctessViewerChecksum() reads them on request.
        for (let k = 0; k < sides.length; k++)
            sides[k].checksum = sides[k].vertices + sides[k].triangles <= CHECKSUM_EVERY_FRAME ? await this.checksum(k) : null;
        const uniformMax = patterns.slice(0, sides.length).some((p) => p.startsWith('uniform')) ? (await pipeline.uniformTables()).maxFactor : null;
        this.ui.diceValue.textContent = `${dice} px`;
        this.ui.patches.textContent = mesh.patches;
        this.ui.vertices.textContent = sides.map((s) => s.vertices).join(' | ');
        this.ui.triangles.textContent = sides.map((s) => s.triangles).join(' | ');
        // A pass is compiled on its first use (ctess_webgpu.mjs): the frame that first runs a set of passes says so,
        // so that its time is not read as the steady frame time.
        const passSet = `${maxFactor}|${patterns.slice(0, sides.length).join(',')}|${displaced}|${mesh.quads.length > 0}`;
        const compiled = !this.passSetsSeen.has(passSet);
        this.passSetsSeen.add(passSet);
        const sideMs = (s) => `${D3D11_PATTERNS.includes(s.mode) ? 'ctess serve' : 'GPU passes'} ${s.computeMs.toFixed(1)} ms`;
        this.ui.frameTime.textContent = `${frameMs.toFixed(1)} ms (${sides.map(sideMs).join(' + ')})` +
            (compiled ? '; first draw with these passes, which compiles them' : '');
        const caption = (s) => `${s.mode === 'uniform' ? 'uniform density' : s.mode === 'uniform-split' ? 'uniform density, split above N'
                                   : D3D11_PATTERNS.includes(s.mode) ? `${s.mode} (ctess serve, CPU)` : 'CP'}: ` +
                               `${s.vertices} vertices, ${s.triangles} triangles`;
        this.ui.captionA.textContent = caption(sides[0]);
        this.ui.captionB.textContent = compare ? caption(sides[1]) : '';
        window.ctessViewer = {
            view: 'mesh', mode: patterns[0], uniformMax, max: maxFactor, mesh: kind, model: kind === 'model' ? this.model.header : null,
            patches: mesh.patches, quads: mesh.quads.length / 4, surface, diceRate: dice, camera: { eye: [...eye], target: [...target], fov: this.fovDegrees },
            resolution: [canvas.width, canvas.height], factorScaleBits: sides[0].factorScaleBits,
            displacement: displaced ? { scale, factor: h.factor, offset, factorBound, vector: !!h.vector, address: this.ui.displaceAddress.value,
                                        width: h.width, height: h.height, name: h.name, fromModel: h.fromModel } : null,
            wireframe: settings.wireframe, vertices: sides[0].vertices, triangles: sides[0].triangles, checksum: sides[0].checksum,
            compare: compare ? { mode: patterns[1], vertices: sides[1].vertices, triangles: sides[1].triangles, checksum: sides[1].checksum } : null,
            ms: { frame: frameMs, compute: sides.map((s) => s.computeMs) }, readback,
        };
        return window.ctessViewer;
    }
}
