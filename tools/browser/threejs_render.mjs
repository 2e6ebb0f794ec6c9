// Renders a glTF asset with three.js's own renderer (GLTFLoader, MeshPhysicalMaterial transmission) in
// headless Chromium (SwiftShader, WebGL 2) and writes the linear RGBA float image: the lab's row
// "three.js (its renderer)". The page is threejs_render_page.js, run by run_page.mjs; three.js comes
// from examples/web/node_modules (npm ci --prefix examples/web).
//
//   node tools/browser/threejs_render.mjs --gltf FILE.glb --environment ENV.f32 --env-size WxH
//        --camera CAMERA.json --size WxH --out OUT.f32 [--info INFO.json] [--chromium=PATH] [--quiet]
//   node tools/browser/threejs_render.mjs --gltf FILE.glb --bundle BUNDLE_DIR --out OUT.f32 [...]
//
// Options take "--name value" or "--name=value".
//   --gltf        the asset: a .glb, or a .gltf whose buffers and images are data: URIs
//   --environment the environment, equirectangular RGBA float32 little-endian, row 0 at the bottom
//                 (the nadir), longitude u = atan2(d.x, -d.z) / 2pi + 0.5: the lab's Environment image,
//                 intensity applied (snell-lab --web-bundle writes it as environment.f32)
//   --env-size    its width x height in texels
//   --camera      JSON: position, target, up (3 numbers each, world space), fovYDegrees (vertical), near,
//                 far; and either envX, envY, envZ (the lab's LabParams axes: a view-space direction d
//                 looks the environment up along d.x envX + d.y envY + d.z envZ; bundle.json has them)
//                 or environmentRotationDegrees (the lab's Environment rotation about +Y; default 0)
//   --size        the render's width x height in pixels (the aspect ratio is W / H)
//   --bundle      instead of --environment/--env-size/--camera/--size: a snell-lab --web-bundle folder,
//                 whose camera (viewFromWorld, clipFromView, zNear, zFar, envX/Y/Z), size and
//                 environment.f32 are used
//   --out         where the image goes: W x H RGBA float32 little-endian, row 0 at the bottom, linear RGB
//                 (no tone mapping, no sRGB encoding; the alpha is what three.js wrote)
//   --info        also write what the page reports (JSON): three.js's revision, the WebGL renderer, the
//                 glass materials as GLTFLoader made them, the timings
//   --chromium    the Chromium to run (default: chromium on the PATH). SNELL_SHARED_CHROMIUM opens the page
//                 in the suite's shared Chromium instead (see shared_chromium.mjs).
//
// Exit status: 0 written; 1 failure (a missing or malformed file, no three.js, no Chromium, no WebGL 2 or
// float render targets, a page error, a timeout), with a message naming the cause on stderr; 2 usage.
import { spawn } from "node:child_process";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import { fileURLToPath } from "node:url";

import { cameraFromBundle } from "../../examples/web/bundle_camera.js";

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, "..", "..");
const threeDir = path.join(root, "examples", "web", "node_modules", "three");
const known = ["gltf", "environment", "env-size", "camera", "size", "bundle", "out", "info", "chromium", "quiet", "help"];
const flags = ["quiet", "help"];

const usageText = "usage: node tools/browser/threejs_render.mjs --gltf FILE.glb (--environment ENV.f32 --env-size WxH " +
  "--camera CAMERA.json --size WxH | --bundle BUNDLE_DIR) --out OUT.f32 [--info INFO.json] [--chromium=PATH] [--quiet]";
function usage(message) {
  console.error(`threejs_render.mjs: ${message}\n${usageText}`);
  process.exit(2);
}
function fail(message) {
  console.error(`threejs_render.mjs: ${message}`);
  process.exit(1);
}

// --name value, --name=value; flags take no value.
function parseArgs(argv) {
  const o = {};
  for (let i = 0; i < argv.length; ++i) {
    const a = argv[i];
    if (!a.startsWith("--")) usage(`unexpected argument ${a}`);
    const eq = a.indexOf("=");
    const name = a.slice(2, eq < 0 ? undefined : eq);
    if (!known.includes(name)) usage(`unknown option --${name}`);
    if (name in o) usage(`--${name} given twice`);
    if (flags.includes(name)) {
      if (eq >= 0) usage(`--${name} takes no value`);
      o[name] = true;
    } else if (eq >= 0) {
      o[name] = a.slice(eq + 1);
    } else {
      if (i + 1 >= argv.length) usage(`--${name} needs a value`);
      o[name] = argv[++i];
    }
  }
  return o;
}

