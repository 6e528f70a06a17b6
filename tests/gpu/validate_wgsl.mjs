// Validates WGSL files with Dawn's null backend (npm `webgpu`): Tint compiles each module and a compute pipeline
// is created for every listed entry point, with nothing executed and no driver needed.
//   node validate_wgsl.mjs FILE.wgsl [ENTRY ...]
// Without entries, those of the generated FILE's layout.json (ctess_mesh_<max>.layout.json, its "passes").
// Exit status: 0 when every file and entry point is valid, 1 otherwise (messages as file:line:col), 2 for usage.
import { existsSync, readFileSync } from 'node:fs';
import { create, globals } from 'webgpu';

Object.assign(globalThis, globals);
const [file, ...entries] = process.argv.slice(2);
const layoutFile = file?.replace(/\.wgsl$/, '.layout.json');
if (file && entries.length === 0 && existsSync(layoutFile))
    entries.push(...JSON.parse(readFileSync(layoutFile, 'utf8')).passes.map((p) => p.entry));
if (!file || entries.length === 0) {
    console.error('usage: node validate_wgsl.mjs FILE.wgsl [ENTRY ...] (no entries: FILE.layout.json has none)');
    process.exit(2);
}
// Kept referenced: a collected instance takes Dawn down under the live device (run_wgsl.mjs).
const gpu = create(['backend=null']);
const adapter = await gpu.requestAdapter();
if (!adapter) {
    console.error('no Dawn null adapter');
    process.exit(1);
}
const device = await adapter.requestDevice({
    requiredLimits: { maxStorageBuffersPerShaderStage: adapter.limits.maxStorageBuffersPerShaderStage },
});
device.addEventListener('uncapturederror', () => {});
let failed = 0;
device.pushErrorScope('validation');
const module = device.createShaderModule({ code: readFileSync(file, 'utf8') });
const info = await module.getCompilationInfo();
for (const m of info.messages) {
    console.log(`${file}:${m.lineNum}:${m.linePos}: ${m.type}: ${m.message}`);
    if (m.type === 'error') failed++;
}
const moduleError = await device.popErrorScope();
if (moduleError && failed === 0) {
    console.log(`${file}: ${moduleError.message.split('\n')[0]}`);
    failed++;
}
if (failed === 0) {
    for (const entry of entries) {
        device.pushErrorScope('validation');
        device.createComputePipeline({ layout: 'auto', compute: { module, entryPoint: entry } });
        const err = await device.popErrorScope();
        if (err) {
            failed++;
            console.log(`${file}: entry ${entry}: ${err.message.split('\n')[0]}`);
        } else {
            console.log(`ok   ${file} ${entry}`);
        }
    }
}
device.destroy();
console.log(failed ? `FAILED ${file}: ${failed} error(s)` : `valid ${file}`);
process.exit(failed ? 1 : 0);
