// The WebGPU host of the generated mesh pipeline (docs/shaders.md, "Hosts"), for the browser and for Node (npm
// `webgpu`, Dawn). It ships beside the shaders it runs (build/<preset>/shaders/, share/ctess/shaders/) and takes
// every layout number from their layout.json: params words, record and vertex words, workgroup sizes, limits.
//
//   import { MeshPipeline, requiredLimits } from './shaders/ctess_webgpu.mjs';
//   const device = await adapter.requestDevice({ requiredLimits: requiredLimits(adapter) });
//   const load = (name) => fetch(`shaders/${name}`).then((r) => (name.endsWith('.bin') ? r.arrayBuffer() : r.text()));
//   const pipeline = await MeshPipeline.create(device, { maxFactor: 64, load });
//   const params = pipeline.params({ patchCount, surface: 'pn', alpha: 1, factorScale, eye, meshVertexCount });
//   const out = await pipeline.run(params, meshVertices, meshIndices); // out.vertices, out.indices: GPUBuffers
//
// Bindings (group 0, BINDINGS storage buffers): params, table blob, mesh vertices, mesh indices, patch records and
// totals, output vertices, output indices, the welded output's area (a placeholder when not welding). Errors throw;
// a mesh past the pipeline's limits throws an Error whose `pastLimits` is true, before any output buffer is made.

export function f32Bits(x) {
    return new Uint32Array(new Float32Array([x]).buffer)[0];
}

// The limits a device must be requested with: the adapter's own storage limits (the defaults are too small for
// large outputs; MeshPipeline.create checks the storage buffers per stage against the layout's BINDINGS).
export function requiredLimits(adapter) {
    return {
        maxStorageBuffersPerShaderStage: adapter.limits.maxStorageBuffersPerShaderStage,
        maxStorageBufferBindingSize: adapter.limits.maxStorageBufferBindingSize,
        maxBufferSize: adapter.limits.maxBufferSize,
    };
}

// The mesh's edges as rt::weld_edge_list lists them (docs/shaders.md, "Welded output"): each face's (a face with an
// index >= vertexCount is culled and has none; a triangle's (w0, w1), (w1, w2), (w2, w0), a quad's four), keyed
// lo = min, hi = max, sorted by (lo, hi) and distinct. meshIndices: the triangles' 3 indices each, then the quads'
// 4. Returns a Uint32Array of 4 words per edge (rt::WeldedEdge: lo, hi, then 0, 0 for the passes to fill).
export function weldEdgeList(meshIndices, triangleCount, quadCount, vertexCount) {
    // A counting sort by lo (lo < vertexCount), then each lo's few hi sorted: no 64-bit keys in JS.
    const start = new Uint32Array(vertexCount + 1);
    const each = (visit) => {
        for (let f = 0; f < triangleCount + quadCount; f++) {
            const m = f < triangleCount ? 3 : 4, at = f < triangleCount ? 3 * f : 3 * triangleCount + 4 * (f - triangleCount);
            let culled = false;
            for (let k = 0; k < m; k++) culled ||= meshIndices[at + k] >= vertexCount;
            if (culled) continue;
            for (let k = 0; k < m; k++) {
                const i = meshIndices[at + k], j = meshIndices[at + (k + 1) % m];
                visit(Math.min(i, j), Math.max(i, j));
            }
        }
    };
    each((lo) => { start[lo + 1]++; });
    for (let v = 0; v < vertexCount; v++) start[v + 1] += start[v];
    const hi = new Uint32Array(start[vertexCount]), fill = start.slice(0, vertexCount);
    each((lo, h) => { hi[fill[lo]++] = h; });
    const out = new Uint32Array(4 * hi.length);
    let n = 0;
    for (let lo = 0; lo < vertexCount; lo++) {
        const his = hi.subarray(start[lo], start[lo + 1]).sort();
        for (let k = 0; k < his.length; k++) {
            if (k > 0 && his[k] === his[k - 1]) continue;
            out[4 * n] = lo;
            out[4 * n + 1] = his[k];
            n++;
        }
    }
    return out.slice(0, 4 * n);
}

// The weld by one sort over the mesh (docs/shaders.md, "Welded output"; the params' WELD_SORTED): its sort's records,
// rank blocks and binding 7's words, as rt::gpu::weld_sort_records, weld_rank_blocks and weld_sorted_buffer_words
// (shader_interface.hpp) compute them, from the layout's constants C. slots and triangles: the unwelded totals.
export function weldSortedSizes(C, { edges, patches, meshVertices, slots, triangles }) {
    // The slots, or more where the triangles' flags (a word each, WELD_RECORD_WORDS to a record) need the room; the
    // network treats the records past them as +inf. width: the network's, a power of two, at least the records and
    // WELD_SORT_CHUNK.
    const records = Math.max(slots, Math.ceil(triangles / C.WELD_RECORD_WORDS), 1);
    let width = C.WELD_SORT_CHUNK;
    while (width < records) width *= 2;
    const blocks = Math.ceil(Math.max(records, triangles) / C.WELD_RANK_BLOCK);
    // The header, edges and patches, a writer word per id, a map word and two words of base weights per slot, the
    // records and two words per rank block.
    const words = C.WELD_HEADER_WORDS + edges * C.WELD_EDGE_WORDS + patches * C.WELD_PATCH_WORDS + meshVertices + 4 * slots +
                  C.WELD_RECORD_WORDS * records + 2 * blocks;
    return { records, width, blocks, words };
}

