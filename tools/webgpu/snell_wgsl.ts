// snell-wgsl: a WebGPU shader that includes snell, as WGSL. Your Vulkan GLSL
// (a compute or fragment shader with #include "snell/..." after
// #include "snell_webgpu_prelude.glsl") -> glslangValidator -V -g ->
// spirv-val -> spirv-opt's local passes -> naga -> WGSL named as the GLSL
// (readable_wgsl.ts). The WebGPU parity runtime writes its WGSL the same way,
// spirv-opt aside (run_parity.ts; its --spirv-opt adds it). `--help` prints
// the options.
import { rawWgsl, readableWgsl, spirvOptPasses, TranslationError } from "./readable_wgsl.ts";
import { runOnce } from "./run_check.ts";

const usage = `usage: snell-wgsl [OPTION]... SHADER.(comp|frag|vert) -o OUT.wgsl

Translates a Vulkan GLSL shader that includes snell to WGSL: glslangValidator
-V -g (snell's glsl/ and this tool's directory, with snell_webgpu_prelude.glsl,
on the include path), spirv-val, spirv-opt (local passes: no inlining), naga
(npm naga-wasm). The WGSL keeps the GLSL's names (a function overloaded in
GLSL gets a suffix of its parameter types), takes parameters by value, and
holds only the functions the entry point calls: a strategy that
SNELL_INTERSECT_STRATEGIES leaves out is not in it.

  -o FILE          write the WGSL to FILE (required)
  -I DIR           add DIR to the include path (repeatable; also -IDIR)
  -D NAME[=VALUE]  define a macro for the shader (repeatable; also -DNAME=VALUE)
  --check          also compile the WGSL on this machine's WebGPU device
                   (Deno's wgpu, whose compiler is naga) and with Tint
                   (Dawn's and Chrome's compiler, tools/webgpu/tint_check.mjs);
                   fail on any error either reports
  --run            also run the entry point once on that device (implies
                   --check): every resource it declares bound to a stand-in
                   (zero-filled buffers, 4x4 textures, a linear sampler), a
                   fragment shader drawing one triangle, a compute shader one
                   workgroup; fail on any WebGPU error (tools/webgpu/run_check.ts)
  --stats          print the WGSL's size, lines, functions and longest name
  --raw            write naga's WGSL of glslang's SPIR-V as it comes (mangled
                   names, pointer parameters, every strategy), to compare
  -h, --help       print this text and exit

Textures: WGSL has no combined image samplers and naga refuses a sampler2D
passed to a function. Declare each texture as a texture2D, one sampler for
the reads that filter, and let the prelude define snell's texture hooks on
them: #define SNELL_WEBGPU_SAMPLER <your sampler> before including
snell_webgpu_prelude.glsl (examples/webgpu/refract.frag; docs/recipes.md,
"WebGPU (WGSL)").

When naga refuses the shader, the message names the GLSL file and line it
stopped at. Exit status: 0 on success, 1 when a step fails, 2 on a usage
error.`;

const here = new URL(".", import.meta.url).pathname;
const snellGlsl = `${here}../../glsl`;
const args = [...Deno.args];
const includes: string[] = [], defines: string[] = [];
let input = "", output = "", check = false, runIt = false, stats = false, raw = false;
function usageError(message: string): never {
  console.error(`snell-wgsl: ${message}\n(snell-wgsl --help lists the options)`);
  Deno.exit(2);
}
for (let i = 0; i < args.length; ++i) {
  const a = args[i];
  const value = () => (i + 1 < args.length ? args[++i] : usageError(`${a} needs a value`));
  if (a === "-h" || a === "--help") {
    console.log(usage);
    Deno.exit(0);
  } else if (a === "-o") output = value();
  else if (a === "--check") check = true;
  else if (a === "--run") check = runIt = true;
  else if (a === "--stats") stats = true;
  else if (a === "--raw") raw = true;
  else if (a === "-I") includes.push(value());
  else if (a.startsWith("-I")) includes.push(a.slice(2));
  else if (a === "-D") defines.push(value());
  else if (a.startsWith("-D")) defines.push(a.slice(2));
  else if (!a.startsWith("-") && !input) input = a;
  else usageError(a.startsWith("-") ? `unknown option '${a}'` : `one shader at a time ('${input}', then '${a}')`);
}
if (!input) usageError("no shader given");
if (!output) usageError("no output given (-o OUT.wgsl)");

function run(program: string, argv: string[], pkg: string): string {
  let r;
  try {
    r = new Deno.Command(program, { args: argv, stdout: "piped", stderr: "piped" }).outputSync();
  } catch {
    console.error(`snell-wgsl: cannot run ${program}: install the Debian package ${pkg}`);
    Deno.exit(1);
  }
  const text = new TextDecoder().decode(r.stdout) + new TextDecoder().decode(r.stderr);
  if (!r.success) {
    console.error(`snell-wgsl: ${program} failed on ${input}:\n${text}`);
    Deno.exit(1);
  }
  return text;
}

// A path as the user would write it: relative to the working directory when under it, `..` resolved.
function shown(path: string): string {
  const parts: string[] = [];
  for (const p of path.split("/")) {
    if (p === "..") parts.pop();
    else if (p !== "." && p !== "") parts.push(p);
  }
  const abs = (path.startsWith("/") ? "/" : "") + parts.join("/");
  const cwd = Deno.cwd() + "/";
  return abs.startsWith(cwd) ? abs.slice(cwd.length) : abs;
}

