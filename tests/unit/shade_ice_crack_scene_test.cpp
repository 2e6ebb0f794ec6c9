// The ice shader's crack clipping (glsl/snell/shade/ice_crack_clip.glsl)
// against an analytic convex ice object: a sphere seen by a perspective
// camera. Per pixel, the front- and back-face depths come from a double ray-
// sphere intersection, converted to window depth for the convention and
// rounded once to float (what the two depth passes store; the front texture
// is cleared to the far value, the back texture to the near value outside the
// silhouette). Crack fragments: a crack plane through the object rasterized
// at every pixel, random points along each pixel ray, points just inside and
// just outside both faces (1e-4 relative: beyond the rounding band, so they
// must be classified exactly), and points on the faces (exactly, and 1e-8
// relative inside: within the band, either answer allowed). snellIceCrackKeep must keep exactly the
// fragments whose point p lies inside the sphere, |p - c| <= R evaluated in
// double, independently of any depth.
//
// Tolerance (the only disagreements allowed): the float rounding of the three
// depth values. A fragment may be misclassified only when its double window
// depth lies within 2^-23 (relative) of the front or back depth (each of the
// two values is rounded to the nearest float, an error of at most 2^-24
// relative), i.e. the fragment lies in a band of the surface whose width is
// that rounding mapped back to view distance; the test also measures that
// band and asserts it is below 1e-4 view units along the ray (the sphere's
// radius is 1.8).
#include <snell/shade.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "support/depth_scenes.hpp"

namespace {

using glm::dvec3;

constexpr int kW = 128, kH = 128;
constexpr double kTanHalf = 0.5;
constexpr double kNear = 0.5, kFar = 40.0;
const dvec3 kCentre(0.25, -0.15, -5.0);
constexpr double kRadius = 1.8;
// The crack plane: through the centre, offset a little, tilted.
const dvec3 kCrackPoint = kCentre + dvec3(0.2, -0.1, 0.3);
const dvec3 kCrackNormal = glm::normalize(dvec3(0.4, 0.6, 0.7));

double windowDepth(double v, int convention) { return snell_test::windowDepth(v, kNear, kFar, convention); }
bool reversed(int c) { return c == SNELL_DEPTH_REVERSED || c == SNELL_DEPTH_INFINITE_REVERSED; }

// Within the rounding of two float depths (2^-24 relative each, plus slack for the double evaluation).
bool withinRounding(double a, double b) { return std::fabs(a - b) <= std::ldexp(std::max(std::fabs(a), std::fabs(b)), -23); }

TEST(ShadeIceCrackScene, KeepsExactlyTheCrackFragmentsInsideAnAnalyticSphere) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int conv = 0; conv < SNELL_DEPTH_CONVENTION_COUNT; ++conv) {
    const float frontClear = reversed(conv) ? 0.0f : 1.0f, backClear = reversed(conv) ? 1.0f : 0.0f;
    long fragments = 0, inside = 0, kept = 0, disagree = 0, disagreeOutsideBand = 0, disagreeOffSurface = 0;
    double bandAlongRay = 0.0;  // largest |s_crack - s_face| among the disagreements (view distance along the ray)
    for (int j = 0; j < kH; ++j)
      for (int i = 0; i < kW; ++i) {
        const dvec3 q((2.0 * (i + 0.5) / kW - 1.0) * kTanHalf, (2.0 * (j + 0.5) / kH - 1.0) * kTanHalf, -1.0);
        // Front and back faces: s q on the sphere (s = view distance along -z).
        const double a = glm::dot(q, q), b = -2.0 * glm::dot(q, kCentre);
        const double cc = glm::dot(kCentre, kCentre) - kRadius * kRadius, disc = b * b - 4.0 * a * cc;
        const bool covered = disc >= 0.0;
        const double s0 = covered ? (-b - std::sqrt(disc)) / (2.0 * a) : 0.0;
        const double s1 = covered ? (-b + std::sqrt(disc)) / (2.0 * a) : 0.0;
        const double d0 = covered ? windowDepth(s0, conv) : double(frontClear);
        const double d1 = covered ? windowDepth(s1, conv) : double(backClear);
        const float front = float(d0), back = float(d1);
        // Crack fragments along this pixel's ray, as view distances.
        double cracks[16];
        int n = 0;
        const double den = glm::dot(q, kCrackNormal);
        if (den != 0.0) cracks[n++] = glm::dot(kCrackPoint, kCrackNormal) / den;  // the crack plane
        const double lo = covered ? s0 - 0.4 : 2.0, hi = covered ? s1 + 0.4 : 9.0;
        for (int k = 0; k < 6; ++k) cracks[n++] = lo + (hi - lo) * u01(rng);
        if (covered) {  // just inside / outside each face, beyond the rounding band
          cracks[n++] = s0 * (1.0 - 1e-4);
          cracks[n++] = s0 * (1.0 + 1e-4);
          cracks[n++] = s1 * (1.0 - 1e-4);
          cracks[n++] = s1 * (1.0 + 1e-4);
        }
        const int onSurfaceFrom = n;
        if (covered) {  // on the faces and within the rounding band: either answer is allowed
          cracks[n++] = s0;
          cracks[n++] = s1;
          cracks[n++] = s0 * (1.0 + 1e-8);
          cracks[n++] = s1 * (1.0 - 1e-8);
        }
        for (int k = 0; k < n; ++k) {
          const double s = cracks[k];
          if (!(s >= kNear && s <= kFar)) continue;  // clipped by the camera, never rasterized
          const double dc = windowDepth(s, conv);
          const bool want = glm::length(s * q - kCentre) <= kRadius;  // independent of every depth
          const bool got = snell::snellIceCrackKeep(float(dc), front, back, conv);
          ++fragments;
          inside += want;
          kept += got;
          if (got != want) {
            ++disagree;
            disagreeOffSurface += k < onSurfaceFrom;
            const bool band = covered && (withinRounding(dc, d0) || withinRounding(dc, d1));
            if (!band) {
              ++disagreeOutsideBand;
              ADD_FAILURE() << "convention " << conv << " pixel " << i << "," << j << " s " << s << " |p-c| "
                            << glm::length(s * q - kCentre) << " want " << want;
            } else {
              bandAlongRay = std::max(bandAlongRay, std::min(std::fabs(s - s0), std::fabs(s - s1)));
            }
          }
        }
      }
    std::printf("[ice crack scene] convention %d: %ld fragments, %ld inside, %ld kept, %ld disagreements (%ld of them "
                "not placed on the surface; all within the float-depth band: max %.3g view units from the surface)\n",
                conv, fragments, inside, kept, disagree, disagreeOffSurface, bandAlongRay);
    EXPECT_EQ(disagreeOutsideBand, 0) << conv;
    EXPECT_LT(bandAlongRay, 1e-4) << conv;
    EXPECT_GT(disagree, 0) << conv;  // the on-surface fragments do reach the band
    EXPECT_LE(disagreeOffSurface, fragments / 10000) << conv;  // rare: only fragments closer than the band to a face
    EXPECT_GT(inside, fragments / 10) << conv;
    EXPECT_GT(fragments - inside, fragments / 10) << conv;
  }
}

}  // namespace
