// The gallery's iridescence page (web/iridescence.html, built by web/build-iridescence-page.mjs):
// a soap bubble and an oil film on water in three.js, rendered twice with the same camera, light
// and parameters: on the left through irid's exact film chunk (web/irid-three.js), on the right
// through three.js's stock MeshPhysicalMaterial iridescence (glTF's model).
//
// Expects irid's table as JSON in <script type="application/json" id="irid-table">: the fields
// of makeIridTable with `data` as base64 of little-endian float32 RGBA texels.
// After each rendered frame, document.body.dataset.frames holds the number of frames drawn (for
// scripted use: the page's test waits on it). The canvas keeps its drawing buffer, so it can be
// saved or read back.
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
    texture.minFilter = THREE.LinearFilter;
    texture.needsUpdate = true;
    return texture;
}

// A bubble drains: its film is thinnest at the top and thickest at the bottom, with swirls.
// (u, v) of three's SphereGeometry: u around, v = 1 at the top; the noise is taken at the point
// on the sphere, so it has no seam.
function bubbleFraction(u, v) {
    const phi = 2 * Math.PI * u;
    const theta = Math.PI * (1 - v);
    const [x, y, z] = [Math.sin(theta) * Math.cos(phi), Math.cos(theta), Math.sin(theta) * Math.sin(phi)];
    return 0.25 + 0.6 * (1 - v) + 0.35 * turbulence(1.6 * x + 7.1, 1.6 * y, 1.6 * z);
}

// An oil slick: thickness e^(−k₁(r² + k₂ turbulence)), Smits 1990 eq. 27–28, around two centres.
function oilFraction(u, v) {
    const blob = (cx, cy, k1) => {
        const [x, y] = [u - cx, v - cy];
        return Math.exp(-k1 * (x * x + y * y + 0.08 * turbulence(4 * u, 4 * v, 3.7)));
    };
    return Math.min(1, blob(0.42, 0.55, 9) + 0.7 * blob(0.7, 0.3, 25));
}

const controlIds = ['bubble-thickness', 'bubble-ior', 'oil-thickness', 'oil-ior', 'light-azimuth', 'light-elevation'];
const units = { 'bubble-thickness': ' nm', 'oil-thickness': ' nm', 'light-azimuth': '°', 'light-elevation': '°' };

function main() {
    const table = embeddedTable();
    document.getElementById('three-revision').textContent = `r${THREE.REVISION}`;
    const view = document.getElementById('view');
    const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    renderer.toneMapping = THREE.NeutralToneMapping;
    renderer.setScissorTest(true);
    view.appendChild(renderer.domElement);

    const camera = new THREE.PerspectiveCamera(40, 1, 0.05, 100);
    camera.position.set(0.0, 4.6, 7.4);
    const controls = new OrbitControls(camera, renderer.domElement);
    controls.target.set(0, 0.7, 0);
    controls.maxDistance = 30;
    controls.update();

    const environment = new THREE.PMREMGenerator(renderer).fromScene(new RoomEnvironment(), 0.04).texture;
    const bubbleGeometry = new THREE.SphereGeometry(1, 128, 64);
    const oilGeometry = new THREE.PlaneGeometry(14, 14, 1, 1);
    oilGeometry.rotateX(-Math.PI / 2);
    const bubbleMap = thicknessMap(256, bubbleFraction);
    const oilMap = thicknessMap(256, oilFraction);

    // One scene per half, equal but for the materials' evalIridescence.
    const halves = [true, false].map((irid) => {
        const scene = new THREE.Scene();
        scene.background = new THREE.Color(0x0d1014);
        scene.environment = environment;
        // The water's far edge fades into the background.
        scene.fog = new THREE.Fog(0x0d1014, 9, 16);
        // The bubble: no base colour and a base of air (ior 1, F0 0); what it reflects is added
        // to what is behind it (a film this thin transmits nearly all the rest).
        const bubble = new THREE.MeshPhysicalMaterial({
            color: 0x000000, metalness: 0, roughness: 0, ior: 1.0, iridescenceThicknessMinimum: 0,
            iridescence: 1, iridescenceThicknessMap: bubbleMap,
            transparent: true, blending: THREE.AdditiveBlending, depthWrite: false, side: THREE.DoubleSide,
        });
        // Oil on water: dark, smooth water (ior 1.33) under the film.
        const oil = new THREE.MeshPhysicalMaterial({
            color: 0x04090d, metalness: 0, roughness: 0.08, ior: 1.33, iridescenceThicknessMinimum: 0,
            iridescence: 1, iridescenceThicknessMap: oilMap,
        });
        if (irid) {
            applyIridescence(bubble, { table });
            applyIridescence(oil, { table });
        }
        const oilMesh = new THREE.Mesh(oilGeometry, oil);
        const bubbleMesh = new THREE.Mesh(bubbleGeometry, bubble);
        bubbleMesh.position.set(0, 1.5, -0.8);
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
        const half = Math.floor(width / 2);
        camera.aspect = half / height;
        camera.updateProjectionMatrix();
        halves.forEach((h, i) => {
            const x = i === 0 ? 0 : half;
            const w = i === 0 ? half : width - half;
            renderer.setViewport(x, 0, w, height);
            renderer.setScissor(x, 0, w, height);
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
