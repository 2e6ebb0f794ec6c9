// glsl/snell/intersect/single_sample.glsl, surface_point.glsl, plane_refine.glsl
// and depth_surface.glsl against the analytic scenes (tests/support/depth_scenes.hpp).
#include <gtest/gtest.h>

#include <snell/intersect.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "support/depth_scenes.hpp"

namespace {

using namespace snell;
using snell_test::DepthScene;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

TEST(IntersectSingle, SurfacePointIsTheAnalyticPointAtTheTexelCentre) {
  for (int conv = 0; conv < SNELL_DEPTH_CONVENTION_COUNT; ++conv) {
    const DepthScene sc = snell_test::sphereBack(97, 61, conv);
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int valid = 0;
    for (int i = 0; i < 2000; ++i) {
      const glm::dvec2 uv(u(rng), u(rng));
      const SnellSurfacePoint p = snellSurfacePoint(sc.depth, glm::vec2(uv), sc.surface());
      const glm::dvec2 centre((double(std::floor(float(uv.x) * 97.0f)) + 0.5) / 97.0,
                               (double(std::floor(float(uv.y) * 61.0f)) + 0.5) / 61.0);
      const snell_test::AnalyticSample a = sc.sampleAt(centre);
      ASSERT_EQ(p.valid, a.valid) << conv << " " << uv.x << " " << uv.y;
      if (!a.valid) continue;
      ++valid;
      const glm::dvec3 truth = sc.pixelRay(centre) * a.s;
      EXPECT_LT(glm::length(glm::dvec3(p.position) - truth), 2e-5 * a.s) << conv;
      EXPECT_NEAR(p.uv.x, centre.x, 1e-7);
      EXPECT_NEAR(p.uv.y, centre.y, 1e-7);
    }
    EXPECT_GT(valid, 500);
  }
}

// SNELL_DEPTH_FILTER_BILINEAR: on a slanted plane the interpolated window depth is the plane's depth at
// any uv (window depth is affine in screen space over a plane), in every depth convention; nearest reads
// are off by up to half a texel's depth step. Next to an empty texel it is the nearest texel's value.
TEST(IntersectSingle, BilinearDepthIsExactOnAPlaneAndNeverBlendsEmptyTexels) {
  for (int conv = 0; conv < SNELL_DEPTH_CONVENTION_COUNT; ++conv) {
    const DepthScene sc = snell_test::slantedPlane(64, 48, conv);
    SnellDepthSurface linear = sc.surface();
    linear.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(1.0 / 64.0, 1.0 - 1.0 / 48.0);  // keep all four texels inside
    double worstLinear = 0.0, worstNearest = 0.0;
    for (int i = 0; i < 2000; ++i) {
      const glm::dvec2 uv(u(rng), u(rng));
      const snell_test::AnalyticSample a = sc.sampleAt(uv);
      if (!a.valid) continue;
      const double truth = (sc.pixelRay(uv) * a.s).z;
      const SnellSurfaceSample l = snellSampleSurface(sc.depth, glm::vec2(uv), linear);
      const SnellSurfaceSample n = snellSampleSurface(sc.depth, glm::vec2(uv), sc.surface());
      ASSERT_TRUE(l.valid && n.valid) << conv;
      worstLinear = std::max(worstLinear, std::abs(double(l.viewZ) - truth) / -truth);
      worstNearest = std::max(worstNearest, std::abs(double(n.viewZ) - truth) / -truth);
    }
    EXPECT_LT(worstLinear, 2e-4) << conv;  // float window depth, linearized
    EXPECT_GT(worstNearest, 10.0 * worstLinear) << conv;
  }
  // A surface texel next to empty ones (the silhouette scene's rim): the texel's own depth.
  const DepthScene rim = snell_test::silhouette(64, 64);
  SnellDepthSurface linear = rim.surface();
  linear.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  int rimTexels = 0;
  for (int y = 1; y < 63; ++y)
    for (int x = 1; x < 63; ++x) {
      const bool here = rim.depth.fetch(glm::ivec2(x, y), 0).x != rim.emptyDepth;
      const bool emptyRight = rim.depth.fetch(glm::ivec2(x + 1, y), 0).x == rim.emptyDepth;
      if (!here || !emptyRight) continue;
      ++rimTexels;
      // Towards the empty neighbour (three quarters of the way to this texel's right edge).
      const glm::vec2 uv((float(x) + 0.75f) / 64.0f, (float(y) + 0.5f) / 64.0f);
      EXPECT_EQ(snellSampleSurface(rim.depth, uv, linear).viewZ, snellSampleSurface(rim.depth, uv, rim.surface()).viewZ);
    }
  EXPECT_GT(rimTexels, 4);
}

TEST(IntersectSingle, UvZToViewInvertsTheProjection) {
  const glm::mat4 m = snellPerspective(1.1f, 1.4f, 0.2f, 90.0f);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 1000; ++i) {
    const glm::vec2 uv(u(rng) * 1.4f - 0.2f, u(rng) * 1.4f - 0.2f);
    const float z = -0.3f - 50.0f * u(rng);
    const SnellViewPoint p = snellUvZToView(m, uv, z);
    ASSERT_TRUE(p.valid);
    EXPECT_EQ(p.position.z, z);
    const SnellScreenPoint sp = snellViewToUv(m, p.position);
    EXPECT_NEAR(sp.uv.x, uv.x, 2e-6f);
    EXPECT_NEAR(sp.uv.y, uv.y, 2e-6f);
  }
  EXPECT_FALSE(snellUvZToView(m, glm::vec2(0.5f), 0.0f).valid);
  EXPECT_FALSE(snellUvZToView(m, glm::vec2(0.5f), 1.0f).valid);
  EXPECT_FALSE(snellUvZToView(m, glm::vec2(kNaN, 0.5f), -1.0f).valid);
  EXPECT_FALSE(snellUvZToView(glm::mat4(0.0f), glm::vec2(0.5f), -1.0f).valid);
}

