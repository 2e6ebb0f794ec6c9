// Fresnel terms and IOR helpers against independent double-precision formulas:
// the textbook Fresnel equations in their sine/tangent form, Schlick's and
// Sousa's formulas, the ice paper's cubic; hostile inputs give the documented
// finite values.
#include <snell/optics.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace {

using glm::dvec3;
using glm::vec3;

const float kInf = std::numeric_limits<float>::infinity();
const float kNaN = std::numeric_limits<float>::quiet_NaN();

// Unpolarized reflectance from Snell's law in angles and the Fresnel equations
// r_s = -sin(ti - tt) / sin(ti + tt), r_p = tan(ti - tt) / tan(ti + tt)
// (Born & Wolf 1.5.2), with n1 / n2 = eta.
double fresnelRef(double cosI, double eta) {
  cosI = std::min(std::fabs(cosI), 1.0);
  double ti = std::acos(cosI);
  double sinT = eta * std::sin(ti);
  if (sinT >= 1.0) return 1.0;
  double tt = std::asin(sinT);
  if (ti < 1e-9) {  // normal incidence: the sine/tangent form is 0/0
    double r = (eta - 1.0) / (eta + 1.0);
    return r * r;
  }
  double rs = -std::sin(ti - tt) / std::sin(ti + tt);
  double rp = std::tan(ti - tt) / std::tan(ti + tt);
  return 0.5 * (rs * rs + rp * rp);
}

TEST(OpticsFresnelDielectric, MatchesFresnelEquations) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> cosD(-1.0f, 1.0f), etaD(0.3f, 3.0f);
  int checked = 0;
  for (int k = 0; k < 50000; ++k) {
    float c = cosD(rng), eta = etaD(rng);
    double sin2T = double(eta) * double(eta) * (1.0 - double(c) * double(c));
    // Near the critical angle cos_t = sqrt(1 - sin2T) amplifies the float
    // rounding of sin2T (~eta^2 ulp) by 1 / (2 cos_t); the boundary itself has its
    // own test.
    if (std::fabs(1.0 - sin2T) < 1e-6) continue;
    double cosT = sin2T < 1.0 ? std::sqrt(1.0 - sin2T) : 1.0;
    double tol = 2e-6 + 1e-6 * double(eta) * double(eta) / cosT;
    EXPECT_NEAR(snell::snellFresnelDielectric(c, eta), fresnelRef(c, eta), tol) << c << " " << eta;
    ++checked;
  }
  EXPECT_GT(checked, 49000);
}

TEST(OpticsFresnelDielectric, KnownValues) {
  // Air to glass 1.5 at normal incidence: 0.04; Brewster angle: r_p = 0.
  EXPECT_NEAR(snell::snellFresnelDielectric(1.0f, 1.0f / 1.5f), 0.04f, 1e-7f);
  double brewster = std::atan(1.5);
  double rs = -std::sin(brewster - std::asin(std::sin(brewster) / 1.5)) /
              std::sin(brewster + std::asin(std::sin(brewster) / 1.5));
  EXPECT_NEAR(snell::snellFresnelDielectric(static_cast<float>(std::cos(brewster)), 1.0f / 1.5f), 0.5 * rs * rs, 1e-6);
  // Grazing: 1. eta = 1: 0.
  EXPECT_FLOAT_EQ(snell::snellFresnelDielectric(0.0f, 1.0f / 1.5f), 1.0f);
  EXPECT_FLOAT_EQ(snell::snellFresnelDielectric(0.5f, 1.0f), 0.0f);
  // Sign of cosI does not matter.
  EXPECT_FLOAT_EQ(snell::snellFresnelDielectric(-0.3f, 1.33f), snell::snellFresnelDielectric(0.3f, 1.33f));
}

TEST(OpticsFresnelDielectric, TirAndCriticalAngle) {
  double eta = 1.5, cosC = std::sqrt(1.0 - 1.0 / (eta * eta));
  EXPECT_EQ(snell::snellFresnelDielectric(static_cast<float>(cosC - 1e-3), 1.5f), 1.0f);  // beyond: TIR
  EXPECT_EQ(snell::snellFresnelDielectric(0.1f, 1.5f), 1.0f);
  // Approaching the critical angle from inside, F tends to 1 continuously.
  float inside = snell::snellFresnelDielectric(static_cast<float>(cosC + 1e-5), 1.5f);
  EXPECT_GT(inside, 0.9f);
  EXPECT_LE(inside, 1.0f);
}