function explainAndExit(e: unknown): never {
  if (!(e instanceof TranslationError)) {
    console.error(`snell-wgsl: ${input}: ${(e as Error).message}`);
    Deno.exit(1);
  }
  const where = e.location ? `${shown(e.location.file)}:${e.location.line}` : shown(input);
  let text = `${where}: error: naga cannot translate ${shown(input)} to WGSL: ${e.message}`;
  if (e.instruction || e.location?.fn)
    text += `\n  naga stopped at ${e.instruction ?? "a SPIR-V instruction"}` + (e.location?.fn ? ` in ${e.location.fn}` : "");
  const params = e.combinedSamplers.filter((c) => c.fn !== undefined);
  const uniforms = e.combinedSamplers.filter((c) => c.fn === undefined);
  const at = (c: { location?: { file: string; line: number } }) =>
    c.location ? ` (${shown(c.location.file)}:${c.location.line})` : "";
  if (params.length) {
    const s = params.find((p) => p.fn === e.location?.fn) ?? params[0];
    const others = params.length - 1;
    text += `\n  cause: ${s.fn}${at(s)}${others ? ` and ${others} other function(s)` : ""} take a sampler2D` +
      ` parameter (${s.name}): WGSL has no combined image samplers, and naga cannot translate one passed` +
      ` to a function.`;
  }
  if (uniforms.length) {
    text += `\n  cause: ${uniforms.map((u) => `${u.name}${at(u)}`).join(", ")} ${uniforms.length > 1 ? "are" : "is a"}` +
      ` sampler2D uniform${uniforms.length > 1 ? "s" : ""}: WGSL has no combined image samplers.`;
  }
  if (e.combinedSamplers.length) {
    text += `\n  fix: declare each texture as a texture2D, one sampler beside them, and #define` +
      ` SNELL_WEBGPU_SAMPLER <that sampler>\n  before #include "snell_webgpu_prelude.glsl"` +
      ` (examples/webgpu/refract.frag; docs/recipes.md, "WebGPU (WGSL)").`;
  }
  const detail = e.naga.split("\n").slice(1).filter((l) => l.trim() && l.trim() !== `error: ${e.message.replace(/^\w+: /, "")}`);
  if (detail.length) text += `\n  naga's message:\n    ${detail.join("\n    ")}`;
  console.error(text);
  Deno.exit(1);
}

const tmp = await Deno.makeTempDir({ prefix: "snell-wgsl" });
// Deno.exit skips `finally`, not the unload event.
globalThis.addEventListener("unload", () => Deno.removeSync(tmp, { recursive: true }));
{
  const spv = `${tmp}/shader.spv`;
  run("glslangValidator", ["-V", "-g", "--target-env", "vulkan1.1", `-I${here}`, `-I${snellGlsl}`,
    ...includes.map((d) => `-I${d}`), ...defines.map((d) => `-D${d}`), "-o", spv, input], "glslang-tools");
  run("spirv-val", ["--target-env", "vulkan1.1", spv], "spirv-tools");
  const optimize = (spirv: Uint8Array) => {
    Deno.writeFileSync(`${tmp}/tidy.spv`, spirv);
    run("spirv-opt", ["--target-env=vulkan1.1", ...spirvOptPasses, `${tmp}/tidy.spv`, "-o", `${tmp}/opt.spv`],
      "spirv-tools");
    run("spirv-val", ["--target-env", "vulkan1.1", `${tmp}/opt.spv`], "spirv-tools");
    return Deno.readFileSync(`${tmp}/opt.spv`);
  };
  let wgsl = "";
  try {
    wgsl = raw ? rawWgsl(Deno.readFileSync(spv)) : readableWgsl(Deno.readFileSync(spv), { optimize });
  } catch (e) {
    explainAndExit(e);
  }
  const how = raw ? "glslang -V, naga" : "glslang -V, spirv-opt, naga";
  Deno.writeTextFileSync(output, `// WGSL from ${input.split("/").pop()} by snell-wgsl (${how})\n` + wgsl);
  if (stats) {
    const text = Deno.readTextFileSync(output);
    const fns = [...text.matchAll(/^fn (\w+)/gm)].length;
    const longest = [...text.matchAll(/[A-Za-z_][A-Za-z0-9_]*/g)].reduce((a, m) => (m[0].length > a.length ? m[0] : a), "");
    console.log(`snell-wgsl: ${output}: ${new TextEncoder().encode(text).length} bytes, ` +
      `${text.split("\n").length - 1} lines, ${fns} functions, longest name ${longest.length} characters (${longest})`);
  }
  if (check) {
    const adapter = await navigator.gpu.requestAdapter();
    if (!adapter) {
      console.error("snell-wgsl: --check: no WebGPU adapter (Deno's WebGPU runs on Vulkan: mesa-vulkan-drivers)");
      Deno.exit(1);
    }
    const device = await adapter.requestDevice();
    const info = await device.createShaderModule({ code: wgsl }).getCompilationInfo();
    const errors = info.messages.filter((m) => m.type === "error");
    if (errors.length) {
      console.error(`snell-wgsl: ${adapter.info.description} rejects ${output}:\n` +
        errors.map((m) => `  ${m.lineNum}:${m.linePos} ${m.message}`).join("\n"));
      Deno.exit(1);
    }
    const tint = new Deno.Command("node", { args: [`${here}tint_check.mjs`, output], stderr: "piped" }).outputSync();
    if (!tint.success) {
      console.error(new TextDecoder().decode(tint.stderr));
      Deno.exit(1);
    }
    console.log(`snell-wgsl: ${output} compiles on ${adapter.info.description} and with Tint`);
    if (runIt) {
      try {
        console.log(`snell-wgsl: ${output} runs on ${adapter.info.description}: ${await runOnce(device, wgsl)}`);
      } catch (e) {
        console.error(`snell-wgsl: --run: ${output} fails on ${adapter.info.description}:\n${(e as Error).message}`);
        Deno.exit(1);
      }
    }
  }
}
