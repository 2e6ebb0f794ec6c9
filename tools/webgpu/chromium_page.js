// The WebGPU smoke run's page in Chromium (served by tools/browser/run_page.mjs
// --webgpu): the WGSL a parity job's Deno run left (shader.wgsl), dispatched by
// dispatch.js on Chromium's WebGPU (Dawn; its SwiftShader adapter with no GPU).
import { get, post } from "/browser/page_io.js";
import { runParityJob } from "/lib/dispatch.js";

async function run() {
  if (!navigator.gpu) throw new Error("this browser has no WebGPU (Chromium needs --enable-unsafe-webgpu)");
  const job = await (await get("job.json")).json();
  const wgsl = await (await get("shader.wgsl")).text();
  const started = performance.now();
  const { results, adapter } = await runParityJob(navigator.gpu, job, wgsl, async (name) => (await get(name)).arrayBuffer());
  await post("/renderer", adapter);
  await post("/log", `compile and dispatch ${(performance.now() - started).toFixed(0)} ms`);
  await post("/results", results);
}

run().catch((e) => post("/error", `${e.message ?? e}`));