TEST(IntersectSingle, ExactWhenTheRayPointsAtTheSurfaceBehindTheOrigin) {
  const DepthScene sc = snell_test::sphereBack(128, 128);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.25, 0.75), f(0.2, 0.9);
  int n = 0;
  for (int i = 0; i < 1000; ++i) {
    const glm::dvec2 px(std::floor(u(rng) * 128.0) + 0.5, std::floor(u(rng) * 128.0) + 0.5);
    const glm::dvec2 uv = px / 128.0;
    const snell_test::AnalyticSample a = sc.sampleAt(uv);
    if (!a.valid) continue;
    const glm::dvec3 b = sc.pixelRay(uv) * a.s, o = b * f(rng);
    // Any direction from o: the hit is d = |B - o| along it; towards B it is B.
    const SnellHit h = snellIntersectSingleSample(glm::vec3(o), glm::vec3(b - o) * 3.0f, sc.depth, sc.surface());
    ASSERT_TRUE(h.valid);
    EXPECT_EQ(h.fetches, 1);
    EXPECT_LT(glm::length(glm::dvec3(h.position) - b), 1e-4 * a.s);
    ++n;
  }
  EXPECT_GT(n, 300);
}

TEST(IntersectSingle, DistanceAlongTheRayEqualsTheDistanceToB) {
  const DepthScene sc = snell_test::slantedPlane(64, 64);
  const glm::vec3 o = glm::vec3(sc.pixelRay({0.5, 0.5}) * 5.0);
  const glm::vec3 d = glm::normalize(glm::vec3(0.2f, -0.1f, -1.0f));
  const SnellHit h = snellIntersectSingleSample(o, d, sc.depth, sc.surface());
  ASSERT_TRUE(h.valid);
  const SnellSurfacePoint b = snellSurfacePoint(sc.depth, snellViewToUv(sc.clipFromView, o).uv, sc.surface());
  EXPECT_NEAR(glm::length(h.position - o), glm::length(b.position - o), 1e-5f);
  // Towards the camera: accepted, the point d towards the camera.
  const SnellHit t = snellIntersectSingleSample(o, -d, sc.depth, sc.surface());
  EXPECT_TRUE(t.valid);
  EXPECT_GT(t.position.z, o.z);
}

