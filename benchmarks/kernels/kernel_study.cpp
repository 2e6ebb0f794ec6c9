// Kernel study: one intersection strategy run
// over the 20000 rays of kernel_scene.hpp by snell's C++ mirror of the GLSL and
// by the minimal hand-written kernel of kernels.hpp, which must agree in every
// output bit (position xyz, uv, valid, fetches) ray by ray.
//
//   g++ -std=c++17 -O2 -ffp-contract=off -Iinclude -Iglsl -DSTRATEGY=cbs_5 -DIMPL=kernel
//       benchmarks/kernels/kernel_study.cpp
//
//   -DSTRATEGY=name  single_sample, plane_normal_0/1/2, cbs_5, plane_depth_0/1/2,
//                    linear_march_32x4, dda_1 (the KS_STRATEGY list below has
//                    each one's snell call and kernel call)
//   -DIMPL=snell|kernel  (default snell) runs that implementation on the first
//                    RAYS rays; prints "<hash of all output bits> valid=<n>"
//   -DRAYS=n         rays run (default 20000); a first argument overrides it at
//                    run time, so one binary gives callgrind both counts (a
//                    second one repeats the run that many times, default 1)
//   -DCHECK          runs both; prints the number of rays whose outputs differ
//                    in any bit and the first such ray with both results; exit 1
//                    when any differs. Also on a second, wider ray set
//                    (kernel_scene.hpp: misses, rim rays, rays towards the
//                    camera), reported on its own line, so that the kernels'
//                    other branches are checked too
//   -DTIME           runs both alternately (TIME_ROUNDS = 21 rounds, each
//                    implementation TIME_REPS passes over all rays per round,
//                    by default as many as make the faster one's measurement
//                    last >= 2 ms; the order swapped every round) and prints
//                    the median ns/ray of each
// The output array always has 20000 entries (zero beyond RAYS) and is hashed
// whole, so (Ir(RAYS = 20000) - Ir(RAYS = 0)) / 20000 counts the intersection
// and the store of its result only. kernel_table.sh drives it.
#include "kernel_scene.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#ifndef STRATEGY
#error "define STRATEGY (see the header comment)"
#endif
#ifndef IMPL
#define IMPL snell
#endif
#ifndef RAYS
#define RAYS 20000
#endif
#ifndef TIME_ROUNDS
#define TIME_ROUNDS 21
#endif
#ifndef TIME_REPS
#define TIME_REPS 0  // 0: enough passes for >= 2 ms per measurement
#endif

#define KS_CAT2(a, b) a##b
#define KS_CAT(a, b) KS_CAT2(a, b)
#define KS_STR2(x) #x
#define KS_STR(x) KS_STR2(x)

namespace {

using kern::Hit;
using kscene::Ray;
using kscene::Scene;

Hit fromSnell(const snell::SnellHit& h) {
  return Hit{h.position.x, h.position.y, h.position.z, h.uv.x, h.uv.y, h.valid ? 1 : 0, h.fetches};
}
glm::vec3 v3(const float* p) { return glm::vec3(p[0], p[1], p[2]); }

// name, snell's call, the kernel's call (S: the scene, R: the ray). The parameters
// are the flag study's (plane normal: normalLod 0; CBS: zNearest -4, zFarthest
// -6.2, 5 steps), intersect_plane_bench.cpp's (depth plane: maxLod = the
// pyramid's top level) and intersect_search_bench.cpp's (LinearMarch32x4:
// maxDistance 5, 32 steps, 4 refinements; DdaMarchStride1: maxDistance 5,
// infinite thickness, stride 1, at most 1024 steps).
#define KS_STRATEGY(name, snellCall, ...)                                               \
  inline Hit snell_##name(const Scene& S, const Ray& R) { return fromSnell(snellCall); } \
  inline Hit kernel_##name(const Scene& S, const Ray& R) {                              \
    (void)S;                                                                           \
    return __VA_ARGS__;                                                                \
  }

KS_STRATEGY(single_sample, snell::snellIntersectSingleSample(v3(R.o), v3(R.d), S.depth, S.surface),
            kern::singleSample(S.cam, R.o, R.d))
KS_STRATEGY(plane_normal_0, snell::snellIntersectPlaneNormal(v3(R.o), v3(R.d), S.depth, S.normal, S.depth, S.surface, 0.0f, 0, false),
            kern::planeNormal<0>(S.cam, R.o, R.d))
