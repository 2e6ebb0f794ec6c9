// three.js's own render of a glTF asset, as a three.js user gets it: GLTFLoader, its
// MeshPhysicalMaterial with transmission for the glass, the renderer's transmission pass. Served by
// run_page.mjs with --three (threejs_render.mjs prepares the job); it posts the linear RGBA float image.
//
// Job files: job.json, asset.glb (the asset), tex_0.f32 (the environment: equirectangular RGBA float32,
// row 0 at the bottom = nadir, as snell-lab's web bundle writes environment.f32). job.json:
//   { "width": W, "height": H,
//     "environment": { "width": EW, "height": EH },
//     "camera": { "position": [x, y, z], "target": [x, y, z], "up": [x, y, z], "fovYDegrees": f,
//                 "near": n, "far": f,
//                 "envX": [..], "envY": [..], "envZ": [..]      (optional: the lab's view-to-environment axes)
//                 "environmentRotationDegrees": r }              (optional, when the axes are not given) }
//
// The scene set-up (the opaque materials made unlit, the environment and its rotation, the camera, the float
// target) is examples/web/gltf_scene.js's, which the three.js page (examples/web, ?renderer=threejs) shares;
// run_page.mjs serves it as /web/gltf_scene.js.
//
// Posts: /renderer (WebGL renderer string), /log (JSON: three.js revision, materials, timings), /results
// (W x H RGBA float32, row 0 at the bottom: the render target as WebGL reads it back), or /error.
import * as THREE from "three";

import { get, post } from "/browser/page_io.js";
import { configureRenderer, gltfScene } from "/web/gltf_scene.js";

const fail = (message) => post("/error", message);
window.addEventListener("error", (e) => fail(`page error: ${e.message}`));
window.addEventListener("unhandledrejection", (e) => fail(`page error: ${e.reason?.message ?? e.reason}`));

async function main() {
  const t0 = performance.now();
  const job = await (await get("job.json")).json();
  const W = job.width, H = job.height;
  if (!Number.isInteger(W) || !Number.isInteger(H) || W < 1 || H < 1) throw new Error("job.json: width/height");

  const canvas = document.createElement("canvas");
  canvas.width = W;
  canvas.height = H;
  const gl = canvas.getContext("webgl2", { antialias: false, alpha: true, depth: true, stencil: false,
    premultipliedAlpha: false, preserveDrawingBuffer: false, powerPreference: "high-performance" });
  if (!gl) throw new Error("no WebGL 2 context in this Chromium (it needs SwiftShader: --use-angle=swiftshader " +
    "--enable-unsafe-swiftshader, which tools/browser/chromium.mjs passes)");
  const debug = gl.getExtension("WEBGL_debug_renderer_info");
  const rendererName = debug ? gl.getParameter(debug.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER);
  await post("/renderer", `${rendererName} | three.js r${THREE.REVISION}`);
  if (!gl.getExtension("EXT_color_buffer_float"))
    throw new Error(`WebGL 2 without EXT_color_buffer_float (${rendererName}): cannot render into a float target`);
  if (!gl.getExtension("OES_texture_float_linear"))
    throw new Error(`WebGL 2 without OES_texture_float_linear (${rendererName}): cannot filter the float environment`);

  const renderer = new THREE.WebGLRenderer({ canvas, context: gl, antialias: false });
  configureRenderer(renderer, W, H);
  canvas.addEventListener("webglcontextlost", () => fail("the WebGL context was lost (SwiftShader out of memory?)"));

  const envBytes = await (await get("tex_0.f32")).arrayBuffer();
  const glb = await (await get("asset.glb")).arrayBuffer();
  const t1 = performance.now();
  const { scene, camera, target, glass, unlit, glassMeshes, opaqueMeshes, ms } = await gltfScene({ glb,
    environment: { texels: envBytes, width: job.environment?.width, height: job.environment?.height },
    camera: job.camera ?? {}, width: W, height: H, where: "job.json" });
  const t2 = t1 + ms.gltf;
  renderer.setRenderTarget(target);
  renderer.render(scene, camera);
  const pixels = new Float32Array(W * H * 4);
  renderer.readRenderTargetPixels(target, 0, 0, W, H, pixels);
  const t3 = performance.now();
  // A second frame: the cost once the programs, the cube map and the PMREM exist (not read back: a 1-texel read
  // waits for it).
  renderer.render(scene, camera);
  const one = new Float32Array(4);
  renderer.readRenderTargetPixels(target, 0, 0, 1, 1, one);
  const t4 = performance.now();
  const err = gl.getError();
  if (err !== gl.NO_ERROR) throw new Error(`WebGL error 0x${err.toString(16)} after the render`);
  let finite = true;
  for (let i = 0; i < pixels.length && finite; ++i) finite = Number.isFinite(pixels[i]);
  if (!finite) throw new Error("the render holds non-finite values");

  const info = {
    three: THREE.REVISION,
    renderer: rendererName,
    size: [W, H],
    glassMeshes,
    opaqueMeshes,
    materials: glass.map((m) => ({
      name: m.name, type: m.type, transmission: m.transmission, ior: m.ior, thickness: m.thickness,
      attenuationColor: m.attenuationColor.toArray(), attenuationDistance: m.attenuationDistance,
      roughness: m.roughness, metalness: m.metalness, dispersion: m.dispersion, side: m.side,
      color: m.color.toArray(), specularIntensity: m.specularIntensity, transparent: m.transparent })),
    unlit: unlit.map((m) => ({ name: m.name, color: m.color.toArray(), map: !!m.map })),
    backgroundRotation: scene.backgroundRotation.toArray().slice(0, 3),
    programs: renderer.info.programs?.length ?? null,
    ms: { fetch: t1 - t0, gltf: t2 - t1, firstFrame: t3 - t2, secondFrame: t4 - t3 },
  };
  await post("/log", JSON.stringify(info));
  await post("/results", pixels.buffer);
}

main().catch((e) => fail(e?.message ?? String(e)));
