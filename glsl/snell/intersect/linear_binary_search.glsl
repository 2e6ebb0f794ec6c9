/*
description: linear-then-binary search (relief mapping) of a view-space ray
  against a depth-buffer surface, in texture space along S-E: equal steps in
  beta until the first sample that is not in front of the surface, then a plain
  binary search inside that step. Finds thin structures the pure binary searches
  skip, at the cost of the linear steps; like snellBinarySearch it may end on an
  empty texel.
use: SnellHit h = snellLinearBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest);
     SnellHit h = snellLinearBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest,
                                          linearSteps, binarySteps);
  arguments as snellConservativeBinarySearch
  linearSteps   number of equal beta steps (1/linearSteps each, one fetch each)
  binarySteps   binary steps inside the bracketing step (one fetch each)
options:
  SNELL_LINEAR_SEARCH_STEPS      default linearSteps (10, relief mapping's usual)
  SNELL_LINEAR_SEARCH_MAX_STEPS  compile-time bound (256); linearSteps is
                                 clamped to [1, SNELL_LINEAR_SEARCH_MAX_STEPS]
  SNELL_BINARY_SEARCH_STEPS, SNELL_BINARY_SEARCH_MAX_STEPS  (binary_search.glsl):
                                 default and bound of binarySteps (clamped to [0, max])
contract:
  - segment S-E and beta as snellConservativeBinarySearch. Linear phase: beta_i
    = i / linearSteps, i = 1 .. linearSteps; it stops at the first sample that
    is not (valid texel and strictly in front of the surface, z > viewZ): behind
    the surface or an empty / off-screen texel (relief mapping's depth-0 rule).
  - no such sample up to E: valid = false, snellHitMiss numbers, fetches spent.
  - binary phase: bracket [beta_(i-1), beta_i], the rule of snellBinarySearch;
    the result is the last point tested (the linear sample itself when
    binarySteps = 0); valid = that point's texel is valid; when not, uv and
    position still report where the search ended (finite), as snellBinarySearch.
  - precision: for a ray crossing the surface once on S-E, |beta - beta*| <=
    0.5^binarySteps / linearSteps.
  - invalid segment (rays towards the camera, Zmin == Zmax, NaN: see
    search_segment.glsl): valid = false, snellHitMiss numbers, 0 fetches.
source: F. Policarpo, M. M. Oliveira, J. Comba, "Real-Time Relief Mapping on
  Arbitrary Polygonal Surfaces", I3D 2005 (linear then binary search);
  Oliveira & Brauwers 2007, sec. 3.3 (why refraction can skip the linear
  phase), eqs. 3-10.
*/
#ifndef SNELL_INTERSECT_LINEAR_BINARY_SEARCH_GLSL
#define SNELL_INTERSECT_LINEAR_BINARY_SEARCH_GLSL
#include "../prelude.glsl"
#include "../camera/tex_ray.glsl"
#include "hit.glsl"
#include "depth_surface.glsl"
#include "search_segment.glsl"
#include "binary_search.glsl"

#ifndef SNELL_LINEAR_SEARCH_STEPS
#  define SNELL_LINEAR_SEARCH_STEPS 10
#endif
#ifndef SNELL_LINEAR_SEARCH_MAX_STEPS
#  define SNELL_LINEAR_SEARCH_MAX_STEPS 256
#endif

/* Policarpo et al. 2005, linear + binary search, on Oliveira & Brauwers 2007 eqs. 5-10 */
SNELL_FN SnellHit snellLinearBinarySearch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface,
                                          float zNearest, float zFarthest, int linearSteps, int binarySteps) {
  SnellTexRay r = snellSearchSegment(origin, dir, zNearest, zFarthest, surface.clipFromView);
  if (!r.valid) {
    return snellHitMiss(0);
  }
  int nl = clamp(linearSteps, 1, SNELL_LINEAR_SEARCH_MAX_STEPS);
  int nb = clamp(binarySteps, 0, SNELL_BINARY_SEARCH_MAX_STEPS);
  float dz = r.e.z - r.s.z;
  float stepBeta = 1.0f / float(nl);
  int fetches = 0;
  int found = -1;
  float beta = 0.0f;
  float z = r.s.z;
  vec2 uv = r.ts;
  bool lastValid = false;
  for (int i = 1; i <= SNELL_LINEAR_SEARCH_MAX_STEPS; ++i) {
    beta = float(i) * stepBeta;
    z = r.s.z + beta * dz;
    uv = snellTexRayUv(r, z);
    SnellSurfaceSample x = snellSampleSurface(depthTex, uv, surface);
    fetches = fetches + 1;
    if (!(x.valid && z > x.viewZ)) {
      found = i;
      lastValid = x.valid;
      break;
    }
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (i >= nl) {
      break;
    }
  }
  if (found < 0) {
    return snellHitMiss(fetches);
  }
  SnellHit h;
  h.uv = uv;
  h.position = vec3(r.s.x + beta * (r.e.x - r.s.x), r.s.y + beta * (r.e.y - r.s.y), z);
  h.valid = lastValid;
  h.fetches = fetches;
  return snellBisectTexRay(r, depthTex, surface, float(found - 1) * stepBeta, beta, nb, h);
}

SNELL_FN SnellHit snellLinearBinarySearch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) surface,
                                          float zNearest, float zFarthest) {
  return snellLinearBinarySearch(origin, dir, depthTex, surface, zNearest, zFarthest, SNELL_LINEAR_SEARCH_STEPS,
                                 SNELL_BINARY_SEARCH_STEPS);
}

#endif
