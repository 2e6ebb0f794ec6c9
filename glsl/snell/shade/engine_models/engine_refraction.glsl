/*
description: what the engines' screen-space refraction models return, and
  the step they all share: refract the view ray at the front face, then read
  the opaque scene's colour where a point projects. The models themselves
  (threejs.glsl, filament.glsl, hdrp.glsl, godot.glsl) re-derive, from each
  engine's documented source, where that engine reads its scene colour, so a
  host can score them against snell's techniques on the same buffers (the lab
  does). They need no back-face pass: they are snell's cheapest tier.
use: SnellEngineEntry t = snellEngineEntry(p, n, eta);   // the entry refraction every refracting model starts from
     SnellEngineRefraction e = snellEngineSeePoint(x, direction, distance, clipFromView);
     SnellEngineRefraction e = snellEngineInvalid();   // what every model returns for invalid input
     vec4 s = SNELL_SAMPLE_LOD(sceneColor, clamp(e.uv, vec2(0.0f, 0.0f), vec2(1.0f, 1.0f)), 0.0f);
     vec3 c = mix(environmentAlong(e.direction), vec3(s.x, s.y, s.z), e.sceneWeight);
  p, n      the front-face fragment's view-space position and normal (the
            normal may face either way; it is turned towards the eye)
  eta       n_outside / n_inside (1 / ior: every engine refracts from air)
  x         the view-space point whose projection is read
contract:
  - SnellEngineRefraction.uv: where the model reads the scene colour, in the
    uv of clipFromView's buffers; it may lie outside [0,1]^2: every engine
    reads it clamped to the edge (its sampler), the caller clamps.
  - sceneWeight in [0,1]: the scene colour's share; the rest is the
    environment along `direction` (HDRP's probe fallback; 0 also where the
    point does not project: at or behind the camera).
  - direction: unit, the direction an environment read follows.
  - distance in [0, SNELL_FLT_MAX]: the length the engine absorbs over.
  - valid false (uv 0, weight 0, direction 0, distance 0): p or n zero, NaN or
    infinite, or (every model but Godot's, which has no eta) eta not a finite
    positive normal number (snellRefract's rules); the caller shows what it
    shows for an invalid fragment.
  - snellEngineEntry(p, n, eta): direction, tir and valid of snellRefract(p,
    n, eta, SNELL_TIR_ZERO); normal = n / |n| turned towards the eye exactly as
    snellRefract turns it (0 when n is zero or not finite); cosine =
    dot(normal, direction) (0 on TIR or invalid input).
  - every model that refracts starts with snellEngineEntry: where it is not valid,
    snellEngineInvalid(); on TIR at the entry (eta > 1, direction 0),
    snellEngineSeePoint(p, p, 0, clipFromView): the fragment's own texel, no
    displacement. A length parameter that is negative or NaN counts as 0, as
    the engines clamp theirs.
  - snellEngineSeePoint(x, direction, distance, clipFromView): uv =
    snellViewToUv(clipFromView, x).uv and weight 1 where x projects, else uv 0
    and weight 0; direction normalized (0 stays 0), distance clamped to
    [0, SNELL_FLT_MAX] (NaN: 0).
source: the engines' shared first step: T = refract(-V, N, 1/ior) at the front
  face (three.js transmission_pars_fragment, Filament surface_light_indirect.fs,
  HDRP Refraction.hlsl, Bevy transmission.wesl).
*/
#ifndef SNELL_SHADE_ENGINE_MODELS_ENGINE_REFRACTION_GLSL
#define SNELL_SHADE_ENGINE_MODELS_ENGINE_REFRACTION_GLSL
#include "../../prelude.glsl"
#include "../../camera/view_to_uv.glsl"
#include "../../optics/safe_normalize.glsl"
#include "../../optics/refract.glsl"

struct SnellEngineEntry {
  vec3 direction;  // T (0 on TIR)
  vec3 normal;     // the unit normal turned as snellRefract turns it (towards the eye)
  float cosine;    // dot(normal, T), <= 0
  bool tir;
  bool valid;
};

struct SnellEngineRefraction {
  vec2 uv;
  float sceneWeight;
  vec3 direction;
  float distance;
  bool valid;
};

SNELL_FN SnellEngineRefraction snellEngineInvalid() {
  SnellEngineRefraction e;
  e.uv = vec2(0.0f, 0.0f);
  e.sceneWeight = 0.0f;
  e.direction = vec3(0.0f, 0.0f, 0.0f);
  e.distance = 0.0f;
  e.valid = false;
  return e;
}

/* The entry refraction every refracting model starts from: T = refract(-V, N, 1/ior) */
SNELL_FN SnellEngineEntry snellEngineEntry(vec3 p, vec3 n, float eta) {
  SnellRefraction t = snellRefract(p, n, eta, SNELL_TIR_ZERO);
  SnellEngineEntry e;
  e.direction = t.direction;
  e.normal = snellSafeNormalize(n);
  e.normal = -dot(e.normal, snellSafeNormalize(p)) < 0.0f ? -e.normal : e.normal;
  e.cosine = dot(e.normal, t.direction);
  e.tir = t.tir;
  e.valid = t.valid;
  return e;
}

SNELL_FN SnellEngineRefraction snellEngineSeePoint(vec3 x, vec3 direction, float distance, mat4 clipFromView) {
  SnellEngineRefraction e = snellEngineInvalid();
  SnellScreenPoint sp = snellViewToUv(clipFromView, x);
  if (sp.valid) {
    e.uv = sp.uv;
    e.sceneWeight = 1.0f;
  }
  e.direction = snellSafeNormalize(direction);
  float d = distance > 0.0f ? distance : 0.0f;
  e.distance = d < SNELL_FLT_MAX ? d : SNELL_FLT_MAX;
  e.valid = true;
  return e;
}

#endif
