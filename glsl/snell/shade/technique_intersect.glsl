/*
description: the strategy dispatcher: one call that runs any intersection
  strategy of intersect/ against a depth buffer, chosen by an int constant, so
  the back-face slot and the scene slot of a technique are interchangeable.
use: SnellHit h = snellIntersectWith(SNELL_STRATEGY_CBS, origin, dir, depthTex, normalTex,
                                     pyramidTex, surface, snellIntersectOptions(SNELL_STRATEGY_CBS));
  strategy    SNELL_STRATEGY_* (technique_options.glsl); usually o.strategy
  origin, dir view-space ray (P1, T1 for the back faces; P2, T2 for the scene)
  depthTex    the depth buffer `surface` describes
  normalTex   its view-space normals (PLANE_NORMAL only; any texture otherwise)
  pyramidTex  its depth min/max pyramid (intersect/depth_pyramid.glsl), full mip
              chain: the search range for CBS / BINARY / LINEAR_BINARY when
              o.rangeSource is SNELL_RANGE_PYRAMID, and the depth mips of
              PLANE_DEPTH (its .x is the mean depth value)
  o           parameters (snellIntersectOptions(strategy) gives the defaults)
options:
  SNELL_TECHNIQUE_STRATEGIES  bit mask of the strategies compiled in (bit k =
                              strategy k, 0x1FF = all, the default). Every
                              technique call inlines the dispatcher, and with
                              it every strategy: a shader that uses one or two
                              presets compiles much faster (llvmpipe: minutes
                              -> seconds) with only their bits, e.g.
                              #define SNELL_TECHNIQUE_STRATEGIES ((1 << SNELL_STRATEGY_CBS) | 1)
                              A strategy left out answers snellHitMiss(0).
  the rest: technique_options.glsl
contract:
  - SINGLE and WYMAN: snellIntersectSingleSample(origin, dir, depthTex, surface).
  - PLANE_NORMAL: snellIntersectPlaneNormal(.., normalTex, surface, o.normalLod, o.steps).
  - PLANE_DEPTH: snellIntersectPlaneDepth(origin, dir, pyramidTex, surface,
    maxLod, o.steps), maxLod = o.maxLod, or snellTextureTopLod(pyramidTex) when
    o.maxLod < 0.
  - CBS / BINARY / LINEAR_BINARY: the range [zNearest, zFarthest] is
    snellDepthRangeFromPyramid(pyramidTex) (1 fetch, counted in h.fetches) or
    (o.zNearest, o.zFarthest); an invalid pyramid range is a miss with that
    fetch; then the strategy with o.steps (and o.refineSteps for LINEAR_BINARY).
  - LINEAR_MARCH: snellLinearMarch(.., o.maxDistance, o.steps, o.refineSteps);
    DDA: snellDdaMarch(.., o.maxDistance, o.thickness, o.stride, o.steps).
  - any other strategy value: snellHitMiss(0).
  - every result is the strategy's own SnellHit (contracts in intersect/), with
    the range fetch added.
  - the strategy reads the surface with o.depthFilter (the surface's
    depthFilter field is replaced by it).
source: DESIGN.md sec. 2 ("every intersector is interchangeable in both
  slots"); the strategies' own sources.
*/
#ifndef SNELL_SHADE_TECHNIQUE_INTERSECT_GLSL
#define SNELL_SHADE_TECHNIQUE_INTERSECT_GLSL
#include "../prelude.glsl"
#include "../intersect/hit.glsl"
#include "../intersect/depth_surface.glsl"
#include "../intersect/single_sample.glsl"
#include "../intersect/plane_normal.glsl"
#include "../intersect/plane_depth.glsl"
#include "../intersect/conservative_binary_search.glsl"
#include "../intersect/binary_search.glsl"
#include "../intersect/linear_binary_search.glsl"
#include "../intersect/linear_march.glsl"
#include "../intersect/dda_march.glsl"
#include "technique_options.glsl"
#include "../intersect/depth_range.glsl"

