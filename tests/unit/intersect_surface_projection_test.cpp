// glsl/snell/intersect/surface_projection.glsl: the perspective path of a depth
// surface's projection and reconstruction against the general matrix path
// (camera/view_to_uv.glsl, camera/uv_z_to_view.glsl: a full 4x4 product and
// Cramer's rule) bit for bit, and against the projection in double.
#include <gtest/gtest.h>

#include <snell/camera.hpp>
#include <snell/intersect.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace {

using namespace snell;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Perspective-shaped matrices as engines build them: symmetric, off-centre,
// jittered (TAA: the jitter lands in column 2), GL and zero-to-one depth.
glm::mat4 randomPerspective(std::mt19937& rng, int kind) {
  std::uniform_real_distribution<float> fovy(0.2f, 2.8f), aspect(0.3f, 3.0f), logNear(-2.0f, 0.5f), u(-1.0f, 1.0f);
  const float n = std::pow(10.0f, logNear(rng));
  const float f = n * 1000.0f;
  switch (kind % 4) {
    case 0:
      return glm::perspective(fovy(rng), aspect(rng), n, f);
    case 1:
      return glm::perspectiveZO(fovy(rng), aspect(rng), n, f);
    case 2: {
      const float t = n * std::tan(0.5f * fovy(rng)), r = t * aspect(rng);
      const float dx = 0.5f * r * u(rng), dy = 0.5f * t * u(rng);
      return glm::frustum(-r + dx, r + dx, -t + dy, t + dy, n, f);
    }
    default: {
      glm::mat4 m = snellPerspective(fovy(rng), aspect(rng), n, f);
      m[2][0] += 1e-3f * u(rng);  // sub-pixel jitter
      m[2][1] += 1e-3f * u(rng);
      return m;
    }
  }
}

TEST(SurfaceProjection, PerspectiveShapesAreRecognized) {
  std::mt19937 rng(41);
  for (int i = 0; i < 400; ++i) {
    const glm::mat4 m = randomPerspective(rng, i);
    EXPECT_TRUE(snellDepthSurface(m, 0.1f, 100.0f, SNELL_DEPTH_GL, 0.0f).perspective) << i;
  }
  glm::mat4 sheared = glm::perspective(1.0f, 1.3f, 0.1f, 100.0f);
  sheared[1][0] = 0.01f;
  EXPECT_FALSE(snellDepthSurface(sheared, 0.1f, 100.0f, SNELL_DEPTH_GL, 0.0f).perspective);
  glm::mat4 translated = glm::perspective(1.0f, 1.3f, 0.1f, 100.0f);
  translated[3][0] = 0.5f;
  EXPECT_FALSE(snellDepthSurface(translated, 0.1f, 100.0f, SNELL_DEPTH_GL, 0.0f).perspective);
  EXPECT_FALSE(snellDepthSurface(glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.1f, 10.0f), 0.1f, 10.0f, SNELL_DEPTH_GL, 0.0f)
                   .perspective);
  EXPECT_FALSE(snellDepthSurface(glm::mat4(kNaN), 0.1f, 10.0f, SNELL_DEPTH_GL, 0.0f).perspective);
}

