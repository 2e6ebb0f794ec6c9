// glsl/snell/camera/perspective.glsl, view_to_clip.glsl, view_to_uv.glsl,
// pixel_to_uv.glsl, uv_depth_to_view.glsl and uv_z_to_view.glsl, checked against GLM (matrices,
// glm::inverse and glm::project in double) and against exact arithmetic.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>

#include <snell/camera.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <limits>
#include <random>

namespace {

using namespace snell;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

const int kAll[] = {SNELL_DEPTH_GL, SNELL_DEPTH_ZERO_ONE, SNELL_DEPTH_REVERSED, SNELL_DEPTH_INFINITE_GL,
                    SNELL_DEPTH_INFINITE_REVERSED};

struct Cam {
  float fovy, aspect, n, f;
};

Cam randomCam(std::mt19937& rng) {
  std::uniform_real_distribution<float> fovy(0.2f, 2.8f), aspect(0.3f, 3.0f), logNear(-2.0f, 0.5f),
      logRatio(1.0f, 3.0f);
  const float n = std::pow(10.0f, logNear(rng));
  return {fovy(rng), aspect(rng), n, n * std::pow(10.0f, logRatio(rng))};
}

// A view-space point inside the frustum, at view distance in [n, f].
glm::vec3 randomPointInFrustum(std::mt19937& rng, const Cam& c) {
  std::uniform_real_distribution<float> t(0.0f, 1.0f), s(-1.0f, 1.0f);
  const float v = c.n * std::pow(c.f / c.n, t(rng));
  const float ty = std::tan(c.fovy * 0.5f);
  return glm::vec3(s(rng) * v * ty * c.aspect, s(rng) * v * ty, -v);
}

// The GLM matrix of each convention in double; reversed Z is perspectiveZO with
// near/far swapped, infinite reversed Z is written out (GLM has none).
glm::dmat4 glmProjection(const Cam& c, int conv) {
  const double fovy = c.fovy, aspect = c.aspect, n = c.n, f = c.f;
  switch (conv) {
    case SNELL_DEPTH_GL: return glm::perspective(fovy, aspect, n, f);
    case SNELL_DEPTH_ZERO_ONE: return glm::perspectiveZO(fovy, aspect, n, f);
    case SNELL_DEPTH_REVERSED: return glm::perspectiveZO(fovy, aspect, f, n);
    case SNELL_DEPTH_INFINITE_GL: return glm::infinitePerspective(fovy, aspect, n);
    default: {
      glm::dmat4 m = glm::perspectiveZO(fovy, aspect, f, n);
      m[2][2] = 0.0;
      m[3][2] = n;
      return m;
    }
  }
}

void expectMatNear(const glm::mat4& got, const glm::dmat4& want, double rel, const char* what) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      EXPECT_NEAR(got[i][j], want[i][j], rel * std::abs(want[i][j]) + 1e-30) << what << " [" << i << "][" << j << "]";
}

// Units in the last place between two floats of the same sign.
std::int64_t ulpDistance(float a, float b) {
  std::int32_t ia = 0, ib = 0;
  std::memcpy(&ia, &a, 4);
  std::memcpy(&ib, &b, 4);
  return std::llabs(static_cast<std::int64_t>(ia) - static_cast<std::int64_t>(ib));
}

// Entries [0][0] and [1][1] (1 / (aspect tan), 1 / tan) within 3 ulp, all others equal.
void expectGlmEntries(const glm::mat4& got, const glm::mat4& glm) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      if ((i == 0 && j == 0) || (i == 1 && j == 1)) {
        ASSERT_LE(ulpDistance(got[i][j], glm[i][j]), 3) << "[" << i << "][" << j << "] " << got[i][j] << " vs " << glm[i][j];
      } else {
        ASSERT_EQ(got[i][j], glm[i][j]) << "[" << i << "][" << j << "]";
      }
    }
}

bool isZero(const glm::mat4& m) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      if (m[i][j] != 0.0f) return false;
  return true;
}

TEST(CameraProjection, PerspectiveMatchesGlm) {
  std::mt19937 rng(10);
  for (int i = 0; i < 2000; ++i) {
    const Cam c = randomCam(rng);
    // Same float operations as GLM: glm::perspective / perspectiveZO's entries bit for bit but for
    // the two that hold tan(fovy/2) (snell's polynomial, std::tan in GLM): within 3 ulp there.
    const glm::mat4 gl = glm::perspective(c.fovy, c.aspect, c.n, c.f);
    ASSERT_EQ(snellPerspective(c.fovy, c.aspect, c.n, c.f), snellPerspectiveWithDepth(c.fovy, c.aspect, c.n, c.f, SNELL_DEPTH_GL));
    expectGlmEntries(snellPerspective(c.fovy, c.aspect, c.n, c.f), gl);
    expectGlmEntries(snellPerspectiveWithDepth(c.fovy, c.aspect, c.n, c.f, SNELL_DEPTH_ZERO_ONE),
                     glm::perspectiveZO(c.fovy, c.aspect, c.n, c.f));
    expectGlmEntries(snellPerspectiveWithDepth(c.fovy, c.aspect, c.n, c.f, SNELL_DEPTH_REVERSED),
                     glm::perspectiveZO(c.fovy, c.aspect, c.f, c.n));
    for (int conv : kAll) {
      expectMatNear(snellPerspectiveWithDepth(c.fovy, c.aspect, c.n, c.f, conv), glmProjection(c, conv), 2e-6,
                    "projection");
      // The analytic inverse against glm::inverse in double.
      expectMatNear(snellPerspectiveInverse(c.fovy, c.aspect, c.n, c.f, conv), glm::inverse(glmProjection(c, conv)),
                    2e-6, "inverse");
    }
  }
}

