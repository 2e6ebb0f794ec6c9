/*
description: Godot 4's refraction (BaseMaterial3D "Refraction"): no ray at
  all, the screen uv shifted against the view-space normal's xy by a constant
  scale, the shift faded out where the opaque scene at the shifted uv lies
  less than one unit behind the surface.
use: SnellEngineRefraction e = snellEngineGodot(p, n, scale, sceneDepth, scene);
  p, n            the front-face fragment's view-space position and normal (the
                  normal is turned towards the eye)
  scale           Godot's "refraction" (uv units per unit of normal, default
                  0.05; the editor offers -1 .. 1)
  sceneDepth, scene  the opaque scene's depth buffer and its SnellDepthSurface
                  (its clipFromView is the colour buffer's projection)
contract:
  - u0 = snellViewToUv(scene.clipFromView, p).uv, N the unit normal turned
    towards the eye, k = scale clamped to [-1, 1] (the editor's range; NaN:
    0), u1 = u0 - k N.xy.
  - g = S(clamp(p.z - z, 0, 1)), S(x) = x^2 (3 - 2x), with z the scene's view z
    at u1 clamped to [0,1]^2 (snellSampleSurface), g = 1 where that read is not
    valid (no surface: the far plane); uv = u0 + g (u1 - u0).
  - weight 1 (0 where p does not project), direction p / |p|, distance 0 (no
    absorption). p or n zero, NaN or infinite: snellEngineInvalid().
  - The uv is in the buffer's own convention (origin bottom-left here); on
    Godot's Vulkan renderers SCREEN_UV runs downwards while the normal's y
    runs upwards, so there the vertical shift has the other sign: this function
    keeps both axes consistent. Not modelled: the blur lod 8 roughness, the
    emission blend.
source: Godot (MIT), scene/resources/material.cpp at
  0059d788b03b559846087c2a1b86a0e19cbdc4ce (BaseMaterial3D::_update_shader,
  the refraction block: ref_ofs = SCREEN_UV - ref_normal.xy * refraction, the
  depth-guarded mix). Re-derived from the generated shader's behaviour, not
  copied.
*/
#ifndef SNELL_SHADE_ENGINE_MODELS_GODOT_GLSL
#define SNELL_SHADE_ENGINE_MODELS_GODOT_GLSL
#include "engine_refraction.glsl"
#include "../../intersect/depth_surface.glsl"

SNELL_FN SnellEngineRefraction snellEngineGodot(vec3 p, vec3 n, float scale, SNELL_TEX2D sceneDepth,
                                                SNELL_IN(SnellDepthSurface) scene) {
  vec3 v = snellSafeNormalize(p);
  vec3 nf = snellSafeNormalize(n);
  if (dot(v, v) == 0.0f || dot(nf, nf) == 0.0f) {
    return snellEngineInvalid();
  }
  nf = -dot(nf, v) < 0.0f ? -nf : nf;
  SnellEngineRefraction e = snellEngineSeePoint(p, p, 0.0f, scene.clipFromView);
  if (e.sceneWeight > 0.0f) {
    float k = isnan(scale) ? 0.0f : clamp(scale, -1.0f, 1.0f);
    vec2 u0 = e.uv;
    vec2 u1 = u0 - k * vec2(nf.x, nf.y);
    SnellSurfaceSample b = snellSampleSurface(sceneDepth, clamp(u1, vec2(0.0f, 0.0f), vec2(1.0f, 1.0f)), scene);
    float g = 1.0f;
    if (b.valid) {
      g = clamp(p.z - b.viewZ, 0.0f, 1.0f);
      g = g * g * (3.0f - 2.0f * g);
    }
    e.uv = u0 + g * (u1 - u0);
  }
  return e;
}

#endif
