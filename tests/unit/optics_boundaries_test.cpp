// The optics/ functions at the exact boundaries their contracts state (the smallest valid IOR, the clamps,
// the parallel-ray epsilon, the thresholds below which an angle or a length counts as 0), each side of the
// boundary computed here from the contract's words.
#include <gtest/gtest.h>

#include <snell/optics.hpp>

#include <cfloat>
#include <cmath>
#include <limits>
#include <random>

namespace {

using namespace snell;

const float kBelow30 = std::nextafter(1e-30f, 0.0f);
const float kBelowMax = std::nextafter(FLT_MAX, 0.0f);
constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(OpticsBoundaries, IorToEtaAtTheSmallestAndLargestIor) {
  EXPECT_EQ(snellIorToEta(1e-30f, 1.5f), 1e-6f);     // 1e-30 is valid: the ratio, clamped up to 1e-6
  EXPECT_EQ(snellIorToEta(1.5f, 1e-30f), 1e6f);      // and down to 1e6
  EXPECT_EQ(snellIorToEta(kBelow30, 1.5f), 1.0f);    // below it: the interface is ignored
  EXPECT_EQ(snellIorToEta(1.5f, kBelow30), 1.0f);
  EXPECT_EQ(snellIorToEta(kBelowMax, 1.5f), 1e6f);   // the largest finite IOR is valid
  EXPECT_EQ(snellIorToEta(1.5f, kBelowMax), 1e-6f);
  EXPECT_EQ(snellIorToEta(FLT_MAX, 1.5f), 1.0f);     // contract: below FLT_MAX
  EXPECT_EQ(snellIorToEta(1.5f, FLT_MAX), 1.0f);
  EXPECT_EQ(snellIorToEta(1.5f, kInf), 1.0f);
  EXPECT_EQ(snellIorToEta(1.0f, 1.25f), 0.8f);
  EXPECT_EQ(snellIorToEta(1.0f, 1e6f), 1e-6f);       // exactly the bounds
  EXPECT_EQ(snellIorToEta(1e6f, 1.0f), 1e6f);
  EXPECT_EQ(snellIorToEta(2e6f, 1.0f), 1e6f);
}

TEST(OpticsBoundaries, IorToF0AtTheSmallestAndLargestIor) {
  EXPECT_EQ(snellIorToF0(1e-30f, 1.5f), 1.0f);  // (n1 - n2) / (n1 + n2) = -1 to float precision
  EXPECT_EQ(snellIorToF0(1.5f, 1e-30f), 1.0f);
  EXPECT_EQ(snellIorToF0(kBelow30, 1.5f), 0.0f);
  EXPECT_EQ(snellIorToF0(1.5f, kBelow30), 0.0f);
  EXPECT_GT(snellIorToF0(kBelowMax, 1.5f), 0.99f);
  EXPECT_GT(snellIorToF0(1.5f, kBelowMax), 0.99f);
  EXPECT_EQ(snellIorToF0(FLT_MAX, 1.5f), 0.0f);
  EXPECT_EQ(snellIorToF0(1.5f, FLT_MAX), 0.0f);
  EXPECT_FLOAT_EQ(snellIorToF0(1.0f, 1.5f), 0.04f);
}

TEST(OpticsBoundaries, FresnelBiasPowerClamps) {
  // power 1e-30 counts (t = facing^1e-30, 1 to float precision but through pow), below it t = 1 exactly.
  EXPECT_EQ(snellFresnelBiasPower(0.5f, 0.25f, kBelow30), 1.0f);
  EXPECT_FLOAT_EQ(snellFresnelBiasPower(0.5f, 0.25f, 1e-30f), 0.25f + 0.75f * std::pow(0.5f, 1e-30f));
  EXPECT_EQ(snellFresnelBiasPower(1.0f, 0.25f, 1e-30f), 0.25f);  // a base of 0 with power > 0: t = 0
  EXPECT_EQ(snellFresnelBiasPower(1.0f, 0.25f, 0.0f), 1.0f);     // power 0: t = 1
  // power clamped to 1e6: at and past it the same.
  EXPECT_EQ(snellFresnelBiasPower(1e-7f, 0.0f, 2e6f), snellFresnelBiasPower(1e-7f, 0.0f, 1e6f));
  EXPECT_FLOAT_EQ(snellFresnelBiasPower(1e-7f, 0.0f, 1e6f), std::pow(1.0f - 1e-7f, 1e6f));
  // bias clamped to [-1e6, 1e6]; NaN is 1.
  EXPECT_EQ(snellFresnelBiasPower(0.0f, 2e6f, 1.0f), snellFresnelBiasPower(0.0f, 1e6f, 1.0f));
  EXPECT_EQ(snellFresnelBiasPower(0.0f, -2e6f, 1.0f), snellFresnelBiasPower(0.0f, -1e6f, 1.0f));
  EXPECT_EQ(snellFresnelBiasPower(0.5f, -1e6f, 1.0f), 0.0f);  // -1e6 + (1 + 1e6) 0.5 > 0
  EXPECT_FLOAT_EQ(snellFresnelBiasPower(0.5f, -1e6f, 2.0f), std::max(-1e6f + (1.0f + 1e6f) * 0.25f, 0.0f));
  EXPECT_EQ(snellFresnelBiasPower(0.5f, std::nanf(""), 3.0f), 1.0f);
  // nDotL saturated: 1 and above give facing 0; 0 and below facing 1.
  EXPECT_EQ(snellFresnelBiasPower(1.0f, 0.3f, 2.0f), 0.3f);
  EXPECT_EQ(snellFresnelBiasPower(1.5f, 0.3f, 2.0f), 0.3f);
  EXPECT_EQ(snellFresnelBiasPower(0.0f, 0.3f, 2.0f), 1.0f);
  EXPECT_EQ(snellFresnelBiasPower(-0.5f, 0.3f, 2.0f), 1.0f);
}

TEST(OpticsBoundaries, WymanDistanceAtNormalIncidenceAndTheClamps) {
  // |thetaI| >= 1e-30 uses the ratio; below it r = 1 (d = dV).
  EXPECT_EQ(snellWymanDistance(0.5e-30f, 1e-30f, 4.0f, 2.0f), 3.0f);  // r = 0.5
  EXPECT_EQ(snellWymanDistance(0.5e-30f, kBelow30, 4.0f, 2.0f), 4.0f);
  EXPECT_EQ(snellWymanDistance(0.0f, 0.3f, 4.0f, 2.0f), 2.0f);        // r = 0: dN
  EXPECT_EQ(snellWymanDistance(0.6f, 0.3f, 4.0f, 2.0f), 4.0f);        // r > 1 clamped to 1
  EXPECT_EQ(snellWymanDistance(-0.15f, -0.3f, 4.0f, 2.0f), 3.0f);     // angles by absolute value
  EXPECT_EQ(snellWymanDistance(0.15f, 0.3f, -4.0f, 2.0f), 1.0f);      // negative dV is 0
  EXPECT_EQ(snellWymanDistance(0.15f, 0.3f, 4.0f, -2.0f), 2.0f);      // negative dN is 0
  EXPECT_EQ(snellWymanDistance(0.0f, 0.3f, 4.0f, kInf), FLT_MAX);     // +inf clamped to FLT_MAX
  EXPECT_EQ(snellWymanDistance(0.3f, 0.3f, kInf, 2.0f), FLT_MAX);
}

TEST(OpticsBoundaries, SafeNormalizeAtItsThresholds) {
  // |v|^2 must be above 1e-30 and below FLT_MAX.
  const float atThreshold = std::sqrt(1e-30f);  // |v|^2 rounds to about 1e-30
  EXPECT_NEAR(snellSafeNormalize(glm::vec3(atThreshold * 1.001f, 0.0f, 0.0f)).x, 1.0f, 1e-6f);
  EXPECT_EQ(snellSafeNormalize(glm::vec3(atThreshold * 0.999f, 0.0f, 0.0f)), glm::vec3(0.0f));
  const float big = std::sqrt(FLT_MAX);
  EXPECT_NEAR(snellSafeNormalize(glm::vec3(big * 0.999f, 0.0f, 0.0f)).x, 1.0f, 1e-6f);
  EXPECT_EQ(snellSafeNormalize(glm::vec3(big * 1.001f, 0.0f, 0.0f)), glm::vec3(0.0f));
}

TEST(OpticsBoundaries, RayPlaneAtItsThresholds) {
  const glm::vec3 o(0.0f, 0.0f, 0.0f), p(0.0f, 0.0f, -2.0f), n(0.0f, 0.0f, 1.0f);
  // A ray starting on the plane hits at t = 0.
  SnellRayPlaneHit h = snellRayPlane(p, glm::vec3(0.0f, 0.0f, -1.0f), p, n);
  EXPECT_TRUE(h.valid);
  EXPECT_EQ(h.t, 0.0f);
  EXPECT_EQ(h.position, p);
  // Just behind the origin: no hit, t and position 0.
  h = snellRayPlane(glm::vec3(0.0f, 0.0f, -2.5f), glm::vec3(0.0f, 0.0f, -1.0f), p, n);
  EXPECT_FALSE(h.valid);
  EXPECT_EQ(h.t, 0.0f);
  EXPECT_EQ(h.position, glm::vec3(0.0f));
  // |dir|^2 above 1e-30 counts; at or below it does not.
  const float d = std::sqrt(1e-30f);
  h = snellRayPlane(o, glm::vec3(0.0f, 0.0f, -d * 1.001f), p, n);
  EXPECT_TRUE(h.valid);
  EXPECT_FLOAT_EQ(h.position.z, -2.0f);
  EXPECT_FALSE(snellRayPlane(o, glm::vec3(0.0f, 0.0f, -d * 0.999f), p, n).valid);
  // Parallel within 1e-6 of |dir|: a grazing angle just past the epsilon hits, one just under it does not.
  EXPECT_TRUE(snellRayPlane(o, glm::vec3(1.0f, 0.0f, -1.001e-6f), glm::vec3(0.0f, 0.0f, -1e-6f), n).valid);
  EXPECT_FALSE(snellRayPlane(o, glm::vec3(1.0f, 0.0f, -0.999e-6f), glm::vec3(0.0f, 0.0f, -1e-6f), n).valid);
  // t overflowing FLT_MAX: no hit.
  EXPECT_FALSE(snellRayPlane(o, glm::vec3(1.0f, 0.0f, -2e-6f), glm::vec3(0.0f, 0.0f, -1e33f), n).valid);
}

TEST(OpticsBoundaries, BeerLambertAtItsThresholds) {
  // The smallest positive absorption still absorbs over the longest distance: exp(-1e-40 FLT_MAX).
  const glm::vec3 t = snellBeerLambert(glm::vec3(1e-40f, 1e-40f, 1e-40f), FLT_MAX);
  const float want = std::exp(-1e-40f * FLT_MAX);
  EXPECT_LT(want, 0.9999f);
  EXPECT_FLOAT_EQ(t.x, want);
  EXPECT_FLOAT_EQ(t.y, want);
  EXPECT_FLOAT_EQ(t.z, want);
  // The product is capped at 1e30 (exp underflows to 0 long before): the largest inputs give 0, not NaN.
  EXPECT_EQ(snellBeerLambert(glm::vec3(FLT_MAX), FLT_MAX), glm::vec3(0.0f));
  EXPECT_EQ(snellBeerLambert(glm::vec3(FLT_MAX), 0.0f), glm::vec3(1.0f));
  // Each channel by itself; negative absorption or distance counts as 0.
  const glm::vec3 c = snellBeerLambert(glm::vec3(1e-40f, 0.0f, -1.0f), FLT_MAX);
  EXPECT_FLOAT_EQ(c.x, want);
  EXPECT_EQ(c.y, 1.0f);
  EXPECT_EQ(c.z, 1.0f);
  EXPECT_EQ(snellBeerLambert(glm::vec3(2.0f), -3.0f), glm::vec3(1.0f));
  // The smallest positive distance with the largest absorption.
  EXPECT_FLOAT_EQ(snellBeerLambert(glm::vec3(FLT_MAX), 1e-40f).x, std::exp(-FLT_MAX * 1e-40f));
}

TEST(OpticsBoundaries, FresnelDielectricAtTheSmallestAndLargestEta) {
  // eta 1e-30 is valid (clamped to 1e-6: from a near-vacuum into glass), below it the interface reflects all.
  EXPECT_EQ(snellFresnelDielectric(0.5f, 1e-30f), snellFresnelDielectric(0.5f, 1e-6f));
  EXPECT_LT(snellFresnelDielectric(0.5f, 1e-30f), 1.0f);
  EXPECT_EQ(snellFresnelDielectric(0.5f, kBelow30), 1.0f);
  EXPECT_EQ(snellFresnelDielectric(0.5f, kBelowMax), snellFresnelDielectric(0.5f, 1e6f));  // clamped to 1e6
  EXPECT_EQ(snellFresnelDielectric(0.5f, FLT_MAX), 1.0f);
  // The clamps' own values, against the formula at normal incidence: ((e - 1) / (e + 1))^2.
  const auto normal = [](double e) { return float(((e - 1.0) / (e + 1.0)) * ((e - 1.0) / (e + 1.0))); };
  EXPECT_FLOAT_EQ(snellFresnelDielectric(1.0f, 1e-7f), normal(1e-6));
  EXPECT_EQ(snellFresnelDielectric(0.9f, 1e7f), snellFresnelDielectric(0.9f, 1e6f));
  EXPECT_FLOAT_EQ(snellFresnelDielectric(1.0f, 1.5f), normal(1.5));
  // cosI = 0 (grazing) is valid input, and reflects all.
  EXPECT_EQ(snellFresnelDielectric(0.0f, 1.5f), 1.0f);
  EXPECT_EQ(snellFresnelDielectric(-0.0f, 0.5f), 1.0f);
}

TEST(OpticsBoundaries, ApproxRefractAtItsThresholds) {
  const auto near = [](glm::vec3 a, glm::vec3 b) { return glm::length(a - b) < 1e-6f; };
  const glm::vec3 i = glm::normalize(glm::vec3(0.3f, 0.0f, -1.0f)), n(0.0f, 0.0f, 1.0f);
  // i - k n, written as i / k - n above 1 (the same direction, (i - k n) / k, without overflow for huge k).
  EXPECT_TRUE(near(snellApproxRefract(i, n, 1.0f), glm::normalize(i - n)));
  EXPECT_TRUE(near(snellApproxRefract(i, n, 1e30f), -n));
  EXPECT_TRUE(near(snellApproxRefract(i, n, 4.0f), glm::normalize(i * 0.25f - n)));
  EXPECT_TRUE(near(snellApproxRefract(i, n, 1.1f), glm::normalize(i * (1.0f / 1.1f) - n)));
  // factor 0 or below: the incident direction itself.
  EXPECT_TRUE(near(snellApproxRefract(i, n, 0.0f), i));
  EXPECT_TRUE(near(snellApproxRefract(i, n, -2.0f), i));
  // A normal facing along the ray is flipped first; one perpendicular to it (dot 0) is not.
  EXPECT_TRUE(near(snellApproxRefract(i, -n, 0.5f), snellApproxRefract(i, n, 0.5f)));
  const glm::vec3 along(1.0f, 0.0f, 0.0f), side(0.0f, 0.0f, 1.0f);
  EXPECT_TRUE(near(snellApproxRefract(along, side, 0.5f), glm::normalize(along - 0.5f * side)));
}

// Vectors whose squared length, as dot(v, v) rounds it in float, is exactly a
// given threshold: x^2 rounds to 1e-30f for one float x near 1e-15, and adding
// a y^2 of about one ulp of 1e-30f moves the sum one float up; sqrt(FLT_MAX)
// is no float, but (2^64 - 2^40)^2 rounds to the float below FLT_MAX, one ulp
// (2^104 = (2^52)^2) short of it.
struct Thresholds {
  glm::vec3 at30, above30, atMax;
};

Thresholds squaredLengthThresholds() {
  Thresholds t{};
  float x = float(std::sqrt(1e-30));
  for (int k = 0; k < 8 && x * x != 1e-30f; ++k) x = std::nextafter(x, x * x < 1e-30f ? 1.0f : 0.0f);
  const float y = float(std::sqrt(std::ldexp(1.0, -123)));
  t.at30 = glm::vec3(x, 0.0f, 0.0f);
  t.above30 = glm::vec3(x, y, 0.0f);
  t.atMax = glm::vec3(std::nextafter(std::ldexp(1.0f, 64), 0.0f), std::ldexp(1.0f, 52), 0.0f);
  return t;
}

TEST(OpticsBoundaries, SafeNormalizeAtItsExactThresholds) {
  const Thresholds t = squaredLengthThresholds();
  ASSERT_EQ(glm::dot(t.at30, t.at30), 1e-30f);
  ASSERT_EQ(glm::dot(t.above30, t.above30), std::nextafter(1e-30f, 1.0f));
  ASSERT_EQ(glm::dot(t.atMax, t.atMax), FLT_MAX);
  // |v|^2 must be above 1e-30 and below FLT_MAX: exactly 1e-30 or FLT_MAX is (0,0,0).
  EXPECT_EQ(snellSafeNormalize(t.at30), glm::vec3(0.0f));
  EXPECT_EQ(snellSafeNormalize(t.atMax), glm::vec3(0.0f));
  const glm::dvec3 u = glm::normalize(glm::dvec3(t.above30));
  const glm::vec3 got = snellSafeNormalize(t.above30);
  EXPECT_NEAR(got.x, u.x, 1e-6);
  EXPECT_NEAR(got.y, u.y, 1e-6);
  const glm::vec3 belowMax(t.atMax.x, 0.0f, 0.0f);  // |v|^2 one float under FLT_MAX
  EXPECT_NEAR(snellSafeNormalize(belowMax).x, 1.0f, 1e-6f);
}

TEST(OpticsBoundaries, RayPlaneAtItsExactThresholds) {
  const Thresholds t = squaredLengthThresholds();
  const glm::vec3 o(0.0f), n(1.0f, 0.0f, 0.0f), p(2.0f, 0.0f, 0.0f);
  // |dir|^2 at 1e-30: a zero-like direction; one float above it: the hit at x = 2.
  EXPECT_FALSE(snellRayPlane(o, t.at30, p, n).valid);
  const SnellRayPlaneHit h = snellRayPlane(o, t.above30, p, n);
  EXPECT_TRUE(h.valid);
  EXPECT_NEAR(h.position.x, 2.0f, 1e-6f);
  EXPECT_NEAR(h.t, 2.0 / double(t.above30.x), 1e-6 * 2.0 / double(t.above30.x));
  // |cos| exactly at the epsilon: |dir| = 1 in float, dot(dir, n) = -1e-6f. The exact
  // cosine, 1e-6f / sqrt(1 + 1e-12), is below the epsilon: parallel. Twice the epsilon hits.
  const glm::vec3 nz(0.0f, 0.0f, 1.0f), pz(0.0f, 0.0f, -1.0f);
  EXPECT_FALSE(snellRayPlane(o, glm::vec3(1.0f, 0.0f, -1e-6f), pz, nz).valid);
  const SnellRayPlaneHit g = snellRayPlane(o, glm::vec3(1.0f, 0.0f, -2e-6f), pz, nz);
  EXPECT_TRUE(g.valid);
  EXPECT_NEAR(g.t, 1.0 / double(2e-6f), 1e-6 / double(2e-6f));
  // t exactly FLT_MAX is finite, and so is the point: a hit.
  const SnellRayPlaneHit far = snellRayPlane(o, glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 0.0f, -FLT_MAX), nz);
  EXPECT_TRUE(far.valid);
  EXPECT_EQ(far.t, FLT_MAX);
  EXPECT_EQ(far.position, glm::vec3(0.0f, 0.0f, -FLT_MAX));
}

