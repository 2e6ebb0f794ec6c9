// Headless Chromium on one URL, for the pages the suite runs (run_page.mjs: the WebGL 2 and WebGPU parity
// runtimes; examples/web/serve.mjs: the three.js page's test). SwiftShader gives WebGL 2 (through ANGLE)
// and WebGPU (through Dawn) with no GPU, the same on every machine.
//
//   const browser = launchChromium(url, { chromium: "chromium", webgpu: false, onFailure: (message) => ... });
//   await browser.close();  // kills its whole process group, waits, removes its profile folder
//
// onFailure is called once, with a message naming the cause, when Chromium cannot start, exits by itself
// or its GPU process crashes (a page may not learn of that before it reads back); its second argument,
// { crashed: true }, says the cause was a crash (a signal, or the GPU process), not a refusal to start.
import { spawn } from "node:child_process";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";

// The flags every Chromium the suite starts shares (also the shared one, shared_chromium.mjs).
export function chromiumFlags(profile, webgpu) {
  const flags = ["--headless=new", "--no-sandbox", "--no-first-run", "--no-default-browser-check", "--disable-extensions",
    "--use-angle=swiftshader", "--enable-unsafe-swiftshader", `--user-data-dir=${profile}`,
    // The pages draw nothing on screen: without GPU compositing Chromium starts in a third of the time.
    "--disable-gpu-compositing"];
  if (webgpu) flags.push("--enable-unsafe-webgpu", "--use-webgpu-adapter=swiftshader");
  return flags;
}

// Chromium's complaints that there is no D-Bus (none in a container) hide what went wrong.
const withoutDbus = (log) => log.split("\n").filter((l) => !/dbus/.test(l)).join("\n");

export function launchChromium(url, { chromium = "chromium", webgpu = false, onFailure = () => {} } = {}) {
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), "snell-chromium-"));
  const flags = chromiumFlags(profile, webgpu);
  let log = "";
  let closing = false;
  let failed = false;
  const failure = (message, crashed = false) => {
    if (closing || failed) return;
    failed = true;
    onFailure(message, { crashed });
  };
  const browser = spawn(chromium, [...flags, url], { stdio: ["ignore", "ignore", "pipe"], detached: true });
  browser.stderr.on("data", (d) => {
    log = (log + d).slice(-4000);
    if (/GPU process exited unexpectedly/.test(log))
      failure(`Chromium's GPU process crashed; its last output:\n${withoutDbus(log)}`, true);
  });
  browser.on("error", (e) =>
    failure(`cannot start ${chromium}: ${e.message} (install Debian's chromium: apt-get install chromium)`));
  browser.on("exit", (code, signal) =>
    failure(`Chromium exited (${signal ?? code}) before the page was done; its last output:\n${withoutDbus(log)}`,
      signal !== null));

  // Chromium is killed and waited for before its profile folder is removed (its helper processes still
  // write there while they go down).
  const close = () => new Promise((resolve) => {
    closing = true;
    const done = () => {
      try {
        fs.rmSync(profile, { recursive: true, force: true, maxRetries: 10, retryDelay: 100 });
      } catch (e) {
        console.error(`chromium.mjs: cannot remove ${profile}: ${e.message}`);
      }
      resolve();
    };
    try {
      // The whole process group: Chromium's GPU and renderer processes outlive a killed browser process.
      process.kill(-browser.pid, "SIGKILL");
    } catch {
      // already gone
    }
    if (browser.exitCode === null && browser.signalCode === null) browser.once("exit", () => setTimeout(done, 50));
    else done();
  });
  return { close };
}
