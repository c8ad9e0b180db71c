// Runs one page module in headless Chromium (WebGL2 through SwiftShader) and writes what it
// returns as JSON. The page is served from local folders only, under https://irid.test/ (no
// network: every request is answered from disk or refused).
//
//   node tests/browser/run_page.mjs --serve NAME=DIR ... --module /NAME/file.js
//        --input in.json --output out.json [--timeout SECONDS] [--page FILE] [--screenshot PNG]
//        [--viewport WxH]
//
// /NAME/... is DIR/...; /web/... is the repository's web/ folder and the import map resolves
// 'three', 'three/webgpu', 'three/tsl' and 'three/addons/' to web/node_modules. The module's `run(input)` is awaited in
// the page; its value is written to out.json. Exits 1 when the module throws, a request fails,
// or the page logs an error; 2 on bad arguments or when Chromium or web/node_modules is
// missing (scripts/install-deps installs both).
// --page FILE opens FILE itself from file:// instead (a page that must work without a server):
// any request it makes is refused and counted as a failure, and the module (read from its
// --serve folder) is imported as a data: URL, since file:// pages load no module from a server.
// --screenshot PNG saves the page as it is after run() returned. --viewport sets the page's size
// in CSS pixels (default 1280x720).
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const webDir = path.resolve(here, '../../web');
const origin = 'https://irid.test';

function usage(message) {
    console.error(`run_page.mjs: ${message}`);
    process.exit(2);
}

function parseArgs(argv) {
    const args = { serve: { web: webDir }, timeout: 300 };
    for (let i = 0; i < argv.length; i += 2) {
        const [key, value] = [argv[i], argv[i + 1]];
        if (value === undefined) usage(`${key} needs a value`);
        if (key === '--serve') {
            const eq = value.indexOf('=');
            if (eq <= 0) usage(`--serve '${value}' is not NAME=DIR`);
            args.serve[value.slice(0, eq)] = path.resolve(value.slice(eq + 1));
        } else if (key === '--module') args.module = value;
        else if (key === '--input') args.input = value;
        else if (key === '--output') args.output = value;
        else if (key === '--timeout') args.timeout = Number(value);
        else if (key === '--page') args.page = path.resolve(value);
        else if (key === '--screenshot') args.screenshot = value;
        else if (key === '--viewport') {
            const m = /^(\d+)x(\d+)$/.exec(value);
            if (!m) usage(`--viewport '${value}' is not WIDTHxHEIGHT`);
            args.viewport = { width: Number(m[1]), height: Number(m[2]) };
        } else usage(`unknown option '${key}' (valid: --serve, --module, --input, --output, --timeout, --page, --screenshot, --viewport)`);
    }
    for (const k of ['module', 'input', 'output']) if (!args[k]) usage(`--${k} is required`);
    return args;
}

function findChromium() {
    for (const dir of (process.env.PATH || '').split(path.delimiter)) {
        for (const name of ['chromium', 'chromium-browser']) {
            const p = path.join(dir, name);
            try {
                fs.accessSync(p, fs.constants.X_OK);
                return p;
            } catch {
                // not here
            }
        }
    }
    return null;
}

const contentTypes = {
    '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript',
    '.json': 'application/json', '.glsl': 'text/plain', '.f32': 'application/octet-stream',
};

const args = parseArgs(process.argv.slice(2));
const playwrightEntry = path.join(webDir, 'node_modules/playwright-core/index.mjs');
if (!fs.existsSync(playwrightEntry) || !fs.existsSync(path.join(webDir, 'node_modules/three'))) {
    usage(`web/node_modules lacks three or playwright-core (${webDir}): run scripts/install-deps`);
}
const chromiumPath = findChromium();
if (!chromiumPath) usage('chromium is not on PATH: run scripts/install-deps');
const { chromium } = await import(pathToFileURL(playwrightEntry).href);

