/*
description: plain binary search of a view-space ray against a depth-buffer
  surface, in texture space along S-E (Policarpo et al. 2005's refinement, with
  Oliveira & Brauwers' perspective parameterization). It may end on an empty
  texel: the failure conservative_binary_search.glsl exists to avoid. Kept as a
  baseline so tests and the lab can show it.
use: SnellHit h = snellBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest);
     SnellHit h = snellBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest, steps);
     SnellHit h = snellBisectTexRay(r, depthTex, surface, lo, hi, steps, hitSoFar);
  arguments as snellConservativeBinarySearch; steps = binary steps (one fetch each)
options:
  SNELL_BINARY_SEARCH_STEPS      default steps (5)
  SNELL_BINARY_SEARCH_MAX_STEPS  compile-time loop bound (24); steps is clamped
                                 to [0, SNELL_BINARY_SEARCH_MAX_STEPS]
contract:
  - segment S-E and beta as snellConservativeBinarySearch. Bracket [lo, hi] =
    [0, 1]; each step tests mid = (lo + hi) / 2 (one fetch): a valid texel with
    the point strictly in front of the surface (z > viewZ) moves lo to mid,
    anything else (behind the surface, or an empty / off-screen texel, which the
    paper's depth-0 storage makes look like "behind") moves hi to mid.
  - the result is the last point tested (Figure 6's point 4), uv its texture
    coordinate, position S + beta (E - S); steps = 0 tests S itself (one fetch).
  - valid = whether that last texel was valid (non-empty, on screen). When it
    is not, uv and position still report where the search ended (finite), so
    the failure can be seen and counted: that is this function's point.
  - precision: for a ray crossing the surface once on S-E, |beta - beta*| <=
    0.5^c (the last midpoint is an end of the final bracket, of width 0.5^c).
  - valid = false with snellHitMiss numbers and 0 fetches when the segment is
    invalid (rays towards the camera, Zmin == Zmax, NaN: see search_segment.glsl).
  - snellBisectTexRay(r, depthTex, surface, lo, hi, steps, h): the loop itself,
    for a valid segment r (snellSearchSegment) and a bracket [lo, hi] in beta,
    each clamped to [0, 1]: clamp(steps, 0, SNELL_BINARY_SEARCH_MAX_STEPS)
    steps of the rule above; after each, h = the point tested (uv, position,
    valid as above) with h.fetches + 1. With 0 steps, or a NaN lo or hi, h is
    returned as given.
source: F. Policarpo, M. M. Oliveira, J. Comba, "Real-Time Relief Mapping on
  Arbitrary Polygonal Surfaces", I3D 2005 (binary search); Oliveira & Brauwers
  2007, sec. 3.3 and Figure 6 (why it can end on an invalid texel), eqs. 3-10.
*/
#ifndef SNELL_INTERSECT_BINARY_SEARCH_GLSL
#define SNELL_INTERSECT_BINARY_SEARCH_GLSL
#include "../prelude.glsl"
#include "../camera/tex_ray.glsl"
#include "hit.glsl"
#include "depth_surface.glsl"
#include "search_segment.glsl"

#ifndef SNELL_BINARY_SEARCH_STEPS
#  define SNELL_BINARY_SEARCH_STEPS 5
#endif
#ifndef SNELL_BINARY_SEARCH_MAX_STEPS
#  define SNELL_BINARY_SEARCH_MAX_STEPS 24
#endif

/* The bisection loop of Policarpo et al. 2005, shared by snellBinarySearch and
   the refinement of snellLinearBinarySearch (see the contract). */
SNELL_FN SnellHit snellBisectTexRay(SnellTexRay r, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface, float lo,
                                    float hi, int steps, SnellHit h) {
  if (isnan(lo) || isnan(hi)) {
    return h;
  }
  // Outside [0, 1] the midpoints would extrapolate past S or E.
  lo = clamp(lo, 0.0f, 1.0f);
  hi = clamp(hi, 0.0f, 1.0f);
  int n = clamp(steps, 0, SNELL_BINARY_SEARCH_MAX_STEPS);
  float dz = r.e.z - r.s.z;
  for (int i = 0; n > 0 && i < SNELL_BINARY_SEARCH_MAX_STEPS; ++i) {
    float beta = 0.5f * (lo + hi);
    float z = r.s.z + beta * dz;
    vec2 uv = snellTexRayUv(r, z);
    SnellSurfaceSample x = snellSampleSurface(depthTex, uv, surface);
    h.uv = uv;
    h.position = vec3(r.s.x + beta * (r.e.x - r.s.x), r.s.y + beta * (r.e.y - r.s.y), z);
    h.valid = x.valid;
    h.fetches = h.fetches + 1;
    if (x.valid && z > x.viewZ) {
      lo = beta;
    } else {
      hi = beta;
    }
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (i + 1 >= n) {
      break;
    }
  }
  return h;
}

/* Policarpo et al. 2005 binary search on Oliveira & Brauwers 2007, eqs. 5-10 */
SNELL_FN SnellHit snellBinarySearch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface,
                                    float zNearest, float zFarthest, int steps) {
  SnellTexRay r = snellSearchSegment(origin, dir, zNearest, zFarthest, surface.clipFromView);
  if (!r.valid) {
    return snellHitMiss(0);
  }
  SnellHit h;
  h.uv = r.ts;
  h.position = r.s;
  h.valid = false;
  h.fetches = 0;
  if (steps <= 0) {
    h.valid = snellSampleSurface(depthTex, r.ts, surface).valid;
    h.fetches = 1;
    return h;
  }
  return snellBisectTexRay(r, depthTex, surface, 0.0f, 1.0f, steps, h);
}

SNELL_FN SnellHit snellBinarySearch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface,
                                    float zNearest, float zFarthest) {
  return snellBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest, SNELL_BINARY_SEARCH_STEPS);
}

#endif
