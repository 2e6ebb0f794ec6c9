// SNELL_PERSPECTIVE_ONLY 1 (glsl/snell/intersect/surface_projection.glsl). Its
// own binary: the option changes inline functions that every other test binary
// compiles without it. Perspective surfaces must give the general matrix path's
// bits (camera/view_to_uv.glsl and camera/uv_z_to_view.glsl, which the option
// does not touch); any other surface must project and reconstruct nothing.
#define SNELL_PERSPECTIVE_ONLY 1
#include <gtest/gtest.h>

#include <snell/camera.hpp>
#include <snell/intersect.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cstring>
#include <random>

namespace {

using namespace snell;

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(PerspectiveOnly, PerspectiveSurfacesGiveTheGeneralPathsBits) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> fovy(0.2f, 2.8f), aspect(0.3f, 3.0f), xy(-4.0f, 4.0f), z(-60.0f, 1.0f),
      uv(-0.2f, 1.2f);
  int valid = 0;
  for (int i = 0; i < 200000; ++i) {
    const glm::mat4 m = glm::perspective(fovy(rng), aspect(rng), 0.1f, 100.0f);
    const SnellDepthSurface s = snellDepthSurface(m, 0.1f, 100.0f, SNELL_DEPTH_GL, 0.0f);
    ASSERT_TRUE(s.perspective);
    const glm::vec3 p(xy(rng), xy(rng), z(rng));
    const SnellScreenPoint a = snellSurfaceViewToUv(s, p), b = snellViewToUv(m, p);
    ASSERT_EQ(a.valid, b.valid) << i;
    if (a.valid) {
      ++valid;
      ASSERT_TRUE(sameBits(a.uv.x, b.uv.x) && sameBits(a.uv.y, b.uv.y) && a.ndcZ == b.ndcZ) << i;
    }
    const glm::vec2 q(uv(rng), uv(rng));
    const SnellViewPoint c = snellSurfaceUvZToView(s, q, p.z), d = snellUvZToView(m, q, p.z);
    ASSERT_EQ(c.valid, d.valid) << i;
    if (c.valid) {
      ASSERT_TRUE(sameBits(c.position.x, d.position.x) && sameBits(c.position.y, d.position.y)) << i;
    }
  }
  EXPECT_GT(valid, 100000);
}

TEST(PerspectiveOnly, OtherSurfacesProjectNothingAndEveryStrategyMisses) {
  glm::mat4 sheared = glm::perspective(1.0f, 1.3f, 0.1f, 100.0f);
  sheared[1][0] = 0.2f;
  const SnellDepthSurface s = snellDepthSurface(sheared, 0.1f, 100.0f, SNELL_DEPTH_GL, 0.0f);
  ASSERT_FALSE(s.perspective);
  const glm::vec3 p(0.3f, -0.4f, -2.0f);
  ASSERT_TRUE(snellViewToUv(sheared, p).valid);  // the general path would answer
  EXPECT_FALSE(snellSurfaceViewToUv(s, p).valid);
  EXPECT_FALSE(snellSurfaceUvZToView(s, glm::vec2(0.4f, 0.6f), -2.0f).valid);
  // A surface everywhere (window depth 0.99: view z about -9.1, behind p): the strategies still miss at once.
  const Texture2D depth(Image(64, 64, glm::vec4(0.99f)));
  const Texture2D normal(Image(64, 64, glm::vec4(0.0f, 0.0f, 1.0f, 0.0f)), Filter::Linear);
  const glm::vec3 dir(0.1f, 0.0f, -1.0f);
  const SnellHit single = snellIntersectSingleSample(p, dir, depth, s);
  EXPECT_FALSE(single.valid);
  EXPECT_EQ(single.fetches, 0);
  const SnellHit plane = snellIntersectPlaneNormal(p, dir, depth, normal, depth, s, 0.0f, 1, false);
  EXPECT_FALSE(plane.valid);
  EXPECT_EQ(plane.fetches, 0);
  // The same buffers with the unsheared perspective: both find the surface.
  const SnellDepthSurface ok = snellDepthSurface(glm::perspective(1.0f, 1.3f, 0.1f, 100.0f), 0.1f, 100.0f,
                                                 SNELL_DEPTH_GL, 0.0f);
  EXPECT_TRUE(snellIntersectSingleSample(p, dir, depth, ok).valid);
  EXPECT_TRUE(snellIntersectPlaneNormal(p, dir, depth, normal, depth, ok, 0.0f, 1, false).valid);
}

}  // namespace
