/*
description: Unity HDRP's screen-space refraction (Lit, transparent), its
  refraction models "Sphere" and "Box" (the UI's "Thin" is the box model at a
  fixed thickness, 5 cm in Unity's documentation): the model gives an exit point and
  direction, the exit ray is cast against the reflection probe's proxy volume,
  and the scene colour is read where that hit projects, faded out towards the
  screen's edges (the probe fills the rest) and replaced by the fragment's
  own texel where the opaque scene there lies in front of the surface.
use: SnellEngineRefraction e = snellEngineHdrpSphere(p, n, eta, thickness, proxyFromView, sceneDepth, scene);
     SnellEngineRefraction e = snellEngineHdrpBox(p, n, eta, thickness, proxyFromView, sceneDepth, scene);
     float s = snellEngineProxyExit(origin, dir, proxyFromView);
     SnellEngineRefraction e = snellEngineHdrpProxyLookup(p, origin, dir, dist, proxyFromView, sceneDepth, scene);
     float w = snellEngineHdrpEdgeFade(uv);
  p, n, eta       as in engine_refraction.glsl
  thickness       the sphere's diameter / the box's (slab's) thickness
                  (HDRP's material "thickness"), view-space units
  proxyFromView   the probe's proxy box: the affine map from view space to the
                  box's own space, where the box is [-1,1]^3 (a box of half
                  extents h centred at c with axes A: scale(1/h) A^T translate(-c))
  sceneDepth, scene  the opaque scene's depth buffer and its SnellDepthSurface
                  (its clipFromView is the colour buffer's projection)
options:
  SNELL_HDRP_SCREEN_FADE_DISTANCE  the edge fade's width (HDRP's volume
                  setting screenFadeDistance, default 0.1f)
contract:
  - T = snellEngineEntry(p, n, eta).direction, N the unit normal turned
    towards the eye, c = dot(N, T), t = thickness (0 when negative or NaN).
  - sphere: d = -c t, P1 = p + d T, N1 = (c T - 0.5 N) / |c T - 0.5 N| (towards
    the sphere's centre p - N t / 2), R2 = snellRefract(T, N1, 1 / eta,
    SNELL_TIR_ZERO) (T on TIR); snellEngineHdrpProxyLookup(p, P1, R2, d, ...).
  - box: d = t / max(-c, 1e-5), snellEngineHdrpProxyLookup(p, p + d T, p / |p|,
    d, ...): a slab's exit restores the view direction.
  - snellEngineProxyExit(o, dir, M): with o', d' = o and dir in the box's space,
    s = min over the axes with |d'_i| >= SNELL_FLT_MIN of (sign(d'_i) - o'_i) / d'_i, then
    max(s, 0): the distance to the box's far side, in units of |dir|;
    SNELL_FLT_MAX when no axis is crossed (a degenerate proxy); 0 when o' or
    d' is not finite.
  - snellEngineHdrpProxyLookup(p, o, dir, d, ...): H = o + s dir/|dir|; where H
    does not project, weight 0 (the probe); else uv = H's projection, weight =
    snellEngineHdrpEdgeFade(uv), and when the scene depth at uv is valid and no
    farther from the eye than p, uv becomes p's own projection (HDRP's halo
    test; weight kept). direction dir/|dir|, distance d.
  - snellEngineHdrpEdgeFade(uv) = S(x) S(y) with x = clamp((1 - |2 u - 1|) /
    SNELL_HDRP_SCREEN_FADE_DISTANCE, 0, 1) (y from v), S(x) = x^2 (3 - 2x);
    non-finite uv: 0.
  - TIR at the entry and invalid input as engine_refraction.glsl says. Not modelled:
    the mip level from roughness (alpha^1.3 (levels - 1), its halo shrink), the
    probe's content (the caller's environment), Fresnel and absorption weights.
source: Unity Graphics (Unity Companion License), Packages/
  com.unity.render-pipelines.core/ShaderLibrary/Refraction.hlsl at
  d220553d7b20798d48be08af60db4048cbd39f7d (RefractionModelSphere,
  RefractionModelBox); com.unity.render-pipelines.high-definition/Runtime/
  Material/Lit/Lit.hlsl at 1390609ca74ecc860907a6e87759644f944fbada
  (EvaluateBSDF_ScreenspaceRefraction: proxy raycast, EdgeOfScreenFade, the
  depth test against the refracting pixel). Re-derived from the engine's
  documented behaviour, not copied.
*/
#ifndef SNELL_SHADE_ENGINE_MODELS_HDRP_GLSL
#define SNELL_SHADE_ENGINE_MODELS_HDRP_GLSL
#include "engine_refraction.glsl"
#include "../../intersect/depth_surface.glsl"

#ifndef SNELL_HDRP_SCREEN_FADE_DISTANCE
#  define SNELL_HDRP_SCREEN_FADE_DISTANCE 0.1f
#endif