TEST(OpticsFresnelDielectric, BadInputs) {
  for (float c : {kNaN}) EXPECT_EQ(snell::snellFresnelDielectric(c, 0.7f), 1.0f);  // NaN cos: grazing
  EXPECT_NEAR(snell::snellFresnelDielectric(2.0f, 0.7f), snell::snellFresnelDielectric(1.0f, 0.7f), 0.0f);
  EXPECT_NEAR(snell::snellFresnelDielectric(-kInf, 0.7f), snell::snellFresnelDielectric(1.0f, 0.7f), 0.0f);
  for (float eta : {0.0f, -1.0f, kNaN, kInf, 1e-40f}) EXPECT_EQ(snell::snellFresnelDielectric(0.5f, eta), 1.0f);
  for (float eta : {1e-20f, 1e20f, 3e38f}) {
    float f = snell::snellFresnelDielectric(0.5f, eta);
    EXPECT_TRUE(f >= 0.0f && f <= 1.0f) << eta;
  }
}

TEST(OpticsFresnelSchlick, MatchesFormula) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> cosD(-1.0f, 1.0f), f0D(0.0f, 1.0f);
  for (int k = 0; k < 20000; ++k) {
    float c = cosD(rng), f0 = f0D(rng);
    double want = double(f0) + (1.0 - double(f0)) * std::pow(1.0 - std::fabs(double(c)), 5.0);
    EXPECT_NEAR(snell::snellFresnelSchlick(c, f0), want, 1e-6);
  }
}

TEST(OpticsFresnelSchlick, F0AtNormalIncidenceEqualsExactFresnel) {
  for (float n2 : {1.0f, 1.33f, 1.5f, 2.42f, 4.0f}) {
    float f0 = snell::snellIorToF0(1.0f, n2);
    EXPECT_NEAR(snell::snellFresnelSchlick(1.0f, f0), f0, 1e-7f);
    EXPECT_NEAR(snell::snellFresnelDielectric(1.0f, snell::snellIorToEta(1.0f, n2)), f0, 1e-6f);
    EXPECT_NEAR(f0, fresnelRef(1.0, 1.0 / double(n2)), 1e-6);
    EXPECT_FLOAT_EQ(snell::snellFresnelSchlick(0.0f, f0), 1.0f);
  }
}

TEST(OpticsFresnelSchlick, BadInputs) {
  EXPECT_EQ(snell::snellFresnelSchlick(kNaN, 0.04f), 1.0f);
  EXPECT_EQ(snell::snellFresnelSchlick(0.5f, kNaN), 1.0f);
  EXPECT_NEAR(snell::snellFresnelSchlick(0.5f, -1.0f), std::pow(0.5, 5.0), 1e-7);
  EXPECT_EQ(snell::snellFresnelSchlick(0.5f, 2.0f), 1.0f);
  EXPECT_EQ(snell::snellFresnelSchlick(kInf, 0.04f), 0.04f);
  EXPECT_EQ(snell::snellFresnelSchlick(-3.0f, 0.04f), 0.04f);
}

double biasPowerRef(double ndl, double bias, double power) {
  double facing = 1.0 - std::min(std::max(ndl, 0.0), 1.0);
  return std::max(bias + (1.0 - bias) * std::pow(facing, power), 0.0);
}

TEST(OpticsFresnelBiasPower, MatchesSousa) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<float> ndlD(-0.5f, 1.5f), biasD(-0.5f, 1.0f), powD(0.1f, 10.0f);
  for (int k = 0; k < 20000; ++k) {
    float ndl = ndlD(rng), b = biasD(rng), p = powD(rng);
    EXPECT_NEAR(snell::snellFresnelBiasPower(ndl, b, p), biasPowerRef(ndl, b, p), 2e-6) << ndl << " " << b << " " << p;
  }
  // Sousa's water (0.2, 5) and glass (0.4, 5).
  EXPECT_NEAR(snell::snellFresnelBiasPower(1.0f, 0.2f, 5.0f), 0.2f, 1e-7f);
  EXPECT_NEAR(snell::snellFresnelBiasPower(0.0f, 0.4f, 5.0f), 1.0f, 1e-7f);
  EXPECT_NEAR(snell::snellFresnelBiasPower(0.5f, 0.2f, 5.0f), 0.2 + 0.8 / 32.0, 1e-7);
}

