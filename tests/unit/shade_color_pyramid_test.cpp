// glsl/snell/shade/color_pyramid.glsl and include/snell/color_pyramid.hpp:
// every level against a brute-force reduce in double written from the
// contract's definition (the tent max(0, 1 - |x - c| / 2) sampled at every
// texel within reach of the output texel's centre and normalised by its sum,
// the centre from the level sizes), on even, odd and degenerate sizes; a
// constant and an affine image against their analytic values; non-finite
// texels; and the reason for the chain: a read barely depends on where the
// image falls on the levels' grids, far less than through glGenerateMipmap's
// box chain.
#include <gtest/gtest.h>

#include <snell/color_pyramid.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

namespace {

using namespace snell;

Image randomImage(int w, int h, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 4.0f);
  Image img(w, h);
  for (vec4& t : img.texels) t = vec4(u(rng), u(rng), u(rng), u(rng));
  return img;
}

// The weights of the texels along one axis of a level of n texels for output texel p: the tent around the
// centre, sampled at every texel index within 2 of it (clamped to the edge afterwards), normalised.
std::vector<std::pair<int, double>> tentWeights(int p, int n) {
  const int m = std::max(1, n / 2);
  const double c = (p + 0.5) * double(n) / double(m) - 0.5;
  std::vector<std::pair<int, double>> w;
  double sum = 0.0;
  for (int i = int(std::floor(c)) - 3; i <= int(std::ceil(c)) + 3; ++i) {
    const double t = std::max(0.0, 1.0 - std::fabs(i - c) / 2.0);
    if (t > 0.0) {
      w.emplace_back(std::clamp(i, 0, n - 1), t);
      sum += t;
    }
  }
  for (auto& e : w) e.second /= sum;
  return w;
}

// Level L + 1 of `above` (level L) by brute force, non-finite texels as 0.
Image bruteReduce(const Image& above) {
  Image out(std::max(1, above.width / 2), std::max(1, above.height / 2));
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      glm::dvec4 s(0.0);
      for (const auto& [j, wy] : tentWeights(y, above.height))
        for (const auto& [i, wx] : tentWeights(x, above.width)) {
          const vec4 t = above.at(i, j);
          const bool finite = std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z) && std::isfinite(t.w);
          if (finite) s += wx * wy * glm::dvec4(t);
        }
      out.at(x, y) = vec4(s);
    }
  return out;
}

// Every level of snellBuildColorPyramid(base) against bruteReduce of the level below it (the built one, so
// rounding does not accumulate across levels), within float rounding.
void expectBruteForceLevels(const Image& base) {
  const Texture2D p = snellBuildColorPyramid(base);
  int levels = 1;
  for (int w = base.width, h = base.height; w > 1 || h > 1; w = std::max(1, w / 2), h = std::max(1, h / 2)) ++levels;
  ASSERT_EQ(p.levelCount(), levels);
  EXPECT_EQ(p.minFilter, Filter::Linear);
  EXPECT_EQ(p.mipFilter, MipFilter::Linear);
  for (int lod = 0; lod + 1 < p.levelCount(); ++lod) {
    const Image want = bruteReduce(p.level(lod));
    const Image& got = p.level(lod + 1);
    ASSERT_EQ(got.width, want.width);
    ASSERT_EQ(got.height, want.height);
    float worst = 0.0f;
    for (std::size_t i = 0; i < want.texels.size(); ++i)
      for (int c = 0; c < 4; ++c)
        worst = std::max(worst, std::fabs(got.texels[i][c] - want.texels[i][c]) / std::max(1.0f, std::fabs(want.texels[i][c])));
    EXPECT_LT(worst, 2e-6f) << base.width << "x" << base.height << " level " << lod + 1;
  }
}

TEST(ShadeColorPyramid, EveryLevelIsTheTentReduceOfTheOneBelow) {
  for (const auto& [w, h] : {std::pair{64, 64}, {96, 40}, {37, 22}, {5, 3}, {1, 7}, {9, 1}, {1, 1}, {320, 320}})
    expectBruteForceLevels(randomImage(w, h, unsigned(w * 1000 + h)));
}

