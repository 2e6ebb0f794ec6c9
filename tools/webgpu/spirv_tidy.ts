// SPIR-V passes that make naga's WGSL read like the GLSL it came from, for
// readable_wgsl.ts (snell_wgsl.ts and run_parity.ts). glslang names a function
// by its mangled signature ("snellRefract(vf3;vf3;f1;i1;"), which naga turns
// into identifiers of up to 2,000 characters, passes every argument through a
// pointer to a copy, which naga writes as `ptr<function, T>` parameters and a
// `var param_N` per argument, and writes `a || b` as a branch around b, which
// naga writes as a variable set in an `if`. Here:
//   - valueParameters: a parameter the callee only reads, or whose callers
//     never read it back, is a value; the callee keeps a local copy only
//     where it writes to it (spirv-opt's local passes then remove the
//     callers' copies);
//   - shortCircuits: the branch around a side-effect-free b becomes
//     OpLogicalOr / OpLogicalAnd again;
//   - foldConstantLogic: `true && x`, `false || x` as x;
//   - glslNames: each function named as in GLSL; GLSL overloads that both
//     survive get a suffix naming their parameter types (twice_f32,
//     twice_vec3f); nameAnonymousBlocks: `uniform Frame {...};` is `frame`;
//   - withoutLineInfo: the module without OpLine, OpString and OpSource, which
//     naga refuses where glslang -g puts them; the ids stay as they were, so
//     an id naga names is found in the module with line info (sourceOf,
//     functionLocation);
//   - combinedSamplers: the sampler2D parameters and uniforms, which WGSL
//     cannot have (what to tell the user when naga refuses them).
// Nothing here changes what the shader computes: the WebGPU parity runtime
// (run_parity.ts) runs every case's WGSL through these passes, and its results
// are the same as without them, bit for bit.

const Op = {
  SourceContinued: 2, Source: 3, SourceExtension: 4, Name: 5, MemberName: 6, String: 7, Line: 8,
  EntryPoint: 15, TypeVoid: 19, TypeBool: 20, TypeInt: 21, TypeFloat: 22, TypeVector: 23, TypeMatrix: 24,
  TypeImage: 25, TypeSampler: 26, TypeSampledImage: 27, TypeArray: 28, TypeRuntimeArray: 29, TypeStruct: 30,
  TypePointer: 32, TypeFunction: 33, Constant: 43, Function: 54, FunctionParameter: 55, FunctionEnd: 56,
  FunctionCall: 57, Variable: 59, Load: 61, Store: 62, AccessChain: 65, InBoundsAccessChain: 66, CompositeExtract: 81,
  CopyObject: 83, Label: 248,
  NoLine: 317, ModuleProcessed: 330,
} as const;
const StorageClassUniformConstant = 0, StorageClassFunction = 7;
// What may come first in a function's first block: its variables (and line information).
const preamble = new Set<number>([Op.Variable, Op.Line, Op.NoLine]);

export interface Instruction {
  op: number;
  words: number[];  // every word, the first (count and opcode) included
}

export class SpirvModule {
  header: number[];
  instructions: Instruction[];

  constructor(bytes: Uint8Array) {
    if (bytes.byteLength % 4 !== 0 || bytes.byteLength < 20) throw new Error("not a SPIR-V module (size)");
    const words = new Uint32Array(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength));
    if (words[0] !== 0x07230203) throw new Error("not a SPIR-V module (magic number)");
    this.header = [...words.subarray(0, 5)];
    this.instructions = [];
    for (let i = 5; i < words.length;) {
      const count = words[i] >>> 16, op = words[i] & 0xffff;
      if (count === 0 || i + count > words.length) throw new Error(`malformed SPIR-V at word ${i}`);
      this.instructions.push({ op, words: [...words.subarray(i, i + count)] });
      i += count;
    }
  }

  binary(): Uint8Array {
    const total = 5 + this.instructions.reduce((n, ins) => n + ins.words.length, 0);
    const out = new Uint32Array(total);
    out.set(this.header, 0);
    let at = 5;
    for (const ins of this.instructions) {
      ins.words[0] = (ins.words.length << 16) | ins.op;
      out.set(ins.words, at);
      at += ins.words.length;
    }
    return new Uint8Array(out.buffer);
  }

  newId(): number {
    return this.header[3]++;
  }
}

function instruction(op: number, operands: number[]): Instruction {
  return { op, words: [((operands.length + 1) << 16) | op, ...operands] };
}

