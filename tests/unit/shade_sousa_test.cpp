// Sousa's screen-space techniques (GPU Gems 2 ch. 19): perturbation, the
// refraction mask and its depth-aware variant, the screen-edge fade, water and
// glass, against the listings' formulas evaluated independently in double over
// NEAREST textures whose texels are addressed by hand; hostile inputs give the
// documented finite values.
#include <snell/shade.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "support/rng.hpp"

namespace {

using glm::dvec2;
using glm::dvec3;
using glm::dvec4;
using glm::vec2;
using glm::vec3;
using glm::vec4;

const float kInf = std::numeric_limits<float>::infinity();
const float kNaN = std::numeric_limits<float>::quiet_NaN();

struct Rng : snell_test::Rng {
  Rng() : snell_test::Rng(1234u) {}
};

// A W x H NEAREST texture with random texels; alpha is 0 or 1 (a mask) when
// mask is set.
snell::Texture2D randomTexture(int w, int h, unsigned seed, bool mask) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  snell::Image img(w, h);
  for (vec4& t : img.texels) t = vec4(u(rng), u(rng), u(rng), mask ? (u(rng) < 0.5f ? 0.0f : 1.0f) : u(rng));
  return snell::Texture2D(img);
}

// The texel NEAREST picks at uv (double), after clamping uv into [0,1].
dvec4 texelAt(const snell::Texture2D& t, dvec2 uv) {
  const snell::Image& l = t.level(0);
  uv = glm::clamp(uv, dvec2(0.0), dvec2(1.0));
  int x = std::min(static_cast<int>(std::floor(uv.x * l.width)), l.width - 1);
  int y = std::min(static_cast<int>(std::floor(uv.y * l.height)), l.height - 1);
  return dvec4(l.at(x, y));
}

// uv whose perturbations stay away from texel edges (the float and double sums
// could otherwise pick different texels): texel centres plus bumps that move by
// whole texels plus less than half a texel.
bool nearTexelEdge(double uv, int size) {
  double f = uv * size - std::floor(uv * size);
  return f < 1e-3 || f > 1.0 - 1e-3;
}

// --- perturbation (Example 19-1) ---------------------------------------------

TEST(ShadePerturb, UnpackIsTwoTMinusOne) {
  vec3 b = snell::snellUnpackBump(vec3(0.0f, 0.5f, 1.0f));
  EXPECT_EQ(b, vec3(-1.0f, 0.0f, 1.0f));
  EXPECT_FLOAT_EQ(snell::snellUnpackBump(vec3(0.75f)).x, 0.5f);
}

TEST(ShadePerturb, UvIsProjectedUvPlusScaledBump) {
  Rng r;
  for (int k = 0; k < 20000; ++k) {
    vec2 uv(r.uniform(-0.5f, 1.5f), r.uniform(-0.5f, 1.5f));
    vec2 bump(r.uniform(-1, 1), r.uniform(-1, 1));
    float scale = r.uniform(0.0f, 0.2f);
    vec2 p = snell::snellPerturbUv(uv, bump, scale);
    EXPECT_NEAR(p.x, double(uv.x) + double(scale) * double(bump.x), 1e-6);
    EXPECT_NEAR(p.y, double(uv.y) + double(scale) * double(bump.y), 1e-6);
  }
  // Default scale: the chapter's 0.05.
  vec2 d = snell::snellPerturbUv(vec2(0.5f, 0.25f), vec2(1.0f, -1.0f));
  EXPECT_NEAR(d.x, 0.55, 1e-7);
  EXPECT_NEAR(d.y, 0.20, 1e-7);
}

TEST(ShadePerturb, HostileInputsAreFinite) {
  EXPECT_EQ(snell::snellPerturbUv(vec2(kNaN, 0.25f), vec2(1.0f, 1.0f), 0.1f), vec2(0.6f, 0.35f));
  EXPECT_EQ(snell::snellPerturbUv(vec2(kInf, -kInf), vec2(0.0f), 0.1f), vec2(0.5f, 0.5f));
  EXPECT_EQ(snell::snellPerturbUv(vec2(0.25f, 0.75f), vec2(kNaN, 1.0f), 0.5f), vec2(0.25f, 1.25f));
  EXPECT_EQ(snell::snellPerturbUv(vec2(0.25f, 0.75f), vec2(1.0f, 1.0f), kNaN), vec2(0.25f, 0.75f));
  EXPECT_EQ(snell::snellPerturbUv(vec2(0.25f, 0.75f), vec2(kInf, 0.0f), 0.0f), vec2(0.25f, 0.75f));  // 0 * inf
  vec2 big = snell::snellPerturbUv(vec2(3e38f, -3e38f), vec2(1.0f, -1.0f), 3e38f);
  EXPECT_EQ(big, vec2(3.402823466e38f, -3.402823466e38f));
}