TEST(ShadeColorPyramid, EvenLevelsWeighOneThreeThreeOne) {
  // A single bright texel: on an even level, the texels around it get its weights' products.
  Image img(16, 16);
  img.at(6, 9) = vec4(64.0f);
  const Texture2D p = snellBuildColorPyramid(img);
  // Output texel 3 reads 5..8 (weights 1, 3, 3, 1 / 8): texel 6 is its second; output 2 reads 3..6: its last.
  EXPECT_FLOAT_EQ(p.level(1).at(3, 4).x, 64.0f * (3.0f / 8.0f) * (3.0f / 8.0f));  // rows 7..10: 9 is the third
  EXPECT_FLOAT_EQ(p.level(1).at(2, 4).x, 64.0f * (1.0f / 8.0f) * (3.0f / 8.0f));
  EXPECT_FLOAT_EQ(p.level(1).at(3, 5).x, 64.0f * (3.0f / 8.0f) * (1.0f / 8.0f));  // rows 9..12: the first
  EXPECT_FLOAT_EQ(p.level(1).at(4, 4).x, 0.0f);
  // The reduce itself, on a texture with level 0 only: the same texel; a texel beyond the output level reads
  // as the nearest one inside it.
  const Texture2D base(img, Filter::Linear);
  EXPECT_EQ(snellColorPyramidReduce(base, 0, ivec2(3, 4)), p.level(1).at(3, 4));
  EXPECT_EQ(snellColorPyramidReduce(base, 0, ivec2(99, -4)), p.level(1).at(7, 0));
  EXPECT_EQ(snellColorPyramidReduce(base, 0, ivec2(-1, 5)), p.level(1).at(0, 5));
}

TEST(ShadeColorPyramid, AxisWeightsAndFirstTexel) {
  for (int n : {2, 3, 5, 8, 17, 640, 1}) {
    for (int px = 0; px < std::max(1, n / 2); ++px) {
      const SnellColorPyramidAxis a = snellColorPyramidAxis(px, n);
      // Brute force by unclamped index: the axis's four texels from `first`.
      const int m = std::max(1, n / 2);
      const double c = (px + 0.5) * double(n) / double(m) - 0.5;
      EXPECT_EQ(a.first, int(std::floor(c)) - 1) << n << " " << px;
      double sum = 0.0;
      for (int k = 0; k < 4; ++k) {
        const double t = std::max(0.0, 1.0 - std::fabs(a.first + k - c) / 2.0);
        EXPECT_NEAR(double(a.weights[k]), t / 2.0, 1e-6) << n << " " << px << " tap " << k;
        sum += double(a.weights[k]);
      }
      EXPECT_NEAR(sum, 1.0, 1e-6);
    }
  }
  // Out of range: px clamped into the output level, sizes below 1 read as 1.
  EXPECT_EQ(snellColorPyramidAxis(99, 8).first, snellColorPyramidAxis(3, 8).first);
  EXPECT_EQ(snellColorPyramidAxis(-5, 8).first, snellColorPyramidAxis(0, 8).first);
  EXPECT_EQ(snellColorPyramidAxis(0, 0).first, snellColorPyramidAxis(0, 1).first);
  EXPECT_EQ(snellColorPyramidAxis(0, -3).first, -1);
}

