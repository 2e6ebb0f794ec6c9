#!/usr/bin/env node
// Generates the bundled glTF 2.0 assets in examples/scenes/gltf/:
//
//   glass_bunny.glb          the scanned Stanford bunny (npm `bunny`) in green-tinted glass
//   suzanne_paperweight.glb  an opaque Suzanne (npm `@pmndrs/assets`) inside a rounded glass block
//   ior_grid.glb             a 3 x 3 grid of glass spheres, IOR 1.1 to 1.9
//   flint_ball.glb           a dense flint glass ball: dispersion (KHR_materials_dispersion)
//
// Each has a glass material written with KHR_materials_transmission, _ior and
// _volume (and _dispersion where the glass disperses), one perspective camera (aspect ratio 1) framing the content and an
// opaque backdrop quad textured with a generated test card (PNG, sRGB).
// Every glass mesh is checked here to be closed, manifold, consistently wound
// counter-clockwise seen from outside (positive volume) and to have unit
// per-vertex normals; the script fails otherwise.
//
// Deterministic: the same package versions (tools/gltf/package-lock.json) and
// the same Node.js give the same bytes on every run (the PNG goes through
// Node's zlib, so another zlib could compress it differently).
//
// Usage (from the repository root):
//   npm ci --prefix tools/gltf && node tools/gltf/make_assets.mjs [OUT_DIR]
// OUT_DIR defaults to examples/scenes/gltf/ beside this repository's tools/.

import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { Document, NodeIO } from '@gltf-transform/core';
import {
  KHRDracoMeshCompression,
  KHRMaterialsDispersion,
  KHRMaterialsIOR,
  KHRMaterialsTransmission,
  KHRMaterialsVolume,
} from '@gltf-transform/extensions';
import draco3d from 'draco3dgltf';
import { PNG } from 'pngjs';
import bunny from 'bunny';
import suzanneDataUri from '@pmndrs/assets/models/suzi.glb.js';

const here = path.dirname(fileURLToPath(import.meta.url));
// The installed packages' own package.json (some do not export it, so read the file).
const packageJson = (name) => JSON.parse(fs.readFileSync(path.join(here, 'node_modules', name, 'package.json'), 'utf8'));
const version = (name) => packageJson(name).version;
const outDir = path.resolve(process.argv[2] ?? path.join(here, '..', '..', 'examples', 'scenes', 'gltf'));
const GENERATOR = `snell tools/gltf/make_assets.mjs (glTF-Transform ${version('@gltf-transform/core')})`;
const MAX_BYTES = 2 * 1024 * 1024;

// ---------------------------------------------------------------- small math

const deg = (d) => (d * Math.PI) / 180;
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const len = (a) => Math.sqrt(dot(a, a));
const normalize = (a) => {
  const l = len(a);
  return [a[0] / l, a[1] / l, a[2] / l];
};
// Quaternion [x, y, z, w] for a rotation by `angle` radians about a unit axis.
const quatAxisAngle = (axis, angle) => {
  const s = Math.sin(angle / 2);
  return [axis[0] * s, axis[1] * s, axis[2] * s, Math.cos(angle / 2)];
};
const quatRotate = (q, v) => {
  // v' = v + 2 w (u x v) + 2 u x (u x v), u = q.xyz
  const u = [q[0], q[1], q[2]];
  const t = cross(u, v).map((c) => 2 * c);
  const ut = cross(u, t);
  return [v[0] + q[3] * t[0] + ut[0], v[1] + q[3] * t[1] + ut[1], v[2] + q[3] * t[2] + ut[2]];
};
const quatConj = (q) => [-q[0], -q[1], -q[2], q[3]];
// Beer-Lambert: the colour left after `distance` for absorption coefficients sigma (per unit).
const attenuationColorFor = (sigma, distance) => sigma.map((s) => Math.exp(-s * distance));

// ---------------------------------------------------------------- meshes
// A mesh here is { positions: [[x,y,z]...], normals: [[x,y,z]...] | null,
//                  uvs: [[u,v]...] | null, triangles: [[a,b,c]...] }.

