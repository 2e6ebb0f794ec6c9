// The fields of two-interface refraction that the scene-wide tests
// (technique_two_interface_test.cpp) do not look at, each against its
// contract (glsl/snell/shade/two_interface.glsl, two_interface_shade.glsl):
// the invalid path, the fallbacks, the fetch counts, the exit slot's
// environment, edge fade and foreground rule, the Fresnel blend with the
// reflection, and an opaque surface inside the object. The expected values
// come from double-precision optics (glm::refract, glm::reflect, the Fresnel
// equations) and from buffers whose content is known everywhere (constant
// colours, planes).
#include <gtest/gtest.h>

#include <snell/snell.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <new>

#include "support/technique_scene.hpp"
#include "support/rough_read.hpp"
#include "support/texel_density.hpp"

namespace {

using namespace snell;
using glm::dvec3;
using technique_test::Scene;

constexpr double kIor = 1.5;
const float kNaN = std::numeric_limits<float>::quiet_NaN();

// Runs f with its result constructed in storage filled with a non-zero byte pattern (the callee builds its
// result in place: C++17 guaranteed elision plus the named return value), so a field the function leaves
// unset shows up as garbage rather than as a lucky zero.
template <class R, class F>
R inPoisonedStorage(F f) {
  alignas(R) unsigned char storage[sizeof(R)];
  std::memset(storage, 0xA5, sizeof storage);
  R* r = ::new (static_cast<void*>(storage)) R(f());
  R out = *r;
  r->~R();
  return out;
}

// A bool read from such storage: its byte must hold false (0); a test of the bool itself would be undefined.
bool storedFalse(const bool& b) {
  unsigned char byte;
  std::memcpy(&byte, &b, 1);
  return byte == 0;
}

const Scene& smallScene() {
  static const Scene s = technique_test::makeScene(64, 64);
  return s;
}

// Two colours split by longitude: A around the view direction -z (u in [0.25, 0.75]), B around +z.
const vec3 kAhead(0.2f, 0.5f, 0.9f), kBehind(0.8f, 0.3f, 0.1f);
Texture2D twoHalvesEnvironment() {
  Image img(64, 32, glm::vec4(kBehind, 1.0f));
  for (int j = 0; j < 32; ++j)
    for (int i = 16; i < 48; ++i) img.at(i, j) = glm::vec4(kAhead, 1.0f);
  return Texture2D(img, Filter::Linear);
}

// The unpolarized Fresnel reflectance (Born & Wolf sec. 1.5.2), eta = n_i / n_t.
double fresnel(double cosI, double eta) {
  cosI = std::abs(cosI);
  const double sinT2 = eta * eta * (1.0 - cosI * cosI);
  if (sinT2 >= 1.0) return 1.0;
  const double cosT = std::sqrt(1.0 - sinT2);
  const double rs = (eta * cosI - cosT) / (eta * cosI + cosT), rp = (cosI - eta * cosT) / (cosI + eta * cosT);
  return 0.5 * (rs * rs + rp * rp);
}

SnellTwoInterfacePath traceIn(const Scene& s, glm::vec3 p1, glm::vec3 n1, float eta, const SnellTechnique& t,
                              int tirPolicy, float dN = 0.0f) {
  return snellTwoInterfaceTrace(p1, n1, eta, dN, TECH_OBJECT_ARGS(s), t, tirPolicy);
}

// ---------------------------------------------------------------------------------------------------------
// snellTwoInterfaceTrace

// The contract: T1 invalid or zero makes the whole path invalid with every vector 0 and no fetch.
TEST(TwoInterfaceTraceFields, InvalidEntryLeavesEveryFieldAtItsEmptyValue) {
  const Scene& s = smallScene();
  const SnellTechnique t = snellTechnique();
  const glm::vec3 p1(0.1f, 0.2f, -4.0f), n1(0.0f, 0.0f, 1.0f);
  struct Case {
    const char* what;
    glm::vec3 p1, n1;
    float eta;
    int tirPolicy;
  };
  // From inside glass (eta 1.5) at 60 deg the first interface reflects totally: ZERO gives no T1.
  const glm::vec3 grazing(std::sqrt(3.0f), 0.0f, -1.0f);
  const Case cases[] = {{"NaN position", glm::vec3(kNaN, 0.0f, -4.0f), n1, 1.0f / 1.5f, SNELL_TIR_CRITICAL},
                        {"zero normal", p1, glm::vec3(0.0f), 1.0f / 1.5f, SNELL_TIR_CRITICAL},
                        {"NaN eta", p1, n1, kNaN, SNELL_TIR_CRITICAL},
                        {"TIR under ZERO", grazing, n1, 1.5f, SNELL_TIR_ZERO}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    const SnellTwoInterfacePath p = inPoisonedStorage<SnellTwoInterfacePath>(
        [&] { return traceIn(s, c.p1, c.n1, c.eta, t, c.tirPolicy); });
    EXPECT_TRUE(storedFalse(p.valid));
    EXPECT_TRUE(storedFalse(p.hit));
    EXPECT_TRUE(storedFalse(p.tir));
    EXPECT_TRUE(storedFalse(p.exitFront));
    EXPECT_TRUE(p.fellBack);
    EXPECT_EQ(p.fetches, 0);
    EXPECT_EQ(p.bounces, 0);
    EXPECT_EQ(p.entryDirection, glm::vec3(0.0f));
    EXPECT_EQ(p.exitPoint, glm::vec3(0.0f));
    EXPECT_EQ(p.exitNormal, glm::vec3(0.0f));
    EXPECT_EQ(p.exitDirection, glm::vec3(0.0f));
    EXPECT_EQ(p.exitUv, glm::vec2(0.0f));
    EXPECT_EQ(p.pathLength, 0.0f);
    EXPECT_EQ(p.entryLength, 0.0f);
    EXPECT_EQ(p.exitIncident, glm::vec3(0.0f));
  }
}

// SNELL_SOURCE_ENVIRONMENT in the back slot: no back-face read; the ray leaves at P1 along T1 (a thin surface).
TEST(TwoInterfaceTraceFields, EnvironmentBackSlotReadsNothingAndLeavesAtP1AlongT1) {
  const Scene& s = smallScene();
  SnellTechnique t = snellTechnique();
  t.back.source = SNELL_SOURCE_ENVIRONMENT;
  const glm::vec3 p1(0.4f, -0.3f, -3.9f), n1 = glm::normalize(glm::vec3(0.1f, -0.2f, 1.0f));
  const dvec3 t1 = glm::refract(glm::normalize(dvec3(p1)), glm::normalize(dvec3(n1)), 1.0 / kIor);
  const SnellTwoInterfacePath p = inPoisonedStorage<SnellTwoInterfacePath>(
      [&] { return traceIn(s, p1, n1, snellIorToEta(1.0f, 1.5f), t, SNELL_TIR_CRITICAL); });
  EXPECT_TRUE(p.valid);
  EXPECT_TRUE(storedFalse(p.hit));
  EXPECT_TRUE(p.fellBack);
  EXPECT_TRUE(storedFalse(p.tir));
  EXPECT_EQ(p.fetches, 0);
  EXPECT_EQ(p.bounces, 0);
  EXPECT_EQ(p.exitPoint, p1);
  EXPECT_EQ(p.pathLength, 0.0f);
  EXPECT_EQ(p.entryLength, 0.0f);
  EXPECT_LT(glm::length(dvec3(p.entryDirection) - t1), 1e-6);
  EXPECT_LT(glm::length(dvec3(p.exitDirection) - t1), 1e-6);
  EXPECT_EQ(p.exitIncident, glm::vec3(0.0f));  // T2 is no refraction here
}

// Wyman's variant: one read of the back depth at P1's projection, then snellHitOnSurface at his P2 (2 fetches),
// and the normal read at the hit (1 more). Over an empty back texel only the first read is made.
TEST(TwoInterfaceTraceFields, WymanCountsItsDepthReadsAndFallsBackOverAnEmptyTexel) {
  const Scene& s = smallScene();
  SnellTechnique t = snellPresetIsr();
  ASSERT_EQ(t.back.source, SNELL_SOURCE_WYMAN);
  const float eta = snellIorToEta(1.0f, 1.5f), dN = float(2.0 * technique_test::kRadius);
  const technique_test::Exact e = technique_test::exactTrace(s.front, glm::dvec2(0.5, 0.5), kIor);
  ASSERT_TRUE(e.hitsSphere);
  const SnellTwoInterfacePath hit = traceIn(s, glm::vec3(e.p1), glm::vec3(e.n1), eta, t, SNELL_TIR_CRITICAL, dN);
  EXPECT_TRUE(hit.hit);
  EXPECT_FALSE(hit.fellBack);
  EXPECT_EQ(hit.fetches, 3);
  // Near normal incidence Wyman's estimate is the chord itself.
  EXPECT_LT(glm::length(dvec3(hit.exitPoint) - e.p2), 0.05);
  // Beside the sphere (its silhouette ends at x = 2.5 at the centre's depth) the back buffer is empty there.
  const glm::vec3 beside(3.2f, -0.2f, -6.0f);
  const SnellTwoInterfacePath none = traceIn(s, beside, glm::vec3(0.0f, 0.0f, 1.0f), eta, t, SNELL_TIR_CRITICAL, dN);
  EXPECT_TRUE(none.valid);
  EXPECT_FALSE(none.hit);
  EXPECT_TRUE(none.fellBack);
  EXPECT_EQ(none.fetches, 1);
  EXPECT_EQ(none.exitPoint, beside);
  EXPECT_EQ(none.pathLength, 0.0f);
}

// At the back hit N2 is the back face's normal turned to face T1 (the buffer stores it outward, along T1),
// T2 refracts out about it, and the counts are the strategy's plus the normal read.
TEST(TwoInterfaceTraceFields, BackHitNormalFacesT1AndTheCountAddsTheNormalRead) {
  const Scene& s = smallScene();
  SnellTechnique t = snellPresetPlaneDepth(3);
  const float eta = snellIorToEta(1.0f, 1.5f);
  int checked = 0;
  for (const glm::dvec2 uv : {glm::dvec2(0.5, 0.5), glm::dvec2(0.42, 0.57), glm::dvec2(0.58, 0.44)}) {
    const technique_test::Exact e = technique_test::exactTrace(s.front, uv, kIor);
    ASSERT_TRUE(e.hitsSphere && !e.tir);
    const SnellTwoInterfacePath p = traceIn(s, glm::vec3(e.p1), glm::vec3(e.n1), eta, t, SNELL_TIR_CRITICAL);
    ASSERT_TRUE(p.hit);
    EXPECT_FALSE(p.fellBack);
    const SnellHit h = snellIntersectWith(glm::vec3(e.p1), p.entryDirection, s.back.depth, s.backNormalMips,
                                          s.backPyramid, s.backSurface(), t.back.intersect);
    EXPECT_EQ(p.fetches, h.fetches + 1);
    EXPECT_EQ(p.exitUv, h.uv);
    EXPECT_LE(glm::dot(p.exitNormal, p.entryDirection), 0.0f);
    EXPECT_LT(glm::length(dvec3(p.exitNormal) + e.n2), 0.03);
    EXPECT_LT(glm::length(dvec3(p.exitDirection) - e.t2), 0.05);
    EXPECT_EQ(p.exitIncident, p.entryDirection);
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}

// Rough glass leaves along the rough refraction of the ray that met the last interface
// (optics/refract_rough.glsl, tested against GGX's slopes on its own); smooth glass along the trace's ray, bit
// for bit. On the view axis T1 is (0, 0, -1); back normals stored at phi from it take the exit through the
// critical angle (41.8 deg): past it the smooth ray grazes the back face, the rough one leaves it.
TEST(TwoInterfaceShadeFields, RoughGlassLeavesAlongTheRoughRefraction) {
  Scene s = smallScene();
  const SnellTechnique t = snellPresetPlaneDepth(3);
  const float eta = snellIorToEta(1.0f, 1.5f);
  SnellMaterial m = snellMaterial();
  m.reflection = false;
  m.tirPolicy = SNELL_TIR_CRITICAL;
  const SnellView v = snellView();
  const glm::vec3 p1(0.0f, 0.0f, -4.0f), n1(0.0f, 0.0f, 1.0f);
  int pastCritical = 0;
  for (int deg = 30; deg <= 56; deg += 2) {
    const double phi = deg * 3.14159265358979323846 / 180.0;
    const glm::vec3 stored(static_cast<float>(std::sin(phi)), 0.0f, static_cast<float>(std::cos(phi)));
    s.backNormalMips = Texture2D(Image(s.width, s.height, glm::vec4(stored, 0.0f)));
    const SnellTwoInterfacePath p = traceIn(s, p1, n1, eta, t, SNELL_TIR_CRITICAL);
    ASSERT_TRUE(p.hit && !p.fellBack) << deg;
    ASSERT_EQ(p.exitIncident, glm::vec3(0.0f, 0.0f, -1.0f));
    m.roughness = 0.0f;
    const SnellTwoInterfaceResult smooth =
        snellTwoInterfaceRefraction(p1, n1, 0.0f, TECH_OBJECT_ARGS(s), TECH_SCENE_ARGS(s), t, m, v);
    m.roughness = 0.3f;
    const SnellTwoInterfaceResult rough =
        snellTwoInterfaceRefraction(p1, n1, 0.0f, TECH_OBJECT_ARGS(s), TECH_SCENE_ARGS(s), t, m, v);
    EXPECT_EQ(smooth.exitDirection, p.exitDirection) << deg;
    EXPECT_EQ(rough.exitDirection,
              snellRefractRough(p.exitIncident, p.exitNormal, 1.0f / eta, 0.09f, SNELL_TIR_CRITICAL).direction)
        << deg;
    EXPECT_EQ(rough.tir, deg >= 42) << deg;
    if (p.tir) {
      EXPECT_LT(std::abs(glm::dot(smooth.exitDirection, p.exitNormal)), 1e-5f) << deg;
      EXPECT_GT(-glm::dot(rough.exitDirection, p.exitNormal), 0.1f) << deg;
      ++pastCritical;
    }
  }
  EXPECT_EQ(pastCritical, 8);
}

// N2 faces T1 after the turn: a stored normal tilted towards T1 by as little as a denormal is negated; one
// exactly perpendicular to T1 (dot 0: it faces neither way) is kept as stored. On the view axis at normal
// incidence T1 is exactly (0, 0, -1), so both dot products are exact.
TEST(TwoInterfaceTraceFields, NormalAtTheBackIsTurnedToFaceT1ByAnyTilt) {
  const Scene& s = smallScene();
  const SnellTechnique t = snellPresetPlaneDepth(3);
  const float tiny = 1e-39f;
  ASSERT_GT(tiny, 0.0f);
  for (const glm::vec3 stored : {glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(1.0f, 0.0f, -tiny)}) {
    const Texture2D normals(Image(s.width, s.height, glm::vec4(stored, 0.0f)));
    const SnellTwoInterfacePath p = snellTwoInterfaceTrace(
        glm::vec3(0.0f, 0.0f, -4.0f), glm::vec3(0.0f, 0.0f, 1.0f), snellIorToEta(1.0f, 1.5f), 0.0f, s.back.depth,
        normals, s.backPyramid, s.backSurface(), s.front.depth, s.front.normals, s.frontSurface(), t, SNELL_TIR_CRITICAL);
    ASSERT_TRUE(p.hit);
    ASSERT_EQ(p.entryDirection, glm::vec3(0.0f, 0.0f, -1.0f));
    EXPECT_LE(glm::dot(p.exitNormal, p.entryDirection), 0.0f) << stored.z;
    EXPECT_EQ(p.exitNormal, stored.z == 0.0f ? stored : -stored);
  }
}

// ---------------------------------------------------------------------------------------------------------
// snellTwoInterfaceRefraction: the reflection at the first interface

// Everything resolved by the environment: the transmitted colour is the environment along T1 (no back slot:
// the thin-surface fallback), the reflection the environment along R; the two lie in different halves of it.
TEST(TwoInterfaceShadeFields, ReflectionBlendsBothEnvironmentReadsByTheFresnelFactor) {
  Scene s = technique_test::makeScene(32, 32);
  s.env = twoHalvesEnvironment();
  SnellTechnique t = snellTechnique();
  t.back.source = SNELL_SOURCE_ENVIRONMENT;
  const SnellMaterial m = snellMaterial();
  ASSERT_TRUE(m.reflection);
  const SnellView v = snellView();
  int checked = 0;
  for (const glm::vec3 n1 : {glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.3f, 0.1f, 1.0f), glm::vec3(-0.4f, 0.3f, 1.0f)}) {
    const glm::vec3 p1(0.2f, 0.1f, -4.0f);
    const dvec3 vv = glm::normalize(dvec3(p1)), nn = glm::normalize(dvec3(n1));
    const double f = fresnel(glm::dot(vv, nn), 1.0 / kIor);
    const dvec3 r = glm::reflect(vv, nn);
    ASSERT_GT(r.z, 0.3);  // B's half, away from the seams (and T1 in A's)
    ASSERT_LT(glm::refract(vv, nn, 1.0 / kIor).z, -0.3);
    const SnellTwoInterfaceResult res =
        snellTwoInterfaceRefraction(p1, n1, 0.0f, TECH_OBJECT_ARGS(s), TECH_SCENE_ARGS(s), t, m, v);
    EXPECT_NEAR(res.fresnel, f, 1e-6);
    const glm::dvec3 expected = f * dvec3(kBehind) + (1.0 - f) * dvec3(kAhead);
    EXPECT_LT(glm::length(dvec3(res.color) - expected), 1e-5) << f;
    // No back read: one environment read for the exit, one for the reflection.
    EXPECT_EQ(res.fetches, 2);
    EXPECT_FALSE(res.reflectionHit.valid);
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}

// R = reflect(V, N1) is undefined at a zero position or normal: no reflection (F = 0), and the path is
// invalid too (colour 0).
TEST(TwoInterfaceShadeFields, UndefinedReflectionAddsNothing) {
  Scene s = technique_test::makeScene(32, 32);
  s.env = twoHalvesEnvironment();
  const SnellTechnique t = snellTechnique();
  const SnellMaterial m = snellMaterial();
  const SnellView v = snellView();
  for (const auto& pn : {std::make_pair(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, 1.0f)),
                         std::make_pair(glm::vec3(0.1f, 0.0f, -4.0f), glm::vec3(0.0f))}) {
    const SnellTwoInterfaceResult r =
        snellTwoInterfaceRefraction(pn.first, pn.second, 0.0f, TECH_OBJECT_ARGS(s), TECH_SCENE_ARGS(s), t, m, v);
    EXPECT_EQ(r.fresnel, 0.0f);
    EXPECT_EQ(r.color, glm::vec3(0.0f));
    EXPECT_TRUE(r.fellBack);
    EXPECT_EQ(r.fetches, 0);
    EXPECT_FALSE(r.reflectionHit.valid);
    EXPECT_EQ(r.reflectionHit.fetches, 0);
  }
}

// Without the reflection the reflect slot is never run: its hit is a miss with no fetch, F = 0. Built in
// poisoned storage, so that every field must have been written.
TEST(TwoInterfaceShadeFields, WithoutReflectionTheReflectionHitIsAMiss) {
  Scene s = technique_test::makeScene(32, 32);
  s.env = twoHalvesEnvironment();
  SnellTechnique t = snellTechnique();
  t.back.source = SNELL_SOURCE_ENVIRONMENT;
  t.reflect.source = SNELL_SOURCE_BUFFERS;
  SnellMaterial m = snellMaterial();
  m.reflection = false;
  const SnellView v = snellView();
  const SnellTwoInterfaceResult r = inPoisonedStorage<SnellTwoInterfaceResult>([&] {
    return snellTwoInterfaceRefraction(glm::vec3(0.2f, 0.1f, -4.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f,
                                       TECH_OBJECT_ARGS(s), TECH_SCENE_ARGS(s), t, m, v);
  });
  EXPECT_TRUE(storedFalse(r.reflectionHit.valid));
  EXPECT_EQ(r.reflectionHit.fetches, 0);
  EXPECT_EQ(r.fresnel, 0.0f);
  EXPECT_EQ(r.fetches, 1);
  // The path's own fields: the thin-surface fallback, no back hit, no tir, no bounce, nothing inside.
  EXPECT_TRUE(storedFalse(r.backHit));
  EXPECT_TRUE(storedFalse(r.tir));
  EXPECT_TRUE(storedFalse(r.insideHit));
  EXPECT_EQ(r.bounces, 0);
  EXPECT_TRUE(r.fellBack);
  EXPECT_LT(glm::length(r.color - kAhead), 1e-6f);
}


// Dispersion: fellBack covers every channel's trace. On the view axis at normal incidence T1 is the same for
// all three; stored back normals tilted 42 deg from it reflect red (IOR 1.56, critical angle 39.9 deg) totally,
// under SNELL_TIR_ZERO a fallback, and let green (1.45, 43.6 deg) and blue (1.40) out.
TEST(TwoInterfaceShadeFields, DispersionFallsBackWhenAnyChannelDoes) {
  const Scene& s = smallScene();
  const double tilt = 42.0 * M_PI / 180.0;
  ASSERT_GT(1.56 * std::sin(tilt), 1.0);
  ASSERT_LT(1.45 * std::sin(tilt), 1.0);
  const Texture2D tilted(
      Image(s.width, s.height, glm::vec4(float(std::sin(tilt)), 0.0f, -float(std::cos(tilt)), 0.0f)));
  SnellTechnique t = snellPresetPlaneDepth(3);
  SnellMaterial m = snellMaterial();
  m.reflection = false;
  m.tirPolicy = SNELL_TIR_ZERO;
  m.dispersion = 3;
  m.iors = glm::vec3(1.56f, 1.45f, 1.40f);
  const SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(
      glm::vec3(0.0f, 0.0f, -4.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, s.back.depth, tilted, s.backPyramid,
      s.backSurface(), s.front.depth, s.front.normals, s.frontSurface(), TECH_SCENE_ARGS(s), t, m, snellView());
  EXPECT_TRUE(r.backHit);
  EXPECT_FALSE(r.tir);  // green's
  EXPECT_TRUE(r.fellBack);
  // With red at green's IOR no channel falls back.
  m.iors = glm::vec3(1.45f, 1.45f, 1.40f);
  EXPECT_FALSE(snellTwoInterfaceRefraction(glm::vec3(0.0f, 0.0f, -4.0f), glm::vec3(0.0f, 0.0f, 1.0f), 0.0f,
                                           s.back.depth, tilted, s.backPyramid, s.backSurface(), s.front.depth,
                                           s.front.normals, s.frontSurface(), TECH_SCENE_ARGS(s), t, m, snellView())
                   .fellBack);
}

// ---------------------------------------------------------------------------------------------------------
// snellTwoInterfaceRefraction: an opaque surface inside the object (t.insideScene)

// The card of technique_two_interface_test.cpp's OpaqueCardInsideTheSphere, inside the sphere near its back.
const dvec3 kCardNormal = glm::normalize(dvec3(0.1, -0.05, 1.0));
const dvec3 kCardPoint = technique_test::kCentre + dvec3(0.0, 0.0, -1.8);

const Scene& cardScene() {
  static const Scene s = technique_test::makeScene(64, 64, kCardPoint, kCardNormal);
  return s;
}

// Distance along T1 from P1 to the card (closed-form ray-plane), and whether it lies before the back face.
double cardDistance(const technique_test::Exact& e) {
  return glm::dot(kCardPoint - e.p1, kCardNormal) / glm::dot(e.t1, kCardNormal);
}

SnellTechnique cardTechnique() {
  SnellTechnique t = snellPresetPlaneNormal(2);
  t.exit.source = SNELL_SOURCE_BUFFERS;
  t.insideScene = true;
  return t;
}

const glm::dvec2 kCardPixels[] = {glm::dvec2(0.5, 0.5), glm::dvec2(0.45, 0.53), glm::dvec2(0.55, 0.47)};

// The path ends on the card: its colour absorbed over the chord to it, the card's hit as the exit, T1 unbent,
// no tir, no bounce, no fallback; the counts add the scene search, its foreground read and the colour read.
TEST(TwoInterfaceInsideScene, CardBeforeTheBackFaceEndsThePathOnIt) {
  const Scene& s = cardScene();
  const SnellTechnique t = cardTechnique();
  SnellMaterial m = snellMaterial();
  m.reflection = false;
  m.absorption = glm::vec3(0.3f, 0.1f, 0.2f);
  const SnellView v = snellView();
  for (const glm::dvec2 uv : kCardPixels) {
    SCOPED_TRACE(testing::Message() << uv.x << ", " << uv.y);
    const technique_test::Exact e = technique_test::exactTrace(s.front, uv, kIor);
    ASSERT_TRUE(e.hitsSphere);
    const double tCard = cardDistance(e);
    ASSERT_GT(tCard, 0.0);
    ASSERT_LT(tCard, glm::length(e.p2 - e.p1) - 0.1);
    const dvec3 card = e.p1 + tCard * e.t1;
    const SnellTwoInterfaceResult r =
        snellTwoInterfaceRefraction(glm::vec3(e.p1), glm::vec3(e.n1), 0.0f, TECH_OBJECT_ARGS(s), TECH_SCENE_ARGS(s), t, m, v);
    EXPECT_TRUE(r.insideHit);
    EXPECT_TRUE(r.backHit);
    EXPECT_FALSE(r.fellBack);
    EXPECT_FALSE(r.tir);
    EXPECT_EQ(r.bounces, 0);
    EXPECT_LT(glm::length(dvec3(r.exitDirection) - e.t1), 1e-5);
    EXPECT_LT(glm::length(dvec3(r.exitPoint) - card), 0.01);
    EXPECT_TRUE(r.exitHit.valid);
    EXPECT_EQ(r.exitHit.position, r.exitPoint);
    EXPECT_NEAR(r.pathLength, tCard, 0.01);
    const dvec3 expected = dvec3(technique_test::paintingColor(card)) * glm::exp(-dvec3(m.absorption) * tCard);
    EXPECT_LT(glm::length(dvec3(r.color) - expected), 0.01);
    const SnellTwoInterfacePath path = traceIn(s, glm::vec3(e.p1), glm::vec3(e.n1), snellIorToEta(1.0f, 1.5f), t,
                                               m.tirPolicy);
    const SnellHit ih = snellIntersectWith(glm::vec3(e.p1), path.entryDirection, s.plane.depth, s.sceneNormalMips,
                                           s.scenePyramid, s.sceneSurface(), t.exit.intersect);
    ASSERT_TRUE(ih.valid);
    EXPECT_EQ(r.fetches, path.fetches + ih.fetches + 2);
  }
}

// Rough glass: the card is seen through the entry lobe alone, at the width it has reached there: radius
// s (1 - eta) |card - P1| (shade/rough_cone.glsl), at the card's texel density; a colour whose level k reads k.
TEST(TwoInterfaceInsideScene, RoughGlassReadsTheCardAtTheEntryLobesWidth) {
  Scene s = cardScene();
  Texture2D levels(Image(s.width, s.height, glm::vec4(0.0f)), Filter::Linear, MipFilter::Linear);
  for (int k = 1, w = s.width / 2; w >= 1; ++k, w /= 2) levels.addLevel(Image(w, w, glm::vec4(float(k))));
  s.sceneColor = levels;
  const SnellTechnique t = cardTechnique();
  SnellMaterial m = snellMaterial();
  m.reflection = false;
  m.roughness = 0.5f;
  SnellView v = snellView();
  v.sceneColorLevels = levels.levelCount();
  for (const glm::dvec2 uv : kCardPixels) {
    const technique_test::Exact e = technique_test::exactTrace(s.front, uv, kIor);
    const double tCard = cardDistance(e);
    const dvec3 card = e.p1 + tCard * e.t1;
    const double a = 0.25 * (1.0 - 1.0 / kIor);
    const double lod = std::clamp(std::log2(double(SNELL_ROUGH_CONE_LOD_SCALE) * a * tCard *
                                            snell_test::texelsPerUnit(s.sceneSurface().clipFromView, card, s.width, s.height)),
                                  0.0, double(levels.levelCount() - 1));
    ASSERT_GT(lod, 1.0);
    const SnellTwoInterfaceResult r =
        snellTwoInterfaceRefraction(glm::vec3(e.p1), glm::vec3(e.n1), 0.0f, TECH_OBJECT_ARGS(s), TECH_SCENE_ARGS(s), t, m, v);
    ASSERT_TRUE(r.insideHit);
    EXPECT_NEAR(r.color.x, snell_test::roughReadOfLevelTexture(lod, levels.levelCount()), 0.02) << uv.x << ", " << uv.y;
  }
}

// Whatever the path did at the back face (here its stored normals, tilted 60 deg from T1, reflect it totally,
// and an inside slot that cannot follow the bounce makes it a fallback), the card before the back face ends
// it: no tir, no bounce, no fallback.
TEST(TwoInterfaceInsideScene, CardEndsAPathThatReflectedAtTheBack) {
  const Scene& s = cardScene();
  const Texture2D tilted(Image(s.width, s.height, glm::vec4(std::sqrt(0.75f), 0.0f, -0.5f, 0.0f)));
  SnellTechnique t = cardTechnique();
  t.bounces = 1;
  t.inside.source = SNELL_SOURCE_ENVIRONMENT;
  SnellMaterial m = snellMaterial();
  m.reflection = false;
  const SnellView v = snellView();
  const technique_test::Exact e = technique_test::exactTrace(s.front, glm::dvec2(0.5, 0.5), kIor);
  const SnellTwoInterfacePath path =
      snellTwoInterfaceTrace(glm::vec3(e.p1), glm::vec3(e.n1), snellIorToEta(1.0f, 1.5f), 0.0f, s.back.depth, tilted,
                             s.backPyramid, s.backSurface(), s.front.depth, s.front.normals, s.frontSurface(), t,
                             m.tirPolicy);
  ASSERT_TRUE(path.hit && path.tir && path.fellBack);
  ASSERT_EQ(path.bounces, 1);
  const SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(
      glm::vec3(e.p1), glm::vec3(e.n1), 0.0f, s.back.depth, tilted, s.backPyramid, s.backSurface(), s.front.depth,
      s.front.normals, s.frontSurface(), TECH_SCENE_ARGS(s), t, m, v);
  EXPECT_TRUE(r.insideHit);
  EXPECT_FALSE(r.tir);
  EXPECT_EQ(r.bounces, 0);
  EXPECT_FALSE(r.fellBack);
  EXPECT_LT(glm::length(dvec3(r.exitDirection) - e.t1), 1e-5);
}

// A scene surface that is the back face itself (the scene buffers are the back buffers, searched the same
// way) is met exactly where the back hit is: not nearer, so the path goes on through the back face.
TEST(TwoInterfaceInsideScene, SurfaceOnTheBackFaceIsNotInside) {
  const Scene& s = cardScene();
  SnellTechnique t = cardTechnique();
  t.exit.intersect = t.back.intersect;
  SnellMaterial m = snellMaterial();
  m.reflection = false;
  const SnellView v = snellView();
  for (const glm::dvec2 uv : kCardPixels) {
    const technique_test::Exact e = technique_test::exactTrace(s.front, uv, kIor);
    const SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(
        glm::vec3(e.p1), glm::vec3(e.n1), 0.0f, TECH_OBJECT_ARGS(s), s.back.depth, s.backNormalMips, s.backPyramid,
        s.sceneColor, s.backSurface(), s.env, t, m, v);
    EXPECT_TRUE(r.backHit);
    EXPECT_FALSE(r.insideHit) << uv.x << ", " << uv.y;
    EXPECT_LT(glm::length(dvec3(r.exitDirection) - e.t2), 0.05);
  }
}

// A surface in front of the whole object (a pillar between it and the camera) is what a march along T1 meets
// first in the scene buffer; it is a foreground, not a surface inside the object.
TEST(TwoInterfaceInsideScene, ForegroundInFrontOfTheObjectIsNotInside) {
  const Scene pillar = technique_test::makeScene(64, 64, dvec3(0.0, 0.0, -3.0), dvec3(0.0, 0.0, 1.0));
  SnellTechnique t = cardTechnique();
  t.exit.intersect = snellIntersectOptions(SNELL_STRATEGY_LINEAR_MARCH);
  SnellMaterial m = snellMaterial();
  m.reflection = false;
  const SnellView v = snellView();
  int marchedOntoIt = 0;
  for (const glm::dvec2 uv : kCardPixels) {
    const technique_test::Exact e = technique_test::exactTrace(pillar.front, uv, kIor);
    const SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(glm::vec3(e.p1), glm::vec3(e.n1), 0.0f,
                                                                  TECH_OBJECT_ARGS(pillar), TECH_SCENE_ARGS(pillar), t, m, v);
    EXPECT_TRUE(r.backHit);
    EXPECT_FALSE(r.insideHit) << uv.x << ", " << uv.y;
    marchedOntoIt += snellIntersectWith(glm::vec3(e.p1), glm::vec3(e.t1), pillar.plane.depth, pillar.sceneNormalMips,
                                        pillar.scenePyramid, pillar.sceneSurface(), t.exit.intersect)
                         .valid;
  }
  EXPECT_GT(marchedOntoIt, 0);
}

// ---------------------------------------------------------------------------------------------------------
// snellTwoInterfaceExitRough: one slot

SnellTwoInterfaceExit exitRough(const Scene& s, const Texture2D& sceneDepth, const Texture2D& scenePyramid,
                                const Texture2D& sceneColor, glm::vec3 origin, glm::vec3 dir, const SnellSlot& slot) {
  return snellTwoInterfaceExitRough(origin, dir, snellRoughConeReflect(0.0f), sceneDepth, s.sceneNormalMips,
                                    scenePyramid, sceneColor, s.sceneSurface(), s.env, slot, snellView());
}

TEST(TwoInterfaceExitFields, ZeroDirectionReadsNothing) {
  const Scene& s = smallScene();
  for (int source : {SNELL_SOURCE_BUFFERS, SNELL_SOURCE_ENVIRONMENT}) {
    const SnellTwoInterfaceExit e = exitRough(s, s.plane.depth, s.scenePyramid, s.sceneColor,
                                              glm::vec3(0.0f, 0.0f, -4.0f), glm::vec3(0.0f),
                                              snellSlot(source, SNELL_STRATEGY_PLANE_NORMAL));
    EXPECT_EQ(e.color, glm::vec3(0.0f));
    EXPECT_TRUE(e.fellBack);
    EXPECT_EQ(e.fetches, 0);
    EXPECT_FALSE(e.hit.valid);
  }
}

// A BUFFERS slot that meets the painting: its colour at the analytic point; the strategy's reads, the
// foreground rule's and the colour read.
TEST(TwoInterfaceExitFields, SceneHitReadsTheSceneColourThere) {
  const Scene& s = smallScene();
  const SnellSlot slot = snellSlot(SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_PLANE_NORMAL);
  const glm::vec3 origin(0.3f, -0.2f, -6.0f);
  int checked = 0;
  for (const glm::dvec2 uv : {glm::dvec2(0.6, 0.45), glm::dvec2(0.35, 0.62)}) {
    const snell_test::AnalyticSample a = s.plane.sampleAt(uv);
    ASSERT_TRUE(a.valid);
    const dvec3 target = s.plane.pixelRay(uv) * a.s;
    const glm::vec3 dir = glm::vec3(target) - origin;
    const SnellTwoInterfaceExit e = exitRough(s, s.plane.depth, s.scenePyramid, s.sceneColor, origin, dir, slot);
    ASSERT_TRUE(e.hit.valid);
    EXPECT_FALSE(e.fellBack);
    EXPECT_LT(glm::length(dvec3(e.hit.position) - target), 0.01);
    EXPECT_LT(glm::length(dvec3(e.color) - dvec3(technique_test::paintingColor(target))), 0.01);
    const SnellHit h = snellIntersectWith(origin, dir, s.plane.depth, s.sceneNormalMips, s.scenePyramid,
                                          s.sceneSurface(), slot.intersect);
    EXPECT_EQ(e.fetches, h.fetches + 2);
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

// No scene hit: the environment along the ray (one read more than the strategy's), a fallback.
TEST(TwoInterfaceExitFields, MissFallsBackToTheEnvironmentAlongTheRay) {
  const Scene& s = smallScene();
  const SnellSlot slot = snellSlot(SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_LINEAR_MARCH);
  const glm::vec3 origin(0.3f, -0.2f, -6.0f), dir(1.0f, 0.2f, 0.3f);  // sideways and back: never meets the painting
  const SnellTwoInterfaceExit e = exitRough(s, s.plane.depth, s.scenePyramid, s.sceneColor, origin, dir, slot);
  EXPECT_TRUE(e.fellBack);
  EXPECT_FALSE(e.hit.valid);
  const SnellHit h = snellIntersectWith(origin, dir, s.plane.depth, s.sceneNormalMips, s.scenePyramid,
                                        s.sceneSurface(), slot.intersect);
  ASSERT_FALSE(h.valid);
  EXPECT_EQ(e.fetches, h.fetches + 1);
  EXPECT_EQ(e.color, glm::vec3(snellSampleEquirect(s.env, glm::normalize(dir), 0.0f)));
}

// EDGE_FADE over an empty scene buffer: q = origin + fallbackDistance dir / |dir| projects into the fade band,
// so the colour is mix(environment, scene colour at q, w) with w its distance to the edge over the width;
// where q projects off screen w = 0 and the scene colour is not read.
TEST(TwoInterfaceExitFields, EdgeFadeMixesTheSceneColourAtTheFallbackPoint) {
  const Scene& s = smallScene();
  const Texture2D emptyDepth(Image(s.width, s.height, glm::vec4(1.0f, 0.0f, 0.0f, 0.0f)));
  const Texture2D emptyPyramid = snellBuildDepthPyramid(emptyDepth, s.sceneSurface());
  const glm::vec3 sceneRgb(0.9f, 0.6f, 0.05f), envRgb(0.1f, 0.2f, 0.7f);
  const Texture2D sceneColor(Image(s.width, s.height, glm::vec4(sceneRgb, 1.0f)));
  Scene flat = s;
  flat.env = Texture2D(Image(16, 8, glm::vec4(envRgb, 1.0f)));
  SnellSlot slot = snellSlot(SNELL_SOURCE_BUFFERS, SNELL_STRATEGY_LINEAR_MARCH);
  slot.fallback = SNELL_FALLBACK_EDGE_FADE;
  slot.edgeFadeWidth = 0.1f;
  const glm::vec3 origin(0.0f, 0.0f, -4.0f);
  for (const double u : {0.03, 0.07, -0.05}) {
    // q at depth 6 on the pixel ray through (u, 0.5), the fallback distance the way there.
    const dvec3 q = flat.plane.pixelRay(glm::dvec2(u, 0.5)) * 6.0 / -flat.plane.pixelRay(glm::dvec2(u, 0.5)).z;
    const glm::vec3 dir = glm::vec3(q) - origin;
    slot.fallbackDistance = glm::length(dir);
    const SnellTwoInterfaceExit e = exitRough(flat, emptyDepth, emptyPyramid, sceneColor, origin, dir, slot);
    const SnellHit h = snellIntersectWith(origin, dir, emptyDepth, s.sceneNormalMips, emptyPyramid,
                                          s.sceneSurface(), slot.intersect);
    ASSERT_FALSE(h.valid);
    EXPECT_TRUE(e.fellBack);
    const double w = std::clamp(std::min(u, 1.0 - u) / 0.1, 0.0, 1.0);
    const dvec3 expected = (1.0 - w) * dvec3(envRgb) + w * dvec3(sceneRgb);
    EXPECT_LT(glm::length(dvec3(e.color) - expected), 1e-4) << u;
    EXPECT_EQ(e.fetches, h.fetches + (w > 0.0 ? 2 : 1)) << u;
  }
}

// The foreground rule: a surface between the camera and the whole ray (a pillar in front of the glass) is
// what a strategy lands on first, and is refused; the ray falls back to the environment.
TEST(TwoInterfaceExitFields, SurfaceInFrontOfTheWholeRayIsRefused) {
  const Scene pillar = technique_test::makeScene(64, 64, dvec3(0.0, 0.0, -3.0), dvec3(0.0, 0.0, 1.0));
  const glm::vec3 origin(0.2f, 0.1f, -6.0f), dir(0.05f, 0.0f, -1.0f);
  for (int strategy : {SNELL_STRATEGY_LINEAR_MARCH, SNELL_STRATEGY_SINGLE}) {
    const SnellSlot slot = snellSlot(SNELL_SOURCE_BUFFERS, strategy);
    const SnellHit h = snellIntersectWith(origin, dir, pillar.plane.depth, pillar.sceneNormalMips,
                                          pillar.scenePyramid, pillar.sceneSurface(), slot.intersect);
    const SnellTwoInterfaceExit e =
        exitRough(pillar, pillar.plane.depth, pillar.scenePyramid, pillar.sceneColor, origin, dir, slot);
    EXPECT_TRUE(e.fellBack) << strategy;
    EXPECT_FALSE(e.hit.valid) << strategy;
    EXPECT_EQ(e.color, glm::vec3(snellSampleEquirect(pillar.env, glm::normalize(dir), 0.0f))) << strategy;
    // The rule's read is counted when the strategy had a hit to check.
    EXPECT_EQ(e.fetches, h.fetches + (h.valid ? 2 : 1)) << strategy;
  }
}

// The environment slot: one read along the ray, no fallback.
TEST(TwoInterfaceExitFields, EnvironmentSlotIsOneRead) {
  const Scene& s = smallScene();
  const glm::vec3 dir(0.3f, -0.4f, -1.0f);
  const SnellTwoInterfaceExit e = exitRough(s, s.plane.depth, s.scenePyramid, s.sceneColor,
                                            glm::vec3(0.0f, 0.0f, -4.0f), dir,
                                            snellSlot(SNELL_SOURCE_ENVIRONMENT, SNELL_STRATEGY_PLANE_NORMAL));
  EXPECT_FALSE(e.fellBack);
  EXPECT_FALSE(e.hit.valid);
  EXPECT_EQ(e.fetches, 1);
  EXPECT_EQ(e.color, glm::vec3(snellSampleEquirect(s.env, glm::normalize(dir), 0.0f)));
}

// snellTwoInterfaceExit: a ray through a thin sheet of rough glass, both lobes and no path inside: angle =
// s |1 - eta| / eta (the entry lobe, magnified by the exit), exitAngle = s |1 / eta - 1|, s = roughness^2;
// read from an environment whose level k reads k.
TEST(TwoInterfaceExitFields, ThinSheetReadsTheEnvironmentLevelOfBothLobes) {
  Scene s = technique_test::makeScene(32, 32);
  Texture2D env(Image(256, 128, glm::vec4(0.0f)), Filter::Linear, MipFilter::Linear);
  for (int k = 1, w = 128, h = 64; w >= 1; ++k, w /= 2, h = std::max(1, h / 2)) env.addLevel(Image(w, h, glm::vec4(float(k))));
  s.env = env;
  SnellView v = snellView();
  v.environmentLevels = env.levelCount();
  ASSERT_EQ(v.environmentLevels, 9);
  SnellMaterial m = snellMaterial();
  for (const float roughness : {0.3f, 0.5f}) {
    m.roughness = roughness;
    const double a = double(roughness) * double(roughness), eta = 1.0 / double(m.ior);
    const double spread = std::hypot(a * (1.0 - eta) / eta, a * (1.0 / eta - 1.0));
    const double lod = std::log2(double(SNELL_ROUGH_CONE_LOD_SCALE) * spread * 256.0 / (2.0 * M_PI));
    const SnellTwoInterfaceExit e = snellTwoInterfaceExit(glm::vec3(0.0f, 0.0f, -4.0f), glm::vec3(0.2f, 0.1f, -1.0f),
                                                          TECH_SCENE_ARGS(s), snellSlot(SNELL_SOURCE_ENVIRONMENT, 0), m, v);
    EXPECT_NEAR(e.color.x, snell_test::roughReadOfLevelTexture(lod, v.environmentLevels), 1e-3) << roughness;
  }
}

}  // namespace