TEST(OpticsFresnelBiasPower, BadInputs) {
  EXPECT_EQ(snell::snellFresnelBiasPower(kNaN, 0.2f, 5.0f), 1.0f);  // NaN: facing = 1
  EXPECT_EQ(snell::snellFresnelBiasPower(0.5f, kNaN, 5.0f), 1.0f);
  EXPECT_EQ(snell::snellFresnelBiasPower(0.5f, 0.2f, kNaN), 1.0f);  // pow term 1
  EXPECT_EQ(snell::snellFresnelBiasPower(1.0f, 0.2f, 0.0f), 1.0f);  // 0^0 := 1
  EXPECT_EQ(snell::snellFresnelBiasPower(1.0f, 0.2f, -2.0f), 1.0f);
  EXPECT_EQ(snell::snellFresnelBiasPower(1.0f, 0.2f, 1e-40f), 1.0f);
  EXPECT_FLOAT_EQ(snell::snellFresnelBiasPower(1.0f, 0.2f, 3.0f), 0.2f);  // base 0
  EXPECT_FLOAT_EQ(snell::snellFresnelBiasPower(2.0f, 0.2f, 3.0f), 0.2f);  // saturated, no pow of negative
  EXPECT_FLOAT_EQ(snell::snellFresnelBiasPower(0.5f, 0.2f, kInf), 0.2f);
  EXPECT_EQ(snell::snellFresnelBiasPower(0.5f, -kInf, 2.0f), 0.0f);
  float big = snell::snellFresnelBiasPower(0.5f, kInf, 2.0f);
  EXPECT_TRUE(std::isfinite(big));
}

TEST(OpticsFresnelCubic, MatchesEquation4) {
  std::mt19937 rng(10);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int k = 0; k < 20000; ++k) {
    vec3 e(u(rng), u(rng), u(rng)), n(u(rng), u(rng), u(rng));
    if (glm::dot(e, e) < 1e-3f || glm::dot(n, n) < 1e-3f) continue;
    double c = std::fabs(glm::dot(glm::normalize(dvec3(e)), glm::normalize(dvec3(n))));
    double want = std::pow(1.0 - c, 3.0);
    EXPECT_NEAR(snell::snellFresnelCubic(e, n), want, 1e-6);
    // Both orientations of e give the same term.
    EXPECT_FLOAT_EQ(snell::snellFresnelCubic(-e, n), snell::snellFresnelCubic(e, n));
  }
  EXPECT_NEAR(snell::snellFresnelCubic(vec3(0, 0, -1), vec3(0, 0, 1)), 0.0f, 1e-7f);  // head-on
  EXPECT_NEAR(snell::snellFresnelCubic(vec3(1, 0, 0), vec3(0, 0, 1)), 1.0f, 1e-7f);   // grazing
}

TEST(OpticsFresnelCubic, BadInputs) {
  for (vec3 b : {vec3(0.0f), vec3(kNaN, 0, 0), vec3(kInf, 0, 0), vec3(1e-20f)}) {
    EXPECT_EQ(snell::snellFresnelCubic(b, vec3(0, 0, 1)), 1.0f);
    EXPECT_EQ(snell::snellFresnelCubic(vec3(0, 0, 1), b), 1.0f);
  }
}

TEST(OpticsIor, EtaAndF0) {
  EXPECT_FLOAT_EQ(snell::snellIorToEta(1.0f, 1.5f), 1.0f / 1.5f);
  EXPECT_FLOAT_EQ(snell::snellIorToEta(1.3091f, 1.0003f), 1.3091f / 1.0003f);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> iorD(1.0f, 4.0f);
  for (int k = 0; k < 10000; ++k) {
    float a = iorD(rng), b = iorD(rng);
    double r = (double(a) - double(b)) / (double(a) + double(b));
    EXPECT_NEAR(snell::snellIorToF0(a, b), r * r, 1e-7);
    EXPECT_EQ(snell::snellIorToF0(a, b), snell::snellIorToF0(b, a));
    EXPECT_NEAR(snell::snellIorToEta(a, b), double(a) / double(b), 1e-6);
  }
  EXPECT_NEAR(snell::snellIorToF0(1.0f, 1.5f), 0.04f, 1e-7f);
}

TEST(OpticsIor, BadInputs) {
  for (float bad : {0.0f, -1.5f, kNaN, kInf, -kInf, 1e-40f}) {
    EXPECT_EQ(snell::snellIorToEta(bad, 1.5f), 1.0f);
    EXPECT_EQ(snell::snellIorToEta(1.5f, bad), 1.0f);
    EXPECT_EQ(snell::snellIorToF0(bad, 1.5f), 0.0f);
    EXPECT_EQ(snell::snellIorToF0(1.5f, bad), 0.0f);
  }
  EXPECT_EQ(snell::snellIorToEta(1e30f, 1e-20f), 1e6f);
  EXPECT_EQ(snell::snellIorToEta(1e-20f, 1e30f), 1e-6f);
  float f0 = snell::snellIorToF0(3e38f, 1e-20f);
  EXPECT_TRUE(f0 >= 0.0f && f0 <= 1.0f);
}

}  // namespace
