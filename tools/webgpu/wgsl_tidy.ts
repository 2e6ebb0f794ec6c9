// Passes over naga's WGSL, for readable_wgsl.ts.
//
// restoreNames: the GLSL names back. naga's namer makes every name unique in
// the whole module, so the third `origin` parameter becomes `origin_2` and a
// texture declared `backDepth` becomes `backDepth_6` when functions before it
// have parameters of that name (and a name ending in a digit gets a `_`).
// WGSL needs a name unique only within its scope, so this drops naga's suffix
// wherever the plain name is free:
//   - a module-scope name (global, function, struct, constant) when no other
//     module-scope declaration has it and no function refers to something
//     else by it (a builtin, or a name of its own);
//   - a parameter or local when nothing else in its function has the name
//     (it may then shadow a module-scope name the function does not use,
//     which WGSL allows).
// Struct members keep naga's names (they are GLSL's already).
//
// eagerLogic: `a || b` and `a && b` as `a | b` and `a & b`. naga writes
// SPIR-V's OpLogicalOr / OpLogicalAnd, whose operands are values already
// computed, as WGSL's short-circuit operators; Tint (Dawn, Chrome) then
// branches around b, and with hundreds of such branches Chrome's GPU process
// on SwiftShader (its WebGPU without a GPU) crashed after 4 to 7 minutes
// compiling the two-interface technique (ParityWebGpuChromium.TwoInterfaceTrace;
// 23 s with | and &). WGSL's | and & on bool evaluate both sides, as SPIR-V
// did; naga compiles either to OpLogicalOr, so wgpu's results do not change.
//
// runtimeNonFinite: a NaN or infinity spirv-opt folded into a constant, which
// naga writes as `bitcast<f32>(2143289344u)`: Tint rejects a constant that
// is not finite ("value nan cannot be represented as 'f32'"), so its bits go
// to a private variable and the bitcast happens at run time, as it did before
// the folding (the parity cases hide their NaNs from folding that way).
//
// All three are for naga's own output only: one declaration or statement a line,
// every binary operation in parentheses with spaces around its operator, no
// comments or strings.

const RESERVED = new Set([
  // keywords and reserved words (naga's list, naga/src/keywords/wgsl.rs) and WGSL's predeclared types
  "array", "atomic", "bool", "f32", "f16", "i32", "i64", "mat2x2", "mat2x3", "mat2x4", "mat3x2", "mat3x3",
  "mat3x4", "mat4x2", "mat4x3", "mat4x4", "ptr", "sampler", "sampler_comparison", "texture_1d", "texture_2d",
  "texture_2d_array", "texture_3d", "texture_cube", "texture_cube_array", "texture_multisampled_2d",
  "texture_storage_1d", "texture_storage_2d", "texture_storage_2d_array", "texture_storage_3d",
  "texture_depth_2d", "texture_depth_2d_array", "texture_depth_cube", "texture_depth_cube_array",
  "texture_depth_multisampled_2d", "u32", "u64", "vec2", "vec3", "vec4", "alias", "bitcast", "break", "case",
  "const", "const_assert", "continue", "continuing", "default", "diagnostic", "discard", "else", "enable",
  "false", "fn", "for", "if", "let", "loop", "override", "requires", "return", "static_assert", "struct",
  "switch", "true", "type", "var", "while", "CompileShader", "ComputeShader", "DomainShader", "GeometryShader",
  "Hullshader", "NULL", "Self", "abstract", "active", "alignas", "alignof", "as", "asm", "asm_fragment", "async",
  "attribute", "auto", "await", "become", "binding_array", "cast", "catch", "class", "co_await", "co_return",
  "co_yield", "coherent", "column_major", "common", "compile", "compile_fragment", "concept", "const_cast",
  "consteval", "constexpr", "constinit", "crate", "debugger", "decltype", "delete", "demote",
  "demote_to_helper", "do", "dynamic_cast", "enum", "explicit", "export", "extends", "extern", "external",
  "fallthrough", "filter", "final", "finally", "friend", "from", "fxgroup", "get", "goto", "groupshared",
  "handle", "highp", "impl", "implements", "import", "inline", "inout", "instanceof", "interface", "layout",
  "lowp", "macro", "macro_rules", "match", "mediump", "meta", "mod", "module", "move", "mut", "mutable",
  "namespace", "new", "nil", "noexcept", "noinline", "nointerpolation", "noperspective", "null", "nullptr",
  "of", "operator", "package", "packoffset", "partition", "pass", "patch", "pixelfragment", "precise",
  "precision", "premerge", "priv", "protected", "pub", "public", "readonly", "ref", "regardless", "register",
  "reinterpret_cast", "resource", "restrict", "self", "set", "shared", "signed", "sizeof", "smooth", "snorm",
  "static", "static_cast", "std", "subroutine", "super", "target", "template", "this", "thread_local", "throw",
  "trait", "try", "typedef", "typeid", "typename", "typeof", "union", "unless", "unorm", "unsafe", "unsized",
  "use", "using", "varying", "virtual", "volatile", "wgsl", "where", "with", "writeonly", "yield",
  "vec2f", "vec3f", "vec4f", "vec2i", "vec3i", "vec4i", "vec2u", "vec3u", "vec4u", "vec2h", "vec3h", "vec4h",
  "mat2x2f", "mat2x3f", "mat2x4f", "mat3x2f", "mat3x3f", "mat3x4f", "mat4x2f", "mat4x3f", "mat4x4f",
  "function", "private", "workgroup", "uniform", "storage", "read", "write", "read_write",
]);

