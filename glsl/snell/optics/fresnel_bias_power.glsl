/*
description: Sousa's artist-tuned Fresnel term for water and glass,
  max(bias + (1 - bias) (1 - N.L)^power, 0).
use: float F = snellFresnelBiasPower(nDotL, bias, power);
  nDotL  cosine between the unit normal and the unit vector towards the eye
         (Sousa: NdotL = max(dot(vEye, vReflBump), 0))
  bias   reflectance at normal incidence (Sousa: 0.2 water, 0.4 glass)
  power  falloff exponent (Sousa: 5.0 for both)
options: -
contract:
  - nDotL is saturated to [0, 1] as the water listing does with max(.., 0) (and
    the upper clamp keeps pow() off a negative base); a NaN nDotL is treated
    as 0 (facing = 1);
  - power is clamped to [0, 1e6]; power below 1e-30 (0, negative, denormal)
    or NaN makes the pow term exactly 1 (x^0 = 1; GLSL leaves pow(0, 0) undefined); a base of exactly 0
    with power > 0 gives 0 without calling pow;
  - bias is clamped to [-1e6, 1e6]; a NaN bias is treated as 1;
  - result = max(bias + (1 - bias) t, 0) with t in [0, 1]: in [bias, 1] for
    bias in [0, 1]; Sousa's formula does not cap bias > 1 and neither does
    this; never NaN or infinite.
source: T. Sousa, "Generic Refraction Simulation", GPU Gems 2, ch. 19 (2005),
  Example 19-3 (Fresnel(NdotL, fresnelBias, fresnelPow)), used with
  (0.2, 5.0) in Example 19-4 (water) and (0.4, 5.0) in Example 19-5 (glass).
*/
#ifndef SNELL_OPTICS_FRESNEL_BIAS_POWER_GLSL
#define SNELL_OPTICS_FRESNEL_BIAS_POWER_GLSL
#include "../prelude.glsl"

SNELL_FN float snellFresnelBiasPower(float nDotL, float bias, float power) {
  // Comparisons rather than clamp()/max(): they are undefined for NaN in GLSL.
  float c = nDotL > 0.0f ? min(nDotL, 1.0f) : 0.0f;
  float facing = 1.0f - c;
  // Below 1e-30 counts as 0: GPUs may flush denormals, and pow(0, tiny) is 0.
  float p = power >= 1e-30f ? min(power, 1e6f) : 0.0f;
  float b = bias >= -1e6f ? min(bias, 1e6f) : (bias < 0.0f ? -1e6f : 1.0f);
  float t = 1.0f;
  if (p > 0.0f) {
    t = facing > 0.0f ? pow(facing, p) : 0.0f;
  }
  return max(b + (1.0f - b) * t, 0.0f);
}

#endif