// bias clamped to [-1e6, 1e6]. At nDotL = 1/2 with power 1 (t = 1/2 exactly) the
// result (1 + bias) / 2 is exact in float: 500000.5 for every bias from 1e6 up.
// Below -1e6: nDotL = 2^-20 gives t = 1 - 2^-20 exactly and the result 1 - (1 -
// bias) 2^-20, 0.0463 for bias -1e6, which the float evaluation rounds only once,
// at (1 - bias) t (half an ulp of 1e6: 1/32); a bias of -1048575 or below would give 0.
TEST(OpticsBoundaries, FresnelBiasPowerBiasClampValues) {
  for (float bias : {1e6f, 1.05e6f, 2e6f, FLT_MAX, kInf}) {
    EXPECT_EQ(snellFresnelBiasPower(0.5f, bias, 1.0f), 500000.5f) << bias;
  }
  const double exact = 1.0 - 1000001.0 * std::ldexp(1.0, -20);
  for (float bias : {-1e6f, -1.05e6f, -1e7f, -FLT_MAX, -kInf}) {
    EXPECT_NEAR(snellFresnelBiasPower(std::ldexp(1.0f, -20), bias, 1.0f), exact, 1.0 / 32.0) << bias;
  }
}

// Schlick at normal incidence is f0 itself, also for the smallest normal f0.
TEST(OpticsBoundaries, FresnelSchlickSmallestNormalF0) {
  EXPECT_EQ(snellFresnelSchlick(1.0f, FLT_MIN), FLT_MIN);
  EXPECT_EQ(snellFresnelSchlick(-1.0f, FLT_MIN), FLT_MIN);
}

