/*
description: normalize that never produces NaN or infinity.
use: vec3 n = snellSafeNormalize(v);
options: -
contract: returns v / |v| when every component is finite and |v|^2 is a normal
  float above 1e-30 and below FLT_MAX; otherwise (0,0,0) (zero, denormal-small,
  NaN, infinite, or so large that |v|^2 overflows). Callers test dot(n, n) == 0
  for "invalid".
source: -
*/
#ifndef SNELL_OPTICS_SAFE_NORMALIZE_GLSL
#define SNELL_OPTICS_SAFE_NORMALIZE_GLSL
#include "../prelude.glsl"

SNELL_FN vec3 snellSafeNormalize(vec3 v) {
  float len2 = dot(v, v);
  // NaN fails every comparison; an infinite component makes len2 infinite.
  if (!(len2 > 1e-30f) || !(len2 < SNELL_FLT_MAX)) {
    return vec3(0.0f, 0.0f, 0.0f);
  }
  return v * inversesqrt(len2);
}

#endif
