// The generated mesh pipeline (build/<preset>/shaders/ctess_mesh_<max>.wgsl and its table blobs) on the browser's
// WebGPU, driven as tests/gpu/run_wgsl.mjs drives it on Dawn: bindings and record layouts in docs/shaders.md.
// Every layout number (params words, record and vertex words, pattern codes, workgroup sizes, dispatch limits)
// is the generated ctess_mesh_<max>.layout.json's (docs/shaders.md, "Generated constants"): `constants` below.
// The params' pattern word selects the pattern (docs/shaders.md, "Pattern option"): CP binds the CP blob, uniform
// density the uniform blob (the same CP sections, then the uniform ones), fetched on first use.
export const PATTERN_NAMES = ['cp', 'uniform']; // the layout's PATTERN_CP, PATTERN_UNIFORM

// Resolves to {device, adapterInfo} or throws an Error whose message says plainly why WebGPU is unusable.
export async function openDevice() {
    if (!('gpu' in navigator))
        throw new Error('This browser has no WebGPU (navigator.gpu is missing). Use a recent Chromium; headless ' +
                        'or Linux builds need --enable-unsafe-webgpu.');
    const adapter = await navigator.gpu.requestAdapter();
    if (!adapter)
        throw new Error('WebGPU is present but no adapter is available (requestAdapter() returned null). On ' +
                        'Linux, start Chromium with --enable-unsafe-webgpu.');
    if (adapter.limits.maxStorageBuffersPerShaderStage < 7)
        throw new Error(`This WebGPU adapter allows ${adapter.limits.maxStorageBuffersPerShaderStage} storage ` +
                        'buffers per stage; the ctess pipeline needs 7.');
    const device = await adapter.requestDevice({
        requiredLimits: {
            maxStorageBuffersPerShaderStage: adapter.limits.maxStorageBuffersPerShaderStage,
            maxStorageBufferBindingSize: adapter.limits.maxStorageBufferBindingSize,
            maxBufferSize: adapter.limits.maxBufferSize,
        },
    });
    return { device, adapterInfo: adapter.info ?? {} };
}

async function fetchOk(url) {
    const r = await fetch(url);
    if (!r.ok) throw new Error(`${url}: HTTP ${r.status} (serve the viewer with \`ctess serve\`)`);
    return r;
}

export class WgslPipeline {
    static async load(device, maxFactor) {
        const [wgsl, extra, blob, layout] = await Promise.all([
            fetchOk(`shaders/ctess_mesh_${maxFactor}.wgsl`).then((r) => r.text()),
            fetchOk('explicit_factors.wgsl').then((r) => r.text()),
            fetchOk(`shaders/ctess_mesh_${maxFactor}.tables.bin`).then((r) => r.arrayBuffer()),
            fetchOk(`shaders/ctess_mesh_${maxFactor}.layout.json`).then((r) => r.json()),
        ]);
        const p = new WgslPipeline(device, maxFactor);
        p.constants = layout.constants; // the generated constants (names as in the shaders)
        p.patchWords = layout.constants.PATCH_WORDS; // words per patch record
        p.setupGroup = layout.passes.find((pass) => pass.name === 'patch_setup').workgroup_size;
        device.pushErrorScope('validation');
        const module = device.createShaderModule({ code: `${wgsl}\n${extra}` });
        const errors = (await module.getCompilationInfo()).messages.filter((m) => m.type === 'error');
        if (errors.length) throw new Error(`WGSL ${errors[0].lineNum}:${errors[0].linePos}: ${errors[0].message}`);
        const entries = [];
        for (let i = 0; i < 7; i++)
            entries.push({ binding: i, visibility: GPUShaderStage.COMPUTE, buffer: { type: i < 4 ? 'read-only-storage' : 'storage' } });
        p.layout = device.createBindGroupLayout({ entries });
        const pipelineLayout = device.createPipelineLayout({ bindGroupLayouts: [p.layout] });
        // Compiled concurrently (each pipeline compiles the whole module: seconds on a software adapter).
        const make = (entryPoint) => device.createComputePipelineAsync({ layout: pipelineLayout, compute: { module, entryPoint } });
        [p.explicitSetup, p.setup, p.scan, p.emitVertices, p.emitTriangles] = await Promise.all([
            make('viewer_explicit_setup'), make('ctess_patch_setup'), make('ctess_prefix_sum'),
            make('ctess_emit_vertices'), make('ctess_emit_triangles')]);
        const err = await device.popErrorScope();
        if (err) throw new Error(err.message);
        p.tables = p.storage(new Uint32Array(blob));
        return p;
    }

    constructor(device, maxFactor) {
        this.device = device;
        this.maxFactor = maxFactor;
        this.uniform = null; // Promise<{tables, maxFactor}>: the uniform blob and its N (uniform_max_factor)
    }

