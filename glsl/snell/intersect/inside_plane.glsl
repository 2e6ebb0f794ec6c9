/*
description: where a ray inside a closed object leaves it, with Mayer &
  Assarsson's normal-based plane in place of the bisection: a coarse march
  between the object's two depth layers brackets the exit (the last inside
  sample, the first outside one: snellInsideBracket), then the layer the ray
  crossed is read at the outside sample (depth and normal) and the ray is
  intersected with that tangent plane, re-read where it lands and
  intersected again, `iterations` times (their step 5). Exact on planar
  faces from the first plane; a few march steps replace the march's
  bisections. Why the plane is not started at the ray origin as on the back
  slot: a ray inside starts on a layer (the point of the last total internal
  reflection), so the layer at its own pixel is the face it leaves from,
  whose plane it meets at t = 0; its exit lies elsewhere on screen, which
  only a search finds.
use: SnellInsideHit h = snellInsidePlane(origin, dir, backDepth, backNormal, back,
                                         frontDepth, frontNormal, front, maxDistance, steps, iterations);
  origin, dir        view-space ray starting inside the object; dir any length
  backDepth, backNormal, back    the back-face depth (GL_GREATER after
                     clearing to the near value), its view-space normals
                     (xyz, any length, either orientation; read at level 0
                     with the texture's filter) and how to read the depth
  frontDepth, frontNormal, front the front faces' (GL_LESS after clearing to
                     the far value)
  maxDistance        view-space length of the marched part of the ray
  steps              march steps (snellInsideMarch's), clamped to
                     [1, SNELL_LINEAR_MARCH_MAX_STEPS]
  iterations         planes, clamped to [0, SNELL_PLANE_MAX_ITERATIONS]; 0 is
                     the bracket's outside sample
contract:
  - the bracket is snellInsideBracket(origin, dir, ..., maxDistance, steps)
    (inside_march.glsl); when it is invalid: valid = false, snellHitMiss with
    its fetches.
  - plane k (k = 1 .. iterations) on the layer the bracket crossed (its side):
    B_k = snellSurfacePoint of that layer's depth at uv_(k-1) (uv_0 the
    bracket's uv, the outside sample's pixel; when plane 1 read there is not
    kept, it is read again at the bracket's loUv, the last inside sample's
    pixel, where the object is, and then on the other layer at loUv, whose
    plane, when kept, makes that layer the side; then each kept hit's
    projection), n_k = xyz of its normals read at
    B_k's texel centre, level 0 (SNELL_SAMPLE_LOD); t_k = snellRayPlane(origin,
    dir, B_k, n_k).t. The plane is kept only when it is met inside the
    bracket, lo <= t_k <= hi (a tangent plane met outside it describes another
    part of the layer) and t_k's point projects on screen; otherwise the
    iterations stop at the last kept t (the bracket's hi at first).
  - the hit: position origin + t dir, uv its projection (the bracket's uv when
    no plane was kept), valid = true, front = the side is the front layer (the
    bracket's side, or the other layer's when its plane 1 was kept).
  - fetches: the bracket's, plus 2 per plane read (depth and normal; 1 when
    the depth texel is empty), plane 1's second and third reads included.
  - bad input (NaN or Inf, zero dir, maxDistance <= 0): the bracket's miss,
    0 fetches; never NaN.
source: C. Mayer, U. Assarsson, "Constant-Time Light Refraction Simulation",
  "Method 1: Normal-based" and step 5; C. Davis & C. Wyman, "Interactive
  Refractions with Total Internal Reflection", Graphics Interface 2007 (the
  search between front and back depth maps).
*/
#ifndef SNELL_INTERSECT_INSIDE_PLANE_GLSL
#define SNELL_INTERSECT_INSIDE_PLANE_GLSL
#include "../prelude.glsl"
#include "../optics/ray_plane.glsl"
#include "hit.glsl"
#include "depth_surface.glsl"
#include "surface_projection.glsl"
#include "surface_point.glsl"
#include "plane_refine.glsl"
#include "inside_march.glsl"

/* Mayer & Assarsson's normal plane on the layer a march between the two layers crossed (Davis & Wyman 2007) */
SNELL_FN SnellInsideHit snellInsidePlane(vec3 origin, vec3 dir, SNELL_TEX2D backDepth, SNELL_TEX2D backNormal,
                                         SNELL_IN(SnellDepthSurface) back, SNELL_TEX2D frontDepth,
                                         SNELL_TEX2D frontNormal, SNELL_IN(SnellDepthSurface) front,
                                         float maxDistance, int steps, int iterations) {
  SnellInsideHit r;
  r.front = false;
  SnellInsideBracket b = snellInsideBracket(origin, dir, backDepth, back, frontDepth, front, maxDistance, steps);
  r.hit = snellHitMiss(b.fetches);
  if (!b.valid) {
    return r;
  }
  bool onFront = b.side == 2;
  int n = clamp(iterations, 0, SNELL_PLANE_MAX_ITERATIONS);
  int fetches = b.fetches;
  float t = b.hi;
  vec2 uv = b.uv;
  // Plane 1 is read at the outside sample's pixel, else at the last inside one's, else on the other layer
  // there: beside the silhouette the outside pixel holds neither layer (and the side is the guess of
  // snellInsideSide), near an edge of the object the inside pixel may hold the face the ray comes from.
  vec2 readUv = b.uv;
  bool readFront = onFront;
  int planes = 0;
  int misses = 0;
  for (int k = 1; n > 0 && k <= SNELL_PLANE_MAX_ITERATIONS + 2; ++k) {
    SnellSurfacePoint s;  // not ?: : WebGL rejects it on structs
    if (readFront) {
      s = snellSurfacePoint(frontDepth, readUv, front);
    } else {
      s = snellSurfacePoint(backDepth, readUv, back);
    }
    fetches = fetches + 1;
    bool kept = false;
    if (s.valid) {
      vec4 nk = readFront ? SNELL_SAMPLE_LOD(frontNormal, s.uv, 0.0f) : SNELL_SAMPLE_LOD(backNormal, s.uv, 0.0f);
      fetches = fetches + 1;
      SnellRayPlaneHit ph = snellRayPlane(origin, dir, s.position, vec3(nk.x, nk.y, nk.z));
      if (ph.valid && ph.t >= b.lo && ph.t <= b.hi) {
        SnellScreenPoint sp = snellSurfaceViewToUv(back, ph.position);
        if (sp.valid && sp.uv.x >= 0.0f && sp.uv.x <= 1.0f && sp.uv.y >= 0.0f && sp.uv.y <= 1.0f) {
          t = ph.t;
          uv = sp.uv;
          readUv = sp.uv;
          onFront = readFront;
          planes = planes + 1;
          kept = true;
        }
      }
    }
    if (!kept) {
      if (planes > 0 || misses >= 2) {
        break;
      }
      misses = misses + 1;
      readUv = b.loUv;
      readFront = misses == 1 ? onFront : !onFront;
    }
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (planes >= n) {
      break;
    }
  }
  r.hit.position = origin + t * dir;
  r.hit.uv = uv;
  r.hit.valid = true;
  r.hit.fetches = fetches;
  r.front = onFront;
  return r;
}

#endif
