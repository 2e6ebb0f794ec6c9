// glsl/snell/camera/tex_ray.glsl (Oliveira & Brauwers 2007, eqs. 3-10): S and E
// recomputed from eqs. 3-4 in double, and the uv of eq. 10 checked against the
// projection, with glm::perspective in double, of the point P of the segment at
// the same z (eq. 5); alpha against the image-space ratio |t - t's| / |t'e - t's|.
#include <gtest/gtest.h>

#include <snell/camera.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>
#include <random>

namespace {

using namespace snell;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

glm::dvec2 projectUv(const glm::dmat4& proj, const glm::dvec3& p) {
  const glm::dvec4 c = proj * glm::dvec4(p, 1.0);
  return glm::dvec2(c.x, c.y) / c.w * 0.5 + 0.5;
}

void expectZeroInvalid(const SnellTexRay& r) {
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.s, glm::vec3(0.0f));
  EXPECT_EQ(r.e, glm::vec3(0.0f));
  EXPECT_EQ(r.k1, 0.0f);
  EXPECT_EQ(r.k2, 0.0f);
  EXPECT_EQ(r.ts, glm::vec2(0.0f));
  EXPECT_EQ(r.dt, glm::vec2(0.0f));
  EXPECT_EQ(snellTexRayAlpha(r, -1.0f), 0.0f);
  EXPECT_EQ(snellTexRayUv(r, -1.0f), glm::vec2(0.0f));
}

TEST(CameraTexRay, UvEqualsProjectionOfThePointAtThatDepth) {
  std::mt19937 rng(20);
  std::uniform_real_distribution<float> u(0.0f, 1.0f), s(-1.0f, 1.0f);
  int checked = 0;
  for (int i = 0; i < 5000; ++i) {
    const float fovy = 0.3f + 2.0f * u(rng), aspect = 0.5f + 2.0f * u(rng);
    const float n = 0.05f + u(rng), f = n * (20.0f + 1000.0f * u(rng));
    const int conv = static_cast<int>(u(rng) * 4.999f);  // any convention: x, y, w do not depend on it
    const glm::mat4 m = snellPerspectiveWithDepth(fovy, aspect, n, f, conv);
    const glm::dmat4 proj = glm::perspective(double(fovy), double(aspect), double(n), double(f));
    // The front-face hit P1 somewhere in the frustum, a refracted direction
    // heading away from the camera (mostly), and the back-face depth range behind P1.
    const float d1 = n * (1.5f + 30.0f * u(rng));
    const float th = std::tan(fovy * 0.5f);
    const glm::vec3 p1(s(rng) * d1 * th * aspect, s(rng) * d1 * th, -d1);
    glm::vec3 t1(s(rng), s(rng), -0.05f - u(rng));
    if (u(rng) < 0.1f) t1.z = -1e-3f;  // nearly parallel to the planes: long segment
    const float zNearest = p1.z - d1 * 0.5f * u(rng);
    const float zFarthest = zNearest - d1 * (u(rng) < 0.1f ? 1e-3f * u(rng) : 2.0f * u(rng));
    const SnellTexRay r = snellTexRaySetup(p1, t1, zNearest, zFarthest, m);
    ASSERT_TRUE(r.valid);

    // Eqs. 3-4 in double.
    const glm::dvec3 P1(p1), T1(t1);
    const glm::dvec3 S = P1 + (double(zNearest) - P1.z) * (T1 / T1.z);
    const glm::dvec3 E = P1 + (double(zFarthest) - P1.z) * (T1 / T1.z);
    const double scale = std::max(1.0, glm::length(S) + glm::length(E));
    for (int k = 0; k < 3; ++k) {
      ASSERT_NEAR(r.s[k], S[k], 1e-6 * scale);
      ASSERT_NEAR(r.e[k], E[k], 1e-6 * scale);
    }
    ASSERT_EQ(r.s.z, zNearest);
    ASSERT_EQ(r.e.z, zFarthest);
    // k1, k2 of eq. 9.
    ASSERT_NEAR(r.k1, 1.0 / S.z, 1e-6 * std::abs(1.0 / S.z));
    const double k2 = S.z * E.z / (S.z - E.z);
    ASSERT_NEAR(r.k2, k2, 1e-6 * std::abs(k2));
    // t's and dt (eq. 10) from the double projection.
    const glm::dvec2 ts = projectUv(proj, S), te = projectUv(proj, E);
    const double uvScale = std::max(1.0, glm::length(ts) + glm::length(te));
    ASSERT_NEAR(r.ts.x, ts.x, 2e-6 * uvScale);
    ASSERT_NEAR(r.ts.y, ts.y, 2e-6 * uvScale);
    ASSERT_NEAR(r.dt.x, te.x - ts.x, 4e-6 * uvScale);
    ASSERT_NEAR(r.dt.y, te.y - ts.y, 4e-6 * uvScale);

    for (int j = 0; j < 8; ++j) {
      // P = (1 - beta) S + beta E (eq. 5), beta in [-0.25, 1.25] (extrapolation too).
      const double beta = -0.25 + 1.5 * double(u(rng));
      const float pz = static_cast<float>((1.0 - beta) * S.z + beta * E.z);
      if (!(pz < 0.0f)) continue;
      // The point of the line at exactly the float z the function receives.
      const double b = (double(pz) - S.z) / (E.z - S.z);
      const glm::dvec3 P = (1.0 - b) * S + b * E;
      const glm::dvec2 uvTrue = projectUv(proj, P);
      const glm::vec2 uv = snellTexRayUv(r, pz);
      ASSERT_NEAR(uv.x, uvTrue.x, 1e-5 * uvScale) << i << " beta " << beta;
      ASSERT_NEAR(uv.y, uvTrue.y, 1e-5 * uvScale) << i << " beta " << beta;
      // alpha: position of t along ts -> te in image space (beta != alpha).
      const glm::dvec2 d = te - ts;
      if (glm::length(d) > 1e-3) {
        const double alphaTrue = glm::dot(uvTrue - ts, d) / glm::dot(d, d);
        ASSERT_NEAR(snellTexRayAlpha(r, pz), alphaTrue, 1e-5 * std::max(1.0, std::abs(alphaTrue))) << i;
        ++checked;
      }
    }
    // End points: alpha 0 at S.z, 1 at E.z (when the segment is not a point).
    ASSERT_EQ(snellTexRayAlpha(r, zNearest), 0.0f);
    if (zFarthest != zNearest) {
      ASSERT_NEAR(snellTexRayAlpha(r, zFarthest), 1.0f, 1e-6f);
    }
  }
  EXPECT_GT(checked, 20000);
}

