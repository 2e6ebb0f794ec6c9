/*
description: G. Oliveira's approximate refracted ray: the incident direction
  plus the inverted normal weighted by a made-up "refraction factor",
  normalized. No angles, no square root of Snell's law; the factor has nothing
  to do with an index of refraction (0: no bending, large: straight down -N).
use: vec3 t = snellApproxRefract(incident, normal, factor);
  incident  direction of travel towards the surface (need not be normalized);
            the paper's camera_ray is its negation (vertex to eye)
  normal    surface normal (need not be normalized); flipped to face the
            incident ray when it points away from it, as in snellRefract
  factor    refraction factor >= 0 (the paper's refraction_coeff)
options: -
contract:
  - returns normalize(i - factor * n) with i = normalize(incident) and n the
    unit normal facing the incident ray (dot(i, n) <= 0): a unit vector;
  - factor 0 returns i (up to rounding); a negative or NaN factor is treated
    as 0;
    as factor grows the result tends to -n; factor = +inf returns -n;
    for factor > 1 it is evaluated as normalize(i / factor - n) so huge
    factors never overflow;
  - the sum never vanishes: for factor > 0 its component along n is
    dot(i, n) - factor < 0, and for factor 0 it is i itself;
  - returns (0,0,0) when incident or normal is zero, denormal-small, NaN or
    infinite.
source: G. Oliveira, "Refractive Texture Mapping, Part Two", Gamasutra 2000,
  Equation 8 ("adding the incident ray with the inverted normal and
  multiplying a factor to the normal") and Listing 4
  (refracted = -(normal * refraction_coeff + camera_ray), normalized).
*/
#ifndef SNELL_OPTICS_APPROX_REFRACT_GLSL
#define SNELL_OPTICS_APPROX_REFRACT_GLSL
#include "../prelude.glsl"
#include "safe_normalize.glsl"

SNELL_FN vec3 snellApproxRefract(vec3 incident, vec3 normal, float factor) {
  vec3 i = snellSafeNormalize(incident);
  vec3 n = snellSafeNormalize(normal);
  if (dot(i, i) == 0.0f || dot(n, n) == 0.0f) {
    return vec3(0.0f, 0.0f, 0.0f);
  }
  if (dot(i, n) > 0.0f) {
    n = -n;
  }
  // A comparison, not max(): max() with a NaN operand is undefined in GLSL.
  float k = factor > 0.0f ? factor : 0.0f;
  if (k > 1.0f) {
    return snellSafeNormalize(i * (1.0f / k) - n);
  }
  return snellSafeNormalize(i - k * n);
}

#endif
