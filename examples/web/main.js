// snell in three.js: one of snell-lab's frames (a bundle written by `snell-lab --web-bundle DIR`) rendered
// with snell's two-interface refraction in WebGL 2, every refractive object of it as the lab draws them. In
// three.js render targets, `margin` texels wider than the canvas on every side (the lab's guard band, rendered
// through the bundle's bufferClipFromView, so exits just off screen are found):
//   1. the whole opaque scene (environment, then the paintings): colour, view-space normal, depth;
//   2. per object, its back faces (depth test GREATER after clearing depth to 0) and front faces: normal,
//      depth; and the min/max depth pyramid of its back faces (targets.js: WebGL 2 builds it level by level);
//   3. the frame: the opaque scene's colour, then the objects back to front (the bundle's drawOrder, by their
//      nearest points), each
//      a. over its scene layer: the opaque scene behind its nearest point (the paintings clipped there) and
//         the front faces of the objects drawn before it, coloured from the frame so far; and its pyramid;
//      b. its front faces through the technique's program (shaders/refract.frag, snell's single-file GLSL as
//         the ShaderChunk "snell"), depth-tested against the whole opaque scene, over the frame;
//   4. the canvas: the frame's viewport, encoded to sRGB (8 bits).
// Colour: every buffer and the frame hold linear RGB in float targets; only the canvas pass encodes.
// ?technique=<name> picks the technique; ?buffers=lab runs it on the lab's own buffers and front-face inputs
// (in the bundle: per object, its scene layer as the lab drew it) instead of the page's, which sets snell's
// code apart from the two rasterizers; ?test=1 renders once and posts the canvas to serve.mjs, which answers
// with the next check's query: the page loads it, or draws again itself when only ?fault= differs.
// A bundle of a glTF scene (bundle.asset: the asset, as snell-lab read it) can also be drawn with three.js's
// OWN renderer: ?renderer=threejs (or the page's renderer picker) loads bundle/asset.glb with GLTFLoader and
// renders it with MeshPhysicalMaterial transmission, set up as the lab's row "three.js (its renderer)"
// (gltf_scene.js, which that row uses too), into a float target that the canvas pass encodes;
// ?renderer=snell (the default) is snell's technique as above.
import * as THREE from "three";

import { bytes, floatTexture, labObjectBuffers, loadBundle, matrix, objectGeometry, paintingGeometry, text, vector } from "./bundle.js";
import { layerTarget, Pyramids, rawMaterial, setFilter } from "./targets.js";

let query = new URLSearchParams(location.search);
const testMode = query.has("test");
// A deliberately wrong page for the tests that show the checks can fail (serve.mjs --fault=ior): every IOR
// 0.2 % higher. A uniform, so a test's next check may change it without compiling anything again.
const faultIorScale = (q) => (testMode && q.get("fault") === "ior" ? 1.002 : 1);
let iorScale = faultIorScale(query);
const labBuffers = query.get("buffers") === "lab";
const drawWith = query.get("renderer") ?? "snell";
const statusLine = document.getElementById("status");

// Posts to serve.mjs, naming the check this page draws; serve.mjs's answer.
async function report(what, body) {
  if (!testMode) return "";
  return (await fetch(`/report/${what}?check=${query.get("check") ?? ""}`, { method: "POST", body })).text();
}

function fail(error) {
  const message = error && error.stack ? `${error.message}\n${error.stack}` : String(error);
  statusLine.textContent = `error: ${message}`;
  report("error", message);
}
window.addEventListener("error", (e) => fail(e.error ?? e.message));
window.addEventListener("unhandledrejection", (e) => fail(e.reason));

// The renderer picker, when the bundle carries a glTF asset: picking reloads the page with ?renderer=.
function rendererPicker(bundle) {
  if (!["snell", "threejs"].includes(drawWith))
    throw new Error(`?renderer=${drawWith}: snell (snell's technique) or threejs (three.js's own renderer)`);
  if (!bundle.asset) {
    if (drawWith === "threejs")
      throw new Error("?renderer=threejs: this bundle has no glTF asset (snell-lab writes one for a glTF scene)");
    return;
  }
  const picker = document.getElementById("draw-with");
  picker.add(new Option("snell's technique", "snell"));
  picker.add(new Option("three.js's own renderer (MeshPhysicalMaterial transmission)", "threejs"));
  picker.value = drawWith;
  picker.addEventListener("change", () => {
    query.set("renderer", picker.value);
    location.search = query.toString();
  });
  document.getElementById("draw-with-choice").hidden = false;
}

