// The WebGPU host's refusals of displacement data that the params do not describe (docs/shaders.md,
// "Displacement") and of welded runs it does not make ("Welded output"), its weld edge list and the sizes of the
// weld by one sort, on Dawn's null backend: run() throws before it dispatches anything, so no driver is needed.
//   node host_checks.mjs SHADER_DIR
// Exit status 0 when every check holds, else 1 with the failed checks.
import { readFileSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import { create, globals } from 'webgpu';

Object.assign(globalThis, globals);
const [dir] = process.argv.slice(2);
const gpu = create(['backend=null']); // kept referenced for the whole run (docs/shaders.md, "Running them")
const adapter = await gpu.requestAdapter();
const { MeshPipeline, requiredLimits, weldEdgeList, weldSortedSizes } = await import(pathToFileURL(`${dir}/ctess_webgpu.mjs`).href);
const device = await adapter.requestDevice({ requiredLimits: requiredLimits(adapter) });
const load = (name) => {
    const bytes = readFileSync(`${dir}/${name}`);
    return Promise.resolve(name.endsWith('.bin') ? bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.length)
                                                 : bytes.toString('utf8'));
};
const pipeline = await MeshPipeline.create(device, { maxFactor: 64, load });
const C = pipeline.constants;

let failed = 0;
const check = (what, ok) => {
    if (!ok) failed++;
    console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
};
const throws = async (what, run, pattern) => {
    try {
        await run();
        check(`${what}: throws`, false);
    } catch (e) {
        check(`${what}: throws "${e.message}"`, pattern.test(e.message));
    }
};

// One triangle of three mesh vertices (position, normal, uv).
const vertices = new Float32Array([0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 0, 1]);
const indices = new Uint32Array([0, 1, 2]);
const base = { patchCount: 1, surface: 'flat', factorScale: 10, eye: [0, 0, 5], meshVertexCount: 3 };
const vector = pipeline.params({ ...base, displacement: { vector: true, width: 2, height: 1 } });
check('params: displacement.vector sets DISPLACEMENT_VECTOR',
      (vector[C.PARAM_DISPLACEMENT_FLAGS] & (C.DISPLACEMENT_ON | C.DISPLACEMENT_VECTOR)) ===
          (C.DISPLACEMENT_ON | C.DISPLACEMENT_VECTOR));
const scalar = pipeline.params({ ...base, displacement: { width: 2, height: 1 } });
check('params: a height map leaves DISPLACEMENT_VECTOR clear', (scalar[C.PARAM_DISPLACEMENT_FLAGS] & C.DISPLACEMENT_VECTOR) === 0);
const tangents = new Float32Array(12);
// Vector mode reads 3 floats a texel: width x height floats are a height map's, not enough.
await throws('vector map given width x height floats', () => pipeline.run(vector, vertices, indices, { texels: new Float32Array(2), tangents }),
             /2 texel floats given for a 2 x 1 RGB vector map/);
await throws('vector map given one float too many', () => pipeline.run(vector, vertices, indices, { texels: new Float32Array(7), tangents }),
             /7 texel floats/);
await throws('height map given 3 floats a texel', () => pipeline.run(scalar, vertices, indices, { texels: new Float32Array(6) }),
             /6 texel floats given for a 2 x 1 height map/);
await throws('vector mode without tangents', () => pipeline.run(vector, vertices, indices, { texels: new Float32Array(6) }),
             /no tangent floats given for 3 mesh vertices/);
await throws('vector mode with 4 x 3 - 1 tangent floats', () => pipeline.run(vector, vertices, indices, { texels: new Float32Array(6), tangents: new Float32Array(11) }),
             /11 tangent floats given for 3 mesh vertices/);
await throws('vector mode with tangents that are not a Float32Array', () => pipeline.run(vector, vertices, indices, { texels: new Float32Array(6), tangents: [0, 0, 0, 1] }),
             /tangent floats/);

