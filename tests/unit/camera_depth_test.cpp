// glsl/snell/camera/linearize_depth.glsl and depth_to_ndc_z.glsl, checked against
// GLM's projection matrices evaluated in double (glm::perspective,
// perspectiveZO, infinitePerspective) and against the analytic reversed-Z
// formulas, never against the functions' own output.
#include <gtest/gtest.h>

#include <snell/camera.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>
#include <random>

namespace {

using snell::snellDelinearizeDepth;
using snell::snellDepthToNdcZ;
using snell::snellLinearizeDepth;
using snell::snellNdcZToDepth;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kFltMax = std::numeric_limits<float>::max();

const int kFinite[] = {SNELL_DEPTH_GL, SNELL_DEPTH_ZERO_ONE, SNELL_DEPTH_REVERSED};
const int kAll[] = {SNELL_DEPTH_GL, SNELL_DEPTH_ZERO_ONE, SNELL_DEPTH_REVERSED, SNELL_DEPTH_INFINITE_GL,
                    SNELL_DEPTH_INFINITE_REVERSED};

bool isInfinite(int c) { return c == SNELL_DEPTH_INFINITE_GL || c == SNELL_DEPTH_INFINITE_REVERSED; }
bool isReversed(int c) { return c == SNELL_DEPTH_REVERSED || c == SNELL_DEPTH_INFINITE_REVERSED; }

// The depth-buffer value of the view-space point (0, 0, -v): projected with the
// GLM matrix of the convention in double, divided by w, mapped to window depth
// with the default glDepthRange(0, 1). Reversed Z with a finite far plane is
// glm::perspectiveZO with near and far swapped; infinite reversed Z has no GLM
// matrix and uses the analytic n / v.
double referenceDepth(double v, double n, double f, int convention) {
  const double fovy = 1.0, aspect = 1.5;
  glm::dmat4 m(1.0);
  bool glNdc = false;
  switch (convention) {
    case SNELL_DEPTH_GL: m = glm::perspective(fovy, aspect, n, f); glNdc = true; break;
    case SNELL_DEPTH_ZERO_ONE: m = glm::perspectiveZO(fovy, aspect, n, f); break;
    case SNELL_DEPTH_REVERSED: m = glm::perspectiveZO(fovy, aspect, f, n); break;
    case SNELL_DEPTH_INFINITE_GL: m = glm::infinitePerspective(fovy, aspect, n); glNdc = true; break;
    default: return n / v;
  }
  const glm::dvec4 clip = m * glm::dvec4(0.0, 0.0, -v, 1.0);
  const double ndcZ = clip.z / clip.w;
  return glNdc ? 0.5 * ndcZ + 0.5 : ndcZ;
}

struct Camera {
  float n, f;
};

Camera randomCamera(std::mt19937& rng) {
  std::uniform_real_distribution<float> logNear(-3.0f, 1.0f), logRatio(0.2f, 6.0f);
  const float n = std::pow(10.0f, logNear(rng));
  return {n, n * std::pow(10.0f, logRatio(rng))};
}

float randomDistance(std::mt19937& rng, Camera c) {
  std::uniform_real_distribution<float> t(0.0f, 1.0f);
  return std::min(c.f, c.n * std::pow(c.f / c.n, t(rng)));
}

TEST(CameraDepth, DelinearizeMatchesGlmProjection) {
  std::mt19937 rng(1);
  for (int i = 0; i < 20000; ++i) {
    const Camera c = randomCamera(rng);
    const float v = randomDistance(rng, c);
    for (int conv : kAll) {
      const double expected = referenceDepth(v, c.n, c.f, conv);
      const float got = snellDelinearizeDepth(v, c.n, c.f, conv);
      // A few float ulps of 1 (the map is well conditioned from distance to depth;
      // the reference itself rounds f - n etc. in double only).
      ASSERT_NEAR(got, expected, 5e-7) << "conv " << conv << " n " << c.n << " f " << c.f << " v " << v;
    }
  }
}

TEST(CameraDepth, LinearizeMatchesGlmProjection) {
  std::mt19937 rng(2);
  for (int i = 0; i < 20000; ++i) {
    const Camera c = randomCamera(rng);
    const float v = randomDistance(rng, c);
    for (int conv : kAll) {
      // Depth of v as GLM computes it, then rounded to what a float depth buffer stores.
      const double dExact = referenceDepth(v, c.n, c.f, conv);
      const float d = static_cast<float>(dExact);
      // The distance that d really encodes differs from v by the rounding of d
      // times dv/dd (large near the far plane: depth precision, not an error of
      // the function). dv/dd from the reference by central differences in double.
      const double vd = v;
      const double h = 1e-4 * vd;
      const double dvdd =
          2.0 * h / std::abs(referenceDepth(vd + h, c.n, c.f, conv) - referenceDepth(vd - h, c.n, c.f, conv));
      const double quantization = std::abs(static_cast<double>(d) - dExact) * dvdd;
      // Where one float depth step spans more than 1% of the distance the
      // linearization of that step is inaccurate and the depth says little anyway.
      if (quantization > 0.01 * vd) continue;
      const double tol = quantization * 1.05 + 4e-7 * vd;
      const float got = snellLinearizeDepth(d, c.n, c.f, conv);
      ASSERT_NEAR(got, v, tol) << "conv " << conv << " n " << c.n << " f " << c.f << " d " << d;
    }
  }
}

TEST(CameraDepth, RoundTrips) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int i = 0; i < 20000; ++i) {
    const Camera c = randomCamera(rng);
    for (int conv : kAll) {
      // depth -> distance -> depth: well conditioned, a few ulps of 1.
      const float d = unit(rng);
      const float v = snellLinearizeDepth(d, c.n, c.f, conv);
      ASSERT_GE(v, c.n);
      if (!isInfinite(conv)) {
        ASSERT_LE(v, c.f);
      }
      ASSERT_NEAR(snellDelinearizeDepth(v, c.n, c.f, conv), d, 1e-6) << conv;
      // distance -> depth -> distance: relative error grows with dv/dd, so only
      // where depth resolves distance well (within 10 near-distances).
      const float w = c.n * (1.0f + 9.0f * unit(rng));
      if (w < c.f) {
        const float back = snellLinearizeDepth(snellDelinearizeDepth(w, c.n, c.f, conv), c.n, c.f, conv);
        const double wd = w;
        ASSERT_NEAR(back, w, 2e-5 * wd * (isInfinite(conv) ? 1.0 : 1.0 + wd / double(c.n))) << conv;
      }
    }
  }
}