export function decodeString(words: number[], from: number): string {
  const bytes: number[] = [];
  for (let i = from; i < words.length; ++i)
    for (let b = 0; b < 4; ++b) {
      const c = (words[i] >>> (8 * b)) & 0xff;
      if (c === 0) return new TextDecoder().decode(new Uint8Array(bytes));
      bytes.push(c);
    }
  return new TextDecoder().decode(new Uint8Array(bytes));
}

function encodeString(s: string): number[] {
  const bytes = new TextEncoder().encode(s);
  const words = new Array(Math.floor(bytes.length / 4) + 1).fill(0);
  bytes.forEach((c, i) => (words[i >> 2] |= c << (8 * (i & 3))));
  return words;
}

// The result id of an instruction, or undefined. Opcodes with no result, and those whose result
// is their first operand (types, labels, strings); every other has a result type, then its result.
const noResult = new Set<number>([0, 2, 3, 4, 5, 6, 8, 10, 14, 15, 16, 17, 39, 56, 62, 63, 64, 71, 72, 74, 75,
  99, 218, 219, 220, 221, 224, 225, 228, 246, 247, 249, 250, 251, 252, 253, 254, 255, 317, 330, 331, 332, 4416,
  5380, 5632, 5633]);
function resultId(ins: Instruction): number | undefined {
  if (noResult.has(ins.op)) return undefined;
  if (ins.op === Op.String || ins.op === 11 || (ins.op >= 19 && ins.op <= 38) || ins.op === 73 ||
      ins.op === Op.Label || ins.op === 322 || ins.op === 327) return ins.words[1];
  return ins.words[2];
}

interface FunctionRange {
  id: number;
  start: number;  // index of OpFunction
  end: number;    // index of OpFunctionEnd
}

function functionRanges(m: SpirvModule): FunctionRange[] {
  const ranges: FunctionRange[] = [];
  let open: FunctionRange | undefined;
  m.instructions.forEach((ins, i) => {
    if (ins.op === Op.Function) open = { id: ins.words[2], start: i, end: i };
    else if (ins.op === Op.FunctionEnd && open) {
      open.end = i;
      ranges.push(open);
      open = undefined;
    }
  });
  return ranges;
}

function definitions(m: SpirvModule): Map<number, Instruction> {
  const defs = new Map<number, Instruction>();
  for (const ins of m.instructions) {
    const id = resultId(ins);
    if (id !== undefined) defs.set(id, ins);
  }
  return defs;
}

// True when `id` occurs among the operands of `ins` (any word but the first: conservative, a
// literal that happens to equal the id counts as a use).
function mentions(ins: Instruction, id: number): boolean {
  for (let i = 1; i < ins.words.length; ++i) if (ins.words[i] === id) return true;
  return false;
}

function isOpaque(defs: Map<number, Instruction>, type: number): boolean {
  const t = defs.get(type);
  if (!t) return true;
  if (t.op === Op.TypeImage || t.op === Op.TypeSampler || t.op === Op.TypeSampledImage) return true;
  if (t.op === Op.TypeArray || t.op === Op.TypeRuntimeArray) return isOpaque(defs, t.words[2]);
  if (t.op === Op.TypeStruct) return t.words.slice(2).some((member) => isOpaque(defs, member));
  return false;
}

