// The mutation score of glsl/snell (tests/mutation/README.md): every mutant of the chosen files, one at a
// time, against the tests that reach it. Not part of the test command: it takes about two hours on 2 cores.
//
//   node tests/mutation/run.mjs [--work=DIR] [--jobs=N] [--report=FILE] [--carry-from=COMMIT] [--prepare]
//                               [--only=ID,ID.. | --resume | --report-only] [FILE|FOLDER ...]
//
// FILE|FOLDER: paths under glsl/snell (default: intersect optics camera shade/two_interface.glsl
// shade/two_interface_shade.glsl). --work (default build/mutation): the source copy with the schemata
// (DIR/src), its build (DIR/build), the mutant list, the reach of each test and the results (DIR/results.json,
// DIR/report.md). --report also writes the Markdown report there (docs/mutation.md). --only reruns the
// named mutants (after a new test) and merges them into the last results; --resume runs the mutants the last
// (interrupted) run did not; --report-only writes the report of the last results again (after a change to
// tests/mutation/explained.tsv).
//
// Each mutant runs the tests that evaluate its site (recorded once per test on the unmutated build): the
// C++ unit tests (snell_unit_tests, snell_perspective_only_tests, snell_normal_fetch_tests), the CPU
// property test (snell_property_tests) and the parity cases on OSMesa (snell_parity_tests, Parity_osmesa.*),
// which compile the mutated GLSL beside the mutated C++. Killed: any of them fails, crashes or runs past its
// time limit (ten times the unmutated run, at least 30 s). Survived: all pass. Unreached: no test evaluates the site.
// To keep a run near two hours on 2 cores: the property test draws 100,000 hostile inputs per function
// (SNELL_PROPERTY_INPUTS), and the parity step runs the cases of the functions the mutated file defines.
import { spawn, spawnSync } from "node:child_process";
import crypto from "node:crypto";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import { fileURLToPath } from "node:url";

import { schemaOf } from "./schema.mjs";

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), "..", "..");
const args = process.argv.slice(2);
const option = (name, fallback) => {
  const a = args.find((x) => x.startsWith(`--${name}=`));
  return a ? a.slice(name.length + 3) : fallback;
};
for (const a of args.filter((x) => x.startsWith("--")))
  if (!["work", "jobs", "report", "only", "resume", "report-only", "carry-from", "prepare"].includes(a.slice(2).split("=")[0])) usage(`unknown option ${a}`);
function usage(message) {
  console.error(`run.mjs: ${message}\nusage: node tests/mutation/run.mjs [--work=DIR] [--jobs=N] [--report=FILE] ` +
    "[--carry-from=COMMIT] [--prepare] [--only=ID,ID.. | --resume | --report-only] [FILE|FOLDER under glsl/snell ...]");
  process.exit(2);
}
const work = path.resolve(option("work", path.join(root, "build", "mutation")));
const jobs = Math.max(1, Number(option("jobs", String(Math.min(2, os.cpus().length)))));
const only = option("only", "") ? new Set(option("only", "").split(",").map(Number)) : null;
const glslRoot = path.join(root, "glsl", "snell");
const chosen = args.filter((a) => !a.startsWith("--"));
const defaults = ["intersect", "optics", "camera", "shade/two_interface.glsl", "shade/two_interface_shade.glsl"];
const files = [];
for (const c of chosen.length ? chosen : defaults) {
  const p = path.join(glslRoot, c);
  if (!fs.existsSync(p)) usage(`no ${p}`);
  if (fs.statSync(p).isDirectory()) for (const f of fs.readdirSync(p).sort()) { if (f.endsWith(".glsl")) files.push(path.join(c, f)); }
  else files.push(c);
}
const log = (s) => console.log(`run.mjs: ${s}`);
function run(command, argv, options = {}) {
  const r = spawnSync(command, argv, { encoding: "utf8", maxBuffer: 1 << 28, ...options });
  if (r.error) throw new Error(`${command}: ${r.error.message}`);
  return r;
}
function must(command, argv, options = {}) {
  const r = run(command, argv, options);
  if (r.status !== 0) {
    console.error(`${r.stdout ?? ""}${r.stderr ?? ""}`.split("\n").slice(-40).join("\n"));
    throw new Error(`${command} ${argv.join(" ")} failed (${r.status ?? r.signal})`);
  }
  return r;
}