const importMap = {
    imports: {
        three: '/web/node_modules/three/build/three.module.js',
        'three/webgpu': '/web/node_modules/three/build/three.webgpu.js',
        'three/tsl': '/web/node_modules/three/build/three.tsl.js',
        'three/addons/': '/web/node_modules/three/examples/jsm/',
    },
};
const indexHtml = `<!doctype html><html><head><meta charset="utf-8">
<script type="importmap">${JSON.stringify(importMap)}</script></head><body></body></html>`;

// The module's file on disk: /NAME/rest under its --serve folder.
function servedFile(urlPath) {
    const parts = decodeURIComponent(urlPath).split('/').filter(Boolean);
    const root = args.serve[parts[0]];
    const file = root ? path.resolve(root, ...parts.slice(1)) : null;
    return file && file.startsWith(root + path.sep) && fs.existsSync(file) ? file : null;
}

const problems = [];
const browser = await chromium.launch({
    executablePath: chromiumPath,
    headless: true,
    // WebGL 2 through SwiftShader, and WebGPU on SwiftShader's Vulkan adapter.
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
           '--ignore-gpu-blocklist', '--disable-gpu-watchdog', '--enable-unsafe-webgpu',
           '--use-webgpu-adapter=swiftshader'],
});
let status = 0;
try {
    const page = await browser.newPage(args.viewport ? { viewport: args.viewport } : {});
    page.on('console', (m) => {
        if (m.type() === 'error') problems.push(`console error: ${m.text()}`);
        else console.log(`page ${m.type()}: ${m.text()}`);
    });
    page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
    page.on('requestfailed', (r) => problems.push(`failed request: ${r.url().slice(0, 200)} (${r.failure()?.errorText})`));
    await page.route('**/*', async (route) => {
        const url = new URL(route.request().url());
        if (args.page) {
            if (url.href === pathToFileURL(args.page).href) return route.continue();
            problems.push(`refused a request of the page: ${url.href}`);
            return route.abort();
        }
        if (url.origin !== origin) {
            problems.push(`refused a request outside the page: ${url.href}`);
            return route.abort();
        }
        if (url.pathname === '/' || url.pathname === '/index.html') {
            return route.fulfill({ status: 200, contentType: 'text/html', body: indexHtml });
        }
        const file = servedFile(url.pathname);
        if (!file) {
            problems.push(`not found: ${url.pathname}`);
            return route.fulfill({ status: 404, body: '' });
        }
        const type = contentTypes[path.extname(file)] || 'application/octet-stream';
        return route.fulfill({ status: 200, contentType: type, body: fs.readFileSync(file) });
    });
    let module = args.module;
    if (args.page) {
        const file = servedFile(args.module);
        if (!file) throw new Error(`--module ${args.module} is in no --serve folder`);
        module = `data:text/javascript;base64,${fs.readFileSync(file).toString('base64')}`;
        if (!fs.existsSync(args.page)) throw new Error(`--page ${args.page} does not exist`);
        await page.goto(pathToFileURL(args.page).href);
    } else {
        await page.goto(`${origin}/index.html`);
    }
    const input = JSON.parse(fs.readFileSync(args.input, 'utf8'));
    let timer;
    const timeout = new Promise((_, reject) => {
        timer = setTimeout(() => reject(new Error(`the page ran longer than ${args.timeout} s`)),
                           args.timeout * 1000);
    });
    const result = await Promise.race([timeout, page.evaluate(async ({ module, input }) => {
        const m = await import(module);
        return await m.run(input);
    }, { module, input })]);
    clearTimeout(timer);
    if (args.screenshot) await page.screenshot({ path: args.screenshot });
    fs.writeFileSync(args.output, JSON.stringify(result));
} catch (e) {
    // A module given as a data: URL would be spelled out in full in every line of a stack.
    console.error(`run_page.mjs: ${e.message.replace(/data:text\/javascript;base64,[A-Za-z0-9+/=]+/g, '<module>')}`);
    status = 1;
} finally {
    await browser.close();
}
for (const p of problems) console.error(`run_page.mjs: ${p}`);
process.exit(problems.length ? 1 : status);