// Parameters passed by value where the caller cannot tell the difference: glslang copies every
// argument into a temporary and passes its address, so a parameter the callee never writes
// through, or one whose temporaries no caller reads after the call, can be the value itself.
// In the callee, a parameter it only reads becomes the value: each load of it (or of a member,
// through an access chain with constant indices) becomes a copy (an extract) of the value; any
// other parameter gets a local variable with the parameter's old id holding the value, so its
// loads, stores and access chains stay as they are. Each call loads the temporary and passes the
// value. Returns the number of parameters changed.
export function valueParameters(m: SpirvModule): number {
  const defs = definitions(m);
  const ranges = functionRanges(m);
  const rangeOf = new Map(ranges.map((r) => [r.id, r]));
  const entryPoints = new Set(m.instructions.filter((i) => i.op === Op.EntryPoint).map((i) => i.words[2]));
  const intConstants = new Map<number, number>();
  for (const ins of m.instructions)
    if (ins.op === Op.Constant && defs.get(ins.words[1])?.op === Op.TypeInt) intConstants.set(ins.words[2], ins.words[3]);

  // Calls of each function: [caller range, instruction index].
  const calls = new Map<number, [FunctionRange, number][]>();
  for (const r of ranges)
    for (let i = r.start; i <= r.end; ++i) {
      const ins = m.instructions[i];
      if (ins.op !== Op.FunctionCall) continue;
      const list = calls.get(ins.words[3]) ?? [];
      list.push([r, i]);
      calls.set(ins.words[3], list);
    }

  // The access chains rooted at pointer `p` in range r (chain id -> its indices from p, null when
  // one is not a constant), or null when p (or a chain) is used by anything but a load or a chain.
  const readPaths = (r: FunctionRange, p: number, path: (number | null)[] = [],
                     out = new Map<number, (number | null)[]>()): Map<number, (number | null)[]> | null => {
    for (let i = r.start + 1; i < r.end; ++i) {
      const ins = m.instructions[i];
      if (!mentions(ins, p) || resultId(ins) === p) continue;
      if (ins.op === Op.Load && ins.words[3] === p && ins.words.indexOf(p, 4) < 0) continue;
      if ((ins.op === Op.AccessChain || ins.op === Op.InBoundsAccessChain) && ins.words[3] === p &&
          ins.words.indexOf(p, 4) < 0) {
        const chain = [...path, ...ins.words.slice(4).map((w) => intConstants.get(w) ?? null)];
        out.set(ins.words[2], chain);
        if (readPaths(r, ins.words[2], chain, out) === null) return null;
        continue;
      }
      return null;
    }
    return out;
  };
  // True when the caller uses temporary `arg` only to store the argument before the call.
  const unobserved = (caller: FunctionRange, callIndex: number, arg: number): boolean => {
    const def = defs.get(arg);
    if (!def || def.op !== Op.Variable || def.words[3] !== StorageClassFunction) return false;
    for (let i = caller.start + 1; i < caller.end; ++i) {
      const ins = m.instructions[i];
      if (i === callIndex || ins === def || !mentions(ins, arg)) continue;
      if (ins.op === Op.Store && ins.words[1] === arg && ins.words.indexOf(arg, 2) < 0) continue;
      return false;
    }
    return m.instructions[callIndex].words.slice(4).filter((w) => w === arg).length === 1;
  };

  // Decide every parameter first, then rewrite (the decisions read the original code).
  interface Change {
    fn: number; index: number; param: number; valueType: number; value: number;
    chains: Map<number, number[]> | null;  // read-only with constant chains: extract; null: a local copy
  }
  const changes: Change[] = [];
  for (const r of ranges) {
    if (entryPoints.has(r.id)) continue;
    const fnCalls = calls.get(r.id) ?? [];
    for (let i = r.start + 1, index = 0; m.instructions[i].op === Op.FunctionParameter; ++i, ++index) {
      const param = m.instructions[i];
      const ptr = defs.get(param.words[1]);
      if (!ptr || ptr.op !== Op.TypePointer || ptr.words[2] !== StorageClassFunction) continue;
      if (isOpaque(defs, ptr.words[3])) continue;
      const p = param.words[2];
      const paths = readPaths(r, p);
      const constant = paths !== null && [...paths.values()].every((c) => c.every((k) => k !== null));
      const ok = paths !== null ||
        fnCalls.every(([caller, at]) => unobserved(caller, at, m.instructions[at].words[4 + index]));
      if (!ok) continue;
      changes.push({ fn: r.id, index, param: p, valueType: ptr.words[3], value: 0,
                     chains: constant ? paths as Map<number, number[]> : null });
    }
  }
  if (!changes.length) return 0;

  // Function types: one per signature (SPIR-V allows no duplicates).
  const fnTypes = new Map<string, number>();
  for (const ins of m.instructions)
    if (ins.op === Op.TypeFunction) fnTypes.set(ins.words.slice(2).join(","), ins.words[1]);
  const newTypes: Instruction[] = [];
  const byFn = new Map<number, Change[]>();
  for (const c of changes) byFn.set(c.fn, [...(byFn.get(c.fn) ?? []), c]);
  const pointerTo = new Map<number, number>();
  for (const ins of m.instructions)
    if (ins.op === Op.TypePointer && ins.words[2] === StorageClassFunction && !pointerTo.has(ins.words[3]))
      pointerTo.set(ins.words[3], ins.words[1]);

  // Insertions [index, order, instructions], applied from the end so indices stay valid; at one
  // index the parameters' stores (order 0) come before any call's loads (order 1).
  const inserts: [number, number, Instruction[]][] = [];
  const removed = new Set<Instruction>();
  for (const [fn, list] of byFn) {
    const r = rangeOf.get(fn)!;
    const fnIns = m.instructions[r.start];
    const sig = defs.get(fnIns.words[4])!.words.slice(2);
    for (const c of list) {
      sig[1 + c.index] = c.valueType;
      c.value = m.newId();
      const param = m.instructions[r.start + 1 + c.index];
      param.words = [param.words[0], c.valueType, c.value];
    }
    const key = sig.join(",");
    let typeId = fnTypes.get(key);
    if (typeId === undefined) {
      typeId = m.newId();
      fnTypes.set(key, typeId);
      newTypes.push(instruction(Op.TypeFunction, [typeId, ...sig]));
    }
    fnIns.words[4] = typeId;
    // Read-only parameters: loads become copies and extracts of the value, the chains go.
    for (const c of list) {
      if (!c.chains) continue;
      for (let i = r.start + 1; i < r.end; ++i) {
        const ins = m.instructions[i];
        if (ins.op === Op.Load && ins.words[3] === c.param) {
          ins.op = Op.CopyObject;
          ins.words = [0, ins.words[1], ins.words[2], c.value];
        } else if (ins.op === Op.Load && c.chains.has(ins.words[3])) {
          ins.words = [0, ins.words[1], ins.words[2], c.value, ...c.chains.get(ins.words[3])!];
          ins.op = Op.CompositeExtract;
        } else if ((ins.op === Op.AccessChain || ins.op === Op.InBoundsAccessChain) && c.chains.has(ins.words[2])) {
          removed.add(ins);
        }
      }
    }
    // The others: a local copy, variables after the entry block's label, stores after its variables.
    const copied = list.filter((c) => !c.chains);
    if (copied.length) {
      let label = r.start + 1;
      while (m.instructions[label].op !== Op.Label) ++label;
      let afterVars = label + 1;
      while (preamble.has(m.instructions[afterVars].op)) ++afterVars;
      inserts.push([afterVars, 0, copied.map((c) => instruction(Op.Store, [c.param, c.value]))]);
      inserts.push([label + 1, 0, copied.map((c) => {
        const ptr = pointerTo.get(c.valueType);
        if (ptr === undefined) throw new Error(`valueParameters: no Function pointer type to ${c.valueType}`);
        return instruction(Op.Variable, [ptr, c.param, StorageClassFunction]);
      })]);
    }
    // Every call: load the temporary just before it.
    for (const [, at] of calls.get(fn) ?? []) {
      const call = m.instructions[at];
      const loads: Instruction[] = [];
      for (const c of list) {
        const loaded = m.newId();
        loads.push(instruction(Op.Load, [c.valueType, loaded, call.words[4 + c.index]]));
        call.words[4 + c.index] = loaded;
      }
      inserts.push([at, 1, loads]);
    }
  }
  inserts.sort((a, b) => b[0] - a[0] || b[1] - a[1]);
  for (const [at, , list] of inserts) m.instructions.splice(at, 0, ...list);
  m.instructions = m.instructions.filter((i) => !removed.has(i));
  // The new function types go before the first function (every type they name is declared by then).
  const firstFn = m.instructions.findIndex((i) => i.op === Op.Function);
  m.instructions.splice(firstFn, 0, ...newTypes);
  // The parameters' names go to the values (naga names the arguments after them); a local copy
  // keeps its name too.
  for (const c of changes) {
    const at = m.instructions.findIndex((i) => i.op === Op.Name && i.words[1] === c.param);
    if (at < 0) continue;
    if (c.chains) m.instructions[at].words[1] = c.value;  // the old id is gone
    else m.instructions.splice(at, 0, { op: Op.Name, words: [0, c.value, ...m.instructions[at].words.slice(2)] });
  }
  return changes.length;
}