// Area-weighted smooth vertex normals (sum of the triangles' cross products).
function smoothNormals(positions, triangles) {
  const acc = positions.map(() => [0, 0, 0]);
  for (const [a, b, c] of triangles) {
    const n = cross(sub(positions[b], positions[a]), sub(positions[c], positions[a]));
    for (const i of [a, b, c]) for (let k = 0; k < 3; ++k) acc[i][k] += n[k];
  }
  return acc.map((n) => {
    if (!(len(n) > 0)) throw new Error('vertex with a zero normal (unused or only degenerate triangles)');
    return normalize(n);
  });
}

// Topology of a triangle mesh: boundary edges (used by one triangle),
// non-manifold edges (more than two), edges whose two triangles run them the
// same way (inconsistent winding), distinct indices at equal positions
// (seams), unused vertices, degenerate triangles, the signed volume (positive:
// counter-clockwise seen from outside) and the Euler characteristic.
function topology(mesh) {
  const { positions: P, triangles: T } = mesh;
  const edges = new Map();
  let volume = 0;
  let degenerate = 0;
  for (const [a, b, c] of T) {
    const [A, B, C] = [P[a], P[b], P[c]].map((p) => p.map(Math.fround)); // as stored (float32)
    if (a === b || b === c || c === a || len(cross(sub(B, A), sub(C, A))) === 0) ++degenerate;
    for (const [u, v] of [[a, b], [b, c], [c, a]]) {
      const key = u < v ? u * 4294967296 + v : v * 4294967296 + u;
      const e = edges.get(key) ?? { count: 0, direction: 0 };
      e.count += 1;
      e.direction += u < v ? 1 : -1;
      edges.set(key, e);
    }
    volume += dot(P[a], cross(P[b], P[c])) / 6;
  }
  let boundary = 0;
  let nonManifold = 0;
  let misoriented = 0;
  for (const e of edges.values()) {
    if (e.count === 1) ++boundary;
    else if (e.count > 2) ++nonManifold;
    else if (e.direction !== 0) ++misoriented;
  }
  const used = new Set();
  for (const t of T) for (const i of t) used.add(i);
  const seen = new Set();
  let duplicatePositions = 0;
  for (const i of used) {
    const key = P[i].map(Math.fround).join(','); // as stored (float32)
    if (seen.has(key)) ++duplicatePositions;
    else seen.add(key);
  }
  return {
    vertices: P.length,
    triangles: T.length,
    boundary,
    nonManifold,
    misoriented,
    duplicatePositions,
    unused: P.length - used.size,
    degenerate,
    volume,
    euler: used.size - edges.size + T.length,
  };
}

// Fails unless the mesh is a closed, consistently outward-wound 2-manifold
// with one vertex per position and unit normals.
function requireClosedGlass(name, mesh) {
  const t = topology(mesh);
  const problems = [];
  if (t.boundary) problems.push(`${t.boundary} boundary edges`);
  if (t.nonManifold) problems.push(`${t.nonManifold} non-manifold edges`);
  if (t.misoriented) problems.push(`${t.misoriented} inconsistently wound edges`);
  if (t.duplicatePositions) problems.push(`${t.duplicatePositions} duplicated positions (seams)`);
  if (t.unused) problems.push(`${t.unused} unused vertices`);
  if (t.degenerate) problems.push(`${t.degenerate} degenerate triangles`);
  if (!(t.volume > 0)) problems.push(`volume ${t.volume} (inward winding)`);
  for (const n of mesh.normals) if (Math.abs(len(n) - 1) > 1e-6) {
    problems.push('a normal that is not unit length');
    break;
  }
  if (problems.length) throw new Error(`${name}: not a closed outward-wound glass mesh: ${problems.join(', ')}`);
  return t;
}

// The Stanford bunny from npm `bunny`, centred on its bounding box and scaled
// so that its largest extent is `size` (as the lab's "fit_size" does).
function bunnyMesh(size) {
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (const p of bunny.positions) for (let k = 0; k < 3; ++k) {
    lo[k] = Math.min(lo[k], p[k]);
    hi[k] = Math.max(hi[k], p[k]);
  }
  const centre = [0, 1, 2].map((k) => (lo[k] + hi[k]) / 2);
  const scale = size / Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  const positions = bunny.positions.map((p) => [0, 1, 2].map((k) => (p[k] - centre[k]) * scale));
  const triangles = bunny.cells.map((c) => [c[0], c[1], c[2]]);
  const mesh = { positions, normals: null, uvs: null, triangles };
  // Closedness is checked before the normals (a hole would be reported as such).
  const t = topology(mesh);
  if (t.boundary) console.warn(`warning: the npm bunny mesh has ${t.boundary} boundary edges (holes); not patched`);
  mesh.normals = smoothNormals(positions, triangles);
  return mesh;
}

