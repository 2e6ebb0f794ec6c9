// glsl/snell/intersect/plane_far_start.glsl against an independent double-precision
// computation on the analytic back faces of a sphere (tests/support/depth_scenes.hpp):
// the farthest view distance of the sphere's texel centres over the whole buffer and
// over the footprint of the level the contract names, from the analytic surface and
// a max pyramid built here with GL's floor sizes (not snell's reduction), then the
// ray's hit on that constant-depth plane.
#include <gtest/gtest.h>

#include <snell/depth_pyramid.hpp>
#include <snell/intersect.hpp>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <limits>
#include <vector>

#include "support/depth_scenes.hpp"
#include "support/search_rays.hpp"

namespace {

using namespace snell;
using snell_test::DepthScene;

constexpr int kW = 160, kH = 120;

const DepthScene& scene() {
  static const DepthScene s = snell_test::sphereBack(kW, kH, SNELL_DEPTH_GL);
  return s;
}

// The level-0 columns (or rows) below each texel of every level, with GL's floor sizes: 2 children,
// 3 for the last when the size is odd, 1 when the size is 1.
std::vector<std::vector<glm::ivec2>> coverage(int size0) {
  std::vector<std::vector<glm::ivec2>> levels(1);
  for (int i = 0; i < size0; ++i) levels[0].push_back({i, i});
  while (levels.back().size() > 1) {
    const auto& prev = levels.back();
    const int n = int(prev.size()), m = std::max(1, n / 2);
    std::vector<glm::ivec2> next;
    for (int i = 0; i < m; ++i) next.push_back({prev[size_t(2 * i)].x, prev[size_t(i == m - 1 && n % 2 ? 2 * i + 2 : 2 * i + 1)].y});
    levels.push_back(next);
  }
  return levels;
}

// levels[L][y][x]: the farthest analytic view distance of the level-0 texel centres below (0: none).
// Children as GL's floor sizes give them: 2x2, the last column / row takes a third when the size is odd.
std::vector<std::vector<std::vector<double>>> farthestPyramid(const DepthScene& sc) {
  std::vector<std::vector<std::vector<double>>> levels(1, std::vector<std::vector<double>>(kH, std::vector<double>(kW)));
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const snell_test::AnalyticSample a = sc.sampleAt({(x + 0.5) / kW, (y + 0.5) / kH});
      levels[0][y][x] = a.valid ? a.s : 0.0;
    }
  while (levels.back().size() > 1 || levels.back()[0].size() > 1) {
    const auto& prev = levels.back();
    const int ph = int(prev.size()), pw = int(prev[0].size());
    const int nh = std::max(1, ph / 2), nw = std::max(1, pw / 2);
    std::vector<std::vector<double>> next(nh, std::vector<double>(nw, 0.0));
    for (int y = 0; y < nh; ++y)
      for (int x = 0; x < nw; ++x) {
        const int x1 = pw == 1 ? 0 : (x == nw - 1 && pw % 2 ? 2 * x + 2 : 2 * x + 1);
        const int y1 = ph == 1 ? 0 : (y == nh - 1 && ph % 2 ? 2 * y + 2 : 2 * y + 1);
        for (int cy = ph == 1 ? 0 : 2 * y; cy <= y1; ++cy)
          for (int cx = pw == 1 ? 0 : 2 * x; cx <= x1; ++cx) next[y][x] = std::max(next[y][x], prev[cy][cx]);
      }
    levels.push_back(next);
  }
  return levels;
}

// Refracted rays through the front of the sphere (tests/support/search_rays.hpp), at four IORs.
std::vector<snell_search_test::Ray> sphereRays(const DepthScene& sc) {
  std::vector<snell_search_test::Ray> rays;
  for (double ior : {1.1, 1.3, 1.5, 1.6}) {
    const auto some = snell_search_test::sphereRefractedRays(sc, 1000, 2026u, ior);
    rays.insert(rays.end(), some.begin(), some.end());
  }
  return rays;
}

// The ray's t where it reaches view distance v (z = -v).
double tAtDistance(glm::dvec3 o, glm::dvec3 d, double v) { return (-v - o.z) / d.z; }

