/*
description: Mayer & Assarsson's planar approximation, method 1 (normal-based):
  the depth and normal stored behind the ray origin define a plane; the ray is
  intersected with it, the intersection projected and the buffers sampled
  there; optionally the plane is rebuilt at that sample and the ray
  re-intersected, N times (step 5). Constant time for a fixed N.
use: SnellHit h = snellIntersectPlaneNormal(origin, dir, depthTex, normalTex, pyramidTex,
                                            surface, normalLod, SNELL_PLANE_ITERATIONS, true);
  origin     view-space ray start W (z < 0): front-face point (back-face buffer)
             or exit point (opaque scene buffer)
  dir        ray direction (any length)
  depthTex   the depth texture `surface` describes (read at level surface.lod)
  normalTex  view-space normals (xyz, any length, either orientation) matching
             depthTex texel for texel at level 0; it may be mipmapped and filtered
             (Mayer & Assarsson: "a more blurred mip level gives a more complete
             representation of the scene for drastic refraction effects")
  pyramidTex depthTex's min/max pyramid (intersect/depth_pyramid.glsl), read by
             the far start only (any texture when farStart is false)
  normalLod  the level normals are read at (SNELL_SAMPLE_LOD, the texture's filters)
  iterations refinement iterations, clamped to [0, SNELL_PLANE_MAX_ITERATIONS]
  farStart   true: on a closed surface (surface.closed, an object's back faces),
             plane 0's hit is the nearer of the poster's (below) and the far
             start's (intersect/plane_far_start.glsl: the farthest back face the
             pyramid holds under the ray's way); false: the poster's method
contract:
  - plane k (k = 0 .. N): uv_0 = projection of W, uv_k = projection of P_(k-1);
    B_k = snellSurfacePoint(depthTex, uv_k, surface) (texel centre point),
    n_k = xyz of SNELL_SAMPLE_LOD(normalTex, B_k.uv, normalLod) (the same texel
    centre); P_k = snellRayPlane(W, dir, B_k, n_k), or, when the ray does not
    meet that plane ahead of W and SNELL_PLANE_FACING_FALLBACK is 1 (default),
    P_k = snellRayPlane(W, dir, B_k, B_k): the plane through B_k facing the
    camera (normal along the line of sight through B_k), see plane_refine.glsl.
    With farStart and a valid far start F (snellPlaneFarStart) at k = 0,
    P_0 = F.position when the plane at B_0 is not met or meets the ray further
    than F (F.t < t); the facing fallback then applies only when neither is
    met; refinements are unchanged. The hit is
    snellPlaneHit(P_N): position P_N (on the ray), uv its projection, valid
    when the surface exists there. A refinement step that cannot build its plane
    (B_k empty or off screen, ray parallel) stops the refinement at P_(k-1).
    With SNELL_PLANE_HOLD (default 1), a final P whose projection lands on an
    empty texel stays valid on the last plane, uv = that plane's texel
    (plane_refine.glsl): rim rays of convex objects keep their bend instead of
    being dropped.
  - exact (up to float rounding) for a planar surface with exact normals, for
    every N >= 0 (farStart false or an open surface) or N >= 1 (with the far
    start: plane 0 may be the far plane, and the first refinement returns to
    the surface's plane): every other plane is the surface's plane.
  - fetches = 2 (N + 1) + 1 on success (a depth and a normal read per plane,
    one final depth read), plus the far start's (0-2, with farStart); on
    failure the reads issued so far (lookups at an off-screen uv included).
  - rays towards the camera are accepted: the plane is intersected wherever it
    lies ahead of W (t >= 0).
  - valid = false (snellHitMiss, finite): origin/dir NaN/Inf, |dir|^2 below 1e-30
    or overflowing, W at or behind the camera plane (fetches 0); B_k empty or off
    screen; for the first plane: n_k zero/NaN, the ray parallel to it or the
    plane behind W (snellRayPlane invalid), and with the fallback also the
    facing plane (a ray that does not go deeper than B_0), and no far start;
    P behind the camera or off
    screen; the final sample empty with SNELL_PLANE_HOLD 0.
source: C. Mayer, U. Assarsson, "Constant-Time Light Refraction Simulation",
  steps 1-5 and "Method 1: Normal-based"; plane intersection in
  optics/ray_plane.glsl; the far start is snell's (plane_far_start.glsl).
*/
#ifndef SNELL_INTERSECT_PLANE_NORMAL_GLSL
#define SNELL_INTERSECT_PLANE_NORMAL_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"
#include "../camera/view_to_uv.glsl"
#include "../optics/ray_plane.glsl"
#include "hit.glsl"
#include "depth_surface.glsl"
#include "surface_projection.glsl"
#include "surface_point.glsl"
#include "plane_refine.glsl"
#include "plane_far_start.glsl"