// Icosphere: the icosahedron subdivided `levels` times, midpoints shared
// (one vertex per position), projected onto the sphere; normals radial.
function icosphere(radius, levels) {
  const t = (1 + Math.sqrt(5)) / 2;
  let unit = [
    [-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0],
    [0, -1, t], [0, 1, t], [0, -1, -t], [0, 1, -t],
    [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1],
  ].map(normalize);
  let faces = [
    [0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11],
    [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8],
    [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9],
    [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1],
  ];
  for (let level = 0; level < levels; ++level) {
    const mid = new Map();
    const midpoint = (a, b) => {
      const key = a < b ? `${a},${b}` : `${b},${a}`;
      let i = mid.get(key);
      if (i === undefined) {
        i = unit.length;
        unit.push(normalize([0, 1, 2].map((k) => (unit[a][k] + unit[b][k]) / 2)));
        mid.set(key, i);
      }
      return i;
    };
    const next = [];
    for (const [a, b, c] of faces) {
      const ab = midpoint(a, b);
      const bc = midpoint(b, c);
      const ca = midpoint(c, a);
      next.push([a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]);
    }
    faces = next;
  }
  return {
    positions: unit.map((n) => n.map((c) => c * radius)),
    normals: unit,
    uvs: null,
    triangles: faces,
  };
}

// Rounded box: half extents `half`, edge/corner radius `r`. Built on the
// surface of a lattice over the box (vertices on the box's edges are shared
// by the faces that meet there, so the surface is closed). A lattice point q
// maps to c + r * normalize(q - c) with c = q clamped to the inner box
// (half - r); lattice coordinates in the rounded band are placed at
// I + r tan(phi), phi uniform in [0, 45 degrees], so the arcs are sampled
// evenly. Normals are analytic: normalize(q - c).
function roundedBox(half, r, flatStep, roundSegments) {
  const inner = half.map((h) => h - r);
  const axisCoords = (I) => {
    const round = [];
    for (let i = 1; i <= roundSegments; ++i) round.push(I + r * Math.tan((deg(45) * i) / roundSegments));
    const nFlat = Math.max(1, Math.ceil((2 * I) / flatStep));
    const flat = [];
    for (let i = 0; i <= nFlat; ++i) flat.push(-I + (2 * I * i) / nFlat);
    return [...round.slice().reverse().map((x) => -x), ...flat, ...round];
  };
  const coords = inner.map(axisCoords);
  const last = coords.map((c) => c.length - 1);
  const positions = [];
  const normals = [];
  const index = new Map();
  const vertex = (i, j, k) => {
    const key = `${i},${j},${k}`;
    let v = index.get(key);
    if (v === undefined) {
      const q = [coords[0][i], coords[1][j], coords[2][k]];
      const c = q.map((x, a) => Math.min(inner[a], Math.max(-inner[a], x)));
      const n = normalize(sub(q, c));
      v = positions.length;
      positions.push([0, 1, 2].map((a) => c[a] + r * n[a]));
      normals.push(n);
      index.set(key, v);
    }
    return v;
  };
  // Each face: the fixed axis and its side, then the (u, v) axes with u x v = outward normal.
  const faces = [
    [0, 1, 1, 2], [0, -1, 2, 1],
    [1, 1, 2, 0], [1, -1, 0, 2],
    [2, 1, 0, 1], [2, -1, 1, 0],
  ];
  const triangles = [];
  for (const [axis, side, ua, va] of faces) {
    const fixed = side > 0 ? last[axis] : 0;
    const at = (u, v) => {
      const ijk = [0, 0, 0];
      ijk[axis] = fixed;
      ijk[ua] = u;
      ijk[va] = v;
      return vertex(ijk[0], ijk[1], ijk[2]);
    };
    for (let u = 0; u < last[ua]; ++u) {
      for (let v = 0; v < last[va]; ++v) {
        const a = at(u, v);
        const b = at(u + 1, v);
        const c = at(u + 1, v + 1);
        const d = at(u, v + 1);
        triangles.push([a, b, c], [a, c, d]);
      }
    }
  }
  return { positions, normals, uvs: null, triangles };
}