function size(text, what) {
  const m = /^(\d+)x(\d+)$/.exec(text ?? "");
  if (!m) usage(`${what}: WxH, e.g. 512x512, not ${text}`);
  const w = Number(m[1]), h = Number(m[2]);
  if (!(w >= 1 && h >= 1 && w <= 8192 && h <= 8192)) usage(`${what}: each side in [1, 8192], not ${text}`);
  return [w, h];
}

function readJson(file, what) {
  let text;
  try {
    text = fs.readFileSync(file, "utf8");
  } catch (e) {
    fail(`cannot read ${what} ${file}: ${e.code === "ENOENT" ? "no such file" : e.message}`);
  }
  try {
    return JSON.parse(text);
  } catch (e) {
    fail(`${what} ${file} is not JSON: ${e.message}`);
  }
}

function mustExist(file, what) {
  let st;
  try {
    st = fs.statSync(file);
  } catch (e) {
    fail(`${what} ${file}: ${e.code === "ENOENT" ? "no such file" : e.message}`);
  }
  if (!st.isFile()) fail(`${what} ${file} is not a file`);
  return st.size;
}

const vec3ok = (v) => Array.isArray(v) && v.length === 3 && v.every(Number.isFinite);

function checkCamera(c, file) {
  if (typeof c !== "object" || c === null) fail(`${file}: not a JSON object`);
  for (const k of ["position", "target", "up"]) if (!vec3ok(c[k])) fail(`${file}: ${k} must be 3 finite numbers`);
  for (const k of ["fovYDegrees", "near", "far"]) if (!Number.isFinite(c[k])) fail(`${file}: ${k} must be a number`);
  if (!(c.fovYDegrees > 0 && c.fovYDegrees < 180)) fail(`${file}: fovYDegrees must be in (0, 180)`);
  if (!(c.near > 0 && c.far > c.near)) fail(`${file}: need 0 < near < far`);
  const d = c.target.map((t, i) => t - c.position[i]);
  const cross = [d[1] * c.up[2] - d[2] * c.up[1], d[2] * c.up[0] - d[0] * c.up[2], d[0] * c.up[1] - d[1] * c.up[0]];
  if (!(Math.hypot(...cross) > 1e-9 * Math.hypot(...d) * Math.hypot(...c.up)))
    fail(`${file}: target - position and up must be non-zero and not parallel`);
  const axes = ["envX", "envY", "envZ"].filter((k) => c[k] !== undefined);
  if (axes.length !== 0 && axes.length !== 3) fail(`${file}: give all of envX, envY, envZ or none`);
  for (const k of axes) if (!vec3ok(c[k])) fail(`${file}: ${k} must be 3 finite numbers`);
  if (c.environmentRotationDegrees !== undefined && !Number.isFinite(c.environmentRotationDegrees))
    fail(`${file}: environmentRotationDegrees must be a number`);
}

// A snell-lab web bundle's camera, as CAMERA.json has it (shared with the three.js page, which renders the
// bundle's asset the same way).
export { cameraFromBundle };

// A .gltf must carry everything inside (the page serves the one file).
function checkAsset(file) {
  const bytes = fs.readFileSync(file);
  if (bytes.length >= 12 && bytes.toString("latin1", 0, 4) === "glTF") return;
  let j;
  try {
    j = JSON.parse(bytes.toString("utf8"));
  } catch {
    fail(`${file} is neither a .glb (no "glTF" magic) nor glTF JSON`);
  }
  for (const kind of ["buffers", "images"])
    for (const [i, x] of (j[kind] ?? []).entries())
      if (x.uri !== undefined && !String(x.uri).startsWith("data:"))
        fail(`${file}: ${kind}[${i}] refers to the external file "${x.uri}"; only self-contained assets are ` +
          "rendered (pack it as .glb, e.g. gltf-transform copy in.gltf out.glb)");
}

