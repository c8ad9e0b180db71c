// The page of tests/browser/three_material_test.py: a MeshPhysicalMaterial sphere patched by
// web/irid-three.js, rendered by three.js into an RGBA32F target, beside the unpatched material.
//
// The unit sphere is seen by an orthographic camera along −z filling the target, so the pixel at
// NDC (x, y) sees the normal (x, y, √(1 − x² − y²)) and cos θ = √(1 − x² − y²).
// Two kinds of renders:
//   isolated: the fragment's output is replaced by three's material.iridescenceFresnel, the value
//     of evalIridescence where lights_fragment_begin calls it (after the thickness range and map
//     and the IOR have been applied by three.js);
//   lit: the full material (black base colour, metalness 0) lit by one directional light from
//     the camera, whose specular is iridescenceFresnel times a grey factor.
//
// input: {table: URL of irid's folder, size, filmIOR, baseIOR, thicknessMinimum, thicknessMaximum,
//         mapGreen: 0–255 (the thickness map's G), samples: [[px, py], ...], cosines: cos θ
//         of each sample}
// returns: {isolated: {patched, unpatched, patchedMap}, lit: {patched, unpatched}}: each a list
//          of [r, g, b] at the samples; stock: three's own chunk evaluated directly
//          (web/film-grid.js) at the samples' cos θ and the range's maximum; and programs: the
//          number of programs three.js compiled.
import * as THREE from 'three';
import { createContext, renderGrid, stockChunk } from '/web/film-grid.js';
import { applyIridescence, loadIridTable } from '/web/irid-three.js';

function isolate(material) {
    // Test-only: output material.iridescenceFresnel instead of the lit colour.
    material.onBeforeCompile = (shader) => {
        shader.fragmentShader = shader.fragmentShader.replace(
            '#include <opaque_fragment>', 'gl_FragColor = vec4( material.iridescenceFresnel, 1.0 );');
    };
    material.customProgramCacheKey = () => 'isolated-iridescence-fresnel';
}

export async function run(input) {
    const table = await loadIridTable(input.table);
    const size = input.size;
    const canvas = document.createElement('canvas');
    canvas.width = canvas.height = size;
    const renderer = new THREE.WebGLRenderer({ canvas, antialias: false });
    const target = new THREE.WebGLRenderTarget(size, size, { type: THREE.FloatType, format: THREE.RGBAFormat,
                                                             depthBuffer: true });
    const camera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0.1, 10);
    camera.position.set(0, 0, 5);
    camera.lookAt(0, 0, 0);
    const geometry = new THREE.SphereGeometry(1, 512, 256);
    const thicknessMap = new THREE.DataTexture(new Uint8Array([0, input.mapGreen, 0, 255]), 1, 1);
    thicknessMap.needsUpdate = true;

    const material = ({ patched, isolated, map }) => {
        const m = new THREE.MeshPhysicalMaterial({
            color: 0x000000, metalness: 0, roughness: 0.5, ior: input.baseIOR,
            iridescence: 1, iridescenceIOR: input.filmIOR,
            iridescenceThicknessMinimum: input.thicknessMinimum,
            iridescenceThicknessMaximum: input.thicknessMaximum,
        });
        if (map) m.iridescenceThicknessMap = thicknessMap;
        if (isolated) isolate(m);
        if (patched) applyIridescence(m, { table });
        return m;
    };

    const render = (mat) => {
        const scene = new THREE.Scene();
        scene.add(new THREE.Mesh(geometry, mat));
        const light = new THREE.DirectionalLight(0xffffff, 3.0);
        light.position.set(0, 0, 5);
        scene.add(light);
        renderer.setRenderTarget(target);
        renderer.setClearColor(0x000000, 0);
        renderer.clear();
        renderer.render(scene, camera);
        const pixels = new Float32Array(size * size * 4);
        renderer.readRenderTargetPixels(target, 0, 0, size, size, pixels);
        renderer.setRenderTarget(null);
        return input.samples.map(([x, y]) => {
            const i = 4 * (y * size + x);
            return [pixels[i], pixels[i + 1], pixels[i + 2]];
        });
    };

    const out = {
        isolated: {
            patched: render(material({ patched: true, isolated: true })),
            unpatched: render(material({ patched: false, isolated: true })),
            patchedMap: render(material({ patched: true, isolated: true, map: true })),
        },
        lit: {
            patched: render(material({ patched: true })),
            unpatched: render(material({ patched: false })),
        },
    };
    out.programs = renderer.info.programs.length;
    const baseF0 = ((input.baseIOR - 1) / (input.baseIOR + 1)) ** 2;
    const params = new Float32Array(input.cosines.flatMap(
        (c) => [1, input.filmIOR, c, input.thicknessMaximum, baseF0, baseF0, baseF0]));
    const stock = renderGrid(createContext(), stockChunk(THREE.ShaderChunk), params, 'stock');
    out.stock = input.cosines.map((_, i) => [stock[3 * i], stock[3 * i + 1], stock[3 * i + 2]]);
    const gl = renderer.getContext();
    if (gl.getError() !== gl.NO_ERROR) throw new Error('WebGL reported an error');
    return out;
}