// Signed distance from p to the rounded box (negative inside).
function roundedBoxDistance(p, half, r) {
  const q = p.map((x, a) => Math.abs(x) - (half[a] - r));
  const outside = len(q.map((x) => Math.max(x, 0)));
  return outside + Math.min(Math.max(q[0], q[1], q[2]), 0) - r;
}

// Suzanne from @pmndrs/assets (a Draco-compressed GLB as a data URI).
async function suzanneMesh() {
  const io = new NodeIO()
    .registerExtensions([KHRDracoMeshCompression])
    .registerDependencies({ 'draco3d.decoder': await draco3d.createDecoderModule() });
  const src = await io.readBinary(Buffer.from(suzanneDataUri.slice(suzanneDataUri.indexOf(',') + 1), 'base64'));
  const meshes = src.getRoot().listMeshes();
  const nodes = src.getRoot().listNodes();
  if (meshes.length !== 1 || meshes[0].listPrimitives().length !== 1 || nodes.length !== 1)
    throw new Error('@pmndrs/assets suzi.glb: expected one node with one mesh of one primitive');
  const n = nodes[0];
  const identity = [...n.getTranslation(), ...n.getRotation(), ...n.getScale()].join(',') === '0,0,0,0,0,0,1,1,1,1';
  if (!identity) throw new Error('@pmndrs/assets suzi.glb: expected an identity node transform');
  const prim = meshes[0].listPrimitives()[0];
  const p = prim.getAttribute('POSITION').getArray();
  const nn = prim.getAttribute('NORMAL').getArray();
  const idx = prim.getIndices().getArray();
  const positions = [];
  const normals = [];
  for (let i = 0; i < p.length; i += 3) {
    positions.push([p[i], p[i + 1], p[i + 2]]);
    normals.push(normalize([nn[i], nn[i + 1], nn[i + 2]]));
  }
  const triangles = [];
  for (let i = 0; i < idx.length; i += 3) triangles.push([idx[i], idx[i + 1], idx[i + 2]]);
  return { positions, normals, uvs: null, triangles };
}

function transformMesh(mesh, { rotation = [0, 0, 0, 1], scale = 1, translation = [0, 0, 0] }) {
  return {
    ...mesh,
    positions: mesh.positions.map((p) => quatRotate(rotation, p).map((x, k) => x * scale + translation[k])),
    normals: mesh.normals && mesh.normals.map((n) => normalize(quatRotate(rotation, n))),
  };
}

// ---------------------------------------------------------------- test card

// A colourful high-frequency test card, sRGB, RGB8: a hue sweep left to right
// (brighter towards the top), an 8-pixel checker that darkens every other
// square, concentric rings about the centre, a 64-pixel grid of thin white
// lines and orientation marks (white square top left, black square bottom
// right, so a flipped or mirrored texture is seen at once).
function testCardPng(width, height) {
  const png = new PNG({ width, height, colorType: 2, inputHasAlpha: false, bitDepth: 8 });
  const hsv = (h, s, v) => {
    const f = (n) => {
      const k = (n + h * 6) % 6;
      return v - v * s * Math.max(0, Math.min(k, 4 - k, 1));
    };
    return [f(5), f(3), f(1)];
  };
  const cx = (width - 1) / 2;
  const cy = (height - 1) / 2;
  const data = Buffer.alloc(width * height * 3);
  for (let y = 0; y < height; ++y) {
    for (let x = 0; x < width; ++x) {
      let rgb = hsv(x / width, 0.85, 1 - 0.45 * (y / (height - 1)));
      if (((x >> 3) + (y >> 3)) & 1) rgb = rgb.map((c) => c * 0.62);
      const radius = Math.hypot(x - cx, y - cy);
      const ring = radius % 24;
      if (ring < 2) rgb = rgb.map((c) => c * 0.15);
      else if (ring >= 12 && ring < 13) rgb = rgb.map((c) => c + (1 - c) * 0.8);
      if (x % 64 === 0 || y % 64 === 0) rgb = [1, 1, 1];
      if (x < 24 && y < 24) rgb = [1, 1, 1];
      if (x >= width - 24 && y >= height - 24) rgb = [0, 0, 0];
      const o = (y * width + x) * 3;
      for (let k = 0; k < 3; ++k) data[o + k] = Math.round(Math.min(1, Math.max(0, rgb[k])) * 255);
    }
  }
  // pngjs wants RGBA input; colorType 2 writes RGB.
  const rgba = Buffer.alloc(width * height * 4);
  for (let i = 0; i < width * height; ++i) {
    rgba[i * 4] = data[i * 3];
    rgba[i * 4 + 1] = data[i * 3 + 1];
    rgba[i * 4 + 2] = data[i * 3 + 2];
    rgba[i * 4 + 3] = 255;
  }
  png.data = rgba;
  return PNG.sync.write(png, { colorType: 2, inputHasAlpha: true, deflateLevel: 9, filterType: 4 });
}

