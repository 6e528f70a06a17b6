// Mesh view: a built-in icosahedron/icosphere or quad torus run through the whole generated pipeline with the
// CP or the uniform-density pattern (projected edge factors over a DiceRate, PN or Phong evaluation), drawn
// shaded with its wireframe, under an orbit camera.
import { PATTERN_NAMES } from './ctess_gpu.js';

const FOV_Y = Math.PI / 4;
// The meshes below: position xyz, normal xyz, uv per vertex (checked against the pipeline's MESH_VERTEX_FLOATS).
const MESH_VERTEX_FLOATS = 8;

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
    return { vertices, indices: new Uint32Array(f.flat()), patches: f.length };
}

// A torus (major radius 1, minor 0.4) of 12 x 8 quads, with the smooth surface's normals. The pipeline takes
// triangles only, so each quad q0 q1 q2 q3 (counter-clockwise seen from outside) becomes (q0, q1, q3) and
// (q2, q3, q1), the halves of cp::split_quad: the diagonal q1q3 is one shared edge and gets one factor.
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
    const tris = [];
    for (let i = 0; i < around; i++) {
        for (let j = 0; j < across; j++) {
            const q = [at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)]; // counter-clockwise from outside
            tris.push([q[0], q[1], q[3]], [q[2], q[3], q[1]]);
        }
    }
    return { vertices, indices: new Uint32Array(tris.flat()), patches: tris.length };
}
const MESHES = { ico0: () => icosphere(0), ico1: () => icosphere(1), torus: () => torus(TORUS) };
export const MESH_NAMES = Object.keys(MESHES);

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
function lookAt(eye) {
    const norm = (v) => { const l = Math.hypot(...v); return v.map((x) => x / l); };
    const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    const z = norm(eye), x = norm(cross([0, 1, 0], z)), y = cross(z, x);
    const d = (a) => -(a[0] * eye[0] + a[1] * eye[1] + a[2] * eye[2]);
    return new Float32Array([x[0], y[0], z[0], 0, x[1], y[1], z[1], 0, x[2], y[2], z[2], 0, d(x), d(y), d(z), 1]);
}

