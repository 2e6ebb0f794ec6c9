/*
description: where a ray inside a closed object leaves it, in image space:
  a linear march with bisection between the object's two depth layers as the
  camera sees them, its front faces and its back faces. A point is inside
  while it lies between the two (behind the front depth, in front of the
  back depth); the first step outside is refined by bisection and names the
  layer the ray crossed. Davis & Wyman 2007 bounce inside with a binary
  search between front and back depth maps; Oliveira & Brauwers 2007 (sec. 7)
  sketch the same for TIR: front- and back-facing depth and normals, the ray
  intersection procedure run again.
use: SnellInsideHit h = snellInsideMarch(origin, dir, backDepth, back, frontDepth, front,
                                         maxDistance, steps, refineSteps);
     SnellInsideBracket b = snellInsideBracket(origin, dir, backDepth, back, frontDepth, front,
                                               maxDistance, steps);   // the march alone
  origin, dir        view-space ray starting inside the object (a point of
                     the back or front layer after a total internal
                     reflection, say); dir need not be normalized
  backDepth, back    the back-face depth (GL_GREATER after clearing to the
                     near value) and how to read it (depth_surface.glsl)
  frontDepth, front  the front-face depth (GL_LESS after clearing to the far
                     value), how to read it
  maxDistance        view-space length of the marched part of the ray (the
                     object's extent)
  steps              equal steps of maxDistance / steps (two fetches each)
  refineSteps        bisection steps inside the step that left (two fetches
                     each while on screen)
options: the linear march's bounds, SNELL_LINEAR_MARCH_MAX_STEPS (512) and
  SNELL_LINEAR_MARCH_MAX_REFINE_STEPS (24): steps is clamped to [1, max],
  refineSteps to [0, max]; SNELL_INSIDE_FIRST_STEP_HALVINGS (3): the
  samples that halve a first step that has already left.
contract:
  - samples t_i = i tMax / steps, i = 1 .. steps, tMax = maxDistance / |dir|,
    cut at the near plane z = -back.zNear when dir.z > 0 (the origin itself
    is not tested), each projected with back.clipFromView and read in both
    layers at that uv (the two layers share the camera and the size).
  - a sample is outside when it is on or behind the back layer (valid back
    texel, z <= back viewZ: left through the back faces), on or in front of
    the front layer (valid front texel, z >= front viewZ: left through the
    front faces), or where both texels are empty (beside the silhouette).
    The ray leaves at the first outside sample after an inside one: samples
    before the first inside sample do not count (a ray that starts on a layer,
    as after a reflection there, reads as outside within that layer's texel).
    When the first sample t_1 is outside, the first step is halved first:
    t_1 / 2, t_1 / 4, ... up to SNELL_INSIDE_FIRST_STEP_HALVINGS (3) samples
    (2 fetches each); the halving ends at a sample off screen or less than a
    texel (of backDepth at back.lod, in x and in y) from the origin's
    projection (not read: there the layer the ray starts on reads as
    outside), or when the origin does not project. The first inside one is
    the last inside sample and the halving sample before it (t_1 at first)
    the outside one: a chord shorter than a step is still found. When none
    is inside, the march goes on from t_2 as above.
  - the first sample that projects off screen ends the march: valid = false
    (the exit is not in the buffers).
  - refinement brackets [last inside t, first outside t after it]; a midpoint outside moves hi, any other
    (inside, off screen: no fetch) moves lo; the hit is hi: position, uv.
    front = true when hi crossed the front layer only, or both texels are
    empty and dir.z > 0 (a ray heading towards the camera leaves beside the
    silhouette through the front); false for the back layer (both crossed: the
    layer whose depth is nearer the point along z).
  - valid = false with snellHitMiss numbers when no inside sample is followed
    by an outside one (the ray stays inside over maxDistance, or never gets
    inside); with 0 fetches when an input is NaN
    or Inf, |dir| is 0 or denormal-small, maxDistance <= 0, or the whole ray
    lies in front of the near plane.
  - fetches: 2 per sample read, both layers.
  - snellInsideBracket: the samples above without the refinement: valid, lo
    (the last inside sample's t), hi (the first outside one's), uv and side
    (1 back, 2 front: snellInsideSide at hi), loUv (lo's uv) and fetches as
    above; on every miss valid = false, lo = hi = 0, both uvs 0, side 0,
    fetches those read.
source: C. Davis & C. Wyman, "Interactive Refractions with Total Internal
  Reflection", Graphics Interface 2007 (bounces between front and back depth
  maps); M. M. Oliveira & M. Brauwers, "Real-Time Refraction Through
  Deformable Objects", I3D 2007, sec. 7 (TIR as future work: front- and
  back-facing buffers, the same intersection procedure); the linear march of
  linear_march.glsl.
*/
#ifndef SNELL_INTERSECT_INSIDE_MARCH_GLSL
#define SNELL_INTERSECT_INSIDE_MARCH_GLSL
#include "../prelude.glsl"
#include "../camera/view_to_uv.glsl"
#include "hit.glsl"
#include "depth_surface.glsl"
#include "surface_projection.glsl"
#include "linear_march.glsl"