TEST(CameraProjection, PerspectiveInvalidParametersGiveZeroMatrix) {
  for (int conv : kAll) {
    EXPECT_TRUE(isZero(snellPerspectiveWithDepth(0.0f, 1.0f, 0.1f, 10.0f, conv)));
    EXPECT_TRUE(isZero(snellPerspectiveWithDepth(-1.0f, 1.0f, 0.1f, 10.0f, conv)));
    EXPECT_TRUE(isZero(snellPerspectiveWithDepth(3.2f, 1.0f, 0.1f, 10.0f, conv)));
    EXPECT_TRUE(isZero(snellPerspectiveWithDepth(kNaN, 1.0f, 0.1f, 10.0f, conv)));
    EXPECT_TRUE(isZero(snellPerspectiveWithDepth(1.0f, 0.0f, 0.1f, 10.0f, conv)));
    EXPECT_TRUE(isZero(snellPerspectiveWithDepth(1.0f, kInf, 0.1f, 10.0f, conv)));
    EXPECT_TRUE(isZero(snellPerspectiveWithDepth(1.0f, 1.0f, 0.0f, 10.0f, conv)));
    EXPECT_TRUE(isZero(snellPerspectiveWithDepth(1.0f, 1.0f, -0.1f, 10.0f, conv)));
    EXPECT_TRUE(isZero(snellPerspectiveInverse(1.0f, 1.0f, kNaN, 10.0f, conv)));
  }
  for (int conv : {SNELL_DEPTH_GL, SNELL_DEPTH_ZERO_ONE, SNELL_DEPTH_REVERSED}) {
    EXPECT_TRUE(isZero(snellPerspectiveWithDepth(1.0f, 1.0f, 1.0f, 1.0f, conv)));
    EXPECT_TRUE(isZero(snellPerspectiveWithDepth(1.0f, 1.0f, 1.0f, kInf, conv)));
    EXPECT_TRUE(isZero(snellPerspectiveInverse(1.0f, 1.0f, 2.0f, 1.0f, conv)));
  }
  EXPECT_FALSE(isZero(snellPerspectiveWithDepth(1.0f, 1.0f, 1.0f, kNaN, SNELL_DEPTH_INFINITE_GL)));
  EXPECT_TRUE(isZero(snellPerspectiveWithDepth(1.0f, 1.0f, 0.1f, 10.0f, 5)));
  EXPECT_TRUE(isZero(snellPerspectiveWithDepth(1.0f, 1.0f, 0.1f, 10.0f, -1)));
  // A zero matrix projects everything to w = 0: invalid downstream.
  const glm::mat4 z = snellPerspective(kNaN, 1.0f, 0.1f, 10.0f);
  EXPECT_FALSE(snellViewToUv(z, glm::vec3(0.0f, 0.0f, -1.0f)).valid);
}

// The contract's "a denormal fovy or aspect counts as 0": the zero matrix, as for 0 (a GPU that
// flushes denormals sees 0), where arithmetic on the denormal itself would give finite entries: fovy
// 1.1e-38 has 1 / tan(fovy / 2) = 1.8e38, and aspect 1e-39 beside a fovy just under pi (tan(fovy / 2)
// = 1.3e7) has 1 / (aspect tan) = 7.7e31. The smallest normal values beside them are positive
// parameters, and their matrices hold the textbook entries (computed here in double): the rule, not
// an overflow, is what zeroes the denormal ones.
TEST(CameraProjection, DenormalFovyAndAspectCountAsZero) {
  const float denormalFovy = 1.1e-38f, denormalAspect = 1e-39f;
  const float fovyUnderPi = std::nextafter(SNELL_PI, 0.0f);
  ASSERT_EQ(std::fpclassify(denormalFovy), FP_SUBNORMAL);
  ASSERT_EQ(std::fpclassify(denormalAspect), FP_SUBNORMAL);
  ASSERT_LT(double(fovyUnderPi), 3.14159265358979323846);
  const float smallestNormal = std::numeric_limits<float>::min();
  struct Params {
    float fovy, aspect;
  };
  const Params denormal[] = {{denormalFovy, 1.0f}, {-denormalFovy, 1.0f}, {fovyUnderPi, denormalAspect},
                             {1.0f, denormalAspect}, {std::numeric_limits<float>::denorm_min(), 1.0f}};
  const Params normal[] = {{2.0f * smallestNormal, 1.0f}, {fovyUnderPi, smallestNormal}};
  for (int conv : kAll) {
    for (const Params& p : denormal) {
      SCOPED_TRACE(testing::Message() << "fovy " << p.fovy << " aspect " << p.aspect << " convention " << conv);
      EXPECT_TRUE(isZero(snellPerspectiveWithDepth(p.fovy, p.aspect, 0.1f, 10.0f, conv)));
      EXPECT_TRUE(isZero(snellPerspectiveInverse(p.fovy, p.aspect, 0.1f, 10.0f, conv)));
    }
    for (const Params& p : normal) {
      SCOPED_TRACE(testing::Message() << "fovy " << p.fovy << " aspect " << p.aspect << " convention " << conv);
      const double t = std::tan(0.5 * double(p.fovy));
      const glm::mat4 m = snellPerspectiveWithDepth(p.fovy, p.aspect, 0.1f, 10.0f, conv);
      EXPECT_NEAR(m[0][0], 1.0 / (double(p.aspect) * t), 2e-6 / (double(p.aspect) * t));
      EXPECT_NEAR(m[1][1], 1.0 / t, 2e-6 / t);
      EXPECT_EQ(m[2][3], -1.0f);
      const glm::mat4 inv = snellPerspectiveInverse(p.fovy, p.aspect, 0.1f, 10.0f, conv);
      EXPECT_NEAR(inv[0][0], double(p.aspect) * t, 2e-6 * double(p.aspect) * t);
      EXPECT_NEAR(inv[1][1], t, 2e-6 * t);
    }
  }
}

