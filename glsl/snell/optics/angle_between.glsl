/*
description: the angle between two directions, in radians [0, pi], accurate
  for tiny and near-pi angles and identical on every backend.
use: float theta = snellAngleBetween(a, b);  // neither needs to be normalized
options: -
contract:
  - theta = 2 asin(|u - v| / 2) for the unit vectors u, v (or pi - 2 asin(|u + v|
    / 2) when that argument is smaller), which keeps full relative precision
    for small angles where acos(dot(u, v)) loses it all;
  - asin is evaluated here with plain arithmetic and sqrt (Taylor series to
    x^17 on [0, 1/2], error < 5e-8, and asin(x) = pi/2 - 2 asin(sqrt((1 - x) / 2))
    above), because GPU drivers lower the asin builtin to cheap polynomials
    (absolute error ~1e-4 on Mesa), which ruins ratios of small angles such as
    Wyman's theta_t / theta_i;
  - a or b zero, denormal-small, NaN or infinite: 0.
source: the half-chord identity |u - v| = 2 sin(theta / 2) for unit vectors;
  Maclaurin series of asin (Abramowitz & Stegun, eq. 4.4.40).
*/
#ifndef SNELL_OPTICS_ANGLE_BETWEEN_GLSL
#define SNELL_OPTICS_ANGLE_BETWEEN_GLSL
#include "../prelude.glsl"
#include "safe_normalize.glsl"

SNELL_FN float snellAngleBetween(vec3 a, vec3 b) {
  vec3 u = snellSafeNormalize(a);
  vec3 v = snellSafeNormalize(b);
  if (dot(u, u) == 0.0f || dot(v, v) == 0.0f) {
    return 0.0f;
  }
  float chordMinus = length(u - v);
  float chordPlus = length(u + v);
  // chordMinus^2 + chordPlus^2 = 4, so the smaller half-chord is <= sqrt(2)/2.
  float x = min(0.5f * min(chordMinus, chordPlus), 1.0f);
  // asin(x): series on [0, 1/2]; above, reduce with w = sqrt((1 - x) / 2) <= 1/2.
  bool reduced = x > 0.5f;
  float y = reduced ? sqrt(0.5f * (1.0f - x)) : x;
  float y2 = y * y;
  float p = 0.0115518009f;
  p = p * y2 + 0.0139648438f;
  p = p * y2 + 0.0173527644f;
  p = p * y2 + 0.0223721591f;
  p = p * y2 + 0.0303819444f;
  p = p * y2 + 0.0446428571f;
  p = p * y2 + 0.075f;
  p = p * y2 + 0.166666667f;
  float asinY = y + y * y2 * p;
  float asinX = reduced ? 0.5f * SNELL_PI - 2.0f * asinY : asinY;
  return chordMinus <= chordPlus ? 2.0f * asinX : SNELL_PI - 2.0f * asinX;
}

#endif
