// glsl/snell/intersect/foreground.glsl (snellRejectForeground) against the
// analytic step scene (tests/support/depth_scenes.hpp): a half-plane at view
// z = -3 (the foreground) in front of a plane through z = -8. The expected
// verdict comes from the analytic surface at the centre of the texel the hit
// falls in, in double, not from the library's depth read.
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
constexpr int kW = 160, kH = 120;

SnellHit hitAt(const DepthScene& sc, glm::dvec2 uv, double distance, int fetches) {
  SnellHit h;
  h.uv = glm::vec2(uv);
  h.position = glm::vec3(sc.pixelRay(uv) * distance);
  h.valid = true;
  h.fetches = fetches;
  return h;
}

// The centre of the texel containing uv (the rule reads that texel).
glm::dvec2 texelCentre(glm::dvec2 uv) {
  return glm::dvec2((double(std::floor(float(uv.x) * kW)) + 0.5) / kW, (double(std::floor(float(uv.y) * kH)) + 0.5) / kH);
}

// Random hits and origins in front of and behind both surfaces: the verdict is the analytic one wherever it
// is not within float rounding of the threshold, and both verdicts occur often.
TEST(IntersectForeground, RefusesExactlyTheSurfacesNearerThanTheWholeRay) {
  for (int conv = 0; conv < SNELL_DEPTH_CONVENTION_COUNT; ++conv) {
    const DepthScene sc = snell_test::stepEdge(kW, kH, conv);
    const SnellDepthSurface s = sc.surface();
    std::mt19937 rng(31 + conv);
    std::uniform_real_distribution<double> u(0.0, 1.0), dist(1.0, 12.0), tol(0.0, 0.3);
    int refused = 0, kept = 0;
    for (int i = 0; i < 4000; ++i) {
      const glm::dvec2 uv(u(rng), u(rng));
      const double hitDistance = dist(rng), originDistance = dist(rng);
      const float tolerance = i % 3 == 0 ? 0.0f : float(tol(rng));
      const glm::vec3 origin(0.1f, -0.2f, float(-originDistance));
      const SnellHit h = hitAt(sc, uv, hitDistance, 7);
      const snell_test::AnalyticSample a = sc.sampleAt(texelCentre(uv));
      ASSERT_TRUE(a.valid);  // the step scene covers the whole screen
      // The analytic surface's distance along the view axis (pixel rays have q.z = -1).
      const double surface = a.s;
      const double dNear = std::min(originDistance, -double(h.position.z));
      const double threshold = dNear * (1.0 - double(tolerance));
      if (std::abs(surface - threshold) < 1e-4 * threshold) continue;  // float rounding decides
      const SnellHit r = snellRejectForeground(h, origin, sc.depth, s, tolerance);
      EXPECT_EQ(r.fetches, 8) << conv << " " << i;
      if (surface < threshold) {
        ++refused;
        EXPECT_FALSE(r.valid) << conv << " " << uv.x << " " << uv.y << " surface " << surface << " near " << dNear;
        EXPECT_EQ(r.position, glm::vec3(0.0f));
        EXPECT_EQ(r.uv, glm::vec2(0.0f));
      } else {
        ++kept;
        EXPECT_TRUE(r.valid) << conv << " " << uv.x << " " << uv.y << " surface " << surface << " near " << dNear;
        EXPECT_EQ(r.position, h.position);
        EXPECT_EQ(r.uv, h.uv);
      }
    }
    EXPECT_GT(refused, 800) << conv;
    EXPECT_GT(kept, 800) << conv;
  }
}