export class MeshPipeline {
    // load(name) gives a file of the shader folder: a Promise of a string (.wgsl, .json) or an ArrayBuffer (.bin).
    // extraCode is WGSL appended to the module (entry points of the caller's own, sharing its bindings), and
    // extraEntryPoints their names: pipeline.extra[name] is then a compute pipeline for run()'s `setup` option.
    static async create(device, { maxFactor, load, extraCode = '', extraEntryPoints = [] }) {
        const [wgsl, layout] = await Promise.all([load(`ctess_mesh_${maxFactor}.wgsl`),
                                                  load(`ctess_mesh_${maxFactor}.layout.json`).then(JSON.parse)]);
        const p = new MeshPipeline(device, maxFactor, load, layout);
        const C = layout.constants;
        if (device.limits.maxStorageBuffersPerShaderStage < C.BINDINGS)
            throw new Error(`This WebGPU device allows ${device.limits.maxStorageBuffersPerShaderStage} storage ` +
                            `buffers per stage; the ctess pipeline needs ${C.BINDINGS} (request requiredLimits(adapter)).`);
        device.pushErrorScope('validation');
        const module = device.createShaderModule({ code: extraCode ? `${wgsl}\n${extraCode}` : wgsl });
        const errors = (await module.getCompilationInfo()).messages.filter((m) => m.type === 'error');
        if (errors.length) {
            await device.popErrorScope();
            throw new Error(`WGSL ${errors[0].lineNum}:${errors[0].linePos}: ${errors[0].message}`);
        }
        const entries = [];
        for (let i = 0; i < C.BINDINGS; i++)
            entries.push({ binding: i, visibility: GPUShaderStage.COMPUTE, buffer: { type: i < C.READ_ONLY_BINDINGS ? 'read-only-storage' : 'storage' } });
        p.layout = device.createBindGroupLayout({ entries });
        const pipelineLayout = device.createPipelineLayout({ bindGroupLayouts: [p.layout] });
        // Compiled concurrently (seconds each on a software adapter). The quad and displaced vertex passes (more
        // than half of the module's code) compile on the first run that needs each (pipelineOf), so a triangle
        // mesh never waits for them.
        p.make = (entryPoint) => device.createComputePipelineAsync({ layout: pipelineLayout, compute: { module, entryPoint } });
        p.entries = Object.fromEntries(layout.passes.map((x) => [x.name, x.entry]));
        const own = ['patch_setup', 'prefix_sum', 'emit_vertices', 'emit_triangles'];
        const made = await Promise.all(own.map((x) => p.make(p.entries[x])).concat(extraEntryPoints.map(p.make)));
        own.forEach((name, k) => p.pipelines.set(name, Promise.resolve(made[k])));
        [p.setup, p.scan] = made;
        extraEntryPoints.forEach((name, k) => { p.extra[name] = made[own.length + k]; });
        const err = await device.popErrorScope();
        if (err) throw new Error(err.message);
        return p;
    }

    constructor(device, maxFactor, load, layout) {
        this.device = device;
        this.maxFactor = maxFactor;
        this.load = load;
        this.layoutJson = layout;
        this.constants = layout.constants; // the generated constants (names as in the shaders)
        this.patchWords = layout.constants.PATCH_WORDS;
        this.setupGroup = layout.passes.find((x) => x.name === 'patch_setup').workgroup_size;
        this.extra = {};
        this.pipelines = new Map(); // pass name (layout.json) -> Promise<GPUComputePipeline>
        this.blobs = new Map(); // pattern -> Promise<{tables, maxFactor}>
    }

    // The table blob a pattern binds, uploaded once: CP binds ctess_mesh_<max>.tables.bin, uniform density the
    // uniform blob (the same CP sections, then the uniform ones), whose table's N is maxFactor.
    tables(pattern) {
        const C = this.constants;
        const uniform = ['uniform', 'uniform-split', C.PATTERN_UNIFORM, C.PATTERN_UNIFORM_SPLIT].includes(pattern);
        const key = uniform ? 'uniform' : 'cp';
        if (!this.blobs.has(key)) {
            const base = `ctess_mesh_${this.maxFactor}${uniform ? '.uniform' : ''}`;
            const blob = Promise.all([this.load(`${base}.tables.bin`),
                                      uniform ? this.load(`${base}.layout.json`).then(JSON.parse) : null])
                .then(([bytes, layout]) => ({ tables: this.storage(new Uint32Array(bytes)),
                                              maxFactor: uniform ? layout.uniform_max_factor : this.maxFactor }));
            blob.catch(() => this.blobs.delete(key));
            this.blobs.set(key, blob);
        }
        return this.blobs.get(key);
    }

    storage(data, words = data.length, extraUsage = 0) {
        const buffer = this.device.createBuffer({
            size: Math.max(16, words * 4),
            usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC | GPUBufferUsage.COPY_DST | extraUsage,
        });
        if (data) this.device.queue.writeBuffer(buffer, 0, data);
        return buffer;
    }

    // words u32 of buffer from word `at` on.
    async read(buffer, words, at = 0) {
        const size = Math.max(16, words * 4);
        const staging = this.device.createBuffer({ size, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });
        const enc = this.device.createCommandEncoder();
        enc.copyBufferToBuffer(buffer, at * 4, staging, 0, size);
        this.device.queue.submit([enc.finish()]);
        await staging.mapAsync(GPUMapMode.READ);
        const out = new Uint32Array(staging.getMappedRange().slice(0, words * 4));
        staging.unmap();
        staging.destroy();
        return out;
    }

    // Encodes passes ([pipeline, workgroups] each, one compute pass each; workgroups a count, or [buffer, offset]
    // for an indirect dispatch of the three words at that byte offset; or {copy: [source, offset, target,
    // offset, bytes]} between passes) on the eight buffers, submits them and resolves when the queue is done, with
    // the milliseconds from submit.
    async dispatch(buffers, passes) {
        const bindGroup = this.device.createBindGroup({
            layout: this.layout,
            entries: buffers.map((buffer, binding) => ({ binding, resource: { buffer } })),
        });
        const enc = this.device.createCommandEncoder();
        for (const step of passes) {
            if (step.copy) {
                enc.copyBufferToBuffer(...step.copy);
                continue;
            }
            const [pipeline, groups] = step;
            const pass = enc.beginComputePass();
            pass.setPipeline(pipeline);
            pass.setBindGroup(0, bindGroup);
            if (Array.isArray(groups)) pass.dispatchWorkgroupsIndirect(groups[0], groups[1]);
            else pass.dispatchWorkgroups(groups);
            pass.end();
        }
        const start = performance.now();
        this.device.queue.submit([enc.finish()]);
        await this.device.queue.onSubmittedWorkDone();
        return performance.now() - start;
    }

