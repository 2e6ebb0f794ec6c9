/*
description: any intersection strategy of intersect/, chosen at run time: the
  strategy ids, one options struct whose fields are named after the strategy
  they belong to, and the dispatcher, so a technique's back-face, exit and
  reflection slots are interchangeable (GLSL has no function pointers: a
  strategy is an int constant that snellIntersectWith branches on).
use: SnellIntersectOptions o = snellIntersectOptions(SNELL_STRATEGY_CBS);
     o.cbsSteps = 8;
     SnellHit h = snellIntersectWith(origin, dir, depthTex, normalTex, pyramidTex, surface, o);
  origin, dir view-space ray (P1, T1 for the back faces; P2, T2 for the scene)
  depthTex    the depth buffer `surface` describes
  normalTex   its view-space normals (PLANE_NORMAL only; any texture otherwise)
  pyramidTex  its depth min/max pyramid (intersect/depth_pyramid.glsl), full mip
              chain: the search range of CBS / BINARY / LINEAR_BINARY when
              o.rangeSource is SNELL_RANGE_PYRAMID, and the depth mips of
              PLANE_DEPTH (its .x is the mean depth value)
  o           the strategy and its parameters
options (strategy ids, the values of SnellIntersectOptions.strategy):
  SNELL_STRATEGY_SINGLE         0  snellIntersectSingleSample (1 fetch)
  SNELL_STRATEGY_PLANE_NORMAL   1  snellIntersectPlaneNormal
  SNELL_STRATEGY_PLANE_DEPTH    2  snellIntersectPlaneDepth (the pyramid's
                                   levels as depth mips)
  SNELL_STRATEGY_CBS            3  snellConservativeBinarySearch
  SNELL_STRATEGY_BINARY         4  snellBinarySearch
  SNELL_STRATEGY_LINEAR_BINARY  5  snellLinearBinarySearch
  SNELL_STRATEGY_LINEAR_MARCH   6  snellLinearMarch
  SNELL_STRATEGY_DDA            7  snellDdaMarch
  SNELL_STRATEGY_COUNT          8  the number of strategies (ids 0 .. COUNT - 1;
                                   any other id misses)
  range sources of the searches: SNELL_RANGE_PYRAMID 0 (the pyramid's top
  level, snellDepthRangeFromPyramid, 1 fetch), SNELL_RANGE_EXPLICIT 1 (o.range
  as given, e.g. snellDepthRangeFromBox: Oliveira & Brauwers' bounding box)
  SNELL_INTERSECT_STRATEGIES  bit mask of the strategies compiled in (bit k =
                              strategy k; all SNELL_STRATEGY_COUNT of them,
                              the default). Every
                              technique call inlines the dispatcher, and with
                              it every strategy: a shader that uses one or two
                              presets compiles much faster (llvmpipe: minutes
                              -> seconds) with only their bits, e.g.
                              #define SNELL_INTERSECT_STRATEGIES ((1 << SNELL_STRATEGY_CBS) | 1)
                              A strategy left out answers snellHitMiss(0).
  The fields of SnellIntersectOptions, by the strategy that reads them, with
  their defaults (each default is the strategy file's own macro):
  every strategy  depthFilter = SNELL_DEPTH_FILTER_NEAREST (how the strategy
                  reads depth: intersect/depth_surface.glsl; it replaces the
                  surface's depthFilter field)
  PLANE_NORMAL, PLANE_DEPTH  planeIterations = SNELL_PLANE_ITERATIONS
                  (refinements after the first plane), planeFarStart =
                  SNELL_PLANE_FAR_START != 0 (true: on a closed surface the
                  first plane may start at the farthest back face the pyramid
                  holds under the ray, intersect/plane_far_start.glsl; false:
                  the poster's first plane)
  PLANE_NORMAL    planeNormalLod = 0 (the normal texture's level)
  PLANE_DEPTH     planeMaxLod = -1 (the coarsest depth mip: the pyramid's top
                  level, snellTextureTopLod)
  CBS             cbsSteps = SNELL_CBS_STEPS
  BINARY, LINEAR_BINARY  binarySteps = SNELL_BINARY_SEARCH_STEPS (bisections)
  LINEAR_BINARY   linearSteps = SNELL_LINEAR_SEARCH_STEPS
  CBS, BINARY, LINEAR_BINARY  rangeSource = SNELL_RANGE_PYRAMID, range =
                  snellDepthRangeInvalid() (read under SNELL_RANGE_EXPLICIT only)
  LINEAR_MARCH    marchSteps = SNELL_LINEAR_MARCH_STEPS, marchBisections =
                  SNELL_LINEAR_MARCH_REFINE_STEPS, marchMaxDistance =
                  SNELL_LINEAR_MARCH_MAX_DISTANCE
  DDA             ddaSteps = SNELL_DDA_STEPS, ddaMaxDistance =
                  SNELL_DDA_MAX_DISTANCE, ddaThickness = SNELL_DDA_THICKNESS,
                  ddaStride = SNELL_DDA_STRIDE
contract:
  - snellIntersectOptions(strategy): the strategy as given (an unknown one is
    stored too, and answered with a miss) and every field's default above.
  - snellIntersectWith, by o.strategy:
    SINGLE: snellIntersectSingleSample(origin, dir, depthTex, surface).
    PLANE_NORMAL: snellIntersectPlaneNormal(.., normalTex, pyramidTex, surface,
    o.planeNormalLod, o.planeIterations, o.planeFarStart).
    PLANE_DEPTH: snellIntersectPlaneDepth(origin, dir, pyramidTex, surface,
    maxLod, o.planeIterations, o.planeFarStart), maxLod = o.planeMaxLod, or
    snellTextureTopLod(pyramidTex) when o.planeMaxLod < 0.
    CBS / BINARY / LINEAR_BINARY: the range is snellDepthRangeFromPyramid(
    pyramidTex) (1 fetch, counted in h.fetches) or o.range; an invalid range is
    a miss (with the pyramid's fetch); then the strategy with o.cbsSteps,
    o.binarySteps, or o.linearSteps and o.binarySteps.
    LINEAR_MARCH: snellLinearMarch(.., o.marchMaxDistance, o.marchSteps,
    o.marchBisections). DDA: snellDdaMarch(.., o.ddaMaxDistance,
    o.ddaThickness, o.ddaStride, o.ddaSteps).
    Any other strategy: snellHitMiss(0).
  - every result is the strategy's own SnellHit (contracts in intersect/), with
    the range fetch added; each strategy clamps its own counts.
source: DESIGN.md sec. 2 ("every intersector is interchangeable in both
  slots"); Oliveira & Brauwers 2007 sec. 3 and sec. 6 (the two range sources);
  the strategies' own sources.
*/
#ifndef SNELL_INTERSECT_INTERSECT_WITH_GLSL
#define SNELL_INTERSECT_INTERSECT_WITH_GLSL
#include "../prelude.glsl"
#include "hit.glsl"
#include "depth_surface.glsl"
#include "depth_range.glsl"
#include "single_sample.glsl"
#include "plane_refine.glsl"
#include "plane_normal.glsl"
#include "plane_depth.glsl"
#include "conservative_binary_search.glsl"
#include "binary_search.glsl"
#include "linear_binary_search.glsl"
#include "linear_march.glsl"
#include "dda_march.glsl"

