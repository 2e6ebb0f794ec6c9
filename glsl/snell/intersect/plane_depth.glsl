/*
description: Mayer & Assarsson's planar approximation, method 2 (depth-based):
  no normal buffer; three surface points define the plane: B directly behind
  the ray's reference point, the surface seen at the point d = |B - W| further
  along the ray, and a neighbouring texel (the "screen-space derivative" of B,
  taken as a texel offset so the method works outside fragment shaders too),
  all read at the mip level whose texels span the region the points cover.
  Optional refinement as in plane_normal.glsl.
use: SnellHit h = snellIntersectPlaneDepth(origin, dir, depthMips, surface, maxLod,
                                           SNELL_PLANE_ITERATIONS, true);
  origin, dir  view-space ray (origin z < 0; dir any length)
  depthMips    a depth texture whose level L holds, in .x, a depth value
               representative of each 2^L x 2^L block, emptyDepth where the block
               is empty: the depth pyramid of depth_pyramid.glsl (.x = mean depth
               of the valid texels; snellBuildDepthPyramid in C++), or a plain
               one-level depth texture with maxLod = surface.lod
  surface      its camera and conventions; surface.lod is the finest level read
  maxLod       the coarsest level that exists (and may be read)
  iterations   refinement iterations, clamped to [0, SNELL_PLANE_MAX_ITERATIONS]
  farStart     true: on a closed surface (surface.closed), once B0 was read, the
               first plane's hit is the nearer of the one below and the far
               start's (intersect/plane_far_start.glsl; depthMips must then be
               the min/max pyramid: it reads its .z and .w); false: the poster's
options:
  SNELL_PLANE_DEPTH_MAX_SPAN_LOD  the level chosen is at most surface.lod + this (6)
contract (one plane, built around a reference point Q on the ray: Q = W for the
  first plane, Q = P_(k-1) when refining):
  - uvQ = projection of Q; B0 = snellSurfacePoint(depthMips, uvQ) at level
    surface.lod (1 fetch); d = |B0 - Q|; Q2 = Q + d dir/|dir|, or Q - d dir/|dir|
    when Q is deeper than B0 (Q.z < B0.z: the ray is past the surface);
    uv2 = projection of Q2 (uvQ when Q2 does not project).
  - span = largest |uv2 - uvQ| component in texels of level surface.lod; level L =
    surface.lod + ceil(log2(span)) (0 for span <= 1), clamped to
    [surface.lod, min(maxLod, surface.lod + SNELL_PLANE_DEPTH_MAX_SPAN_LOD)].
  - texels at level L: pB containing uvQ, pC containing uv2 (clamped to the
    level); a = the unit step along the larger component of pC - pB (+x when
    pC == pB, and pC is then pB + a), b = the perpendicular unit step (+y or +x).
    B = texel-centre point of pB (B0 reused when L == surface.lod, else 1
    fetch); C = point of pC, or of pB - a when pC is empty (1-2 fetches); D =
    point of pB + b, or of pB - b when empty (1-2 fetches). The three texels are
    never collinear in the image, so the plane is defined whenever they are valid.
  - P = snellRayPlane(W, dir, B, cross(C - B, D - B)). With
    SNELL_PLANE_FACING_FALLBACK 1 (default), when B was read but C or D is
    empty, the three points are degenerate, or the ray does not meet their plane
    ahead of W, the plane through B facing the camera is used instead:
    P = snellRayPlane(W, dir, B, B) (plane_refine.glsl). With farStart and a
    valid far start F for the first plane (B0 read), P_0 = F.position when
    the plane of B, C, D is not met or meets the ray further than F (before the
    facing fallback, as in plane_normal.glsl). After N refinements the
    hit is snellHitOnSurface(P_N) (position on the ray, valid when the surface
    exists at its projection).
  - exact (up to float rounding) on a planar surface (with the far start:
    for N >= 1, as in plane_normal.glsl) at every level whose
    texels hold the depth at their centre: level 0 always; the pyramid's mean
    levels for power-of-two sizes and fully covered blocks (window depth is
    affine in screen space over a plane, so a block mean is its centre value).
  - fetches per plane 3..6 (1 for B0, 1 for B when L > surface.lod, 1-2 each for
    C and D), plus the far start's 0-2 for the first plane, plus 1 final
    lookup; on failure the reads issued so far.
  - valid = false (snellHitMiss, finite): origin/dir NaN/Inf, |dir|^2 below 1e-30
    or overflowing, W at or behind the camera plane (fetches 0); B0 or B empty or
    off screen; C or D empty after the fallback, a degenerate plane, the ray
    parallel to it or the plane behind W (with SNELL_PLANE_FACING_FALLBACK 0,
    or when the facing plane is not met either); P behind the camera; the final lookup
    empty or off screen. Rays towards the camera are accepted as in
    plane_normal.glsl.
source: C. Mayer, U. Assarsson, "Constant-Time Light Refraction Simulation",
  "Method 2: Depth-based" ("sample all three points using the mipmap level that
  encompasses the entire region these three points span") and step 5; the
  far start is snell's (plane_far_start.glsl).
*/
#ifndef SNELL_INTERSECT_PLANE_DEPTH_GLSL
#define SNELL_INTERSECT_PLANE_DEPTH_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"
#include "../camera/pixel_to_uv.glsl"
#include "../camera/view_to_uv.glsl"
#include "../optics/ray_plane.glsl"
#include "hit.glsl"
#include "depth_surface.glsl"
#include "surface_projection.glsl"
#include "surface_point.glsl"
#include "plane_refine.glsl"
#include "plane_far_start.glsl"

