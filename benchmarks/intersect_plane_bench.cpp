// Rays/s of the constant-time strategies (single thread, C++ build of the GLSL):
// single sample, normal-based plane (0/1/2 refinement iterations), depth-based
// plane on the depth pyramid (0/1/2), on a 512x512 back-face buffer of a sphere
// (tests/support/depth_scenes.hpp). Rays: the refracted rays (eta 1/1.5) of
// every pixel of the sphere's front face, in raster order (as a refraction pass
// would run them: neighbouring rays read neighbouring texels), cycled.
#include <benchmark/benchmark.h>

#include <snell/depth_pyramid.hpp>
#include <snell/intersect.hpp>

#include <cmath>
#include <vector>

#include "support/depth_scenes.hpp"

namespace {

using namespace snell;

struct Fixture {
  snell_test::DepthScene scene = snell_test::sphereBack(512, 512);
  SnellDepthSurface surface = scene.surface();
  Texture2D normals = snellBuildNormalMips(scene.normals);
  Texture2D pyramid = snellBuildDepthPyramid(scene.depth, scene.surface());
  std::vector<glm::vec3> origins, dirs;
  Fixture() {
    const glm::dvec3 c(0.3, -0.2, -6.0);
    const double r = 2.2;
    for (int j = 0; j < 512; ++j)
      for (int x = 0; x < 512; ++x) {
      const glm::dvec3 q = scene.pixelRay({(x + 0.5) / 512.0, (j + 0.5) / 512.0});
      const double a = glm::dot(q, q), b = -2.0 * glm::dot(q, c), cc = glm::dot(c, c) - r * r, disc = b * b - 4 * a * cc;
      if (disc < 0.0) continue;
      const glm::dvec3 w = (-b - std::sqrt(disc)) / (2.0 * a) * q, n = (w - c) / r, i = glm::normalize(q);
      const double eta = 1.0 / 1.5, ci = -glm::dot(i, n), k = 1.0 - eta * eta * (1.0 - ci * ci);
      origins.push_back(glm::vec3(w));
      dirs.push_back(glm::vec3(eta * i + (eta * ci - std::sqrt(k)) * n));
      }
  }
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

template <class F>
void runRays(benchmark::State& state, F intersect) {
  const Fixture& f = fixture();
  std::size_t i = 0;
  long fetches = 0, valid = 0, rays = 0;
  for (auto _ : state) {
    const SnellHit h = intersect(f, f.origins[i], f.dirs[i]);
    benchmark::DoNotOptimize(h);
    fetches += h.fetches;
    valid += h.valid;
    ++rays;
    if (++i == f.origins.size()) i = 0;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
  state.counters["fetches/ray"] = double(fetches) / double(rays);
  state.counters["valid"] = double(valid) / double(rays);
}

void BM_SingleSample(benchmark::State& state) {
  runRays(state, [](const Fixture& f, glm::vec3 o, glm::vec3 d) {
    return snellIntersectSingleSample(o, d, f.scene.depth, f.surface);
  });
}
void BM_PlaneNormal(benchmark::State& state) {
  const int it = static_cast<int>(state.range(0));
  runRays(state, [it](const Fixture& f, glm::vec3 o, glm::vec3 d) {
    return snellIntersectPlaneNormal(o, d, f.scene.depth, f.normals, f.scene.depth, f.surface, 0.0f, it, false);
  });
}
void BM_PlaneDepth(benchmark::State& state) {
  const int it = static_cast<int>(state.range(0));
  runRays(state, [it](const Fixture& f, glm::vec3 o, glm::vec3 d) {
    return snellIntersectPlaneDepth(o, d, f.pyramid, f.surface, f.pyramid.levelCount() - 1, it, false);
  });
}

}  // namespace

BENCHMARK(BM_SingleSample);
BENCHMARK(BM_PlaneNormal)->Arg(0)->Arg(1)->Arg(2);
BENCHMARK(BM_PlaneDepth)->Arg(0)->Arg(1)->Arg(2);