// GLSL's names for glslang's mangled function names (glslang writes "name(signature"); a suffix
// that would make a name longer than `nameLimit` gives way to the parameter count. Returns the renames.
export function glslNames(m: SpirvModule, nameLimit = 80): Map<string, string> {
  const defs = definitions(m);
  const fnIds = new Set(m.instructions.filter((i) => i.op === Op.Function).map((i) => i.words[2]));
  const nameOf = new Map<number, Instruction>();
  for (const ins of m.instructions) if (ins.op === Op.Name) nameOf.set(ins.words[1], ins);
  const typeName = (id: number): string => {
    const t = defs.get(id);
    if (!t) return "t";
    switch (t.op) {
      case Op.TypeVoid: return "void";
      case Op.TypeBool: return "bool";
      case Op.TypeInt: return t.words[3] ? "i32" : "u32";
      case Op.TypeFloat: return t.words[2] === 16 ? "f16" : "f32";
      case Op.TypeVector: {
        const c = typeName(t.words[2]);
        return `vec${t.words[3]}${c === "bool" ? "b" : c[0]}`;
      }
      case Op.TypeMatrix: {
        const col = defs.get(t.words[2])!;
        return `mat${t.words[3]}x${col.words[3]}f`;
      }
      case Op.TypeImage: return "texture";
      case Op.TypeSampler: return "sampler";
      case Op.TypeSampledImage: return "sampler2D";
      case Op.TypeArray: case Op.TypeRuntimeArray: return `array_${typeName(t.words[2])}`;
      case Op.TypePointer: return typeName(t.words[3]);
      case Op.TypeStruct: {
        const n = nameOf.get(id);
        return n ? decodeString(n.words, 2) : "struct";
      }
    }
    return "t";
  };
  // Group the functions by GLSL name.
  const groups = new Map<string, number[]>();
  for (const ins of m.instructions) {
    if (ins.op !== Op.Name || !fnIds.has(ins.words[1])) continue;
    const full = decodeString(ins.words, 2);
    const paren = full.indexOf("(");
    if (paren <= 0) continue;
    const base = full.slice(0, paren);
    groups.set(base, [...(groups.get(base) ?? []), ins.words[1]]);
  }
  const renamed = new Map<string, string>();
  const taken = new Set<string>(groups.keys());
  for (const [base, ids] of groups) {
    let names: string[];
    if (ids.length === 1) names = [base];
    else {
      const params = ids.map((id) => {
        const fn = defs.get(id)!;
        const type = defs.get(fn.words[4])!;
        return type.words.slice(3).map(typeName);
      });
      names = params.map((p) => `${base}_${p.length ? p.join("_") : "void"}`);
      if (new Set(names).size !== names.length || names.some((n) => n.length > nameLimit || taken.has(n)))
        names = params.map((p, k) => `${base}_${p.length}args` + (params.filter((q) => q.length === p.length).length > 1 ? `_${k}` : ""));
    }
    ids.forEach((id, k) => {
      const ins = nameOf.get(id)!;
      renamed.set(decodeString(ins.words, 2), names[k]);
      ins.words = [ins.words[0], id, ...encodeString(names[k])];
      taken.add(names[k]);
    });
  }
  return renamed;
}

