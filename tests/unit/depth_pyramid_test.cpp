// glsl/snell/intersect/depth_pyramid.glsl and include/snell/depth_pyramid.hpp:
// every level's min/max view distance against a brute-force scan of the
// analytic distances of the level-0 texels below it (footprints computed here
// from GL's floor mip sizes), coverage against the count of covered texels, and
// the mean level of a plane against the analytic depth at the block centre.
#include <gtest/gtest.h>

#include <snell/depth_pyramid.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <utility>

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

// snellDepthMinMaxReduce texel by texel against the contract's children, computed here: 2 x 2 blocks, the
// third column or row of odd sizes at the last texel, column / row 0 alone at size 1; a child counts when
// its w > 0; the sums in the same order (row by row), so the results agree exactly. Random texels with
// empty ones, on sizes odd and even, down to 1 x 1.
TEST(DepthPyramid, MinMaxReduceIsTheContractsChildrenByHand) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const float empty = 1.0f;
  for (const auto& [w, h] : {std::pair{8, 8}, {7, 5}, {5, 7}, {3, 3}, {2, 1}, {1, 2}, {1, 1}, {9, 1}, {1, 9}, {6, 3}}) {
    snell::Image level(w, h);
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const bool valid = u(rng) < 0.7f;
        const float y = 1.0f + 5.0f * u(rng);
        // Some children with the smallest coverage there is (a denormal w still counts: w > 0).
        const float cover = u(rng) < 0.1f ? 1e-40f : 0.1f + 0.9f * u(rng);
        level.at(i, j) = valid ? glm::vec4(u(rng), y, y + 3.0f * u(rng), cover) : glm::vec4(empty, 0.0f, 0.0f, 0.0f);
      }
    const snell::Texture2D tex(level);
    for (int py = 0; py < std::max(1, h / 2); ++py)
      for (int px = 0; px < std::max(1, w / 2); ++px) {
        const int x0 = w == 1 ? 0 : 2 * px, x1 = w == 1 ? 0 : (px == w / 2 - 1 ? w - 1 : 2 * px + 1);
        const int y0 = h == 1 ? 0 : 2 * py, y1 = h == 1 ? 0 : (py == h / 2 - 1 ? h - 1 : 2 * py + 1);
        float sum = 0.0f, coverage = 0.0f, nearest = 0.0f, farthest = 0.0f;
        int valid = 0, children = 0;
        for (int y = y0; y <= y1; ++y)
          for (int x = x0; x <= x1; ++x) {
            const glm::vec4 t = level.at(x, y);
            ++children;
            coverage += t.w;
            if (!(t.w > 0.0f)) continue;
            sum += t.x;
            nearest = valid == 0 ? t.y : std::min(nearest, t.y);
            farthest = valid == 0 ? t.z : std::max(farthest, t.z);
            ++valid;
          }
        const glm::vec4 want = valid == 0 ? glm::vec4(empty, 0.0f, 0.0f, 0.0f)
                                          : glm::vec4(sum / float(valid), nearest, farthest, coverage / float(children));
        const glm::vec4 got = snell::snellDepthMinMaxReduce(tex, 0, glm::ivec2(px, py), empty);
        EXPECT_EQ(got, want) << w << "x" << h << " texel " << px << "," << py << " (" << children << " children)";
      }
  }
}

// The smallest distance a base texel can hold: zNear = FLT_MIN at depth 0 is FLT_MIN away, and valid.
TEST(DepthPyramid, BaseKeepsTheSmallestDistance) {
  const snell::SnellDepthSurface s = snell::snellDepthSurface(glm::mat4(1.0f), FLT_MIN, 1.0f, SNELL_DEPTH_GL, 1.0f);
  EXPECT_EQ(snell::snellDepthPyramidBase(0.0f, s), glm::vec4(0.0f, FLT_MIN, FLT_MIN, 1.0f));
  EXPECT_EQ(snell::snellDepthPyramidBase(1.0f, s), glm::vec4(1.0f, 0.0f, 0.0f, 0.0f));  // the empty value
}