    // The params words (the layout's PARAM_*), with `extra` zero words after them: {patchCount (triangles +
    // quads), surface ('flat', 'pn', 'phong' or the code), alpha, factorScale, eye: [x, y, z], meshVertexCount,
    // first, end, pattern ('cp', 'uniform', 'uniform-split' or the code), quadCount (the last patches; meshIndices holds the
    // triangles' 3 indices each, then the quads' 4), quadRule ('longer-pair', the default, or 'as-labelled')}.
    // Surface names: 'flat', 'pn', 'phong', 'pn-aen'. An unknown name throws.
    // displacement (docs/shaders.md, "Displacement"): {scale, factor, offset, normalStep,
    // factorBound (rt::Displacement's defaults 1, 1, 0, 1/256, 0), width, height (the height map's texels; 0 x 0
    // an empty map), address ('repeat', the default, or 'clamp'), directions (true: run() gets options.directions),
    // adjacency (true: meshIndices holds the adjacency after the indices), vector (true: vector displacement,
    // docs/algorithm.md §8.7: RGB texels, 3 floats each, and run() gets options.tangents)}; run() then needs
    // options.texels. Values rt::displacement_valid refuses (non-finite numbers, factorBound < 0, normalStep
    // outside (0, 0.5]) throw.
    // weld (true: the welded output, docs/shaders.md "Welded output"; run() then welds), keepDegenerate
    // (WeldOptions::keep_degenerate: keep the welded triangles whose ids repeat; default false).
    params(f, extra = 0) {
        const C = this.constants;
        const code = (value, what, names) => {
            if (typeof value === 'number') return value;
            if (!(value in names)) throw new Error(`unknown ${what} '${value}' (one of ${Object.keys(names).join(', ')})`);
            return names[value];
        };
        const surfaces = { flat: C.SURFACE_FLAT, pn: C.SURFACE_PN, phong: C.SURFACE_PHONG, 'pn-aen': C.SURFACE_PN_AEN };
        const p = new Uint32Array(C.PARAMS_WORDS + extra);
        p[C.PARAM_PATCH_COUNT] = f.patchCount;
        p[C.PARAM_SURFACE] = code(f.surface ?? 'flat', 'surface', surfaces);
        p[C.PARAM_ALPHA] = f32Bits(f.alpha ?? 1);
        p[C.PARAM_FACTOR_SCALE] = f32Bits(f.factorScale);
        p.set(f.eye.map(f32Bits), C.PARAM_EYE);
        p[C.PARAM_MESH_VERTEX_COUNT] = f.meshVertexCount;
        p[C.PARAM_FIRST_PATCH] = f.first ?? 0;
        p[C.PARAM_END_PATCH] = f.end ?? f.patchCount;
        p[C.PARAM_PATTERN] = code(f.pattern ?? 'cp', 'pattern',
                                  { cp: C.PATTERN_CP, uniform: C.PATTERN_UNIFORM, 'uniform-split': C.PATTERN_UNIFORM_SPLIT });
        p[C.PARAM_QUAD_COUNT] = f.quadCount ?? 0;
        p[C.PARAM_QUAD_RULE] = code(f.quadRule ?? 'longer-pair', 'quad rule',
                                    { 'longer-pair': C.QUAD_RULE_LONGER_PAIR, 'as-labelled': C.QUAD_RULE_AS_LABELLED });
        p[C.PARAM_WELD] = f.weld ? C.WELD_ON | (f.keepDegenerate ? C.WELD_KEEP_DEGENERATE : 0) : 0;
        const d = f.displacement;
        if (d) {
            const [scale, factor, offset, normalStep, bound] = [d.scale ?? 1, d.factor ?? 1, d.offset ?? 0,
                                                                d.normalStep ?? 1 / 256, d.factorBound ?? 0].map(Math.fround);
            if (![scale, factor, offset, bound].every(Number.isFinite) || !(bound >= 0) || !(normalStep > 0 && normalStep <= 0.5))
                throw new Error('displacement: scale, factor, offset and factorBound must be finite, factorBound >= 0, normalStep in (0, 0.5]');
            p[C.PARAM_DISPLACEMENT_FLAGS] = C.DISPLACEMENT_ON | (d.directions ? C.DISPLACEMENT_DIRECTIONS : 0) |
                                            (d.adjacency ? C.DISPLACEMENT_ADJACENCY : 0) | (d.vector ? C.DISPLACEMENT_VECTOR : 0);
            p.set([scale, factor, offset, normalStep, bound].map(f32Bits), C.PARAM_DISPLACEMENT_SCALE);
            p[C.PARAM_HEIGHT_MAP_WIDTH] = d.width ?? 0;
            p[C.PARAM_HEIGHT_MAP_HEIGHT] = d.height ?? 0;
            p[C.PARAM_HEIGHT_MAP_ADDRESS] = code(d.address ?? 'repeat', 'address mode', { repeat: C.ADDRESS_REPEAT, clamp: C.ADDRESS_CLAMP });
        }
        return p;
    }