// The module without line information (OpLine, OpNoLine, OpString, OpSource...): ids unchanged.
export function withoutLineInfo(m: SpirvModule): SpirvModule {
  const copy = Object.create(SpirvModule.prototype) as SpirvModule;
  copy.header = [...m.header];
  const lineInfo = new Set<number>([Op.Line, Op.NoLine, Op.String, Op.Source, Op.SourceContinued,
    Op.SourceExtension, Op.ModuleProcessed]);
  copy.instructions = m.instructions.filter((i) => !lineInfo.has(i.op));
  return copy;
}

export interface SourceLocation {
  file: string;
  line: number;
  fn?: string;  // the GLSL name of the function it is in
}

// Where the instruction defining `id` (or, when nothing defines it, the first one using it)
// came from: the OpLine before it (glslang -g).
export function sourceOf(m: SpirvModule, id: number): { location?: SourceLocation; text: string } | undefined {
  const strings = new Map<number, string>();
  const names = new Map<number, string>();
  for (const ins of m.instructions) {
    if (ins.op === Op.String) strings.set(ins.words[1], decodeString(ins.words, 2));
    if (ins.op === Op.Name) names.set(ins.words[1], decodeString(ins.words, 2));
  }
  let at = m.instructions.findIndex((i) => resultId(i) === id);
  if (at < 0) at = m.instructions.findIndex((i) => i.op !== Op.Name && mentions(i, id));
  if (at < 0) return undefined;
  let location: SourceLocation | undefined;
  let fn: string | undefined;
  for (let i = at; i >= 0; --i) {
    const ins = m.instructions[i];
    if (!location && ins.op === Op.Line) location = { file: strings.get(ins.words[1]) ?? "?", line: ins.words[2] };
    if (ins.op === Op.Function) {
      const n = names.get(ins.words[2]) ?? "";
      fn = n.includes("(") ? n.slice(0, n.indexOf("(")) : n;
      location ??= functionLocation(m, ins.words[2]);  // no line inside the function before it: its declaration
      break;
    }
    if (ins.op === Op.FunctionEnd) break;
  }
  if (location) location.fn = fn;
  const ins = m.instructions[at];
  const operand = (w: number) => names.has(w) ? `%${names.get(w)!.split("(")[0]}` : `%${w}`;
  const result = resultId(ins);
  // `%r = OpX operands` (the result type left out); operands that are literals show as ids too.
  const operands = ins.words.slice(result === undefined ? 1 : result === ins.words[1] ? 2 : 3).map(operand);
  const text = (result === undefined ? "" : `${operand(result)} = `) + `${opName(ins.op)} ${operands.join(" ")}`;
  return { location, text };
}