async function main() {
  const bundle = await loadBundle();
  rendererPicker(bundle);
  if (drawWith === "threejs") return threejsMain(bundle);
  THREE.ShaderChunk.snell = await text("snell/snell.glsl");
  THREE.ShaderChunk.srgb_encode = await text("shaders/srgb_encode.glsl");
  const src = {};
  for (const name of ["fullscreen.vert", "background.frag", "painting.vert", "painting.frag", "mesh.vert",
    "layer.frag", "drawn.frag", "pyramid.frag", "copy.frag", "present.frag", "refract.frag"])
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
  const clear = (target, depth, color = true) => {
    renderer.setRenderTarget(target);
    if (color) renderer.state.buffers.color.setMask(true);  // a colorWrite: false draw leaves the mask off
    renderer.state.buffers.depth.setClear(depth);
    renderer.clear(color, true, false);
  };
  const fullscreen = new THREE.BufferGeometry();
  fullscreen.setAttribute("position", new THREE.Float32BufferAttribute([-1, -1, 0, 3, -1, 0, -1, 3, 0], 3));
  const unculled = (geometry, material) => {
    const m = new THREE.Mesh(geometry, material);
    m.frustumCulled = false;
    return m;
  };
  const quad = (material) => unculled(fullscreen, material);
  const normalFilter = bundle.normalFilter === "linear" ? THREE.LinearFilter : THREE.NearestFilter;
  const sceneTarget = () => {
    const t = layerTarget(BW, BH, 2);
    setFilter(t.textures[0], THREE.LinearFilter);  // colour: bilinear, no mips
    setFilter(t.textures[1], normalFilter);
    return t;
  };
  const pyramids = new Pyramids(BW, BH, src, bundle, draw, quad);

  // The opaque scene: the environment, then the paintings (clipped nearer than clipNearerThan in a layer).
  const environment = await floatTexture(bundle.environment);
  const background = quad(rawMaterial(src["fullscreen.vert"], src["background.frag"], {
    environment: { value: environment },
    viewFromClip: { value: matrix(bundle.bufferViewFromClip) },
    envX: { value: vector(bundle.envX) },
    envY: { value: vector(bundle.envY) },
    envZ: { value: vector(bundle.envZ) },
    viewport: { value: new THREE.Vector2(BW, BH) },
  }, { depthTest: false, depthWrite: false }));
  const paintingClip = { value: 0 };
  const paintings = new THREE.Group();
  for (const p of bundle.paintings) {
    paintings.add(unculled(await paintingGeometry(p.mesh), rawMaterial(src["painting.vert"], src["painting.frag"], {
      painting: { value: await floatTexture(p) },
      viewFromWorld: { value: viewFromWorld },
      clipFromView: { value: bufferClipFromView },
      clipNearerThan: paintingClip,
    }, { side: THREE.DoubleSide, depthFunc: THREE.LessDepth })));
  }
  const drawOpaque = (target, clipNearerThan) => {
    paintingClip.value = clipNearerThan;
    clear(target, 1);
    draw(background, target);
    draw(paintings, target);
  };
  // The opaque scene's depth alone (the paintings, colour untouched), as the lab copies it before each
  // object's refraction pass.
  const drawOpaqueDepth = (target) => {
    paintingClip.value = 0;
    for (const m of paintings.children) m.material.colorWrite = false;
    clear(target, 1, false);
    draw(paintings, target);
    for (const m of paintings.children) m.material.colorWrite = true;
  };

  // The objects: each its mesh, constants, back and front faces and back-face pyramid; on the lab's buffers,
  // the lab's instead of the page's (the pyramids the page's own, from the lab's depth).
  const layerUniforms = { viewFromWorld: { value: viewFromWorld }, clipFromView: { value: bufferClipFromView } };
  const backMaterial = rawMaterial(src["mesh.vert"], src["layer.frag"], layerUniforms,
    { side: THREE.BackSide, depthFunc: THREE.GreaterDepth });
  const frontMaterial = rawMaterial(src["mesh.vert"], src["layer.frag"], layerUniforms,
    { side: THREE.FrontSide, depthFunc: THREE.LessDepth });
  const drawnUniforms = { ...layerUniforms, frame: { value: null }, clipNearerThan: { value: 0 } };
  const drawnMaterial = rawMaterial(src["mesh.vert"], src["drawn.frag"], drawnUniforms,
    { side: THREE.FrontSide, depthFunc: THREE.LessDepth });
  const objects = [];
  for (const [i, o] of bundle.objects.entries()) {
    const geometry = await objectGeometry(o.mesh);
    const object = {
      constants: o,
      geometry,
      drawn: unculled(geometry, drawnMaterial),
      clip: bundle.sceneLayer === "behind" ? o.objectNearDistance : 0,
      backPyramid: pyramids.target(),
    };
    if (labBuffers) {
      if (!o.labBuffers) throw new Error(`this bundle has no lab buffers of object ${i}: write it again with snell-lab --web-bundle`);
      object.lab = await labObjectBuffers(o.labBuffers, normalFilter);
      object.scenePyramid = pyramids.target();
    } else {
      object.back = layerTarget(BW, BH, 1);
      object.front = layerTarget(BW, BH, 1);
      setFilter(object.back.textures[0], normalFilter);
      setFilter(object.front.textures[0], normalFilter);
    }
    objects.push(object);
  }
  const order = bundle.drawOrder.map((o) => objects[o]);

  // The frame so far (linear colour, the whole opaque scene's depth), and the scene layer an object reads.
  const full = sceneTarget();
  const frame = layerTarget(BW, BH, 1);
  const layer = sceneTarget();
  const scenePyramid = pyramids.target();
  // On the lab's buffers the frame starts from the lab's opaque colour: the object pixels no pass shades
  // (silhouettes) then show the lab's texels, not the other rasterizer's.
  if (labBuffers && !bundle.labOpaqueColor) throw new Error("this bundle has no lab buffers: write it again with snell-lab --web-bundle");
  const opaqueColor = labBuffers ? await floatTexture(bundle.labOpaqueColor, THREE.NearestFilter) : full.texture;
  const copyToFrame = quad(rawMaterial(src["fullscreen.vert"], src["copy.frag"], { source: { value: opaqueColor } },
    { depthTest: false, depthWrite: false }));
  drawnUniforms.frame.value = frame.texture;
  // An object's scene layer (page's own buffers): the opaque scene behind its nearest point, then the front
  // faces of the objects drawn before it with the frame's colour, under the same clip plane; its pyramid.
  const drawLayer = (object, drawnBefore) => {
    drawOpaque(layer, object.clip);
    drawnUniforms.clipNearerThan.value = object.clip;
    for (const d of drawnBefore) draw(d.drawn, layer);
    pyramids.build(layer.depthTexture, 1, scenePyramid);
  };
  // What an object's pass reads.
  const buffersOf = (object) => object.lab ? { ...object.lab, scenePyramid: object.scenePyramid } : {
    sceneColor: layer.textures[0], sceneNormal: layer.textures[1], sceneDepth: layer.depthTexture, scenePyramid,
    backNormal: object.back.textures[0], backDepth: object.back.depthTexture,
    frontLayerNormal: object.front.textures[0], frontLayerDepth: object.front.depthTexture,
  };
  // The first object's layer holds no other object: it does not change from frame to frame.
  const layersChange = order.length > 1;

  const t0 = performance.now();
  drawOpaque(full, 0);
  for (const object of objects) {
    if (object.lab) {
      pyramids.build(object.lab.backDepth, 0, object.backPyramid);
      pyramids.build(object.lab.sceneDepth, 1, object.scenePyramid);
      continue;
    }
    clear(object.back, 0);
    draw(unculled(object.geometry, backMaterial), object.back);
    clear(object.front, 1);
    draw(unculled(object.geometry, frontMaterial), object.front);
    pyramids.build(object.back.depthTexture, 0, object.backPyramid);
  }
  if (!labBuffers && !layersChange) drawLayer(order[0], []);
  finish(renderer);
  const staticMs = performance.now() - t0;

  const present = quad(rawMaterial(src["fullscreen.vert"], src["present.frag"], {
    frame: { value: frame.texture },
    margin: { value: margin },
  }, { depthTest: false, depthWrite: false }));
  const u = (value) => ({ value });
  const techniqueUniforms = {
    viewFromWorld: u(viewFromWorld), clipFromView: u(matrix(bundle.clipFromView)),
    backDepth: u(null), backNormal: u(null), backPyramid: u(null),
    frontLayerDepth: u(null), frontLayerNormal: u(null),
    sceneDepth: u(null), sceneNormal: u(null), scenePyramid: u(null), sceneColor: u(null),
    frontPositions: u(null), frontNormals: u(null), margin: u(margin),
    environment: u(environment), bufferClipFromView: u(bufferClipFromView),
    zNear: u(bundle.zNear), zFar: u(bundle.zFar),
    envX: u(vector(bundle.envX)), envY: u(vector(bundle.envY)), envZ: u(vector(bundle.envZ)),
    depthFilter: u(bundle.depthFilter), reflectSource: u(bundle.reflectSource),
    ior: u(0), iors: u(new THREE.Vector3()), dispersion: u(0), absorption: u(new THREE.Vector3()), backRange: u(0),
    insideScene: u(0),
  };
  const setObjectUniforms = (object) => {
    const b = buffersOf(object);
    for (const name of ["backDepth", "backNormal", "frontLayerDepth", "frontLayerNormal", "sceneDepth", "sceneNormal",
      "scenePyramid", "sceneColor"]) techniqueUniforms[name].value = b[name];
    techniqueUniforms.backPyramid.value = object.backPyramid.texture;
    techniqueUniforms.frontPositions.value = b.frontPositions ?? null;
    techniqueUniforms.frontNormals.value = b.frontNormals ?? null;
    const c = object.constants;
    techniqueUniforms.ior.value = c.ior * iorScale;
    techniqueUniforms.iors.value = vector(c.iors).multiplyScalar(iorScale);
    techniqueUniforms.dispersion.value = c.dispersion;
    techniqueUniforms.absorption.value = vector(c.absorption);
    techniqueUniforms.backRange.value = c.backRange;
    techniqueUniforms.insideScene.value = c.insideScene;
  };
  // One program per technique, with only the strategies its slots call on any object (the bundle lists them
  // as the lab computes them with snellStrategiesUsed) and the perspective-only depth path (the lab's camera
  // is one); per object a mesh of it. On the lab's buffers: a full-screen pass over the lab's front-face
  // inputs instead of the mesh.
  const programs = new Map();
  const techniquePasses = (t) => {
    if (!programs.has(t.name)) {
      const defines = { PAGE_TECHNIQUE: t.id, SNELL_INTERSECT_STRATEGIES: t.strategies, SNELL_PERSPECTIVE_ONLY: 1 };
      const material = labBuffers
        ? rawMaterial(src["fullscreen.vert"], src["refract.frag"], techniqueUniforms,
          { depthTest: false, depthWrite: false, defines: { ...defines, PAGE_FRONT_FROM_TEXTURES: 1 } })
        : rawMaterial(src["mesh.vert"], src["refract.frag"], techniqueUniforms,
          { side: THREE.FrontSide, depthFunc: THREE.LessDepth, defines });
      programs.set(t.name, new Map(objects.map((o) => [o, labBuffers ? quad(material) : unculled(o.geometry, material)])));
    }
    return programs.get(t.name);
  };
  // The lab's refraction pass draws the viewport (clipFromView) into a target of its own; here it is the
  // frame's viewport part, so a pixel lands where the lab composites it.
  const drawTechnique = (pass) => {
    frame.viewport.set(margin, margin, W, H);
    pass.material.uniformsNeedUpdate = true;
    draw(pass, frame);
    frame.viewport.set(0, 0, BW, BH);
  };
  const renderFrame = (t) => {
    const passes = techniquePasses(t);
    draw(copyToFrame, frame);
    for (const [position, object] of order.entries()) {
      if (!labBuffers && layersChange) drawLayer(object, order.slice(0, position));
      if (!labBuffers) drawOpaqueDepth(frame);
      setObjectUniforms(object);
      drawTechnique(passes.get(object));
    }
    draw(present, null);
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
  // With several objects the lab's scene layers hold the frame as one row drew it.
  const labRowNote = labBuffers && objects.length > 1 ? ` (their scene layers as ${bundle.labBuffersRow} drew them)` : "";
  document.getElementById("scene").textContent = `${bundle.scene}, ${W}x${H}, ${objects.length} ` +
    `object${objects.length > 1 ? "s" : ""}, ${labBuffers ? "on the lab's buffers" + labRowNote : "the page's own buffers"}`;

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
  statusLine.textContent = `${current.label}: ` +
    timingsText(firstDrawMs, `first draw (compile) ${(firstDrawMs / 1000).toFixed(1)} s; static passes ${staticMs.toFixed(0)} ms`);
  if (testMode) return reportCanvas(renderer, canvas, W, H, { firstDrawMs, staticMs }, () => renderFrame(current));
  // The frame time: one frame (the opaque scene's colour, per object its scene layer when there are several,
  // and its refraction pass; the canvas pass), waited for, the median of the
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
    statusLine.textContent = `${current.label}: ` + timingsText(firstDrawMs, `${frameTimeText(times)}; ` +
      `first draw (compile) ${(firstDrawMs / 1000).toFixed(1)} s; static passes ${staticMs.toFixed(0)} ms`);
    requestAnimationFrame(loop);
  };
  requestAnimationFrame(loop);
}

