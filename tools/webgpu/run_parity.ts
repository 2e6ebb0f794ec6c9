// The WebGPU parity runtime's device side (include/snell/gpu/parity_webgpu.hpp
// writes the job and reads the results): SPIR-V -> WGSL with naga, then one
// compute dispatch on Deno's WebGPU (wgpu; Mesa's lavapipe in the test suite)
// by dispatch.js, which Chromium's run (chromium_page.js) shares.
//
//   deno run --allow-read --allow-write --allow-env --node-modules-dir=manual run_parity.ts JOB_DIR
//
// JOB_DIR holds job.json ({count, textures: [{levels: [[w, h], ...], mag,
// min, mip}]}), shader.spv, inputs.f32 (16 floats per case) and tex_<k>.f32
// (every level's RGBA32F texels, level 0 first). Writes shader.wgsl,
// results.f32 and adapter.txt. Any failure (translation, no adapter, a WebGPU
// error) exits with status 1 and a message on stderr.
import { spirvToWgsl } from "./naga_wgsl.ts";
import { runParityJob } from "./dispatch.js";

function fail(message: string): never {
  console.error(`run_parity.ts: ${message}`);
  Deno.exit(1);
}

const dir = Deno.args[0];
if (!dir) fail("usage: run_parity.ts JOB_DIR");
const job = JSON.parse(Deno.readTextFileSync(`${dir}/job.json`));

let wgsl = "";
try {
  wgsl = spirvToWgsl(Deno.readFileSync(`${dir}/shader.spv`));
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
