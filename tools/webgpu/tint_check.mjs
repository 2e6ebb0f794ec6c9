// Tint (Dawn's WGSL compiler, the one Chrome's WebGPU uses) on WGSL files: the
// npm package webgpu (dawn.node) with its null backend, which runs Tint's
// parser and validator and needs no GPU. wgpu (Deno) and Tint disagree on
// some WGSL (naga's 39-digit float literals: wgpu accepts them, Tint does
// not), so the WebGPU runtime and snell-wgsl --check pass both.
//
//   node tint_check.mjs FILE.wgsl...
//
// Exit status 1, with each rejection's line, column and message, when Tint
// rejects any file. tint_server.mjs runs the same checks for a whole ctest run
// in one process.
import { create, globals } from "webgpu";
import { readFileSync, realpathSync } from "node:fs";
import { pathToFileURL } from "node:url";

// dawn.node's null-backend device. Throws when there is none.
export async function openTint() {
  Object.assign(globalThis, globals);
  const gpu = create(["backend=null"]);
  const adapter = await gpu.requestAdapter();
  if (!adapter) throw new Error("dawn.node gives no adapter for its null backend");
  const device = await adapter.requestDevice();
  // Kept reachable: dawn.node aborts when its GPU or adapter object is collected while a device lives.
  globalThis.snellTint = { gpu, adapter, device };
  return device;
}

// Tint on `file`: {validation, rejection}, both "" when Tint accepts it. validation is the error
// dawn.node prints on stdout when nothing captures it (the one-shot script prints it there, as it
// always has); rejection is the script's own message for stderr. One check at a time per device:
// error scopes are a stack.
export async function tintCheck(device, file) {
  const code = readFileSync(file, "utf8");
  device.pushErrorScope("validation");
  const info = await device.createShaderModule({ code }).getCompilationInfo();
  const error = await device.popErrorScope();
  const errors = info.messages.filter((m) => m.type === "error");
  return {
    validation: error ? `validation:\n${error.message}` : "",
    rejection: errors.length
      ? `tint_check: Tint rejects ${file}:\n` + errors.map((m) => `  ${m.lineNum}:${m.linePos} ${m.message}`).join("\n") + "\n"
      : "",
  };
}

// Run as a script (Node gives the module its real path: a symlinked script must still check).
if (process.argv[1] && import.meta.url === pathToFileURL(realpathSync(process.argv[1])).href) {
  let device;
  try {
    device = await openTint();
  } catch (e) {
    console.error(`tint_check: ${e.message}`);
    process.exit(1);
  }
  let rejected = 0;
  for (const file of process.argv.slice(2)) {
    const { validation, rejection } = await tintCheck(device, file);
    process.stdout.write(validation);
    process.stderr.write(rejection);
    if (rejection) ++rejected;
  }
  process.exit(rejected ? 1 : 0);
}
