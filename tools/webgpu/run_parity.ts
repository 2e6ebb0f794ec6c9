// The WebGPU parity runtime's device side (include/snell/gpu/parity_webgpu.hpp
// writes the job and reads the results): SPIR-V -> WGSL with naga, named and
// shaped as snell-wgsl writes it (readable_wgsl.ts: GLSL names, parameters by
// value, glslang's branches for || and && as | and &), then one compute dispatch on Deno's WebGPU
// (wgpu; Mesa's lavapipe in the test suite) by dispatch.js, which Chromium's
// run (chromium_page.js) shares.
//
//   deno run --allow-read --allow-write --allow-env --node-modules-dir=manual run_parity.ts JOB_DIR [--spirv-opt]
//
// --spirv-opt (needs --allow-run as well): also spirv-opt's passes, as snell-wgsl runs them, so
// the job's WGSL is exactly what snell-wgsl writes for its shader. The test suite runs without it
// (parity_webgpu.hpp gives Deno no --allow-run).
//
// JOB_DIR holds job.json ({count, textures: [{levels: [[w, h], ...], mag,
// min, mip}]}), shader.spv, inputs.f32 (16 floats per case) and tex_<k>.f32
// (every level's RGBA32F texels, level 0 first). Writes shader.wgsl,
// results.f32 and adapter.txt. Any failure (translation, no adapter, a WebGPU
// error) exits with status 1 and a message on stderr.
import { readableWgsl, spirvOptPasses } from "./readable_wgsl.ts";
import { runParityJob } from "./dispatch.js";

function fail(message: string): never {
  console.error(`run_parity.ts: ${message}`);
  Deno.exit(1);
}

const dir = Deno.args[0];
const spirvOpt = Deno.args[1] === "--spirv-opt";
if (!dir || Deno.args.length > (spirvOpt ? 2 : 1)) fail("usage: run_parity.ts JOB_DIR [--spirv-opt]");
const job = JSON.parse(Deno.readTextFileSync(`${dir}/job.json`));

function optimize(spirv: Uint8Array): Uint8Array {
  Deno.writeFileSync(`${dir}/shader.tidy.spv`, spirv);
  const r = new Deno.Command("spirv-opt", {
    args: ["--target-env=vulkan1.1", ...spirvOptPasses, `${dir}/shader.tidy.spv`, "-o", `${dir}/shader.opt.spv`],
    stderr: "piped",
  }).outputSync();
  if (!r.success) fail(`spirv-opt failed on ${dir}/shader.tidy.spv:\n${new TextDecoder().decode(r.stderr)}`);
  return Deno.readFileSync(`${dir}/shader.opt.spv`);
}

let wgsl = "";
try {
  wgsl = readableWgsl(Deno.readFileSync(`${dir}/shader.spv`), spirvOpt ? { optimize } : {});
} catch (e) {
  fail(`naga cannot translate ${dir}/shader.spv to WGSL: ${(e as Error).message}`);
}
Deno.writeTextFileSync(`${dir}/shader.wgsl`, wgsl);

try {
  const { results, adapter } = await runParityJob(navigator.gpu, job, wgsl,
    (name: string) => Promise.resolve(Deno.readFileSync(`${dir}/${name}`).buffer));
  Deno.writeTextFileSync(`${dir}/adapter.txt`, `${adapter}\n`);
  Deno.writeFileSync(`${dir}/results.f32`, results);
} catch (e) {
  fail((e as Error).message);
}
