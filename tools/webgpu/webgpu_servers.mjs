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
import { spawn } from "node:child_process";
import fs from "node:fs";
import path from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";

const here = path.dirname(fileURLToPath(import.meta.url));
const deno = path.join(here, "node_modules", "@deno", "linux-x64-glibc", "deno");
const servers = ["parity", "tint"];

// A killed server stays a zombie until init reaps it, which can take seconds here: gone all the same.
const alive = (pid) => {
  try {
    return !/^\d+ \(.*\) Z/.test(fs.readFileSync(`/proc/${pid}/stat`, "utf8"));
  } catch {
    return false;
  }
};
const sleep = (ms) => new Promise((resolve) => setTimeout(resolve, ms));
const readPid = (dir, name) => {
  try {
    return Number(fs.readFileSync(path.join(dir, `${name}.pid`), "utf8"));
  } catch {
    return 0;
  }
};
const logTail = (dir, name) => {
  try {
    return fs.readFileSync(path.join(dir, `${name}_server.log`), "utf8").slice(-4000);
  } catch {
    return "";
  }
};
const listening = (file) => {
  try {
    return fs.statSync(file).isSocket();
  } catch {
    return false;
  }
};

export async function stopWebGpuServers(dir) {
  for (const name of servers) {
    const pid = readPid(dir, name);
    if (pid > 0) {
      try {
        process.kill(-pid, "SIGKILL");
      } catch {
        // already gone
      }
      for (let i = 0; i < 100 && alive(pid); ++i) await sleep(50);
    }
    fs.rmSync(path.join(dir, `${name}.pid`), { force: true });
    fs.rmSync(path.join(dir, `${name}.sock`), { force: true });
  }
  fs.rmSync(path.join(dir, "xdg"), { recursive: true, force: true });
}

export async function startWebGpuServers(dir) {
  fs.mkdirSync(dir, { recursive: true });
  dir = fs.realpathSync(dir);
  await stopWebGpuServers(dir);  // servers left by an interrupted run
  if (!fs.existsSync(deno)) throw new Error(`no Deno at ${deno}: run 'npm ci' in ${here} (scripts/install-deps.sh does)`);
  const sock = (name) => path.join(dir, `${name}.sock`);
  // sun_path is 108 bytes: a deeper build folder cannot have the servers.
  if (Buffer.byteLength(sock("parity")) > 107) throw new Error(`the socket path ${sock("parity")} is over 107 bytes`);
  // Deno's WebGPU warns without a runtime directory: give it a private one (as snell-wgsl does).
  const env = { ...process.env };
  if (!env.XDG_RUNTIME_DIR) {
    env.XDG_RUNTIME_DIR = path.join(dir, "xdg");
    fs.mkdirSync(env.XDG_RUNTIME_DIR, { mode: 0o700 });
  }
  const commands = {
    parity: [deno, ["run", "--quiet", "--allow-read", "--allow-write", "--allow-env", `--allow-net=unix:${sock("parity")}`,
      "--node-modules-dir=manual", path.join(here, "parity_server.ts"), sock("parity")]],
    tint: [process.execPath, [path.join(here, "tint_server.mjs"), sock("tint")]],
  };
  const started = {};
  for (const name of servers) {
    const log = fs.openSync(path.join(dir, `${name}_server.log`), "w");
    const [program, args] = commands[name];
    // A process group of its own, as ctest waits for this script's, not for the servers.
    const child = spawn(program, args, { cwd: here, env, stdio: ["ignore", log, log], detached: true });
    fs.closeSync(log);
    child.unref();
    child.on("error", (e) => (child.spawnError = e));
    fs.writeFileSync(path.join(dir, `${name}.pid`), String(child.pid));
    started[name] = child;
  }
  for (let i = 0; i < 1200; ++i) {
    for (const name of servers) {
      const child = started[name];
      if (child.spawnError) throw new Error(`cannot start the ${name} server: ${child.spawnError.message}`);
      if (child.exitCode !== null || child.signalCode !== null)
        throw new Error(`the ${name} server exited (${child.signalCode ?? child.exitCode}) while starting; its output:\n` +
          logTail(dir, name));
    }
    if (servers.every((name) => listening(sock(name)))) return { parity: started.parity.pid, tint: started.tint.pid };
    await sleep(50);
  }
  await stopWebGpuServers(dir);
  throw new Error(`the servers did not listen in 60 s; their output:\n${servers.map((n) => logTail(dir, n)).join("\n")}`);
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