TEST(CameraTexRay, AlphaIsNotBeta) {
  // Perspective: equal steps in 3D are unequal in the image (paper, Figure 5).
  const glm::mat4 m = snellPerspective(1.0f, 1.0f, 0.1f, 100.0f);
  const SnellTexRay r = snellTexRaySetup(glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(1.0f, 0.0f, -1.0f), -1.0f, -9.0f, m);
  ASSERT_TRUE(r.valid);
  const float mid = snellTexRayAlpha(r, -5.0f);  // beta = 0.5
  // From eq. 8: 1/Pz = (1-alpha)/Sz + alpha/Ez  =>  alpha = (1/5 - 1)/(1/9 - 1) = 0.9.
  EXPECT_NEAR(mid, 0.9f, 1e-6f);
}

TEST(CameraTexRay, DegenerateAndHostileInputs) {
  const glm::mat4 m = snellPerspective(1.0f, 1.5f, 0.1f, 100.0f);
  const glm::vec3 p1(0.2f, -0.1f, -2.0f), t1(0.3f, 0.1f, -1.0f);
  // zNearest == zFarthest: S == E, k2 = 0, alpha = 0 and uv = t's for every pz.
  const SnellTexRay pt = snellTexRaySetup(p1, t1, -3.0f, -3.0f, m);
  EXPECT_TRUE(pt.valid);
  EXPECT_EQ(pt.s, pt.e);
  EXPECT_EQ(pt.k2, 0.0f);
  EXPECT_EQ(pt.dt, glm::vec2(0.0f));
  for (float pz : {-3.0f, -1.0f, -50.0f, -1e-30f, 0.0f, 1.0f, kNaN}) {
    EXPECT_EQ(snellTexRayAlpha(pt, pz), 0.0f);
    EXPECT_EQ(snellTexRayUv(pt, pz), pt.ts);
  }
  // T1.z == 0: parallel to the planes, never reaches them.
  expectZeroInvalid(snellTexRaySetup(p1, glm::vec3(1.0f, 0.0f, 0.0f), -3.0f, -5.0f, m));
  expectZeroInvalid(snellTexRaySetup(p1, glm::vec3(1.0f, 0.0f, -0.0f), -3.0f, -5.0f, m));
  expectZeroInvalid(snellTexRaySetup(p1, glm::vec3(0.0f), -3.0f, -5.0f, m));
  // T1.z so small that S is at infinity: overflow -> invalid, finite fields.
  expectZeroInvalid(snellTexRaySetup(p1, glm::vec3(1.0f, 0.0f, -1e-38f), -3.0f, -5.0f, m));
  // Planes at or behind the eye.
  expectZeroInvalid(snellTexRaySetup(p1, t1, 0.0f, -5.0f, m));
  expectZeroInvalid(snellTexRaySetup(p1, t1, -1.0f, 0.5f, m));
  expectZeroInvalid(snellTexRaySetup(p1, t1, 2.0f, 1.0f, m));
  // NaN / Inf anywhere.
  expectZeroInvalid(snellTexRaySetup(glm::vec3(kNaN, 0, -1), t1, -3.0f, -5.0f, m));
  expectZeroInvalid(snellTexRaySetup(p1, glm::vec3(0, kInf, -1), -3.0f, -5.0f, m));
  expectZeroInvalid(snellTexRaySetup(p1, t1, kNaN, -5.0f, m));
  expectZeroInvalid(snellTexRaySetup(p1, t1, -3.0f, -kInf, m));
  glm::mat4 bad = m;
  bad[1][1] = kNaN;
  expectZeroInvalid(snellTexRaySetup(p1, t1, -3.0f, -5.0f, bad));
  // Zero matrix (invalid camera): S projects with w = 0.
  expectZeroInvalid(snellTexRaySetup(p1, t1, -3.0f, -5.0f, glm::mat4(0.0f)));

  // The third row (clip z) is never read: NaN there gives the clean segment.
  glm::mat4 zRowNaN = m;
  for (int c = 0; c < 4; ++c) zRowNaN[c][2] = kNaN;
  const SnellTexRay clean = snellTexRaySetup(p1, t1, -3.0f, -5.0f, m);
  const SnellTexRay noZ = snellTexRaySetup(p1, t1, -3.0f, -5.0f, zRowNaN);
  ASSERT_TRUE(clean.valid);
  EXPECT_TRUE(noZ.valid);
  EXPECT_EQ(noZ.s, clean.s);
  EXPECT_EQ(noZ.e, clean.e);
  EXPECT_EQ(noZ.ts, clean.ts);
  EXPECT_EQ(noZ.dt, clean.dt);
  EXPECT_EQ(noZ.k1, clean.k1);
  EXPECT_EQ(noZ.k2, clean.k2);
  // S so close to the eye plane (w = 1e-37) that its ndc x overflows
  // (about 122 / 1e-37): invalid, not clamped to a huge finite uv.
  expectZeroInvalid(snellTexRaySetup(glm::vec3(100.0f, 0.0f, -2.0f), glm::vec3(0.0f, 0.0f, -1.0f), -1e-37f, -5.0f, m));

  // A ray towards the camera: S and E behind P1 on the line, still valid.
  const SnellTexRay back = snellTexRaySetup(p1, glm::vec3(0.0f, 0.0f, 1.0f), -3.0f, -5.0f, m);
  EXPECT_TRUE(back.valid);
  EXPECT_EQ(back.s, glm::vec3(0.2f, -0.1f, -3.0f));

  // pz at or behind the eye, NaN, Inf: alpha 0, uv = t's. Tiny pz: finite.
  const SnellTexRay r = snellTexRaySetup(p1, t1, -3.0f, -5.0f, m);
  ASSERT_TRUE(r.valid);
  for (float pz : {0.0f, -0.0f, 2.0f, kNaN, kInf, -kInf}) {
    EXPECT_EQ(snellTexRayAlpha(r, pz), 0.0f) << pz;
    EXPECT_EQ(snellTexRayUv(r, pz), r.ts) << pz;
  }
  for (float pz : {-1e-30f, -1e-44f, -1e30f}) {
    EXPECT_TRUE(std::isfinite(snellTexRayAlpha(r, pz))) << pz;
    const glm::vec2 uv = snellTexRayUv(r, pz);
    EXPECT_TRUE(std::isfinite(uv.x) && std::isfinite(uv.y)) << pz;
  }
}

