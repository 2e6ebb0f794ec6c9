// snellInsideBracket against its contract run in double: the same samples
// (i tMax / steps, the first step's halvings) projected with the analytic
// camera and classified from the sphere's analytic layers at the texel a
// nearest read picks (support/inside_layers.hpp). A ray with a sample within
// rounding of a layer or of a texel edge is left out (float may read either
// side there); the rest must give the bracket exactly, its fetches included.
// The two searches built on the bracket, snellInsideMarch (bisection) and
// snellInsidePlane (tangent planes of the crossed layer, analytic normals at
// the texel centres), are run the same way from their contracts.
#include <snell/snell.hpp>

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "support/inside_layers.hpp"
#include "support/rng.hpp"

namespace {

using namespace snell;
using glm::dvec2;
using glm::dvec3;

constexpr double kLayerMargin = 1e-3;  // view z; float depth rounding is a few 1e-6 here
constexpr double kTexelMargin = 1e-3;  // texels; float projection rounding is about 1e-5 texels

struct Bracket {
  bool valid = false, ambiguous = false;
  double lo = 0.0, hi = 0.0;
  dvec2 uv{0.0}, loUv{0.0};
  int side = 0, fetches = 0;
  bool halved = false;  // bracketed by a halving of the first step
};

enum Read { kOffScreen = -3, kAmbiguous = -1 };

// The side of p (inside_layers.hpp) where it projects, or kOffScreen, or kAmbiguous.
int readAt(const inside_test::Layers& l, const dvec3& p, double dirZ, dvec2* uv) {
  *uv = l.front.project(p);
  const dvec2 x = *uv * double(l.size);
  const dvec2 f = glm::abs(x - glm::round(x));
  if (std::min(f.x, f.y) < kTexelMargin) return kAmbiguous;
  if (uv->x < 0.0 || uv->x > 1.0 || uv->y < 0.0 || uv->y > 1.0) return kOffScreen;
  const int s = inside_test::expectedSide(inside_test::layersAt(l, inside_test::texelOf(l, *uv)), p.z, dirZ,
                                          kLayerMargin);
  return s < 0 ? kAmbiguous : s;
}

Bracket bruteForce(const inside_test::Layers& l, const dvec3& o, const dvec3& d, double maxDistance, int steps) {
  Bracket b;
  double tMax = maxDistance / glm::length(d);
  if (d.z > 0.0) tMax = std::min(tMax, (-double(snell_test::kSceneNear) - o.z) / d.z);
  const int n = std::clamp(steps, 1, SNELL_LINEAR_MARCH_MAX_STEPS);
  const double dt = tMax / n;
  bool wasInside = false;
  double lo = 0.0;
  dvec2 loUv(0.0);
  for (int i = 1; i <= n; ++i) {
    const double t = i * dt;
    dvec2 uv;
    const int s = readAt(l, o + t * d, d.z, &uv);
    if (s == kAmbiguous) {
      b.ambiguous = true;
      return b;
    }
    if (s == kOffScreen) return b;
    b.fetches += 2;
    if (s == 0) {
      wasInside = true;
      lo = t;
      loUv = uv;
    } else if (wasInside) {
      b = {true, false, lo, t, uv, loUv, s, b.fetches};
      return b;
    } else if (i == 1) {
      double hiT = t;
      dvec2 hiUv = uv;
      int hiSide = s;
      const dvec2 so = l.front.project(o);
      for (int h = 1; h <= SNELL_INSIDE_FIRST_STEP_HALVINGS; ++h) {
        const double th = 0.5 * hiT;
        dvec2 sq;
        const dvec3 q = o + th * d;
        const dvec2 x = l.front.project(q) * double(l.size);
        const dvec2 f = glm::abs(x - glm::round(x));
        if (std::min(f.x, f.y) < kTexelMargin) {
          b.ambiguous = true;
          return b;
        }
        sq = x / double(l.size);
        if (sq.x < 0.0 || sq.x > 1.0 || sq.y < 0.0 || sq.y > 1.0) break;
        const dvec2 awayXY = glm::abs(sq - so) * double(l.size);
        const double away = std::max(awayXY.x, awayXY.y);
        if (std::abs(away - 1.0) < kTexelMargin) {
          b.ambiguous = true;
          return b;
        }
        if (away < 1.0) break;
        const int sh = readAt(l, q, d.z, &sq);
        if (sh == kAmbiguous) {
          b.ambiguous = true;
          return b;
        }
        b.fetches += 2;
        if (sh == 0) {
          b = {true, false, th, hiT, hiUv, sq, hiSide, b.fetches, true};
          return b;
        }
        hiT = th;
        hiUv = sq;
        hiSide = sh;
      }
    }
  }
  return b;
}

void expectBracket(const SnellInsideBracket& got, const Bracket& want, int ray) {
  ASSERT_EQ(got.valid, want.valid) << "ray " << ray;
  EXPECT_EQ(got.fetches, want.fetches) << "ray " << ray;
  EXPECT_EQ(got.side, want.side) << "ray " << ray;
  EXPECT_NEAR(got.lo, want.lo, 1e-5 * std::max(1.0, want.lo)) << "ray " << ray;
  EXPECT_NEAR(got.hi, want.hi, 1e-5 * std::max(1.0, want.hi)) << "ray " << ray;
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(got.uv[k], want.uv[k], 1e-5) << "ray " << ray;
    EXPECT_NEAR(got.loUv[k], want.loUv[k], 1e-5) << "ray " << ray;
  }
}

