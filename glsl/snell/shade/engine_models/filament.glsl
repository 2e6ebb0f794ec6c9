/*
description: Filament's screen-space refraction (refractionMode screenspace),
  its two refractionType models: "solid", which takes the object for a sphere
  of diameter `thickness` tangent to the surface at the fragment and reads the
  scene where the refracted ray leaves that sphere; and "thin", a slab of
  thickness `microThickness` crossed along the refracted ray (no offset at all
  when microThickness is 0).
use: SnellEngineRefraction e = snellEngineFilamentSolid(p, n, eta, thickness, clipFromView);
     SnellEngineRefraction e = snellEngineFilamentThin(p, n, eta, microThickness, clipFromView);
  p, n, eta       as in engine_refraction.glsl
  thickness       the sphere's diameter (Filament's material "thickness"), view-space units
  microThickness  the slab's thickness (Filament's "microThickness")
  clipFromView    the projection of the opaque pass's colour buffer
contract:
  - T = snellEngineEntry(p, n, eta).direction, N the unit normal turned
    towards the eye, c = dot(N, T) (<= 0), t = thickness or microThickness (0 when
    negative or NaN).
  - solid: d = -c t (the sphere's chord along T), X = p + d T.
  - thin: d = t / max(-c, 0.001), X = p + d T.
  - the result is snellEngineSeePoint(X, T, d, clipFromView) (solid) or
    snellEngineSeePoint(X, p, d, clipFromView) (thin: a slab's exit restores
    the view direction); TIR at the entry and invalid input as
    engine_refraction.glsl says. Screen-space mode
    reads only X's projection, so the sphere's exit refraction (Filament's
    cubemap mode) is not computed.
source: Filament (Apache-2.0), shaders/src/surface_light_indirect.fs at
  3681fe96573edd94dde8a98369a7e8aec588cfd0: refractionSolidSphere (d =
  thickness * -NoR, position = P + d r), refractionThinSphere (d = uThickness
  / max(-NoR, 0.001)), evaluateRefraction (screen space: the position's
  projection). Re-derived from the engine's documented behaviour, not copied.
*/
#ifndef SNELL_SHADE_ENGINE_MODELS_FILAMENT_GLSL
#define SNELL_SHADE_ENGINE_MODELS_FILAMENT_GLSL
#include "engine_refraction.glsl"

/* Filament refractionSolidSphere, screen space: the exit of the tangent sphere of diameter thickness */
SNELL_FN SnellEngineRefraction snellEngineFilamentSolid(vec3 p, vec3 n, float eta, float thickness,
                                                        mat4 clipFromView) {
  SnellEngineEntry t = snellEngineEntry(p, n, eta);
  if (!t.valid) {
    return snellEngineInvalid();
  }
  if (t.tir) {
    return snellEngineSeePoint(p, p, 0.0f, clipFromView);
  }
  float c = t.cosine;
  float d = -c * (thickness > 0.0f ? thickness : 0.0f);
  return snellEngineSeePoint(p + d * t.direction, t.direction, d, clipFromView);
}

/* Filament refractionThinSphere, screen space: a slab of thickness microThickness */
SNELL_FN SnellEngineRefraction snellEngineFilamentThin(vec3 p, vec3 n, float eta, float microThickness,
                                                       mat4 clipFromView) {
  SnellEngineEntry t = snellEngineEntry(p, n, eta);
  if (!t.valid) {
    return snellEngineInvalid();
  }
  if (t.tir) {
    return snellEngineSeePoint(p, p, 0.0f, clipFromView);
  }
  float c = t.cosine;
  float d = (microThickness > 0.0f ? microThickness : 0.0f) / max(-c, 0.001f);
  return snellEngineSeePoint(p + d * t.direction, p, d, clipFromView);
}

#endif