#ifndef SNELL_PLANE_DEPTH_MAX_SPAN_LOD
#  define SNELL_PLANE_DEPTH_MAX_SPAN_LOD 6
#endif

/* One plane around the reference point q (see the contract); valid false when
   it cannot be built. fetches: the reads spent. */
struct SnellDepthPlane {
  vec2 uv;        // where B was read
  vec3 position;  // B once it was read (also when C or D was not), else 0
  vec3 normal;    // cross(C - B, D - B), not normalized; 0 unless valid
  bool valid;
  int fetches;
};

SNELL_FN SnellDepthPlane snellDepthPlaneAt(vec3 q, vec3 dirN, SNELL_TEX2D depthMips, SNELL_IN(SnellDepthSurface) s, int maxLod) {
  SnellDepthPlane r;
  r.uv = vec2(0.0f, 0.0f);
  r.position = vec3(0.0f, 0.0f, 0.0f);
  r.normal = vec3(0.0f, 0.0f, 0.0f);
  r.valid = false;
  r.fetches = 0;
  SnellScreenPoint sq = snellSurfaceViewToUv(s, q);
  if (!sq.valid) {
    return r;
  }
  SnellSurfacePoint b0 = snellSurfacePoint(depthMips, sq.uv, s);
  r.fetches = 1;
  if (!b0.valid) {
    return r;
  }
  r.uv = b0.uv;
  vec3 toB = b0.position - q;
  float d = sqrt(dot(toB, toB));
  vec3 q2 = q.z < b0.position.z ? q - d * dirN : q + d * dirN;
  SnellScreenPoint s2 = snellSurfaceViewToUv(s, q2);
  vec2 uv2 = s2.valid ? s2.uv : sq.uv;
  ivec2 size0 = SNELL_TEXTURE_SIZE(depthMips, s.lod);
  float span = max(abs(uv2.x - sq.uv.x) * float(size0.x), abs(uv2.y - sq.uv.y) * float(size0.y));
  int top = min(maxLod, s.lod + SNELL_PLANE_DEPTH_MAX_SPAN_LOD);
  int level = s.lod;
  if (span > 1.0f && SNELL_FINITE(span)) {
    level = s.lod + int(ceil(log2(span)));
  }
  level = max(s.lod, min(level, top));
  SnellDepthSurface sl = s;
  sl.lod = level;
  ivec2 size = SNELL_TEXTURE_SIZE(depthMips, level);
  ivec2 pb = snellUvToPixel(sq.uv, size);
  ivec2 pc = snellUvToPixel(uv2, size);
  ivec2 a = ivec2(1, 0);
  ivec2 dpc = pc - pb;
  if (abs(dpc.y) > abs(dpc.x)) {
    a = ivec2(0, dpc.y > 0 ? 1 : -1);
  } else if (dpc.x != 0) {
    a = ivec2(dpc.x > 0 ? 1 : -1, 0);
  }
  if (dpc.x == 0 && dpc.y == 0) {
    pc = pb + a;
  }
  ivec2 b = a.x != 0 ? ivec2(0, 1) : ivec2(1, 0);
  vec3 pB = b0.position;
  if (level != s.lod) {
    SnellSurfacePoint bl = snellSurfacePoint(depthMips, snellPixelToUv(pb, size), sl);
    r.fetches += 1;
    if (!bl.valid) {
      return r;
    }
    pB = bl.position;
  }
  r.position = pB;
  // C (at pc, else on the other side of B) and D (across the way, else its opposite) through one read in
  // the code, as WebGL's compilers inline every call: t = 0 C at pc, 1 C at pb - a (pc empty), 2 D at
  // pb + b, 3 D at pb - b (pb + b empty). Both candidates of a point empty: no plane.
  vec3 pC = vec3(0.0f, 0.0f, 0.0f);
  vec3 pD = vec3(0.0f, 0.0f, 0.0f);
  int found = 0;
  for (int t = 0; t < 4; ++t) {
    if (t == 1 && found == 1) {
      continue;
    }
    if (t == 3 && found == 2) {
      break;
    }
    ivec2 px = pc;
    if (t == 1) {
      px = pb - a;
    } else if (t == 2) {
      px = pb + b;
    } else if (t == 3) {
      px = pb - b;
    }
    SnellSurfacePoint n = snellSurfacePoint(depthMips, snellPixelToUv(px, size), sl);
    r.fetches += 1;
    if (n.valid) {
      if (found == 0) {
        pC = n.position;
      } else {
        pD = n.position;
      }
      found += 1;
    } else if (t == 1 || t == 3) {
      return r;
    }
  }
  r.normal = cross(pC - pB, pD - pB);
  r.valid = true;
  return r;
}