TEST(CameraProjection, ViewToUvMatchesGlmProject) {
  // glm::project with an identity model matrix and the viewport (0, 0, 1, 1)
  // returns exactly (uv, window depth) under GL conventions.
  std::mt19937 rng(11);
  for (int i = 0; i < 20000; ++i) {
    const Cam c = randomCam(rng);
    const glm::vec3 p = randomPointInFrustum(rng, c);
    const glm::dmat4 proj = glm::perspective(double(c.fovy), double(c.aspect), double(c.n), double(c.f));
    const glm::dvec3 w = glm::projectNO(glm::dvec3(p), glm::dmat4(1.0), proj, glm::dvec4(0, 0, 1, 1));
    const glm::mat4 m = snellPerspective(c.fovy, c.aspect, c.n, c.f);
    const SnellScreenPoint sp = snellViewToUv(m, p);
    ASSERT_TRUE(sp.valid);
    ASSERT_NEAR(sp.uv.x, w.x, 2e-6);
    ASSERT_NEAR(sp.uv.y, w.y, 2e-6);
    ASSERT_NEAR(snellNdcZToDepth(sp.ndcZ, SNELL_DEPTH_GL), w.z, 2e-6);
    // The projected point lies in the viewport and in the depth range.
    ASSERT_GE(sp.uv.x, -1e-6f);
    ASSERT_LE(sp.uv.x, 1.0f + 1e-6f);
    // snellViewToClip is the plain matrix product.
    const glm::vec4 clip = snellViewToClip(m, p);
    const glm::vec4 want = m * glm::vec4(p, 1.0f);
    ASSERT_EQ(clip, want);
  }
}

TEST(CameraProjection, BehindCameraAndHostileInputs) {
  const glm::mat4 m = snellPerspective(1.0f, 1.0f, 0.1f, 100.0f);
  for (glm::vec3 p : {glm::vec3(0, 0, 0), glm::vec3(1, 2, 0), glm::vec3(0, 0, 1), glm::vec3(3, -2, 5),
                      glm::vec3(kNaN, 0, -1), glm::vec3(0, kInf, -1), glm::vec3(0, 0, -kInf)}) {
    const SnellScreenPoint sp = snellViewToUv(m, p);
    EXPECT_FALSE(sp.valid) << p.x << " " << p.y << " " << p.z;
    EXPECT_EQ(sp.uv, glm::vec2(0.0f));
    EXPECT_EQ(sp.ndcZ, 0.0f);
  }
  // w <= 0, NaN, Inf: invalid, ndc zero.
  for (glm::vec4 c : {glm::vec4(1, 1, 1, 0), glm::vec4(1, 1, 1, -0.0f), glm::vec4(1, 1, 1, -2),
                      glm::vec4(kNaN, 0, 0, 1), glm::vec4(0, 0, 0, kNaN), glm::vec4(0, kInf, 0, 1),
                      glm::vec4(0, 0, 0, kInf)}) {
    const SnellNdc n = snellClipToNdc(c);
    EXPECT_FALSE(n.valid);
    EXPECT_EQ(n.ndc, glm::vec3(0.0f));
  }
  // Tiny positive w (a point just in front of the eye's plane): valid, clamped finite.
  const SnellNdc tiny = snellClipToNdc(glm::vec4(1e30f, -1e30f, 0.5f, 1e-30f));
  EXPECT_TRUE(tiny.valid);
  EXPECT_TRUE(std::isfinite(tiny.ndc.x) && std::isfinite(tiny.ndc.y));
  EXPECT_EQ(tiny.ndc.x, std::numeric_limits<float>::max());
  EXPECT_EQ(tiny.ndc.y, -std::numeric_limits<float>::max());
  // Clip z decides nothing: a NaN in the third row leaves uv as with the clean
  // matrix (ndcZ 0), a huge entry there (clip z overflows) clamps ndcZ.
  const glm::vec3 q(0.3f, -0.2f, -2.0f);
  const SnellScreenPoint clean = snellViewToUv(m, q);
  glm::mat4 zNaN = m, zHuge = m;
  zNaN[2][2] = kNaN;
  zHuge[2][2] = 3e38f;
  const SnellScreenPoint noZ = snellViewToUv(zNaN, q), bigZ = snellViewToUv(zHuge, q);
  ASSERT_TRUE(clean.valid);
  EXPECT_TRUE(noZ.valid);
  EXPECT_EQ(noZ.uv, clean.uv);
  EXPECT_EQ(noZ.ndcZ, 0.0f);
  EXPECT_TRUE(bigZ.valid);
  EXPECT_EQ(bigZ.uv, clean.uv);
  EXPECT_EQ(bigZ.ndcZ, -std::numeric_limits<float>::max());
  // A point in front but off screen: valid, uv outside [0,1].
  const SnellScreenPoint off = snellViewToUv(m, glm::vec3(50.0f, 0.0f, -1.0f));
  EXPECT_TRUE(off.valid);
  EXPECT_GT(off.uv.x, 1.0f);
  // Near-plane point: NDC z = -1 (GL), window depth 0.
  const SnellScreenPoint nearPt = snellViewToUv(m, glm::vec3(0.0f, 0.0f, -0.1f));
  EXPECT_TRUE(nearPt.valid);
  EXPECT_NEAR(nearPt.ndcZ, -1.0f, 1e-6f);
}