/* HDRP EdgeOfScreenFade */
SNELL_FN float snellEngineHdrpEdgeFade(vec2 uv) {
  if (!SNELL_FINITE(uv.x) || !SNELL_FINITE(uv.y)) {
    return 0.0f;
  }
  float x = clamp((1.0f - abs(2.0f * uv.x - 1.0f)) / SNELL_HDRP_SCREEN_FADE_DISTANCE, 0.0f, 1.0f);
  float y = clamp((1.0f - abs(2.0f * uv.y - 1.0f)) / SNELL_HDRP_SCREEN_FADE_DISTANCE, 0.0f, 1.0f);
  return (x * x * (3.0f - 2.0f * x)) * (y * y * (3.0f - 2.0f * y));
}

/* HDRP IntersectBoxProxy: the far side of the proxy box along the ray */
SNELL_FN float snellEngineProxyExit(vec3 origin, vec3 dir, mat4 proxyFromView) {
  vec4 o4 = SNELL_MUL(proxyFromView, vec4(origin.x, origin.y, origin.z, 1.0f));
  vec4 d4 = SNELL_MUL(proxyFromView, vec4(dir.x, dir.y, dir.z, 0.0f));
  if (!SNELL_FINITE(o4.x) || !SNELL_FINITE(o4.y) || !SNELL_FINITE(o4.z) || !SNELL_FINITE(d4.x) ||
      !SNELL_FINITE(d4.y) || !SNELL_FINITE(d4.z)) {
    return 0.0f;
  }
  // Comparisons, not min(): min() of a NaN differs between languages.
  float s = SNELL_FLT_MAX;
  // An axis the ray does not cross: zero or denormal (the prelude's rule: a GPU may flush it to 0).
  if (abs(d4.x) >= SNELL_FLT_MIN) {
    float c = ((d4.x > 0.0f ? 1.0f : -1.0f) - o4.x) / d4.x;
    s = c < s ? c : s;
  }
  if (abs(d4.y) >= SNELL_FLT_MIN) {
    float c = ((d4.y > 0.0f ? 1.0f : -1.0f) - o4.y) / d4.y;
    s = c < s ? c : s;
  }
  if (abs(d4.z) >= SNELL_FLT_MIN) {
    float c = ((d4.z > 0.0f ? 1.0f : -1.0f) - o4.z) / d4.z;
    s = c < s ? c : s;
  }
  return s > 0.0f ? s : 0.0f;
}

/* HDRP EvaluateBSDF_ScreenspaceRefraction: proxy hit, edge fade, halo test */
SNELL_FN SnellEngineRefraction snellEngineHdrpProxyLookup(vec3 p, vec3 origin, vec3 dir, float dist,
                                                          mat4 proxyFromView, SNELL_TEX2D sceneDepth,
                                                          SNELL_IN(SnellDepthSurface) scene) {
  vec3 d = snellSafeNormalize(dir);
  float s = snellEngineProxyExit(origin, d, proxyFromView);
  SnellEngineRefraction e = snellEngineSeePoint(origin + s * d, d, dist, scene.clipFromView);
  if (e.sceneWeight > 0.0f) {
    e.sceneWeight = snellEngineHdrpEdgeFade(e.uv);
    SnellSurfaceSample b = snellSampleSurface(sceneDepth, e.uv, scene);
    if (b.valid && b.viewZ >= p.z) {
      SnellScreenPoint own = snellViewToUv(scene.clipFromView, p);
      e.uv = own.uv;
    }
  }
  return e;
}

/* HDRP RefractionModelSphere, then the proxy lookup */
SNELL_FN SnellEngineRefraction snellEngineHdrpSphere(vec3 p, vec3 n, float eta, float thickness, mat4 proxyFromView,
                                                     SNELL_TEX2D sceneDepth, SNELL_IN(SnellDepthSurface) scene) {
  SnellEngineEntry t = snellEngineEntry(p, n, eta);
  if (!t.valid) {
    return snellEngineInvalid();
  }
  if (t.tir) {
    return snellEngineSeePoint(p, p, 0.0f, scene.clipFromView);
  }
  vec3 nf = t.normal;
  float c = t.cosine;
  float d = -c * (thickness > 0.0f ? thickness : 0.0f);
  vec3 p1 = p + d * t.direction;
  vec3 n1 = snellSafeNormalize(c * t.direction - 0.5f * nf);
  SnellRefraction out2 = snellRefract(t.direction, n1, 1.0f / eta, SNELL_TIR_ZERO);
  vec3 r2 = t.direction;
  if (out2.valid && !out2.tir) {
    r2 = out2.direction;
  }
  return snellEngineHdrpProxyLookup(p, p1, r2, d, proxyFromView, sceneDepth, scene);
}

/* HDRP RefractionModelBox (its "Thin" model at a fixed thickness), then the proxy lookup */
SNELL_FN SnellEngineRefraction snellEngineHdrpBox(vec3 p, vec3 n, float eta, float thickness, mat4 proxyFromView,
                                                  SNELL_TEX2D sceneDepth, SNELL_IN(SnellDepthSurface) scene) {
  SnellEngineEntry t = snellEngineEntry(p, n, eta);
  if (!t.valid) {
    return snellEngineInvalid();
  }
  if (t.tir) {
    return snellEngineSeePoint(p, p, 0.0f, scene.clipFromView);
  }
  float d = (thickness > 0.0f ? thickness : 0.0f) / max(-t.cosine, 1e-5f);
  return snellEngineHdrpProxyLookup(p, p + d * t.direction, p, d, proxyFromView, sceneDepth, scene);
}

#endif