#ifndef SNELL_INSIDE_FIRST_STEP_HALVINGS
#  define SNELL_INSIDE_FIRST_STEP_HALVINGS 3
#endif

struct SnellInsideHit {
  SnellHit hit;
  bool front;  // left through the front layer (else the back layer)
};

/* Which side of the object a point is on at uv: 0 inside, 1 through the back layer, 2 through the front layer
   (an off-screen uv reads as empty in both layers: beside the silhouette) */
SNELL_FN int snellInsideSide(vec3 p, vec2 uv, SNELL_TEX2D backDepth, SNELL_IN(SnellDepthSurface) back,
                             SNELL_TEX2D frontDepth, SNELL_IN(SnellDepthSurface) front, float dirZ) {
  SnellSurfaceSample b = snellSampleSurface(backDepth, uv, back);
  SnellSurfaceSample f = snellSampleSurface(frontDepth, uv, front);
  bool behindBack = b.valid && p.z <= b.viewZ;
  bool beforeFront = f.valid && p.z >= f.viewZ;
  if (behindBack && beforeFront) {
    return (b.viewZ - p.z) <= (p.z - f.viewZ) ? 1 : 2;
  }
  if (behindBack) {
    return 1;
  }
  if (beforeFront) {
    return 2;
  }
  if (!b.valid && !f.valid) {
    return dirZ > 0.0f ? 2 : 1;
  }
  return 0;
}

/* Where the ray leaves, to within one step: the last inside sample (lo) and the first outside one after it (hi) */
struct SnellInsideBracket {
  float lo;      // t of the last inside sample (in units of |dir|)
  float hi;      // t of the first outside sample after it
  vec2 uv;       // hi's uv
  vec2 loUv;     // lo's uv (on the object: both layers hold a surface there)
  int side;      // snellInsideSide at hi: 1 back layer, 2 front layer
  int fetches;
  bool valid;    // false: no inside sample followed by an outside one (or bad input, off screen)
};

/* The march part of snellInsideMarch (its contract's samples, before the refinement), shared with
   snellInsidePlane */