// Rays from inside the sphere and from points on it heading in (the start after a reflection there), with
// coarse and fine marches: brackets through either layer, halved first steps, rays that never get inside.
TEST(InsideBracket, MatchesTheContractsSamplesOnTheSpheresLayers) {
  const int size = 128;
  const inside_test::Layers l = inside_test::sphereLayers(size);
  const dvec3 c = technique_test::kCentre;
  const double R = technique_test::kRadius;
  snell_test::Rng g(8331);
  int checked = 0, skipped = 0, throughFront = 0, throughBack = 0, halved = 0, misses = 0;
  for (int ray = 0; ray < 4000; ++ray) {
    const dvec3 u(g.unit());
    dvec3 d(g.unit());
    dvec3 o;
    if (ray % 2 == 0) {
      o = c + R * double(g.uniform(0.0f, 0.95f)) * u;
    } else {
      o = c + R * u;
      if (glm::dot(d, u) > 0.0) d = -d;
    }
    const double maxDistance = g.uniform(0.5f, 6.0f);
    const int steps = ray % 7 == 0 ? int(g.uniform(-3.0f, 3.0f)) : int(g.uniform(1.0f, 49.0f));
    // The ray as the float inputs the function gets, so both sides start from the same numbers.
    const glm::vec3 of(o), df(d);
    const Bracket want = bruteForce(l, dvec3(of), dvec3(df), maxDistance, steps);
    if (want.ambiguous) {
      ++skipped;
      continue;
    }
    const SnellInsideBracket got = snellInsideBracket(of, df, l.back.depth, l.back.surface(), l.front.depth,
                                                      l.front.surface(), float(maxDistance), steps);
    expectBracket(got, want, ray);
    if (::testing::Test::HasFailure()) return;
    ++checked;
    if (!want.valid) ++misses;
    else (want.side == 2 ? throughFront : throughBack)++;
    halved += want.halved;
  }
  std::printf("[inside bracket] %d rays checked, %d left out, %d through the front, %d through the back, %d from "
              "a halved first step, %d misses\n", checked, skipped, throughFront, throughBack, halved, misses);
  EXPECT_GT(checked, 3000);
  EXPECT_GT(throughFront, 300);
  EXPECT_GT(throughBack, 300);
  EXPECT_GT(halved, 20);
  EXPECT_GT(misses, 100);
}

// snellInsideMarch's contract in double: the bracket above, then refineSteps bisections (a midpoint outside
// moves hi and names the side, any other moves lo; 2 fetches per midpoint on screen); the hit is hi.
struct MarchHit {
  bool valid = false, ambiguous = false, front = false;
  dvec3 position{0.0};
  dvec2 uv{0.0};
  int fetches = 0;
  int planes = 0, misses = 0;  // bruteForcePlane: planes kept, plane 1 reads not kept
};

