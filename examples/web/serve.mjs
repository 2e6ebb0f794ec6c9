// Serves the three.js page (examples/web) with one bundle of snell-lab (`snell-lab --web-bundle DIR`), on
// 127.0.0.1 only, from the source tree: the page, its shaders, three.js from node_modules (npm ci),
// snell's single-file GLSL (single_file/snell.glsl) and the bundle.
//
//   node examples/web/serve.mjs BUNDLE_DIR [--port=8080]
//       then open the printed address in a browser with WebGL 2
//   node examples/web/serve.mjs BUNDLE_DIR --test CHECK [--then CHECK]... [--chromium=PATH]
//       a CHECK: [--technique=plane-normal-2] [--buffers=page|lab] [--renderer=snell|threejs]
//       [--min-share=0.99] [--max-diff=255] [--fault=ior] [--must-fail] [--screenshot=FILE] [--report=FILE]
//
// --test opens the page in headless Chromium (SwiftShader), which renders the technique once and posts the
// canvas; the canvas is compared with the lab's picture of the same technique in the bundle, over the ray
// tracer's object pixels, both as 8-bit sRGB. It passes when at least --min-share of those pixels (99 % by
// default) are within 2/255 in every channel, and no pixel differs by more than --max-diff levels (255 by
// default: no bound). --fault=ior draws a deliberately wrong page (every IOR 0.2 % higher), for a test that
// shows the check can fail: with --must-fail the check passes when its agreement falls short of what it
// asks, and fails when it does not (the check cannot fail). --buffers=lab runs the technique on the lab's
// own buffers and front-face inputs (in the bundle) instead of the page's: what is left is snell's code in
// three.js against the lab's llvmpipe render, without the two rasterizers' differences (SwiftShader snaps
// vertices to 1/16 pixel, llvmpipe to 1/256). --renderer=threejs (a bundle of a glTF scene, with
// bundle.asset) draws the asset with three.js's own renderer instead (the page's ?renderer=threejs) and
// compares the canvas with the lab's render of it with three.js's own renderer (bundle.asset.labThreejsImage:
// the same three.js on the same SwiftShader), over the same object pixels.
//
// --then starts another check, with options of its own (nothing carries over from the check before). The
// checks run one after the other in one Chromium, started once: each loads the page again, except a check
// that differs from the one before only in --fault, which the page draws again with the program that one
// compiled (the IOR is a uniform), without the compile that is most of a check's time on SwiftShader. Each
// check prints its line and writes its report and screenshot; a check whose agreement fails does not stop
// the ones after it. Every check's lab picture is looked up before Chromium starts. Exit status: 0 every check
// passes, 1 a failure (the agreement below what is asked, or a page error, no Chromium, no lab picture in
// the bundle, or a check's page silent for SNELL_BROWSER_TIMEOUT_MS: these end the run, naming the check),
// 2 usage. When Chromium itself crashes (a signal, or its GPU process), the check is drawn again in a new
// Chromium, once per run; a second crash ends the run.
import fs from "node:fs";
import http from "node:http";
import path from "node:path";
import { fileURLToPath } from "node:url";

import { launchChromium } from "../../tools/browser/chromium.mjs";
import { floatsOf } from "../../tools/browser/floats.mjs";

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, "..", "..");
// The arguments before the first --then, then each check's after it.
const groups = [[]];
for (const a of process.argv.slice(2)) {
  if (a === "--then") groups.push([]);
  else groups.at(-1).push(a);
}
const optionIn = (group, name, fallback) => {
  const a = group.find((x) => x.startsWith(`--${name}=`));
  return a ? a.slice(name.length + 3) : fallback;
};
const runOptions = ["test", "chromium", "port"];
const checkOptions = ["technique", "buffers", "renderer", "min-share", "max-diff", "fault", "must-fail", "screenshot",
  "report"];
