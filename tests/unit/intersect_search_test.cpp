// glsl/snell/intersect/{search_segment, conservative_binary_search, binary_search,
// linear_binary_search}.glsl against independent geometry: the analytic depth
// scenes (tests/support/depth_scenes.hpp), texels read back by plain index math,
// and a brute-force double-precision walk of the S-E segment.
#include <gtest/gtest.h>

#include <snell/intersect.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "support/search_rays.hpp"
#include "support/depth_scenes.hpp"

namespace {

using namespace snell;
using snell_search_test::depthRange;
using snell_search_test::finite;
using snell_search_test::Ray;
using snell_search_test::texelValid;
using snell_search_test::texelViewZ;
using snell_test::DepthScene;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

const DepthScene& silhouetteScene() {
  static const DepthScene sc = snell_test::silhouette(256, 256);
  return sc;
}
const DepthScene& sphereScene() {
  static const DepthScene sc = snell_test::sphereBack(256, 256);
  return sc;
}

// beta of a point on S-E (eq. 5), from its z.
double betaOf(const SnellTexRay& r, double z) { return (z - double(r.s.z)) / (double(r.e.z) - double(r.s.z)); }

TEST(IntersectSearch, SegmentStartsAtZNearestOrTheOriginAndRejectsBadInput) {
  const DepthScene& sc = sphereScene();
  const mat4 m = sc.clipFromView;
  SnellTexRay r = snellSearchSegment(vec3(0.1f, 0.0f, -4.0f), vec3(0.0f, 0.1f, -1.0f), -5.0f, -8.0f, m);
  ASSERT_TRUE(r.valid);
  EXPECT_FLOAT_EQ(r.s.z, -5.0f);
  EXPECT_FLOAT_EQ(r.s.y, 0.1f);
  EXPECT_FLOAT_EQ(r.e.z, -8.0f);
  EXPECT_NEAR(r.e.y, 0.4f, 1e-6f);
  // Origin deeper than zNearest: the segment starts at the origin.
  r = snellSearchSegment(vec3(0.1f, 0.0f, -6.0f), vec3(0.0f, 0.1f, -1.0f), -5.0f, -8.0f, m);
  ASSERT_TRUE(r.valid);
  EXPECT_EQ(r.s, vec3(0.1f, 0.0f, -6.0f));
  const vec3 o(0.0f, 0.0f, -4.0f), d(0.0f, 0.0f, -1.0f);
  EXPECT_FALSE(snellSearchSegment(o, vec3(0.0f, 0.1f, 1.0f), -5.0f, -8.0f, m).valid);   // towards the camera
  EXPECT_FALSE(snellSearchSegment(o, vec3(1.0f, 0.0f, 0.0f), -5.0f, -8.0f, m).valid);   // parallel
  EXPECT_FALSE(snellSearchSegment(o, d, -5.0f, -5.0f, m).valid);                        // Zmin == Zmax
  EXPECT_FALSE(snellSearchSegment(o, d, -8.0f, -5.0f, m).valid);                        // swapped
  EXPECT_FALSE(snellSearchSegment(vec3(0.0f, 0.0f, -9.0f), d, -5.0f, -8.0f, m).valid);  // beyond zFarthest
  EXPECT_FALSE(snellSearchSegment(o, d, -5.0f, 1.0f, m).valid);                         // far plane behind the eye
  // A zNearest plane at or behind the eye (a bounding box around the camera): from the origin.
  r = snellSearchSegment(o, d, 1.0f, -8.0f, m);
  ASSERT_TRUE(r.valid);
  EXPECT_EQ(r.s, o);
  EXPECT_FALSE(snellSearchSegment(vec3(kNaN, 0.0f, -4.0f), d, -5.0f, -8.0f, m).valid);
  EXPECT_FALSE(snellSearchSegment(o, vec3(0.0f, kInf, -1.0f), -5.0f, -8.0f, m).valid);
  EXPECT_FALSE(snellSearchSegment(o, d, kNaN, -8.0f, m).valid);
}

// The point of CBS (Oliveira & Brauwers 2007, sec. 3.3): it never returns a
// point whose texel is empty. 120,000 random rays against an annulus seen at an
// angle (empty texels around and inside), checked by reading the texel the
// returned uv maps to with plain index math.
TEST(IntersectSearch, ConservativeBinarySearchNeverReturnsAnInvalidTexel) {
  const DepthScene& sc = silhouetteScene();
  const SnellDepthSurface surf = sc.surface();
  const auto range = depthRange(sc);
  const std::vector<Ray> rays = snell_search_test::sceneRays(sc, 120000, 7);
  int valid = 0, bad = 0, nonFinite = 0;
  for (std::size_t k = 0; k < rays.size(); ++k) {
    const int steps = 1 + static_cast<int>(k % 8);
    const SnellHit h = snellConservativeBinarySearch(rays[k].origin, rays[k].dir, sc.depth, surf, range.first,
                                                     range.second, steps);
    if (!finite(h)) ++nonFinite;
    if (!h.valid) continue;
    ++valid;
    if (!texelValid(sc, h.uv)) ++bad;
  }
  std::printf("[cbs silhouette] rays=%zu valid=%d invalid-texel=%d\n", rays.size(), valid, bad);
  EXPECT_EQ(bad, 0);
  EXPECT_EQ(nonFinite, 0);
  EXPECT_GT(valid, 20000);  // the test exercises many real hits
}

// The failure the paper describes (Figure 6): a plain binary search with a
// finite number of steps ends on an empty texel for some rays; so does the
// relief-mapping linear+binary search. Counted by reading the texel ourselves.
TEST(IntersectSearch, PlainBinarySearchLandsOnInvalidTexelsWhereCbsDoesNot) {
  const DepthScene& sc = silhouetteScene();
  const SnellDepthSurface surf = sc.surface();
  const auto range = depthRange(sc);
  const std::vector<Ray> rays = snell_search_test::sceneRays(sc, 100000, 8);
  int binaryBad = 0, linearBad = 0, cbsBad = 0, flagAgrees = 0, binaryRan = 0, cbsValid = 0, binaryBadWhereCbsOk = 0;
  for (const Ray& ray : rays) {
    const SnellHit b = snellBinarySearch(ray.origin, ray.dir, sc.depth, surf, range.first, range.second, 5);
    const SnellHit l = snellLinearBinarySearch(ray.origin, ray.dir, sc.depth, surf, range.first, range.second, 4, 3);
    const SnellHit c =
        snellConservativeBinarySearch(ray.origin, ray.dir, sc.depth, surf, range.first, range.second, 5);
    if (b.fetches == 0) continue;  // invalid segment
    ++binaryRan;
    const bool bValid = texelValid(sc, b.uv);
    if (!bValid) ++binaryBad;
    if (bValid == b.valid) ++flagAgrees;
    if (l.position.z != 0.0f && !texelValid(sc, l.uv)) ++linearBad;  // z = 0: no crossing found
    if (c.valid && !texelValid(sc, c.uv)) ++cbsBad;
    if (c.valid) {
      ++cbsValid;
      if (!bValid) ++binaryBadWhereCbsOk;
    }
  }
  std::printf(
      "[binary silhouette] rays=%d binary-invalid=%d (%.2f%%) linear+binary-invalid=%d cbs-invalid=%d; of the %d rays "
      "CBS hits, binary ends on an empty texel for %d (%.2f%%)\n",
      binaryRan, binaryBad, 100.0 * binaryBad / binaryRan, linearBad, cbsBad, cbsValid, binaryBadWhereCbsOk,
      100.0 * binaryBadWhereCbsOk / std::max(cbsValid, 1));
  EXPECT_GT(binaryBad, 100);
  EXPECT_GT(binaryBadWhereCbsOk, 0);
  EXPECT_GT(linearBad, 0);
  EXPECT_EQ(cbsBad, 0);
  EXPECT_EQ(flagAgrees, binaryRan);  // binary search's valid flag tells the truth
}

// Brute force, in double, along S-E: beta* = the first beta whose point is not
// strictly in front of the stored surface (empty texels count as not in front,
// as in Algorithm 2); returns NaN unless the predicate changes exactly once on
// the grid (the case the error bound is about).
double bruteForceBeta(const DepthScene& sc, const SnellTexRay& r, int samples) {
  const glm::dvec3 s(r.s), e(r.e);
  auto inFront = [&](double beta) {
    const glm::dvec3 p = s + beta * (e - s);
    const glm::dvec2 uv = sc.project(p);
    if (!(uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0)) return false;
    const int i = std::min(static_cast<int>(std::floor(uv.x * sc.width)), sc.width - 1);
    const int j = std::min(static_cast<int>(std::floor(uv.y * sc.height)), sc.height - 1);
    const double z = texelViewZ(sc, i, j);
    return !std::isnan(z) && p.z > z;
  };
  if (!inFront(0.0)) return std::numeric_limits<double>::quiet_NaN();
  double first = std::numeric_limits<double>::quiet_NaN();
  for (int k = 1; k <= samples; ++k) {
    const double beta = double(k) / samples;
    const bool f = inFront(beta);
    if (std::isnan(first)) {
      if (!f) first = beta;
    } else if (f) {
      return std::numeric_limits<double>::quiet_NaN();  // re-enters: more than one crossing
    }
  }
  return first;
}

// Oliveira & Brauwers 2007, sec. 3.3: after c CBS steps the error in beta is
// 0.5^c - 0.5^k <= 0.5^c when the true hit needs k > c steps; and the result
// never lies past the hit. True beta from a brute-force walk of S-E (20,000
// samples, so the grid adds 5e-5) on refracted rays through the sphere.
TEST(IntersectSearch, ConservativeBinarySearchBetaErrorWithinHalfToTheC) {
  const DepthScene& sc = sphereScene();
  const SnellDepthSurface surf = sc.surface();
  const auto range = depthRange(sc);
  const std::vector<Ray> rays = snell_search_test::sphereRefractedRays(sc, 3000, 9);
  const int kSamples = 20000;
  const double tol = 2.0 / kSamples + 1e-5;
  struct Item {
    Ray ray;
    SnellTexRay r;
    double truth;
  };
  std::vector<Item> items;
  for (const Ray& ray : rays) {
    const SnellTexRay r = snellSearchSegment(ray.origin, ray.dir, range.first, range.second, sc.clipFromView);
    if (!r.valid) continue;
    const double truth = bruteForceBeta(sc, r, kSamples);
    if (!std::isnan(truth)) items.push_back({ray, r, truth});
  }
  for (int c = 1; c <= 12; ++c) {
    int checked = 0, over = 0, past = 0, aboveHalf = 0;
    double worst = 0.0;
    for (const Item& it : items) {
      if (it.truth <= std::ldexp(1.0, -c)) continue;  // the true hit needs more than c steps
      const SnellHit h = snellConservativeBinarySearch(it.ray.origin, it.ray.dir, sc.depth, surf, range.first,
                                                       range.second, c);
      ASSERT_TRUE(h.valid);
      ++checked;
      const double err = it.truth - betaOf(it.r, h.position.z);
      worst = std::max(worst, err);
      if (err > std::ldexp(1.0, -c) + tol) ++over;
      if (err < -tol) ++past;
      if (err > std::ldexp(1.0, -c - 1)) ++aboveHalf;
      EXPECT_EQ(h.fetches, c);
    }
    std::printf("[cbs beta error] c=%d rays=%d worst=%.6f bound=%.6f (+grid %.6f)\n", c, checked, worst,
                std::ldexp(1.0, -c), tol);
    EXPECT_GT(checked, 1000) << "c = " << c;
    EXPECT_EQ(over, 0) << "c = " << c;
    EXPECT_EQ(past, 0) << "c = " << c;
    EXPECT_GT(aboveHalf, 0) << "c = " << c << ": the bound is not tight, is the search really binary?";
  }
}

// Plain binary search: |beta - beta*| <= 0.5^c on the same rays; linear+binary:
// <= 0.5^b / L.
TEST(IntersectSearch, BinaryAndLinearBinarySearchErrorBounds) {
  const DepthScene& sc = sphereScene();
  const SnellDepthSurface surf = sc.surface();
  const auto range = depthRange(sc);
  const std::vector<Ray> rays = snell_search_test::sphereRefractedRays(sc, 2000, 10);
  const double tol = 2.0 / 20000 + 1e-5;
  int checked = 0, binaryOver = 0, linearOver = 0;
  for (const Ray& ray : rays) {
    const SnellTexRay r = snellSearchSegment(ray.origin, ray.dir, range.first, range.second, sc.clipFromView);
    if (!r.valid) continue;
    const double truth = bruteForceBeta(sc, r, 20000);
    if (std::isnan(truth)) continue;
    ++checked;
    const SnellHit b = snellBinarySearch(ray.origin, ray.dir, sc.depth, surf, range.first, range.second, 6);
    if (std::fabs(betaOf(r, b.position.z) - truth) > std::ldexp(1.0, -6) + tol) ++binaryOver;
    const SnellHit l = snellLinearBinarySearch(ray.origin, ray.dir, sc.depth, surf, range.first, range.second, 8, 4);
    if (l.position.z == 0.0f) {
      ++linearOver;  // found no crossing although there is one
      continue;
    }
    if (std::fabs(betaOf(r, l.position.z) - truth) > std::ldexp(1.0, -4) / 8.0 + tol) ++linearOver;
  }
  EXPECT_GT(checked, 1000);
  EXPECT_EQ(binaryOver, 0);
  EXPECT_EQ(linearOver, 0);
}

// Bad input: finite numbers and valid = false everywhere.
TEST(IntersectSearch, BadInputGivesFiniteMisses) {
  const DepthScene& sc = sphereScene();
  const SnellDepthSurface surf = sc.surface();
  const auto range = depthRange(sc);
  const float zn = range.first, zf = range.second;
  const vec3 o(0.3f, -0.2f, -4.0f), d(0.0f, 0.0f, -1.0f);
  // Sanity: this ray hits.
  ASSERT_TRUE(snellConservativeBinarySearch(o, d, sc.depth, surf, zn, zf).valid);
  auto expectMiss = [](const SnellHit& h, const char* what) {
    EXPECT_FALSE(h.valid) << what;
    EXPECT_TRUE(finite(h)) << what;
  };
  // Empty buffer: every texel empty.
  snell::Texture2D empty(snell::Image(64, 64, vec4(surf.emptyDepth, 0.0f, 0.0f, 0.0f)));
  struct Case {
    vec3 o, d;
    float zn, zf;
    const snell::Texture2D* tex;
    const char* what;
  };
  const Case cases[] = {
      {o, vec3(0.0f, 0.1f, 1.0f), zn, zf, &sc.depth, "towards the camera"},
      {o, vec3(1.0f, 0.0f, 0.0f), zn, zf, &sc.depth, "parallel to the image plane"},
      {o, d, zn, zn, &sc.depth, "Zmin == Zmax"},
      {o, d, zf, zn, &sc.depth, "Zmin/Zmax swapped"},
      {vec3(kNaN, 0.0f, -4.0f), d, zn, zf, &sc.depth, "NaN origin"},
      {o, vec3(0.0f, kNaN, -1.0f), zn, zf, &sc.depth, "NaN dir"},
      {o, d, kNaN, zf, &sc.depth, "NaN zNearest"},
      {o, vec3(0.0f, 0.0f, 0.0f), zn, zf, &sc.depth, "zero dir"},
      {o, d, zn, zf, &empty, "empty buffer"},
      {vec3(40.0f, 0.0f, -4.0f), vec3(1.0f, 0.0f, -0.1f), zn, zf, &sc.depth, "off screen, leaving it"},
  };
  for (const Case& c : cases) {
    expectMiss(snellConservativeBinarySearch(c.o, c.d, *c.tex, surf, c.zn, c.zf), c.what);
    expectMiss(snellBinarySearch(c.o, c.d, *c.tex, surf, c.zn, c.zf), c.what);
    expectMiss(snellLinearBinarySearch(c.o, c.d, *c.tex, surf, c.zn, c.zf), c.what);
    EXPECT_TRUE(finite(snellBinarySearch(c.o, c.d, *c.tex, surf, c.zn, c.zf, 7))) << c.what;
  }
  // Step counts outside the range are clamped, never loop out of bounds.
  EXPECT_EQ(snellConservativeBinarySearch(o, d, sc.depth, surf, zn, zf, 1000).fetches, SNELL_CBS_MAX_STEPS);
  EXPECT_EQ(snellConservativeBinarySearch(o, d, sc.depth, surf, zn, zf, -3).fetches, 1);  // tests S only
  EXPECT_EQ(snellBinarySearch(o, d, sc.depth, surf, zn, zf, 0).fetches, 1);
  EXPECT_EQ(snellConservativeBinarySearch(o, d, sc.depth, surf, zn, zf).fetches, SNELL_CBS_STEPS);
}

// Where nothing advances, CBS tests S: valid exactly when S's texel is valid.
TEST(IntersectSearch, ConservativeBinarySearchWithoutAdvanceReturnsAValidStart) {
  const DepthScene& sc = sphereScene();
  const SnellDepthSurface surf = sc.surface();
  // Origin 1e-3 in front of the stored surface at a texel centre, looking along
  // the line of sight, searching 1 unit deep: every tested point (beta >= 1/8)
  // lies behind the surface, so nothing advances and S (= the origin) is tested.
  const glm::dvec2 uv((140 + 0.5) / 256.0, (120 + 0.5) / 256.0);
  const double zs = sc.surfaceZ(uv);
  ASSERT_FALSE(std::isnan(zs));
  const glm::dvec3 q = sc.pixelRay(uv);
  const vec3 o = vec3(q * (-zs - 1e-3));
  const vec3 d = vec3(glm::normalize(q));
  const SnellHit h = snellConservativeBinarySearch(o, d, sc.depth, surf, o.z, o.z - 1.0f, 3);
  ASSERT_TRUE(h.valid);
  EXPECT_EQ(h.fetches, 4);
  EXPECT_EQ(h.position, o);
  EXPECT_TRUE(texelValid(sc, h.uv));
  // The same from off screen: S's texel is invalid, so no hit.
  const vec3 off(o.x + 30.0f, o.y, o.z);
  const SnellHit m = snellConservativeBinarySearch(off, d, sc.depth, surf, o.z, o.z - 1.0f, 3);
  EXPECT_FALSE(m.valid);
  EXPECT_EQ(m.fetches, 4);
}

}  // namespace

