// Runs a parity job in headless Chromium: serves a page module and the job's
// files on 127.0.0.1, starts one Chromium on that page, and writes what the
// page posts back. The WebGL 2 runtime (tools/webgl/parity_page.js) and the
// WebGPU smoke run in Chromium (tools/webgpu/chromium_page.js) use it.
//
//   node run_page.mjs PAGE_JS JOB_DIR RESULTS_FILE [--webgpu] [--chromium=PATH]
//
// The page imports /browser/page_io.js (get, post), fetches /job/<file>
// (job.json, shader.frag, shader.wgsl, inputs.f32, tex_<k>.f32) and posts /renderer (kept in renderer.txt), /log (timing.txt),
// /results (written to JOB_DIR/RESULTS_FILE) or /error. --webgpu turns on
// Chromium's WebGPU on SwiftShader. Any failure (no Chromium, a page error, a
// crashed GPU process, a timeout) exits with status 1 and a message on stderr.
import { spawn } from "node:child_process";
import fs from "node:fs";
import http from "node:http";
import os from "node:os";
import path from "node:path";

const args = process.argv.slice(2);
const webgpu = args.includes("--webgpu");
const chromium = (args.find((a) => a.startsWith("--chromium=")) ?? "--chromium=chromium").slice("--chromium=".length);
const [pageJs, dir, resultsFile] = args.filter((a) => !a.startsWith("--"));
// SwiftShader compiles a whole technique in tens of seconds; a page that says nothing for this long is stuck.
const timeoutMs = Number(process.env.SNELL_BROWSER_TIMEOUT_MS ?? 600000);

let browser = null;
let profile = null;
let finishing = false;
// Chromium is killed and waited for before its profile folder is removed (its helper processes
// still write there while they go down).
function finish(status, message) {
  if (finishing) return;
  finishing = true;
  if (message) console.error(`run_page.mjs: ${message}`);
  const done = () => {
    try {
      if (profile) fs.rmSync(profile, { recursive: true, force: true, maxRetries: 10, retryDelay: 100 });
    } catch (e) {
      console.error(`run_page.mjs: cannot remove ${profile}: ${e.message}`);
    }
    process.exit(status);
  };
  if (browser) {
    // The whole process group: Chromium's GPU and renderer processes outlive a killed browser process.
    try {
      process.kill(-browser.pid, "SIGKILL");
    } catch {
      // already gone
    }
  }
  if (browser && browser.exitCode === null && browser.signalCode === null) browser.once("exit", () => setTimeout(done, 50));
  else done();
}
if (!pageJs || !dir || !resultsFile) finish(1, "usage: run_page.mjs PAGE_JS JOB_DIR RESULTS_FILE [--webgpu] [--chromium=PATH]");
if (!fs.existsSync(pageJs)) finish(1, `no page module ${pageJs}`);
if (!fs.existsSync(path.join(dir, "job.json"))) finish(1, `no job.json in ${dir}`);

const page = '<!doctype html><meta charset="utf-8"><title>snell parity</title><script type="module" src="/page.js"></script>';
const jobFiles = /^\/job\/(job\.json|shader\.frag|shader\.wgsl|inputs\.f32|tex_\d+\.f32)$/;
// Modules the page imports, next to it: /lib/<name>.js.
const libFiles = /^\/lib\/(\w+\.js)$/;
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
    } else if (req.method === "GET" && (m = libFiles.exec(req.url)) && fs.existsSync(path.join(path.dirname(pageJs), m[1]))) {
      res.writeHead(200, { "content-type": "text/javascript" }).end(fs.readFileSync(path.join(path.dirname(pageJs), m[1])));
    } else if (req.method === "GET" && req.url === "/browser/page_io.js") {
      res.writeHead(200, { "content-type": "text/javascript" }).end(fs.readFileSync(new URL("page_io.js", import.meta.url)));
    } else if (req.method === "GET" && (m = jobFiles.exec(req.url))) {
      res.writeHead(200, { "content-type": "application/octet-stream" }).end(fs.readFileSync(path.join(dir, m[1])));
    } else if (req.method === "POST" && req.url === "/renderer") {
      fs.writeFileSync(path.join(dir, "renderer.txt"), data.toString() + "\n");
      res.end();
    } else if (req.method === "POST" && req.url === "/log") {
      fs.writeFileSync(path.join(dir, "timing.txt"), data.toString() + "\n");
      res.end();
    } else if (req.method === "POST" && req.url === "/results") {
      fs.writeFileSync(path.join(dir, resultsFile), data);
      res.end();
      server.close();
      finish(0);
    } else if (req.method === "POST" && req.url === "/error") {
      res.end();
      finish(1, data.toString());
    } else {
      res.writeHead(404).end();
    }
  });
});

server.listen(0, "127.0.0.1", () => {
  const url = `http://127.0.0.1:${server.address().port}/`;
  profile = fs.mkdtempSync(path.join(os.tmpdir(), "snell-chromium-"));
  // SwiftShader: WebGL 2 (through ANGLE) and WebGPU (through Dawn) with no GPU, the same on every machine.
  const flags = ["--headless=new", "--no-sandbox", "--no-first-run", "--no-default-browser-check", "--disable-extensions",
    "--use-angle=swiftshader", "--enable-unsafe-swiftshader", `--user-data-dir=${profile}`,
    // The page draws nothing on screen: without GPU compositing Chromium starts in a third of the time.
    "--disable-gpu-compositing"];
  if (webgpu) flags.push("--enable-unsafe-webgpu", "--use-webgpu-adapter=swiftshader");
  let log = "";
  browser = spawn(chromium, [...flags, url], { stdio: ["ignore", "ignore", "pipe"], detached: true });
  browser.stderr.on("data", (d) => {
    log = (log + d).slice(-4000);
    // A crashed GPU process loses the page's context; the page may not learn of it before it reads back.
    if (/GPU process exited unexpectedly/.test(log))
      finish(1, `Chromium's GPU process crashed running the case's shader; its last output:\n${log.split("\n").filter((l) => !/dbus/.test(l)).join("\n")}`);
  });
  browser.on("error", (e) =>
    finish(1, `cannot start ${chromium}: ${e.message} (install Debian's chromium: apt-get install chromium)`));
  browser.on("exit", (code, signal) =>
    finish(1, `Chromium exited (${signal ?? code}) before the page posted its results; its last output:\n${log}`));
});
setTimeout(() => finish(1, `no results after ${timeoutMs / 1000} s (SNELL_BROWSER_TIMEOUT_MS)`), timeoutMs).unref();
