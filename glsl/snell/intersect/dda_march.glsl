/*
description: perspective-correct march in pixel space (a DDA): the view-space
  ray segment is projected once, then walked in equal pixel steps along its
  major screen axis, every pixel on the way (stride 1) or every stride-th one,
  with the ray's depth recovered per step by homogeneous (1/w) interpolation,
  so no matrix product per step and no pixel skipped or visited twice.
use: SnellHit h = snellDdaMarch(origin, dir, depthTex, surface);
     SnellHit h = snellDdaMarch(origin, dir, depthTex, surface, maxDistance, thickness, stride, steps);
  origin, dir        view-space ray (dir need not be normalized)
  depthTex, surface  the depth buffer and how to read it (depth_surface.glsl);
                     the pixel grid is that of level surface.lod
  maxDistance        view-space length of the marched segment
  thickness          assumed view-space thickness of the surface: a step hits
                     when the ray's depth interval over the step overlaps
                     [viewZ - thickness, viewZ]
  stride             pixels per step along the major axis (>= 1)
  steps              maximum number of steps (one fetch each)
options:
  SNELL_DDA_STEPS         default steps (256)
  SNELL_DDA_MAX_STEPS     compile-time bound (1024); steps is clamped to [1, max]
  SNELL_DDA_STRIDE        default stride (1.0f)
  SNELL_DDA_THICKNESS     default thickness (SNELL_FLT_MAX: a solid height
                          field, as the other strategies assume; use a finite
                          value for opaque scenes with objects in front of
                          others, so rays can pass behind them)
  SNELL_DDA_MAX_DISTANCE  default maxDistance (10.0f view-space units)
contract:
  - segment: origin to end = origin + (min(maxDistance, 1e30)/|dir|) dir, cut
    at the near plane z = -surface.zNear when dir.z > 0 (beyond 1e30 view
    units the end's projection no longer moves for any scene-scale origin; the
    cap keeps 1/w of the end a normal float, so maxDistance = SNELL_FLT_MAX
    works as "unbounded"). Both ends are projected with surface.clipFromView:
    uv0, uv1 and k = 1/w; Q = p/w and k are linear in screen space, so the view
    point at screen parameter s in [0,1] is
    (Q0 (1 - s) + Q1 s) / (k0 (1 - s) + k1 s) (perspective-correct; this form
    is exact at both ends and never cancels, as k0, k1 > 0).
  - step i (i = 0, 1, ...) samples uv0 + s_i (uv1 - uv0), s_i = min(i ds, 1),
    ds = stride / (length of the segment along its major axis in pixels), or
    ds = 1 when the whole segment spans at most stride pixels (a ray along the
    line of sight: two steps, both halves of its depth range at one pixel); it
    owns s in [(i - 1/2) ds, (i + 1/2) ds] clipped to [0,1], whose ends give the
    ray's depth interval [zFar, zNear] for that step. The walk ends after the
    step owning s = 1.
  - a step hits when its texel is valid and zNear >= viewZ - thickness and
    zFar <= viewZ. Empty texels do not stop the march.
  - hit: uv = the uv that was fetched (its texel is the hit texel), position =
    the point of the ray within the step whose z is clamp(viewZ, zFar, zNear)
    (the crossing, when it lies in the step), on the ray, finite.
  - the first step whose uv is off screen ends the walk: valid = false.
  - valid = false with snellHitMiss numbers (finite) and the fetches spent when
    no step hits within steps; with 0 fetches when: an input is NaN or Inf
    (a NaN thickness uses the default, a NaN stride 1), |dir| is 0 or
    denormal-small, maxDistance <= 0, the origin is in front of the near plane
    (z > -surface.zNear) or on it with dir.z > 0 (no part of the ray is inside
    the frustum), an end does not project to a normal 1/w (clip w <= 0,
    below FLT_MIN or above 1/FLT_MIN) or to a finite Q, or the level has no
    texels. thickness < 0 counts as 0, stride < 1 as 1.
source: M. McGuire, M. Mara, "Efficient GPU Screen-Space Ray Tracing", JCGT
  3(4), 2014 (pixel-space march with homogeneous interpolation of 1/w and a
  depth interval per step); our own formulation (per-step parameter instead of
  accumulated increments, exact crossing inside the hit step).
*/
#ifndef SNELL_INTERSECT_DDA_MARCH_GLSL
#define SNELL_INTERSECT_DDA_MARCH_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"
#include "../camera/view_to_clip.glsl"
#include "hit.glsl"
#include "depth_surface.glsl"

