/*
description: the ray segment the texture-space searches walk (conservative
  binary search, binary search, linear+binary search): the part of a view-space
  ray between two constant-z planes that bound the surface in depth, in the
  perspective texture-space parameterization of Oliveira & Brauwers 2007.
use: SnellTexRay r = snellSearchSegment(origin, dir, zNearest, zFarthest, surface.clipFromView);
     // beta in [0,1] along S-E (eq. 5): z = r.s.z + beta (r.e.z - r.s.z), uv = snellTexRayUv(r, z)
  origin     view-space ray origin (P1: the front-face hit for the back-face
             buffer, the back-face exit point for the opaque scene buffer)
  dir        ray direction (need not be normalized)
  zNearest   view-space z (< 0) of the nearest surface point, the paper's Zmin as
             a z value (the LARGER, less negative one); zFarthest: of the farthest
             (the paper's Zmax, more negative). Where they come from is the
             caller's business, both are just two numbers: the top level of the
             depth min/max pyramid (exact for the buffer), or the object's
             bounding box / bounding sphere transformed to view space (looser,
             so more steps for the same precision, never wrong).
contract:
  - the segment starts at S on the plane z = min(zNearest, origin.z): where the
    ray meets zNearest, or at the origin itself when the origin is already
    deeper than zNearest (a search never runs backwards along the ray); it ends
    at E on the plane z = zFarthest. k1, k2, ts, dt as snellTexRaySetup.
  - valid = false (every field 0, finite) when: any input is NaN or Inf (matrix
    included, but for its third row, which snellTexRaySetup does not read);
    dir.z >= 0 or denormal (the ray points towards the camera or runs parallel
    to the image plane: it never reaches deeper planes); zNearest <=
    zFarthest (Zmin == Zmax, swapped or empty range); the origin is at or beyond
    zFarthest (nothing left to search); and every case snellTexRaySetup
    rejects (a plane at or behind the eye, S or E not projectable, overflow).
source: Oliveira & Brauwers 2007, sec. 3.2.1, eqs. 3-4 (S and E), Figure 5
  (Zmin, Zmax); camera/tex_ray.glsl for eqs. 5-10.
*/
#ifndef SNELL_INTERSECT_SEARCH_SEGMENT_GLSL
#define SNELL_INTERSECT_SEARCH_SEGMENT_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"
#include "../camera/tex_ray.glsl"

SNELL_FN_INLINE SnellTexRay snellSearchSegment(vec3 origin, vec3 dir, float zNearest, float zFarthest, mat4 clipFromView) {
  SnellTexRay bad;
  bad.s = vec3(0.0f, 0.0f, 0.0f);
  bad.e = vec3(0.0f, 0.0f, 0.0f);
  bad.k1 = 0.0f;
  bad.k2 = 0.0f;
  bad.ts = vec2(0.0f, 0.0f);
  bad.dt = vec2(0.0f, 0.0f);
  bad.valid = false;
  if (!SNELL_FINITE(origin.z) || !SNELL_FINITE(dir.z) || !SNELL_FINITE(zNearest) ||
      !SNELL_FINITE(zFarthest)) {
    return bad;
  }
  if (!(dir.z <= -SNELL_FLT_MIN) || !(zNearest > zFarthest) || !(origin.z > zFarthest)) {
    return bad;
  }
  float zStart = origin.z < zNearest ? origin.z : zNearest;
  return snellTexRaySetup(origin, dir, zStart, zFarthest, clipFromView);
}

#endif