namespace {

// The contract's bisection replayed in double, with texels read by plain index math: for each step the
// midpoint beta, the point S + beta (E - S), its uv (the scene's own projection) and the rule (a valid texel
// with the point strictly in front moves lo, anything else hi). `ambiguous` is set where float and double
// could decide differently (a point within 1e-4 texel of a texel edge, or within 2e-6 |z| of the surface: float's depth reconstruction) and
// that could show: at a step whose move (half the bracket) exceeds `tolerance` in position, or at the last
// step (its texel is the result's). The caller skips those rays.
struct Bisection {
  glm::dvec3 position{0.0};
  glm::dvec2 uv{0.0};
  bool valid = false;
  int fetches = 0;
  bool ambiguous = false;
};
Bisection referenceBisection(const DepthScene& sc, const SnellTexRay& r, double lo, double hi, int steps,
                             double tolerance) {
  Bisection b;
  const glm::dvec3 s(r.s), e(r.e);
  lo = std::clamp(lo, 0.0, 1.0);
  hi = std::clamp(hi, 0.0, 1.0);
  const int n = std::clamp(steps, 0, SNELL_BINARY_SEARCH_MAX_STEPS);
  for (int c = 0; c < n; ++c) {
    const double mid = 0.5 * (lo + hi);
    const bool shows = c + 1 == n || 0.5 * (hi - lo) * glm::length(e - s) > tolerance;
    const glm::dvec3 p = s + mid * (e - s);
    const glm::dvec2 uv = sc.project(p);
    const glm::dvec2 t(uv.x * sc.width, uv.y * sc.height);
    const bool onScreen = uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0;
    double z = std::numeric_limits<double>::quiet_NaN();
    if (onScreen) {
      z = texelViewZ(sc, std::min(int(std::floor(t.x)), sc.width - 1), std::min(int(std::floor(t.y)), sc.height - 1));
      if (std::fabs(t.x - std::round(t.x)) < 1e-4 || std::fabs(t.y - std::round(t.y)) < 1e-4) b.ambiguous |= shows;
      if (!std::isnan(z) && std::fabs(p.z - z) < 2e-6 * std::fabs(z)) b.ambiguous |= shows;
    } else if (std::max(std::fabs(uv.x - std::clamp(uv.x, 0.0, 1.0)), std::fabs(uv.y - std::clamp(uv.y, 0.0, 1.0))) < 1e-6) {
      b.ambiguous |= shows;
    }
    b.position = p;
    b.uv = uv;
    b.valid = onScreen && !std::isnan(z);
    ++b.fetches;
    if (b.valid && p.z > z) lo = mid;
    else hi = mid;
  }
  return b;
}

}  // namespace

