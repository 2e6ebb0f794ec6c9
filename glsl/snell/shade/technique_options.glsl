/*
description: the knobs of a two-interface refraction technique: which
  intersection strategy fills each slot (GLSL has no function pointers, so a
  strategy is an int constant that snellIntersectWith dispatches on), its
  parameters, and the optics and shading options. Both structs come with a
  constructor that fills every field with the documented default; presets
  (technique_presets.glsl) start from these.
use: SnellIntersectOptions io = snellIntersectOptions(SNELL_STRATEGY_CBS);
     io.steps = 8;
     SnellTechniqueOptions o = snellTechniqueOptions();
     o.back = io; o.exitMode = SNELL_EXIT_SCENE; o.exit = snellIntersectOptions(SNELL_STRATEGY_PLANE_NORMAL);
options (strategy constants, the values of SnellIntersectOptions.strategy):
  SNELL_STRATEGY_SINGLE         0  snellIntersectSingleSample (1 fetch)
  SNELL_STRATEGY_PLANE_NORMAL   1  snellIntersectPlaneNormal, `steps` iterations
  SNELL_STRATEGY_PLANE_DEPTH    2  snellIntersectPlaneDepth, `steps` iterations,
                                   reads the pyramid texture as depth mips
  SNELL_STRATEGY_CBS            3  snellConservativeBinarySearch, `steps` steps
  SNELL_STRATEGY_BINARY         4  snellBinarySearch, `steps` steps
  SNELL_STRATEGY_LINEAR_BINARY  5  snellLinearBinarySearch, `steps` linear +
                                   `refineSteps` binary steps
  SNELL_STRATEGY_LINEAR_MARCH   6  snellLinearMarch, `steps` steps, `refineSteps`
                                   bisections, over `maxDistance`
  SNELL_STRATEGY_DDA            7  snellDdaMarch, `steps`, `stride`, `thickness`,
                                   `maxDistance`
  SNELL_STRATEGY_WYMAN          8  Wyman 2005 distance interpolation (first slot
                                   of snellTwoInterfaceTrace only; it needs the
                                   per-vertex d_N). snellIntersectWith treats it
                                   as SINGLE, which is Wyman's estimate with
                                   d = d_V (ratio 1)
  range sources (searches): SNELL_RANGE_PYRAMID 0 (top level of the pyramid
  texture, snellDepthRangeFromPyramid), SNELL_RANGE_EXPLICIT 1 (zNearest and
  zFarthest fields: a bounding box, snellDepthRangeFromBox)
  exit modes: SNELL_EXIT_ENVIRONMENT 0 (distant environment along T2),
  SNELL_EXIT_SCENE 1 (the opaque scene's depth/colour buffers, exit slot)
  reflection modes (the first surface's reflected ray R, when reflection is
  on): SNELL_REFLECT_ENVIRONMENT 0 (the environment along R),
  SNELL_REFLECT_SCENE 1 (R from P1 against the opaque scene's buffers with the
  `reflect` slot's strategy, the environment where it finds nothing:
  screen-space reflection, what a ray tracer's F bg(R) computes)
  fallbacks when the exit-slot hit is invalid: SNELL_FALLBACK_ENVIRONMENT 0
  (environment along T2), SNELL_FALLBACK_EDGE_FADE 1 (scene colour at the
  clamped projection of P2 + fallbackDistance T2, faded to the environment
  over edgeFadeWidth of uv near and beyond the screen edge)
contract (defaults):
  SnellIntersectOptions: steps = SNELL_CBS_STEPS (CBS), SNELL_BINARY_SEARCH_STEPS
  (BINARY), SNELL_LINEAR_SEARCH_STEPS (LINEAR_BINARY), SNELL_PLANE_ITERATIONS
  (planes), SNELL_LINEAR_MARCH_STEPS, SNELL_DDA_STEPS, 0 (SINGLE, WYMAN);
  refineSteps = SNELL_BINARY_SEARCH_STEPS (LINEAR_BINARY),
  SNELL_LINEAR_MARCH_REFINE_STEPS (LINEAR_MARCH), else 0; maxDistance =
  SNELL_LINEAR_MARCH_MAX_DISTANCE (LINEAR_MARCH) or SNELL_DDA_MAX_DISTANCE;
  thickness = SNELL_DDA_THICKNESS; stride = SNELL_DDA_STRIDE; normalLod = 0;
  maxLod = -1 (the pyramid's top level); rangeSource = PYRAMID; zNearest =
  zFarthest = 0; depthFilter = SNELL_DEPTH_FILTER_NEAREST (how the strategy reads
  the depth buffer: intersect/depth_surface.glsl; the dispatcher hands it to the
  strategy in the surface's depthFilter field). An unknown strategy is stored as given (snellIntersectWith
  answers it with a miss).
  SnellTechniqueOptions: back = CBS, exit = PLANE_NORMAL, exitMode =
  ENVIRONMENT, fallback = ENVIRONMENT, fallbackDistance = 1, edgeFadeWidth =
  0.1, tirPolicy = SNELL_TIR_CRITICAL (Wyman 2005, O&B 2007 sec. 5), ior = 1.5,
  iorOutside = 1, dispersion = 1 (one trace; 3 = one per channel with iors,
  e.g. snellDispersionIors(1.5168f, 64.17f) from shade/dispersion.glsl), iors =
  (1.5, 1.5, 1.5), absorption = 0 (Beer-Lambert sigma per channel, per view
  unit), reflection = true (Fresnel-weighted reflection at the first
  interface), reflectionMode = ENVIRONMENT, reflect = LINEAR_MARCH (its
  defaults; read only in SCENE mode), roughness = 0, sceneColorLevels = environmentLevels = 1
  (mip levels for snellRoughnessToLod), envX/envY/envZ = the columns of the
  world-from-view rotation used for environment lookups (identity).
source: the composition of DESIGN.md sec. 2 (a technique = optics, an
  intersector against the back faces, optics, an intersector against the scene
  or an environment lookup); Oliveira & Brauwers 2007 sec. 3; Mayer &
  Assarsson, "Constant-Time Light Refraction Simulation".
*/
#ifndef SNELL_SHADE_TECHNIQUE_OPTIONS_GLSL
#define SNELL_SHADE_TECHNIQUE_OPTIONS_GLSL
#include "../prelude.glsl"
#include "../optics/refract.glsl"
#include "../intersect/depth_surface.glsl"
#include "../intersect/binary_search.glsl"
#include "../intersect/conservative_binary_search.glsl"
#include "../intersect/linear_binary_search.glsl"
#include "../intersect/linear_march.glsl"
#include "../intersect/dda_march.glsl"
#include "../intersect/plane_refine.glsl"

