// Serves the three.js page (examples/web) with one bundle of snell-lab (`snell-lab --web-bundle DIR`), on
// 127.0.0.1 only, from the source tree: the page, its shaders, three.js from node_modules (npm ci),
// snell's single-file GLSL (single_file/snell.glsl) and the bundle.
//
//   node examples/web/serve.mjs BUNDLE_DIR [--port=8080]
//       then open the printed address in a browser with WebGL 2
//   node examples/web/serve.mjs BUNDLE_DIR --test [--technique=plane-normal-2] [--buffers=page|lab]
//       [--renderer=snell|threejs] [--min-share=0.99] [--max-diff=255] [--fault=ior] [--screenshot=FILE]
//       [--report=FILE] [--chromium=PATH]
//
// --test opens the page in headless Chromium (SwiftShader), which renders the technique once and posts the
// canvas; the canvas is compared with the lab's picture of the same technique in the bundle, over the ray
// tracer's object pixels, both as 8-bit sRGB. It passes when at least --min-share of those pixels (99 % by
// default) are within 2/255 in every channel, and no pixel differs by more than --max-diff levels (255 by
// default: no bound). --fault=ior draws a deliberately wrong page (every IOR 0.2 % higher), for a test that
// shows the check can fail. --buffers=lab runs the technique on the lab's own buffers
// and front-face inputs (in the bundle) instead of the page's: what is left is snell's code in three.js
// against the lab's llvmpipe render, without the two rasterizers' differences (SwiftShader snaps vertices to
// 1/16 pixel, llvmpipe to 1/256). --renderer=threejs (a bundle of a glTF scene, with bundle.asset) draws the
// asset with three.js's own renderer instead (the page's ?renderer=threejs) and compares the canvas with the
// lab's render of it with three.js's own renderer (bundle.asset.labThreejsImage: the same three.js on the same
// SwiftShader), over the same object pixels. Exit status: 0 pass, 1 failure (a page error, no Chromium, no lab
// picture in the bundle, a timeout, or the agreement below --min-share), 2 usage.
import fs from "node:fs";
import http from "node:http";
import path from "node:path";
import { fileURLToPath } from "node:url";

import { launchChromium } from "../../tools/browser/chromium.mjs";

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, "..", "..");
const args = process.argv.slice(2);
let usageLater = "";
const option = (name, fallback) => {
  const a = args.find((x) => x.startsWith(`--${name}=`));
  return a ? a.slice(name.length + 3) : fallback;
};
const positional = args.filter((a) => !a.startsWith("--"));
const known = ["test", "technique", "buffers", "renderer", "min-share", "max-diff", "fault", "screenshot", "report",
  "chromium", "port"];
for (const a of args.filter((x) => x.startsWith("--")))
  if (!known.includes(a.slice(2).split("=")[0])) usageLater = `unknown option ${a}`;
const test = args.includes("--test");
const technique = option("technique", "plane-normal-2");
const buffers = option("buffers", "page");
const drawWith = option("renderer", "snell");
const chromium = option("chromium", "chromium");
const screenshot = option("screenshot", "");
const reportFile = option("report", "");
const port = Number(option("port", test ? "0" : "8080"));
const tolerance = 2;      // 8-bit sRGB levels, every channel
const targetShare = Number(option("min-share", "0.99"));  // of the object pixels
const maxDiffAllowed = Number(option("max-diff", "255"));  // 8-bit levels, any pixel
const fault = option("fault", "");
// SwiftShader compiles and draws a technique in 10-40 s on 2 cores; a page silent this long is stuck.
const timeoutMs = Number(process.env.SNELL_BROWSER_TIMEOUT_MS ?? 600000);

function usage(message) {
  console.error(`serve.mjs: ${message}\nusage: node examples/web/serve.mjs BUNDLE_DIR [--port=N] | ` +
    "BUNDLE_DIR --test [--technique=NAME] [--buffers=page|lab] [--renderer=snell|threejs] [--min-share=F] " +
    "[--max-diff=N] [--fault=ior] [--screenshot=FILE] [--report=FILE] " +
    "[--chromium=PATH]");
  process.exit(2);
}
if (usageLater) usage(usageLater);
if (positional.length !== 1) usage("give exactly one bundle directory (snell-lab --web-bundle DIR writes one)");
const bundleDir = path.resolve(positional[0]);
if (!fs.existsSync(path.join(bundleDir, "bundle.json")))
  usage(`no bundle.json in ${bundleDir} (write one with snell-lab SCENE --web-bundle ${positional[0]})`);
