/*
description: linear march in view space with binary refinement: the screen-space
  ray-marching baseline. Equal steps along the view-space ray, each projected
  with the depth buffer's camera and compared with the stored surface; the
  first step behind the surface is refined by bisection.
use: SnellHit h = snellLinearMarch(origin, dir, depthTex, surface);
     SnellHit h = snellLinearMarch(origin, dir, depthTex, surface, maxDistance, steps, refineSteps);
  origin, dir        view-space ray (dir need not be normalized)
  depthTex, surface  the depth buffer and how to read it (depth_surface.glsl)
  maxDistance        view-space length of the marched part of the ray
  steps              equal steps of maxDistance / steps (one fetch each)
  refineSteps        bisection steps inside the step that crossed (one fetch
                     each while on screen)
options:
  SNELL_LINEAR_MARCH_STEPS              default steps (32)
  SNELL_LINEAR_MARCH_MAX_STEPS          compile-time bound (512); steps is clamped to [1, max]
  SNELL_LINEAR_MARCH_REFINE_STEPS       default refineSteps (4)
  SNELL_LINEAR_MARCH_MAX_REFINE_STEPS   compile-time bound (24); refineSteps clamped to [0, max]
  SNELL_LINEAR_MARCH_MAX_DISTANCE       default maxDistance (10.0f view-space units)
contract:
  - the ray is marched over t in (0, tMax], tMax = maxDistance / |dir|, cut at
    the near plane z = -surface.zNear when dir.z > 0 (a ray towards the camera
    is marched until it would leave the frustum through the near plane).
    Samples t_i = i tMax / steps, i = 1 .. steps (the origin itself is not
    tested); each is projected with surface.clipFromView (snellViewToUv).
  - a sample "crosses" when its texel is valid and the point is on or behind the
    surface (z <= viewZ): the surface is a solid height field (infinitely thick).
    Empty texels do not stop the march (no surface there).
  - the first sample that projects off screen (uv outside [0,1]^2, or not
    projectable) ends the march: valid = false (the ray left the screen).
  - refinement: bracket [t_(i-1), t_i]; a midpoint that crosses moves hi, any
    other (in front, empty, off screen: no fetch then) moves lo. The result is
    hi: a point on or behind the surface at a valid texel, never in front of
    the crossing; uv = the uv that was fetched there. Error along the ray <=
    (tMax / steps) 0.5^refineSteps for a single crossing (plus the depth
    buffer's own discretization).
  - valid = false with snellHitMiss numbers (finite) and the fetches spent when
    no sample crosses; with 0 fetches when: an input is NaN or Inf, |dir| is 0
    or denormal-small, maxDistance <= 0, or the origin is at or in front of
    the near plane with dir.z > 0 (the whole ray is outside the frustum).
source: the classic screen-space ray march (e.g. Sousa, "Crysis 2", 2011;
  Policarpo et al. 2005 for linear + binary search), here in view space with
  the Oliveira & Brauwers 2007 (sec. 3.1) depth-surface reading.
*/
#ifndef SNELL_INTERSECT_LINEAR_MARCH_GLSL
#define SNELL_INTERSECT_LINEAR_MARCH_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"
#include "../camera/view_to_uv.glsl"
#include "hit.glsl"
#include "depth_surface.glsl"
#include "surface_projection.glsl"

#ifndef SNELL_LINEAR_MARCH_STEPS
#  define SNELL_LINEAR_MARCH_STEPS 32
#endif
#ifndef SNELL_LINEAR_MARCH_MAX_STEPS
#  define SNELL_LINEAR_MARCH_MAX_STEPS 512
#endif
#ifndef SNELL_LINEAR_MARCH_REFINE_STEPS
#  define SNELL_LINEAR_MARCH_REFINE_STEPS 4
#endif
#ifndef SNELL_LINEAR_MARCH_MAX_REFINE_STEPS
#  define SNELL_LINEAR_MARCH_MAX_REFINE_STEPS 24
#endif
#ifndef SNELL_LINEAR_MARCH_MAX_DISTANCE
#  define SNELL_LINEAR_MARCH_MAX_DISTANCE 10.0f
#endif