#ifndef SNELL_DDA_STEPS
#  define SNELL_DDA_STEPS 256
#endif
#ifndef SNELL_DDA_MAX_STEPS
#  define SNELL_DDA_MAX_STEPS 1024
#endif
#ifndef SNELL_DDA_STRIDE
#  define SNELL_DDA_STRIDE 1.0f
#endif
#ifndef SNELL_DDA_THICKNESS
#  define SNELL_DDA_THICKNESS SNELL_FLT_MAX
#endif
#ifndef SNELL_DDA_MAX_DISTANCE
#  define SNELL_DDA_MAX_DISTANCE 10.0f
#endif

/* McGuire & Mara 2014: pixel-space march, z from homogeneous interpolation of 1/w */
/* The surface by value, not SNELL_IN: in C++ the march's loop then keeps its
   fields in registers across the library calls it makes (floorf, sqrtf); by
   reference it reloads them every step (8 % more instructions, benchmarks/kernels). */
SNELL_FN SnellHit snellDdaMarch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SnellDepthSurface surface,
                                float maxDistance, float thickness, float stride, int steps) {
  if (!SNELL_FINITE(origin.x) || !SNELL_FINITE(origin.y) || !SNELL_FINITE(origin.z) ||
      !SNELL_FINITE(dir.x) || !SNELL_FINITE(dir.y) || !SNELL_FINITE(dir.z) ||
      !SNELL_FINITE(maxDistance) || !(maxDistance > 0.0f) || !SNELL_FINITE(surface.zNear)) {
    return snellHitMiss(0);
  }
  float thick = isnan(thickness) ? SNELL_DDA_THICKNESS : clamp(thickness, 0.0f, SNELL_FLT_MAX);
  float px = isnan(stride) ? 1.0f : clamp(stride, 1.0f, SNELL_FLT_MAX);
  float len = length(dir);
  if (!SNELL_FINITE(len) || !(len >= SNELL_FLT_MIN) || !(origin.z <= -surface.zNear)) {
    return snellHitMiss(0);
  }
  float tMax = min(maxDistance, 1e30f) / len;
  if (dir.z > 0.0f) {
    float tNear = (-surface.zNear - origin.z) / dir.z;
    // tNear is finite or +-inf here (a finite numerator over dir.z > 0): +inf is a near plane too far along
    // the ray for a float, never reached, and leaves tMax; -inf (the origin is before the plane) ends it.
    tMax = isnan(tNear) ? 0.0f : min(tMax, tNear);
  }
  if (!SNELL_FINITE(tMax) || !(tMax > 0.0f)) {
    return snellHitMiss(0);
  }
  vec3 end = origin + tMax * dir;
  vec4 h0 = snellViewToClip(surface.clipFromView, origin);
  vec4 h1 = snellViewToClip(surface.clipFromView, end);
  ivec2 size = SNELL_TEXTURE_SIZE(depthTex, surface.lod);
  if (!SNELL_FINITE(end.x) || !SNELL_FINITE(end.y) || !SNELL_FINITE(end.z) ||
      !SNELL_FINITE(h0.x) || !SNELL_FINITE(h0.y) || !SNELL_FINITE(h0.w) ||
      !SNELL_FINITE(h1.x) || !SNELL_FINITE(h1.y) || !SNELL_FINITE(h1.w) ||
      !(h0.w >= SNELL_FLT_MIN) || !(h1.w >= SNELL_FLT_MIN) ||
      !(h0.w <= 1.0f / SNELL_FLT_MIN) || !(h1.w <= 1.0f / SNELL_FLT_MIN) || size.x <= 0 || size.y <= 0) {
    return snellHitMiss(0);
  }
  // Homogeneous end points: k = 1/w and Q = p k are linear in screen space.
  // They are interpolated as a (1 - s) + b s, not a + s (b - a): for a far end
  // (k1 below the ulp of k0) k0 + s (k1 - k0) cancels to 0 at s = 1. Written
  // out rather than mix(), which drivers may lower to the cancelling form.
  float k0 = 1.0f / h0.w;
  float k1 = 1.0f / h1.w;
  vec3 q0 = origin * k0;
  vec3 q1 = end * k1;
  vec2 uv0 = vec2(h0.x * k0, h0.y * k0) * 0.5f + 0.5f;
  vec2 duv = vec2(h1.x * k1, h1.y * k1) * 0.5f + 0.5f - uv0;
  float major = max(abs(duv.x * float(size.x)), abs(duv.y * float(size.y)));
  if (!SNELL_FINITE(major) || !SNELL_FINITE(q0.x) || !SNELL_FINITE(q0.y) ||
      !SNELL_FINITE(q0.z) || !SNELL_FINITE(q1.x) || !SNELL_FINITE(q1.y) ||
      !SNELL_FINITE(q1.z)) {
    return snellHitMiss(0);
  }
  float ds = major > px ? px / major : 1.0f;
  int n = clamp(steps, 1, SNELL_DDA_MAX_STEPS);
  int fetches = 0;
  float sA = 0.0f;
  float zA = origin.z;
  for (int i = 0; i < SNELL_DDA_MAX_STEPS; ++i) {
    float sC = min(float(i) * ds, 1.0f);
    float sB = min((float(i) + 0.5f) * ds, 1.0f);
    float zB = (q0.z * (1.0f - sB) + q1.z * sB) / (k0 * (1.0f - sB) + k1 * sB);
    vec2 uv = uv0 + sC * duv;
    if (!(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)) {
      return snellHitMiss(fetches);
    }
    SnellSurfaceSample x = snellSampleSurface(depthTex, uv, surface);
    fetches = fetches + 1;
    float zNearRay = max(zA, zB);
    float zFarRay = min(zA, zB);
    if (x.valid && zNearRay >= x.viewZ - thick && zFarRay <= x.viewZ) {
      // The point of the ray inside this step at depth clamp(viewZ, zFar, zNear).
      float zHit = clamp(x.viewZ, zFarRay, zNearRay);
      vec3 pA = (q0 * (1.0f - sA) + q1 * sA) / (k0 * (1.0f - sA) + k1 * sA);
      vec3 pB = (q0 * (1.0f - sB) + q1 * sB) / (k0 * (1.0f - sB) + k1 * sB);
      float f = pB.z != pA.z ? clamp((zHit - pA.z) / (pB.z - pA.z), 0.0f, 1.0f) : 0.5f;
      SnellHit h;
      h.uv = uv;
      h.position = pA + f * (pB - pA);
      h.valid = true;
      h.fetches = fetches;
      return h;
    }
    sA = sB;
    zA = zB;
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (i + 1 >= n || sA >= 1.0f) {
      break;
    }
  }
  return snellHitMiss(fetches);
}

SNELL_FN SnellHit snellDdaMarch(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SnellDepthSurface surface) {
  return snellDdaMarch(origin, dir, depthTex, surface, SNELL_DDA_MAX_DISTANCE, SNELL_DDA_THICKNESS, SNELL_DDA_STRIDE,
                       SNELL_DDA_STEPS);
}

#endif