function opName(op: number): string {
  for (const [k, v] of Object.entries(Op)) if (v === op) return `Op${k}`;
  return `Op#${op}`;
}

// What naga cannot translate for WGSL, which has no combined image samplers: functions that take
// one (a GLSL sampler2D parameter; `fn` is the function's GLSL name) and uniforms declared as one
// (`fn` undefined); each with its name and where it is (with glslang -g: the function's
// declaration, the uniform's first read).
export function combinedSamplers(m: SpirvModule): { fn?: string; name: string; location?: SourceLocation }[] {
  const defs = definitions(m);
  const names = new Map<number, string>();
  for (const ins of m.instructions) if (ins.op === Op.Name) names.set(ins.words[1], decodeString(ins.words, 2));
  const sampledImage = (type: number) => {
    let t = defs.get(type);
    if (t?.op === Op.TypePointer && t.words[2] === StorageClassUniformConstant) t = defs.get(t.words[3]);
    while (t && (t.op === Op.TypeArray || t.op === Op.TypeRuntimeArray)) t = defs.get(t.words[2]);
    return t?.op === Op.TypeSampledImage;
  };
  const out: { fn?: string; name: string; location?: SourceLocation }[] = [];
  for (const ins of m.instructions) {
    if (ins.op !== Op.Variable || ins.words[3] !== StorageClassUniformConstant || !sampledImage(ins.words[1])) continue;
    const read = m.instructions.find((i) => i.op === Op.Load && i.words[3] === ins.words[2]);
    out.push({ name: names.get(ins.words[2]) ?? `%${ins.words[2]}`, location: read ? sourceOf(m, read.words[2])?.location : undefined });
  }
  for (const r of functionRanges(m)) {
    for (let i = r.start + 1; m.instructions[i].op === Op.FunctionParameter; ++i) {
      const param = m.instructions[i];
      if (!sampledImage(param.words[1])) continue;
      const fn = (names.get(r.id) ?? "?").split("(")[0];
      out.push({ fn, name: names.get(param.words[2]) ?? `%${param.words[2]}`, location: functionLocation(m, r.id) });
    }
  }
  return out;
}

// Where a function is declared: the OpLine glslang -g puts before its OpFunction (else its first).
export function functionLocation(m: SpirvModule, fn: number): SourceLocation | undefined {
  const strings = new Map<number, string>();
  for (const ins of m.instructions) if (ins.op === Op.String) strings.set(ins.words[1], decodeString(ins.words, 2));
  const at = m.instructions.findIndex((i) => i.op === Op.Function && i.words[2] === fn);
  if (at < 0) return undefined;
  let line = at > 0 && m.instructions[at - 1].op === Op.Line ? m.instructions[at - 1] : undefined;
  for (let k = at; !line && k < m.instructions.length && m.instructions[k].op !== Op.FunctionEnd; ++k)
    if (m.instructions[k].op === Op.Line) line = m.instructions[k];
  return line ? { file: strings.get(line.words[1]) ?? "?", line: line.words[2] } : undefined;
}

// The function named `name` (its GLSL name, or glslang's mangled one), or undefined.
export function functionNamed(m: SpirvModule, name: string): number | undefined {
  const fns = new Set(m.instructions.filter((i) => i.op === Op.Function).map((i) => i.words[2]));
  for (const ins of m.instructions) {
    if (ins.op !== Op.Name || !fns.has(ins.words[1])) continue;
    const n = decodeString(ins.words, 2);
    if (n === name || n.split("(")[0] === name) return ins.words[1];
  }
  return undefined;
}