TEST(CameraProjection, PixelUvRoundTripsAndCentres) {
  std::mt19937 rng(12);
  std::uniform_int_distribution<int> sizeDist(1, 8192);
  for (int i = 0; i < 200; ++i) {
    const glm::ivec2 size(sizeDist(rng), sizeDist(rng));
    std::uniform_int_distribution<int> px(0, size.x - 1), py(0, size.y - 1);
    for (int k = 0; k < 200; ++k) {
      const glm::ivec2 p(px(rng), py(rng));
      const glm::vec2 uv = snellPixelToUv(p, size);
      // Pixel centre (i + 0.5)/W, correctly rounded (float division of exact operands).
      ASSERT_EQ(uv.x, static_cast<float>((p.x + 0.5) / size.x));
      ASSERT_EQ(uv.y, static_cast<float>((p.y + 0.5) / size.y));
      ASSERT_EQ(snellUvToPixel(uv, size), p);
    }
    // Corners.
    ASSERT_EQ(snellUvToPixel(glm::vec2(0.0f), size), glm::ivec2(0));
    ASSERT_EQ(snellUvToPixel(glm::vec2(1.0f), size), size - 1);
  }
  // Exact pixel boundaries (power-of-two size: uv = i/W exact) belong to pixel i.
  const glm::ivec2 s(256, 64);
  for (int x = 0; x < 256; ++x) {
    ASSERT_EQ(snellUvToPixel(glm::vec2(float(x) / 256.0f, float(x % 64) / 64.0f), s), glm::ivec2(x, x % 64));
  }
  // Clamp to edge, NaN, bad sizes.
  EXPECT_EQ(snellUvToPixel(glm::vec2(-0.5f, 1.5f), s), glm::ivec2(0, 63));
  EXPECT_EQ(snellUvToPixel(glm::vec2(kInf, -kInf), s), glm::ivec2(255, 0));
  EXPECT_EQ(snellUvToPixel(glm::vec2(kNaN, 0.5f), s), glm::ivec2(0, 32));
  EXPECT_EQ(snellUvToPixel(glm::vec2(0.5f), glm::ivec2(0, 10)), glm::ivec2(0));
  EXPECT_EQ(snellPixelToUv(glm::ivec2(3, 4), glm::ivec2(0, 10)), glm::vec2(0.0f, 0.45f));
  // Pixels outside the viewport are not clamped by snellPixelToUv.
  EXPECT_EQ(snellPixelToUv(glm::ivec2(-1, 10), glm::ivec2(10, 10)), glm::vec2(-0.05f, 1.05f));
}

