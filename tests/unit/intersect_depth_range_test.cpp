// glsl/snell/intersect/depth_range.glsl against its contract, computed here: the top level's index by
// halving, the pyramid's top texel read back with the margin applied, and the box's eight corners
// transformed in double.
#include <gtest/gtest.h>

#include <snell/intersect.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <random>

namespace {

using namespace snell;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// A full mip chain of a width x height texture, every level filled with `fill`, the top level's texel `top`.
Texture2D chain(int width, int height, glm::vec4 fill, glm::vec4 top) {
  if (width == 1 && height == 1) return Texture2D(Image(1, 1, top));
  Texture2D t(Image(width, height, fill));
  while (width > 1 || height > 1) {
    width = std::max(width / 2, 1);
    height = std::max(height / 2, 1);
    t.addLevel(width == 1 && height == 1 ? Image(1, 1, top) : Image(width, height, fill));
  }
  return t;
}

TEST(IntersectDepthRange, TopLodIsTheLastLevelOfAFullChain) {
  for (const auto& [w, h] : {std::pair{1, 1}, {2, 1}, {1, 2}, {3, 5}, {4, 4}, {255, 1}, {256, 100}, {257, 3},
                             {1000, 7}, {7, 1000}, {4096, 2}}) {
    int expected = 0;
    for (int m = std::max(w, h); m > 1; m /= 2) ++expected;
    EXPECT_EQ(snellTextureTopLod(Texture2D(Image(w, h))), expected) << w << "x" << h;
  }
}

TEST(IntersectDepthRange, PyramidRangeIsTheTopTexelWidenedByTheMargin) {
  const glm::vec4 garbage(0.0f, 9.0f, 1.0f, 0.0f);  // invalid if any level but the top were read
  const double m = SNELL_DEPTH_RANGE_MARGIN;
  const SnellDepthRange r = snellDepthRangeFromPyramid(chain(40, 24, garbage, glm::vec4(0.0f, 2.0f, 5.0f, 0.5f)));
  ASSERT_TRUE(r.valid);
  EXPECT_FLOAT_EQ(r.zNearest, float(-2.0 * (1.0 - m)));
  EXPECT_FLOAT_EQ(r.zFarthest, float(-5.0 * (1.0 + m)));
  EXPECT_NE(r.zNearest, -2.0f);  // the margin is applied
  // A fronto-parallel surface (y == z) gets a range with the surface strictly inside.
  const SnellDepthRange flat = snellDepthRangeFromPyramid(chain(8, 8, garbage, glm::vec4(0.0f, 3.0f, 3.0f, 1.0f)));
  ASSERT_TRUE(flat.valid);
  EXPECT_GT(flat.zNearest, -3.0f);
  EXPECT_LT(flat.zFarthest, -3.0f);
  // The smallest coverage and the smallest nearest distance still count (0 < w, 0 < y).
  EXPECT_TRUE(snellDepthRangeFromPyramid(chain(8, 8, garbage, glm::vec4(0.0f, 2.0f, 5.0f, 1e-40f))).valid);
  EXPECT_TRUE(snellDepthRangeFromPyramid(chain(8, 8, garbage, glm::vec4(0.0f, 1e-40f, 5.0f, 1.0f))).valid);
  EXPECT_TRUE(snellDepthRangeFromPyramid(chain(1, 1, garbage, glm::vec4(0.0f, 2.0f, 5.0f, 1.0f))).valid);
  // Invalid: no coverage, y <= 0, z < y, a non-finite z or NaN.
  for (const glm::vec4 top : {glm::vec4(0.0f, 2.0f, 5.0f, 0.0f), glm::vec4(0.0f, 0.0f, 5.0f, 1.0f),
                              glm::vec4(0.0f, -1.0f, 5.0f, 1.0f), glm::vec4(0.0f, 5.0f, 2.0f, 1.0f),
                              glm::vec4(0.0f, 2.0f, kInf, 1.0f), glm::vec4(0.0f, kNaN, 5.0f, 1.0f),
                              glm::vec4(0.0f, 2.0f, 5.0f, kNaN)}) {
    const SnellDepthRange bad = snellDepthRangeFromPyramid(chain(8, 8, garbage, top));
    EXPECT_FALSE(bad.valid) << top.y << " " << top.z << " " << top.w;
    EXPECT_EQ(bad.zNearest, 0.0f);
    EXPECT_EQ(bad.zFarthest, 0.0f);
  }
}

// The eight corners in double through random affine transforms (rotations, scales, translations): every
// corner is the extreme one for some transform.
TEST(IntersectDepthRange, BoxRangeIsTheExtremeCornerDepths) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  int checked = 0;
  int extremeCorner[2][8] = {};
  for (int k = 0; k < 4000; ++k) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(u(rng), u(rng), -6.0f + 2.0f * u(rng)));
    m = glm::rotate(m, 3.2f * u(rng), glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0.0f, 0.0f, 1e-3f)));
    m = glm::scale(m, glm::vec3(1.0f + 0.5f * u(rng), 1.0f + 0.5f * u(rng), 1.0f + 0.5f * u(rng)));
    const glm::vec3 lo(u(rng) - 1.0f, u(rng) - 1.0f, u(rng) - 1.0f), hi(u(rng) + 1.0f, u(rng) + 1.0f, u(rng) + 1.0f);
    double zMax = -DBL_MAX, zMin = DBL_MAX;
    int iMax = 0, iMin = 0;
    for (int c = 0; c < 8; ++c) {
      const glm::dvec3 p((c & 1) ? hi.x : lo.x, (c & 2) ? hi.y : lo.y, (c & 4) ? hi.z : lo.z);
      const double z = (glm::dmat4(m) * glm::dvec4(p, 1.0)).z;
      if (z > zMax) zMax = z, iMax = c;
      if (z < zMin) zMin = z, iMin = c;
    }
    const SnellDepthRange r = snellDepthRangeFromBox(m, lo, hi);
    if (!(zMin < 0.0)) {
      EXPECT_FALSE(r.valid);
      continue;
    }
    ASSERT_TRUE(r.valid);
    ++checked;
    ++extremeCorner[0][iMax];
    ++extremeCorner[1][iMin];
    EXPECT_NEAR(r.zNearest, std::min(zMax, -double(FLT_MIN)), 1e-5 * std::fabs(zMax) + 1e-30) << k;
    EXPECT_NEAR(r.zFarthest, zMin, 1e-5 * std::fabs(zMin)) << k;
  }
  EXPECT_GT(checked, 3000);
  for (int c = 0; c < 8; ++c) {
    EXPECT_GT(extremeCorner[0][c], 100) << "corner " << c << " is never the nearest";
    EXPECT_GT(extremeCorner[1][c], 100) << "corner " << c << " is never the farthest";
  }
}