TEST(ShadePerturb, SampleReadsSAtThePerturbedUv) {
  snell::Texture2D s = randomTexture(16, 8, 1, false);
  Rng r;
  int checked = 0;
  for (int k = 0; k < 5000; ++k) {
    vec2 uv(r.uniform(0, 1), r.uniform(0, 1));
    vec2 bump(r.uniform(-1, 1), r.uniform(-1, 1));
    float scale = r.uniform(0.0f, 0.3f);
    dvec2 p = dvec2(uv) + double(scale) * dvec2(bump);
    if (nearTexelEdge(p.x, 16) || nearTexelEdge(p.y, 8)) continue;
    dvec4 want = texelAt(s, p);  // off screen: the edge texel (clamp)
    vec4 got = snell::snellPerturbSample(s, uv, bump, scale);
    for (int c = 0; c < 4; ++c) EXPECT_EQ(double(got[c]), want[c]);
    ++checked;
  }
  EXPECT_GT(checked, 4500);
  // NaN uv reads the screen centre.
  EXPECT_EQ(dvec4(snell::snellPerturbSample(s, vec2(kNaN), vec2(0.0f), 0.0f)), texelAt(s, dvec2(0.5)));
}

// --- screen-edge fade -----------------------------------------------------------

TEST(ShadeEdgeFade, LinearRampToTheBorder) {
  Rng r;
  for (int k = 0; k < 20000; ++k) {
    vec2 uv(r.uniform(-0.5f, 1.5f), r.uniform(-0.5f, 1.5f));
    float w = r.uniform(0.01f, 0.5f);
    double e = std::min(std::min(double(uv.x), 1.0 - double(uv.x)), std::min(double(uv.y), 1.0 - double(uv.y)));
    double want = std::clamp(e / double(w), 0.0, 1.0);
    EXPECT_NEAR(snell::snellScreenEdgeFade(uv, w), want, 1e-5);
  }
  EXPECT_EQ(snell::snellScreenEdgeFade(vec2(0.5f)), 1.0f);
  EXPECT_NEAR(snell::snellScreenEdgeFade(vec2(0.025f, 0.5f)), 0.5f, 1e-6f);  // default width 0.05
  EXPECT_EQ(snell::snellScreenEdgeFade(vec2(0.0f, 0.5f)), 0.0f);
  EXPECT_EQ(snell::snellScreenEdgeFade(vec2(1.2f, 0.5f)), 0.0f);
}

TEST(ShadeEdgeFade, DegenerateWidthAndHostileUv) {
  EXPECT_EQ(snell::snellScreenEdgeFade(vec2(0.0f, 1.0f), 0.0f), 1.0f);  // hard cut, borders included
  EXPECT_EQ(snell::snellScreenEdgeFade(vec2(-1e-6f, 0.5f), 0.0f), 0.0f);
  EXPECT_EQ(snell::snellScreenEdgeFade(vec2(0.3f, 0.5f), kNaN), 1.0f);
  EXPECT_EQ(snell::snellScreenEdgeFade(vec2(0.3f, 0.5f), -1.0f), 1.0f);
  EXPECT_EQ(snell::snellScreenEdgeFade(vec2(0.5f, 0.5f), 10.0f), 1.0f);  // width capped at 0.5
  EXPECT_EQ(snell::snellScreenEdgeFade(vec2(kNaN, 0.5f), 0.1f), 0.0f);
  EXPECT_EQ(snell::snellScreenEdgeFade(vec2(0.5f, kInf), 0.1f), 0.0f);
}

// --- refraction mask (Example 19-2) -------------------------------------------

