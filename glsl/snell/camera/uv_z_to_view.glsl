/*
description: the inverse projection for a known view z: the view-space point
  on the pixel ray of a uv at a given depth, without an inverse matrix (the
  surface strategies reconstruct every depth texel through it).
use: SnellViewPoint p = snellUvZToView(clipFromView, uv, viewZ);
  uv            viewport uv ([0,1]^2, origin bottom-left)
  viewZ         view-space z (< 0) of the wanted point
  clipFromView  any projection with clip w = -z (perspective.glsl, glm::perspective*,
                glFrustum, off-centre frusta); no inverse matrix is needed
contract:
  - the point p with p.z == viewZ whose projection has NDC xy =
    2 uv - 1, from the 2x2 linear system clip.xy = ndc.xy clip.w (Cramer's rule on
    the matrix columns). valid =
    false, position (0,0,0), when an input is NaN/Inf, viewZ >= 0 or denormal, the
    system is singular (|det| below the smallest normal float) or the result
    overflows.
source: OpenGL 4.5 core spec sec. 13.6 (clip -> NDC).
*/
#ifndef SNELL_CAMERA_UV_Z_TO_VIEW_GLSL
#define SNELL_CAMERA_UV_Z_TO_VIEW_GLSL
#include "../prelude.glsl"
#include "conventions.glsl"
#include "uv_depth_to_view.glsl"

SNELL_FN SnellViewPoint snellUvZToView(mat4 clipFromView, vec2 uv, float viewZ) {
  SnellViewPoint r;
  r.position = vec3(0.0f, 0.0f, 0.0f);
  r.valid = false;
  if (!SNELL_FINITE(uv.x) || !SNELL_FINITE(uv.y) || !SNELL_FINITE(viewZ) ||
      !(viewZ <= -SNELL_FLT_MIN)) {
    return r;
  }
  vec4 c0 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 0);
  vec4 c1 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 1);
  vec4 c2 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 2);
  vec4 c3 = SNELL_CAMERA_MAT_COLUMN(clipFromView, 3);
  float nx = 2.0f * uv.x - 1.0f;
  float ny = 2.0f * uv.y - 1.0f;
  // x a00 + y a01 = b0,  x a10 + y a11 = b1
  float a00 = c0.x - nx * c0.w;
  float a01 = c1.x - nx * c1.w;
  float a10 = c0.y - ny * c0.w;
  float a11 = c1.y - ny * c1.w;
  float b0 = -(viewZ * (c2.x - nx * c2.w) + (c3.x - nx * c3.w));
  float b1 = -(viewZ * (c2.y - ny * c2.w) + (c3.y - ny * c3.w));
  float det = a00 * a11 - a01 * a10;
  if (!SNELL_FINITE(det) || !(abs(det) >= SNELL_FLT_MIN)) {
    return r;
  }
  float x = (b0 * a11 - a01 * b1) / det;
  float y = (a00 * b1 - b0 * a10) / det;
  if (!SNELL_FINITE(x) || !SNELL_FINITE(y)) {
    return r;
  }
  r.position = vec3(x, y, viewZ);
  r.valid = true;
  return r;
}

#endif
