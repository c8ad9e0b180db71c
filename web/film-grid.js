// Evaluates a GLSL `evalIridescence(outsideIOR, eta2, cosTheta1, thinFilmThickness, baseF0)`
// in WebGL2, one fragment per parameter set, into an RGBA32F target read back as floats; and
// times a full-screen quad of it. The browser tests' page helper (plain WebGL2, no three.js).
//
// A chunk is {glsl, table}: glsl is the source that defines evalIridescence (with whatever it
// needs before it), table is null or {data: Float32Array of RGBA texels, width, height,
// filter: 'linear' | 'nearest', uniform: the sampler's name}, bound to texture unit 2.

const vertexShader = `#version 300 es
in vec2 corner;
void main() { gl_Position = vec4(corner, 0.0, 1.0); }
`;

/** A WebGL2 context with float render targets; throws when the browser lacks them. */
export function createContext() {
    const canvas = document.createElement('canvas');
    canvas.width = canvas.height = 1;
    const gl = canvas.getContext('webgl2', { antialias: false, preserveDrawingBuffer: false });
    if (!gl) throw new Error('no WebGL2 context');
    if (!gl.getExtension('EXT_color_buffer_float')) throw new Error('no EXT_color_buffer_float');
    gl.getExtension('OES_texture_float_linear');
    const quad = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, quad);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array([-1, -1, 1, -1, -1, 1, 1, 1]), gl.STATIC_DRAW);
    return gl;
}

function floatTexture(gl, width, height, data, filter) {
    const tex = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, tex);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, width, height, 0, gl.RGBA, gl.FLOAT, data);
    const f = filter === 'linear' ? gl.LINEAR : gl.NEAREST;
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, f);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, f);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    return tex;
}

function floatTarget(gl, width, height) {
    const tex = floatTexture(gl, width, height, null, 'nearest');
    const fbo = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, tex, 0);
    const status = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
    if (status !== gl.FRAMEBUFFER_COMPLETE) throw new Error(`RGBA32F target incomplete (${status})`);
    return { fbo, tex };
}

function compile(gl, fragmentSource, label) {
    const shader = (type, source) => {
        const s = gl.createShader(type);
        gl.shaderSource(s, source);
        gl.compileShader(s);
        if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) {
            throw new Error(`${label}: shader does not compile: ${gl.getShaderInfoLog(s)}`);
        }
        return s;
    };
    const program = gl.createProgram();
    gl.attachShader(program, shader(gl.VERTEX_SHADER, vertexShader));
    gl.attachShader(program, shader(gl.FRAGMENT_SHADER, fragmentSource));
    gl.bindAttribLocation(program, 0, 'corner');
    gl.linkProgram(program);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS)) {
        throw new Error(`${label}: program does not link: ${gl.getProgramInfoLog(program)}`);
    }
    return program;
}

function header(chunk) {
    return `#version 300 es
precision highp float;
precision highp int;
precision highp sampler2D;
${chunk.glsl}
out vec4 fragColor;
`;
}

function draw(gl, program, chunk, tableTexture, width, height) {
    gl.useProgram(program);
    if (chunk.table) {
        gl.activeTexture(gl.TEXTURE2);
        gl.bindTexture(gl.TEXTURE_2D, tableTexture);
        gl.uniform1i(gl.getUniformLocation(program, chunk.table.uniform), 2);
    }
    gl.viewport(0, 0, width, height);
    gl.enableVertexAttribArray(0);
    gl.vertexAttribPointer(0, 2, gl.FLOAT, false, 0, 0);
    gl.drawArrays(gl.TRIANGLE_STRIP, 0, 4);
}

function tableTextureOf(gl, chunk) {
    const t = chunk.table;
    if (!t) return null;
    if (t.data.length !== t.width * t.height * 4) {
        throw new Error(`table: ${t.data.length} floats, but ${t.width}×${t.height} RGBA texels need ${t.width * t.height * 4}`);
    }
    return floatTexture(gl, t.width, t.height, t.data, t.filter);
}

/**
 * evalIridescence of each parameter set: params is a Float32Array of 7 floats a set (outsideIOR,
 * eta2, cosTheta1, thickness [nm], baseF0 r, g, b). Returns a Float32Array of 3 floats a set.
 */