TEST(IntersectPlaneFarStart, PlaneAtTheFarthestBackFaceUnderTheRaysWay) {
  const DepthScene& sc = scene();
  const SnellDepthSurface s = sc.surface();
  const Texture2D pyramid = snellBuildDepthPyramid(sc.depth, s);
  const auto far = farthestPyramid(sc);
  const int top = int(far.size()) - 1;
  ASSERT_EQ(top, snellTextureTopLod(pyramid));
  const auto columns = coverage(kW), rows = coverage(kH);
  ASSERT_EQ(columns.size(), far.size());
  int checked = 0, ambiguous = 0, beyondExit = 0, withExit = 0, inside = 0, insideBeyond = 0;
  for (const snell_search_test::Ray& r : sphereRays(sc)) {
    const glm::vec3 o = r.origin, d = r.dir;
    const glm::vec2 uv0 = snellSurfaceViewToUv(s, o).uv;
    const SnellFarPlane f = snellPlaneFarStart(o, d, uv0, pyramid, s);
    // The independent computation, in double from the float origin and direction.
    const glm::dvec3 od(o), dd(d);
    const double zAll = far[size_t(top)][0][0];
    const glm::dvec2 g = sc.project(od + tAtDistance(od, dd, zAll) * dd);
    const double way = glm::length((g - glm::dvec2(uv0)) * glm::dvec2(kW, kH));
    int level = 0;
    while (level < top && std::ldexp(1.0, level) < way) ++level;
    const int lw = int(far[size_t(level)][0].size()), lh = int(far[size_t(level)].size());
    const glm::dvec2 mid = glm::clamp(0.5 * (g + glm::dvec2(uv0)), 0.0, 1.0) * glm::dvec2(lw, lh);
    // Float rounding may put the way on the other side of a power of two, or the midpoint across a texel edge.
    const double rel = std::fabs(way / std::ldexp(1.0, level) - 1.0), rel2 = std::fabs(way / std::ldexp(1.0, level - 1) - 1.0);
    const double edge = std::min(std::fabs(mid.x - std::round(mid.x)), std::fabs(mid.y - std::round(mid.y)));
    if (rel < 1e-4 || rel2 < 1e-4 || edge < 1e-4) {
      ++ambiguous;
      continue;
    }
    const int px = std::min(int(mid.x), lw - 1), py = std::min(int(mid.y), lh - 1);
    const double zL = far[size_t(level)][size_t(py)][size_t(px)];
    ASSERT_GT(zL, 0.0);
    const double t = tAtDistance(od, dd, zL);
    ASSERT_TRUE(f.valid) << "ray " << checked;
    EXPECT_EQ(f.fetches, 2);
    EXPECT_NEAR(f.t, t, 2e-4 * std::max(1.0, t)) << "level " << level << " texel " << px << "," << py;
    EXPECT_NEAR(f.position.z, -zL, 2e-4 * zL);
    ++checked;
    // Where the footprint holds the ray's whole way, no exit lies deeper than the plane (on this convex
    // sphere; up to the texel-centre sampling of the pyramid); elsewhere the plane is an estimate.
    if (const auto exit = sc.referenceHit(od, dd)) {
      const bool beyond = double(f.position.z) <= exit->z + 0.02;
      const glm::ivec2 cx = columns[size_t(level)][size_t(px)], cy = rows[size_t(level)][size_t(py)];
      const auto holds = [&](glm::dvec2 uv) {
        return uv.x * kW >= cx.x && uv.x * kW <= cx.y + 1 && uv.y * kH >= cy.x && uv.y * kH <= cy.y + 1;
      };
      ++withExit;
      beyondExit += beyond;
      if (holds(glm::dvec2(uv0)) && holds(g)) {
        ++inside;
        insideBeyond += beyond;
      }
    }
  }
  std::printf("[far start] %d rays checked (%d ambiguous in float); plane at or beyond the exit: %d of %d, "
              "%d of the %d whose way the footprint holds\n", checked, ambiguous, beyondExit, withExit, insideBeyond, inside);
  EXPECT_GT(checked, 3900);
  EXPECT_LT(ambiguous, 100);
  EXPECT_GT(inside, withExit / 4);
  EXPECT_GE(insideBeyond, inside * 999 / 1000);
}

