// The lab's C++ mirror (stage 4 of a run): the read-back buffers as the C++ build samples them, the same
// technique call per covered pixel of the GPU's front pass, and each row's CPU-vs-GPU comparison.
#pragma once
#include "gpu_lab.hpp"
#include "lab_run.hpp"
#include "technique.hpp"

#include "lab/mask.hpp"
#include "lab/scene.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <thread>
#include <vector>

namespace snell::lab {

inline float clamp01(float v) { return std::min(std::max(v, 0.0f), 1.0f); }

// The largest input nudge (ulps per component of P1 or N1) under which a CPU/GPU difference beyond 4/255
// still counts as a rounding tie in the table: float32 positions read back from the G-buffer and the GPU's
// own arithmetic (fused multiply-adds in llvmpipe) differ from the C++ build by about this much.
constexpr int kTieUlps = 4;

// The read-back buffers as the C++ side samples them (the same filters as GL).
struct CpuBuffers {
  Texture2D backDepth, backNormal, backPyramid;
  Texture2D frontDepth, frontNormal;
  Texture2D sceneDepth, sceneNormal, scenePyramid, sceneColor;  // the layer snell's rows read
  Texture2D fullDepth, fullNormal, fullPyramid, fullColor;      // the whole opaque scene (engine rows)
  Image sceneSurface, fullSurface;  // which surface each texel shows (StaticBuffers), for the leak count
  Texture2D environment;
};

CpuBuffers cpuBuffers(const StaticBuffers& b, const ShadeConstants& k, const SceneFrame& frame);

// Runs f(y) for every row on `threads` threads.
template <class F>
void parallelRows(int height, int threads, F&& f) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::atomic<int> next{0};
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([&] {
      for (int y = next++; y < height; y = next++) f(y);
    });
  for (std::thread& t : pool) t.join();
}

// Stage 4, per technique: what the C++ build computes for one covered pixel of the GPU's front pass.
struct CpuShader {
  const LabRowSpec& info;
  float engineParameter;  // the engine model's free value (engine rows)
  const CpuBuffers& cb;
  const LabParams& params;
  int margin;  // guard band of the buffers, texels per side

  bool readsFullScene() const { return info.engine != nullptr; }

  SnellTwoInterfaceResult operator()(vec3 p1, vec3 n1, float dN) const {
    const bool full = readsFullScene();
    return labShadeRow(info.techniqueId(), info.engineModel(), engineParameter, info.reference(), p1, n1, dN,
                       cb.backDepth, cb.backNormal, cb.backPyramid, cb.frontDepth, cb.frontNormal,
                       full ? cb.fullDepth : cb.sceneDepth, full ? cb.fullNormal : cb.sceneNormal,
                       full ? cb.fullPyramid : cb.scenePyramid, full ? cb.fullColor : cb.sceneColor, cb.environment,
                       params);
  }

  // A foreground leak: the transmitted colour of the pixel whose front face is at p1 comes from an opaque
  // surface nearer the camera than that front face (the surface at the exit hit's texel of the depth
  // buffer the row read). Counted where the exit ray heads away from the camera: a path that leaves
  // through the front faces after bouncing inside may rightly see what stands in front. `surface`: which
  // surface leaked (StaticBuffers::sceneSurface's ids: k + 1 painting k, -(o + 1) object o).
  bool leaks(vec3 p1, const SnellTwoInterfaceResult& r, float* surface = nullptr) const {
    if (!r.exitHit.valid || !(r.exitDirection.z <= 0.0f)) return false;
    const Image& depth = (readsFullScene() ? cb.fullDepth : cb.sceneDepth).level(0);
    const Image& ids = readsFullScene() ? cb.fullSurface : cb.sceneSurface;
    const vec2 uv = glm::clamp(r.exitHit.uv, vec2(0.0f), vec2(1.0f));
    const int x = std::min(depth.width - 1, static_cast<int>(uv.x * static_cast<float>(depth.width)));
    const int y = std::min(depth.height - 1, static_cast<int>(uv.y * static_cast<float>(depth.height)));
    const double d = static_cast<double>(depth.at(x, y).x);
    if (!(d < 1.0)) return false;  // empty: the environment
    // Window depth to view distance in double (GL convention: d = (f (z - n)) / (z (f - n)) for distance z).
    const double n = static_cast<double>(params.zNear), f = static_cast<double>(params.zFar);
    const double distance = n * f / (f - d * (f - n));
    if (!(distance < -static_cast<double>(p1.z))) return false;
    if (surface && ids.width == depth.width && ids.height == depth.height) *surface = ids.at(x, y).x;
    return true;
  }