// The welded output: the params' weld word, the refusals, rt::weld_edge_list's list (culled faces add none, a
// degenerate face its lo == hi edge, shared edges once, sorted by (lo, hi)) and the weld by one sort's sizes.
const weld = pipeline.params({ ...base, weld: true, keepDegenerate: true });
check('params: weld and keepDegenerate set WELD_ON | WELD_KEEP_DEGENERATE',
      weld[C.PARAM_WELD] === (C.WELD_ON | C.WELD_KEEP_DEGENERATE));
check('params: no weld leaves PARAM_WELD 0', pipeline.params(base)[C.PARAM_WELD] === 0);
// The split pattern is welded (by one sort over the mesh), no longer refused: run() gets past its checks and
// dispatches (the null backend executes nothing, so its readback may fail; the weld itself is test_gpu's Dawn cases).
const splitWeld = await pipeline.run(pipeline.params({ ...base, weld: true, pattern: 'uniform-split' }), vertices, indices)
    .then(() => 'resolved', (e) => e.message);
check(`weld with the uniform-split pattern: not refused (${splitWeld})`, !/uniform-split|not welded/.test(splitWeld));
await throws('weld with a batched emit', () => pipeline.run(weld, vertices, indices, { batchVertices: 1000 }), /one batch/);
// Triangles (2, 1, 0), (0, 2, 3), (1, 1, 4), (0, 1, 9) (culled: 9 >= 5 vertices), quad (3, 2, 4, 0).
const list = weldEdgeList(new Uint32Array([2, 1, 0, 0, 2, 3, 1, 1, 4, 0, 1, 9, 3, 2, 4, 0]), 4, 1, 5);
const expected = [[0, 1], [0, 2], [0, 3], [0, 4], [1, 1], [1, 2], [1, 4], [2, 3], [2, 4]];
check(`weldEdgeList: ${list.length / 4} edges, sorted and distinct`,
      list.length === 4 * expected.length && expected.every(([lo, hi], e) => list[4 * e] === lo && list[4 * e + 1] === hi &&
                                                                          list[4 * e + 2] === 0 && list[4 * e + 3] === 0));
// rt::gpu::weld_sort_records (the slots, or a flag word per unwelded triangle, 4 to a record, where that is more),
// weld_sort_width (the network's: a power of two, at least the records and weld_sort_chunk = 512), weld_rank_blocks
// and weld_sorted_buffer_words, worked out by hand from shader_interface.hpp.
const sizes = (edges, patches, meshVertices, slots, triangles) => weldSortedSizes(C, { edges, patches, meshVertices, slots, triangles });
const header = C.WELD_HEADER_WORDS + 3 * C.WELD_EDGE_WORDS + C.WELD_PATCH_WORDS + 3;
for (const [args, records, width, blocks, words] of [[[3, 1, 3, 1, 1], 1, 512, 1, header + 4 + 4 + 2],
                                                     [[3, 1, 3, 10, 13], 10, 512, 1, header + 40 + 40 + 2],
                                                     [[3, 1, 3, 512, 2048], 512, 512, 1, header + 2048 + 2048 + 2],
                                                     [[3, 1, 3, 100, 2049], 513, 1024, 1, header + 400 + 2052 + 2],
                                                     [[3, 1, 3, 5000, 40000], 10000, 16384, 10, header + 20000 + 40000 + 20],
                                                     [[3, 1, 3, 70000, 4096], 70000, 131072, 18, header + 280000 + 280000 + 36]]) {
    const got = sizes(...args);
    check(`weldSortedSizes(${args.join(', ')}): ${got.records} records, width ${got.width}, ${got.blocks} blocks, ${got.words} words`,
          got.records === records && got.width === width && got.blocks === blocks && got.words === words);
}
device.destroy();
console.log(`${failed ? 'FAILED' : 'passed'}: ${failed} failed`);
process.exit(failed ? 1 : 0);