// ---------------------------------------------------------------- glTF building

class Builder {
  constructor(copyright) {
    this.doc = new Document();
    this.doc.getRoot().getAsset().generator = GENERATOR;
    this.doc.getRoot().getAsset().copyright = copyright;
    this.buffer = this.doc.createBuffer('Buffer');
    this.scene = this.doc.createScene('Scene');
    this.doc.getRoot().setDefaultScene(this.scene);
    this.transmission = this.doc.createExtension(KHRMaterialsTransmission);
    this.ior = this.doc.createExtension(KHRMaterialsIOR);
    this.volume = this.doc.createExtension(KHRMaterialsVolume);
    this.stats = [];
  }

  accessor(name, type, array) {
    return this.doc.createAccessor(name).setType(type).setArray(array).setBuffer(this.buffer);
  }

  // Accessors for a mesh, so several primitives can share them.
  geometry(name, mesh) {
    const n = mesh.positions.length;
    const g = {
      name,
      mesh,
      position: this.accessor(`${name}_POSITION`, 'VEC3', new Float32Array(mesh.positions.flat())),
      normal: this.accessor(`${name}_NORMAL`, 'VEC3', new Float32Array(mesh.normals.flat())),
      uv: mesh.uvs ? this.accessor(`${name}_TEXCOORD_0`, 'VEC2', new Float32Array(mesh.uvs.flat())) : null,
      indices: this.accessor(
        `${name}_indices`,
        'SCALAR',
        n < 65536 ? new Uint16Array(mesh.triangles.flat()) : new Uint32Array(mesh.triangles.flat()),
      ),
    };
    return g;
  }

  meshNode(name, geometry, material, trs = {}) {
    const prim = this.doc
      .createPrimitive()
      .setAttribute('POSITION', geometry.position)
      .setAttribute('NORMAL', geometry.normal)
      .setIndices(geometry.indices)
      .setMaterial(material);
    if (geometry.uv) prim.setAttribute('TEXCOORD_0', geometry.uv);
    const mesh = this.doc.createMesh(name).addPrimitive(prim);
    const node = this.doc.createNode(name).setMesh(mesh);
    if (trs.translation) node.setTranslation(trs.translation);
    if (trs.rotation) node.setRotation(trs.rotation);
    if (trs.scale) node.setScale(trs.scale);
    this.scene.addChild(node);
    this.stats.push({
      node: name,
      geometry: geometry.name,
      material: material.getName(),
      vertices: geometry.mesh.positions.length,
      triangles: geometry.mesh.triangles.length,
    });
    return node;
  }

  glass(name, { ior, thickness, attenuationColor = null, attenuationDistance = null, dispersion = 0 }) {
    const vol = this.volume.createVolume().setThicknessFactor(thickness);
    if (attenuationColor) vol.setAttenuationColor(attenuationColor).setAttenuationDistance(attenuationDistance);
    const material = this.doc
      .createMaterial(name)
      .setBaseColorFactor([1, 1, 1, 1])
      .setMetallicFactor(0)
      .setRoughnessFactor(0)
      .setExtension('KHR_materials_transmission', this.transmission.createTransmission().setTransmissionFactor(1))
      .setExtension('KHR_materials_ior', this.ior.createIOR().setIOR(ior))
      .setExtension('KHR_materials_volume', vol);
    // Created only where a glass disperses, so the other assets do not list the extension as used.
    if (dispersion > 0) {
      this.dispersion ??= this.doc.createExtension(KHRMaterialsDispersion);
      material.setExtension('KHR_materials_dispersion', this.dispersion.createDispersion().setDispersion(dispersion));
    }
    return material;
  }