// snellBinarySearch and snellBisectTexRay against the contract replayed step by step: the last point tested
// (uv, position on S-E), whether its texel is valid, and one fetch per step, for step counts 0..30 (the
// count is clamped to SNELL_BINARY_SEARCH_MAX_STEPS) on the silhouette (empty texels) and the sphere.
TEST(IntersectSearch, BinarySearchIsTheContractsBisectionStepByStep) {
  for (const DepthScene* sc : {&silhouetteScene(), &sphereScene()}) {
    const SnellDepthSurface surf = sc->surface();
    const auto range = depthRange(*sc);
    const std::vector<Ray> rays = snell_search_test::sceneRays(*sc, 3000, 21);
    int checked = 0, skipped = 0, invalidEnds = 0;
    for (std::size_t k = 0; k < rays.size(); ++k) {
      const Ray& ray = rays[k];
      const int steps = static_cast<int>(k % 31);
      const SnellTexRay r = snellSearchSegment(ray.origin, ray.dir, range.first, range.second, sc->clipFromView);
      const SnellHit h = snellBinarySearch(ray.origin, ray.dir, sc->depth, surf, range.first, range.second, steps);
      if (!r.valid) {  // an invalid segment: a miss without a fetch
        EXPECT_FALSE(h.valid);
        EXPECT_EQ(h.fetches, 0);
        continue;
      }
      Bisection want;
      if (steps == 0) {  // S itself, one fetch
        want.position = glm::dvec3(r.s);
        want.uv = glm::dvec2(r.ts);
        want.valid = texelValid(*sc, r.ts);
        want.fetches = 1;
      } else {
        want = referenceBisection(*sc, r, 0.0, 1.0, steps, 1e-5);
      }
      if (want.ambiguous) {
        ++skipped;
        continue;
      }
      ++checked;
      if (!want.valid) ++invalidEnds;
      EXPECT_EQ(h.fetches, want.fetches) << "ray " << k << ", steps " << steps;
      EXPECT_EQ(h.valid, want.valid) << "ray " << k << ", steps " << steps;
      const double scale = std::max(1.0, glm::length(glm::dvec3(r.e)));
      EXPECT_NEAR(h.position.x, want.position.x, 2e-5 * scale) << "ray " << k << ", steps " << steps;
      EXPECT_NEAR(h.position.y, want.position.y, 2e-5 * scale) << "ray " << k << ", steps " << steps;
      EXPECT_NEAR(h.position.z, want.position.z, 2e-5 * scale) << "ray " << k << ", steps " << steps;
      EXPECT_NEAR(h.uv.x, want.uv.x, 2e-5) << "ray " << k << ", steps " << steps;
      EXPECT_NEAR(h.uv.y, want.uv.y, 2e-5) << "ray " << k << ", steps " << steps;
      if (::testing::Test::HasFailure()) return;
    }
    std::printf("[binary step by step] %s: %d rays checked, %d skipped as ambiguous, %d ending on an empty texel\n",
                sc->name.c_str(), checked, skipped, invalidEnds);
    // Long searches converge on the sphere's surface, where the last steps are within float's reach of it:
    // measured 312 of 3000 skipped on the silhouette, 692 on the sphere.
    EXPECT_GT(checked, 2000);
    EXPECT_LT(skipped, checked / 2);
  }
}

