// irid's exact thin-film colour in three.js's WebGPURenderer: a TSL node that takes the place of
// the iridescence Fresnel of MeshPhysicalNodeMaterial, from the WGSL chunk `irid shader --lang
// wgsl -o DIR` writes. Usage:
//
//   import * as THREE from 'three/webgpu';
//   import { loadIridTable } from './irid-three.js';
//   import { applyIridescenceNode } from './irid-three-webgpu.js';
//   const table = await loadIridTable('irid-shader-wgsl/', { lang: 'wgsl' });
//   const material = new THREE.MeshPhysicalNodeMaterial({ iridescence: 1, iridescenceIOR: 1.33,
//       iridescenceThicknessMinimum: 100, iridescenceThicknessMaximum: 800 });
//   applyIridescenceNode(material, { table });
//
// three.js computes the iridescence Fresnel in PhysicalLightingModel.start() from its own
// evalIridescence, over the dielectric specular colour and over the metallic base colour, mixed
// by metalness, at cos θ = N·V; applyIridescenceNode keeps all of that and replaces only the two
// evaluations by irid's (the lighting model's iridescenceFresnel and the two F0 derived from it). The chunk is WGSL: the node needs WebGPURenderer's WebGPU backend (its
// WebGL 2 fallback compiles GLSL; use irid-three.js's applyIridescence with WebGLRenderer there).
import * as THREE from 'three/webgpu';
import {
    Schlick_to_F0, code, diffuseColor, float, iridescenceIOR, iridescenceThickness, metalness, mix,
    normalView, positionViewDirection, specularColor, texture, wgslFn,
} from 'three/tsl';
import { checkIridTable, iridPatchOf, iridTableTexture, makeIridTable, trackIridPatch, wrapCopy } from './irid-three.js';

const BINDING_MARKER = '\n// --- evalIridescence with the table bound at module scope ---\n';

/**
 * The chunk as a TSL function: (outsideIOR, eta2, cosTheta1, thinFilmThickness, baseF0) → the
 * film's linear RGB node, and the DataTexture of its table (dispose it when done). table: a
 * table object with `wgsl` (loadIridTable(url, { lang: 'wgsl' })).
 */
export function iridescenceNode(table) {
    const t = makeIridTable(table);
    if (typeof t.wgsl !== 'string') throw new Error('iridescenceNode: the table has no WGSL chunk (irid shader --lang wgsl)');
    const end = t.wgsl.indexOf(BINDING_MARKER);
    const start = t.wgsl.indexOf('\nfn irid_eval(');
    if (end < 0 || start < 0 || start > end) throw new Error('iridescenceNode: the WGSL chunk is not irid shader\'s');
    // irid_eval, which takes the table as a texture, with the rest of the chunk as its include;
    // the binding and evalIridescence after the marker are left to three's node system.
    const evaluate = wgslFn(t.wgsl.slice(start + 1, end), [code(t.wgsl.slice(0, start))]);
    const map = iridTableTexture(t);
    const fn = (outsideIOR, eta2, cosTheta1, thinFilmThickness, baseF0) => evaluate({
        table: texture(map), outsideIOR, eta2, cosTheta1, thinFilmThickness, baseF0,
    });
    return { fn, texture: map, table: t };
}

/**
 * Replaces the iridescence Fresnel of a MeshPhysicalNodeMaterial by irid's exact film, after
 * checking the table against the renderer (irid-three.js's checkIridTable: workingColorSpace,
 * illuminant). Applying again replaces the patch; clone() and copy() keep it; the table's
 * texture is disposed with the material. Returns the texture.
 */
export function applyIridescenceNode(material, { table, workingColorSpace, illuminant } = {}) {
    if (!material.isNodeMaterial) throw new Error('applyIridescenceNode: the material is not a node material (MeshPhysicalNodeMaterial)');
    const t = makeIridTable(table);
    checkIridTable(t, { workingColorSpace, illuminant });
    return install(material, t);
}

// FNV-1a of a string, hex.
function hashOf(text) {
    let h = 0x811c9dc5;
    for (let i = 0; i < text.length; ++i) h = Math.imul(h ^ text.charCodeAt(i), 0x01000193) >>> 0;
    return h.toString(16);
}

// NodeMaterial.copy does not call Material.copy: it is wrapped once too, so that clone() and
// copy() of a node material carry the patch.
let copyWrapped = false;

function install(material, table) {
    if (!copyWrapped) {
        copyWrapped = true;
        wrapCopy(THREE.NodeMaterial.prototype);
    }
    const previous = iridPatchOf(material);
    if (previous) previous.remove(material);
    const node = iridescenceNode(table);
    const own = Object.prototype.hasOwnProperty.call(material, 'setupLightingModel') ? material.setupLightingModel : null;
    const setup = function (builder) {
        const model = (own ?? Object.getPrototypeOf(this).setupLightingModel).call(this, builder);
        if (model.iridescence !== true) return model;
        // As PhysicalLightingModel.start() computes them, with irid's film in place of three's.
        // start() assigns its own and then runs the lights (LightingModel.start), which read
        // these three: accessors that keep irid's make the lights see them.
        const dotNVi = normalView.dot(positionViewDirection).clamp();
        const dielectric = node.fn(float(1.0), iridescenceIOR, dotNVi, iridescenceThickness, specularColor);
        const metallic = node.fn(float(1.0), iridescenceIOR, dotNVi, iridescenceThickness, diffuseColor.rgb);
        const nodes = {
            iridescenceFresnel: mix(dielectric, metallic, metalness),
            iridescenceF0Dielectric: Schlick_to_F0({ f: dielectric, f90: 1.0, dotVH: dotNVi }),
            iridescenceF0Metallic: Schlick_to_F0({ f: metallic, f90: 1.0, dotVH: dotNVi }),
        };
        for (const [name, value] of Object.entries(nodes)) {
            Object.defineProperty(model, name, { get: () => value, set: () => {}, configurable: true });
        }
        return model;
    };
    // A node material's program is cached by its nodes' key (customProgramCacheKey), which does
    // not see setupLightingModel: the chunk's hash is added, or a stock material of the same
    // nodes would share the patched program (or the patched one the stock's).
    const ownKey = Object.prototype.hasOwnProperty.call(material, 'customProgramCacheKey') ? material.customProgramCacheKey : null;
    const tag = `irid-node-${hashOf(table.wgsl)}`;
    const key = function () {
        return `${(ownKey ?? Object.getPrototypeOf(this).customProgramCacheKey).call(this)}|${tag}`;
    };
    const dispose = () => node.texture.dispose();
    material.addEventListener('dispose', dispose);
    material.setupLightingModel = setup;
    material.customProgramCacheKey = key;
    material.needsUpdate = true;
    trackIridPatch(material, {
        table,
        reapply: (target) => install(target, table),
        remove: (target) => {
            target.removeEventListener('dispose', dispose);
            node.texture.dispose();
            if (target.setupLightingModel === setup) {
                if (own) target.setupLightingModel = own;
                else delete target.setupLightingModel;
            }
            if (target.customProgramCacheKey === key) {
                if (ownKey) target.customProgramCacheKey = ownKey;
                else delete target.customProgramCacheKey;
            }
            target.needsUpdate = true;
        },
    });
    return node.texture;
}

