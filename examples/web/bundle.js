// Reading a bundle of `snell-lab --web-bundle DIR` (examples/lab/app/web_bundle.hpp): its JSON, its float
// images as textures and its objects' meshes as geometry.
import * as THREE from "three";

async function fetchOk(url) {
  const r = await fetch(url);
  if (!r.ok) throw new Error(`cannot load ${url} (HTTP ${r.status})`);
  return r;
}
export const text = async (url) => (await fetchOk(url)).text();
export const bytes = async (url) => (await fetchOk(url)).arrayBuffer();

export const matrix = (a) => new THREE.Matrix4().fromArray(a);  // column-major, as the bundle writes it
export const vector = (a) => new THREE.Vector3(a[0], a[1], a[2]);

// bundle.json, checked for what the page reads from every object.
export async function loadBundle() {
  const bundle = await (await fetchOk("bundle/bundle.json")).json();
  if (!Array.isArray(bundle.objects) || bundle.objects.length === 0)
    throw new Error("bundle.json lists no objects (a bundle of an older snell-lab?): write it again with " +
      "snell-lab SCENE --web-bundle DIR");
  const n = bundle.objects.length;
  const order = bundle.drawOrder;
  if (!Array.isArray(order) || order.length !== n || new Set(order).size !== n ||
      !order.every((o) => Number.isInteger(o) && o >= 0 && o < n))
    throw new Error(`bundle.json: drawOrder ${JSON.stringify(order)} is not an order of its ${n} objects`);
  if (!Array.isArray(bundle.paintings) || !bundle.paintings.every((p) => p.mesh))
    throw new Error("bundle.json's paintings have no meshes (a bundle of an older snell-lab?): write it again " +
      "with snell-lab SCENE --web-bundle DIR");
  if (!["behind", "full"].includes(bundle.sceneLayer))
    throw new Error(`bundle.json: the page draws the behind and full scene layers, not ${bundle.sceneLayer}`);
  return bundle;
}

// A float image of the bundle as an RGBA texture (clamped to the edge, no mips); linear filtering is how the
// lab samples its paintings and its environment. A one-channel image (a depth buffer) lands in x.
export async function floatTexture(image, filter = THREE.LinearFilter) {
  const channels = image.channels ?? 4;
  const stored = new Float32Array(await bytes(`bundle/${image.texels}`));
  if (stored.length !== image.width * image.height * channels)
    throw new Error(`bundle/${image.texels}: wrong size for ${image.width}x${image.height}x${channels}`);
  let data = stored;
  if (channels !== 4) {
    data = new Float32Array(image.width * image.height * 4);
    for (let i = 0; i < image.width * image.height; ++i)
      for (let c = 0; c < channels; ++c) data[4 * i + c] = stored[channels * i + c];
  }
  const t = new THREE.DataTexture(data, image.width, image.height, THREE.RGBAFormat, THREE.FloatType);
  t.minFilter = filter;
  t.magFilter = filter;
  t.generateMipmaps = false;
  t.needsUpdate = true;
  return t;
}

// An object's mesh as the lab's GL pass pulls it: positions with Wyman's d_N in w, normals, indices.
export async function objectGeometry(mesh) {
  const positions = new THREE.InterleavedBuffer(new Float32Array(await bytes(`bundle/${mesh.positions}`)), 4);
  const normals = new THREE.InterleavedBuffer(new Float32Array(await bytes(`bundle/${mesh.normals}`)), 4);
  const indices = new Uint32Array(await bytes(`bundle/${mesh.triangles}`));
  if (positions.count !== mesh.vertices || normals.count !== mesh.vertices || indices.length !== mesh.indices)
    throw new Error(`bundle: the files of mesh ${mesh.positions} do not match bundle.json`);
  const g = new THREE.BufferGeometry();
  g.setAttribute("position", new THREE.InterleavedBufferAttribute(positions, 3, 0));
  g.setAttribute("dn", new THREE.InterleavedBufferAttribute(positions, 1, 3));
  g.setAttribute("normal", new THREE.InterleavedBufferAttribute(normals, 3, 0));
  g.setIndex(new THREE.BufferAttribute(indices, 1));
  return g;
}

// A painting's mesh as the lab draws it: positions, normals (the side the normal buffer reports), uvs.
export async function paintingGeometry(mesh) {
  const positions = new THREE.InterleavedBuffer(new Float32Array(await bytes(`bundle/${mesh.positions}`)), 4);
  const normals = new THREE.InterleavedBuffer(new Float32Array(await bytes(`bundle/${mesh.normals}`)), 4);
  const uvs = new Float32Array(await bytes(`bundle/${mesh.uvs}`));
  const indices = new Uint32Array(await bytes(`bundle/${mesh.triangles}`));
  if (positions.count !== mesh.vertices || normals.count !== mesh.vertices || uvs.length !== 2 * mesh.vertices ||
      indices.length !== mesh.indices)
    throw new Error(`bundle: the files of painting mesh ${mesh.positions} do not match bundle.json`);
  const g = new THREE.BufferGeometry();
  g.setAttribute("position", new THREE.InterleavedBufferAttribute(positions, 3, 0));
  g.setAttribute("normal", new THREE.InterleavedBufferAttribute(normals, 3, 0));
  g.setAttribute("uv", new THREE.BufferAttribute(uvs, 2));
  g.setIndex(new THREE.BufferAttribute(indices, 1));
  return g;
}

// The lab's buffers one object read (its scene layer, back and front faces, front-pass inputs), as the
// technique samples them: depth nearest, normals as the lab filters them, the scene's colour bilinear.
export async function labObjectBuffers(lab, normalFilter) {
  return {
    sceneColor: await floatTexture(lab.sceneColor),
    sceneNormal: await floatTexture(lab.sceneNormal, normalFilter),
    sceneDepth: await floatTexture(lab.sceneDepth, THREE.NearestFilter),
    backNormal: await floatTexture(lab.backNormal, normalFilter),
    backDepth: await floatTexture(lab.backDepth, THREE.NearestFilter),
    frontLayerNormal: await floatTexture(lab.frontLayerNormal, normalFilter),
    frontLayerDepth: await floatTexture(lab.frontLayerDepth, THREE.NearestFilter),
    frontPositions: await floatTexture(lab.frontPosition, THREE.NearestFilter),
    frontNormals: await floatTexture(lab.frontNormal, THREE.NearestFilter),
  };
}