const three = path.join(here, "node_modules", "three", "build");
const addons = path.join(here, "node_modules", "three", "examples", "jsm");
if (!fs.existsSync(path.join(three, "three.module.js")) || !fs.existsSync(path.join(addons, "loaders", "GLTFLoader.js")))
  usage(`three.js is not installed in ${path.join(here, "node_modules")}: run npm ci --prefix examples/web ` +
    "(or scripts/install-deps.sh)");
if (!["page", "lab"].includes(buffers)) usage(`--buffers: page or lab, not ${buffers}`);
if (!["snell", "threejs"].includes(drawWith)) usage(`--renderer: snell or threejs, not ${drawWith}`);
if (drawWith === "threejs" && (option("buffers") || option("technique")))
  usage("--renderer=threejs draws with three.js's own renderer: --buffers and --technique are snell's");
if (!(targetShare >= 0 && targetShare <= 1)) usage(`--min-share: a share in [0, 1], not ${option("min-share")}`);
if (!(Number.isInteger(maxDiffAllowed) && maxDiffAllowed >= 0 && maxDiffAllowed <= 255))
  usage(`--max-diff: a whole number of 8-bit levels in [0, 255], not ${option("max-diff")}`);
if (!["", "ior"].includes(fault)) usage(`--fault: ior, not ${fault}`);
if (fault && drawWith === "threejs") usage("--fault=ior is a fault of snell's technique, not of three.js's renderer");
if (!Number.isInteger(port) || port < 0 || port > 65535) usage(`--port: not a port number: ${option("port")}`);

// Served files: a fixed map of names, so nothing outside these folders can be read.
const files = new Map([
  ["/", [path.join(here, "index.html"), "text/html"]],
  ["/main.js", [path.join(here, "main.js"), "text/javascript"]],
  ["/bundle.js", [path.join(here, "bundle.js"), "text/javascript"]],
  ["/targets.js", [path.join(here, "targets.js"), "text/javascript"]],
  ["/bundle_camera.js", [path.join(here, "bundle_camera.js"), "text/javascript"]],
  ["/gltf_scene.js", [path.join(here, "gltf_scene.js"), "text/javascript"]],
  ["/three/three.module.js", [path.join(three, "three.module.js"), "text/javascript"]],
  ["/three/three.core.js", [path.join(three, "three.core.js"), "text/javascript"]],
  // GLTFLoader and what it imports, for ?renderer=threejs (the import map's "three/addons/").
  ["/three/addons/loaders/GLTFLoader.js", [path.join(addons, "loaders", "GLTFLoader.js"), "text/javascript"]],
  ["/three/addons/utils/BufferGeometryUtils.js", [path.join(addons, "utils", "BufferGeometryUtils.js"), "text/javascript"]],
  ["/three/addons/utils/SkeletonUtils.js", [path.join(addons, "utils", "SkeletonUtils.js"), "text/javascript"]],
  ["/snell/snell.glsl", [path.join(root, "single_file", "snell.glsl"), "text/plain"]],
]);
for (const f of fs.readdirSync(path.join(here, "shaders")))
  files.set(`/shaders/${f}`, [path.join(here, "shaders", f), "text/plain"]);
for (const f of fs.readdirSync(bundleDir))
  files.set(`/bundle/${f}`, [path.join(bundleDir, f), f.endsWith(".json") ? "application/json" : "application/octet-stream"]);

let browser = null;
let finishing = false;
function finish(status, message) {
  if (finishing) return;
  finishing = true;
  if (message) (status === 0 ? console.log : console.error)(message);
  if (!browser) process.exit(status);
  browser.close().then(() => process.exit(status));
}