SNELL_FN SnellInsideBracket snellInsideBracket(vec3 origin, vec3 dir, SNELL_TEX2D backDepth,
                                               SNELL_IN(SnellDepthSurface) back, SNELL_TEX2D frontDepth,
                                               SNELL_IN(SnellDepthSurface) front, float maxDistance, int steps) {
  SnellInsideBracket b;
  b.lo = 0.0f;
  b.hi = 0.0f;
  b.uv = vec2(0.0f, 0.0f);
  b.loUv = vec2(0.0f, 0.0f);
  b.side = 0;
  b.fetches = 0;
  b.valid = false;
  if (!SNELL_FINITE(origin.x) || !SNELL_FINITE(origin.y) || !SNELL_FINITE(origin.z) ||
      !SNELL_FINITE(dir.x) || !SNELL_FINITE(dir.y) || !SNELL_FINITE(dir.z) ||
      !SNELL_FINITE(maxDistance) || !(maxDistance > 0.0f)) {
    return b;
  }
  float len = length(dir);
  if (!SNELL_FINITE(len) || !(len >= SNELL_FLT_MIN)) {
    return b;
  }
  float tMax = maxDistance / len;
  if (dir.z > 0.0f) {
    float tNear = (-back.zNear - origin.z) / dir.z;
    // As in the linear march: +inf is a near plane never reached in float and leaves tMax; -inf ends it.
    tMax = isnan(tNear) ? 0.0f : min(tMax, tNear);
  }
  if (!SNELL_FINITE(tMax) || !(tMax > 0.0f)) {
    return b;
  }
  int n = clamp(steps, 1, SNELL_LINEAR_MARCH_MAX_STEPS);
  float dt = tMax / float(n);
  bool wasInside = false;
  for (int i = 1; i <= SNELL_LINEAR_MARCH_MAX_STEPS; ++i) {
    float t = float(i) * dt;
    vec3 p = origin + t * dir;
    SnellScreenPoint sp = snellSurfaceViewToUv(back, p);
    if (!sp.valid || !(sp.uv.x >= 0.0f && sp.uv.x <= 1.0f && sp.uv.y >= 0.0f && sp.uv.y <= 1.0f)) {
      b.lo = 0.0f;
      b.loUv = vec2(0.0f, 0.0f);
      return b;
    }
    int side = snellInsideSide(p, sp.uv, backDepth, back, frontDepth, front, dir.z);
    b.fetches = b.fetches + 2;
    if (side == 0) {
      wasInside = true;
      b.lo = t;
      b.loUv = sp.uv;
    } else if (wasInside) {
      b.hi = t;
      b.uv = sp.uv;
      b.side = side;
      b.valid = true;
      return b;
    } else if (i == 1) {
      // The first sample has already left (a chord shorter than a step, at a corner or a thin part): the first
      // step is halved until a sample is inside, so a coarse march still brackets the exit.
      // Only while the sample is a texel or more from the origin's pixel: within it, the layer the ray
      // starts on reads as outside (the march's rule above), and an inside reading there is noise.
      float hiT = t;
      vec2 hiUv = sp.uv;
      int hiSide = side;
      SnellScreenPoint so = snellSurfaceViewToUv(back, origin);
      vec2 texels = vec2(SNELL_TEXTURE_SIZE(backDepth, back.lod));
      for (int h = 1; h <= SNELL_INSIDE_FIRST_STEP_HALVINGS; ++h) {
        float th = 0.5f * hiT;
        vec3 q = origin + th * dir;
        SnellScreenPoint sq = snellSurfaceViewToUv(back, q);
        if (!so.valid || !sq.valid || !(sq.uv.x >= 0.0f && sq.uv.x <= 1.0f && sq.uv.y >= 0.0f && sq.uv.y <= 1.0f)) {
          break;
        }
        vec2 away = abs(sq.uv - so.uv) * texels;
        if (!(max(away.x, away.y) >= 1.0f)) {
          break;
        }
        int s = snellInsideSide(q, sq.uv, backDepth, back, frontDepth, front, dir.z);
        b.fetches = b.fetches + 2;
        if (s == 0) {
          b.lo = th;
          b.loUv = sq.uv;
          b.hi = hiT;
          b.uv = hiUv;
          b.side = hiSide;
          b.valid = true;
          return b;
        }
        hiT = th;
        hiUv = sq.uv;
        hiSide = s;
      }
    }
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (i >= n) {
      break;
    }
  }
  b.lo = 0.0f;
  b.loUv = vec2(0.0f, 0.0f);
  return b;
}

/* Davis & Wyman 2007: a ray inside the object, marched between the front and back depth layers */
SNELL_FN SnellInsideHit snellInsideMarch(vec3 origin, vec3 dir, SNELL_TEX2D backDepth, SNELL_IN(SnellDepthSurface) back,
                                         SNELL_TEX2D frontDepth, SNELL_IN(SnellDepthSurface) front, float maxDistance,
                                         int steps, int refineSteps) {
  SnellInsideHit r;
  r.front = false;
  SnellInsideBracket b = snellInsideBracket(origin, dir, backDepth, back, frontDepth, front, maxDistance, steps);
  r.hit = snellHitMiss(b.fetches);
  if (!b.valid) {
    return r;
  }
  int nr = clamp(refineSteps, 0, SNELL_LINEAR_MARCH_MAX_REFINE_STEPS);
  int fetches = b.fetches;
  int side = b.side;
  float lo = b.lo;
  float tHit = b.hi;
  vec2 uvHit = b.uv;
  for (int j = 0; nr > 0 && j < SNELL_LINEAR_MARCH_MAX_REFINE_STEPS; ++j) {
    float mid = 0.5f * (lo + tHit);
    vec3 q = origin + mid * dir;
    SnellScreenPoint sq = snellSurfaceViewToUv(back, q);
    int s = 0;
    if (sq.valid && sq.uv.x >= 0.0f && sq.uv.x <= 1.0f && sq.uv.y >= 0.0f && sq.uv.y <= 1.0f) {
      s = snellInsideSide(q, sq.uv, backDepth, back, frontDepth, front, dir.z);
      fetches = fetches + 2;
    }
    if (s > 0) {
      tHit = mid;
      uvHit = sq.uv;
      side = s;
    } else {
      lo = mid;
    }
    // The count at the end of the pass, not at the top (docs/DESIGN.md, the common subset).
    if (j + 1 >= nr) {
      break;
    }
  }
  r.hit.uv = uvHit;
  r.hit.position = origin + tHit * dir;
  r.hit.valid = true;
  r.hit.fetches = fetches;
  r.front = side == 2;
  return r;
}

#endif