// The median of the last frames' times.
function frameTimeText(times) {
  const median = [...times].sort((a, b) => a - b)[times.length >> 1];
  return `${median.toFixed(1)} ms per frame (median of ${times.length})`;
}

// The page's times, or why there are none: under a headless browser's virtual time (--virtual-time-budget)
// performance.now() stands still while the page draws, so the first draw, which compiles the shaders, reads
// 0 ms, and so would every frame.
function timingsText(firstDrawMs, text) {
  return firstDrawMs > 0 ? text : "times not measurable here (the page's clock stood still while it compiled " +
    "and drew: a headless browser's virtual time)";
}

// Test mode: the canvas (its screenshot and its pixels, row 0 at the bottom as the bundle's) and a log line,
// posted to serve.mjs. Its answer is the next check's query, or nothing after the last. A check that differs
// from this one only in its fault (or not at all) is drawn here again by redraw(), with the programs this
// page compiled, which on SwiftShader are most of a check's time; any other is a page load of its own.
async function reportCanvas(renderer, canvas, W, H, log, redraw) {
  const gl = renderer.getContext();
  const pixels = new Uint8Array(W * H * 4);
  renderer.setRenderTarget(null);
  gl.readPixels(0, 0, W, H, gl.RGBA, gl.UNSIGNED_BYTE, pixels);  // row 0 at the bottom, as the bundle's
  const png = await new Promise((resolve) => canvas.toBlob(resolve, "image/png"));
  await report("screenshot", png);
  await report("log", JSON.stringify({ renderer: rendererName(gl), subpixelBits: gl.getParameter(gl.SUBPIXEL_BITS), ...log }));
  const next = new URLSearchParams(await report("pixels", pixels));
  if (!next.has("test")) return;
  const page = (q) => {
    const p = new URLSearchParams(q);
    p.delete("check");
    p.delete("fault");
    p.sort();
    return p.toString();
  };
  if (page(next) !== page(query)) {
    location.search = next.toString();
    return;
  }
  query = next;
  history.replaceState(null, "", `?${next}`);
  iorScale = faultIorScale(query);
  const d0 = performance.now();
  redraw();
  return reportCanvas(renderer, canvas, W, H, { ...log, redrawMs: performance.now() - d0 }, redraw);
}