// The fast path gives the general path's bits: uv, ndcZ (up to the sign of an
// exact zero), position and valid, on points in and out of the frustum,
// behind the camera and non-finite ones.
TEST(SurfaceProjection, PerspectivePathIsTheGeneralPathBitForBit) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> s(-2.0f, 2.0f), logZ(-3.0f, 4.0f), uv(-0.3f, 1.3f), pick(0.0f, 1.0f);
  const float hostile[] = {kNaN, kInf, -kInf, 0.0f, -0.0f, 1e-40f, 3e38f, -3e38f};
  int validUv = 0, validPos = 0;
  for (int i = 0; i < 200000; ++i) {
    const glm::mat4 m = randomPerspective(rng, i);
    const SnellDepthSurface surf = snellDepthSurface(m, 0.1f, 100.0f, SNELL_DEPTH_GL, 0.0f);
    ASSERT_TRUE(surf.perspective);
    const float z = -std::pow(10.0f, logZ(rng));
    glm::vec3 p(s(rng) * -z, s(rng) * -z, z);
    glm::vec2 t(uv(rng), uv(rng));
    float vz = z;
    if (pick(rng) < 0.1f) p[i % 3] = hostile[i % 8];
    if (pick(rng) < 0.05f) p.z = -p.z;  // behind the camera
    if (pick(rng) < 0.1f) t[i % 2] = hostile[(i / 2) % 8];
    if (pick(rng) < 0.05f) vz = hostile[(i / 3) % 8];

    const SnellScreenPoint a = snellSurfaceViewToUv(surf, p);
    const SnellScreenPoint b = snellViewToUv(m, p);
    ASSERT_EQ(a.valid, b.valid) << i;
    ASSERT_TRUE(sameBits(a.uv.x, b.uv.x) && sameBits(a.uv.y, b.uv.y)) << i;
    ASSERT_TRUE(a.ndcZ == b.ndcZ) << i;
    validUv += a.valid;

    const SnellViewPoint c = snellSurfaceUvZToView(surf, t, vz);
    const SnellViewPoint d = snellUvZToView(m, t, vz);
    ASSERT_EQ(c.valid, d.valid) << i;
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(sameBits(c.position[k], d.position[k])) << i << " " << k;
    validPos += c.valid;
  }
  // Most inputs are ordinary points, so the comparisons above are mostly of numbers.
  EXPECT_GT(validUv, 150000);
  EXPECT_GT(validPos, 150000);
}

// Against the projection in double: uv = 0.5 clip.xy / clip.w + 0.5, and the
// reconstruction of (uv, z) is the point.
TEST(SurfaceProjection, MatchesTheProjectionInDouble) {
  std::mt19937 rng(43);
  std::uniform_real_distribution<float> s(-1.0f, 1.0f), logZ(-1.0f, 2.0f);
  for (int i = 0; i < 20000; ++i) {
    const glm::mat4 m = randomPerspective(rng, i);
    const SnellDepthSurface surf = snellDepthSurface(m, 0.1f, 100.0f, SNELL_DEPTH_GL, 0.0f);
    const float z = -std::pow(10.0f, logZ(rng));
    const glm::vec3 p(s(rng) * -z, s(rng) * -z, z);
    const glm::dvec4 clip = glm::dmat4(m) * glm::dvec4(glm::dvec3(p), 1.0);
    const SnellScreenPoint sp = snellSurfaceViewToUv(surf, p);
    ASSERT_TRUE(sp.valid);
    EXPECT_NEAR(sp.uv.x, 0.5 * clip.x / clip.w + 0.5, 1e-5) << i;
    EXPECT_NEAR(sp.uv.y, 0.5 * clip.y / clip.w + 0.5, 1e-5) << i;
    EXPECT_NEAR(sp.ndcZ, clip.z / clip.w, 1e-4) << i;
    const SnellViewPoint q = snellSurfaceUvZToView(surf, sp.uv, z);
    ASSERT_TRUE(q.valid);
    EXPECT_NEAR(q.position.x, p.x, 1e-4 * (1.0 - static_cast<double>(z))) << i;
    EXPECT_NEAR(q.position.y, p.y, 1e-4 * (1.0 - static_cast<double>(z))) << i;
    EXPECT_EQ(q.position.z, z);
  }
}

