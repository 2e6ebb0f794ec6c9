// A tool author's view of snell: the functions a shader calls, called from C++.
// Traces parallel rays through a glass ball (unit sphere, IOR 1.5) with
// snellRefract at both interfaces and prints each ray's deviation next to the
// textbook value D = 2 (theta_i - theta_t), with the Fresnel reflectance at entry.
#include <snell/snell.hpp>

#include <cmath>
#include <cstdio>

namespace {
// Far intersection of a ray starting inside the unit sphere.
snell::vec3 exitPoint(snell::vec3 p, snell::vec3 d) {
  const float b = snell::dot(p, d);
  const float c = snell::dot(p, p) - 1.0f;
  return p + d * (-b + std::sqrt(b * b - c));
}
}  // namespace

int main() {
  const float eta = snell::snellIorToEta(1.0f, 1.5f);
  std::printf("impact  deviation(snell)  deviation(analytic)  fresnel(entry)\n");
  for (int i = 0; i <= 9; ++i) {
    const float h = 0.1f * static_cast<float>(i);  // impact parameter
    const snell::vec3 dir(0.0f, 0.0f, -1.0f);
    const snell::vec3 p1(h, 0.0f, std::sqrt(1.0f - h * h));  // entry point = outward normal
    const snell::SnellRefraction in = snell::snellRefract(dir, p1, eta, SNELL_TIR_CRITICAL);
    const snell::vec3 p2 = exitPoint(p1, in.direction);
    const snell::SnellRefraction out = snell::snellRefract(in.direction, -p2, 1.0f / eta, SNELL_TIR_CRITICAL);
    const float deviation = std::acos(snell::clamp(snell::dot(out.direction, dir), -1.0f, 1.0f));
    const float thetaI = std::asin(h), thetaT = std::asin(h / 1.5f);
    const float fresnel = snell::snellFresnelDielectric(snell::dot(-dir, p1), eta);
    std::printf("%6.2f  %16.6f  %19.6f  %14.6f\n", static_cast<double>(h), static_cast<double>(deviation),
                static_cast<double>(2.0f * (thetaI - thetaT)), static_cast<double>(fresnel));
  }
  return 0;
}
