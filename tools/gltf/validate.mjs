#!/usr/bin/env node
// Validates glTF 2.0 files (.glb or .gltf) with the Khronos glTF-Validator
// (npm gltf-validator, pinned in package-lock.json).
//
// Usage:  node tools/gltf/validate.mjs [--all] FILE...
//
// For each file it prints one line with the counts of errors, warnings, infos
// and hints, then every error with its JSON pointer (with --all, every
// warning, info and hint too). External resources (buffers and images given
// by a relative URI) are read from beside the file; data: URIs are read by
// the validator itself; any other scheme is refused (and so reported as an
// error). Exit status: 1 if any file has an error or cannot be read or
// parsed, 2 on a usage error, 0 otherwise.
// Needs `npm ci --prefix tools/gltf` first.

import fs from 'node:fs';
import path from 'node:path';
import { validateBytes, version } from 'gltf-validator';

const SEVERITY = ['error', 'warning', 'info', 'hint'];

function usage(message) {
  if (message) console.error(`validate.mjs: ${message}`);
  console.error('usage: node tools/gltf/validate.mjs [--all] FILE...');
  process.exit(2);
}

const args = process.argv.slice(2);
let all = false;
const files = [];
for (const a of args) {
  if (a === '--all') all = true;
  else if (a === '--help' || a === '-h') usage();
  else if (a.startsWith('--')) usage(`unknown option ${a}`);
  else files.push(a);
}
if (files.length === 0) usage('no files given');

// Reads an external resource named by a relative URI, beside the asset.
function resourceReader(file) {
  const dir = path.dirname(path.resolve(file));
  return async (uri) => {
    if (/^[a-zA-Z][a-zA-Z0-9+.-]*:/.test(uri)) throw new Error(`not a relative URI: ${uri}`);
    return new Uint8Array(await fs.promises.readFile(path.resolve(dir, decodeURIComponent(uri))));
  };
}

let failed = false;
for (const file of files) {
  let bytes;
  try {
    bytes = new Uint8Array(fs.readFileSync(file));
  } catch (e) {
    console.log(`${file}: cannot read: ${e.message}`);
    failed = true;
    continue;
  }
  let report;
  try {
    report = await validateBytes(bytes, {
      uri: path.basename(file),
      maxIssues: 0, // unlimited
      writeTimestamp: false,
      externalResourceFunction: resourceReader(file),
    });
  } catch (e) {
    // Rejected: the input is neither glTF JSON nor GLB, or the options were invalid.
    console.log(`${file}: cannot validate: ${e?.message ?? e}`);
    failed = true;
    continue;
  }
  const i = report.issues;
  console.log(
    `${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ${i.numHints} hints` +
      (i.truncated ? ' (issue list truncated)' : ''),
  );
  for (const m of i.messages) {
    if (m.severity !== 0 && !all) continue;
    // JSON issues carry a pointer; GLB container issues a byte offset instead.
    const where = m.pointer !== undefined ? m.pointer : m.offset !== undefined ? `byte ${m.offset}` : '(no pointer)';
    console.log(`  ${SEVERITY[m.severity] ?? `severity ${m.severity}`} ${m.code} at ${where}: ${m.message}`);
  }
  if (i.numErrors > 0) failed = true;
}
if (all) console.log(`(glTF-Validator ${version()})`);
process.exit(failed ? 1 : 0);
