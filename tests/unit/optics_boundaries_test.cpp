// The optics/ functions at the exact boundaries their contracts state (the smallest valid IOR, the clamps,
// the parallel-ray epsilon, the thresholds below which an angle or a length counts as 0), each side of the
// boundary computed here from the contract's words.
#include <gtest/gtest.h>

#include <snell/optics.hpp>

#include <cfloat>
#include <cmath>
#include <limits>

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

}  // namespace