// Thicknesses at the smallest normal float are thicknesses, not 0: at normal
// incidence d = dV, with thetaT = 0 (r = 0) d = dN.
TEST(OpticsBoundaries, WymanDistanceSmallestNormalThickness) {
  EXPECT_EQ(snellWymanDistance(0.0f, 0.0f, FLT_MIN, 0.0f), FLT_MIN);
  EXPECT_EQ(snellWymanDistance(0.0f, 1.0f, 0.0f, FLT_MIN), FLT_MIN);
}

// Grazing incidence, i perpendicular to n (dot 0): the normal is not pointing
// away from the ray, so it is kept as given. With eta = 1 the ray goes on
// unchanged (cos_t^2 = 0 exactly is no TIR); with eta = 1/2 the formula t = eta i
// + (eta cos_i - cos_t) n leaves on the far side of n at 30 degrees from -n.
TEST(OpticsBoundaries, RefractAtGrazingIncidence) {
  const glm::vec3 i(1.0f, 0.0f, 0.0f), n(0.0f, 0.0f, 1.0f);
  for (int policy : {SNELL_TIR_ZERO, SNELL_TIR_CRITICAL, SNELL_TIR_REFLECT}) {
    const SnellRefraction r = snellRefract(i, n, 1.0f, policy);
    EXPECT_TRUE(r.valid);
    EXPECT_FALSE(r.tir) << policy;
    EXPECT_EQ(r.direction, i) << policy;
    const SnellRefraction h = snellRefract(i, n, 0.5f, policy);
    EXPECT_TRUE(h.valid);
    EXPECT_FALSE(h.tir);
    EXPECT_NEAR(h.direction.x, 0.5, 1e-6) << policy;
    EXPECT_EQ(h.direction.y, 0.0f);
    EXPECT_NEAR(h.direction.z, -std::sqrt(0.75), 1e-6) << policy;
  }
}

