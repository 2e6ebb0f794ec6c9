/*
description: reconstruct the view-space position seen at a uv from a depth-buffer
  value (snellUvDepthToView) or from a linear view distance (snellUvDistanceToView).
use: SnellViewPoint p = snellUvDepthToView(uv, depthValue, viewFromClip, SNELL_DEPTH_GL);
     SnellViewPoint p = snellUvDistanceToView(uv, viewDistance, viewFromClip);
  viewFromClip  inverse of the projection (snellPerspectiveInverse, or your
                engine's inverse projection matrix)
  depthValue    the stored depth-buffer value ([0,1], window space), not NDC z
  viewDistance  -z_view (> 0), e.g. snellLinearizeDepth(...) or a linear depth texture
contract:
  - snellUvDepthToView: ndc = (2 uv - 1, snellDepthToNdcZ(depthValue, convention)),
    h = viewFromClip * vec4(ndc, 1), position = h.xyz / h.w. depthValue is clamped
    to [0,1]; uv outside [0,1] is allowed (the point is off screen).
  - snellUvDistanceToView: the point at z = -viewDistance on the ray from the eye
    through uv (found by unprojecting NDC z = 0.5, a finite point in front of the
    camera for every convention); position.z == -viewDistance exactly. Requires a
    perspective projection (eye at the view-space origin).
  - valid is true exactly when the result is finite and in front of the camera
    (position.z < 0). It is false, with position (0,0,0), for NaN/Inf inputs, an
    unknown convention, depth on the far plane of an infinite convention (depth 1
    INFINITE_GL, depth 0 INFINITE_REVERSED: h.w = 0, the point is at infinity, e.g.
    sky pixels), a zero/singular matrix (|h.w| below the smallest normal float),
    viewDistance <= 0 or denormal (at or behind the camera) or a reconstruction at or behind the camera plane.
source: OpenGL 4.5 core spec sec. 13.6, inverted; Oliveira & Brauwers 2007 sec.
  3.2.1 (camera-space points from depth maps under perspective projection).
*/
#ifndef SNELL_CAMERA_UV_DEPTH_TO_VIEW_GLSL
#define SNELL_CAMERA_UV_DEPTH_TO_VIEW_GLSL
#include "../prelude.glsl"
#include "conventions.glsl"
#include "depth_to_ndc_z.glsl"

struct SnellViewPoint {
  vec3 position;
  bool valid;
};

SNELL_FN SnellViewPoint snellUvDepthToView(vec2 uv, float depthValue, mat4 viewFromClip, int convention) {
  SnellViewPoint r;
  r.position = vec3(0.0f, 0.0f, 0.0f);
  r.valid = false;
  if (!SNELL_FINITE(uv.x) || !SNELL_FINITE(uv.y) || isnan(depthValue) || convention < 0 ||
      convention >= SNELL_DEPTH_CONVENTION_COUNT) {
    return r;
  }
  float zNdc = snellDepthToNdcZ(depthValue, convention);
  vec4 h = SNELL_MUL(viewFromClip, vec4(2.0f * uv.x - 1.0f, 2.0f * uv.y - 1.0f, zNdc, 1.0f));
  if (!SNELL_FINITE(h.w) || !(abs(h.w) >= SNELL_FLT_MIN)) {
    return r;
  }
  vec3 p = vec3(h.x, h.y, h.z) / h.w;
  if (!SNELL_FINITE(p.x) || !SNELL_FINITE(p.y) || !SNELL_FINITE(p.z) || !(p.z < 0.0f)) {
    return r;
  }
  r.position = p;
  r.valid = true;
  return r;
}

SNELL_FN SnellViewPoint snellUvDistanceToView(vec2 uv, float viewDistance, mat4 viewFromClip) {
  SnellViewPoint r;
  r.position = vec3(0.0f, 0.0f, 0.0f);
  r.valid = false;
  if (!SNELL_FINITE(uv.x) || !SNELL_FINITE(uv.y) || !SNELL_FINITE(viewDistance) ||
      !(viewDistance >= SNELL_FLT_MIN)) {
    return r;
  }
  vec4 h = SNELL_MUL(viewFromClip, vec4(2.0f * uv.x - 1.0f, 2.0f * uv.y - 1.0f, 0.5f, 1.0f));
  if (!SNELL_FINITE(h.w) || !(abs(h.w) >= SNELL_FLT_MIN)) {
    return r;
  }
  vec3 q = vec3(h.x, h.y, h.z) / h.w;
  if (!SNELL_FINITE(q.x) || !SNELL_FINITE(q.y) || !SNELL_FINITE(q.z) || !(q.z < 0.0f)) {
    return r;
  }
  float s = viewDistance / -q.z;
  vec3 p = vec3(q.x * s, q.y * s, -viewDistance);
  if (!SNELL_FINITE(p.x) || !SNELL_FINITE(p.y)) {
    return r;
  }
  r.position = p;
  r.valid = true;
  return r;
}

#endif
