// `ctess mesh --backend webgpu` (docs/cli.md, "GPU backends"): runs the generated WGSL mesh pipeline on Dawn in
// Node (npm `webgpu`) through the WebGPU host beside it (ctess_webgpu.mjs, docs/shaders.md "Hosts"), on one job
// file that ctess writes, and writes the output (unwelded, or welded where the params weld) to a result file. Installed beside the shaders.
//   node ctess_mesh_node.mjs JOB_FILE RESULT_FILE
// JOB_FILE, little-endian u32 words: 'CTMN' (0x4E4D5443), version 1, max factor, then the word counts P, V, I, T,
// D, G, then P params words (rt::gpu::pipeline_params), V mesh vertex floats, I index words (the triangles, the
// quads, then the adjacency where the params need it), T texel floats, D direction floats, G tangent floats.
// RESULT_FILE: 'CTMR' (0x524D5443), version 1, the word counts of the records (with the totals; for params that
// weld, the edge list, the welded patch records and the welded totals' vertices, triangles and edges), vertices and
// indices, the run's milliseconds (f32 bits), the adapter's description's byte length, then those arrays and the
// description (UTF-8, zero-padded to 4 bytes).
// Backend: CTESS_DAWN_BACKEND names one (e.g. "opengles", "vulkan"); otherwise Dawn's Vulkan backend (core
// WebGPU) is tried first, then its OpenGL ES backend in compatibility mode with EGL_PLATFORM=surfaceless (Dawn's
// Vulkan backend rejects Debian bookworm's lavapipe: docs/shaders.md, "Running them").
// Exit status: 0; 1 an error (the message on stderr); 3 the mesh is past the pipeline's limits; 4 the npm package
// `webgpu` is not installed; 5 no WebGPU adapter.
import { readFileSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { dirname, join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const fail = (message, status = 1) => {
    console.error(`ctess_mesh_node: ${message}`);
    process.exit(status);
};
const [jobFile, resultFile] = process.argv.slice(2);
if (!jobFile || !resultFile) fail('usage: node ctess_mesh_node.mjs JOB_FILE RESULT_FILE');

// npm `webgpu`: beside this module (a node_modules folder above it), else where CommonJS would find it from the
// working directory (its node_modules folders, NODE_PATH, the global folders).
async function importWebgpu() {
    try {
        return await import('webgpu');
    } catch (first) {
        if (first?.code !== 'ERR_MODULE_NOT_FOUND') throw first;
        try {
            const resolved = createRequire(join(process.cwd(), 'noop.js')).resolve('webgpu');
            return await import(pathToFileURL(resolved).href);
        } catch {
            fail("the npm package 'webgpu' (Dawn for Node) is not installed: run `npm install webgpu` in the " +
                 'folder you run ctess from (or one above it), or set NODE_PATH to a node_modules folder that has it', 4);
        }
    }
    return null;
}
const { create, globals } = await importWebgpu();
Object.assign(globalThis, globals);

const job = new Uint32Array((() => {
    const bytes = readFileSync(jobFile);
    if (bytes.length % 4 !== 0 || bytes.length < 36) fail('the job file is truncated');
    return bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.length);
})());
if (job[0] !== 0x4E4D5443 || job[1] !== 1) fail('the job file is not a version 1 ctess mesh job');
const maxFactor = job[2];
const counts = Array.from(job.subarray(3, 9));
if (9 + counts.reduce((a, b) => a + b, 0) !== job.length) fail('the job file\'s sizes do not add up');
let at = 9;
const take = (n) => job.slice(at, (at += n));
const params = take(counts[0]);
const floats = (words) => new Float32Array(words.buffer);
const vertices = floats(take(counts[1])), indices = take(counts[2]);
const texels = floats(take(counts[3])), directions = floats(take(counts[4])), tangents = floats(take(counts[5]));

// The instances stay referenced for the whole run: collected, one takes Dawn down under the live device
// (docs/shaders.md, "Running them").
const instances = [];
async function adapterFor(backend) {
    if (backend === 'opengles' || backend === 'opengl') process.env.EGL_PLATFORM ??= 'surfaceless';
    const gpu = create([`backend=${backend}`]);
    instances.push(gpu);
    const compat = backend === 'opengles' || backend === 'opengl';
    return gpu.requestAdapter(compat ? { featureLevel: 'compatibility' } : {});
}
const tried = process.env.CTESS_DAWN_BACKEND ? [process.env.CTESS_DAWN_BACKEND] : ['vulkan', 'opengles'];
let adapter = null;
for (const backend of tried) {
    adapter = await adapterFor(backend).catch(() => null);
    if (adapter) break;
}
if (!adapter) fail(`no WebGPU adapter from Dawn's ${tried.join(' or ')} backend`, 5);

const here = dirname(fileURLToPath(import.meta.url));
const { MeshPipeline, requiredLimits } = await import(pathToFileURL(join(here, 'ctess_webgpu.mjs')).href);
const device = await adapter.requestDevice({ requiredLimits: requiredLimits(adapter) });
let deviceError = null;
device.addEventListener('uncapturederror', (e) => { deviceError ??= e.error.message; });
const load = (name) => {
    const bytes = readFileSync(join(here, name));
    return Promise.resolve(name.endsWith('.bin') ? bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.length)
                                                 : bytes.toString('utf8'));
};
try {
    const pipeline = await MeshPipeline.create(device, { maxFactor, load });
    const C = pipeline.constants;
    const displaced = (params[C.PARAM_DISPLACEMENT_FLAGS] & C.DISPLACEMENT_ON) !== 0;
    // The welded output (params' weld flag, docs/shaders.md "Welded output") runs in one batch.
    const welded = (params[C.PARAM_WELD] & C.WELD_ON) !== 0;
    const out = await pipeline.run(params, vertices, indices, {
        ...(welded ? {} : { batchVertices: 1 << 20 }),
        ...(displaced ? { texels, ...(directions.length ? { directions } : {}), ...(tangents.length ? { tangents } : {}) } : {}),
    });
    const outVertices = await pipeline.read(out.vertices, out.vertexCount * C.VERTEX_WORDS);
    const outIndices = await pipeline.read(out.indices, out.triangleCount * 3);
    out.vertices.destroy();
    out.indices.destroy();
    if (deviceError) throw new Error(`WebGPU: ${deviceError}`);
    const info = adapter.info ?? {};
    const name = new TextEncoder().encode(`Dawn ${info.description || info.vendor || 'adapter'}`);
    // Welded: the records are the edge list, the patch records, then the totals' vertices, triangles and edges.
    let records = out.patches;
    if (welded) {
        const { edges, patches } = out.weld;
        records = new Uint32Array(edges.length + patches.length + 3);
        records.set(edges, 0);
        records.set(patches, edges.length);
        records.set([out.weld.vertexCount, out.weld.triangleCount, out.weld.edgeCount], edges.length + patches.length);
    }
    const header = new Uint32Array([0x524D5443, 1, records.length, outVertices.length, outIndices.length, 0, name.length]);
    new Float32Array(header.buffer, 20, 1)[0] = out.milliseconds;
    const words = header.length + records.length + outVertices.length + outIndices.length + Math.ceil(name.length / 4);
    const result = new Uint32Array(words);
    result.set(header, 0);
    result.set(records, header.length);
    result.set(outVertices, header.length + records.length);
    result.set(outIndices, header.length + records.length + outVertices.length);
    new Uint8Array(result.buffer, 4 * (words - Math.ceil(name.length / 4))).set(name);
    writeFileSync(resultFile, result);
} catch (e) {
    fail(e.message, e.pastLimits ? 3 : 1);
}
device.destroy();
process.exit(0);
