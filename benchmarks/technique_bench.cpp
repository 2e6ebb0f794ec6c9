// CPU-build throughput of the two-interface refraction technique per row of
// the technique table (snellTechniqueTable(): BM_TwoInterface/<name>, exit slot
// on the opaque scene; snellTwoInterfaceRefraction on the glass sphere in front of a painting,
// tests/support/technique_scene.hpp, 256x256 buffers): pixels/s, fetches/px.
#include <benchmark/benchmark.h>

#include <snell/snell.hpp>
#include <snell/technique_table.hpp>

#include <vector>

#include "support/technique_scene.hpp"

namespace {

using namespace snell;

const technique_test::Scene& scene() {
  static const technique_test::Scene s = technique_test::makeScene(256, 256);
  return s;
}

struct Pixel {
  glm::vec3 p, n;
};

const std::vector<Pixel>& pixels() {
  static const std::vector<Pixel> v = [] {
    std::vector<Pixel> r;
    const technique_test::Scene& s = scene();
    for (int j = 0; j < s.height; j += 2)
      for (int i = 0; i < s.width; i += 2) {
        const technique_test::Exact e =
            technique_test::exactTrace(s.front, glm::dvec2((i + 0.5) / s.width, (j + 0.5) / s.height), 1.5);
        if (e.hitsSphere) r.push_back({glm::vec3(e.p1), glm::vec3(e.n1)});
      }
    return r;
  }();
  return v;
}

void twoInterface(benchmark::State& state, int technique) {
  const technique_test::Scene& s = scene();
  SnellTechnique t = snellTechniquePreset(technique);
  t.exit.source = SNELL_SOURCE_BUFFERS;
  const SnellMaterial m = snellMaterial();
  const SnellView v = snellView();
  const std::vector<Pixel>& px = pixels();
  double fetches = 0.0;
  std::size_t n = 0;
  for (auto _ : state) {
    for (const Pixel& p : px) {
      const SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(
          p.p, p.n, 4.4f, TECH_OBJECT_ARGS(s), TECH_SCENE_ARGS(s), t, m, v);
      benchmark::DoNotOptimize(r.color);
      fetches += r.fetches;
    }
    n += px.size();
  }
  state.SetItemsProcessed(int64_t(n));
  state.counters["fetches/px"] = n ? fetches / double(n) : 0.0;
}
const bool kRegistered = [] {
  for (const SnellTechniqueInfo& t : snellTechniqueTable())
    benchmark::RegisterBenchmark(("BM_TwoInterface/" + std::string(t.name)).c_str(), twoInterface, t.id);
  return true;
}();

}  // namespace