KS_STRATEGY(plane_normal_1, snell::snellIntersectPlaneNormal(v3(R.o), v3(R.d), S.depth, S.normal, S.depth, S.surface, 0.0f, 1, false),
            kern::planeNormal<1>(S.cam, R.o, R.d))
KS_STRATEGY(plane_normal_2, snell::snellIntersectPlaneNormal(v3(R.o), v3(R.d), S.depth, S.normal, S.depth, S.surface, 0.0f, 2, false),
            kern::planeNormal<2>(S.cam, R.o, R.d))
KS_STRATEGY(cbs_5, snell::snellConservativeBinarySearch(v3(R.o), v3(R.d), S.depth, S.surface, -4.0f, -6.2f, 5),
            kern::cbs<5>(S.cam, R.o, R.d, -4.0f, -6.2f))
KS_STRATEGY(linear_march_32x4, snell::snellLinearMarch(v3(R.o), v3(R.d), S.depth, S.surface, 5.0f, 32, 4),
            kern::linearMarch<32, 4>(S.cam, R.o, R.d, 5.0f))
KS_STRATEGY(dda_1,
            snell::snellDdaMarch(v3(R.o), v3(R.d), S.depth, S.surface, 5.0f, SNELL_DDA_THICKNESS, 1.0f, 1024),
            kern::ddaMarch(S.cam, R.o, R.d, 5.0f, 1.0f, 1024))
KS_STRATEGY(plane_depth_0,
            snell::snellIntersectPlaneDepth(v3(R.o), v3(R.d), S.pyramid, S.surface, S.pyramid.levelCount() - 1, 0, false),
            kern::planeDepth<0>(S.cam, R.o, R.d, S.cam.levels - 1))
KS_STRATEGY(plane_depth_1,
            snell::snellIntersectPlaneDepth(v3(R.o), v3(R.d), S.pyramid, S.surface, S.pyramid.levelCount() - 1, 1, false),
            kern::planeDepth<1>(S.cam, R.o, R.d, S.cam.levels - 1))
KS_STRATEGY(plane_depth_2,
            snell::snellIntersectPlaneDepth(v3(R.o), v3(R.d), S.pyramid, S.surface, S.pyramid.levelCount() - 1, 2, false),
            kern::planeDepth<2>(S.cam, R.o, R.d, S.cam.levels - 1))

// The measured loop (not inlined, so callgrind_annotate shows it as one function).
template <Hit (*F)(const Scene&, const Ray&)>
__attribute__((noinline)) void runRays(const Scene& S, Hit* out, int n, const Ray* rays) {
  for (int i = 0; i < n; ++i) out[i] = F(S, rays[i]);
}
template <Hit (*F)(const Scene&, const Ray&)>
void runRays(const Scene& S, Hit* out, int n) {
  runRays<F>(S, out, n, S.rays.data());
}

std::uint64_t hashHits(const std::vector<Hit>& hits) {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&](const void* p) {
    std::uint32_t u;
    std::memcpy(&u, p, 4);
    h = (h ^ u) * 1099511628211ull;
  };
  for (const Hit& x : hits) {
    mix(&x.x), mix(&x.y), mix(&x.z), mix(&x.u), mix(&x.v), mix(&x.valid), mix(&x.fetches);
  }
  return h;
}
int validCount(const std::vector<Hit>& hits) {
  int n = 0;
  for (const Hit& x : hits) n += x.valid;
  return n;
}

#ifdef CHECK
bool sameBits(const Hit& a, const Hit& b) { return std::memcmp(&a, &b, sizeof(Hit)) == 0; }
unsigned bits(float f) {
  unsigned u;
  std::memcpy(&u, &f, 4);
  return u;
}
void printHit(const char* who, const Hit& h) {
  std::printf("  %-6s position (%.9g, %.9g, %.9g) [%08x %08x %08x] uv (%.9g, %.9g) [%08x %08x] valid %d fetches %d\n",
              who, h.x, h.y, h.z, bits(h.x), bits(h.y), bits(h.z), h.u, h.v, bits(h.u), bits(h.v), h.valid, h.fetches);
}
#endif
#ifdef TIME
double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
#endif

}  // namespace

