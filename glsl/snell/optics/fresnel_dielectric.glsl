/*
description: exact Fresnel reflectance of a smooth dielectric interface for
  unpolarized light: the average of the s- and p-polarized reflectances, 1
  under total internal reflection.
use: float F = snellFresnelDielectric(cosI, eta);
  cosI  cosine of the angle between the incident ray and the normal; its sign
        is ignored (either orientation of the normal works)
  eta   n_incident / n_transmitted (1.0f / 1.5f entering glass from air);
        snellIorToEta(nI, nT) builds it
options: -
contract:
  - result in [0, 1]; never NaN;
  - |cosI| is clamped to [0, 1]; a NaN cosI is treated as 0 (grazing), so the
    result is 1;
  - TIR (eta^2 (1 - cos_i^2) >= 1, evaluated as cos_t^2 = (1 - eta^2) +
    eta^2 cos_i^2 <= 0, as in snellRefract) gives exactly 1; at sin_t = 1 the formula's
    limit is 1 as well, so the switch is continuous;
  - eta NaN, below 1e-30 (zero, negative, denormal: GPUs may flush them) or
    +inf gives 1 (treated as an opaque mirror: nothing is
    transmitted); finite positive eta is clamped to [1e-6, 1e6], far outside
    any physical ratio, so that no product overflows;
  - eta = 1 gives 0 except at grazing incidence (cosI = 0), where it is 1
    (the TIR branch: sin_t = 1).
source: Fresnel equations for dielectrics (e.g. Born & Wolf, Principles of
  Optics, sec. 1.5.2; Pharr, Jakob & Humphreys, PBRT 3rd ed., sec. 8.2.1):
  r_s = (eta cos_i - cos_t) / (eta cos_i + cos_t),
  r_p = (cos_i - eta cos_t) / (cos_i + eta cos_t),
  F = (r_s^2 + r_p^2) / 2, cos_t = sqrt(1 - eta^2 (1 - cos_i^2)),
  written with eta = n_i / n_t (each ratio divided through by n_t).
*/
#ifndef SNELL_OPTICS_FRESNEL_DIELECTRIC_GLSL
#define SNELL_OPTICS_FRESNEL_DIELECTRIC_GLSL
#include "../prelude.glsl"

SNELL_FN float snellFresnelDielectric(float cosI, float eta) {
  // Comparisons are false for NaN; eta < FLT_MAX is false for +inf.
  if (!(eta >= 1e-30f) || !(eta < SNELL_FLT_MAX)) {
    return 1.0f;
  }
  float e = min(max(eta, 1e-6f), 1e6f);
  float c = abs(cosI);
  // NaN: grazing. Tested before min(): GPUs return 1 for min(NaN, 1) (llvmpipe),
  // GLM returns NaN; and not as `c > 0 ? .. : 0`, which compilers rewrite as
  // cosI != 0, true for NaN.
  if (!(c >= 0.0f)) {
    return 1.0f;
  }
  c = min(c, 1.0f);
  // cos_t^2 = 1 - eta^2 (1 - cos_i^2), as (1 - eta^2) + eta^2 cos_i^2 (exact for
  // eta = 1, accurate at grazing incidence), the same form as snellRefract.
  float e2 = e * e;
  float cos2T = (1.0f - e2) + e2 * (c * c);
  if (cos2T <= 0.0f) {
    return 1.0f;
  }
  float cosT = sqrt(cos2T);  // > 0 here, so no denominator vanishes
  float rs = (e * c - cosT) / (e * c + cosT);
  float rp = (c - e * cosT) / (c + e * cosT);
  return 0.5f * (rs * rs + rp * rp);
}

#endif