TEST(CameraProjection, UvDepthToViewReconstructsGlmProjectedPoints) {
  std::mt19937 rng(13);
  int checked = 0;
  for (int i = 0; i < 20000; ++i) {
    const Cam c = randomCam(rng);
    const glm::vec3 p = randomPointInFrustum(rng, c);
    for (int conv : kAll) {
      // uv and depth-buffer value of p from the GLM matrix in double.
      const glm::dvec4 clip = glmProjection(c, conv) * glm::dvec4(glm::dvec3(p), 1.0);
      const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
      const bool glNdc = conv == SNELL_DEPTH_GL || conv == SNELL_DEPTH_INFINITE_GL;
      const double depth = glNdc ? 0.5 * ndc.z + 0.5 : ndc.z;
      const glm::vec2 uv(glm::dvec2(ndc) * 0.5 + 0.5);
      const float d = static_cast<float>(depth);
      const glm::mat4 inv = snellPerspectiveInverse(c.fovy, c.aspect, c.n, c.f, conv);
      const SnellViewPoint r = snellUvDepthToView(uv, d, inv, conv);
      ASSERT_TRUE(r.valid) << conv;
      // The float depth encodes p's distance only up to its rounding (plus the
      // GL 2d - 1 step): tolerance from dv/dd of the exact depth of this convention.
      const double v = -double(p.z), n = c.n, f = c.f;
      double dvdd = 0.0;
      switch (conv) {
        case SNELL_DEPTH_GL:
        case SNELL_DEPTH_ZERO_ONE: dvdd = v * v * (f - n) / (f * n); break;
        case SNELL_DEPTH_REVERSED: dvdd = v * v * (f - n) / (f * n); break;
        case SNELL_DEPTH_INFINITE_GL: dvdd = v * v / n; break;
        default: dvdd = v * v / n; break;
      }
      // Depth error budget, in units of float ulp(1) = 1.19e-7: 0.5 for storing d, ~2
      // for zc + C wc in the float inverse matrix (C is -1 + O(n/f): cancellation),
      // 1 more for GL's 2d - 1.
      const double relV = (glNdc ? 4 * 1.2e-7 : 3 * 1.2e-7) * dvdd / v;
      if (relV > 0.01) continue;  // depth does not resolve this distance
      ++checked;
      const double tol = (relV * 1.1 + 4e-6) * glm::length(glm::dvec3(p));
      ASSERT_NEAR(r.position.x, p.x, tol) << conv;
      ASSERT_NEAR(r.position.y, p.y, tol) << conv;
      ASSERT_NEAR(r.position.z, p.z, tol) << conv;

      // From the linear distance instead: no depth quantization; z exact.
      const SnellViewPoint q = snellUvDistanceToView(uv, -p.z, inv);
      ASSERT_TRUE(q.valid);
      ASSERT_EQ(q.position.z, p.z);
      const double tol2 = 4e-6 * glm::length(glm::dvec3(p));
      ASSERT_NEAR(q.position.x, p.x, tol2) << conv;
      ASSERT_NEAR(q.position.y, p.y, tol2) << conv;
    }
  }
  EXPECT_GT(checked, 80000);  // of 100,000: most distances are resolved by the depth
}

TEST(CameraProjection, UvDepthToViewEdgeCases) {
  const float n = 0.1f, f = 50.0f;
  for (int conv : kAll) {
    const glm::mat4 inv = snellPerspectiveInverse(1.0f, 1.3f, n, f, conv);
    const bool reversed = conv == SNELL_DEPTH_REVERSED || conv == SNELL_DEPTH_INFINITE_REVERSED;
    // Near plane: z = -n at the centre.
    const SnellViewPoint nearPt = snellUvDepthToView(glm::vec2(0.5f), reversed ? 1.0f : 0.0f, inv, conv);
    EXPECT_TRUE(nearPt.valid);
    EXPECT_NEAR(nearPt.position.z, -n, 1e-6f);
    // Far plane: z = -f (finite), invalid at infinity.
    const SnellViewPoint farPt = snellUvDepthToView(glm::vec2(0.25f), reversed ? 0.0f : 1.0f, inv, conv);
    if (conv == SNELL_DEPTH_INFINITE_GL || conv == SNELL_DEPTH_INFINITE_REVERSED) {
      EXPECT_FALSE(farPt.valid) << conv;
      EXPECT_EQ(farPt.position, glm::vec3(0.0f));
    } else {
      EXPECT_TRUE(farPt.valid) << conv;
      EXPECT_NEAR(farPt.position.z, -f, 1e-3f * f) << conv;
    }
    // Hostile inputs.
    EXPECT_FALSE(snellUvDepthToView(glm::vec2(kNaN, 0.5f), 0.5f, inv, conv).valid);
    EXPECT_FALSE(snellUvDepthToView(glm::vec2(0.5f, kInf), 0.5f, inv, conv).valid);
    EXPECT_FALSE(snellUvDepthToView(glm::vec2(0.5f), kNaN, inv, conv).valid);
    EXPECT_EQ(snellUvDepthToView(glm::vec2(0.5f), kNaN, inv, conv).position, glm::vec3(0.0f));
    EXPECT_FALSE(snellUvDepthToView(glm::vec2(0.5f), 0.5f, glm::mat4(0.0f), conv).valid);
    EXPECT_FALSE(snellUvDistanceToView(glm::vec2(0.5f), 0.0f, inv).valid);
    EXPECT_FALSE(snellUvDistanceToView(glm::vec2(0.5f), -1.0f, inv).valid);
    EXPECT_FALSE(snellUvDistanceToView(glm::vec2(0.5f), kNaN, inv).valid);
    EXPECT_FALSE(snellUvDistanceToView(glm::vec2(0.5f), kInf, inv).valid);
    EXPECT_FALSE(snellUvDistanceToView(glm::vec2(kNaN), 1.0f, inv).valid);
    EXPECT_FALSE(snellUvDistanceToView(glm::vec2(0.5f), 1.0f, glm::mat4(0.0f)).valid);
    // Depth out of [0,1] is clamped: same as the plane value.
    EXPECT_EQ(snellUvDepthToView(glm::vec2(0.3f), -2.0f, inv, conv).position,
              snellUvDepthToView(glm::vec2(0.3f), 0.0f, inv, conv).position);
  }
  EXPECT_FALSE(snellUvDepthToView(glm::vec2(0.5f), 0.5f, snellPerspectiveInverse(1.0f, 1.0f, n, f, 0), 7).valid);
}

constexpr float kFltMin = std::numeric_limits<float>::min();

