// glsl/snell/intersect/{linear_march, dda_march}.glsl against the analytic
// reference hit of tests/support/depth_scenes.hpp (a dense double-precision
// march of the continuous surface): errors shrink as the march gets finer;
// bad input gives finite misses.
#include <gtest/gtest.h>

#include <snell/intersect.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

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

namespace {

// The DDA's contract replayed in double: the segment (capped, cut at the near plane), both ends projected
// with the scene's matrix, steps of ds along the major axis, each owning [s - ds/2, s + ds/2] of the screen
// parameter and that part's depth interval, texels read by plain index math, the first step whose texel is
// valid with zNear >= viewZ - thickness and zFar <= viewZ hitting at the ray's point of depth
// clamp(viewZ, zFar, zNear). `ambiguous` where float could decide otherwise (a uv within 1e-3 texel of a
// texel edge or the screen's border, a depth within 1e-5 |z| of a bound). The linear march's replay below
// returns the same record.
struct MarchReference {
  glm::dvec3 position{0.0};
  glm::dvec2 uv{0.0};
  bool valid = false;
  int fetches = 0;
  bool ambiguous = false;
};
MarchReference ddaReference(const DepthScene& sc, glm::dvec3 o, glm::dvec3 d, double maxDistance, double thickness,
                          double stride, int steps) {
  MarchReference r;
  const double thick = std::isnan(thickness) ? double(SNELL_DDA_THICKNESS) : std::clamp(thickness, 0.0, double(FLT_MAX));
  const double px = std::isnan(stride) ? 1.0 : std::max(stride, 1.0);
  double tMax = std::min(maxDistance, 1e30) / glm::length(d);
  if (d.z > 0.0) tMax = std::min(tMax, (-double(sc.zNear) - o.z) / d.z);
  const glm::dvec3 e = o + tMax * d;
  const glm::dmat4 m(sc.clipFromView);
  const glm::dvec4 h0 = m * glm::dvec4(o, 1.0), h1 = m * glm::dvec4(e, 1.0);
  const double k0 = 1.0 / h0.w, k1 = 1.0 / h1.w;
  const glm::dvec3 q0 = o * k0, q1 = e * k1;
  const glm::dvec2 uv0 = glm::dvec2(h0.x, h0.y) * k0 * 0.5 + 0.5;
  const glm::dvec2 duv = glm::dvec2(h1.x, h1.y) * k1 * 0.5 + 0.5 - uv0;
  const double major = std::max(std::fabs(duv.x * sc.width), std::fabs(duv.y * sc.height));
  const double ds = major > px ? px / major : 1.0;
  const int n = std::clamp(steps, 1, SNELL_DDA_MAX_STEPS);
  const auto at = [&](double s) { return (q0 * (1.0 - s) + q1 * s) / (k0 * (1.0 - s) + k1 * s); };
  double sA = 0.0, zA = o.z;
  for (int i = 0; i < SNELL_DDA_MAX_STEPS; ++i) {
    const double sC = std::min(i * ds, 1.0), sB = std::min((i + 0.5) * ds, 1.0);
    const double zB = at(sB).z;
    const glm::dvec2 uv = uv0 + sC * duv;
    const glm::dvec2 t(uv.x * sc.width, uv.y * sc.height);
    const double border = std::min({std::fabs(uv.x), std::fabs(uv.x - 1.0), std::fabs(uv.y), std::fabs(uv.y - 1.0)});
    if (border < 1e-6) r.ambiguous = true;
    if (!(uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0)) return r;
    if (std::fabs(t.x - std::round(t.x)) < 1e-3 || std::fabs(t.y - std::round(t.y)) < 1e-3) r.ambiguous = true;
    const double z = snell_search_test::texelViewZ(sc, std::min(int(std::floor(t.x)), sc.width - 1),
                                                   std::min(int(std::floor(t.y)), sc.height - 1));
    ++r.fetches;
    const double zNear = std::max(zA, zB), zFar = std::min(zA, zB);
    if (!std::isnan(z)) {
      const double eps = 1e-5 * std::fabs(z);
      if (std::fabs(zNear - (z - thick)) < eps || std::fabs(zFar - z) < eps) r.ambiguous = true;
      if (zNear >= z - thick && zFar <= z) {
        const double zHit = std::clamp(z, zFar, zNear);
        const glm::dvec3 pA = at(sA), pB = at(sB);
        const double f = pB.z != pA.z ? std::clamp((zHit - pA.z) / (pB.z - pA.z), 0.0, 1.0) : 0.5;
        r.position = pA + f * (pB - pA);
        r.uv = uv;
        r.valid = true;
        return r;
      }
    }
    sA = sB;
    zA = zB;
    if (i + 1 >= n || sA >= 1.0) break;
  }
  return r;
}

// The same fetches and validity, and for a hit the same texel (uv within 1e-4) and point (1e-4 relative).
void expectTheReferenceHit(const SnellHit& h, const MarchReference& want, const std::string& what) {
  EXPECT_EQ(h.fetches, want.fetches) << what;
  EXPECT_EQ(h.valid, want.valid) << what;
  if (!want.valid || !h.valid) return;
  EXPECT_NEAR(h.uv.x, want.uv.x, 1e-4) << what;
  EXPECT_NEAR(h.uv.y, want.uv.y, 1e-4) << what;
  EXPECT_LT(glm::length(glm::dvec3(h.position) - want.position), 1e-4 * glm::length(want.position)) << what;
}

}  // namespace