TEST(CameraDepth, AnalyticReversedAndInfinite) {
  // Reversed Z (finite): d = n (f - v) / (v (f - n)); infinite GL: d = 1 - n / v;
  // infinite reversed: d = n / v (written out here, independent of the GLM path).
  const double n = 0.1, f = 100.0;
  for (double v : {0.1, 0.2, 1.0, 7.5, 50.0, 99.0, 100.0}) {
    EXPECT_NEAR(snellDelinearizeDepth(float(v), float(n), float(f), SNELL_DEPTH_REVERSED), n * (f - v) / (v * (f - n)), 1e-7);
    EXPECT_NEAR(snellDelinearizeDepth(float(v), float(n), float(f), SNELL_DEPTH_INFINITE_GL), 1.0 - n / v, 1e-7);
    EXPECT_NEAR(snellDelinearizeDepth(float(v), float(n), float(f), SNELL_DEPTH_INFINITE_REVERSED), n / v, 1e-7);
  }
  for (double dd : {0.0, 0.001, 0.25, 0.5, 0.9, 0.999}) {
    const double d = double(float(dd));  // the value the function receives
    EXPECT_NEAR(snellLinearizeDepth(float(d), float(n), float(f), SNELL_DEPTH_INFINITE_GL), n / (1.0 - d), 1e-6 * n / (1.0 - d));
    const double vr = n * f / (n + d * (f - n));
    EXPECT_NEAR(snellLinearizeDepth(float(d), float(n), float(f), SNELL_DEPTH_REVERSED), vr, 1e-6 * vr);
  }
  for (double dd : {1.0, 0.5, 0.01, 1e-6}) {
    const double d = double(float(dd));
    EXPECT_NEAR(snellLinearizeDepth(float(d), float(n), float(f), SNELL_DEPTH_INFINITE_REVERSED), n / d, 1e-6 * n / d);
  }
}

