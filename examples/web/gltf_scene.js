// A glTF asset set up for three.js's OWN renderer (GLTFLoader, MeshPhysicalMaterial transmission, the
// renderer's transmission pass) over the lab's opaque world, environment and camera. One module, two users:
//   - examples/web/main.js with ?renderer=threejs (the page's "three.js's own renderer"; served by
//     examples/web/serve.mjs as /gltf_scene.js);
//   - tools/browser/threejs_render_page.js, the lab's row "three.js (its renderer)" (served by
//     tools/browser/run_page.mjs as /web/gltf_scene.js).
// Both resolve "three" and "three/addons/" through their page's import map, so this module and its caller
// share one three.js.
//
// What it changes, so that the opaque world is the lab's: every primitive whose material is not
// transmissive (transmission 0, as the lab's glTF loader decides) gets an unlit MeshBasicMaterial with the
// glTF base colour factor and base colour texture (sRGB; bilinear, no mips, clamped: as the lab samples it),
// drawn on both sides (the lab draws its opaque meshes without culling). The transmissive
// MeshPhysicalMaterials stay as GLTFLoader made them.
//
// The environment is both scene.background and scene.environment (three.js converts the equirectangular
// texture to a cube map for the background and to a PMREM for the glass's reflections). The lab looks a
// world direction d up at u = atan2(d.x, -d.z) / 2pi + 0.5 after turning d by its environment rotation;
// three.js at u = atan2(d.z, d.x) / 2pi + 0.5 after turning d by backgroundRotation's inverse: the scene's
// backgroundRotation and environmentRotation are set so that both give the same texel (v, asin(d.y) / pi +
// 0.5 and row 0 at the bottom, is the same in both).
//
// The camera description (what the lab passes to tools/browser/threejs_render.mjs, or cameraFromBundle of
// bundle_camera.js):
//   { "position": [x, y, z], "target": [x, y, z], "up": [x, y, z], "fovYDegrees": f, "near": n, "far": f,
//     "envX": [..], "envY": [..], "envZ": [..]      (optional: the lab's view-to-environment axes)
//     "environmentRotationDegrees": r }              (optional, when the axes are not given; default 0)
import * as THREE from "three";
import { GLTFLoader } from "three/addons/loaders/GLTFLoader.js";

const vec3 = (a, what) => {
  if (!Array.isArray(a) || a.length !== 3 || !a.every(Number.isFinite)) throw new Error(`${what} is not 3 numbers`);
  return new THREE.Vector3(a[0], a[1], a[2]);
};

// The renderer as both users set it: one pixel per texel, linear output, no tone mapping (the image is read
// from a float target; the page encodes it for the canvas itself). Fails without float targets.
export function configureRenderer(renderer, width, height) {
  const gl = renderer.getContext();
  if (!gl.getExtension("EXT_color_buffer_float"))
    throw new Error("WebGL 2 without EXT_color_buffer_float: cannot render into a float target");
  if (!gl.getExtension("OES_texture_float_linear"))
    throw new Error("WebGL 2 without OES_texture_float_linear: cannot filter the float environment");
  renderer.setPixelRatio(1);
  renderer.setSize(width, height, false);
  renderer.outputColorSpace = THREE.LinearSRGBColorSpace;
  renderer.toneMapping = THREE.NoToneMapping;
}

// The environment, as the lab samples it: bilinear, longitude repeats, latitude clamps, no mips. `texels`:
// equirectangular RGBA float32, row 0 at the bottom (the nadir), as the lab writes environment.f32.
export function environmentTexture(texels, width, height) {
  const bytes = texels.byteLength;
  if (!Number.isInteger(width) || !Number.isInteger(height) || bytes !== width * height * 16)
    throw new Error(`the environment has ${bytes} bytes, not ${width} x ${height} RGBA float32 texels`);
  const data = texels instanceof Float32Array ? texels : new Float32Array(texels);
  const env = new THREE.DataTexture(data, width, height, THREE.RGBAFormat, THREE.FloatType);
  env.mapping = THREE.EquirectangularReflectionMapping;
  env.colorSpace = THREE.LinearSRGBColorSpace;
  env.wrapS = THREE.RepeatWrapping;
  env.wrapT = THREE.ClampToEdgeWrapping;
  env.magFilter = THREE.LinearFilter;
  env.minFilter = THREE.LinearFilter;
  env.generateMipmaps = false;
  env.flipY = false;  // row 0 (the nadir) at v = 0, as the lab stores it
  env.needsUpdate = true;
  return env;
}

