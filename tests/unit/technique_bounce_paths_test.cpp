// Paths with two, three and four total internal reflections, followed with the bounce count the
// shipped bounce presets use (SNELL_PRESET_BOUNCES, 4), in analytic buffers of a Porro prism (the
// path leaves through the front layer) and a light guide (through the back layer):
// snellTwoInterfaceTrace of the image-space bound with bounces (the inside march, snellInsideMarch,
// at its limits) and with the normal plane inside (snellInsidePlane) against the textbook path in
// double precision (tests/support/bounce_shapes.hpp). Each path is also followed with fewer bounces
// allowed, b = 0 .. k - 1: it must stop at its (b + 1)-th face, totally reflected there, so every
// interface of the path is checked, not only the last. Paths through a tilted plate, with five total
// reflections or more, check that more bounces than SNELL_MAX_BOUNCES are not followed.
#include <snell/snell.hpp>

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include "support/bounce_path_checks.hpp"
#include "support/bounce_shapes.hpp"
#include "support/depth_scenes.hpp"
#include "support/shape_buffers.hpp"

namespace {

using namespace snell;
using glm::dvec2;
using glm::dvec3;
using snell_test::BounceShape;
using snell_test::PixelPath;

using snell_test::ShapeBuffers;
using snell_test::shapeBuffers;

// A technique to follow the paths with, and the shortest chord inside (face to face) it is asked to
// find: a march finds where a ray leaves to within its step, and a chord shorter than a step only
// down to an eighth of it (inside_march.glsl: the first step's halvings).
struct Follower {
  const char* name;
  SnellTechnique technique;
  double minChord;
};

// The measured worst, over both shapes and both followers (every fourth pixel): the exit 0.0002 px from
// the textbook one, its direction 7e-7 rad off, the path length 1.4e-6 relative; the bounds below
// leave a margin of 7x or more.
constexpr double kLengthRel = 1e-5;  // kBounceExitPx, kBounceDirectionRad: bounce_path_checks.hpp

// Follows every fourth pixel's path through the shape with each follower; returns the paths compared
// with two, three and four reflections (the fewest over the followers).
std::map<int, int> checkPaths(const BounceShape& shape) {
  const int size = 256;
  const ShapeBuffers b = shapeBuffers(shape, size);
  const double eta = 1.0 / shape.ior, px = 1.0 / size;
  const SnellTechnique march = snell_test::shapeTechnique(shape);
  EXPECT_EQ(march.bounces, 4);
  // The normal plane inside after a march of 32 steps.
  SnellTechnique plane = march;
  plane.inside.intersect.strategy = SNELL_STRATEGY_PLANE_NORMAL;
  plane.inside.intersect.marchSteps = 32;
  plane.inside.intersect.planeIterations = 2;
  const Follower followers[] = {{"inside march", march, shape.extent / SNELL_LINEAR_MARCH_MAX_STEPS},
                                {"inside plane", plane, shape.extent / 32.0}};
  const auto layerNormalAt = [&b](dvec2 uv, bool frontLayer) { return b.layerNormalAt(uv, frontLayer); };
  const auto uvOf = [&b](dvec3 p) { return b.uvOf(p); };
  std::map<int, int> fewest;
  for (const Follower& with : followers) {
    SCOPED_TRACE(with.name);
    std::map<int, int> paths;
    for (int j = 2; j < size; j += 4)
      for (int i = 2; i < size; i += 4) {
        const std::optional<PixelPath> p = snell_test::pixelPath(shape, b.front.pixelRay(dvec2(i + 0.5, j + 0.5) * px));
        if (!p) continue;
        const int k = p->inside.reflections();
        if (k < 2 || k > 4 || !snell_test::buffersHoldPath(*p, uvOf, layerNormalAt, px)) continue;
        if (snell_test::shortestChord(*p) < with.minChord) continue;
        SCOPED_TRACE(testing::Message() << shape.name << ", pixel " << i << " " << j << ", " << k << " reflections");
        snell_test::expectTracedPath(
            *p, with.technique.bounces,
            [&](int bounces) { return b.trace(*p, eta, with.technique, bounces, SNELL_TIR_CRITICAL); },
            uvOf, px, kLengthRel);
        ++paths[k];
      }
    std::printf("[bounce paths] %s, %s: %d paths with 2 reflections, %d with 3, %d with 4\n", shape.name.c_str(),
                with.name, paths[2], paths[3], paths[4]);
    for (int k : {2, 3, 4}) fewest[k] = fewest.count(k) ? std::min(fewest[k], paths[k]) : paths[k];
  }
  return fewest;
}

TEST(TechniqueBouncePaths, PorroPrismLeavesThroughTheFrontAfterTwoToFourReflections) {
  const std::map<int, int> n = checkPaths(snell_test::porroPrism());
  for (int k : {2, 3, 4}) EXPECT_GE(n.at(k), 20) << k << " reflections";
}

TEST(TechniqueBouncePaths, LightGuideLeavesThroughTheBackAfterTwoToFourReflections) {
  const std::map<int, int> n = checkPaths(snell_test::lightGuide());
  for (int k : {2, 3, 4}) EXPECT_GE(n.at(k), 20) << k << " reflections";
}

// More bounces asked than SNELL_MAX_BOUNCES (4) allow: the count is clamped, so a path through the tilted
// plate, which reflects totally at its first five faces, stops at its fifth as with four allowed, that
// interface taking the material's policy (SNELL_TIR_REFLECT here: the mirror, as the textbook path does).
// An unclamped count would follow the fifth reflection as a bounce too.
TEST(TechniqueBouncePaths, TiltedPlateStopsAtTheFifthFaceWhenMoreBouncesAreAsked) {
  const BounceShape& shape = snell_test::tiltedPlate();
  const int size = 256;
  const ShapeBuffers b = shapeBuffers(shape, size);
  const double eta = 1.0 / shape.ior, px = 1.0 / size;
  const SnellTechnique t = snell_test::shapeTechnique(shape);
  const auto layerNormalAt = [&b](dvec2 uv, bool frontLayer) { return b.layerNormalAt(uv, frontLayer); };
  const auto uvOf = [&b](dvec3 p) { return b.uvOf(p); };
  const int faces = SNELL_MAX_BOUNCES + 1;
  int n = 0;
  for (int j = 1; j < size; j += 2)
    for (int i = 1; i < size; i += 2) {
      const dvec3 q = b.front.pixelRay(dvec2(i + 0.5, j + 0.5) * px);
      const auto entry = shape.prism.entry(q);
      if (!entry) continue;
      // The path's first five faces only: the clamped trace reads no further.
      PixelPath p;
      p.entry = entry->first * q;
      p.entryNormal = entry->second;
      p.t1 = glm::refract(glm::normalize(q), p.entryNormal, eta);
      p.inside = shape.prism.inside(p.entry, p.t1, eta, faces);
      if (int(p.inside.faces.size()) != faces || p.inside.leaves) continue;
      if (!snell_test::buffersHoldPath(p, uvOf, layerNormalAt, px)) continue;
      if (snell_test::shortestChord(p) < shape.extent / SNELL_LINEAR_MARCH_MAX_STEPS) continue;
      SCOPED_TRACE(testing::Message() << "pixel " << i << " " << j);
      const snell_test::Prism::Face& last = p.inside.faces.back();
      const dvec3 towards = glm::normalize(last.point - p.inside.faces[faces - 2].point);
      const double length = snell_test::insideLength(p);
      for (int asked : {SNELL_MAX_BOUNCES, SNELL_MAX_BOUNCES + 1, 1000}) {
        SCOPED_TRACE(testing::Message() << asked << " bounces asked");
        const SnellTwoInterfacePath r = b.trace(p, eta, t, asked, SNELL_TIR_REFLECT);
        EXPECT_TRUE(r.valid);
        EXPECT_TRUE(r.hit);
        EXPECT_EQ(r.bounces, SNELL_MAX_BOUNCES);
        EXPECT_TRUE(r.tir);
        EXPECT_FALSE(r.fellBack);
        EXPECT_EQ(r.exitFront, snell_test::onFrontLayer(last));
        EXPECT_LT(glm::length(uvOf(dvec3(r.exitPoint)) - uvOf(last.point)), snell_test::kBounceExitPx * px);
        EXPECT_LT(glm::length(dvec3(r.exitNormal) + last.normal), 1e-5);
        EXPECT_GT(glm::dot(glm::normalize(dvec3(r.exitDirection)), glm::reflect(towards, last.normal)),
                  std::cos(snell_test::kBounceDirectionRad));
        EXPECT_NEAR(r.pathLength, length, kLengthRel * length);
      }
      ++n;
    }
  std::printf("[bounce paths] %s: %d paths with five total reflections\n", shape.name.c_str(), n);
  EXPECT_GE(n, 100);
}

// One reflection, then out through a front face (the wedge), followed with exactly one bounce allowed: the
// normal there is the front layer's, and the composed technique resolves the exit ray with the reflect slot
// (here the environment: one read; the exit slot would search the scene buffers first). The same paths
// show the first interface's other outcomes: no bounce allowed under SNELL_TIR_ZERO (a fallback along T1
// from there), and a bounce the inside slot cannot follow or that leaves where no normal is stored (a
// fallback along the reflection).
TEST(TechniqueBouncePaths, WedgeLeavesThroughTheFrontAfterOneReflection) {
  const BounceShape& shape = snell_test::frontExitWedge();
  const int size = 128;
  const ShapeBuffers b = shapeBuffers(shape, size);
  const double eta = 1.0 / shape.ior, px = 1.0 / size;
  SnellTechnique t = snell_test::shapeTechnique(shape);
  t.bounces = 1;
  t.exit.source = SNELL_SOURCE_BUFFERS;
  t.reflect.source = SNELL_SOURCE_ENVIRONMENT;
  SnellMaterial m = snellMaterial();
  m.ior = float(shape.ior);
  m.reflection = false;
  const Texture2D emptyScene(Image(size, size, glm::vec4(1.0f, 0.0f, 0.0f, 0.0f)));
  const Texture2D emptyPyramid = snellBuildDepthPyramid(emptyScene, b.front.surface());
  const Texture2D env(Image(16, 8, glm::vec4(0.5f)));
  const Texture2D noNormals(Image(size, size, glm::vec4(0.0f)));
  const auto layerNormalAt = [&b](dvec2 uv, bool frontLayer) { return b.layerNormalAt(uv, frontLayer); };
  const auto uvOf = [&b](dvec3 p) { return b.uvOf(p); };
  int n = 0;
  for (int j = 1; j < size; j += 2)
    for (int i = 1; i < size; i += 2) {
      const std::optional<PixelPath> p = snell_test::pixelPath(shape, b.front.pixelRay(dvec2(i + 0.5, j + 0.5) * px));
      if (!p || p->inside.reflections() != 1 || !snell_test::onFrontLayer(p->inside.faces.back())) continue;
      if (!snell_test::buffersHoldPath(*p, uvOf, layerNormalAt, px)) continue;
      if (snell_test::shortestChord(*p) < shape.extent / SNELL_LINEAR_MARCH_MAX_STEPS) continue;
      SCOPED_TRACE(testing::Message() << "pixel " << i << " " << j);
      const SnellTwoInterfacePath one = snell_test::expectTracedPath(
          *p, 1, [&](int bounces) { return b.trace(*p, eta, t, bounces, SNELL_TIR_CRITICAL); }, uvOf, px, kLengthRel);
      ASSERT_TRUE(one.exitFront);
      const snell_test::Prism::Face& first = p->inside.faces.front();
      // The bounce adds its march's reads (at least one) and the normal read at the exit.
      const SnellTwoInterfacePath zero = b.trace(*p, eta, t, 0, SNELL_TIR_CRITICAL);
      EXPECT_GE(one.fetches, zero.fetches + 2);
      // No bounce allowed, SNELL_TIR_ZERO: the ray leaves the first face unbent, along T1.
      const SnellTwoInterfacePath clamped = b.trace(*p, eta, t, 0, SNELL_TIR_ZERO);
      EXPECT_TRUE(clamped.fellBack);
      EXPECT_TRUE(clamped.tir);
      EXPECT_LT(glm::length(uvOf(dvec3(clamped.exitPoint)) - uvOf(first.point)), snell_test::kBounceExitPx * px);
      EXPECT_LT(glm::length(dvec3(clamped.exitDirection) - p->t1), 1e-5);
      // An inside slot that cannot follow the bounce: a fallback along the reflection from the first face.
      SnellTechnique unfollowed = t;
      unfollowed.inside.source = SNELL_SOURCE_ENVIRONMENT;
      const SnellTwoInterfacePath stopped = b.trace(*p, eta, unfollowed, 1, SNELL_TIR_CRITICAL);
      EXPECT_TRUE(stopped.fellBack);
      EXPECT_TRUE(stopped.tir);
      EXPECT_EQ(stopped.bounces, 1);
      EXPECT_EQ(stopped.fetches, zero.fetches);
      EXPECT_LT(glm::length(uvOf(dvec3(stopped.exitPoint)) - uvOf(first.point)), snell_test::kBounceExitPx * px);
      EXPECT_LT(glm::length(dvec3(stopped.exitDirection) - glm::reflect(p->t1, first.normal)), 1e-5);
      // A zero normal where the bounce leaves (the front layer's normals cleared): the path stops there as a
      // fallback along the reflection, and the last interface it took is still the total reflection.
      const SnellTwoInterfacePath blind =
          snellTwoInterfaceTrace(glm::vec3(p->entry), glm::vec3(p->entryNormal), float(eta), 0.0f, b.back.depth,
                                 b.back.normals, b.backPyramid, b.backSurface, b.front.depth, noNormals,
                                 b.frontSurface, t, SNELL_TIR_CRITICAL);
      EXPECT_TRUE(blind.fellBack);
      EXPECT_TRUE(blind.tir);
      EXPECT_EQ(blind.bounces, 1);
      EXPECT_LT(glm::length(dvec3(blind.exitNormal) + first.normal), 1e-5);
      EXPECT_LT(glm::length(dvec3(blind.exitDirection) - glm::reflect(p->t1, first.normal)), 1e-5);
      // The composed technique: the front exit goes to the reflect slot (one environment read, its miss).
      const SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(
          glm::vec3(p->entry), glm::vec3(p->entryNormal), 0.0f, b.back.depth, b.back.normals, b.backPyramid,
          b.backSurface, b.front.depth, b.front.normals, b.frontSurface, emptyScene, b.front.normals, emptyPyramid, env,
          b.front.surface(), env, t, m, snellView());
      EXPECT_EQ(r.bounces, 1);
      EXPECT_FALSE(r.fellBack);
      EXPECT_FALSE(r.tir);
      EXPECT_EQ(r.fetches, one.fetches + 1);
      EXPECT_EQ(r.exitHit.fetches, 0);
      ++n;
    }
  std::printf("[bounce paths] %s: %d paths with one reflection out through the front\n", shape.name.c_str(), n);
  EXPECT_GE(n, 20);
}

}  // namespace