TEST(CameraDepth, PlanesAndEdgeCases) {
  const float n = 0.5f, f = 200.0f;
  // Depth at the planes.
  EXPECT_FLOAT_EQ(snellLinearizeDepth(0.0f, n, f, SNELL_DEPTH_GL), n);
  EXPECT_FLOAT_EQ(snellLinearizeDepth(1.0f, n, f, SNELL_DEPTH_GL), f);
  EXPECT_FLOAT_EQ(snellLinearizeDepth(0.0f, n, f, SNELL_DEPTH_ZERO_ONE), n);
  EXPECT_FLOAT_EQ(snellLinearizeDepth(1.0f, n, f, SNELL_DEPTH_ZERO_ONE), f);
  EXPECT_FLOAT_EQ(snellLinearizeDepth(1.0f, n, f, SNELL_DEPTH_REVERSED), n);
  EXPECT_FLOAT_EQ(snellLinearizeDepth(0.0f, n, f, SNELL_DEPTH_REVERSED), f);
  EXPECT_FLOAT_EQ(snellLinearizeDepth(0.0f, n, f, SNELL_DEPTH_INFINITE_GL), n);
  EXPECT_FLOAT_EQ(snellLinearizeDepth(1.0f, n, f, SNELL_DEPTH_INFINITE_REVERSED), n);
  // The far plane of an infinite convention: the largest finite float.
  EXPECT_EQ(snellLinearizeDepth(1.0f, n, f, SNELL_DEPTH_INFINITE_GL), kFltMax);
  EXPECT_EQ(snellLinearizeDepth(0.0f, n, f, SNELL_DEPTH_INFINITE_REVERSED), kFltMax);
  // Infinite conventions ignore zFar entirely (NaN, below near).
  EXPECT_FLOAT_EQ(snellLinearizeDepth(0.5f, n, kNaN, SNELL_DEPTH_INFINITE_GL), 2.0f * n);
  EXPECT_FLOAT_EQ(snellLinearizeDepth(0.5f, n, 0.0f, SNELL_DEPTH_INFINITE_REVERSED), 2.0f * n);
  // Out of range depth clamps into [0, 1].
  for (int conv : kAll) {
    EXPECT_EQ(snellLinearizeDepth(-3.0f, n, f, conv), snellLinearizeDepth(0.0f, n, f, conv)) << conv;
    EXPECT_EQ(snellLinearizeDepth(7.0f, n, f, conv), snellLinearizeDepth(1.0f, n, f, conv)) << conv;
    EXPECT_EQ(snellLinearizeDepth(-kInf, n, f, conv), snellLinearizeDepth(0.0f, n, f, conv)) << conv;
    EXPECT_EQ(snellLinearizeDepth(kInf, n, f, conv), snellLinearizeDepth(1.0f, n, f, conv)) << conv;
  }
  // Invalid input: 0 (never a valid distance).
  for (int conv : kAll) {
    EXPECT_EQ(snellLinearizeDepth(kNaN, n, f, conv), 0.0f);
    EXPECT_EQ(snellLinearizeDepth(0.5f, 0.0f, f, conv), 0.0f);
    EXPECT_EQ(snellLinearizeDepth(0.5f, -1.0f, f, conv), 0.0f);
    EXPECT_EQ(snellLinearizeDepth(0.5f, kNaN, f, conv), 0.0f);
    EXPECT_EQ(snellLinearizeDepth(0.5f, kInf, f, conv), 0.0f);
  }
  for (int conv : kFinite) {
    EXPECT_EQ(snellLinearizeDepth(0.5f, n, n, conv), 0.0f);
    EXPECT_EQ(snellLinearizeDepth(0.5f, n, 0.1f, conv), 0.0f);
    EXPECT_EQ(snellLinearizeDepth(0.5f, n, kInf, conv), 0.0f);
    EXPECT_EQ(snellLinearizeDepth(0.5f, n, kNaN, conv), 0.0f);
  }
  EXPECT_EQ(snellLinearizeDepth(0.5f, n, f, 17), 0.0f);
  EXPECT_EQ(snellLinearizeDepth(0.5f, n, f, -1), 0.0f);

  // Delinearize: near plane / behind camera -> near value; beyond far -> far value.
  for (int conv : kAll) {
    const float nearValue = isReversed(conv) ? 1.0f : 0.0f;
    const float farValue = isReversed(conv) ? 0.0f : 1.0f;
    EXPECT_EQ(snellDelinearizeDepth(n, n, f, conv), nearValue) << conv;
    EXPECT_EQ(snellDelinearizeDepth(0.0f, n, f, conv), nearValue) << conv;
    EXPECT_EQ(snellDelinearizeDepth(-5.0f, n, f, conv), nearValue) << conv;
    EXPECT_EQ(snellDelinearizeDepth(-kInf, n, f, conv), nearValue) << conv;
    EXPECT_EQ(snellDelinearizeDepth(kInf, n, f, conv), farValue) << conv;
    EXPECT_EQ(snellDelinearizeDepth(kNaN, n, f, conv), farValue) << conv;
    EXPECT_EQ(snellDelinearizeDepth(1.0f, kNaN, f, conv), farValue) << conv;
    EXPECT_EQ(snellDelinearizeDepth(1.0f, -1.0f, f, conv), farValue) << conv;
    if (!isInfinite(conv)) {
      EXPECT_EQ(snellDelinearizeDepth(f, n, f, conv), farValue) << conv;
      EXPECT_EQ(snellDelinearizeDepth(1e30f, n, f, conv), farValue) << conv;
      EXPECT_EQ(snellDelinearizeDepth(1.0f, n, 0.25f, conv), farValue) << conv;
    } else {
      const float d = snellDelinearizeDepth(kFltMax, n, f, conv);
      EXPECT_NEAR(d, farValue, 1e-30) << conv;
    }
  }
  EXPECT_EQ(snellDelinearizeDepth(1.0f, n, f, 9), 1.0f);
}