// snellBisectTexRay's own edges: the bracket clamped to [0, 1], the step count to [0, max], and a NaN end or
// no step returning the hit as given.
TEST(IntersectSearch, BisectTexRayClampsItsBracketAndSteps) {
  const DepthScene& sc = sphereScene();
  const SnellDepthSurface surf = sc.surface();
  const auto range = depthRange(sc);
  const SnellTexRay r = snellSearchSegment(vec3(0.3f, -0.2f, -4.0f), vec3(0.05f, 0.02f, -1.0f), range.first,
                                           range.second, sc.clipFromView);
  ASSERT_TRUE(r.valid);
  SnellHit given;
  given.uv = vec2(0.25f, 0.75f);
  given.position = vec3(1.0f, 2.0f, -3.0f);
  given.valid = true;
  given.fetches = 7;
  const auto same = [](const SnellHit& a, const SnellHit& b) {
    return a.uv == b.uv && a.position == b.position && a.valid == b.valid && a.fetches == b.fetches;
  };
  EXPECT_TRUE(same(snellBisectTexRay(r, sc.depth, surf, -0.5f, 1.5f, 6, given),
                   snellBisectTexRay(r, sc.depth, surf, 0.0f, 1.0f, 6, given)));
  EXPECT_TRUE(same(snellBisectTexRay(r, sc.depth, surf, 0.25f, 3.0f, 4, given),
                   snellBisectTexRay(r, sc.depth, surf, 0.25f, 1.0f, 4, given)));
  EXPECT_TRUE(same(snellBisectTexRay(r, sc.depth, surf, 0.0f, 1.0f, 1000, given),
                   snellBisectTexRay(r, sc.depth, surf, 0.0f, 1.0f, SNELL_BINARY_SEARCH_MAX_STEPS, given)));
  EXPECT_EQ(snellBisectTexRay(r, sc.depth, surf, 0.0f, 1.0f, 5, given).fetches, 7 + 5);
  EXPECT_EQ(snellBisectTexRay(r, sc.depth, surf, 0.0f, 1.0f, 1000, given).fetches, 7 + SNELL_BINARY_SEARCH_MAX_STEPS);
  EXPECT_TRUE(same(snellBisectTexRay(r, sc.depth, surf, 0.0f, 1.0f, 0, given), given));
  EXPECT_TRUE(same(snellBisectTexRay(r, sc.depth, surf, 0.0f, 1.0f, -4, given), given));
  EXPECT_TRUE(same(snellBisectTexRay(r, sc.depth, surf, kNaN, 1.0f, 5, given), given));
  EXPECT_TRUE(same(snellBisectTexRay(r, sc.depth, surf, 0.0f, kNaN, 5, given), given));
}

