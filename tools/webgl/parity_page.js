// The WebGL 2 parity runtime's page (served by tools/browser/run_page.mjs): one job, parity_job.js.
import { get, post } from "/browser/page_io.js";
import { run } from "/lib/parity_job.js";

run({ get, post }).catch((e) => post("/error", `${e.message ?? e}`));