// snellDdaMarch against its contract replayed step by step, over strides, thicknesses, distances and step
// counts: the same fetches, the same hit texel and validity, the same point.
TEST(IntersectMarch, DdaIsTheContractsWalkStepByStep) {
  const float thicknesses[] = {FLT_MAX, 0.5f, 0.05f, 0.0f};
  const float strides[] = {1.0f, 2.5f, 7.0f, 0.25f};
  const float distances[] = {10.0f, 3.0f, 1e31f};
  for (const DepthScene* sc : {&sphereScene(), &planeScene()}) {
    const SnellDepthSurface surf = sc->surface();
    const std::vector<Ray> rays = snell_search_test::sceneRays(*sc, 3000, 31);
    int checked = 0, skipped = 0, hits = 0;
    for (std::size_t k = 0; k < rays.size(); ++k) {
      const Ray& ray = rays[k];
      const float thick = thicknesses[k % 4], stride = strides[(k / 4) % 4], dist = distances[(k / 16) % 3];
      const int steps = 1 + static_cast<int>((k * 37) % 400);
      const SnellHit h = snellDdaMarch(ray.origin, ray.dir, sc->depth, surf, dist, thick, stride, steps);
      const MarchReference want = ddaReference(*sc, glm::dvec3(ray.origin), glm::dvec3(ray.dir), dist, thick, stride, steps);
      if (want.ambiguous) {
        ++skipped;
        continue;
      }
      ++checked;
      hits += want.valid;
      const std::string what = "ray " + std::to_string(k) + " thickness " + std::to_string(thick) + " stride " +
                               std::to_string(stride) + " distance " + std::to_string(dist) + " steps " +
                               std::to_string(steps);
      expectTheReferenceHit(h, want, what);
      if (::testing::Test::HasFailure()) return;
    }
    std::printf("[dda step by step] %s: %d rays checked (%d hits), %d skipped as ambiguous\n", sc->name.c_str(),
                checked, hits, skipped);
    EXPECT_GT(checked, 2500);
    EXPECT_GT(hits, 500);
  }
}

// The edges the contract names: the defaults are the documented values; a ray parallel to the image plane
// (dir.z = 0) marches; an origin exactly on the near plane marches, one in front of it does not; a NaN
// thickness is the default and a negative one 0; a NaN stride is 1 and one below 1 is 1; steps are clamped
// to [1, SNELL_DDA_MAX_STEPS].
TEST(IntersectMarch, DdaEdgesOfTheContract) {
  const DepthScene& sc = planeScene();
  const SnellDepthSurface surf = sc.surface();
  const auto same = [](const SnellHit& a, const SnellHit& b) {
    return a.uv == b.uv && a.position == b.position && a.valid == b.valid && a.fetches == b.fetches;
  };
  const std::vector<Ray> rays = snell_search_test::sceneRays(sc, 400, 32);
  int differsFromStride11 = 0, differsFromDistance11 = 0;
  for (const Ray& r : rays) {
    const SnellHit h = snellDdaMarch(r.origin, r.dir, sc.depth, surf);
    EXPECT_TRUE(same(h, snellDdaMarch(r.origin, r.dir, sc.depth, surf, 10.0f, FLT_MAX, 1.0f, 256)));
    differsFromStride11 += !same(h, snellDdaMarch(r.origin, r.dir, sc.depth, surf, 10.0f, FLT_MAX, 1.1f, 256));
    differsFromDistance11 += !same(h, snellDdaMarch(r.origin, r.dir, sc.depth, surf, 11.0f, FLT_MAX, 1.0f, 256));
    EXPECT_TRUE(same(snellDdaMarch(r.origin, r.dir, sc.depth, surf, 10.0f, kNaN, kNaN, 256), h));
    EXPECT_TRUE(same(snellDdaMarch(r.origin, r.dir, sc.depth, surf, 10.0f, -3.0f, 0.5f, 256),
                     snellDdaMarch(r.origin, r.dir, sc.depth, surf, 10.0f, 0.0f, 1.0f, 256)));
    EXPECT_TRUE(same(snellDdaMarch(r.origin, r.dir, sc.depth, surf, 10.0f, FLT_MAX, 1.0f, 1 << 30),
                     snellDdaMarch(r.origin, r.dir, sc.depth, surf, 10.0f, FLT_MAX, 1.0f, SNELL_DDA_MAX_STEPS)));
    EXPECT_TRUE(same(snellDdaMarch(r.origin, r.dir, sc.depth, surf, 10.0f, FLT_MAX, 1.0f, -5),
                     snellDdaMarch(r.origin, r.dir, sc.depth, surf, 10.0f, FLT_MAX, 1.0f, 1)));
  }
  EXPECT_GT(differsFromStride11, 40);    // the checks above see the stride's default
  EXPECT_GT(differsFromDistance11, 4);   // and the distance's
  // dir.z = 0: no near-plane cut; the march crosses the screen and hits the slanted plane.
  const SnellHit flat = snellDdaMarch(vec3(-1.0f, 0.0f, -5.0f), vec3(1.0f, 0.0f, 0.0f), sc.depth, surf, 10.0f,
                                      FLT_MAX, 1.0f, 1024);
  const MarchReference flatWant = ddaReference(sc, glm::dvec3(-1.0, 0.0, -5.0), glm::dvec3(1.0, 0.0, 0.0), 10.0,
                                             FLT_MAX, 1.0, 1024);
  EXPECT_GT(flat.fetches, 1);
  EXPECT_EQ(flat.fetches, flatWant.fetches);
  EXPECT_EQ(flat.valid, flatWant.valid);
  // The near plane itself is inside the frustum; anything in front of it is not.
  const float zNear = surf.zNear;
  EXPECT_GT(snellDdaMarch(vec3(0.0f, 0.0f, -zNear), vec3(0.0f, 0.0f, -1.0f), sc.depth, surf).fetches, 0);
  EXPECT_EQ(snellDdaMarch(vec3(0.0f, 0.0f, std::nextafter(-zNear, 0.0f)), vec3(0.0f, 0.0f, -1.0f), sc.depth, surf)
                .fetches, 0);
}