export function renderGrid(gl, chunk, params, label = 'chunk') {
    const count = params.length / 7;
    const width = Math.min(count, 256);
    const height = Math.ceil(count / width);
    const a = new Float32Array(width * height * 4);
    const b = new Float32Array(width * height * 4);
    for (let i = 0; i < count; ++i) {
        for (let k = 0; k < 4; ++k) a[4 * i + k] = params[7 * i + k];
        for (let k = 0; k < 3; ++k) b[4 * i + k] = params[7 * i + 4 + k];
    }
    const program = compile(gl, `${header(chunk)}
uniform highp sampler2D gridParamsA;  // outsideIOR, eta2, cosTheta1, thickness
uniform highp sampler2D gridParamsB;  // baseF0
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 a = texelFetch(gridParamsA, p, 0);
    vec3 f0 = texelFetch(gridParamsB, p, 0).rgb;
    fragColor = vec4(evalIridescence(a.x, a.y, a.z, a.w, f0), 1.0);
}
`, label);
    const target = floatTarget(gl, width, height);
    const texA = floatTexture(gl, width, height, a, 'nearest');
    const texB = floatTexture(gl, width, height, b, 'nearest');
    const table = tableTextureOf(gl, chunk);
    gl.useProgram(program);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, texA);
    gl.uniform1i(gl.getUniformLocation(program, 'gridParamsA'), 0);
    gl.activeTexture(gl.TEXTURE1);
    gl.bindTexture(gl.TEXTURE_2D, texB);
    gl.uniform1i(gl.getUniformLocation(program, 'gridParamsB'), 1);
    gl.bindFramebuffer(gl.FRAMEBUFFER, target.fbo);
    draw(gl, program, chunk, table, width, height);
    const pixels = new Float32Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.FLOAT, pixels);
    const out = new Float32Array(count * 3);
    for (let i = 0; i < count; ++i) for (let k = 0; k < 3; ++k) out[3 * i + k] = pixels[4 * i + k];
    for (const o of [program]) gl.deleteProgram(o);
    for (const t of [texA, texB, table, target.tex]) if (t) gl.deleteTexture(t);
    gl.deleteFramebuffer(target.fbo);
    return out;
}

/**
 * Milliseconds per frame of a size × size full-screen quad into an RGBA32F target, for each
 * chunk of `chunks` ({name: chunk}): parameters vary across the screen (film index 1.2–2.4
 * along x, cos θ 1–0 along y, grazing incidence included, thickness 0–2000 nm in stripes, a
 * dielectric base, the right quarter under a clearcoat of 1.5). After
 * `warmup` frames, the chunks' frames are interleaved (so that a change of the machine's load
 * falls on all alike); each frame is synchronised by reading one pixel back. Returns
 * {name: {median, frames: [...]}}.
 */
export function timeChunks(gl, chunks, { size = 1024, frames = 7, warmup = 2 } = {}) {
    const target = floatTarget(gl, size, size);
    const programs = {};
    for (const [name, chunk] of Object.entries(chunks)) {
        const program = compile(gl, `${header(chunk)}
uniform vec2 viewSize;
void main() {
    vec2 uv = gl_FragCoord.xy / viewSize;
    float eta2 = 1.2 + 1.2 * uv.x;
    float cosTheta1 = 1.0 - uv.y;
    float thickness = 2000.0 * fract(3.0 * uv.x + 7.0 * uv.y);
    vec3 baseF0 = vec3(0.02 + 0.16 * uv.y, 0.04, 0.02 + 0.16 * uv.x);
    float outsideIOR = uv.x > 0.75 ? 1.5 : 1.0;
    fragColor = vec4(evalIridescence(outsideIOR, eta2, cosTheta1, thickness, baseF0), 1.0);
}
`, name);
        programs[name] = { program, chunk, table: tableTextureOf(gl, chunk), frames: [] };
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, target.fbo);
    const pixel = new Float32Array(4);
    const frame = (p) => {
        gl.useProgram(p.program);
        gl.uniform2f(gl.getUniformLocation(p.program, 'viewSize'), size, size);
        const t0 = performance.now();
        draw(gl, p.program, p.chunk, p.table, size, size);
        gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, pixel);
        return performance.now() - t0;
    };
    for (let i = 0; i < warmup; ++i) for (const p of Object.values(programs)) frame(p);
    for (let i = 0; i < frames; ++i) for (const p of Object.values(programs)) p.frames.push(frame(p));
    const out = {};
    for (const [name, p] of Object.entries(programs)) {
        const sorted = [...p.frames].sort((x, y) => x - y);
        out[name] = { median: sorted[Math.floor(sorted.length / 2)], frames: p.frames };
        gl.deleteProgram(p.program);
        if (p.table) gl.deleteTexture(p.table);
    }
    gl.deleteTexture(target.tex);
    gl.deleteFramebuffer(target.fbo);
    return out;
}

/**
 * three.js's own evalIridescence with what it needs before it (its common chunk: PI, pow2,
 * F_Schlick), given three's ShaderChunk. schlick: 'three' keeps three's F_Schlick (Epic's
 * exp2 fit of Schlick's factor); 'pow5' puts Schlick's (1 − cos θ)⁵ back, as the glTF Sample
 * Renderer's iridescence has it, so that the chunk is the glTF model irid ports on the CPU.
 */
export function stockChunk(ShaderChunk, { schlick = 'three' } = {}) {
    let common = ShaderChunk.common;
    if (schlick === 'pow5') {
        const fit = /float fresnel = exp2\( \( - 5\.55473 \* dotVH - 6\.98316 \) \* dotVH \);/g;
        const count = (common.match(fit) || []).length;
        if (count !== 2) throw new Error(`stockChunk: expected three's two exp2 Schlick fits, found ${count}`);
        common = common.replace(fit, 'float m = clamp( 1.0 - dotVH, 0.0, 1.0 ); float fresnel = m * m * m * m * m;');
    } else if (schlick !== 'three') {
        throw new Error(`stockChunk: schlick '${schlick}' is neither 'three' nor 'pow5'`);
    }
    return { glsl: `#define USE_IRIDESCENCE\n${common}\n${ShaderChunk.iridescence_fragment}`, table: null };
}