SNELL_FN SnellHit snellIntersectPlaneDepth(vec3 origin, vec3 dir, SNELL_TEX2D depthMips, SNELL_IN(SnellDepthSurface) s,
                                           int maxLod, int iterations, bool farStart) {
  float len2 = dot(dir, dir);
  if (!SNELL_FINITE(origin.x) || !SNELL_FINITE(origin.y) || !SNELL_FINITE(origin.z) ||
      !SNELL_FINITE(len2) || !(len2 >= 1e-30f)) {
    return snellHitMiss(0);
  }
  SnellScreenPoint w = snellSurfaceViewToUv(s, origin);
  if (!w.valid) {
    return snellHitMiss(0);
  }
  vec3 dirN = dir / sqrt(len2);
  int n = clamp(iterations, 0, SNELL_PLANE_MAX_ITERATIONS);
  // Plane 0 (at W, with the far start and the facing fallback), then the refinements, in one loop: the
  // plane's construction (up to six depth reads) appears once in the code, which halves what WebGL's
  // compilers inline and compile.
  vec3 p = origin;
  vec2 planeUv = vec2(0.0f, 0.0f);
  int fetches = 0;
  for (int k = 0; k <= SNELL_PLANE_MAX_ITERATIONS; ++k) {
    SnellDepthPlane plk = snellDepthPlaneAt(p, dirN, depthMips, s, maxLod);
    fetches += plk.fetches;
    // An unbuilt plane has a zero normal, so the ray misses it; its facing plane exists
    // only when B was read (position 0, the camera, gives no plane either). B read has
    // z = viewZ <= -zNear <= -FLT_MIN, which no runtime flushes; its squared length
    // underflows to 0 for a surface within 2^-75 of the eye, which zNear allows.
    SnellRayPlaneHit hk = snellRayPlane(origin, dir, plk.position, plk.normal);
    if (k == 0 && farStart && plk.position.z < 0.0f) {
      SnellFarPlane f = snellPlaneFarStart(origin, dir, w.uv, depthMips, s);
      fetches += f.fetches;
      if (f.valid && (!hk.valid || f.t < hk.t)) {
        hk.t = f.t;
        hk.position = f.position;
        hk.valid = true;
      }
    }
#if SNELL_PLANE_FACING_FALLBACK
    if (!hk.valid) {
      hk = snellRayPlane(origin, dir, plk.position, plk.position);
    }
#endif
    if (!hk.valid) {
      if (k == 0) {
        return snellHitMiss(fetches);
      }
      break;  // keep P_(k-1) on plane k-1
    }
    p = hk.position;
    planeUv = plk.uv;
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (k >= n) {
      break;
    }
  }
  return snellPlaneHit(p, planeUv, depthMips, s, fetches);
}

#endif
