// Sousa's leakage problem on a small scene rendered analytically on the CPU
// (GPU Gems 2 ch. 19, sec. 19.2): a refractive sphere, an opaque red occluder
// in front of it covering part of its right side, a patterned background
// plane. The scene texture S (the scene without the refractive mesh) is ray
// cast in double at pixel centres; its alpha is Sousa's mask (cleared to 1, the
// refractive mesh's visible pixels written 0: where the occluder is in front
// the mesh fails the depth test and the alpha stays 1). A smooth bump that
// pushes every read to the right (towards the occluder) is applied over the
// sphere's visible pixels:
//   - snellPerturbSample (no mask) shows the occluder's red on sphere pixels;
//   - snellRefractionMasked shows none (a read outside the mask falls back to
//     the pixel's own unperturbed read, which is behind the sphere);
//   - snellRefractionMaskedDepth (the scene's depth buffer instead of the
//     mask) shows none either, in every depth convention, and keeps the
//     perturbed reads that land on the background beside the sphere.
#include <snell/camera.hpp>
#include <snell/shade.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/depth_scenes.hpp"

namespace {

using glm::dvec2;
using glm::dvec3;
using glm::vec2;
using glm::vec3;
using glm::vec4;

constexpr int kW = 96, kH = 96;
constexpr double kTanHalf = 0.45;  // tan of half the field of view, both axes (square image)
constexpr double kNear = 0.5, kFar = 40.0;
const dvec3 kSphereCentre(0.0, 0.0, -6.0);
constexpr double kSphereRadius = 1.6;
// The occluder: a fronto-parallel rectangle at z = -3, x in [0.15, 1.5], y in [-0.4, 0.5] (view space).
constexpr double kOccZ = -3.0, kOccX0 = 0.15, kOccX1 = 1.5, kOccY0 = -0.4, kOccY1 = 0.5;
constexpr double kBackgroundZ = -12.0;
const vec3 kOccluderColor(1.0f, 0.0f, 0.0f);
constexpr float kBumpScale = 0.12f;  // uv per unit bump: up to ~11.5 px

dvec3 pixelRay(int i, int j) {
  return dvec3((2.0 * (i + 0.5) / kW - 1.0) * kTanHalf, (2.0 * (j + 0.5) / kH - 1.0) * kTanHalf, -1.0);
}

// View distance (along -z: the ray is scaled to z = -1, so s = -z) of the sphere's front, or -1.
double sphereFrontS(const dvec3& q) {
  const double a = glm::dot(q, q), b = -2.0 * glm::dot(q, kSphereCentre);
  const double c = glm::dot(kSphereCentre, kSphereCentre) - kSphereRadius * kSphereRadius;
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return -1.0;
  return (-b - std::sqrt(disc)) / (2.0 * a);
}

bool hitsOccluder(const dvec3& q) {
  const double x = q.x * -kOccZ, y = q.y * -kOccZ;
  return x >= kOccX0 && x <= kOccX1 && y >= kOccY0 && y <= kOccY1;
}

// The background's colour: a checker of greens and blues, red channel 0.
vec3 backgroundColor(const dvec3& q) {
  const double x = q.x * -kBackgroundZ, y = q.y * -kBackgroundZ;
  const bool odd = (int(std::floor(x)) + int(std::floor(y))) % 2 != 0;
  return odd ? vec3(0.0f, 0.7f, 0.3f) : vec3(0.0f, 0.3f, 0.8f);
}

double windowDepth(double v, int convention) { return snell_test::windowDepth(v, kNear, kFar, convention); }

struct MaskScene {
  snell::Texture2D color;                          // S: rgb, alpha = Sousa's mask
  snell::Texture2D depth[SNELL_DEPTH_CONVENTION_COUNT];  // the opaque scene's depth (no sphere), NEAREST
  bool sphereVisible[kW * kH] = {};                 // the refractive mesh's fragments that pass the depth test
  float sphereDepth[SNELL_DEPTH_CONVENTION_COUNT][kW * kH] = {};  // their gl_FragCoord.z
  int visibleCount = 0, occludedSphereCount = 0;
};

const MaskScene& maskScene() {
  static const MaskScene* s = [] {
    auto* m = new MaskScene;
    snell::Image color(kW, kH);
    snell::Image depth[SNELL_DEPTH_CONVENTION_COUNT];
    for (auto& d : depth) d = snell::Image(kW, kH);
    for (int j = 0; j < kH; ++j)
      for (int i = 0; i < kW; ++i) {
        const dvec3 q = pixelRay(i, j);
        const bool occ = hitsOccluder(q);
        const double sphere = sphereFrontS(q);
        const bool visible = sphere > 0.0 && !occ;  // the occluder (s = 3) is nearer than any sphere point
        if (sphere > 0.0 && occ) ++m->occludedSphereCount;
        m->sphereVisible[j * kW + i] = visible;
        m->visibleCount += visible;
        color.at(i, j) = vec4(occ ? kOccluderColor : backgroundColor(q), visible ? 0.0f : 1.0f);
        const double sceneS = occ ? -kOccZ : -kBackgroundZ;
        for (int c = 0; c < SNELL_DEPTH_CONVENTION_COUNT; ++c) {
          depth[c].at(i, j) = vec4(float(windowDepth(sceneS, c)), 0.0f, 0.0f, 0.0f);
          if (visible) m->sphereDepth[c][j * kW + i] = float(windowDepth(sphere, c));
        }
      }
    m->color = snell::Texture2D(color);
    for (int c = 0; c < SNELL_DEPTH_CONVENTION_COUNT; ++c) m->depth[c] = snell::Texture2D(depth[c]);
    return m;
  }();
  return *s;
}

// A smooth normal map over the sphere, unpacked: always to the right (x in
// [0.35, 1]), a little up or down with the sphere's normal.
vec2 bumpAt(int i, int j) {
  const dvec3 q = pixelRay(i, j);
  const double s = sphereFrontS(q);
  const dvec3 n = (s * q - kSphereCentre) / kSphereRadius;
  return vec2(float(0.675 + 0.325 * n.x), float(0.3 * n.y));
}

vec2 pixelUv(int i, int j) { return vec2((float(i) + 0.5f) / float(kW), (float(j) + 0.5f) / float(kH)); }

bool isOccluder(const vec4& c) { return vec3(c) == kOccluderColor; }

TEST(ShadeMaskScene, SceneHasAnOccluderInFrontOfPartOfTheObject) {
  const MaskScene& s = maskScene();
  EXPECT_GT(s.visibleCount, 1000);
  EXPECT_GT(s.occludedSphereCount, 200);
}

TEST(ShadeMaskScene, AlphaMaskStopsTheOccluderLeaking) {
  const MaskScene& s = maskScene();
  int leakUnmasked = 0, leakMasked = 0, perturbedKept = 0;
  for (int j = 0; j < kH; ++j)
    for (int i = 0; i < kW; ++i) {
      if (!s.sphereVisible[j * kW + i]) continue;
      const vec2 uv = pixelUv(i, j), bump = bumpAt(i, j);
      const vec4 plain = snell::snellPerturbSample(s.color, uv, bump, kBumpScale);
      const vec4 masked = snell::snellRefractionMasked(s.color, uv, bump, kBumpScale);
      leakUnmasked += isOccluder(plain);
      leakMasked += isOccluder(masked);
      // The mask keeps the perturbed read where it stays on the object: a refraction still happens.
      perturbedKept += masked == plain && plain.w == 0.0f;
    }
  std::printf("[mask scene] %d visible object px: occluder leaks into %d without the mask, %d with it; %d perturbed "
              "reads kept\n",
              s.visibleCount, leakUnmasked, leakMasked, perturbedKept);
  EXPECT_GT(leakUnmasked, 100);  // the leakage Sousa's mask exists for
  EXPECT_EQ(leakMasked, 0);
  EXPECT_GT(perturbedKept, s.visibleCount / 4);
}

TEST(ShadeMaskScene, DepthMaskStopsTheOccluderLeakingInEveryConvention) {
  const MaskScene& s = maskScene();
  for (int c = 0; c < SNELL_DEPTH_CONVENTION_COUNT; ++c) {
    int leakUnmasked = 0, leakMasked = 0, keptOutsideObject = 0;
    for (int j = 0; j < kH; ++j)
      for (int i = 0; i < kW; ++i) {
        if (!s.sphereVisible[j * kW + i]) continue;
        const vec2 uv = pixelUv(i, j), bump = bumpAt(i, j);
        const vec4 plain = snell::snellPerturbSample(s.color, uv, bump, kBumpScale);
        const vec4 masked = snell::snellRefractionMaskedDepth(s.color, s.depth[c], uv, bump, kBumpScale,
                                                              s.sphereDepth[c][j * kW + i], c);
        leakUnmasked += isOccluder(plain);
        leakMasked += isOccluder(masked);
        // Unlike the alpha mask, a read that lands on the background beside the object is kept.
        keptOutsideObject += masked == plain && plain.w == 1.0f;
      }
    std::printf("[depth mask scene] convention %d: leaks %d without, %d with; %d reads beside the object kept\n", c,
                leakUnmasked, leakMasked, keptOutsideObject);
    EXPECT_GT(leakUnmasked, 100) << c;
    EXPECT_EQ(leakMasked, 0) << c;
    EXPECT_GT(keptOutsideObject, 0) << c;
  }
}

}  // namespace
