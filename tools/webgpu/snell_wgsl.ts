// snell-wgsl: a WebGPU shader that includes snell, as WGSL. Your Vulkan GLSL
// (a compute or fragment shader with #include "snell/..." after
// #include "snell_webgpu_prelude.glsl") -> glslangValidator -V -> spirv-val ->
// naga -> WGSL, the path the WebGPU parity runtime proves.
//
//   tools/webgpu/snell-wgsl [--check] [-I DIR]... [-D NAME[=VALUE]]... SHADER.(comp|frag|vert) -o OUT.wgsl
//
// --check: also compile the WGSL on this machine's WebGPU device (Deno's wgpu)
// and with Tint (Dawn's and Chrome's compiler, tint_check.mjs), and fail on
// any error either reports.
// snell's glsl/ and this directory (the WebGPU prelude) are always on the
// include path. Textures: WGSL has no combined samplers and naga rejects a
// sampler2D passed to a function, so define SNELL_TEX2D and the sampling
// hooks for your bindings before including snell (examples/webgpu/refract.frag
// shows the pattern: a texture is a slot number, each slot a texture2D and its
// own sampler). Exit status 1 with the tool's message on any failure.
import { spirvToWgsl } from "./naga_wgsl.ts";

const here = new URL(".", import.meta.url).pathname;
const snellGlsl = `${here}../../glsl`;
const args = [...Deno.args];
const includes: string[] = [], defines: string[] = [];
let input = "", output = "", check = false;
for (let i = 0; i < args.length; ++i) {
  const a = args[i];
  if (a === "-o") output = args[++i] ?? "";
  else if (a === "--check") check = true;
  else if (a === "-I") includes.push(args[++i] ?? "");
  else if (a.startsWith("-I")) includes.push(a.slice(2));
  else if (a === "-D") defines.push(args[++i] ?? "");
  else if (a.startsWith("-D")) defines.push(a.slice(2));
  else if (!a.startsWith("-") && !input) input = a;
  else {
    console.error(`snell-wgsl: unknown argument '${a}'`);
    Deno.exit(2);
  }
}
if (!input || !output) {
  console.error("usage: snell-wgsl [--check] [-I DIR]... [-D NAME[=VALUE]]... SHADER.(comp|frag|vert) -o OUT.wgsl");
  Deno.exit(2);
}

function run(program: string, argv: string[], pkg: string) {
  let r;
  try {
    r = new Deno.Command(program, { args: argv, stdout: "piped", stderr: "piped" }).outputSync();
  } catch {
    console.error(`snell-wgsl: cannot run ${program}: install the Debian package ${pkg}`);
    Deno.exit(1);
  }
  if (!r.success) {
    const text = new TextDecoder().decode(r.stdout) + new TextDecoder().decode(r.stderr);
    console.error(`snell-wgsl: ${program} failed on ${input}:\n${text}`);
    Deno.exit(1);
  }
}

const spv = await Deno.makeTempFile({ suffix: ".spv" });
try {
  run("glslangValidator", ["-V", "--target-env", "vulkan1.1", `-I${here}`, `-I${snellGlsl}`,
    ...includes.map((d) => `-I${d}`), ...defines.map((d) => `-D${d}`), "-o", spv, input], "glslang-tools");
  run("spirv-val", ["--target-env", "vulkan1.1", spv], "spirv-tools");
  let wgsl = "";
  try {
    wgsl = spirvToWgsl(Deno.readFileSync(spv));
  } catch (e) {
    console.error(`snell-wgsl: naga cannot translate ${input}: ${(e as Error).message}`);
    Deno.exit(1);
  }
  Deno.writeTextFileSync(output, `// WGSL from ${input.split("/").pop()} by snell-wgsl (glslang -V, naga)\n` + wgsl);
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
  }
} finally {
  Deno.removeSync(spv);
}
