// glsl/snell/intersect/{linear_march, dda_march}.glsl against the analytic
// reference hit of tests/support/depth_scenes.hpp (a dense double-precision
// march of the continuous surface): errors shrink as the march gets finer;
// bad input gives finite misses.
#include <gtest/gtest.h>

#include <snell/intersect.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <string>

#include "support/search_rays.hpp"
#include "support/depth_scenes.hpp"

namespace {

using namespace snell;
using snell_search_test::finite;
using snell_search_test::Ray;
using snell_search_test::texelValid;
using snell_test::DepthScene;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

struct ErrorStats {
  double mean = 0.0;
  double hitShare = 0.0;
  double fetches = 0.0;
};

// Mean |hit - reference| over the rays that have a reference hit; misses are
// counted in hitShare (the share of those rays the strategy hit), not in the mean.
ErrorStats measure(const DepthScene& sc, const std::vector<Ray>& rays,
                   const std::function<SnellHit(const Ray&)>& strategy) {
  ErrorStats st;
  int withRef = 0, hits = 0;
  double sum = 0.0, fetches = 0.0;
  for (const Ray& ray : rays) {
    const std::optional<glm::dvec3> ref = sc.referenceHit(glm::dvec3(ray.origin), glm::dvec3(ray.dir));
    const SnellHit h = strategy(ray);
    fetches += h.fetches;
    if (!ref) continue;
    ++withRef;
    if (!h.valid) continue;
    ++hits;
    sum += glm::length(glm::dvec3(h.position) - *ref);
  }
  st.mean = hits ? sum / hits : std::numeric_limits<double>::infinity();
  st.hitShare = withRef ? double(hits) / withRef : 0.0;
  st.fetches = fetches / double(rays.size());
  return st;
}

const DepthScene& sphereScene() {
  static const DepthScene sc = snell_test::sphereBack(256, 256);
  return sc;
}
const DepthScene& planeScene() {
  static const DepthScene sc = snell_test::slantedPlane(256, 256);
  return sc;
}

void expectConverges(const char* what, const ErrorStats (&e)[3]) {
  std::printf("[%s] mean error %.5f %.5f %.5f, hit share %.4f %.4f %.4f, fetches %.1f %.1f %.1f\n", what, e[0].mean,
              e[1].mean, e[2].mean, e[0].hitShare, e[1].hitShare, e[2].hitShare, e[0].fetches, e[1].fetches,
              e[2].fetches);
  EXPECT_GT(e[0].mean, e[1].mean) << what;
  EXPECT_GT(e[1].mean, e[2].mean) << what;
  EXPECT_GT(e[2].hitShare, 0.98) << what;
}

TEST(IntersectMarch, LinearMarchConvergesToTheAnalyticHit) {
  const int steps[3] = {8, 32, 128};
  {
    const DepthScene& sc = sphereScene();
    const std::vector<Ray> rays = snell_search_test::sphereRefractedRays(sc, 1500, 21);
    ErrorStats e[3], r[3];
    for (int k = 0; k < 3; ++k) {
      e[k] = measure(sc, rays, [&](const Ray& ray) {
        return snellLinearMarch(ray.origin, ray.dir, sc.depth, sc.surface(), 5.0f, steps[k], 0);
      });
      r[k] = measure(sc, rays, [&](const Ray& ray) {
        return snellLinearMarch(ray.origin, ray.dir, sc.depth, sc.surface(), 5.0f, steps[k], 4);
      });
    }
    expectConverges("linear march sphereBack, no refinement", e);
    expectConverges("linear march sphereBack, 4 refinements", r);
    EXPECT_LT(r[2].mean, 0.02);  // 256 px over ~4.6 units: a texel is ~0.02 wide at the sphere
    for (int k = 0; k < 3; ++k) EXPECT_LT(r[k].mean, e[k].mean);
  }
  {
    const DepthScene& sc = planeScene();
    const std::vector<Ray> rays = snell_search_test::sceneRays(sc, 1500, 22);
    ErrorStats e[3];
    for (int k = 0; k < 3; ++k)
      e[k] = measure(sc, rays, [&](const Ray& ray) {
        return snellLinearMarch(ray.origin, ray.dir, sc.depth, sc.surface(), 16.0f, steps[k], 0);
      });
    std::printf("(slantedPlane: rays leaving the screen before the plane are misses for every step count)\n");
    EXPECT_GT(e[0].mean, e[1].mean);
    EXPECT_GT(e[1].mean, e[2].mean);
  }
}

TEST(IntersectMarch, DdaMarchConvergesAsTheStrideShrinks) {
  const float strides[3] = {16.0f, 4.0f, 1.0f};
  {
    const DepthScene& sc = sphereScene();
    const std::vector<Ray> rays = snell_search_test::sphereRefractedRays(sc, 1500, 23);
    ErrorStats e[3];
    for (int k = 0; k < 3; ++k)
      e[k] = measure(sc, rays, [&](const Ray& ray) {
        return snellDdaMarch(ray.origin, ray.dir, sc.depth, sc.surface(), 5.0f, SNELL_DDA_THICKNESS, strides[k], 1024);
      });
    expectConverges("dda sphereBack, stride 16/4/1", e);
    EXPECT_LT(e[2].mean, 0.02);
  }
  {
    const DepthScene& sc = planeScene();
    const std::vector<Ray> rays = snell_search_test::sceneRays(sc, 1500, 24);
    ErrorStats e[3];
    for (int k = 0; k < 3; ++k)
      e[k] = measure(sc, rays, [&](const Ray& ray) {
        return snellDdaMarch(ray.origin, ray.dir, sc.depth, sc.surface(), 16.0f, SNELL_DDA_THICKNESS, strides[k], 1024);
      });
    std::printf("[dda slantedPlane] mean error %.5f %.5f %.5f\n", e[0].mean, e[1].mean, e[2].mean);
    EXPECT_GT(e[0].mean, e[1].mean);
    EXPECT_GT(e[1].mean, e[2].mean);
  }
}

// The DDA visits every pixel of the segment with stride 1: it does not miss
// the thin spike (about 2 px wide) that a coarse linear march steps over.
TEST(IntersectMarch, DdaStrideOneDoesNotSkipAThinSpike) {
  const DepthScene sc = snell_test::thinSpike(256, 256);
  // Rays crossing the spike sideways behind its front face (z -4 .. -5.5).
  int ddaHits = 0, coarseHits = 0, total = 0;
  std::mt19937 rng(26);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int k = 0; k < 400; ++k) {
    const float y = -0.8f + 1.6f * u(rng);
    const vec3 o(-0.8f + 0.4f * u(rng), y, -4.0f - u(rng)), target(0.7f + 0.4f * u(rng), y, -4.5f - u(rng));
    const vec3 d = glm::normalize(target - o);
    const std::optional<glm::dvec3> ref = sc.referenceHit(glm::dvec3(o), glm::dvec3(d));
    if (!ref || ref->x > 0.16 || ref->x < 0.09) continue;  // the reference hits the spike
    ++total;
    const SnellHit h = snellDdaMarch(o, d, sc.depth, sc.surface(), 1.6f, SNELL_DDA_THICKNESS, 1.0f, 1024);
    if (h.valid && glm::length(glm::dvec3(h.position) - *ref) < 0.05) ++ddaHits;
    const SnellHit c = snellLinearMarch(o, d, sc.depth, sc.surface(), 1.6f, 6, 4);
    if (c.valid && glm::length(glm::dvec3(c.position) - *ref) < 0.05) ++coarseHits;
  }
  std::printf("[thin spike] rays=%d dda-hits=%d coarse-linear-hits=%d\n", total, ddaHits, coarseHits);
  ASSERT_GT(total, 50);
  EXPECT_EQ(ddaHits, total);
  EXPECT_LT(coarseHits, total);
}

