// Multi-threaded CPU use (a tool, not a shader): work split over explicit
// std::threads, wall-clock time (UseRealTime), one benchmark per thread count
// (1, 2, ... up to the hardware's, at least 2). The scaling ratio is
// items_per_second(T threads) / items_per_second(1 thread).
//
//   BM_BakeWymanDn/<mesh>/threads:T   Wyman's d_N for every vertex of a mesh
//     (include/snell/wyman_dn.hpp): the BVH is built once (its top levels on
//     the T threads, counted in the time, as a tool pays it), then vertex
//     chunks of 256 go to the threads through an atomic counter. Meshes: the bundled Stanford bunny
//     (examples/scenes/bunny.obj) and a bumpy icosphere of 7 subdivisions
//     (the lab's blob, 164k vertices). Items: vertices; counter bvh_share:
//     the BVH build's share of the calling thread's CPU time (with 1
//     thread: of the whole bake; CPU time, so other processes' load does not
//     move it).
//   BM_RefractFrame/<technique>/threads:T   snellTwoInterfaceRefraction for every
//     pixel of the glass sphere of tests/support/technique_scene.hpp in a
//     512x512 frame (rows through an atomic counter, colours written to a
//     frame buffer), per row of the technique table. Items: sphere pixels.
#include <benchmark/benchmark.h>

#include <snell/snell.hpp>
#include <snell/technique_table.hpp>
#include <snell/wyman_dn.hpp>

#include "lab/mesh_generators.hpp"
#include "lab/obj_loader.hpp"

#include <algorithm>
#include <atomic>
#include <ctime>
#include <string>
#include <thread>
#include <vector>

#include "support/technique_scene.hpp"

namespace {

double threadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

int maxThreads() { return std::max(2, static_cast<int>(std::thread::hardware_concurrency())); }

// Runs work(worker) on `threads` threads (the calling one among them) and joins.
template <class F>
void onThreads(int threads, F&& work) {
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
}

// ---- d_N baking ----

struct MeshInput {
  std::string name;
  snell::lab::Mesh mesh;
};

const std::vector<MeshInput>& meshes() {
  static const std::vector<MeshInput> m = [] {
    std::vector<MeshInput> v;
    v.push_back({"bunny", snell::lab::loadObj(std::string(SNELL_BENCH_SCENES_DIR) + "/bunny.obj")});
    snell::lab::BlobParams blob;
    blob.subdivisions = 7;
    v.push_back({"blob7", snell::lab::makeBlob(blob, 0.0f)});
    return v;
  }();
  return m;
}

void bakeWymanDn(benchmark::State& state, const MeshInput* input) {
  const snell::lab::Mesh& m = input->mesh;
  const int threads = static_cast<int>(state.range(0));
  constexpr std::size_t kChunk = 256;
  std::vector<float> out(m.positions.size());
  double buildSeconds = 0.0, totalSeconds = 0.0;
  for (auto _ : state) {
    const double t0 = threadCpuSeconds();
    const snell::wyman_detail::Baker baker(m.positions, m.normals, m.indices, 1e-7, threads);
    const double t1 = threadCpuSeconds();
    std::atomic<std::size_t> next{0};
    onThreads(threads, [&] {
      for (std::size_t first = next.fetch_add(kChunk); first < out.size(); first = next.fetch_add(kChunk))
        baker.bake(first, std::min(first + kChunk, out.size()), 0.0f, out.data());
    });
    benchmark::DoNotOptimize(out.data());
    buildSeconds += t1 - t0;
    totalSeconds += threadCpuSeconds() - t0;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * m.positions.size()));
  state.counters["vertices"] = static_cast<double>(m.positions.size());
  state.counters["triangles"] = static_cast<double>(m.indices.size() / 3);
  state.counters["bvh_share"] = totalSeconds > 0.0 ? buildSeconds / totalSeconds : 0.0;
}

// ---- a full frame of two-interface refraction ----

constexpr int kFrameSize = 512;

struct FramePixel {
  int index;  // y * width + x
  glm::vec3 p, n;
};

struct FrameInput {
  technique_test::Scene scene = technique_test::makeScene(kFrameSize, kFrameSize);
  std::vector<std::vector<FramePixel>> rows;  // the sphere's pixels, per row
  std::size_t pixels = 0;
  FrameInput() {
    rows.resize(kFrameSize);
    for (int j = 0; j < kFrameSize; ++j)
      for (int i = 0; i < kFrameSize; ++i) {
        const technique_test::Exact e = technique_test::exactTrace(
            scene.front, glm::dvec2((i + 0.5) / kFrameSize, (j + 0.5) / kFrameSize), 1.5);
        if (!e.hitsSphere) continue;
        rows[static_cast<std::size_t>(j)].push_back({j * kFrameSize + i, glm::vec3(e.p1), glm::vec3(e.n1)});
        ++pixels;
      }
  }
};

const FrameInput& frameInput() {
  static const FrameInput f;
  return f;
}

void refractFrame(benchmark::State& state, int technique) {
  const FrameInput& f = frameInput();
  const technique_test::Scene& s = f.scene;
  snell::SnellTechnique t = snell::snellTechniquePreset(technique);
  t.exit.source = SNELL_SOURCE_BUFFERS;
  const snell::SnellMaterial m = snell::snellMaterial();
  const snell::SnellView v = snell::snellView();
  const int threads = static_cast<int>(state.range(0));
  std::vector<glm::vec3> color(static_cast<std::size_t>(kFrameSize * kFrameSize));
  for (auto _ : state) {
    std::atomic<int> next{0};
    onThreads(threads, [&] {
      for (int y = next++; y < kFrameSize; y = next++)
        for (const FramePixel& p : f.rows[static_cast<std::size_t>(y)])
          color[static_cast<std::size_t>(p.index)] =
              snell::snellTwoInterfaceRefraction(p.p, p.n, 4.4f, TECH_OBJECT_ARGS(s), TECH_SCENE_ARGS(s), t, m, v)
                  .color;
    });
    benchmark::DoNotOptimize(color.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * f.pixels));
  state.counters["pixels"] = static_cast<double>(f.pixels);
}

void threadCounts(benchmark::internal::Benchmark* b) {
  for (int t = 1; t <= maxThreads(); t *= 2) b->Arg(t);
  if ((maxThreads() & (maxThreads() - 1)) != 0) b->Arg(maxThreads());  // not a power of two
  b->ArgName("threads")->UseRealTime()->Unit(benchmark::kMillisecond);
}

const bool kRegistered = [] {
  for (const char* mesh : {"bunny", "blob7"})
    benchmark::RegisterBenchmark(("BM_BakeWymanDn/" + std::string(mesh)).c_str(), [mesh](benchmark::State& st) {
      for (const MeshInput& m : meshes())
        if (m.name == mesh) bakeWymanDn(st, &m);
    })->Apply(threadCounts);
  // The real-time rows only: the image-space bound (a reference, ~50x single sample) would dominate the run.
  for (const snell::SnellTechniqueInfo& t : snell::snellTechniqueTable())
    if (t.kind != snell::SnellTechniqueKind::Reference)
      benchmark::RegisterBenchmark(("BM_RefractFrame/" + std::string(t.name)).c_str(), refractFrame, t.id)
          ->Apply(threadCounts);
  return true;
}();

}  // namespace
