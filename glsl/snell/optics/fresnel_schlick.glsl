/*
description: Schlick's approximation of the Fresnel reflectance,
  F = f0 + (1 - f0) (1 - cos_i)^5.
use: float F = snellFresnelSchlick(cosI, f0);
  cosI  cosine of the angle between the incident ray and the normal; its sign
        is ignored
  f0    reflectance at normal incidence, e.g. snellIorToF0(1.0f, 1.5f) = 0.04f
  Leaving a denser medium (n_i > n_t) Schlick knows nothing about TIR: pass the
  cosine of the transmitted angle there, or use snellFresnelDielectric.
options: -
contract:
  - result in [f0, 1] (so in [0, 1]); never NaN;
  - |cosI| is clamped to [0, 1]; a NaN cosI is treated as 0 (grazing): 1;
  - f0 is clamped to [0, 1]; a NaN f0 is treated as 1 (result 1);
  - the fifth power is written as multiplications (no pow), so GLSL, HLSL and
    C++ round it identically.
source: C. Schlick, "An Inexpensive BRDF Model for Physically-based
  Rendering", Computer Graphics Forum 13(3), 1994, eq. 24.
*/
#ifndef SNELL_OPTICS_FRESNEL_SCHLICK_GLSL
#define SNELL_OPTICS_FRESNEL_SCHLICK_GLSL
#include "../prelude.glsl"

SNELL_FN float snellFresnelSchlick(float cosI, float f0) {
  float c = abs(cosI);
  // NaN: grazing, result 1. Tested before min(): GPUs return 1 for min(NaN, 1)
  // (llvmpipe), GLM returns NaN; and not as `c > 0 ? .. : 0`, which compilers
  // rewrite as cosI != 0, true for NaN.
  if (!(c >= 0.0f)) {
    return 1.0f;
  }
  c = min(c, 1.0f);
  // Comparisons rather than clamp(): clamp() of a NaN is undefined in GLSL.
  float f = f0 > 0.0f ? min(f0, 1.0f) : (f0 <= 0.0f ? 0.0f : 1.0f);
  float m = 1.0f - c;
  float m2 = m * m;
  return f + (1.0f - f) * (m2 * m2 * m);
}

#endif
