// SNELL_TWO_INTERFACE_NORMAL_SAMPLE 0 (glsl/snell/shade/two_interface.glsl): every normal of the path is
// the level-0 texel containing the interface's uv, fetched, not a filtered sample. Its own binary: the
// option changes inline functions that every other test binary compiles with the default (1).
//
// The back face: a plane (its depth exact under bilinear reads), its normal buffer perturbed texel by
// texel, so the texel's normal, its neighbours', a filtered sample and a coarser level all differ; the
// exit direction is compared with the double-precision refraction at the stored normal of the texel the
// exact hit lies in. A front face after a bounce: the wedge of tests/support/bounce_shapes.hpp, against
// its textbook path.
#define SNELL_TWO_INTERFACE_NORMAL_SAMPLE 0
#include <snell/depth_pyramid.hpp>
#include <snell/snell.hpp>

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <optional>

#include "support/bounce_path_checks.hpp"
#include "support/bounce_shapes.hpp"
#include "support/depth_scenes.hpp"
#include "support/shape_buffers.hpp"

namespace {

using namespace snell;
using glm::dvec2;
using glm::dvec3;

constexpr double kIor = 1.5;

// A value in [-1, 1] fixed by the texel and the channel (a hash: neighbouring texels unrelated).
double jitter(int i, int j, int channel) {
  std::uint32_t h = std::uint32_t(i) * 73856093u ^ std::uint32_t(j) * 19349663u ^ std::uint32_t(channel) * 83492791u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return double(h % 2001u) / 1000.0 - 1.0;
}

TEST(TwoInterfaceNormalFetch, BackNormalIsTheTexelContainingTheHit) {
  const int size = 64;
  const double px = 1.0 / size;
  // Front face: a plane at z = -3, turned a little; back face: a plane at z = -6, nearly parallel to it, so
  // that no ray meets its stored normals beyond the critical angle (27 deg inside at most, the planes 3 deg
  // apart, the normals tilted 10 deg at most).
  const dvec3 frontPoint(0.0, 0.0, -3.0), frontNormal = glm::normalize(dvec3(-0.1, 0.12, 1.0));
  const dvec3 backPoint(0.0, 0.0, -6.0), backFacing = glm::normalize(dvec3(-0.05, 0.08, 1.0));
  const snell_test::DepthScene back = snell_test::detail::makeScene(
      "back plane", size, size, SNELL_DEPTH_GL, true, snell_test::kScenePlane,
      [&](dvec3 q) { return snell_test::detail::rayPlane(q, backPoint, backFacing); });
  const snell_test::DepthScene front = snell_test::detail::makeScene(
      "front plane", size, size, SNELL_DEPTH_GL, false, snell_test::kScenePlane,
      [&](dvec3 q) { return snell_test::detail::rayPlane(q, frontPoint, frontNormal); });
  // The back face's outward normal (away from the camera), tilted up to 0.12 per texel in x and y; bilinear
  // with a mip chain, as a normal buffer is bound (snellBuildNormalMips).
  Image normals(size, size, glm::vec4(0.0f));
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const dvec3 n = glm::normalize(-backFacing + 0.12 * dvec3(jitter(i, j, 0), jitter(i, j, 1), 0.0));
      normals.at(i, j) = glm::vec4(glm::vec3(n), 1.0f);
    }
  const Texture2D backNormals = snellBuildNormalMips(Texture2D(normals));
  SnellDepthSurface backSurface = back.surface();
  backSurface.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  const Texture2D backPyramid = snellBuildDepthPyramid(back.depth, back.surface());
  SnellTechnique t = snellPresetImageSpaceBound();
  t.back.intersect.marchMaxDistance = 8.0f;

