// snellRefract and snellApproxRefract against independent double-precision
// geometry: Snell's law checked through angles (sin_t = eta sin_i), the plane of
// incidence, and the side of the normal; TIR policies; hostile inputs.
#include <snell/optics.hpp>

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>

#include "support/rng.hpp"

namespace {

using glm::dvec3;
using glm::vec3;

const float kInf = std::numeric_limits<float>::infinity();
const float kNaN = std::numeric_limits<float>::quiet_NaN();

dvec3 d(vec3 v) { return dvec3(v); }

struct Rng : snell_test::Rng {
  Rng() : snell_test::Rng(1234u) {}
};

// Geometry of one incidence, in double: the unit normal facing the incident
// ray, cos/sin of the incidence angle and the unit tangent of the incident ray.
struct Incidence {
  dvec3 i, n, tangent;
  double cosI, sinI;
};

Incidence incidence(vec3 incidentF, vec3 normalF) {
  Incidence g;
  g.i = glm::normalize(d(incidentF));
  g.n = glm::normalize(d(normalF));
  if (glm::dot(g.i, g.n) > 0.0) g.n = -g.n;
  g.cosI = -glm::dot(g.i, g.n);
  dvec3 tang = g.i + g.cosI * g.n;  // component of i in the surface plane
  g.sinI = glm::length(tang);
  g.tangent = g.sinI > 0.0 ? tang / g.sinI : dvec3(0.0);
  return g;
}

TEST(OpticsRefract, SnellsLawThroughAngles) {
  Rng r;
  int checked = 0;
  for (int k = 0; k < 20000; ++k) {
    vec3 i = r.unit() * r.uniform(0.1f, 10.0f);
    vec3 n = r.unit() * r.uniform(0.1f, 10.0f);
    float eta = r.uniform(0.3f, 2.5f);
    Incidence g = incidence(i, n);
    double sinT = double(eta) * g.sinI;
    if (sinT > 0.999 || g.sinI < 1e-3) continue;  // away from TIR and normal incidence
    ++checked;
    snell::SnellRefraction res = snell::snellRefract(i, n, eta, SNELL_TIR_CRITICAL);
    ASSERT_TRUE(res.valid);
    ASSERT_FALSE(res.tir);
    dvec3 t = d(res.direction);
    EXPECT_NEAR(glm::length(t), 1.0, 1e-6);
    // The transmission angle: sin_t = |t x n|, and t continues through the surface.
    double sinTGot = glm::length(glm::cross(t, g.n));
    EXPECT_NEAR(sinTGot, sinT, 2e-6) << "eta " << eta << " sinI " << g.sinI;
    EXPECT_NEAR(std::asin(std::min(sinTGot, 1.0)), std::asin(sinT), 1e-4);
    EXPECT_LT(glm::dot(t, g.n), 0.0);
    // In the plane of incidence, on the far side of the normal: the tangential part
    // of t is the tangent of i scaled by sin_t.
    dvec3 planeNormal = glm::normalize(glm::cross(g.i, g.n));
    EXPECT_NEAR(glm::dot(t, planeNormal), 0.0, 2e-6);
    EXPECT_NEAR(glm::dot(t, g.tangent), sinT, 2e-6);
  }
  EXPECT_GT(checked, 9000);
}

// A huge eta (leaving a medium thousands of times denser; snellIorToEta's range reaches 1e6, the
// contract all finite normal floats): at normal incidence the ray goes straight through, however huge;
// slightly off it Snell's law still holds (here i's tangent part is its x, exact in float, so sin_t is
// within rounding), and past sin_i = 1 / eta it reflects totally.
TEST(OpticsRefract, HugeEtaKeepsSnellsLaw) {
  for (const float eta : {4097.0f, 5000.0f, 1e6f, 1e19f, 1e30f, 3e38f, FLT_MAX}) {
    SCOPED_TRACE(eta);
    const snell::SnellRefraction res = snell::snellRefract(vec3(0.0f, 0.0f, -1.0f), vec3(0.0f, 0.0f, 1.0f), eta, SNELL_TIR_ZERO);
    ASSERT_TRUE(res.valid);
    EXPECT_FALSE(res.tir);
    EXPECT_EQ(res.direction, vec3(0.0f, 0.0f, -1.0f));
  }
  Rng r;
  int refracted = 0, reflected = 0;
  for (int k = 0; k < 2000; ++k) {
    const float eta = std::pow(10.0f, r.uniform(3.7f, 6.0f));
    const float sinI = r.uniform(0.0f, 2.0f) / eta;
    vec3 i(sinI, 0.0f, -std::sqrt(1.0f - sinI * sinI));
    const Incidence g = incidence(i, vec3(0.0f, 0.0f, 1.0f));
    const double sinT = double(eta) * g.sinI;
    if (std::abs(sinT - 1.0) < 0.05) continue;  // the float input cannot tell which side of the critical angle
    const snell::SnellRefraction res = snell::snellRefract(i, vec3(0.0f, 0.0f, 1.0f), eta, SNELL_TIR_ZERO);
    ASSERT_TRUE(res.valid);
    ASSERT_EQ(res.tir, sinT > 1.0) << "eta " << eta << " sin_t " << sinT;
    if (res.tir) {
      EXPECT_EQ(res.direction, vec3(0.0f));
      ++reflected;
      continue;
    }
    ++refracted;
    const dvec3 t = d(res.direction);
    EXPECT_NEAR(glm::length(t), 1.0, 1e-6);
    EXPECT_LT(t.z, 0.0);
    EXPECT_NEAR(t.x, sinT, 2e-6) << "eta " << eta;
    EXPECT_NEAR(t.y, 0.0, 1e-6);
  }
  EXPECT_GT(refracted, 500);
  EXPECT_GT(reflected, 500);
}

// From eta = 8 to 4096 (no real pair of materials, but snellIorToEta's range) the float cos_i near 1 is
// quantized finely enough for glass and too coarsely for eta^2 cos_i^2: rays against Snell's law in double,
// whose tangent part is exact (i in the xz-plane, x the sine). At eta = 8 itself, sin_i 0x1.fee35p-4 is where
// (1 - eta^2) + eta^2 cos_i^2 is furthest off (1.3e-5 of the direction).
TEST(OpticsRefract, LargeEtaKeepsSnellsLaw) {
  Rng r;
  int refracted = 0, reflected = 0;
  for (int k = 0; k < 4000; ++k) {
    const float eta = k == 0 ? 8.0f : k == 1 ? 4096.0f : std::pow(10.0f, r.uniform(0.91f, 3.61f));
    const float sinI = k == 0 ? 0x1.fee35p-4f : k == 1 ? 0.5f / eta : r.uniform(0.0f, 2.0f) / eta;
    vec3 i(sinI, 0.0f, -std::sqrt(1.0f - sinI * sinI));
    const Incidence g = incidence(i, vec3(0.0f, 0.0f, 1.0f));
    const double sinT = double(eta) * g.sinI;
    // Within 2^-20 of sin_t = 1 (times eta, the float input's own resolution) the side is a matter of rounding.
    if (std::abs(sinT - 1.0) < double(eta) * 1e-6) continue;
    const snell::SnellRefraction res = snell::snellRefract(i, vec3(0.0f, 0.0f, 1.0f), eta, SNELL_TIR_ZERO);
    ASSERT_TRUE(res.valid);
    ASSERT_EQ(res.tir, sinT > 1.0) << "eta " << eta << " sin_t " << sinT;
    if (res.tir) {
      ++reflected;
      continue;
    }
    ++refracted;
    const dvec3 t = d(res.direction);
    EXPECT_NEAR(glm::length(t), 1.0, 1e-6);
    EXPECT_NEAR(t.x, sinT, 2e-6) << "eta " << eta;
    EXPECT_NEAR(t.z, -std::sqrt(1.0 - sinT * sinT), 2e-6 + 2e-6 * sinT / std::sqrt(1.0 - sinT * sinT)) << "eta " << eta;
  }
  EXPECT_GT(refracted, 1500);
  EXPECT_GT(reflected, 1500);
}

TEST(OpticsRefract, NormalFacingAwayIsFlipped) {
  vec3 i(0.6f, -0.8f, 0.0f), n(0.0f, 1.0f, 0.0f);
  snell::SnellRefraction a = snell::snellRefract(i, n, 1.0f / 1.5f, SNELL_TIR_ZERO);
  snell::SnellRefraction b = snell::snellRefract(i, -n, 1.0f / 1.5f, SNELL_TIR_ZERO);
  EXPECT_EQ(a.direction, b.direction);
  EXPECT_NEAR(a.direction.x, 0.4f, 1e-6f);  // sin_t = 0.6 / 1.5
}

TEST(OpticsRefract, EtaOneIsIdentity) {
  Rng r;
  for (int k = 0; k < 1000; ++k) {
    vec3 i = r.unit(), n = r.unit();
    snell::SnellRefraction res = snell::snellRefract(i, n, 1.0f, SNELL_TIR_ZERO);
    ASSERT_TRUE(res.valid);
    EXPECT_NEAR(glm::length(d(res.direction) - d(i)), 0.0, 1e-5);
  }
}

TEST(OpticsRefract, TirPolicies) {
  Rng r;
  int checked = 0;
  for (int k = 0; k < 20000; ++k) {
    vec3 i = r.unit(), n = r.unit();
    float eta = r.uniform(1.05f, 2.5f);
    Incidence g = incidence(i, n);
    if (double(eta) * g.sinI < 1.001) continue;  // clearly beyond the critical angle
    ++checked;
    snell::SnellRefraction z = snell::snellRefract(i, n, eta, SNELL_TIR_ZERO);
    EXPECT_TRUE(z.valid && z.tir);
    EXPECT_EQ(z.direction, vec3(0.0f));

    // Critical: the ray grazes the surface (theta_t = 90 deg) along i's tangent.
    snell::SnellRefraction c = snell::snellRefract(i, n, eta, SNELL_TIR_CRITICAL);
    EXPECT_TRUE(c.valid && c.tir);
    dvec3 tc = d(c.direction);
    EXPECT_NEAR(glm::dot(tc, g.n), 0.0, 1e-6);
    EXPECT_NEAR(glm::dot(tc, g.tangent), 1.0, 1e-6);

    // Reflect: angle of reflection equals angle of incidence, same tangent, back
    // to the incident side.
    snell::SnellRefraction m = snell::snellRefract(i, n, eta, SNELL_TIR_REFLECT);
    EXPECT_TRUE(m.valid && m.tir);
    dvec3 tm = d(m.direction);
    EXPECT_NEAR(glm::dot(tm, g.n), g.cosI, 2e-6);
    EXPECT_NEAR(glm::dot(tm, g.tangent), g.sinI, 2e-6);
    EXPECT_NEAR(std::acos(std::min(1.0, glm::dot(tm, g.n))), std::acos(std::min(1.0, g.cosI)), 1e-3);
  }
  EXPECT_GT(checked, 1000);
}

TEST(OpticsRefract, CriticalAngleBoundary) {
  // Just inside the critical angle: transmitted, sin_t close to 1.
  double eta = 1.5, thetaC = std::asin(1.0 / eta);
  for (double off : {-1e-3, 1e-3}) {
    double th = thetaC + off;
    vec3 i(static_cast<float>(std::sin(th)), static_cast<float>(-std::cos(th)), 0.0f);
    snell::SnellRefraction res = snell::snellRefract(i, vec3(0, 1, 0), 1.5f, SNELL_TIR_ZERO);
    EXPECT_TRUE(res.valid);
    EXPECT_EQ(res.tir, off > 0.0);
    if (off < 0.0) {
      EXPECT_NEAR(res.direction.x, eta * std::sin(th), 1e-5);
    }
  }
}

TEST(OpticsRefract, BadInputsAreInvalid) {
  const vec3 n(0, 1, 0), i(0.3f, -1.0f, 0.0f);
  const vec3 bad[] = {vec3(0.0f), vec3(1e-20f), vec3(kNaN, 0, 0), vec3(0, kInf, 0), vec3(-kInf, 1, 1)};
  for (int p = 0; p < 3; ++p) {
    for (vec3 b : bad) {
      for (snell::SnellRefraction res : {snell::snellRefract(b, n, 0.7f, p), snell::snellRefract(i, b, 0.7f, p)}) {
        EXPECT_FALSE(res.valid);
        EXPECT_FALSE(res.tir);
        EXPECT_EQ(res.direction, vec3(0.0f));
      }
    }
    // Denormal etas count as 0 (a runtime that flushes denormals sees 0 there);
    // the smallest normal one is an eta like any other.
    for (float eta : {0.0f, -1.0f, kNaN, kInf, -kInf, 1e-40f, std::numeric_limits<float>::denorm_min(),
                      std::nextafter(std::numeric_limits<float>::min(), 0.0f)}) {
      snell::SnellRefraction res = snell::snellRefract(i, n, eta, p);
      EXPECT_FALSE(res.valid) << eta;
      EXPECT_EQ(res.direction, vec3(0.0f));
    }
    EXPECT_TRUE(snell::snellRefract(i, n, std::numeric_limits<float>::min(), p).valid);
  }
}

// --- G. Oliveira's approximate refraction -----------------------------------

TEST(OpticsApproxRefract, MatchesEquation8) {
  Rng r;
  for (int k = 0; k < 20000; ++k) {
    vec3 i = r.unit() * r.uniform(0.01f, 100.0f);
    vec3 n = r.unit() * r.uniform(0.01f, 100.0f);
    float f = r.uniform(0.0f, 4.0f);
    Incidence g = incidence(i, n);
    dvec3 want = glm::normalize(g.i - double(f) * g.n);  // incident + factor * inverted normal
    vec3 got = snell::snellApproxRefract(i, n, f);
    EXPECT_NEAR(glm::length(d(got) - want), 0.0, 2e-6) << "factor " << f;
  }
}

TEST(OpticsApproxRefract, Limits) {
  Rng r;
  for (int k = 0; k < 2000; ++k) {
    vec3 i = r.unit(), n = r.unit();
    Incidence g = incidence(i, n);
    // factor 0: the incident direction.
    EXPECT_NEAR(glm::length(d(snell::snellApproxRefract(i, n, 0.0f)) - g.i), 0.0, 1e-6);
    EXPECT_NEAR(glm::length(d(snell::snellApproxRefract(i, n, -3.0f)) - g.i), 0.0, 1e-6);
    // Large factor: -N (N facing the incident ray). Error of the limit ~ 1/factor.
    EXPECT_NEAR(glm::length(d(snell::snellApproxRefract(i, n, 1e6f)) + g.n), 0.0, 2.1e-6);
    EXPECT_NEAR(glm::length(d(snell::snellApproxRefract(i, n, 1e30f)) + g.n), 0.0, 1e-6);
    EXPECT_NEAR(glm::length(d(snell::snellApproxRefract(i, n, kInf)) + g.n), 0.0, 1e-6);
    // Bending increases with the factor.
    double a1 = glm::dot(d(snell::snellApproxRefract(i, n, 0.5f)), -g.n);
    double a2 = glm::dot(d(snell::snellApproxRefract(i, n, 2.0f)), -g.n);
    EXPECT_GE(a2, a1 - 1e-7);
  }
}

TEST(OpticsApproxRefract, BadInputs) {
  const vec3 n(0, 1, 0), i(0.3f, -1.0f, 0.0f);
  for (vec3 b : {vec3(0.0f), vec3(1e-20f), vec3(kNaN, 0, 0), vec3(0, kInf, 0)}) {
    EXPECT_EQ(snell::snellApproxRefract(b, n, 1.0f), vec3(0.0f));
    EXPECT_EQ(snell::snellApproxRefract(i, b, 1.0f), vec3(0.0f));
  }
  // NaN factor is treated as 0: the incident direction.
  vec3 got = snell::snellApproxRefract(i, n, kNaN);
  EXPECT_NEAR(glm::length(d(got) - glm::normalize(d(i))), 0.0, 1e-6);
}

}  // namespace
