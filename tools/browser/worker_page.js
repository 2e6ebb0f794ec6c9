// A tab page_server.mjs keeps open in the shared Chromium: asks for a job, runs it with the job's page
// module (a module of the server's pages folder exporting run({get, post}), imported once), and asks
// again. One job at a time, so a job has the tab's renderer to itself, as in a page of its own.
import { jobIo } from "/browser/page_io.js";

const worker = new URLSearchParams(location.search).get("worker");
const modules = new Map();
for (;;) {
  const r = await fetch(`/next?worker=${worker}`).catch(() => null);
  // The server is gone, or has given up on this tab: it idles until the browser closes it.
  if (!r || r.status === 404) break;
  if (r.status !== 200) continue;  // no job for a while: ask again
  const { id, page } = await r.json();
  const io = jobIo(`/jobs/${id}`);
  try {
    if (!modules.has(page)) modules.set(page, import(`/lib/${page}`));
    await (await modules.get(page)).run(io);
  } catch (e) {
    await io.post("/error", `${e.message ?? e}`).catch(() => {});
  }
}
