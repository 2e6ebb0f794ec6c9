// What run_page.mjs does for one job, for every job of a ctest run: a few tabs kept open in the shared
// Chromium (shared_chromium.mjs) run the jobs one after another, instead of each job starting a Node
// process and opening, loading and closing a tab of its own (~1 CPU-s per job, for hundreds of WebGL 2
// jobs). tools/webgl/webgl_server.mjs starts it for the ctest run.
//
//   node page_server.mjs SOCKET SHARED_CHROMIUM_DIR PAGES_DIR
//
// A client (include/snell/gpu/chromium_page.hpp) writes one line, "PAGE RESULTS_FILE JOB_DIR": PAGE a
// module of PAGES_DIR exporting run({get, post}) (tools/webgl/parity_job.js), JOB_DIR an absolute path.
// The job's files are read and written as run_page.mjs reads and writes them (page_job.mjs); the
// answer is "<status>\n<output>", 0 and nothing once the results are written, 1 and the failure
// otherwise, as run_page.mjs would exit and print; then the server closes the connection.
//
// SNELL_PAGE_WORKERS tabs (2 by default) take the jobs in arrival order, one job per tab at a time.
// A job with no results after SNELL_BROWSER_TIMEOUT_MS (600 s by default, as run_page.mjs) fails and
// its tab is replaced, as is every tab after a crash of the GPU process (the job it ran fails, as in
// run_page.mjs). With the shared Chromium gone, every job fails and the server exits.
import fs from "node:fs";
import http from "node:http";
import path from "node:path";

import { answerJobRequest, libFile } from "./page_job.mjs";
import { serveLines } from "../servers/servers.mjs";
import { openSharedPage } from "./shared_chromium.mjs";

const [socketPath, chromiumDir, pagesDir] = process.argv.slice(2);
if (!socketPath || !chromiumDir || !pagesDir || process.argv.length !== 5) {
  console.error("usage: page_server.mjs SOCKET SHARED_CHROMIUM_DIR PAGES_DIR");
  process.exit(2);
}
const workerCount = Math.max(1, Number(process.env.SNELL_PAGE_WORKERS) || 2);
const timeoutMs = Number(process.env.SNELL_BROWSER_TIMEOUT_MS ?? 600000);
// A worker's request for a job is answered "none yet" after this long, and asked again.
const pollMs = 30000;

const jobs = new Map();     // id -> {id, page, resultsFile, dir, answer(text), worker, timer}
const waiting = [];         // jobs no worker has taken yet
const workers = new Map();  // id -> {id, tab: Promise of {close}, poll: a /next response or null, job}
let nextJob = 1;
let nextWorker = 1;
let baseUrl = "";

function finishJob(job, status, message) {
  if (!jobs.delete(job.id)) return;
  clearTimeout(job.timer);
  if (job.worker?.job === job) job.worker.job = null;
  if (status !== 0) console.error(`page_server.mjs: ${job.dir}: ${message}`);
  job.answer(status === 0 ? "0\n" : `${status}\npage_server.mjs: ${message}\n`);
}

// Every job fails and the server exits: later clients find no server, which names the socket.
let givenUp = false;
function giveUp(message) {
  if (givenUp) return;
  givenUp = true;
  console.error(`page_server.mjs: giving up: ${message}`);
  for (const job of [...jobs.values()]) finishJob(job, 1, message);
  setTimeout(() => process.exit(1), 100);
}

function dispatch() {
  for (const worker of workers.values()) {
    while (waiting.length && !jobs.has(waiting[0].id)) waiting.shift();  // failed while it waited
    if (!waiting.length) return;
    if (!worker.poll || worker.job) continue;
    const job = waiting.shift();
    worker.job = job;
    job.worker = worker;
    job.timer = setTimeout(() => {
      finishJob(job, 1, `no results after ${timeoutMs / 1000} s (SNELL_BROWSER_TIMEOUT_MS)`);
      replaceWorker(worker);
    }, timeoutMs);
    const next = JSON.stringify({ id: job.id, page: job.page });
    worker.poll.writeHead(200, { "content-type": "application/json" }).end(next);
    worker.poll = null;
  }
}