MarchHit bruteForceMarch(const inside_test::Layers& l, const dvec3& o, const dvec3& d, double maxDistance, int steps,
                         int refineSteps) {
  MarchHit m;
  const Bracket b = bruteForce(l, o, d, maxDistance, steps);
  m.ambiguous = b.ambiguous;
  m.fetches = b.fetches;
  if (b.ambiguous || !b.valid) return m;
  double lo = b.lo, hi = b.hi;
  dvec2 uv = b.uv;
  int side = b.side;
  for (int j = 0; j < std::clamp(refineSteps, 0, SNELL_LINEAR_MARCH_MAX_REFINE_STEPS); ++j) {
    const double mid = 0.5 * (lo + hi);
    dvec2 at;
    const int s = readAt(l, o + mid * d, d.z, &at);
    if (s == kAmbiguous) {
      m.ambiguous = true;
      return m;
    }
    if (s != kOffScreen) m.fetches += 2;
    if (s > 0) {
      hi = mid;
      uv = at;
      side = s;
    } else {
      lo = mid;
    }
  }
  m.valid = true;
  m.position = o + hi * d;
  m.uv = uv;
  m.front = side == 2;
  return m;
}

// snellInsidePlane's contract in double: plane k on the crossed layer at the texel of uv_(k-1), B_k its
// texel-centre point and n_k the analytic normal there, kept when met within [lo, hi] at a point on screen;
// plane 1 read again at loUv, then on the other layer there, when not kept.
MarchHit bruteForcePlane(const inside_test::Layers& l, const dvec3& o, const dvec3& d, double maxDistance, int steps,
                         int iterations) {
  MarchHit m;
  const Bracket b = bruteForce(l, o, d, maxDistance, steps);
  m.ambiguous = b.ambiguous;
  m.fetches = b.fetches;
  if (b.ambiguous || !b.valid) return m;
  bool onFront = b.side == 2, readFront = onFront;
  const int n = std::clamp(iterations, 0, SNELL_PLANE_MAX_ITERATIONS);
  double t = b.hi;
  dvec2 uv = b.uv, readUv = b.uv;
  int planes = 0, misses = 0;
  for (int k = 1; n > 0 && k <= SNELL_PLANE_MAX_ITERATIONS + 2; ++k) {
    if (inside_test::nearTexelEdge(l, readUv, kTexelMargin)) {
      m.ambiguous = true;
      return m;
    }
    const glm::ivec2 texel = inside_test::texelOf(l, readUv);
    const dvec2 centre((texel.x + 0.5) / l.size, (texel.y + 0.5) / l.size);
    const snell_test::DepthScene& layer = readFront ? l.front : l.back;
    const snell_test::AnalyticSample a = layer.sampleAt(centre);
    ++m.fetches;
    bool kept = false;
    if (a.valid) {
      ++m.fetches;
      const dvec3 B = layer.pixelRay(centre) * a.s;
      const double den = glm::dot(d, a.normal), tk = glm::dot(B - o, a.normal) / den;
      if (std::abs(den) < 1e-3 * glm::length(d) || std::abs(tk - b.lo) < 1e-4 || std::abs(tk - b.hi) < 1e-4) {
        m.ambiguous = true;  // nearly parallel, or met within rounding of the bracket's ends
        return m;
      }
      if (tk >= b.lo && tk <= b.hi) {
        const dvec2 at = l.front.project(o + tk * d);
        if (at.x >= 0.0 && at.x <= 1.0 && at.y >= 0.0 && at.y <= 1.0) {
          t = tk;
          uv = readUv = at;
          onFront = readFront;
          ++planes;
          kept = true;
        }
      }
    }
    if (!kept) {
      if (planes > 0 || misses >= 2) break;
      ++misses;
      readUv = b.loUv;
      readFront = misses == 1 ? onFront : !onFront;
    }
    if (planes >= n) break;
  }
  m.valid = true;
  m.position = o + t * d;
  m.uv = uv;
  m.front = onFront;
  m.planes = planes;
  m.misses = misses;
  return m;
}

void expectHit(const SnellInsideHit& got, const MarchHit& want, int ray) {
  ASSERT_EQ(got.hit.valid, want.valid) << "ray " << ray;
  EXPECT_EQ(got.hit.fetches, want.fetches) << "ray " << ray;
  if (!want.valid) return;
  EXPECT_EQ(got.front, want.front) << "ray " << ray;
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got.hit.position[k], want.position[k], 2e-4) << "ray " << ray;
  for (int k = 0; k < 2; ++k) EXPECT_NEAR(got.hit.uv[k], want.uv[k], 2e-5) << "ray " << ray;
}

