/*
description: the far start of the plane strategies on a closed surface (an
  object's back faces): a constant-depth plane at the farthest back-face
  distance that the depth min/max pyramid holds over the ray's way across the
  screen, a second candidate for the first plane next to Mayer & Assarsson's
  (built at B_0, the point behind the ray origin). snellIntersectPlaneNormal
  and snellIntersectPlaneDepth take the nearer of the two.
use: SnellFarPlane f = snellPlaneFarStart(origin, dir, originUv, pyramidTex, surface);
     if (f.valid && (!tangent.valid || f.t < tangent.t)) { ... f.position ... }
  origin, dir  the view-space ray (dir any length; t in units of |dir|)
  originUv     the origin's projection (snellSurfaceViewToUv(surface, origin).uv)
  pyramidTex   the surface's depth min/max pyramid (intersect/depth_pyramid.glsl
               layout, z = farthest view distance, w = coverage), full mip chain
  surface      the depth surface the pyramid was built from
options:
  SNELL_PLANE_FAR_START  1 (default): SnellIntersectOptions.planeFarStart is
                         true by default (intersect/intersect_with.glsl), for both
                         plane strategies; 0: false
contract:
  - step 1 (1 fetch): the top level's texel (0, 0): z_all, the farthest
    distance of the whole buffer. The ray meets the plane z = -z_all at G
    (snellRayPlane); its projection g.
  - step 2 (1 fetch): the level L whose texels are the smallest at least as
    wide as the ray's way from originUv to g (D = |g - originUv| in level-0
    texels; L = the least L with 2^L >= D, at most the top level), its texel
    at the way's midpoint m (clamped to [0,1]^2): min(int(m * size_L),
    size_L - 1), as a nearest read at level L picks it: z_L. The result is
    the ray's hit on the plane z = -z_L: t, position, valid, fetches 2.
  - invalid (t = 0, position 0): surface.closed false or originUv not finite
    (no fetch); the top texel empty (w <= 0) or its z not finite and
    positive (1 fetch); the ray
    not meeting z = -z_all ahead of origin (a ray towards the camera or one
    already beyond the object) or G at or behind the camera (1 fetch); the
    level texel empty or its z not finite and positive (2 fetches).
  - why it helps: on a convex object the tangent plane at B_0 lies beyond the
    exit, and near the silhouette the refracted ray, bent inwards, meets it
    far away or never (the facing fallback of plane_refine.glsl then starts at
    B_0's depth, next to the origin, and the refinement crawls). No exit lies
    deeper than the farthest back face under the ray's way: where the level's
    texel holds the whole way, the far plane is at or beyond the exit (a
    quarter of a sphere's refracted rays in the unit test, all of them at or
    beyond); elsewhere it is an estimate. The plane strategies take the nearer
    of the two candidates.
  - the level loop compares with powers of two (no log2), so C++ and the GPU
    pick the same level.
source: the search range of Oliveira & Brauwers 2007 (sec. 3.2: "Zmax", the
  min/max reduction) used as a plane of Mayer & Assarsson's method
  ("Constant-Time Light Refraction Simulation", step 2; "a more blurred mip
  level gives a more complete representation of the scene for drastic
  refraction effects"); snell's own combination.
*/
#ifndef SNELL_INTERSECT_PLANE_FAR_START_GLSL
#define SNELL_INTERSECT_PLANE_FAR_START_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"
#include "../optics/ray_plane.glsl"
#include "depth_surface.glsl"
#include "depth_range.glsl"
#include "surface_projection.glsl"

/* 1 (default): snellIntersectOptions sets planeFarStart (the plane
   strategies' far start on closed surfaces); 0: the poster's first plane. */
#ifndef SNELL_PLANE_FAR_START
#  define SNELL_PLANE_FAR_START 1
#endif

struct SnellFarPlane {
  float t;
  vec3 position;
  bool valid;
  int fetches;
};

SNELL_FN SnellFarPlane snellPlaneFarStart(vec3 origin, vec3 dir, vec2 originUv, SNELL_TEX2D pyramidTex,
                                          SNELL_IN(SnellDepthSurface) s) {
  SnellFarPlane f;
  f.t = 0.0f;
  f.position = vec3(0.0f, 0.0f, 0.0f);
  f.valid = false;
  f.fetches = 0;
  if (!s.closed || !SNELL_FINITE(originUv.x) || !SNELL_FINITE(originUv.y)) {
    return f;
  }
  int top = snellTextureTopLod(pyramidTex);
  vec4 whole = SNELL_TEXEL_FETCH(pyramidTex, ivec2(0, 0), top);
  f.fetches = 1;
  if (!(whole.w > 0.0f) || !(whole.z > 0.0f) || !SNELL_FINITE(whole.z)) {
    return f;
  }
  vec3 facing = vec3(0.0f, 0.0f, 1.0f);
  SnellRayPlaneHit g = snellRayPlane(origin, dir, vec3(0.0f, 0.0f, -whole.z), facing);
  SnellScreenPoint gp = snellSurfaceViewToUv(s, g.position);
  if (!g.valid || !gp.valid) {
    return f;
  }
  vec2 size0 = vec2(SNELL_TEXTURE_SIZE(pyramidTex, 0));
  vec2 way = (gp.uv - originUv) * size0;
  float d = sqrt(dot(way, way));
  int level = 0;
  for (int k = 0; k < 31; ++k) {
    // !(<) also ends the loop for a NaN way, at level 0
    if (level >= top || !(float(1 << level) < d)) {
      break;
    }
    level += 1;
  }
  vec2 mid = clamp(0.5f * (gp.uv + originUv), vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
  ivec2 sizeL = SNELL_TEXTURE_SIZE(pyramidTex, level);
  ivec2 px = min(ivec2(mid * vec2(sizeL)), sizeL - ivec2(1, 1));
  vec4 under = SNELL_TEXEL_FETCH(pyramidTex, px, level);
  f.fetches = 2;
  if (!(under.w > 0.0f) || !(under.z > 0.0f) || !SNELL_FINITE(under.z)) {
    return f;
  }
  SnellRayPlaneHit h = snellRayPlane(origin, dir, vec3(0.0f, 0.0f, -under.z), facing);
  f.t = h.t;
  f.position = h.position;
  f.valid = h.valid;
  return f;
}

#endif
