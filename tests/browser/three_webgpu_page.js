// The page of tests/browser/three_webgpu_test.py: irid's TSL node (web/irid-three-webgpu.js) in
// three.js's WebGPURenderer on Chromium's WebGPU.
//
// 1. The node on parameter sets: a full-screen quad whose fragment is the node's colour, the
//    parameters of pixel (i, row) read from two RGBA32F textures, into an RGBA32F target.
// 2. A MeshPhysicalNodeMaterial sphere patched by applyIridescenceNode and the same unpatched,
//    black base, metalness 0, lit by a directional light from an orthographic camera along −z.
//
// input: {wgsl: URL of the folder `irid shader --lang wgsl` wrote, params: URL of float32 sets (7 a
//         set: outsideIOR, eta2, cosTheta1, thickness, baseF0 r, g, b), sphere: {size, filmIOR,
//         baseIOR, thicknessMaximum, samples: [[px, py], ...]}}
// returns: {backend, grid: [r, g, b, ...], sphere: {patched, unpatched, clone}: lists of [r, g, b]}
import * as THREE from 'three/webgpu';
import { float, ivec2, screenCoordinate, textureLoad, vec3, vec4 } from 'three/tsl';
import { loadIridTable } from '/web/irid-three.js';
import { applyIridescenceNode, iridescenceNode } from '/web/irid-three-webgpu.js';

const WIDTH = 1024;

async function floats(url) {
    const response = await fetch(url);
    if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
    return new Float32Array(await response.arrayBuffer());
}

function floatTexture(data, width, height) {
    const t = new THREE.DataTexture(data, width, height, THREE.RGBAFormat, THREE.FloatType);
    t.minFilter = t.magFilter = THREE.NearestFilter;
    t.generateMipmaps = false;
    t.needsUpdate = true;
    return t;
}

async function grid(renderer, table, params) {
    const count = params.length / 7;
    const height = Math.ceil(count / WIDTH);
    const a = new Float32Array(WIDTH * height * 4);
    const b = new Float32Array(WIDTH * height * 4);
    for (let i = 0; i < count; ++i) {
        for (let k = 0; k < 4; ++k) a[4 * i + k] = params[7 * i + k];
        for (let k = 0; k < 3; ++k) b[4 * i + k] = params[7 * i + 4 + k];
    }
    const texA = floatTexture(a, WIDTH, height);
    const texB = floatTexture(b, WIDTH, height);
    const node = iridescenceNode(table);
    const at = ivec2(screenCoordinate.xy);
    const pa = textureLoad(texA, at);
    const pb = textureLoad(texB, at);
    const material = new THREE.MeshBasicNodeMaterial();
    material.fragmentNode = vec4(node.fn(pa.x, pa.y, pa.z, pa.w, vec3(pb.x, pb.y, pb.z)), float(1.0));
    const target = new THREE.RenderTarget(WIDTH, height, { type: THREE.FloatType, format: THREE.RGBAFormat });
    const quad = new THREE.QuadMesh(material);
    renderer.setRenderTarget(target);
    quad.render(renderer);
    renderer.setRenderTarget(null);
    const pixels = await renderer.readRenderTargetPixelsAsync(target, 0, 0, WIDTH, height);
    const out = new Float32Array(3 * count);
    // The target's rows are read bottom-up as rendered: pixel (x, y) of the quad is row y.
    for (let i = 0; i < count; ++i) for (let k = 0; k < 3; ++k) out[3 * i + k] = pixels[4 * i + k];
    for (const t of [texA, texB, node.texture]) t.dispose();
    target.dispose();
    material.dispose();
    return out;
}

async function sphere(renderer, table, input) {
    const size = input.size;
    const target = new THREE.RenderTarget(size, size, { type: THREE.FloatType, format: THREE.RGBAFormat,
                                                        depthBuffer: true });
    const camera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0.1, 10);
    camera.position.set(0, 0, 5);
    camera.lookAt(0, 0, 0);
    const geometry = new THREE.SphereGeometry(1, 256, 128);
    const make = (patched) => {
        const m = new THREE.MeshPhysicalNodeMaterial({
            color: 0x000000, metalness: 0, roughness: 0.5, ior: input.baseIOR, iridescence: 1,
            iridescenceIOR: input.filmIOR, iridescenceThicknessMinimum: 0,
            iridescenceThicknessMaximum: input.thicknessMaximum,
        });
        if (patched) applyIridescenceNode(m, { table });
        return m;
    };
    const render = async (material) => {
        const scene = new THREE.Scene();
        scene.add(new THREE.Mesh(geometry, material));
        const light = new THREE.DirectionalLight(0xffffff, 3.0);
        light.position.set(0, 0, 5);
        scene.add(light);
        renderer.setRenderTarget(target);
        renderer.setClearColor(0x000000, 0);
        renderer.render(scene, camera);
        renderer.setRenderTarget(null);
        const pixels = await renderer.readRenderTargetPixelsAsync(target, 0, 0, size, size);
        return input.samples.map(([x, y]) => {
            const i = 4 * (y * size + x);
            return [pixels[i], pixels[i + 1], pixels[i + 2]];
        });
    };
    const patched = make(true);
    const plain = make(false);
    plain.iridescence = 0;
    console.log('no film', JSON.stringify(await render(plain)));
    const u = make(false);
    console.log('unpatched first', JSON.stringify(await render(u)));
    return { patched: await render(patched), unpatched: await render(make(false)),
             clone: await render(patched.clone()) };
}

export async function run(input) {
    const renderer = new THREE.WebGPURenderer({ antialias: false });
    await renderer.init();
    const out = { backend: renderer.backend.isWebGPUBackend ? 'WebGPU' : 'WebGL 2 (fallback)' };
    if (!renderer.backend.isWebGPUBackend) throw new Error('WebGPURenderer fell back to WebGL 2: no WebGPU adapter');
    const table = await loadIridTable(input.wgsl, { lang: 'wgsl' });
    out.grid = Array.from(await grid(renderer, table, await floats(input.params)));
    out.sphere = await sphere(renderer, table, input.sphere);
    return out;
}
