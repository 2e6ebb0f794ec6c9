/*
description: the knobs of a two-interface refraction technique: how the back
  face is found (any intersection strategy in the back slot, or Wyman's
  distance interpolation), which strategy fills the exit and reflection slots
  (intersect/intersect_with.glsl: SnellIntersectOptions, one per slot), and
  the optics and shading options. The constructor fills every field with the
  documented default; presets (technique_presets.glsl) start from it.
use: SnellTechniqueOptions o = snellTechniqueOptions();
     o.back = snellIntersectOptions(SNELL_STRATEGY_CBS);
     o.back.cbsSteps = 8;
     o.exitMode = SNELL_EXIT_SCENE;
     o.exit = snellIntersectOptions(SNELL_STRATEGY_PLANE_NORMAL);
options:
  back methods (how P2 is found, snellTwoInterfaceTrace): SNELL_BACK_INTERSECT
  0 (the back slot's strategy against the back-face depth buffer),
  SNELL_BACK_WYMAN 1 (Wyman 2005 distance interpolation between d_V and the
  per-vertex d_N; the back slot is not read)
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
contract (defaults): backMethod = INTERSECT, back = CBS, exit =
  PLANE_NORMAL (each slot with snellIntersectOptions' defaults), exitMode =
  ENVIRONMENT, fallback = ENVIRONMENT, fallbackDistance = 1, edgeFadeWidth =
  0.1, tirPolicy = SNELL_TIR_CRITICAL (Wyman 2005, O&B 2007 sec. 5), ior = 1.5,
  iorOutside = 1, dispersion = 1 (one trace; 3 = one per channel with iors,
  e.g. snellDispersionIors(1.5168f, 64.17f) from shade/dispersion.glsl), iors =
  (1.5, 1.5, 1.5), absorption = 0 (Beer-Lambert sigma per channel, per view
  unit), reflection = true (Fresnel-weighted reflection at the first
  interface), reflectionMode = ENVIRONMENT, reflect = LINEAR_MARCH (its
  defaults; read only in SCENE mode), roughness = 0, sceneColorLevels =
  environmentLevels = 1 (mip levels for snellRoughnessToLod), envX/envY/envZ
  = the columns of the world-from-view rotation used for environment lookups
  (identity).
source: the composition of DESIGN.md sec. 2 (a technique = optics, an
  intersector against the back faces, optics, an intersector against the scene
  or an environment lookup); Oliveira & Brauwers 2007 sec. 3; Wyman 2005;
  Mayer & Assarsson, "Constant-Time Light Refraction Simulation".
*/
#ifndef SNELL_SHADE_TECHNIQUE_OPTIONS_GLSL
#define SNELL_SHADE_TECHNIQUE_OPTIONS_GLSL
#include "../prelude.glsl"
#include "../optics/refract.glsl"
#include "../intersect/intersect_with.glsl"

#define SNELL_BACK_INTERSECT 0
#define SNELL_BACK_WYMAN 1

#define SNELL_EXIT_ENVIRONMENT 0
#define SNELL_EXIT_SCENE 1

#define SNELL_FALLBACK_ENVIRONMENT 0
#define SNELL_FALLBACK_EDGE_FADE 1

#define SNELL_REFLECT_ENVIRONMENT 0
#define SNELL_REFLECT_SCENE 1

struct SnellTechniqueOptions {
  int backMethod;
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

SNELL_FN SnellTechniqueOptions snellTechniqueOptions() {
  SnellTechniqueOptions o;
  o.backMethod = SNELL_BACK_INTERSECT;
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