// The rays of the bracket test (a coarser march, so the bisection has room), refinement counts from
// below 0 to above the bound: hits through either layer, refined or not.
TEST(InsideMarch, BisectsTheBracketAsTheContractSays) {
  const int size = 128;
  const inside_test::Layers l = inside_test::sphereLayers(size);
  const dvec3 c = technique_test::kCentre;
  const double R = technique_test::kRadius;
  snell_test::Rng g(8332);
  int checked = 0, front = 0, back = 0, misses = 0;
  for (int ray = 0; ray < 3000; ++ray) {
    const dvec3 u(g.unit());
    const glm::vec3 o(c + R * double(g.uniform(0.0f, 0.95f)) * u), d(g.unit());
    const double maxDistance = g.uniform(0.5f, 6.0f);
    const int steps = ray % 7 == 3 ? 600 : int(g.uniform(1.0f, 12.0f));  // 600: clamped to the bound
    const int refine = ray % 5 == 0 ? int(g.uniform(-3.0f, 1.0f)) : ray % 5 == 1 ? 30 : int(g.uniform(1.0f, 7.0f));
    const MarchHit want = bruteForceMarch(l, dvec3(o), dvec3(d), maxDistance, steps, refine);
    if (want.ambiguous) continue;
    const SnellInsideHit got = snellInsideMarch(o, d, l.back.depth, l.back.surface(), l.front.depth, l.front.surface(),
                                                float(maxDistance), steps, refine);
    expectHit(got, want, ray);
    if (::testing::Test::HasFailure()) return;
    ++checked;
    if (!want.valid) ++misses;
    else (want.front ? front : back)++;
  }
  std::printf("[inside march] %d rays checked: %d through the front, %d through the back, %d misses\n", checked, front,
              back, misses);
  EXPECT_GT(checked, 1000);
  EXPECT_GT(front, 200);
  EXPECT_GT(back, 200);
  EXPECT_GT(misses, 50);
}

TEST(InsidePlane, IntersectsTheCrossedLayersTangentPlanesAsTheContractSays) {
  const int size = 128;
  const inside_test::Layers l = inside_test::sphereLayers(size);
  const dvec3 c = technique_test::kCentre;
  const double R = technique_test::kRadius;
  snell_test::Rng g(8333);
  int checked = 0, front = 0, back = 0, misses = 0, noPlane = 0, reread = 0, otherLayer = 0, several = 0;
  for (int ray = 0; ray < 3000; ++ray) {
    const dvec3 u(g.unit());
    glm::vec3 o, d(g.unit());
    if (ray % 2 == 0) {
      o = glm::vec3(c + R * double(g.uniform(0.0f, 0.95f)) * u);
    } else {
      o = glm::vec3(c + R * u);
      if (glm::dot(dvec3(d), u) > 0.0) d = -d;
    }
    const double maxDistance = g.uniform(0.5f, 6.0f);
    const int steps = int(g.uniform(1.0f, 24.0f));
    const int iterations = ray % 5 == 0 ? int(g.uniform(-3.0f, 1.0f)) : ray % 5 == 1 ? 12 : int(g.uniform(1.0f, 5.0f));
    const MarchHit want = bruteForcePlane(l, dvec3(o), dvec3(d), maxDistance, steps, iterations);
    if (want.ambiguous) continue;
    const SnellInsideHit got = snellInsidePlane(o, d, l.back.depth, l.back.normals, l.back.surface(), l.front.depth,
                                                l.front.normals, l.front.surface(), float(maxDistance), steps,
                                                iterations);
    expectHit(got, want, ray);
    if (::testing::Test::HasFailure()) return;
    ++checked;
    if (!want.valid) ++misses;
    else (want.front ? front : back)++;
    if (!want.valid) continue;
    noPlane += want.planes == 0;
    reread += want.planes > 0 && want.misses == 1;
    otherLayer += want.planes > 0 && want.misses == 2;
    several += want.planes >= 3;
  }
  std::printf("[inside plane] %d rays checked: %d through the front, %d through the back, %d misses; no plane kept "
              "%d, plane 1 kept at loUv %d, on the other layer %d, three planes or more %d\n", checked, front, back,
              misses, noPlane, reread, otherLayer, several);
  EXPECT_GT(checked, 1000);
  EXPECT_GT(front, 200);
  EXPECT_GT(back, 200);
  EXPECT_GT(misses, 50);
  EXPECT_GT(noPlane, 20);
  EXPECT_GT(reread, 20);
  EXPECT_GT(otherLayer, 5);
  EXPECT_GT(several, 200);
}

