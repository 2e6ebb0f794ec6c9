// Ray sets and plain index-math checks shared by the intersect/ search and march
// tests and benchmarks (tests/unit/intersect_search*.cpp, intersect_march*.cpp,
// benchmarks/intersect_search_bench.cpp). Independent of the code under test:
// texels are read with floor(uv * size) on the Image, sphere points and normals
// come from the scene's analytic sphere, refraction from glm::refract.
#pragma once

#include <snell/intersect.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "support/depth_scenes.hpp"

namespace snell_search_test {

struct Ray {
  glm::vec3 origin;
  glm::vec3 dir;
};

// The texel a uv maps to, by plain index math (GL: texel i covers [i, i+1)/W);
// false when off screen or empty.
inline bool texelValid(const snell_test::DepthScene& sc, glm::vec2 uv) {
  if (!(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)) return false;
  const snell::Image& img = sc.depth.level(0);
  const int i = std::min(static_cast<int>(std::floor(uv.x * static_cast<float>(img.width))), img.width - 1);
  const int j = std::min(static_cast<int>(std::floor(uv.y * static_cast<float>(img.height))), img.height - 1);
  return img.at(i, j).x != sc.emptyDepth;
}

// The view-space z of the stored surface at a texel (double), NaN where empty.
inline double texelViewZ(const snell_test::DepthScene& sc, int i, int j) {
  const double d = sc.depth.level(0).at(i, j).x;
  if (static_cast<float>(d) == sc.emptyDepth) return std::numeric_limits<double>::quiet_NaN();
  const double n = sc.zNear, f = sc.zFar;
  // GL / ZERO_ONE window depth d = f (v - n) / (v (f - n))  =>  v = f n / (f - d (f - n)).
  return -(f * n / (f - d * (f - n)));
}

// What the top level of a min/max depth pyramid holds: the nearest and farthest
// surface z over all non-empty texels (view space, zNearest > zFarthest).
inline std::pair<float, float> depthRange(const snell_test::DepthScene& sc) {
  double zNearest = -std::numeric_limits<double>::infinity(), zFarthest = std::numeric_limits<double>::infinity();
  for (int j = 0; j < sc.height; ++j)
    for (int i = 0; i < sc.width; ++i) {
      const double z = texelViewZ(sc, i, j);
      if (std::isnan(z)) continue;
      zNearest = std::max(zNearest, z);
      zFarthest = std::min(zFarthest, z);
    }
  return {static_cast<float>(zNearest), static_cast<float>(zFarthest)};
}

// Refracted rays through the front of sphereBack's sphere (params[0] = centre,
// radius): origin = the front-face hit of a random pixel ray inside the
// silhouette, dir = glm::refract(view ray, outward normal, 1/ior).
inline std::vector<Ray> sphereRefractedRays(const snell_test::DepthScene& sc, int count, unsigned seed,
                                            double ior = 1.2) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const glm::dvec3 c(sc.params[0].x, sc.params[0].y, sc.params[0].z);
  const double r = sc.params[0].w;
  std::vector<Ray> rays;
  while (static_cast<int>(rays.size()) < count) {
    const glm::dvec3 q = sc.pixelRay(glm::dvec2(u01(rng), u01(rng)));
    const double a = glm::dot(q, q), b = -2.0 * glm::dot(q, c), cc = glm::dot(c, c) - r * r;
    const double disc = b * b - 4.0 * a * cc;
    if (!(disc > 0.0)) continue;
    const double s = (-b - std::sqrt(disc)) / (2.0 * a);
    const glm::dvec3 p = s * q, n = (p - c) / r;
    const glm::dvec3 t = glm::refract(glm::normalize(q), n, 1.0 / ior);
    if (glm::dot(t, t) == 0.0) continue;
    rays.push_back({glm::vec3(p), glm::vec3(glm::normalize(t))});
  }
  return rays;
}

// The same refracted rays for every pixel centre inside the silhouette, in
// scan order (what a refraction pass shades: coherent texel accesses).
inline std::vector<Ray> sphereRefractedRaysScan(const snell_test::DepthScene& sc, double ior = 1.2) {
  const glm::dvec3 c(sc.params[0].x, sc.params[0].y, sc.params[0].z);
  const double r = sc.params[0].w;
  std::vector<Ray> rays;
  for (int j = 0; j < sc.height; ++j)
    for (int i = 0; i < sc.width; ++i) {
      const glm::dvec3 q = sc.pixelRay(glm::dvec2((i + 0.5) / sc.width, (j + 0.5) / sc.height));
      const double a = glm::dot(q, q), b = -2.0 * glm::dot(q, c), cc = glm::dot(c, c) - r * r;
      const double disc = b * b - 4.0 * a * cc;
      if (!(disc > 0.0)) continue;
      const double s = (-b - std::sqrt(disc)) / (2.0 * a);
      const glm::dvec3 p = s * q, n = (p - c) / r;
      const glm::dvec3 t = glm::refract(glm::normalize(q), n, 1.0 / ior);
      if (glm::dot(t, t) == 0.0) continue;
      rays.push_back({glm::vec3(p), glm::vec3(glm::normalize(t))});
    }
  return rays;
}

// Rays for an opaque scene: origin at a random point of the frustum between
// view distance 1 and 2.5, aimed at a random point of the screen at view
// distance 3 .. 12 (some aimed beyond the screen edge, so they leave it).
inline std::vector<Ray> sceneRays(const snell_test::DepthScene& sc, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::vector<Ray> rays;
  rays.reserve(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    const glm::dvec3 o = (1.0 + 1.5 * u01(rng)) * sc.pixelRay(glm::dvec2(u01(rng), u01(rng)));
    const glm::dvec3 target =
        (3.0 + 9.0 * u01(rng)) * sc.pixelRay(glm::dvec2(-0.1 + 1.2 * u01(rng), -0.1 + 1.2 * u01(rng)));
    rays.push_back({glm::vec3(o), glm::vec3(glm::normalize(target - o))});
  }
  return rays;
}

inline bool finite(const snell::SnellHit& h) {
  return std::isfinite(h.uv.x) && std::isfinite(h.uv.y) && std::isfinite(h.position.x) &&
         std::isfinite(h.position.y) && std::isfinite(h.position.z);
}

}  // namespace snell_search_test
