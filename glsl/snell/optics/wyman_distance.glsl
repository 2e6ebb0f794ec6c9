/*
description: Wyman's estimate of the distance a refracted ray travels inside an
  object before it reaches the back surface: interpolate between the thickness
  along the view direction (dV) and along the inverted normal (dN) by the
  ratio of the transmission and incidence angles. Then P2 ~ P1 + d T1
  (equation 1).
use: float d = snellWymanDistance(thetaT, thetaI, dV, dN);
     float d = snellWymanDistanceVec(incident, normal, refracted, dV, dN);
  thetaT     angle between the refracted ray T1 and -N1, radians
  thetaI     angle between the incident (view) ray V and -N1, radians
  dV         thickness along the view ray (back depth minus front depth)
  dN         thickness along -N1 (per vertex, precomputed)
  incident   direction of travel of V (need not be normalized)
  normal     N1, either orientation (flipped to face the incident ray)
  refracted  T1, e.g. snellRefract(...).direction
options: -
contract:
  - snellWymanDistance returns r dV + (1 - r) dN, evaluated as
    dN + r (dV - dN), with r = thetaT / thetaI;
  - angles are taken by absolute value; r is clamped to [0, 1], the range the
    heuristic is defined on (entering a denser medium: eta = n_i / n_t <= 1, so
    thetaT <= thetaI; r = 1 means eta = 1: d = dV; r = 0 an infinite IOR:
    d = dN); leaving a denser medium (r > 1) is clamped to dV rather than
    extrapolated;
  - normal incidence (|thetaI| < 1e-30, which also covers denormals that GPUs
    may flush to 0) or a NaN ratio: r = 1, d = dV. The limit of thetaT /
    thetaI there is eta, but at normal incidence the view ray runs
    along -N1, so dV and dN measure the same segment and any r gives the same
    d; dV is the measured one;
  - dV, dN negative or NaN are treated as 0, +inf is clamped to FLT_MAX; the
    result lies between them, so it is finite and >= 0;
  - snellWymanDistanceVec measures the angles with snellAngleBetween
    (thetaI = angle(V, -N1), thetaT = angle(T1, -N1)); if any of the three
    vectors is zero, denormal-small, NaN or infinite (e.g. a TIR result of
    SNELL_TIR_ZERO) it returns the normal-incidence value, d = dV.
source: M. M. Oliveira & M. Brauwers, "Real-Time Refraction Through
  Deformable Objects", I3D 2007, sec. 2, equations 1 and 2 (after C. Wyman,
  "An Approximate Image-Space Approach for Interactive Refraction",
  SIGGRAPH 2005): d~ = (theta_t / theta_i) d_V + (1 - theta_t / theta_i) d_N.
*/
#ifndef SNELL_OPTICS_WYMAN_DISTANCE_GLSL
#define SNELL_OPTICS_WYMAN_DISTANCE_GLSL
#include "../prelude.glsl"
#include "safe_normalize.glsl"
#include "angle_between.glsl"

SNELL_FN float snellWymanDistance(float thetaT, float thetaI, float dV, float dN) {
  float ti = abs(thetaI);
  float tt = abs(thetaT);
  float r = 1.0f;
  if (ti >= 1e-30f) {
    float q = tt / ti;
    // Comparisons rather than clamp(): clamp() of a NaN is undefined in GLSL.
    r = q >= 0.0f ? min(q, 1.0f) : 1.0f;
  }
  float v = dV > 0.0f ? min(dV, SNELL_FLT_MAX) : 0.0f;
  float n = dN > 0.0f ? min(dN, SNELL_FLT_MAX) : 0.0f;
  return n + r * (v - n);
}

SNELL_FN float snellWymanDistanceVec(vec3 incident, vec3 normal, vec3 refracted, float dV, float dN) {
  vec3 i = snellSafeNormalize(incident);
  vec3 n = snellSafeNormalize(normal);
  vec3 t = snellSafeNormalize(refracted);
  if (dot(i, i) == 0.0f || dot(n, n) == 0.0f || dot(t, t) == 0.0f) {
    return snellWymanDistance(0.0f, 0.0f, dV, dN);
  }
  if (dot(i, n) > 0.0f) {
    n = -n;
  }
  return snellWymanDistance(snellAngleBetween(t, -n), snellAngleBetween(i, -n), dV, dN);
}

#endif