TEST(ShadeColorPyramid, ConstantAndAffineImagesStayExact) {
  Image flat(50, 34, vec4(0.25f, 1.5f, 3.0f, 1.0f));
  const Texture2D pf = snellBuildColorPyramid(flat);
  for (int lod = 1; lod < pf.levelCount(); ++lod)
    for (const vec4& t : pf.level(lod).texels) {
      EXPECT_NEAR(t.x, 0.25f, 1e-6f);
      EXPECT_NEAR(t.y, 1.5f, 1e-6f);
      EXPECT_NEAR(t.z, 3.0f, 1e-6f);
      EXPECT_NEAR(t.w, 1.0f, 1e-6f);
    }
  // An affine image (x and y of the texel centre, level-0 units): level 1 holds it at each texel's centre,
  // where the four taps lie inside the image.
  Image ramp(64, 48);
  for (int y = 0; y < ramp.height; ++y)
    for (int x = 0; x < ramp.width; ++x) ramp.at(x, y) = vec4(float(x) + 0.5f, float(y) + 0.5f, 2.0f * (float(x) + 0.5f) - (float(y) + 0.5f), 0.0f);
  const Texture2D pr = snellBuildColorPyramid(ramp);
  const Image& l1 = pr.level(1);
  for (int y = 1; y + 1 < l1.height; ++y)
    for (int x = 1; x + 1 < l1.width; ++x) {
      const float cx = 2.0f * (float(x) + 0.5f), cy = 2.0f * (float(y) + 0.5f);
      EXPECT_NEAR(l1.at(x, y).x, cx, 1e-4f);
      EXPECT_NEAR(l1.at(x, y).y, cy, 1e-4f);
      EXPECT_NEAR(l1.at(x, y).z, 2.0f * cx - cy, 1e-4f);
    }
}

TEST(ShadeColorPyramid, AnEmptyImageIsAnError) {
  EXPECT_THROW(snellBuildColorPyramid(Image()), std::invalid_argument);
}

TEST(ShadeColorPyramid, NonFiniteTexelsCountAsZero) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  Image img = randomImage(33, 20, 7);
  img.at(4, 5) = vec4(nan, 1.0f, 1.0f, 1.0f);
  img.at(20, 11) = vec4(1.0f, inf, 1.0f, 1.0f);
  img.at(32, 19) = vec4(1.0f, 1.0f, 1.0f, -inf);
  Image zeroed = img;
  for (const auto& [x, y] : {std::pair{4, 5}, {20, 11}, {32, 19}}) zeroed.at(x, y) = vec4(0.0f);
  const Texture2D p = snellBuildColorPyramid(img), z = snellBuildColorPyramid(zeroed);
  for (int lod = 1; lod < p.levelCount(); ++lod)
    for (std::size_t i = 0; i < p.level(lod).texels.size(); ++i)
      for (int c = 0; c < 4; ++c) {
        ASSERT_TRUE(std::isfinite(p.level(lod).texels[i][c])) << "level " << lod;
        EXPECT_EQ(p.level(lod).texels[i][c], z.level(lod).texels[i][c]);
      }
  EXPECT_EQ(snellColorPyramidTexel(vec4(1.0f, 2.0f, nan, 4.0f)), vec4(0.0f));
  EXPECT_EQ(snellColorPyramidTexel(vec4(1.0f, 2.0f, 3.0f, 4.0f)), vec4(1.0f, 2.0f, 3.0f, 4.0f));
  EXPECT_EQ(snellColorPyramidTexel(vec4(-0.0f, 1e-40f, -3.0f, 3.4e38f)), vec4(-0.0f, 1e-40f, -3.0f, 3.4e38f));
}

