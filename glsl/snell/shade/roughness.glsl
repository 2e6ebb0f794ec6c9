/*
description: surface roughness -> mip level of the scene-colour texture, for
  blurred (frosted) refraction: read S with SNELL_SAMPLE_LOD at this level of
  a mipmapped (ideally pre-blurred) chain. A fixed share of the chain per
  roughness, whatever the distances and the resolution: the composed
  technique blurs by the cone of light instead (shade/rough_cone.glsl: the
  same width in the world at every resolution, measured closer to a rough
  ray trace); this mapping suits a host without the path's lengths.
use: float lod = snellRoughnessToLod(perceptualRoughness, levelCount);
     vec4 c = SNELL_SAMPLE_LOD(sceneColor, uvRefracted, lod);
  roughness  perceptual roughness in [0, 1] (0 smooth, 1 fully rough)
  levels     number of mip levels of the texture (base level included), e.g.
             floor(log2(max(width, height))) + 1 for a full chain
options: -
contract:
  - lod = (levels - 1) r (2 - r) = (levels - 1) (1 - (1 - r)^2) with r = roughness clamped to [0, 1]: 0 at
    r = 0, levels - 1 at r = 1, monotone non-decreasing in r, always in
    [0, levels - 1] (finite);
  - a NaN roughness counts as 0 (sharp); levels <= 1 gives 0.
source: the quadratic fit of log2(roughness) + level used for prefiltered
  environment maps in Google Filament (perceptualRoughnessToLod: lod =
  iblRoughnessOneLevel * r * (2 - r), with the roughness-one level being the
  last mip level), applied here to the scene-colour mip chain.
*/
#ifndef SNELL_SHADE_ROUGHNESS_GLSL
#define SNELL_SHADE_ROUGHNESS_GLSL
#include "../prelude.glsl"

SNELL_FN float snellRoughnessToLod(float roughness, int levels) {
  if (levels <= 1) {
    return 0.0f;
  }
  // isnan first: clamp of a NaN differs between GPUs and GLM.
  float r = isnan(roughness) ? 0.0f : clamp(roughness, 0.0f, 1.0f);
  float top = float(levels - 1);
  // r (2 - r) written as 1 - (1 - r)^2: the same value, but every step is
  // monotone, so the rounded result is too (r * (2 - r) is not near r = 1).
  float m = 1.0f - r;
  return min(top * (1.0f - m * m), top);
}

#endif
