// glsl/snell/intersect/depth_pyramid.glsl and include/snell/depth_pyramid.hpp:
// every level's min/max view distance against a brute-force scan of the
// analytic distances of the level-0 texels below it (footprints computed here
// from GL's floor mip sizes), coverage against the count of covered texels, and
// the mean level of a plane against the analytic depth at the block centre.
#include <gtest/gtest.h>

#include <snell/depth_pyramid.hpp>

#include <cmath>
#include <limits>

#include "support/depth_scenes.hpp"

namespace {

using namespace snell;
using snell_test::DepthScene;

// Level-0 index range [lo, hi] below index i of level L along one axis of size n0.
std::pair<int, int> footprint(int n0, int level, int i) {
  int lo = i, hi = i;
  for (int l = level; l > 0; --l) {
    int n = n0;  // size of level l - 1
    for (int k = 0; k < l - 1; ++k) n = std::max(1, n / 2);
    const int last = std::max(1, n / 2) - 1;
    const int nlo = 2 * lo;
    const int nhi = n == 1 ? 0 : (hi == last ? n - 1 : 2 * hi + 1);
    lo = n == 1 ? 0 : nlo;
    hi = nhi;
  }
  return {lo, hi};
}

void checkPyramid(const DepthScene& sc) {
  const Texture2D p = snellBuildDepthPyramid(sc.depth, sc.surface());
  ASSERT_EQ(p.level(p.levelCount() - 1).width, 1);
  ASSERT_EQ(p.level(p.levelCount() - 1).height, 1);
  for (int lod = 0; lod < p.levelCount(); ++lod) {
    const Image& img = p.level(lod);
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const auto fx = footprint(sc.width, lod, x), fy = footprint(sc.height, lod, y);
        double mn = 1e30, mx = -1.0;
        int covered = 0;
        for (int j = fy.first; j <= fy.second; ++j)
          for (int i = fx.first; i <= fx.second; ++i) {
            const snell_test::AnalyticSample a = sc.sampleAt({(i + 0.5) / sc.width, (j + 0.5) / sc.height});
            if (!a.valid) continue;
            ++covered;
            mn = std::min(mn, a.s);
            mx = std::max(mx, a.s);
          }
        const glm::vec4 t = img.at(x, y);
        SCOPED_TRACE(sc.name + " level " + std::to_string(lod) + " texel " + std::to_string(x) + "," + std::to_string(y));
        if (covered == 0) {
          EXPECT_EQ(t, glm::vec4(sc.emptyDepth, 0.0f, 0.0f, 0.0f));
          continue;
        }
        EXPECT_GT(t.w, 0.0f);
        EXPECT_LE(t.w, 1.0f);
        EXPECT_NEAR(t.y, mn, 3e-5 * mn);
        EXPECT_NEAR(t.z, mx, 3e-5 * mx);
        const int all = (fx.second - fx.first + 1) * (fy.second - fy.first + 1);
        if (covered == all) {
          EXPECT_EQ(t.w, 1.0f);
        }
      }
  }
}

TEST(DepthPyramid, MinMaxMatchBruteForceOnEveryScene) {
  for (int conv : {SNELL_DEPTH_GL, SNELL_DEPTH_REVERSED, SNELL_DEPTH_INFINITE_REVERSED}) {
    checkPyramid(snell_test::sphereBack(67, 45, conv));   // odd sizes: 3-wide footprints
    checkPyramid(snell_test::silhouette(64, 40, conv));
    checkPyramid(snell_test::thinSpike(50, 64, conv));
    checkPyramid(snell_test::stepEdge(33, 17, conv));
  }
}

TEST(DepthPyramid, MeanLevelOfAPlaneIsTheDepthAtTheBlockCentre) {
  const DepthScene sc = snell_test::slantedPlane(128, 64);
  const Texture2D p = snellBuildDepthPyramid(sc.depth, sc.surface());
  for (int lod = 1; lod < p.levelCount(); ++lod) {
    const Image& img = p.level(lod);
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const glm::dvec2 uv((x + 0.5) / img.width, (y + 0.5) / img.height);
        const double d = sc.windowDepth(sc.sampleAt(uv).s);
        EXPECT_NEAR(img.at(x, y).x, d, 2e-6) << lod;
      }
  }
}

TEST(DepthPyramid, EmptyAndNaNBuffersStayEmpty) {
  DepthScene sc = snell_test::sphereBack(20, 12);
  for (glm::vec4& t : sc.depth.level(0).texels) t.x = sc.emptyDepth;
  sc.depth.level(0).at(3, 4).x = std::numeric_limits<float>::quiet_NaN();
  const Texture2D p = snellBuildDepthPyramid(sc.depth, sc.surface());
  for (int lod = 0; lod < p.levelCount(); ++lod)
    for (const glm::vec4& t : p.level(lod).texels) EXPECT_EQ(t, glm::vec4(sc.emptyDepth, 0.0f, 0.0f, 0.0f));
}

TEST(DepthPyramid, NormalMipsHaveEveryLevel) {
  const DepthScene sc = snell_test::sphereBack(64, 32);
  const Texture2D n = snellBuildNormalMips(sc.normals);
  EXPECT_EQ(n.levelCount(), 7);
  EXPECT_EQ(n.mipFilter, MipFilter::Linear);
}

}  // namespace