TEST(ShadeRefractionMask, BlendIsTheListingsFormula) {
  Rng r;
  for (int k = 0; k < 20000; ++k) {
    vec4 a(r.uniform(0, 1), r.uniform(0, 1), r.uniform(0, 1), r.uniform(0, 1));
    vec4 b(r.uniform(0, 1), r.uniform(0, 1), r.uniform(0, 1), r.uniform(0, 1));
    // vRefrB * vRefrA.w + vRefrA * (1 - vRefrA.w)
    dvec4 want = dvec4(b) * double(a.w) + dvec4(a) * (1.0 - double(a.w));
    vec4 got = snell::snellRefractionMaskBlend(a, b);
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], 1e-6);
  }
  vec4 a(0.1f, 0.2f, 0.3f, 0.0f), b(0.9f, 0.8f, 0.7f, 1.0f);
  EXPECT_EQ(snell::snellRefractionMaskBlend(a, b), a);  // inside the refractive mesh: perturbed
  a.w = 1.0f;
  EXPECT_EQ(snell::snellRefractionMaskBlend(a, b), b);  // outside: unperturbed
  a.w = kNaN;
  EXPECT_EQ(snell::snellRefractionMaskBlend(a, b), b);
  a.w = 7.0f;
  EXPECT_EQ(snell::snellRefractionMaskBlend(a, b), b);
  a.w = -3.0f;
  EXPECT_EQ(snell::snellRefractionMaskBlend(a, b), vec4(0.1f, 0.2f, 0.3f, 0.0f));
}

TEST(ShadeRefractionMask, MaskedReadKeepsPerturbedOnlyInsideTheMask) {
  snell::Texture2D s = randomTexture(16, 16, 2, true);
  Rng r;
  int inside = 0, outside = 0;
  for (int k = 0; k < 5000; ++k) {
    vec2 uv(r.uniform(0, 1), r.uniform(0, 1));
    vec2 bump(r.uniform(-1, 1), r.uniform(-1, 1));
    float scale = r.uniform(0.0f, 0.2f);
    dvec2 p = dvec2(uv) + double(scale) * dvec2(bump);
    if (nearTexelEdge(p.x, 16) || nearTexelEdge(p.y, 16) || nearTexelEdge(uv.x, 16) || nearTexelEdge(uv.y, 16))
      continue;
    dvec4 a = texelAt(s, p), b = texelAt(s, dvec2(uv));
    dvec4 want = a.w == 0.0 ? a : b;
    vec4 got = snell::snellRefractionMasked(s, uv, bump, scale);
    for (int c = 0; c < 4; ++c) EXPECT_EQ(double(got[c]), want[c]);
    (a.w == 0.0 ? inside : outside)++;
  }
  EXPECT_GT(inside, 1000);
  EXPECT_GT(outside, 1000);
}

// --- depth-aware mask -----------------------------------------------------------

TEST(ShadeRefractionMaskDepth, AcceptUnlessTheSceneIsInFront) {
  for (int conv : {SNELL_DEPTH_GL, SNELL_DEPTH_ZERO_ONE, SNELL_DEPTH_INFINITE_GL}) {
    EXPECT_TRUE(snell::snellRefractionDepthAccept(0.8f, 0.5f, conv));   // behind the surface
    EXPECT_TRUE(snell::snellRefractionDepthAccept(0.5f, 0.5f, conv));
    EXPECT_FALSE(snell::snellRefractionDepthAccept(0.3f, 0.5f, conv));  // occluder in front
  }
  for (int conv : {SNELL_DEPTH_REVERSED, SNELL_DEPTH_INFINITE_REVERSED}) {
    EXPECT_TRUE(snell::snellRefractionDepthAccept(0.3f, 0.5f, conv));
    EXPECT_TRUE(snell::snellRefractionDepthAccept(0.5f, 0.5f, conv));
    EXPECT_FALSE(snell::snellRefractionDepthAccept(0.8f, 0.5f, conv));
  }
  EXPECT_FALSE(snell::snellRefractionDepthAccept(kNaN, 0.5f, SNELL_DEPTH_GL));
  EXPECT_FALSE(snell::snellRefractionDepthAccept(0.5f, kNaN, SNELL_DEPTH_REVERSED));
  EXPECT_FALSE(snell::snellRefractionDepthAccept(0.9f, 0.5f, 7));
  EXPECT_FALSE(snell::snellRefractionDepthAccept(0.9f, 0.5f, -1));
}