namespace {

// The linear phase of snellLinearBinarySearch replayed in double (beta_i = i / L, texels by index math, the
// first sample that is not a valid texel strictly in front ends it), then the bisection of its step
// (referenceBisection), whose last point is the result; with no bisection step the linear sample itself.
Bisection referenceLinearBinary(const DepthScene& sc, const SnellTexRay& r, int linearSteps, int binarySteps) {
  Bisection b;
  const glm::dvec3 s(r.s), e(r.e);
  const int nl = std::clamp(linearSteps, 1, SNELL_LINEAR_SEARCH_MAX_STEPS);
  for (int i = 1; i <= nl; ++i) {
    const double beta = double(i) / nl;
    const glm::dvec3 p = s + beta * (e - s);
    const glm::dvec2 uv = sc.project(p);
    const glm::dvec2 t(uv.x * sc.width, uv.y * sc.height);
    const bool onScreen = uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0;
    double z = std::numeric_limits<double>::quiet_NaN();
    if (onScreen) {
      z = texelViewZ(sc, std::min(int(std::floor(t.x)), sc.width - 1), std::min(int(std::floor(t.y)), sc.height - 1));
      if (std::fabs(t.x - std::round(t.x)) < 1e-4 || std::fabs(t.y - std::round(t.y)) < 1e-4) b.ambiguous = true;
      if (!std::isnan(z) && std::fabs(p.z - z) < 2e-6 * std::fabs(z)) b.ambiguous = true;
    } else if (std::max(std::fabs(uv.x - std::clamp(uv.x, 0.0, 1.0)), std::fabs(uv.y - std::clamp(uv.y, 0.0, 1.0))) < 1e-6) {
      b.ambiguous = true;
    }
    ++b.fetches;
    const bool valid = onScreen && !std::isnan(z);
    if (valid && p.z > z) continue;
    if (std::clamp(binarySteps, 0, SNELL_BINARY_SEARCH_MAX_STEPS) == 0) {
      b.position = p;
      b.uv = uv;
      b.valid = valid;
      return b;
    }
    const Bisection tail = referenceBisection(sc, r, double(i - 1) / nl, beta, binarySteps, 1e-5);
    Bisection out = tail;
    out.fetches += b.fetches;
    out.ambiguous |= b.ambiguous;
    return out;
  }
  b.position = glm::dvec3(0.0);  // no crossing: a miss
  b.valid = false;
  b.uv = glm::dvec2(0.0);
  return b;
}

}  // namespace