TEST(IntersectSingle, BadInputs) {
  const DepthScene sc = snell_test::sphereBack(64, 64);
  const SnellDepthSurface s = sc.surface();
  const glm::vec3 o(0.3f, -0.2f, -3.9f), d(0.1f, 0.0f, -1.0f);
  ASSERT_TRUE(snellIntersectSingleSample(o, d, sc.depth, s).valid);
  auto miss = [](const SnellHit& h, int fetches) {
    EXPECT_FALSE(h.valid);
    EXPECT_EQ(h.position, glm::vec3(0.0f));
    EXPECT_EQ(h.uv, glm::vec2(0.0f));
    EXPECT_EQ(h.fetches, fetches);
  };
  miss(snellIntersectSingleSample(glm::vec3(kNaN), d, sc.depth, s), 0);
  miss(snellIntersectSingleSample(o, glm::vec3(0.0f), sc.depth, s), 0);
  miss(snellIntersectSingleSample(o, glm::vec3(1e30f, 0.0f, -1.0f), sc.depth, s), 0);
  miss(snellIntersectSingleSample(glm::vec3(0.0f, 0.0f, 2.0f), d, sc.depth, s), 0);
  miss(snellIntersectSingleSample(glm::vec3(9.0f, 0.0f, -3.0f), d, sc.depth, s), 1);   // origin off screen
  miss(snellIntersectSingleSample(glm::vec3(-2.5f, 1.8f, -4.0f), d, sc.depth, s), 1);  // nothing behind
  miss(snellIntersectSingleSample(o, glm::vec3(1.0f, 0.0f, -0.01f), sc.depth, s), 1);  // leaves the screen
  DepthScene empty = sc;
  for (glm::vec4& t : empty.depth.level(0).texels) t.x = sc.emptyDepth;
  miss(snellIntersectSingleSample(o, d, empty.depth, s), 1);
}

TEST(IntersectSingle, HitOnSurfaceAndSampleSurface) {
  const DepthScene sc = snell_test::silhouette(128, 96, SNELL_DEPTH_REVERSED);
  const SnellDepthSurface s = sc.surface();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.05, 1.05);
  for (int i = 0; i < 3000; ++i) {
    const glm::dvec2 uv(u(rng), u(rng));
    const SnellSurfaceSample x = snellSampleSurface(sc.depth, glm::vec2(uv), s);
    const bool on = uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0;
    if (!on) {
      EXPECT_FALSE(x.valid);
      continue;
    }
    const glm::dvec2 centre((double(std::min(std::floor(float(uv.x) * 128.0f), 127.0f)) + 0.5) / 128.0,
                            (double(std::min(std::floor(float(uv.y) * 96.0f), 95.0f)) + 0.5) / 96.0);
    const snell_test::AnalyticSample a = sc.sampleAt(centre);
    ASSERT_EQ(x.valid, a.valid);
    if (a.valid) {
      EXPECT_NEAR(x.viewZ, -a.s, 2e-5 * a.s);
    }
    // A point on the pixel ray: hit exactly when the surface is there.
    const glm::vec3 p = glm::vec3(sc.pixelRay(centre) * 3.0);
    const SnellHit h = snellHitOnSurface(p, sc.depth, s, 4);
    EXPECT_EQ(h.valid, a.valid);
    EXPECT_EQ(h.fetches, 5);
    if (h.valid) {
      EXPECT_EQ(h.position, p);
    }
  }
  EXPECT_EQ(snellHitOnSurface(glm::vec3(0.0f, 0.0f, 1.0f), sc.depth, s, 2).fetches, 2);
  const SnellHit m = snellHitMiss(7);
  EXPECT_FALSE(m.valid);
  EXPECT_EQ(m.fetches, 7);
}

}  // namespace