    // The uniform blob, bound for the uniform pattern, and the largest factor its table holds.
    uniformTables() {
        if (!this.uniform) {
            const base = `shaders/ctess_mesh_${this.maxFactor}.uniform`;
            this.uniform = Promise.all([fetchOk(`${base}.tables.bin`).then((r) => r.arrayBuffer()),
                                        fetchOk(`${base}.layout.json`).then((r) => r.json())])
                .then(([blob, layout]) => ({ tables: this.storage(new Uint32Array(blob)), maxFactor: layout.uniform_max_factor }));
            this.uniform.catch(() => { this.uniform = null; });
        }
        return this.uniform;
    }

    storage(data, words = data.length, extraUsage = 0) {
        const buffer = this.device.createBuffer({
            size: Math.max(16, words * 4),
            usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC | GPUBufferUsage.COPY_DST | extraUsage,
        });
        if (data) this.device.queue.writeBuffer(buffer, 0, data);
        return buffer;
    }

    async read(buffer, words) {
        const size = Math.max(16, words * 4);
        const staging = this.device.createBuffer({ size, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });
        const enc = this.device.createCommandEncoder();
        enc.copyBufferToBuffer(buffer, 0, staging, 0, size);
        this.device.queue.submit([enc.finish()]);
        await staging.mapAsync(GPUMapMode.READ);
        const out = new Uint32Array(staging.getMappedRange().slice(0, words * 4));
        staging.unmap();
        staging.destroy();
        return out;
    }

    dispatch(buffers, passes) {
        const bindGroup = this.device.createBindGroup({
            layout: this.layout,
            entries: buffers.map((buffer, binding) => ({ binding, resource: { buffer } })),
        });
        const enc = this.device.createCommandEncoder();
        for (const [pipeline, groups] of passes) {
            const pass = enc.beginComputePass();
            pass.setPipeline(pipeline);
            pass.setBindGroup(0, bindGroup);
            pass.dispatchWorkgroups(groups);
            pass.end();
        }
        this.device.queue.submit([enc.finish()]);
    }

    // The params buffer (the layout's PARAM_* words), with `extra` words after it (the explicit factors):
    // {patchCount, surface, alpha, factorScale, eye: [x, y, z], meshVertexCount, first, end, pattern: 'cp' | 'uniform'}.
    params(f, extra = 0) {
        const C = this.constants;
        const p = new Uint32Array(C.PARAMS_WORDS + extra);
        p[C.PARAM_PATCH_COUNT] = f.patchCount;
        p[C.PARAM_SURFACE] = f.surface;
        p[C.PARAM_ALPHA] = f32Bits(f.alpha);
        p[C.PARAM_FACTOR_SCALE] = f32Bits(f.factorScale);
        p.set(f.eye.map(f32Bits), C.PARAM_EYE);
        p[C.PARAM_MESH_VERTEX_COUNT] = f.meshVertexCount;
        p[C.PARAM_FIRST_PATCH] = f.first ?? 0;
        p[C.PARAM_END_PATCH] = f.end ?? f.patchCount;
        p[C.PARAM_PATTERN] = C[`PATTERN_${f.pattern.toUpperCase()}`];
        return p;
    }

    // Runs setup (explicit factors, or projected from the mesh) and the prefix sum, then both emit passes, with
    // the blob of the pattern the params name. Returns {patches, vertexCount, triangleCount, vertices,
    // indices} with the output as GPU buffers.
    async run(params, meshVertices, meshIndices, explicit, indexUsage = 0) {
        const C = this.constants;
        const n = params[C.PARAM_PATCH_COUNT];
        const tables = params[C.PARAM_PATTERN] === C.PATTERN_UNIFORM ? (await this.uniformTables()).tables : this.tables;
        const bParams = this.storage(params);
        const bMesh = this.storage(meshVertices);
        const bIndices = this.storage(meshIndices);
        const patchWords = n * this.patchWords + C.TOTALS_WORDS;
        const bPatches = this.storage(null, patchWords);
        const none = [this.storage(null, 4), this.storage(null, 4)];
        const setup = explicit ? [this.explicitSetup, n] : [this.setup, Math.ceil(n / this.setupGroup)];
        this.dispatch([bParams, tables, bMesh, bIndices, bPatches, ...none], [setup, [this.scan, 1]]);
        const patches = await this.read(bPatches, patchWords);
        const vertexCount = patches[n * this.patchWords], triangleCount = patches[n * this.patchWords + 1];
        const vertices = this.storage(null, vertexCount * C.VERTEX_WORDS);
        const indices = this.storage(null, triangleCount * 3, indexUsage);
        this.dispatch([bParams, tables, bMesh, bIndices, bPatches, vertices, indices],
                      [[this.emitVertices, Math.min(n, C.MAX_DISPATCH_WORKGROUPS)],
                       [this.emitTriangles, Math.min(n, C.MAX_DISPATCH_WORKGROUPS)]]);
        for (const b of [bParams, bMesh, bIndices, bPatches, ...none]) b.destroy();
        return { patches, vertexCount, triangleCount, vertices, indices };
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

export function f32Bits(x) {
    return new Uint32Array(new Float32Array([x]).buffer)[0];
}