// 1. The source copy: the working tree as it is (tracked and untracked files git does not ignore), with the
// chosen files replaced by their schemata and the prelude defining SNELL_MUT.
const src = path.join(work, "src");
const listed = must("git", ["-C", root, "ls-files", "-z", "--cached", "--others", "--exclude-standard"]).stdout
  .split("\0").filter((f) => f && fs.existsSync(path.join(root, f)));
let mutants = [];
const schemata = new Map();
let nextId = 0;
const unparsed = [];
for (const f of files) {
  const s = schemaOf(fs.readFileSync(path.join(glslRoot, f), "utf8"), { file: f, firstId: nextId });
  nextId = s.nextId;
  mutants.push(...s.mutants);
  schemata.set(path.join("glsl", "snell", f), s.text);
  unparsed.push(...s.unparsed);
}
const schemaHash = crypto.createHash("sha256").update(JSON.stringify(mutants)).digest("hex").slice(0, 16);
const resultsFile = path.join(work, "results.json");
// A mutant's identity across edits of the one body: its file, operator, source line's text, code and change,
// and which of the mutants alike in that file it is (line numbers move when a file changes).
function identities(list, textOf) {
  const seen = new Map();
  return list.map((m) => {
    const base = [m.file, m.op, textOf(m), m.original, m.mutated].join("\t");
    const n = seen.get(base) ?? 0;
    seen.set(base, n + 1);
    return `${base}\t${n}`;
  });
}
const lineOf = (text) => { const lines = text.split("\n"); return (m) => (lines[m.line - 1] ?? "").trim().replace(/\s+/g, " "); };
// --carry-from=COMMIT: the last results were of the one body at COMMIT (checked: its mutants give the results'
// schema hash). Each of them that was killed and is still a mutant now (same identity) keeps its result; every
// other mutant runs. Sound while no test that killed one has been weakened since; a full run settles it.
const carryFrom = option("carry-from", "");
const carried = new Map();
// The last results of COMMIT's one body: DIR/results.json when it holds them, else the report written from
// them (--report's file, docs/mutation.md by default), which lists every survivor and unreached mutant by id:
// the others were killed. A fresh checkout has only the report.
function lastResultsAt(commit, oldMutants, oldHash) {
  const last = fs.existsSync(resultsFile) ? JSON.parse(fs.readFileSync(resultsFile, "utf8")) : null;
  if (last?.schemaHash === oldHash) return last.results;
  const reportFile = path.resolve(option("report", path.join(root, "docs", "mutation.md")));
  const text = fs.existsSync(reportFile) ? fs.readFileSync(reportFile, "utf8") : "";
  const of = /^Mutants of glsl\/snell, commit (\w+),/.exec(text)?.[1];
  const same = (a, b) => run("git", ["-C", root, "rev-parse", `${a}^{commit}`]).stdout === run("git", ["-C", root, "rev-parse", `${b}^{commit}`]).stdout;
  if (!of || !same(of, commit))
    usage(`--carry-from=${commit}: ${last ? `${resultsFile} holds another one body's results` : `no results in ${resultsFile}`}, ` +
      `and ${reportFile} is ${of ? `of commit ${of}` : "no report of a run"}`);
  const listed = new Set([...text.matchAll(/^- (\d+) /gm)].map((m) => Number(m[1])));
  const all = /^\| all \| (\d+) \| (\d+) \|/m.exec(text);
  if (!all || Number(all[1]) !== oldMutants.length || Number(all[2]) !== oldMutants.length - listed.size)
    throw new Error(`--carry-from=${commit}: ${reportFile}'s counts do not fit commit ${commit}'s ${oldMutants.length} mutants`);
  log(`--carry-from=${commit}: the kills from ${path.relative(root, reportFile)} (no results of that run in ${resultsFile})`);
  return oldMutants.filter((m) => !listed.has(m.id)).map((m) => ({ id: m.id, status: "killed", by: path.relative(root, reportFile) }));
}
if (carryFrom) {
  const oldMutants = [], oldText = new Map();
  let id = 0;
  for (const f of files) {
    const r = run("git", ["-C", root, "show", `${carryFrom}:glsl/snell/${f}`]);
    if (r.status !== 0) continue;  // a file new since
    const s = schemaOf(r.stdout, { file: f, firstId: id });
    id = s.nextId;
    oldMutants.push(...s.mutants);
    oldText.set(f, lineOf(r.stdout));
  }
  const oldHash = crypto.createHash("sha256").update(JSON.stringify(oldMutants)).digest("hex").slice(0, 16);
  const lastResults = lastResultsAt(carryFrom, oldMutants, oldHash);
  const newText = new Map(files.map((f) => [f, lineOf(fs.readFileSync(path.join(glslRoot, f), "utf8"))]));
  const byKey = new Map(identities(mutants, (m) => newText.get(m.file)(m)).map((k, i) => [k, mutants[i]]));
  const lastById = new Map(lastResults.map((r) => [r.id, r]));
  identities(oldMutants, (m) => oldText.get(m.file)(m)).forEach((k, i) => {
    const was = lastById.get(oldMutants[i].id), now = byKey.get(k);
    if (was?.status === "killed" && now) carried.set(now.id, { ...now, status: "killed", by: `${was.by} (at ${carryFrom})`, tests: was.tests });
  });
  log(`--carry-from=${carryFrom}: ${carried.size} of ${mutants.length} mutants keep their kill`);
}
if (args.includes("--report-only")) {
  const last = fs.existsSync(resultsFile) ? JSON.parse(fs.readFileSync(resultsFile, "utf8")) : null;
  if (last?.schemaHash !== schemaHash) throw new Error(`no results of these mutants in ${resultsFile}: run without --report-only`);
  writeReport(last.results);
  process.exit(0);
}

