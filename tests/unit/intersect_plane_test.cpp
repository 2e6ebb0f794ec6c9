// glsl/snell/intersect/plane_normal.glsl and plane_depth.glsl (Mayer & Assarsson,
// methods 1 and 2, with refinement) against the analytic scenes of
// tests/support/depth_scenes.hpp: hits compared with DepthScene::referenceHit,
// a dense double-precision march through the continuous surface.
#include <gtest/gtest.h>

#include <snell/depth_pyramid.hpp>
#include <snell/intersect.hpp>

#include <cfloat>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include "support/depth_scenes.hpp"

namespace {

using namespace snell;
using snell_test::DepthScene;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

struct TestRay {
  glm::dvec3 o, d;
  glm::dvec3 ref;
};

// Refracted rays entering the sphere of sphereBack through its front face.
std::vector<TestRay> sphereRays(const DepthScene& sc, int count, unsigned seed) {
  const glm::dvec3 c(0.3, -0.2, -6.0);
  const double r = 2.2;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<TestRay> rays;
  while (static_cast<int>(rays.size()) < count) {
    const glm::dvec3 q = sc.pixelRay({u(rng), u(rng)});
    const double a = glm::dot(q, q), b = -2.0 * glm::dot(q, c), cc = glm::dot(c, c) - r * r, disc = b * b - 4 * a * cc;
    if (disc < 0.0) continue;
    const glm::dvec3 w = (-b - std::sqrt(disc)) / (2.0 * a) * q, n = (w - c) / r, i = glm::normalize(q);
    const double eta = 1.0 / (1.1 + 0.5 * u(rng)), ci = -glm::dot(i, n), k = 1.0 - eta * eta * (1.0 - ci * ci);
    const glm::dvec3 t = eta * i + (eta * ci - std::sqrt(k)) * n;
    const auto ref = sc.referenceHit(w, t);
    if (!ref) continue;
    rays.push_back({w, t, *ref});
  }
  return rays;
}

// Rays from points between the camera and a full-screen plane, towards it.
std::vector<TestRay> planeRays(const DepthScene& sc, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
  std::vector<TestRay> rays;
  while (static_cast<int>(rays.size()) < count) {
    const glm::dvec2 uv(0.1 + 0.8 * u(rng), 0.1 + 0.8 * u(rng));
    const double surf = sc.surfaceZ(uv);
    const glm::dvec3 o = sc.pixelRay(uv) * (-surf * (0.3 + 0.5 * u(rng)));
    const glm::dvec3 d = glm::normalize(glm::dvec3(0.4 * s(rng), 0.4 * s(rng), -1.0));
    const auto ref = sc.referenceHit(o, d);
    if (!ref) continue;
    const glm::dvec2 ruv = sc.project(*ref);
    if (ruv.x < 0.02 || ruv.x > 0.98 || ruv.y < 0.02 || ruv.y > 0.98) continue;  // not at the border texels
    rays.push_back({o, d, *ref});
  }
  return rays;
}

double depthRange(const DepthScene& sc) {
  double lo = 1e30, hi = 0.0;
  for (int j = 0; j < sc.height; ++j)
    for (int i = 0; i < sc.width; ++i) {
      const double z = sc.surfaceZ({(i + 0.5) / sc.width, (j + 0.5) / sc.height});
      if (std::isnan(z)) continue;
      lo = std::min(lo, -z);
      hi = std::max(hi, -z);
    }
  return hi - lo;
}

enum class Method { Normal, Depth };

struct Stats {
  double meanErr = 0, maxErr = 0;
  int valid = 0, total = 0;
  double fetches = 0;
};

Stats evaluate(const DepthScene& sc, const Texture2D& normals, const Texture2D& pyramid, const std::vector<TestRay>& rays,
               Method m, int iterations, float normalLod = 0.0f, bool farStart = false) {
  Stats st;
  const SnellDepthSurface s = sc.surface();
  for (const TestRay& r : rays) {
    const SnellHit h = m == Method::Normal
                           ? snellIntersectPlaneNormal(glm::vec3(r.o), glm::vec3(r.d), sc.depth, normals, pyramid, s, normalLod,
                                                       iterations, farStart)
                           : snellIntersectPlaneDepth(glm::vec3(r.o), glm::vec3(r.d), pyramid, s, pyramid.levelCount() - 1,
                                                      iterations, farStart);
    ++st.total;
    st.fetches += h.fetches;
    if (!h.valid) continue;
    ++st.valid;
    const double e = glm::length(glm::dvec3(h.position) - r.ref);
    st.meanErr += e;
    st.maxErr = std::max(st.maxErr, e);
  }
  if (st.valid) st.meanErr /= st.valid;
  st.fetches /= std::max(1, st.total);
  return st;
}

TEST(IntersectPlane, ExactOnAPlanarSurface) {
  for (int conv : {SNELL_DEPTH_GL, SNELL_DEPTH_REVERSED, SNELL_DEPTH_INFINITE_GL}) {
    const DepthScene sc = snell_test::slantedPlane(256, 256, conv);
    const Texture2D normals = snellBuildNormalMips(sc.normals);
    const Texture2D pyramid = snellBuildDepthPyramid(sc.depth, sc.surface());
    const std::vector<TestRay> rays = planeRays(sc, 2000, 11u + unsigned(conv));
    const double range = depthRange(sc);
    for (Method m : {Method::Normal, Method::Depth})
      for (int it : {0, 1, 3}) {
        const Stats st = evaluate(sc, normals, pyramid, rays, m, it);
        SCOPED_TRACE("convention " + std::to_string(conv) + (m == Method::Normal ? " normal" : " depth") +
                     " iterations " + std::to_string(it));
        EXPECT_EQ(st.valid, st.total);
        EXPECT_LT(st.maxErr, 1e-4 * range) << "mean " << st.meanErr << " range " << range;
        // With the far start, plane 0 may be the far plane (where the pyramid texel misses the hit), and one
        // refinement brings every ray back to the surface's own plane.
        if (it > 0) {
          const Stats far = evaluate(sc, normals, pyramid, rays, m, it, 0.0f, true);
          EXPECT_EQ(far.valid, far.total);
          EXPECT_LT(far.maxErr, 1e-4 * range) << "far start, mean " << far.meanErr;
        }
      }
  }
}

TEST(IntersectPlane, ErrorFallsWithIterationsOnTheSphere) {
  const DepthScene sc = snell_test::sphereBack(256, 256);
  const Texture2D normals = snellBuildNormalMips(sc.normals);
  const Texture2D pyramid = snellBuildDepthPyramid(sc.depth, sc.surface());
  const std::vector<TestRay> rays = sphereRays(sc, 1500, 5);
  const double range = depthRange(sc);
  for (Method m : {Method::Normal, Method::Depth}) {
    double prev = 1e30;
    for (int it = 0; it <= 3; ++it) {
      const Stats st = evaluate(sc, normals, pyramid, rays, m, it);
      std::printf("[plane] sphere 256^2 %s iterations %d: valid %d/%d mean error %.3g (%.3g of depth range) fetches %.2f\n",
                  m == Method::Normal ? "normal" : "depth", it, st.valid, st.total, st.meanErr, st.meanErr / range,
                  st.fetches);
      EXPECT_GT(st.valid, st.total * 8 / 10);
      if (it <= 2) {
        EXPECT_LT(st.meanErr, prev * 0.5) << "iterations " << it;
      }
      prev = st.meanErr;
    }
    EXPECT_LT(prev, 2e-3 * range);
  }
}

TEST(IntersectPlane, NormalMethodFetchCount) {
  const DepthScene sc = snell_test::slantedPlane(64, 64);
  const std::vector<TestRay> rays = planeRays(sc, 200, 3);
  for (int it = -2; it <= 10; ++it)
    for (const TestRay& r : rays) {
      const SnellHit h = snellIntersectPlaneNormal(glm::vec3(r.o), glm::vec3(r.d), sc.depth, sc.normals, sc.depth, sc.surface(), 0.0f, it, false);
      ASSERT_TRUE(h.valid);
      const int n = std::min(std::max(it, 0), SNELL_PLANE_MAX_ITERATIONS);
      EXPECT_EQ(h.fetches, 2 * (n + 1) + 1);
    }
}

// Every plane read in full (B0 at level 0 of a one-level read, C and D beside it on the plane), so the
// depth method's count is exact: 3 per plane and the final lookup, plus the far start's 2 reads when it is
// asked for (the pyramid's level 0 is the depth, read with maxLod 0). The normal method: 2 per plane.
TEST(IntersectPlane, ExactFetchCountsOnAFullPlane) {
  const DepthScene sc = snell_test::slantedPlane(64, 64);
  const Texture2D pyramid = snellBuildDepthPyramid(sc.depth, sc.surface());
  const std::vector<TestRay> rays = planeRays(sc, 100, 4);
  for (int it = -2; it <= 10; ++it)
    for (const TestRay& r : rays) {
      const int n = std::min(std::max(it, 0), SNELL_PLANE_MAX_ITERATIONS);
      const glm::vec3 o(r.o), d(r.d);
      const SnellHit depth = snellIntersectPlaneDepth(o, d, sc.depth, sc.surface(), 0, it, false);
      const SnellHit depthFar = snellIntersectPlaneDepth(o, d, pyramid, sc.surface(), 0, it, true);
      const SnellHit normalFar =
          snellIntersectPlaneNormal(o, d, sc.depth, sc.normals, pyramid, sc.surface(), 0.0f, it, true);
      ASSERT_TRUE(depth.valid && depthFar.valid && normalFar.valid);
      EXPECT_EQ(depth.fetches, 3 * (n + 1) + 1) << it;
      EXPECT_EQ(depthFar.fetches, 3 * (n + 1) + 1 + 2) << it;
      EXPECT_EQ(normalFar.fetches, 2 * (n + 1) + 1 + 2) << it;
    }
}

TEST(IntersectPlane, DepthMethodFetchCountWithinDocumentedBounds) {
  const DepthScene sc = snell_test::sphereBack(128, 128);
  const Texture2D pyramid = snellBuildDepthPyramid(sc.depth, sc.surface());
  const std::vector<TestRay> rays = sphereRays(sc, 300, 9);
  for (int it = 0; it <= 3; ++it)
    for (const TestRay& r : rays) {
      const SnellHit h = snellIntersectPlaneDepth(glm::vec3(r.o), glm::vec3(r.d), pyramid, sc.surface(),
                                                  pyramid.levelCount() - 1, it, false);
      EXPECT_LE(h.fetches, 6 * (it + 1) + 1);
      if (h.valid) {
        EXPECT_GE(h.fetches, 3 * (it + 1) + 1);
      }
    }
  // One-level texture, ray along the pixel ray (span 0): exactly B, C, D + the final lookup per plane.
  const DepthScene pl = snell_test::slantedPlane(64, 64);
  const glm::vec3 o = glm::vec3(pl.pixelRay({0.5, 0.5}) * 2.0);
  const SnellHit h = snellIntersectPlaneDepth(o, o, pl.depth, pl.surface(), 0, 0, false);
  ASSERT_TRUE(h.valid);
  EXPECT_EQ(h.fetches, 3 + 1);
}

TEST(IntersectPlane, WorksOnTheOpaqueSceneBuffers) {
  // The same functions against an opaque scene buffer (GL_LESS, empty = far).
  const DepthScene sc = snell_test::stepEdge(256, 256, SNELL_DEPTH_ZERO_ONE);
  const Texture2D pyramid = snellBuildDepthPyramid(sc.depth, sc.surface());
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int good = 0, total = 0;
  for (int i = 0; i < 500; ++i) {
    // Rays from the far plane's side that stay away from the edge: a plane each.
    const glm::dvec2 uv(0.75 + 0.2 * u(rng), 0.1 + 0.8 * u(rng));
    const glm::dvec3 o = sc.pixelRay(uv) * 5.0;
    const glm::dvec3 d = glm::normalize(glm::dvec3(0.05 * (u(rng) - 0.5), 0.2 * (u(rng) - 0.5), -1.0));
    const auto ref = sc.referenceHit(o, d);
    if (!ref || sc.project(*ref).x < 0.72) continue;
    ++total;
    const SnellHit hn = snellIntersectPlaneNormal(glm::vec3(o), glm::vec3(d), sc.depth, sc.normals, sc.depth, sc.surface(), 0.0f, 1, false);
    const SnellHit hd = snellIntersectPlaneDepth(glm::vec3(o), glm::vec3(d), pyramid, sc.surface(), 0, 1, false);
    if (hn.valid && hd.valid && glm::length(glm::dvec3(hn.position) - *ref) < 1e-3 &&
        glm::length(glm::dvec3(hd.position) - *ref) < 1e-3)
      ++good;
  }
  EXPECT_GT(total, 100);
  EXPECT_EQ(good, total);
}

void expectMiss(const SnellHit& h) {
  EXPECT_FALSE(h.valid);
  EXPECT_EQ(h.uv, glm::vec2(0.0f));
  EXPECT_EQ(h.position, glm::vec3(0.0f));
  EXPECT_GE(h.fetches, 0);
}

TEST(IntersectPlane, BadInputsAreInvalidAndFinite) {
  const DepthScene sc = snell_test::sphereBack(64, 64);
  const Texture2D pyramid = snellBuildDepthPyramid(sc.depth, sc.surface());
  const SnellDepthSurface s = sc.surface();
  const glm::vec3 o(0.3f, -0.2f, -3.9f), d(0.0f, 0.0f, -1.0f);
  auto both = [&](glm::vec3 oo, glm::vec3 dd, const Texture2D& depth, const Texture2D& pyr, int expectFetches) {
    const SnellHit a = snellIntersectPlaneNormal(oo, dd, depth, sc.normals, depth, s, 0.0f, 2, false);
    const SnellHit b = snellIntersectPlaneDepth(oo, dd, pyr, s, pyr.levelCount() - 1, 2, false);
    expectMiss(a);
    expectMiss(b);
    if (expectFetches >= 0) {
      EXPECT_EQ(a.fetches, expectFetches);
      EXPECT_EQ(b.fetches, expectFetches);
    }
  };
  // Sanity: the good ray hits.
  ASSERT_TRUE(snellIntersectPlaneNormal(o, d, sc.depth, sc.normals, sc.depth, s, 0.0f, 2, false).valid);
  ASSERT_TRUE(snellIntersectPlaneDepth(o, d, pyramid, s, pyramid.levelCount() - 1, 2, false).valid);
  both(glm::vec3(kNaN, 0.0f, -3.0f), d, sc.depth, pyramid, 0);
  both(o, glm::vec3(0.0f, kInf, -1.0f), sc.depth, pyramid, 0);
  both(o, glm::vec3(0.0f), sc.depth, pyramid, 0);
  both(o, glm::vec3(0.0f, 0.0f, kNaN), sc.depth, pyramid, 0);
  both(glm::vec3(0.0f, 0.0f, 1.0f), d, sc.depth, pyramid, 0);   // behind the camera
  both(glm::vec3(0.0f, 0.0f, 0.0f), d, sc.depth, pyramid, 0);   // at the eye
  both(glm::vec3(30.0f, 0.0f, -3.0f), d, sc.depth, pyramid, 1); // off screen: B lookup off screen
  // Nothing behind the origin (outside the silhouette).
  both(glm::vec3(-2.5f, 1.8f, -4.0f), d, sc.depth, pyramid, 1);
  // Leaving the screen: steep sideways ray, the plane hit projects off screen.
  {
    const SnellHit a = snellIntersectPlaneNormal(glm::vec3(2.0f, -0.2f, -5.5f), glm::vec3(1.0f, 0.0f, -0.02f), sc.depth,
                                                 sc.normals, sc.depth, s, 0.0f, 0, false);
    expectMiss(a);
  }
  // Empty buffers.
  DepthScene empty = sc;
  for (glm::vec4& t : empty.depth.level(0).texels) t.x = sc.emptyDepth;
  const Texture2D emptyPyr = snellBuildDepthPyramid(empty.depth, s);
  EXPECT_EQ(emptyPyr.level(emptyPyr.levelCount() - 1).at(0, 0), glm::vec4(sc.emptyDepth, 0.0f, 0.0f, 0.0f));
  both(o, d, empty.depth, emptyPyr, 1);
  // NaN depth texels.
  for (glm::vec4& t : empty.depth.level(0).texels) t.x = kNaN;
  both(o, d, empty.depth, snellBuildDepthPyramid(empty.depth, s), 1);
}

// |dir|^2 at exactly 1e-30 is not "below 1e-30": the methods read the surface (and then find no plane:
// snellRayPlane takes only |dir|^2 above 1e-30), and a little above it the hit is the unit ray's.
TEST(IntersectPlane, DirectionsAtTheLengthThreshold) {
  const DepthScene sc = snell_test::slantedPlane(64, 64);
  const SnellDepthSurface s = sc.surface();
  const glm::dvec3 o = sc.pixelRay({0.5, 0.5}) * 2.0;
  // A direction whose float square is exactly 1e-30f (searched among the floats near 1e-15, along -z).
  float x = 1e-15f;
  for (int k = 0; k < 1000 && x * x != 1e-30f; ++k) x = std::nextafter(x, x * x < 1e-30f ? 1.0f : 0.0f);
  float y = 0.0f;
  if (x * x != 1e-30f) {  // no single float: two components, the second taking up the rest
    x = 7e-16f;
    y = std::sqrt(1e-30f - x * x);
    for (int k = 0; k < 1000 && x * x + y * y != 1e-30f; ++k)
      y = std::nextafter(y, x * x + y * y < 1e-30f ? 1.0f : 0.0f);
  }
  const glm::vec3 atThreshold(y, 0.0f, -x);
  ASSERT_EQ(glm::dot(atThreshold, atThreshold), 1e-30f);
  const SnellHit n0 = snellIntersectPlaneNormal(glm::vec3(o), atThreshold, sc.depth, sc.normals, sc.depth, s, 0.0f, 1, false);
  const SnellHit d0 = snellIntersectPlaneDepth(glm::vec3(o), atThreshold, sc.depth, s, 0, 1, false);
  expectMiss(n0);
  expectMiss(d0);
  EXPECT_GT(n0.fetches, 0);
  EXPECT_GT(d0.fetches, 0);
  const auto ref = sc.referenceHit(o, glm::dvec3(0.0, 0.0, -1.0));
  ASSERT_TRUE(ref.has_value());
  const glm::vec3 small(0.0f, 0.0f, -1.02e-15f);  // |dir|^2 = 1.04e-30
  const SnellHit n1 = snellIntersectPlaneNormal(glm::vec3(o), small, sc.depth, sc.normals, sc.depth, s, 0.0f, 1, false);
  const SnellHit d1 = snellIntersectPlaneDepth(glm::vec3(o), small, sc.depth, s, 0, 1, false);
  ASSERT_TRUE(n1.valid && d1.valid);
  EXPECT_LT(glm::length(glm::dvec3(n1.position) - *ref), 1e-4);
  EXPECT_LT(glm::length(glm::dvec3(d1.position) - *ref), 1e-4);
}

// The far start needs B0: over an empty texel of a closed surface (beside the sphere) a ray heading for
// the sphere misses after that one read, far start asked for or not.
TEST(IntersectPlane, NoFarStartWithoutB0) {
  const DepthScene sc = snell_test::sphereBack(64, 64);
  const Texture2D pyramid = snellBuildDepthPyramid(sc.depth, sc.surface());
  const glm::vec3 o(-2.6f, -0.2f, -4.0f), d(glm::normalize(glm::vec3(0.6f, 0.0f, -1.0f)));
  ASSERT_FALSE(sc.sampleAt(sc.project(glm::dvec3(o))).valid);
  for (bool farStart : {false, true}) {
    const SnellHit h = snellIntersectPlaneDepth(o, d, pyramid, sc.surface(), pyramid.levelCount() - 1, 2, farStart);
    expectMiss(h);
    EXPECT_EQ(h.fetches, 1) << farStart;
  }
  // The far start itself would have met the sphere's farthest depth: it is B0 that is missing.
  EXPECT_TRUE(snellPlaneFarStart(o, d, snellSurfaceViewToUv(sc.surface(), o).uv, pyramid, sc.surface()).valid);
}

// B0 read counts however close to the eye it lies: a valid surface may have zNear down to FLT_MIN, and a
// wall at view distance 2^-64 (zNear 2^-67) puts B0 within 2^-63 of the eye, |B0|^2 below FLT_MIN (a
// denormal), at 2^-78 below the smallest denormal (0 in float). The far start still runs for the first plane. At that scale the plane of B, C, D (its normal
// is a cross product of texel-sized vectors, about 2^-138) and the facing plane (normal B0) are too small
// to normalize (|n|^2 above 1e-30), so the far start's plane, the wall itself (farthest distance 2^-64), is
// plane 0: a ray along W's pixel ray (span 0, level 0) reads B0, C, D, the far start's top texel and
// level-0 texel, then the final lookup, and hits the wall at twice W.
TEST(IntersectPlane, FarStartRunsForAB0WithinADenormalSquaredDistanceOfTheEye) {
  for (const int kScale : {-66, -80}) {
    SCOPED_TRACE(kScale);
    glm::mat4 m(0.0f);  // the square perspective, INFINITE_REVERSED: clip = (x, y, zNear, -z)
    const float zNear = std::ldexp(1.0f, kScale - 1);
    m[0][0] = 1.0f;
    m[1][1] = 1.0f;
    m[2][3] = -1.0f;
    m[3][2] = zNear;
    const SnellDepthSurface s = snellDepthSurface(m, zNear, 1.0f, SNELL_DEPTH_INFINITE_REVERSED, 0.0f);
    ASSERT_TRUE(s.perspective && s.linearizable && s.closed);
    const Texture2D wall(Image(64, 64, glm::vec4(0.125f, 0.0f, 0.0f, 0.0f)));  // distance zNear / 0.125
    const Texture2D pyramid = snellBuildDepthPyramid(wall, s);
    const double scale = std::ldexp(1.0, kScale);
    const glm::dvec3 unit(0.3, -0.2, -2.0);
    const glm::vec3 w(unit * scale), d(unit);
    const glm::dvec3 want = 2.0 * unit * scale;  // on the wall, at z = -2^(kScale + 2)
    const glm::dvec2 centre = (glm::floor((0.5 * glm::dvec2(unit) / 2.0 + 0.5) * 64.0) + 0.5) / 64.0;  // W's texel
    const glm::dvec3 b0 = 4.0 * scale * glm::dvec3(2.0 * centre - 1.0, -1.0);
    ASSERT_GT(glm::dot(b0, b0), 0.0);
    ASSERT_LT(glm::dot(b0, b0), double(FLT_MIN));
    const SnellHit h = snellIntersectPlaneDepth(w, d, pyramid, s, pyramid.levelCount() - 1, 0, true);
    ASSERT_TRUE(h.valid);
    EXPECT_EQ(h.fetches, 3 + 2 + 1);
    EXPECT_LT(glm::length(glm::dvec3(h.position) - want), 1e-5 * glm::length(want));
    // Without the far start nothing at this scale builds a plane: the miss after B0, C and D.
    const SnellHit poster = snellIntersectPlaneDepth(w, d, pyramid, s, pyramid.levelCount() - 1, 0, false);
    EXPECT_FALSE(poster.valid);
    EXPECT_EQ(poster.fetches, 3);
  }
}

// A ray moving away from the slanted plane (dot(dir, n) > 0) but deeper never meets it: plane 0 is the
// plane through B0 (W's texel centre point) facing the camera, met where the ray reaches B0's depth along
// the line of sight. One plane (N = 0), no far start; the point is in front of the surface, on screen.
TEST(IntersectPlane, FacingPlaneWhenTheRayDoesNotMeetTheSurfacesPlane) {
  const DepthScene sc = snell_test::slantedPlane(64, 64);
  const glm::dvec3 w = sc.pixelRay({0.5, 0.5}) * 5.9, d(1.0, 1.0, -0.5);
  const glm::dvec2 uvW = sc.project(w);
  const glm::dvec2 centre = (glm::floor(uvW * 64.0) + 0.5) / 64.0;
  const glm::dvec3 b = sc.pixelRay(centre) * sc.sampleAt(centre).s;
  const glm::dvec3 want = w + glm::dot(b - w, b) / glm::dot(d, b) * d;
  const SnellHit hn = snellIntersectPlaneNormal(glm::vec3(w), glm::vec3(d), sc.depth, sc.normals, sc.depth,
                                                sc.surface(), 0.0f, 0, false);
  const SnellHit hd = snellIntersectPlaneDepth(glm::vec3(w), glm::vec3(d), sc.depth, sc.surface(), 0, 0, false);
  for (const SnellHit& h : {hn, hd}) {
    ASSERT_TRUE(h.valid);
    EXPECT_LT(glm::length(glm::dvec3(h.position) - want), 1e-3);
  }
}

// W behind the slanted plane, heading deeper: neither the surface's plane nor the facing one lies ahead, so
// without the far start both methods miss; with it plane 0 is the far start's plane (F.position), where
// the final lookup finds the surface.
TEST(IntersectPlane, FarStartWhenNoPlaneAtB0IsAhead) {
  const DepthScene sc = snell_test::slantedPlane(64, 64);
  const SnellDepthSurface s = sc.surface();
  const Texture2D pyramid = snellBuildDepthPyramid(sc.depth, s);
  const glm::vec3 w(sc.pixelRay({0.5, 0.5}) * 6.5), d(1.0f, 1.0f, -1.0f);
  const int top = pyramid.levelCount() - 1;
  expectMiss(snellIntersectPlaneNormal(w, d, sc.depth, sc.normals, pyramid, s, 0.0f, 0, false));
  expectMiss(snellIntersectPlaneDepth(w, d, pyramid, s, top, 0, false));
  const SnellFarPlane f = snellPlaneFarStart(w, d, snellSurfaceViewToUv(s, w).uv, pyramid, s);
  ASSERT_TRUE(f.valid);
  for (const SnellHit& h : {snellIntersectPlaneNormal(w, d, sc.depth, sc.normals, pyramid, s, 0.0f, 0, true),
                            snellIntersectPlaneDepth(w, d, pyramid, s, top, 0, true)}) {
    ASSERT_TRUE(h.valid);
    EXPECT_LT(glm::length(h.position - f.position), 1e-4f);
  }
}

// A refinement that cannot build its plane keeps P_(k-1): on the annulus, a ray from in front of its ring
// aimed at a point of its plane inside the hole; plane 0 is the annulus' plane (exact), plane 1 would be
// read in the hole (empty). The final lookup is empty too, so the closed surface holds the hit on plane 0:
// at the target, uv = W's texel centre.
TEST(IntersectPlane, RefinementStopsOnAnEmptyTexelAndHoldsThePreviousPlane) {
  const DepthScene sc = snell_test::silhouette(128, 128);
  const glm::dvec3 c(-0.2, 0.1, -7.0), n = glm::normalize(glm::dvec3(0.2, 0.75, 0.6));
  const glm::dvec3 e1 = glm::normalize(glm::cross(n, glm::dvec3(0.0, 0.0, 1.0))), e2 = glm::cross(n, e1);
  int checked = 0;
  for (int k = 0; k < 12; ++k) {
    const double a = 0.5236 * k;
    const glm::dvec3 ring = c + 1.7 * (std::cos(a) * e1 + std::sin(a) * e2);
    const glm::dvec3 target = c + 0.4 * (std::cos(a + 2.0) * e1 + std::sin(a + 2.0) * e2);
    const glm::dvec3 w = ring * 0.85;  // on the line of sight through the ring point, in front of it
    const glm::dvec2 uvW = sc.project(w);
    const glm::dvec2 centre = (glm::floor(uvW * 128.0) + 0.5) / 128.0;
    if (!sc.sampleAt(centre).valid || sc.sampleAt(sc.project(target)).valid) continue;
    const glm::vec3 wf(w), df(target - w);
    const SnellHit hn = snellIntersectPlaneNormal(wf, df, sc.depth, sc.normals, sc.depth, sc.surface(), 0.0f, 2, false);
    const SnellHit hd = snellIntersectPlaneDepth(wf, df, sc.depth, sc.surface(), 0, 2, false);
    EXPECT_EQ(hn.fetches, 2 + 1 + 1);  // plane 0, plane 1's empty depth read, the final lookup
    for (const SnellHit& h : {hn, hd}) {
      ASSERT_TRUE(h.valid) << k;
      EXPECT_LT(glm::length(glm::dvec3(h.position) - target), 1e-3) << k;
      EXPECT_NEAR(h.uv.x, centre.x, 1e-6) << k;
      EXPECT_NEAR(h.uv.y, centre.y, 1e-6) << k;
    }
    ++checked;
  }
  EXPECT_GE(checked, 8);
}

// A refinement whose plane is behind W keeps P_(k-1) (the normal method): W at z = -4 over the step's far
// plane, heading left and deeper; plane 0 is the far plane (exact), hit at a point seen through the near
// half-plane (z = -3), whose plane and facing plane lie behind W. The hit stays on the far plane there.
TEST(IntersectPlane, RefinementStopsWhenThePlaneIsBehindW) {
  const DepthScene sc = snell_test::stepEdge(128, 128);
  const glm::dvec3 p(0.0, 0.0, -8.0), n = glm::normalize(glm::dvec3(-0.1, 0.2, 1.0));
  for (double y : {-0.5, 0.0, 0.4}) {
    const glm::dvec3 w(1.0, y, -4.0), d(-1.0, 0.1, -1.0);
    const glm::dvec3 want = w + glm::dot(p - w, n) / glm::dot(d, n) * d;
    ASSERT_LT(3.0 * sc.pixelRay(sc.project(want)).x, 0.25);  // seen through the near half-plane
    ASSERT_GT(3.0 * sc.pixelRay(sc.project(w)).x, 0.25);     // W over the far plane
    const SnellHit h = snellIntersectPlaneNormal(glm::vec3(w), glm::vec3(d), sc.depth, sc.normals, sc.depth,
                                                 sc.surface(), 0.0f, 1, false);
    ASSERT_TRUE(h.valid) << y;
    EXPECT_LT(glm::length(glm::dvec3(h.position) - want), 1e-3) << y;
    EXPECT_EQ(h.fetches, 2 + 2 + 1);
  }
}

// The hold keeps the texel of the last plane built: fronto-parallel texels (normals (0, 0, 1)) at view
// distances 3 (W's column 4), 6 (column 6), nothing in column 7, a 90 degree camera. The ray from
// (0, 0, -1) along (1, 0, -1) meets plane 0 at z = -3 (x = 2, uv.x 0.83: column 6), plane 1 at z = -6
// (x = 5, uv.x 0.92: column 7), where plane 2 cannot be read: the hit stays on plane 1, uv column 6's centre.
TEST(IntersectPlane, HeldHitTakesTheTexelOfTheLastPlaneBuilt) {
  const glm::mat4 proj = snellPerspectiveWithDepth(1.5707964f, 1.0f, 0.5f, 40.0f, SNELL_DEPTH_GL);
  const SnellDepthSurface s = snellDepthSurface(proj, 0.5f, 40.0f, SNELL_DEPTH_GL, 0.0f);
  Image depth(8, 8, glm::vec4(0.0f)), normals(8, 8, glm::vec4(0.0f, 0.0f, 1.0f, 1.0f));
  for (int j = 0; j < 8; ++j) {
    for (int i = 0; i <= 5; ++i) depth.at(i, j).x = float(snell_test::windowDepth(3.0, 0.5, 40.0, SNELL_DEPTH_GL));
    depth.at(6, j).x = float(snell_test::windowDepth(6.0, 0.5, 40.0, SNELL_DEPTH_GL));
  }
  const Texture2D depthTex(depth), normalTex(normals);
  const SnellHit h = snellIntersectPlaneNormal(glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(1.0f, 0.0f, -1.0f), depthTex,
                                               normalTex, depthTex, s, 0.0f, 2, false);
  ASSERT_TRUE(h.valid);
  EXPECT_LT(glm::length(h.position - glm::vec3(5.0f, 0.0f, -6.0f)), 1e-4f);
  EXPECT_EQ(h.uv, glm::vec2(6.5f / 8.0f, 4.5f / 8.0f));
  EXPECT_EQ(h.fetches, 2 + 2 + 1 + 1);
}

// Plane 0 met behind the camera (a ray towards it, the slanted plane's extension): the refinement cannot
// project P_0 and stops; the hit is a miss after plane 0's two reads.
TEST(IntersectPlane, PlaneHitBehindTheCameraIsAMissAfterItsReads) {
  const DepthScene sc = snell_test::slantedPlane(64, 64);
  const glm::vec3 w(0.0f, 0.0f, -1.0f), d(-1.0f, -1.0f, 0.3f);
  const SnellHit h = snellIntersectPlaneNormal(w, d, sc.depth, sc.normals, sc.depth, sc.surface(), 0.0f, 2, false);
  expectMiss(h);
  EXPECT_EQ(h.fetches, 2);
}

// Q exactly at B0's depth is not deeper than it: Q2 = Q + d dir. On the sphere (one level, 16 texels),
// Q sits 0.4 texel right of and above B0's texel centre at its depth and heads diagonally within the
// image plane: Q2 lands in the texel up and right (0.8, 0.8), which C is read at; D is the texel above.
// (Q - d dir would land in B's own texel and read C to its right: another plane on the curved surface.)
TEST(IntersectPlane, DepthPlaneAtQLevelWithB0StepsForward) {
  const DepthScene sc = snell_test::sphereBack(16, 16);
  const SnellDepthSurface s = sc.surface();
  const glm::ivec2 pb(5, 9);
  const glm::vec2 centre((float(pb.x) + 0.5f) / 16.0f, (float(pb.y) + 0.5f) / 16.0f);
  const SnellSurfacePoint b0 = snellSurfacePoint(sc.depth, centre, s);
  ASSERT_TRUE(b0.valid);
  const float h = -b0.position.z * float(2.0 * sc.tanHalfX) / 16.0f;  // a texel's width at B0's depth
  const glm::vec3 q = b0.position + glm::vec3(0.4f * h, 0.4f * h, 0.0f);
  const glm::vec3 dirN(0.70710677f, 0.70710677f, 0.0f);
  auto point = [&](glm::ivec2 px) {
    const glm::dvec2 uv((px.x + 0.5) / 16.0, (px.y + 0.5) / 16.0);
    return sc.pixelRay(uv) * sc.sampleAt(uv).s;
  };
  const glm::dvec3 B = point(pb), C = point(pb + glm::ivec2(1, 1)), D = point(pb + glm::ivec2(0, 1));
  const glm::dvec3 want = glm::cross(C - B, D - B);
  const SnellDepthPlane got = snellDepthPlaneAt(q, dirN, sc.depth, s, 0);
  ASSERT_TRUE(got.valid);
  EXPECT_EQ(got.fetches, 3);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got.normal[k], want[k], 2e-3 * glm::length(want)) << k;
  // The other plane (C to the right) is far outside that tolerance here.
  const glm::dvec3 other = glm::cross(point(pb + glm::ivec2(1, 0)) - B, D - B);
  EXPECT_GT(glm::length(other - want), 0.05 * glm::length(want));
}

