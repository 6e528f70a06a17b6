// Pictures through headless chromium (npm playwright-core, the viewer test's flags):
//   node docs/img/snapshot.mjs viewer CTESS OUT.png [QUERY]   screenshot of the viewer served by `CTESS serve`
//   node docs/img/snapshot.mjs png IN.svg WIDTH OUT.png        an SVG as a PNG at WIDTH px (to check by eye)
// Exit status 0, or 1 with a message.
import { spawn } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { chromium } from 'playwright-core';

const [what, ...rest] = process.argv.slice(2);
const fail = (msg) => { console.error(`snapshot: ${msg}`); process.exit(1); };
const browser = await chromium.launch({
    executablePath: process.env.CTESS_CHROMIUM ?? '/usr/bin/chromium', headless: true,
    args: ['--no-sandbox', '--disable-quic', '--disable-background-networking', '--disable-component-update',
           '--disable-sync', '--no-first-run', '--use-angle=vulkan', '--enable-features=Vulkan',
           '--use-vulkan=swiftshader', '--enable-unsafe-webgpu'],
});
try {
    if (what === 'viewer') {
        const [ctess, out, query = '?mode=cp&factors=10.3,6,3'] = rest;
        const server = spawn(ctess, ['serve', '--port', '0'], { stdio: ['ignore', 'pipe', 'inherit'] });
        const base = await new Promise((resolve, reject) => {
            let text = '';
            server.stdout.on('data', (d) => { text += d; const m = text.match(/http:\/\/127\.0\.0\.1:\d+\//); if (m) resolve(m[0]); });
            server.on('exit', (code) => reject(new Error(`ctess serve exited with ${code}`)));
        });
        try {
            const page = await browser.newPage({ viewport: { width: 990, height: 730 } });
            await page.goto(`${base}${query}`);
            await page.waitForFunction(() => window.ctessViewer, null, { timeout: 120000 });
            let state = await page.evaluate(() => window.ctessViewer);
            if (state.error) fail(state.error);
            if (state.view === 'mesh') {
                // Draw once more, so the frame time shown is a steady frame's, not the first one's (which compiles
                // the passes it uses).
                await page.evaluate(() => {
                    const { eye, target } = window.ctessViewer.camera;
                    window.ctessViewer = null;
                    window.ctessViewerSetCamera(eye, target);
                });
                await page.waitForFunction(() => window.ctessViewer, null, { timeout: 120000 });
                state = await page.evaluate(() => window.ctessViewer);
                if (state.error) fail(state.error);
            }
            await page.screenshot({ path: out });
        } finally {
            server.kill();
        }
    } else if (what === 'png') {
        const [svg, width, out] = rest;
        const text = readFileSync(svg, 'utf8');
        const [, w, h] = text.match(/<svg[^>]*width="([\d.]+)"[^>]*height="([\d.]+)"/) ?? fail(`${svg}: no width/height`);
        const height = Math.round((Number(width) * Number(h)) / Number(w));
        const page = await browser.newPage({ viewport: { width: Number(width), height } });
        await page.setContent(`<body style="margin:0"><img src="data:image/svg+xml;base64,${Buffer.from(text).toString('base64')}" width="${width}" height="${height}"></body>`);
        await page.screenshot({ path: out });
    } else {
        fail('usage: snapshot.mjs viewer CTESS OUT.png [QUERY] | png IN.svg WIDTH OUT.png');
    }
} finally {
    await browser.close();
}
