// snell::gpu::compareFrames (include/snell/gpu/frame_compare.hpp), the
// whole-frame GPU-vs-C++ comparison of the lab, the gallery and the GPU tests,
// on images whose differences are set by hand.
#include <snell/gpu/frame_compare.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace {

using snell::Image;
using snell::gpu::ClampChannels;
using snell::gpu::compareFrames;

Image filled(int w, int h, glm::vec4 v) {
  Image img(w, h);
  for (glm::vec4& t : img.texels) t = v;
  return img;
}

auto all = [](int, int) { return true; };

}  // namespace

TEST(FrameCompare, CountsByTheLargestChannel) {
  Image a = filled(4, 2, glm::vec4(0.5f)), b = a;
  b.at(1, 0).y += 0.5f / 255.0f;  // within 1/255
  b.at(2, 0).z += 2.0f / 255.0f;  // beyond 1/255, not beyond 4
  b.at(3, 1).x -= 5.0f / 255.0f;  // beyond 4/255: the worst
  b.at(0, 1).w = 7.0f;            // alpha is not compared
  std::vector<std::pair<int, int>> beyond;
  const auto c = compareFrames(a, b, all, ClampChannels::No, [&](int x, int y) { beyond.push_back({x, y}); });
  EXPECT_EQ(c.pixels, 8u);
  EXPECT_EQ(c.within1, 6u);
  EXPECT_EQ(c.beyond4, 1u);
  EXPECT_NEAR(c.maxAbs, 5.0 / 255.0, 1e-7);
  EXPECT_EQ(c.worstX, 3);
  EXPECT_EQ(c.worstY, 1);
  ASSERT_EQ(beyond.size(), 1u);
  EXPECT_EQ(beyond[0], std::make_pair(3, 1));
  EXPECT_DOUBLE_EQ(c.shareWithin1(), 0.75);
  EXPECT_DOUBLE_EQ(c.shareBeyond1(), 0.25);
  EXPECT_DOUBLE_EQ(c.shareBeyond4(), 0.125);
}

TEST(FrameCompare, ANaNNeverAgrees) {
  Image a = filled(2, 1, glm::vec4(0.5f)), b = a;
  b.at(1, 0).y = std::numeric_limits<float>::quiet_NaN();
  for (ClampChannels k : {ClampChannels::No, ClampChannels::ToUnit}) {
    int called = 0;
    const auto c = compareFrames(a, b, all, k, [&](int x, int) { called += x == 1; });
    EXPECT_EQ(c.within1, 1u);
    EXPECT_EQ(c.beyond4, 1u);
    EXPECT_EQ(c.nanPixels, 1u);
    EXPECT_EQ(called, 1);
    EXPECT_EQ(c.maxAbs, 0.0);  // the largest finite difference: reports stay numbers
    EXPECT_EQ(c.worstX, -1);
  }
}

TEST(FrameCompare, ClampsToDisplayableValuesOnRequest) {
  const Image a = filled(1, 1, glm::vec4(1.5f, -2.0f, 0.25f, 1.0f)), b = filled(1, 1, glm::vec4(1.0f, 0.0f, 0.25f, 1.0f));
  EXPECT_EQ(compareFrames(a, b, all, ClampChannels::ToUnit).within1, 1u);
  const auto c = compareFrames(a, b, all, ClampChannels::No);
  EXPECT_EQ(c.within1, 0u);
  EXPECT_DOUBLE_EQ(c.maxAbs, 2.0);
}

TEST(FrameCompare, OnlyTheChosenPixelsAndEqualSizes) {
  Image a = filled(3, 3, glm::vec4(0.0f)), b = filled(3, 3, glm::vec4(1.0f));
  const auto c = compareFrames(a, b, [](int x, int y) { return x == 1 && y == 2; });
  EXPECT_EQ(c.pixels, 1u);
  EXPECT_EQ(c.worstX, 1);
  EXPECT_EQ(c.worstY, 2);
  const auto none = compareFrames(a, a, all);
  EXPECT_EQ(none.worstX, -1);  // nothing differs
  EXPECT_EQ(none.within1, 9u);
  EXPECT_THROW(compareFrames(a, filled(2, 3, glm::vec4(0.0f)), all), std::invalid_argument);
}
