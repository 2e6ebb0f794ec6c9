// Ray-plane intersection, Wyman's distance interpolation, the angle helper, the
// ice normal blend and Beer-Lambert absorption, against independent double
// computations; hostile inputs give the documented finite values.
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

struct Rng : snell_test::Rng {
  Rng() : snell_test::Rng(99u) {}
};

bool finite(vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// --- ray / plane ---------------------------------------------------------------

TEST(OpticsRayPlane, MatchesParametricSolve) {
  Rng r;
  int hits = 0, behind = 0;
  for (int k = 0; k < 20000; ++k) {
    vec3 o(r.uniform(-10, 10), r.uniform(-10, 10), r.uniform(-10, 10));
    vec3 dir = r.unit() * r.uniform(0.1f, 10.0f);
    vec3 p0(r.uniform(-10, 10), r.uniform(-10, 10), r.uniform(-10, 10));
    vec3 n = r.unit() * r.uniform(0.1f, 10.0f);
    // Solve o + t dir on the plane with Cramer's rule on the 3x3 system
    // o + t dir = p0 + u e1 + v e2 (e1, e2 spanning the plane): independent of
    // the dot-product formula.
    dvec3 nd = glm::normalize(dvec3(n));
    dvec3 e1 = glm::normalize(glm::cross(nd, std::fabs(nd.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
    dvec3 e2 = glm::cross(nd, e1);
    glm::dmat3 m(dvec3(dir), -e1, -e2);  // columns
    double det = glm::determinant(m);
    double cosAngle = std::fabs(glm::dot(glm::normalize(dvec3(dir)), nd));
    if (cosAngle < 1e-3) continue;  // near-parallel: tested separately
    dvec3 rhs = dvec3(p0) - dvec3(o);
    glm::dmat3 mt = m;
    mt[0] = rhs;
    double t = glm::determinant(mt) / det;
    snell::SnellRayPlaneHit h = snell::snellRayPlane(o, dir, p0, n);
    if (t < -1e-4) {
      ++behind;
      EXPECT_FALSE(h.valid);
      EXPECT_EQ(h.t, 0.0f);
      EXPECT_EQ(h.position, vec3(0.0f));
    } else if (t > 1e-4) {
      ++hits;
      ASSERT_TRUE(h.valid);
      EXPECT_NEAR(h.t, t, 1e-4 * (1.0 + t));
      dvec3 want = dvec3(o) + t * dvec3(dir);
      EXPECT_NEAR(glm::length(dvec3(h.position) - want), 0.0, 1e-4 * (1.0 + glm::length(want)));
      // On the plane.
      EXPECT_NEAR(glm::dot(dvec3(h.position) - dvec3(p0), nd), 0.0, 1e-4 * (1.0 + glm::length(want)));
    }
  }
  EXPECT_GT(hits, 5000);
  EXPECT_GT(behind, 5000);
}

TEST(OpticsRayPlane, EdgeCases) {
  const vec3 o(1, 2, 3), p0(0, 0, 0), n(0, 0, 1);
  // Straight down onto z = 0.
  snell::SnellRayPlaneHit h = snell::snellRayPlane(o, vec3(0, 0, -2), p0, n);
  EXPECT_TRUE(h.valid);
  EXPECT_FLOAT_EQ(h.t, 1.5f);
  EXPECT_EQ(h.position, vec3(1, 2, 0));
  // The normal's orientation does not matter.
  EXPECT_FLOAT_EQ(snell::snellRayPlane(o, vec3(0, 0, -2), p0, -n).t, 1.5f);
  // Behind the origin.
  h = snell::snellRayPlane(o, vec3(0, 0, 1), p0, n);
  EXPECT_FALSE(h.valid);
  EXPECT_EQ(h.t, 0.0f);
  EXPECT_EQ(h.position, vec3(0.0f));
  // Parallel, off the plane and in the plane.
  EXPECT_FALSE(snell::snellRayPlane(o, vec3(1, 0, 0), p0, n).valid);
  EXPECT_FALSE(snell::snellRayPlane(vec3(1, 2, 0), vec3(1, 0, 0), p0, n).valid);
  EXPECT_FALSE(snell::snellRayPlane(o, vec3(1, 0, 1e-8f), p0, n).valid);
  // Origin on the plane: a hit at t = 0.
  h = snell::snellRayPlane(vec3(1, 2, 0), vec3(0.3f, 0, -1), p0, n);
  EXPECT_TRUE(h.valid);
  EXPECT_EQ(h.t, 0.0f);
  EXPECT_EQ(h.position, vec3(1, 2, 0));
}

TEST(OpticsRayPlane, BadInputs) {
  const vec3 o(1, 2, 3), dir(0, 0, -1), p0(0, 0, 0), n(0, 0, 1);
  const vec3 bad[] = {vec3(kNaN, 0, 0), vec3(0, kInf, 0), vec3(0, 0, -kInf)};
  auto expectInvalid = [](snell::SnellRayPlaneHit h) {
    EXPECT_FALSE(h.valid);
    EXPECT_EQ(h.t, 0.0f);
    EXPECT_EQ(h.position, vec3(0.0f));
  };
  for (vec3 b : bad) {
    expectInvalid(snell::snellRayPlane(b, dir, p0, n));
    expectInvalid(snell::snellRayPlane(o, b, p0, n));
    expectInvalid(snell::snellRayPlane(o, dir, b, n));
    expectInvalid(snell::snellRayPlane(o, dir, p0, b));
  }
  expectInvalid(snell::snellRayPlane(o, vec3(0.0f), p0, n));
  expectInvalid(snell::snellRayPlane(o, dir, p0, vec3(0.0f)));
  expectInvalid(snell::snellRayPlane(o, vec3(0, 0, -1e-20f), p0, n));
  // Overflowing t or point.
  expectInvalid(snell::snellRayPlane(vec3(0, 0, 3e38f), vec3(1e-3f, 0, -1e-3f), vec3(0, 0, -3e38f), n));
}

// A dir whose squared length rounds to FLT_MAX itself is a finite ray, hit where double precision puts it;
// one ulp longer, its square overflows and the ray is refused.
TEST(OpticsRayPlane, ADirSquaringToTheLargestFloatStillHits) {
  const float a = 0x1.000002p+63f, b = 0x1.bb67acp+63f;
  ASSERT_EQ(a * a + b * b, FLT_MAX);
  const vec3 o(0.0f, 0.0f, -1.0f), p0(100.0f, 0.0f, 0.0f), nx(1.0f, 0.0f, 0.0f);
  const snell::SnellRayPlaneHit h = snell::snellRayPlane(o, vec3(a, b, 0.0f), p0, nx);
  ASSERT_TRUE(h.valid);
  const double t = 100.0 / double(a);
  EXPECT_NEAR(h.t, t, 1e-6 * t);
  EXPECT_NEAR(h.position.x, 100.0, 1e-4);
  EXPECT_NEAR(h.position.y, t * double(b), 1e-4);
  EXPECT_EQ(h.position.z, -1.0f);
  const float longer = std::nextafter(b, kInf);
  ASSERT_TRUE(std::isinf(a * a + longer * longer));
  EXPECT_FALSE(snell::snellRayPlane(o, vec3(a, longer, 0.0f), p0, nx).valid);
}

// --- angle between ------------------------------------------------------------

TEST(OpticsAngleBetween, MatchesAtan2InDouble) {
  Rng r;
  for (int k = 0; k < 20000; ++k) {
    vec3 a = r.unit() * r.uniform(0.01f, 100.0f);
    vec3 b = r.unit() * r.uniform(0.01f, 100.0f);
    dvec3 da(a), db(b);
    double want = std::atan2(glm::length(glm::cross(da, db)), glm::dot(da, db));
    EXPECT_NEAR(snell::snellAngleBetween(a, b), want, 1e-6);
  }
  // Tiny angles keep their relative precision (acos of a float dot would give 0).
  for (double th : {1e-2, 1e-3, 1e-4, 3e-5}) {
    vec3 a(1, 0, 0), b(static_cast<float>(std::cos(th)), static_cast<float>(std::sin(th)), 0);
    double want = std::atan2(double(b.y), double(b.x));
    EXPECT_NEAR(snell::snellAngleBetween(a, b), want, 1e-5 * want) << th;
  }
  EXPECT_NEAR(snell::snellAngleBetween(vec3(1, 0, 0), vec3(-1, 1e-4f, 0)), M_PI - 1e-4, 1e-6);
  EXPECT_NEAR(snell::snellAngleBetween(vec3(1, 0, 0), vec3(-1, 0, 0)), M_PI, 1e-6);
  EXPECT_EQ(snell::snellAngleBetween(vec3(1, 0, 0), vec3(2, 0, 0)), 0.0f);
  EXPECT_NEAR(snell::snellAngleBetween(vec3(1, 0, 0), vec3(0, 0, 5)), M_PI / 2, 1e-6);
}

TEST(OpticsAngleBetween, BadInputs) {
  for (vec3 b : {vec3(0.0f), vec3(kNaN, 0, 0), vec3(kInf, 0, 0), vec3(1e-20f)}) {
    EXPECT_EQ(snell::snellAngleBetween(b, vec3(0, 0, 1)), 0.0f);
    EXPECT_EQ(snell::snellAngleBetween(vec3(0, 0, 1), b), 0.0f);
  }
}

// --- Wyman distance -------------------------------------------------------------

TEST(OpticsWymanDistance, MatchesEquation2) {
  Rng r;
  for (int k = 0; k < 20000; ++k) {
    float ti = r.uniform(1e-3f, 1.5f);
    float tt = r.uniform(0.0f, 1.0f) * ti;
    float dV = r.uniform(0.0f, 10.0f), dN = r.uniform(0.0f, 10.0f);
    double q = double(tt) / double(ti);
    double want = q * double(dV) + (1.0 - q) * double(dN);
    EXPECT_NEAR(snell::snellWymanDistance(tt, ti, dV, dN), want, 1e-5 * (1.0 + want));
  }
}

TEST(OpticsWymanDistance, LimitsAndBadInputs) {
  EXPECT_EQ(snell::snellWymanDistance(0.3f, 0.3f, 2.0f, 5.0f), 2.0f);  // eta = 1: dV
  EXPECT_EQ(snell::snellWymanDistance(0.0f, 0.3f, 2.0f, 5.0f), 5.0f);  // infinite IOR: dN
  EXPECT_EQ(snell::snellWymanDistance(0.0f, 0.0f, 2.0f, 5.0f), 2.0f);  // normal incidence: dV
  EXPECT_EQ(snell::snellWymanDistance(1e-40f, 1e-40f, 2.0f, 5.0f), 2.0f);
  EXPECT_EQ(snell::snellWymanDistance(0.6f, 0.3f, 2.0f, 5.0f), 2.0f);  // r > 1 clamped
  EXPECT_FLOAT_EQ(snell::snellWymanDistance(-0.1f, -0.4f, 2.0f, 6.0f), 5.0f);  // |angles|
  EXPECT_EQ(snell::snellWymanDistance(kNaN, 0.3f, 2.0f, 5.0f), 2.0f);
  EXPECT_EQ(snell::snellWymanDistance(0.1f, kNaN, 2.0f, 5.0f), 2.0f);
  EXPECT_EQ(snell::snellWymanDistance(kInf, kInf, 2.0f, 5.0f), 2.0f);
  EXPECT_EQ(snell::snellWymanDistance(0.1f, kInf, 2.0f, 5.0f), 5.0f);
  EXPECT_EQ(snell::snellWymanDistance(0.1f, 0.2f, kNaN, -3.0f), 0.0f);
  float big = snell::snellWymanDistance(0.1f, 0.2f, kInf, kInf);
  EXPECT_TRUE(std::isfinite(big));
  EXPECT_GE(big, 0.0f);
}

TEST(OpticsWymanDistanceVec, AnglesFromVectors) {
  Rng r;
  for (int k = 0; k < 20000; ++k) {
    vec3 n = r.unit();
    vec3 i = r.unit();
    if (glm::dot(i, n) > 0.0f) n = -n;
    float eta = r.uniform(0.4f, 1.0f);
    // The refracted direction, built independently in double from angles.
    dvec3 di = glm::normalize(dvec3(i)), dn = glm::normalize(dvec3(n));
    double cosI = -glm::dot(di, dn);
    dvec3 tang = di + cosI * dn;
    double sinI = glm::length(tang);
    if (sinI < 1e-3 || cosI < 1e-3) continue;
    double thetaI = std::asin(std::min(sinI, 1.0));
    double thetaT = std::asin(double(eta) * sinI);
    dvec3 t = std::sin(thetaT) * tang / sinI - std::cos(thetaT) * dn;
    float dV = r.uniform(0.0f, 5.0f), dN = r.uniform(0.0f, 5.0f);
    double q = thetaT / thetaI;
    double want = q * double(dV) + (1.0 - q) * double(dN);
    float got = snell::snellWymanDistanceVec(i, n, vec3(t), dV, dN);
    EXPECT_NEAR(got, want, 2e-4 * (1.0 + std::fabs(double(dV) - double(dN)))) << thetaI;
    // The normal's orientation does not matter.
    EXPECT_NEAR(snell::snellWymanDistanceVec(i, -n, vec3(t), dV, dN), got, 1e-6f);
  }
}

TEST(OpticsWymanDistanceVec, BadInputsGiveDv) {
  const vec3 i(0.3f, -1, 0), n(0, 1, 0), t(0.2f, -1, 0);
  for (vec3 b : {vec3(0.0f), vec3(kNaN, 0, 0), vec3(kInf, 0, 0)}) {
    EXPECT_EQ(snell::snellWymanDistanceVec(b, n, t, 2.0f, 5.0f), 2.0f);
    EXPECT_EQ(snell::snellWymanDistanceVec(i, b, t, 2.0f, 5.0f), 2.0f);
    EXPECT_EQ(snell::snellWymanDistanceVec(i, n, b, 2.0f, 5.0f), 2.0f);
  }
  // Normal incidence.
  EXPECT_EQ(snell::snellWymanDistanceVec(vec3(0, -1, 0), n, vec3(0, -1, 0), 2.0f, 5.0f), 2.0f);
}

// --- ice normal blend -------------------------------------------------------------

TEST(OpticsIceNormalBlend, MatchesEquation1) {
  Rng r;
  for (int k = 0; k < 20000; ++k) {
    vec3 f = r.unit() * r.uniform(0.1f, 10.0f), b = r.unit() * r.uniform(0.1f, 10.0f);
    float a = r.uniform(0.0f, 1.0f);
    dvec3 nf = glm::normalize(dvec3(f)), nb = glm::normalize(dvec3(b));
    dvec3 raw = (1.0 - double(a)) * nf - double(a) * nb;
    if (glm::length(raw) < 1e-2) continue;
    dvec3 want = glm::normalize(raw);
    EXPECT_NEAR(glm::length(dvec3(snell::snellIceNormalBlend(f, b, a)) - want), 0.0, 2e-5);
  }
}

TEST(OpticsIceNormalBlend, DefaultAndLimits) {
  vec3 f(0, 0, 1), b(0.6f, 0, -0.8f);
  EXPECT_EQ(snell::snellIceNormalBlend(f, b), snell::snellIceNormalBlend(f, b, 0.33f));
  EXPECT_EQ(snell::snellIceNormalBlend(f, b, 0.0f), f);
  vec3 one = snell::snellIceNormalBlend(f, b, 1.0f);
  EXPECT_NEAR(glm::length(dvec3(one) + dvec3(b)), 0.0, 1e-6);
  EXPECT_EQ(snell::snellIceNormalBlend(f, b, 2.0f), one);             // clamped
  EXPECT_EQ(snell::snellIceNormalBlend(f, b, -1.0f), f);              // clamped
  EXPECT_EQ(snell::snellIceNormalBlend(f, b, kNaN), snell::snellIceNormalBlend(f, b));  // NaN: default
  EXPECT_EQ(snell::snellIceNormalBlend(f, f, 0.5f), f);               // degenerate: front
  for (vec3 bad : {vec3(0.0f), vec3(kNaN, 0, 0), vec3(kInf, 0, 0)}) {
    EXPECT_EQ(snell::snellIceNormalBlend(bad, b, 0.33f), vec3(0.0f));
    EXPECT_EQ(snell::snellIceNormalBlend(f * 3.0f, bad, 0.33f), f);
  }
}

// --- Beer-Lambert -----------------------------------------------------------------

TEST(OpticsBeerLambert, MatchesExp) {
  Rng r;
  for (int k = 0; k < 20000; ++k) {
    vec3 s(r.uniform(0, 5), r.uniform(0, 5), r.uniform(0, 5));
    float dist = r.uniform(0, 10);
    vec3 got = snell::snellBeerLambert(s, dist);
    for (int c = 0; c < 3; ++c) {
      double want = std::exp(-double(s[c]) * double(dist));
      EXPECT_NEAR(got[c], want, 1e-6 + 1e-5 * want);
    }
  }
}

TEST(OpticsBeerLambert, BadInputs) {
  const vec3 s(0.5f, 1.0f, 2.0f);
  EXPECT_EQ(snell::snellBeerLambert(s, -1.0f), vec3(1.0f));
  EXPECT_EQ(snell::snellBeerLambert(s, kNaN), vec3(1.0f));
  EXPECT_EQ(snell::snellBeerLambert(s, -kInf), vec3(1.0f));
  EXPECT_EQ(snell::snellBeerLambert(s, kInf), vec3(0.0f));
  EXPECT_EQ(snell::snellBeerLambert(vec3(kInf, kNaN, -1.0f), 0.0f), vec3(1.0f));
  EXPECT_EQ(snell::snellBeerLambert(vec3(kInf, kNaN, -1.0f), 2.0f), vec3(0.0f, 1.0f, 1.0f));
  EXPECT_EQ(snell::snellBeerLambert(vec3(0.0f), kInf), vec3(1.0f));
  vec3 all = snell::snellBeerLambert(vec3(3e38f), 3e38f);
  EXPECT_TRUE(finite(all));
  EXPECT_EQ(all, vec3(0.0f));
}

}  // namespace