// |dir|^2 below 1e-30 is rejected, 1e-30 itself is not; a position 5 % past the screen's right edge is
// off screen. On a wall at z = -4 (INFINITE_REVERSED depth 0.125 = zNear / 4), seen through
// clip = (x, y, -z - 1, -z): from W = (0, 0, -3) B is 1 behind, so the position is W + 1 along dir.
TEST(IntersectSingle, DirectionLengthThresholdAndTheScreensEdge) {
  mat4 m(0.0f);
  m[0][0] = 1.0f;
  m[1][1] = 1.0f;
  m[2][2] = -1.0f;
  m[2][3] = -1.0f;
  m[3][2] = -1.0f;
  const snell::SnellDepthSurface s = snell::snellDepthSurface(m, 0.5f, 100.0f, SNELL_DEPTH_INFINITE_REVERSED, 0.0f);
  const snell::Texture2D wall(snell::Image(64, 64, glm::vec4(0.125f, 0.0f, 0.0f, 0.0f)));
  // The float x whose square (dot(dir, dir) for dir = (x, 0, 0)) is 1e-30f exactly.
  float x = 1e-15f;
  for (int k = 0; k < 64 && x * x != 1e-30f; ++k) x = std::nextafter(x, x * x < 1e-30f ? 1.0f : 0.0f);
  ASSERT_EQ(x * x, 1e-30f);
  const glm::vec3 w(0.0f, 0.0f, -3.0f);
  const snell::SnellHit h = snell::snellIntersectSingleSample(w, glm::vec3(x, 0.0f, 0.0f), wall, s);
  EXPECT_TRUE(h.valid);
  EXPECT_EQ(h.fetches, 1);
  const float below = std::nextafter(x, 0.0f);
  ASSERT_LT(below * below, 1e-30f);
  EXPECT_EQ(snell::snellIntersectSingleSample(w, glm::vec3(below, 0.0f, 0.0f), wall, s).fetches, 0);
  // From W = (0, 0, -1.9), B (the centre of the texel at uv 1/2) is about 2.1 behind, so the position
  // (2.1, 0, -1.9) or (0, 2.1, -1.9) projects to uv 0.5 + 0.5 (2.1 / 1.9) = 1.05: off screen.
  const glm::vec3 w2(0.0f, 0.0f, -1.9f);
  for (const glm::vec3 dir : {glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f)}) {
    const snell::SnellHit o = snell::snellIntersectSingleSample(w2, dir, wall, s);
    EXPECT_FALSE(o.valid);
    EXPECT_EQ(o.fetches, 1);
  }
}

// The position's screen test is the closed [0,1]^2, to the float: a position projecting exactly onto
// an edge (uv 0 or 1) is a hit, one projecting one float past 1 is not. An exact scene: a wall at
// z = -2 (INFINITE_REVERSED depth 0.25 = zNear / 2) seen through clip = (a x, b y, -z - 1, -z) on a
// 63 x 63 buffer, whose middle texel's centre is uv 0.5: from W = (0, 0, -1), B = (0, 0, -2), d = 1,
// and the position W + dir for a unit dir along x or y projects to uv 0.5 +- 0.5 a (or b).
TEST(IntersectSingle, PositionsExactlyOnTheScreensEdgesAreHits) {
  const snell::Texture2D wall(snell::Image(63, 63, glm::vec4(0.25f, 0.0f, 0.0f, 0.0f)));
  auto surfaceWithScales = [](float a, float b) {
    mat4 m(0.0f);
    m[0][0] = a;
    m[1][1] = b;
    m[2][2] = -1.0f;
    m[2][3] = -1.0f;
    m[3][2] = -1.0f;
    return snell::snellDepthSurface(m, 0.5f, 100.0f, SNELL_DEPTH_INFINITE_REVERSED, 0.0f);
  };
  const glm::vec3 w(0.0f, 0.0f, -1.0f);
  const snell::SnellDepthSurface unit = surfaceWithScales(1.0f, 1.0f);
  struct Edge {
    glm::vec3 dir;
    glm::vec2 uv;
  };
  for (const Edge e : {Edge{{1.0f, 0.0f, 0.0f}, {1.0f, 0.5f}}, Edge{{-1.0f, 0.0f, 0.0f}, {0.0f, 0.5f}},
                       Edge{{0.0f, 1.0f, 0.0f}, {0.5f, 1.0f}}, Edge{{0.0f, -1.0f, 0.0f}, {0.5f, 0.0f}}}) {
    const snell::SnellHit h = snell::snellIntersectSingleSample(w, e.dir, wall, unit);
    EXPECT_TRUE(h.valid) << e.dir.x << "," << e.dir.y;
    EXPECT_EQ(h.uv, e.uv) << e.dir.x << "," << e.dir.y;
    EXPECT_EQ(h.position, w + e.dir);
    EXPECT_EQ(h.fetches, 1);
  }
  // A scale of 1 + 2^-22 puts the same positions at uv 1 + 2^-23, the float after 1: off screen.
  const float wider = 1.0f + std::ldexp(1.0f, -22);
  for (const Edge e : {Edge{{1.0f, 0.0f, 0.0f}, {}}, Edge{{0.0f, 1.0f, 0.0f}, {}}}) {
    const snell::SnellDepthSurface s = e.dir.x > 0.0f ? surfaceWithScales(wider, 1.0f) : surfaceWithScales(1.0f, wider);
    const snell::SnellHit h = snell::snellIntersectSingleSample(w, e.dir, wall, s);
    EXPECT_FALSE(h.valid) << e.dir.x << "," << e.dir.y;
    EXPECT_EQ(h.fetches, 1);
  }
}