constexpr float kFltMin = std::numeric_limits<float>::min();
constexpr float kFltMax = std::numeric_limits<float>::max();

// The smallest normal |T1.z| still reaches the planes: along the optical axis
// S and E are P1 moved to the two planes, (zFarthest - P1.z) / T1.z = 2^126 is finite.
TEST(CameraTexRay, SmallestNormalT1zReachesThePlanes) {
  const glm::mat4 m = snellPerspective(1.0f, 1.0f, 0.1f, 100.0f);
  const SnellTexRay r = snellTexRaySetup(glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 0.0f, -kFltMin), -1.0f, -2.0f, m);
  EXPECT_TRUE(r.valid);
  EXPECT_EQ(r.s, glm::vec3(0.0f, 0.0f, -1.0f));
  EXPECT_EQ(r.e, glm::vec3(0.0f, 0.0f, -2.0f));
  EXPECT_EQ(r.ts, glm::vec2(0.5f));
}

// Planes at the smallest normal z, -FLT_MIN, are in front of the eye (only
// denormal z counts as 0); there clip w = -z = FLT_MIN. On the optical axis,
// from eq. 9, alpha = (1/pz - 1/S.z) S.z E.z / (S.z - E.z) is 0 at S.z and 1 at
// E.z, whichever of the two is the tiny one (k2 is then +-FLT_MIN).
TEST(CameraTexRay, PlanesAtTheSmallestNormalZ) {
  const glm::mat4 m = snellPerspective(1.0f, 1.0f, 0.1f, 100.0f);
  const glm::vec3 p1(0.0f, 0.0f, -0.5f), t1(0.0f, 0.0f, -1.0f);
  const SnellTexRay fromEye = snellTexRaySetup(p1, t1, -kFltMin, -1.0f, m);
  ASSERT_TRUE(fromEye.valid);
  EXPECT_EQ(fromEye.s, glm::vec3(0.0f, 0.0f, -kFltMin));
  EXPECT_EQ(fromEye.ts, glm::vec2(0.5f));
  EXPECT_EQ(fromEye.k2, kFltMin);
  EXPECT_EQ(snellTexRayAlpha(fromEye, -kFltMin), 0.0f);
  EXPECT_EQ(snellTexRayAlpha(fromEye, -1.0f), 1.0f);
  const SnellTexRay toEye = snellTexRaySetup(p1, t1, -1.0f, -kFltMin, m);
  ASSERT_TRUE(toEye.valid);
  EXPECT_EQ(toEye.e, glm::vec3(0.0f, 0.0f, -kFltMin));
  EXPECT_EQ(toEye.dt, glm::vec2(0.0f));
  EXPECT_EQ(snellTexRayAlpha(toEye, -1.0f), 0.0f);
  EXPECT_EQ(snellTexRayAlpha(toEye, -kFltMin), 1.0f);
}

// A point segment on the farthest finite plane, z = -FLT_MAX: clip w = FLT_MAX
// is finite, so the segment is valid (k2 = 0, alpha 0).
TEST(CameraTexRay, PointSegmentAtTheLargestFiniteDepth) {
  const glm::mat4 m = snellPerspective(1.0f, 1.0f, 0.1f, 100.0f);
  const SnellTexRay r = snellTexRaySetup(glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 0.0f, -1.0f), -kFltMax, -kFltMax, m);
  ASSERT_TRUE(r.valid);
  EXPECT_EQ(r.s, glm::vec3(0.0f, 0.0f, -kFltMax));
  EXPECT_EQ(r.e, r.s);
  EXPECT_EQ(r.ts, glm::vec2(0.5f));
  EXPECT_EQ(r.k2, 0.0f);
}

}  // namespace