TEST(CameraDepth, NdcZMapping) {
  // GL: window depth = 0.5 z_ndc + 0.5 (glDepthRange(0,1)); 0..1 conventions: identity.
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int i = 0; i < 1000; ++i) {
    const float d = unit(rng);
    EXPECT_EQ(snellDepthToNdcZ(d, SNELL_DEPTH_GL), 2.0f * d - 1.0f);
    EXPECT_EQ(snellDepthToNdcZ(d, SNELL_DEPTH_INFINITE_GL), 2.0f * d - 1.0f);
    EXPECT_EQ(snellDepthToNdcZ(d, SNELL_DEPTH_ZERO_ONE), d);
    EXPECT_EQ(snellDepthToNdcZ(d, SNELL_DEPTH_REVERSED), d);
    EXPECT_EQ(snellDepthToNdcZ(d, SNELL_DEPTH_INFINITE_REVERSED), d);
    EXPECT_NEAR(snellNdcZToDepth(snellDepthToNdcZ(d, SNELL_DEPTH_GL), SNELL_DEPTH_GL), d, 1e-7);
    EXPECT_EQ(snellNdcZToDepth(d, SNELL_DEPTH_REVERSED), d);
  }
  // The GL NDC z of glm::perspective maps to the same window depth as perspectiveZO
  // (the conventions store the same value for the same point).
  const glm::dmat4 gl = glm::perspective(1.0, 1.0, 0.3, 40.0);
  const glm::dmat4 zo = glm::perspectiveZO(1.0, 1.0, 0.3, 40.0);
  for (double v : {0.3, 0.5, 3.0, 39.0}) {
    const glm::dvec4 a = gl * glm::dvec4(0, 0, -v, 1), b = zo * glm::dvec4(0, 0, -v, 1);
    EXPECT_NEAR(snellNdcZToDepth(float(a.z / a.w), SNELL_DEPTH_GL), b.z / b.w, 2e-7);
  }
  // Clamping and NaN.
  EXPECT_EQ(snellDepthToNdcZ(2.0f, SNELL_DEPTH_GL), 1.0f);
  EXPECT_EQ(snellDepthToNdcZ(-2.0f, SNELL_DEPTH_ZERO_ONE), 0.0f);
  EXPECT_EQ(snellDepthToNdcZ(kNaN, SNELL_DEPTH_GL), -1.0f);
  EXPECT_EQ(snellDepthToNdcZ(kNaN, SNELL_DEPTH_REVERSED), 0.0f);
  EXPECT_EQ(snellNdcZToDepth(-5.0f, SNELL_DEPTH_GL), 0.0f);
  EXPECT_EQ(snellNdcZToDepth(kInf, SNELL_DEPTH_GL), 1.0f);
  EXPECT_EQ(snellNdcZToDepth(-0.5f, SNELL_DEPTH_ZERO_ONE), 0.0f);
  EXPECT_EQ(snellNdcZToDepth(1.05f, SNELL_DEPTH_ZERO_ONE), 1.0f);
  EXPECT_EQ(snellNdcZToDepth(kInf, SNELL_DEPTH_REVERSED), 1.0f);
  EXPECT_EQ(snellNdcZToDepth(kNaN, SNELL_DEPTH_INFINITE_GL), 0.0f);
  EXPECT_EQ(snellNdcZToDepth(kNaN, SNELL_DEPTH_ZERO_ONE), 0.0f);
}