// The bundle's glTF asset with three.js's own renderer (?renderer=threejs): the scene as the lab's row
// "three.js (its renderer)" sets it up (gltf_scene.js: the opaque materials unlit, the lab's environment
// turned by the lab's rotation, the lab's camera, from the bundle's matrices), rendered into a float target
// of the frame's size, which the canvas pass encodes to sRGB as it does snell's frame.
async function threejsMain(bundle) {
  // Imported here: a page of snell's technique alone loads no GLTFLoader.
  const { cameraFromBundle } = await import("./bundle_camera.js");
  const { configureRenderer, gltfScene } = await import("./gltf_scene.js");
  THREE.ShaderChunk.srgb_encode = await text("shaders/srgb_encode.glsl");
  const vert = await text("shaders/fullscreen.vert"), frag = await text("shaders/present.frag");
  const W = bundle.width, H = bundle.height;
  const canvas = document.getElementById("frame");
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
  configureRenderer(renderer, W, H);
  const gl = renderer.getContext();
  document.getElementById("renderer").textContent = rendererName(gl);
  document.getElementById("technique-choice").hidden = true;
  document.getElementById("title").textContent = "three.js's own transmission, for comparison";

  const env = bundle.environment;
  if ((env.channels ?? 4) !== 4) throw new Error("bundle.json: the environment is not RGBA");
  // The camera as the lab passes it to three.js (position, target, up, field of view, clip distances; the
  // environment turned by its rotation about +Y), from the bundle's matrices.
  const { envX, envY, envZ, ...camera } = cameraFromBundle(bundle);
  camera.environmentRotationDegrees = bundle.asset.environmentRotationDegrees ?? 0;
  const t0 = performance.now();
  const s = await gltfScene({ glb: await bytes(`bundle/${bundle.asset.file}`),
    environment: { texels: await bytes(`bundle/${env.texels}`), width: env.width, height: env.height },
    camera, width: W, height: H, where: "bundle.json" });
  const staticMs = performance.now() - t0;
  const glass = s.glass.map((m) => `${m.name || "glass"} (ior ${m.ior}, thickness ${m.thickness})`).join(", ");
  document.getElementById("scene").textContent = `${bundle.scene}, ${W}x${H}, three.js's own renderer ` +
    `(GLTFLoader, MeshPhysicalMaterial transmission): ${glass}`;

  const fullscreen = new THREE.BufferGeometry();
  fullscreen.setAttribute("position", new THREE.Float32BufferAttribute([-1, -1, 0, 3, -1, 0, -1, 3, 0], 3));
  const present = new THREE.Mesh(fullscreen, rawMaterial(vert, frag, { frame: { value: s.target.texture },
    margin: { value: 0 } }, { depthTest: false, depthWrite: false }));
  present.frustumCulled = false;
  const renderFrame = () => {
    renderer.setRenderTarget(s.target);
    renderer.render(s.scene, s.camera);
    renderer.setRenderTarget(null);
    renderer.render(present, s.camera);
    finish(renderer);
  };
  statusLine.textContent = "three.js's own renderer: compiling ...";
  for (let i = 0; i < 2; ++i) await new Promise((resolve) => requestAnimationFrame(resolve));
  const c0 = performance.now();
  renderFrame();
  const firstDrawMs = performance.now() - c0;
  const timings = `first draw (compile, cube map, PMREM) ${(firstDrawMs / 1000).toFixed(1)} s; loading ${staticMs.toFixed(0)} ms`;
  statusLine.textContent = `three.js's own renderer: ${timingsText(firstDrawMs, timings)}`;
  if (testMode) return reportCanvas(renderer, canvas, W, H, { firstDrawMs, staticMs }, renderFrame);
  // The frame time, as for snell's technique: one frame (three.js's render, the canvas pass), waited for,
  // the median of the last 31.
  const times = [];
  const loop = () => {
    const f0 = performance.now();
    renderFrame();
    times.push(performance.now() - f0);
    if (times.length > 31) times.shift();
    statusLine.textContent = `three.js's own renderer: ${timingsText(firstDrawMs, `${frameTimeText(times)}; ${timings}`)}`;
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