TEST(ShadeRefractionMaskDepth, MaskedReadRejectsOccluders) {
  snell::Texture2D s = randomTexture(16, 16, 3, false);
  snell::Texture2D depth = randomTexture(16, 16, 4, false);  // depth in .x, NEAREST
  Rng r;
  int accepted = 0, rejected = 0;
  for (int k = 0; k < 5000; ++k) {
    vec2 uv(r.uniform(0, 1), r.uniform(0, 1));
    vec2 bump(r.uniform(-1, 1), r.uniform(-1, 1));
    float scale = r.uniform(0.0f, 0.2f);
    float surface = r.uniform(0, 1);
    int conv = k % 2 ? SNELL_DEPTH_GL : SNELL_DEPTH_REVERSED;
    dvec2 p = dvec2(uv) + double(scale) * dvec2(bump);
    if (nearTexelEdge(p.x, 16) || nearTexelEdge(p.y, 16) || nearTexelEdge(uv.x, 16) || nearTexelEdge(uv.y, 16))
      continue;
    double d = texelAt(depth, p).x;
    bool inFront = conv == SNELL_DEPTH_GL ? d < double(surface) : d > double(surface);
    dvec4 want = inFront ? texelAt(s, dvec2(uv)) : texelAt(s, p);
    vec4 got = snell::snellRefractionMaskedDepth(s, depth, uv, bump, scale, surface, conv);
    for (int c = 0; c < 4; ++c) EXPECT_EQ(double(got[c]), want[c]);
    (inFront ? rejected : accepted)++;
  }
  EXPECT_GT(accepted, 1000);
  EXPECT_GT(rejected, 1000);
}

// --- water (Examples 19-3, 19-4) ----------------------------------------------

double sousaFresnel(double nDotL, double bias, double power) {  // Example 19-3
  return std::max(bias + (1.0 - bias) * std::pow(1.0 - nDotL, power), 0.0);
}

TEST(ShadeWater, DefaultsAreTheChaptersConstants) {
  snell::SnellWaterParams p = snell::snellWaterParams();
  EXPECT_EQ(p.refractionBumpScale, vec3(0.075f, 0.075f, 1.0f));
  EXPECT_EQ(p.reflectionBumpScale, vec3(0.02f, 0.02f, 1.0f));
  EXPECT_EQ(p.fresnelBias, 0.2f);
  EXPECT_EQ(p.fresnelPower, 5.0f);
  EXPECT_EQ(p.deepDistance, 10.0f);
  EXPECT_EQ(p.waterColor, vec3(0.0f, 0.15f, 0.115f));
  EXPECT_EQ(p.deepColor, vec3(0.0f, 0.15f, 0.115f));
}

TEST(ShadeWater, BumpAverageOfFourLayers) {
  Rng r;
  for (int k = 0; k < 5000; ++k) {
    vec3 t[4];
    dvec3 sum(0.0);
    for (vec3& x : t) {
      x = vec3(r.uniform(0, 1), r.uniform(0, 1), r.uniform(0.5f, 1));
      sum += 2.0 * dvec3(x) - 1.0;  // unpack each layer, then average
    }
    dvec3 want = glm::normalize(sum / 4.0);
    vec3 got = snell::snellWaterBumpAverage(t[0], t[1], t[2], t[3]);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 2e-6);
  }
  EXPECT_EQ(snell::snellWaterBumpAverage(vec3(0.5f), vec3(0.5f), vec3(0.5f), vec3(0.5f)), vec3(0, 0, 1));
  EXPECT_EQ(snell::snellWaterBumpAverage(vec3(kNaN), vec3(0.5f), vec3(0.5f), vec3(0.5f)), vec3(0, 0, 1));
}

TEST(ShadeWater, MatchesListing19_4) {
  snell::Texture2D s = randomTexture(32, 32, 5, true);
  snell::Texture2D refl = randomTexture(32, 32, 6, false);
  snell::SnellWaterParams p = snell::snellWaterParams();
  Rng r;
  int checked = 0;
  for (int k = 0; k < 5000; ++k) {
    vec2 uv(r.uniform(0, 1), r.uniform(0, 1));
    vec3 n = r.unit();
    n.z = std::fabs(n.z) + 0.2f;  // a bump normal pointing up
    vec3 eye = r.unit() * r.uniform(0.5f, 5.0f);
    eye.z = std::fabs(eye.z);
    float dist = k % 10 == 0 ? r.uniform(0.5f, 10.0f) : r.uniform(0.5f, 100.0f);
    dvec3 nb = glm::normalize(dvec3(n));
    dvec3 ve = glm::normalize(dvec3(eye));
    dvec3 refrBump = nb * dvec3(0.075, 0.075, 1.0);
    dvec3 reflBump = nb * dvec3(0.02, 0.02, 1.0);
    dvec2 uvRefl = dvec2(uv) + dvec2(reflBump.x, reflBump.y);
    dvec2 uvRefr = dvec2(uv) + dvec2(refrBump.x, refrBump.y);
    if (nearTexelEdge(uvRefl.x, 32) || nearTexelEdge(uvRefl.y, 32) || nearTexelEdge(uvRefr.x, 32) ||
        nearTexelEdge(uvRefr.y, 32) || nearTexelEdge(uv.x, 32) || nearTexelEdge(uv.y, 32))
      continue;
    dvec4 reflection = texelAt(refl, uvRefl);
    dvec4 a = texelAt(s, uvRefr), b = texelAt(s, dvec2(uv));
    dvec4 refraction = b * a.w + a * (1.0 - a.w);
    double nDotL = std::max(glm::dot(ve, reflBump), 0.0);
    double facing = 1.0 - nDotL;
    double fresnel = sousaFresnel(nDotL, 0.2, 5.0);
    double fDist = std::clamp(10.0 / double(dist), 0.0, 1.0);
    dvec3 color(0.0, 0.15, 0.115);
    dvec3 deep = dvec3(refraction) * fDist + (1.0 - fDist) * color;
    dvec3 water = color * facing + deep * (1.0 - facing);
    dvec3 want = fresnel * dvec3(reflection) + water;
    vec4 got = snell::snellWater(s, refl, uv, n, eye, dist, p);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 2e-6) << k;
    EXPECT_EQ(got.w, 1.0f);
    ++checked;
  }
  EXPECT_GT(checked, 4000);
}