  // Is a CPU/GPU difference at (x, y) a rounding tie (a texel or TIR boundary that the two builds'
  // last-bit differences put on opposite sides) rather than a disagreement between the functions?
  // Nudges P1 or N1 by 1..maxUlps ulps per component (every sign pattern) and looks for a C++ result
  // within 1/255 of the GPU colour: returns the smallest nudge that reproduces it, or -1. With
  // `reproduced`, counts every reproducing nudge (and `tried`, every nudge) instead of stopping.
  int tieUlps(const TechniqueBuffers& tb, int x, int y, int maxUlps, int* reproduced, int* tried) const {
    const vec4 pf = tb.position.at(x, y), nf = tb.normal.at(x, y), gf = tb.color.at(x, y);
    int best = -1;
    for (int ulps = 1; ulps <= maxUlps; ulps *= 2)
      for (int which = 0; which < 2; ++which)
        for (int dx = -1; dx <= 1; ++dx)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dz = -1; dz <= 1; ++dz) {
              vec3 q(pf), m(nf);
              vec3& v = which == 0 ? q : m;
              const int d[3] = {dx, dy, dz};
              for (int a = 0; a < 3; ++a)
                for (int s = 0; s < ulps * std::abs(d[a]); ++s) v[a] = std::nextafter(v[a], d[a] > 0 ? 1e30f : -1e30f);
              const SnellTwoInterfaceResult rr = (*this)(q, m, pf.w);
              float e = 0.0f;
              for (int a = 0; a < 3; ++a) e = std::max(e, std::abs(clamp01(rr.color[a]) - clamp01(gf[a])));
              if (tried) ++*tried;
              if (e <= 1.0f / 255.0f) {
                if (reproduced) ++*reproduced;
                if (best < 0) best = ulps;
                if (!reproduced) return best;
              }
            }
    return best;
  }
};

// Stage 4a: the C++ image of one technique: the same labShade per covered pixel of the GPU's front
// pass, on the read-back inputs. rgb colour; stats x = fell back, y = fetches, z = a foreground leak
// (CpuShader::leaks).
void shadeOnCpu(const CpuShader& shade, const TechniqueBuffers& tb, int threads, Image& color, Image& stats);

// The row's shares and the CPU-vs-GPU agreement, summed over the front passes of the objects.
struct CpuGpuTally {
  std::size_t pixels = 0, within1 = 0, beyond4 = 0, ties = 0;
  std::size_t invalid = 0, backMiss = 0, exitMiss = 0, fetchDiff = 0, leaks = 0;
  std::map<int, std::size_t> leakSurfaces;  // leaked pixels per surface id (StaticBuffers::sceneSurface)
  double fetches = 0.0;
  double maxAbs = 0.0;
  int worstX = -1, worstY = -1;  // the pixel of maxAbs
  CpuGpuTally& operator+=(const CpuGpuTally& o);  // another object's pass
  void into(TechniqueRow& row) const;
  void agreementInto(TechniqueRow& row) const;  // the CPU-GPU fields only (pixels of every pass, back sides too)
};

// Stage 4b: the tally of one object's front pass (its covered pixels). `escapes` (References::escapes):
// where a fallback to the environment is right (not counted invalid) when the row found the back face, or
// has no back-face slot (an engine row).
CpuGpuTally compareCpuGpu(const CpuShader& shade, const TechniqueBuffers& tb, const Image& cpuColor,
                          const Image& cpuStats, const Mask& escapes);

// SNELL_LAB_DEBUG_PARITY: the worst pixel of one object's pass (`tally` of that pass alone): its inputs and both
// builds' results, on stderr.
void debugWorstPixel(const CpuShader& shade, const TechniqueBuffers& tb, const Image& cpuColor, const Image& cpuStats,
                     const CpuGpuTally& tally);

}  // namespace snell::lab
