// irid's exact thin-film colour in three.js: patches a MeshPhysicalMaterial so that its
// iridescence evaluates irid's GLSL chunk (written by `irid shader --lang glsl -o DIR`) instead
// of three.js's own evalIridescence. Usage:
//
//   import { loadIridTable, applyIridescence } from './irid-three.js';
//   const table = await loadIridTable('irid-shader/');      // the folder `irid shader` wrote
//   const material = new THREE.MeshPhysicalMaterial({ iridescence: 1, iridescenceIOR: 1.33,
//       iridescenceThicknessMinimum: 100, iridescenceThicknessMaximum: 800 });
//   applyIridescence(material, { table });
//
// Only the definition of evalIridescence changes (three.js's `iridescence_fragment` chunk);
// where and how three.js calls it (lights_fragment_begin: the film over the dielectric
// specular colour and over the metallic base colour, mixed by metalness) and every iridescence
// parameter of the material (iridescence, iridescenceMap, iridescenceIOR, the thickness minimum,
// maximum and map) stay three.js's. The patch composes with the material's own onBeforeCompile
// and customProgramCacheKey, is replaced by a second applyIridescence (another table), and is
// kept by clone() and copy() (docs/OPTICS.md, "In the browser").
import * as THREE from 'three';

/**
 * The table object: {glsl, data, width, height, filter, uniform, illuminant, space, primaries,
 * white}. primaries: [rx, ry, gx, gy, bx, by] and white: [x, y] of the working space the chunk's
 * linear RGB is in (irid_film_table.json records them).
 * glsl: the chunk's text (defines evalIridescence and declares `uniform highp sampler2D
 * <uniform>;`); data: Float32Array of width × height RGBA texels, row-major; filter: 'linear'
 * (sampled with texture(), linear filtering) or 'nearest' (texelFetch).
 */
export function makeIridTable({ glsl, wgsl, data, width, height, filter, uniform = 'iridFilmTable',
                                illuminant, space, primaries, white }) {
    const defines = (text) => typeof text === 'string' && text.includes('evalIridescence');
    if (!defines(glsl) && !defines(wgsl)) {
        throw new Error('irid table: glsl (or wgsl) must be the chunk text that defines evalIridescence');
    }
    if (!(data instanceof Float32Array)) throw new Error('irid table: data must be a Float32Array');
    if (!Number.isInteger(width) || !Number.isInteger(height) || width < 1 || height < 1) {
        throw new Error(`irid table: width and height must be positive integers (got ${width}, ${height})`);
    }
    if (data.length !== width * height * 4) {
        throw new Error(`irid table: ${data.length} floats, but ${width}×${height} RGBA texels need ${width * height * 4}`);
    }
    if (filter !== 'linear' && filter !== 'nearest') {
        throw new Error(`irid table: filter '${filter}' is neither 'linear' nor 'nearest'`);
    }
    if (!(glsl ?? wgsl).includes(uniform)) throw new Error(`irid table: the chunk does not declare '${uniform}'`);
    const numbers = (v, n) => Array.isArray(v) && v.length === n && v.every(Number.isFinite);
    if (!numbers(primaries, 6) || !numbers(white, 2)) {
        throw new Error('irid table: primaries must be 6 numbers and white 2 (irid_film_table.json records them; '
                        + 'a table from before they were recorded must be written again with irid shader)');
    }
    if (typeof illuminant !== 'string' || typeof space !== 'string') {
        throw new Error('irid table: illuminant and space must be the names irid_film_table.json records');
    }
    return { glsl, wgsl, data, width, height, filter, uniform, illuminant, space, primaries: [...primaries],
             white: [...white] };
}

/**
 * Fetches the three files `irid shader --lang glsl -o DIR` writes (irid_iridescence.glsl,
 * irid_film_table.f32, irid_film_table.json) from baseUrl (the folder's URL) and returns the
 * table object. The .f32 file is little-endian float32. With lang 'wgsl', the folder
 * `irid shader --lang wgsl` wrote (irid_iridescence.wgsl; the table object's `wgsl`).
 */
