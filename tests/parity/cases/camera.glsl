/* Parity cases for glsl/snell/camera: one entry per public function.
   Inputs arrive as four vec4s, results leave as four vec4s (bools as 0/1).
   Depth conventions and integer pixel values arrive as integral floats (the
   generators never send NaN there: int(NaN) is undefined). Matrices are built
   from (fovy, aspect, zNear, zFar) with snellPerspectiveWithDepth, the same way
   on both sides, and leave as their four columns. */
#include "snell/camera.glsl"

SNELL_FN float cameraParityFlag(bool b) {
  return b ? 1.0f : 0.0f;
}

SNELL_FN SnellParityOut cameraParityMatrix(mat4 m) {
  SnellParityOut o;
  o.a = SNELL_MUL(m, vec4(1.0f, 0.0f, 0.0f, 0.0f));
  o.b = SNELL_MUL(m, vec4(0.0f, 1.0f, 0.0f, 0.0f));
  o.c = SNELL_MUL(m, vec4(0.0f, 0.0f, 1.0f, 0.0f));
  o.d = SNELL_MUL(m, vec4(0.0f, 0.0f, 0.0f, 1.0f));
  return o;
}

SNELL_FN SnellParityOut cameraParityOut(vec4 a) {
  SnellParityOut o;
  o.a = a;
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* a = (depthValue, zNear, zFar, convention) */
SNELL_FN SnellParityOut caseSnellLinearizeDepth(vec4 a, vec4 b, vec4 c, vec4 d) {
  return cameraParityOut(vec4(snellLinearizeDepth(a.x, a.y, a.z, int(a.w)), 0.0f, 0.0f, 0.0f));
}

/* a = (viewDistance, zNear, zFar, convention) */
SNELL_FN SnellParityOut caseSnellDelinearizeDepth(vec4 a, vec4 b, vec4 c, vec4 d) {
  return cameraParityOut(vec4(snellDelinearizeDepth(a.x, a.y, a.z, int(a.w)), 0.0f, 0.0f, 0.0f));
}

/* a = (depthValue, convention) */
SNELL_FN SnellParityOut caseSnellDepthToNdcZ(vec4 a, vec4 b, vec4 c, vec4 d) {
  return cameraParityOut(vec4(snellDepthToNdcZ(a.x, int(a.y)), 0.0f, 0.0f, 0.0f));
}

/* a = (ndcZ, convention) */
SNELL_FN SnellParityOut caseSnellNdcZToDepth(vec4 a, vec4 b, vec4 c, vec4 d) {
  return cameraParityOut(vec4(snellNdcZToDepth(a.x, int(a.y)), 0.0f, 0.0f, 0.0f));
}

/* a = (fovy, aspect, zNear, zFar); out: the four columns */
SNELL_FN SnellParityOut caseSnellPerspective(vec4 a, vec4 b, vec4 c, vec4 d) {
  return cameraParityMatrix(snellPerspective(a.x, a.y, a.z, a.w));
}

/* a = (fovy, aspect, zNear, zFar), b.x = convention */
SNELL_FN SnellParityOut caseSnellPerspectiveWithDepth(vec4 a, vec4 b, vec4 c, vec4 d) {
  return cameraParityMatrix(snellPerspectiveWithDepth(a.x, a.y, a.z, a.w, int(b.x)));
}

/* a = (fovy, aspect, zNear, zFar), b.x = convention */
SNELL_FN SnellParityOut caseSnellPerspectiveInverse(vec4 a, vec4 b, vec4 c, vec4 d) {
  return cameraParityMatrix(snellPerspectiveInverse(a.x, a.y, a.z, a.w, int(b.x)));
}

/* a = camera, b.x = convention, c.xyz = view-space point; out a = clip */
SNELL_FN SnellParityOut caseSnellViewToClip(vec4 a, vec4 b, vec4 c, vec4 d) {
  mat4 m = snellPerspectiveWithDepth(a.x, a.y, a.z, a.w, int(b.x));
  return cameraParityOut(snellViewToClip(m, vec3(c.x, c.y, c.z)));
}

/* a = clip; out a = (ndc, valid) */
SNELL_FN SnellParityOut caseSnellClipToNdc(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellNdc n = snellClipToNdc(a);
  return cameraParityOut(vec4(n.ndc.x, n.ndc.y, n.ndc.z, cameraParityFlag(n.valid)));
}

/* a = camera, b.x = convention, c.xyz = view-space point; out a = (uv, ndcZ, valid) */
SNELL_FN SnellParityOut caseSnellViewToUv(vec4 a, vec4 b, vec4 c, vec4 d) {
  mat4 m = snellPerspectiveWithDepth(a.x, a.y, a.z, a.w, int(b.x));
  SnellScreenPoint sp = snellViewToUv(m, vec3(c.x, c.y, c.z));
  return cameraParityOut(vec4(sp.uv.x, sp.uv.y, sp.ndcZ, cameraParityFlag(sp.valid)));
}

/* a = (px.x, px.y, size.x, size.y) as integral floats; out a.xy = uv */
SNELL_FN SnellParityOut caseSnellPixelToUv(vec4 a, vec4 b, vec4 c, vec4 d) {
  vec2 uv = snellPixelToUv(ivec2(int(a.x), int(a.y)), ivec2(int(a.z), int(a.w)));
  return cameraParityOut(vec4(uv.x, uv.y, 0.0f, 0.0f));
}

/* a = (uv.x, uv.y, size.x, size.y); out a.xy = pixel (integral floats) */
SNELL_FN SnellParityOut caseSnellUvToPixel(vec4 a, vec4 b, vec4 c, vec4 d) {
  ivec2 px = snellUvToPixel(vec2(a.x, a.y), ivec2(int(a.z), int(a.w)));
  return cameraParityOut(vec4(float(px.x), float(px.y), 0.0f, 0.0f));
}

/* a = camera, b = (convention, uv.x, uv.y, depthValue); viewFromClip from
   snellPerspectiveInverse; out a = (position, valid) */
SNELL_FN SnellParityOut caseSnellUvDepthToView(vec4 a, vec4 b, vec4 c, vec4 d) {
  mat4 inv = snellPerspectiveInverse(a.x, a.y, a.z, a.w, int(b.x));
  SnellViewPoint p = snellUvDepthToView(vec2(b.y, b.z), b.w, inv, int(b.x));
  return cameraParityOut(vec4(p.position.x, p.position.y, p.position.z, cameraParityFlag(p.valid)));
}

/* a = camera, b = (convention, uv.x, uv.y, viewDistance); out a = (position, valid) */
SNELL_FN SnellParityOut caseSnellUvDistanceToView(vec4 a, vec4 b, vec4 c, vec4 d) {
  mat4 inv = snellPerspectiveInverse(a.x, a.y, a.z, a.w, int(b.x));
  SnellViewPoint p = snellUvDistanceToView(vec2(b.y, b.z), b.w, inv);
  return cameraParityOut(vec4(p.position.x, p.position.y, p.position.z, cameraParityFlag(p.valid)));
}

/* a = camera, b = (p1, zNearest), c = (t1, zFarthest), d.x = convention */
SNELL_FN SnellTexRay cameraParityTexRay(vec4 a, vec4 b, vec4 c, vec4 d) {
  mat4 m = snellPerspectiveWithDepth(a.x, a.y, a.z, a.w, int(d.x));
  return snellTexRaySetup(vec3(b.x, b.y, b.z), vec3(c.x, c.y, c.z), b.w, c.w, m);
}

/* out a = (S, valid), b = (E, k1), c = (t's, dt), d = (k2, 0, 0, 0) */
SNELL_FN SnellParityOut caseSnellTexRaySetup(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellTexRay r = cameraParityTexRay(a, b, c, d);
  SnellParityOut o;
  o.a = vec4(r.s.x, r.s.y, r.s.z, cameraParityFlag(r.valid));
  o.b = vec4(r.e.x, r.e.y, r.e.z, r.k1);
  o.c = vec4(r.ts.x, r.ts.y, r.dt.x, r.dt.y);
  o.d = vec4(r.k2, 0.0f, 0.0f, 0.0f);
  return o;
}

/* as caseSnellTexRaySetup, d.y = pz; out a = (alpha, valid) */
SNELL_FN SnellParityOut caseSnellTexRayAlpha(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellTexRay r = cameraParityTexRay(a, b, c, d);
  return cameraParityOut(vec4(snellTexRayAlpha(r, d.y), cameraParityFlag(r.valid), 0.0f, 0.0f));
}

/* as caseSnellTexRaySetup, d.y = pz; out a = (uv, valid) */
SNELL_FN SnellParityOut caseSnellTexRayUv(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellTexRay r = cameraParityTexRay(a, b, c, d);
  vec2 uv = snellTexRayUv(r, d.y);
  return cameraParityOut(vec4(uv.x, uv.y, cameraParityFlag(r.valid), 0.0f));
}
