// snell in three.js: one of snell-lab's frames (a bundle written by `snell-lab --web-bundle DIR`) rendered
// with snell's two-interface refraction in WebGL 2. Every pass a technique needs, in three.js render targets:
//   1. the opaque scene (environment, then the paintings): colour, view-space normal, depth;
//   2. the object's back faces (depth test GREATER after clearing depth to 0) and front faces: normal, depth;
//   3. the min/max depth pyramid of the back faces and of the scene, one target per level, each copied into
//      its level of a mip-chained target (WebGL 2 will not render one level of a texture while sampling
//      another level of it);
//   4. on the canvas: the scene's colour, then the object's front faces through the technique's program
//      (shaders/refract.frag, snell's single-file GLSL as the ShaderChunk "snell").
// Colour: every buffer holds linear RGB in float targets; only the canvas passes encode to sRGB (8 bits).
// The scene and object buffers extend `margin` texels beyond the canvas on every side (the lab's guard
// band), rendered through the bundle's bufferClipFromView, so exits just off screen are found.
// ?technique=<name> picks the technique; ?buffers=lab runs it on the lab's own buffers and front-face inputs
// (in the bundle) instead of the page's, which sets snell's code apart from the two rasterizers; ?test=1
// renders once and posts the canvas to serve.mjs.
import * as THREE from "three";

const query = new URLSearchParams(location.search);
const testMode = query.has("test");
const labBuffers = query.get("buffers") === "lab";
const statusLine = document.getElementById("status");

async function fetchOk(url) {
  const r = await fetch(url);
  if (!r.ok) throw new Error(`cannot load ${url} (HTTP ${r.status})`);
  return r;
}
const text = async (url) => (await fetchOk(url)).text();
const bytes = async (url) => (await fetchOk(url)).arrayBuffer();

async function report(what, body) {
  if (testMode) await fetch(`/report/${what}`, { method: "POST", body });
}

function fail(error) {
  const message = error && error.stack ? `${error.message}\n${error.stack}` : String(error);
  statusLine.textContent = `error: ${message}`;
  report("error", message);
}
window.addEventListener("error", (e) => fail(e.error ?? e.message));
window.addEventListener("unhandledrejection", (e) => fail(e.reason));

const matrix = (a) => new THREE.Matrix4().fromArray(a);  // column-major, as the bundle writes it
const vector = (a) => new THREE.Vector3(a[0], a[1], a[2]);

// A float RGBA image of the bundle as a texture (clamped to the edge, no mips); linear filtering is how the
// lab samples its paintings and its environment.
async function floatTexture(image, filter = THREE.LinearFilter) {
  const data = new Float32Array(await bytes(`bundle/${image.texels}`));
  if (data.length !== image.width * image.height * 4) throw new Error(`bundle/${image.texels}: wrong size`);
  const t = new THREE.DataTexture(data, image.width, image.height, THREE.RGBAFormat, THREE.FloatType);
  t.minFilter = filter;
  t.magFilter = filter;
  t.generateMipmaps = false;
  t.needsUpdate = true;
  return t;
}

function floatTarget(width, height, options = {}) {
  return new THREE.WebGLRenderTarget(width, height, {
    type: THREE.FloatType,
    format: THREE.RGBAFormat,
    minFilter: THREE.NearestFilter,
    magFilter: THREE.NearestFilter,
    generateMipmaps: false,
    depthBuffer: false,
    ...options,
  });
}

// A target with `count` float colour attachments and a float depth texture, as the lab's framebuffers.
function layerTarget(width, height, count) {
  return floatTarget(width, height, {
    count,
    depthBuffer: true,
    depthTexture: new THREE.DepthTexture(width, height, THREE.FloatType),
  });
}

function setFilter(texture, filter) {
  texture.minFilter = filter;
  texture.magFilter = filter;
}

function rawMaterial(vertexShader, fragmentShader, uniforms, options = {}) {
  return new THREE.RawShaderMaterial({ glslVersion: THREE.GLSL3, vertexShader, fragmentShader, uniforms, ...options });
}

