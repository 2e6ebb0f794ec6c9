// snellInsideSide against the sphere's two analytic layers: the side of a
// point follows from its view z and the layers' z at the texel a nearest read
// picks, computed in double (support/inside_layers.hpp), independent of
// snell's depth reads.
#include <snell/snell.hpp>

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "support/inside_layers.hpp"
#include "support/rng.hpp"

namespace {

using namespace snell;

// Beyond float depth rounding (a few 1e-6 at the sphere's distance) and far from any real layer gap.
constexpr double kMargin = 1e-3;

// Both layers, then each alone (a texel of one layer beside an empty one is inside unless the point crossed it).
TEST(InsideSide, PointsAtRandomDepthsGetTheSideTheAnalyticLayersGive) {
  const int size = 64;
  const inside_test::Layers configs[3] = {inside_test::sphereLayers(size), inside_test::oneLayerEmpty(size, true),
                                          inside_test::oneLayerEmpty(size, false)};
  snell_test::Rng g(8301);
  for (int c = 0; c < 3; ++c) {
    const inside_test::Layers& l = configs[c];
    SCOPED_TRACE(c == 0 ? "both layers" : c == 1 ? "front layer empty" : "back layer empty");
    int counts[3] = {0, 0, 0}, beside = 0;
    for (int k = 0; k < 20000; ++k) {
      // uv inside a texel, away from its edges: the nearest read picks that texel.
      const glm::dvec2 at(g.uniform(0.0f, 1.0f), g.uniform(0.0f, 1.0f));
      if (inside_test::nearTexelEdge(l, at, 0.01)) continue;
      const inside_test::TexelLayers t = inside_test::layersAt(l, inside_test::texelOf(l, at));
      // Depths around the sphere (z in [-8.2, -3.8]) and beyond it on both sides.
      const double z = g.uniform(-10.0f, -2.0f);
      const double dirZ = g.uniform(-1.0f, 1.0f);
      const int want = inside_test::expectedSide(t, z, dirZ, kMargin);
      if (want < 0) continue;
      const glm::vec3 p(g.uniform(-3.0f, 3.0f), g.uniform(-3.0f, 3.0f), float(z));
      const int got = snellInsideSide(p, glm::vec2(at), l.back.depth, l.back.surface(), l.front.depth,
                                      l.front.surface(), float(dirZ));
      ASSERT_EQ(got, want) << "uv " << at.x << " " << at.y << " z " << z << " dirZ " << dirZ << " layers "
                           << t.frontZ << " (" << t.frontValid << ") " << t.backZ << " (" << t.backValid << ")";
      ++counts[want];
      beside += !t.frontValid && !t.backValid;
    }
    // Every side the configuration has met often, and the silhouette's outside (both layers empty) too.
    EXPECT_GT(counts[0], 1000);
    EXPECT_GT(counts[1], 1000);
    EXPECT_GT(counts[2], 1000);
    EXPECT_GT(beside, 1000);
  }
}

// Off screen both layers read empty: the side is where the ray heads (front towards the camera).
TEST(InsideSide, OffScreenReadsAsBesideTheSilhouette) {
  const inside_test::Layers l = inside_test::sphereLayers(32);
  const glm::vec3 p(0.3f, -0.2f, -6.0f);  // the sphere's centre: inside wherever both layers are read
  for (const glm::vec2 uv : {glm::vec2(-0.01f, 0.5f), glm::vec2(0.5f, 1.01f), glm::vec2(1.5f, -0.5f)}) {
    EXPECT_EQ(snellInsideSide(p, uv, l.back.depth, l.back.surface(), l.front.depth, l.front.surface(), 0.5f), 2);
    EXPECT_EQ(snellInsideSide(p, uv, l.back.depth, l.back.surface(), l.front.depth, l.front.surface(), -0.5f), 1);
    EXPECT_EQ(snellInsideSide(p, uv, l.back.depth, l.back.surface(), l.front.depth, l.front.surface(), 0.0f), 1);
    // Any positive dir.z heads towards the camera, the smallest (denormal) one too.
    EXPECT_EQ(snellInsideSide(p, uv, l.back.depth, l.back.surface(), l.front.depth, l.front.surface(), 1e-40f), 2);
  }
  // At the sphere's centre pixel the same point is inside.
  const glm::vec2 centre = glm::vec2(l.front.project(glm::dvec3(p)));
  EXPECT_EQ(snellInsideSide(p, centre, l.back.depth, l.back.surface(), l.front.depth, l.front.surface(), 0.5f), 0);
}

// "On or behind the back layer", "on or in front of the front layer": a point at exactly the depth a layer's
// read gives has left through that layer.
TEST(InsideSide, APointExactlyOnALayerHasLeftThroughIt) {
  const inside_test::Layers l = inside_test::sphereLayers(32);
  const glm::vec2 uv(0.5f + 0.5f / 32.0f, 0.5f + 0.5f / 32.0f);
  const SnellSurfaceSample b = snellSampleSurface(l.back.depth, uv, l.back.surface());
  const SnellSurfaceSample f = snellSampleSurface(l.front.depth, uv, l.front.surface());
  ASSERT_TRUE(b.valid && f.valid);
  for (float dirZ : {-1.0f, 1.0f}) {
    EXPECT_EQ(snellInsideSide(glm::vec3(0.0f, 0.0f, b.viewZ), uv, l.back.depth, l.back.surface(), l.front.depth,
                              l.front.surface(), dirZ), 1);
    EXPECT_EQ(snellInsideSide(glm::vec3(0.0f, 0.0f, f.viewZ), uv, l.back.depth, l.back.surface(), l.front.depth,
                              l.front.surface(), dirZ), 2);
  }
}

// Layers passed the wrong way round (the back one nearer the camera): a point between them is behind one and
// in front of the other, outside either way, never inside, and through the layer whose depth is nearer the
// point along z (the contract; a tie goes to the back layer).
TEST(InsideSide, APointPastBothLayersLeavesThroughTheNearerOne) {
  const inside_test::Layers l = inside_test::sphereLayers(32);
  const glm::dvec2 uv(0.5 + 0.5 / 32, 0.5 + 0.5 / 32);
  const inside_test::TexelLayers t = inside_test::layersAt(l, inside_test::texelOf(l, uv));
  ASSERT_TRUE(t.frontValid && t.backValid);
  for (double s = 0.1; s < 1.0; s += 0.1) {
    const glm::vec3 p(0.0f, 0.0f, float(t.backZ + s * (t.frontZ - t.backZ)));
    const int side = snellInsideSide(p, glm::vec2(uv), l.front.depth, l.front.surface(), l.back.depth,
                                     l.back.surface(), -1.0f);
    // Passed as the back layer here: the front one (frontZ); as the front layer: the back one (backZ).
    const double toBackArgument = t.frontZ - double(p.z), toFrontArgument = double(p.z) - t.backZ;
    if (std::abs(toBackArgument - toFrontArgument) < 1e-5) continue;  // a tie within the float layers' rounding
    EXPECT_EQ(side, toBackArgument < toFrontArgument ? 1 : 2) << s;
  }
}

}  // namespace