SNELL_FN SnellHit snellIntersectPlaneNormal(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_TEX2D normalTex,
                                            SNELL_TEX2D pyramidTex, SNELL_IN(SnellDepthSurface) s, float normalLod,
                                            int iterations, bool farStart) {
  float len2 = dot(dir, dir);
  if (!SNELL_FINITE(origin.x) || !SNELL_FINITE(origin.y) || !SNELL_FINITE(origin.z) ||
      !SNELL_FINITE(len2) || !(len2 >= 1e-30f)) {
    return snellHitMiss(0);
  }
  SnellScreenPoint w = snellSurfaceViewToUv(s, origin);
  if (!w.valid) {
    return snellHitMiss(0);
  }
  int n = clamp(iterations, 0, SNELL_PLANE_MAX_ITERATIONS);
  // Plane 0 (W's texel, the far start, the facing fallback), then the
  // refinements: the loop holds only what every refinement does. With plane 0
  // inside it, llvmpipe spent 58% more instructions on the normal plane (1 it.)
  // with the far start and 10% more without (benchmarks/kernels/gpu_kernel_table.sh).
  SnellSurfacePoint b = snellSurfacePoint(depthTex, w.uv, s);
  int fetches = 1;
  if (!b.valid) {
    return snellHitMiss(fetches);
  }
  vec4 nt = SNELL_SAMPLE_LOD(normalTex, b.uv, normalLod);
  fetches += 1;
  SnellRayPlaneHit ph = snellRayPlane(origin, dir, b.position, vec3(nt.x, nt.y, nt.z));
  if (farStart) {
    SnellFarPlane f = snellPlaneFarStart(origin, dir, w.uv, pyramidTex, s);
    fetches += f.fetches;
    if (f.valid && (!ph.valid || f.t < ph.t)) {
      ph.t = f.t;
      ph.position = f.position;
      ph.valid = true;
    }
  }
#if SNELL_PLANE_FACING_FALLBACK
  if (!ph.valid) {
    ph = snellRayPlane(origin, dir, b.position, b.position);
  }
#endif
  if (!ph.valid) {
    return snellHitMiss(fetches);
  }
  vec3 p = ph.position;
  vec2 planeUv = b.uv;
  for (int k = 1; n > 0 && k <= SNELL_PLANE_MAX_ITERATIONS; ++k) {
    SnellScreenPoint sp = snellSurfaceViewToUv(s, p);
    if (!sp.valid) {
      break;  // keep P_(k-1) on plane k-1
    }
    SnellSurfacePoint bk = snellSurfacePoint(depthTex, sp.uv, s);
    fetches += 1;
    if (!bk.valid) {
      break;
    }
    vec4 nk = SNELL_SAMPLE_LOD(normalTex, bk.uv, normalLod);
    fetches += 1;
    SnellRayPlaneHit hk = snellRayPlane(origin, dir, bk.position, vec3(nk.x, nk.y, nk.z));
#if SNELL_PLANE_FACING_FALLBACK
    if (!hk.valid) {
      hk = snellRayPlane(origin, dir, bk.position, bk.position);
    }
#endif
    if (!hk.valid) {
      break;
    }
    p = hk.position;
    planeUv = bk.uv;
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (k >= n) {
      break;
    }
  }
  return snellPlaneHit(p, planeUv, depthTex, s, fetches);
}

#endif
