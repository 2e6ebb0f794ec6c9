/*
description: project a view-space point to viewport uv ([0,1]^2, origin
  bottom-left) and NDC z, in one call.
use: SnellScreenPoint sp = snellViewToUv(clipFromView, pView);
     if (sp.valid) { vec4 c = SNELL_SAMPLE_LOD(tex, sp.uv, 0.0f); float d = snellNdcZToDepth(sp.ndcZ, conv); }
contract:
  - with clip = snellViewToClip(clipFromView, pView): uv = 0.5 clip.xy / clip.w
    + 0.5 and ndcZ = clip.z / clip.w, each quotient clamped to
    +-SNELL_FLT_MAX (as snellClipToNdc's ndc).
  - valid is false (uv = (0,0), ndcZ = 0) when clip x, y or w is NaN or Inf
    or clip w <= 0 (denormal w counting as 0): points at or behind the camera,
    NaN or Inf coordinates, NaN or Inf entries outside the matrix's third row;
    otherwise all results are finite, also for points off screen (uv outside
    [0,1]).
  - clip z decides nothing, so a caller that reads only uv does not pay for
    the matrix's third row: an infinite clip z (an Inf in that row, or an
    overflow) gives ndcZ = +-SNELL_FLT_MAX, a NaN one (a NaN in that row, or
    Inf - Inf, Inf * 0 there) ndcZ = 0; uv and valid are those of a clean
    row. (snellClipToNdc, which takes the clip point, still rejects a
    non-finite z.)
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
  vec4 clip = snellViewToClip(clipFromView, pView);
  SnellScreenPoint r;
  r.uv = vec2(0.0f, 0.0f);
  r.ndcZ = 0.0f;
  r.valid = false;
  // Clip z decides nothing: a caller that reads only uv lets the compiler
  // drop the matrix's third row.
  if (!SNELL_FINITE(clip.x) || !SNELL_FINITE(clip.y) || !SNELL_FINITE(clip.w) || !(clip.w >= SNELL_FLT_MIN)) {
    return r;
  }
  float ndcX = clamp(clip.x / clip.w, -SNELL_FLT_MAX, SNELL_FLT_MAX);
  float ndcY = clamp(clip.y / clip.w, -SNELL_FLT_MAX, SNELL_FLT_MAX);
  float ndcZ = clip.z / clip.w;
  r.uv = vec2(ndcX, ndcY) * 0.5f + 0.5f;
  r.ndcZ = isnan(ndcZ) ? 0.0f : clamp(ndcZ, -SNELL_FLT_MAX, SNELL_FLT_MAX);
  r.valid = true;
  return r;
}

#endif
