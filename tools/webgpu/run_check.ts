// snell-wgsl --run: the WGSL's entry point run once on a WebGPU device (Deno's
// wgpu; lavapipe in the test suite), with every resource it declares bound to
// a stand-in of its type (zero-filled buffers, 4x4 textures, a linear sampler):
// a fragment entry point draws one triangle over a 4x4 target with a vertex
// stage made here to feed its inputs, a compute one runs one workgroup. The
// values mean nothing; what it shows is that the pipeline builds, binds and
// executes without a WebGPU error. Reads naga's WGSL layout (an attribute line,
// then the declaration or `fn`), as dispatch.js does.

interface Binding {
  group: number;  // @group(group) @binding(binding) var<kind> name: type
  binding: number;
  kind: string;  // `var` template, e.g. "<uniform>", "<storage, read>", or ""
  type: string;
}

// The integer scalar types need flat interpolation between stages.
const integer = (type: string) => /\b(i32|u32)\b|vec\di\b|vec\du\b/.test(type);

function targetFormat(type: string): GPUTextureFormat {
  if (/\bi32\b|vec\di\b/.test(type)) return "rgba32sint";
  if (/\bu32\b|vec\du\b/.test(type)) return "rgba32uint";
  return "rgba32float";
}

// Throws an Error saying what failed.
export async function runOnce(device: GPUDevice, wgsl: string): Promise<string> {
  const entry = /^@(fragment|compute)[^\n]*\nfn (\w+)\(([^\n]*)\)(?: -> ([^{\n]*))? \{$/m.exec(wgsl);
  if (!entry) throw new Error("no fragment or compute entry point to run (a vertex shader is compiled, not run)");
  const [, stage, name, params, result] = entry;
  // The resources it declares and uses: a layout: "auto" pipeline has no slot for one no code
  // mentions (a sampler declared for texelFetch, which needs none, say).
  const bindings: Binding[] = [...wgsl.matchAll(/@group\((\d+)\)\s*@binding\((\d+)\)\s*var(<[^>]*>)?\s+(\w+)\s*:\s*([^;]+);/g)]
    .filter((m) => (wgsl.match(new RegExp(`\\b${m[4]}\\b`, "g")) ?? []).length > 1)
    .map((m) => ({ group: Number(m[1]), binding: Number(m[2]), kind: m[3] ?? "", type: m[5].trim() }));

  device.pushErrorScope("validation");
  device.pushErrorScope("internal");
  device.pushErrorScope("out-of-memory");
  let pipeline: GPURenderPipeline | GPUComputePipeline;
  let targets: GPUTextureFormat[] = [];
  if (stage === "compute") {
    pipeline = device.createComputePipeline({
      layout: "auto",
      compute: { module: device.createShaderModule({ code: wgsl }), entryPoint: name },
    });
  } else {
    // The vertex stage: a triangle covering the target, and a zero of each fragment input.
    const inputs = [...params.matchAll(/((?:@\w+(?:\([^)]*\))?\s*)+)(\w+): ([^,]+?)(?=, @|$)/g)]
      .filter((m) => m[1].includes("@location"))
      .map((m) => ({ attrs: m[1].trim(), name: m[2], type: m[3].trim() }));
    const members = inputs.map((i) =>
      `  ${i.attrs}${integer(i.type) && !i.attrs.includes("@interpolate") ? " @interpolate(flat)" : ""} ${i.name}: ${i.type},`);
    const vertex = `
struct SnellCheckVarying {
  @builtin(position) position: vec4<f32>,
${members.join("\n")}
}
@vertex
fn snellCheckVertex(@builtin(vertex_index) i: u32) -> SnellCheckVarying {
  var v: SnellCheckVarying;
  v.position = vec4<f32>(f32(i & 1u) * 4.0 - 1.0, f32(i >> 1u) * 4.0 - 1.0, 0.5, 1.0);
${inputs.map((i) => `  v.${i.name} = ${i.type}();`).join("\n")}
  return v;
}
`;
    // The targets: the return type's @location, or a struct's @location members.
    const out = (result ?? "").trim();
    if (out.startsWith("@location")) targets = [targetFormat(out)];
    else if (out) {
      const struct = new RegExp(`^struct ${out} \\{\\n([\\s\\S]*?)^\\}`, "m").exec(wgsl);
      for (const m of (struct?.[1] ?? "").matchAll(/@location\((\d+)\)[^:]*: ([^,\n]+)/g))
        targets[Number(m[1])] = targetFormat(m[2]);
    }
    const module = device.createShaderModule({ code: wgsl + vertex });
    pipeline = device.createRenderPipeline({
      layout: "auto",
      vertex: { module, entryPoint: "snellCheckVertex" },
      fragment: { module, entryPoint: name, targets: [...targets].map((format) => ({ format })) },
      primitive: { topology: "triangle-list" },
    });
  }

  // Stand-ins for the resources, bind group by bind group.
  const groups = new Map<number, GPUBindGroupEntry[]>();
  const made: { destroy(): void }[] = [];
  for (const b of bindings) {
    let resource: GPUBindingResource;
    if (b.kind.startsWith("<uniform") || b.kind.startsWith("<storage")) {
      const uniform = b.kind.startsWith("<uniform");
      const size = uniform ? Math.min(65536, device.limits.maxUniformBufferBindingSize) : 1 << 20;
      const buffer = device.createBuffer({ size, usage: uniform ? GPUBufferUsage.UNIFORM : GPUBufferUsage.STORAGE });
      made.push(buffer);
      resource = { buffer };
    } else if (b.type.startsWith("sampler_comparison")) {
      resource = device.createSampler({ compare: "less" });
    } else if (b.type.startsWith("sampler")) {
      resource = device.createSampler({ magFilter: "linear", minFilter: "linear", mipmapFilter: "linear" });
    } else if (b.type.startsWith("texture_storage")) {
      throw new Error(`--run makes no stand-in for a storage texture (${b.type}, group ${b.group} binding ${b.binding})`);
    } else if (b.type.startsWith("texture")) {
      const depth = b.type.startsWith("texture_depth");
      const cube = b.type.includes("cube");
      const array = b.type.includes("array");
      const format: GPUTextureFormat = depth ? "depth32float" : /<i32>/.test(b.type) ? "rgba32sint" :
        /<u32>/.test(b.type) ? "rgba32uint" : "rgba16float";
      const texture = device.createTexture({
        size: [4, 4, cube ? (array ? 12 : 6) : array ? 2 : 1],
        format,
        usage: GPUTextureUsage.TEXTURE_BINDING,
      });
      made.push(texture);
      resource = texture.createView({ dimension: cube ? (array ? "cube-array" : "cube") : array ? "2d-array" : "2d" });
    } else {
      throw new Error(`--run makes no stand-in for ${b.type} (group ${b.group} binding ${b.binding})`);
    }
    groups.set(b.group, [...(groups.get(b.group) ?? []), { binding: b.binding, resource }]);
  }

  const encoder = device.createCommandEncoder();
  const setGroups = (pass: GPURenderPassEncoder | GPUComputePassEncoder) => {
    for (const [group, entries] of groups)
      pass.setBindGroup(group, device.createBindGroup({ layout: pipeline.getBindGroupLayout(group), entries }));
  };
  if (stage === "compute") {
    const pass = encoder.beginComputePass();
    pass.setPipeline(pipeline as GPUComputePipeline);
    setGroups(pass);
    pass.dispatchWorkgroups(1);
    pass.end();
  } else {
    const views = [...targets].map((format) => {
      const t = device.createTexture({ size: [4, 4], format, usage: GPUTextureUsage.RENDER_ATTACHMENT });
      made.push(t);
      return t.createView();
    });
    const pass = encoder.beginRenderPass({
      colorAttachments: views.map((view) => ({ view, loadOp: "clear", storeOp: "store" })),
    });
    pass.setPipeline(pipeline as GPURenderPipeline);
    setGroups(pass);
    pass.draw(3);
    pass.end();
  }
  device.queue.submit([encoder.finish()]);
  await device.queue.onSubmittedWorkDone();
  const errors = [await device.popErrorScope(), await device.popErrorScope(), await device.popErrorScope()]
    .filter((e) => e !== null);
  for (const m of made) m.destroy();
  if (errors.length) throw new Error(errors.map((e) => e!.message).join("\n"));
  return stage === "compute" ? `${name} ran one workgroup` :
    `${name} drew a 4x4 target with ${bindings.length} resources bound`;
}
