/*
description: three.js's transmission (MeshPhysicalMaterial, r187), as a
  screen-space refraction model: refract at the front face only, walk the
  material's thickness along the refracted ray, and read the opaque pass's
  colour where that point projects. Bevy's specular transmission (0.20,
  transmission.wesl) places its point the same way (X = P + t T), so on a
  uniformly scaled object both engines read the same texel.
use: SnellEngineRefraction e = snellEngineThreeJs(p, n, eta, thickness, clipFromView);
  p, n, eta       as in engine_refraction.glsl
  thickness       the material's thickness times the model's scale (three.js
                  "thickness", default 0: no displacement; Bevy "thickness"),
                  view-space units; it is a constant, not the object's chord
  clipFromView    the projection of the opaque pass's colour buffer
contract:
  - T = snellEngineEntry(p, n, eta).direction, t = thickness (0 when negative or NaN);
    X = p + t T; the result is snellEngineSeePoint(X, T, t, clipFromView);
    TIR at the entry and invalid input as engine_refraction.glsl says.
  - What the engines do around it is not modelled here: three.js's roughness
    lod (log2(width) roughness clamp(2 ior - 2, 0, 1), bicubic mips), Bevy's
    blur taps, the Fresnel weights and Beer-Lambert over t (the caller's).
source: three.js r187 (npm three@0.187.0, MIT),
  src/renderers/shaders/ShaderChunk/transmission_pars_fragment.glsl.js
  (getVolumeTransmissionRay: refract(-v, n, 1 / ior), normalized, times
  thickness and the model matrix's scale; getTransmissionSample at the
  projected point); Bevy 0.20-dev (MIT OR Apache-2.0),
  crates/bevy_pbr/src/transmission.wesl (specular_transmissive_light: the exit
  point P + thickness T). Re-derived from their documented behaviour, not
  copied.
*/
#ifndef SNELL_SHADE_ENGINE_MODELS_THREEJS_GLSL
#define SNELL_SHADE_ENGINE_MODELS_THREEJS_GLSL
#include "engine_refraction.glsl"

SNELL_FN SnellEngineRefraction snellEngineThreeJs(vec3 p, vec3 n, float eta, float thickness, mat4 clipFromView) {
  SnellEngineEntry t = snellEngineEntry(p, n, eta);
  if (!t.valid) {
    return snellEngineInvalid();
  }
  if (t.tir) {
    return snellEngineSeePoint(p, p, 0.0f, clipFromView);
  }
  float d = (thickness > 0.0f ? thickness : 0.0f);
  return snellEngineSeePoint(p + d * t.direction, t.direction, d, clipFromView);
}

#endif