namespace {

// The linear march's contract replayed in double: samples t_i = i tMax / steps (cut at the near plane), a
// sample crossing when its texel (plain index math) is valid and z <= viewZ, the first off-screen sample a
// miss, then the bisection of [t_(i-1), t_i] (an off-screen midpoint moves lo without a fetch).
MarchReference linearReference(const DepthScene& sc, glm::dvec3 o, glm::dvec3 d, double maxDistance, int steps,
                             int refineSteps) {
  MarchReference r;
  double tMax = maxDistance / glm::length(d);
  if (d.z > 0.0) tMax = std::min(tMax, (-double(sc.zNear) - o.z) / d.z);
  const int n = std::clamp(steps, 1, SNELL_LINEAR_MARCH_MAX_STEPS);
  const int nr = std::clamp(refineSteps, 0, SNELL_LINEAR_MARCH_MAX_REFINE_STEPS);
  const double dt = tMax / n;
  // 0: in front or empty, 1: crosses, -1: off screen; ambiguity where float could decide otherwise.
  // `matters`: whether a different decision here could show (in the march always; in the bisection while its
  // move is above the position tolerance).
  const auto test = [&](double t, glm::dvec2* uvOut, bool matters = true) {
    const glm::dvec3 p = o + t * d;
    const glm::dvec2 uv = sc.project(p);
    *uvOut = uv;
    const double border = std::min({std::fabs(uv.x), std::fabs(uv.x - 1.0), std::fabs(uv.y), std::fabs(uv.y - 1.0)});
    if (border < 1e-6) r.ambiguous = true;  // off screen costs no fetch: always shows
    if (!(p.z < 0.0) || !(uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0)) return -1;
    const glm::dvec2 tx(uv.x * sc.width, uv.y * sc.height);
    // The decision at the texel, and at the texels 1e-3 texel away (float may pick either near an edge).
    const auto decide = [&](double x, double y) {
      const double z = snell_search_test::texelViewZ(sc, std::clamp(int(std::floor(x)), 0, sc.width - 1),
                                                     std::clamp(int(std::floor(y)), 0, sc.height - 1));
      if (std::isnan(z)) return 0;
      if (std::fabs(p.z - z) < 1e-5 * std::fabs(z)) r.ambiguous |= matters;
      return p.z <= z ? 1 : 0;
    };
    const int c = decide(tx.x, tx.y);
    for (const double ex : {-1e-3, 1e-3})
      for (const double ey : {-1e-3, 1e-3})
        if (decide(tx.x + ex, tx.y + ey) != c) r.ambiguous |= matters;
    return c;
  };
  double tHit = 0.0;
  bool found = false;
  for (int i = 1; i <= n; ++i) {
    const double t = i * dt;
    glm::dvec2 uv;
    const int c = test(t, &uv);
    if (c < 0) return r;
    ++r.fetches;
    if (c == 1) {
      found = true;
      tHit = t;
      r.uv = uv;
      break;
    }
  }
  if (!found) return r;
  double lo = tHit - dt;
  for (int j = 0; j < nr; ++j) {
    const double mid = 0.5 * (lo + tHit);
    glm::dvec2 uv;
    const int c = test(mid, &uv, j + 1 == nr || 0.5 * (tHit - lo) * glm::length(d) > 1e-5);
    if (c >= 0) ++r.fetches;
    if (c == 1) {
      tHit = mid;
      r.uv = uv;
    } else {
      lo = mid;
    }
  }
  r.valid = true;
  r.position = o + tHit * d;
  return r;
}

}  // namespace

// snellLinearMarch against its contract replayed step by step over distances, step and refinement counts
// (clamped ones too): the same fetches, validity, hit texel and point.
TEST(IntersectMarch, LinearMarchIsTheContractsWalkStepByStep) {
  const float distances[] = {10.0f, 4.0f, 25.0f};
  for (const DepthScene* sc : {&sphereScene(), &planeScene()}) {
    const SnellDepthSurface surf = sc->surface();
    const std::vector<Ray> rays = snell_search_test::sceneRays(*sc, 3000, 33);
    int checked = 0, skipped = 0, hits = 0;
    for (std::size_t k = 0; k < rays.size(); ++k) {
      const Ray& ray = rays[k];
      const float dist = distances[k % 3];
      const int steps = static_cast<int>((k * 7) % 300) - 3;        // -3 .. 296: clamped below to 1
      const int refine = static_cast<int>((k / 3) % 20) - 2;        // -2 .. 17: clamped to [0, max]
      const SnellHit h = snellLinearMarch(ray.origin, ray.dir, sc->depth, surf, dist, steps, refine);
      const MarchReference want = linearReference(*sc, glm::dvec3(ray.origin), glm::dvec3(ray.dir), dist, steps, refine);
      if (want.ambiguous) {
        ++skipped;
        continue;
      }
      ++checked;
      hits += want.valid;
      const std::string what = "ray " + std::to_string(k) + " distance " + std::to_string(dist) + " steps " +
                               std::to_string(steps) + " refine " + std::to_string(refine);
      expectTheReferenceHit(h, want, what);
      if (::testing::Test::HasFailure()) return;
    }
    std::printf("[linear march step by step] %s: %d rays checked (%d hits), %d skipped as ambiguous\n",
                sc->name.c_str(), checked, hits, skipped);
    EXPECT_GT(checked, 1500);
    EXPECT_GT(hits, 300);
  }
  // The defaults are the documented values.
  const DepthScene& sc = sphereScene();
  for (const Ray& r : snell_search_test::sceneRays(sc, 200, 34)) {
    const SnellHit a = snellLinearMarch(r.origin, r.dir, sc.depth, sc.surface());
    const SnellHit b = snellLinearMarch(r.origin, r.dir, sc.depth, sc.surface(), SNELL_LINEAR_MARCH_MAX_DISTANCE,
                                        SNELL_LINEAR_MARCH_STEPS, SNELL_LINEAR_MARCH_REFINE_STEPS);
    EXPECT_TRUE(a.uv == b.uv && a.position == b.position && a.valid == b.valid && a.fetches == b.fetches);
  }
}