// Entries at the smallest normal float are kept (only denormal ones zero the
// matrix): infinite reversed Z has D = zNear, so zNear = FLT_MIN gives D =
// FLT_MIN and the inverse's 1 / D = 2^126; aspect 2^126 at fovy = 2 float(pi/4)
// has A = 1 / (2^126 tanf(pi/4)) = FLT_MIN in glm::perspective (tanf rounds to 1).
// Normal parameters whose matrix or inverse would hold a denormal (a GPU that flushes denormals sees 0
// there): each gives the zero matrix, as a denormal parameter does. The doubles show each case is one.
TEST(CameraProjection, ADenormalEntryOrIntermediateGivesTheZeroMatrix) {
  const double fltMin = double(kFltMin);
  // fovy = FLT_MIN: tan(fovy / 2) is denormal.
  ASSERT_LT(std::tan(0.5 * fltMin), fltMin);
  // aspect = FLT_MIN, fovy = 1: aspect tan(fovy / 2), the inverse's first entry, is denormal.
  ASSERT_LT(fltMin * std::tan(0.5), fltMin);
  for (int conv : kAll) {
    SCOPED_TRACE(conv);
    EXPECT_TRUE(isZero(snellPerspectiveWithDepth(kFltMin, 1.0f, 0.1f, 10.0f, conv)));
    EXPECT_TRUE(isZero(snellPerspectiveInverse(kFltMin, 1.0f, 0.1f, 10.0f, conv)));
    EXPECT_TRUE(isZero(snellPerspectiveWithDepth(1.0f, kFltMin, 0.1f, 10.0f, conv)));
    EXPECT_TRUE(isZero(snellPerspectiveInverse(1.0f, kFltMin, 0.1f, 10.0f, conv)));
  }
  // INFINITE_REVERSED with zNear = 2e38: D = n is a normal float, the inverse's 1 / D is not.
  ASSERT_LT(1.0 / 2e38, fltMin);
  const glm::mat4 far = snellPerspectiveWithDepth(1.0f, 1.0f, 2e38f, 0.0f, SNELL_DEPTH_INFINITE_REVERSED);
  EXPECT_EQ(far[3][2], 2e38f);
  EXPECT_TRUE(isZero(snellPerspectiveInverse(1.0f, 1.0f, 2e38f, 0.0f, SNELL_DEPTH_INFINITE_REVERSED)));
  // REVERSED with zFar = 2e38 zNear: C = n / (f - n) is denormal.
  ASSERT_LT(1.0 / (2e38 - 1.0), fltMin);
  EXPECT_TRUE(isZero(snellPerspectiveWithDepth(1.0f, 1.0f, 1.0f, 2e38f, SNELL_DEPTH_REVERSED)));
  EXPECT_TRUE(isZero(snellPerspectiveInverse(1.0f, 1.0f, 1.0f, 2e38f, SNELL_DEPTH_REVERSED)));
  // Exactly the smallest normal float is kept: REVERSED with zFar = 2^126 + 1 (2^126 in float) over zNear = 1
  // has C = 1 / 2^126 = FLT_MIN and C / D = FLT_MIN; INFINITE_REVERSED with zNear = 2^126 has 1 / D = FLT_MIN.
  const float p126 = std::ldexp(1.0f, 126);
  const glm::mat4 cMin = snellPerspectiveWithDepth(1.0f, 1.0f, 1.0f, p126 + 1.0f, SNELL_DEPTH_REVERSED);
  EXPECT_EQ(cMin[2][2], kFltMin);
  const glm::mat4 cMinInverse = snellPerspectiveInverse(1.0f, 1.0f, 1.0f, p126 + 1.0f, SNELL_DEPTH_REVERSED);
  EXPECT_EQ(cMinInverse[3][3], kFltMin);
  const glm::mat4 dMaxInverse = snellPerspectiveInverse(1.0f, 1.0f, p126, 0.0f, SNELL_DEPTH_INFINITE_REVERSED);
  EXPECT_EQ(dMaxInverse[2][3], kFltMin);
  // Just inside: zFar = 1e37 zNear keeps C = 1e-37 and its inverse entries normal.
  EXPECT_FALSE(isZero(snellPerspectiveWithDepth(1.0f, 1.0f, 1.0f, 1e37f, SNELL_DEPTH_REVERSED)));
  EXPECT_FALSE(isZero(snellPerspectiveInverse(1.0f, 1.0f, 1.0f, 1e37f, SNELL_DEPTH_REVERSED)));
}

TEST(CameraProjection, EntriesAtTheSmallestNormalFloatAreKept) {
  const glm::mat4 m = snellPerspectiveWithDepth(1.0f, 1.0f, kFltMin, 10.0f, SNELL_DEPTH_INFINITE_REVERSED);
  EXPECT_EQ(m[3][2], kFltMin);
  EXPECT_EQ(m[2][3], -1.0f);
  const glm::mat4 inv = snellPerspectiveInverse(1.0f, 1.0f, kFltMin, 10.0f, SNELL_DEPTH_INFINITE_REVERSED);
  EXPECT_EQ(inv[2][3], 1.0f / kFltMin);
  EXPECT_EQ(inv[3][2], -1.0f);

  const float fovy = 2.0f * 0.78539818525f, aspect = std::ldexp(1.0f, 126);
  const glm::mat4 g = glm::perspective(fovy, aspect, 1.0f, 10.0f);
  ASSERT_EQ(g[0][0], kFltMin);
  const glm::mat4 p = snellPerspective(fovy, aspect, 1.0f, 10.0f);
  ASSERT_FALSE(isZero(p));
  expectGlmEntries(p, g);
  const glm::mat4 pi = snellPerspectiveInverse(fovy, aspect, 1.0f, 10.0f, SNELL_DEPTH_GL);
  EXPECT_NEAR(pi[0][0], 1.0 / double(kFltMin), 4e-7 / double(kFltMin));
}

