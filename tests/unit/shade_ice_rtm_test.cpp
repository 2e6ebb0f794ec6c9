// Ice (two-sided refraction by normal blending, reflection, cubic Fresnel,
// crack clipping), G. Oliveira's refractive texture mapping, dispersion and
// roughness -> lod, against independent computations: Snell's law checked in
// angles (sines) and coplanarity, the mirror law, an interval test written
// out, a double-precision parametric ray/plane solve, Abbe's definition.
#include <snell/shade.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "support/rng.hpp"

namespace {

using glm::dvec2;
using glm::dvec3;
using glm::vec2;
using glm::vec3;
using glm::vec4;

const float kInf = std::numeric_limits<float>::infinity();
const float kNaN = std::numeric_limits<float>::quiet_NaN();

struct Rng : snell_test::Rng {
  Rng() : snell_test::Rng(4321u) {}
};

double sinBetween(dvec3 a, dvec3 b) { return glm::length(glm::cross(glm::normalize(a), glm::normalize(b))); }

// --- ice -----------------------------------------------------------------------

TEST(ShadeIce, RefractsAboutTheBlendedNormalBySnellsLaw) {
  Rng r;
  const double eta = 1.0003 / 1.3091;
  for (int k = 0; k < 20000; ++k) {
    vec3 nf = r.unit(), nb = r.unit();
    vec3 eye = r.unit();
    if (glm::dot(eye, nf) > -0.05f) eye = glm::reflect(eye, nf) - nf * 0.1f;  // a front face: e . nf < 0
    float a = r.uniform(0, 1);
    snell::SnellIce s = snell::snellIce(eye * 3.0f, nf * 2.0f, nb, a, float(eta));
    ASSERT_TRUE(s.valid);
    // Eq. 1, written out.
    dvec3 nr = (1.0 - double(a)) * glm::normalize(dvec3(nf)) - double(a) * glm::normalize(dvec3(nb));
    if (glm::length(nr) < 1e-3) continue;
    nr = glm::normalize(nr);
    dvec3 e = glm::normalize(dvec3(eye));
    dvec3 t(s.refracted);
    EXPECT_NEAR(glm::length(t), 1.0, 1e-5);
    // Snell: sin_t = eta sin_i; t coplanar with e and nr, on the far side.
    EXPECT_NEAR(sinBetween(t, nr), eta * sinBetween(e, nr), 2e-5) << k;
    EXPECT_NEAR(glm::dot(glm::cross(e, nr), t), 0.0, 2e-5);
    EXPECT_GT(glm::dot(t, nr) * glm::dot(e, nr), 0.0);
    // Eq. 3: mirror about nf: same angle, coplanar, tangent part kept.
    dvec3 n = glm::normalize(dvec3(nf));
    dvec3 rr(s.reflected);
    EXPECT_NEAR(glm::dot(rr, n), -glm::dot(e, n), 1e-5);
    dvec3 tanE = e - glm::dot(e, n) * n, tanR = rr - glm::dot(rr, n) * n;
    EXPECT_NEAR(glm::length(tanE - tanR), 0.0, 1e-5);
    // Eq. 4: (1 - |e.n|)^3.
    double c = std::fabs(glm::dot(e, n));
    EXPECT_NEAR(s.fresnel, std::pow(1.0 - c, 3.0), 1e-5);
  }
}

TEST(ShadeIce, DefaultsAndHostileInputs) {
  vec3 eye = glm::normalize(vec3(0.3f, 0.0f, -1.0f)), nf(0, 0, 1), nb(0.2f, 0.0f, -1.0f);
  snell::SnellIce d = snell::snellIce(eye, nf, nb);
  snell::SnellIce e = snell::snellIce(eye, nf, nb, 0.33f, 1.0003f / 1.3091f);
  EXPECT_EQ(d.refracted, e.refracted);
  EXPECT_EQ(d.fresnel, e.fresnel);
  // Head-on: no bending, Fresnel 0, reflection straight back.
  snell::SnellIce h = snell::snellIce(vec3(0, 0, -1), vec3(0, 0, 1), vec3(0, 0, -1), 0.33f, 0.7641f);
  EXPECT_NEAR(glm::distance(h.refracted, vec3(0, 0, -1)), 0.0f, 1e-6f);
  EXPECT_EQ(h.reflected, vec3(0, 0, 1));
  EXPECT_EQ(h.fresnel, 0.0f);
  // eta 0 / NaN / inf: no bending (eta 1).
  for (float bad : {0.0f, -1.0f, kNaN, kInf, 1e-40f}) {
    snell::SnellIce b = snell::snellIce(eye, nf, vec3(0.0f), 0.0f, bad);
    EXPECT_TRUE(b.valid);
    EXPECT_NEAR(glm::distance(b.refracted, eye), 0.0f, 1e-6f) << bad;
  }
  // Invalid eye or front normal: invalid, zero directions, Fresnel 1.
  for (vec3 bad : {vec3(0.0f), vec3(kNaN), vec3(kInf, 0, 0)}) {
    snell::SnellIce b1 = snell::snellIce(bad, nf, nb, 0.33f, 0.76f);
    snell::SnellIce b2 = snell::snellIce(eye, bad, nb, 0.33f, 0.76f);
    for (const snell::SnellIce& b : {b1, b2}) {
      EXPECT_FALSE(b.valid);
      EXPECT_EQ(b.refracted, vec3(0.0f));
      EXPECT_EQ(b.reflected, vec3(0.0f));
      EXPECT_EQ(b.fresnel, 1.0f);
    }
  }
  // Invalid back normal: one-sided refraction about nf.
  snell::SnellIce one = snell::snellIce(eye, nf, vec3(kNaN), 0.33f, 0.76f);
  snell::SnellRefraction ref = snell::snellRefract(eye, nf, 0.76f, SNELL_TIR_REFLECT);
  EXPECT_NEAR(glm::distance(one.refracted, ref.direction), 0.0f, 1e-6f);
  // TIR with the ZERO policy is not reachable with the default REFLECT policy:
  // leaving ice at grazing angles reflects instead.
  snell::SnellIce tir = snell::snellIce(glm::normalize(vec3(1.0f, 0.0f, -0.1f)), nf, vec3(0.0f), 0.0f, 1.3091f);
  EXPECT_TRUE(tir.valid);
  EXPECT_NEAR(glm::length(tir.refracted), 1.0f, 1e-6f);
}

TEST(ShadeIce, ComposeMixesByFresnel) {
  vec4 refl(1.0f, 0.0f, 0.5f, 1.0f), refr(0.0f, 1.0f, 0.25f, 0.5f);
  EXPECT_EQ(snell::snellIceCompose(refl, refr, 0.0f), refr);
  EXPECT_EQ(snell::snellIceCompose(refl, refr, 1.0f), refl);
  vec4 m = snell::snellIceCompose(refl, refr, 0.25f);
  EXPECT_NEAR(m.x, 0.25f, 1e-7f);
  EXPECT_NEAR(m.y, 0.75f, 1e-7f);
  EXPECT_EQ(snell::snellIceCompose(refl, refr, kNaN), refl);
  EXPECT_EQ(snell::snellIceCompose(refl, refr, 5.0f), refl);
  EXPECT_EQ(snell::snellIceCompose(refl, refr, -5.0f), refr);
}

TEST(ShadeIceCrack, KeepsExactlyTheFragmentsInsideTheDepthInterval) {
  Rng r;
  for (int k = 0; k < 50000; ++k) {
    float f = r.uniform(0, 1), b = r.uniform(0, 1), c = r.uniform(0, 1);
    if (k % 7 == 0) c = f;  // on the ends
    if (k % 11 == 0) c = b;
    const int conv = k % 5;
    const bool reversed = conv == SNELL_DEPTH_REVERSED || conv == SNELL_DEPTH_INFINITE_REVERSED;
    // Interval test written out: distance-ordered front <= crack <= back.
    bool want = reversed ? (c <= f && c >= b) : (c >= f && c <= b);
    EXPECT_EQ(snell::snellIceCrackKeep(c, f, b, conv), want) << c << " " << f << " " << b << " " << conv;
  }
}

TEST(ShadeIceCrack, InvalidDepthsAreClipped) {
  EXPECT_TRUE(snell::snellIceCrackKeep(0.5f, 0.4f, 0.6f, SNELL_DEPTH_GL));
  EXPECT_TRUE(snell::snellIceCrackKeep(0.0f, 0.0f, 1.0f, SNELL_DEPTH_GL));
  EXPECT_FALSE(snell::snellIceCrackKeep(0.5f, 0.6f, 0.4f, SNELL_DEPTH_GL));  // empty interval
  EXPECT_TRUE(snell::snellIceCrackKeep(0.5f, 0.6f, 0.4f, SNELL_DEPTH_REVERSED));
  for (float bad : {kNaN, kInf, -kInf, -0.1f, 1.1f}) {
    EXPECT_FALSE(snell::snellIceCrackKeep(bad, 0.0f, 1.0f, SNELL_DEPTH_GL)) << bad;
    EXPECT_FALSE(snell::snellIceCrackKeep(0.5f, bad, 1.0f, SNELL_DEPTH_GL)) << bad;
    EXPECT_FALSE(snell::snellIceCrackKeep(0.5f, 0.0f, bad, SNELL_DEPTH_GL)) << bad;
  }
  EXPECT_FALSE(snell::snellIceCrackKeep(0.5f, 0.4f, 0.6f, 5));
  EXPECT_FALSE(snell::snellIceCrackKeep(0.5f, 0.4f, 0.6f, -1));
}

// --- refractive texture mapping -----------------------------------------------

struct RtmRef {
  bool hit;
  dvec3 p;
  dvec2 uv;  // eqs. 12-13, before any policy
};

// Listing 4 in double: camera_ray = eye - vertex (normalized), refracted =
// -(n k + camera_ray) (normalized); then the parametric line (eq. 9) meets the
// map plane y = restY - depth: t from the y equation (eq. 10).
RtmRef rtmReference(dvec3 v, dvec3 n, dvec3 eye, double k, double restY, double depth, dvec2 lo, dvec2 hi) {
  dvec3 cam = glm::normalize(eye - v);
  n = glm::normalize(n);
  if (glm::dot(cam, n) < 0.0) n = -n;  // the normal faces the eye
  dvec3 rf = glm::normalize(-(n * k + cam));
  RtmRef r{};
  double planeY = restY - depth;
  double t = (planeY - v.y) / rf.y;
  r.hit = rf.y < 0.0 && t >= 0.0;
  r.p = r.hit ? v + rf * t : dvec3(v.x, planeY, v.z);
  r.uv = dvec2((r.p.x - lo.x) / (hi.x - lo.x), (r.p.z - lo.y) / (hi.y - lo.y));
  return r;
}

TEST(ShadeRefractiveTextureMap, HitsThePlanarMapLikeAParametricSolve) {
  Rng r;
  int hits = 0, inRange = 0;
  for (int k = 0; k < 20000; ++k) {
    vec2 lo(r.uniform(-10, 0), r.uniform(-10, 0));
    vec2 hi = lo + vec2(r.uniform(1, 20), r.uniform(1, 20));
    float restY = r.uniform(-2, 2), depth = r.uniform(0.1f, 5.0f), factor = r.uniform(0.0f, 3.0f);
    vec3 v(r.uniform(lo.x, hi.x), restY + r.uniform(-0.3f, 0.3f), r.uniform(lo.y, hi.y));
    vec3 n = glm::normalize(vec3(r.uniform(-0.5f, 0.5f), 1.0f, r.uniform(-0.5f, 0.5f)));
    vec3 eye(r.uniform(-20, 20), r.uniform(1, 20) + restY, r.uniform(-20, 20));
    snell::SnellRefractiveTextureMapParams p = snell::snellRefractiveTextureMapParams(lo, hi, restY, depth, factor);
    snell::SnellRefractiveTextureMapHit h = snell::snellRefractiveTextureMap(v, n, eye, p);
    RtmRef ref = rtmReference(v, n, eye, factor, restY, depth, lo, hi);
    // Near-horizontal rays: t is ill-conditioned; skip those within the epsilon.
    if (ref.hit && std::fabs((double(restY) - double(depth) - double(v.y)) / glm::length(ref.p - dvec3(v))) < 1e-3) continue;
    ASSERT_EQ(h.valid, ref.hit) << k;
    double scale = 1.0 + glm::length(ref.p - dvec3(v));
    EXPECT_NEAR(h.position.x, ref.p.x, 2e-5 * scale) << k;
    EXPECT_NEAR(h.position.y, ref.p.y, 2e-5 * scale) << k;
    EXPECT_NEAR(h.position.z, ref.p.z, 2e-5 * scale) << k;
    dvec2 want = glm::clamp(ref.uv, dvec2(0.0), dvec2(1.0));  // default: clamp to [0, 1]
    double uvTol = 2e-5 * scale / double(std::min(hi.x - lo.x, hi.y - lo.y));
    EXPECT_NEAR(h.uv.x, want.x, uvTol) << k;
    EXPECT_NEAR(h.uv.y, want.y, uvTol) << k;
    bool in = ref.uv.x > 1e-4 && ref.uv.x < 1 - 1e-4 && ref.uv.y > 1e-4 && ref.uv.y < 1 - 1e-4;
    bool out = ref.uv.x < -1e-4 || ref.uv.x > 1 + 1e-4 || ref.uv.y < -1e-4 || ref.uv.y > 1 + 1e-4;
    if (ref.hit && in) {
      EXPECT_TRUE(h.inRange);
    }
    if (out || !ref.hit) {
      EXPECT_FALSE(h.inRange);
    }
    hits += ref.hit;
    inRange += h.inRange;
  }
  EXPECT_GT(hits, 15000);
  EXPECT_GT(inRange, 5000);
}

TEST(ShadeRefractiveTextureMap, StraightDownAndFactorZero) {
  // Eye straight above: the ray goes straight down whatever the factor.
  snell::SnellRefractiveTextureMapParams p =
      snell::snellRefractiveTextureMapParams(vec2(0.0f), vec2(10.0f, 20.0f), 0.0f, 2.0f, 0.7f);
  snell::SnellRefractiveTextureMapHit h = snell::snellRefractiveTextureMap(vec3(2.5f, 0.5f, 5.0f), vec3(0, 1, 0),
                                                                           vec3(2.5f, 10.0f, 5.0f), p);
  EXPECT_TRUE(h.valid);
  EXPECT_TRUE(h.inRange);
  EXPECT_NEAR(h.position.x, 2.5f, 1e-6f);
  EXPECT_NEAR(h.position.y, -2.0f, 1e-6f);
  EXPECT_NEAR(h.uv.x, 0.25f, 1e-6f);
  EXPECT_NEAR(h.uv.y, 0.25f, 1e-6f);
  // Factor 0: the ray continues the eye ray (eye (0,4,0), vertex (1,2,0): it
  // drops 2 per 1 in x, so 4 more down (depth 2 + 2 above rest) is 2 more in x).
  p = snell::snellRefractiveTextureMapParams(vec2(0.0f), vec2(10.0f), 0.0f, 2.0f, 0.0f);
  h = snell::snellRefractiveTextureMap(vec3(1.0f, 2.0f, 0.5f), vec3(0, 1, 0), vec3(0.0f, 4.0f, 0.5f), p);
  EXPECT_TRUE(h.valid);
  EXPECT_NEAR(h.position.x, 3.0f, 1e-5f);
  EXPECT_NEAR(h.position.y, -2.0f, 1e-6f);
  // A reversed z extent flips v (Listing 4's DirectX 7 v).
  p = snell::snellRefractiveTextureMapParams(vec2(0.0f, 20.0f), vec2(10.0f, 0.0f), 0.0f, 2.0f, 0.7f);
  h = snell::snellRefractiveTextureMap(vec3(2.5f, 0.0f, 5.0f), vec3(0, 1, 0), vec3(2.5f, 10.0f, 5.0f), p);
  EXPECT_NEAR(h.uv.y, 0.75f, 1e-6f);
}

TEST(ShadeRefractiveTextureMap, BothOutOfRangePolicies) {
  Rng r;
  for (int k = 0; k < 20000; ++k) {
    vec2 lo(0.0f), hi(10.0f, 10.0f);
    vec3 v(r.uniform(0, 10), 0.0f, r.uniform(0, 10));
    vec3 eye(r.uniform(-30, 30), r.uniform(1, 10), r.uniform(-30, 30));
    float depth = r.uniform(0.5f, 5.0f);
    snell::SnellRefractiveTextureMapParams p = snell::snellRefractiveTextureMapParams(lo, hi, 0.0f, depth, 0.3f);
    float a = r.uniform(0.0f, 0.3f), b = r.uniform(0.7f, 1.0f);
    p.uvMin = a;
    p.uvMax = b;
    RtmRef ref = rtmReference(v, vec3(0, 1, 0), eye, 0.3, 0.0, depth, lo, hi);
    ASSERT_TRUE(ref.hit);
    p.policy = SNELL_RTM_CLAMP;
    snell::SnellRefractiveTextureMapHit c = snell::snellRefractiveTextureMap(v, vec3(0, 1, 0), eye, p);
    EXPECT_NEAR(c.uv.x, std::clamp(ref.uv.x, double(a), double(b)), 1e-5);
    EXPECT_NEAR(c.uv.y, std::clamp(ref.uv.y, double(a), double(b)), 1e-5);
    p.policy = SNELL_RTM_SHRINK;
    snell::SnellRefractiveTextureMapHit s = snell::snellRefractiveTextureMap(v, vec3(0, 1, 0), eye, p);
    EXPECT_NEAR(s.uv.x, std::clamp(double(a) + (double(b) - double(a)) * ref.uv.x, 0.0, 1.0), 1e-5);
    EXPECT_NEAR(s.uv.y, std::clamp(double(a) + (double(b) - double(a)) * ref.uv.y, 0.0, 1.0), 1e-5);
    EXPECT_EQ(c.inRange, s.inRange);
  }
  // The shrunk interval m / (L + 2m) keeps rays reaching m beyond the edge in range.
  const float L = 10.0f, m = 2.0f;
  snell::SnellRefractiveTextureMapParams p = snell::snellRefractiveTextureMapParams(vec2(0.0f), vec2(L), 0.0f, 1.0f, 0.0f);
  p.policy = SNELL_RTM_SHRINK;
  p.uvMin = m / (L + 2.0f * m);
  p.uvMax = 1.0f - p.uvMin;
  // Vertex at x = 0, eye ray dropping 1 per 2 in -x: lands at x = -2 = -m.
  snell::SnellRefractiveTextureMapHit h =
      snell::snellRefractiveTextureMap(vec3(0.0f, 0.0f, 5.0f), vec3(0, 1, 0), vec3(4.0f, 2.0f, 5.0f), p);
  EXPECT_NEAR(h.position.x, -2.0f, 1e-5f);
  EXPECT_FALSE(h.inRange);
  EXPECT_NEAR(h.uv.x, 0.0f, 1e-6f);
  EXPECT_NEAR(h.uv.y, 0.5f, 1e-6f);
  // Swapped / NaN / out-of-[0,1] interval bounds.
  p.policy = SNELL_RTM_CLAMP;
  p.uvMin = 0.8f;
  p.uvMax = 0.2f;
  h = snell::snellRefractiveTextureMap(vec3(0.0f, 0.0f, 5.0f), vec3(0, 1, 0), vec3(4.0f, 2.0f, 5.0f), p);
  EXPECT_NEAR(h.uv.x, 0.2f, 1e-7f);
  p.uvMin = kNaN;
  p.uvMax = 5.0f;
  h = snell::snellRefractiveTextureMap(vec3(0.0f, 0.0f, 5.0f), vec3(0, 1, 0), vec3(4.0f, 2.0f, 5.0f), p);
  EXPECT_EQ(h.uv.x, 0.0f);
}

TEST(ShadeRefractiveTextureMap, NoHitAndHostileInputs) {
  snell::SnellRefractiveTextureMapParams p =
      snell::snellRefractiveTextureMapParams(vec2(0.0f), vec2(10.0f), 0.0f, 1.0f, 0.5f);
  // Vertex below the map: no hit; straight-down fallback.
  snell::SnellRefractiveTextureMapHit h =
      snell::snellRefractiveTextureMap(vec3(2.0f, -3.0f, 4.0f), vec3(0, 1, 0), vec3(0, 5, 0), p);
  EXPECT_FALSE(h.valid);
  EXPECT_FALSE(h.inRange);
  EXPECT_EQ(h.position, vec3(2.0f, -1.0f, 4.0f));
  EXPECT_NEAR(h.uv.x, 0.2f, 1e-7f);
  // Eye below the surface looking up: the ray goes up.
  h = snell::snellRefractiveTextureMap(vec3(2.0f, 0.0f, 4.0f), vec3(0, 1, 0), vec3(2.0f, -0.5f, 3.0f), p);
  EXPECT_FALSE(h.valid);
  const float bad[] = {kNaN, kInf, -kInf};
  for (float x : bad) {
    snell::SnellRefractiveTextureMapHit hs[] = {
        snell::snellRefractiveTextureMap(vec3(x), vec3(0, 1, 0), vec3(0, 5, 0), p),
        snell::snellRefractiveTextureMap(vec3(1.0f), vec3(x), vec3(0, 5, 0), p),
        snell::snellRefractiveTextureMap(vec3(1.0f), vec3(0, 1, 0), vec3(x), p),
        snell::snellRefractiveTextureMap(vec3(1.0f), vec3(0, 1, 0), vec3(0, 5, 0),
                                         snell::snellRefractiveTextureMapParams(vec2(x), vec2(10.0f), x, x, x))};
    for (const auto& q : hs) {
      EXPECT_TRUE(std::isfinite(q.uv.x) && std::isfinite(q.uv.y)) << x;
      EXPECT_TRUE(std::isfinite(q.position.x) && std::isfinite(q.position.y) && std::isfinite(q.position.z)) << x;
      EXPECT_TRUE(q.uv.x >= 0.0f && q.uv.x <= 1.0f && q.uv.y >= 0.0f && q.uv.y <= 1.0f);
    }
  }
  EXPECT_EQ(snell::snellRefractiveTextureMapAxis(kNaN, 0.0f, 1.0f), 0.5f);
  EXPECT_EQ(snell::snellRefractiveTextureMapAxis(0.3f, 1.0f, 1.0f), 0.5f);  // empty extent
  EXPECT_EQ(snell::snellRefractiveTextureMapAxis(3e38f, -3e38f, 1.0f), 1e6f);
  EXPECT_NEAR(snell::snellRefractiveTextureMapAxis(0.25f, 1.0f, 0.0f), 0.75f, 1e-7f);
}

// --- dispersion ------------------------------------------------------------------

TEST(ShadeDispersion, AbbeNumberAndOrdering) {
  Rng r;
  for (int k = 0; k < 5000; ++k) {
    float nd = r.uniform(1.05f, 2.5f), v = r.uniform(15.0f, 90.0f);
    vec3 n = snell::snellDispersionIors(nd, v);
    EXPECT_GT(n.z, n.y);  // blue (F) > green (d) > red (C)
    EXPECT_GT(n.y, n.x);
    EXPECT_NEAR(n.y, nd, 1e-6f);
    // Abbe's definition: V = (n_d - 1) / (n_F - n_C).
    EXPECT_NEAR((double(nd) - 1.0) / (double(n.z) - double(n.x)), double(v), 1e-3 * double(v)) << nd << " " << v;
  }
  // BK7 (n_d 1.5168, V 64.17): catalogue n_F - n_C = 0.00805.
  vec3 bk7 = snell::snellDispersionIors(1.5168f, 64.17f);
  EXPECT_NEAR(bk7.z - bk7.x, 0.00805f, 2e-5f);
}

TEST(ShadeDispersion, HostileInputs) {
  EXPECT_EQ(snell::snellDispersionIors(kNaN, 50.0f), vec3(1.0f));
  EXPECT_EQ(snell::snellDispersionIors(0.0f, 50.0f), vec3(1.0f));
  EXPECT_EQ(snell::snellDispersionIors(kInf, 50.0f), vec3(1.0f));
  EXPECT_EQ(snell::snellDispersionIors(1.5f, kNaN), vec3(1.5f));
  EXPECT_EQ(snell::snellDispersionIors(1.5f, 0.0f), vec3(1.5f));
  EXPECT_EQ(snell::snellDispersionIors(1.5f, kInf), vec3(1.5f));
  EXPECT_EQ(snell::snellDispersionIors(1.5f, 0.01f), snell::snellDispersionIors(1.5f, 1.0f));
  vec3 n = snell::snellDispersionIors(1e-30f, 1.0f);
  EXPECT_TRUE(n.x >= 1e-6f && n.z <= 1e6f);
}

TEST(ShadeDispersion, BlueBendsMost) {
  Rng r;
  for (int k = 0; k < 5000; ++k) {
    vec3 nrm = r.unit();
    vec3 d = r.unit();
    if (glm::dot(d, nrm) > -0.05f) d = glm::reflect(d, nrm) - nrm * 0.1f;
    vec3 iors = snell::snellDispersionIors(r.uniform(1.3f, 1.9f), r.uniform(20.0f, 60.0f));
    snell::SnellDispersion s = snell::snellDispersionRefract(d, nrm, 1.0f, iors, SNELL_TIR_CRITICAL);
    ASSERT_TRUE(s.valid);
    EXPECT_FALSE(s.tir);
    // Snell per channel, in sines: sin_t = sin_i / n_c.
    double sinI = sinBetween(dvec3(d), dvec3(nrm));
    EXPECT_NEAR(sinBetween(dvec3(s.red), dvec3(nrm)), sinI / double(iors.x), 2e-5);
    EXPECT_NEAR(sinBetween(dvec3(s.blue), dvec3(nrm)), sinI / double(iors.z), 2e-5);
    // Deviation from the incident direction: blue > green > red.
    double devR = std::acos(std::clamp(glm::dot(glm::normalize(dvec3(d)), dvec3(s.red)), -1.0, 1.0));
    double devB = std::acos(std::clamp(glm::dot(glm::normalize(dvec3(d)), dvec3(s.blue)), -1.0, 1.0));
    if (sinI > 0.1) {
      EXPECT_GT(devB, devR);
    }
  }
  // TIR in any channel is reported; invalid vectors give invalid and zeros.
  snell::SnellDispersion t = snell::snellDispersionRefract(glm::normalize(vec3(1.0f, 0.0f, -0.2f)), vec3(0, 0, 1),
                                                           1.5f, vec3(1.0f, 1.0f, 1.0f), SNELL_TIR_ZERO);
  EXPECT_TRUE(t.tir);
  EXPECT_TRUE(t.valid);
  EXPECT_EQ(t.red, vec3(0.0f));
  snell::SnellDispersion bad = snell::snellDispersionRefract(vec3(kNaN), vec3(0, 0, 1), 1.0f, vec3(1.5f), 0);
  EXPECT_FALSE(bad.valid);
  EXPECT_EQ(bad.blue, vec3(0.0f));
}

// --- roughness -> lod -----------------------------------------------------------

TEST(ShadeRoughness, MonotoneAndWithinTheChain) {
  for (int levels : {1, 2, 5, 11, 14}) {
    float prev = -1.0f;
    for (int i = 0; i <= 10000; ++i) {
      float r = float(i) / 10000.0f;
      float lod = snell::snellRoughnessToLod(r, levels);
      EXPECT_GE(lod, prev);
      EXPECT_GE(lod, 0.0f);
      EXPECT_LE(lod, float(levels - 1));
      EXPECT_NEAR(lod, double(levels - 1) * double(r) * (2.0 - double(r)), 1e-5 * levels);
      prev = lod;
    }
    EXPECT_EQ(snell::snellRoughnessToLod(0.0f, levels), 0.0f);
    EXPECT_EQ(snell::snellRoughnessToLod(1.0f, levels), float(levels - 1));
  }
  EXPECT_EQ(snell::snellRoughnessToLod(kNaN, 8), 0.0f);
  EXPECT_EQ(snell::snellRoughnessToLod(-2.0f, 8), 0.0f);
  EXPECT_EQ(snell::snellRoughnessToLod(kInf, 8), 7.0f);
  EXPECT_EQ(snell::snellRoughnessToLod(0.5f, 0), 0.0f);
  EXPECT_EQ(snell::snellRoughnessToLod(0.5f, -3), 0.0f);
}

}  // namespace