namespace {

// A fronto-parallel wall at view z = -4 filling a size.x x size.y buffer, seen through the projection
// clip = (x, y, -z - 1, -z): uv = 0.5 (x, y) / -z + 0.5 with no rounding for the points below, so a
// ray can be put exactly on the screen's edge or exactly on the wall. INFINITE_REVERSED depth 0.125 is
// view distance zNear / 0.125 = 4 (the convention's v = n / d, exact in float).
struct FlatWall {
  snell::Texture2D depth;
  SnellDepthSurface surface;
};
FlatWall flatWall(int w, int h, float scale = 1.0f) {
  mat4 m(0.0f);
  m[0][0] = scale;
  m[1][1] = scale;
  m[2][2] = -scale;
  m[2][3] = -scale;
  m[3][2] = -scale;
  FlatWall fw{snell::Texture2D(snell::Image(w, h, vec4(0.125f, 0.0f, 0.0f, 0.0f))),
              snellDepthSurface(m, 0.5f, 100.0f, SNELL_DEPTH_INFINITE_REVERSED, 0.0f)};
  return fw;
}
constexpr float kWallZ = -4.0f;
const float kJustPastOne = std::nextafter(1.0f, 2.0f);

}  // namespace

// The screen is the closed square [0,1]^2: a sample exactly on an edge is read (the texel at the edge), one
// an ulp past it ends the march. Points at view z -8 with x or y = +-8 project exactly onto the edges.
TEST(IntersectMarch, LinearMarchSamplesOnTheScreensEdgeAreOnScreen) {
  const FlatWall fw = flatWall(64, 64);
  const vec3 down(0.0f, 0.0f, -1.0f);
  struct Edge {
    vec2 xy;
    vec2 uv;
  };
  const Edge edges[] = {{{-8.0f, 2.0f}, {0.0f, 0.625f}}, {{8.0f, 2.0f}, {1.0f, 0.625f}},
                        {{2.0f, -8.0f}, {0.625f, 0.0f}}, {{2.0f, 8.0f}, {0.625f, 1.0f}}};
  for (const Edge& e : edges) {
    // One step of 6 from z = -2: the sample is (x, y, -8), on the edge and behind the wall.
    const SnellHit h = snellLinearMarch(vec3(e.xy, -2.0f), down, fw.depth, fw.surface, 6.0f, 1, 0);
    ASSERT_TRUE(h.valid) << e.uv.x << " " << e.uv.y;
    EXPECT_EQ(h.fetches, 1);
    EXPECT_EQ(h.uv, e.uv);
    EXPECT_EQ(h.position, vec3(e.xy, -8.0f));
    // An ulp past the edge: off screen, the march ends without a fetch.
    const vec2 past = e.xy * kJustPastOne * kJustPastOne;  // x / 8 = 1 + 2^-22: uv = 1 + 2^-23 (or -2^-23)
    const SnellHit m = snellLinearMarch(vec3(past, -2.0f), down, fw.depth, fw.surface, 6.0f, 1, 0);
    EXPECT_FALSE(m.valid);
    EXPECT_EQ(m.fetches, 0);
    // Refinement: the one step from z = -2 to -14 crosses; its midpoint (z = -8) is on the edge and crosses
    // too, so it becomes the hit. Past the edge (an ulp, or 10 %), the midpoint is off screen: no fetch, the
    // bracket's far end stays the hit.
    const SnellHit r = snellLinearMarch(vec3(e.xy, -2.0f), down, fw.depth, fw.surface, 12.0f, 1, 1);
    ASSERT_TRUE(r.valid);
    EXPECT_EQ(r.fetches, 2);
    EXPECT_EQ(r.uv, e.uv);
    EXPECT_EQ(r.position, vec3(e.xy, -8.0f));
    for (const vec2 xy : {past, e.xy * 1.1f}) {
      const SnellHit o = snellLinearMarch(vec3(xy, -2.0f), down, fw.depth, fw.surface, 12.0f, 1, 1);
      ASSERT_TRUE(o.valid);
      EXPECT_EQ(o.fetches, 1);
      EXPECT_EQ(o.position, vec3(xy, -14.0f));
    }
  }
}

// "On or behind the surface (z <= viewZ)" crosses: a sample exactly on the wall is a hit, in the march and
// in the refinement.
TEST(IntersectMarch, LinearMarchSampleExactlyOnTheSurfaceCrosses) {
  const FlatWall fw = flatWall(64, 64);
  const vec3 o(0.3f, 0.2f, -1.0f), down(0.0f, 0.0f, -1.0f);
  const SnellHit h = snellLinearMarch(o, down, fw.depth, fw.surface, 3.0f, 1, 0);
  ASSERT_TRUE(h.valid);
  EXPECT_EQ(h.fetches, 1);
  EXPECT_EQ(h.position, vec3(0.3f, 0.2f, kWallZ));
  // One step to z = -7, its midpoint exactly on the wall: the hit moves there.
  const SnellHit r = snellLinearMarch(o, down, fw.depth, fw.surface, 6.0f, 1, 3);
  ASSERT_TRUE(r.valid);
  EXPECT_EQ(r.fetches, 4);
  EXPECT_EQ(r.position.z, kWallZ);
}

