/*
description: refraction at a rough (GGX) interface as one ray: Snell's law
  about the mean normal, with cos_t^2 replaced by its mean over the
  microfacets' slopes, so that the transmitted direction turns smoothly
  through the critical angle instead of snapping to the surface's tangent.
use: SnellRefraction r = snellRefractRough(incident, normal, eta, alpha, SNELL_TIR_CRITICAL);
  incident, normal, eta, policy  as snellRefract (optics/refract.glsl)
  alpha     the GGX width of the interface's microfacet slopes
            (snellRoughConeSlope(roughness), shade/rough_cone.glsl); below
            SNELL_FLT_MIN (0, negative, denormal: GPUs may flush them) or
            NaN: a smooth interface
contract:
  - alpha below SNELL_FLT_MIN or NaN, an invalid r, TIR under ZERO or
    REFLECT, or eta >= 8 (no pair of real materials): exactly
    r = snellRefract(incident, normal, eta, policy), bit for bit.
  - otherwise r.valid and r.tir are snellRefract's (TIR about the mean normal,
    so that a caller's choice between leaving and reflecting is unchanged),
    and r.direction is the unit vector
      t = eta i + (eta cos_i - sqrt(c')) n,  c' = min(1, (c + sqrt(c^2 + w^2)) / 2),
    with i, n, cos_i as snellRefract forms them (n facing i), the smooth
    c = cos_t^2 = (1 - eta^2) + eta^2 cos_i^2 (negative under TIR) and
    w = 2 eta^2 sin_i cos_i min(alpha, 1);
    (c + sqrt(c^2 + w^2)) / 2 is evaluated as w^2 / (2 (sqrt(c^2 + w^2) - c))
    for c < 0, where the first form cancels.
  - c' >= max(c, 0): the rough ray leaves at least as near the normal as the
    smooth one where Snell allows it, and leaves the surface (c' > 0) under
    TIR, where the smooth ray grazes; c' -> max(c, 0) far from the critical angle (|c| >> w), and
    c' = max(c, 0) at normal and grazing incidence (w = 0); t is a continuous function of the
    incidence with a bounded derivative at the critical angle (the smooth
    cos_t = sqrt(c) has an infinite one there: a ray near it swings over the
    scene behind as the object or the camera moves by a fraction of a pixel).
  - every output is finite; never NaN.
derivation: a microfacet tilted by slope x in the plane of incidence meets
  the ray at the incidence angle theta_i - atan(x), so to first order in x its
  cos_t^2 is c + k x, k = dc/dtheta_i = -2 eta^2 sin_i cos_i. GGX's slopes
  (Walter et al. 2007, eq. 33 written over slopes: P(x, y) = 1 / (pi alpha^2
  (1 + (x^2 + y^2) / alpha^2)^2)) have the marginal p(x) = alpha^2 / (2 (x^2 +
  alpha^2)^(3/2)) in the plane, a Student's t with 2 degrees of freedom, and
  for it the mean of max(c + k x, 0) (a facet past TIR leaves along the
  surface, as SNELL_TIR_CRITICAL has it) is exactly (c + sqrt(c^2 + w^2)) / 2
  with w = |k| alpha (its second derivative in c is the density of k x,
  w^2 / (2 (c^2 + w^2)^(3/2))). The direction is the
  one whose cos_t^2 is that mean. First order in the tilt: against the exact
  mean over both slopes (tests/unit/optics_refract_rough_test.cpp) c' is
  0.002 high at the critical angle for alpha 0.0225 (roughness 0.15), 0.026
  for alpha 0.09 (0.3), 0.14 for alpha 0.25 (0.5), where the concave c and the
  tilts across the plane of incidence pull the exact mean lower.
source: B. Walter, S. Marschner, H. Li, K. Torrance, "Microfacet Models for
  Refraction through Rough Surfaces", EGSR 2007, eq. 33 (GGX) and eq. 40
  (refraction about a microfacet normal); Snell's law as optics/refract.glsl.
*/
#ifndef SNELL_OPTICS_REFRACT_ROUGH_GLSL
#define SNELL_OPTICS_REFRACT_ROUGH_GLSL
#include "../prelude.glsl"
#include "safe_normalize.glsl"
#include "refract.glsl"

SNELL_FN SnellRefraction snellRefractRough(vec3 incident, vec3 normal, float eta, float alpha, int policy) {
  SnellRefraction r = snellRefract(incident, normal, eta, policy);
  if (!(alpha >= SNELL_FLT_MIN) || !r.valid || (r.tir && policy != SNELL_TIR_CRITICAL) || eta >= 8.0f) {
    return r;
  }
  vec3 i = snellSafeNormalize(incident);
  vec3 n = snellSafeNormalize(normal);
  float cosI = -dot(n, i);
  if (cosI < 0.0f) {
    n = -n;
    cosI = -cosI;
  }
  cosI = min(cosI, 1.0f);
  float sinI = length(i + cosI * n);
  float eta2 = eta * eta;
  float c = (1.0f - eta2) + eta2 * (cosI * cosI);
  float w = 2.0f * eta2 * sinI * cosI * min(alpha, 1.0f);
  float root = sqrt(c * c + w * w);
  float mean = c < 0.0f ? (w * w) / (2.0f * (root - c)) : 0.5f * (c + root);
  r.direction = snellSafeNormalize(eta * i + (eta * cosI - sqrt(min(mean, 1.0f))) * n);
  return r;
}

#endif
