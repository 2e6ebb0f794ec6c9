// SPIR-V from glslang to WGSL a WebGPU programmer can read, for snell_wgsl.ts
// and run_parity.ts: the functions keep their GLSL names (a suffix of
// parameter types where two GLSL overloads survive), parameters are values,
// what glslang wrote as a branch around the right side of `a || b` or `a && b`
// is an operator again (WGSL's | and &: both sides are evaluated, as they
// have no side effects), and naga's numeric suffixes go where the plain name
// is free (spirv_tidy.ts, wgsl_tidy.ts). With `optimize` (snell_wgsl.ts runs
// spirv-opt's local passes there), the copies glslang makes disappear, and so
// do the branches a constant settles (the strategies SNELL_INTERSECT_STRATEGIES
// leaves out) with the functions only they called.
//
// When naga refuses the SPIR-V, the error says where in the GLSL (with
// glslang -g, which snell_wgsl.ts passes): TranslationError.
import { NagaError, parseWgsl, validate } from "naga-wasm";
import { spirvToWgsl } from "./naga_wgsl.ts";
import {
  combinedSamplers, foldConstantLogic, functionLocation, functionNamed, glslNames, nameAnonymousBlocks, shortCircuits,
  type SourceLocation, sourceOf, SpirvModule, valueParameters, withoutLineInfo,
} from "./spirv_tidy.ts";
import { eagerLogic, restoreNames, runtimeNonFinite } from "./wgsl_tidy.ts";

// spirv-opt's passes for snell_wgsl.ts: local variables to values where they are stored once,
// constants propagated, the branches they settle and the functions no one calls any more removed.
// Not used: --inline-* (the functions are what the WGSL is read by), --simplify-instructions
// (it fuses a * b + c into fma, which changes results), --ssa-rewrite and
// --convert-local-access-chains (every struct member assignment becomes a constructor call).
export const spirvOptPasses = [
  "--eliminate-local-single-block", "--eliminate-local-single-store", "--ccp", "--eliminate-dead-branches",
  "--merge-blocks", "--eliminate-dead-functions", "--eliminate-dead-code-aggressive",
];

export class TranslationError extends Error {
  constructor(
    message: string,
    readonly naga: string,                   // naga's own message
    readonly location?: SourceLocation,      // where in the GLSL, when known
    readonly instruction?: string,           // the SPIR-V instruction naga stopped at
    readonly combinedSamplers: { fn?: string; name: string; location?: SourceLocation }[] = [],
  ) {
    super(message);
  }
}

// naga's error on module `m` (ids as naga saw them), with the place in the GLSL it comes from.
function explain(naga: string, m: SpirvModule): TranslationError {
  const samplers = combinedSamplers(m);
  let location: SourceLocation | undefined, instruction: string | undefined;
  const id = /\bId\((\d+)\)|InvalidId\((\d+)\)|Invalid\w*Id\((\d+)\)|\bid (\d+)\b/i.exec(naga);
  if (id) {
    const s = sourceOf(m, Number(id[1] ?? id[2] ?? id[3] ?? id[4]));
    location = s?.location;
    instruction = s?.text;
  }
  if (!location) {
    // A validation error names the function ("Function [3] 'snellFoo' is invalid").
    for (const q of naga.matchAll(/'(\w+)'/g)) {
      const fn = functionNamed(m, q[1]);
      if (fn !== undefined) {
        location = { ...functionLocation(m, fn)!, fn: q[1] };
        break;
      }
    }
  }
  return new TranslationError(naga.split("\n")[0], naga, location, instruction, samplers);
}

export interface ReadableOptions {
  optimize?: (spirv: Uint8Array) => Uint8Array;  // spirv-opt with spirvOptPasses (needs to run a program)
}

export function readableWgsl(spirv: Uint8Array, options: ReadableOptions = {}): string {
  let m = new SpirvModule(spirv);
  valueParameters(m);
  shortCircuits(m);
  if (options.optimize) {
    m = new SpirvModule(options.optimize(m.binary()));
    shortCircuits(m);  // those spirv-opt's merged blocks made simple
  }
  foldConstantLogic(m);
  glslNames(m);
  nameAnonymousBlocks(m);
  let wgsl: string;
  try {
    wgsl = spirvToWgsl(withoutLineInfo(m).binary());
  } catch (e) {
    const refused = explain((e as Error).message, m);
    try {
      rawWgsl(spirv);
    } catch {
      throw refused;  // naga refuses the shader as glslang wrote it too
    }
    throw new Error(`naga refuses the SPIR-V after snell's passes, not before (a bug of ` +
      `tools/webgpu/spirv_tidy.ts; --raw writes the WGSL without them): ${refused.naga}`);
  }
  const named = runtimeNonFinite(eagerLogic(restoreNames(wgsl)));
  try {
    const parsed = parseWgsl(named);
    validate(parsed).free();
    parsed.free();
  } catch (e) {
    throw new Error(`snell's WGSL names broke naga's WGSL (a bug of tools/webgpu/wgsl_tidy.ts): ` +
      (e instanceof NagaError ? e.formatted : String(e)));
  }
  return named;
}

// naga's WGSL of glslang's SPIR-V as it comes (line information dropped), for comparison.
export function rawWgsl(spirv: Uint8Array): string {
  const m = new SpirvModule(spirv);
  try {
    return spirvToWgsl(withoutLineInfo(m).binary());
  } catch (e) {
    throw explain((e as Error).message, m);
  }
}