// The asset (a .glb, or a self-contained .gltf, as an ArrayBuffer) in a THREE.Scene, its opaque materials
// replaced. Returns the scene, the glass materials kept (transmissive MeshPhysicalMaterials), the unlit
// materials made, and how many meshes are glass or opaque.
export async function loadAsset(glb) {
  const gltf = await new GLTFLoader().parseAsync(glb, "").catch((e) => {
    throw new Error(`GLTFLoader cannot read the asset: ${e?.message ?? e}`);
  });
  // gltf.scene is a Group (the file's default scene); three.js's background and environment live on a Scene.
  const scene = new THREE.Scene();
  scene.add(gltf.scene);

  // Every material once: transmissive ones kept, the others replaced by their unlit colour.
  const replaced = new Map();
  const kept = new Map();
  const unlit = (m) => {
    if (!replaced.has(m)) {
      const basic = new THREE.MeshBasicMaterial({ name: m.name, color: m.color ? m.color.clone() : new THREE.Color(1, 1, 1),
        map: m.map ?? null, side: THREE.DoubleSide });
      if (basic.map) {
        // sRGB (GLTFLoader's choice for a base colour texture; made sure), and sampled as the lab samples its
        // opaque meshes' textures: bilinear, without mips, clamped to the edge (GLTFLoader follows the file's
        // sampler: in the bundled assets trilinear, clamped).
        basic.map.colorSpace = THREE.SRGBColorSpace;
        basic.map.wrapS = THREE.ClampToEdgeWrapping;
        basic.map.wrapT = THREE.ClampToEdgeWrapping;
        basic.map.minFilter = THREE.LinearFilter;
        basic.map.magFilter = THREE.LinearFilter;
        basic.map.generateMipmaps = false;
        basic.map.needsUpdate = true;
      }
      replaced.set(m, basic);
    }
    return replaced.get(m);
  };
  let glassMeshes = 0, opaqueMeshes = 0;
  scene.traverse((o) => {
    if (!o.isMesh) return;
    const one = (m) => {
      if (m.isMeshPhysicalMaterial && m.transmission > 0) {
        kept.set(m.uuid, m);
        return m;
      }
      return unlit(m);
    };
    const before = Array.isArray(o.material) ? o.material : [o.material];
    o.material = Array.isArray(o.material) ? o.material.map(one) : one(o.material);
    if (before.some((m) => kept.has(m.uuid))) ++glassMeshes;
    else ++opaqueMeshes;
  });
  if (kept.size === 0) throw new Error("the asset has no transmissive material (KHR_materials_transmission with " +
    "transmissionFactor > 0): nothing for three.js's transmission to show");
  return { scene, glass: [...kept.values()], unlit: [...replaced.values()], glassMeshes, opaqueMeshes };
}

// The camera description `c` as a three.js camera for a width x height image. `where` names its source in
// error messages.
export function assetCamera(c, width, height, where = "camera") {
  for (const k of ["fovYDegrees", "near", "far"])
    if (!Number.isFinite(c?.[k])) throw new Error(`${where}: camera.${k} is not a number`);
  const camera = new THREE.PerspectiveCamera(c.fovYDegrees, width / height, c.near, c.far);
  camera.position.copy(vec3(c.position, `${where}: camera.position`));
  camera.up.copy(vec3(c.up, `${where}: camera.up`));
  camera.lookAt(vec3(c.target, `${where}: camera.target`));
  camera.updateMatrixWorld(true);
  camera.updateProjectionMatrix();
  return camera;
}

