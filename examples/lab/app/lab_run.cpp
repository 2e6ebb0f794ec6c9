#include "lab_run.hpp"
#include "cpu_mirror.hpp"
#include "engine_sweep.hpp"
#include "pictures.hpp"
#include "references.hpp"
#include "report.hpp"
#include "web_bundle.hpp"

#include "technique.hpp"

#include "lab/error.hpp"
#include "lab/metrics.hpp"
#include "lab/scene.hpp"

#include <snell/wyman_dn.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace snell::lab {

namespace fs = std::filesystem;

namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// ---- The stages of one lab run, in order (runLab below). ----

// Stage 1: the requested rows of the technique table, in table order, and the image-space bounds
// they are measured against: always the two-interface one, the one with B bounces when a row with B
// runs. Before the scene loads: a typo should not cost a ray trace.
std::vector<LabRowSpec> selectTechniques(const LabOptions& options) {
  const auto asked = [&](const std::string& name) {
    return options.techniques.empty() ||
           std::find(options.techniques.begin(), options.techniques.end(), name) != options.techniques.end();
  };
  const auto someRowBounces = [&](int bounces) {
    for (const SnellTechniqueInfo& t : snellTechniqueTable())
      if (t.kind != SnellTechniqueKind::Reference && asked(t.name) && snellTechniqueBounces(t) == bounces) return true;
    return false;
  };
  std::vector<LabRowSpec> rows;
  for (const SnellTechniqueInfo& t : snellTechniqueTable()) {
    const bool bound = t.kind == SnellTechniqueKind::Reference &&
                       (snellTechniqueBounces(t) == 0 || someRowBounces(snellTechniqueBounces(t)));
    if (bound || (t.kind != SnellTechniqueKind::Reference && asked(t.name))) rows.push_back(LabRowSpec{&t, nullptr});
  }
  // The engines' models after the techniques: snell's cheapest tier, compared on the same buffers.
  for (const SnellEngineModelInfo& m : snellEngineModelTable())
    if (asked(m.name)) rows.push_back(LabRowSpec{nullptr, &m});
  return rows;
}

// Wyman's d_N per vertex, when a technique reads it (else none: the shaders read 0).
std::vector<float> wymanDnIfNeeded(const SceneFrame& frame, const std::vector<LabRowSpec>& techniques) {
  const bool wanted = std::any_of(techniques.begin(), techniques.end(),
                                  [](const LabRowSpec& t) { return t.needsDn(); });
  if (!wanted) return {};
  return computeWymanDn(frame.object.positions, frame.object.normals, frame.object.indices);
}

// Stage 4: one technique on the GPU, the same in C++, compared; its image (the object composited over
// the scene) for the pictures.
TechniqueRow runTechnique(GpuLab& gpu, std::size_t index, const CpuShader& shade, const StaticBuffers& sb,
                          const References& refs, int threads, Image& image) {
  gpu.renderTechnique(index);  // also compiles the shader's JIT code: not timed
  const TechniqueBuffers tb = gpu.readTechnique();
  Image cpuColor(tb.color.width, tb.color.height), cpuStats(tb.color.width, tb.color.height);
  shadeOnCpu(shade, tb, threads, cpuColor, cpuStats);
  TechniqueRow row;
  row.name = shade.info.name();
  row.label = shade.info.label();
  compareCpuGpu(shade, tb, cpuColor, cpuStats, row);
  debugWorstPixel(shade, tb, cpuColor, cpuStats, row);
  // Coverage: the ray tracer's object pixels that the front pass did not shade (near-plane clipping,
  // silhouette rasterization) hold the scene colour in the composite; say how many, and refuse to score
  // a technique that shaded none of them.
  const Mask& object = refs.full.mask;
  std::size_t unshaded = 0, overdrawn = 0;
  for (int y = 0; y < tb.normal.height; ++y)
    for (int x = 0; x < tb.normal.width; ++x) {
      const bool covered = tb.normal.at(x, y).w > 0.0f;
      unshaded += object.at(x, y) && !covered;
      overdrawn += !object.at(x, y) && covered;
    }
  const std::size_t objectPixels = object.count();
  if (unshaded == objectPixels)
    throw Error(ErrorKind::Render,
                "technique " + shade.info.name() + " shaded none of the " + std::to_string(objectPixels) +
                    " pixels where the ray tracer sees the object (does the near plane cut the object, or does the "
                    "camera sit inside it?); no error can be measured");
  row.unshadedShare = objectPixels ? static_cast<double>(unshaded) / static_cast<double>(objectPixels) : 0.0;
  row.overdrawnShare = objectPixels ? static_cast<double>(overdrawn) / static_cast<double>(objectPixels) : 0.0;
  image = composite(tb.color, tb.normal, sb.fullColor, shade.margin);
  row.mseFull = compareImages(refs.full.color, image, refs.full.mask).mse;
  row.mseTwo = compareImages(refs.two.color, image, refs.full.mask).mse;
  row.mseFullTir = compareImages(refs.full.color, image, refs.tir).mse;
  row.bounces = shade.info.bounces();
  row.modelEvents = 2 + row.bounces;
  row.mseModel = compareImages(refs.modelOf(row.bounces).color, image, refs.full.mask).mse;
  return row;
}