TEST(IntersectPlaneFarStart, InvalidCasesAreFiniteWithTheirFetches) {
  const DepthScene& sc = scene();
  SnellDepthSurface s = sc.surface();
  const Texture2D pyramid = snellBuildDepthPyramid(sc.depth, s);
  const glm::vec3 o(0.3f, -0.2f, -3.9f), d(0.05f, 0.02f, -1.0f);
  const glm::vec2 uv0 = snellSurfaceViewToUv(s, o).uv;
  const auto expectMiss = [](const SnellFarPlane& f, int fetches) {
    EXPECT_FALSE(f.valid);
    EXPECT_EQ(f.fetches, fetches);
    EXPECT_EQ(f.t, 0.0f);
    EXPECT_EQ(f.position, glm::vec3(0.0f));
  };
  ASSERT_TRUE(snellPlaneFarStart(o, d, uv0, pyramid, s).valid);
  expectMiss(snellPlaneFarStart(o, -d, uv0, pyramid, s), 1);                     // towards the camera
  expectMiss(snellPlaneFarStart(glm::vec3(0.3f, -0.2f, -30.0f), d, uv0, pyramid, s), 1);  // beyond the object
  expectMiss(snellPlaneFarStart(o, glm::vec3(0.0f), uv0, pyramid, s), 1);       // no direction
  const float nan = std::numeric_limits<float>::quiet_NaN();
  expectMiss(snellPlaneFarStart(o, d, glm::vec2(nan, 0.5f), pyramid, s), 0);
  expectMiss(snellPlaneFarStart(glm::vec3(nan), d, uv0, pyramid, s), 1);
  // An empty buffer: the top texel has no coverage.
  const Texture2D empty = snellBuildDepthPyramid(Texture2D(Image(kW, kH, glm::vec4(s.emptyDepth))), s);
  expectMiss(snellPlaneFarStart(o, d, uv0, empty, s), 1);
  // An open surface (the opaque scene): no far start, no fetch.
  s.closed = false;
  expectMiss(snellPlaneFarStart(o, d, uv0, pyramid, s), 0);
}

// A hand-made 8x8 pyramid (levels 8, 4, 2, 1; z = farthest distance, w = coverage) seen by a 90 degree
// camera whose focal terms are exactly 1, so uv = x / -z / 2 + 1 / 2 without rounding: the level and the
// texel the contract names are then exact, and each case gives them a depth of their own.
struct HandPyramid {
  Texture2D tex;
  SnellDepthSurface s;
  HandPyramid() : tex(Image(8, 8, glm::vec4(0.0f, 2.0f, 8.0f, 1.0f)), Filter::Nearest, MipFilter::Nearest) {
    for (int size = 4; size >= 1; size /= 2) tex.addLevel(Image(size, size, glm::vec4(0.0f, 2.0f, 8.0f, 1.0f)));
    glm::mat4 m = snellPerspectiveWithDepth(1.5707964f, 1.0f, 0.5f, 40.0f, SNELL_DEPTH_GL);
    m[0][0] = 1.0f;
    m[1][1] = 1.0f;
    s = snellDepthSurface(m, 0.5f, 40.0f, SNELL_DEPTH_GL, 0.0f);
  }
  glm::vec4& at(int level, int x, int y) { return tex.level(level).at(x, y); }
  SnellFarPlane run(glm::vec3 o, glm::vec3 d) const {
    return snellPlaneFarStart(o, d, snellSurfaceViewToUv(s, o).uv, tex, s);
  }
};

