/*
description: Sousa's refractive/reflective water in one pass: four animated
  bump layers averaged into one normal, the masked screen-space refraction of
  S, a planar reflection map read at a (less) perturbed uv, a per-pixel
  bias/power Fresnel term, and the deep-water colour blended in by distance.
use: SnellWaterParams p = snellWaterParams();   // the chapter's constants
     vec3 n = snellWaterBumpAverage(t0, t1, t2, t3);   // four bump texels, [0,1]
     vec4 c = snellWater(sceneColor, reflectionMap, uv, n, eyeTs, viewDistance, p);
  With refraction read your own way (for example the depth-aware mask of
  refraction_mask_depth.glsl instead of the alpha mask), compose the two reads:
     vec4 c = snellWaterCompose(reflection, refraction, n, eyeTs, viewDistance, p);
  t0..t3         the bump map read at the four wave coordinates (rgb, [0,1])
  sceneColor     texture S: the scene without the water, refraction mask in
                 alpha (water written as 0, the rest 1; see refraction_mask.glsl)
  reflectionMap  the scene mirrored through the water plane
  uv             projected viewport uv of the fragment (ScreenPos.xy / ScreenPos.w)
  bumpNormal     the averaged bump normal, tangent space (z up); need not be unit
  eye            fragment-to-eye vector in the same tangent space (the
                 listing's Eye); need not be unit
  viewDistance   the listing's Wave0.w: the fragment's distance from the eye
  reflection, refraction  (snellWaterCompose) the reflection map and scene
                 colours as read; snellWater reads them as described below
options: -
contract:
  SnellWaterParams fields (snellWaterParams() defaults, Example 19-4):
    refractionBumpScale (0.075, 0.075, 1)  bump scale for the refraction read
    reflectionBumpScale (0.02, 0.02, 1)    bump scale for the reflection read and
                                           the Fresnel term
    fresnelBias 0.2, fresnelPower 5        snellFresnelBiasPower (Example 19-3)
    deepDistance 10                        fDistScale = saturate(10 / Wave0.w)
    waterColor (0, 0.15, 0.115)            colour blended in by facing
    deepColor (0, 0.15, 0.115)             colour blended in by distance
  - snellWaterBumpAverage = normalize(2 (t0 + t1 + t2 + t3) - 4) (the average of
    the four unpacked normals, normalized); (0,0,1) when that vanishes or is not
    finite.
  - snellWater computes, with n = normalize(bumpNormal) ((0,0,1) when bumpNormal
    is zero, NaN or infinite), e = normalize(eye) ((0,0,0) likewise):
      refrBump = n * refractionBumpScale, reflBump = n * reflectionBumpScale
      reflection = reflectionMap(uv + reflBump.xy)
      refraction = snellRefractionMaskBlend(S(uv + refrBump.xy), S(uv))
      NdotL = saturate(dot(e, reflBump)) (0 when NaN), facing = 1 - NdotL
      fresnel = snellFresnelBiasPower(NdotL, fresnelBias, fresnelPower)
      fDist = saturate(deepDistance / viewDistance); 1 when viewDistance is
              NaN, <= 0 or denormal, or the quotient is NaN
      deep = refraction.rgb fDist + (1 - fDist) deepColor
      water = waterColor facing + deep (1 - facing)
      result = vec4(fresnel reflection.rgb + water, 1)
  - snellWaterCompose(reflection, refraction, bumpNormal, eye, viewDistance, p)
    is everything above after the two reads (n, e, reflBump, NdotL, fresnel,
    fDist, deep, water, result), with the given colours; snellWater returns
    snellWaterCompose of its own reads.
    Reads use snellPerturbUv (NaN uv -> screen centre, NaN displacement -> 0),
    clamped to [0,1]^2, lod 0. reflBump is not renormalized, as in the listing.
    Colours (parameters and texels) are used as given.
source: T. Sousa, "Generic Refraction Simulation", GPU Gems 2, ch. 19 (2005),
  sec. 19.3.1, Examples 19-3 and 19-4.
*/
#ifndef SNELL_SHADE_WATER_GLSL
#define SNELL_SHADE_WATER_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"
#include "../optics/safe_normalize.glsl"
#include "../optics/fresnel_bias_power.glsl"
#include "perturb.glsl"
#include "refraction_mask.glsl"