let usageLater = "";
for (const [i, group] of groups.entries())
  for (const a of group.filter((x) => x.startsWith("--"))) {
    const name = a.slice(2).split("=")[0];
    if (i > 0 && runOptions.includes(name)) usageLater = `${a} is the run's, not a check's: give it before the first --then`;
    else if (!runOptions.includes(name) && !checkOptions.includes(name)) usageLater = `unknown option ${a}`;
  }
const positional = groups[0].filter((a) => !a.startsWith("--"));
const test = groups[0].includes("--test");
const chromium = optionIn(groups[0], "chromium", "chromium");
const port = Number(optionIn(groups[0], "port", test ? "0" : "8080"));
const tolerance = 2;      // 8-bit sRGB levels, every channel
// SwiftShader compiles and draws a technique in 10-40 s on 2 cores; a page silent this long is stuck.
const timeoutMs = Number(process.env.SNELL_BROWSER_TIMEOUT_MS ?? 600000);

function usage(message) {
  console.error(`serve.mjs: ${message}\nusage: node examples/web/serve.mjs BUNDLE_DIR [--port=N] | ` +
    "BUNDLE_DIR --test CHECK [--then CHECK]... [--chromium=PATH], a CHECK: [--technique=NAME] [--buffers=page|lab] " +
    "[--renderer=snell|threejs] [--min-share=F] [--max-diff=N] [--fault=ior] [--must-fail] [--screenshot=FILE] " +
    "[--report=FILE]");
  process.exit(2);
}
if (usageLater) usage(usageLater);
if (groups.length > 1 && !test) usage("--then starts another check of --test");
if (positional.length !== 1 || groups.slice(1).some((g) => g.some((a) => !a.startsWith("--"))))
  usage("give exactly one bundle directory (snell-lab --web-bundle DIR writes one), before the first --then");

// One check: what the page draws and how its canvas must agree with the lab's picture.
function parseCheck(group, n) {
  const option = (name, fallback) => optionIn(group, name, fallback);
  const c = {
    n, technique: option("technique", "plane-normal-2"), buffers: option("buffers", "page"),
    drawWith: option("renderer", "snell"),
    targetShare: Number(option("min-share", "0.99")),  // of the object pixels
    maxDiffAllowed: Number(option("max-diff", "255")),  // 8-bit levels, any pixel
    fault: option("fault", ""), mustFail: group.includes("--must-fail"),
    screenshot: option("screenshot", ""), reportFile: option("report", ""),
    // For the interactive page's address: only what was given.
    given: { technique: option("technique"), buffers: option("buffers"), renderer: option("renderer") },
  };
  const bad = (message) => usage(groups.length > 1 ? `check ${n}: ${message}` : message);
  if (!["page", "lab"].includes(c.buffers)) bad(`--buffers: page or lab, not ${c.buffers}`);
  if (!["snell", "threejs"].includes(c.drawWith)) bad(`--renderer: snell or threejs, not ${c.drawWith}`);
  if (c.drawWith === "threejs" && (c.given.buffers || c.given.technique))
    bad("--renderer=threejs draws with three.js's own renderer: --buffers and --technique are snell's");
  if (!(c.targetShare >= 0 && c.targetShare <= 1)) bad(`--min-share: a share in [0, 1], not ${option("min-share")}`);
  if (!(Number.isInteger(c.maxDiffAllowed) && c.maxDiffAllowed >= 0 && c.maxDiffAllowed <= 255))
    bad(`--max-diff: a whole number of 8-bit levels in [0, 255], not ${option("max-diff")}`);
  if (!["", "ior"].includes(c.fault)) bad(`--fault: ior, not ${c.fault}`);
  if (c.fault && c.drawWith === "threejs") bad("--fault=ior is a fault of snell's technique, not of three.js's renderer");
  if (group.some((a) => a.startsWith("--must-fail="))) bad("--must-fail takes no value");
  return c;
}
const checks = groups.map((group, i) => parseCheck(group, i + 1));
if (!Number.isInteger(port) || port < 0 || port > 65535) usage(`--port: not a port number: ${optionIn(groups[0], "port")}`);
const bundleDir = path.resolve(positional[0]);
if (!fs.existsSync(path.join(bundleDir, "bundle.json")))
  usage(`no bundle.json in ${bundleDir} (write one with snell-lab SCENE --web-bundle ${positional[0]})`);
