/*
description: depth-buffer value <-> positive view distance, for every depth
  convention of conventions.glsl.
use: float v = snellLinearizeDepth(depthValue, zNear, zFar, SNELL_DEPTH_GL);
     float d = snellDelinearizeDepth(v, zNear, zFar, SNELL_DEPTH_REVERSED);
  depthValue    what the depth buffer stores (window-space depth, [0,1]), NOT NDC z
  viewDistance  -z_view of the point (> 0 in front of the camera)
  zNear, zFar   the camera's clip-plane distances (> 0); zFar is ignored by the
                two INFINITE conventions
  convention    SNELL_DEPTH_GL, _ZERO_ONE, _REVERSED, _INFINITE_GL, _INFINITE_REVERSED
contract (v = view distance, d = depth value, n = zNear, f = zFar):
  - GL, ZERO_ONE:     d = f (v - n) / (v (f - n)),  v = n / ((1 - d) + d n / f)
    REVERSED:         d = n (f - v) / (v (f - n)),  v = n / (d + (1 - d) n / f)
    INFINITE_GL:      d = 1 - n / v,                v = n / (1 - d)
    INFINITE_REVERSED d = n / v,                    v = n / d
    (each evaluated in a form without cancellation: every sum adds positive terms)
  - snellLinearizeDepth returns a value in [n, f] (finite conventions) or
    [n, SNELL_FLT_MAX] (infinite ones): depth out of [0,1] is clamped into it
    first; the far plane of an infinite convention (d = 1 INFINITE_GL, d = 0
    INFINITE_REVERSED) returns SNELL_FLT_MAX. Depth 0 (GL/ZERO_ONE) returns n, depth
    1 returns f (REVERSED: the other way round).
  - snellLinearizeDepth returns 0.0f (never a valid distance, every valid one is
    >= n > 0) when: depthValue is NaN, zNear is not a finite positive number, zFar
    is not finite or not > zNear (finite conventions only), or the convention is
    unknown. A denormal zNear or depthValue counts as 0 (GPUs may flush it).
  - snellDelinearizeDepth returns a value in [0,1]; the distance is clamped into
    [n, f] (finite conventions) or [n, +inf) first, so points nearer than the near
    plane, at or behind the camera (v <= 0), give the near-plane value and points
    beyond the far plane (or +Inf) the far-plane value. NaN distance or invalid
    zNear/zFar/convention (as above) give the far-plane value, i.e. the depth
    buffer's clear value "nothing there": 1.0f, or 0.0f for the REVERSED ones
    (1.0f for an unknown convention).
  - the maps are inverse to each other up to rounding (a few ulp relative in v).
source: the window depth of glm::perspective / perspectiveZO / infinitePerspective
  (GLM 0.9.9 ext/matrix_clip_space.inl) under glDepthRange(0,1) (OpenGL 4.5 core
  spec sec. 13.6.1); reversed Z: 1 - d of the ZERO_ONE mapping. Oliveira &
  Brauwers 2007 (Algorithm 2) use such a positive view distance ("recover a
  positive Z value") for the stored depth.
*/
#ifndef SNELL_CAMERA_LINEARIZE_DEPTH_GLSL
#define SNELL_CAMERA_LINEARIZE_DEPTH_GLSL
#include "../prelude.glsl"
#include "conventions.glsl"

SNELL_FN_INLINE float snellLinearizeDepth(float depthValue, float zNear, float zFar, int convention) {
  bool infinite = convention == SNELL_DEPTH_INFINITE_GL || convention == SNELL_DEPTH_INFINITE_REVERSED;
  if (isnan(depthValue) || !SNELL_FINITE(zNear) || !(zNear >= SNELL_FLT_MIN)) {
    return 0.0f;
  }
  if (!infinite && (!SNELL_FINITE(zFar) || !(zFar > zNear))) {
    return 0.0f;
  }
  float d = clamp(depthValue, 0.0f, 1.0f);
  float v = 0.0f;
  if (convention == SNELL_DEPTH_GL || convention == SNELL_DEPTH_ZERO_ONE) {
    v = zNear / ((1.0f - d) + d * (zNear / zFar));
  } else if (convention == SNELL_DEPTH_REVERSED) {
    v = zNear / (d + (1.0f - d) * (zNear / zFar));
  } else if (convention == SNELL_DEPTH_INFINITE_GL) {
    v = d < 1.0f ? zNear / (1.0f - d) : SNELL_FLT_MAX;
  } else if (convention == SNELL_DEPTH_INFINITE_REVERSED) {
    v = d >= SNELL_FLT_MIN ? zNear / d : SNELL_FLT_MAX;  // a denormal depth is 0, the far plane
  } else {
    return 0.0f;
  }
  // Division results can overflow (n / denormal); clamp keeps them finite.
  return clamp(v, zNear, infinite ? SNELL_FLT_MAX : zFar);
}

SNELL_FN float snellDelinearizeDepth(float viewDistance, float zNear, float zFar, int convention) {
  bool reversed = convention == SNELL_DEPTH_REVERSED || convention == SNELL_DEPTH_INFINITE_REVERSED;
  bool infinite = convention == SNELL_DEPTH_INFINITE_GL || convention == SNELL_DEPTH_INFINITE_REVERSED;
  float farValue = reversed ? 0.0f : 1.0f;
  if (convention < 0 || convention >= SNELL_DEPTH_CONVENTION_COUNT || isnan(viewDistance) ||
      !SNELL_FINITE(zNear) || !(zNear >= SNELL_FLT_MIN)) {
    return farValue;
  }
  if (!infinite && (!SNELL_FINITE(zFar) || !(zFar > zNear))) {
    return farValue;
  }
  if (!(viewDistance > zNear)) {
    return reversed ? 1.0f : 0.0f;  // at or nearer than the near plane, or behind the camera
  }
  float v = viewDistance;
  if (infinite) {
    if (isinf(v)) {
      return farValue;
    }
  } else if (v >= zFar) {
    return farValue;
  }
  float d = 0.0f;
  if (convention == SNELL_DEPTH_GL || convention == SNELL_DEPTH_ZERO_ONE) {
    d = ((v - zNear) / v) * (zFar / (zFar - zNear));
  } else if (convention == SNELL_DEPTH_REVERSED) {
    d = (zNear / v) * ((zFar - v) / (zFar - zNear));
  } else if (convention == SNELL_DEPTH_INFINITE_GL) {
    d = (v - zNear) / v;
  } else {
    d = zNear / v;
  }
  return clamp(d, 0.0f, 1.0f);
}

#endif