function main() {
  const o = parseArgs(process.argv.slice(2));
  if (o.help) {
    console.log(usageText);
    process.exit(0);
  }
  if (!o.gltf) usage("--gltf is required");
  if (!o.out) usage("--out is required");
  if (o.bundle && (o.environment || o["env-size"] || o.camera || o.size))
    usage("--bundle replaces --environment, --env-size, --camera and --size: give one or the other");
  if (!o.bundle) for (const k of ["environment", "env-size", "camera", "size"]) if (!o[k]) usage(`--${k} is required (or --bundle)`);

  mustExist(o.gltf, "glTF asset");
  checkAsset(o.gltf);
  if (!fs.existsSync(path.join(threeDir, "build", "three.module.js")) ||
      !fs.existsSync(path.join(threeDir, "examples", "jsm", "loaders", "GLTFLoader.js")))
    fail(`three.js is not installed in ${path.dirname(threeDir)}: run npm ci --prefix examples/web`);

  let camera, W, H, envW, envH, envFile;
  if (o.bundle) {
    const b = readJson(path.join(o.bundle, "bundle.json"), "web bundle");
    try {
      camera = cameraFromBundle(b);
    } catch (e) {
      fail(`${o.bundle}/bundle.json: ${e.message}`);
    }
    [W, H] = [b.width, b.height];
    envW = b.environment?.width;
    envH = b.environment?.height;
    envFile = path.join(o.bundle, b.environment?.texels ?? "environment.f32");
    if ((b.environment?.channels ?? 4) !== 4) fail(`${o.bundle}/bundle.json: the environment is not RGBA`);
    checkCamera(camera, `${o.bundle}/bundle.json`);
  } else {
    camera = readJson(o.camera, "camera file");
    checkCamera(camera, o.camera);
    [W, H] = size(o.size, "--size");
    [envW, envH] = size(o["env-size"], "--env-size");
    envFile = o.environment;
  }
  const envBytes = mustExist(envFile, "environment");
  if (envBytes !== envW * envH * 16)
    fail(`environment ${envFile} has ${envBytes} bytes; ${envW}x${envH} RGBA float32 texels are ${envW * envH * 16}`);
  const outDir = path.dirname(path.resolve(o.out));
  if (!fs.existsSync(outDir)) fail(`cannot write ${o.out}: no folder ${outDir}`);

  // The job folder run_page.mjs serves: job.json, asset.glb, tex_0.f32 (links to the files).
  const job = fs.mkdtempSync(path.join(os.tmpdir(), "snell-threejs-"));
  const cleanup = () => fs.rmSync(job, { recursive: true, force: true });
  const link = (from, name) => {
    try {
      fs.symlinkSync(path.resolve(from), path.join(job, name));
    } catch {
      fs.copyFileSync(from, path.join(job, name));
    }
  };
  link(o.gltf, "asset.glb");
  link(envFile, "tex_0.f32");
  fs.writeFileSync(path.join(job, "job.json"),
    JSON.stringify({ width: W, height: H, environment: { width: envW, height: envH }, camera }, null, 1));

  const args = [path.join(here, "run_page.mjs"), path.join(here, "threejs_render_page.js"), job, "image.f32",
    `--three=${threeDir}`];
  if (o.chromium) args.push(`--chromium=${o.chromium}`);
  const start = Date.now();
  const child = spawn(process.execPath, args, { stdio: ["ignore", "inherit", "pipe"] });
  let stderr = "";
  child.stderr.on("data", (d) => (stderr += d));
  const onSignal = (s) => {
    child.kill(s);
  };
  process.on("SIGINT", onSignal);
  process.on("SIGTERM", onSignal);
  child.on("close", (code) => {
    const seconds = (Date.now() - start) / 1000;
    if (code !== 0) {
      cleanup();
      fail(`three.js's render of ${o.gltf} failed: ${stderr.trim().replace(/^run_page\.mjs: /, "") || `run_page.mjs exited ${code}`}`);
    }
    const image = path.join(job, "image.f32");
    const bytes = fs.existsSync(image) ? fs.statSync(image).size : -1;
    if (bytes !== W * H * 16) {
      cleanup();
      fail(`the page posted ${bytes} bytes, not ${W}x${H} RGBA float32`);
    }
    let info = {};
    try {
      info = JSON.parse(fs.readFileSync(path.join(job, "timing.txt"), "utf8"));
    } catch {
      // the page posts it before the pixels; without it the image is still good
    }
    info.seconds = seconds;
    fs.copyFileSync(image, o.out);
    if (o.info) fs.writeFileSync(o.info, JSON.stringify(info, null, 1) + "\n");
    cleanup();
    if (!o.quiet) {
      const glass = (info.materials ?? []).map((m) => `${m.name} (ior ${m.ior}, thickness ${m.thickness})`).join(", ");
      console.error(`threejs_render.mjs: ${o.out}: ${W}x${H}, three.js r${info.three} on ${info.renderer}, ` +
        `${seconds.toFixed(1)} s (first frame ${Math.round(info.ms?.firstFrame ?? NaN)} ms, next ` +
        `${Math.round(info.ms?.secondFrame ?? NaN)} ms); glass: ${glass}`);
    }
    process.exit(0);
  });
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) main();
