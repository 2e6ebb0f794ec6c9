// The WebGL 2 runtime's page server for a whole ctest run (the webgl_server fixture,
// tests/CMakeLists.txt): tools/browser/page_server.mjs on this folder's pages, in the shared Chromium
// the run started (shared_chromium.mjs). A case then costs its page's work instead of a Node process
// and a tab of its own (~1 CPU-s); the suite has hundreds of them. parity_webgl.hpp asks it when
// SNELL_WEBGL_SERVER names STATE_DIR.
//
//   node webgl_server.mjs start STATE_DIR SHARED_CHROMIUM_DIR   // waits until it listens
//   node webgl_server.mjs stop STATE_DIR
//
// STATE_DIR holds the server's socket (page.sock), pid (page.pid) and output (page_server.log).
import fs from "node:fs";
import path from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";

import { socketOf, startServers, stopServers } from "../servers/servers.mjs";

const here = path.dirname(fileURLToPath(import.meta.url));

export const stopWebGlServer = (dir) => stopServers(dir, ["page"]);

export async function startWebGlServer(dir, chromiumDir) {
  fs.mkdirSync(dir, { recursive: true });
  dir = fs.realpathSync(dir);
  const server = path.join(here, "..", "browser", "page_server.mjs");
  const args = [server, socketOf(dir, "page"), chromiumDir, here];
  return startServers(dir, { page: [process.execPath, args, { cwd: here }] });
}

if (process.argv[1] && import.meta.url === pathToFileURL(fs.realpathSync(process.argv[1])).href) {
  const [command, dir, chromiumDir] = process.argv.slice(2);
  try {
    if (command === "start" && dir && chromiumDir && process.argv.length === 5) {
      const { page } = await startWebGlServer(dir, chromiumDir);
      console.log(`WebGL 2 page server: page_server.mjs pid ${page}, state in ${dir}, ` +
        `tabs of the Chromium in ${chromiumDir}`);
    } else if (command === "stop" && dir && process.argv.length === 4) {
      await stopWebGlServer(dir);
    } else {
      throw new Error("usage: webgl_server.mjs start STATE_DIR SHARED_CHROMIUM_DIR | stop STATE_DIR");
    }
  } catch (e) {
    console.error(`webgl_server.mjs: ${e.message}`);
    process.exit(1);
  }
}
