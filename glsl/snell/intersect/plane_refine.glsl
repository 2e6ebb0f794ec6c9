/*
description: what the two plane strategies (plane_normal.glsl, plane_depth.glsl)
  share: the iteration options of Mayer & Assarsson's step 5 ("iteratively
  refine the approximation, using P_e as the location to sample screen buffers
  and generate a new plane") and the final step 4 lookup that turns a plane
  hit into a SnellHit (snellPlaneHit, on intersect/hit_on_surface.glsl).
use: SnellHit h = snellPlaneHit(p, planeUv, depthTex, surface, fetchesSoFar);
options:
  SNELL_PLANE_ITERATIONS      refinement iterations callers pass by default (1);
                              0 is the constant-time method (one plane)
  SNELL_PLANE_MAX_ITERATIONS  compile-time bound of the refinement loops (8); a
                              per-call count is clamped to [0, this]
  SNELL_PLANE_FACING_FALLBACK 1 (default): when a ray does not meet plane k
                              ahead of its origin, plane k is replaced by the
                              plane through the same surface point B_k facing
                              the camera (normal = B_k, the line of sight);
                              0: plane k is a miss (k = 0) or ends the
                              refinement, as in the poster
contract (snellPlaneHit): the comment above the function.
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
#include "surface_projection.glsl"
#include "hit_on_surface.glsl"

#ifndef SNELL_PLANE_ITERATIONS
#  define SNELL_PLANE_ITERATIONS 1
#endif
#ifndef SNELL_PLANE_MAX_ITERATIONS
#  define SNELL_PLANE_MAX_ITERATIONS 8
#endif
/* Why the facing fallback: near the silhouette of a convex object, the back
   face's tangent plane at B_0 (the point behind W) leans away from the
   refracted ray, which is bent inwards, so the ray never meets it and the
   poster's method has no hit at all for a band of rim pixels (21.8% of a
   glass sphere's non-TIR pixels, normal-based). The facing plane is the limit
   of Mayer & Assarsson's blurred normal level ("a more blurred mip level gives
   a more complete representation of the scene for drastic refraction
   effects"): a ray going deeper always meets it, and the refinement then walks
   along the back surface to tangent planes the ray does meet. Same fetches. */
#ifndef SNELL_PLANE_FACING_FALLBACK
#  define SNELL_PLANE_FACING_FALLBACK 1
#endif
/* 1: a plane hit whose projection lands on an empty texel is kept on the last
   valid plane (snellPlaneHit) on a surface whose emptiness hides more of it
   (SnellDepthSurface.closed, the default: a closed object's back faces curve
   away behind their silhouette); 0: it is a miss on every surface. */
#ifndef SNELL_PLANE_HOLD
#  define SNELL_PLANE_HOLD 1
#endif

/* The last step of both plane methods (Mayer & Assarsson steps 4-5): the plane
   hit p is accepted where the buffer has a surface at its projection. Where it has
   none (the tangent plane of a convex object's back face lies outside the object,
   so rim rays project past the silhouette), the plane itself is the best estimate
   left: with SNELL_PLANE_HOLD, on a closed surface (s.closed: an open one such
   as the opaque scene has nothing behind its empty texels but the
   environment), the hit stays at p, valid, with uv = planeUv, the
   texel the plane was built from, so a normal read at h.uv returns that plane's
   normal. Off-screen or behind-the-camera p is a miss either way, and so is a
   NaN or infinite planeUv (no texel: the hit's uv stays finite). */
SNELL_FN SnellHit snellPlaneHit(vec3 p, vec2 planeUv, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) s, int fetchesSoFar) {
  SnellHit h = snellHitOnSurface(p, depthTex, s, fetchesSoFar);
  if (h.valid || SNELL_PLANE_HOLD == 0 || !s.closed) {
    return h;
  }
  SnellScreenPoint sp = snellSurfaceViewToUv(s, p);
  if (!sp.valid || !(sp.uv.x >= 0.0f && sp.uv.x <= 1.0f && sp.uv.y >= 0.0f && sp.uv.y <= 1.0f) ||
      !SNELL_FINITE(planeUv.x) || !SNELL_FINITE(planeUv.y)) {
    return h;
  }
  h.uv = planeUv;
  h.position = p;
  h.valid = true;
  return h;
}

#endif
