/*
description: depth-buffer value <-> NDC z for a depth convention (the
  glDepthRange / viewport depth transform with its default range).
use: float zNdc = snellDepthToNdcZ(depthValue, SNELL_DEPTH_GL);
     float depthValue = snellNdcZToDepth(zNdc, SNELL_DEPTH_GL);
contract:
  - SNELL_DEPTH_GL and SNELL_DEPTH_INFINITE_GL: z_ndc = 2 d - 1, d = 0.5 z_ndc + 0.5;
    every other convention (ZERO_ONE, REVERSED, INFINITE_REVERSED, and unknown
    values) has NDC z in [0,1] and stores it unchanged.
  - inputs are clamped into their range first (depth [0,1]; NDC z [-1,1] or
    [0,1]), which is what a depth buffer (or GL_DEPTH_CLAMP) does with them;
    NaN is treated as the low end of the range. Results are always finite.
source: OpenGL 4.5 core spec sec. 13.6.1 (z_w = (f - n)/2 z_d + (n + f)/2 with the
  default glDepthRange(0,1)) and sec. 13.7 (glClipControl GL_ZERO_TO_ONE: z_w = z_d).
*/
#ifndef SNELL_CAMERA_DEPTH_TO_NDC_Z_GLSL
#define SNELL_CAMERA_DEPTH_TO_NDC_Z_GLSL
#include "../prelude.glsl"
#include "conventions.glsl"

SNELL_FN float snellDepthToNdcZ(float depthValue, int convention) {
  float d = isnan(depthValue) ? 0.0f : clamp(depthValue, 0.0f, 1.0f);
  if (convention == SNELL_DEPTH_GL || convention == SNELL_DEPTH_INFINITE_GL) {
    return 2.0f * d - 1.0f;
  }
  return d;
}

SNELL_FN float snellNdcZToDepth(float ndcZ, int convention) {
  if (convention == SNELL_DEPTH_GL || convention == SNELL_DEPTH_INFINITE_GL) {
    float z = isnan(ndcZ) ? -1.0f : clamp(ndcZ, -1.0f, 1.0f);
    return 0.5f * z + 0.5f;
  }
  return isnan(ndcZ) ? 0.0f : clamp(ndcZ, 0.0f, 1.0f);
}

#endif