TEST(IntersectPlane, RaysTowardsTheCameraUseThePlaneAhead) {
  // A plane facing the camera, origin in front of it, ray pointing partly towards
  // the camera but still reaching the (tilted) plane: valid, on the ray, exact.
  const DepthScene sc = snell_test::slantedPlane(128, 128);
  const glm::dvec3 o = sc.pixelRay({0.5, 0.5}) * 5.5;  // 0.5 in front of the plane
  const glm::dvec3 d = glm::normalize(glm::dvec3(-1.0, -1.0, 0.05));  // n = (0.35, 0.45, 1): heads into the plane
  const auto ref = sc.referenceHit(o, d);
  ASSERT_TRUE(ref.has_value());
  const SnellHit h = snellIntersectPlaneNormal(glm::vec3(o), glm::vec3(d), sc.depth, sc.normals, sc.depth, sc.surface(), 0.0f, 1, false);
  ASSERT_TRUE(h.valid);
  EXPECT_LT(glm::length(glm::dvec3(h.position) - *ref), 1e-4);
}

TEST(IntersectPlane, NormalMipLevelsAreUsable) {
  // Blurrier normal levels: still valid, and on a plane still exact (the plane's
  // normal is constant, so every level holds it).
  const DepthScene sc = snell_test::slantedPlane(128, 128);
  const Texture2D normals = snellBuildNormalMips(sc.normals);
  const std::vector<TestRay> rays = planeRays(sc, 300, 8);
  const Texture2D none;
  for (float lod : {0.0f, 1.5f, 3.0f}) {
    const Stats st = evaluate(sc, normals, none, rays, Method::Normal, 1, lod);
    EXPECT_EQ(st.valid, st.total);
    EXPECT_LT(st.maxErr, 1e-4 * depthRange(sc)) << lod;
  }
}