const three = path.join(here, "node_modules", "three", "build");
const addons = path.join(here, "node_modules", "three", "examples", "jsm");
if (!fs.existsSync(path.join(three, "three.module.js")) || !fs.existsSync(path.join(addons, "loaders", "GLTFLoader.js")))
  usage(`three.js is not installed in ${path.join(here, "node_modules")}: run npm ci --prefix examples/web ` +
    "(or scripts/install-deps.sh)");

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
let relaunched = false;
let finishing = false;
function finish(status, message) {
  if (finishing) return;
  finishing = true;
  if (message) (status === 0 ? console.log : console.error)(message);
  if (!browser) process.exit(status);
  browser.close().then(() => process.exit(status));
}

// What a check draws, as its result line names it.
function drawnBy(c) {
  return c.drawWith === "threejs" ? "three.js's own renderer"
    : `${c.technique}, ${c.buffers === "lab" ? "the lab's buffers" : "the page's buffers"}`;
}
// A check as the messages name it; with one check, nothing (the messages read as before --then).
function checkName(c) {
  if (checks.length === 1) return "";
  return `check ${c.n} of ${checks.length} (${drawnBy(c)}${c.fault ? `, fault ${c.fault}` : ""}): `;
}
// A failure that ends the run: the checks after it are not run, and the message says so.
function abort(c, message) {
  const left = checks.length - c.n;
  finish(1, `serve.mjs: ${checkName(c)}${message}${left ? ` (${left} check${left > 1 ? "s" : ""} after it not run)` : ""}`);
}