function openWorker() {
  const worker = { id: nextWorker++, tab: null, poll: null, job: null };
  workers.set(worker.id, worker);
  worker.tab = openSharedPage(chromiumDir, `${baseUrl}?worker=${worker.id}`, (message) => {
    if (worker.job) finishJob(worker.job, 1, message);
    replaceWorker(worker);
  });
  worker.tab.catch((e) => giveUp(e.message));
}

// A tab stuck in a job, or whose context a GPU crash took, gives way to a new one.
function replaceWorker(worker) {
  if (!workers.delete(worker.id)) return;
  worker.poll?.writeHead(404).end();
  worker.tab.then((tab) => tab.close(), () => {});
  openWorker();
}

const html = '<!doctype html><meta charset="utf-8"><title>snell pages</title>' +
  '<script type="module" src="/worker_page.js"></script>';
const server = http.createServer((req, res) => {
  const body = [];
  req.on("data", (d) => body.push(d));
  req.on("end", () => {
    const data = Buffer.concat(body);
    const url = new URL(req.url, "http://localhost");
    let m;
    if (req.method === "GET" && url.pathname === "/") {
      res.writeHead(200, { "content-type": "text/html" }).end(html);
    } else if (req.method === "GET" && (url.pathname === "/worker_page.js" || url.pathname === "/browser/page_io.js")) {
      const file = new URL(path.basename(url.pathname), import.meta.url);
      res.writeHead(200, { "content-type": "text/javascript" }).end(fs.readFileSync(file));
    } else if (req.method === "GET" && (m = libFile(pagesDir, url.pathname))) {
      res.writeHead(200, { "content-type": "text/javascript" }).end(fs.readFileSync(m));
    } else if (req.method === "GET" && url.pathname === "/next") {
      const worker = workers.get(Number(url.searchParams.get("worker")));
      if (!worker) return res.writeHead(404).end();
      worker.poll = res;
      const idle = setTimeout(() => res.writeHead(204).end(), pollMs);
      res.on("close", () => {
        clearTimeout(idle);
        if (worker.poll === res) worker.poll = null;
      });
      dispatch();
    } else if ((m = /^\/jobs\/(\d+)(\/.*)$/.exec(url.pathname)) && jobs.has(Number(m[1]))) {
      const job = jobs.get(Number(m[1]));
      let answer;
      try {
        answer = answerJobRequest(req, m[2], data, res, job.dir, job.resultsFile);
      } catch (e) {
        // What ends run_page.mjs (a job file it cannot read or write) ends the job, not the server.
        res.writeHead(500).end();
        return finishJob(job, 1, e.message);
      }
      if (!answer) res.writeHead(404).end();
      else if (answer.done) finishJob(job, 0, "");
      else if (answer.error !== undefined) finishJob(job, 1, answer.error);
    } else {
      res.writeHead(404).end();
    }
  });
});

function request(line) {
  const m = /^(\w+\.js) (\w[\w.]*) (\/.*)$/.exec(line);
  if (!m) return Promise.resolve(`1\npage_server.mjs: not "PAGE RESULTS_FILE /JOB_DIR": '${line}'\n`);
  const [, page, resultsFile, dir] = m;
  if (!fs.existsSync(path.join(pagesDir, page)))
    return Promise.resolve(`1\npage_server.mjs: no page module ${path.join(pagesDir, page)}\n`);
  if (!fs.existsSync(path.join(dir, "job.json"))) return Promise.resolve(`1\npage_server.mjs: no job.json in ${dir}\n`);
  return new Promise((answer) => {
    const job = { id: nextJob++, page, resultsFile, dir, answer, worker: null, timer: null };
    jobs.set(job.id, job);
    waiting.push(job);
    dispatch();
  });
}

server.listen(0, "127.0.0.1", async () => {
  baseUrl = `http://127.0.0.1:${server.address().port}/`;
  for (let i = 0; i < workerCount; ++i) openWorker();
  // The socket only once the tabs are open: webgl_server.mjs waits for it, and reports a server that
  // exits before (no shared Chromium) with its output.
  try {
    await Promise.all([...workers.values()].map((w) => w.tab));
  } catch {
    return;  // giveUp says why
  }
  console.error(`page_server.mjs: tabs: ${workerCount}, of the shared Chromium in ${chromiumDir} on ${baseUrl}`);
  serveLines(socketPath, request, "page_server.mjs");
});