#define SNELL_STRATEGY_SINGLE 0
#define SNELL_STRATEGY_PLANE_NORMAL 1
#define SNELL_STRATEGY_PLANE_DEPTH 2
#define SNELL_STRATEGY_CBS 3
#define SNELL_STRATEGY_BINARY 4
#define SNELL_STRATEGY_LINEAR_BINARY 5
#define SNELL_STRATEGY_LINEAR_MARCH 6
#define SNELL_STRATEGY_DDA 7
#define SNELL_STRATEGY_COUNT 8

#define SNELL_RANGE_PYRAMID 0
#define SNELL_RANGE_EXPLICIT 1

#ifndef SNELL_INTERSECT_STRATEGIES
#  define SNELL_INTERSECT_STRATEGIES ((1 << SNELL_STRATEGY_COUNT) - 1)
#endif
/* true when strategy k is compiled in (a constant expression: the branch folds away) */
#define SNELL_INTERSECT_HAS(k) ((SNELL_INTERSECT_STRATEGIES & (1 << (k))) != 0)

struct SnellIntersectOptions {
  int strategy;
  int depthFilter;
  int planeIterations;
  float planeNormalLod;
  bool planeFarStart;
  int planeMaxLod;
  int cbsSteps;
  int binarySteps;
  int linearSteps;
  int rangeSource;
  SnellDepthRange range;
  int marchSteps;
  int marchBisections;
  float marchMaxDistance;
  int ddaSteps;
  float ddaMaxDistance;
  float ddaThickness;
  float ddaStride;
};

