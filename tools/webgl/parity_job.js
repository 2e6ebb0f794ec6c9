// A WebGL 2 parity job: the job's ES 3.00 fragment shader once per case, the four output vectors of
// every case posted back as 16 floats. parity_page.js runs one in a page of its own
// (tools/browser/run_page.mjs); under ctest, tools/browser/page_server.mjs's page runs every job with
// it: the same code either way, for the same bits.
//
// get(file) reads a file of the job; post(what, body) posts "/renderer", "/log" or "/results".
export async function run({ get, post }) {
  const job = await (await get("job.json")).json();
  const gl = document.createElement("canvas").getContext("webgl2", { antialias: false, depth: false, alpha: true });
  if (!gl) throw new Error("this browser gives no WebGL 2 context");
  try {
    await runOn(gl, job, { get, post });
  } finally {
    // A page that runs every job would otherwise keep each job's context until it is collected, and
    // Chromium takes the oldest context away from a page that has too many.
    gl.getExtension("WEBGL_lose_context")?.loseContext();
  }
}

async function runOn(gl, job, { get, post }) {
  const info = gl.getExtension("WEBGL_debug_renderer_info");
  await post("/renderer", info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER));
  if (!gl.getExtension("EXT_color_buffer_float")) throw new Error("no EXT_color_buffer_float: float results cannot be read back");
  const linear = job.textures.some((t) => t.mag === "linear" || t.min === "linear" || t.mip === "linear");
  if (linear && !gl.getExtension("OES_texture_float_linear"))
    throw new Error("no OES_texture_float_linear, which a LINEAR RGBA32F texture needs");

  const compileStarted = performance.now();
  const compile = (type, text, what) => {
    const s = gl.createShader(type);
    gl.shaderSource(s, text);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(`the ${what} does not compile:\n${gl.getShaderInfoLog(s)}`);
    return s;
  };
  // One triangle over the whole viewport.
  const vs = compile(gl.VERTEX_SHADER, "#version 300 es\nvoid main() {\n" +
    "  gl_Position = vec4(float((gl_VertexID << 1) & 2) * 2.0 - 1.0, float(gl_VertexID & 2) * 2.0 - 1.0, 0.0, 1.0);\n}\n", "vertex shader");
  const fs = compile(gl.FRAGMENT_SHADER, await (await get("shader.frag")).text(), "case's fragment shader");
  const program = gl.createProgram();
  gl.attachShader(program, vs);
  gl.attachShader(program, fs);
  gl.linkProgram(program);
  if (!gl.getProgramParameter(program, gl.LINK_STATUS)) throw new Error(`the program does not link:\n${gl.getProgramInfoLog(program)}`);
  gl.useProgram(program);
  if (gl.isContextLost()) throw new Error("the WebGL context was lost while compiling the case's shader");

  const columns = job.columns;
  const rows = Math.max(1, Math.ceil(job.count / columns));
  const limit = gl.getParameter(gl.MAX_TEXTURE_SIZE);
  if (4 * columns > limit || rows > limit) throw new Error(`${job.count} cases need a ${4 * columns} x ${rows} texture, the limit is ${limit}`);
  const upload = (unit, width, height, data) => {
    const t = gl.createTexture();
    gl.activeTexture(gl.TEXTURE0 + unit);
    gl.bindTexture(gl.TEXTURE_2D, t);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, width, height, 0, gl.RGBA, gl.FLOAT, data);
    return t;
  };
  // Unit 0: the inputs, 4 texels per case, padded to whole rows.
  const inputs = new Float32Array(16 * columns * rows);
  inputs.set(new Float32Array(await (await get("inputs.f32")).arrayBuffer()));
  upload(0, 4 * columns, rows, inputs);
  for (const p of [gl.TEXTURE_MIN_FILTER, gl.TEXTURE_MAG_FILTER]) gl.texParameteri(gl.TEXTURE_2D, p, gl.NEAREST);
  gl.uniform1i(gl.getUniformLocation(program, "snellParityInputs"), 0);
  gl.uniform1i(gl.getUniformLocation(program, "snellParityCount"), job.count);

  // Unit 1 + k: texture k with its levels and filters, as the GL runtime sets them (clamp to edge; no
  // mips: the base level only). A sampler the compiler removed has no location and is skipped.
  const filter = { nearest: gl.NEAREST, linear: gl.LINEAR };
  const minify = { none: { nearest: gl.NEAREST, linear: gl.LINEAR },
    nearest: { nearest: gl.NEAREST_MIPMAP_NEAREST, linear: gl.LINEAR_MIPMAP_NEAREST },
    linear: { nearest: gl.NEAREST_MIPMAP_LINEAR, linear: gl.LINEAR_MIPMAP_LINEAR } };
  for (const [k, t] of job.textures.entries()) {
    const location = gl.getUniformLocation(program, t.uniform);
    if (location === null) continue;
    const data = new Float32Array(await (await get(`tex_${k}.f32`)).arrayBuffer());
    const tex = upload(1 + k, t.levels[0][0], t.levels[0][1], null);
    let offset = 0;
    t.levels.forEach(([w, h], level) => {
      gl.texImage2D(gl.TEXTURE_2D, level, gl.RGBA32F, w, h, 0, gl.RGBA, gl.FLOAT, data.subarray(offset, offset + 4 * w * h));
      offset += 4 * w * h;
    });
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAX_LEVEL, t.mip === "none" ? 0 : t.levels.length - 1);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, filter[t.mag]);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, minify[t.mip][t.min]);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    gl.uniform1i(location, 1 + k);
    if (!tex) throw new Error(`cannot create texture ${t.uniform}`);
  }

  // Four RGBA32F colour attachments: the case's four output vectors.
  const fbo = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
  const targets = [0, 1, 2, 3].map((a) => {
    const t = upload(1 + job.textures.length + a, columns, rows, null);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + a, gl.TEXTURE_2D, t, 0);
    return t;
  });
  gl.drawBuffers(targets.map((_, a) => gl.COLOR_ATTACHMENT0 + a));
  if (gl.checkFramebufferStatus(gl.FRAMEBUFFER) !== gl.FRAMEBUFFER_COMPLETE) throw new Error("four RGBA32F colour attachments are not a complete framebuffer");
  gl.viewport(0, 0, columns, rows);
  gl.disable(gl.BLEND);
  gl.disable(gl.DITHER);
  gl.enable(gl.SCISSOR_TEST);

  // One row of cases per draw, each read back before the next: a single draw of a whole technique over
  // every case outlasts Chromium's GPU watchdog, which then loses the context.
  const results = new Float32Array(16 * job.count);
  const row = new Float32Array(4 * columns);
  const started = performance.now();
  for (let y = 0; y < rows; ++y) {
    gl.scissor(0, y, columns, 1);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    for (let a = 0; a < 4; ++a) {
      gl.readBuffer(gl.COLOR_ATTACHMENT0 + a);
      gl.readPixels(0, y, columns, 1, gl.RGBA, gl.FLOAT, row);
      for (let x = 0, i = y * columns; x < columns && i < job.count; ++x, ++i)
        results.set(row.subarray(4 * x, 4 * x + 4), 16 * i + 4 * a);
    }
    if (gl.isContextLost()) throw new Error(`the WebGL context was lost at row ${y} of ${rows}`);
  }
  const error = gl.getError();
  if (error !== gl.NO_ERROR) throw new Error(`WebGL error 0x${error.toString(16)}`);
  await post("/log", `compile and link ${(started - compileStarted).toFixed(0)} ms, ${rows} draws ${(performance.now() - started).toFixed(0)} ms`);
  await post("/results", results);
}