/* screen-space ray march: equal view-space steps, then bisection */
SNELL_FN SnellHit snellLinearMarch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface,
                                   float maxDistance, int steps, int refineSteps) {
  if (!SNELL_FINITE(origin.x) || !SNELL_FINITE(origin.y) || !SNELL_FINITE(origin.z) ||
      !SNELL_FINITE(dir.x) || !SNELL_FINITE(dir.y) || !SNELL_FINITE(dir.z) ||
      !SNELL_FINITE(maxDistance) || !(maxDistance > 0.0f)) {
    return snellHitMiss(0);
  }
  float len = length(dir);
  if (!SNELL_FINITE(len) || !(len >= SNELL_FLT_MIN)) {
    return snellHitMiss(0);
  }
  float tMax = maxDistance / len;
  if (dir.z > 0.0f) {
    float tNear = (-surface.zNear - origin.z) / dir.z;
    // tNear is finite or +-inf here (a finite numerator over dir.z > 0): +inf is a near plane too far along
    // the ray for a float, never reached, and leaves tMax; -inf (the origin is before the plane) ends it.
    tMax = isnan(tNear) ? 0.0f : min(tMax, tNear);
  }
  if (!SNELL_FINITE(tMax) || !(tMax > 0.0f)) {
    return snellHitMiss(0);
  }
  int n = clamp(steps, 1, SNELL_LINEAR_MARCH_MAX_STEPS);
  int nr = clamp(refineSteps, 0, SNELL_LINEAR_MARCH_MAX_REFINE_STEPS);
  float dt = tMax / float(n);
  int fetches = 0;
  bool found = false;
  float tHit = 0.0f;
  vec2 uvHit = vec2(0.0f, 0.0f);
  for (int i = 1; i <= SNELL_LINEAR_MARCH_MAX_STEPS; ++i) {
    float t = float(i) * dt;
    vec3 p = origin + t * dir;
    SnellScreenPoint sp = snellSurfaceViewToUv(surface, p);
    if (!sp.valid || !(sp.uv.x >= 0.0f && sp.uv.x <= 1.0f && sp.uv.y >= 0.0f && sp.uv.y <= 1.0f)) {
      return snellHitMiss(fetches);
    }
    SnellSurfaceSample x = snellSampleSurface(depthTex, sp.uv, surface);
    fetches = fetches + 1;
    if (x.valid && p.z <= x.viewZ) {
      found = true;
      tHit = t;
      uvHit = sp.uv;
      break;
    }
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (i >= n) {
      break;
    }
  }
  if (!found) {
    return snellHitMiss(fetches);
  }
  float lo = tHit - dt;
  for (int j = 0; nr > 0 && j < SNELL_LINEAR_MARCH_MAX_REFINE_STEPS; ++j) {
    float mid = 0.5f * (lo + tHit);
    vec3 q = origin + mid * dir;
    SnellScreenPoint sq = snellSurfaceViewToUv(surface, q);
    bool crosses = false;
    if (sq.valid && sq.uv.x >= 0.0f && sq.uv.x <= 1.0f && sq.uv.y >= 0.0f && sq.uv.y <= 1.0f) {
      SnellSurfaceSample y = snellSampleSurface(depthTex, sq.uv, surface);
      fetches = fetches + 1;
      crosses = y.valid && q.z <= y.viewZ;
    }
    if (crosses) {
      tHit = mid;
      uvHit = sq.uv;
    } else {
      lo = mid;
    }
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (j + 1 >= nr) {
      break;
    }
  }
  SnellHit h;
  h.uv = uvHit;
  h.position = origin + tHit * dir;
  h.valid = true;
  h.fetches = fetches;
  return h;
}

SNELL_FN SnellHit snellLinearMarch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface) {
  return snellLinearMarch(origin, dir, depthTex, surface, SNELL_LINEAR_MARCH_MAX_DISTANCE, SNELL_LINEAR_MARCH_STEPS,
                          SNELL_LINEAR_MARCH_REFINE_STEPS);
}

#endif
