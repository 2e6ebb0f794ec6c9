// tint_check.mjs as one process for a whole ctest run (webgpu_servers.mjs starts it): dawn.node
// loaded and its device made once instead of for every case (~0.18 CPU-s each; a check is ~5 ms).
//
//   node tint_server.mjs SOCKET
//
// A client (include/snell/gpu/parity_webgpu.hpp) writes one line, a WGSL file's absolute path; the
// answer is what `node tint_check.mjs FILE` would exit with and print, "<status>\n<output>", then the
// server closes the connection. Checks run one at a time (tintCheck's error scope).
import path from "node:path";

import { serveLines } from "../servers/servers.mjs";
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

serveLines(socketPath, (line) => (queue = queue.then(() => answer(line))), "tint_server");
