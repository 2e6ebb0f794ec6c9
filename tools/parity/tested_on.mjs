// The README's "tested on" tables from a parity run's report lines
// ("[parity] <function> file=... backend=... cases=N mismatches=M flushed=F
// maxAbs=A maxRel=R digests in=... cpu=C gpu=G runtime="..." renderer="...", in ctest's LastTest.log):
// per runtime the functions, cases, mismatches, flushed-denormal matches and
// bit-identical functions; then runtime x function family (the folder of
// glsl/snell a function is defined in; the texture hooks apart) with the cases
// and the largest relative difference.
//
//   node tools/parity/tested_on.mjs build/Testing/Temporary/LastTest.log [more logs]
import fs from "node:fs";
import path from "node:path";
import { fileURLToPath } from "node:url";

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), "../..");
const logs = process.argv.slice(2);
if (!logs.length) {
  console.error("usage: tested_on.mjs LastTest.log [more logs]");
  process.exit(2);
}

// function -> family, from the SNELL_FN definitions under glsl/snell/<family>/.
const family = new Map();
const walk = (dir) => {
  for (const e of fs.readdirSync(dir, { withFileTypes: true })) {
    const p = path.join(dir, e.name);
    if (e.isDirectory()) walk(p);
    else if (p.endsWith(".glsl")) {
      const rel = path.relative(path.join(root, "glsl", "snell"), p).split(path.sep);
      for (const m of fs.readFileSync(p, "utf8").matchAll(/SNELL_FN(?:_INLINE)?\s+\w+\s+(snell\w+)\s*\(/g))
        family.set(m[1], rel.length > 1 ? rel[0] : "prelude");
    }
  }
};
walk(path.join(root, "glsl", "snell"));

// Each report line names its runtime (backend= its name, runtime="..." the language and device, as the
// runtime describes itself: snell::gpu::Runtime); the tables list them by that description.
const runs = new Map();  // runtime -> function -> record (the last one wins)
const line = /^\[parity\] (\w+) file=\S+ backend=(\S+) cases=(\d+) mismatches=(\d+) flushed=(\d+) maxAbs=(\S+) maxRel=(\S+) digests in=\w+ cpu=(\w+) gpu=(\w+) runtime="([^"]*)"/;
for (const text of logs.flatMap((log) => fs.readFileSync(log, "utf8").split("\n"))) {
  const m = line.exec(text);
  if (!m) continue;
  const runtime = `${m[10]} (${m[2]})`;
  if (!runs.has(runtime)) runs.set(runtime, new Map());
  runs.get(runtime).set(m[1], { cases: +m[3], mismatches: +m[4], flushed: +m[5], maxRel: +m[7], identical: m[8] === m[9] });
}
for (const [runtime, fns] of runs) if (fns.size === 0) runs.delete(runtime);
const sorted = [...runs.entries()].sort(([a], [b]) => a.localeCompare(b));
runs.clear();
for (const [runtime, fns] of sorted) runs.set(runtime, fns);
if (runs.size === 0) {
  console.error(`no parity report lines in ${logs.join(", ")}`);
  process.exit(1);
}
const fmt = (n) => n.toLocaleString("en-US");
const families = [...new Set([...family.values(), "hooks"])].sort();
const familyOf = (fn) => family.get(fn) ?? (fn.startsWith("SNELL_") ? "hooks" : "?");

console.log("| runtime | functions | cases | mismatches | flushed | bit-identical |");
console.log("|---|---:|---:|---:|---:|---:|");
for (const [runtime, fns] of runs) {
  const all = [...fns.values()];
  const sum = (k) => all.reduce((a, r) => a + r[k], 0);
  console.log(`| ${runtime} | ${fns.size} | ${fmt(sum("cases"))} | ${sum("mismatches")} | ${sum("flushed")} | ${all.filter((r) => r.identical).length} |`);
}
console.log("");
console.log(`| runtime | ${families.join(" | ")} |`);
console.log(`|---|${families.map(() => "---:").join("|")}|`);
for (const [runtime, fns] of runs) {
  const cells = families.map((f) => {
    const rs = [...fns.entries()].filter(([fn]) => familyOf(fn) === f).map(([, r]) => r);
    if (!rs.length) return "-";
    const cases = rs.reduce((a, r) => a + r.cases, 0);
    const rel = Math.max(...rs.map((r) => r.maxRel));
    return `${fmt(cases)}, ${rel.toPrecision(2)}`;
  });
  console.log(`| ${runtime} | ${cells.join(" | ")} |`);
}
