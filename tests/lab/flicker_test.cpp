// The flicker measure (lab/flicker.hpp) on small hand-made images whose answer is worked out here: a row that
// follows the truth reads 0, a row that adds a known offset per frame reads that offset, and only the pixels in
// both frames' masks count.
#include "lab/flicker.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

using snell::Image;
using snell::vec4;
using snell::lab::FlickerPair;
using snell::lab::Mask;
using snell::lab::meanFlicker;
using snell::lab::pairFlicker;

namespace {

// A 4x3 image whose pixel (x, y) holds (0.1 x + 0.05 y + shift) in every channel, alpha 1.
Image ramp(float shift) {
  Image im(4, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 4; ++x) {
      const float v = 0.1f * static_cast<float>(x) + 0.05f * static_cast<float>(y) + shift;
      im.at(x, y) = vec4(v, v, v, 1.0f);
    }
  return im;
}

Mask full(int w, int h) {
  Mask m(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) m.set(x, y, true);
  return m;
}

}  // namespace

TEST(LabFlicker, AStaticRowEqualToTheTruthReadsZero) {
  const Image truth = ramp(0.2f);
  const FlickerPair p = pairFlicker(truth, truth, full(4, 3), full(4, 3), truth, truth);
  EXPECT_EQ(p.flicker, 0.0);
  EXPECT_EQ(p.truthChange, 0.0);
  EXPECT_EQ(p.pixels, 12u);
}

TEST(LabFlicker, ARowThatFollowsAMovingTruthWithAFixedErrorReadsZero) {
  // The truth brightens by 0.1 between the frames; the row is off by a constant 0.05 in both: an error that
  // does not change between frames is no flicker.
  const FlickerPair p = pairFlicker(ramp(0.1f), ramp(0.2f), full(4, 3), full(4, 3), ramp(0.15f), ramp(0.25f));
  EXPECT_NEAR(p.flicker, 0.0, 1e-6);
  EXPECT_NEAR(p.truthChange, 0.1, 1e-6);
}

TEST(LabFlicker, AKnownOffsetPerFrameReadsThatOffset) {
  // A static truth; the row adds +0.03 in frame 1 and -0.02 in frame 2 (each frame's offset from frame 0's),
  // in the red channel alone: per pair, |change| is 0.03 then 0.05 on one channel of three.
  const Image truth = ramp(0.2f);
  Image row1 = truth, row2 = truth;
  for (vec4& c : row1.texels) c.x += 0.03f;
  for (vec4& c : row2.texels) c.x -= 0.02f;
  const Mask m = full(4, 3);
  const FlickerPair a = pairFlicker(truth, truth, m, m, truth, row1);
  const FlickerPair b = pairFlicker(truth, truth, m, m, row1, row2);
  EXPECT_NEAR(a.flicker, 0.03 / 3.0, 1e-6);
  EXPECT_NEAR(b.flicker, 0.05 / 3.0, 1e-6);
  // The run's flicker weighs the pairs alike.
  EXPECT_NEAR(meanFlicker({a, b}), 0.5 * (0.03 + 0.05) / 3.0, 1e-6);
  EXPECT_EQ(meanFlicker({}), 0.0);
}

TEST(LabFlicker, ValuesAreClampedToTheUnitRangeFirst) {
  // Beyond 1 the picture cannot show a change (linear RGB clamped as the MSE is): 1.5 -> 2.5 reads as 1 -> 1.
  Image before(1, 1, vec4(1.5f, 0.5f, 0.5f, 1.0f)), after(1, 1, vec4(2.5f, 0.5f, 0.5f, 1.0f));
  const Image truth(1, 1, vec4(0.5f, 0.5f, 0.5f, 1.0f));
  EXPECT_EQ(pairFlicker(truth, truth, full(1, 1), full(1, 1), before, after).flicker, 0.0);
}

TEST(LabFlicker, OnlyPixelsInBothFramesMasksCount) {
  // Pixel (0, 0) jumps by 0.9 in the row; it is in frame 0's mask only, so it does not count; pixel (1, 0),
  // in both, changes by 0.3 in every channel.
  const Image truth(2, 1, vec4(0.0f, 0.0f, 0.0f, 1.0f));
  Image before(2, 1, vec4(0.0f, 0.0f, 0.0f, 1.0f)), after = before;
  after.at(0, 0) = vec4(0.9f, 0.9f, 0.9f, 1.0f);
  after.at(1, 0) = vec4(0.3f, 0.3f, 0.3f, 1.0f);
  Mask m0(2, 1), m1(2, 1);
  m0.set(0, 0, true);
  m0.set(1, 0, true);
  m1.set(1, 0, true);
  const FlickerPair p = pairFlicker(truth, truth, m0, m1, before, after);
  EXPECT_EQ(p.pixels, 1u);
  EXPECT_NEAR(p.flicker, 0.3, 1e-6);
  // The same the other way round: the intersection, not frame 0's or frame 1's mask alone.
  EXPECT_NEAR(pairFlicker(truth, truth, m1, m0, before, after).flicker, 0.3, 1e-6);
  // No pixel in both: nothing to measure, 0.
  Mask none(2, 1);
  EXPECT_EQ(pairFlicker(truth, truth, m0, none, before, after).pixels, 0u);
  EXPECT_EQ(pairFlicker(truth, truth, m0, none, before, after).flicker, 0.0);
}

TEST(LabFlicker, SizesThatDifferAreRefused) {
  const Image a(2, 2), b(3, 2);
  const Mask m(2, 2);
  EXPECT_THROW(pairFlicker(a, a, m, m, a, b), std::invalid_argument);
  EXPECT_THROW(pairFlicker(a, a, m, Mask(3, 2), a, a), std::invalid_argument);
}