// How wide a read is: a bright column read across at level L (trilinear) spreads around the column with
// the standard deviation the contract gives, sqrt(0.25 (4^L - 1) + 4^L / 6) level-0 texels for the tent
// chain (about 0.65 x 2^L) and sqrt((4^L - 1) / 12 + 4^L / 6) for the box chain (0.5 x 2^L), averaged over
// where the column falls on the level's grid.
TEST(ShadeColorPyramid, AReadIsAsWideAsTheContractSays) {
  const int n = 512;
  for (int level : {2, 3, 4}) {
    const double cells = std::ldexp(1.0, level);
    double tentVar = 0.0, boxVar = 0.0;
    const int positions = 8;
    for (int k = 0; k < positions; ++k) {
      const int x0 = n / 2 + int(k * cells / positions);
      Image img(n, 8);
      for (int y = 0; y < img.height; ++y) img.at(x0, y) = vec4(1.0f);
      Texture2D box(img, Filter::Linear, MipFilter::Linear);
      box.generateMipmaps();
      const Texture2D tent = snellBuildColorPyramid(img);
      const auto variance = [&](const Texture2D& t) {
        double w = 0.0, m1 = 0.0, m2 = 0.0;
        for (int i = 0; i < 16 * n; ++i) {
          const double x = (i + 0.5) / 16.0;  // level-0 texel units
          const double r = double(t.sampleLod(vec2(float(x / n), 0.5f), float(level)).x);
          const double d = x - (x0 + 0.5);
          w += r;
          m1 += r * d;
          m2 += r * d * d;
        }
        // About the column, not the read's own mean: the box chain moves what it blurs to its block's
        // centre, which is spread too (a third of its variance); the tent chain keeps the mean in place.
        if (&t == &tent) {
          EXPECT_NEAR(m1 / w, 0.0, 1e-3 * cells) << "level " << level << " column " << x0;
        }
        return m2 / w;
      };
      tentVar += variance(tent) / positions;
      boxVar += variance(box) / positions;
    }
    const double fourL = cells * cells;
    const double tentWant = 0.25 * (fourL - 1.0) + fourL / 6.0, boxWant = (fourL - 1.0) / 12.0 + fourL / 6.0;
    std::printf("[width] level %d: sd tent %.3f (contract %.3f) box %.3f (contract %.3f) texels\n", level,
                std::sqrt(tentVar), std::sqrt(tentWant), std::sqrt(boxVar), std::sqrt(boxWant));
    EXPECT_NEAR(std::sqrt(tentVar), std::sqrt(tentWant), 0.03 * std::sqrt(tentWant)) << "level " << level;
    EXPECT_NEAR(std::sqrt(boxVar), std::sqrt(boxWant), 0.03 * std::sqrt(boxWant)) << "level " << level;
  }
}

// Why the chain: the same picture moved by one level-0 texel, read through the same point of the picture
// (its uv moved along) at levels 2.5 to 4.5: the read changes only as much as a blur of that width lets
// it, not by where the picture falls on the coarse levels' grids. Noise is the hardest case (all its
// energy near the Nyquist frequency of the finer levels). At equal width (the box chain read 0.37 levels
// higher, as the test above measures) the tent chain's reads change less than half as much as the box
// chain's.
TEST(ShadeColorPyramid, AReadBarelyDependsOnWhereThePictureFallsOnTheGrid) {
  const int n = 256;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<float> noise(static_cast<std::size_t>(n + 1) * (n + 1));
  for (float& v : noise) v = u(rng);
  Image a(n, n), b(n, n);  // b: the picture moved right by one texel
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      a.at(x, y) = vec4(noise[std::size_t(y) * (n + 1) + x + 1]);
      b.at(x, y) = vec4(noise[std::size_t(y) * (n + 1) + x]);
    }
  const auto change = [&](Texture2D ta, Texture2D tb, float lod) {
    double diff = 0.0, signal = 0.0;
    std::mt19937 pick(5);
    std::uniform_real_distribution<float> at(0.25f, 0.75f);
    for (int k = 0; k < 4000; ++k) {
      const vec2 uv(at(pick), at(pick));
      const float ra = ta.sampleLod(uv, lod).x, rb = tb.sampleLod(uv + vec2(1.0f / n, 0.0f), lod).x;
      diff += double(ra - rb) * double(ra - rb);
      signal += double(ra - 0.5f) * double(ra - 0.5f);
    }
    return std::sqrt(diff / signal);
  };
  for (float lod : {2.5f, 3.0f, 3.5f, 4.0f, 4.5f}) {
    Texture2D boxA(a, Filter::Linear, MipFilter::Linear), boxB(b, Filter::Linear, MipFilter::Linear);
    boxA.generateMipmaps();
    boxB.generateMipmaps();
    const double tent = change(snellBuildColorPyramid(a), snellBuildColorPyramid(b), lod);
    // At equal width: the box read log2(0.65 / 0.5) levels higher (the contract's standard deviations).
    const double box = change(boxA, boxB, lod + std::log2(0.65f / 0.5f));
    std::printf("[shift] lod %.1f: relative change tent %.3f box %.3f\n", double(lod), tent, box);
    EXPECT_LT(tent, 0.5 * box) << "lod " << lod;
  }
}

}  // namespace