// The pillar in front of the glass: an exit ray leaving the object at view depth 5 behind the step lands,
// by any strategy, on a texel of the step (depth 3): refused. Beside the step the plane behind is kept.
TEST(IntersectForeground, AnExitRayBehindAForegroundNeverShowsIt) {
  const DepthScene sc = snell_test::stepEdge(kW, kH);
  const SnellDepthSurface s = sc.surface();
  const glm::vec3 origin(0.0f, 0.0f, -5.0f);
  // uv 0.3 lies left of the edge (view x = 0.25 at depth 3), uv 0.8 right of it.
  const SnellHit onStep = snellRejectForeground(hitAt(sc, {0.3, 0.5}, 7.0, 3), origin, sc.depth, s, 0.01f);
  EXPECT_FALSE(onStep.valid);
  EXPECT_EQ(onStep.fetches, 4);
  // A bilinear surface is read at the texel all the same: a hit in the step's last texel column, from a ray
  // whose nearest point is at 3.5, is refused (the step there is at 3); the bilinear depth would blend the
  // step with the plane behind it (about 8) to about 4 and let it through.
  SnellDepthSurface bilinear = s;
  bilinear.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  int lastStep = 0;
  for (int i = 0; i < kW; ++i)
    if (std::abs(sc.sampleAt(glm::dvec2((i + 0.5) / kW, (60 + 0.5) / kH)).s - 3.0) < 1e-9) lastStep = i;
  ASSERT_GT(lastStep, 0);
  const glm::dvec2 edge((lastStep + 0.9) / kW, (60 + 0.5) / kH);
  const glm::vec3 near(0.0f, 0.0f, -3.5f);
  EXPECT_FALSE(snellRejectForeground(hitAt(sc, edge, 7.0, 0), near, sc.depth, bilinear, 0.01f).valid);
  const SnellHit behind = snellRejectForeground(hitAt(sc, {0.8, 0.5}, 8.0, 3), origin, sc.depth, s, 0.01f);
  EXPECT_TRUE(behind.valid);
  EXPECT_EQ(behind.fetches, 4);
  // A ray towards the camera whose hit is itself nearer than the step: the step is behind it, kept.
  const SnellHit nearHit = snellRejectForeground(hitAt(sc, {0.3, 0.5}, 2.5, 0), origin, sc.depth, s, 0.01f);
  EXPECT_TRUE(nearHit.valid);
  // The tolerance: a surface 0.5 % nearer than the ray's nearest point (3 vs 3.015) is kept at 1 %, refused at 0.
  const glm::vec3 justBehind(0.0f, 0.0f, -3.015f);
  EXPECT_TRUE(snellRejectForeground(hitAt(sc, {0.3, 0.5}, 6.0, 0), justBehind, sc.depth, s, 0.01f).valid);
  EXPECT_FALSE(snellRejectForeground(hitAt(sc, {0.3, 0.5}, 6.0, 0), justBehind, sc.depth, s, 0.0f).valid);
}

TEST(IntersectForeground, BadInputs) {
  const DepthScene sc = snell_test::stepEdge(kW, kH);
  const SnellDepthSurface s = sc.surface();
  const glm::vec3 origin(0.0f, 0.0f, -5.0f);
  const SnellHit onStep = hitAt(sc, {0.3, 0.5}, 7.0, 5);
  // An invalid hit is returned as it is, without a read.
  SnellHit invalid = onStep;
  invalid.valid = false;
  const SnellHit r = snellRejectForeground(invalid, origin, sc.depth, s, 0.01f);
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(r.fetches, 5);
  EXPECT_EQ(r.position, invalid.position);
  // A non-finite origin depth: a miss, no read.
  for (float z : {kNaN, std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity()}) {
    const SnellHit m = snellRejectForeground(onStep, glm::vec3(0.0f, 0.0f, z), sc.depth, s, 0.01f);
    EXPECT_FALSE(m.valid);
    EXPECT_EQ(m.fetches, 5);
    EXPECT_EQ(m.position, glm::vec3(0.0f));
  }
  // A hit with a non-finite depth (no strategy returns one): a miss, no read.
  SnellHit nanHit = onStep;
  nanHit.position.z = kNaN;
  const SnellHit n = snellRejectForeground(nanHit, origin, sc.depth, s, 0.01f);
  EXPECT_FALSE(n.valid);
  EXPECT_EQ(n.fetches, 5);
  // Tolerance: NaN and negative values count as 0, values above 1 as 1 (nothing is refused).
  const glm::vec3 justBehind(0.0f, 0.0f, -3.015f);
  for (float t : {kNaN, -0.5f, -std::numeric_limits<float>::infinity()})
    EXPECT_FALSE(snellRejectForeground(hitAt(sc, {0.3, 0.5}, 6.0, 0), justBehind, sc.depth, s, t).valid) << t;
  for (float t : {1.0f, 3.0f, std::numeric_limits<float>::infinity()})
    EXPECT_TRUE(snellRejectForeground(onStep, origin, sc.depth, s, t).valid) << t;
  // An origin at or behind the camera plane: the ray reaches the camera, nothing is in front of all of it.
  EXPECT_TRUE(snellRejectForeground(onStep, glm::vec3(0.0f, 0.0f, 1.0f), sc.depth, s, 0.01f).valid);
  // The same with a tolerance above 1, which counts as 1 (dNear = -50 times 1 - t = 0: the step at 3 is not nearer).
  EXPECT_TRUE(snellRejectForeground(onStep, glm::vec3(0.0f, 0.0f, 50.0f), sc.depth, s, 3.0f).valid);
  // An empty texel or a uv off the buffer holds no foreground: kept, the read counted.
  DepthScene empty = sc;
  for (glm::vec4& t : empty.depth.level(0).texels) t.x = sc.emptyDepth;
  const SnellHit e = snellRejectForeground(onStep, origin, empty.depth, s, 0.01f);
  EXPECT_TRUE(e.valid);
  EXPECT_EQ(e.fetches, 6);
  SnellHit off = onStep;
  off.uv = glm::vec2(1.5f, 0.5f);
  EXPECT_TRUE(snellRejectForeground(off, origin, sc.depth, s, 0.01f).valid);
  off.uv = glm::vec2(kNaN, 0.5f);
  EXPECT_TRUE(snellRejectForeground(off, origin, sc.depth, s, 0.01f).valid);
}

