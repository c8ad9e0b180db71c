// The page of tests/browser/three_compose_test.py: irid-three.js's patch beside other code that
// patches the same materials. Each render is a small sphere into an RGBA32F target, read back at
// its centre pixel (cos θ = 1), three.js's material.iridescenceFresnel isolated as the output.
//
// input: {tables: {d65, a, p3}: URLs of folders `irid shader` wrote (D65 sRGB, A sRGB, D65
//         Display P3), size}
// returns: {tinted: {red, green, plain, plainAlone}: [r, g, b] each; programs: how many three.js
//          compiled for them; swapped: {before, after, direct}; copies: {original, clone, copied,
//          uncopied, stock}; refusals: {space, illuminant}: the messages; disposed: bool}
import * as THREE from 'three';
import { applyIridescence, loadIridTable } from '/web/irid-three.js';

const FRESNEL = 'material.iridescenceFresnel';

// Two shader patches of a material's own: iridescenceFresnel times a tint. Two functions of
// their own text, as two pieces of code would write them (three.js tells programs apart by the
// text of onBeforeCompile: closures of one text would share a program without irid too).
function red(shader) {
    shader.fragmentShader = shader.fragmentShader.replace(
        '#include <opaque_fragment>', `gl_FragColor = vec4( ${FRESNEL} * vec3( 1.0, 0.0, 0.0 ), 1.0 );`);
}
function green(shader) {
    shader.fragmentShader = shader.fragmentShader.replace(
        '#include <opaque_fragment>', `gl_FragColor = vec4( ${FRESNEL} * vec3( 0.0, 1.0, 0.0 ), 1.0 );`);
}
function tint(material, patch) {
    material.onBeforeCompile = patch;
    return material;
}

// The same output without a tint, for materials that have no patch of their own: written into
// three's own chunk, so that the material's onBeforeCompile stays three's default.
function isolateEverywhere() {
    THREE.ShaderChunk.opaque_fragment =
        `#ifdef USE_IRIDESCENCE\ngl_FragColor = vec4( ${FRESNEL}, 1.0 );\n#else\n`
        + `${THREE.ShaderChunk.opaque_fragment}\n#endif\n`;
}

function physical() {
    return new THREE.MeshPhysicalMaterial({
        color: 0x000000, metalness: 0, roughness: 0.5, ior: 1.5, iridescence: 1, iridescenceIOR: 1.33,
        iridescenceThicknessMinimum: 0, iridescenceThicknessMaximum: 420,
    });
}

export async function run(input) {
    const tables = {};
    for (const [name, url] of Object.entries(input.tables)) tables[name] = await loadIridTable(url);
    isolateEverywhere();
    const size = input.size;
    const makeRenderer = () => {
        const canvas = document.createElement('canvas');
        canvas.width = canvas.height = size;
        return new THREE.WebGLRenderer({ canvas, antialias: false });
    };
    const target = new THREE.WebGLRenderTarget(size, size, { type: THREE.FloatType, format: THREE.RGBAFormat });
    const camera = new THREE.OrthographicCamera(-1, 1, 1, -1, 0.1, 10);
    camera.position.set(0, 0, 5);
    camera.lookAt(0, 0, 0);
    const geometry = new THREE.SphereGeometry(1, 64, 32);
    const centre = (renderer, material) => {
        const scene = new THREE.Scene();
        scene.add(new THREE.Mesh(geometry, material));
        renderer.setRenderTarget(target);
        renderer.setClearColor(0x000000, 0);
        renderer.clear();
        renderer.render(scene, camera);
        const pixel = new Float32Array(4);
        renderer.readRenderTargetPixels(target, size / 2, size / 2, 1, 1, pixel);
        renderer.setRenderTarget(null);
        return [pixel[0], pixel[1], pixel[2]];
    };
    const out = {};

    // 1. Materials that patch their own shaders keep their own programs.
    const renderer = makeRenderer();
    const reddened = tint(physical(), red);
    const greened = tint(physical(), green);
    const plain = physical();
    for (const m of [reddened, greened, plain]) applyIridescence(m, { table: tables.d65 });
    out.tinted = { red: centre(renderer, reddened), green: centre(renderer, greened),
                   plain: centre(renderer, plain) };
    out.programs = renderer.info.programs.length;
    const alone = physical();
    applyIridescence(alone, { table: tables.d65 });
    out.tinted.plainAlone = centre(makeRenderer(), alone);

    // 2. Applying again swaps the table.
    const swapped = physical();
    applyIridescence(swapped, { table: tables.d65 });
    out.swapped = { before: centre(renderer, swapped) };
    applyIridescence(swapped, { table: tables.a, illuminant: 'A' });
    out.swapped.after = centre(renderer, swapped);
    const direct = physical();
    applyIridescence(direct, { table: tables.a, illuminant: 'A' });
    out.swapped.direct = centre(makeRenderer(), direct);

    // 3. clone() and copy() keep the patch; copying an unpatched material removes it.
    const original = physical();
    applyIridescence(original, { table: tables.d65 });
    const copied = physical();
    copied.copy(original);
    const uncopied = physical();
    applyIridescence(uncopied, { table: tables.d65 });
    uncopied.copy(physical());
    out.copies = {
        original: centre(renderer, original), clone: centre(renderer, original.clone()),
        copied: centre(renderer, copied), uncopied: centre(renderer, uncopied), stock: centre(renderer, physical()),
    };

    // 4. A table for another space or illuminant than the renderer's is refused.
    out.refusals = {};
    for (const [name, table] of [['space', tables.p3], ['illuminant', tables.a]]) {
        try {
            applyIridescence(physical(), { table });
            out.refusals[name] = null;
        } catch (e) {
            out.refusals[name] = e.message;
        }
    }

    // 5. The table's texture goes with the material.
    const owned = physical();
    const texture = applyIridescence(owned, { table: tables.d65 });
    let disposed = false;
    texture.addEventListener('dispose', () => { disposed = true; });
    owned.dispose();
    out.disposed = disposed;
    const gl = renderer.getContext();
    if (gl.getError() !== gl.NO_ERROR) throw new Error('WebGL reported an error');
    return out;
}