    // The whole pipeline: setup (or options.setup = {entry, groups}, an extra entry point) and the prefix sum, the
    // totals recounted from the records and checked against the layout's limits, then both emit passes in batches
    // of about options.batchVertices output vertices (default: one batch; a split run takes one), at most options.maxWorkgroups workgroups
    // per dispatch. options.countsOnly stops after the counts. Resolves to {patches (the records and totals, a
    // Uint32Array), vertexCount, triangleCount (the prefix sum's totals), vertices, indices (GPUBuffers, or null
    // with countsOnly), milliseconds}. indexUsage and vertexUsage add usage flags to the output buffers (e.g.
    // GPUBufferUsage.INDEX to draw the indices). Params that do not describe the arrays given, a binding past the
    // device's maxStorageBufferBindingSize and any validation or out-of-memory error of the run throw.
    // Displacement (params' displacement): options.texels (a Float32Array of exactly width x height texels, 3
    // floats each in vector mode) and, when the params name them, options.directions (3 floats per mesh vertex)
    // and in vector mode options.tangents (4 floats per mesh vertex, glTF TANGENT's layout) go after the mesh's
    // own data.
    // Splitting (pattern 'uniform-split'; docs/shaders.md, "Splitting"): between the setup and the prefix sum run
    // the split passes, SPLIT_DEPTH_BOUND levels of them, on split regions of options.splitCapacity nodes (default
    // at least 65,536 and the roots; the host sets the params' capacity word); a level that needs more runs the
    // levels again on regions grown to what it needed (at least twice the nodes), up to options.maxSplitCapacity
    // (default: the device's binding size), past which run() throws, naming the nodes needed. The result then
    // also has splitLeaves and splitCapacity.
    // Welding (params' weld; docs/shaders.md, "Welded output"; every pattern, in one batch: options.batchVertices
    // throws): after the counts (the unwelded totals are the weld's slots) binding 7 gets the mesh's edge list
    // (weldEdgeList) and the weld's counting passes run (each edge's points and their prefix sums, each patch's weld,
    // each shared id's writer, the patches' prefix sums; the 'uniform-split' pattern, and a mesh with a patch past
    // WELD_MAX_PATCH_SLOTS slots, by one sort over the mesh instead of each patch's weld); a patch edge missing from
    // the list or a prefix sum past its bound throws, and the welded totals are recounted and checked against the
    // limits before the outputs are made at those totals. The emit is the vertex passes (each slot writing the
    // welded vertex it owns), ctess_weld_triangles or ctess_weld_sorted_triangles (the kept triangles) and
    // ctess_weld_lone_vertices (the mesh vertices no face reaches). vertexCount and triangleCount are the welded
    // totals, and the result also has weld: {edges (rt::WeldedEdge, 4 words each), patches (rt::WeldedPatch, 4
    // words each; Uint32Arrays), edgeCount, vertexCount, triangleCount}. With countsOnly the weld's counts run too.
    async run(params, meshVertices, meshIndices, options = {}) {
        const C = this.constants;
        const { max_patches: maxPatches, max_vertices: maxVertices, max_triangles: maxTriangles } = this.layoutJson.limits;
        const maxGroups = options.maxWorkgroups ?? C.MAX_DISPATCH_WORKGROUPS;
        const n = params[C.PARAM_PATCH_COUNT], quads = params[C.PARAM_QUAD_COUNT];
        const first0 = params[C.PARAM_FIRST_PATCH], end0 = params[C.PARAM_END_PATCH];
        const pastLimits = (what) => Object.assign(new Error(`${what}: past the pipeline's limits (${maxPatches} ` +
                                                             `patches, ${maxVertices} vertices, ${maxTriangles} triangles)`), { pastLimits: true });
        if (n > maxPatches) throw pastLimits(`${n} patches`);
        // The same checks as the C++ host (ctess::vulkan::Runner): the params must describe the mesh given.
        if (quads > n || first0 > end0 || end0 > n)
            throw new Error(`params: ${quads} quads, emit range [${first0}, ${end0}) for ${n} patches`);
        if (3 * (n - quads) + 4 * quads > meshIndices.length || params[C.PARAM_MESH_VERTEX_COUNT] * C.MESH_VERTEX_FLOATS > meshVertices.length)
            throw new Error('params: more patches or mesh vertices than the index and vertex arrays hold');
        const maxBinding = this.device.limits.maxStorageBufferBindingSize;
        const displaced = (params[C.PARAM_DISPLACEMENT_FLAGS] & C.DISPLACEMENT_ON) !== 0;
        if (displaced) // after the checks above, on the caller's arrays
            [meshVertices, meshIndices] = this.displacementData(params, meshVertices, meshIndices, options, maxBinding);
        const patchWords = n * this.patchWords + C.TOTALS_WORDS;
        for (const [what, words] of [['mesh vertices', meshVertices.length], ['mesh indices', meshIndices.length], ['patch records', patchWords]])
            if (words * 4 > maxBinding) throw new Error(`${what}: ${words * 4} bytes in one storage binding, past the device's ${maxBinding}`);
        // Splitting: binding 4 holds the split area after the totals (rt::gpu::split_buffer_words).
        const split = params[C.PARAM_PATTERN] === C.PATTERN_UNIFORM_SPLIT;
        const welded = (params[C.PARAM_WELD] & C.WELD_ON) !== 0;
        if (welded && (options.batchVertices ?? Infinity) !== Infinity)
            throw new Error('weld: the welded output is emitted in one batch (no batchVertices)');
        const roots = n + quads; // one per base triangle, two per quad
        // A default start never above the run's limit; at least the roots.
        let capacity = split ? Math.max(options.splitCapacity || Math.min(65536, options.maxSplitCapacity || 65536), roots, 1) : 0;
        const splitWords = (nodes) => {
            const words = patchWords + C.SPLIT_HEADER_WORDS + 2 * nodes * C.NODE_WORDS;
            if (words * 4 > maxBinding)
                throw new Error(`splitting needs ${nodes} nodes per region: binding 4 would be ${words * 4} bytes, past the device's ${maxBinding}`);
            if (options.maxSplitCapacity && nodes > options.maxSplitCapacity)
                throw new Error(`splitting needs ${nodes} nodes per region, past the run's maxSplitCapacity (${options.maxSplitCapacity})`);
            return words;
        };
        const splitPasses = split ? await Promise.all(['split_roots', 'split_count', 'split_scan', 'split_expand', 'split_records',
                                                       'split_points'].map((name) => this.pipelineOf(name))) : [];
        const { tables } = await this.tables(params[C.PARAM_PATTERN]);
        // Displaced vertices come from their own entry points (the others write none for such params).
        const triangles = n - quads;
        // Vector displacement (docs/algorithm.md §8.7) has its own two.
        const vector = displaced && (params[C.PARAM_DISPLACEMENT_FLAGS] & C.DISPLACEMENT_VECTOR) !== 0;
        const vertexPass = (quad) => `emit_${vector ? 'vector_' : ''}${displaced ? 'displaced_' : ''}${quad ? 'quad_' : ''}vertices`;
        // A welded run's triangles are ctess_weld_triangles'.
        const wanted = [first0 < Math.min(end0, triangles) ? vertexPass(false) : null,
                        first0 < Math.min(end0, triangles) && !welded ? 'emit_triangles' : null,
                        end0 > Math.max(first0, triangles) ? vertexPass(true) : null,
                        end0 > Math.max(first0, triangles) && !welded ? 'emit_quad_triangles' : null];
        const [emitVertices, emitTriangles, emitQuadVertices, emitQuadTriangles] =
            options.countsOnly ? [] : await Promise.all(wanted.map((name) => name && this.pipelineOf(name)));
        // The split pattern is always welded by one sort over the mesh (weldRun compiles its passes): no patch's own weld.
        const weldPasses = welded ? await Promise.all(['weld_edges', 'weld_edge_scan', split ? null : 'weld_count', 'weld_writers', 'weld_scan',
                                                       split ? null : 'weld_triangles', 'weld_lone_vertices']
                                                          .map((name) => name && this.pipelineOf(name))) : [];
        // Validation and out-of-memory errors of this run throw, instead of reading back zeros.
        this.device.pushErrorScope('out-of-memory');
        this.device.pushErrorScope('validation');
        const temporary = [];
        let scopes = 2; // still pushed
        const scoped = async (result) => {
            scopes = 0;
            const validation = await this.device.popErrorScope();
            const memory = await this.device.popErrorScope();
            if (validation || memory) throw new Error(`WebGPU: ${(validation ?? memory).message}`);
            return result;
        };
        try {
            const keep = (buffer) => { temporary.push(buffer); return buffer; };
            const bParams = keep(this.storage(params));
            const bMesh = keep(this.storage(meshVertices));
            const bIndices = keep(this.storage(meshIndices));
            // Placeholders for bindings 5 to 7 where a pass writes no outputs or no weld (every binding is bound in
            // every pass; one buffer may not be two writable bindings).
            const none = [keep(this.storage(null, 4)), keep(this.storage(null, 4)), keep(this.storage(null, 4))];
            const setup = options.setup ? [this.extra[options.setup.entry], options.setup.groups]
                                        : [this.setup, Math.max(1, Math.min(Math.ceil(n / this.setupGroup), maxGroups))];
            let bPatches, patches, splitLeaves = 0, milliseconds = 0;
            // The split passes' indirect dispatches read a copy of the header's dispatch words: a buffer bound as
            // writable storage cannot be a dispatch's indirect buffer too.
            const bDispatch = split ? keep(this.storage(null, 4, GPUBufferUsage.INDIRECT)) : null;
            for (;;) { // once, or again with larger split regions until the levels fit them
                bPatches = keep(this.storage(null, split ? splitWords(capacity) : patchWords));
                const passes = [setup];
                if (split) {
                    const runParams = params.slice();
                    runParams[C.PARAM_SPLIT_CAPACITY] = capacity;
                    this.device.queue.writeBuffer(bParams, 0, runParams);
                    const [roots_, count, scan, expand, records] = splitPasses;
                    const indirect = { copy: [bPatches, (patchWords + C.SPLIT_DISPATCH) * 4, bDispatch, 0, 12] };
                    passes.push([roots_, Math.max(1, Math.min(Math.ceil(roots / C.SPLIT_GROUP), maxGroups))], indirect);
                    for (let level = 0; level <= C.SPLIT_DEPTH_BOUND; level++)
                        passes.push([count, [bDispatch, 0]], [scan, 1], indirect, [level < C.SPLIT_DEPTH_BOUND ? expand : records, [bDispatch, 0]]);
                }
                passes.push([this.scan, 1]);
                milliseconds += await this.dispatch([bParams, tables, bMesh, bIndices, bPatches, ...none], passes);
                patches = await this.read(bPatches, patchWords);
                if (!split) break;
                const header = await this.read(bPatches, C.SPLIT_HEADER_WORDS, patchWords);
                if (header[C.SPLIT_OVERFLOW] === 0) {
                    splitLeaves = header[C.SPLIT_PARENTS];
                    break;
                }
                // A level asked for more nodes than a region holds: grow to what it asked, at least twice.
                let grown = Math.max(header[C.SPLIT_NEEDED], 2 * capacity);
                if (options.maxSplitCapacity && grown > options.maxSplitCapacity && capacity < options.maxSplitCapacity)
                    grown = Math.max(options.maxSplitCapacity, header[C.SPLIT_NEEDED]);
                splitWords(grown); // throws past the device's binding size or the run's limit
                capacity = grown;
                temporary.splice(temporary.indexOf(bPatches), 1);
                bPatches.destroy();
            }
            const totalV = patches[n * this.patchWords], totalT = patches[n * this.patchWords + 1];
            const splitInfo = split ? { splitLeaves, splitCapacity: capacity } : {};
            if (options.countsOnly && !welded)
                return await scoped({ patches, vertexCount: totalV, triangleCount: totalT, vertices: null, indices: null, milliseconds, ...splitInfo });
            // The u32 totals wrap (the shader then writes TOTALS_OVERFLOW): recount them exactly before sizing.
            let sumV = 0, sumT = 0;
            for (let t = 0; t < n; t++) {
                sumV += patches[t * this.patchWords + C.REC_VERTEX_COUNT];
                sumT += patches[t * this.patchWords + C.REC_TRIANGLE_COUNT];
            }
            if (sumV > maxVertices || sumT > maxTriangles) throw pastLimits(`${sumV} vertices, ${sumT} triangles`);
            if (sumV !== totalV || sumT !== totalT) throw new Error("the prefix sum's totals differ from the records' counts");
            if (welded) {
                return await scoped(await this.weldRun({ params, patches, slots: totalV, unweldedTriangles: totalT, meshIndices,
                                                         tables, bParams, bMesh, bIndices, bPatches, none, keep, milliseconds,
                                                         maxGroups, maxBinding, emitVertices, emitQuadVertices, weldPasses,
                                                         pastLimits, options, split, splitLeaves, capacity, splitInfo }));
            }
            const vertexCount = totalV, triangleCount = totalT;
            if (vertexCount * C.VERTEX_WORDS * 4 > maxBinding || triangleCount * 12 > maxBinding)
                throw new Error(`${vertexCount} vertices / ${triangleCount} triangles need more than ${maxBinding} ` +
                                'bytes in one storage binding');
            const vertices = this.storage(null, vertexCount * C.VERTEX_WORDS, options.vertexUsage ?? 0);
            const indices = this.storage(null, triangleCount * 3, options.indexUsage ?? 0);
            // The emit passes' patch range (PARAM_FIRST_PATCH, PARAM_END_PATCH), one submit per batch, as a host
            // that streams a large mesh would use it.
            // A split run emits in one batch: each batch's passes take a workgroup per leaf of the whole mesh (the
            // leaves of its patches do the work), so batches would add workgroups, not split them.
            const batch = split ? Infinity : options.batchVertices ?? Infinity;
            const batchParams = params.slice();
            batchParams[C.PARAM_SPLIT_CAPACITY] = capacity; // the split regions the counts were made in
            for (let first = first0; first < end0;) {
                let end = first, count = 0;
                while (end < end0 && (end === first || count + patches[end * this.patchWords + C.REC_VERTEX_COUNT] <= batch))
                    count += patches[this.patchWords * end++ + C.REC_VERTEX_COUNT];
                batchParams[C.PARAM_FIRST_PATCH] = first;
                batchParams[C.PARAM_END_PATCH] = end;
                this.device.queue.writeBuffer(bParams, 0, batchParams);
                // The batch's triangles and quads go to their own entry points (the quads are the last patches); a
                // split run's passes take a workgroup per leaf (of the patches in the pass's range).
                const groups = [Math.max(0, Math.min(end, triangles) - first), Math.max(0, end - Math.max(first, triangles))]
                    .map((count) => Math.min(count && split ? splitLeaves : count, maxGroups));
                // A split run's leaves' points first, read by its vertex passes (docs/shaders.md, "Splitting").
                const passes = [[splitPasses[5], split ? Math.min(splitLeaves, maxGroups) : 0], [emitVertices, groups[0]],
                                [emitTriangles, groups[0]], [emitQuadVertices, groups[1]], [emitQuadTriangles, groups[1]]]
                    .filter(([, g]) => g > 0);
                milliseconds += await this.dispatch([bParams, tables, bMesh, bIndices, bPatches, vertices, indices, none[2]], passes);
                first = end;
            }
            return await scoped({ patches, vertexCount, triangleCount, vertices, indices, milliseconds, ...splitInfo });
        } catch (e) {
            for (; scopes > 0; scopes--) await this.device.popErrorScope().catch(() => {});
            throw e;
        } finally {
            for (const b of temporary) b.destroy();
        }
    }

