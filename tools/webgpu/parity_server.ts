// run_parity.ts as one process for a whole ctest run (webgpu_servers.mjs starts it): naga's wasm
// compiled once and one WebGPU adapter and device kept, instead of a Deno process per case (~0.85
// CPU-s each, half of it requestAdapter; a job here is 0.05-0.1 s).
//
//   deno run --allow-read --allow-write --allow-env --allow-net=unix:SOCKET --node-modules-dir=manual parity_server.ts SOCKET
//
// A client (include/snell/gpu/parity_webgpu.hpp) writes one line, a job folder's absolute path; the
// server runs runParityDir on it and answers what `run_parity.ts JOB_DIR` would exit with and print,
// "<status>\n<output>", then closes the connection. Jobs run one at a time (a device's error scopes
// are a stack); after a failed job, which may leave scopes pushed, the next one gets a new adapter and
// device.
import { failureText, runParityDir } from "./run_parity.ts";

const socketPath = Deno.args[0];
if (!socketPath || Deno.args.length !== 1) {
  console.error("usage: parity_server.ts SOCKET");
  Deno.exit(2);
}

let adapter: Promise<GPUAdapter | null> | null = null;
let device: Promise<GPUDevice> | null = null;
function forget() {
  device?.then((d) => d.destroy(), () => {});
  adapter = device = null;
}
// What runParityJob asks navigator.gpu for, kept from job to job: one adapter, and one device with
// float32-filterable whenever the adapter has it (runParityJob refuses a job that needs it before
// asking for a device on an adapter without it).
const keptGpu = {
  async requestAdapter() {
    const a = await (adapter ??= navigator.gpu.requestAdapter());
    if (!a) {
      adapter = null;
      return null;
    }
    return {
      features: a.features,
      limits: a.limits,
      info: a.info,
      requestDevice() {
        if (!device) {
          const made: Promise<GPUDevice> = a.requestDevice({
            requiredFeatures: a.features.has("float32-filterable") ? ["float32-filterable"] : [],
            requiredLimits: { maxStorageBufferBindingSize: a.limits.maxStorageBufferBindingSize },
          });
          made.then((d) => d.lost.then(() => device === made && forget()), () => device === made && forget());
          device = made;
        }
        return device;
      },
    };
  },
};

let queue: Promise<unknown> = Promise.resolve();
function run(dir: string): Promise<string> {
  const answer = queue.then(async () => {
    if (!dir.startsWith("/")) return `1\nparity_server.ts: not an absolute path: '${dir}'\n`;
    try {
      await runParityDir(keptGpu, dir);
      return "0\n";
    } catch (e) {
      forget();
      return `1\n${failureText(e)}`;
    }
  });
  queue = answer;
  return answer;
}

async function serve(conn: Deno.Conn) {
  const decoder = new TextDecoder();
  const buf = new Uint8Array(4096);
  let line = "";
  for (let n; !line.includes("\n") && (n = await conn.read(buf)) !== null;) {
    line += decoder.decode(buf.subarray(0, n), { stream: true });
  }
  if (line.includes("\n")) {
    const reply = new TextEncoder().encode(await run(line.slice(0, line.indexOf("\n"))));
    for (let off = 0; off < reply.length;) off += await conn.write(reply.subarray(off));
  }
  conn.close();
}

// The adapter and device made before the first job (a failure here is each job's to report).
try {
  await (await keptGpu.requestAdapter())?.requestDevice();
} catch {
  forget();
}
try {
  Deno.removeSync(socketPath);
} catch {
  // no socket left by an earlier server
}
const listener = Deno.listen({ transport: "unix", path: socketPath });
console.error(`parity_server.ts: listening on ${socketPath}`);
for await (const conn of listener) serve(conn).catch((e) => console.error(`parity_server.ts: ${e}`));