// Only a test's reports keep a request body, and none longer than the largest one the page posts (its
// canvas's pixels, RGBA8; an error message is shorter): any web page open in the same browser can post to
// a loopback port, and a body kept whole would hold its memory until the server exits.
const bundle = JSON.parse(fs.readFileSync(path.join(bundleDir, "bundle.json"), "utf8"));
const maxReportBytes = Math.max(1 << 20, 4 * (bundle.width | 0) * (bundle.height | 0));
// The check the page draws now, its reports so far, and how many checks failed.
let current = checks[0];
let reports = {};
let failed = 0;
let timer = null;
const server = http.createServer((req, res) => {
  const [url, search] = req.url.split("?");
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
      // The page names the check it draws: an error names it too, and a report of another is dropped.
      const from = checks[Number(new URLSearchParams(search ?? "").get("check")) - 1] ?? current;
      if (what === "error") {
        res.end();
        return abort(from, `the page failed: ${Buffer.concat(body).toString()}`);
      }
      if (from !== current) return res.end();
      reports[what] = Buffer.concat(body);
      if (what !== "pixels") return res.end();
      // The answer to the pixels: the next check's page, which the page loads, or draws again itself when
      // only the fault differs (a uniform: the program it compiled serves it); nothing after the last.
      const status = compare(current);
      if (status === undefined) return res.end();  // the run is over
      failed += status;
      const next = checks[current.n];
      res.end(next ? pageQuery(next) : "");
      if (!next) return finish(failed ? 1 : 0, checks.length > 1 && failed
        ? `serve.mjs: ${failed} of ${checks.length} checks failed` : "");
      current = next;
      reports = {};
      timer.refresh();
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

// The lab's picture a check's canvas is compared with: of the technique (snell's), or the lab's render with
// three.js's own renderer (--renderer=threejs); a message when the bundle lacks it.
function labPicture(bundle, c) {
  if (c.drawWith === "threejs") {
    if (!bundle.asset) return { missing: "the bundle has no glTF asset (snell-lab writes one for a glTF scene)" };
    if (!bundle.asset.labThreejsImage)
      return { missing: "the bundle has no lab render with three.js's own renderer (snell-lab skipped that row: " +
        "run it without --no-threejs, with Node.js, three.js and Chromium installed)" };
    return { image: bundle.asset.labThreejsImage };
  }
  const t = bundle.techniques.find((x) => x.name === c.technique);
  if (!t || !t.labImage) return { missing: `the bundle has no lab picture of ${c.technique} (run snell-lab with -t ${c.technique})` };
  return { image: t.labImage };
}

// What the page is asked to draw for a check.
function pageQuery(c) {
  const q = new URLSearchParams({ test: 1, check: c.n });
  if (c.drawWith === "threejs") q.set("renderer", "threejs");
  else {
    q.set("buffers", c.buffers);
    q.set("technique", c.technique);
    if (c.fault) q.set("fault", c.fault);
  }
  return q.toString();
}

// Compares the check's canvas with the lab's picture, prints its line and writes its report and screenshot:
// its status (0 pass, 1 fail), or undefined when the run ended here.
function compare(c) {
  const picture = labPicture(bundle, c);
  if (picture.missing) return abort(c, picture.missing);
  const W = bundle.width, H = bundle.height;
  if (picture.image.width !== W || picture.image.height !== H || (picture.image.channels ?? 4) !== 4)
    return abort(c, `the lab's picture ${picture.image.texels} is not ${W}x${H} RGBA`);
  const lab = floatsOf(fs.readFileSync(path.join(bundleDir, picture.image.texels)));
  const mask = fs.readFileSync(path.join(bundleDir, bundle.objectMask.bits));
  const page = reports.pixels;
  if (page.length !== W * H * 4 || lab.length !== W * H * 4 || mask.length !== W * H)
    return abort(c, `sizes differ: page ${page.length} bytes, lab ${lab.length} floats, mask ${mask.length}`);
  let object = 0, within = 0, maxDiff = 0, sumDiff = 0;
  const histogram = new Array(256).fill(0);
  for (let i = 0; i < W * H; ++i) {
    if (!mask[i]) continue;
    ++object;
    let d = 0;
    for (let ch = 0; ch < 3; ++ch) d = Math.max(d, Math.abs(page[4 * i + ch] - srgb8(lab[4 * i + ch])));
    ++histogram[d];
    if (d <= tolerance) ++within;
    maxDiff = Math.max(maxDiff, d);
    sumDiff += d;
  }
  if (object === 0) return abort(c, "the bundle's object mask is empty: nothing to compare");
  const share = within / object;
  const log = reports.log ? JSON.parse(reports.log.toString()) : {};
  // A check the page drew again with the program an earlier check compiled: its draw, not that compile.
  const redrawn = log.redrawMs !== undefined;
  const result = {
    scene: bundle.scene, drawnWith: c.drawWith, ...(c.drawWith === "snell" ? { technique: c.technique, buffers: c.buffers } : {}),
    objectPixels: object, tolerance, withinShare: share, target: c.targetShare,
    maxDiff, maxDiffAllowed: c.maxDiffAllowed, ...(c.fault ? { fault: c.fault } : {}), meanMaxChannelDiff: sumDiff / object,
    diffHistogram: Object.fromEntries(histogram.map((n, d) => [d, n]).filter(([, n]) => n > 0)),
    renderer: log.renderer, subpixelBits: log.subpixelBits,
    ...(redrawn ? { redrawMs: log.redrawMs } : { firstDrawMs: log.firstDrawMs }), staticPassesMs: log.staticMs,
  };
  if (c.reportFile) fs.writeFileSync(c.reportFile, JSON.stringify(result, null, 1) + "\n");
  if (c.screenshot && reports.screenshot) fs.writeFileSync(c.screenshot, reports.screenshot);
  const agrees = share >= c.targetShare && maxDiff <= c.maxDiffAllowed;
  // --must-fail: a deliberately wrong page, which shows the check can fail.
  const status = agrees === c.mustFail ? 1 : 0;
  const verdict = !c.mustFail ? "" : agrees ? "; it passes, and it must fail (--must-fail): the check cannot fail"
    : "; it fails, as it must (--must-fail)";
  const draw = redrawn ? `drawn again in ${(log.redrawMs / 1000).toFixed(1)} s on ${log.renderer}, with the program ` +
    "the check before compiled" : `first draw ${(log.firstDrawMs / 1000).toFixed(1)} s on ${log.renderer}`;
  const line = `serve.mjs: ${bundle.scene}, ${drawnBy(c)}: ${(100 * share).toFixed(2)} % of ${object} object pixels ` +
    `within ${tolerance}/255 of the lab's (at least ${100 * c.targetShare} % asked), largest difference ${maxDiff}/255 ` +
    `(at most ${c.maxDiffAllowed} asked)${c.fault ? `, with the fault ${c.fault}` : ""}; ${draw}${verdict}`;
  (status === 0 ? console.log : console.error)(line);
  return status;
}

server.on("error", (e) =>
  finish(1, e.code === "EADDRINUSE" ? `serve.mjs: port ${port} is in use; pick another with --port=N`
    : `serve.mjs: cannot serve on 127.0.0.1:${port}: ${e.message}`));
server.listen(port, "127.0.0.1", () => {
  const base = `http://127.0.0.1:${server.address().port}/`;
  if (!test) {
    const q = new URLSearchParams();
    const given = checks[0].given;
    if (given.technique) q.set("technique", given.technique);
    if (given.buffers) q.set("buffers", given.buffers);
    if (given.renderer) q.set("renderer", given.renderer);
    console.log(`serve.mjs: the page for ${bundleDir} at ${base}${q.size ? `?${q}` : ""} (Ctrl-C stops)`);
    return;
  }
  // Every check's picture before Chromium starts: a run that would stop at a later check stops here.
  // With several objects each scene layer in the bundle holds the frame as one row of the lab drew it: the
  // page matches the lab's picture on those buffers with that row's technique only.
  for (const c of checks) {
    if (c.drawWith === "snell" && c.buffers === "lab" && (bundle.objects?.length ?? 0) > 1 && bundle.labBuffersRow !== c.technique)
      return finish(1, `serve.mjs: ${checkName(c)}the bundle's lab buffers hold the scene layers ${bundle.labBuffersRow} ` +
        `drew, not ${c.technique}'s: test ${bundle.labBuffersRow} on them, or write the bundle with -t ${c.technique}`);
    const picture = labPicture(bundle, c);
    if (picture.missing) return finish(1, `serve.mjs: ${checkName(c)}${picture.missing}`);
  }
  // One Chromium for every check: each starts it again otherwise (a few seconds), and a check that differs
  // from the one before only in its fault does not compile the technique again (most of a check's time).
  const launch = () => {
    browser = launchChromium(`${base}?${pageQuery(current)}`, { chromium, onFailure: (message, { crashed }) => {
      if (!crashed || relaunched || finishing) return abort(current, message);
      // Chromium itself crashed (seen once in CI, two seconds after start-up): the check is drawn again in
      // a new one, once per run. A crash that the page's own work causes happens again and ends the run.
      relaunched = true;
      console.error(`serve.mjs: ${checkName(current)}${message.split(/;|\n/)[0]}: drawing the check again in a new ` +
        "Chromium (once per run)");
      reports = {};
      timer.refresh();
      browser.close().then(() => { if (!finishing) launch(); });
    } });
  };
  launch();
  timer = setTimeout(() => abort(current, `no picture from the page after ${timeoutMs / 1000} s (SNELL_BROWSER_TIMEOUT_MS)`),
    timeoutMs).unref();
});