// snellWaterCompose is snellWater after its two reads: composing the reads
// rebuilt by hand (the same uvs and mask blend) gives snellWater's colour, and
// the head-on case, worked out on paper, shows a refraction read some other
// way going straight into `deep`.
TEST(ShadeWater, ComposeIsWaterAfterItsReads) {
  snell::Texture2D s = randomTexture(16, 16, 5, true);
  snell::Texture2D refl = randomTexture(16, 16, 6, false);
  snell::SnellWaterParams p = snell::snellWaterParams();
  Rng r;
  for (int k = 0; k < 2000; ++k) {
    vec3 n = r.unit();
    n.z = std::fabs(n.z) + 0.2f;
    vec3 eye = r.unit() * r.uniform(0.5f, 5.0f);
    eye.z = std::fabs(eye.z);
    const float dist = r.uniform(0.5f, 100.0f);
    const vec2 uv(r.uniform(0, 1), r.uniform(0, 1));
    vec3 nn = glm::normalize(n);
    vec2 uvRefl = glm::clamp(uv + vec2(nn) * 0.02f, vec2(0.0f), vec2(1.0f));
    vec2 uvRefr = glm::clamp(uv + vec2(nn) * 0.075f, vec2(0.0f), vec2(1.0f));
    vec4 a = s.sampleLod(uvRefr, 0.0f), b = s.sampleLod(uv, 0.0f);
    vec4 refraction = b * a.w + vec4(vec3(a), a.w) * (1.0f - a.w);
    vec4 got = snell::snellWaterCompose(refl.sampleLod(uvRefl, 0.0f), refraction, n, eye, dist, p);
    vec4 want = snell::snellWater(s, refl, uv, n, eye, dist, p);
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], 1e-5) << k;
  }
  // Head-on (NdotL = 1): Fresnel = bias + (1 - bias) (1 - 1)^5 = bias, facing 0, fDist = 1 at distance 1:
  // result = bias * reflection + refraction.
  vec4 c = snell::snellWaterCompose(vec4(1.0f, 0.0f, 0.0f, 1.0f), vec4(0.0f, 0.5f, 0.25f, 1.0f), vec3(0, 0, 1),
                                    vec3(0, 0, 1), 1.0f, p);
  EXPECT_NEAR(c.x, 0.2f, 1e-6);
  EXPECT_NEAR(c.y, 0.5f, 1e-6);
  EXPECT_NEAR(c.z, 0.25f, 1e-6);
  EXPECT_EQ(c.w, 1.0f);
}