// A ray along the line of sight projects to one pixel: the DDA covers its whole
// depth range there and puts the hit at the stored depth.
TEST(IntersectMarch, DdaRayAlongTheLineOfSight) {
  const DepthScene& sc = planeScene();
  const glm::dvec2 uv(0.3, 0.6);
  const glm::dvec3 q = sc.pixelRay(uv);
  const vec3 o = vec3(2.0 * q), d = vec3(glm::normalize(q));
  const SnellHit h = snellDdaMarch(o, d, sc.depth, sc.surface(), 20.0f, SNELL_DDA_THICKNESS, 1.0f, 64);
  ASSERT_TRUE(h.valid);
  EXPECT_LE(h.fetches, 2);
  const std::optional<glm::dvec3> ref = sc.referenceHit(glm::dvec3(o), glm::dvec3(d));
  ASSERT_TRUE(ref.has_value());
  EXPECT_LT(glm::length(glm::dvec3(h.position) - *ref), 0.05);  // one texel of a slanted plane
}

// Finite thickness lets a ray pass behind a foreground object: on stepEdge a
// ray runs behind the z = -3 half-plane (1..2 units deeper than it).
TEST(IntersectMarch, DdaThicknessLetsRaysPassBehind) {
  const DepthScene sc = snell_test::stepEdge(256, 256);
  const vec3 o(0.6f, 0.05f, -4.0f);
  const vec3 d = glm::normalize(vec3(-2.1f, 0.0f, -1.5f));
  const SnellHit solid = snellDdaMarch(o, d, sc.depth, sc.surface(), 3.0f, SNELL_DDA_THICKNESS, 1.0f, 1024);
  ASSERT_TRUE(solid.valid);
  EXPECT_GT(solid.position.z, -4.5f);  // stopped where it went behind the half-plane
  const SnellHit thin = snellDdaMarch(o, d, sc.depth, sc.surface(), 3.0f, 0.5f, 1.0f, 1024);
  EXPECT_TRUE(!thin.valid || thin.position.z < -6.0f);
  EXPECT_TRUE(finite(thin));
}