  opaque(name, baseColor, roughness) {
    return this.doc
      .createMaterial(name)
      .setBaseColorFactor([...baseColor, 1])
      .setMetallicFactor(0)
      .setRoughnessFactor(roughness);
  }

  // The camera looks from `eye` at `target` (glTF cameras look down their
  // node's -Z with +Y up); the view is a pitch about X only (eye and target
  // share x), so the image stays level.
  camera(name, eye, target, { yfovDeg, znear, zfar }) {
    const d = sub(target, eye);
    if (d[0] !== 0) throw new Error('camera: keep eye and target at the same x');
    const pitch = Math.atan2(d[1], -d[2]);
    const rotation = pitch === 0 ? [0, 0, 0, 1] : quatAxisAngle([1, 0, 0], pitch);
    const cam = this.doc
      .createCamera(name)
      .setType('perspective')
      .setYFov(deg(yfovDeg))
      .setAspectRatio(1)
      .setZNear(znear)
      .setZFar(zfar);
    const node = this.doc.createNode(name).setCamera(cam).setTranslation(eye).setRotation(rotation);
    this.scene.addChild(node);
    this.cam = { name, eye, rotation, yfov: deg(yfovDeg), znear, zfar };
    return node;
  }

  // An upright quad at depth z facing +Z (towards the camera), width x height,
  // centred on (0, centreY); UV (0,0) is the image's top left.
  backdrop(png, { z, width, height, centreY = 0 }) {
    const w = width / 2;
    const h = height / 2;
    const mesh = {
      positions: [[-w, centreY - h, z], [w, centreY - h, z], [w, centreY + h, z], [-w, centreY + h, z]],
      normals: [[0, 0, 1], [0, 0, 1], [0, 0, 1], [0, 0, 1]],
      uvs: [[0, 1], [1, 1], [1, 0], [0, 0]],
      triangles: [[0, 1, 2], [0, 2, 3]],
    };
    const texture = this.doc.createTexture('TestCard').setImage(png).setMimeType('image/png');
    const material = this.opaque('BackdropTestCard', [1, 1, 1], 1).setBaseColorTexture(texture);
    material
      .getBaseColorTextureInfo()
      .setMagFilter(9729) // LINEAR
      .setMinFilter(9987) // LINEAR_MIPMAP_LINEAR
      .setWrapS(33071) // CLAMP_TO_EDGE
      .setWrapT(33071);
    this.meshNode('Backdrop', this.geometry('Backdrop', mesh), material);
    this.backdropInfo = { z, width, height, centreY };
  }

  // Every vertex of the given meshes (world space) must project inside
  // `fraction` of the half-frame, in front of the camera.
  requireFramed(worldMeshes, fraction) {
    const { eye, rotation, yfov, znear, zfar } = this.cam;
    const t = Math.tan(yfov / 2);
    let worst = 0;
    for (const m of worldMeshes) {
      for (const p of m.positions) {
        const c = quatRotate(quatConj(rotation), sub(p, eye));
        const depth = -c[2];
        if (!(depth > znear && depth < zfar)) throw new Error(`${this.cam.name}: content outside the depth range`);
        worst = Math.max(worst, Math.abs(c[0]) / (depth * t), Math.abs(c[1]) / (depth * t));
      }
    }
    if (worst > fraction) throw new Error(`${this.cam.name}: content reaches ${worst.toFixed(3)} of the half-frame`);
    this.cam.framed = worst;
    // The backdrop must cover the whole frame (its corners outside it).
    const { z, width, height, centreY } = this.backdropInfo;
    for (const [sx, sy] of [[-1, -1], [1, -1], [1, 1], [-1, 1]]) {
      const dirCam = [sx * t, sy * t, -1];
      const dir = quatRotate(rotation, dirCam);
      const s = (z - eye[2]) / dir[2];
      const hit = [eye[0] + s * dir[0], eye[1] + s * dir[1]];
      if (!(s > 0 && Math.abs(hit[0]) < width / 2 && Math.abs(hit[1] - centreY) < height / 2))
        throw new Error(`${this.cam.name}: the backdrop does not cover the frame's corner (${sx}, ${sy})`);
    }
  }

