// Tint (Dawn's WGSL compiler, the one Chrome's WebGPU uses) on WGSL files: the
// npm package webgpu (dawn.node) with its null backend, which runs Tint's
// parser and validator and needs no GPU. wgpu (Deno) and Tint disagree on
// some WGSL (naga's 39-digit float literals: wgpu accepts them, Tint does
// not), so the WebGPU runtime and snell-wgsl --check pass both.
//
//   node tint_check.mjs FILE.wgsl...
//
// Exit status 1, with each rejection's line, column and message, when Tint
// rejects any file.
import { create, globals } from "webgpu";
import { readFileSync } from "node:fs";

Object.assign(globalThis, globals);
const adapter = await create(["backend=null"]).requestAdapter();
if (!adapter) {
  console.error("tint_check: dawn.node gives no adapter for its null backend");
  process.exit(1);
}
const device = await adapter.requestDevice();
let rejected = 0;
for (const file of process.argv.slice(2)) {
  const info = await device.createShaderModule({ code: readFileSync(file, "utf8") }).getCompilationInfo();
  const errors = info.messages.filter((m) => m.type === "error");
  if (errors.length) {
    ++rejected;
    console.error(`tint_check: Tint rejects ${file}:\n` + errors.map((m) => `  ${m.lineNum}:${m.linePos} ${m.message}`).join("\n"));
  }
}
process.exit(rejected ? 1 : 0);