interface Token {
  start: number;
  end: number;
  text: string;
  ident: boolean;
  member: boolean;     // an identifier after `.` or `@`: a member or an attribute, never renamed
  fn: number;          // index of the function it is in (signature included), -1 at module scope
  inStruct: boolean;   // inside a struct's braces (member declarations)
  decl: boolean;       // the identifier a declaration introduces
}

function followedByColon(src: string, at: number): boolean {
  const colon = /\s*:/y;
  colon.lastIndex = at;
  return colon.test(src);
}

// naga's WGSL as tokens. Numbers (1e-5f, 0x7fu, 2i) are one token; naga writes no comments or
// strings, but a `//` line (the tool's header) is skipped.
function tokenize(src: string): Token[] {
  const tokens: Token[] = [];
  const re = /\/\/[^\n]*|0[xX][0-9a-fA-F.]+(?:[pP][+-]?\d+)?[fhiu]?|\d+\.?\d*(?:[eE][+-]?\d+)?[fhiu]?|\.\d+(?:[eE][+-]?\d+)?[fh]?|[A-Za-z_][A-Za-z0-9_]*|->|\S/g;
  let depth = 0, paren = 0, fnCount = 0, fn = -1, inStruct = false;
  let state: "" | "fnName" | "signature" | "structName" | "structBody" | "declName" = "";
  let declTemplate = 0;  // inside `var<...>` before the name
  for (let m; (m = re.exec(src));) {
    const text = m[0];
    if (text.startsWith("//")) continue;
    const ident = /^[A-Za-z_]/.test(text);
    const prev = tokens[tokens.length - 1];
    const t: Token = { start: m.index, end: m.index + text.length, text, ident, member: false, fn, inStruct, decl: false };
    if (ident) t.member = prev !== undefined && (prev.text === "." || prev.text === "@");
    if (text === "{") {
      if (depth === 0 && state === "structBody") inStruct = true;
      if (state === "signature" || state === "structBody") state = "";
      ++depth;
    } else if (text === "}") {
      if (--depth === 0) { fn = -1; inStruct = false; }
      t.fn = fn;
      t.inStruct = inStruct;
    } else if (text === "(") ++paren;
    else if (text === ")") --paren;
    else if (text === "<" && state === "declName") ++declTemplate;
    else if (text === ">" && state === "declName" && declTemplate > 0) --declTemplate;
    else if (ident && !t.member) {
      if (state === "fnName") {
        fn = fnCount++;
        t.fn = fn;
        t.decl = true;
        state = "signature";
      } else if (state === "structName") {
        t.decl = true;
        state = "structBody";
      } else if (state === "declName" && declTemplate === 0) {
        t.decl = true;
        state = "";
      } else if (state === "signature" && paren === 1 && followedByColon(src, t.end) &&
                 prev !== undefined && ["(", ",", ")"].includes(prev.text)) {
        t.decl = true;  // a parameter
      } else if (!inStruct && state === "") {
        if (text === "fn" && depth === 0) state = "fnName";
        else if (text === "struct" && depth === 0) state = "structName";
        else if (["var", "let", "const", "override", "alias"].includes(text)) { state = "declName"; declTemplate = 0; }
      }
    }
    tokens.push(t);
  }
  return tokens;
}

