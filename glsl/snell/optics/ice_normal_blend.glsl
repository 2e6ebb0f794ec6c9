/*
description: two-sided refraction on the cheap: blend the front-face normal
  with the (negated) back-face normal, then refract once with the result
  instead of refracting at both interfaces. Not physically correct; fine for
  strongly distorting materials such as ice.
use: vec3 nr = snellIceNormalBlend(frontNormal, backNormal, a);
     vec3 nr = snellIceNormalBlend(frontNormal, backNormal);  // a = SNELL_ICE_NORMAL_BLEND
     then snellRefract(eye, nr, eta, policy) (the paper's equation 2).
  frontNormal  outward normal of the front face at the pixel
  backNormal   outward normal of the back face at the pixel, as stored by a
               back-face normal pass (it points away from the viewer; the
               equation negates it). Neither needs to be normalized.
  a            share of the back-face normal in [0, 1]
options:
  SNELL_ICE_NORMAL_BLEND  default a (0.33f, the value used in the paper)
contract:
  - returns normalize((1 - a) nf - a nb) with nf, nb the normalized inputs: a
    unit vector, or (0,0,0) when frontNormal is invalid;
  - a is clamped to [0, 1]; a NaN a uses SNELL_ICE_NORMAL_BLEND;
  - a = 0 returns nf; a = 1 returns -nb;
  - frontNormal zero, denormal-small, NaN or infinite: (0,0,0);
  - backNormal invalid (same tests): nf (one-sided refraction);
  - the blend vanishes (nb = nf with a = 0.5, or a direction lost to
    cancellation): nf.
source: "Real-Time Ice Rendering", sec. 3.2, equation 1,
  n_r = (1 - a) n_f - a n_b, a = 0.33.
*/
#ifndef SNELL_OPTICS_ICE_NORMAL_BLEND_GLSL
#define SNELL_OPTICS_ICE_NORMAL_BLEND_GLSL
#include "../prelude.glsl"
#include "safe_normalize.glsl"

#ifndef SNELL_ICE_NORMAL_BLEND
#  define SNELL_ICE_NORMAL_BLEND 0.33f
#endif

SNELL_FN vec3 snellIceNormalBlend(vec3 frontNormal, vec3 backNormal, float a) {
  vec3 nf = snellSafeNormalize(frontNormal);
  if (dot(nf, nf) == 0.0f) {
    return vec3(0.0f, 0.0f, 0.0f);
  }
  vec3 nb = snellSafeNormalize(backNormal);
  if (dot(nb, nb) == 0.0f) {
    return nf;
  }
  // Comparisons rather than clamp(): clamp() of a NaN is undefined in GLSL.
  float w = a >= 0.0f ? min(a, 1.0f) : (a < 0.0f ? 0.0f : SNELL_ICE_NORMAL_BLEND);
  vec3 r = snellSafeNormalize((1.0f - w) * nf - w * nb);
  if (dot(r, r) == 0.0f) {
    return nf;
  }
  return r;
}

SNELL_FN vec3 snellIceNormalBlend(vec3 frontNormal, vec3 backNormal) {
  return snellIceNormalBlend(frontNormal, backNormal, SNELL_ICE_NORMAL_BLEND);
}

#endif
