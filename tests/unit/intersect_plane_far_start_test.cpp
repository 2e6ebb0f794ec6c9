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

}  // namespace