// One-pixel-wide or -high viewports are viewports: their only column or row has
// its centre at 1/2; a zero height is no viewport at all.
TEST(CameraProjection, OnePixelWideViewports) {
  EXPECT_EQ(snellPixelToUv(glm::ivec2(0, 0), glm::ivec2(1, 1)), glm::vec2(0.5f, 0.5f));
  EXPECT_EQ(snellPixelToUv(glm::ivec2(2, 1), glm::ivec2(1, 3)), glm::vec2(2.5f, float(1.5 / 3.0)));
  EXPECT_EQ(snellUvToPixel(glm::vec2(0.5f, 0.9f), glm::ivec2(1, 4)), glm::ivec2(0, 3));
  EXPECT_EQ(snellUvToPixel(glm::vec2(0.9f, 0.5f), glm::ivec2(4, 1)), glm::ivec2(3, 0));
  EXPECT_EQ(snellUvToPixel(glm::vec2(0.9f, 0.5f), glm::ivec2(4, 0)), glm::ivec2(0, 0));
  EXPECT_EQ(snellUvToPixel(glm::vec2(0.9f, 0.5f), glm::ivec2(4, -2)), glm::ivec2(0, 0));
}

// clip w = FLT_MIN is the smallest positive normal w: in front of the camera.
TEST(CameraProjection, SmallestNormalClipWIsInFront) {
  const SnellNdc n = snellClipToNdc(glm::vec4(0.0f, kFltMin, -kFltMin, kFltMin));
  EXPECT_TRUE(n.valid);
  EXPECT_EQ(n.ndc, glm::vec3(0.0f, 1.0f, -1.0f));
  // A point FLT_MIN in front of the eye on the axis: w = -z = FLT_MIN; NDC z
  // (C z + D) / w is finite here (|D| / FLT_MIN < FLT_MAX).
  const glm::mat4 m = snellPerspective(1.0f, 1.0f, 0.1f, 100.0f);
  const SnellScreenPoint sp = snellViewToUv(m, glm::vec3(0.0f, 0.0f, -kFltMin));
  ASSERT_TRUE(sp.valid);
  EXPECT_EQ(sp.uv, glm::vec2(0.5f));
  const glm::dmat4 gl = glm::perspective(1.0, 1.0, 0.1, 100.0);
  const double ndcZ = (gl[2][2] * -double(kFltMin) + gl[3][2]) / double(kFltMin);
  EXPECT_NEAR(sp.ndcZ, ndcZ, 1e-6 * std::abs(ndcZ));
}

// A homogeneous matrix may be scaled by any factor: the points are the same.
// The inverse of infinite reversed Z with A = B = zNear = 1 maps (x, y, z, w)
// to (x, y, -w, z); scaled by 2 FLT_MIN it gives h.w = FLT_MIN for NDC z = 1/2,
// the smallest normal w, still a point: p = (1, 1, -2) seen at uv (3/4, 3/4)
// with depth n / 2 = 1/2.
TEST(CameraProjection, ScaledInverseDownToSmallestNormalW) {
  for (float scale : {1.0f, 2.0f * kFltMin}) {
    const glm::mat4 inv(glm::vec4(scale, 0, 0, 0), glm::vec4(0, scale, 0, 0), glm::vec4(0, 0, 0, scale),
                        glm::vec4(0, 0, -scale, 0));
    const SnellViewPoint a = snellUvDepthToView(glm::vec2(0.75f), 0.5f, inv, SNELL_DEPTH_INFINITE_REVERSED);
    EXPECT_TRUE(a.valid) << scale;
    EXPECT_EQ(a.position, glm::vec3(1.0f, 1.0f, -2.0f)) << scale;
    const SnellViewPoint b = snellUvDistanceToView(glm::vec2(0.75f), 2.0f, inv);
    EXPECT_TRUE(b.valid) << scale;
    EXPECT_EQ(b.position, glm::vec3(1.0f, 1.0f, -2.0f)) << scale;
  }
}

// viewFromClip = identity (an orthographic camera whose view volume is the NDC
// cube): GL depth d is the view z 2 d - 1, so depth 1/2 lies on the eye's plane
// z = 0 (not in front: invalid) and depth 1/4 at z = -1/2.
TEST(CameraProjection, UvDepthToViewRejectsThePlaneOfTheEye) {
  const glm::mat4 id(1.0f);
  const SnellViewPoint onPlane = snellUvDepthToView(glm::vec2(0.25f, 0.75f), 0.5f, id, SNELL_DEPTH_GL);
  EXPECT_FALSE(onPlane.valid);
  EXPECT_EQ(onPlane.position, glm::vec3(0.0f));
  const SnellViewPoint inFront = snellUvDepthToView(glm::vec2(0.25f, 0.75f), 0.25f, id, SNELL_DEPTH_GL);
  EXPECT_TRUE(inFront.valid);
  EXPECT_EQ(inFront.position, glm::vec3(-0.5f, 0.5f, -0.5f));
  // SNELL_DEPTH_CONVENTION_COUNT is no convention.
  EXPECT_FALSE(snellUvDepthToView(glm::vec2(0.5f), 0.5f, snellPerspectiveInverse(1.0f, 1.0f, 0.1f, 10.0f, 0),
                                  SNELL_DEPTH_CONVENTION_COUNT).valid);
}