// The angles of the Wyman estimate are measured from -N1 with N1 facing the
// incident ray. Grazing incidence (dot(V, N1) = 0) keeps N1: T1 at 30 degrees
// from -N1 against thetaI = 90 degrees, r = 1/3. A dot of +1e-39 (two normal
// components whose product is denormal; the CPU keeps it, the prelude's rule for
// data) points N1 away: flipped, the same T1 is then 30 degrees from the new -N1.
TEST(OpticsBoundaries, WymanDistanceVecAtGrazingIncidence) {
  const float dV = 3.0f, dN = 0.0f;
  const glm::vec3 t(0.5f, 0.0f, -float(std::sqrt(0.75)));
  EXPECT_NEAR(snellWymanDistanceVec(glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f), t, dV, dN), 1.0, 1e-6);
  const glm::vec3 i(1.0f, 0.0f, 1e-20f), n(0.0f, 1.0f, 1e-19f), t2(0.5f, float(std::sqrt(0.75)), 0.0f);
  ASSERT_GT(glm::dot(i, n), 0.0f);
  const glm::dvec3 I = glm::normalize(glm::dvec3(i)), N = -glm::normalize(glm::dvec3(n)),
                   T = glm::normalize(glm::dvec3(t2));
  const double r = std::acos(glm::dot(T, -N)) / std::acos(glm::dot(I, -N));
  EXPECT_NEAR(r, 1.0 / 3.0, 1e-6);
  EXPECT_NEAR(snellWymanDistanceVec(i, n, t2, dV, dN), double(dN) + r * double(dV - dN), 1e-6);
}

