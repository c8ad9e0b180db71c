// Evaluates irid's WGSL chunk (`irid shader --lang wgsl`: irid_eval(table, outsideIOR, eta2,
// cosTheta1, thinFilmThickness, baseF0)) on parameter sets in a WebGPU compute shader and reads
// the colours back: the WGSL counterpart of film-grid.js, for the browser tests.

/** The WGSL text before its module-scope binding (the part that takes the table as a parameter). */
export function wgslFunctions(wgsl) {
    const marker = '\n// --- evalIridescence with the table bound at module scope ---\n';
    const at = wgsl.indexOf(marker);
    if (at < 0) throw new Error('film-grid-webgpu: the WGSL chunk has no binding marker');
    return wgsl.slice(0, at);
}

/** A WebGPU device, or an Error naming what is missing. */
export async function webgpuDevice() {
    if (!navigator.gpu) throw new Error('WebGPU: navigator.gpu is missing (not a secure context, or no --enable-unsafe-webgpu)');
    const adapter = await navigator.gpu.requestAdapter();
    if (!adapter) throw new Error('WebGPU: no adapter');
    const device = await adapter.requestDevice();
    return { device, adapter: adapter.info ? `${adapter.info.vendor} ${adapter.info.architecture}` : 'unknown' };
}

/**
 * Colours of the sets (7 floats a set: outsideIOR, eta2, cosTheta1, thickness [nm], baseF0 r,
 * g, b) through the chunk, 3 floats a set. table: {data: Float32Array, width, height}.
 */
export async function evaluateWgsl(device, wgsl, table, params) {
    const count = params.length / 7;
    const code = `${wgslFunctions(wgsl)}
@group(0) @binding(0) var<storage, read> gridParams: array<f32>;
@group(0) @binding(1) var<storage, read_write> gridResult: array<f32>;
@group(0) @binding(2) var gridTable: texture_2d<f32>;
@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) id: vec3u) {
    let i = id.x + 65535u * 64u * id.y;
    if (i >= ${count}u) {
        return;
    }
    let p = 7u * i;
    let c = irid_eval(gridTable, gridParams[p], gridParams[p + 1u], gridParams[p + 2u], gridParams[p + 3u],
                      vec3f(gridParams[p + 4u], gridParams[p + 5u], gridParams[p + 6u]));
    gridResult[3u * i] = c.x;
    gridResult[3u * i + 1u] = c.y;
    gridResult[3u * i + 2u] = c.z;
}
`;
    device.pushErrorScope('validation');
    const module = device.createShaderModule({ code });
    const info = await module.getCompilationInfo();
    const errors = info.messages.filter((m) => m.type === 'error');
    if (errors.length) {
        throw new Error(`WGSL: ${errors.map((m) => `line ${m.lineNum}: ${m.message}`).join('; ')}`);
    }
    const pipeline = device.createComputePipeline({ layout: 'auto', compute: { module, entryPoint: 'main' } });
    const input = device.createBuffer({ size: Math.max(16, params.byteLength), usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST });
    device.queue.writeBuffer(input, 0, params);
    const bytes = Math.max(16, count * 12);
    const output = device.createBuffer({ size: bytes, usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC });
    const readback = device.createBuffer({ size: bytes, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });
    const texture = device.createTexture({ size: [table.width, table.height], format: 'rgba32float',
                                           usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST });
    device.queue.writeTexture({ texture }, table.data, { bytesPerRow: table.width * 16 }, [table.width, table.height]);
    const bind = device.createBindGroup({
        layout: pipeline.getBindGroupLayout(0),
        entries: [{ binding: 0, resource: { buffer: input } }, { binding: 1, resource: { buffer: output } },
                  { binding: 2, resource: texture.createView() }],
    });
    const encoder = device.createCommandEncoder();
    const pass = encoder.beginComputePass();
    pass.setPipeline(pipeline);
    pass.setBindGroup(0, bind);
    const groups = Math.ceil(count / 64);
    pass.dispatchWorkgroups(Math.min(groups, 65535), Math.ceil(groups / 65535));
    pass.end();
    encoder.copyBufferToBuffer(output, 0, readback, 0, bytes);
    device.queue.submit([encoder.finish()]);
    await readback.mapAsync(GPUMapMode.READ);
    const out = new Float32Array(readback.getMappedRange().slice(0, count * 12));
    readback.unmap();
    const error = await device.popErrorScope();
    if (error) throw new Error(`WebGPU: ${error.message}`);
    for (const b of [input, output, readback]) b.destroy();
    texture.destroy();
    return out;
}