// snellLinearBinarySearch against the contract replayed step by step, for linear step counts -2 .. 299
// (clamped to [1, SNELL_LINEAR_SEARCH_MAX_STEPS]) and binary ones -1 .. 29, also with depth ranges that end
// in front of the surface (no crossing: a miss with the fetches spent).
TEST(IntersectSearch, LinearBinarySearchIsTheContractsWalkStepByStep) {
  for (const DepthScene* sc : {&silhouetteScene(), &sphereScene()}) {
    const SnellDepthSurface surf = sc->surface();
    const auto range = depthRange(*sc);
    const std::vector<Ray> rays = snell_search_test::sceneRays(*sc, 2000, 22);
    int checked = 0, skipped = 0, misses = 0, invalidEnds = 0;
    for (std::size_t k = 0; k < rays.size(); ++k) {
      const Ray& ray = rays[k];
      const int linear = static_cast<int>((k * 37) % 302) - 2, binary = static_cast<int>(k % 31) - 1;
      // Every third ray searches only the front part of the range, which may hold no crossing.
      const float zf = k % 3 ? range.second : range.first - 0.2f * (range.first - range.second);
      const SnellTexRay r = snellSearchSegment(ray.origin, ray.dir, range.first, zf, sc->clipFromView);
      const SnellHit h = snellLinearBinarySearch(ray.origin, ray.dir, sc->depth, surf, range.first, zf, linear, binary);
      if (!r.valid) {
        EXPECT_FALSE(h.valid);
        EXPECT_EQ(h.fetches, 0);
        continue;
      }
      const Bisection want = referenceLinearBinary(*sc, r, linear, binary);
      if (want.ambiguous) {
        ++skipped;
        continue;
      }
      ++checked;
      const std::string what = "ray " + std::to_string(k) + ", linear " + std::to_string(linear) + ", binary " +
                               std::to_string(binary);
      EXPECT_EQ(h.fetches, want.fetches) << what;
      EXPECT_EQ(h.valid, want.valid) << what;
      const bool miss = want.position == glm::dvec3(0.0);
      misses += miss;
      invalidEnds += !miss && !want.valid;
      const double scale = std::max(1.0, glm::length(glm::dvec3(r.e)));
      EXPECT_NEAR(h.position.x, want.position.x, 2e-5 * scale) << what;
      EXPECT_NEAR(h.position.y, want.position.y, 2e-5 * scale) << what;
      EXPECT_NEAR(h.position.z, want.position.z, 2e-5 * scale) << what;
      EXPECT_NEAR(h.uv.x, want.uv.x, 2e-5) << what;
      EXPECT_NEAR(h.uv.y, want.uv.y, 2e-5) << what;
      if (::testing::Test::HasFailure()) return;
    }
    std::printf("[linear+binary step by step] %s: %d checked (%d misses, %d ending on an empty texel), %d skipped\n",
                sc->name.c_str(), checked, misses, invalidEnds, skipped);
    EXPECT_GT(checked, 1000);
    EXPECT_GT(misses, 10);
    EXPECT_GT(invalidEnds, 10);
  }
}