async function main() {
  const bundle = await (await fetchOk("bundle/bundle.json")).json();
  THREE.ShaderChunk.snell = await text("snell/snell.glsl");
  THREE.ShaderChunk.srgb_encode = await text("shaders/srgb_encode.glsl");
  const src = {};
  for (const name of ["fullscreen.vert", "background.frag", "painting.vert", "painting.frag", "mesh.vert",
    "layer.frag", "pyramid.frag", "copy.frag", "present.frag", "refract.frag"])
    src[name] = await text(`shaders/${name}`);

  const W = bundle.width, H = bundle.height, margin = bundle.margin;
  const BW = W + 2 * margin, BH = H + 2 * margin;
  const canvas = document.getElementById("frame");
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.setSize(W, H, false);
  renderer.autoClear = false;
  renderer.setClearColor(0x000000, 0);
  const gl = renderer.getContext();
  for (const ext of ["EXT_color_buffer_float", "OES_texture_float_linear"])
    if (!renderer.extensions.has(ext)) throw new Error(`this browser's WebGL 2 lacks ${ext}: snell's float buffers need it`);
  document.getElementById("renderer").textContent = rendererName(gl);

  const camera = new THREE.Camera();  // unused by raw shaders: every matrix comes from the bundle
  const viewFromWorld = matrix(bundle.viewFromWorld);
  const bufferClipFromView = matrix(bundle.bufferClipFromView);
  const draw = (object, target, level = 0) => {
    renderer.setRenderTarget(target, 0, level);
    renderer.render(object, camera);
  };
  const clear = (target, depth) => {
    renderer.setRenderTarget(target);
    renderer.state.buffers.depth.setClear(depth);
    renderer.clear(true, true, false);
  };
  const fullscreen = new THREE.BufferGeometry();
  fullscreen.setAttribute("position", new THREE.Float32BufferAttribute([-1, -1, 0, 3, -1, 0, -1, 3, 0], 3));
  const quad = (material) => {
    const m = new THREE.Mesh(fullscreen, material);
    m.frustumCulled = false;
    return m;
  };

  // The object, as the lab's GL pass pulls it: positions with Wyman's d_N in w, normals, indices.
  const positions = new THREE.InterleavedBuffer(new Float32Array(await bytes(`bundle/${bundle.mesh.positions}`)), 4);
  const normals = new THREE.InterleavedBuffer(new Float32Array(await bytes(`bundle/${bundle.mesh.normals}`)), 4);
  const indices = new Uint32Array(await bytes(`bundle/${bundle.mesh.triangles}`));
  if (positions.count !== bundle.mesh.vertices || normals.count !== bundle.mesh.vertices ||
      indices.length !== bundle.mesh.indices)
    throw new Error("bundle: the mesh's files do not match bundle.json");
  const object = new THREE.BufferGeometry();
  object.setAttribute("position", new THREE.InterleavedBufferAttribute(positions, 3, 0));
  object.setAttribute("dn", new THREE.InterleavedBufferAttribute(positions, 1, 3));
  object.setAttribute("normal", new THREE.InterleavedBufferAttribute(normals, 3, 0));
  object.setIndex(new THREE.BufferAttribute(indices, 1));
  const objectMesh = (material) => {
    const m = new THREE.Mesh(object, material);
    m.frustumCulled = false;
    return m;
  };

  // (1) The opaque scene.
  const scene = layerTarget(BW, BH, 2);
  setFilter(scene.textures[0], THREE.LinearFilter);  // colour: bilinear, no mips
  const normalFilter = bundle.normalFilter === "linear" ? THREE.LinearFilter : THREE.NearestFilter;
  setFilter(scene.textures[1], normalFilter);
  const environment = await floatTexture(bundle.environment);
  const background = quad(rawMaterial(src["fullscreen.vert"], src["background.frag"], {
    environment: { value: environment },
    viewFromClip: { value: matrix(bundle.bufferViewFromClip) },
    envX: { value: vector(bundle.envX) },
    envY: { value: vector(bundle.envY) },
    envZ: { value: vector(bundle.envZ) },
    viewport: { value: new THREE.Vector2(BW, BH) },
  }, { depthTest: false, depthWrite: false }));
  const paintings = new THREE.Group();
  for (const p of bundle.paintings) {
    const c = p.corners.map(vector);
    const g = new THREE.BufferGeometry();
    g.setAttribute("position", new THREE.Float32BufferAttribute(p.corners.flat(), 3));
    g.setAttribute("uv", new THREE.Float32BufferAttribute([0, 0, 1, 0, 1, 1, 0, 1], 2));
    g.setIndex([0, 1, 2, 0, 2, 3]);
    const faceNormal = new THREE.Vector3().crossVectors(c[1].clone().sub(c[0]), c[3].clone().sub(c[0]));
    const m = new THREE.Mesh(g, rawMaterial(src["painting.vert"], src["painting.frag"], {
      painting: { value: await floatTexture(p) },
      viewFromWorld: { value: viewFromWorld },
      clipFromView: { value: bufferClipFromView },
      faceNormal: { value: faceNormal },
    }, { side: THREE.DoubleSide, depthFunc: THREE.LessDepth }));
    m.frustumCulled = false;
    paintings.add(m);
  }

  // (2) The object's back faces and front faces.
  const back = layerTarget(BW, BH, 1);
  const front = layerTarget(BW, BH, 1);
  setFilter(back.textures[0], normalFilter);
  setFilter(front.textures[0], normalFilter);
  const layerUniforms = { viewFromWorld: { value: viewFromWorld }, clipFromView: { value: bufferClipFromView } };
  const backFaces = objectMesh(rawMaterial(src["mesh.vert"], src["layer.frag"], layerUniforms,
    { side: THREE.BackSide, depthFunc: THREE.GreaterDepth }));
  const frontFaces = objectMesh(rawMaterial(src["mesh.vert"], src["layer.frag"], layerUniforms,
    { side: THREE.FrontSide, depthFunc: THREE.LessDepth }));

  // (3) The pyramids: levels halve (floor, at least 1) down to 1x1, as snell::gpu::DepthPyramid's.
  const sizes = [[BW, BH]];
  while (sizes.at(-1)[0] > 1 || sizes.at(-1)[1] > 1)
    sizes.push([Math.max(1, sizes.at(-1)[0] >> 1), Math.max(1, sizes.at(-1)[1] >> 1)]);
  const levelTargets = sizes.map(([w, h]) => floatTarget(w, h));
  const pyramidTarget = () => {
    const t = floatTarget(BW, BH, { minFilter: THREE.NearestMipmapNearestFilter });
    t.texture.mipmaps = sizes.map(([width, height]) => ({ width, height }));  // three.js: a level per entry
    return t;
  };
  const backPyramid = pyramidTarget(), scenePyramid = pyramidTarget();
  const pyramidPass = quad(rawMaterial(src["fullscreen.vert"], src["pyramid.frag"], {
    source: { value: null },
    fromDepth: { value: 1 },
    zNear: { value: bundle.zNear },
    zFar: { value: bundle.zFar },
    emptyDepth: { value: 0 },
  }, { depthTest: false, depthWrite: false }));
  const copyPass = quad(rawMaterial(src["fullscreen.vert"], src["copy.frag"], { source: { value: null } },
    { depthTest: false, depthWrite: false }));
  const buildPyramid = (depthTexture, emptyDepth, pyramid) => {
    const u = pyramidPass.material.uniforms;
    u.emptyDepth.value = emptyDepth;
    for (let lod = 0; lod < sizes.length; ++lod) {
      u.source.value = lod === 0 ? depthTexture : levelTargets[lod - 1].texture;
      u.fromDepth.value = lod === 0 ? 1 : 0;
      draw(pyramidPass, levelTargets[lod]);
      copyPass.material.uniforms.source.value = levelTargets[lod].texture;
      pyramid.viewport.set(0, 0, sizes[lod][0], sizes[lod][1]);
      draw(copyPass, pyramid, lod);
    }
  };

  const t0 = performance.now();
  clear(scene, 1);
  draw(background, scene);
  draw(paintings, scene);
  clear(back, 0);
  draw(backFaces, back);
  clear(front, 1);
  draw(frontFaces, front);
  // The buffers the technique reads: the page's own, or the lab's (their depth in x of a float texture).
  let buffers = {
    sceneColor: scene.textures[0], sceneNormal: scene.textures[1], sceneDepth: scene.depthTexture,
    backNormal: back.textures[0], backDepth: back.depthTexture,
    frontLayerNormal: front.textures[0], frontLayerDepth: front.depthTexture,
  };
  if (labBuffers) {
    const lab = bundle.labBuffers;
    if (!lab) throw new Error("this bundle has no lab buffers: write it again with snell-lab --web-bundle");
    buffers = {
      sceneColor: await floatTexture(lab.sceneColor),
      sceneNormal: await floatTexture(lab.sceneNormal, normalFilter),
      sceneDepth: await floatTexture(lab.sceneDepth, THREE.NearestFilter),
      backNormal: await floatTexture(lab.backNormal, normalFilter),
      backDepth: await floatTexture(lab.backDepth, THREE.NearestFilter),
      frontLayerNormal: await floatTexture(lab.frontLayerNormal, normalFilter),
      frontLayerDepth: await floatTexture(lab.frontLayerDepth, THREE.NearestFilter),
      frontPositions: await floatTexture(lab.frontPosition, THREE.NearestFilter),
      frontNormals: await floatTexture(lab.frontNormal, THREE.NearestFilter),
    };
  }
  buildPyramid(buffers.backDepth, 0, backPyramid);
  buildPyramid(buffers.sceneDepth, 1, scenePyramid);
  finish(renderer);
  const staticMs = performance.now() - t0;

  // (4) The frame: the scene's colour, then the object through the technique's program.
  const present = quad(rawMaterial(src["fullscreen.vert"], src["present.frag"], {
    sceneColor: { value: buffers.sceneColor },
    margin: { value: margin },
  }, { depthTest: false, depthWrite: false }));
  const techniqueUniforms = {
    viewFromWorld: { value: viewFromWorld },
    clipFromView: { value: matrix(bundle.clipFromView) },
    backDepth: { value: buffers.backDepth },
    backNormal: { value: buffers.backNormal },
    backPyramid: { value: backPyramid.texture },
    frontLayerDepth: { value: buffers.frontLayerDepth },
    frontLayerNormal: { value: buffers.frontLayerNormal },
    sceneDepth: { value: buffers.sceneDepth },
    sceneNormal: { value: buffers.sceneNormal },
    scenePyramid: { value: scenePyramid.texture },
    sceneColor: { value: buffers.sceneColor },
    frontPositions: { value: buffers.frontPositions ?? null },
    frontNormals: { value: buffers.frontNormals ?? null },
    environment: { value: environment },
    bufferClipFromView: { value: bufferClipFromView },
    zNear: { value: bundle.zNear },
    zFar: { value: bundle.zFar },
    ior: { value: bundle.ior },
    absorption: { value: vector(bundle.absorption) },
    envX: { value: vector(bundle.envX) },
    envY: { value: vector(bundle.envY) },
    envZ: { value: vector(bundle.envZ) },
    backRange: { value: bundle.backRange },
    depthFilter: { value: bundle.depthFilter },
    reflectSource: { value: bundle.reflectSource },
  };
  // One program per technique, with only the strategies its slots call (the bundle lists them as the lab
  // computes them with snellStrategiesUsed) and the perspective-only depth path (the lab's camera is one).
  // On the lab's buffers: a full-screen pass over the lab's front-face inputs instead of the mesh.
  const programs = new Map();
  const techniqueMesh = (t) => {
    if (!programs.has(t.name)) {
      const defines = { PAGE_TECHNIQUE: t.id, SNELL_INTERSECT_STRATEGIES: t.strategies, SNELL_PERSPECTIVE_ONLY: 1 };
      programs.set(t.name, labBuffers
        ? quad(rawMaterial(src["fullscreen.vert"], src["refract.frag"], techniqueUniforms,
          { depthTest: false, depthWrite: false, defines: { ...defines, PAGE_FRONT_FROM_TEXTURES: 1 } }))
        : objectMesh(rawMaterial(src["mesh.vert"], src["refract.frag"], techniqueUniforms,
          { side: THREE.FrontSide, depthFunc: THREE.LessDepth, defines })));
    }
    return programs.get(t.name);
  };
  const renderFrame = (t) => {
    clear(null, 1);
    draw(present, null);
    draw(techniqueMesh(t), null);
    finish(renderer);
  };

  const picker = document.getElementById("technique");
  for (const t of bundle.techniques) picker.add(new Option(t.label, t.name));
  const wanted = query.get("technique") ?? "plane-normal-2";
  const technique = (name) => {
    const t = bundle.techniques.find((x) => x.name === name);
    if (!t) throw new Error(`no technique ${name}; the bundle has ${bundle.techniques.map((x) => x.name).join(", ")}`);
    return t;
  };
  picker.value = technique(wanted).name;
  document.getElementById("scene").textContent =
    `${bundle.scene}, ${W}x${H}, ${labBuffers ? "on the lab's buffers" : "the page's own buffers"}`;

  let current = technique(wanted);
  // The first draw compiles the program; the browser shows the status line first (two frames).
  const compile = async () => {
    statusLine.textContent = `compiling ${current.label} (the page does not respond until it is done) ...`;
    for (let i = 0; i < 2; ++i) await new Promise((resolve) => requestAnimationFrame(resolve));
    const c0 = performance.now();
    renderFrame(current);
    return performance.now() - c0;
  };
  let firstDrawMs = await compile();
  statusLine.textContent = `${current.label}: first draw (compile) ${(firstDrawMs / 1000).toFixed(1)} s; ` +
    `static passes ${staticMs.toFixed(0)} ms`;
  if (testMode) {
    const pixels = new Uint8Array(W * H * 4);
    renderer.setRenderTarget(null);
    gl.readPixels(0, 0, W, H, gl.RGBA, gl.UNSIGNED_BYTE, pixels);  // row 0 at the bottom, as the bundle's
    const png = await new Promise((resolve) => canvas.toBlob(resolve, "image/png"));
    await report("screenshot", png);
    await report("log", JSON.stringify({ renderer: rendererName(gl), subpixelBits: gl.getParameter(gl.SUBPIXEL_BITS),
      firstDrawMs, staticMs }));
    await report("pixels", pixels);
    return;
  }
  // The frame time: one frame (the scene's colour, the technique's pass), waited for, the median of the
  // last 31 frames of the technique picked.
  const times = [];
  let compiling = false;
  picker.addEventListener("change", async () => {
    compiling = true;
    current = technique(picker.value);
    times.length = 0;
    firstDrawMs = await compile();
    compiling = false;
  });
  const loop = () => {
    if (compiling) {
      requestAnimationFrame(loop);
      return;
    }
    const f0 = performance.now();
    renderFrame(current);
    times.push(performance.now() - f0);
    if (times.length > 31) times.shift();
    const median = [...times].sort((a, b) => a - b)[times.length >> 1];
    statusLine.textContent = `${current.label}: ${median.toFixed(1)} ms per frame (median of ${times.length}); ` +
      `first draw (compile) ${(firstDrawMs / 1000).toFixed(1)} s; static passes ${staticMs.toFixed(0)} ms`;
    requestAnimationFrame(loop);
  };
  requestAnimationFrame(loop);
}

// Waits for the GPU: a one-texel read back of the canvas (gl.finish does not wait in every browser).
function finish(renderer) {
  renderer.setRenderTarget(null);
  const gl = renderer.getContext();
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
}

function rendererName(gl) {
  const info = gl.getExtension("WEBGL_debug_renderer_info");
  return info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
}

main().catch(fail);
