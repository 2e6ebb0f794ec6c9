// The rough read's two taps (glsl/snell/shade/rough_cone.glsl, snellRoughConeTaps and the reads): their
// constants against a brute-force fit of GGX's lobe, the levels and reads against the contract written out
// in double, smooth glass reading exactly as before, and bad levels.
#include <gtest/gtest.h>

#include <snell/snell.hpp>

#include "support/rough_read.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace {

using namespace snell;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// GGX's distribution of slopes with width a is the bivariate Student t with 2 degrees of freedom,
// 1 / (pi a^2 (1 + |m|^2 / a^2)^2); its spectrum (a 2D radial Fourier transform) is w a K1(w a).
// A read at level L is taken as a Gaussian of standard deviation proportional to 2^L: spectrum
// exp(-sigma^2 w^2 / 2). The distance of a blur kernel from the lobe: the squared difference of the
// spectra weighted as natural images' 1 / f^2 power spectrum weighs it, which over a 2D frequency plane is
// an integral in log frequency.
struct LobeFit {
  std::vector<double> w, lobe;
  LobeFit() {
    for (int i = 0; i < 500; ++i) {
      const double f = std::exp(-7.0 + 0.02 * i);
      w.push_back(f);
      lobe.push_back(f * std::cyl_bessel_k(1.0, f));
    }
  }
  double distance(double sigma1, double sigma2, double tailWeight) const {
    double sum = 0.0;
    for (std::size_t i = 0; i < w.size(); ++i) {
      const double g1 = std::exp(-0.5 * sigma1 * sigma1 * w[i] * w[i]);
      const double g2 = std::exp(-0.5 * sigma2 * sigma2 * w[i] * w[i]);
      const double d = lobe[i] - ((1.0 - tailWeight) * g1 + tailWeight * g2);
      sum += d * d;
    }
    return sum * 0.02;
  }
};

// The constants are the fit the contract names: a brute-force search over single Gaussians, then over
// mixtures of two, finds the library's offsets (relative to the single one) and weight within its steps,
// and the library's mixture is within 2 % of the best one found and over ten times nearer the lobe than the
// best single read.
TEST(ShadeRoughTaps, TheConstantsAreTheTwoGaussianFitOfTheGgxLobe) {
  const LobeFit fit;
  double bestSingle = 1e30, sigma0 = 0.0;
  for (int i = 0; i <= 1000; ++i) {
    const double s = 0.5 + 0.001 * i;
    const double d = fit.distance(s, s, 0.0);
    if (d < bestSingle) bestSingle = d, sigma0 = s;
  }
  double best = 1e30, s1 = 0.0, s2 = 0.0, weight = 0.0;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 60; ++j)
      for (int k = 0; k <= 40; ++k) {
        const double a = 0.45 + 0.01 * i, b = 1.5 + 0.02 * j, t = 0.2 + 0.005 * k;
        const double d = fit.distance(a, b, t);
        if (d < best) best = d, s1 = a, s2 = b, weight = t;
      }
  ASSERT_GT(s1, 0.45);  // the optimum is inside the searched box, not on its edge
  ASSERT_LT(s1, 0.85);
  ASSERT_GT(s2, 1.5);
  ASSERT_LT(s2, 2.7);
  ASSERT_GT(weight, 0.2);
  ASSERT_LT(weight, 0.4);
  EXPECT_NEAR(double(SNELL_ROUGH_CONE_CORE_OFFSET), std::log2(s1 / sigma0), 0.03);
  EXPECT_NEAR(double(SNELL_ROUGH_CONE_TAIL_OFFSET), std::log2(s2 / sigma0), 0.03);
  EXPECT_NEAR(double(SNELL_ROUGH_CONE_TAIL_WEIGHT), weight, 0.01);
  const double library = fit.distance(sigma0 * std::exp2(double(SNELL_ROUGH_CONE_CORE_OFFSET)),
                                       sigma0 * std::exp2(double(SNELL_ROUGH_CONE_TAIL_OFFSET)),
                                       double(SNELL_ROUGH_CONE_TAIL_WEIGHT));
  EXPECT_LT(library, 1.02 * best);
  EXPECT_LT(10.0 * library, bestSingle);
}