// Instructions with no side effect, cheap enough to run whether or not a branch is taken.
const pureOps = new Set<number>([
  12 /* ExtInst (GLSL.std.450) */, 77, 79, 80, 81, 82, 83 /* vector/composite access, copy */,
  109, 110, 111, 112, 113, 114, 115, 116, 124 /* conversions, bitcast */,
  126, 127, 128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147,
  148 /* arithmetic */, 154, 155, 156, 157 /* any, all, isnan, isinf */,
  164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 179, 180, 181, 182, 183, 184, 185,
  186, 187, 188, 189, 190, 191 /* logic, select, comparisons */,
  194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204 /* bit operations */,
  Op.Line, Op.NoLine,
]);
const OpPhi = 245, OpSelectionMerge = 247, OpBranch = 249, OpBranchConditional = 250, OpSwitch = 251,
  OpLogicalOr = 166, OpLogicalAnd = 167, OpLogicalNot = 168, OpSelect = 169;
const terminators = new Set<number>([OpBranch, OpBranchConditional, OpSwitch, 252, 253, 254, 255, 4416]);

// glslang writes `a || b` and `a && b` as a branch around b and an OpPhi, which naga turns into
// a variable assigned in an `if`, five lines each: where b is a few side-effect-free
// instructions, they move before the branch and the OpPhi becomes OpLogicalOr / OpLogicalAnd
// (WGSL's || and && then skip b as before; its value is the same). Returns the number of
// branches removed.
export function shortCircuits(m: SpirvModule): number {
  const defs = definitions(m);
  const fnVarPointers = new Set<number>();
  for (const ins of m.instructions)
    if (ins.op === Op.Variable && ins.words[3] === StorageClassFunction) fnVarPointers.add(ins.words[2]);
  for (const ins of m.instructions)  // access chains into function variables, in order of definition
    if ((ins.op === Op.AccessChain || ins.op === Op.InBoundsAccessChain) && fnVarPointers.has(ins.words[3]))
      fnVarPointers.add(ins.words[2]);
  const isPure = (ins: Instruction) => pureOps.has(ins.op) ||
    (ins.op === Op.Load && fnVarPointers.has(ins.words[3]) && ins.words.length === 4) ||
    ((ins.op === Op.AccessChain || ins.op === Op.InBoundsAccessChain) && fnVarPointers.has(ins.words[3]));
  let changed = 0;
  // From the last function to the first, so that rewriting one leaves the earlier ones' indices valid.
  for (const r of functionRanges(m).reverse()) {
    // Blocks by label: the indices of the label and of the terminator; and each block's predecessors.
    const blocks = new Map<number, { start: number; end: number }>();
    const preds = new Map<number, number[]>();
    for (let i = r.start; i <= r.end; ++i) {
      if (m.instructions[i].op !== Op.Label) continue;
      let e = i + 1;
      while (!terminators.has(m.instructions[e].op)) ++e;
      const label = m.instructions[i].words[1];
      blocks.set(label, { start: i, end: e });
      const t = m.instructions[e];
      const targets = t.op === OpBranch ? [t.words[1]] : t.op === OpBranchConditional ? [t.words[2], t.words[3]] :
        t.op === OpSwitch ? [t.words[2], ...t.words.slice(4).filter((_, k) => k % 2 === 0)] : [];
      for (const target of targets) preds.set(target, [...(preds.get(target) ?? []), label]);
    }
    const removed = new Set<Instruction>();
    const inserted = new Map<Instruction, Instruction[]>();  // before this (rewritten) terminator
    for (const [h, hb] of blocks) {
      const br = m.instructions[hb.end], sm = m.instructions[hb.end - 1];
      if (br.op !== OpBranchConditional || sm.op !== OpSelectionMerge || removed.has(br)) continue;
      const merge = sm.words[1], c = br.words[1];
      const rhs = br.words[2] === merge ? br.words[3] : br.words[3] === merge ? br.words[2] : undefined;
      if (rhs === undefined || rhs === merge) continue;
      const rb = blocks.get(rhs), mb = blocks.get(merge);
      if (!rb || !mb || (preds.get(rhs) ?? []).length !== 1) continue;
      const mp = preds.get(merge) ?? [];
      if (mp.length !== 2 || !mp.includes(h) || !mp.includes(rhs)) continue;
      const rEnd = m.instructions[rb.end];
      if (rEnd.op !== OpBranch || rEnd.words[1] !== merge) continue;
      const body = m.instructions.slice(rb.start + 1, rb.end);
      if (!body.every(isPure)) continue;
      const phis: Instruction[] = [];
      for (let i = mb.start + 1; i < mb.end; ++i) {
        const ins = m.instructions[i];
        if (ins.op === OpPhi) phis.push(ins);
        else if (ins.op !== Op.Line && ins.op !== Op.NoLine) break;
      }
      if (!phis.length || phis.some((p) => p.words.length !== 7 || defs.get(p.words[1])?.op !== Op.TypeBool)) continue;
      const takenWhenTrue = br.words[2] === rhs;
      const cDef = defs.get(c);
      const replacement = phis.map((p) => {
        const fromH = p.words[4] === h ? p.words[3] : p.words[5];
        const fromR = p.words[4] === rhs ? p.words[3] : p.words[5];
        const [type, result] = [p.words[1], p.words[2]];
        if (takenWhenTrue && fromH === c) return instruction(OpLogicalAnd, [type, result, c, fromR]);
        if (!takenWhenTrue && fromH === c) return instruction(OpLogicalOr, [type, result, c, fromR]);
        if (takenWhenTrue && cDef?.op === OpLogicalNot && cDef.words[3] === fromH)
          return instruction(OpLogicalOr, [type, result, fromH, fromR]);
        return takenWhenTrue ? instruction(OpSelect, [type, result, c, fromR, fromH])
          : instruction(OpSelect, [type, result, c, fromH, fromR]);
      });
      // The header runs b and branches to the merge block; the rhs block and the OpPhis go.
      inserted.set(br, [...body, ...replacement]);
      br.op = OpBranch;
      br.words = [0, merge];
      removed.add(sm);
      for (let i = rb.start; i <= rb.end; ++i) removed.add(m.instructions[i]);
      for (const p of phis) removed.add(p);
      preds.set(merge, [h]);  // a branch out of the merge block may head the next such diamond
      ++changed;
    }
    if (!removed.size) continue;
    const out: Instruction[] = [];
    for (let i = r.start; i <= r.end; ++i) {
      const ins = m.instructions[i];
      if (inserted.has(ins)) out.push(...inserted.get(ins)!);
      if (!removed.has(ins)) out.push(ins);
    }
    m.instructions.splice(r.start, r.end - r.start + 1, ...out);
  }
  return changed;
}