namespace {

// A fronto-parallel wall at view z = -4 (INFINITE_REVERSED depth 0.125 = zNear / 4, exact in float) filling
// a 64 x 64 buffer, seen through a plain perspective (clip = (x, y, -z - 1, -z)). With S at z = -2 and E at
// z = -6, beta = 1/2 is z = -4 exactly: a point exactly on the surface, which is not strictly in front.
struct Wall {
  snell::Texture2D depth{snell::Image(64, 64, vec4(0.125f, 0.0f, 0.0f, 0.0f))};
  SnellDepthSurface surface;
  Wall() {
    mat4 m(0.0f);
    m[0][0] = 1.0f;
    m[1][1] = 1.0f;
    m[2][2] = -1.0f;
    m[2][3] = -1.0f;
    m[3][2] = -1.0f;
    surface = snellDepthSurface(m, 0.5f, 100.0f, SNELL_DEPTH_INFINITE_REVERSED, 0.0f);
  }
};

}  // namespace

// "Strictly in front (z > viewZ)" advances: a point exactly on the surface does not, in each search.
TEST(IntersectSearch, APointExactlyOnTheSurfaceIsNotInFront) {
  const Wall w;
  const vec3 o(0.3f, 0.2f, -1.0f), d(0.0f, 0.0f, -1.0f);
  // Binary: mid 1/2 is on the wall, so hi moves there and the next mid is 1/4 (z = -3).
  const SnellHit b = snellBinarySearch(o, d, w.depth, w.surface, -2.0f, -6.0f, 2);
  EXPECT_TRUE(b.valid);
  EXPECT_EQ(b.fetches, 2);
  EXPECT_EQ(b.position, vec3(0.3f, 0.2f, -3.0f));
  // Linear + binary: the first linear sample (1/2) ends the linear phase.
  const SnellHit l = snellLinearBinarySearch(o, d, w.depth, w.surface, -2.0f, -6.0f, 2, 0);
  EXPECT_TRUE(l.valid);
  EXPECT_EQ(l.fetches, 1);
  EXPECT_EQ(l.position, vec3(0.3f, 0.2f, -4.0f));
  // CBS: the one step (1/2) does not advance, so S is tested and returned.
  const SnellHit c = snellConservativeBinarySearch(o, d, w.depth, w.surface, -2.0f, -6.0f, 1);
  EXPECT_TRUE(c.valid);
  EXPECT_EQ(c.fetches, 2);
  EXPECT_EQ(c.position, vec3(0.3f, 0.2f, -2.0f));
  // CBS with no step tests S only.
  const SnellHit c0 = snellConservativeBinarySearch(o, d, w.depth, w.surface, -2.0f, -6.0f, 0);
  EXPECT_TRUE(c0.valid);
  EXPECT_EQ(c0.fetches, 1);
  EXPECT_EQ(c0.position, vec3(0.3f, 0.2f, -2.0f));
  // snellBisectTexRay clamps lo above 1 to 1: the one midpoint is E.
  const SnellTexRay r = snellSearchSegment(o, d, -2.0f, -6.0f, w.surface.clipFromView);
  ASSERT_TRUE(r.valid);
  const SnellHit e = snellBisectTexRay(r, w.depth, w.surface, 1.05f, 1.0f, 1, snellHitMiss(0));
  EXPECT_EQ(e.fetches, 1);
  EXPECT_EQ(e.position.z, -6.0f);
}

