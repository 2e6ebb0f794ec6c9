/*
description: relative index of refraction eta = n_incident / n_transmitted, the
  eta that snellRefract and snellFresnelDielectric take.
use: float eta = snellIorToEta(1.0f, 1.5f);  // air into glass: 0.6667
  iorIncident     absolute IOR of the medium the ray travels in
  iorTransmitted  absolute IOR of the medium it enters
options: -
contract:
  - either IOR NaN, below 1e-30 (zero, negative, denormal: GPUs may flush
    denormals to 0, so they cannot count as valid) or +inf: returns 1 (no
    bending, no reflection: the interface is ignored);
  - otherwise iorIncident / iorTransmitted clamped to [1e-6, 1e6] (finite,
    positive, and far outside any physical ratio), so the result is always a
    valid eta for snellRefract.
source: Snell's law n_1 sin(theta_1) = n_2 sin(theta_2) (G. Oliveira 2000,
  Equation 7), so sin(theta_2) = (n_1 / n_2) sin(theta_1).
*/
#ifndef SNELL_OPTICS_IOR_TO_ETA_GLSL
#define SNELL_OPTICS_IOR_TO_ETA_GLSL
#include "../prelude.glsl"

SNELL_FN float snellIorToEta(float iorIncident, float iorTransmitted) {
  if (!(iorIncident >= 1e-30f) || !(iorIncident < SNELL_FLT_MAX) || !(iorTransmitted >= 1e-30f) ||
      !(iorTransmitted < SNELL_FLT_MAX)) {
    return 1.0f;
  }
  return min(max(iorIncident / iorTransmitted, 1e-6f), 1e6f);
}

#endif