// The same tiny positive dot for the approximate refraction: N1 points away from
// the ray and is flipped, so i - k n bends towards +y.
TEST(OpticsBoundaries, ApproxRefractFlipsANormalAtATinyPositiveDot) {
  const glm::vec3 i(1.0f, 0.0f, 1e-20f), n(0.0f, 1.0f, 1e-19f);
  ASSERT_GT(glm::dot(i, n), 0.0f);
  const glm::dvec3 I = glm::normalize(glm::dvec3(i)), N = -glm::normalize(glm::dvec3(n));
  const glm::dvec3 want = glm::normalize(I - 0.5 * N);
  const glm::vec3 got = snellApproxRefract(i, n, 0.5f);
  EXPECT_NEAR(got.x, want.x, 1e-6);
  EXPECT_NEAR(got.y, want.y, 1e-6);
  EXPECT_NEAR(got.z, want.z, 1e-6);
}

// An invalid back normal leaves the front normal nf, the normalized input itself
// (one-sided refraction), whatever the blend weight: not nf scaled by 1 - a and
// normalized again, which moves it by rounding.
TEST(OpticsBoundaries, IceNormalBlendWithoutBackNormalIsTheFrontNormal) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int k = 0; k < 200; ++k) {
    const glm::vec3 f(u(rng), u(rng), u(rng));
    const glm::vec3 nf = snellSafeNormalize(f);
    ASSERT_NE(nf, glm::vec3(0.0f));
    for (float a : {0.0f, 0.33f, 0.5f, 0.7f, 1.0f, std::nanf("")}) {
      ASSERT_EQ(snellIceNormalBlend(f, glm::vec3(0.0f), a), nf) << a;
      ASSERT_EQ(snellIceNormalBlend(f, glm::vec3(kInf, 0.0f, 0.0f), a), nf) << a;
    }
  }
}

}  // namespace
