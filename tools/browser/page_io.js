// What a page served by run_page.mjs uses to talk to it: read a job file,
// post a result, a log line or an error.
export async function post(what, body) {
  await fetch(what, { method: "POST", body });
}
export async function get(file) {
  const r = await fetch(`/job/${file}`);
  if (!r.ok) throw new Error(`cannot read the job's ${file} (${r.status})`);
  return r;
}
