// Double-precision interface optics for the reference tracer: the same
// formulas as glsl/snell/optics/refract.glsl and fresnel_dielectric.glsl
// (Snell's law in vector form; unpolarized exact dielectric Fresnel), in
// double, with the same TIR policies. Cross-checked against the float shader
// functions in tests/lab.
#pragma once
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace snell::lab {

enum class TirPolicy {
  Reflect,   // mirror reflection (physical; SNELL_TIR_REFLECT)
  Critical,  // transmission clamped to the critical angle (SNELL_TIR_CRITICAL)
};

struct ExactRefraction {
  glm::dvec3 direction{0.0};
  bool tir = false;
};

// incident: unit direction of travel; normal: unit, any orientation (flipped to
// face the incident ray); eta = n_incident / n_transmitted.
inline ExactRefraction refractExact(const glm::dvec3& incident, glm::dvec3 normal, double eta, TirPolicy policy) {
  ExactRefraction r;
  double cosI = -glm::dot(normal, incident);
  if (cosI < 0.0) {
    normal = -normal;
    cosI = -cosI;
  }
  cosI = std::min(cosI, 1.0);
  const double eta2 = eta * eta;
  const double cos2T = (1.0 - eta2) + eta2 * cosI * cosI;
  if (cos2T < 0.0) {
    r.tir = true;
    r.direction = policy == TirPolicy::Reflect ? incident + 2.0 * cosI * normal : incident + cosI * normal;
    r.direction = glm::normalize(r.direction);
    return r;
  }
  r.direction = glm::normalize(eta * incident + (eta * cosI - std::sqrt(cos2T)) * normal);
  return r;
}

inline glm::dvec3 reflectExact(const glm::dvec3& incident, const glm::dvec3& normal) {
  return glm::normalize(incident - 2.0 * glm::dot(incident, normal) * normal);
}

// Unpolarized Fresnel reflectance, 1 under TIR; |cosI| is used.
inline double fresnelExact(double cosI, double eta) {
  const double c = std::min(std::abs(cosI), 1.0);
  const double eta2 = eta * eta;
  const double cos2T = (1.0 - eta2) + eta2 * c * c;
  if (cos2T <= 0.0) return 1.0;
  const double cosT = std::sqrt(cos2T);
  const double rs = (eta * c - cosT) / (eta * c + cosT);
  const double rp = (c - eta * cosT) / (c + eta * cosT);
  return 0.5 * (rs * rs + rp * rp);
}

}  // namespace snell::lab
