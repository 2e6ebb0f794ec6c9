/*
description: Sousa's refraction mask: S's alpha is cleared to white (1) and the
  refractive meshes are written black (0) into it, so a perturbed read that
  leaves the refractive object's screen area (for example onto an occluder in
  front of it) is replaced by the unperturbed read.
use: vec4 c = snellRefractionMaskBlend(refrA, refrB);
     vec4 c = snellRefractionMasked(sceneColor, uv, vec2(bump.x, bump.y), 0.05f);
  refrA       S read at the perturbed uv (its alpha is the mask there)
  refrB       S read at the unperturbed uv
  sceneColor, uv, bump, scale  as in snellPerturbSample (perturb.glsl)
options: -
contract:
  - snellRefractionMaskBlend = refrB * w + (refrA.rgb, w) * (1 - w) with w =
    refrA.w clamped to [0, 1] (Example 19-2's vRefrB * vRefrA.w + vRefrA * (1 -
    vRefrA.w), identical for a mask in [0, 1], the result's alpha included);
    alpha 1 (outside every refractive mesh) gives refrB, alpha 0 (inside)
    gives refrA. A NaN alpha counts as 1 (unperturbed). Colours are blended
    as given (NaN colours propagate).
  - snellRefractionMasked reads S at snellPerturbUv(uv, bump, scale) and at uv,
    both clamped to [0,1]^2 (a NaN or infinite uv component reads the screen
    centre, as in snellPerturbUv), lod 0, and blends them as above.
source: T. Sousa, "Generic Refraction Simulation", GPU Gems 2, ch. 19 (2005),
  sec. 19.2 and Example 19-2.
*/
#ifndef SNELL_SHADE_REFRACTION_MASK_GLSL
#define SNELL_SHADE_REFRACTION_MASK_GLSL
#include "../prelude.glsl"
#include "perturb.glsl"

SNELL_FN vec4 snellRefractionMaskBlend(vec4 refrA, vec4 refrB) {
  // isnan first: min/max/clamp of a NaN differ between GPUs and GLM.
  float w = isnan(refrA.w) ? 1.0f : clamp(refrA.w, 0.0f, 1.0f);
  return refrB * w + vec4(refrA.x, refrA.y, refrA.z, w) * (1.0f - w);
}

SNELL_FN vec4 snellRefractionMasked(SNELL_TEX2D sceneColor, vec2 uv, vec2 bump, float scale) {
  vec2 uvA = clamp(snellPerturbUv(uv, bump, scale), vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
  vec2 uvB = clamp(snellPerturbUv(uv, vec2(0.0f, 0.0f), 0.0f), vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
  vec4 refrA = SNELL_SAMPLE_LOD(sceneColor, uvA, 0.0f);
  vec4 refrB = SNELL_SAMPLE_LOD(sceneColor, uvB, 0.0f);
  return snellRefractionMaskBlend(refrA, refrB);
}

#endif