  async write(file) {
    const io = new NodeIO().registerExtensions([
      KHRMaterialsTransmission,
      KHRMaterialsIOR,
      KHRMaterialsVolume,
      KHRMaterialsDispersion,
    ]);
    const bytes = await io.writeBinary(this.doc);
    if (bytes.length > MAX_BYTES) throw new Error(`${file}: ${bytes.length} bytes, over ${MAX_BYTES}`);
    fs.writeFileSync(file, bytes);
    return bytes.length;
  }
}

const quatToString = (q) => `[${q.map((x) => +x.toFixed(6)).join(', ')}]`;

// ---------------------------------------------------------------- the assets

const CAMERA = { yfovDeg: 40, znear: 0.1, zfar: 50 };

async function glassBunny(png) {
  const b = new Builder(
    'Stanford bunny: Stanford University Computer Graphics Laboratory, Stanford 3D Scanning Repository ' +
      `(npm "bunny" ${version('bunny')}, license "${packageJson('bunny').license}"). ` +
      'Scene and test card generated by snell tools/gltf/make_assets.mjs.',
  );
  b.camera('Camera', [0, 0.35, 4.2], [0, 0, 0], CAMERA);
  b.backdrop(png, { z: -2.5, width: 8, height: 6 });
  const mesh = bunnyMesh(2.2);
  const topo = requireClosedGlass('bunny', mesh);
  const sigma = [0.25, 0.05, 0.2];
  const glass = b.glass('GreenGlass', {
    ior: 1.5,
    thickness: 1.0,
    attenuationColor: attenuationColorFor(sigma, 1),
    attenuationDistance: 1,
  });
  const rotation = quatAxisAngle([0, 1, 0], deg(-20));
  b.meshNode('Bunny', b.geometry('Bunny', mesh), glass, { rotation });
  b.requireFramed([transformMesh(mesh, { rotation })], 0.85);
  return { builder: b, notes: { bunny: topo, sigma } };
}

async function suzannePaperweight(png) {
  const b = new Builder(
    'Suzanne: Blender Foundation (Blender\'s monkey primitive), from npm "@pmndrs/assets" ' +
      `${version('@pmndrs/assets')}/models/suzi.glb (license "${packageJson('@pmndrs/assets').license}"). ` +
      'Glass block, scene and test card generated by snell tools/gltf/make_assets.mjs.',
  );
  b.camera('Camera', [0, 0.6, 5.2], [0, 0, 0], CAMERA);
  b.backdrop(png, { z: -2.5, width: 9.6, height: 7.2 });
  const half = [1.3, 1.0, 0.95];
  const radius = 0.4;
  const block = roundedBox(half, radius, 0.1, 10);
  const topo = requireClosedGlass('paperweight block', block);
  // Suzanne faces +Z in the package; turned 20 degrees about +Y (nose towards +X, the viewer's right).
  const suzanneSrc = await suzanneMesh();
  const suzanneTrs = { rotation: quatAxisAngle([0, 1, 0], deg(20)), scale: 1, translation: [0, 0, 0] };
  const suzanne = transformMesh(suzanneSrc, suzanneTrs);
  let clearance = Infinity;
  for (const p of suzanne.positions) clearance = Math.min(clearance, -roundedBoxDistance(p, half, radius));
  if (!(clearance > 0.1)) throw new Error(`Suzanne is ${clearance} from the glass surface (want > 0.1 inside)`);
  const sigma = [0.08, 0.04, 0.02];
  const glass = b.glass('PaperweightGlass', {
    ior: 1.5,
    thickness: 1.9,
    attenuationColor: attenuationColorFor(sigma, 1),
    attenuationDistance: 1,
  });
  b.meshNode('GlassBlock', b.geometry('GlassBlock', block), glass);
  // Suzanne's transform is baked into her vertices (she is not glass; only the glass is checked closed).
  const sTopo = topology(suzanne);
  b.meshNode('Suzanne', b.geometry('Suzanne', suzanne), b.opaque('SuzanneOrange', [0.9, 0.3, 0.04], 0.45));
  b.requireFramed([block, suzanne], 0.85);
  return { builder: b, notes: { block: topo, suzanne: sTopo, clearance, sigma, half, radius } };
}