// The default tolerance is the documented 1 %: a surface 1.05 % nearer than the ray's nearest point is
// refused, one 0.95 % nearer is kept (the step at distance 3; dNear = 3 / (1 - share)).
TEST(IntersectForeground, TheDefaultToleranceIsOnePercent) {
  const DepthScene sc = snell_test::stepEdge(kW, kH);
  const SnellDepthSurface s = sc.surface();
  ASSERT_LT(std::abs(sc.sampleAt(texelCentre({0.3, 0.5})).s - 3.0), 1e-6);
  const glm::vec3 refusedFrom(0.0f, 0.0f, float(-3.0 / (1.0 - 0.0105)));
  const glm::vec3 keptFrom(0.0f, 0.0f, float(-3.0 / (1.0 - 0.0095)));
  EXPECT_FALSE(snellRejectForeground(hitAt(sc, {0.3, 0.5}, 6.0, 0), refusedFrom, sc.depth, s, SNELL_FOREGROUND_TOLERANCE).valid);
  EXPECT_TRUE(snellRejectForeground(hitAt(sc, {0.3, 0.5}, 6.0, 0), keptFrom, sc.depth, s, SNELL_FOREGROUND_TOLERANCE).valid);
}

// Refused only when strictly nearer: a surface exactly at dNear (1 - t) is kept. GL depth 1 with
// zNear 1, zFar 2 is exactly distance 2 (v = n / (0 + 1 n / f)), and 2 = 2 (1 - 0) = 4 (1 - 0.5) exactly.
TEST(IntersectForeground, ASurfaceExactlyAtTheThresholdIsKept) {
  const Texture2D depth(Image(2, 2, glm::vec4(1.0f)));
  const SnellDepthSurface s = snellDepthSurface(glm::mat4(1.0f), 1.0f, 2.0f, SNELL_DEPTH_GL, 0.0f);
  SnellHit h;
  h.uv = glm::vec2(0.25f, 0.75f);
  h.valid = true;
  h.fetches = 0;
  struct Case {
    float originZ, hitZ, tolerance;
  };
  for (const Case c : {Case{-2.0f, -3.0f, 0.0f}, Case{-3.0f, -2.0f, 0.0f}, Case{-4.0f, -6.0f, 0.5f}}) {
    h.position = glm::vec3(0.1f, 0.2f, c.hitZ);
    const SnellHit r = snellRejectForeground(h, glm::vec3(0.0f, 0.0f, c.originZ), depth, s, c.tolerance);
    EXPECT_TRUE(r.valid) << c.originZ << " " << c.hitZ << " " << c.tolerance;
    EXPECT_EQ(r.fetches, 1);
    // One ulp further from the camera and the surface is nearer than the whole ray: refused.
    const float further = std::nextafter(c.originZ, -10.0f);
    h.position.z = std::nextafter(c.hitZ, -10.0f);
    EXPECT_FALSE(snellRejectForeground(h, glm::vec3(0.0f, 0.0f, further), depth, s, c.tolerance).valid);
  }
}

}  // namespace
