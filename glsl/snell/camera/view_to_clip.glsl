/*
description: view space -> clip space -> NDC, with the perspective divide made
  safe for points at or behind the camera.
use: vec4 clip = snellViewToClip(clipFromView, pView);
     SnellNdc n = snellClipToNdc(clip);   // n.ndc, n.valid
contract:
  - snellViewToClip is clipFromView * vec4(pView, 1) (SNELL_MUL), nothing else:
    no check, NaN and Inf propagate as the matrix product makes them.
  - snellClipToNdc: valid is true exactly when all four clip components are
    finite and clip.w > 0, denormal w counting as 0 (for the perspective matrices of perspective.glsl,
    w = -z_view: the point is in front of the camera). Then ndc = clip.xyz / w,
    each component clamped to [-SNELL_FLT_MAX, SNELL_FLT_MAX] (a tiny w makes the
    quotient overflow). Otherwise (w <= 0: at or behind the camera's plane; NaN
    or Inf) valid is false and ndc is (0,0,0).
  - points outside the frustum but in front of the camera are valid; their NDC
    lie outside [-1,1].
source: OpenGL 4.5 core spec sec. 13.6 (perspective division).
*/
#ifndef SNELL_CAMERA_VIEW_TO_CLIP_GLSL
#define SNELL_CAMERA_VIEW_TO_CLIP_GLSL
#include "../prelude.glsl"
#include "conventions.glsl"

struct SnellNdc {
  vec3 ndc;
  bool valid;
};

SNELL_FN vec4 snellViewToClip(mat4 clipFromView, vec3 pView) {
  return SNELL_MUL(clipFromView, vec4(pView.x, pView.y, pView.z, 1.0f));
}

SNELL_FN SnellNdc snellClipToNdc(vec4 clip) {
  SnellNdc r;
  r.ndc = vec3(0.0f, 0.0f, 0.0f);
  r.valid = false;
  if (!SNELL_FINITE(clip.x) || !SNELL_FINITE(clip.y) || !SNELL_FINITE(clip.z) ||
      !SNELL_FINITE(clip.w) || !(clip.w >= SNELL_FLT_MIN)) {
    return r;
  }
  vec3 q = vec3(clip.x, clip.y, clip.z) / clip.w;
  r.ndc = clamp(q, vec3(-SNELL_FLT_MAX, -SNELL_FLT_MAX, -SNELL_FLT_MAX),
                vec3(SNELL_FLT_MAX, SNELL_FLT_MAX, SNELL_FLT_MAX));
  r.valid = true;
  return r;
}

#endif
