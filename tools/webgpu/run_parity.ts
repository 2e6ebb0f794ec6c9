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
// error) exits with status 1 and a message on stderr. parity_server.ts runs
// the same runParityDir for every job of a ctest run in one process.
import { readableWgsl, type ReadableOptions, spirvOptPasses } from "./readable_wgsl.ts";
import { runParityJob } from "./dispatch.js";

// What the script prints for a failed job (the server answers the same).
export function failureText(e: unknown): string {
  return `run_parity.ts: ${e instanceof Error ? e.message : String(e)}\n`;
}

// The job in `dir` on `gpu` (navigator.gpu, or parity_server.ts's kept adapter and device); throws an
// Error on any failure.
export async function runParityDir(gpu: { requestAdapter(): Promise<unknown> }, dir: string,
                                   options: ReadableOptions = {}): Promise<void> {
  const job = JSON.parse(Deno.readTextFileSync(`${dir}/job.json`));
  let wgsl = "";
  try {
    wgsl = readableWgsl(Deno.readFileSync(`${dir}/shader.spv`), options);
  } catch (e) {
    throw new Error(`naga cannot translate ${dir}/shader.spv to WGSL: ${(e as Error).message}`);
  }
  Deno.writeTextFileSync(`${dir}/shader.wgsl`, wgsl);
  const { results, adapter } = await runParityJob(gpu, job, wgsl,
    (name: string) => Promise.resolve(Deno.readFileSync(`${dir}/${name}`).buffer));
  Deno.writeTextFileSync(`${dir}/adapter.txt`, `${adapter}\n`);
  Deno.writeFileSync(`${dir}/results.f32`, results);
}

if (import.meta.main) {
  const fail = (e: unknown): never => {
    Deno.stderr.writeSync(new TextEncoder().encode(failureText(e)));
    Deno.exit(1);
  };
  const dir = Deno.args[0];
  const spirvOpt = Deno.args[1] === "--spirv-opt";
  if (!dir || Deno.args.length > (spirvOpt ? 2 : 1)) fail("usage: run_parity.ts JOB_DIR [--spirv-opt]");

  const optimize = (spirv: Uint8Array): Uint8Array => {
    Deno.writeFileSync(`${dir}/shader.tidy.spv`, spirv);
    const r = new Deno.Command("spirv-opt", {
      args: ["--target-env=vulkan1.1", ...spirvOptPasses, `${dir}/shader.tidy.spv`, "-o", `${dir}/shader.opt.spv`],
      stderr: "piped",
    }).outputSync();
    if (!r.success) fail(`spirv-opt failed on ${dir}/shader.tidy.spv:\n${new TextDecoder().decode(r.stderr)}`);
    return Deno.readFileSync(`${dir}/shader.opt.spv`);
  };
  await runParityDir(navigator.gpu, dir, spirvOpt ? { optimize } : {}).catch(fail);
}
