/*
description: project a view-space point to viewport uv ([0,1]^2, origin
  bottom-left) and NDC z, in one call.
use: SnellScreenPoint sp = snellViewToUv(clipFromView, pView);
     if (sp.valid) { vec4 c = SNELL_SAMPLE_LOD(tex, sp.uv, 0.0f); float d = snellNdcZToDepth(sp.ndcZ, conv); }
contract:
  - uv = 0.5 ndc.xy + 0.5 and ndcZ = ndc.z with ndc from
    snellClipToNdc(snellViewToClip(clipFromView, pView)); valid is that call's valid.
  - valid is false (uv = (0,0), ndcZ = 0) for points at or behind the camera
    (clip w <= 0), NaN or Inf; otherwise all results are finite (clamped to
    +-SNELL_FLT_MAX), also for points off screen (uv outside [0,1]).
  - ndcZ is NDC z, not a depth-buffer value: snellNdcZToDepth converts it.
source: Oliveira & Brauwers 2007, Algorithm 1 (t' = 0.5 (S~.xy / S~.w) + 0.5).
*/
#ifndef SNELL_CAMERA_VIEW_TO_UV_GLSL
#define SNELL_CAMERA_VIEW_TO_UV_GLSL
#include "../prelude.glsl"
#include "conventions.glsl"
#include "view_to_clip.glsl"

struct SnellScreenPoint {
  vec2 uv;
  float ndcZ;
  bool valid;
};

SNELL_FN SnellScreenPoint snellViewToUv(mat4 clipFromView, vec3 pView) {
  SnellNdc n = snellClipToNdc(snellViewToClip(clipFromView, pView));
  SnellScreenPoint r;
  r.uv = vec2(0.0f, 0.0f);
  r.ndcZ = 0.0f;
  r.valid = n.valid;
  if (n.valid) {
    r.uv = vec2(n.ndc.x, n.ndc.y) * 0.5f + 0.5f;
    r.ndcZ = n.ndc.z;
  }
  return r;
}

#endif