// snellDepthPlaneAt's contract in double, from the texels of the texture it is given (its level images,
// read here directly; a texel's point is the pixel ray through its centre at the view distance its window
// depth gives): B0, the level, the texels pB, pC, pD and their fallbacks, the normal, the fetches. Cases
// where float may decide otherwise (a uv within 1e-3 texels of a texel edge, a span within 1e-3 of a power
// of two, Q within 1e-4 of B0's depth) are left out.
struct DepthPlaneWant {
  bool ambiguous = false, valid = false;
  glm::dvec2 uv{0.0};
  glm::dvec3 position{0.0}, normal{0.0};
  int fetches = 0, level = 0;
  bool fallback = false;  // C or D read on the other side
};

double viewDistance(double d, const DepthScene& sc) {  // GL: the inverse of snell_test::windowDepth
  return double(sc.zFar) * double(sc.zNear) / (double(sc.zFar) - d * (double(sc.zFar) - double(sc.zNear)));
}

DepthPlaneWant depthPlaneWant(const DepthScene& sc, const Texture2D& mips, int maxLod, glm::dvec3 q, glm::dvec3 dirN) {
  DepthPlaneWant w;
  auto edgy = [&](glm::dvec2 uv, int level) {
    const Image& im = mips.level(level);
    const glm::dvec2 x = uv * glm::dvec2(im.width, im.height), f = glm::abs(x - glm::round(x));
    return std::min(f.x, f.y) < 1e-3;
  };
  // The point of texel px at `level`, or nullopt where empty or outside the level.
  auto point = [&](int level, glm::ivec2 px) -> std::optional<glm::dvec3> {
    const Image& im = mips.level(level);
    if (px.x < 0 || px.y < 0 || px.x >= im.width || px.y >= im.height) return std::nullopt;
    const float d = im.at(px.x, px.y).x;
    if (d == sc.emptyDepth) return std::nullopt;
    const glm::dvec2 centre((px.x + 0.5) / im.width, (px.y + 0.5) / im.height);
    return sc.pixelRay(centre) * viewDistance(double(d), sc);
  };
  auto texel = [&](glm::dvec2 uv, int level) {
    const Image& im = mips.level(level);
    return glm::clamp(glm::ivec2(glm::floor(uv * glm::dvec2(im.width, im.height))), glm::ivec2(0),
                      glm::ivec2(im.width - 1, im.height - 1));
  };
  if (!(q.z < 0.0)) return w;
  const glm::dvec2 uvQ = sc.project(q);
  if (edgy(uvQ, 0)) {
    w.ambiguous = true;
    return w;
  }
  w.fetches = 1;
  if (uvQ.x < 0.0 || uvQ.x > 1.0 || uvQ.y < 0.0 || uvQ.y > 1.0) return w;
  const glm::ivec2 p0 = texel(uvQ, 0);
  const auto b0 = point(0, p0);
  if (!b0) return w;
  w.uv = (glm::dvec2(p0) + 0.5) / glm::dvec2(mips.level(0).width, mips.level(0).height);
  if (std::abs(q.z - b0->z) < 1e-4) {
    w.ambiguous = true;
    return w;
  }
  const double d = glm::length(*b0 - q);
  const glm::dvec3 q2 = q.z < b0->z ? q - d * dirN : q + d * dirN;
  const glm::dvec2 uv2 = q2.z < 0.0 ? sc.project(q2) : uvQ;
  const glm::dvec2 size0(mips.level(0).width, mips.level(0).height);
  const glm::dvec2 way = glm::abs(uv2 - uvQ) * size0;
  const double span = std::max(way.x, way.y);
  const int top = std::min(maxLod, SNELL_PLANE_DEPTH_MAX_SPAN_LOD);
  int level = 0;
  if (span > 1.0) {
    const double l2 = std::log2(span);
    if (std::abs(l2 - std::round(l2)) < 1e-3) {
      w.ambiguous = true;
      return w;
    }
    level = int(std::ceil(l2));
  }
  level = std::max(0, std::min(level, top));
  w.level = level;
  if (edgy(uvQ, level) || edgy(uv2, level)) {
    w.ambiguous = true;
    return w;
  }
  const glm::ivec2 pb = texel(uvQ, level);
  glm::ivec2 pc = texel(uv2, level);
  const glm::ivec2 dpc = pc - pb;
  glm::ivec2 a(1, 0);
  if (std::abs(dpc.y) > std::abs(dpc.x)) a = glm::ivec2(0, dpc.y > 0 ? 1 : -1);
  else if (dpc.x != 0) a = glm::ivec2(dpc.x > 0 ? 1 : -1, 0);
  if (dpc == glm::ivec2(0)) pc = pb + a;
  const glm::ivec2 b = a.x != 0 ? glm::ivec2(0, 1) : glm::ivec2(1, 0);
  glm::dvec3 B = *b0;
  if (level != 0) {
    ++w.fetches;
    const auto bl = point(level, pb);
    if (!bl) return w;
    B = *bl;
  }
  w.position = B;
  ++w.fetches;
  auto C = point(level, pc);
  if (!C) {
    ++w.fetches;
    w.fallback = true;
    C = point(level, pb - a);
    if (!C) return w;
  }
  ++w.fetches;
  auto D = point(level, pb + b);
  if (!D) {
    ++w.fetches;
    w.fallback = true;
    D = point(level, pb - b);
    if (!D) return w;
  }
  w.normal = glm::cross(*C - B, *D - B);
  w.valid = true;
  return w;
}