// Only a test's reports keep a request body, and none longer than the largest one the page posts (its
// canvas's pixels, RGBA8; an error message is shorter): any web page open in the same browser can post to
// a loopback port, and a body kept whole would hold its memory until the server exits.
const bundleSize = JSON.parse(fs.readFileSync(path.join(bundleDir, "bundle.json"), "utf8"));
const maxReportBytes = Math.max(1 << 20, 4 * (bundleSize.width | 0) * (bundleSize.height | 0));
const reports = {};
const server = http.createServer((req, res) => {
  const url = req.url.split("?")[0];
  const reporting = test && req.method === "POST" && url.startsWith("/report/");
  const body = [];
  let bodyBytes = 0;
  req.on("data", (d) => {
    if (!reporting) return;  // read and dropped
    bodyBytes += d.length;
    if (bodyBytes > maxReportBytes) {
      res.writeHead(413, { connection: "close" }).end();
      req.destroy();
      body.length = 0;
      return;
    }
    body.push(d);
  });
  req.on("end", () => {
    if (req.method === "GET" && files.has(url)) {
      const [file, type] = files.get(url);
      let data;
      try {
        data = fs.readFileSync(file);
      } catch (e) {
        res.writeHead(404).end();
        console.error(`serve.mjs: cannot read ${file}: ${e.message}`);
        return;
      }
      res.writeHead(200, { "content-type": type }).end(data);
    } else if (reporting) {
      const what = url.slice("/report/".length);
      res.end();
      reports[what] = Buffer.concat(body);
      if (what === "error") finish(1, `serve.mjs: the page failed: ${reports.error.toString()}`);
      else if (what === "pixels") compare();
    } else {
      res.writeHead(404).end();
    }
  });
});

// sRGB encoding of a linear value clamped to [0, 1], as the page's shaders/srgb_encode.glsl, then 8 bits.
function srgb8(v) {
  const c = Math.min(1, Math.max(0, v));
  const e = c < 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055;
  return Math.round(255 * e);
}

// The lab's picture the canvas is compared with: of the technique (snell's), or the lab's render with three.js's
// own renderer (--renderer=threejs); a message when the bundle lacks it.
function labPicture(bundle) {
  if (drawWith === "threejs") {
    if (!bundle.asset) return { missing: "the bundle has no glTF asset (snell-lab writes one for a glTF scene)" };
    if (!bundle.asset.labThreejsImage)
      return { missing: "the bundle has no lab render with three.js's own renderer (snell-lab skipped that row: " +
        "run it without --no-threejs, with Node.js, three.js and Chromium installed)" };
    return { image: bundle.asset.labThreejsImage };
  }
  const t = bundle.techniques.find((x) => x.name === technique);
  if (!t || !t.labImage) return { missing: `the bundle has no lab picture of ${technique} (run snell-lab with -t ${technique})` };
  return { image: t.labImage };
}

