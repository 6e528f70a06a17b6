// Runs the generated WGSL mesh pipeline (either pattern) on Dawn (npm `webgpu`) and writes every output buffer to a file.
//   node run_wgsl.mjs SHADER_DIR MAX_FACTOR SCENE_FILE RESULT_FILE
// Backend: Dawn's OpenGL ES backend on Mesa's llvmpipe in compatibility mode, with EGL_PLATFORM=surfaceless
// (Dawn's Vulkan backend rejects bookworm's lavapipe 22.3, docs/shaders.md). CTESS_DAWN_BACKEND
// overrides the backend flag (e.g. "vulkan" on a machine with a newer driver).
// CTESS_MAX_WORKGROUPS caps every dispatch (the passes stride over the rest; default MAX_DISPATCH_WORKGROUPS,
// the one-dispatch limit); CTESS_COUNTS_ONLY=1 runs only the setup and prefix-sum passes and returns no outputs.
// Every layout number (params words, record and vertex words, workgroup sizes, limits) comes from the generated
// ctess_mesh_<max>.layout.json (docs/shaders.md, "Generated constants"). File formats: tests/gpu/gpu_pipeline.cpp. Exit status 0, or 1 with a message (also when the mesh's totals do
// not fit in 32 bits: the prefix sum then writes 0xFFFFFFFF).
import { readFileSync, writeFileSync } from 'node:fs';
import { create, globals } from 'webgpu';

Object.assign(globalThis, globals);
const fail = (msg) => { console.error(`run_wgsl: ${msg}`); process.exit(1); };
const [dir, max, scenePath, resultPath] = process.argv.slice(2);
if (!resultPath) fail('usage: node run_wgsl.mjs SHADER_DIR MAX_FACTOR SCENE_FILE RESULT_FILE');
process.env.EGL_PLATFORM ??= 'surfaceless';
const backend = process.env.CTESS_DAWN_BACKEND ?? 'opengles';
// The instance stays referenced for the whole run: collected (it is not needed after requestAdapter), it
// takes Dawn down under the live device, aborting node at random (futex errors, segfaults).
const gpu = create([`backend=${backend}`]);
const adapter = await gpu.requestAdapter({ featureLevel: 'compatibility' });
if (!adapter) fail(`no Dawn adapter for backend=${backend} (Mesa's EGL/GLES on llvmpipe are needed)`);
const limits = adapter.limits;
const device = await adapter.requestDevice({
    requiredLimits: {
        maxStorageBuffersPerShaderStage: limits.maxStorageBuffersPerShaderStage,
        maxStorageBufferBindingSize: limits.maxStorageBufferBindingSize,
        maxBufferSize: limits.maxBufferSize,
    },
});
let deviceError = null;
device.addEventListener('uncapturederror', (e) => { deviceError ??= e.error.message; });

const layoutJson = JSON.parse(readFileSync(`${dir}/ctess_mesh_${max}.layout.json`, 'utf8'));
const C = layoutJson.constants;
const scene = new Uint32Array(readFileSync(scenePath).buffer.slice(0));
if (scene[0] !== 0x43535443 || scene[1] !== 3) fail('bad scene file');
const sizes = 2 + C.PARAMS_WORDS;
const params = scene.slice(2, sizes);
const vertexFloats = scene[sizes], indexCount = scene[sizes + 1];
const meshVertices = scene.slice(sizes + 2, sizes + 2 + vertexFloats);
const meshIndices = scene.slice(sizes + 2 + vertexFloats, sizes + 2 + vertexFloats + indexCount);
const uniformPattern = params[C.PARAM_PATTERN] === C.PATTERN_UNIFORM;
const n = params[C.PARAM_PATCH_COUNT];
const maxGroups = Number(process.env.CTESS_MAX_WORKGROUPS ?? C.MAX_DISPATCH_WORKGROUPS);
const countsOnly = process.env.CTESS_COUNTS_ONLY === '1';
const recordWords = C.PATCH_WORDS;
const vertexCountWord = C.REC_VERTEX_COUNT, triangleCountWord = C.REC_TRIANGLE_COUNT;
// The pipeline's limits (runtime/include/ctess/runtime/pipeline/mesh_pipeline.hpp): past them, exit status 3.
const { max_patches: maxPatches, max_vertices: maxVertices, max_triangles: maxTriangles } = layoutJson.limits;
const pastLimits = (msg) => { console.error(`run_wgsl: ${msg}: past the pipeline's limits (${maxPatches} patches, ` +
                                            `${maxVertices} vertices, ${maxTriangles} triangles)`); process.exit(3); };
if (n > maxPatches) pastLimits(`${n} patches`);
// The CP blob serves the CP pattern; the uniform pattern needs the blob with the uniform sections.
const tables = new Uint32Array(readFileSync(`${dir}/ctess_mesh_${max}${uniformPattern ? '.uniform' : ''}.tables.bin`).buffer.slice(0));

