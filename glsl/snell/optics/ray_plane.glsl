/*
description: intersection of a ray with a plane given by a point and a normal.
use: SnellRayPlaneHit h = snellRayPlane(origin, dir, planePoint, planeNormal);
     if (h.valid) { ... h.position ... }
  origin       ray origin
  dir          ray direction (need not be normalized: h.t is measured in units
               of |dir|, h.position = origin + h.t * dir)
  planePoint   any point on the plane
  planeNormal  plane normal, either orientation, need not be normalized
options:
  SNELL_RAY_PLANE_PARALLEL_EPS  |cos| between dir and the plane normal below
                                which the ray counts as parallel (1e-6f)
contract:
  - valid hit: t = dot(planePoint - origin, n) / dot(dir, n) >= 0 (a ray
    starting on the plane hits at t = 0), point = origin + t dir;
  - h.valid is false, with h.t = 0 and h.position = (0,0,0) (finite, never NaN),
    when: the ray is parallel to the plane (within the epsilon above, also when
    it lies in it), the hit is behind the origin (t < 0), dir or planeNormal is
    zero, denormal-small, NaN or infinite, dir's squared length overflows a
    float (|dir| above about 1.8e19), origin or planePoint has a NaN or
    infinite component, or t or the point overflows.
source: the parametric line p = o + t d (G. Oliveira 2000, Equations 9-10)
  substituted into the plane equation dot(p - p0, n) = 0.
*/
#ifndef SNELL_OPTICS_RAY_PLANE_GLSL
#define SNELL_OPTICS_RAY_PLANE_GLSL
#include "../prelude.glsl"
#include "safe_normalize.glsl"

#ifndef SNELL_RAY_PLANE_PARALLEL_EPS
#  define SNELL_RAY_PLANE_PARALLEL_EPS 1e-6f
#endif

struct SnellRayPlaneHit {
  float t;
  vec3 position;  // not "point": a reserved word in HLSL (geometry shader input)
  bool valid;
};

SNELL_FN SnellRayPlaneHit snellRayPlane(vec3 origin, vec3 dir, vec3 planePoint, vec3 planeNormal) {
  SnellRayPlaneHit h;
  h.t = 0.0f;
  h.position = vec3(0.0f, 0.0f, 0.0f);
  h.valid = false;
  vec3 n = snellSafeNormalize(planeNormal);
  float dirLen2 = dot(dir, dir);
  // dirLen2 = +inf is a dir too long to square; FLT_MAX itself is a finite length, sqrt and all.
  if (dot(n, n) == 0.0f || !(dirLen2 > 1e-30f) || !(dirLen2 <= SNELL_FLT_MAX)) {
    return h;
  }
  if (!SNELL_FINITE(origin.x) || !SNELL_FINITE(origin.y) || !SNELL_FINITE(origin.z) ||
      !SNELL_FINITE(planePoint.x) || !SNELL_FINITE(planePoint.y) || !SNELL_FINITE(planePoint.z)) {
    return h;
  }
  float denom = dot(dir, n);
  if (!(abs(denom) > SNELL_RAY_PLANE_PARALLEL_EPS * sqrt(dirLen2))) {
    return h;
  }
  float t = dot(planePoint - origin, n) / denom;
  if (!(t >= 0.0f) || !(t <= SNELL_FLT_MAX)) {
    return h;
  }
  vec3 p = origin + t * dir;
  if (!SNELL_FINITE(p.x) || !SNELL_FINITE(p.y) || !SNELL_FINITE(p.z)) {
    return h;
  }
  h.t = t;
  h.position = p;
  h.valid = true;
  return h;
}

#endif