const preludeRel = path.join("glsl", "snell", "prelude.glsl");
const mutationBlock = `
/* mutation testing (tests/mutation): SNELL_MUT(k) is true when mutant k is the one under test. C++: the
   environment's SNELL_MUTANT, and SNELL_MUTANT_REACH names a file that receives every site evaluated;
   GLSL: the literal in mutant.glsl, rewritten for each mutant (a file C++ never reads, so the C++ build
   stays as it is). */
#if defined(SNELL_LANG_CXX)
struct SnellMutation {
  int id = -1;
  const char* reach = nullptr;
  unsigned char seen[${nextId + 1}] = {};
  SnellMutation() {
    if (const char* e = std::getenv("SNELL_MUTANT")) id = std::atoi(e);
    reach = std::getenv("SNELL_MUTANT_REACH");
  }
  ~SnellMutation() {
    if (reach == nullptr) return;
    if (std::FILE* f = std::fopen(reach, "w")) {
      for (int k = 0; k < ${nextId}; ++k)
        if (seen[k]) std::fprintf(f, "%d\\n", k);
      std::fclose(f);
    }
  }
};
inline SnellMutation& snellMutation() {
  static SnellMutation m;
  return m;
}
inline bool snellMutantIs(int k) {
  SnellMutation& m = snellMutation();
  if (m.reach) __atomic_store_n(&m.seen[k], 1, __ATOMIC_RELAXED);
  return m.id == k;
}
#  define SNELL_MUT(k) (::snell::snellMutantIs(k))
#else
#  include "mutant.glsl"
#  define SNELL_MUT(k) (SNELL_MUTANT == (k))
#endif
`;
const preludeText = fs.readFileSync(path.join(root, preludeRel), "utf8");
const guard = "#define SNELL_PRELUDE_GLSL\n";
if (!preludeText.includes(guard)) throw new Error(`${preludeRel} has no '${guard.trim()}'`);
// The block goes after the language is known (SNELL_LANG_CXX), before any function.
const langEnd = preludeText.indexOf("#ifndef SNELL_FN\n");
if (langEnd < 0) throw new Error(`${preludeRel}: no '#ifndef SNELL_FN' to put the mutation block before`);
const preludeWith = preludeText.slice(0, langEnd) + mutationBlock + preludeText.slice(langEnd);

