// What a page uses to talk to the server of its job: read a job file, post a result, a log line or an
// error. `base` is where the server keeps the job's routes: "" for run_page.mjs (one job per page),
// "/jobs/<id>" for a job of page_server.mjs (every job in one page).
export function jobIo(base) {
  return {
    async post(what, body) {
      await fetch(`${base}${what}`, { method: "POST", body });
    },
    async get(file) {
      const r = await fetch(`${base}/job/${file}`);
      if (!r.ok) throw new Error(`cannot read the job's ${file} (${r.status})`);
      return r;
    },
  };
}
export const { get, post } = jobIo("");
