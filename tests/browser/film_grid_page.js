// The page of tests/browser/film_grid_test.py: evaluates three.js's stock evalIridescence and
// irid's chunk on parameter grids, and times both on a full-screen quad.
//
// input: {grids: {name: URL of float32 parameter sets, 7 a set (see web/film-grid.js)},
//         table: URL of the folder `irid shader --lang glsl` wrote, or null,
//         wgsl: URL of the folder `irid shader --lang wgsl` wrote, or null (evaluated in WebGPU),
//         timing: {size, frames, warmup} or null}
// returns: {renderer, extensions, webgpu, grids: {name: {stock: [r, g, b, ...], gltf: [...], irid: [...],
//           wgsl: [...]}},
//           timing: {stock: {median, frames}, irid: {...}}}
import * as THREE from 'three';
import { createContext, renderGrid, stockChunk, timeChunks } from '/web/film-grid.js';
import { loadIridTable } from '/web/irid-three.js';
import { evaluateWgsl, webgpuDevice } from '/web/film-grid-webgpu.js';

async function floats(url) {
    const response = await fetch(url);
    if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
    return new Float32Array(await response.arrayBuffer());
}

export async function run(input) {
    const gl = createContext();
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    const out = {
        three: THREE.REVISION,
        renderer: gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER),
        extensions: ['EXT_color_buffer_float', 'OES_texture_float_linear'].filter((e) => gl.getExtension(e)),
        grids: {},
    };
    // stock: three.js as it ships; gltf: the same with the glTF Sample Renderer's Schlick factor.
    const chunks = { stock: stockChunk(THREE.ShaderChunk),
                     gltf: stockChunk(THREE.ShaderChunk, { schlick: 'pow5' }) };
    if (input.table) {
        const table = await loadIridTable(input.table);
        chunks.irid = { glsl: table.glsl, table };
        out.table = { width: table.width, height: table.height, filter: table.filter };
    }
    let wgsl = null;
    if (input.wgsl) {
        const { device, adapter } = await webgpuDevice();
        out.webgpu = adapter;
        wgsl = { device, text: await (await fetch(`${input.wgsl}irid_iridescence.wgsl`)).text(),
                 table: await loadIridTable(input.table) };
    }
    for (const [name, url] of Object.entries(input.grids)) {
        const params = await floats(url);
        out.grids[name] = {};
        for (const [chunkName, chunk] of Object.entries(chunks)) {
            out.grids[name][chunkName] = Array.from(renderGrid(gl, chunk, params, chunkName));
        }
        if (wgsl) out.grids[name].wgsl = Array.from(await evaluateWgsl(wgsl.device, wgsl.text, wgsl.table, params));
    }
    if (input.timing) {
        const timed = { stock: chunks.stock };
        if (chunks.irid) timed.irid = chunks.irid;
        out.timing = timeChunks(gl, timed, input.timing);
    }
    return out;
}