function compare() {
  const bundle = JSON.parse(fs.readFileSync(path.join(bundleDir, "bundle.json"), "utf8"));
  const picture = labPicture(bundle);
  if (picture.missing) return finish(1, `serve.mjs: ${picture.missing}`);
  const W = bundle.width, H = bundle.height;
  if (picture.image.width !== W || picture.image.height !== H || (picture.image.channels ?? 4) !== 4)
    return finish(1, `serve.mjs: the lab's picture ${picture.image.texels} is not ${W}x${H} RGBA`);
  const lab = new Float32Array(fs.readFileSync(path.join(bundleDir, picture.image.texels)).buffer.slice(0));
  const mask = fs.readFileSync(path.join(bundleDir, bundle.objectMask.bits));
  const page = reports.pixels;
  if (page.length !== W * H * 4 || lab.length !== W * H * 4 || mask.length !== W * H)
    return finish(1, `serve.mjs: sizes differ: page ${page.length} bytes, lab ${lab.length} floats, mask ${mask.length}`);
  let object = 0, within = 0, maxDiff = 0, sumDiff = 0;
  const histogram = new Array(256).fill(0);
  for (let i = 0; i < W * H; ++i) {
    if (!mask[i]) continue;
    ++object;
    let d = 0;
    for (let c = 0; c < 3; ++c) d = Math.max(d, Math.abs(page[4 * i + c] - srgb8(lab[4 * i + c])));
    ++histogram[d];
    if (d <= tolerance) ++within;
    maxDiff = Math.max(maxDiff, d);
    sumDiff += d;
  }
  const share = object ? within / object : 0;
  const log = reports.log ? JSON.parse(reports.log.toString()) : {};
  const result = {
    scene: bundle.scene, drawnWith: drawWith, ...(drawWith === "snell" ? { technique, buffers } : {}),
    objectPixels: object, tolerance, withinShare: share, target: targetShare,
    maxDiff, maxDiffAllowed, ...(fault ? { fault } : {}), meanMaxChannelDiff: object ? sumDiff / object : 0,
    diffHistogram: Object.fromEntries(histogram.map((n, d) => [d, n]).filter(([, n]) => n > 0)),
    renderer: log.renderer, subpixelBits: log.subpixelBits, firstDrawMs: log.firstDrawMs, staticPassesMs: log.staticMs,
  };
  if (reportFile) fs.writeFileSync(reportFile, JSON.stringify(result, null, 1) + "\n");
  if (screenshot && reports.screenshot) fs.writeFileSync(screenshot, reports.screenshot);
  const what = drawWith === "threejs" ? "three.js's own renderer"
    : `${technique}, ${buffers === "lab" ? "the lab's buffers" : "the page's buffers"}`;
  const line = `serve.mjs: ${bundle.scene}, ${what}: ${(100 * share).toFixed(2)} % of ${object} object pixels ` +
    `within ${tolerance}/255 of the lab's (at least ${100 * targetShare} % asked), largest difference ${maxDiff}/255 ` +
    `(at most ${maxDiffAllowed} asked)${fault ? `, with the fault ${fault}` : ""}; ` +
    `first draw ${(log.firstDrawMs / 1000).toFixed(1)} s on ${log.renderer}`;
  if (object === 0) finish(1, "serve.mjs: the bundle's object mask is empty: nothing to compare");
  else finish(share >= targetShare && maxDiff <= maxDiffAllowed ? 0 : 1, line);
}

server.on("error", (e) =>
  finish(1, e.code === "EADDRINUSE" ? `serve.mjs: port ${port} is in use; pick another with --port=N`
    : `serve.mjs: cannot serve on 127.0.0.1:${port}: ${e.message}`));
server.listen(port, "127.0.0.1", () => {
  const base = `http://127.0.0.1:${server.address().port}/`;
  if (!test) {
    const q = new URLSearchParams();
    if (option("technique")) q.set("technique", technique);
    if (option("buffers")) q.set("buffers", buffers);
    if (option("renderer")) q.set("renderer", drawWith);
    console.log(`serve.mjs: the page for ${bundleDir} at ${base}${q.size ? `?${q}` : ""} (Ctrl-C stops)`);
    return;
  }
  // With several objects each scene layer in the bundle holds the frame as one row of the lab drew it: the
  // page matches the lab's picture on those buffers with that row's technique only.
  const bundle = JSON.parse(fs.readFileSync(path.join(bundleDir, "bundle.json"), "utf8"));
  if (buffers === "lab" && (bundle.objects?.length ?? 0) > 1 && bundle.labBuffersRow !== technique)
    return finish(1, `serve.mjs: the bundle's lab buffers hold the scene layers ${bundle.labBuffersRow} drew, not ` +
      `${technique}'s: test ${bundle.labBuffersRow} on them, or write the bundle with -t ${technique}`);
  const picture = labPicture(bundle);
  if (picture.missing) return finish(1, `serve.mjs: ${picture.missing}`);
  const page = drawWith === "threejs" ? `${base}?test=1&renderer=threejs`
    : `${base}?test=1&buffers=${buffers}&technique=${encodeURIComponent(technique)}${fault ? `&fault=${fault}` : ""}`;
  browser = launchChromium(page,
    { chromium, onFailure: (message) => finish(1, `serve.mjs: ${message}`) });
  setTimeout(() => finish(1, `serve.mjs: no picture from the page after ${timeoutMs / 1000} s (SNELL_BROWSER_TIMEOUT_MS)`),
    timeoutMs).unref();
});