// An invalid segment: every field 0, and each search misses without a fetch. dir.z = -FLT_MIN is not
// denormal (a valid, if steep, segment); an origin exactly at zFarthest has nothing left to search.
TEST(IntersectSearch, SegmentEdgesAndInvalidSegmentsCostNoFetch) {
  const Wall w;
  const vec3 o(0.3f, 0.2f, -1.0f), towards(0.0f, 0.1f, 1.0f);
  const SnellTexRay bad = snellSearchSegment(o, towards, -2.0f, -6.0f, w.surface.clipFromView);
  EXPECT_FALSE(bad.valid);
  EXPECT_EQ(bad.s, vec3(0.0f));
  EXPECT_EQ(bad.e, vec3(0.0f));
  EXPECT_EQ(bad.k1, 0.0f);
  EXPECT_EQ(bad.k2, 0.0f);
  EXPECT_EQ(bad.ts, vec2(0.0f));
  EXPECT_EQ(bad.dt, vec2(0.0f));
  EXPECT_EQ(snellBinarySearch(o, towards, w.depth, w.surface, -2.0f, -6.0f, 4).fetches, 0);
  EXPECT_EQ(snellConservativeBinarySearch(o, towards, w.depth, w.surface, -2.0f, -6.0f, 4).fetches, 0);
  EXPECT_EQ(snellLinearBinarySearch(o, towards, w.depth, w.surface, -2.0f, -6.0f, 4, 4).fetches, 0);
  EXPECT_TRUE(snellSearchSegment(vec3(0.3f, 0.2f, -5.0f), vec3(0.0f, 0.0f, -FLT_MIN), -2.0f, -6.0f,
                                 w.surface.clipFromView).valid);  // E at t = 2^126
  EXPECT_FALSE(snellSearchSegment(vec3(0.3f, 0.2f, -6.0f), vec3(0.0f, 0.0f, -1.0f), -2.0f, -6.0f,
                                  w.surface.clipFromView).valid);
}

// A range whose nearest plane is z = -FLT_MIN, the nearest plane a segment may start on: with
// zFarthest = -4 the segment's k2 = S.z E.z / (S.z - E.z) is FLT_MIN itself, not the underflowed 0,
// so the texture-space parameter still moves along the ray. From S = (0, 0, -FLT_MIN) (uv 0.5) towards
// E = (-2, 0, -4) (uv 0.25) every point but S projects to uv 0.25 (the ray leaves from the eye's
// plane), where a wall stands at z = -2; the texels under S are empty. CBS (5 steps) then ends on the
// last of the points beta = k / 32 in front of the wall (z = -4 beta): beta = 15 / 32.
TEST(IntersectSearch, ASegmentFromTheSmallestNearPlaneStillWalks) {
  mat4 m(0.0f);
  m[0][0] = 1.0f;
  m[1][1] = 1.0f;
  m[2][2] = -1.0f;
  m[2][3] = -1.0f;
  m[3][2] = -1.0f;
  const SnellDepthSurface s = snellDepthSurface(m, 0.5f, 100.0f, SNELL_DEPTH_INFINITE_REVERSED, 0.0f);
  Image img(64, 64);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 32; ++x) img.at(x, y) = glm::vec4(0.25f);  // z = -2: zNear / 0.25
  const Texture2D wall(std::move(img));
  const glm::vec3 origin(0.0f, 0.0f, -FLT_MIN), dir(-2.0f, 0.0f, -4.0f);
  const SnellTexRay r = snellSearchSegment(origin, dir, -FLT_MIN, -4.0f, m);
  ASSERT_TRUE(r.valid);
  ASSERT_EQ(r.k2, FLT_MIN);
  const SnellHit h = snellConservativeBinarySearch(origin, dir, wall, s, -FLT_MIN, -4.0f, 5);
  ASSERT_TRUE(h.valid);
  EXPECT_NEAR(h.position.z, -4.0 * 15.0 / 32.0, 1e-6);
  EXPECT_NEAR(h.position.x, -2.0 * 15.0 / 32.0, 1e-6);
  EXPECT_NEAR(h.uv.x, 0.25, 1e-6);
  EXPECT_EQ(h.fetches, 5);
}