// The smallest normal distance or view z is in front of the camera: the point
// on the optical axis at that z.
TEST(CameraProjection, SmallestNormalDistanceIsInFront) {
  const glm::mat4 inv = snellPerspectiveInverse(1.0f, 1.3f, 0.1f, 10.0f, SNELL_DEPTH_GL);
  const SnellViewPoint a = snellUvDistanceToView(glm::vec2(0.5f), kFltMin, inv);
  EXPECT_TRUE(a.valid);
  EXPECT_EQ(a.position, glm::vec3(0.0f, 0.0f, -kFltMin));
  const SnellViewPoint b = snellUvZToView(snellPerspective(1.0f, 1.3f, 0.1f, 10.0f), glm::vec2(0.5f), -kFltMin);
  EXPECT_TRUE(b.valid);
  EXPECT_EQ(b.position, glm::vec3(0.0f, 0.0f, -kFltMin));
}

// Any projection with clip w = -z: a frustum rolled about the axis and shifted
// off centre (clip x depends on view y, clip x and y have constant terms). The
// point at p.z whose NDC is the uv of p, projected in double, is p.
TEST(CameraProjection, UvZToViewInvertsRolledOffCentreFrusta) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> angle(-3.0, 3.0), shift(-0.5, 0.5), s(-1.0, 1.0), dist(0.2, 40.0);
  for (int i = 0; i < 2000; ++i) {
    const glm::dmat4 proj = glm::perspective(1.1, 1.4, 0.1, 50.0) *
                            glm::translate(glm::dmat4(1.0), glm::dvec3(shift(rng), shift(rng), 0.0)) *
                            glm::rotate(glm::dmat4(1.0), angle(rng), glm::dvec3(0.0, 0.0, 1.0));
    const glm::mat4 m(proj);
    const double v = dist(rng);
    const glm::vec3 p(float(s(rng) * v), float(s(rng) * v), float(-v));
    const glm::dvec4 clip = glm::dmat4(m) * glm::dvec4(glm::dvec3(p), 1.0);
    const glm::vec2 uv(glm::dvec2(clip) / clip.w * 0.5 + 0.5);
    const SnellViewPoint r = snellUvZToView(m, uv, p.z);
    ASSERT_TRUE(r.valid);
    ASSERT_EQ(r.position.z, p.z);
    // uv carries p to float precision; unprojected, that is a few ulp of the
    // point's extent.
    const double tol = 2e-6 * (std::abs(double(p.x)) + std::abs(double(p.y)) + v);
    ASSERT_NEAR(r.position.x, p.x, tol) << i;
    ASSERT_NEAR(r.position.y, p.y, tol) << i;
  }
}

// A field of view with tan(fovy / 2) = 2^63 on both axes: the 2x2 system's
// determinant A B is exactly FLT_MIN, the smallest non-singular one. The point
// at view z -1 with NDC (1/2, -1/2) is (1/2, -1/2) / A = (2^62, -2^62).
TEST(CameraProjection, UvZToViewAtTheSmallestNormalDeterminant) {
  const float a = std::ldexp(1.0f, -63);
  glm::mat4 m(0.0f);
  m[0][0] = a;
  m[1][1] = a;
  m[2][2] = -1.0f;
  m[2][3] = -1.0f;
  m[3][2] = -0.2f;
  const SnellViewPoint r = snellUvZToView(m, glm::vec2(0.75f, 0.25f), -1.0f);
  EXPECT_TRUE(r.valid);
  EXPECT_EQ(r.position, glm::vec3(std::ldexp(1.0f, 62), -std::ldexp(1.0f, 62), -1.0f));
}

// A projection whose NDC z = 1/2 plane lies behind the eye: viewFromClip maps
// (x, y, z, 1) to (x, y, -1, z + w3), so the unprojected point has z = -1 / (1/2
// + w3) > 0 for w3 < -1/2: no distance puts a point of that ray in front,
// also when that z is as small as 2^-127 (w3 = -2^127).
TEST(CameraProjection, UvDistanceToViewRejectsAnUnprojectionBehindTheEye) {
  for (float w3 : {-2.0f, std::ldexp(-1.0f, 127)}) {
    const glm::mat4 inv(glm::vec4(1, 0, 0, 0), glm::vec4(0, 1, 0, 0), glm::vec4(0, 0, 0, 1), glm::vec4(0, 0, -1, w3));
    const SnellViewPoint r = snellUvDistanceToView(glm::vec2(0.5f), 1.0f, inv);
    EXPECT_FALSE(r.valid) << w3;
    EXPECT_EQ(r.position, glm::vec3(0.0f)) << w3;
  }
}

}  // namespace