// The pipeline's output vertex layout (VERTEX_WORDS, VERTEX_POSITION, VERTEX_NORMAL) is the generated module's
// (its layout.json constants, docs/shaders.md), prefixed to the render shader.
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
@fragment fn fs(in: VOut) -> @location(0) vec4<f32> {
    let w = fwidth(in.bary);
    let a = smoothstep(vec3<f32>(0.0), 1.2 * w, in.bary);
    let edge = 1.0 - min(min(a.x, a.y), a.z);
    let n = normalize(in.normal);
    let lit = 0.25 + 0.75 * max(dot(n, normalize(cam.light.xyz)), 0.0);
    return vec4<f32>(mix(vec3<f32>(0.55, 0.7, 0.9) * lit, vec3<f32>(0.08, 0.12, 0.2), edge), 1.0);
}`;

export class MeshView {
    constructor(canvas, ui, pipeline, redraw) {
        Object.assign(this, { canvas, ui, pipeline, requestRedraw: redraw });
        this.camera = { yaw: 0.6, pitch: 0.35, distance: 4 };
        let drag = null;
        canvas.addEventListener('pointerdown', (e) => { drag = [e.clientX, e.clientY]; canvas.setPointerCapture(e.pointerId); });
        canvas.addEventListener('pointerup', () => { drag = null; });
        canvas.addEventListener('pointermove', (e) => {
            if (!drag) return;
            this.camera.yaw -= (e.clientX - drag[0]) * 0.01;
            this.camera.pitch = Math.max(-1.5, Math.min(1.5, this.camera.pitch + (e.clientY - drag[1]) * 0.01));
            drag = [e.clientX, e.clientY];
            redraw();
        });
        canvas.addEventListener('wheel', (e) => {
            e.preventDefault();
            this.camera.distance = Math.max(1.3, Math.min(40, this.camera.distance * Math.exp(e.deltaY * 0.001)));
            redraw();
        }, { passive: false });
        for (const el of [ui.kind, ui.surface, ui.dice, ui.pattern]) el.addEventListener('input', () => redraw());
    }

    attach(device) {
        this.device = device;
        this.context = this.canvas.getContext('webgpu');
        this.format = navigator.gpu.getPreferredCanvasFormat();
        this.context.configure({ device, format: this.format, alphaMode: 'opaque' });
        this.render = null; // made on the first redraw, from the pipeline's vertex layout
        this.depth = device.createTexture({ size: [this.canvas.width, this.canvas.height], format: 'depth24plus', usage: GPUTextureUsage.RENDER_ATTACHMENT });
        this.uniform = device.createBuffer({ size: 80, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });
    }

    async redraw(maxFactor) {
        const kind = MESHES[this.ui.kind.value] ? this.ui.kind.value : 'ico0';
        const mesh = MESHES[kind]();
        const { yaw, pitch, distance } = this.camera;
        const eye = [distance * Math.cos(pitch) * Math.sin(yaw), distance * Math.sin(pitch), distance * Math.cos(pitch) * Math.cos(yaw)];
        const dice = Number(this.ui.dice.value);
        const projectionScale = this.canvas.height / (2 * Math.tan(FOV_Y / 2));
        const surface = Number(this.ui.surface.value);
        const pattern = PATTERN_NAMES.includes(this.ui.pattern.value) ? this.ui.pattern.value : 'cp';
        const pipeline = await this.pipeline();
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
        // The pattern word: uniform factors are rounded and clamped to [1, N] by the setup pass.
        const params = pipeline.params({ patchCount: mesh.patches, surface, alpha: 1, factorScale: projectionScale / dice, eye,
                                         meshVertexCount: mesh.vertices.length / MESH_VERTEX_FLOATS, pattern });
        const out = await pipeline.run(params, new Uint32Array(mesh.vertices.buffer), mesh.indices, false);
        const uniformMax = pattern === 'uniform' ? (await pipeline.uniformTables()).maxFactor : null;
        const viewProj = mul(perspective(FOV_Y, this.canvas.width / this.canvas.height, 0.05, 100), lookAt(eye));
        const u = new Float32Array(20);
        u.set(viewProj);
        u.set([eye[0] + 1, eye[1] + 2, eye[2], 0], 16);
        this.device.queue.writeBuffer(this.uniform, 0, u);
        const bind = this.device.createBindGroup({
            layout: this.render.getBindGroupLayout(0),
            entries: [{ binding: 0, resource: { buffer: this.uniform } }, { binding: 1, resource: { buffer: out.vertices } },
                      { binding: 2, resource: { buffer: out.indices } }],
        });
        const enc = this.device.createCommandEncoder();
        const pass = enc.beginRenderPass({
            colorAttachments: [{ view: this.context.getCurrentTexture().createView(), clearValue: [1, 1, 1, 1], loadOp: 'clear', storeOp: 'store' }],
            depthStencilAttachment: { view: this.depth.createView(), depthClearValue: 1, depthLoadOp: 'clear', depthStoreOp: 'store' },
        });
        pass.setPipeline(this.render);
        pass.setBindGroup(0, bind);
        pass.draw(out.triangleCount * 3);
        pass.end();
        this.device.queue.submit([enc.finish()]);
        await this.device.queue.onSubmittedWorkDone();
        // What the pipeline wrote, for the test's watertightness check (docs/shaders.md's vertex records).
        const readback = { vertices: await pipeline.read(out.vertices, out.vertexCount * C.VERTEX_WORDS),
                           indices: await pipeline.read(out.indices, out.triangleCount * 3), records: out.patches };
        out.vertices.destroy();
        out.indices.destroy();
        this.ui.diceValue.textContent = `${dice} px`;
        this.ui.vertices.textContent = out.vertexCount;
        this.ui.triangles.textContent = out.triangleCount;
        window.ctessViewer = {
            view: 'mesh', mode: pattern, uniformMax, max: maxFactor, mesh: kind, patches: mesh.patches,
            surface: ['flat', 'pn', 'phong'][surface], diceRate: dice, vertices: out.vertexCount,
            triangles: out.triangleCount, readback,
        };
        return window.ctessViewer;
    }
}