fs.mkdirSync(src, { recursive: true });
for (const f of listed) {
  const to = path.join(src, f);
  const text = schemata.get(f) ?? (f === preludeRel ? preludeWith : null);
  fs.mkdirSync(path.dirname(to), { recursive: true });
  if (text !== null) {
    if (!fs.existsSync(to) || fs.readFileSync(to, "utf8") !== text) fs.writeFileSync(to, text);
  } else if (!fs.existsSync(to) || fs.statSync(to).mtimeMs < fs.statSync(path.join(root, f)).mtimeMs) {
    fs.copyFileSync(path.join(root, f), to);
  }
}
for (const nm of ["tools/webgpu/node_modules", "node_modules", "examples/web/node_modules"]) {
  const from = path.join(root, nm), to = path.join(src, nm);
  if (fs.existsSync(from) && !fs.existsSync(to)) fs.symlinkSync(from, to);
}
const mutantFile = path.join(src, "glsl", "snell", "mutant.glsl");
const setGlslMutant = (id) => fs.writeFileSync(mutantFile, `#define SNELL_MUTANT ${id}\n`);
setGlslMutant(-1);
log(`${mutants.length} mutants in ${files.length} files${unparsed.length ? `; not parsed, left unmutated: ${unparsed.join("; ")}` : ""}`);
// --prepare: the source copy and DIR/mutants.tsv only (id, file:line, operator, code, change, and the last
// result when one is known), for writing a test against one mutant: build a test file against DIR/src and
// run it with SNELL_MUTANT=ID.
if (args.includes("--prepare")) {
  const known = fs.existsSync(resultsFile) ? JSON.parse(fs.readFileSync(resultsFile, "utf8")) : null;
  const last = new Map(known?.schemaHash === schemaHash ? known.results.map((r) => [r.id, r]) : carried);
  fs.writeFileSync(path.join(work, "mutants.tsv"), mutants.map((m) =>
    [m.id, `${m.file}:${m.line}`, m.op, m.original, m.mutated || "(dropped)", last.get(m.id)?.status ?? "not run"].join("\t"))
    .join("\n") + "\n");
  log(`the source copy is ${src}; the mutants are listed in ${path.join(work, "mutants.tsv")}`);
  process.exit(0);
}