// Hostile free entries (NaN, +-Inf, huge, zero, denormal in a..f) and -0 in
// the zero entries still pass the shape test; the fast path then agrees with
// the general one on valid and on every value (up to the sign of a zero).
TEST(SurfaceProjection, HostileEntriesAgreeWithTheGeneralPath) {
  std::mt19937 rng(44);
  std::uniform_real_distribution<float> s(-2.0f, 2.0f), logZ(-3.0f, 4.0f), uv(-0.3f, 1.3f), pick(0.0f, 1.0f);
  const float hostile[] = {kNaN, kInf, -kInf, 0.0f, -0.0f, 1e-40f, 3e38f, -3e38f, 1e20f};
  const int freeEntries[6][2] = {{0, 0}, {1, 1}, {2, 0}, {2, 1}, {2, 2}, {3, 2}};
  const int zeroEntries[9][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 0}, {1, 2}, {1, 3}, {3, 0}, {3, 1}, {3, 3}};
  auto same = [](float a, float b) { return a == b || (std::isnan(a) && std::isnan(b)); };
  int valid = 0;
  for (int i = 0; i < 200000; ++i) {
    glm::mat4 m = randomPerspective(rng, i);
    if (pick(rng) < 0.5f) {
      const int* e = freeEntries[i % 6];
      m[e[0]][e[1]] = hostile[(i / 6) % 9];
    }
    if (pick(rng) < 0.3f) {
      const int* z = zeroEntries[i % 9];
      m[z[0]][z[1]] = -0.0f;
    }
    const SnellDepthSurface surf = snellDepthSurface(m, 0.1f, 100.0f, SNELL_DEPTH_GL, 0.0f);
    ASSERT_TRUE(surf.perspective);
    const float z = -std::pow(10.0f, logZ(rng));
    glm::vec3 p(s(rng) * -z, s(rng) * -z, z);
    if (pick(rng) < 0.1f) p[i % 3] = hostile[i % 9];
    const glm::vec2 t(uv(rng), uv(rng));
    const SnellScreenPoint a = snellSurfaceViewToUv(surf, p), b = snellViewToUv(m, p);
    ASSERT_EQ(a.valid, b.valid) << i;
    ASSERT_TRUE(same(a.uv.x, b.uv.x) && same(a.uv.y, b.uv.y) && same(a.ndcZ, b.ndcZ)) << i;
    const SnellViewPoint c = snellSurfaceUvZToView(surf, t, z), d = snellUvZToView(m, t, z);
    ASSERT_EQ(c.valid, d.valid) << i;
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(same(c.position[k], d.position[k])) << i << " " << k;
    valid += a.valid && c.valid;
  }
  EXPECT_GT(valid, 80000);
}

// Clip z decides nothing on the perspective path either: NaN or a huge value
// in the third row leaves valid and uv as with the clean matrix; ndcZ is 0
// for a NaN clip z and clamped for an overflowing one.
TEST(SurfaceProjection, ClipZDecidesNothing) {
  const glm::mat4 m = glm::perspective(1.0f, 1.3f, 0.1f, 100.0f);
  const glm::vec3 p(0.4f, -0.3f, -3.0f);
  const SnellScreenPoint clean = snellSurfaceViewToUv(snellDepthSurface(m, 0.1f, 100.0f, SNELL_DEPTH_GL, 0.0f), p);
  ASSERT_TRUE(clean.valid);
  for (float e : {kNaN, 3e38f}) {
    glm::mat4 bad = m;
    bad[2][2] = e;
    const SnellDepthSurface surf = snellDepthSurface(bad, 0.1f, 100.0f, SNELL_DEPTH_GL, 0.0f);
    ASSERT_TRUE(surf.perspective);
    const SnellScreenPoint sp = snellSurfaceViewToUv(surf, p);
    EXPECT_TRUE(sp.valid) << e;
    EXPECT_EQ(sp.uv, clean.uv) << e;
    EXPECT_EQ(sp.ndcZ, std::isnan(e) ? 0.0f : -std::numeric_limits<float>::max()) << e;
  }
}

