// The gallery's iridescence page (web/iridescence.html, built by web/build-iridescence-page.mjs):
// a soap bubble and an oil film on water in three.js, rendered twice with the same camera, light
// and parameters: through irid's exact film chunk (web/irid-three.js) and through three.js's
// stock MeshPhysicalMaterial iridescence (glTF's model), side by side on a landscape screen and
// one above the other on a portrait one.
//
// Expects irid's table as JSON in <script type="application/json" id="irid-table">: the fields
// of makeIridTable with `data` as base64 of little-endian float32 RGBA texels.
// After each rendered frame, document.body.dataset.frames holds the number of frames drawn and
// dataset.layout "side-by-side" (irid left) or "stacked" (irid on top), for scripted use (the
// page's test waits on them); window.iridPage holds the camera and the controls. The canvas keeps
// its drawing buffer, so it can be saved or read back.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { RoomEnvironment } from 'three/addons/environments/RoomEnvironment.js';
import { applyIridescence, makeIridTable } from './irid-three.js';

/** The table embedded in the page, as makeIridTable's object. */
function embeddedTable() {
    const element = document.getElementById('irid-table');
    if (!element) throw new Error('the page has no embedded irid table (script#irid-table)');
    const t = JSON.parse(element.textContent);
    const bytes = Uint8Array.from(atob(t.data), (c) => c.charCodeAt(0));
    const view = new DataView(bytes.buffer);
    const data = new Float32Array(bytes.length / 4);
    for (let i = 0; i < data.length; ++i) data[i] = view.getFloat32(4 * i, true);
    return makeIridTable({ ...t, data });
}

// Value noise on the integer lattice of 3D space, smoothly interpolated, and its turbulence
// (Perlin 1985, as Smits 1990 eq. 30 uses it): enough to make a film's thickness vary.
function hash3(x, y, z) {
    let h = Math.imul(x, 374761393) + Math.imul(y, 668265263) + Math.imul(z, 2147483647);
    h = Math.imul(h ^ (h >>> 13), 1274126177);
    return ((h ^ (h >>> 16)) >>> 0) / 4294967295;
}

function noise3(x, y, z) {
    const [ix, iy, iz] = [Math.floor(x), Math.floor(y), Math.floor(z)];
    const s = (t) => t * t * (3 - 2 * t);
    const [fx, fy, fz] = [s(x - ix), s(y - iy), s(z - iz)];
    const lerp = (a, b, t) => a + (b - a) * t;
    const c = (dx, dy, dz) => hash3(ix + dx, iy + dy, iz + dz);
    return lerp(lerp(lerp(c(0, 0, 0), c(1, 0, 0), fx), lerp(c(0, 1, 0), c(1, 1, 0), fx), fy),
                lerp(lerp(c(0, 0, 1), c(1, 0, 1), fx), lerp(c(0, 1, 1), c(1, 1, 1), fx), fy), fz);
}

function turbulence(x, y, z, octaves = 5) {
    let sum = 0;
    for (let i = 0, f = 1; i < octaves; ++i, f *= 2) sum += (noise3(f * x, f * y, f * z) - 0.5) / f;
    return sum;
}

/** A size × size thickness map: G (what three.js reads) = 255 · fraction(u, v), fraction in 0..1. */
function thicknessMap(size, fraction) {
    const data = new Uint8Array(size * size * 4);
    for (let j = 0; j < size; ++j) {
        for (let i = 0; i < size; ++i) {
            const g = Math.round(255 * Math.min(1, Math.max(0, fraction((i + 0.5) / size, (j + 0.5) / size))));
            data.set([g, g, g, 255], 4 * (j * size + i));
        }
    }
    const texture = new THREE.DataTexture(data, size, size);
    texture.colorSpace = THREE.NoColorSpace;
    texture.wrapS = THREE.RepeatWrapping;
    texture.magFilter = THREE.LinearFilter;
    // Mipmaps: far away, a pixel averages the thickness it covers rather than picking one value,
    // which would alias into moiré where the bands are dense.
    texture.minFilter = THREE.LinearMipmapLinearFilter;
    texture.generateMipmaps = true;
    texture.anisotropy = 8;
    texture.needsUpdate = true;
    return texture;
}

