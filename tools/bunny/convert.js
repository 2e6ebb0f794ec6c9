#!/usr/bin/env node
// Converts the `bunny` npm package (the Stanford bunny, Mikola Lysenko's
// public-domain packaging of the Stanford 3D Scanning Repository model) into a
// Wavefront OBJ: one `v` line per position, one `f` line per triangle
// (1-based indices), positions written exactly as the package stores them.
// Usage (from tools/bunny/):  npm ci && node convert.js ../../examples/scenes/bunny.obj
'use strict';
const fs = require('fs');
const bunny = require('bunny');
const pkg = require('bunny/package.json');

const out = process.argv[2];
if (!out) {
  console.error('usage: node convert.js <output.obj>');
  process.exit(2);
}
const { positions, cells } = bunny;
const lo = [Infinity, Infinity, Infinity];
const hi = [-Infinity, -Infinity, -Infinity];
for (const p of positions) {
  if (p.length !== 3 || !p.every(Number.isFinite)) throw new Error('bad position ' + JSON.stringify(p));
  for (let k = 0; k < 3; ++k) { lo[k] = Math.min(lo[k], p[k]); hi[k] = Math.max(hi[k], p[k]); }
}
for (const c of cells) {
  if (c.length !== 3 || !c.every((i) => Number.isInteger(i) && i >= 0 && i < positions.length))
    throw new Error('bad cell ' + JSON.stringify(c));
}
const lines = [];
lines.push('# The Stanford bunny (Stanford 3D Scanning Repository), from the npm package');
lines.push(`# ${pkg.name}@${pkg.version} (license: ${pkg.license}), converted by tools/bunny/convert.js.`);
lines.push(`# ${positions.length} vertices, ${cells.length} triangles, +Y up.`);
lines.push(`# bounds min ${lo.join(' ')} max ${hi.join(' ')}`);
for (const p of positions) lines.push(`v ${p[0]} ${p[1]} ${p[2]}`);
for (const c of cells) lines.push(`f ${c[0] + 1} ${c[1] + 1} ${c[2] + 1}`);
fs.writeFileSync(out, lines.join('\n') + '\n');
console.log(`wrote ${out}: ${positions.length} vertices, ${cells.length} triangles`);