// Reference points around the two surfaces (in front of them and behind), directions in every quadrant,
// on the mean pyramid (levels up to the top or a lower maxLod) and on the one-level texture.
TEST(IntersectPlane, DepthPlaneReadsThePointsTheContractNames) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked = 0, leveled = 0, fallbacks = 0, invalid = 0, behind = 0;
  for (const DepthScene& sc : {snell_test::sphereBack(128, 128), snell_test::slantedPlane(128, 96)}) {
    const SnellDepthSurface s = sc.surface();
    const Texture2D pyramid = snellBuildDepthPyramid(sc.depth, s);
    for (int i = 0; i < 3000; ++i) {
      const bool one = i % 4 == 0;
      const Texture2D& mips = one ? sc.depth : pyramid;
      const int maxLod = one ? 0 : i % 4 == 1 ? 2 : pyramid.levelCount() - 1;
      const glm::dvec2 uv(u(rng), u(rng));
      const double depth = 3.0 + 8.0 * u(rng);
      const glm::vec3 q(sc.pixelRay(uv) * depth);
      const double phi = 6.283185307179586 * u(rng), lat = 0.2 + 1.2 * u(rng);
      const glm::vec3 dirN(glm::normalize(glm::dvec3(std::cos(phi) * std::cos(lat), std::sin(phi) * std::cos(lat),
                                                     -std::sin(lat))));
      const DepthPlaneWant want = depthPlaneWant(sc, mips, maxLod, glm::dvec3(q), glm::dvec3(dirN));
      if (want.ambiguous) continue;
      const SnellDepthPlane got = snellDepthPlaneAt(q, dirN, mips, s, maxLod);
      ASSERT_EQ(got.valid, want.valid) << sc.name << " " << i;
      EXPECT_EQ(got.fetches, want.fetches) << sc.name << " " << i;
      EXPECT_NEAR(got.uv.x, want.uv.x, 1e-6) << sc.name << " " << i;
      EXPECT_NEAR(got.uv.y, want.uv.y, 1e-6) << sc.name << " " << i;
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(got.position[k], want.position[k], 1e-4 * 12.0) << sc.name << " " << i;
      if (want.valid) {
        const double n = glm::length(want.normal);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(got.normal[k], want.normal[k], 2e-3 * n) << sc.name << " " << i;
      } else {
        EXPECT_EQ(got.normal, glm::vec3(0.0f));
      }
      if (::testing::Test::HasFailure()) return;
      ++checked;
      leveled += want.level > 0;
      fallbacks += want.fallback;
      invalid += !want.valid;
      behind += want.position != glm::dvec3(0.0) && double(q.z) < want.position.z;
    }
  }
  // No plane around a point that does not project (at or behind the eye): nothing read.
  const DepthScene sc = snell_test::slantedPlane(64, 64);
  for (const glm::vec3 q : {glm::vec3(0.0f), glm::vec3(0.2f, 0.1f, 1.0f)}) {
    const SnellDepthPlane none = snellDepthPlaneAt(q, glm::vec3(0.0f, 0.0f, -1.0f), sc.depth, sc.surface(), 0);
    EXPECT_FALSE(none.valid);
    EXPECT_EQ(none.fetches, 0);
    EXPECT_EQ(none.position, glm::vec3(0.0f));
  }
  std::printf("[depth plane] %d checked, %d above level 0, %d with a fallback texel, %d invalid, %d from behind the "
              "surface\n", checked, leveled, fallbacks, invalid, behind);
  EXPECT_GT(checked, 4000);
  EXPECT_GT(leveled, 1000);
  EXPECT_GT(fallbacks, 50);
  EXPECT_GT(invalid, 200);
  EXPECT_GT(behind, 500);
}

}  // namespace