int main(int argc, char** argv) {
  int rays = RAYS;
  if (argc > 1) rays = std::atoi(argv[1]);
  rays = std::max(0, std::min(rays, kscene::kRays));
  Scene S;
  const char* name = KS_STR(STRATEGY);
  const bool pyramid = std::strncmp(name, "plane_depth", 11) == 0;
#ifdef CHECK
  kscene::build(S, pyramid, true);
#else
  kscene::build(S, pyramid, false);
#endif
  std::vector<Hit> out(kscene::kRays, Hit{});
  int status = 0;
#if defined(CHECK) || defined(TIME)
  std::vector<Hit> outK(kscene::kRays, Hit{});
  constexpr auto snellF = &KS_CAT(snell_, STRATEGY);
  constexpr auto kernelF = &KS_CAT(kernel_, STRATEGY);
#endif
#ifdef CHECK
  // The benchmark's rays, then (reported apart) the wide set of kernel_scene.hpp.
  for (int set = 0; set < 2; ++set) {
    const std::vector<Ray>& R = set == 0 ? S.rays : S.wide;
    const int n = set == 0 ? rays : kscene::kRays;
    std::fill(out.begin(), out.end(), Hit{});
    std::fill(outK.begin(), outK.end(), Hit{});
    runRays<snellF>(S, out.data(), n, R.data());
    runRays<kernelF>(S, outK.data(), n, R.data());
    int differ = 0, first = -1;
    for (int i = 0; i < n; ++i)
      if (!sameBits(out[static_cast<std::size_t>(i)], outK[static_cast<std::size_t>(i)])) {
        if (first < 0) first = i;
        ++differ;
      }
    std::printf("check %s %s rays=%d differ=%d snell=%016llx kernel=%016llx valid=%d/%d\n", name,
                set == 0 ? "bench" : "wide", n, differ, (unsigned long long)hashHits(out),
                (unsigned long long)hashHits(outK), validCount(out), validCount(outK));
    if (first >= 0) {
      const Ray& r = R[static_cast<std::size_t>(first)];
      std::printf("first differing ray %d: origin (%.9g, %.9g, %.9g) dir (%.9g, %.9g, %.9g)\n", first, r.o[0], r.o[1],
                  r.o[2], r.d[0], r.d[1], r.d[2]);
      printHit("snell", out[static_cast<std::size_t>(first)]);
      printHit("kernel", outK[static_cast<std::size_t>(first)]);
      status = 1;
    }
  }
#endif
#ifdef TIME
  {
    using clock = std::chrono::steady_clock;
    const int n = kscene::kRays;
    auto once = [&](bool kernel) {  // warm-up, and the pass time the repeat count follows
      const auto t0 = clock::now();
      if (kernel)
        runRays<kernelF>(S, outK.data(), n);
      else
        runRays<snellF>(S, out.data(), n);
      return std::chrono::duration<double, std::nano>(clock::now() - t0).count();
    };
    const double pass = std::min(once(false), once(true));
    const int reps = TIME_REPS > 0 ? TIME_REPS : std::max(1, static_cast<int>(std::ceil(2e6 / std::max(pass, 1.0))));
    std::vector<double> ts, tk;
    auto timeOne = [&](bool kernel) {
      const auto t0 = clock::now();
      for (int rep = 0; rep < reps; ++rep) {
        if (kernel)
          runRays<kernelF>(S, outK.data(), n);
        else
          runRays<snellF>(S, out.data(), n);
      }
      const auto t1 = clock::now();
      const double ns = std::chrono::duration<double, std::nano>(t1 - t0).count() / (double(reps) * n);
      (kernel ? tk : ts).push_back(ns);
    };
    for (int round = 0; round < TIME_ROUNDS; ++round) {
      timeOne(round % 2 != 0);
      timeOne(round % 2 == 0);
    }
    std::printf("time %s snell_ns=%.2f kernel_ns=%.2f (median of %d rounds, %d passes of %d rays each) %016llx %016llx\n",
                name, median(ts), median(tk), TIME_ROUNDS, reps, n,
                (unsigned long long)hashHits(out), (unsigned long long)hashHits(outK));
  }
#endif
#if !defined(CHECK) && !defined(TIME)
  // Called from a loop with a run-time count (1), as in the CHECK/TIME builds: a
  // function GCC sees called once from main is compiled as "executed once", for
  // size in places (sqrtf as a library call, snellViewToUv not inlined), so the
  // instructions callgrind counts would not be those that are timed.
  const int passes = argc > 2 ? std::atoi(argv[2]) : 1;
  for (int pass = 0; pass < passes; ++pass) runRays<&KS_CAT(KS_CAT(IMPL, _), STRATEGY)>(S, out.data(), rays);
  std::printf("%016llx valid=%d\n", (unsigned long long)hashHits(out), validCount(out));
#endif
  return status;
}
