// A snell-lab web bundle's camera (bundle.json: viewFromWorld, clipFromView, zNear, zFar, envX/Y/Z) as the
// camera description gltf_scene.js takes (position, target, up, fovYDegrees, near, far, envX/Y/Z). No
// imports: Node (tools/browser/threejs_render.mjs --bundle) and the page (main.js, ?renderer=threejs) both
// use it.
export function cameraFromBundle(b) {
  const v = b.viewFromWorld, p = b.clipFromView;
  if (!Array.isArray(v) || v.length !== 16 || !Array.isArray(p) || p.length !== 16) throw new Error("no viewFromWorld/clipFromView");
  // viewFromWorld = [R t; 0 1]: worldFromView = [R^T, -R^T t]. Column-major: R(r, c) = v[4c + r].
  const R = (r, c) => v[4 * c + r];
  const t = [v[12], v[13], v[14]];
  const position = [0, 1, 2].map((i) => -(R(0, i) * t[0] + R(1, i) * t[1] + R(2, i) * t[2]));
  const row = (r) => [R(r, 0), R(r, 1), R(r, 2)];  // the view axes in world space: rows of R
  const forward = row(2).map((x) => -x);
  return {
    position,
    target: position.map((x, i) => x + forward[i]),
    up: row(1),
    fovYDegrees: (2 * Math.atan(1 / p[5]) * 180) / Math.PI,
    near: b.zNear,
    far: b.zFar,
    envX: b.envX,
    envY: b.envY,
    envZ: b.envZ,
  };
}