// Regression (property test input #12805 of snellDdaMarch): a far end
// whose 1/w (~1e-21) is below the ulp of the origin's made k0 + s (k1 - k0)
// cancel to 0 at s = 1, and the hit in the last step got a NaN position. The
// hit must be a point of the ray at the sphere's back face (the analytic
// reference, within the stride: 5.9 px of ~0.018 units), for maxDistance 1e21,
// 1e30 and FLT_MAX (capped at 1e30 by contract).
TEST(IntersectMarch, DdaHugeMaxDistanceHitsAtAFinitePointOfTheRay) {
  const DepthScene& sc = sphereScene();
  const vec3 o(-0.0621630959f, -0.00107261236f, -3.83915162f);
  const vec3 d(0.0144228153f, -0.0155654298f, -0.999774814f);
  const std::optional<glm::dvec3> ref = sc.referenceHit(glm::dvec3(o), glm::dvec3(d));
  ASSERT_TRUE(ref.has_value());
  for (const float maxDistance : {8.67736336e20f, 1e30f, std::numeric_limits<float>::max()}) {
    const SnellHit h = snellDdaMarch(o, d, sc.depth, sc.surface(), maxDistance, kInf, 5.88873959f, 173);
    ASSERT_TRUE(h.valid) << maxDistance;
    ASSERT_TRUE(finite(h)) << maxDistance;
    const glm::dvec3 p(h.position), od(o), dd = glm::normalize(glm::dvec3(d));
    EXPECT_LT(glm::length(glm::cross(p - od, dd)), 1e-4) << maxDistance;  // on the ray
    EXPECT_LT(glm::length(p - *ref), 0.15) << maxDistance;
  }
}