    // run()'s welded branch (docs/shaders.md, "Welded output"), after the counts: binding 7 (rt::gpu::weld_word,
    // rt::gpu::weld_buffer_words words, or weldSortedSizes' for the weld by one sort) with the header and the edge
    // list, the weld's counting passes as the Vulkan host's MeshPipeline::record_weld_counts (or
    // record_sorted_weld_counts), the welded totals recounted and checked, then the emit as record_weld_emit (or
    // record_sorted_weld_emit). Resolves to run()'s result.
    async weldRun({ params, patches, slots, unweldedTriangles, meshIndices, tables, bParams, bMesh, bIndices, bPatches, none, keep,
                    milliseconds, maxGroups, maxBinding, emitVertices, emitQuadVertices, weldPasses, pastLimits, options, split,
                    splitLeaves, capacity, splitInfo }) {
        const C = this.constants;
        const { max_vertices: maxVertices, max_triangles: maxTriangles } = this.layoutJson.limits;
        const n = params[C.PARAM_PATCH_COUNT], quads = params[C.PARAM_QUAD_COUNT], triangles = n - quads;
        const meshVertexCount = params[C.PARAM_MESH_VERTEX_COUNT];
        // A patch's weld runs in one workgroup up to WELD_MAX_PATCH_SLOTS slots (past it a software driver's loop limit
        // could cut its sort short); the split pattern, and a mesh with a larger patch, are welded by one sort over the
        // mesh (as the C++ host).
        let sorted = split;
        for (let t = 0; t < n && !sorted; t++) sorted = patches[t * this.patchWords + C.REC_VERTEX_COUNT] > C.WELD_MAX_PATCH_SLOTS;
        if (sorted) {
            const sortedParams = params.slice();
            if (split) sortedParams[C.PARAM_SPLIT_CAPACITY] = capacity; // the split regions the counts were made in
            sortedParams[C.PARAM_WELD] |= C.WELD_SORTED;
            this.device.queue.writeBuffer(bParams, 0, sortedParams);
        }
        const edgeList = weldEdgeList(meshIndices, triangles, quads, meshVertexCount);
        const edgeCount = edgeList.length / C.WELD_EDGE_WORDS;
        const sizes = weldSortedSizes(C, { edges: edgeCount, patches: n, meshVertices: meshVertexCount, slots, triangles: unweldedTriangles });
        const weldWords = sorted ? sizes.words : C.WELD_HEADER_WORDS + edgeCount * C.WELD_EDGE_WORDS + n * C.WELD_PATCH_WORDS +
                                                 meshVertexCount + slots * (2 + C.WELD_SORT_WORDS);
        if (weldWords * 4 > maxBinding)
            throw new Error(`weld: binding 7 would be ${weldWords * 4} bytes, past the device's ${maxBinding}`);
        const head = new Uint32Array(C.WELD_HEADER_WORDS + edgeList.length);
        head[C.WELD_EDGES] = edgeCount;
        head[C.WELD_SLOTS] = slots;
        head[C.WELD_SORT_RECORDS] = sizes.records;
        head.set(edgeList, C.WELD_HEADER_WORDS);
        const bWeld = keep(this.storage(head, weldWords));
        const group = C.EMIT_GROUP;
        const grid = (items, size = group) => Math.max(1, Math.min(Math.ceil(items / size), maxGroups)); // grid-stride passes
        const [edgePoints, edgeScan, count, writers, scan, weldTriangles, lone] = weldPasses;
        // The count and triangle passes run a patch per workgroup, in batches of maxGroups whose first patch is
        // copied into the header's WELD_FIRST_PATCH word before each dispatch (as the C++ host's vkCmdFillBuffer).
        const firsts = [];
        for (let first = 0; first < n; first += maxGroups) firsts.push(first);
        const bFirsts = keep(this.storage(Uint32Array.from(firsts.length ? firsts : [0])));
        const batches = (pass, from, to) => {
            const steps = [];
            for (let first = from; first < to; first += maxGroups) {
                steps.push({ copy: [bFirsts, 4 * Math.floor(first / maxGroups), bWeld, 4 * C.WELD_FIRST_PATCH, 4] });
                steps.push([pass, Math.min(maxGroups, to - first)]);
            }
            return steps;
        };
        const sortedPasses = sorted ? await Promise.all(['weld_keys', 'weld_sort_step', 'weld_sort_local', 'weld_rank_blocks', 'weld_rank_scan',
                                                         'weld_rank_write', 'weld_keep', 'weld_owner_counts', 'weld_sorted_triangles']
                                                            .map((name) => this.pipelineOf(name)))
                                    : [];
        const [keys, sortStep, sortLocal, rankBlocks, rankScan, rankWrite, keepPass, ownerCounts, sortedTriangles] = sortedPasses;
        const items = split ? splitLeaves : n; // the weld by one sort's work items: the leaves, or the patches
        let counting;
        if (sorted) {
            // As record_sorted_weld_counts. The header words the host sets between passes (the sort's stage and step,
            // the rank mode) are copies from a buffer of their values, as WELD_FIRST_PATCH's: queue.writeBuffer is not
            // ordered between the dispatches of one submit.
            // The bitonic network: the stages up to a chunk in workgroup memory (stage word 0), then each larger
            // stage's steps of a chunk or more over binding 7 and the rest in workgroup memory again.
            const records = sizes.records, chunks = grid(records, C.WELD_SORT_CHUNK), sortWords = [], sort = [];
            const sortWord = (w, value) => { sort.push({ w, at: sortWords.length }); sortWords.push(value); };
            sortWord(C.WELD_SORT_STAGE, 0);
            sort.push([sortLocal, chunks]);
            for (let stage = 2 * C.WELD_SORT_CHUNK; stage <= sizes.width; stage *= 2) {
                sortWord(C.WELD_SORT_STAGE, stage);
                for (let step = stage / 2; step >= C.WELD_SORT_CHUNK; step /= 2) {
                    sortWord(C.WELD_SORT_STEP, step);
                    sort.push([sortStep, grid(records)]);
                }
                sort.push([sortLocal, chunks]);
            }
            const bWords = keep(this.storage(Uint32Array.from([...sortWords, C.WELD_RANK_KEYS, C.WELD_RANK_TRIANGLES])));
            const word = (w, at) => ({ copy: [bWords, 4 * at, bWeld, 4 * w, 4] });
            const rank = (at, ranked) => [word(C.WELD_RANK_MODE, at), [rankBlocks, grid(ranked, C.WELD_RANK_BLOCK)], [rankScan, 1],
                                          [rankWrite, grid(ranked, C.WELD_RANK_BLOCK)]];
            counting = [[edgePoints, grid(Math.max(edgeCount, n, meshVertexCount + slots))],
                        [keys, Math.max(Math.min(items, maxGroups), grid(records - slots))],
                        ...sort.map((x) => (Array.isArray(x) ? x : word(x.w, x.at)))];
            counting.push(...rank(sortWords.length, records), [keepPass, Math.max(1, Math.min(items, maxGroups))],
                          ...rank(sortWords.length + 1, unweldedTriangles), [ownerCounts, grid(Math.max(edgeCount, n))],
                          [edgeScan, 1], [scan, 1], [writers, grid(slots)]);
        } else {
            counting = [[edgePoints, grid(Math.max(edgeCount, meshVertexCount + slots))], [edgeScan, 1], ...batches(count, 0, n),
                        [writers, grid(slots)], [scan, 1]];
        }
        milliseconds += await this.dispatch([bParams, tables, bMesh, bIndices, bPatches, none[0], none[1], bWeld], counting);
        const records = C.WELD_HEADER_WORDS + edgeCount * C.WELD_EDGE_WORDS;
        const words = await this.read(bWeld, records + n * C.WELD_PATCH_WORDS);
        if (words[C.WELD_STATUS] & C.WELD_MISSING_EDGE) throw new Error('weld: a patch edge is missing from the edge list');
        const edges = words.slice(C.WELD_HEADER_WORDS, records), weldPatches = words.slice(records);
        // Recounted exactly, as the CPU's setup_welded adds them up.
        let vertexCount = meshVertexCount, triangleCount = 0;
        for (let e = 0; e < edgeCount; e++) vertexCount += edges[e * C.WELD_EDGE_WORDS + C.WEDGE_VERTEX_COUNT];
        for (let t = 0; t < n; t++) {
            vertexCount += weldPatches[t * C.WELD_PATCH_WORDS + C.WPATCH_VERTEX_COUNT];
            triangleCount += weldPatches[t * C.WELD_PATCH_WORDS + C.WPATCH_TRIANGLE_COUNT];
        }
        if (vertexCount > maxVertices || triangleCount > maxTriangles) throw pastLimits(`welded: ${vertexCount} vertices, ${triangleCount} triangles`);
        if ((words[C.WELD_STATUS] & C.WELD_OVERFLOW) || words[C.WELD_VERTICES] !== vertexCount || words[C.WELD_TRIANGLES] !== triangleCount)
            throw new Error("weld: the prefix sums differ from the records' counts");
        const weld = { edges, patches: weldPatches, edgeCount, vertexCount, triangleCount };
        if (options.countsOnly) return { patches, vertexCount, triangleCount, vertices: null, indices: null, milliseconds, weld, ...splitInfo };
        if (vertexCount * C.VERTEX_WORDS * 4 > maxBinding || triangleCount * 12 > maxBinding)
            throw new Error(`${vertexCount} welded vertices / ${triangleCount} triangles need more than ${maxBinding} ` +
                            'bytes in one storage binding');
        const vertices = this.storage(null, vertexCount * C.VERTEX_WORDS, options.vertexUsage ?? 0);
        const indices = this.storage(null, triangleCount * 3, options.indexUsage ?? 0);
        // The emit range's triangles and quads (the params' [first, end)), then every mesh vertex no face reaches.
        const first = params[C.PARAM_FIRST_PATCH], end = params[C.PARAM_END_PATCH];
        const groups = [Math.max(0, Math.min(end, triangles) - first), Math.max(0, end - Math.max(first, triangles))];
        let passes;
        if (sorted) {
            // As record_sorted_weld_emit: a split run's passes take a workgroup per leaf (of the patches in the range).
            const kinds = groups.map((count) => (count && split ? splitLeaves : count));
            passes = [[emitVertices, Math.min(kinds[0], maxGroups)], [emitQuadVertices, Math.min(kinds[1], maxGroups)]]
                .filter(([, g]) => g > 0);
            passes.push([sortedTriangles, Math.max(1, Math.min(kinds[0] + kinds[1], maxGroups))], [lone, grid(meshVertexCount)]);
        } else {
            // The triangles' batches start at multiples of maxGroups (bFirsts' entries) from the one holding `first`.
            passes = [[emitVertices, Math.min(groups[0], maxGroups)], [emitQuadVertices, Math.min(groups[1], maxGroups)],
                      [lone, grid(meshVertexCount)]].filter(([, g]) => g > 0);
            if (end > first) passes.push(...batches(weldTriangles, first - (first % maxGroups), end));
        }
        milliseconds += await this.dispatch([bParams, tables, bMesh, bIndices, bPatches, vertices, indices, bWeld], passes);
        return { patches, vertexCount, triangleCount, vertices, indices, milliseconds, weld, ...splitInfo };
    }