SNELL_FN SnellIntersectOptions snellIntersectOptions(int strategy) {
  SnellIntersectOptions o;
  o.strategy = strategy;
  o.depthFilter = SNELL_DEPTH_FILTER_NEAREST;
  o.planeIterations = SNELL_PLANE_ITERATIONS;
  o.planeNormalLod = 0.0f;
  o.planeFarStart = SNELL_PLANE_FAR_START != 0;
  o.planeMaxLod = -1;
  o.cbsSteps = SNELL_CBS_STEPS;
  o.binarySteps = SNELL_BINARY_SEARCH_STEPS;
  o.linearSteps = SNELL_LINEAR_SEARCH_STEPS;
  o.rangeSource = SNELL_RANGE_PYRAMID;
  o.range = snellDepthRangeInvalid();
  o.marchSteps = SNELL_LINEAR_MARCH_STEPS;
  o.marchBisections = SNELL_LINEAR_MARCH_REFINE_STEPS;
  o.marchMaxDistance = SNELL_LINEAR_MARCH_MAX_DISTANCE;
  o.ddaSteps = SNELL_DDA_STEPS;
  o.ddaMaxDistance = SNELL_DDA_MAX_DISTANCE;
  o.ddaThickness = SNELL_DDA_THICKNESS;
  o.ddaStride = SNELL_DDA_STRIDE;
  return o;
}

SNELL_FN SnellHit snellIntersectWith(vec3 origin, vec3 dir, SNELL_TEX2D depthTex, SNELL_TEX2D normalTex,
                                     SNELL_TEX2D pyramidTex, SNELL_IN(SnellDepthSurface) readAs, SnellIntersectOptions o) {
  SnellDepthSurface surface = readAs;
  surface.depthFilter = o.depthFilter;
  int strategy = o.strategy;
  if (SNELL_INTERSECT_HAS(SNELL_STRATEGY_SINGLE) && strategy == SNELL_STRATEGY_SINGLE) {
    return snellIntersectSingleSample(origin, dir, depthTex, surface);
  }
  if (SNELL_INTERSECT_HAS(SNELL_STRATEGY_PLANE_NORMAL) && strategy == SNELL_STRATEGY_PLANE_NORMAL) {
    return snellIntersectPlaneNormal(origin, dir, depthTex, normalTex, pyramidTex, surface, o.planeNormalLod, o.planeIterations, o.planeFarStart);
  }
  if (SNELL_INTERSECT_HAS(SNELL_STRATEGY_PLANE_DEPTH) && strategy == SNELL_STRATEGY_PLANE_DEPTH) {
    int maxLod = o.planeMaxLod >= 0 ? o.planeMaxLod : snellTextureTopLod(pyramidTex);
    return snellIntersectPlaneDepth(origin, dir, pyramidTex, surface, maxLod, o.planeIterations, o.planeFarStart);
  }
  if (SNELL_INTERSECT_HAS(SNELL_STRATEGY_LINEAR_MARCH) && strategy == SNELL_STRATEGY_LINEAR_MARCH) {
    return snellLinearMarch(origin, dir, depthTex, surface, o.marchMaxDistance, o.marchSteps, o.marchBisections);
  }
  if (SNELL_INTERSECT_HAS(SNELL_STRATEGY_DDA) && strategy == SNELL_STRATEGY_DDA) {
    return snellDdaMarch(origin, dir, depthTex, surface, o.ddaMaxDistance, o.ddaThickness, o.ddaStride, o.ddaSteps);
  }
  bool cbs = SNELL_INTERSECT_HAS(SNELL_STRATEGY_CBS) && strategy == SNELL_STRATEGY_CBS;
  bool binary = SNELL_INTERSECT_HAS(SNELL_STRATEGY_BINARY) && strategy == SNELL_STRATEGY_BINARY;
  bool linearBinary = SNELL_INTERSECT_HAS(SNELL_STRATEGY_LINEAR_BINARY) && strategy == SNELL_STRATEGY_LINEAR_BINARY;
  if (!cbs && !binary && !linearBinary) {
    return snellHitMiss(0);
  }
  SnellDepthRange range = o.range;
  int rangeFetches = 0;
  if (o.rangeSource != SNELL_RANGE_EXPLICIT) {
    range = snellDepthRangeFromPyramid(pyramidTex);
    rangeFetches = 1;
  }
  if (!range.valid) {
    return snellHitMiss(rangeFetches);
  }
  SnellHit h;
  if (cbs) {
    h = snellConservativeBinarySearch(origin, dir, depthTex, surface, range.zNearest, range.zFarthest, o.cbsSteps);
  } else if (binary) {
    h = snellBinarySearch(origin, dir, depthTex, surface, range.zNearest, range.zFarthest, o.binarySteps);
  } else {
    h = snellLinearBinarySearch(origin, dir, depthTex, surface, range.zNearest, range.zFarthest, o.linearSteps,
                                o.binarySteps);
  }
  h.fetches = h.fetches + rangeFetches;
  return h;
}

#endif
