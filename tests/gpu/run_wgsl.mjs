// Runs the generated WGSL mesh pipeline (either pattern) on Dawn (npm `webgpu`) and writes every output buffer to a file,
// for one scene or several in turn (the device and pipelines are made once):
//   node run_wgsl.mjs SHADER_DIR MAX_FACTOR SCENE_FILE RESULT_FILE [SCENE_FILE RESULT_FILE ...]
// Backend: Dawn's OpenGL ES backend on Mesa's llvmpipe in compatibility mode, with EGL_PLATFORM=surfaceless
// (Dawn's Vulkan backend rejects bookworm's lavapipe 22.3, docs/shaders.md). CTESS_DAWN_BACKEND
// overrides the backend flag (e.g. "vulkan" on a machine with a newer driver).
// CTESS_MAX_WORKGROUPS caps every dispatch (the passes stride over the rest; default MAX_DISPATCH_WORKGROUPS,
// the one-dispatch limit); CTESS_COUNTS_ONLY=1 runs only the setup and prefix-sum passes and returns no outputs;
// CTESS_SPLIT_CAPACITY and CTESS_MAX_SPLIT_CAPACITY are run()'s splitCapacity and maxSplitCapacity (0: defaults).
// A scene whose params weld (PARAM_WELD's WELD_ON; docs/shaders.md, "Welded output") runs welded, in one batch, and
// its result's records are the weld's: the edges' words, the patches' words, then the welded vertex, triangle and
// edge totals (run_cpu_welded's shape, tests/gpu/pipeline_output.hpp).
// The passes run through the installed host module ctess_webgpu.mjs beside the shaders (docs/shaders.md,
// "Hosts"), which takes every layout number from the generated ctess_mesh_<max>.layout.json. File formats: tests/gpu/gpu_pipeline.cpp. Exit status 0, or 1 with a message (also when the mesh's totals do
// not fit in 32 bits: the prefix sum then writes 0xFFFFFFFF).
import { readFileSync, writeFileSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import { create, globals } from 'webgpu';

Object.assign(globalThis, globals);
const fail = (msg) => { console.error(`run_wgsl: ${msg}`); process.exit(1); };
const [dir, max, ...files] = process.argv.slice(2);
if (files.length === 0 || files.length % 2 !== 0)
    fail('usage: node run_wgsl.mjs SHADER_DIR MAX_FACTOR SCENE_FILE RESULT_FILE [SCENE_FILE RESULT_FILE ...]');
process.env.EGL_PLATFORM ??= 'surfaceless';
const backend = process.env.CTESS_DAWN_BACKEND ?? 'opengles';
// The instance stays referenced for the whole run: collected (it is not needed after requestAdapter), it
// takes Dawn down under the live device, aborting node at random (futex errors, segfaults).
const gpu = create([`backend=${backend}`]);
const adapter = await gpu.requestAdapter({ featureLevel: 'compatibility' });
if (!adapter) fail(`no Dawn adapter for backend=${backend} (Mesa's EGL/GLES on llvmpipe are needed)`);
// The installed host module beside the shaders (docs/shaders.md, "Hosts") drives every pass.
const { MeshPipeline, requiredLimits } = await import(pathToFileURL(`${dir}/ctess_webgpu.mjs`).href);
const device = await adapter.requestDevice({ requiredLimits: requiredLimits(adapter) });
let deviceError = null;
device.addEventListener('uncapturederror', (e) => { deviceError ??= e.error.message; });

const load = (name) => {
    const bytes = readFileSync(`${dir}/${name}`);
    return Promise.resolve(name.endsWith('.bin') ? bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.length)
                                                 : bytes.toString('utf8'));
};
const pipeline = await MeshPipeline.create(device, { maxFactor: Number(max), load }).catch((e) => fail(e.message));
const C = pipeline.constants;
const countsOnly = process.env.CTESS_COUNTS_ONLY === '1';
const info = adapter.info ?? {};
for (let job = 0; job < files.length; job += 2) {
    // (A small file's Buffer is a view into Node's shared pool: copy its own bytes, not the pool's.)
    const bytes = readFileSync(files[job]);
    const scene = new Uint32Array(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.length));
    if (scene[0] !== 0x43535443 || scene[1] !== 3) fail('bad scene file');
    const sizes = 2 + C.PARAMS_WORDS;
    const params = scene.slice(2, sizes);
    const vertexFloats = scene[sizes], indexCount = scene[sizes + 1];
    let meshVertices = scene.slice(sizes + 2, sizes + 2 + vertexFloats);
    let meshIndices = scene.slice(sizes + 2 + vertexFloats, sizes + 2 + vertexFloats + indexCount);
    // Displacement: the scene's vertex floats end with the directions and in vector mode the tangents, its index
    // words with the texels (gpu_scenes.hpp); the host takes them as run()'s texels, directions and tangents.
    const displacement = {};
    const flags = params[C.PARAM_DISPLACEMENT_FLAGS];
    if (flags & C.DISPLACEMENT_ON) {
        const vector = (flags & C.DISPLACEMENT_VECTOR) !== 0;
        const texelFloats = params[C.PARAM_HEIGHT_MAP_WIDTH] * params[C.PARAM_HEIGHT_MAP_HEIGHT] * (vector ? 3 : 1);
        displacement.texels = new Float32Array(meshIndices.slice(meshIndices.length - texelFloats).buffer);
        meshIndices = meshIndices.slice(0, meshIndices.length - texelFloats);
        const count = params[C.PARAM_MESH_VERTEX_COUNT], own = count * C.MESH_VERTEX_FLOATS;
        const directionFloats = flags & C.DISPLACEMENT_DIRECTIONS ? 3 * count : 0;
        if (directionFloats) displacement.directions = new Float32Array(meshVertices.slice(own, own + directionFloats).buffer);
        if (vector) displacement.tangents = new Float32Array(meshVertices.slice(own + directionFloats).buffer);
        meshVertices = meshVertices.slice(0, own);
    }
    const n = params[C.PARAM_PATCH_COUNT];
    const welded = (params[C.PARAM_WELD] & C.WELD_ON) !== 0;
    // Emit in batches of about 128k vertices, one submit each (the emit passes' patch range), as a host that streams
    // a large mesh would; a welded run in one.
    let out;
    try {
        out = await pipeline.run(params, meshVertices, meshIndices, {
            maxWorkgroups: Number(process.env.CTESS_MAX_WORKGROUPS ?? C.MAX_DISPATCH_WORKGROUPS), countsOnly,
            batchVertices: welded ? undefined : 1 << 17,
            splitCapacity: Number(process.env.CTESS_SPLIT_CAPACITY ?? 0), maxSplitCapacity: Number(process.env.CTESS_MAX_SPLIT_CAPACITY ?? 0),
            ...displacement });
    } catch (e) {
        console.error(`run_wgsl: ${e.message}`);
        process.exit(e.pastLimits ? 3 : 1);
    }
    const vertices = countsOnly ? new Uint32Array(0) : await pipeline.read(out.vertices, out.vertexCount * C.VERTEX_WORDS);
    const indices = countsOnly ? new Uint32Array(0) : await pipeline.read(out.indices, out.triangleCount * 3);
    out.vertices?.destroy();
    out.indices?.destroy();
    if (deviceError) fail(deviceError);
    const ms = out.milliseconds;
    let patches = out.patches;
    if (welded) {
        const w = out.weld;
        patches = new Uint32Array(w.edges.length + w.patches.length + 3);
        patches.set(w.edges, 0);
        patches.set(w.patches, w.edges.length);
        patches.set([w.vertexCount, w.triangleCount, w.edgeCount], w.edges.length + w.patches.length);
    }

    const header = new Uint32Array([0x4F475443, patches.length, vertices.length, indices.length, 0]);
    new Float32Array(header.buffer, 16, 1)[0] = ms;
    const result = new Uint32Array(header.length + patches.length + vertices.length + indices.length);
    result.set(header, 0);
    result.set(patches, header.length);
    result.set(vertices, header.length + patches.length);
    result.set(indices, header.length + patches.length + vertices.length);
    writeFileSync(files[job + 1], result);
    console.log(`run_wgsl: ${info.description ?? backend}: ${n} patches, ${out.vertexCount} vertices, ${out.triangleCount} triangles${welded ? ' (welded)' : ''}, ${ms.toFixed(2)} ms`);
}
device.destroy();
process.exit(0);