TEST(IntersectDepthRange, BoxRangeEdges) {
  const glm::mat4 id(1.0f);
  const double m = SNELL_DEPTH_RANGE_MARGIN;
  // A box reaching behind the camera: the searches start at the ray origin.
  SnellDepthRange r = snellDepthRangeFromBox(id, glm::vec3(-1.0f, -1.0f, -3.0f), glm::vec3(1.0f, 1.0f, 2.0f));
  ASSERT_TRUE(r.valid);
  EXPECT_EQ(r.zNearest, -FLT_MIN);
  EXPECT_EQ(r.zFarthest, -3.0f);
  // A flat box facing the camera is widened by the margin; a thin but not flat one is not.
  r = snellDepthRangeFromBox(id, glm::vec3(-1.0f, -1.0f, -4.0f), glm::vec3(1.0f, 1.0f, -4.0f));
  ASSERT_TRUE(r.valid);
  EXPECT_FLOAT_EQ(r.zNearest, float(-4.0 * (1.0 - m)));
  EXPECT_FLOAT_EQ(r.zFarthest, float(-4.0 * (1.0 + m)));
  r = snellDepthRangeFromBox(id, glm::vec3(-1.0f, -1.0f, -4.0f), glm::vec3(1.0f, 1.0f, std::nextafter(-4.0f, 0.0f)));
  ASSERT_TRUE(r.valid);
  EXPECT_EQ(r.zNearest, std::nextafter(-4.0f, 0.0f));
  EXPECT_EQ(r.zFarthest, -4.0f);
  // Invalid: the farthest corner at or behind the camera plane, a non-finite corner.
  EXPECT_FALSE(snellDepthRangeFromBox(id, glm::vec3(-1.0f, -1.0f, 0.0f), glm::vec3(1.0f, 1.0f, 0.0f)).valid);
  EXPECT_FALSE(snellDepthRangeFromBox(id, glm::vec3(-1.0f, -1.0f, kNaN), glm::vec3(1.0f, 1.0f, -2.0f)).valid);
  EXPECT_FALSE(snellDepthRangeFromBox(id, glm::vec3(-1.0f, -1.0f, -3.0f), glm::vec3(1.0f, 1.0f, kInf)).valid);
  glm::mat4 nanM = id;
  nanM[1][2] = kNaN;  // y feeds z: only the corners' z decide
  EXPECT_FALSE(snellDepthRangeFromBox(nanM, glm::vec3(-1.0f, -1.0f, -3.0f), glm::vec3(1.0f, 1.0f, -2.0f)).valid);
  const SnellDepthRange bad = snellDepthRangeInvalid();
  EXPECT_FALSE(bad.valid);
  EXPECT_EQ(bad.zNearest, 0.0f);
  EXPECT_EQ(bad.zFarthest, 0.0f);
}

}  // namespace