// A bubble drains: gravity pulls the film down, so it is thinnest at the top, where a cap of
// black film (tens of nanometres, too thin to reflect much) forms, and thickens towards the
// bottom in horizontal bands that convection twists into swirls. (u, v) of three's
// SphereGeometry: u around, v = 1 at the top; the noise is taken at the point on the sphere, so
// it has no seam, and is stretched vertically so that its features lie along the bands.
function bubbleFraction(u, v) {
    const phi = 2 * Math.PI * u;
    const theta = Math.PI * (1 - v);
    const [x, y, z] = [Math.sin(theta) * Math.cos(phi), Math.cos(theta), Math.sin(theta) * Math.sin(phi)];
    const depth = 1 - v;  // 0 at the top, 1 at the bottom
    const swirl = turbulence(1.3 * x + 7.1, 4.5 * y, 1.3 * z) + 0.5 * turbulence(3 * x, 9 * y + 2.3, 3 * z);
    const drained = 0.04 + 0.96 * Math.pow(Math.min(1, depth + 0.25 * swirl * depth), 0.8);
    // The black cap: above 14 % of the depth the film has drained to a few percent of the maximum.
    const cap = 1 / (1 + Math.exp(-(depth - 0.14 - 0.03 * swirl) / 0.012));
    return 0.015 + (drained - 0.015) * cap;
}

// An oil slick: lenses of oil on the water, nearly flat inside and thinning steeply at their
// edges, where the interference bands crowd together; their rims are frayed by turbulence
// (Perlin's, as Smits 1990 eq. 27–28 perturbs his slick's radius). Outside them, bare water.
function oilFraction(u, v) {
    const lens = (cx, cy, radius, edge) => {
        const r = Math.hypot(u - cx, v - cy) + 0.045 * turbulence(7 * u, 7 * v, 3.7);
        const p = Math.min(1, Math.max(0, (radius - r) / edge));
        return Math.pow(p, 0.7) * (0.8 + 0.2 * noise3(11 * u, 11 * v, 1.3));
    };
    return Math.max(lens(0.47, 0.55, 0.19, 0.09), lens(0.66, 0.37, 0.08, 0.05));
}

const controlIds = ['bubble-thickness', 'bubble-ior', 'oil-thickness', 'oil-ior', 'light-azimuth', 'light-elevation'];
const units = { 'bubble-thickness': ' nm', 'oil-thickness': ' nm', 'light-azimuth': '°', 'light-elevation': '°' };