device.pushErrorScope('validation');
const module = device.createShaderModule({ code: readFileSync(`${dir}/ctess_mesh_${max}.wgsl`, 'utf8') });
for (const m of (await module.getCompilationInfo()).messages) if (m.type === 'error') fail(`WGSL ${m.lineNum}:${m.linePos}: ${m.message}`);
const entries = [];
for (let i = 0; i < 7; i++) {
    entries.push({ binding: i, visibility: GPUShaderStage.COMPUTE, buffer: { type: i < 4 ? 'read-only-storage' : 'storage' } });
}
const layout = device.createBindGroupLayout({ entries });
const pipelineLayout = device.createPipelineLayout({ bindGroupLayouts: [layout] });
const pipeline = (entryPoint) => device.createComputePipeline({ layout: pipelineLayout, compute: { module, entryPoint } });
const entry = Object.fromEntries(layoutJson.passes.map((p) => [p.name, p]));
const setup = pipeline(entry.patch_setup.entry), scan = pipeline(entry.prefix_sum.entry);
const emitV = pipeline(entry.emit_vertices.entry), emitT = pipeline(entry.emit_triangles.entry);
const creationError = await device.popErrorScope();
if (creationError) fail(creationError.message);

const storage = (words, data) => {
    const buffer = device.createBuffer({
        size: Math.max(16, words * 4),
        usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC | GPUBufferUsage.COPY_DST,
    });
    if (data) device.queue.writeBuffer(buffer, 0, data);
    return buffer;
};
const read = async (buffer, words) => {
    const staging = device.createBuffer({ size: Math.max(16, words * 4), usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });
    const enc = device.createCommandEncoder();
    enc.copyBufferToBuffer(buffer, 0, staging, 0, Math.max(16, words * 4));
    device.queue.submit([enc.finish()]);
    await staging.mapAsync(GPUMapMode.READ);
    const out = new Uint32Array(staging.getMappedRange().slice(0, words * 4));
    staging.unmap();
    staging.destroy();
    return out;
};
const run = async (buffers, dispatches) => {
    const bindGroup = device.createBindGroup({ layout, entries: buffers.map((buffer, binding) => ({ binding, resource: { buffer } })) });
    const enc = device.createCommandEncoder();
    for (const [p, groups] of dispatches) {
        const pass = enc.beginComputePass();
        pass.setPipeline(p);
        pass.setBindGroup(0, bindGroup);
        pass.dispatchWorkgroups(groups);
        pass.end();
    }
    const start = performance.now();
    device.queue.submit([enc.finish()]);
    await device.queue.onSubmittedWorkDone();
    return performance.now() - start;
};

const bParams = storage(params.length, params), bTables = storage(tables.length, tables);
const bMesh = storage(meshVertices.length, meshVertices), bIndices = storage(meshIndices.length, meshIndices);
const patchWords = n * recordWords + C.TOTALS_WORDS;
const bPatches = storage(patchWords), bNone = storage(4), bNone2 = storage(4);
let ms = await run([bParams, bTables, bMesh, bIndices, bPatches, bNone, bNone2], [[setup, Math.min(Math.ceil(n / entry.patch_setup.workgroup_size), maxGroups)], [scan, 1]]);
const patches = await read(bPatches, patchWords);
const totalV = countsOnly ? 0 : patches[n * recordWords], totalT = countsOnly ? 0 : patches[n * recordWords + 1];
// The u32 totals wrap (the shader then writes 0xFFFFFFFF): recount them exactly (JS numbers) before sizing the
// output buffers.
if (!countsOnly) {
    let sumV = 0, sumT = 0;
    for (let t = 0; t < n; t++) { sumV += patches[t * recordWords + vertexCountWord]; sumT += patches[t * recordWords + triangleCountWord]; }
    if (sumV > maxVertices || sumT > maxTriangles) pastLimits(`${sumV} vertices, ${sumT} triangles`);
}
const maxBinding = limits.maxStorageBufferBindingSize;
if (totalV * C.VERTEX_WORDS * 4 > maxBinding || totalT * 12 > maxBinding) {
    fail(`${totalV} vertices / ${totalT} triangles need more than ${maxBinding} bytes in one storage binding`);
}
const bVertices = storage(totalV * C.VERTEX_WORDS), bOut = storage(totalT * 3);
// Emit in batches of about 128k vertices, one submit each: the emit passes' patch range (PARAM_FIRST_PATCH and
// PARAM_END_PATCH), as a host that streams a large mesh would use it.
const batchVertices = 1 << 17;
for (let first = 0; first < (countsOnly ? 0 : n);) {
    let end = first, vertices = 0;
    while (end < n && (end === first || vertices + patches[end * recordWords + vertexCountWord] <= batchVertices)) vertices += patches[recordWords * end++ + vertexCountWord];
    params[C.PARAM_FIRST_PATCH] = first;
    params[C.PARAM_END_PATCH] = end;
    device.queue.writeBuffer(bParams, 0, params);
    const groups = Math.min(end - first, maxGroups);
    ms += await run([bParams, bTables, bMesh, bIndices, bPatches, bVertices, bOut], [[emitV, groups], [emitT, groups]]);
    first = end;
}
const vertices = await read(bVertices, totalV * C.VERTEX_WORDS);
const indices = await read(bOut, totalT * 3);
if (deviceError) fail(deviceError);

const header = new Uint32Array([0x4F475443, patches.length, vertices.length, indices.length, 0]);
new Float32Array(header.buffer, 16, 1)[0] = ms;
const result = new Uint32Array(header.length + patches.length + vertices.length + indices.length);
result.set(header, 0);
result.set(patches, header.length);
result.set(vertices, header.length + patches.length);
result.set(indices, header.length + patches.length + vertices.length);
writeFileSync(resultPath, result);
const info = adapter.info ?? {};
console.log(`run_wgsl: ${info.description ?? backend}: ${n} patches, ${totalV} vertices, ${totalT} triangles, ${ms.toFixed(2)} ms`);
device.destroy();
process.exit(0);