// Bad input: the miss with nothing read.
// A ray turning towards the camera by a dir.z too small for the near plane's distance along it to be a
// float (+inf, from 1e-38 on; in double it is about 6e38) never reaches that plane: marched in full.
TEST(InsideBracket, ANearPlaneTooFarForAFloatDoesNotCutTheMarch) {
  const inside_test::Layers l = inside_test::sphereLayers(64);
  const glm::vec3 o(0.3f, -0.2f, -6.0f);
  for (const float dz : {1e-30f, 1e-38f, 1e-40f}) {
    const glm::vec3 d(1.0f, 0.0f, dz);
    const Bracket want = bruteForce(l, dvec3(o), dvec3(d), 4.0, 16);
    ASSERT_FALSE(want.ambiguous) << dz;
    ASSERT_TRUE(want.valid) << dz;
    expectBracket(snellInsideBracket(o, d, l.back.depth, l.back.surface(), l.front.depth, l.front.surface(), 4.0f, 16),
                  want, 0);
  }
}

// The near-plane cut is for rays towards the camera: one parallel to the image plane from a point before
// the near plane (z = -0.3, the scene's zNear 0.5) or on it is marched in full, outside the object: a miss
// after its samples' fetches, as the brute force in double has it.
TEST(InsideBracket, ARayAlongTheImagePlaneIsNotCutByTheNearPlane) {
  const inside_test::Layers l = inside_test::sphereLayers(32);
  for (const float z : {-0.3f, -snell_test::kSceneNear}) {
    const glm::vec3 o(0.0031f, 0.0047f, z), d(1.0f, 0.0f, 0.0f);  // samples away from texel edges
    const Bracket want = bruteForce(l, dvec3(o), dvec3(d), 0.1, 4);
    ASSERT_FALSE(want.ambiguous) << z;
    ASSERT_GT(want.fetches, 0) << z;
    expectBracket(snellInsideBracket(o, d, l.back.depth, l.back.surface(), l.front.depth, l.front.surface(), 0.1f, 4),
                  want, 0);
  }
}

TEST(InsideBracket, BadInputIsAMissWithoutFetches) {
  const inside_test::Layers l = inside_test::sphereLayers(32);
  const glm::vec3 o(0.3f, -0.2f, -6.0f), d(0.0f, 0.0f, -1.0f);
  const float nan = std::nanf(""), inf = INFINITY;
  auto run = [&](glm::vec3 oo, glm::vec3 dd, float maxDistance) {
    return snellInsideBracket(oo, dd, l.back.depth, l.back.surface(), l.front.depth, l.front.surface(), maxDistance,
                              16);
  };
  for (const SnellInsideBracket& b : {run(glm::vec3(nan), d, 3.0f), run(o, glm::vec3(inf, 0, 0), 3.0f),
                                      run(o, glm::vec3(0.0f), 3.0f), run(o, d, 0.0f), run(o, d, -1.0f),
                                      run(o, d, nan), run(o, glm::vec3(0, 0, 1e-39f), 3.0f)}) {
    EXPECT_FALSE(b.valid);
    EXPECT_EQ(b.fetches, 0);
    EXPECT_EQ(b.lo, 0.0f);
    EXPECT_EQ(b.hi, 0.0f);
    EXPECT_EQ(b.side, 0);
    EXPECT_EQ(b.uv, glm::vec2(0.0f));
    EXPECT_EQ(b.loUv, glm::vec2(0.0f));
  }
  // The ray from a point on the near plane towards the camera lies in front of it: nothing to march.
  const SnellInsideBracket nearPlane = run(glm::vec3(0.0f, 0.0f, -snell_test::kSceneNear), glm::vec3(0, 0, 1), 3.0f);
  EXPECT_FALSE(nearPlane.valid);
  EXPECT_EQ(nearPlane.fetches, 0);
  // Any positive maxDistance is marched, a denormal one too: its 16 samples round to the centre, inside.
  const SnellInsideBracket tiny = run(o, d, 1e-40f);
  EXPECT_FALSE(tiny.valid);
  EXPECT_EQ(tiny.fetches, 2 * 16);
  // The sphere's centre, heading straight back: leaves through the back layer, hi - lo one step of 3 / 16.
  const SnellInsideBracket b = run(o, d, 3.0f);
  ASSERT_TRUE(b.valid);
  EXPECT_EQ(b.side, 1);
  EXPECT_NEAR(b.hi - b.lo, 3.0 / 16.0, 1e-6);
  // A nearest read moves the layer by less than a texel's depth change, far below a step here.
  EXPECT_LE(b.lo, technique_test::kRadius + 0.02);
  EXPECT_GE(b.hi, technique_test::kRadius - 0.02);
}

}  // namespace
