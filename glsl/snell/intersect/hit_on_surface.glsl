/*
description: a view-space point accepted as a hit where a depth buffer has a
  surface at its projection: the last lookup of the plane methods (Mayer &
  Assarsson step 4) and of Wyman's distance estimate, which both produce a
  point first and ask the buffer afterwards.
use: SnellHit h = snellHitOnSurface(p, depthTex, surface, fetchesSoFar);
contract:
  - projects the view-space point p; the hit is (uv = its projection, position
    = p) and valid exactly when p is finite, in front of the camera, projects
    into [0,1]^2 and the depth texture has a surface at that uv
    (snellSampleSurface valid, level s.lod): the approximation landed on the
    surface, not in an empty texel or off screen.
  - fetches = fetchesSoFar + 1 when p projects (the step 4 lookup; an off-screen
    uv is counted though snellSampleSurface answers it without reading), else
    fetchesSoFar. A miss is snellHitMiss with that count.
source: C. Mayer, U. Assarsson, "Constant-Time Light Refraction Simulation",
  step 4.
*/
#ifndef SNELL_INTERSECT_HIT_ON_SURFACE_GLSL
#define SNELL_INTERSECT_HIT_ON_SURFACE_GLSL
#include "../prelude.glsl"
#include "../camera/view_to_uv.glsl"
#include "hit.glsl"
#include "depth_surface.glsl"
#include "surface_projection.glsl"

SNELL_FN SnellHit snellHitOnSurface(vec3 p, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) s, int fetchesSoFar) {
  SnellScreenPoint sp = snellSurfaceViewToUv(s, p);
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