TEST(IntersectMarch, BadInputGivesFiniteMisses) {
  const DepthScene& sc = sphereScene();
  const SnellDepthSurface surf = sc.surface();
  const vec3 o(0.3f, -0.2f, -4.0f), d(0.0f, 0.0f, -1.0f);
  ASSERT_TRUE(snellLinearMarch(o, d, sc.depth, surf).valid);
  ASSERT_TRUE(snellDdaMarch(o, d, sc.depth, surf).valid);
  snell::Texture2D empty(snell::Image(64, 64, vec4(surf.emptyDepth, 0.0f, 0.0f, 0.0f)));
  struct Case {
    vec3 o, d;
    float maxDistance;
    const snell::Texture2D* tex;
    const char* what;
  };
  const Case cases[] = {
      {vec3(kNaN, 0.0f, -4.0f), d, 10.0f, &sc.depth, "NaN origin"},
      {o, vec3(0.0f, kInf, -1.0f), 10.0f, &sc.depth, "Inf dir"},
      {o, vec3(0.0f), 10.0f, &sc.depth, "zero dir"},
      {o, vec3(1e-40f, 0.0f, 0.0f), 10.0f, &sc.depth, "denormal dir"},
      {o, d, 0.0f, &sc.depth, "maxDistance 0"},
      {o, d, -1.0f, &sc.depth, "maxDistance < 0"},
      {o, d, kNaN, &sc.depth, "maxDistance NaN"},
      {o, d, 10.0f, &empty, "empty buffer"},
      {o, vec3(1.0f, 0.0f, -0.05f), 30.0f, &sc.depth, "leaves the screen"},
      {vec3(0.0f, 0.0f, -0.2f), d, 10.0f, &sc.depth, "origin in front of the near plane"},
      {o, vec3(0.0f, 0.05f, 1.0f), 10.0f, &sc.depth, "towards the camera (clipped at the near plane)"},
  };
  for (const Case& c : cases) {
    const SnellHit a = snellLinearMarch(c.o, c.d, *c.tex, surf, c.maxDistance, 64, 4);
    const SnellHit b = snellDdaMarch(c.o, c.d, *c.tex, surf, c.maxDistance, SNELL_DDA_THICKNESS, 1.0f, 1024);
    EXPECT_TRUE(finite(a)) << c.what;
    EXPECT_TRUE(finite(b)) << c.what;
    if (std::string(c.what) == "origin in front of the near plane") {
      EXPECT_FALSE(b.valid) << c.what;  // the DDA needs the origin in the frustum
      continue;
    }
    EXPECT_FALSE(a.valid) << c.what;
    EXPECT_FALSE(b.valid) << c.what;
  }
  // Hostile options are clamped.
  EXPECT_TRUE(finite(snellDdaMarch(o, d, sc.depth, surf, 10.0f, kNaN, kNaN, 1 << 30)));
  EXPECT_TRUE(snellDdaMarch(o, d, sc.depth, surf, 10.0f, -1.0f, 0.0f, 1024).valid);
  EXPECT_LE(snellDdaMarch(o, vec3(1.0f, 0.0f, -0.2f), sc.depth, surf, 10.0f, 0.1f, 1.0f, 1 << 30).fetches,
            SNELL_DDA_MAX_STEPS);
  EXPECT_LE(snellLinearMarch(o, d, sc.depth, surf, 10.0f, 1 << 30, 1 << 30).fetches,
            SNELL_LINEAR_MARCH_MAX_STEPS + SNELL_LINEAR_MARCH_MAX_REFINE_STEPS);
}

// Linear march: every hit is on a valid texel, on or behind the stored surface.
TEST(IntersectMarch, LinearMarchHitsLieOnValidTexelsBehindTheSurface) {
  const DepthScene sc = snell_test::silhouette(256, 256);
  const std::vector<Ray> rays = snell_search_test::sceneRays(sc, 20000, 25);
  int hits = 0, bad = 0;
  for (const Ray& ray : rays) {
    const SnellHit h = snellLinearMarch(ray.origin, ray.dir, sc.depth, sc.surface(), 16.0f, 48, 4);
    if (!h.valid) continue;
    ++hits;
    if (!texelValid(sc, h.uv)) ++bad;
  }
  EXPECT_GT(hits, 2000);
  EXPECT_EQ(bad, 0);
}

}  // namespace
