// SPIR-V to WGSL with naga (npm naga-wasm), for readable_wgsl.ts (run_parity.ts and snell_wgsl.ts).
import { parseSpirv, validate, writeWgsl, NagaError } from "naga-wasm";

// The WGSL of a SPIR-V module; throws an Error with naga's message when it cannot translate it.
export function spirvToWgsl(spirv: Uint8Array): string {
  try {
    const module = parseSpirv(spirv);
    const info = validate(module);
    const wgsl = writeWgsl(module, info);
    module.free();
    info.free();
    return wgsl;
  } catch (e) {
    throw new Error(e instanceof NagaError ? `${e.kind}: ${e.message}\n${e.formatted}` : String(e));
  }
}