function main() {
    const table = embeddedTable();
    // On a small screen the controls start folded, leaving the scene in view.
    if (Math.min(window.innerWidth, window.innerHeight) < 600) document.getElementById('panel').open = false;
    document.getElementById('three-revision').textContent = `r${THREE.REVISION}`;
    const view = document.getElementById('view');
    const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    renderer.toneMapping = THREE.NeutralToneMapping;
    renderer.setScissorTest(true);
    view.appendChild(renderer.domElement);

    const camera = new THREE.PerspectiveCamera(40, 1, 0.05, 100);
    camera.position.set(0.0, 3.4, 7.6);
    const controls = new OrbitControls(camera, renderer.domElement);
    controls.target.set(0, 0.9, 0);
    controls.minDistance = 2.5;
    controls.maxDistance = 20;
    // Above the water: the camera never orbits below 5° over the horizon of the target.
    controls.maxPolarAngle = THREE.MathUtils.degToRad(85);
    controls.update();
    window.iridPage = { camera, controls };

    const environment = new THREE.PMREMGenerator(renderer).fromScene(new RoomEnvironment(), 0.04).texture;
    const bubbleGeometry = new THREE.SphereGeometry(1, 128, 64);
    const oilGeometry = new THREE.CircleGeometry(7, 96);
    oilGeometry.rotateX(-Math.PI / 2);
    const bubbleMap = thicknessMap(512, bubbleFraction);
    const oilMap = thicknessMap(1024, oilFraction);

    // One scene per half, equal but for the materials' evalIridescence.
    const halves = [true, false].map((irid) => {
        const scene = new THREE.Scene();
        // The room the bubble reflects is also what is seen around it, dimmed and blurred as a
        // background out of focus would be.
        scene.background = environment;
        scene.backgroundBlurriness = 0.35;
        scene.backgroundIntensity = 0.35;
        scene.environment = environment;
        scene.environmentIntensity = 0.8;
        // The water's far edge fades.
        scene.fog = new THREE.Fog(0x15181c, 10, 17);
        // The bubble: no base colour and a base of air (ior 1, F0 0); what it reflects is added
        // to what is behind it (a film this thin transmits nearly all the rest), front and back
        // face alike.
        const bubble = new THREE.MeshPhysicalMaterial({
            color: 0x000000, metalness: 0, roughness: 0, ior: 1.0, iridescenceThicknessMinimum: 0,
            iridescence: 1, iridescenceThicknessMap: bubbleMap,
            transparent: true, blending: THREE.AdditiveBlending, depthWrite: false, side: THREE.DoubleSide,
        });
        // Oil on water: dark, still water (ior 1.33) under the film; where there is no oil the
        // water reflects the room as bare water does.
        const oil = new THREE.MeshPhysicalMaterial({
            color: 0x010203, metalness: 0, roughness: 0.02, ior: 1.33, iridescenceThicknessMinimum: 0,
            iridescence: 1, iridescenceThicknessMap: oilMap,
        });
        if (irid) {
            applyIridescence(bubble, { table });
            applyIridescence(oil, { table });
        }
        const oilMesh = new THREE.Mesh(oilGeometry, oil);
        const bubbleMesh = new THREE.Mesh(bubbleGeometry, bubble);
        bubbleMesh.position.set(0.2, 1.6, -0.6);
        bubbleMesh.renderOrder = 1;
        const light = new THREE.DirectionalLight(0xffffff, 2.5);
        scene.add(oilMesh, bubbleMesh, light, light.target);
        return { scene, bubble, oil, light };
    });

    let frames = 0;
    let pending = false;
    const render = () => {
        pending = false;
        const width = view.clientWidth;
        const height = view.clientHeight;
        const size = renderer.getSize(new THREE.Vector2());
        if (size.x !== width || size.y !== height) renderer.setSize(width, height, false);
        // Landscape: irid on the left, three.js on the right; portrait: irid above.
        const stacked = height > width;
        document.body.dataset.layout = stacked ? 'stacked' : 'side-by-side';
        document.body.classList.toggle('stacked', stacked);
        const rects = stacked
            ? [[0, height - Math.floor(height / 2), width, Math.floor(height / 2)], [0, 0, width, height - Math.floor(height / 2)]]
            : [[0, 0, Math.floor(width / 2), height], [Math.floor(width / 2), 0, width - Math.floor(width / 2), height]];
        camera.aspect = rects[0][2] / rects[0][3];
        // A narrow view keeps the bubble and the slick in frame: a wider field of view.
        camera.fov = camera.aspect < 1 ? 2 * THREE.MathUtils.radToDeg(Math.atan(Math.tan(THREE.MathUtils.degToRad(20)) / camera.aspect)) : 40;
        camera.updateProjectionMatrix();
        halves.forEach((h, i) => {
            renderer.setViewport(...rects[i]);
            renderer.setScissor(...rects[i]);
            renderer.render(h.scene, camera);
        });
        document.body.dataset.frames = String(++frames);
    };
    const requestRender = () => {
        if (!pending) {
            pending = true;
            requestAnimationFrame(render);
        }
    };

    const inputs = Object.fromEntries(controlIds.map((id) => [id, document.getElementById(id)]));
    const update = () => {
        const value = (id) => Number(inputs[id].value);
        for (const id of controlIds) {
            const shown = id.endsWith('-ior') ? value(id).toFixed(2) : `${value(id)}`;
            document.querySelector(`output[for="${id}"]`).textContent = `${shown}${units[id] ?? ''}`;
        }
        const azimuth = THREE.MathUtils.degToRad(value('light-azimuth'));
        const elevation = THREE.MathUtils.degToRad(value('light-elevation'));
        for (const h of halves) {
            h.bubble.iridescenceIOR = value('bubble-ior');
            h.bubble.iridescenceThicknessMaximum = value('bubble-thickness');
            h.oil.iridescenceIOR = value('oil-ior');
            h.oil.iridescenceThicknessMaximum = value('oil-thickness');
            h.light.position.set(10 * Math.cos(elevation) * Math.sin(azimuth), 10 * Math.sin(elevation),
                                 10 * Math.cos(elevation) * Math.cos(azimuth));
            // The room turns with the light, so that its lamps and the sun stay together.
            h.scene.environmentRotation.set(0, azimuth, 0);
        }
        requestRender();
    };
    for (const id of controlIds) inputs[id].addEventListener('input', update);
    controls.addEventListener('change', requestRender);
    window.addEventListener('resize', requestRender);
    update();
}

try {
    main();
} catch (e) {
    const box = document.getElementById('error');
    box.textContent = `The page could not start: ${e.message}`;
    box.style.display = 'block';
    throw e;
}