  const auto stored = [&](int i, int j) { return glm::normalize(dvec3(glm::vec3(normals.at(i, j)))); };
  int n = 0, unlikeSample = 0;
  const int grid = 150;  // entry points off the texel grid, so the hits fall anywhere in their texels
  for (int b = 0; b < grid; ++b)
    for (int a = 0; a < grid; ++a) {
      const dvec3 q = front.pixelRay(dvec2(a + 0.5, b + 0.5) / double(grid));
      const snell_test::AnalyticSample f = snell_test::detail::rayPlane(q, frontPoint, frontNormal);
      if (!f.valid) continue;
      const glm::vec3 p1 = glm::vec3(f.s * q), n1 = glm::vec3(frontNormal);
      // The exact path from the float inputs.
      const dvec3 t1 = glm::refract(glm::normalize(dvec3(p1)), dvec3(n1), 1.0 / kIor);
      const double s = glm::dot(backPoint - dvec3(p1), backFacing) / glm::dot(t1, backFacing);
      const dvec3 p2 = dvec3(p1) + s * t1;
      const dvec2 uv = back.project(p2), texel = uv * double(size);
      if (!(uv.x > 2.0 * px && uv.x < 1.0 - 2.0 * px && uv.y > 2.0 * px && uv.y < 1.0 - 2.0 * px)) continue;
      // Away from the texel's edges by more than the march's error, so the texel is not in doubt.
      const dvec2 within = texel - glm::floor(texel);
      if (glm::min(within, 1.0 - within).x < 0.02 || glm::min(within, 1.0 - within).y < 0.02) continue;
      const int i = int(texel.x), j = int(texel.y);
      dvec3 n2 = stored(i, j);
      if (glm::dot(n2, t1) > 0.0) n2 = -n2;
      const dvec3 t2 = glm::refract(t1, n2, kIor);
      ASSERT_GT(glm::dot(t2, t2), 0.0) << "the planes are chosen so that no ray is totally reflected";
      // The bilinear sample there (what the default setting reads): unlike the texel's by far more than the
      // tolerance below, so the check tells the two settings apart.
      const dvec2 st = texel - 0.5;
      const int i0 = int(std::floor(st.x)), j0 = int(std::floor(st.y));
      const double fx = st.x - i0, fy = st.y - j0;
      dvec3 sample = glm::normalize((1.0 - fx) * (1.0 - fy) * stored(i0, j0) + fx * (1.0 - fy) * stored(i0 + 1, j0) +
                                    (1.0 - fx) * fy * stored(i0, j0 + 1) + fx * fy * stored(i0 + 1, j0 + 1));
      if (glm::dot(sample, t1) > 0.0) sample = -sample;
      if (glm::length(sample - n2) > 1e-3) ++unlikeSample;
      SCOPED_TRACE(testing::Message() << "entry " << a << " " << b << ", texel " << i << " " << j);
      const SnellTwoInterfacePath r =
          snellTwoInterfaceTrace(p1, n1, float(1.0 / kIor), 0.0f, back.depth, backNormals, backPyramid, backSurface,
                                 front.depth, front.normals, front.surface(), t, SNELL_TIR_CRITICAL);
      ASSERT_TRUE(r.valid);
      ASSERT_TRUE(r.hit);
      EXPECT_FALSE(r.fellBack);
      EXPECT_FALSE(r.tir);
      EXPECT_LT(glm::length(back.project(dvec3(r.exitPoint)) - uv), 0.005 * px);
      EXPECT_LT(glm::length(dvec3(r.exitNormal) - n2), 1e-6);
      EXPECT_GT(glm::dot(glm::normalize(dvec3(r.exitDirection)), glm::normalize(t2)), std::cos(1e-5));
      ++n;
    }
  std::printf("[normal fetch] %d exits through the back plane, %d where a sample would differ\n", n, unlikeSample);
  EXPECT_GE(n, 10000);
  EXPECT_GE(unlikeSample, n * 9 / 10);
}

// After a bounce the path leaves through a front face, whose normal is fetched from the front layer's
// normals: one reflection in the wedge and out through its left face, against the textbook path (and
// with no bounce allowed, the total reflection at its first face, a back face).
TEST(TwoInterfaceNormalFetch, FrontExitAfterABounceReadsTheFrontLayersTexel) {
  const snell_test::BounceShape& shape = snell_test::frontExitWedge();
  const int size = 128;
  const snell_test::ShapeBuffers b = snell_test::shapeBuffers(shape, size);
  // The normals bilinear with a mip chain, as a normal buffer is bound (snellBuildNormalMips).
  const Texture2D frontNormals = snellBuildNormalMips(b.front.normals);
  const Texture2D backNormals = snellBuildNormalMips(b.back.normals);
  const double eta = 1.0 / shape.ior, px = 1.0 / size;
  const SnellTechnique t = snell_test::shapeTechnique(shape);
  const auto layerNormalAt = [&b](dvec2 uv, bool frontLayer) { return b.layerNormalAt(uv, frontLayer); };
  const auto uvOf = [&b](dvec3 p) { return b.uvOf(p); };
  int n = 0;
  for (int j = 1; j < size; j += 2)
    for (int i = 1; i < size; i += 2) {
      const std::optional<snell_test::PixelPath> p =
          snell_test::pixelPath(shape, b.front.pixelRay(dvec2(i + 0.5, j + 0.5) * px));
      if (!p || p->inside.reflections() != 1 || !snell_test::onFrontLayer(p->inside.faces.back())) continue;
      if (!snell_test::buffersHoldPath(*p, uvOf, layerNormalAt, px)) continue;
      if (snell_test::shortestChord(*p) < shape.extent / SNELL_LINEAR_MARCH_MAX_STEPS) continue;
      SCOPED_TRACE(testing::Message() << "pixel " << i << " " << j);
      const SnellTwoInterfacePath one = snell_test::expectTracedPath(
          *p, 1,
          [&](int bounces) {
            SnellTechnique tb = t;
            tb.bounces = bounces;
            return snellTwoInterfaceTrace(glm::vec3(p->entry), glm::vec3(p->entryNormal), float(eta), 0.0f,
                                          b.back.depth, backNormals, b.backPyramid, b.backSurface, b.front.depth,
                                          frontNormals, b.frontSurface, tb, SNELL_TIR_CRITICAL);
          },
          uvOf, px, 1e-5);
      EXPECT_TRUE(one.exitFront);
      EXPECT_LT(glm::length(dvec3(one.exitNormal) + p->inside.faces.back().normal), 1e-6);
      ++n;
    }
  std::printf("[normal fetch] %s: %d paths with one reflection out through the front\n", shape.name.c_str(), n);
  EXPECT_GE(n, 20);
}

}  // namespace