// The smallest normal zNear is a positive near plane (only denormals count as 0):
// depth 0 is the near plane itself, and a point at twice that distance has infinite
// reversed depth n / v = 1/2 exactly.
TEST(CameraDepth, SmallestNormalNearPlaneIsValid) {
  const float n = std::numeric_limits<float>::min();
  EXPECT_EQ(snellLinearizeDepth(0.0f, n, 1.0f, SNELL_DEPTH_GL), n);
  EXPECT_EQ(snellLinearizeDepth(0.5f, n, 1.0f, SNELL_DEPTH_INFINITE_REVERSED), 2.0f * n);
  EXPECT_EQ(snellDelinearizeDepth(2.0f * n, n, 1.0f, SNELL_DEPTH_INFINITE_REVERSED), 0.5f);
  EXPECT_EQ(snellDelinearizeDepth(4.0f * n, n, 1.0f, SNELL_DEPTH_INFINITE_GL), 0.75f);
}

// SNELL_DEPTH_CONVENTION_COUNT is one past the last convention: unknown, so the
// clear value 1; and zFar == zNear is an empty depth range (invalid) whatever the
// distance, also one nearer than the near plane.
TEST(CameraDepth, DelinearizeRejectsCountConventionAndEmptyRange) {
  EXPECT_EQ(snellLinearizeDepth(0.5f, 1.0f, 10.0f, SNELL_DEPTH_CONVENTION_COUNT), 0.0f);
  EXPECT_EQ(snellDelinearizeDepth(2.0f, 1.0f, 10.0f, SNELL_DEPTH_CONVENTION_COUNT), 1.0f);
  for (int conv : kFinite) {
    const float farValue = isReversed(conv) ? 0.0f : 1.0f;
    for (float v : {0.5f, 1.0f, 2.0f}) {
      EXPECT_EQ(snellDelinearizeDepth(v, 1.0f, 1.0f, conv), farValue) << conv << " v " << v;
    }
  }
}

// Depth is a value in [0, 1], and the far plane gives exactly the far value: the
// GL/ZERO_ONE form multiplies two rounded quotients, which can land an ulp off 1
// at the far plane and an ulp above 1 just nearer than it.
TEST(CameraDepth, DelinearizeNeverExceedsOneAtTheFarPlane) {
  std::mt19937 rng(5);
  for (int i = 0; i < 20000; ++i) {
    const Camera c = randomCamera(rng);
    for (int conv : kFinite) {
      const float farValue = isReversed(conv) ? 0.0f : 1.0f;
      ASSERT_EQ(snellDelinearizeDepth(c.f, c.n, c.f, conv), farValue) << conv << " n " << c.n << " f " << c.f;
      const float below = std::nextafter(c.f, 0.0f);
      const float d = snellDelinearizeDepth(below, c.n, c.f, conv);
      ASSERT_GE(d, 0.0f);
      ASSERT_LE(d, 1.0f) << conv << " n " << c.n << " f " << c.f;
      ASSERT_NEAR(d, referenceDepth(below, c.n, c.f, conv), 5e-7);
    }
  }
}

}  // namespace
