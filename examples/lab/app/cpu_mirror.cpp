#include "cpu_mirror.hpp"

#include <snell/depth_pyramid.hpp>
#include <snell/gpu/frame_compare.hpp>

#include <cstdio>
#include <cstdlib>

namespace snell::lab {

CpuBuffers cpuBuffers(const StaticBuffers& b, const ShadeConstants& k, const SceneFrame& frame) {
  const Filter normalFilter = k.normalFilter == NormalFilter::Linear ? Filter::Linear : Filter::Nearest;
  CpuBuffers c;
  c.backDepth = Texture2D(b.backDepth);
  c.backNormal = Texture2D(b.backNormal, normalFilter);
  c.frontDepth = Texture2D(b.frontDepth);
  c.frontNormal = Texture2D(b.frontNormal, normalFilter);
  c.sceneDepth = Texture2D(b.sceneDepth);
  c.sceneNormal = Texture2D(b.sceneNormal, normalFilter);
  c.sceneColor = Texture2D(b.sceneColor, Filter::Linear, b.sceneColorMips.empty() ? MipFilter::None : MipFilter::Linear);
  for (const Image& level : b.sceneColorMips) c.sceneColor.addLevel(level);
  c.fullDepth = Texture2D(b.fullDepth);
  c.fullNormal = Texture2D(b.fullNormal, normalFilter);
  c.fullColor = Texture2D(b.fullColor, Filter::Linear, b.fullColorMips.empty() ? MipFilter::None : MipFilter::Linear);
  for (const Image& level : b.fullColorMips) c.fullColor.addLevel(level);
  c.sceneSurface = b.sceneSurface;
  c.fullSurface = b.fullSurface;
  c.fullPyramid =
      snellBuildDepthPyramid(c.fullDepth, snellDepthSurface(k.params.clipFromView, k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 1.0f));
  c.backPyramid =
      snellBuildDepthPyramid(c.backDepth, snellDepthSurface(k.params.clipFromView, k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 0.0f));
  c.scenePyramid =
      snellBuildDepthPyramid(c.sceneDepth, snellDepthSurface(k.params.clipFromView, k.params.zNear, k.params.zFar, SNELL_DEPTH_GL, 1.0f));
  c.environment = environmentTexture(frame);
  return c;
}

void shadeOnCpu(const CpuShader& shade, const TechniqueBuffers& tb, int threads, Image& color, Image& stats) {
  parallelRows(tb.normal.height, threads, [&](int y) {
    for (int x = 0; x < tb.normal.width; ++x) {
      const vec4 n = tb.normal.at(x, y);
      if (!(n.w > 0.0f)) continue;
      const vec4 p = tb.position.at(x, y);
      const SnellTwoInterfaceResult r = shade(vec3(p), vec3(n), p.w);
      color.at(x, y) = vec4(r.color, 1.0f);
      float surface = 0.0f;
      const bool leaked = shade.leaks(vec3(p), r, &surface);
      stats.at(x, y) = vec4(r.fellBack ? 1.0f : 0.0f, static_cast<float>(r.fetches), leaked ? 1.0f : 0.0f, surface);
    }
  });
}

CpuGpuTally compareCpuGpu(const CpuShader& shade, const TechniqueBuffers& tb, const Image& cpuColor,
                          const Image& cpuStats, const Mask& escapes) {
  const bool backSlot = shade.info.engine == nullptr;
  CpuGpuTally tally;
  auto covered = [&](int x, int y) { return tb.normal.at(x, y).w > 0.0f; };
  const gpu::FrameComparison c =
      gpu::compareFrames(tb.color, cpuColor, covered, gpu::ClampChannels::ToUnit, [&](int x, int y) {
        tally.ties += shade.tieUlps(tb, x, y, kTieUlps, nullptr, nullptr) > 0;
      });
  tally.maxAbs = c.maxAbs;
  tally.worstX = c.worstX;
  tally.worstY = c.worstY;
  tally.pixels = c.pixels;
  tally.within1 = c.within1;
  tally.beyond4 = c.beyond4;
  for (int y = 0; y < tb.normal.height; ++y)
    for (int x = 0; x < tb.normal.width; ++x) {
      if (!covered(x, y)) continue;
      const vec4 s = tb.stats.at(x, y);
      const bool rightlyEscaped = escapes.at(x, y) && s.w < 0.5f && (s.z > 0.5f || !backSlot);
      tally.invalid += s.x > 0.5f && !rightlyEscaped;
      tally.backMiss += s.z < 0.5f;
      tally.exitMiss += s.w < 0.5f;
      tally.fetches += static_cast<double>(s.y);
      tally.fetchDiff += s.y != cpuStats.at(x, y).y;
      if (cpuStats.at(x, y).z > 0.5f) {
        ++tally.leaks;
        ++tally.leakSurfaces[static_cast<int>(cpuStats.at(x, y).w)];
      }
    }
  return tally;
}

CpuGpuTally& CpuGpuTally::operator+=(const CpuGpuTally& o) {
  if (o.worstX >= 0 && (worstX < 0 || o.maxAbs > maxAbs)) {
    maxAbs = o.maxAbs;
    worstX = o.worstX;
    worstY = o.worstY;
  }
  pixels += o.pixels;
  within1 += o.within1;
  beyond4 += o.beyond4;
  ties += o.ties;
  invalid += o.invalid;
  backMiss += o.backMiss;
  exitMiss += o.exitMiss;
  fetchDiff += o.fetchDiff;
  leaks += o.leaks;
  for (const auto& [surface, count] : o.leakSurfaces) leakSurfaces[surface] += count;
  fetches += o.fetches;
  return *this;
}

void CpuGpuTally::into(TechniqueRow& row) const {
  agreementInto(row);
  const double n = pixels ? static_cast<double>(pixels) : 1.0;
  row.invalidShare = static_cast<double>(invalid) / n;
  row.backMissShare = static_cast<double>(backMiss) / n;
  row.exitMissShare = static_cast<double>(exitMiss) / n;
  row.fetchesPerPixel = fetches / n;
  row.fetchMismatch = static_cast<double>(fetchDiff) / n;
  row.leakPixels = static_cast<int>(leaks);
  row.leakSurfaces.clear();
  for (const auto& [surface, count] : leakSurfaces) row.leakSurfaces.emplace_back(surface, static_cast<int>(count));
}

void CpuGpuTally::agreementInto(TechniqueRow& row) const {
  row.cpuGpuMaxAbs = maxAbs;
  row.worstX = worstX;
  row.worstY = worstY;
  row.cpuGpuBeyond4Pixels = static_cast<int>(beyond4);
  row.cpuGpuBeyond4Ties = static_cast<int>(ties);
  const double n = pixels ? static_cast<double>(pixels) : 1.0;
  row.cpuGpuBeyond1 = static_cast<double>(pixels - within1) / n;
  row.cpuGpuBeyond4 = static_cast<double>(beyond4) / n;
}

void debugWorstPixel(const CpuShader& shade, const TechniqueBuffers& tb, const Image& cpuColor, const Image& cpuStats,
                     const CpuGpuTally& tally) {
  if (!std::getenv("SNELL_LAB_DEBUG_PARITY") || tally.worstX < 0) return;
  const int x = tally.worstX, y = tally.worstY;
  const glm::dvec4 p(tb.position.at(x, y)), nn(tb.normal.at(x, y)), g(tb.color.at(x, y)), c(cpuColor.at(x, y));
  const glm::dvec4 gs(tb.stats.at(x, y)), cs(cpuStats.at(x, y));
  std::fprintf(stderr,
               "[parity] %s worst pixel (%d, %d): |d| %.2f/255; P1 (%.9g %.9g %.9g) N1 (%.9g %.9g %.9g) dN %.9g\n"
               "  gpu rgb (%.5f %.5f %.5f) fellBack %g fetches %g backHit %g exitHit %g\n"
               "  cpu rgb (%.5f %.5f %.5f) fellBack %g fetches %g\n",
               shade.info.name().c_str(), x, y, 255.0 * tally.maxAbs, p.x, p.y, p.z, nn.x, nn.y, nn.z, p.w, g.x, g.y, g.z,
               gs.x, gs.y, gs.z, gs.w, c.x, c.y, c.z, cs.x, cs.y);
  int reproduced = 0, tried = 0;
  const int bestUlps = shade.tieUlps(tb, x, y, 32, &reproduced, &tried);
  std::fprintf(stderr, "  input nudges (P1 or N1, 1..32 ulps) reproducing the GPU colour: %d of %d, smallest %d ulps\n",
               reproduced, tried, bestUlps);
}

}  // namespace snell::lab
