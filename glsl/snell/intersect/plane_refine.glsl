/*
description: what the two plane strategies (plane_normal.glsl, plane_depth.glsl)
  share: the iteration options of Mayer & Assarsson's step 5 ("iteratively
  refine the approximation, using P_e as the location to sample screen buffers
  and generate a new plane") and the final step 4 lookup that turns a point on
  the ray into a SnellHit.
use: SnellHit h = snellHitOnSurface(p, depthTex, surface, fetchesSoFar);
options:
  SNELL_PLANE_ITERATIONS      refinement iterations callers pass by default (1);
                              0 is the constant-time method (one plane)
  SNELL_PLANE_MAX_ITERATIONS  compile-time bound of the refinement loops (8); a
                              per-call count is clamped to [0, this]
contract (snellHitOnSurface):
  - projects the view-space point p; the hit is (uv = its projection, position
    = p) and valid exactly when p is finite, in front of the camera, projects
    into [0,1]^2 and the depth texture has a surface at that uv
    (snellSampleSurface valid, level s.lod): the approximation landed on the
    surface, not in an empty texel or off screen.
  - fetches = fetchesSoFar + 1 when p projects (the step 4 lookup; an off-screen
    uv is counted though snellSampleSurface answers it without reading), else
    fetchesSoFar. A miss is snellHitMiss with that count.
source: C. Mayer, U. Assarsson, "Constant-Time Light Refraction Simulation",
  steps 4 and 5.
*/
#ifndef SNELL_INTERSECT_PLANE_REFINE_GLSL
#define SNELL_INTERSECT_PLANE_REFINE_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"
#include "../camera/view_to_uv.glsl"
#include "hit.glsl"
#include "depth_surface.glsl"

#ifndef SNELL_PLANE_ITERATIONS
#  define SNELL_PLANE_ITERATIONS 1
#endif
#ifndef SNELL_PLANE_MAX_ITERATIONS
#  define SNELL_PLANE_MAX_ITERATIONS 8
#endif

SNELL_FN SnellHit snellHitOnSurface(vec3 p, SNELL_TEX2D depthTex, SnellDepthSurface s, int fetchesSoFar) {
  SnellScreenPoint sp = snellViewToUv(s.clipFromView, p);
  if (!sp.valid) {
    return snellHitMiss(fetchesSoFar);
  }
  SnellSurfaceSample x = snellSampleSurface(depthTex, sp.uv, s);
  if (!x.valid) {
    return snellHitMiss(fetchesSoFar + 1);
  }
  SnellHit h;
  h.uv = sp.uv;
  h.position = p;
  h.valid = true;
  h.fetches = fetchesSoFar + 1;
  return h;
}

#endif
