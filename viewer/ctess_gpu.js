// The generated mesh pipeline (build/<preset>/shaders/ctess_mesh_<max>.wgsl and its table blobs) on the browser's
// WebGPU, through the host module that ships beside the shaders (shaders/ctess_webgpu.mjs; docs/shaders.md,
// "Hosts"), plus the viewer's own explicit-factor setup (explicit_factors.wgsl). Every layout number is the
// generated ctess_mesh_<max>.layout.json's: `constants` below.
import { MeshPipeline, f32Bits, requiredLimits } from './shaders/ctess_webgpu.mjs';

export const PATTERN_NAMES = ['cp', 'uniform', 'uniform-split']; // the layout's PATTERN_CP, PATTERN_UNIFORM, PATTERN_UNIFORM_SPLIT

// Resolves to {device, adapterInfo} or throws an Error whose message says plainly why WebGPU is unusable.
export async function openDevice() {
    if (!('gpu' in navigator))
        throw new Error('This browser has no WebGPU (navigator.gpu is missing). Use a recent Chromium; headless ' +
                        'or Linux builds need --enable-unsafe-webgpu.');
    const adapter = await navigator.gpu.requestAdapter();
    if (!adapter)
        throw new Error('WebGPU is present but no adapter is available (requestAdapter() returned null). On ' +
                        'Linux, start Chromium with --enable-unsafe-webgpu.');
    const device = await adapter.requestDevice({ requiredLimits: requiredLimits(adapter) });
    return { device, adapterInfo: adapter.info ?? {} };
}

async function fetchOk(url) {
    const r = await fetch(url);
    if (!r.ok) throw new Error(`${url}: HTTP ${r.status} (serve the viewer with \`ctess serve\`)`);
    return r;
}

export class WgslPipeline {
    static async load(device, maxFactor) {
        const load = (name) => fetchOk(`shaders/${name}`).then((r) => (name.endsWith('.bin') ? r.arrayBuffer() : r.text()));
        const extraCode = await fetchOk('explicit_factors.wgsl').then((r) => r.text());
        const p = new WgslPipeline();
        p.host = await MeshPipeline.create(device, { maxFactor, load, extraCode, extraEntryPoints: ['viewer_explicit_setup'] });
        p.constants = p.host.constants;
        p.patchWords = p.host.patchWords;
        return p;
    }

    // The uniform blob, bound for the uniform pattern, and the largest factor its table holds.
    uniformTables() {
        return this.host.tables('uniform');
    }

    read(buffer, words) {
        return this.host.read(buffer, words);
    }

    // The params buffer (the layout's PARAM_* words), with `extra` words after it (the explicit factors).
    params(f, extra = 0) {
        return this.host.params(f, extra);
    }

    // Runs setup (explicit factors, or projected from the mesh) and the prefix sum, then both emit passes, with
    // the blob of the pattern the params name. Returns {patches, vertexCount, triangleCount, vertices,
    // indices, milliseconds} with the output as GPU buffers. `data` is the displacement's {texels, directions}
    // (the host's run() options).
    run(params, meshVertices, meshIndices, explicit, indexUsage = 0, data = {}) {
        const n = params[this.constants.PARAM_PATCH_COUNT];
        return this.host.run(params, meshVertices, meshIndices,
                             { ...data, setup: explicit ? { entry: 'viewer_explicit_setup', groups: n } : undefined, indexUsage });
    }

    // One CP triangle (three edge factors, floats) or one CP quad (four: q0q1, q1q2, q2q3, q3q0), or with
    // pattern 'uniform' one uniform-density triangle (factors rounded and clamped to [1, N] by the module): the
    // pattern's (u, v) in 2^-24 and its counter-clockwise triangles (CP: provoking first), read back from the GPU.
    // A quad is the two triangles of cp::split_quad (constexpr/ctess/cp/quad.hpp): A = (q0, q1, q3) with
    // factors (f0, f0, f3) and B = (q2, q3, q1) with (f2, f0, f1), the diagonal taking f0; B's points map to
    // (1 - u, 1 - v). Both halves keep their own diagonal points, as the CLI's provoking layout does.
    async pattern(factors, pattern = 'cp') {
        const halves = factors.length === 4 ? [[factors[0], factors[0], factors[3]], [factors[2], factors[0], factors[1]]] : [factors];
        const C = this.constants;
        const n = halves.length;
        // The explicit factors follow the params (explicit_factors.wgsl reads them from word PARAMS_WORDS on).
        const params = this.params({ patchCount: n, surface: C.SURFACE_FLAT, alpha: 0, factorScale: 1, eye: [0, 0, 0],
                                     meshVertexCount: 3, pattern }, 3 * n);
        params.set(halves.flat().map(f32Bits), C.PARAMS_WORDS);
        // Three mesh vertices (position, normal, uv), MESH_VERTEX_FLOATS each.
        const mesh = new Float32Array(3 * C.MESH_VERTEX_FLOATS);
        [[0, 0, 0, 0, 0, 1, 0, 0], [1, 0, 0, 0, 0, 1, 1, 0], [0, 1, 0, 0, 0, 1, 0, 1]].forEach((v, i) => mesh.set(v, i * C.MESH_VERTEX_FLOATS));
        const out = await this.run(params, new Uint32Array(mesh.buffer), new Uint32Array(halves.flatMap(() => [0, 1, 2])), true);
        const words = await this.read(out.vertices, out.vertexCount * C.VERTEX_WORDS);
        const indices = await this.read(out.indices, out.triangleCount * 3);
        out.vertices.destroy();
        out.indices.destroy();
        const one = C.FIXED_ONE;
        const secondHalf = n === 2 ? out.patches[this.patchWords + C.REC_FIRST_VERTEX] : out.vertexCount;
        const uv = new Uint32Array(out.vertexCount * 2);
        for (let i = 0; i < out.vertexCount; i++) {
            const u = words[i * C.VERTEX_WORDS + C.VERTEX_U], v = words[i * C.VERTEX_WORDS + C.VERTEX_V];
            uv[2 * i] = i < secondHalf ? u : one - u;
            uv[2 * i + 1] = i < secondHalf ? v : one - v;
        }
        return { uv, indices, vertexCount: out.vertexCount, triangleCount: out.triangleCount };
    }
}