TEST(ShadeWater, HostileInputsAreFinite) {
  snell::Texture2D s = randomTexture(8, 8, 7, true);
  snell::SnellWaterParams p = snell::snellWaterParams();
  const float bad[] = {kNaN, kInf, -kInf, 0.0f, -1.0f, 1e-40f};
  for (float x : bad) {
    vec4 c1 = snell::snellWater(s, s, vec2(x), vec3(x), vec3(x), x, p);
    vec4 c2 = snell::snellWater(s, s, vec2(0.5f), vec3(0, 0, 1), vec3(0, 0, 1), x, p);
    for (int c = 0; c < 4; ++c) {
      EXPECT_TRUE(std::isfinite(c1[c])) << x;
      EXPECT_TRUE(std::isfinite(c2[c])) << x;
    }
  }
  // A zero eye: NdotL = 0, Fresnel 1, facing 1: reflection + water colour.
  vec4 c = snell::snellWater(s, s, vec2(0.5f), vec3(0, 0, 1), vec3(0.0f), 1.0f, p);
  dvec4 refl = texelAt(s, dvec2(0.5));
  EXPECT_NEAR(c.y, refl.y + 0.15, 1e-6);
  // Distance <= 0 or NaN: fDist = 1 (no deep colour).
  vec4 c0 = snell::snellWater(s, s, vec2(0.5f), vec3(0, 0, 1), vec3(0, 0, 1), 0.0f, p);
  vec4 c5 = snell::snellWater(s, s, vec2(0.5f), vec3(0, 0, 1), vec3(0, 0, 1), 5.0f, p);
  EXPECT_EQ(c0, c5);
}

// --- glass (Example 19-5) -------------------------------------------------------

TEST(ShadeGlass, MatchesListing19_5) {
  snell::Texture2D s = randomTexture(32, 32, 8, true);
  snell::Texture2D env = randomTexture(32, 32, 9, false);
  Rng r;
  int checked = 0;
  for (int k = 0; k < 5000; ++k) {
    vec2 uv(r.uniform(0, 1), r.uniform(0, 1));
    vec3 bumpTexel(r.uniform(0, 1), r.uniform(0, 1), r.uniform(0.6f, 1));
    vec4 diffuse(r.uniform(0, 1), r.uniform(0, 1), r.uniform(0, 1), r.uniform(0, 1));
    vec3 eye = r.unit() * r.uniform(0.5f, 5.0f);
    eye.z = std::fabs(eye.z);
    dvec3 vEye = glm::normalize(dvec3(eye));
    dvec3 vBump = glm::normalize((2.0 * dvec3(bumpTexel) - 1.0) * dvec3(0.2, 0.2, 1.0));
    double lDotN = glm::dot(vBump, vEye);
    dvec3 vReflect = 2.0 * lDotN * vBump - vEye;
    dvec2 uvEnv = (dvec2(vReflect.x, vReflect.y) + 1.0) * 0.5;
    dvec2 uvRefr = dvec2(uv) + dvec2(vBump.x, vBump.y);
    if (nearTexelEdge(uvEnv.x, 32) || nearTexelEdge(uvEnv.y, 32) || nearTexelEdge(uvRefr.x, 32) ||
        nearTexelEdge(uvRefr.y, 32) || nearTexelEdge(uv.x, 32) || nearTexelEdge(uv.y, 32))
      continue;
    dvec4 vEnvMap = texelAt(env, uvEnv);
    dvec4 a = texelAt(s, uvRefr), b = texelAt(s, dvec2(uv));
    dvec4 vFinal = b * a.w + a * (1.0 - a.w);
    double fresnel = sousaFresnel(std::clamp(lDotN, 0.0, 1.0), 0.4, 5.0);
    dvec4 vDiffuse = dvec4(diffuse);
    for (int c = 0; c < 3; ++c) vDiffuse[c] = std::clamp(0.1 + vDiffuse[c] * 0.9, 0.0, 1.0);
    dvec4 want = vDiffuse * vFinal * (1.0 - fresnel) + vEnvMap * fresnel;
    vec4 got = snell::snellGlass(s, env, uv, bumpTexel, diffuse, eye);
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], 2e-6) << k;
    ++checked;
  }
  EXPECT_GT(checked, 4000);
}

TEST(ShadeGlass, HostileInputsAreFinite) {
  snell::Texture2D s = randomTexture(8, 8, 10, true);
  const float bad[] = {kNaN, kInf, -kInf, 0.0f, 1e-40f};
  for (float x : bad) {
    vec4 c = snell::snellGlass(s, s, vec2(x), vec3(x), vec4(x, x, x, 0.5f), vec3(x));
    for (int k = 0; k < 4; ++k) EXPECT_TRUE(std::isfinite(c[k])) << x;
  }
  // Zero eye: F = 1, the reflection map's centre.
  vec4 c = snell::snellGlass(s, s, vec2(0.3f), vec3(0.5f, 0.5f, 1.0f), vec4(1.0f), vec3(0.0f));
  dvec4 want = texelAt(s, dvec2(0.5));
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(c[k], want[k], 1e-7);
}

}  // namespace