    // The pipeline of a pass of layout.json, compiled once, on first use (a failure is not kept: the next run
    // tries again).
    pipelineOf(name) {
        if (!this.pipelines.has(name)) {
            const made = this.make(this.entries[name]);
            made.catch(() => this.pipelines.delete(name));
            this.pipelines.set(name, made);
        }
        return this.pipelines.get(name);
    }

    // Bindings 2 and 3 of a displaced run (docs/shaders.md, "Displacement"): the mesh vertices then the
    // directions and in vector mode the tangents, the indices (and the adjacency when the params' flag says so)
    // then the texels' bits. run() has checked the arrays against the params; each binding is checked against
    // maxBinding bytes before it is allocated.
    displacementData(params, meshVertices, meshIndices, { texels, directions, tangents }, maxBinding) {
        const C = this.constants;
        const flags = params[C.PARAM_DISPLACEMENT_FLAGS];
        const float = (w) => new Float32Array(Uint32Array.of(params[w]).buffer)[0];
        const [scale, factor, offset, normalStep, bound] = [C.PARAM_DISPLACEMENT_SCALE, C.PARAM_DISPLACEMENT_FACTOR,
            C.PARAM_DISPLACEMENT_OFFSET, C.PARAM_DISPLACEMENT_NORMAL_STEP, C.PARAM_DISPLACEMENT_FACTOR_BOUND].map(float);
        if (![scale, factor, offset, bound].every(Number.isFinite) || !(bound >= 0) || !(normalStep > 0 && normalStep <= 0.5))
            throw new Error('displacement: scale, factor, offset and factorBound must be finite, factorBound >= 0, normalStep in (0, 0.5]');
        const width = params[C.PARAM_HEIGHT_MAP_WIDTH], height = params[C.PARAM_HEIGHT_MAP_HEIGHT];
        const vector = (flags & C.DISPLACEMENT_VECTOR) !== 0;
        const count = width * height * (vector ? 3 : 1); // texel floats
        if (!(texels instanceof Float32Array) || texels.length !== count)
            throw new Error(`displacement: ${texels?.length ?? 'no'} texel floats given for a ${width} x ${height} ` +
                            `${vector ? 'RGB vector map (3 floats a texel)' : 'height map'}`);
        const triangles = params[C.PARAM_PATCH_COUNT] - params[C.PARAM_QUAD_COUNT], quads = params[C.PARAM_QUAD_COUNT];
        const indexWords = 3 * triangles + 4 * quads + (flags & C.DISPLACEMENT_ADJACENCY ? 12 * (triangles + 2 * quads) : 0);
        if (meshIndices.length < indexWords) throw new Error('displacement: the adjacency the params name is not in meshIndices');
        if ((indexWords + count) * 4 > maxBinding)
            throw new Error(`displacement: ${(indexWords + count) * 4} bytes of indices and texels in one storage binding, past the device's ${maxBinding}`);
        const indices = new Uint32Array(indexWords + count);
        indices.set(meshIndices.subarray(0, indexWords));
        indices.set(new Uint32Array(texels.buffer, texels.byteOffset, count), indexWords);
        const withDirections = (flags & C.DISPLACEMENT_DIRECTIONS) !== 0;
        if (!withDirections && !vector) return [meshVertices, indices];
        const meshCount = params[C.PARAM_MESH_VERTEX_COUNT], vertexWords = meshCount * C.MESH_VERTEX_FLOATS;
        const n = withDirections ? 3 * meshCount : 0, nt = vector ? 4 * meshCount : 0;
        if (withDirections && (!(directions instanceof Float32Array) || directions.length < n))
            throw new Error(`displacement: ${directions?.length ?? 'no'} direction floats given for ${meshCount} mesh vertices`);
        if (vector && (!(tangents instanceof Float32Array) || tangents.length < nt))
            throw new Error(`displacement: ${tangents?.length ?? 'no'} tangent floats given for ${meshCount} mesh vertices ` +
                            '(vector displacement needs 4 per vertex)');
        if ((vertexWords + n + nt) * 4 > maxBinding)
            throw new Error(`displacement: ${(vertexWords + n + nt) * 4} bytes of mesh vertices, directions and tangents in one storage binding, past the device's ${maxBinding}`);
        const vertices = new Uint32Array(vertexWords + n + nt);
        vertices.set(new Uint32Array(meshVertices.buffer, meshVertices.byteOffset, vertexWords));
        if (n) vertices.set(new Uint32Array(directions.buffer, directions.byteOffset, n), vertexWords);
        if (nt) vertices.set(new Uint32Array(tangents.buffer, tangents.byteOffset, nt), vertexWords + n);
        return [vertices, indices];
    }

    // Frees the table blobs (the pipelines need no freeing).
    destroy() {
        for (const blob of this.blobs.values()) blob.then(({ tables }) => tables.destroy(), () => {});
        this.blobs.clear();
    }
}