#define SNELL_STRATEGY_SINGLE 0
#define SNELL_STRATEGY_PLANE_NORMAL 1
#define SNELL_STRATEGY_PLANE_DEPTH 2
#define SNELL_STRATEGY_CBS 3
#define SNELL_STRATEGY_BINARY 4
#define SNELL_STRATEGY_LINEAR_BINARY 5
#define SNELL_STRATEGY_LINEAR_MARCH 6
#define SNELL_STRATEGY_DDA 7
#define SNELL_STRATEGY_WYMAN 8

#define SNELL_RANGE_PYRAMID 0
#define SNELL_RANGE_EXPLICIT 1

#define SNELL_EXIT_ENVIRONMENT 0
#define SNELL_EXIT_SCENE 1

#define SNELL_FALLBACK_ENVIRONMENT 0
#define SNELL_FALLBACK_EDGE_FADE 1

#define SNELL_REFLECT_ENVIRONMENT 0
#define SNELL_REFLECT_SCENE 1

struct SnellIntersectOptions {
  int strategy;
  int steps;
  int refineSteps;
  float maxDistance;
  float thickness;
  float stride;
  float normalLod;
  int maxLod;
  int rangeSource;
  float zNearest;
  float zFarthest;
  int depthFilter;
};

struct SnellTechniqueOptions {
  SnellIntersectOptions back;
  SnellIntersectOptions exit;
  int exitMode;
  int fallback;
  float fallbackDistance;
  float edgeFadeWidth;
  int tirPolicy;
  float ior;
  float iorOutside;
  int dispersion;
  vec3 iors;
  vec3 absorption;
  bool reflection;
  int reflectionMode;
  SnellIntersectOptions reflect;
  float roughness;
  int sceneColorLevels;
  int environmentLevels;
  vec3 envX;
  vec3 envY;
  vec3 envZ;
};

