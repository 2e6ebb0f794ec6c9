/* Your own function, in snell's common subset (the same text compiles as GLSL
   and as C++ with GLM): the share of light that enters a glass surface and
   leaves through a parallel one, both Fresnel transmittances, no absorption. */
#ifndef MY_TRANSMITTANCE_GLSL
#define MY_TRANSMITTANCE_GLSL
#include "snell/optics.glsl"

SNELL_FN float myTwoSurfaceTransmittance(vec3 incident, vec3 normal, float ior) {
  vec3 i = snellSafeNormalize(incident);
  vec3 n = snellSafeNormalize(normal);
  float eta = snellIorToEta(1.0f, ior);
  SnellRefraction t = snellRefract(i, n, eta, SNELL_TIR_CRITICAL);
  if (!t.valid) {
    return 0.0f;
  }
  float enter = 1.0f - snellFresnelDielectric(dot(i, n), eta);
  // Out through the parallel face: the same angle inside, the inverse ratio.
  float leave = 1.0f - snellFresnelDielectric(dot(t.direction, n), 1.0f / eta);
  return enter * leave;
}

#endif