async function iorGrid(png) {
  const b = new Builder('Generated by snell tools/gltf/make_assets.mjs.');
  b.camera('Camera', [0, 0, 6], [0, 0, 0], CAMERA);
  b.backdrop(png, { z: -2, width: 8, height: 6 });
  const radius = 0.45;
  const spacing = 1.15;
  const sphere = icosphere(radius, 5);
  const topo = requireClosedGlass('sphere', sphere);
  const geometry = b.geometry('Sphere', sphere);
  const placed = [];
  const iors = [];
  for (let row = 0; row < 3; ++row) {
    for (let col = 0; col < 3; ++col) {
      const ior = Math.round((1.1 + 0.1 * (row * 3 + col)) * 10) / 10;
      iors.push(ior);
      const translation = [(col - 1) * spacing, (1 - row) * spacing, 0];
      const tag = ior.toFixed(1).replace('.', '_');
      b.meshNode(`Sphere_IOR_${tag}`, geometry, b.glass(`Glass_IOR_${tag}`, { ior, thickness: 2 * radius }), { translation });
      placed.push(transformMesh(sphere, { translation }));
    }
  }
  b.requireFramed(placed, 0.85);
  return { builder: b, notes: { sphere: topo, iors, radius, spacing } };
}

// A dense flint glass ball (n_d 1.65, Abbe number 33, about Schott's SF2; KHR_materials_dispersion's
// `dispersion` is 20 / V_d): the test card's edges split into colour fringes through it.
async function flintBall(png) {
  const b = new Builder('Generated by snell tools/gltf/make_assets.mjs.');
  b.camera('Camera', [0, 0.3, 3.8], [0, 0, 0], CAMERA);
  b.backdrop(png, { z: -2.5, width: 8, height: 6 });
  const radius = 1;
  const sphere = icosphere(radius, 5);
  const topo = requireClosedGlass('ball', sphere);
  const abbe = 33;
  const glass = b.glass('DenseFlint', { ior: 1.65, thickness: 2 * radius, dispersion: 20 / abbe });
  b.meshNode('FlintBall', b.geometry('FlintBall', sphere), glass);
  b.requireFramed([sphere], 0.85);
  return { builder: b, notes: { ball: topo, abbe, dispersion: 20 / abbe } };
}

// ---------------------------------------------------------------- main

const png = testCardPng(512, 384);
fs.mkdirSync(outDir, { recursive: true });
const assets = [
  ['glass_bunny.glb', glassBunny],
  ['suzanne_paperweight.glb', suzannePaperweight],
  ['ior_grid.glb', iorGrid],
  ['flint_ball.glb', flintBall],
];
console.log(`test card PNG: 512x384 RGB8 sRGB, ${png.length} bytes`);
for (const [file, make] of assets) {
  const { builder, notes } = await make(png);
  const size = await builder.write(path.join(outDir, file));
  const c = builder.cam;
  console.log(`\n${file}: ${size} bytes`);
  console.log(
    `  camera "${c.name}": translation [${c.eye.join(', ')}], rotation ${quatToString(c.rotation)}, ` +
      `yfov ${c.yfov.toFixed(6)} rad (${CAMERA.yfovDeg} deg), aspectRatio 1, znear ${c.znear}, zfar ${c.zfar}; ` +
      `content reaches ${(100 * c.framed).toFixed(0)}% of the half-frame`,
  );
  const shared = new Map();
  for (const s of builder.stats) {
    const key = s.geometry;
    if (shared.has(key)) {
      shared.get(key).nodes.push(s.node);
      continue;
    }
    shared.set(key, { ...s, nodes: [s.node] });
  }
  for (const s of shared.values())
    console.log(`  mesh ${s.geometry}: ${s.vertices} vertices, ${s.triangles} triangles (nodes: ${s.nodes.join(', ')})`);
  for (const [k, v] of Object.entries(notes)) {
    if (v && typeof v === 'object' && 'euler' in v)
      console.log(
        `  ${k}: boundary ${v.boundary}, non-manifold ${v.nonManifold}, misoriented ${v.misoriented}, ` +
          `duplicate positions ${v.duplicatePositions}, volume ${v.volume.toFixed(4)}, Euler characteristic ${v.euler}`,
      );
    else console.log(`  ${k}: ${JSON.stringify(v)}`);
  }
}