// The cases the contract answers with 0 fetches cost none; a ray parallel to the image plane (dir.z = 0) is
// not cut at the near plane; a positive maxDistance, however small, is marched.
TEST(IntersectMarch, LinearMarchEarlyMissesCostNoFetchAndTinyRaysMarch) {
  const FlatWall fw = flatWall(64, 64);
  const SnellDepthSurface& s = fw.surface;
  const vec3 o(0.3f, 0.2f, -2.0f), d(0.0f, 0.0f, -1.0f);
  EXPECT_EQ(snellLinearMarch(vec3(kNaN, 0.2f, -2.0f), d, fw.depth, s, 10.0f, 8, 2).fetches, 0);
  EXPECT_EQ(snellLinearMarch(o, vec3(0.0f), fw.depth, s, 10.0f, 8, 2).fetches, 0);
  // At the near plane, towards the camera (an ulp of dir.z, or a whole one): nothing of the ray is inside.
  for (const float dz : {1e-40f, 1e-30f, 1.0f}) {
    const SnellHit h = snellLinearMarch(vec3(0.3f, 0.2f, -0.5f), vec3(0.1f, 0.0f, dz), fw.depth, s, 0.1f, 8, 2);
    EXPECT_FALSE(h.valid) << dz;
    EXPECT_EQ(h.fetches, 0) << dz;
  }
  // Parallel to the image plane behind the wall: the first sample crosses.
  const SnellHit flat = snellLinearMarch(vec3(-0.5f, 0.25f, -6.0f), vec3(1.0f, 0.0f, 0.0f), fw.depth, s, 4.0f, 4, 0);
  ASSERT_TRUE(flat.valid);
  EXPECT_EQ(flat.fetches, 1);
  EXPECT_EQ(flat.position, vec3(0.5f, 0.25f, -6.0f));
  // A denormal maxDistance from behind the wall: the one sample is (up to rounding) the origin, behind it.
  const SnellHit tiny = snellLinearMarch(vec3(0.3f, 0.2f, -6.0f), d, fw.depth, s, 1e-40f, 1, 0);
  ASSERT_TRUE(tiny.valid);
  EXPECT_EQ(tiny.fetches, 1);
  EXPECT_EQ(tiny.position, vec3(0.3f, 0.2f, -6.0f));
  // Steps beyond the bound are the bound: 512 steps of 4 / 512 from z = -2 meet the wall at step 256.
  const SnellHit many = snellLinearMarch(o, d, fw.depth, s, 4.0f, 100000, 0);
  ASSERT_TRUE(many.valid);
  EXPECT_EQ(many.fetches, SNELL_LINEAR_MARCH_MAX_STEPS / 2);
  EXPECT_EQ(many.position.z, kWallZ);
}

// A ray that turns towards the camera by a normal float too small for the near plane's distance along it
// to be a float (tNear overflows to +inf) never reaches that plane: it is marched as if parallel to it.
// Both marches start behind the wall at z = -6, so their first step already crosses, in the origin's pixel.
TEST(IntersectMarch, ANearPlaneTooFarForAFloatDoesNotCutTheMarch) {
  const FlatWall fw = flatWall(64, 64);
  const vec3 o(-0.5f, 0.25f, -6.0f);
  for (const float dz : {0.0f, 1e-38f}) {
    const vec3 d(1.0f, 0.0f, dz);
    ASSERT_TRUE(std::isinf((-fw.surface.zNear - o.z) / dz) || dz == 0.0f);
    const SnellHit lin = snellLinearMarch(o, d, fw.depth, fw.surface, 4.0f, 4, 0);
    ASSERT_TRUE(lin.valid) << dz;
    EXPECT_EQ(lin.fetches, 1) << dz;
    EXPECT_EQ(lin.position, vec3(0.5f, 0.25f, -6.0f)) << dz;
    const SnellHit dda = snellDdaMarch(o, d, fw.depth, fw.surface, 4.0f, FLT_MAX, 1.0f, 64);
    ASSERT_TRUE(dda.valid) << dz;
    EXPECT_EQ(dda.fetches, 1) << dz;
    // On the ray within its first step, one pixel wide (12 / 64 view units at z = -6).
    EXPECT_GE(dda.position.x, o.x) << dz;
    EXPECT_LE(dda.position.x, o.x + 12.0f / 64.0f) << dz;
    EXPECT_NEAR(dda.position.y, o.y, 1e-6f) << dz;
    EXPECT_NEAR(dda.position.z, o.z, 1e-5f) << dz;
  }
}

// The near-plane cut is for rays towards the camera (dir.z > 0): one parallel to the image plane, even from a
// point before the near plane (z = -0.3, zNear 0.5) or on it, is marched over its whole length. Its four
// samples, x = 0.025 .. 0.1 at that depth, project on screen in front of the wall: a miss after 4 fetches.
TEST(IntersectMarch, ARayAlongTheImagePlaneIsNotCutByTheNearPlane) {
  const FlatWall fw = flatWall(64, 64);
  for (const float z : {-0.3f, -0.5f}) {
    const SnellHit h = snellLinearMarch(vec3(0.0f, 0.0f, z), vec3(1.0f, 0.0f, 0.0f), fw.depth, fw.surface, 0.1f, 4, 0);
    EXPECT_FALSE(h.valid) << z;
    EXPECT_EQ(h.fetches, 4) << z;
  }
}

