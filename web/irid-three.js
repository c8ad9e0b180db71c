// irid's exact thin-film colour in three.js: patches a MeshPhysicalMaterial so that its
// iridescence evaluates irid's GLSL chunk (written by `irid shader --lang glsl -o DIR`) instead
// of three.js's own evalIridescence. Usage:
//
//   import { loadIridTable, applyIridescence } from './irid-three.js';
//   const table = await loadIridTable('irid-shader/');      // the folder `irid shader` wrote
//   const material = new THREE.MeshPhysicalMaterial({ iridescence: 1, iridescenceIOR: 1.33,
//                                                     iridescenceThicknessRange: [100, 800] });
//   applyIridescence(material, { table });
//
// Only the definition of evalIridescence changes (three.js's `iridescence_fragment` chunk);
// where and how three.js calls it (lights_fragment_begin: the film over the dielectric
// specular colour and over the metallic base colour, mixed by metalness) and every iridescence
// parameter of the material (iridescence, iridescenceMap, iridescenceIOR,
// iridescenceThicknessRange, iridescenceThicknessMap) stay three.js's.
import * as THREE from 'three';

/**
 * The table object: {glsl, data, width, height, filter, uniform, illuminant, space}.
 * glsl: the chunk's text (defines evalIridescence and declares `uniform highp sampler2D
 * <uniform>;`); data: Float32Array of width × height RGBA texels, row-major; filter: 'linear'
 * (sampled with texture(), linear filtering) or 'nearest' (texelFetch).
 */
export function makeIridTable({ glsl, data, width, height, filter, uniform = 'iridFilmTable',
                                illuminant, space }) {
    if (typeof glsl !== 'string' || !glsl.includes('evalIridescence')) {
        throw new Error('irid table: glsl must be the chunk text that defines evalIridescence');
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
    if (!glsl.includes(uniform)) throw new Error(`irid table: the chunk does not declare '${uniform}'`);
    return { glsl, data, width, height, filter, uniform, illuminant, space };
}

/**
 * Fetches the three files `irid shader --lang glsl -o DIR` writes (irid_iridescence.glsl,
 * irid_film_table.f32, irid_film_table.json) from baseUrl (the folder's URL) and returns the
 * table object. The .f32 file is little-endian float32.
 */
export async function loadIridTable(baseUrl) {
    const base = baseUrl.endsWith('/') ? baseUrl : `${baseUrl}/`;
    const get = async (name) => {
        const response = await fetch(`${base}${name}`);
        if (!response.ok) throw new Error(`irid table: ${base}${name}: HTTP ${response.status}`);
        return response;
    };
    const [glsl, bytes, meta] = await Promise.all([
        get('irid_iridescence.glsl').then((r) => r.text()),
        get('irid_film_table.f32').then((r) => r.arrayBuffer()),
        get('irid_film_table.json').then((r) => r.json()),
    ]);
    if (bytes.byteLength % 4 !== 0) throw new Error('irid table: irid_film_table.f32 is not whole float32s');
    const view = new DataView(bytes);
    const data = new Float32Array(bytes.byteLength / 4);
    for (let i = 0; i < data.length; ++i) data[i] = view.getFloat32(4 * i, true);
    return makeIridTable({ glsl, data, width: meta.width, height: meta.height, filter: meta.filter,
                           uniform: meta.uniform, illuminant: meta.illuminant, space: meta.space });
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
 * Patches a MeshPhysicalMaterial (or any material whose fragment shader includes
 * <iridescence_fragment>) to evaluate irid's chunk. Keeps a previous onBeforeCompile and
 * customProgramCacheKey (runs and extends them). Returns the DataTexture bound to the table's
 * uniform (dispose it with the material).
 */
export function applyIridescence(material, { table }) {
    const t = makeIridTable(table);
    const texture = iridTableTexture(t);
    const chunk = `#ifdef USE_IRIDESCENCE\n${t.glsl}\n#endif\n`;
    const key = `irid-iridescence-${hashOf(`${t.filter}\n${t.glsl}`)}`;
    const previousCompile = material.onBeforeCompile;
    const previousKey = material.customProgramCacheKey;
    material.onBeforeCompile = function (shader, renderer) {
        previousCompile.call(this, shader, renderer);
        if (!shader.fragmentShader.includes('#include <iridescence_fragment>')) {
            throw new Error('applyIridescence: the fragment shader has no #include <iridescence_fragment>');
        }
        shader.fragmentShader = shader.fragmentShader.replace('#include <iridescence_fragment>', chunk);
        shader.uniforms[t.uniform] = { value: texture };
    };
    material.customProgramCacheKey = function () {
        return `${previousKey.call(this)}|${key}`;
    };
    material.needsUpdate = true;
    return texture;
}