// A surface whose matrix is changed to another shape must be completed again
// (snellDepthSurfaceComplete clears its flag): then the general path runs; a
// stale flag would ignore the shear.
TEST(SurfaceProjection, ClearedFlagRunsTheGeneralPath) {
  SnellDepthSurface surf = snellDepthSurface(glm::perspective(1.0f, 1.3f, 0.1f, 100.0f), 0.1f, 100.0f,
                                             SNELL_DEPTH_GL, 0.0f);
  ASSERT_TRUE(surf.perspective);
  glm::mat4 sheared = surf.clipFromView;
  sheared[1][0] = 0.2f;
  surf.clipFromView = sheared;
  const glm::vec3 p(0.3f, -0.4f, -2.0f);
  const SnellScreenPoint stale = snellSurfaceViewToUv(surf, p);
  surf = snellDepthSurfaceComplete(surf);
  ASSERT_FALSE(surf.perspective);
  const SnellScreenPoint a = snellSurfaceViewToUv(surf, p), b = snellViewToUv(sheared, p);
  EXPECT_TRUE(a.valid && sameBits(a.uv.x, b.uv.x) && sameBits(a.uv.y, b.uv.y));
  EXPECT_GT(std::fabs(stale.uv.x - b.uv.x), 1e-3f);  // what the flag is for
  const SnellViewPoint c = snellSurfaceUvZToView(surf, a.uv, p.z);
  ASSERT_TRUE(c.valid);
  EXPECT_NEAR(c.position.x, p.x, 1e-5f);
  EXPECT_NEAR(c.position.y, p.y, 1e-5f);
}

// The ends of the valid depth range are inclusive, as on the general path: a point at z = -FLT_MIN or
// -FLT_MAX projects, a reconstruction at z = -FLT_MIN is a point, and a determinant of exactly FLT_MIN
// (the smallest perspectiveDet kept) reconstructs. Expected: the general path bit for bit, and the
// projection in double (x = -z nx / a, y = -z ny / b).
TEST(SurfaceProjection, TheEndsOfTheValidRangesAreInside) {
  const glm::mat4 m = glm::perspective(1.0f, 1.3f, 0.1f, 100.0f);
  const SnellDepthSurface surf = snellDepthSurface(m, 0.1f, 100.0f, SNELL_DEPTH_GL, 0.0f);
  ASSERT_TRUE(surf.perspective);
  const float fmax = std::numeric_limits<float>::max();
  for (const glm::vec3 p : {glm::vec3(0.0f, 0.0f, -FLT_MIN), glm::vec3(0.0f, 0.0f, -fmax)}) {
    const SnellScreenPoint a = snellSurfaceViewToUv(surf, p), b = snellViewToUv(m, p);
    EXPECT_TRUE(a.valid) << p.z;
    EXPECT_TRUE(b.valid) << p.z;
    EXPECT_EQ(a.uv, glm::vec2(0.5f)) << p.z;  // on the axis of a symmetric frustum
    EXPECT_TRUE(sameBits(a.ndcZ, b.ndcZ)) << p.z;
  }
  const glm::vec2 uv(0.6f, 0.7f);
  const SnellViewPoint c = snellSurfaceUvZToView(surf, uv, -FLT_MIN), d = snellUvZToView(m, uv, -FLT_MIN);
  EXPECT_TRUE(c.valid);
  EXPECT_TRUE(d.valid);
  EXPECT_EQ(c.position.z, -FLT_MIN);
  EXPECT_TRUE(sameBits(c.position.x, d.position.x) && sameBits(c.position.y, d.position.y));
  glm::mat4 tiny = m;
  tiny[0][0] = 1.0f;
  tiny[1][1] = FLT_MIN;
  const SnellDepthSurface edge = snellDepthSurface(tiny, 0.1f, 100.0f, SNELL_DEPTH_GL, 0.0f);
  ASSERT_EQ(edge.perspectiveDet, FLT_MIN);
  const SnellViewPoint e = snellSurfaceUvZToView(edge, uv, -2.0f);
  ASSERT_TRUE(e.valid);
  const double nx = 2.0 * double(uv.x) - 1.0, ny = 2.0 * double(uv.y) - 1.0;
  EXPECT_NEAR(e.position.x, 2.0 * nx / 1.0, 1e-6);
  EXPECT_NEAR(double(e.position.y) / (2.0 * ny / double(FLT_MIN)), 1.0, 1e-6);
  EXPECT_EQ(e.position.z, -2.0f);
}

}  // namespace
