/*
description: screen-edge fade for perturbed (or reflected) screen-space lookups:
  1 well inside the viewport, falling linearly to 0 at its border, 0 off
  screen. Blend the perturbed sample towards the unperturbed one with it, so
  refraction does not smear the clamped edge texels.
use: float w = snellScreenEdgeFade(uvPerturbed, 0.05f);
     float w = snellScreenEdgeFade(uvPerturbed);   // width SNELL_SCREEN_EDGE_FADE
     vec4 c = mix(unperturbedColor, perturbedColor, w);
  uv     viewport uv, origin bottom-left, [0,1]^2 on screen
  width  width of the fade band, in uv units, measured inwards from each edge
options:
  SNELL_SCREEN_EDGE_FADE  default width (0.05f)
contract:
  - with e = min(u, 1 - u, v, 1 - v) (the uv distance to the nearest edge,
    negative off screen): result = clamp(e / width, 0, 1); in [0, 1], never
    NaN;
  - width is clamped to at most 0.5f; width <= 0, denormal (below the smallest
    normal float) or NaN: a hard cut, 1 on [0,1]^2 (borders included), else 0;
  - a NaN or infinite uv component: 0.
source: common screen-space reflection practice (edge attenuation of
  screen-space hits), e.g. McGuire & Mara, "Efficient GPU Screen-Space Ray
  Tracing", JCGT 3(4), 2014; applied here to Sousa's perturbed uv (GPU Gems 2,
  ch. 19, sec. 19.2, on perturbations that leave the refractive object's area).
*/
#ifndef SNELL_SHADE_PERTURB_EDGE_FADE_GLSL
#define SNELL_SHADE_PERTURB_EDGE_FADE_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"

#ifndef SNELL_SCREEN_EDGE_FADE
#  define SNELL_SCREEN_EDGE_FADE 0.05f
#endif

SNELL_FN float snellScreenEdgeFade(vec2 uv, float width) {
  if (!SNELL_FINITE(uv.x) || !SNELL_FINITE(uv.y)) {
    return 0.0f;
  }
  float e = min(min(uv.x, 1.0f - uv.x), min(uv.y, 1.0f - uv.y));
  if (isnan(width) || !(width >= SNELL_FLT_MIN)) {
    return e >= 0.0f ? 1.0f : 0.0f;
  }
  float w = min(width, 0.5f);
  return clamp(e / w, 0.0f, 1.0f);
}

SNELL_FN float snellScreenEdgeFade(vec2 uv) {
  return snellScreenEdgeFade(uv, SNELL_SCREEN_EDGE_FADE);
}

#endif