// Stage 5: all techniques interleaved, frame after frame; median per technique, ratios to single sample
// (to the first row when single sample did not run).
void timeTechniques(GpuLab& gpu, const std::vector<LabRowSpec>& techniques, int frames,
                    LabResult& result) {
  std::vector<std::vector<double>> times(techniques.size());
  // The bound is a reference, not a contender: one timed frame is enough to show its cost.
  for (int f = 0; f < frames; ++f)
    for (std::size_t i = 0; i < techniques.size(); ++i)
      if (f == 0 || !techniques[i].reference()) times[i].push_back(gpu.renderTechnique(i));
  double unit = 0.0;
  for (std::size_t i = 0; i < techniques.size(); ++i) {
    result.rows[i].medianMs = median(times[i]);
    if (techniques[i].costUnit()) unit = result.rows[i].medianMs;
  }
  if (unit <= 0.0 && !result.rows.empty()) unit = result.rows[0].medianMs;
  for (TechniqueRow& r : result.rows) r.costRatio = unit > 0.0 ? r.medianMs / unit : 0.0;
}


}  // namespace

// The guard band in texels per side: the fraction asked for, grown until both buffer sides are multiples
// of 32 where that is possible: the depth pyramid's levels then halve exactly for five levels (odd sizes
// drop a texel row per level, which shifts the coarse levels the depth-based plane reads).
namespace {
int guardBandMargin(double fraction, int width, int height) {
  int margin = static_cast<int>(std::lround(fraction * std::max(width, height)));
  if (margin > 0)
    for (int m = margin; m < margin + 32; ++m)
      if ((width + 2 * m) % 32 == 0 && (height + 2 * m) % 32 == 0) return m;
  return margin;
}
}  // namespace

LabResult runLab(const LabOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<LabRowSpec> techniques = selectTechniques(options);

  Scene scene = loadScene(options.scenePath);
  if (options.width > 0) scene.camera.width = options.width;
  if (options.height > 0) scene.camera.height = options.height;
  const SceneFrame frame = buildFrame(scene, scene.frameTime(0));

  LabResult result;
  result.scene = scene.name.empty() ? fs::path(options.scenePath).stem().string() : scene.name;
  result.width = frame.camera.width;
  result.height = frame.camera.height;
  result.frames = options.frames;

  const References refs = traceReferences(frame, techniques, options, result);

  // Stage 3: the GPU passes that do not depend on the technique (scene, back faces, pyramids), once:
  // the frame is static. Their read-back buffers are what the C++ side shades from.
  std::vector<LabShader> shaders;
  for (const LabRowSpec& t : techniques) shaders.push_back({t.techniqueId(), t.reference(), t.engineModel()});
  const int margin = guardBandMargin(options.guardBand, result.width, result.height);
  result.guardBand = margin;
  ShadeConstants k = shadeConstants(frame, margin);
  k.normalFilter = options.normalFilter;
  k.params.depthFilter = options.depthFilter;
  k.params.reflectSource = options.reflectSource;
  k.sceneLayer = options.sceneLayer;
  if (options.insideScene >= 0) k.params.insideScene = options.insideScene;
  result.insideScene = k.params.insideScene != 0;
  result.sceneLayer = options.sceneLayer;
  // The web page offers every technique, ISR's d_N included.
  const std::vector<float> dN = options.webBundleDir.empty()
                                    ? wymanDnIfNeeded(frame, techniques)
                                    : computeWymanDn(frame.object.positions, frame.object.normals, frame.object.indices);
  GpuLab gpu(options.backend, frame, dN, shaders, options.dirs, k);
  result.gpu = gpu.description();
  result.staticPassMs = gpu.renderStatic();
  const StaticBuffers sb = gpu.readStatic();
  const CpuBuffers cb = cpuBuffers(sb, k, frame);
  const LabParams& params = k.params;
  result.objectDiagonal = params.backRange;

  std::vector<Image> images(techniques.size());
  for (std::size_t i = 0; i < techniques.size(); ++i) {
    EngineSweep sweep;
    if (techniques[i].engine) {
      sweep = sweepEngineParameter(gpu, i, techniques[i], cb, params, sb, refs, options.threads, k.margin);
      gpu.setEngineParameter(i, sweep.best);
    }
    TechniqueRow row = runTechnique(gpu, i, CpuShader{techniques[i], sweep.best, cb, params, k.margin}, sb, refs,
                                    options.threads, images[i]);
    row.engineSweep = sweep.tried;
    row.engineParameter = sweep.best;
    result.rows.push_back(std::move(row));
  }
  scoreAgainstTheBound(techniques, images, missingInformation(refs, frame, sb, k), refs, result);

  timeTechniques(gpu, techniques, options.frames, result);
  result.markdown = markdownTable(result);
  result.targets = targetsText(result) + whichToPick(result);
  if (!options.outDir.empty()) writeOutputs(options.outDir, refs, images, gpu.description(), result, start);
  if (!options.webBundleDir.empty()) {
    std::vector<WebBundleImage> ran;
    for (std::size_t i = 0; i < techniques.size(); ++i) ran.push_back({techniques[i], &images[i]});
    // The front pass's fragment inputs are the same for every row: the last timed draw left them in pass 4's
    // buffers, so no draw is needed.
    writeWebBundle(options.webBundleDir, result.scene, frame, dN, k, ran, refs.full.mask, sb, gpu.readTechnique());
  }
  result.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace snell::lab

