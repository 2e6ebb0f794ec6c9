// The rough glass's blur cone (glsl/snell/shade/rough_cone.glsl) against independent computations: the
// spread of rays refracted exactly (vector Snell's law in double) about tilted microfacets, finite-difference
// projections for the texel density, and the documented results for bad input.
#include <gtest/gtest.h>

#include <snell/snell.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include "support/texel_density.hpp"

#include <cmath>
#include <limits>

namespace {

using namespace snell;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr double kScale = double(SNELL_ROUGH_CONE_LOD_SCALE);

// The direction refracted about a normal tilted by `tilt` radians (about x) from +z, for a ray along -z
// (entering, eta = n_from / n_to), in double: exact vector Snell's law.
glm::dvec3 refractAboutTilted(glm::dvec3 incident, double tilt, double eta) {
  const glm::dvec3 m(0.0, -std::sin(tilt), std::cos(tilt));
  return glm::refract(glm::normalize(incident), m, eta);
}

// The angle (radians, signed about x) between two directions in the y-z plane.
double angleBetween(glm::dvec3 a, glm::dvec3 b) { return std::atan2(a.y, -a.z) - std::atan2(b.y, -b.z); }

TEST(ShadeRoughCone, EachInterfaceTurnsRaysByTheSmallSlopeSnellFactor) {
  // Entering glass (eta = 1 / 1.5), a facet tilted by d turns the refracted ray by |1 - eta| d; leaving it
  // (eta = 1.5), by |1 - eta| d again; an inside angle leaves magnified by 1 / eta. The cone's angles at
  // alpha = s are those factors times s: compare with exact refraction at a small tilt.
  const double tilt = 1e-4;
  for (double ior : {1.1, 1.33, 1.5, 2.4}) {
    const float eta = float(1.0 / ior);
    const double s = 0.09;  // roughness 0.3
    const SnellRoughCone c = snellRoughConeTransmit(0.3f, eta, 0.0f, 0);
    const glm::dvec3 down(0.0, 0.0, -1.0);
    const double entry = std::abs(angleBetween(refractAboutTilted(down, tilt, 1.0 / ior), down)) / tilt;
    const double exit = std::abs(angleBetween(refractAboutTilted(down, tilt, ior), down)) / tilt;
    // A ray inside at a small angle leaves the flat surface at about 1 / eta times it.
    const glm::dvec3 inside(0.0, std::sin(tilt), -std::cos(tilt));
    const double magnify = std::abs(angleBetween(refractAboutTilted(inside, 0.0, ior), down)) / tilt;
    EXPECT_NEAR(c.angle, s * entry * magnify, 1e-5) << ior;
    EXPECT_NEAR(c.exitAngle, s * exit, 1e-5) << ior;
    EXPECT_EQ(c.radius, 0.0f);
    // Over a path inside of length L the entry lobe is s * entry * L wide where it leaves.
    EXPECT_NEAR(snellRoughConeTransmit(0.3f, eta, 2.0f, 0).radius, s * entry * 2.0, 1e-5) << ior;
  }
}

TEST(ShadeRoughCone, BouncesWidenTheInsideLobeByTwiceTheSlopeEach) {
  const float eta = 1.0f / 1.5f;
  const double s = 0.25;  // roughness 0.5
  for (int b = 0; b <= 6; ++b) {
    const int kept = std::min(b, SNELL_MAX_BOUNCES);
    const double inside = std::sqrt(std::pow(s * (1.0 - 1.0 / 1.5), 2) + kept * std::pow(2.0 * s, 2));
    const SnellRoughCone c = snellRoughConeTransmit(0.5f, eta, 3.0f, b);
    EXPECT_NEAR(c.radius, inside * 3.0, 1e-5) << b;
    EXPECT_NEAR(c.angle, inside * 1.5, 1e-5) << b;
  }
  const SnellRoughCone r = snellRoughConeReflect(0.5f);
  EXPECT_EQ(r.radius, 0.0f);
  EXPECT_FLOAT_EQ(r.angle, 0.5f);  // a mirror turns a ray by twice its tilt
  EXPECT_EQ(r.exitAngle, 0.0f);
}

TEST(ShadeRoughCone, RadiusAddsTheCarriedLobeLinearlyAndTheExitLobeInQuadrature) {
  SnellRoughCone c;
  c.radius = 0.3f;
  c.angle = 0.2f;
  c.exitAngle = 0.1f;
  for (double d : {0.0, 0.5, 2.0, 17.0}) {
    EXPECT_NEAR(snellRoughConeRadius(c, float(d)), std::hypot(0.3 + 0.2 * d, 0.1 * d), 1e-6 * (1.0 + d)) << d;
  }
  EXPECT_FLOAT_EQ(snellRoughConeRadius(c, -5.0f), 0.3f);
  EXPECT_FLOAT_EQ(snellRoughConeRadius(c, kNaN), 0.3f);
  // Huge values stay finite.
  c.angle = 1e30f;
  c.exitAngle = 1e30f;
  EXPECT_TRUE(std::isfinite(snellRoughConeRadius(c, 1e30f)));
  EXPECT_TRUE(std::isfinite(snellRoughConeRadius(c, kInf)));
}

TEST(ShadeRoughCone, SceneLevelIsTheConesWidthInTexels) {
  const glm::mat4 clip = glm::perspective(glm::radians(50.0f), 1.25f, 0.1f, 100.0f);
  const glm::ivec2 size(640, 512);
  SnellRoughCone c = snellRoughConeTransmit(0.4f, 1.0f / 1.5f, 1.2f, 1);
  for (float z : {-1.5f, -4.0f, -20.0f}) {
    for (float d : {0.1f, 1.0f, 5.0f}) {
      const glm::vec3 p(0.4f, -0.3f, z);
      const double radius = std::hypot(double(c.radius) + double(c.angle) * double(d), double(c.exitAngle) * double(d));
      const double expected =
          std::clamp(std::log2(kScale * radius * snell_test::texelsPerUnit(clip, glm::dvec3(p), size.x, size.y)),
                     0.0, 9.0);
      EXPECT_NEAR(snellRoughConeSceneLod(c, d, p, clip, size, 10), expected, 2e-3) << z << " " << d;
    }
  }
  // The same glass at twice the resolution: one level finer texels, the same width in the world.
  const glm::vec3 p(0.0f, 0.0f, -6.0f);
  const float lod = snellRoughConeSceneLod(c, 2.0f, p, clip, size, 12);
  ASSERT_GT(lod, 1.0f);
  ASSERT_LT(lod, 10.0f);
  EXPECT_NEAR(snellRoughConeSceneLod(c, 2.0f, p, clip, 2 * size, 12), lod + 1.0f, 1e-5f);
  // Orthographic: no w, the same width at any depth.
  const glm::mat4 ortho = glm::ortho(-2.0f, 2.0f, -1.6f, 1.6f, 0.1f, 50.0f);
  EXPECT_FLOAT_EQ(snellRoughConeSceneLod(c, 1.0f, glm::vec3(0, 0, -2), ortho, size, 10),
                  snellRoughConeSceneLod(c, 1.0f, glm::vec3(0, 0, -30), ortho, size, 10));
}

TEST(ShadeRoughCone, EnvironmentLevelIsTheConesAngleInTexels) {
  const SnellRoughCone c = snellRoughConeTransmit(0.3f, 1.0f / 1.5f, 0.7f, 0);
  for (int levels : {2, 8, 11, 13}) {
    const double perRadian = std::pow(2.0, levels - 1) / (2.0 * M_PI);
    const double expected = std::clamp(
        std::log2(kScale * std::hypot(double(c.angle), double(c.exitAngle)) * perRadian), 0.0,
        double(levels - 1));
    EXPECT_NEAR(snellRoughConeEnvironmentLod(c, levels), expected, 1e-4) << levels;
  }
  EXPECT_EQ(snellRoughConeEnvironmentLod(c, 1), 0.0f);
  EXPECT_EQ(snellRoughConeEnvironmentLod(c, 0), 0.0f);
  EXPECT_TRUE(std::isfinite(snellRoughConeEnvironmentLod(c, 1 << 30)));
}

TEST(ShadeRoughCone, TheHelpersAgainstTheLibrary) {
  for (float r : {0.0f, 0.05f, 0.3f, 0.77f, 1.0f}) EXPECT_FLOAT_EQ(snellRoughConeSlope(r), float(double(r) * double(r)));
  EXPECT_EQ(snellRoughConeSlope(kNaN), 0.0f);
  EXPECT_EQ(snellRoughConeSlope(-3.0f), 0.0f);
  EXPECT_EQ(snellRoughConeSlope(kInf), 1.0f);
  for (float x : {0.0f, 1e-20f, 0.5f, 3.0f, 1e20f, 3e38f})
    for (float y : {0.0f, 2e-20f, 0.25f, 7.0f, 1e21f, 3e38f}) {
      const double h = std::min(std::hypot(double(x), double(y)), double(std::numeric_limits<float>::max()));
      EXPECT_NEAR(snellRoughConeHypot(x, y), h, 1e-6 * h) << x << " " << y;
      EXPECT_EQ(snellRoughConeHypot(x, y), snellRoughConeHypot(y, x));
    }
  EXPECT_EQ(snellRoughConeHypot(kNaN, 1.0f), 1.0f);  // NaN and negative values count as 0
  EXPECT_EQ(snellRoughConeHypot(-4.0f, 1.0f), 1.0f);
  EXPECT_EQ(snellRoughConeHypot(kInf, kInf), std::numeric_limits<float>::max());
  for (float x : {-1.0f, 0.0f, kNaN, -kInf}) EXPECT_EQ(snellRoughConeMeasure(x), 0.0f);
  EXPECT_EQ(snellRoughConeMeasure(kInf), std::numeric_limits<float>::max());
  EXPECT_EQ(snellRoughConeMeasure(2.5f), 2.5f);
  for (float radius : {0.001f, 0.2f, 3.0f, 1e6f})
    for (float tpu : {0.5f, 40.0f, 1e5f})
      for (int levels : {1, 4, 12}) {
        const double expected = levels <= 1 ? 0.0
                                            : std::clamp(std::log2(kScale * double(radius) * double(tpu)),
                                                         0.0, double(levels - 1));
        EXPECT_NEAR(snellRoughConeLevel(radius, tpu, levels), expected, 1e-5) << radius << " " << tpu;
      }
  EXPECT_EQ(snellRoughConeLevel(0.0f, 10.0f, 8), 0.0f);
  EXPECT_EQ(snellRoughConeLevel(kNaN, 10.0f, 8), 0.0f);
  EXPECT_EQ(snellRoughConeLevel(1.0f, kNaN, 8), 0.0f);
  EXPECT_EQ(snellRoughConeLevel(kInf, 10.0f, 8), 7.0f);
}

TEST(ShadeRoughCone, SmoothGlassAndBadInputGiveTheDocumentedResults) {
  const glm::mat4 clip = glm::perspective(glm::radians(50.0f), 1.0f, 0.1f, 100.0f);
  const glm::vec3 p(0.0f, 0.0f, -5.0f);
  for (float r : {0.0f, -1.0f, kNaN, -kInf}) {
    const SnellRoughCone c = snellRoughConeTransmit(r, 1.0f / 1.5f, 3.0f, 2);
    EXPECT_EQ(c.radius, 0.0f) << r;
    EXPECT_EQ(c.angle, 0.0f) << r;
    EXPECT_EQ(c.exitAngle, 0.0f) << r;
    EXPECT_EQ(snellRoughConeSceneLod(c, 4.0f, p, clip, glm::ivec2(512), 10), 0.0f) << r;
    EXPECT_EQ(snellRoughConeEnvironmentLod(c, 10), 0.0f) << r;
    EXPECT_EQ(snellRoughConeReflect(r).angle, 0.0f) << r;
  }
  // Roughness above 1 counts as 1.
  EXPECT_EQ(snellRoughConeTransmit(7.0f, 0.5f, 1.0f, 0).angle, snellRoughConeTransmit(1.0f, 0.5f, 1.0f, 0).angle);
  EXPECT_EQ(snellRoughConeReflect(kInf).angle, 2.0f);
  // An index-matched or invalid eta bends nothing, so it blurs nothing.
  for (float eta : {1.0f, kNaN, 0.0f, -2.0f, 1e9f}) {
    const SnellRoughCone c = snellRoughConeTransmit(0.5f, eta, 3.0f, 0);
    EXPECT_EQ(c.radius, 0.0f) << eta;
    EXPECT_EQ(c.angle, 0.0f) << eta;
    EXPECT_EQ(c.exitAngle, 0.0f) << eta;
  }
  // A bad path length counts as 0; the angles stay.
  for (float len : {-1.0f, kNaN, kInf}) {
    const SnellRoughCone c = snellRoughConeTransmit(0.5f, 1.0f / 1.5f, len, 0);
    EXPECT_EQ(c.radius, 0.0f) << len;
    EXPECT_GT(c.angle, 0.0f) << len;
  }
  // Points that do not project, fewer than two levels, NaN: level 0; huge cones: the top level.
  const SnellRoughCone c = snellRoughConeTransmit(0.5f, 1.0f / 1.5f, 1.0f, 0);
  EXPECT_EQ(snellRoughConeSceneLod(c, 1.0f, glm::vec3(0.0f, 0.0f, 2.0f), clip, glm::ivec2(512), 10), 0.0f);
  EXPECT_EQ(snellRoughConeSceneLod(c, 1.0f, glm::vec3(kNaN), clip, glm::ivec2(512), 10), 0.0f);
  EXPECT_EQ(snellRoughConeSceneLod(c, 1.0f, p, clip, glm::ivec2(512), 1), 0.0f);
  EXPECT_EQ(snellRoughConeSceneLod(c, 1e30f, p, clip, glm::ivec2(512), 10), 9.0f);
  EXPECT_EQ(snellRoughConeSceneLod(c, kInf, p, clip, glm::ivec2(512), 10), 9.0f);
  EXPECT_EQ(snellRoughConeSceneLod(c, 1.0f, glm::vec3(0.0f, 0.0f, -1e-30f), clip, glm::ivec2(512), 10), 9.0f);
}

}  // namespace
