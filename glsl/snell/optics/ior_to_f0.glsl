/*
description: reflectance at normal incidence from two indices of refraction,
  f0 = ((n1 - n2) / (n1 + n2))^2 (0.04 for air/glass 1.5), the f0 of
  snellFresnelSchlick.
use: float f0 = snellIorToF0(1.0f, 1.5f);
options: -
contract:
  - exactly symmetric in its arguments; result in [0, 1];
  - evaluated as ((n1/2 - n2/2) / (n1/2 + n2/2))^2: halving is exact, keeps the
    sum from overflowing, and the difference of close IORs stays exact (a form
    through eta = n1 / n2 would lose digits there);
  - either IOR invalid for snellIorToEta (NaN, below 1e-30, +inf): 0 (no
    reflection), matching snellIorToEta's eta = 1.
source: normal-incidence limit of the Fresnel equations (cos_i = cos_t = 1 in
  r_s, r_p); Schlick 1994, eq. 24's f0.
*/
#ifndef SNELL_OPTICS_IOR_TO_F0_GLSL
#define SNELL_OPTICS_IOR_TO_F0_GLSL
#include "../prelude.glsl"

SNELL_FN float snellIorToF0(float iorIncident, float iorTransmitted) {
  if (!(iorIncident >= 1e-30f) || !(iorIncident < SNELL_FLT_MAX) || !(iorTransmitted >= 1e-30f) ||
      !(iorTransmitted < SNELL_FLT_MAX)) {
    return 0.0f;
  }
  float a = 0.5f * iorIncident;
  float b = 0.5f * iorTransmitted;
  float r = (a - b) / (a + b);
  return r * r;
}

#endif
