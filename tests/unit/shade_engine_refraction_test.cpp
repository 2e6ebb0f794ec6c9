// The steps the engine models share (engine_refraction.glsl) and HDRP's edge
// fade, against the geometry in double: Snell's law in angle form for the
// entry refraction, the projection for the point an engine reads, and HDRP's
// EdgeOfScreenFade (a smoothstep over the outer tenth of each axis).
#include <snell/shade.hpp>

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

#include "support/rng.hpp"

namespace {

using glm::dvec2;
using glm::dvec3;
using glm::dvec4;
using glm::mat4;
using glm::vec2;
using glm::vec3;
using snell::SnellEngineRefraction;

const float kNaN = std::numeric_limits<float>::quiet_NaN();

mat4 projection() { return glm::perspective(glm::radians(50.0f), 1.3f, 0.1f, 100.0f); }

void expectInvalid(const SnellEngineRefraction& e) {
  EXPECT_FALSE(e.valid);
  EXPECT_EQ(e.uv, vec2(0.0f));
  EXPECT_EQ(e.sceneWeight, 0.0f);
  EXPECT_EQ(e.direction, vec3(0.0f));
  EXPECT_EQ(e.distance, 0.0f);
}

TEST(EngineRefraction, InvalidIsAllZero) { expectInvalid(snell::snellEngineInvalid()); }

// T in the plane of incidence with sin t = eta sin i, the normal turned to face the eye.
TEST(EngineRefraction, EntryFollowsSnellsLawWithTheNormalFacingTheEye) {
  snell_test::Rng g(9102);
  int refracted = 0, tir = 0, flipped = 0;
  for (int i = 0; i < 5000; ++i) {
    const vec3 p = g.unit() * g.uniform(1.0f, 10.0f);
    const vec3 n = g.unit() * g.uniform(0.5f, 2.0f);
    const float eta = g.uniform(0.5f, 1.5f);
    const dvec3 d = glm::normalize(dvec3(p));
    dvec3 nn = glm::normalize(dvec3(n));
    if (glm::dot(nn, d) > 0.0) nn = -nn;
    const double cosI = -glm::dot(d, nn);
    if (cosI < 1e-3) continue;  // grazing: the side the normal turns to is a rounding
    const double sinT = double(eta) * std::sqrt(std::max(0.0, 1.0 - cosI * cosI));
    if (std::abs(sinT - 1.0) < 1e-4) continue;  // at the critical angle TIR is a rounding
    const snell::SnellEngineEntry e = snell::snellEngineEntry(p, n, eta);
    ASSERT_TRUE(e.valid);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(e.normal[k], nn[k], 1e-6);
    flipped += glm::dot(dvec3(n), nn) < 0.0;
    if (sinT > 1.0) {
      EXPECT_TRUE(e.tir);
      EXPECT_EQ(e.direction, vec3(0.0f));
      EXPECT_EQ(e.cosine, 0.0f);
      ++tir;
      continue;
    }
    const dvec3 tangent = d + cosI * nn;
    const dvec3 t = glm::length(tangent) > 0.0 ? glm::normalize(tangent) * sinT - nn * std::sqrt(1.0 - sinT * sinT)
                                               : -nn;
    EXPECT_FALSE(e.tir);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(e.direction[k], t[k], 1e-5);
    EXPECT_NEAR(e.cosine, glm::dot(nn, t), 1e-5);
    ++refracted;
  }
  EXPECT_GT(refracted, 2000);
  EXPECT_GT(tir, 100);
  EXPECT_GT(flipped, 1000);
  EXPECT_FALSE(snell::snellEngineEntry(vec3(0.0f), vec3(0, 0, 1), 0.7f).valid);
  EXPECT_FALSE(snell::snellEngineEntry(vec3(0, 0, -1), vec3(0, 0, 1), kNaN).valid);
}

// The point's projection with weight 1 where it projects (w > 0), else uv 0 and weight 0; always valid.
TEST(EngineRefraction, SeePointReadsWhereThePointProjects) {
  snell_test::Rng g(9103);
  const mat4 clip = projection();
  int behind = 0;
  for (int i = 0; i < 2000; ++i) {
    const vec3 x(g.uniform(-5.0f, 5.0f), g.uniform(-5.0f, 5.0f), g.uniform(-10.0f, 3.0f));
    const vec3 dir = g.unit() * g.uniform(0.1f, 10.0f);
    const float distance = g.uniform(-1.0f, 5.0f);
    const SnellEngineRefraction e = snell::snellEngineSeePoint(x, dir, distance, clip);
    EXPECT_TRUE(e.valid);
    const dvec4 c = glm::dmat4(clip) * dvec4(dvec3(x), 1.0);
    if (c.w > 1e-3) {
      const dvec2 uv = 0.5 * dvec2(c.x, c.y) / c.w + 0.5;
      EXPECT_NEAR(e.uv.x, uv.x, 1e-5 * std::max(1.0, std::abs(uv.x)));
      EXPECT_NEAR(e.uv.y, uv.y, 1e-5 * std::max(1.0, std::abs(uv.y)));
      EXPECT_EQ(e.sceneWeight, 1.0f);
    } else if (c.w < -1e-3) {
      EXPECT_EQ(e.uv, vec2(0.0f));
      EXPECT_EQ(e.sceneWeight, 0.0f);
      ++behind;
    }
    const dvec3 unit = glm::normalize(dvec3(dir));
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(e.direction[k], unit[k], 1e-6);
    EXPECT_EQ(e.distance, std::max(distance, 0.0f));
  }
  EXPECT_GT(behind, 200);
  const SnellEngineRefraction e = snell::snellEngineSeePoint(vec3(0, 0, -2), vec3(0.0f), kNaN, clip);
  EXPECT_EQ(e.direction, vec3(0.0f));
  EXPECT_EQ(e.distance, 0.0f);
  EXPECT_EQ(snell::snellEngineSeePoint(vec3(0, 0, -2), vec3(1, 0, 0), INFINITY, clip).distance, FLT_MAX);
}

// 1 inside the screen's inner 90 % on both axes, 0 on and beyond its edges, a smoothstep between.
TEST(EngineRefraction, HdrpEdgeFadeIsHdrpsScreenEdgeSmoothstep) {
  const auto fade1 = [](double u) {
    const double x = std::clamp((1.0 - std::abs(2.0 * u - 1.0)) / 0.1, 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
  };
  for (double u = -0.2; u <= 1.2; u += 0.0125)
    for (double v = -0.2; v <= 1.2; v += 0.0375)
      EXPECT_NEAR(snell::snellEngineHdrpEdgeFade(vec2(float(u), float(v))), fade1(u) * fade1(v), 1e-5) << u << " " << v;
  EXPECT_EQ(snell::snellEngineHdrpEdgeFade(vec2(0.5f, 0.5f)), 1.0f);
  EXPECT_EQ(snell::snellEngineHdrpEdgeFade(vec2(0.0f, 0.5f)), 0.0f);
  EXPECT_NEAR(snell::snellEngineHdrpEdgeFade(vec2(0.025f, 0.5f)), 0.5f, 1e-5f);  // halfway into the fade band
  EXPECT_EQ(snell::snellEngineHdrpEdgeFade(vec2(kNaN, 0.5f)), 0.0f);
  EXPECT_EQ(snell::snellEngineHdrpEdgeFade(vec2(0.5f, INFINITY)), 0.0f);
}

}  // namespace
