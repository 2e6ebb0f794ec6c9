// The WebGPU runtime's two servers for a whole ctest run (the webgpu_servers fixture,
// tests/CMakeLists.txt): parity_server.ts (Deno: naga and the dispatch) and tint_server.mjs (Node:
// Tint). A case then costs ~0.1 s instead of starting a Deno and a Node process (~1 CPU-s); the
// suite has hundreds of them. parity_webgpu.hpp asks them when SNELL_WEBGPU_SERVER names STATE_DIR.
//
//   node webgpu_servers.mjs start STATE_DIR   // waits until both listen
//   node webgpu_servers.mjs stop STATE_DIR
//
// STATE_DIR holds each server's socket (parity.sock, tint.sock), pid (parity.pid, tint.pid) and
// output (parity_server.log, tint_server.log).
import fs from "node:fs";
import path from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";

import { socketOf, startServers, stopServers } from "../servers/servers.mjs";

const here = path.dirname(fileURLToPath(import.meta.url));
const deno = path.join(here, "node_modules", "@deno", "linux-x64-glibc", "deno");
const servers = ["parity", "tint"];

export async function stopWebGpuServers(dir) {
  await stopServers(dir, servers);
  fs.rmSync(path.join(dir, "xdg"), { recursive: true, force: true });
}

export async function startWebGpuServers(dir) {
  fs.mkdirSync(dir, { recursive: true });
  dir = fs.realpathSync(dir);
  await stopWebGpuServers(dir);  // servers left by an interrupted run
  if (!fs.existsSync(deno)) throw new Error(`no Deno at ${deno}: run 'npm ci' in ${here} (scripts/install-deps.sh does)`);
  const sock = (name) => socketOf(dir, name);
  // Deno's WebGPU warns without a runtime directory: give it a private one (as snell-wgsl does).
  const env = { ...process.env };
  if (!env.XDG_RUNTIME_DIR) {
    env.XDG_RUNTIME_DIR = path.join(dir, "xdg");
    fs.mkdirSync(env.XDG_RUNTIME_DIR, { mode: 0o700 });
  }
  return startServers(dir, {
    parity: [deno, ["run", "--quiet", "--allow-read", "--allow-write", "--allow-env", `--allow-net=unix:${sock("parity")}`,
      "--node-modules-dir=manual", path.join(here, "parity_server.ts"), sock("parity")], { cwd: here, env }],
    tint: [process.execPath, [path.join(here, "tint_server.mjs"), sock("tint")], { cwd: here, env }],
  });
}

if (process.argv[1] && import.meta.url === pathToFileURL(fs.realpathSync(process.argv[1])).href) {
  const [command, dir] = process.argv.slice(2);
  try {
    if (command === "start" && dir && process.argv.length === 4) {
      const pids = await startWebGpuServers(dir);
      console.log(`WebGPU servers: parity_server.ts pid ${pids.parity}, tint_server.mjs pid ${pids.tint}, state in ${dir}`);
    } else if (command === "stop" && dir && process.argv.length === 4) {
      await stopWebGpuServers(dir);
    } else {
      throw new Error("usage: webgpu_servers.mjs start|stop STATE_DIR");
    }
  } catch (e) {
    console.error(`webgpu_servers.mjs: ${e.message}`);
    process.exit(1);
  }
}