// The level is the least L with 2^L >= D: D = 0 (along the line of sight) reads level 0, D = 2 exactly
// (from uv 0.5 to G at uv 0.75, 8 texels wide) level 1, a way longer than the screen the top level.
TEST(IntersectPlaneFarStart, LevelIsTheLeastWithAPowerOfTwoAtLeastTheWay) {
  HandPyramid p;
  p.at(0, 4, 4).z = 8.5f;  // level 0 under uv (0.5, 0.5)
  p.at(1, 2, 2).z = 9.0f;  // level 1 under the midpoint (0.625, 0.5) and under (0.5, 0.5)
  p.at(3, 0, 0).z = 8.0f;  // the whole buffer: G at z = -8
  const SnellFarPlane along = p.run(glm::vec3(0.0f, 0.0f, -4.0f), glm::vec3(0.0f, 0.0f, -1.0f));
  ASSERT_TRUE(along.valid);
  EXPECT_EQ(along.position.z, -8.5f);
  EXPECT_EQ(along.fetches, 2);
  // G = (4, 0, -8): uv 0.75, D = 0.25 * 8 = 2.
  const SnellFarPlane two = p.run(glm::vec3(0.0f, 0.0f, -4.0f), glm::vec3(1.0f, 0.0f, -1.0f));
  ASSERT_TRUE(two.valid);
  EXPECT_FLOAT_EQ(two.position.z, -9.0f);
  EXPECT_FLOAT_EQ(two.t, 5.0f);
  // G far off screen (uv.x 4.5: D = 32 > 8 = 2^top): the top level, z_all itself.
  const SnellFarPlane wide = p.run(glm::vec3(0.0f, 0.0f, -4.0f), glm::vec3(16.0f, 0.0f, -1.0f));
  ASSERT_TRUE(wide.valid);
  EXPECT_FLOAT_EQ(wide.position.z, -8.0f);
}

// The midpoint is clamped to the screen: an origin off screen left (uv.x -0.25) heading deeper, G at uv.x
// -0.125 (D = 1: level 0), the midpoint at uv.x -0.1875 is read at column 0.
TEST(IntersectPlaneFarStart, MidpointOffScreenReadsTheEdgeTexel) {
  HandPyramid p;
  p.at(0, 0, 4).z = 9.5f;  // level 0, column 0, the row of uv.y 0.5
  const SnellFarPlane f = p.run(glm::vec3(-6.0f, 0.0f, -4.0f), glm::vec3(-1.0f, 0.0f, -1.0f));  // G (-10, 0, -8)
  ASSERT_TRUE(f.valid);
  EXPECT_FLOAT_EQ(f.position.z, -9.5f);
  // An origin near the camera plane far right (uv.x 5e9) and G (uv.x 6.25e5): a midpoint of 2.5e9, past
  // any int, clamped to 1: the top level's texel (the way is longer than the screen).
  p.at(3, 0, 0).z = 8.0f;
  const SnellFarPlane g = p.run(glm::vec3(1e7f, 0.0f, -1e-3f), glm::vec3(0.0f, 0.0f, -1.0f));
  ASSERT_TRUE(g.valid);
  EXPECT_FLOAT_EQ(g.position.z, -8.0f);
}

// "Empty (w <= 0) or z not finite and positive": a texel with no coverage is empty whatever its z, and
// any coverage above 0, a denormal one too, is not; z = 0 is not positive, a denormal z is.
TEST(IntersectPlaneFarStart, CoverageAndDepthOfTheTexelsRead) {
  const glm::vec3 o(0.0f, 0.0f, -4.0f), deeper(0.0f, 0.0f, -1.0f);
  {
    HandPyramid p;
    p.at(3, 0, 0).w = 0.0f;
    const SnellFarPlane f = p.run(o, deeper);
    EXPECT_FALSE(f.valid);
    EXPECT_EQ(f.fetches, 1);
    p.at(3, 0, 0).w = 1e-40f;
    EXPECT_TRUE(p.run(o, deeper).valid);
  }
  {
    HandPyramid p;
    p.at(0, 4, 4).w = 0.0f;
    const SnellFarPlane f = p.run(o, deeper);
    EXPECT_FALSE(f.valid);
    EXPECT_EQ(f.fetches, 2);
    p.at(0, 4, 4).w = 1e-40f;
    EXPECT_TRUE(p.run(o, deeper).valid);
  }
  {
    // From beyond the buffer towards the camera (G at z = -8 ahead), the level texel's plane near the eye.
    HandPyramid p;
    const glm::vec3 beyond(0.0f, 0.0f, -20.0f), towards(0.0f, 0.0f, 1.0f);
    p.at(0, 4, 4).z = 0.0f;
    const SnellFarPlane f = p.run(beyond, towards);
    EXPECT_FALSE(f.valid);
    EXPECT_EQ(f.fetches, 2);
    p.at(0, 4, 4).z = 1e-40f;
    const SnellFarPlane g = p.run(beyond, towards);
    EXPECT_TRUE(g.valid);
    EXPECT_FLOAT_EQ(g.t, 20.0f);
  }
}

}  // namespace
