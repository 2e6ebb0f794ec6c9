// Runs a parity job in headless Chromium: serves a page module and the job's
// files on 127.0.0.1, starts one Chromium on that page (or opens it as a tab of
// the Chromium named by SNELL_SHARED_CHROMIUM, see shared_chromium.mjs), and
// writes what the page posts back. The WebGL 2 runtime (tools/webgl/parity_page.js), the
// WebGPU smoke run in Chromium (tools/webgpu/chromium_page.js) and three.js's own render of a glTF
// asset (threejs_render.mjs) use it.
//
//   node run_page.mjs PAGE_JS JOB_DIR RESULTS_FILE [--webgpu] [--chromium=PATH] [--three=DIR]
//
// The page imports /browser/page_io.js (get, post) and may import /web/<name>.js (the three.js page's
// modules in examples/web, e.g. gltf_scene.js), fetches /job/<file>
// (job.json, shader.frag, shader.wgsl, inputs.f32, tex_<k>.f32, asset.glb) and posts /renderer (kept in
// renderer.txt), /log (timing.txt),
// /results (written to JOB_DIR/RESULTS_FILE) or /error: page_job.mjs, which page_server.mjs shares, the
// way under ctest to run every job in one page. --webgpu turns on
// Chromium's WebGPU on SwiftShader. --three=DIR serves the .js files of three.js's package folder
// (examples/web/node_modules/three) under /three/, with an import map for "three" and "three/addons/".
// Any failure (no Chromium, a page error, a crashed GPU process, a timeout) exits with status 1 and a
// message on stderr.
import fs from "node:fs";
import http from "node:http";
import path from "node:path";
import { fileURLToPath } from "node:url";

import { launchChromium } from "./chromium.mjs";
import { answerJobRequest, libFile } from "./page_job.mjs";
import { openSharedPage } from "./shared_chromium.mjs";

const args = process.argv.slice(2);
const webgpu = args.includes("--webgpu");
const chromium = (args.find((a) => a.startsWith("--chromium=")) ?? "--chromium=chromium").slice("--chromium=".length);
const [pageJs, dir, resultsFile] = args.filter((a) => !a.startsWith("--"));
const threeDir = (args.find((a) => a.startsWith("--three=")) ?? "--three=").slice("--three=".length);
// The state folder of a Chromium started once for the whole test run (shared_chromium.mjs): the page
// opens there as a tab. WebGPU pages keep a browser of their own (they need its WebGPU flags).
const shared = webgpu ? "" : process.env.SNELL_SHARED_CHROMIUM ?? "";
// SwiftShader compiles a whole technique in tens of seconds; a page that says nothing for this long is stuck.
const timeoutMs = Number(process.env.SNELL_BROWSER_TIMEOUT_MS ?? 600000);

// A promise of the browser (or tab) showing the page, once there is one.
let browser = null;
let finishing = false;
function finish(status, message) {
  if (finishing) return;
  finishing = true;
  if (message) console.error(`run_page.mjs: ${message}`);
  if (!browser) process.exit(status);
  browser.then((b) => b.close(), () => {}).then(() => process.exit(status));
}
if (!pageJs || !dir || !resultsFile) finish(1, "usage: run_page.mjs PAGE_JS JOB_DIR RESULTS_FILE [--webgpu] [--chromium=PATH] [--three=DIR]");
if (!fs.existsSync(pageJs)) finish(1, `no page module ${pageJs}`);
if (!fs.existsSync(path.join(dir, "job.json"))) finish(1, `no job.json in ${dir}`);
const threeRoot = threeDir ? path.resolve(threeDir) : "";
if (threeRoot && !fs.existsSync(path.join(threeRoot, "build", "three.module.js")))
  finish(1, `--three=${threeDir}: no build/three.module.js there (npm ci --prefix examples/web installs three.js)`);

const importMap = threeRoot
  ? '<script type="importmap">{ "imports": { "three": "/three/build/three.module.js", "three/addons/": "/three/examples/jsm/" } }</script>'
  : "";
const page = `<!doctype html><meta charset="utf-8"><title>snell parity</title>${importMap}<script type="module" src="/page.js"></script>`;
// A .js file of three.js's package under /three/ (--three), never outside that folder.
const threeFile = (url) => {
  if (!threeRoot || !url.startsWith("/three/")) return "";
  try {
    const file = path.resolve(threeRoot, "." + decodeURIComponent(url.slice("/three".length)));
    return file.startsWith(threeRoot + path.sep) && file.endsWith(".js") && fs.statSync(file).isFile() ? file : "";
  } catch {
    return "";  // a malformed or missing name
  }
};
// Modules the page imports, next to it: /lib/<name>.js (page_job.mjs's libFile); and the three.js page's
// modules it shares (examples/web, e.g. gltf_scene.js): /web/<name>.js.
const webFiles = /^\/web\/(\w+\.js)$/;
const webDir = path.join(path.dirname(fileURLToPath(import.meta.url)), "..", "..", "examples", "web");
const server = http.createServer((req, res) => {
  const body = [];
  req.on("data", (d) => body.push(d));
  req.on("end", () => {
    const data = Buffer.concat(body);
    let m;
    if (req.method === "GET" && req.url === "/") {
      res.writeHead(200, { "content-type": "text/html" }).end(page);
    } else if (req.method === "GET" && req.url === "/page.js") {
      res.writeHead(200, { "content-type": "text/javascript" }).end(fs.readFileSync(pageJs));
    } else if (req.method === "GET" && (m = libFile(path.dirname(pageJs), req.url))) {
      res.writeHead(200, { "content-type": "text/javascript" }).end(fs.readFileSync(m));
    } else if (req.method === "GET" && (m = webFiles.exec(req.url)) && fs.existsSync(path.join(webDir, m[1]))) {
      res.writeHead(200, { "content-type": "text/javascript" }).end(fs.readFileSync(path.join(webDir, m[1])));
    } else if (req.method === "GET" && (m = threeFile(req.url))) {
      res.writeHead(200, { "content-type": "text/javascript" }).end(fs.readFileSync(m));
    } else if (req.method === "GET" && req.url === "/browser/page_io.js") {
      res.writeHead(200, { "content-type": "text/javascript" }).end(fs.readFileSync(new URL("page_io.js", import.meta.url)));
    } else if ((m = answerJobRequest(req, req.url, data, res, dir, resultsFile))) {
      if (m.done) {
        server.close();
        finish(0);
      } else if (m.error !== undefined) {
        finish(1, m.error);
      }
    } else {
      res.writeHead(404).end();
    }
  });
});

server.listen(0, "127.0.0.1", () => {
  const url = `http://127.0.0.1:${server.address().port}/`;
  const onFailure = (message) => finish(1, message);
  browser = shared ? openSharedPage(shared, url, onFailure) : Promise.resolve(launchChromium(url, { chromium, webgpu, onFailure }));
  browser.catch((e) => finish(1, e.message));
});
setTimeout(() => finish(1, `no results after ${timeoutMs / 1000} s (SNELL_BROWSER_TIMEOUT_MS)`), timeoutMs).unref();
