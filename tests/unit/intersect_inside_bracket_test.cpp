// snellInsideBracket against its contract run in double: the same samples
// (i tMax / steps, the first step's halvings) projected with the analytic
// camera and classified from the sphere's analytic layers at the texel a
// nearest read picks (support/inside_layers.hpp). A ray with a sample within
// rounding of a layer or of a texel edge is left out (float may read either
// side there); the rest must give the bracket exactly, its fetches included.
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

// Bad input: the miss with nothing read.
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
