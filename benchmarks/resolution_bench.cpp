// Cost against buffer resolution, per intersection strategy (CPU build, single
// thread): the same world-space scene (sphereBack, tests/support/depth_scenes.hpp)
// and the same refraction (eta 1/1.2, every pixel centre inside the silhouette
// in scan order) at 256, 512, 1024 and 2048 pixels square. The constant-time
// strategies do a fixed number of fetches per ray whatever the resolution; the
// DDA march walks pixels, so its fetches grow with the resolution for the same
// world-space segment (maxDistance 5). The linear march takes a fixed number of
// view-space steps, so its fetch count does not grow (its accuracy does not
// improve either). Time per ray may still grow for every strategy: the buffers
// outgrow the caches (a 2048^2 RGBA32F level is 64 MiB).
//
// Benchmarks "BM_Resolution/<strategy>/<N>". Each iteration traces one block
// of 256 consecutive rays (scan order: coherent fetches, as in a refraction
// pass); blocks are visited in a fixed shuffled order, so a short run samples
// the whole silhouette. Counters (machine-independent, over every 16th ray of
// the frame, computed once outside the timed loop):
//   fetches   mean texel fetches per ray
//   valid     share of rays with a valid hit
//   rays      rays in the frame
#include <benchmark/benchmark.h>

#include <snell/depth_pyramid.hpp>
#include <snell/intersect.hpp>

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "support/depth_scenes.hpp"
#include "support/search_rays.hpp"

namespace {

using snell::SnellHit;
using snell_search_test::Ray;

constexpr std::size_t kBlock = 256;
constexpr std::size_t kStatsStride = 16;

struct Frame {
  int size = 0;
  snell_test::DepthScene scene;
  snell::SnellDepthSurface surface;
  snell::Texture2D normals, pyramid;
  std::pair<float, float> range;
  std::vector<Ray> rays;
  std::vector<std::size_t> blocks;  // block start indices, shuffled

  explicit Frame(int n)
      : size(n),
        scene(snell_test::sphereBack(n, n)),
        surface(scene.surface()),
        normals(snell::snellBuildNormalMips(scene.normals)),
        pyramid(snell::snellBuildDepthPyramid(scene.depth, surface)),
        range(snell_search_test::depthRange(scene)),
        rays(snell_search_test::sphereRefractedRaysScan(scene)) {
    for (std::size_t i = 0; i + kBlock <= rays.size(); i += kBlock) blocks.push_back(i);
    std::shuffle(blocks.begin(), blocks.end(), std::mt19937(7));
  }
};

// Built on first use and kept (~0.5 GB for the four sizes): with
// --benchmark_enable_random_interleaving the sizes come in any order.
const Frame& frame(int n) {
  static std::map<int, std::unique_ptr<Frame>> frames;
  std::unique_ptr<Frame>& f = frames[n];
  if (!f) f = std::make_unique<Frame>(n);
  return *f;
}

using Strategy = std::function<SnellHit(const Frame&, const Ray&)>;

struct Named {
  const char* name;
  Strategy fn;
};

const std::vector<Named>& strategies() {
  static const std::vector<Named> s = {
      {"single", [](const Frame& f, const Ray& r) {
         return snell::snellIntersectSingleSample(r.origin, r.dir, f.scene.depth, f.surface);
       }},
      {"plane-normal-1", [](const Frame& f, const Ray& r) {
         return snell::snellIntersectPlaneNormal(r.origin, r.dir, f.scene.depth, f.normals, f.scene.depth, f.surface, 0.0f, 1, false);
       }},
      {"plane-depth-1", [](const Frame& f, const Ray& r) {
         return snell::snellIntersectPlaneDepth(r.origin, r.dir, f.pyramid, f.surface, f.pyramid.levelCount() - 1, 1, false);
       }},
      {"cbs-5", [](const Frame& f, const Ray& r) {
         return snell::snellConservativeBinarySearch(r.origin, r.dir, f.scene.depth, f.surface, f.range.first,
                                                     f.range.second, 5);
       }},
      {"binary-5", [](const Frame& f, const Ray& r) {
         return snell::snellBinarySearch(r.origin, r.dir, f.scene.depth, f.surface, f.range.first, f.range.second, 5);
       }},
      {"linear-binary-10x5", [](const Frame& f, const Ray& r) {
         return snell::snellLinearBinarySearch(r.origin, r.dir, f.scene.depth, f.surface, f.range.first,
                                               f.range.second, 10, 5);
       }},
      {"linear-march-32x4", [](const Frame& f, const Ray& r) {
         return snell::snellLinearMarch(r.origin, r.dir, f.scene.depth, f.surface, 5.0f, 32, 4);
       }},
      {"dda-stride-1", [](const Frame& f, const Ray& r) {
         return snell::snellDdaMarch(r.origin, r.dir, f.scene.depth, f.surface, 5.0f, SNELL_DDA_THICKNESS, 1.0f, 1024);
       }},
      {"dda-stride-4", [](const Frame& f, const Ray& r) {
         return snell::snellDdaMarch(r.origin, r.dir, f.scene.depth, f.surface, 5.0f, SNELL_DDA_THICKNESS, 4.0f, 1024);
       }},
  };
  return s;
}

void run(benchmark::State& state, const Named* strategy, int n) {
  const Frame& f = frame(n);
  double fetches = 0.0, valid = 0.0, sampled = 0.0;
  for (std::size_t i = 0; i < f.rays.size(); i += kStatsStride) {
    const SnellHit h = strategy->fn(f, f.rays[i]);
    fetches += h.fetches;
    valid += h.valid ? 1.0 : 0.0;
    sampled += 1.0;
  }
  std::size_t b = 0;
  for (auto _ : state) {
    const std::size_t first = f.blocks[b];
    for (std::size_t i = first; i < first + kBlock; ++i) {
      const SnellHit h = strategy->fn(f, f.rays[i]);
      benchmark::DoNotOptimize(h);
    }
    if (++b == f.blocks.size()) b = 0;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * kBlock));
  state.counters["fetches"] = fetches / sampled;
  state.counters["valid"] = valid / sampled;
  state.counters["rays"] = static_cast<double>(f.rays.size());
}

const bool kRegistered = [] {
  for (int n : {256, 512, 1024, 2048})
    for (const Named& s : strategies())
      benchmark::RegisterBenchmark(("BM_Resolution/" + std::string(s.name) + "/" + std::to_string(n)).c_str(), run, &s,
                                   n);
  return true;
}();

}  // namespace
