// A page's requests about its job, for both ways of running one: run_page.mjs (a page, or a tab, per
// job) and page_server.mjs (one page for every job of a ctest run, each job's routes under
// /jobs/<id>). Either way the page reads the same files of the job folder and what it posts lands in
// the same files there, so the C++ side reads a job the same whichever ran it.
import fs from "node:fs";
import path from "node:path";

// The job files a page may read (page_io.js's get), nothing else of the folder.
const jobFile = /^\/job\/(job\.json|shader\.frag|shader\.wgsl|inputs\.f32|tex_\d+\.f32|asset\.glb)$/;

// A module the page imports from its own folder (GET /lib/<name>.js): the file, or "" when there is none.
export function libFile(pagesDir, url) {
  const m = /^\/lib\/(\w+\.js)$/.exec(url);
  return m && fs.existsSync(path.join(pagesDir, m[1])) ? path.join(pagesDir, m[1]) : "";
}

// Answers the page's request `url` (its route within the job) with body `data` about the job in `dir`:
// GET /job/<file>, POST /renderer (kept in renderer.txt), /log (timing.txt), /results (written to
// `resultsFile`) or /error. Returns {done: true} once the results are written, {error: message} for a
// page's error, {} for the other job requests, and null, answering nothing, for what is none of these.
export function answerJobRequest(req, url, data, res, dir, resultsFile) {
  let m;
  if (req.method === "GET" && (m = jobFile.exec(url))) {
    res.writeHead(200, { "content-type": "application/octet-stream" }).end(fs.readFileSync(path.join(dir, m[1])));
    return {};
  }
  if (req.method !== "POST") return null;
  let answer;
  switch (url) {
    case "/renderer":
      fs.writeFileSync(path.join(dir, "renderer.txt"), data.toString() + "\n");
      answer = {};
      break;
    case "/log":
      fs.writeFileSync(path.join(dir, "timing.txt"), data.toString() + "\n");
      answer = {};
      break;
    case "/results":
      fs.writeFileSync(path.join(dir, resultsFile), data);
      answer = { done: true };
      break;
    case "/error":
      answer = { error: data.toString() };
      break;
    default:
      return null;
  }
  res.end();
  return answer;
}
