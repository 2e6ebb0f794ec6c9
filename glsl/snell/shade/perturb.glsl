/*
description: Sousa's screen-space refraction, basic form: perturb the projected
  uv of the refracting pixel by a normal map's xy scaled by a small value, then
  read the scene colour (rendered without the refractive meshes) there.
use: vec3 bump = snellUnpackBump(vec3(t.x, t.y, t.z));      // t: normal-map texel
     vec2 uvP = snellPerturbUv(uv, vec2(bump.x, bump.y), 0.05f);
     vec2 uvP = snellPerturbUv(uv, vec2(bump.x, bump.y));   // scale SNELL_PERTURB_SCALE
     vec4 c = snellPerturbSample(sceneColor, uv, vec2(bump.x, bump.y), 0.05f);
  uv          projected viewport uv of the fragment (screenPos.xy / screenPos.w of
              the listing; e.g. snellPixelToUv(gl_FragCoord) or snellViewToUv)
  bump        the normal map's xy, unpacked to [-1, 1]
  scale       displacement per unit of bump, in uv units
  sceneColor  texture S: the scene without the refractive meshes (SNELL_TEX2D),
              read at mip level 0 with its own filter
options:
  SNELL_PERTURB_SCALE  default scale (0.05f, the value the chapter suggests)
contract:
  - snellUnpackBump(t) = 2 t - 1 (the listing's 2.0 * tex2D(..) - 1.0), nothing
    else: NaN propagates.
  - snellPerturbUv(uv, bump, scale) = uv + scale * bump (component-wise), with:
    a NaN or infinite uv component replaced by 0.5 (screen centre); a NaN or
    infinite displacement component scale * bump replaced by 0 (no
    perturbation); the sum clamped to [-SNELL_FLT_MAX, SNELL_FLT_MAX]. Off-screen
    results (outside [0,1]) are returned as they are: finite, never NaN.
  - snellPerturbSample reads sceneColor at snellPerturbUv(..) clamped to [0,1]^2
    (explicit clamp-to-edge, so the result does not depend on the sampler's
    wrap mode), lod 0.
source: T. Sousa, "Generic Refraction Simulation", GPU Gems 2, ch. 19 (2005),
  sec. 19.1 and Example 19-1 (newUV = screenPos.xy / screenPos.w + bumpTex.xy *
  vScale.xy).
*/
#ifndef SNELL_SHADE_PERTURB_GLSL
#define SNELL_SHADE_PERTURB_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"

#ifndef SNELL_PERTURB_SCALE
#  define SNELL_PERTURB_SCALE 0.05f
#endif

SNELL_FN vec3 snellUnpackBump(vec3 texel) {
  return texel * 2.0f - 1.0f;
}

SNELL_FN vec2 snellPerturbUv(vec2 uv, vec2 bump, float scale) {
  float u = SNELL_FINITE(uv.x) ? uv.x : 0.5f;
  float v = SNELL_FINITE(uv.y) ? uv.y : 0.5f;
  float du = scale * bump.x;
  float dv = scale * bump.y;
  du = SNELL_FINITE(du) ? du : 0.0f;
  dv = SNELL_FINITE(dv) ? dv : 0.0f;
  return clamp(vec2(u + du, v + dv), vec2(-SNELL_FLT_MAX, -SNELL_FLT_MAX), vec2(SNELL_FLT_MAX, SNELL_FLT_MAX));
}

SNELL_FN vec2 snellPerturbUv(vec2 uv, vec2 bump) {
  return snellPerturbUv(uv, bump, SNELL_PERTURB_SCALE);
}

SNELL_FN vec4 snellPerturbSample(SNELL_TEX2D sceneColor, vec2 uv, vec2 bump, float scale) {
  vec2 p = clamp(snellPerturbUv(uv, bump, scale), vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
  return SNELL_SAMPLE_LOD(sceneColor, p, 0.0f);
}

#endif
