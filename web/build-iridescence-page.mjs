// Builds the gallery's iridescence page: DIR/iridescence.html, one file that runs from file://
// without a network, and DIR/iridescence/, the chunk and table `irid shader` wrote for it.
//
//   node web/build-iridescence-page.mjs --irid PATH-TO-IRID -o DIR
//
// Chromium loads no module script from file:// (CORS), and fetch() cannot read files there, so
// everything the page runs is inside it: web/iridescence.html is the template; its <head> gets an
// import map whose entries are data: URLs of three.js (build/three.module.js and the
// build/three.core.js it imports), the two addons the page uses and web/irid-three.js, and the
// table as JSON (the .f32 texels in base64); its <body> gets web/iridescence-page.js as an
// inline module. three.module.js imports './three.core.js', which cannot be resolved from a data:
// URL: that one specifier is rewritten to the bare 'three/build/three.core.js' of the import map.
// scripts/run runs this after `irid gallery`; tests/browser/iridescence_page_test.py runs it too.
// Exits 1 when irid or a file fails, 2 on bad arguments.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const three = path.join(here, 'node_modules/three');

function usage(message) {
    console.error(`build-iridescence-page.mjs: ${message}\nusage: node web/build-iridescence-page.mjs --irid PATH -o DIR`);
    process.exit(2);
}

function fail(message) {
    console.error(`build-iridescence-page.mjs: ${message}`);
    process.exit(1);
}

const args = {};
const argv = process.argv.slice(2);
for (let i = 0; i < argv.length; i += 2) {
    const [key, value] = [argv[i], argv[i + 1]];
    if (value === undefined) usage(`${key} needs a value`);
    if (key === '--irid') args.irid = value;
    else if (key === '-o' || key === '--output') args.dir = value;
    else usage(`unknown option '${key}' (valid: --irid, -o)`);
}
if (!args.irid) usage('--irid is required');
if (!args.dir) usage('-o is required');
if (!fs.existsSync(path.join(three, 'build/three.module.js'))) {
    fail(`${three} is missing: run scripts/install-deps (npm ci in web/)`);
}

const read = (file) => {
    try {
        return fs.readFileSync(file, 'utf8');
    } catch (e) {
        return fail(`cannot read ${file}: ${e.message}`);
    }
};

// irid's chunk and table, into DIR/iridescence/ (the page links the folder).
const dir = path.resolve(args.dir);
const shaderDir = path.join(dir, 'iridescence');
try {
    fs.mkdirSync(dir, { recursive: true });
    execFileSync(path.resolve(args.irid), ['shader', '--lang', 'glsl', '-o', shaderDir], { stdio: ['ignore', 'ignore', 'inherit'] });
} catch (e) {
    fail(`irid shader --lang glsl -o ${shaderDir} failed: ${e.message}`);
}
const meta = JSON.parse(read(path.join(shaderDir, 'irid_film_table.json')));
const table = {
    glsl: read(path.join(shaderDir, 'irid_iridescence.glsl')),
    data: fs.readFileSync(path.join(shaderDir, 'irid_film_table.f32')).toString('base64'),
    width: meta.width, height: meta.height, filter: meta.filter, uniform: meta.uniform,
    illuminant: meta.illuminant, space: meta.space, primaries: meta.primaries, white: meta.white,
};

// The modules, each a data: URL in the import map.
const coreImport = "from './three.core.js'";
const threeModule = read(path.join(three, 'build/three.module.js'));
if (!threeModule.includes(coreImport)) fail(`three.module.js no longer has ${coreImport}: update this builder`);
const modules = {
    three: threeModule.replaceAll(coreImport, "from 'three/build/three.core.js'"),
    'three/build/three.core.js': read(path.join(three, 'build/three.core.js')),
    'three/addons/controls/OrbitControls.js': read(path.join(three, 'examples/jsm/controls/OrbitControls.js')),
    'three/addons/environments/RoomEnvironment.js': read(path.join(three, 'examples/jsm/environments/RoomEnvironment.js')),
    // Relative to the page, as iridescence-page.js imports it.
    './irid-three.js': read(path.join(here, 'irid-three.js')),
};
const pageModule = read(path.join(here, 'iridescence-page.js'));
for (const [name, text] of [...Object.entries(modules), ['iridescence-page.js', pageModule]]) {
    // A module importing anything but these (a relative file) would fail in the page.
    for (const m of text.matchAll(/\bfrom\s*['"]([^'"]+)['"]/g)) {
        if (!(m[1] in modules)) fail(`${name} imports '${m[1]}', which the page does not carry`);
    }
}
const importMap = { imports: {} };
for (const [name, text] of Object.entries(modules)) {
    importMap.imports[name] = `data:text/javascript;base64,${Buffer.from(text).toString('base64')}`;
}

// JSON inside <script>: '<' escaped, so that no '</script' can end the element early.
const scriptJson = (value) => JSON.stringify(value).replaceAll('<', '\\u003c');
if (/<\/script/i.test(pageModule)) fail("iridescence-page.js contains '</script', which would end its element");

const template = read(path.join(here, 'iridescence.html'));
const markers = ['<!--IRID:HEAD-->', '<!--IRID:MODULE-->'];
for (const m of markers) {
    if (template.split(m).length !== 2) fail(`web/iridescence.html must hold ${m} exactly once`);
}
const html = template
    .replace(markers[0], () => `<script type="importmap">${scriptJson(importMap)}</script>\n` +
                               `<script type="application/json" id="irid-table">${scriptJson(table)}</script>`)
    .replace(markers[1], () => `<script type="module">\n${pageModule}</script>`);

// Written under a temporary name and renamed when complete.
const out = path.join(dir, 'iridescence.html');
const temporary = `${out}.tmp-${process.pid}`;
try {
    fs.writeFileSync(temporary, html);
    fs.renameSync(temporary, out);
} catch (e) {
    fail(`cannot write ${out}: ${e.message}`);
}
console.log(out);
