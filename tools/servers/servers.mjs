// Long-lived servers for a whole ctest run (the WebGPU runtime's, tools/webgpu/webgpu_servers.mjs; the
// WebGL 2 runtime's page server, tools/webgl/webgl_server.mjs): started detached by a fixture's setup
// test, asked by every case over a Unix socket, killed by its cleanup test.
//
//   await startServers(STATE_DIR, { name: [program, args, options], ... });  // waits until all listen
//   await stopServers(STATE_DIR, ["name", ...]);
//   serveLines(SOCKET, (line) => answer, "who");  // in a server: one request line, one answer
//
// STATE_DIR holds each server's socket (<name>.sock, which the server is given in its args), pid
// (<name>.pid) and output (<name>_server.log).
import { spawn } from "node:child_process";
import fs from "node:fs";
import net from "node:net";
import path from "node:path";

export const socketOf = (dir, name) => path.join(dir, `${name}.sock`);
export const logOf = (dir, name) => path.join(dir, `${name}_server.log`);

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
    return fs.readFileSync(logOf(dir, name), "utf8").slice(-4000);
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

export async function stopServers(dir, names) {
  for (const name of names) {
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
    fs.rmSync(socketOf(dir, name), { force: true });
  }
}

// Starts each `commands` entry, name: [program, args, {cwd, env}], and waits until every one listens on
// its socket. Returns the pids by name. `dir` must exist and be a real path (the sockets' paths are
// checked against sun_path's 108 bytes).
export async function startServers(dir, commands) {
  const names = Object.keys(commands);
  await stopServers(dir, names);  // servers left by an interrupted run
  for (const name of names) {
    if (Buffer.byteLength(socketOf(dir, name)) > 107)
      throw new Error(`the socket path ${socketOf(dir, name)} is over 107 bytes: a shallower build folder can have it`);
  }
  const started = {};
  for (const name of names) {
    const log = fs.openSync(logOf(dir, name), "w");
    const [program, args, options = {}] = commands[name];
    // A process group of its own, as ctest waits for the starting script's, not for the servers.
    const child = spawn(program, args, { ...options, stdio: ["ignore", log, log], detached: true });
    fs.closeSync(log);
    child.unref();
    child.on("error", (e) => (child.spawnError = e));
    fs.writeFileSync(path.join(dir, `${name}.pid`), String(child.pid));
    started[name] = child;
  }
  for (let i = 0; i < 1200; ++i) {
    for (const name of names) {
      const child = started[name];
      if (child.spawnError) throw new Error(`cannot start the ${name} server: ${child.spawnError.message}`);
      if (child.exitCode !== null || child.signalCode !== null)
        throw new Error(`the ${name} server exited (${child.signalCode ?? child.exitCode}) while starting; ` +
          `its output:\n${logTail(dir, name)}`);
    }
    if (names.every((name) => listening(socketOf(dir, name))))
      return Object.fromEntries(names.map((name) => [name, started[name].pid]));
    await sleep(50);
  }
  await stopServers(dir, names);
  throw new Error(`the servers did not listen in 60 s; their output:\n${names.map((n) => logTail(dir, n)).join("\n")}`);
}

// Listens on `socketPath` for one request line per connection and writes back what answer(line)
// resolves to, then closes the connection: the protocol of snell::gpu::detail::askServer (process.hpp).
export function serveLines(socketPath, answer, who) {
  fs.rmSync(socketPath, { force: true });
  return net.createServer((conn) => {
    let line = "";
    conn.setEncoding("utf8");
    conn.on("error", (e) => console.error(`${who}: ${e.message}`));
    conn.on("data", (d) => {
      line += d;
      if (!line.includes("\n")) return;
      conn.pause();
      answer(line.slice(0, line.indexOf("\n"))).then((text) => conn.end(text),
        (e) => conn.end(`1\n${who}: ${e.message ?? e}\n`));
    });
  }).listen(socketPath, () => console.error(`${who}: listening on ${socketPath}`));
}