// Rays towards the camera are marched up to the near plane: t_i = i tMax / steps with tMax cut there, the
// contract's walk replayed in double (linearReference) from origins behind the slanted plane.
TEST(IntersectMarch, LinearMarchTowardsTheCameraStopsAtTheNearPlane) {
  const DepthScene& sc = planeScene();
  const SnellDepthSurface surf = sc.surface();
  std::mt19937 rng(35);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  int checked = 0, cut = 0;
  for (int k = 0; k < 600; ++k) {
    const glm::dvec2 uv(0.2 + 0.6 * u01(rng), 0.2 + 0.6 * u01(rng));
    const double zs = sc.surfaceZ(uv);
    const glm::dvec3 o = (-zs + 0.2 + 2.0 * u01(rng)) * sc.pixelRay(uv);
    const glm::dvec3 target = (0.1 + 2.0 * u01(rng)) * sc.pixelRay(glm::dvec2(0.2 + 0.6 * u01(rng), 0.2 + 0.6 * u01(rng)));
    const vec3 of(o), df(glm::normalize(target - o));
    const float dist = k % 2 ? 25.0f : 6.0f;
    const int steps = 1 + k % 7, refine = k % 5;
    const MarchReference want = linearReference(sc, glm::dvec3(of), glm::dvec3(df), dist, steps, refine);
    if (want.ambiguous) continue;
    ++checked;
    cut += (-sc.zNear - of.z) / df.z < dist;
    expectTheReferenceHit(snellLinearMarch(of, df, sc.depth, surf, dist, steps, refine), want, "ray " + std::to_string(k));
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(checked, 400);
  EXPECT_GT(cut, 100);
}

// The DDA's first step samples the origin's own uv: exactly on an edge of [0,1]^2 it is on screen (a hit
// here, the origin being behind the wall), an ulp past it the walk ends with no fetch.
TEST(IntersectMarch, DdaStepOnTheScreensEdgeIsOnScreen) {
  const FlatWall fw = flatWall(64, 64);
  const vec3 down(0.0f, 0.0f, -1.0f);
  struct Edge {
    vec2 xy;
    vec2 uv;
  };
  const Edge edges[] = {{{-8.0f, 2.0f}, {0.0f, 0.625f}}, {{8.0f, 2.0f}, {1.0f, 0.625f}},
                        {{2.0f, -8.0f}, {0.625f, 0.0f}}, {{2.0f, 8.0f}, {0.625f, 1.0f}}};
  for (const Edge& e : edges) {
    const SnellHit h = snellDdaMarch(vec3(e.xy, -8.0f), down, fw.depth, fw.surface, 10.0f, FLT_MAX, 1.0f, 64);
    ASSERT_TRUE(h.valid) << e.uv.x << " " << e.uv.y;
    EXPECT_EQ(h.fetches, 1);
    EXPECT_EQ(h.uv, e.uv);
    EXPECT_LT(glm::length(h.position - vec3(e.xy, -8.0f)), 1e-5f);
    const vec2 past = e.xy * kJustPastOne * kJustPastOne;  // uv = 1 + 2^-23 (or -2^-23)
    const SnellHit m = snellDdaMarch(vec3(past, -8.0f), down, fw.depth, fw.surface, 10.0f, FLT_MAX, 1.0f, 64);
    EXPECT_FALSE(m.valid);
    EXPECT_EQ(m.fetches, 0);
  }
}

// A step hits when zNear >= viewZ - thickness and zFar <= viewZ, both ends included: with thickness 0 the
// wall is the single depth -4, met by a step that starts on it and by the last step of a segment that ends
// on it (its far end, s = 1, is the end point itself).
TEST(IntersectMarch, DdaDepthIntervalIncludesItsEnds) {
  const FlatWall fw = flatWall(64, 64);
  const vec3 down(0.0f, 0.0f, -1.0f);
  const SnellHit starts = snellDdaMarch(vec3(0.3f, 0.2f, kWallZ), down, fw.depth, fw.surface, 4.0f, 0.0f, 1.0f, 64);
  ASSERT_TRUE(starts.valid);
  EXPECT_EQ(starts.fetches, 1);
  EXPECT_LT(glm::length(starts.position - vec3(0.3f, 0.2f, kWallZ)), 1e-5f);
  // From z = -2 to -4: uv moves 2.4 px in x (0.575 to 0.5375 of 64), so steps s = 0, 1/2.4, 2/2.4, the last
  // owning s = 1.
  const SnellHit ends = snellDdaMarch(vec3(0.3f, 0.2f, -2.0f), down, fw.depth, fw.surface, 2.0f, 0.0f, 1.0f, 64);
  ASSERT_TRUE(ends.valid);
  EXPECT_EQ(ends.fetches, 3);
  EXPECT_LT(glm::length(ends.position - vec3(0.3f, 0.2f, kWallZ)), 1e-5f);
}

// A ray starting on a fronto-parallel wall (at the wall's depth as its read gives it) hits at the first
// step, whose depth interval [zFar, zNear] holds origin.z; the hit is a point of that step: on the ray with
// t in [0, t_B], t_B the ray parameter at the step's end s = ds / 2 (the contract's step, in double). In
// the wall's plane every point of the step has the wall's depth; tilted by a few ulps of depth over the
// step, the contract's point is the origin up to that much depth. In float the step's start is recomputed
// (origin.z k0 / k0: origin.z or the next float, two floats off when origin k0 is a denormal, under a
// projection whose clip w nears 1 / FLT_MIN) and its end's depth rounds an ulp or two to either side, so the
// ratio that places the hit in the step can fall outside [0, 1]: the hit must stay in the step regardless.
// 4096 walls (one a texel), 28 directions each (4 axes, dir.z 0, +-1e-6, +-3e-6, +-1e-5), through the
// square projection (walls at 3.8 to 8, zNear 0.3, so that the distances are not all quotients of a power
// of two) and through it scaled by 1.7 * 2^126 (walls at 0.3 to 0.55: clip w 0.5 to 0.94 * 2^126, inside
// the normal range of 1 / w the contract accepts).
TEST(IntersectMarch, DdaHitAtTheFirstStepIsAPointOfThatStep) {
  constexpr int kSize = 64;
  const auto walk = [](float scale, float zNear, float nearest, float farthest, float stride, float maxDistance) {
    Image im(kSize, kSize, vec4(0.0f));
    for (int j = 0; j < kSize; ++j)
      for (int i = 0; i < kSize; ++i)
        im.at(i, j).x = zNear / (nearest + (farthest - nearest) * float(i + kSize * j) / float(kSize * kSize));
    const Texture2D depth(std::move(im));
    const FlatWall fw = flatWall(kSize, kSize, scale);
    const SnellDepthSurface s =
        snellDepthSurface(fw.surface.clipFromView, zNear, 100.0f, SNELL_DEPTH_INFINITE_REVERSED, 0.0f);
    std::vector<vec3> dirs;
    for (const float dz : {0.0f, 1e-6f, -1e-6f, 3e-6f, -3e-6f, 1e-5f, -1e-5f})
      for (const vec2 xy : {vec2(1.0f, 0.0f), vec2(-1.0f, 0.0f), vec2(0.0f, 1.0f), vec2(0.0f, -1.0f)})
        dirs.push_back(vec3(xy, dz));
    int checked = 0;
    for (int j = 0; j < kSize; ++j)
      for (int i = 0; i < kSize; ++i) {
        const vec2 centre((float(i) + 0.5f) / kSize, (float(j) + 0.5f) / kSize);
        const SnellSurfaceSample wall = snellSampleSurface(depth, centre, s);
        EXPECT_TRUE(wall.valid);
        const float z = wall.viewZ;
        const vec3 o((2.0f * centre.x - 1.0f) * -z, (2.0f * centre.y - 1.0f) * -z, z);  // on the centre's pixel ray
        for (const vec3& d : dirs) {
          const SnellHit h = snellDdaMarch(o, d, depth, s, maxDistance, FLT_MAX, stride, 64);
          const auto what = [&] {  // streamed on failure only
            return "scale " + std::to_string(scale) + " texel " + std::to_string(i) + "," + std::to_string(j) +
                   " dir " + std::to_string(d.x) + "," + std::to_string(d.y) + "," + std::to_string(d.z);
          };
          EXPECT_TRUE(h.valid) << what();
          EXPECT_EQ(h.fetches, 1) << what();
          // The contract's first step in double: the segment's ends (the near plane is far beyond them),
          // uv = 0.5 (x, y) / -z + 0.5 (the scale cancels), ds = stride / the major axis's length in pixels,
          // the view point at s = ds / 2 with k = 1 / -z linear in s.
          const glm::dvec3 od(o), dd = glm::normalize(glm::dvec3(d)), e = od + double(maxDistance) * dd;
          const glm::dvec2 duv = 0.5 * glm::dvec2(e) / -e.z - 0.5 * glm::dvec2(od) / -od.z;
          const double major = std::max(std::fabs(duv.x), std::fabs(duv.y)) * kSize;
          const double sB = 0.5 * (major > double(stride) ? double(stride) / major : 1.0);
          const double k0 = 1.0 / -od.z, k1 = 1.0 / -e.z;
          const glm::dvec3 pB = (od * k0 * (1.0 - sB) + e * k1 * sB) / (k0 * (1.0 - sB) + k1 * sB);
          const double tB = glm::dot(pB - od, dd);
          const glm::dvec3 p(h.position);
          const double t = glm::dot(p - od, dd);
          EXPECT_GE(t, -1e-4 * tB) << what();
          EXPECT_LE(t, tB * (1.0 + 1e-4)) << what();
          EXPECT_LT(glm::length(p - (od + t * dd)), 1e-6 * glm::length(od)) << what();  // on the ray
          if (::testing::Test::HasFailure()) return checked;
          ++checked;
        }
      }
    return checked;
  };
  EXPECT_EQ(walk(1.0f, 0.3f, 3.8f, 8.0f, 8.0f, 4.0f), 28 * kSize * kSize);
  EXPECT_EQ(walk(1.7f * std::ldexp(1.0f, 126), 0.2f, 0.3f, 0.55f, 4.0f, 0.2f), 28 * kSize * kSize);
}

// A segment within one pixel (a ray along the line of sight) is two steps, s in [0, 1/2] and [1/2, 1]:
// from z = -2 to -40, 1/z is linear in s, and the wall (1/z = -1/4) lies at s = 0.25 / 0.475 = 0.526, in
// the second half.
TEST(IntersectMarch, DdaSegmentWithinOnePixelTakesTwoHalves) {
  const FlatWall fw = flatWall(64, 64);
  const vec3 o(0.5f, 0.25f, -2.0f);
  const float dist = 19.0f * glm::length(o);  // end = 20 o
  const SnellHit h = snellDdaMarch(o, o, fw.depth, fw.surface, dist, FLT_MAX, 1.0f, 64);
  ASSERT_TRUE(h.valid);
  EXPECT_EQ(h.fetches, 2);
  EXPECT_LT(glm::length(h.position - 2.0f * o), 1e-4f);
}

// The zero-fetch cases of the contract cost no fetch, and the ends' 1/w is accepted over the whole normal
// range: the same wall seen through the projection scaled by 2^-126 or 2^123 (the same uv, clip w scaled)
// with an end at w exactly FLT_MIN or 1 / FLT_MIN, and rejected just above 1 / FLT_MIN.
TEST(IntersectMarch, DdaEarlyMissesAndTheRangeOfW) {
  const FlatWall fw = flatWall(64, 64);
  const vec3 down(0.0f, 0.0f, -1.0f), up(0.0f, 0.0f, 1.0f);
  EXPECT_EQ(snellDdaMarch(vec3(kNaN, 0.2f, -2.0f), down, fw.depth, fw.surface, 10.0f, FLT_MAX, 1.0f, 64).fetches, 0);
  // The level has no texels.
  SnellDepthSurface lod1 = fw.surface;
  lod1.lod = 1;
  const SnellHit none = snellDdaMarch(vec3(0.3f, 0.2f, -2.0f), down, fw.depth, lod1, 10.0f, FLT_MAX, 1.0f, 64);
  EXPECT_FALSE(none.valid);
  EXPECT_EQ(none.fetches, 0);
  // An origin whose uv overflows (x / w = 3e38 / 0.5): off screen at the first step.
  const SnellHit far = snellDdaMarch(vec3(1.5e38f, 0.0f, -0.5f), down, fw.depth, fw.surface, 10.0f, FLT_MAX, 1.0f, 64);
  EXPECT_FALSE(far.valid);
  EXPECT_EQ(far.fetches, 0);
  // A denormal maxDistance from behind the wall: the segment is the origin, which hits.
  const SnellHit tiny = snellDdaMarch(vec3(0.3f, 0.2f, -6.0f), down, fw.depth, fw.surface, 1e-40f, FLT_MAX, 1.0f, 64);
  ASSERT_TRUE(tiny.valid);
  EXPECT_EQ(tiny.fetches, 1);
  EXPECT_LT(glm::length(tiny.position - vec3(0.3f, 0.2f, -6.0f)), 1e-5f);

  const FlatWall small = flatWall(64, 64, std::ldexp(1.0f, -126));
  // Origin at w = FLT_MIN (z = -1), crossing the wall further on.
  const SnellHit a = snellDdaMarch(vec3(0.25f, 0.125f, -1.0f), down, small.depth, small.surface, 10.0f, FLT_MAX, 1.0f, 64);
  ASSERT_TRUE(a.valid);
  EXPECT_LT(glm::length(a.position - vec3(0.25f, 0.125f, kWallZ)), 1e-5f);
  // End at w = FLT_MIN; the origin is behind the wall, so the first step hits.
  const SnellHit b = snellDdaMarch(vec3(0.25f, 0.125f, -6.0f), up, small.depth, small.surface, 5.0f, FLT_MAX, 1.0f, 64);
  ASSERT_TRUE(b.valid);
  EXPECT_EQ(b.fetches, 1);
  const FlatWall large = flatWall(64, 64, std::ldexp(1.0f, 123));
  // Origin, then end, at w = 8 2^123 = 1 / FLT_MIN, the other end at z = -6; origins behind the wall.
  const SnellHit c = snellDdaMarch(vec3(0.25f, 0.125f, -8.0f), up, large.depth, large.surface, 2.0f, FLT_MAX, 1.0f, 64);
  ASSERT_TRUE(c.valid);
  EXPECT_EQ(c.fetches, 1);
  const SnellHit d = snellDdaMarch(vec3(0.25f, 0.125f, -6.0f), down, large.depth, large.surface, 2.0f, FLT_MAX, 1.0f, 64);
  ASSERT_TRUE(d.valid);
  EXPECT_EQ(d.fetches, 1);
  // w = 8.5 2^123 at the origin, then at the end: 1/w is denormal.
  const SnellHit e = snellDdaMarch(vec3(0.25f, 0.125f, -8.5f), up, large.depth, large.surface, 2.0f, FLT_MAX, 1.0f, 64);
  EXPECT_FALSE(e.valid);
  EXPECT_EQ(e.fetches, 0);
  const SnellHit f = snellDdaMarch(vec3(0.25f, 0.125f, -6.0f), down, large.depth, large.surface, 2.5f, FLT_MAX, 1.0f, 64);
  EXPECT_FALSE(f.valid);
  EXPECT_EQ(f.fetches, 0);
}

// A level one texel wide or high has texels: the DDA marches it.
TEST(IntersectMarch, DdaReadsALevelOneTexelWide) {
  for (const glm::ivec2 size : {glm::ivec2(1, 64), glm::ivec2(64, 1)}) {
    const FlatWall fw = flatWall(size.x, size.y);
    const SnellHit h = snellDdaMarch(vec3(0.3f, 0.2f, -2.0f), vec3(0.0f, 0.0f, -1.0f), fw.depth, fw.surface, 4.0f,
                                     FLT_MAX, 1.0f, 64);
    ASSERT_TRUE(h.valid) << size.x;
    EXPECT_LT(glm::length(h.position - vec3(0.3f, 0.2f, kWallZ)), 1e-5f);
  }
}

// From the near plane itself towards the camera (an ulp of dir.z, or a whole one) no part of the ray is in
// the frustum: a miss with no fetch.
TEST(IntersectMarch, DdaFromTheNearPlaneTowardsTheCameraCostsNoFetch) {
  const FlatWall fw = flatWall(64, 64);
  ASSERT_EQ(fw.surface.zNear, 0.5f);
  for (const float dz : {1e-40f, 1e-30f, 1.0f}) {
    const SnellHit h = snellDdaMarch(vec3(0.3f, 0.2f, -0.5f), vec3(0.1f, 0.0f, dz), fw.depth, fw.surface, 0.1f,
                                     FLT_MAX, 1.0f, 8);
    EXPECT_FALSE(h.valid) << dz;
    EXPECT_EQ(h.fetches, 0) << dz;
  }
  // Along the image plane the same origin is marched: 6.4 pixels in front of the wall (uv.x 0.8 to 0.9), a
  // miss after 7 steps (ds = 1 / 6.4: step 6 owns s = 1).
  const SnellHit along = snellDdaMarch(vec3(0.3f, 0.2f, -0.5f), vec3(0.1f, 0.0f, 0.0f), fw.depth, fw.surface, 0.1f,
                                       FLT_MAX, 1.0f, 8);
  EXPECT_FALSE(along.valid);
  EXPECT_EQ(along.fetches, 7);
}

// Rays towards the camera are cut at the near plane: the contract's walk replayed (ddaReference) from
// origins behind the slanted plane, with thicknesses that let the first steps pass behind it.
TEST(IntersectMarch, DdaTowardsTheCameraStopsAtTheNearPlane) {
  const DepthScene& sc = planeScene();
  const SnellDepthSurface surf = sc.surface();
  std::mt19937 rng(36);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  int checked = 0, cut = 0, hits = 0;
  for (int k = 0; k < 600; ++k) {
    const glm::dvec2 uv(0.2 + 0.6 * u01(rng), 0.2 + 0.6 * u01(rng));
    const double zs = sc.surfaceZ(uv);
    const glm::dvec3 o = (-zs + 0.2 + 2.0 * u01(rng)) * sc.pixelRay(uv);
    const glm::dvec3 target = (0.1 + 2.0 * u01(rng)) * sc.pixelRay(glm::dvec2(0.2 + 0.6 * u01(rng), 0.2 + 0.6 * u01(rng)));
    const vec3 of(o), df(glm::normalize(target - o));
    const float dist = k % 2 ? 25.0f : 6.0f, thick = k % 3 ? 0.3f : 1.0f, stride = 1.0f + float(k % 3);
    const MarchReference want = ddaReference(sc, glm::dvec3(of), glm::dvec3(df), dist, thick, stride, 1024);
    if (want.ambiguous) continue;
    ++checked;
    hits += want.valid;
    cut += (-sc.zNear - of.z) / df.z < dist;
    expectTheReferenceHit(snellDdaMarch(of, df, sc.depth, surf, dist, thick, stride, 1024), want, "ray " + std::to_string(k));
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(checked, 400);
  EXPECT_GT(cut, 100);
  EXPECT_GT(hits, 100);
}