struct SnellWaterParams {
  vec3 refractionBumpScale;
  vec3 reflectionBumpScale;
  float fresnelBias;
  float fresnelPower;
  float deepDistance;
  vec3 waterColor;
  vec3 deepColor;
};

SNELL_FN SnellWaterParams snellWaterParams() {
  SnellWaterParams p;
  p.refractionBumpScale = vec3(0.075f, 0.075f, 1.0f);
  p.reflectionBumpScale = vec3(0.02f, 0.02f, 1.0f);
  p.fresnelBias = 0.2f;
  p.fresnelPower = 5.0f;
  p.deepDistance = 10.0f;
  p.waterColor = vec3(0.0f, 0.15f, 0.115f);
  p.deepColor = vec3(0.0f, 0.15f, 0.115f);
  return p;
}

SNELL_FN vec3 snellWaterBumpAverage(vec3 t0, vec3 t1, vec3 t2, vec3 t3) {
  vec3 n = snellSafeNormalize((t0 + t1 + t2 + t3) * 2.0f - 4.0f);
  if (dot(n, n) == 0.0f) {
    return vec3(0.0f, 0.0f, 1.0f);
  }
  return n;
}

SNELL_FN vec4 snellWaterCompose(vec4 reflection, vec4 refraction, vec3 bumpNormal, vec3 eye, float viewDistance,
                                SnellWaterParams p) {
  vec3 n = snellSafeNormalize(bumpNormal);
  if (dot(n, n) == 0.0f) {
    n = vec3(0.0f, 0.0f, 1.0f);
  }
  vec3 e = snellSafeNormalize(eye);
  vec3 reflBump = n * p.reflectionBumpScale;
  // isnan first: min/max/clamp of a NaN differ between GPUs and GLM.
  float nDotL = dot(e, reflBump);
  nDotL = isnan(nDotL) ? 0.0f : clamp(nDotL, 0.0f, 1.0f);
  float facing = 1.0f - nDotL;
  float fresnel = snellFresnelBiasPower(nDotL, p.fresnelBias, p.fresnelPower);
  float distScale = 1.0f;
  if (!isnan(viewDistance) && viewDistance >= SNELL_FLT_MIN) {
    float q = p.deepDistance / viewDistance;
    distScale = isnan(q) ? 1.0f : clamp(q, 0.0f, 1.0f);
  }
  vec3 refr = vec3(refraction.x, refraction.y, refraction.z);
  vec3 deep = refr * distScale + p.deepColor * (1.0f - distScale);
  vec3 water = p.waterColor * facing + deep * (1.0f - facing);
  vec3 c = vec3(reflection.x, reflection.y, reflection.z) * fresnel + water;
  return vec4(c.x, c.y, c.z, 1.0f);
}

SNELL_FN vec4 snellWater(SNELL_TEX2D sceneColor, SNELL_TEX2D reflectionMap, vec2 uv, vec3 bumpNormal, vec3 eye,
                         float viewDistance, SnellWaterParams p) {
  vec3 n = snellSafeNormalize(bumpNormal);
  if (dot(n, n) == 0.0f) {
    n = vec3(0.0f, 0.0f, 1.0f);
  }
  vec3 refrBump = n * p.refractionBumpScale;
  vec3 reflBump = n * p.reflectionBumpScale;
  vec2 one = vec2(1.0f, 1.0f);
  vec2 zero = vec2(0.0f, 0.0f);
  vec2 uvRefl = clamp(snellPerturbUv(uv, vec2(reflBump.x, reflBump.y), 1.0f), zero, one);
  vec2 uvRefr = clamp(snellPerturbUv(uv, vec2(refrBump.x, refrBump.y), 1.0f), zero, one);
  vec2 uvProj = clamp(snellPerturbUv(uv, zero, 0.0f), zero, one);
  vec4 reflection = SNELL_SAMPLE_LOD(reflectionMap, uvRefl, 0.0f);
  vec4 refrA = SNELL_SAMPLE_LOD(sceneColor, uvRefr, 0.0f);
  vec4 refrB = SNELL_SAMPLE_LOD(sceneColor, uvProj, 0.0f);
  return snellWaterCompose(reflection, snellRefractionMaskBlend(refrA, refrB), bumpNormal, eye, viewDistance, p);
}

#endif