// 2. One build of the copy (the mutants are chosen at run time).
const build = path.join(work, "build");
// Each kind of test, in the order a mutant runs them (the quickest to fail first).
const binaries = {
  unit: path.join(build, "tests", "snell_unit_tests"),
  perspective: path.join(build, "tests", "snell_perspective_only_tests"),
  normalFetch: path.join(build, "tests", "snell_normal_fetch_tests"),
  property: path.join(build, "tests", "property", "snell_property_tests"),
  parity: path.join(build, "tests", "snell_parity_tests"),
};
log(`building ${build} (the first build takes about 10 minutes on 2 cores)`);
must("cmake", ["-S", src, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DCMAKE_CXX_FLAGS=-include cstdlib -include cstdio"]);
must("cmake", ["--build", build, "-j", String(os.cpus().length), "--target",
  ...Object.values(binaries).map((b) => path.basename(b))], { stdio: ["ignore", "ignore", "pipe"] });

// 3. The tests, and which sites each evaluates (on the unmutated build).
function listTests(binary, keep) {
  const out = must(binary, ["--gtest_list_tests"], { cwd: path.dirname(binary) }).stdout;
  const tests = [];
  let suite = "";
  for (const line of out.split("\n")) {
    if (!line.trim()) continue;
    if (!line.startsWith(" ")) suite = line.trim();
    else tests.push(suite + line.trim().split(/\s+/)[0]);
  }
  return tests.filter(keep);
}
// Parity on one runtime, OSMesa.
const suites = Object.fromEntries(Object.entries(binaries).map(([kind, binary]) =>
  [kind, listTests(binary, kind === "parity" ? (t) => t.startsWith("Parity_osmesa.") : () => true)]));
const reachFile = path.join(work, "reach.json");
let reach = fs.existsSync(reachFile) ? JSON.parse(fs.readFileSync(reachFile, "utf8")) : null;
const runOne = (binary, filter, env, timeoutMs, extra = []) => new Promise((resolve) => {
  const started = Date.now();
  const child = spawn(binary, [`--gtest_filter=${filter}`, "--gtest_also_run_disabled_tests", ...extra],
    { cwd: path.dirname(binary), env: { ...process.env, ...env }, stdio: ["ignore", "pipe", "pipe"] });
  let out = "";
  child.stdout.on("data", (d) => { out = (out + d).slice(-20000); });
  child.stderr.on("data", (d) => { out = (out + d).slice(-20000); });
  const timer = setTimeout(() => child.kill("SIGKILL"), timeoutMs);
  child.on("exit", (code, signal) => {
    clearTimeout(timer);
    const ms = Date.now() - started;
    resolve({ code, signal, ms, timedOut: signal === "SIGKILL" && ms >= timeoutMs, out });
  });
});
async function pool(items, worker) {
  let next = 0;
  await Promise.all(Array.from({ length: jobs }, async () => {
    while (next < items.length) await worker(items[next++]);
  }));
}
// Recorded once per schema; a test added since is recorded on its own (the others' reach is unchanged
// unless their code changed: delete DIR/reach.json then).
if (!reach || reach.schemaHash !== schemaHash) reach = { schemaHash, tests: {} };
const unrecorded = Object.entries(suites).flatMap(([kind, tests]) => tests.map((t) => [kind, t]))
  .filter(([kind, t]) => !reach.tests[`${kind}\t${t}`]);
if (unrecorded.length) {
  log(`recording which sites each of ${unrecorded.length} tests evaluates`);
  setGlslMutant(-1);
  const all = unrecorded;
  const failed = [];
  let done = 0;
  await pool(all, async ([kind, test]) => {
    const file = path.join(work, "reach", `${kind}.${test}.txt`);
    fs.mkdirSync(path.dirname(file), { recursive: true });
    const r = await runOne(binaries[kind], test, { SNELL_MUTANT: "-1", SNELL_MUTANT_REACH: file }, 900000);
    if (r.code !== 0) failed.push(`${kind} ${test} (${r.code ?? r.signal}):\n${r.out.split("\n").slice(-15).join("\n")}`);
    const sites = fs.existsSync(file) ? fs.readFileSync(file, "utf8").split("\n").filter(Boolean).map(Number) : [];
    reach.tests[`${kind}\t${test}`] = { ms: r.ms, sites };
    if (++done % 50 === 0) log(`  ${done} of ${all.length} tests`);
  });
  if (failed.length) throw new Error(`the unmutated build fails ${failed.length} tests:\n${failed.join("\n")}`);
  fs.writeFileSync(reachFile, JSON.stringify(reach));
}
const reachedBy = new Map();
for (const [key, { ms, sites }] of Object.entries(reach.tests)) {
  const [kind, test] = key.split("\t");
  for (const s of sites) {
    if (!reachedBy.has(s)) reachedBy.set(s, []);
    reachedBy.get(s).push({ kind, test, ms });
  }
}

// The functions each file defines (for its parity cases).
const definedIn = new Map(files.map((f) => [f, new Set([...fs.readFileSync(path.join(glslRoot, f), "utf8")
  .matchAll(/^SNELL_FN(?:_INLINE)?\s+\w+\s+(\w+)\s*\(/gm)].map((x) => x[1]))]));
// The property test's hostile inputs per function for a mutant (the unmutated run has 1,000,000).
const propertyInputs = process.env.SNELL_PROPERTY_INPUTS ?? "100000";

// 4. Each mutant against the tests that reach it. The GLSL literal is one file, so the parity step of one
// mutant runs at a time.
const previous = fs.existsSync(resultsFile) ? JSON.parse(fs.readFileSync(resultsFile, "utf8")) : null;
const results = new Map(previous?.schemaHash === schemaHash ? previous.results.map((r) => [r.id, r]) : carried);
let glslLock = Promise.resolve();
const resume = args.includes("--resume") || carried.size > 0;
const todo = mutants.filter((m) => (only ? only.has(m.id) : !resume || !results.has(m.id)));
let finished = 0;
const startedAt = Date.now();
await pool(todo, async (m) => {
  const tests = reachedBy.get(m.id) ?? [];
  let status = tests.length ? "survived" : "unreached", by = "";
  for (const kind of Object.keys(binaries)) {
    let mine = tests.filter((t) => t.kind === kind);
    // Parity: the cases of the functions the file defines (each reaches most sites below it); a file with
    // none, the three quickest cases that reach the site.
    if (kind === "parity") {
      const own = mine.filter((t) => definedIn.get(m.file).has(t.test.split(".")[1]));
      mine = own.length ? own : [...mine].sort((a, b) => a.ms - b.ms).slice(0, 3);
    }
    if (!mine.length || status === "killed") continue;
    const timeoutMs = Math.max(30000, 10 * mine.reduce((a, t) => a + t.ms, 0));
    const go = () => runOne(binaries[kind], mine.map((t) => t.test).join(":"),
      { SNELL_MUTANT: String(m.id), SNELL_PROPERTY_INPUTS: propertyInputs },
      timeoutMs, ["--gtest_fail_fast"]);
    let r;
    if (kind === "parity") {
      const turn = glslLock.then(async () => { setGlslMutant(m.id); r = await go(); setGlslMutant(-1); });
      glslLock = turn.catch(() => {});
      await turn;
    } else {
      r = await go();
    }
    if (r.code !== 0) {
      status = "killed";
      const failing = /\[  FAILED  \] (\S+)/.exec(r.out)?.[1];
      by = `${kind}: ${r.timedOut ? "time limit" : r.signal ? r.signal : failing ?? `exit ${r.code}`}`;
    }
  }
  results.set(m.id, { ...m, status, by, tests: tests.length });
  if (++finished % 25 === 0 || finished === todo.length) {
    // Saved as it goes: an interrupted run keeps what it measured (rerun the rest with --only).
    fs.writeFileSync(resultsFile, JSON.stringify({ schemaHash, results: [...results.values()] }, null, 1));
    const eta = ((Date.now() - startedAt) / finished) * (todo.length - finished) / 60000;
    log(`  ${finished} of ${todo.length} mutants, about ${eta.toFixed(0)} min left`);
  }
});
setGlslMutant(-1);
const all = mutants.map((m) => results.get(m.id)).filter(Boolean);
fs.writeFileSync(resultsFile, JSON.stringify({ schemaHash, results: all }, null, 1));

writeReport(all);

function writeReport(all) {
// 5. The report: per folder, per file, the survivors. A survivor is explained by a line of
// tests/mutation/explained.tsv (file, operator, the source line, the code, the change, why: tab-separated;
// matched by the line's text, not its number, which moves as the file changes).
const explainedFile = path.join(root, "tests", "mutation", "explained.tsv");
const explained = new Map();
if (fs.existsSync(explainedFile))
  for (const line of fs.readFileSync(explainedFile, "utf8").split("\n")) {
    if (!line.trim() || line.startsWith("#")) continue;
    const [file, op, text, original, mutated, why] = line.split("\t");
    if (!why) throw new Error(`${explainedFile}: a line needs 6 tab-separated fields: ${line}`);
    // A dropped statement has no mutated code: "(dropped)" there, as mutants.tsv writes it.
    explained.set([file, op, text, original, mutated === "(dropped)" ? "" : mutated].join("\t"), why);
  }
const sourceLines = new Map();
const lineText = (r) => {
  if (!sourceLines.has(r.file)) sourceLines.set(r.file, fs.readFileSync(path.join(glslRoot, r.file), "utf8").split("\n"));
  return (sourceLines.get(r.file)[r.line - 1] ?? "").trim().replace(/\s+/g, " ");
};
const whyOf = (r) => explained.get([r.file, r.op, lineText(r), r.original, r.mutated].join("\t"));
const tally = (list) => {
  const k = list.filter((r) => r.status === "killed").length;
  const s = list.filter((r) => r.status === "survived").length;
  const e = list.filter((r) => r.status === "survived" && whyOf(r)).length;
  const u = list.filter((r) => r.status === "unreached").length;
  // The usual mutation score leaves out the mutants no test can kill: killed / (all - explained).
  return { k, s, e, u, n: list.length, score: list.length ? (100 * k) / list.length : 0,
    scoreOfRest: list.length > e ? (100 * k) / (list.length - e) : 0 };
};
const row = (name, list) => {
  const t = tally(list);
  return `| ${name} | ${t.n} | ${t.k} | ${t.s} | ${t.e} | ${t.u} | ${t.score.toFixed(1)} % | ${t.scoreOfRest.toFixed(1)} % |`;
};
const header = (what) => [`| ${what} | mutants | killed | survived | of them explained | unreached | score | of the unexplained |`,
  "|---|---:|---:|---:|---:|---:|---:|---:|"];
const folderOf = (f) => f.split("/")[0];
  const lines = [`Mutants of glsl/snell, commit ${must("git", ["-C", root, "rev-parse", "--short", "HEAD"]).stdout.trim()}, ` +
  `${new Date().toISOString().slice(0, 16).replace("T", " ")} UTC (tests/mutation/run.mjs). Score: killed / all; ` +
  "an explained survivor is one tests/mutation/explained.tsv says why no test can or should kill; the last " +
  "column leaves those out (killed / (all - explained)).",
  ...(() => {
    const kept = all.filter((r) => / \(at \w+\)$/.test(r.by ?? "")).length;
    return kept ? ["", `${kept} of the kills were kept, not run again, from a run of an earlier one body ` +
      "(--carry-from: the same mutants; sound while no test that killed one has been weakened since); every " +
      "other mutant ran on this tree."] : [];
  })(), "",
...header("folder")];
for (const folder of [...new Set(files.map(folderOf))]) lines.push(row(`${folder}/`, all.filter((r) => folderOf(r.file) === folder)));
lines.push(row("all", all), "", ...header("file"));
for (const f of files) lines.push(row(f, all.filter((r) => r.file === f)));
lines.push("", ...header("operator"));
for (const op of [...new Set(all.map((r) => r.op))].sort()) lines.push(row(op, all.filter((r) => r.op === op)));
lines.push("", "Survivors and unreached mutants (id, file:line, operator, the code, the change; why, when explained):", "");
const code = (t) => `\`${t.replace(/`/g, "'").slice(0, 120)}\``;
for (const r of all.filter((x) => x.status !== "killed"))
  lines.push(`- ${r.id} ${r.file}:${r.line} ${r.op} ${r.status === "unreached" ? "(unreached) " : ""}${code(r.original)}` +
    `${r.mutated ? ` -> ${code(r.mutated)}` : " dropped"}${whyOf(r) ? `: ${whyOf(r)}` : ""}`);
fs.writeFileSync(path.join(work, "report.md"), lines.join("\n") + "\n");
if (option("report", "")) fs.writeFileSync(option("report", ""), lines.join("\n") + "\n");
log(`${all.length} mutants: ${tally(all).k} killed, ${tally(all).s} survived, ${tally(all).u} unreached ` +
  `(${tally(all).score.toFixed(1)} %); ${path.join(work, "report.md")}`);
}
