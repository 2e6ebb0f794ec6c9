// tint_check.mjs as one process for a whole ctest run (webgpu_servers.mjs starts it): dawn.node
// loaded and its device made once instead of for every case (~0.18 CPU-s each; a check is ~5 ms).
//
//   node tint_server.mjs SOCKET
//
// A client (include/snell/gpu/parity_webgpu.hpp) writes one line, a WGSL file's absolute path; the
// answer is what `node tint_check.mjs FILE` would exit with and print, "<status>\n<output>", then the
// server closes the connection. Checks run one at a time (tintCheck's error scope).
import fs from "node:fs";
import net from "node:net";
import path from "node:path";

import { openTint, tintCheck } from "./tint_check.mjs";

const socketPath = process.argv[2];
if (!socketPath || process.argv.length !== 3) {
  console.error("usage: tint_server.mjs SOCKET");
  process.exit(2);
}
let device;
try {
  device = await openTint();
} catch (e) {
  console.error(`tint_server: ${e.message}`);
  process.exit(1);
}

let queue = Promise.resolve();
async function answer(file) {
  if (!path.isAbsolute(file)) return `1\ntint_server: not an absolute path: '${file}'\n`;
  try {
    const { validation, rejection } = await tintCheck(device, file);
    return `${rejection ? 1 : 0}\n${validation}${rejection}`;
  } catch (e) {
    return `1\ntint_check: ${e.message}\n`;
  }
}

fs.rmSync(socketPath, { force: true });
net.createServer((conn) => {
  let line = "";
  conn.setEncoding("utf8");
  conn.on("error", (e) => console.error(`tint_server: ${e.message}`));
  conn.on("data", (d) => {
    line += d;
    if (!line.includes("\n")) return;
    conn.pause();
    const reply = (queue = queue.then(() => answer(line.slice(0, line.indexOf("\n")))));
    reply.then((text) => conn.end(text));
  });
}).listen(socketPath, () => console.error(`tint_server: listening on ${socketPath}`));
