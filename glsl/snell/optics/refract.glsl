/*
description: Snell refraction of a direction at an interface, with an explicit
  policy for total internal reflection (TIR).
use: SnellRefraction r = snellRefract(incident, normal, eta, SNELL_TIR_CRITICAL);
  incident  direction of travel towards the surface (need not be normalized)
  normal    surface normal (need not be normalized); flipped to face the
            incident ray when it points away from it
  eta       n_incident / n_transmitted (1.0f / 1.5f entering glass from air)
  policy    SNELL_TIR_ZERO      direction (0,0,0) on TIR, as GLSL refract()
            SNELL_TIR_CRITICAL  transmission angle clamped to the critical angle:
                                the ray tangent to the surface (Wyman 2005,
                                Oliveira & Brauwers 2007 sec. 5)
            SNELL_TIR_REFLECT   mirror reflection on TIR
contract:
  - r.direction is unit length, or (0,0,0) exactly when r.valid is false or
    (TIR and SNELL_TIR_ZERO);
  - r.tir is true when eta^2 (1 - cos_i^2) > 1, evaluated as
    (1 - eta^2) + eta^2 cos_i^2 < 0 for eta < 8 (every pair of real
    materials), and as eta |i + cos_i n| > 1 from 8 up (so normal incidence
    never reflects): there the first form loses about eta^2 2^-23 of
    cos_t^2 to the rounding of cos_i, and past 4096 1 - eta^2 itself rounds;
  - eta = 1 returns the normalized incident direction (up to rounding);
  - r.valid is false (direction 0, tir false) when incident or normal is zero,
    denormal-small, NaN or infinite, or eta is not a finite positive normal
    number (a denormal eta counts as 0, the prelude's rule: a runtime that
    flushes denormals, SwiftShader's WebGL 2 among them, sees 0 there);
  - at normal incidence under CRITICAL the tangent is undefined, but TIR cannot
    happen there (sin_i = 0), so the case does not arise.
source: Snell's law in vector form: t = eta i + (eta cos_i - cos_t) n with
  cos_t = sqrt(1 - eta^2 (1 - cos_i^2)) (GLSL 4.50 spec, refract()).
*/
#ifndef SNELL_OPTICS_REFRACT_GLSL
#define SNELL_OPTICS_REFRACT_GLSL
#include "../prelude.glsl"
#include "safe_normalize.glsl"

#define SNELL_TIR_ZERO 0
#define SNELL_TIR_CRITICAL 1
#define SNELL_TIR_REFLECT 2

struct SnellRefraction {
  vec3 direction;
  bool tir;
  bool valid;
};

SNELL_FN SnellRefraction snellRefract(vec3 incident, vec3 normal, float eta, int policy) {
  SnellRefraction r;
  r.direction = vec3(0.0f, 0.0f, 0.0f);
  r.tir = false;
  r.valid = false;
  vec3 i = snellSafeNormalize(incident);
  vec3 n = snellSafeNormalize(normal);
  // eta >= FLT_MIN is false for NaN, 0 and denormals; eta <= FLT_MAX is false for +Inf.
  if (dot(i, i) == 0.0f || dot(n, n) == 0.0f || !(eta >= SNELL_FLT_MIN) || !(eta <= SNELL_FLT_MAX)) {
    return r;
  }
  r.valid = true;
  float cosI = -dot(n, i);
  if (cosI < 0.0f) {
    n = -n;
    cosI = -cosI;
  }
  cosI = min(cosI, 1.0f);
  // cos_t^2 = 1 - eta^2 (1 - cos_i^2), written as (1 - eta^2) + eta^2 cos_i^2: the
  // same value, but exact for eta = 1 and accurate near grazing incidence, where
  // 1 - cos_i^2 would round away the small cos_i^2.
  // From eta = 8 up the float cos_i near 1 (its ulp 2^-24, and the rounding before) costs about eta^2 2^-23
  // of cos_t^2, and above 4096 1 - eta^2 rounds (at normal incidence cos_t^2 came out 0 and the direction
  // cancelled to zero): there sin_t = eta |i_t| from i's tangent part i_t = i + cos_i n (exactly 0 at
  // normal incidence), and t = eta i_t - cos_t n. eta^2 is not formed there: it overflows from 1.8e19.
  vec3 tangent = i + cosI * n;
  bool large = eta >= 8.0f;
  float cos2T = 0.0f;
  if (large) {
    float sinT = eta * length(tangent);
    cos2T = (1.0f - sinT) * (1.0f + sinT);
  } else {
    float eta2 = eta * eta;
    cos2T = (1.0f - eta2) + eta2 * (cosI * cosI);
  }
  if (cos2T < 0.0f) {
    r.tir = true;
    if (policy == SNELL_TIR_REFLECT) {
      r.direction = snellSafeNormalize(i + (2.0f * cosI) * n);
    } else if (policy == SNELL_TIR_CRITICAL) {
      // sin_t = 1: the transmitted ray grazes the surface along i's tangent part.
      r.direction = snellSafeNormalize(tangent);
    }
    return r;
  }
  float cosT = sqrt(cos2T);
  r.direction = large ? snellSafeNormalize(eta * tangent - cosT * n) : snellSafeNormalize(eta * i + (eta * cosI - cosT) * n);
  return r;
}

#endif
