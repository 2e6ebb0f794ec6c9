// One headless Chromium shared by many pages: ctest starts it once (the chromium fixture,
// tests/CMakeLists.txt) and each WebGL 2 test opens its page as a tab through the DevTools HTTP
// endpoint instead of starting a browser of its own. Starting and stopping Chromium is ~1.8 s of
// the ~2.2 s a small WebGL case takes; the suite has hundreds of them.
//
//   node shared_chromium.mjs start STATE_DIR [--chromium=PATH]   // waits until it answers
//   node shared_chromium.mjs stop STATE_DIR
//   const tab = await openSharedPage(STATE_DIR, url, (message) => ...);  await tab.close();
//
// STATE_DIR holds the browser's pid, its profile (profile/DevToolsActivePort names the port) and
// its stderr (chromium.log). A tab's onFailure fires, once, when the shared browser is gone or its
// GPU process crashes while the tab is open (every tab open then lost its GL context).
import { spawn } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import { pathToFileURL } from "node:url";

import { chromiumFlags } from "./chromium.mjs";

const alive = (pid) => {
  try {
    process.kill(pid, 0);
    return true;
  } catch {
    return false;
  }
};
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
const readPid = (dir) => {
  try {
    return Number(fs.readFileSync(path.join(dir, "pid"), "utf8"));
  } catch {
    return 0;
  }
};
const logTail = (dir) => {
  try {
    return fs.readFileSync(path.join(dir, "chromium.log"), "utf8").slice(-4000);
  } catch {
    return "";
  }
};

// Kills the browser's whole process group (its GPU and renderer processes outlive the browser
// process), waits for it, and removes its profile.
export async function stopSharedChromium(dir) {
  const pid = readPid(dir);
  if (pid > 0) {
    try {
      process.kill(-pid, "SIGKILL");
    } catch {
      // already gone
    }
    for (let i = 0; i < 100 && alive(pid); ++i) await sleep(50);
  }
  fs.rmSync(path.join(dir, "pid"), { force: true });
  fs.rmSync(path.join(dir, "profile"), { recursive: true, force: true, maxRetries: 10, retryDelay: 100 });
}

export async function startSharedChromium(dir, { chromium = "chromium" } = {}) {
  fs.mkdirSync(dir, { recursive: true });
  await stopSharedChromium(dir);  // a browser left by an interrupted run
  const profile = path.join(dir, "profile");
  const log = fs.openSync(path.join(dir, "chromium.log"), "w");
  const flags = [...chromiumFlags(profile, false), "--remote-debugging-port=0",
    // Every test's tab is a background tab to the others: none may be throttled.
    "--disable-background-timer-throttling", "--disable-renderer-backgrounding", "--disable-backgrounding-occluded-windows"];
  const browser = spawn(chromium, [...flags, "about:blank"], { stdio: ["ignore", "ignore", log], detached: true });
  let spawnError = null;
  browser.on("error", (e) => (spawnError = e));
  browser.unref();
  fs.closeSync(log);
  const portFile = path.join(profile, "DevToolsActivePort");
  for (let i = 0; i < 600; ++i) {
    if (spawnError) throw new Error(`cannot start ${chromium}: ${spawnError.message} (install Debian's chromium: apt-get install chromium)`);
    if (browser.exitCode !== null || browser.signalCode !== null)
      throw new Error(`Chromium exited (${browser.signalCode ?? browser.exitCode}) while starting; its last output:\n${logTail(dir)}`);
    if (fs.existsSync(portFile) && fs.readFileSync(portFile, "utf8").includes("\n")) {
      fs.writeFileSync(path.join(dir, "pid"), String(browser.pid));
      const port = fs.readFileSync(portFile, "utf8").split("\n")[0];
      const r = await fetch(`http://127.0.0.1:${port}/json/version`);
      if (!r.ok) throw new Error(`Chromium's DevTools endpoint on port ${port} answers ${r.status}`);
      return { pid: browser.pid, port };
    }
    await sleep(50);
  }
  process.kill(-browser.pid, "SIGKILL");
  throw new Error(`Chromium did not open its DevTools port in 30 s; its last output:\n${logTail(dir)}`);
}

export async function openSharedPage(dir, url, onFailure = () => {}) {
  const pid = readPid(dir);
  if (!(pid > 0) || !alive(pid))
    throw new Error(`the shared Chromium in ${dir} is not running (ctest starts it in the test browser.chromium_start)`);
  const port = fs.readFileSync(path.join(dir, "profile", "DevToolsActivePort"), "utf8").split("\n")[0];
  const logFile = path.join(dir, "chromium.log");
  let logOffset = fs.statSync(logFile).size;
  let closing = false;
  let failed = false;
  const failure = (message) => {
    if (closing || failed) return;
    failed = true;
    onFailure(message);
  };
  const r = await fetch(`http://127.0.0.1:${port}/json/new?${url}`, { method: "PUT" });
  if (!r.ok) throw new Error(`the shared Chromium (port ${port}) cannot open a tab: ${r.status} ${await r.text()}`);
  const { id } = await r.json();
  const watch = setInterval(() => {
    if (!alive(pid)) return failure(`the shared Chromium (pid ${pid}) exited; its last output:\n${logTail(dir)}`);
    const size = fs.statSync(logFile).size;
    if (size <= logOffset) return;
    const fd = fs.openSync(logFile, "r");
    const added = Buffer.alloc(size - logOffset);
    fs.readSync(fd, added, 0, added.length, logOffset);
    fs.closeSync(fd);
    logOffset = size;
    if (/GPU process exited unexpectedly/.test(added.toString()))
      failure(`the shared Chromium's GPU process crashed while this page ran; its output:\n${added.toString().slice(-4000)}`);
  }, 200);
  watch.unref();
  const close = async () => {
    closing = true;
    clearInterval(watch);
    try {
      await fetch(`http://127.0.0.1:${port}/json/close/${id}`);
    } catch {
      // the browser is gone: nothing left to close
    }
  };
  return { close };
}

if (process.argv[1] && import.meta.url === pathToFileURL(path.resolve(process.argv[1])).href) {
  const args = process.argv.slice(2);
  const chromium = (args.find((a) => a.startsWith("--chromium=")) ?? "--chromium=chromium").slice("--chromium=".length);
  const [command, dir] = args.filter((a) => !a.startsWith("--"));
  try {
    if (command === "start" && dir) {
      const { pid, port } = await startSharedChromium(dir, { chromium });
      console.log(`shared Chromium: pid ${pid}, DevTools on 127.0.0.1:${port}, state in ${dir}`);
    } else if (command === "stop" && dir) {
      await stopSharedChromium(dir);
    } else {
      throw new Error("usage: shared_chromium.mjs start|stop STATE_DIR [--chromium=PATH]");
    }
  } catch (e) {
    console.error(`shared_chromium.mjs: ${e.message}`);
    process.exit(1);
  }
}