export async function loadIridTable(baseUrl, { lang = 'glsl' } = {}) {
    if (lang !== 'glsl' && lang !== 'wgsl') throw new Error(`irid table: lang '${lang}' is neither 'glsl' nor 'wgsl'`);
    const base = baseUrl.endsWith('/') ? baseUrl : `${baseUrl}/`;
    const get = async (name) => {
        const response = await fetch(`${base}${name}`);
        if (!response.ok) throw new Error(`irid table: ${base}${name}: HTTP ${response.status}`);
        return response;
    };
    const [text, bytes, meta] = await Promise.all([
        get(`irid_iridescence.${lang}`).then((r) => r.text()),
        get('irid_film_table.f32').then((r) => r.arrayBuffer()),
        get('irid_film_table.json').then((r) => r.json()),
    ]);
    if (bytes.byteLength % 4 !== 0) throw new Error('irid table: irid_film_table.f32 is not whole float32s');
    const view = new DataView(bytes);
    const data = new Float32Array(bytes.byteLength / 4);
    for (let i = 0; i < data.length; ++i) data[i] = view.getFloat32(4 * i, true);
    return makeIridTable({ [lang]: text, data, width: meta.width, height: meta.height, filter: meta.filter,
                           uniform: meta.uniform, illuminant: meta.illuminant, space: meta.space,
                           primaries: meta.primaries, white: meta.white });
}

/** The table as a THREE.DataTexture: RGBA float, the table's filter, no mipmaps, no colour
 * management (the texels are coefficients, not colours). */
export function iridTableTexture(table) {
    const texture = new THREE.DataTexture(table.data, table.width, table.height, THREE.RGBAFormat,
                                          THREE.FloatType);
    const filter = table.filter === 'linear' ? THREE.LinearFilter : THREE.NearestFilter;
    texture.minFilter = filter;
    texture.magFilter = filter;
    texture.generateMipmaps = false;
    texture.wrapS = THREE.ClampToEdgeWrapping;
    texture.wrapT = THREE.ClampToEdgeWrapping;
    texture.colorSpace = THREE.NoColorSpace;
    texture.flipY = false;
    texture.needsUpdate = true;
    return texture;
}

// FNV-1a of a string, hex: tells programs of different chunks apart in three's program cache.
function hashOf(text) {
    let h = 0x811c9dc5;
    for (let i = 0; i < text.length; ++i) h = Math.imul(h ^ text.charCodeAt(i), 0x01000193) >>> 0;
    return h.toString(16);
}

/**
 * Throws unless the table's colours are what the renderer takes them for: linear RGB in the
 * primaries and white of three.js's working colour space, under the illuminant the scene's
 * white lights stand for.
 */
export function checkIridTable(table, { workingColorSpace = THREE.ColorManagement.workingColorSpace,
                                        illuminant = 'D65' } = {}) {
    const space = THREE.ColorManagement.spaces[workingColorSpace];
    if (!space) throw new Error(`applyIridescence: three.js knows no colour space '${workingColorSpace}'`);
    const close = (a, b) => a.length === b.length && a.every((v, i) => Math.abs(v - b[i]) < 5e-4);
    if (!close(table.primaries, space.primaries) || !close(table.white, space.whitePoint)) {
        throw new Error(`applyIridescence: the table is in ${table.space} (primaries ${table.primaries.join(', ')}; `
                        + `white ${table.white.join(', ')}), but three.js's working colour space `
                        + `'${workingColorSpace}' has primaries ${space.primaries.join(', ')} and white `
                        + `${space.whitePoint.join(', ')}: write the table with irid shader --space for that `
                        + 'space, or pass the workingColorSpace the renderer uses');
    }
    if (table.illuminant.toLowerCase() !== String(illuminant).toLowerCase()) {
        throw new Error(`applyIridescence: the table's colours are under illuminant ${table.illuminant}, but `
                        + `the scene's white light is taken as ${illuminant}: write the table with irid shader `
                        + `--illuminant ${illuminant}, or pass illuminant: '${table.illuminant}' if that is `
                        + 'what the lights stand for');
    }
}

// The patched materials: material → {table, key, texture, own: {compile, key}, wrapper, dispose,
// reapply(target), remove(target)}. `own` is the material's own onBeforeCompile and
// customProgramCacheKey (null: three's default), kept so that a second applyIridescence replaces
// the patch rather than stacking a second one. irid-three-webgpu.js records its node materials'
// patches here too (trackIridPatch), so that one copy() hook serves both.
const patches = new WeakMap();

/** Records a patch of `material` that copy() and clone() carry: reapply(target) patches a copy
 * alike, remove(target) takes the patch off a material copied from an unpatched one. */
export function trackIridPatch(material, record) {
    keepPatchOnCopy();
    patches.set(material, record);
}

