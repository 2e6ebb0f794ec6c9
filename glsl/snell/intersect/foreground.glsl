/*
description: the foreground rule of every slot that reads the opaque scene's
  buffers: a hit never shows a surface nearer the camera than the ray that
  found it. The scene buffer holds, at each pixel, only the nearest surface;
  where something opaque stands between the camera and the refractive object
  (a pillar in front of the glass), that is the pillar, and a strategy that
  lands on such a pixel would show the pillar's colour inside the glass. The
  rule reads the depth at the hit once more and refuses the hit when the
  surface there lies in front of every point of the ray from its origin to
  the hit: no point of that segment can be on it, so its colour belongs to a
  foreground the ray passed behind. The slot then takes its fallback.
use: h = snellRejectForeground(h, origin, depthTex, surface, SNELL_FOREGROUND_TOLERANCE);
  h         the strategy's hit for the ray (origin, any direction)
  origin    the ray's view-space start (z < 0): P2 for the exit slot, P1 for
            the reflect slot
  depthTex, surface  the buffer the strategy read and how it describes the
            depth (its depthFilter is not used: the rule reads the texel
            containing the hit, SNELL_DEPTH_FILTER_NEAREST, so that a
            bilinear read across a foreground's silhouette does not blend
            its depth with the background's and let it through)
  tolerance the share of the ray's nearest distance by which the surface must
            be nearer to count as foreground: it absorbs the depth read's own
            error (a texel's footprint on a sloped surface, depth
            quantization)
options:
  SNELL_FOREGROUND_TOLERANCE  the tolerance snellTwoInterfaceExit passes
            (default 0.01: a surface 1 % nearer than the ray's nearest point)
contract:
  - h invalid: h unchanged (no fetch).
  - origin.z or h.position.z not finite (no strategy returns such a hit):
    snellHitMiss(h.fetches) (no fetch), so that no runtime's NaN-ignoring
    min decides.
  - else one read x = snellSampleSurface(depthTex, h.uv, surface with
    depthFilter SNELL_DEPTH_FILTER_NEAREST) (fetches h.fetches + 1). dNear = min(-origin.z, -h.position.z), the distance of the
    segment's nearest point along the view axis (a ray's view depth is affine
    in its parameter, so the segment is nowhere nearer). When x is valid and
    -x.viewZ < dNear (1 - t), t = tolerance clamped to [0, 1] (NaN and
    negative values: 0), the hit is refused: snellHitMiss(h.fetches + 1).
    Otherwise h with fetches + 1 (an empty texel is no foreground).
  - what it does not catch: a surface between the origin's depth and the
    hit's, at the hit's pixel, on a ray heading away from the camera (the
    searches find such a crossing first; an approximate strategy such as the
    single sample may step past it), and everything the buffer does not hold
    (the surface behind the foreground: that needs a scene layer without it,
    docs/recipes.md).
source: the no-foreground-leak rule of DESIGN.md sec. 2; the leak the engines
  fix with a depth compare (Godot 4's refraction depth test, Bevy's
  transmission prepass depth test: a scene sample nearer than the surface is
  replaced by the environment).
*/
#ifndef SNELL_INTERSECT_FOREGROUND_GLSL
#define SNELL_INTERSECT_FOREGROUND_GLSL
#include "../prelude.glsl"
#include "hit.glsl"
#include "depth_surface.glsl"

#ifndef SNELL_FOREGROUND_TOLERANCE
#  define SNELL_FOREGROUND_TOLERANCE 0.01f
#endif

SNELL_FN SnellHit snellRejectForeground(SnellHit h, vec3 origin, SNELL_TEX2D depthTex, SNELL_IN(SnellDepthSurface) s,
                                        float tolerance) {
  if (!h.valid) {
    return h;
  }
  if (!SNELL_FINITE(origin.z) || !SNELL_FINITE(h.position.z)) {
    return snellHitMiss(h.fetches);
  }
  SnellDepthSurface texel = s;
  texel.depthFilter = SNELL_DEPTH_FILTER_NEAREST;
  SnellSurfaceSample x = snellSampleSurface(depthTex, h.uv, texel);
  h.fetches = h.fetches + 1;
  float t = tolerance > 0.0f ? min(tolerance, 1.0f) : 0.0f;
  float dNear = min(-origin.z, -h.position.z);
  if (x.valid && -x.viewZ < dNear * (1.0f - t)) {
    return snellHitMiss(h.fetches);
  }
  return h;
}

#endif
