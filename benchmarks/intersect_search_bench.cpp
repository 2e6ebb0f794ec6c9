// Rays/s of the CPU build of the intersect/ searches and marches, single
// thread, on a 512x512 sphereBack depth buffer (the back faces of a sphere,
// tests/support/depth_scenes.hpp), with refracted rays through the sphere's
// front (eta 1/1.2, the paper's IOR), one per pixel inside the silhouette in
// scan order, as a refraction pass shades them (coherent texel accesses; a
// random order makes every fetch a cache miss on the 4 MB texture). Counters:
//   items_per_second  rays/s
//   fetches           mean texel fetches per ray (machine-independent cost)
//   error             mean |hit - analytic hit| in view-space units (the
//                     sphere has radius 2.2), over rays both hit (every 16th ray)
//   hitShare          share of the rays with an analytic hit the strategy hit
// Figures are reported, never asserted. Build Release for meaningful numbers.
#include <benchmark/benchmark.h>

#include <snell/intersect.hpp>

#include <functional>
#include <optional>
#include <vector>

#include "support/depth_scenes.hpp"
#include "support/search_rays.hpp"

namespace {

using snell::SnellHit;
using snell_search_test::Ray;

struct Fixture {
  snell_test::DepthScene scene = snell_test::sphereBack(512, 512);
  snell::SnellDepthSurface surface = scene.surface();
  std::pair<float, float> range = snell_search_test::depthRange(scene);
  std::vector<Ray> rays = snell_search_test::sphereRefractedRaysScan(scene);
  std::vector<std::optional<glm::dvec3>> reference;  // of every kErrorStride-th ray
  static constexpr std::size_t kErrorStride = 16;
  Fixture() {
    for (std::size_t i = 0; i < rays.size(); i += kErrorStride)
      reference.push_back(scene.referenceHit(glm::dvec3(rays[i].origin), glm::dvec3(rays[i].dir)));
  }
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

using Strategy = std::function<SnellHit(const Fixture&, const Ray&)>;

void run(benchmark::State& state, const Strategy& strategy) {
  const Fixture& f = fixture();
  // Accuracy and cost once, outside the timed loop.
  double err = 0.0, fetches = 0.0;
  int both = 0, withRef = 0;
  for (std::size_t i = 0; i < f.rays.size(); ++i) {
    const SnellHit h = strategy(f, f.rays[i]);
    fetches += h.fetches;
    if (i % Fixture::kErrorStride != 0 || !f.reference[i / Fixture::kErrorStride]) continue;
    ++withRef;
    if (!h.valid) continue;
    ++both;
    err += glm::length(glm::dvec3(h.position) - *f.reference[i / Fixture::kErrorStride]);
  }
  std::size_t i = 0;
  const std::size_t n = f.rays.size();
  for (auto _ : state) {
    const SnellHit h = strategy(f, f.rays[i]);
    benchmark::DoNotOptimize(h);
    if (++i == n) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["fetches"] = fetches / double(f.rays.size());
  state.counters["error"] = both ? err / both : -1.0;
  state.counters["hitShare"] = withRef ? double(both) / withRef : 0.0;
  state.counters["rays"] = double(n);
}

void BM_ConservativeBinarySearch5(benchmark::State& state) {
  run(state, [](const Fixture& f, const Ray& r) {
    return snell::snellConservativeBinarySearch(r.origin, r.dir, f.scene.depth, f.surface, f.range.first,
                                                f.range.second, 5);
  });
}
void BM_BinarySearch5(benchmark::State& state) {
  run(state, [](const Fixture& f, const Ray& r) {
    return snell::snellBinarySearch(r.origin, r.dir, f.scene.depth, f.surface, f.range.first, f.range.second, 5);
  });
}
void BM_LinearBinarySearch10x5(benchmark::State& state) {
  run(state, [](const Fixture& f, const Ray& r) {
    return snell::snellLinearBinarySearch(r.origin, r.dir, f.scene.depth, f.surface, f.range.first, f.range.second,
                                          10, 5);
  });
}
void BM_LinearMarch32x4(benchmark::State& state) {
  run(state, [](const Fixture& f, const Ray& r) {
    return snell::snellLinearMarch(r.origin, r.dir, f.scene.depth, f.surface, 5.0f, 32, 4);
  });
}
void BM_DdaMarchStride1(benchmark::State& state) {
  run(state, [](const Fixture& f, const Ray& r) {
    return snell::snellDdaMarch(r.origin, r.dir, f.scene.depth, f.surface, 5.0f, SNELL_DDA_THICKNESS, 1.0f, 1024);
  });
}
void BM_DdaMarchStride4(benchmark::State& state) {
  run(state, [](const Fixture& f, const Ray& r) {
    return snell::snellDdaMarch(r.origin, r.dir, f.scene.depth, f.surface, 5.0f, SNELL_DDA_THICKNESS, 4.0f, 1024);
  });
}

// Cost against step count (the marches' one knob), same rays: the linear
// march's view-space steps (+4 bisections); the DDA's step cap at stride 1 (a
// ray that needs more pixels than the cap stops short: hitShare falls) and its
// stride (pixels per step, at a cap of 1024 that no ray reaches).
void BM_LinearMarchSteps(benchmark::State& state) {
  const int steps = static_cast<int>(state.range(0));
  run(state, [steps](const Fixture& f, const Ray& r) {
    return snell::snellLinearMarch(r.origin, r.dir, f.scene.depth, f.surface, 5.0f, steps, 4);
  });
}
void BM_DdaMarchMaxSteps(benchmark::State& state) {
  const int steps = static_cast<int>(state.range(0));
  run(state, [steps](const Fixture& f, const Ray& r) {
    return snell::snellDdaMarch(r.origin, r.dir, f.scene.depth, f.surface, 5.0f, SNELL_DDA_THICKNESS, 1.0f, steps);
  });
}
void BM_DdaMarchStride(benchmark::State& state) {
  const float stride = static_cast<float>(state.range(0));
  run(state, [stride](const Fixture& f, const Ray& r) {
    return snell::snellDdaMarch(r.origin, r.dir, f.scene.depth, f.surface, 5.0f, SNELL_DDA_THICKNESS, stride, 1024);
  });
}

BENCHMARK(BM_ConservativeBinarySearch5);
BENCHMARK(BM_BinarySearch5);
BENCHMARK(BM_LinearBinarySearch10x5);
BENCHMARK(BM_LinearMarch32x4);
BENCHMARK(BM_DdaMarchStride1);
BENCHMARK(BM_DdaMarchStride4);
BENCHMARK(BM_LinearMarchSteps)->RangeMultiplier(2)->Range(8, 128);
BENCHMARK(BM_DdaMarchMaxSteps)->RangeMultiplier(2)->Range(16, 256);
BENCHMARK(BM_DdaMarchStride)->RangeMultiplier(2)->Range(1, 16);

}  // namespace
