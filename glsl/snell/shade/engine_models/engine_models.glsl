/*
description: the engines' screen-space refraction models by number, so a host
  can run any of them through one call (the lab's engine rows); the names and
  labels for C++ are in include/snell/engine_model_table.hpp.
use: SnellEngineRefraction e = snellEngineRefraction(SNELL_ENGINE_THREEJS, p, n, eta, parameter,
                                                     proxyFromView, sceneDepth, scene);
     int blur = snellEngineBlurOf(SNELL_ENGINE_THREEJS);  // how that engine reads rough glass (engine_rough.glsl)
  model       SNELL_ENGINE_* below
  parameter   the model's one free value: thickness (three.js / Bevy,
              Filament solid, HDRP sphere and box), microThickness (Filament
              thin), the uv scale (Godot)
  the rest    as the models' own functions (proxyFromView is read by the HDRP
              models only, sceneDepth by HDRP and Godot; every model projects
              with scene.clipFromView)
ids:
  SNELL_ENGINE_THREEJS          snellEngineThreeJs (threejs.glsl; Bevy's too)
  SNELL_ENGINE_FILAMENT_SOLID   snellEngineFilamentSolid (filament.glsl)
  SNELL_ENGINE_FILAMENT_THIN    snellEngineFilamentThin (filament.glsl)
  SNELL_ENGINE_HDRP_SPHERE      snellEngineHdrpSphere (hdrp.glsl)
  SNELL_ENGINE_HDRP_BOX         snellEngineHdrpBox (hdrp.glsl)
  SNELL_ENGINE_GODOT            snellEngineGodot (godot.glsl)
  SNELL_ENGINE_MODEL_COUNT      the number of ids (0 .. COUNT - 1)
contract: the chosen model's function with these arguments; a model outside
  0 .. SNELL_ENGINE_MODEL_COUNT - 1: snellEngineInvalid().
  snellEngineBlurOf(model): the engine's blur of engine_rough.glsl
  (SNELL_ENGINE_BLUR_THREEJS for three.js, _FILAMENT for both Filament
  models, _HDRP for both HDRP models, _GODOT for Godot); -1 for any other id
  (snellEngineBlurRead then reads the smooth texel). Bevy shares three.js's
  point (SNELL_ENGINE_THREEJS) but has a blur of its own,
  SNELL_ENGINE_BLUR_BEVY, which no model id names: a host that shows Bevy
  pairs the two (the lab's engine-bevy row).
source: the models' own files.
*/
#ifndef SNELL_SHADE_ENGINE_MODELS_ENGINE_MODELS_GLSL
#define SNELL_SHADE_ENGINE_MODELS_ENGINE_MODELS_GLSL
#include "engine_refraction.glsl"
#include "threejs.glsl"
#include "filament.glsl"
#include "hdrp.glsl"
#include "godot.glsl"
#include "engine_rough.glsl"

#define SNELL_ENGINE_THREEJS 0
#define SNELL_ENGINE_FILAMENT_SOLID 1
#define SNELL_ENGINE_FILAMENT_THIN 2
#define SNELL_ENGINE_HDRP_SPHERE 3
#define SNELL_ENGINE_HDRP_BOX 4
#define SNELL_ENGINE_GODOT 5
#define SNELL_ENGINE_MODEL_COUNT 6

SNELL_FN SnellEngineRefraction snellEngineRefraction(int model, vec3 p, vec3 n, float eta, float parameter,
                                                     mat4 proxyFromView, SNELL_TEX2D sceneDepth,
                                                     SNELL_IN(SnellDepthSurface) scene) {
  if (model == SNELL_ENGINE_THREEJS) {
    return snellEngineThreeJs(p, n, eta, parameter, scene.clipFromView);
  }
  if (model == SNELL_ENGINE_FILAMENT_SOLID) {
    return snellEngineFilamentSolid(p, n, eta, parameter, scene.clipFromView);
  }
  if (model == SNELL_ENGINE_FILAMENT_THIN) {
    return snellEngineFilamentThin(p, n, eta, parameter, scene.clipFromView);
  }
  if (model == SNELL_ENGINE_HDRP_SPHERE) {
    return snellEngineHdrpSphere(p, n, eta, parameter, proxyFromView, sceneDepth, scene);
  }
  if (model == SNELL_ENGINE_HDRP_BOX) {
    return snellEngineHdrpBox(p, n, eta, parameter, proxyFromView, sceneDepth, scene);
  }
  if (model == SNELL_ENGINE_GODOT) {
    return snellEngineGodot(p, n, parameter, sceneDepth, scene);
  }
  return snellEngineInvalid();
}

SNELL_FN int snellEngineBlurOf(int model) {
  if (model == SNELL_ENGINE_THREEJS) {
    return SNELL_ENGINE_BLUR_THREEJS;
  }
  if (model == SNELL_ENGINE_FILAMENT_SOLID || model == SNELL_ENGINE_FILAMENT_THIN) {
    return SNELL_ENGINE_BLUR_FILAMENT;
  }
  if (model == SNELL_ENGINE_HDRP_SPHERE || model == SNELL_ENGINE_HDRP_BOX) {
    return SNELL_ENGINE_BLUR_HDRP;
  }
  if (model == SNELL_ENGINE_GODOT) {
    return SNELL_ENGINE_BLUR_GODOT;
  }
  return -1;
}

#endif
