// One parity job on a WebGPU device, for Deno (run_parity.ts, wgpu on lavapipe)
// and for Chromium (chromium_page.js, Dawn on SwiftShader): the same bindings,
// textures, samplers and dispatch on both. Bindings: 0 inputs, 1 results, 2 the
// case count (a uniform: Deno's WebGPU has no push constants), 16 + 2k texture
// k, 17 + 2k its sampler. Throws an Error naming what failed.
//
//   job: {count, textures: [{levels: [[w, h], ...], mag, min, mip}]}
//   readFile(name): the job file's bytes (an ArrayBuffer): inputs.f32, tex_<k>.f32
//   returns {results: Uint8Array (16 floats per case), adapter: string}
export async function runParityJob(gpu, job, wgsl, readFile) {
  const textureData = [];
  for (let k = 0; k < job.textures.length; ++k) textureData.push(new Float32Array(await readFile(`tex_${k}.f32`)));
  const adapter = await gpu.requestAdapter();
  if (!adapter) throw new Error("no WebGPU adapter (Deno's WebGPU runs on Vulkan: is mesa-vulkan-drivers installed? Chromium's on SwiftShader: --enable-unsafe-webgpu)");
  // A LINEAR filter on an RGBA32F texture needs float32-filterable (not core WebGPU).
  const filtering = (t) => t.mag === "linear" || t.min === "linear" || t.mip === "linear";
  const needsF32Filter = job.textures.some(filtering);
  if (needsF32Filter && !adapter.features.has("float32-filterable"))
    throw new Error(`the adapter (${adapter.info.description}) lacks float32-filterable, which a LINEAR RGBA32F texture needs`);
  const device = await adapter.requestDevice({
    requiredFeatures: needsF32Filter ? ["float32-filterable"] : [],
    requiredLimits: { maxStorageBufferBindingSize: adapter.limits.maxStorageBufferBindingSize },
  });
  const adapterName = `${adapter.info.description} (${adapter.info.vendor}, ${adapter.info.architecture})`;

  device.pushErrorScope("validation");
  device.pushErrorScope("internal");
  const module = device.createShaderModule({ code: wgsl });
  const messages = (await module.getCompilationInfo()).messages.filter((m) => m.type === "error");
  if (messages.length) throw new Error("WGSL compilation: " + messages.map((m) => `${m.lineNum}:${m.linePos} ${m.message}`).join("; "));

  // The bindings the WGSL declares (naga drops unused ones), each typed from its declaration.
  const decls = [...wgsl.matchAll(/@group\(0\)\s*@binding\((\d+)\)\s*var(<[^>]*>)?\s+\w+\s*:\s*([^;]+);/g)]
    .map((m) => ({ binding: Number(m[1]), kind: m[2] ?? "", type: m[3].trim() }));
  const slot = (binding) => (binding - 16) >> 1;
  const entries = decls.map((d) => {
    const e = { binding: d.binding, visibility: GPUShaderStage.COMPUTE };
    if (d.kind.startsWith("<storage")) e.buffer = { type: d.kind.includes("read_write") ? "storage" : "read-only-storage" };
    else if (d.kind.startsWith("<uniform")) e.buffer = { type: "uniform" };
    else if (d.type.startsWith("texture_2d")) {
      e.texture = { sampleType: filtering(job.textures[slot(d.binding)]) ? "float" : "unfilterable-float" };
    } else if (d.type === "sampler") e.sampler = { type: filtering(job.textures[slot(d.binding)]) ? "filtering" : "non-filtering" };
    else throw new Error(`binding ${d.binding}: unexpected ${d.kind} ${d.type}`);
    return e;
  });
  const layout = device.createBindGroupLayout({ entries });
  const pipeline = await device.createComputePipelineAsync({
    layout: device.createPipelineLayout({ bindGroupLayouts: [layout] }),
    compute: { module, entryPoint: "main" },
  });

  const inputs = new Float32Array(await readFile("inputs.f32"));
  const bytes = Math.max(inputs.byteLength, 16);
  const inBuf = device.createBuffer({ size: bytes, usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_DST });
  device.queue.writeBuffer(inBuf, 0, inputs);
  const outBuf = device.createBuffer({ size: bytes, usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC });
  const readBuf = device.createBuffer({ size: bytes, usage: GPUBufferUsage.MAP_READ | GPUBufferUsage.COPY_DST });
  const params = device.createBuffer({ size: 16, usage: GPUBufferUsage.UNIFORM | GPUBufferUsage.COPY_DST });
  device.queue.writeBuffer(params, 0, new Int32Array([job.count, 0, 0, 0]));

  // As the Vulkan runtime: clamp to edge, the texture's own filters, and a texture without mips
  // clamped to level 0 (lodMaxClamp 0.25: GL's GL_NEAREST / GL_LINEAR minification).
  const made = new Map();
  function texture(k) {
    const t = job.textures[k];
    if (!t) throw new Error(`the shader reads texture slot ${k}, the job has ${job.textures.length}`);
    if (!made.has(k)) {
      const data = textureData[k];
      const tex = device.createTexture({
        size: t.levels[0], mipLevelCount: t.levels.length, format: "rgba32float",
        usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.COPY_DST,
      });
      let offset = 0;
      t.levels.forEach(([w, h], level) => {
        device.queue.writeTexture({ texture: tex, mipLevel: level }, data.subarray(offset, offset + 4 * w * h),
          { bytesPerRow: 16 * w, rowsPerImage: h }, [w, h]);
        offset += 4 * w * h;
      });
      const sampler = device.createSampler({
        addressModeU: "clamp-to-edge", addressModeV: "clamp-to-edge",
        magFilter: t.mag, minFilter: t.min,
        mipmapFilter: (t.mip === "linear" ? "linear" : "nearest"),
        lodMinClamp: 0, lodMaxClamp: t.mip === "none" ? 0.25 : t.levels.length - 1,
      });
      made.set(k, { tex, view: tex.createView(), sampler });
    }
    return made.get(k);
  }
  const bindGroup = device.createBindGroup({
    layout,
    entries: decls.map((d) => {
      if (d.binding === 0) return { binding: 0, resource: { buffer: inBuf } };
      if (d.binding === 1) return { binding: 1, resource: { buffer: outBuf } };
      if (d.binding === 2) return { binding: 2, resource: { buffer: params } };
      const t = texture(slot(d.binding));
      return { binding: d.binding, resource: d.type === "sampler" ? t.sampler : t.view };
    }),
  });

  const encoder = device.createCommandEncoder();
  const pass = encoder.beginComputePass();
  pass.setPipeline(pipeline);
  pass.setBindGroup(0, bindGroup);
  pass.dispatchWorkgroups(Math.ceil(job.count / 64));
  pass.end();
  encoder.copyBufferToBuffer(outBuf, 0, readBuf, 0, bytes);
  device.queue.submit([encoder.finish()]);
  await readBuf.mapAsync(GPUMapMode.READ);
  const results = new Uint8Array(readBuf.getMappedRange().slice(0, inputs.byteLength));
  readBuf.unmap();
  const internalError = await device.popErrorScope();
  const validationError = await device.popErrorScope();
  if (validationError || internalError) throw new Error(`WebGPU error: ${(validationError ?? internalError).message}`);
  // parity_server.ts keeps the device for the next job (a failed job's device it destroys whole).
  for (const b of [inBuf, outBuf, readBuf, params]) b.destroy();
  for (const t of made.values()) t.tex.destroy();
  return { results, adapter: adapterName };
}