/** The patch recorded for `material`, or undefined. */
export function iridPatchOf(material) {
    return patches.get(material);
}

function install(material, table, key) {
    const previous = patches.get(material);
    let own;
    if (previous && previous.wrapper && material.onBeforeCompile === previous.wrapper.compile
        && material.customProgramCacheKey === previous.wrapper.key) {
        own = previous.own;
    } else {
        // The material's own functions (three's defaults where it has none of its own).
        const ownKey = Object.prototype.hasOwnProperty.call(material, 'customProgramCacheKey')
            ? material.customProgramCacheKey : null;
        own = { compile: material.onBeforeCompile, key: ownKey };
    }
    if (previous) previous.remove(material, { keepOwn: true });
    const texture = iridTableTexture(table);
    const chunk = `#ifdef USE_IRIDESCENCE\n${table.glsl}\n#endif\n`;
    const wrapper = {
        compile(shader, renderer) {
            own.compile.call(this, shader, renderer);
            if (!shader.fragmentShader.includes('#include <iridescence_fragment>')) {
                throw new Error('applyIridescence: the fragment shader has no #include <iridescence_fragment>');
            }
            shader.fragmentShader = shader.fragmentShader.replace('#include <iridescence_fragment>', chunk);
            shader.uniforms[table.uniform] = { value: texture };
        },
        // three's default key is the text of onBeforeCompile, which is now this wrapper for every
        // patched material: the material's own function's text stands in for it.
        key() {
            const base = own.key ? own.key.call(this) : own.compile.toString();
            return `${base}|${key}`;
        },
    };
    const dispose = () => texture.dispose();
    material.addEventListener('dispose', dispose);
    material.onBeforeCompile = wrapper.compile;
    material.customProgramCacheKey = wrapper.key;
    material.needsUpdate = true;
    trackIridPatch(material, {
        table, key, texture, own, wrapper, dispose,
        reapply: (target) => install(target, table, key),
        remove: (target, { keepOwn = false } = {}) => {
            target.removeEventListener('dispose', dispose);
            texture.dispose();
            patches.delete(target);
            if (keepOwn) return;
            if (target.onBeforeCompile === wrapper.compile) target.onBeforeCompile = own.compile;
            if (target.customProgramCacheKey === wrapper.key) {
                if (own.key) target.customProgramCacheKey = own.key;
                else delete target.customProgramCacheKey;
            }
            target.needsUpdate = true;
        },
    });
    return texture;
}

// clone() and copy() carry the patch: Material.prototype.copy (which every material's copy
// reaches through super.copy) is wrapped once, so that a copy of a patched material is patched
// with the same table, and a copy of an unpatched one is not.
let copyWrapped = false;
function keepPatchOnCopy() {
    if (copyWrapped) return;
    copyWrapped = true;
    wrapCopy(THREE.Material.prototype);
}

/** Wraps `prototype.copy` so that a copy takes the source's patch (or loses its own when the
 * source has none). Node materials' copy does not reach Material's: irid-three-webgpu.js wraps
 * NodeMaterial's too. */
export function wrapCopy(prototype) {
    const copy = prototype.copy;
    prototype.copy = function (source) {
        const out = copy.call(this, source);
        const patch = patches.get(source);
        if (patch) {
            patch.reapply(this);
        } else if (patches.has(this)) {
            patches.get(this).remove(this);
            patches.delete(this);
        }
        return out;
    };
}

/**
 * Patches a MeshPhysicalMaterial (or any material whose fragment shader includes
 * <iridescence_fragment>) to evaluate irid's chunk, after checking the table against the
 * renderer (checkIridTable: workingColorSpace, default three's working colour space;
 * illuminant, default 'D65'). The material's own onBeforeCompile runs first and its
 * customProgramCacheKey (or three's default, the text of its onBeforeCompile) is extended, so
 * materials that patch their shaders differently keep programs of their own. Applying again
 * replaces the patch (a new table). The table's DataTexture is the material's: it is disposed
 * with the material (its 'dispose' event) or when the patch is replaced; it is returned.
 */
export function applyIridescence(material, { table, workingColorSpace, illuminant } = {}) {
    const t = makeIridTable(table);
    if (typeof t.glsl !== 'string') throw new Error('applyIridescence: the table has no GLSL chunk (irid shader --lang glsl)');
    checkIridTable(t, { workingColorSpace, illuminant });
    return install(material, t, `irid-iridescence-${hashOf(`${t.filter}\n${t.glsl}`)}`);
}