SNELL_FN SnellIntersectOptions snellIntersectOptions(int strategy) {
  SnellIntersectOptions o;
  o.strategy = strategy;
  o.steps = 0;
  o.refineSteps = 0;
  o.maxDistance = SNELL_DDA_MAX_DISTANCE;
  o.thickness = SNELL_DDA_THICKNESS;
  o.stride = SNELL_DDA_STRIDE;
  o.normalLod = 0.0f;
  o.maxLod = -1;
  o.rangeSource = SNELL_RANGE_PYRAMID;
  o.zNearest = 0.0f;
  o.zFarthest = 0.0f;
  o.depthFilter = SNELL_DEPTH_FILTER_NEAREST;
  if (strategy == SNELL_STRATEGY_CBS) {
    o.steps = SNELL_CBS_STEPS;
  } else if (strategy == SNELL_STRATEGY_BINARY) {
    o.steps = SNELL_BINARY_SEARCH_STEPS;
  } else if (strategy == SNELL_STRATEGY_LINEAR_BINARY) {
    o.steps = SNELL_LINEAR_SEARCH_STEPS;
    o.refineSteps = SNELL_BINARY_SEARCH_STEPS;
  } else if (strategy == SNELL_STRATEGY_PLANE_NORMAL || strategy == SNELL_STRATEGY_PLANE_DEPTH) {
    o.steps = SNELL_PLANE_ITERATIONS;
  } else if (strategy == SNELL_STRATEGY_LINEAR_MARCH) {
    o.steps = SNELL_LINEAR_MARCH_STEPS;
    o.refineSteps = SNELL_LINEAR_MARCH_REFINE_STEPS;
    o.maxDistance = SNELL_LINEAR_MARCH_MAX_DISTANCE;
  } else if (strategy == SNELL_STRATEGY_DDA) {
    o.steps = SNELL_DDA_STEPS;
  }
  return o;
}

SNELL_FN SnellTechniqueOptions snellTechniqueOptions() {
  SnellTechniqueOptions o;
  o.back = snellIntersectOptions(SNELL_STRATEGY_CBS);
  o.exit = snellIntersectOptions(SNELL_STRATEGY_PLANE_NORMAL);
  o.exitMode = SNELL_EXIT_ENVIRONMENT;
  o.fallback = SNELL_FALLBACK_ENVIRONMENT;
  o.fallbackDistance = 1.0f;
  o.edgeFadeWidth = 0.1f;
  o.tirPolicy = SNELL_TIR_CRITICAL;
  o.ior = 1.5f;
  o.iorOutside = 1.0f;
  o.dispersion = 1;
  o.iors = vec3(1.5f, 1.5f, 1.5f);
  o.absorption = vec3(0.0f, 0.0f, 0.0f);
  o.reflection = true;
  o.reflectionMode = SNELL_REFLECT_ENVIRONMENT;
  o.reflect = snellIntersectOptions(SNELL_STRATEGY_LINEAR_MARCH);
  o.roughness = 0.0f;
  o.sceneColorLevels = 1;
  o.environmentLevels = 1;
  o.envX = vec3(1.0f, 0.0f, 0.0f);
  o.envY = vec3(0.0f, 1.0f, 0.0f);
  o.envZ = vec3(0.0f, 0.0f, 1.0f);
  return o;
}

#endif