// World direction -> the direction three.js's equirectUv must see: the lab's (x, y, z) -> (-z, y, x), so that
// atan2(z', x') = atan2(x, -z). A rotation by -90 degrees about +Y (no mirror).
const labToThree = new THREE.Matrix3().set(0, 0, -1, 0, 1, 0, 1, 0, 0);

// The lab's environment rotation (world direction -> environment direction) for this camera.
function labEnvironmentRotation(c, camera, where) {
  if (c.envX !== undefined || c.envY !== undefined || c.envZ !== undefined) {
    // envX/Y/Z map a view-space direction to the environment's: rotation = [envX envY envZ] * viewFromWorld.
    const [x, y, z] = [vec3(c.envX, `${where}: camera.envX`), vec3(c.envY, `${where}: camera.envY`),
      vec3(c.envZ, `${where}: camera.envZ`)];
    const e = new THREE.Matrix3().set(x.x, y.x, z.x, x.y, y.y, z.y, x.z, y.z, z.z);  // columns envX, envY, envZ
    const worldFromView = new THREE.Matrix3().setFromMatrix4(camera.matrixWorld);
    const r = e.multiply(worldFromView.transpose());
    // A rotation, or the axes belong to another camera.
    const rt = r.clone().transpose().multiply(r);
    const id = new THREE.Matrix3();
    const off = Math.max(...rt.elements.map((x, i) => Math.abs(x - id.elements[i])));
    if (!(off < 1e-3) || !(r.determinant() > 0))
      throw new Error(`${where}: camera.envX/envY/envZ and the camera's orientation do not give a rotation ` +
        `(|R^T R - I| = ${off}): the axes must be the lab's for this camera`);
    return r;
  }
  const deg = c.environmentRotationDegrees ?? 0;
  if (!Number.isFinite(deg)) throw new Error(`${where}: camera.environmentRotationDegrees is not a number`);
  return new THREE.Matrix3().setFromMatrix4(new THREE.Matrix4().makeRotationY(THREE.MathUtils.degToRad(deg)));
}

// The environment as the scene's background and environment, turned as the lab turns it for camera
// description `c` (made into `camera` by assetCamera).
export function setEnvironment(scene, env, c, camera, where = "camera") {
  scene.background = env;
  scene.environment = env;
  // three.js looks d up at M^T d (M: backgroundRotation / environmentRotation as a matrix); it must be
  // labToThree * labRotation * d.
  const mt = labToThree.clone().multiply(labEnvironmentRotation(c, camera, where));
  const m4 = new THREE.Matrix4().setFromMatrix3(mt.clone().transpose());
  scene.backgroundRotation.setFromRotationMatrix(m4);
  scene.environmentRotation.setFromRotationMatrix(m4);
}

// The float target the scene is rendered into (linear RGBA, read back or presented by the caller).
export function floatRenderTarget(width, height) {
  return new THREE.WebGLRenderTarget(width, height, { type: THREE.FloatType, format: THREE.RGBAFormat,
    minFilter: THREE.NearestFilter, magFilter: THREE.NearestFilter, generateMipmaps: false, depthBuffer: true,
    stencilBuffer: false, samples: 0 });
}

// All of it, in the order the lab's row has always built it: the environment texture, the asset, the
// camera, the environment's rotation, the target. `environment`: { texels, width, height }; `camera`: the
// description above. Returns { scene, camera, target, environment, glass, unlit, glassMeshes, opaqueMeshes,
// ms: { gltf } } (ms.gltf: GLTFLoader's parse and the material replacement).
export async function gltfScene({ glb, environment, camera: c, width, height, where = "camera" }) {
  if (!Number.isInteger(width) || !Number.isInteger(height) || width < 1 || height < 1)
    throw new Error(`${where}: the image size ${width} x ${height} is not one`);
  const env = environmentTexture(environment.texels, environment.width, environment.height);
  const t0 = performance.now();
  const asset = await loadAsset(glb);
  const ms = { gltf: performance.now() - t0 };
  const camera = assetCamera(c ?? {}, width, height, where);
  setEnvironment(asset.scene, env, c, camera, where);
  return { ...asset, camera, target: floatRenderTarget(width, height), environment: env, ms };
}