// `true && x` and `false || x` (what is left of a test the constant strategy mask settled) as x.
export function foldConstantLogic(m: SpirvModule): number {
  const constants = new Map<number, boolean>();
  for (const ins of m.instructions) {
    if (ins.op === 41) constants.set(ins.words[2], true);   // OpConstantTrue
    if (ins.op === 42) constants.set(ins.words[2], false);  // OpConstantFalse
  }
  let folded = 0;
  for (const ins of m.instructions) {
    if (ins.op !== OpLogicalAnd && ins.op !== OpLogicalOr) continue;
    const neutral = ins.op === OpLogicalAnd;
    const [a, b] = [ins.words[3], ins.words[4]];
    const other = constants.get(a) === neutral ? b : constants.get(b) === neutral ? a : undefined;
    if (other === undefined) continue;
    ins.op = Op.CopyObject;
    ins.words = [0, ins.words[1], ins.words[2], other];
    ++folded;
  }
  return folded;
}

// A GLSL block without an instance name (`uniform Frame { ... };`) is a nameless variable, which
// naga calls `unnamed`: name it after its block, first letter lower case (`frame`).
export function nameAnonymousBlocks(m: SpirvModule): number {
  const defs = definitions(m);
  const names = new Map<number, Instruction>();
  for (const ins of m.instructions) if (ins.op === Op.Name) names.set(ins.words[1], ins);
  const taken = new Set([...names.values()].map((n) => decodeString(n.words, 2)));
  const added: Instruction[] = [];
  for (const ins of m.instructions) {
    if (ins.op !== Op.Variable || ![2, 9, 12].includes(ins.words[3])) continue;  // Uniform, PushConstant, StorageBuffer
    const existing = names.get(ins.words[2]);
    if (existing && decodeString(existing.words, 2) !== "") continue;
    const ptr = defs.get(ins.words[1]);
    const block = ptr && names.get(ptr.words[3]);
    if (!block) continue;
    const blockName = decodeString(block.words, 2);
    const name = blockName.charAt(0).toLowerCase() + blockName.slice(1);
    if (!name || name === blockName || taken.has(name)) continue;
    taken.add(name);
    if (existing) existing.words = [0, ins.words[2], ...encodeString(name)];
    else added.push(instruction(Op.Name, [ins.words[2], ...encodeString(name)]));
  }
  const at = m.instructions.findIndex((i) => i.op === Op.Name);
  if (added.length) m.instructions.splice(at < 0 ? 0 : at, 0, ...added);
  return added.length;
}