#ifndef SNELL_TECHNIQUE_STRATEGIES
#  define SNELL_TECHNIQUE_STRATEGIES 0x1FF
#endif
/* true when strategy k is compiled in (a constant expression: the branch folds away) */
#define SNELL_TECHNIQUE_HAS(k) ((SNELL_TECHNIQUE_STRATEGIES & (1 << (k))) != 0)

SNELL_FN SnellHit snellIntersectWith(int strategy, vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_TEX2D normalTex,
                                     SNELL_TEX2D pyramidTex, SnellDepthSurface readAs, SnellIntersectOptions o) {
  SnellDepthSurface surface = readAs;
  surface.depthFilter = o.depthFilter;
  if ((SNELL_TECHNIQUE_HAS(SNELL_STRATEGY_SINGLE) && strategy == SNELL_STRATEGY_SINGLE) ||
      (SNELL_TECHNIQUE_HAS(SNELL_STRATEGY_WYMAN) && strategy == SNELL_STRATEGY_WYMAN)) {
    return snellIntersectSingleSample(origin, dir, depthTex, surface);
  }
  if (SNELL_TECHNIQUE_HAS(SNELL_STRATEGY_PLANE_NORMAL) && strategy == SNELL_STRATEGY_PLANE_NORMAL) {
    return snellIntersectPlaneNormal(origin, dir, depthTex, normalTex, surface, o.normalLod, o.steps);
  }
  if (SNELL_TECHNIQUE_HAS(SNELL_STRATEGY_PLANE_DEPTH) && strategy == SNELL_STRATEGY_PLANE_DEPTH) {
    int maxLod = o.maxLod >= 0 ? o.maxLod : snellTextureTopLod(pyramidTex);
    return snellIntersectPlaneDepth(origin, dir, pyramidTex, surface, maxLod, o.steps);
  }
  if (SNELL_TECHNIQUE_HAS(SNELL_STRATEGY_LINEAR_MARCH) && strategy == SNELL_STRATEGY_LINEAR_MARCH) {
    return snellLinearMarch(origin, dir, depthTex, surface, o.maxDistance, o.steps, o.refineSteps);
  }
  if (SNELL_TECHNIQUE_HAS(SNELL_STRATEGY_DDA) && strategy == SNELL_STRATEGY_DDA) {
    return snellDdaMarch(origin, dir, depthTex, surface, o.maxDistance, o.thickness, o.stride, o.steps);
  }
  bool cbs = SNELL_TECHNIQUE_HAS(SNELL_STRATEGY_CBS) && strategy == SNELL_STRATEGY_CBS;
  bool binary = SNELL_TECHNIQUE_HAS(SNELL_STRATEGY_BINARY) && strategy == SNELL_STRATEGY_BINARY;
  bool linearBinary = SNELL_TECHNIQUE_HAS(SNELL_STRATEGY_LINEAR_BINARY) && strategy == SNELL_STRATEGY_LINEAR_BINARY;
  if (!cbs && !binary && !linearBinary) {
    return snellHitMiss(0);
  }
  SnellDepthRange range;
  int rangeFetches = 0;
  if (o.rangeSource == SNELL_RANGE_EXPLICIT) {
    range.zNearest = o.zNearest;
    range.zFarthest = o.zFarthest;
    range.valid = true;
  } else {
    range = snellDepthRangeFromPyramid(pyramidTex);
    rangeFetches = 1;
  }
  if (!range.valid) {
    return snellHitMiss(rangeFetches);
  }
  SnellHit h;
  if (cbs) {
    h = snellConservativeBinarySearch(origin, dir, depthTex, surface, range.zNearest, range.zFarthest, o.steps);
  } else if (binary) {
    h = snellBinarySearch(origin, dir, depthTex, surface, range.zNearest, range.zFarthest, o.steps);
  } else {
    h = snellLinearBinarySearch(origin, dir, depthTex, surface, range.zNearest, range.zFarthest, o.steps,
                                o.refineSteps);
  }
  h.fetches = h.fetches + rangeFetches;
  return h;
}

#endif
