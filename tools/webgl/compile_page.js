// The compile-time page (served by tools/browser/run_page.mjs for benchmarks/compile_times): compiles,
// links and draws once each ES 3.00 fragment shader job.json lists (run_page.mjs serves one, shader.frag),
// each in a context of its own,
// and posts per program 16 floats: compile + link ms, first draw ms (drivers may compile more there),
// 1 when it linked, then zeros.
import { get, post } from "/browser/page_io.js";

async function run() {
  const job = await (await get("job.json")).json();
  const out = new Float32Array(16 * job.programs.length);
  let renderer = "";
  for (let i = 0; i < job.programs.length; ++i) {
    const source = await (await get(job.programs[i])).text();
    const gl = document.createElement("canvas").getContext("webgl2", { antialias: false, depth: false });
    if (!gl) throw new Error("this browser gives no WebGL 2 context");
    if (!renderer) {
      const info = gl.getExtension("WEBGL_debug_renderer_info");
      renderer = info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
      await post("/renderer", renderer);
    }
    const compile = (type, text) => {
      const s = gl.createShader(type);
      gl.shaderSource(s, text);
      gl.compileShader(s);
      return s;
    };
    const t0 = performance.now();
    const vs = compile(gl.VERTEX_SHADER, "#version 300 es\nout vec3 vsPosition;\nout vec3 vsNormal;\nvoid main() {\n" +
      "  vec2 q = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2)) * 2.0 - 1.0;\n" +
      "  vsPosition = vec3(q, -2.0);\n  vsNormal = vec3(0.0, 0.0, 1.0);\n  gl_Position = vec4(q, 0.0, 1.0);\n}\n");
    const fs = compile(gl.FRAGMENT_SHADER, source);
    const program = gl.createProgram();
    gl.attachShader(program, vs);
    gl.attachShader(program, fs);
    gl.linkProgram(program);
    const linked = gl.getProgramParameter(program, gl.LINK_STATUS);
    const t1 = performance.now();
    if (!linked)
      throw new Error(`${job.programs[i]} does not link:\n${gl.getShaderInfoLog(fs)}\n${gl.getProgramInfoLog(program)}`);
    gl.useProgram(program);
    gl.viewport(0, 0, 1, 1);
    // The example's uniform block, zeros: the draw only has to run the shader.
    const block = gl.getUniformBlockIndex(program, "Frame");
    if (block !== gl.INVALID_INDEX) {
      const ubo = gl.createBuffer();
      gl.bindBuffer(gl.UNIFORM_BUFFER, ubo);
      gl.bufferData(gl.UNIFORM_BUFFER, gl.getActiveUniformBlockParameter(program, block, gl.UNIFORM_BLOCK_DATA_SIZE),
                    gl.STATIC_DRAW);
      gl.uniformBlockBinding(program, block, 0);
      gl.bindBufferBase(gl.UNIFORM_BUFFER, 0, ubo);
    }
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
    const t2 = performance.now();
    if (gl.isContextLost()) throw new Error(`the context was lost drawing ${job.programs[i]}`);
    const error = gl.getError();
    if (error !== gl.NO_ERROR) throw new Error(`GL error 0x${error.toString(16)} drawing ${job.programs[i]}`);
    out.set([t1 - t0, t2 - t1, 1], 16 * i);
    gl.getExtension("WEBGL_lose_context")?.loseContext();
  }
  await post("/results", out);
}

run().catch((e) => post("/error", `${e.stack ?? e}`));