// The name naga started from: `x_3` -> `x`, `x1_` -> `x1`, `x1_2` -> `x1`; undefined when naga added nothing.
function baseName(name: string): string | undefined {
  const m = /^(.*[A-Za-z0-9])_(\d*)$/.exec(name);
  if (!m || /^_e\d+$/.test(name)) return undefined;
  return m[1];
}

export function restoreNames(src: string): string {
  const tokens = tokenize(src).filter((t) => t.ident && !t.member && !t.inStruct);
  // naga's names are unique in the whole module (struct members aside), so a name declared in a
  // function is that declaration wherever the function mentions it.
  const moduleDecls = new Set<string>();
  const localDecls = new Map<number, Set<string>>();
  let fnKeyword = false;
  for (const t of tokens) {
    if (t.decl && (t.fn < 0 || fnKeyword)) moduleDecls.add(t.text);
    else if (t.decl) localDecls.set(t.fn, (localDecls.get(t.fn) ?? new Set()).add(t.text));
    fnKeyword = t.text === "fn";
  }
  const isLocal = (t: Token) => t.fn >= 0 && localDecls.get(t.fn)?.has(t.text) === true;
  // Each function's free names (what it refers to at module scope or among the builtins).
  const free = new Map<number, Set<string>>();
  const anyFree = new Set<string>();
  for (const t of tokens) {
    if (isLocal(t) || t.decl) continue;
    anyFree.add(t.text);
    if (t.fn >= 0) free.set(t.fn, (free.get(t.fn) ?? new Set()).add(t.text));
  }

  // Module scope: x_N -> x when no module-scope declaration is x, nothing refers to a free x (a
  // builtin), and no function that refers to x_N has a local x.
  const rename = new Map<string, string>();
  const taken = new Set<string>();
  for (const name of moduleDecls) {
    const base = baseName(name);
    if (!base || RESERVED.has(base) || moduleDecls.has(base) || anyFree.has(base) || taken.has(base)) continue;
    let clash = false;
    for (const [fn, names] of free) if (names.has(name) && localDecls.get(fn)?.has(base)) clash = true;
    if (clash) continue;
    rename.set(name, base);
    taken.add(base);
  }
  // Function scope, with the module renames applied: x_N -> x when nothing else in the function is x.
  const localRename = new Map<number, Map<string, string>>();
  for (const [fn, decls] of localDecls) {
    const used = new Set<string>(decls);
    for (const name of free.get(fn) ?? []) used.add(rename.get(name) ?? name);
    const map = new Map<string, string>();
    for (const name of decls) {
      const base = baseName(name);
      if (!base || RESERVED.has(base) || used.has(base)) continue;
      map.set(name, base);
      used.add(base);
    }
    localRename.set(fn, map);
  }

  let out = "";
  let at = 0;
  for (const t of tokens) {
    const to = isLocal(t) ? localRename.get(t.fn)?.get(t.text) : rename.get(t.text);
    if (to === undefined) continue;
    out += src.slice(at, t.start) + to;
    at = t.end;
  }
  return out + src.slice(at);
}

export function eagerLogic(src: string): string {
  return src.replaceAll(" || ", " | ").replaceAll(" && ", " & ");
}

export function runtimeNonFinite(src: string): string {
  const bits = new Set<number>();
  const out = src.replace(/bitcast<f32>\((\d+)u\)/g, (whole, n: string) => {
    const b = Number(n);
    if ((b & 0x7f800000) !== 0x7f800000) return whole;
    bits.add(b);
    return `bitcast<f32>(snellNonFinite${b.toString(16)})`;
  });
  if (!bits.size) return src;
  const decls = [...bits].map((b) => `var<private> snellNonFinite${b.toString(16)}: u32 = ${b}u;`).join("\n");
  return `// NaN and infinity by their bits, read at run time: Tint rejects a constant that is not finite.\n${decls}\n\n${out}`;
}