TEST(ShadeRoughTaps, LevelsFollowTheContract) {
  using snell_test::kRoughCoreOffset, snell_test::kRoughTailOffset, snell_test::kRoughTailWeight;
  for (int levels : {2, 5, 10}) {
    const double top = levels - 1;
    for (int i = 1; i <= 200; ++i) {
      const float lod = 0.05f * float(i);
      const SnellRoughTaps t = snellRoughConeTaps(lod, levels);
      const double l = std::min(double(lod), top);
      const double c = std::clamp(l + kRoughCoreOffset, 0.0, top), w = std::clamp(l + kRoughTailOffset, 0.0, top);
      EXPECT_NEAR(t.coreLod, c, 1e-6) << lod << " of " << levels;
      EXPECT_NEAR(t.tailLod, w, 1e-6) << lod << " of " << levels;
      EXPECT_GT(t.tailLod, t.coreLod);
      EXPECT_NEAR(t.tailWeight, kRoughTailWeight, 1e-7);
      EXPECT_EQ(snellRoughConeFetches(t), 2);
    }
  }
}

// Smooth glass (level 0), a chain of one level, and levels that are no number read once at level 0.
TEST(ShadeRoughTaps, LevelZeroAndBadInputReadOnceAtTheBase) {
  for (const float lod : {0.0f, -1.0f, -0.0f, kNaN, -std::numeric_limits<float>::infinity()}) {
    const SnellRoughTaps t = snellRoughConeTaps(lod, 10);
    EXPECT_EQ(t.coreLod, 0.0f) << lod;
    EXPECT_EQ(t.tailWeight, 0.0f) << lod;
    EXPECT_EQ(snellRoughConeFetches(t), 1);
  }
  for (const int levels : {1, 0, -3}) {
    const SnellRoughTaps t = snellRoughConeTaps(3.0f, levels);
    EXPECT_EQ(t.coreLod, 0.0f) << levels;
    EXPECT_EQ(t.tailWeight, 0.0f) << levels;
  }
  // Beyond the chain: the tail at the top level, the core still below it.
  const SnellRoughTaps inf = snellRoughConeTaps(std::numeric_limits<float>::infinity(), 6);
  EXPECT_NEAR(inf.coreLod, 5.0 + snell_test::kRoughCoreOffset, 1e-6);
  EXPECT_EQ(inf.tailLod, 5.0f);
  EXPECT_NEAR(inf.tailWeight, snell_test::kRoughTailWeight, 1e-7);
}

// The reads against the texture's own samples mixed in double; at level 0 the read is the texture's read to
// the bit, so smooth glass looks exactly as it did with one read.
TEST(ShadeRoughTaps, ReadsMixTheTwoLevelsOfTheTexture) {
  Image img(64, 32, glm::vec4(0.0f));
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      img.at(x, y) = glm::vec4(float((x * 7 + y * 3) % 11) / 10.0f, float(x % 2), float(y) / 32.0f, 1.0f);
  Texture2D tex(img, Filter::Linear, MipFilter::Linear);
  tex.generateMipmaps();
  const int levels = tex.levelCount();
  for (const float lod : {0.0f, 0.3f, 1.0f, 2.7f, 4.9f, 6.0f}) {
    for (const glm::vec2 uv : {glm::vec2(0.31f, 0.62f), glm::vec2(0.9f, 0.05f)}) {
      const SnellRoughTaps t = snellRoughConeTaps(lod, levels);
      const glm::vec4 got = snellRoughConeSample(tex, uv, t);
      if (lod == 0.0f) {
        EXPECT_EQ(got, tex.sampleLod(uv, 0.0f));
        continue;
      }
      const glm::dvec4 a(tex.sampleLod(uv, t.coreLod)), b(tex.sampleLod(uv, t.tailLod));
      const glm::dvec4 want = t.tailWeight > 0.0f ? (1.0 - double(t.tailWeight)) * a + double(t.tailWeight) * b : a;
      for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], 1e-6) << lod << " channel " << c;
    }
  }
  // The environment's read: the same mix of snellSampleEquirect at the two levels.
  const glm::vec3 dir(0.3f, -0.2f, 0.9f);
  const SnellRoughTaps t = snellRoughConeTaps(2.2f, levels);
  const glm::dvec4 want = (1.0 - double(t.tailWeight)) * glm::dvec4(snellSampleEquirect(tex, dir, t.coreLod)) +
                          double(t.tailWeight) * glm::dvec4(snellSampleEquirect(tex, dir, t.tailLod));
  const glm::vec4 got = snellRoughConeSampleEnvironment(tex, dir, t);
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], 1e-6);
}

}  // namespace
