/*
description: Sousa's stained glass: environment bump mapping with a 2D
  reflection map, the masked screen-space refraction of S modulated by the
  diffuse (stain) colour, blended by a bias/power Fresnel term.
use: vec4 c = snellGlass(sceneColor, reflectionMap, uv, bumpTexel, diffuse, eyeTs);
  sceneColor     texture S: the scene without the glass, refraction mask in
                 alpha (glass written as 0, the rest 1; see refraction_mask.glsl)
  reflectionMap  2D environment map indexed by the reflection vector's xy
  uv             projected viewport uv of the fragment (ScreenPos.xy / ScreenPos.w)
  bumpTexel      the bump map's texel at the base uv (rgb in [0,1], unpacked here)
  diffuse        the diffuse (stain) texture's texel at the base uv
  eye            fragment-to-eye vector in the bump map's tangent space (z up);
                 need not be unit
options:
  SNELL_GLASS_BUMP_SCALE     xy scale of the unpacked bump before normalizing (0.2f)
  SNELL_GLASS_FRESNEL_BIAS   snellFresnelBiasPower bias (0.4f)
  SNELL_GLASS_FRESNEL_POWER  snellFresnelBiasPower power (5.0f)
contract (Example 19-5, s = SNELL_GLASS_BUMP_SCALE):
  - b = normalize((2 bumpTexel - 1) * (s, s, 1)), (0,0,1) when that vanishes or
    is not finite; e = normalize(eye), (0,0,0) when eye is zero, NaN or infinite;
  - LdotN = dot(b, e) (0 when NaN); r = 2 LdotN b - e;
    env = reflectionMap((r.xy + 1) * 0.5);
  - refraction = snellRefractionMaskBlend(S(uv + b.xy), S(uv));
  - F = snellFresnelBiasPower(LdotN, bias, power) (LdotN saturated there);
  - tint = (saturate(0.1 + 0.9 diffuse.rgb), diffuse.a), a NaN diffuse.rgb
    channel counting as 1 (clear);
  - result = tint * refraction * (1 - F) + env * F (all four channels).
  Reads use snellPerturbUv (NaN uv -> screen centre) clamped to [0,1]^2, lod 0;
  an invalid eye gives F = 1 and the reflection map's centre. Other colours
  (texels, diffuse.a) are used as given.
source: T. Sousa, "Generic Refraction Simulation", GPU Gems 2, ch. 19 (2005),
  sec. 19.3.2, Example 19-5 (Fresnel(LdotN, 0.4, 5.0) of Example 19-3).
*/
#ifndef SNELL_SHADE_GLASS_GLSL
#define SNELL_SHADE_GLASS_GLSL
#include "../prelude.glsl"
#include "../optics/safe_normalize.glsl"
#include "../optics/fresnel_bias_power.glsl"
#include "perturb.glsl"
#include "refraction_mask.glsl"

#ifndef SNELL_GLASS_BUMP_SCALE
#  define SNELL_GLASS_BUMP_SCALE 0.2f
#endif
#ifndef SNELL_GLASS_FRESNEL_BIAS
#  define SNELL_GLASS_FRESNEL_BIAS 0.4f
#endif
#ifndef SNELL_GLASS_FRESNEL_POWER
#  define SNELL_GLASS_FRESNEL_POWER 5.0f
#endif

SNELL_FN vec4 snellGlass(SNELL_TEX2D sceneColor, SNELL_TEX2D reflectionMap, vec2 uv, vec3 bumpTexel, vec4 diffuse,
                         vec3 eye) {
  vec3 b = snellSafeNormalize(snellUnpackBump(bumpTexel) *
                              vec3(SNELL_GLASS_BUMP_SCALE, SNELL_GLASS_BUMP_SCALE, 1.0f));
  if (dot(b, b) == 0.0f) {
    b = vec3(0.0f, 0.0f, 1.0f);
  }
  vec3 e = snellSafeNormalize(eye);
  float lDotN = dot(b, e);
  lDotN = isnan(lDotN) ? 0.0f : lDotN;
  vec3 r = b * (2.0f * lDotN) - e;
  vec2 one = vec2(1.0f, 1.0f);
  vec2 zero = vec2(0.0f, 0.0f);
  vec2 uvEnv = clamp((vec2(r.x, r.y) + 1.0f) * 0.5f, zero, one);
  vec4 env = SNELL_SAMPLE_LOD(reflectionMap, uvEnv, 0.0f);
  vec2 uvRefr = clamp(snellPerturbUv(uv, vec2(b.x, b.y), 1.0f), zero, one);
  vec2 uvProj = clamp(snellPerturbUv(uv, zero, 0.0f), zero, one);
  vec4 refraction =
      snellRefractionMaskBlend(SNELL_SAMPLE_LOD(sceneColor, uvRefr, 0.0f), SNELL_SAMPLE_LOD(sceneColor, uvProj, 0.0f));
  float f = snellFresnelBiasPower(lDotN, SNELL_GLASS_FRESNEL_BIAS, SNELL_GLASS_FRESNEL_POWER);
  // isnan first: clamp of a NaN differs between GPUs and GLM.
  vec3 d = vec3(isnan(diffuse.x) ? 1.0f : diffuse.x, isnan(diffuse.y) ? 1.0f : diffuse.y,
                isnan(diffuse.z) ? 1.0f : diffuse.z);
  vec3 t = clamp(d * 0.9f + 0.1f, vec3(0.0f, 0.0f, 0.0f), vec3(1.0f, 1.0f, 1.0f));
  vec4 tint = vec4(t.x, t.y, t.z, diffuse.w);
  return tint * refraction * (1.0f - f) + env * f;
}

#endif
