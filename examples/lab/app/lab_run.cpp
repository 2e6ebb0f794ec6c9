#include "lab_run.hpp"
#include "cpu_mirror.hpp"
#include "engine_sweep.hpp"
#include "pictures.hpp"
#include "references.hpp"
#include "sequence.hpp"
#include "threejs_renderer.hpp"
#include "report.hpp"
#include "web_bundle.hpp"

#include "technique.hpp"

#include "lab/error.hpp"
#include "lab/metrics.hpp"
#include "lab/scene.hpp"

#include <snell/wyman_dn.hpp>

#include <algorithm>
#include <cstdio>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

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
  // The engines' multi-object strategies: named, or with every row when the scene has several objects (runLab
  // drops them otherwise).
  for (const LabRowSpec& r : multiObjectRows())
    if (asked(r.name())) rows.push_back(r);
  // The engines' rough-only rows: named, or with every row when an object is rough (runLab drops them otherwise).
  for (const LabRowSpec& r : roughRows())
    if (asked(r.name())) rows.push_back(r);
  return rows;
}

// Wyman's d_N per vertex of each object, when a technique reads it or `always` (else none: the shaders read 0).
std::vector<std::vector<float>> wymanDn(const SceneFrame& frame, const std::vector<LabRowSpec>& techniques, bool always) {
  const bool wanted = always || std::any_of(techniques.begin(), techniques.end(),
                                            [](const LabRowSpec& t) { return t.needsDn(); });
  std::vector<std::vector<float>> dN(frame.objects.size());
  if (wanted)
    for (std::size_t i = 0; i < frame.objects.size(); ++i)
      dN[i] = computeWymanDn(frame.objects[i].mesh.positions, frame.objects[i].mesh.normals, frame.objects[i].mesh.indices);
  return dN;
}

// What every row's GPU run shares: the objects' constants and order, the whole opaque scene.
struct FrameSetup {
  std::vector<ShadeConstants> k;   // per object, in the file's order
  std::vector<std::size_t> order;  // draw order: back to front
  Image fullColor;                 // the whole opaque scene, buffer-sized (the frame before any object)
  int margin = 0;
  bool several() const { return order.size() > 1; }
  // Whether `row` copies the frame before groups of objects (Bevy's steps; one object: the one copy is the
  // opaque scene).
  bool stepped(const LabRowSpec& row) const { return several() && row.steps > 1; }
};

// One object's pass of one row: the buffers it was shaded from (C++ textures) and what the GPU wrote.
struct ObjectPass {
  std::size_t object = 0;
  CpuBuffers cb;
  TechniqueBuffers tb;
  bool backSide = false;  // its back faces (three.js's WebGPU order), not the object's pixels in the picture
};

// Bevy's steps over n objects in draw order (its split_range): whether a group, and its colour copy, starts at
// each position; the first n % groups groups hold one object more.
std::vector<bool> stepStarts(std::size_t n, int steps) {
  std::vector<bool> starts(n, false);
  if (n == 0) return starts;
  const std::size_t groups = std::min<std::size_t>(n, static_cast<std::size_t>(std::max(1, steps)));
  std::size_t rem = n % groups, start = 0;
  for (std::size_t g = 0; g < groups; ++g) {
    starts[start] = true;
    start += n / groups + (rem > 0 ? 1 : 0);
    if (rem > 0) --rem;
  }
  return starts;
}

// The objects drawn before the one at `position` of the draw order.
std::vector<std::size_t> drawnBefore(const FrameSetup& setup, std::size_t position) {
  return std::vector<std::size_t>(setup.order.begin(), setup.order.begin() + static_cast<std::ptrdiff_t>(position));
}

// The object's colour over `frame` (buffer-sized) where its pass covered the pixel.
void drawOver(Image& frame, const Image& color, const Image& coverage, int margin) {
  for (int y = 0; y < color.height; ++y)
    for (int x = 0; x < color.width; ++x)
      if (coverage.at(x, y).w > 0.0f) frame.at(x + margin, y + margin) = vec4(vec3(color.at(x, y)), 1.0f);
}

// drawOver with a depth test, as three.js's WebGPU order writes depth between its transmissive draws:
// `nearest` (buffer-sized, view distances) holds what the frame shows of the passes so far.
void drawOverNearer(Image& frame, std::vector<float>& nearest, const TechniqueBuffers& tb, int margin) {
  for (int y = 0; y < tb.color.height; ++y)
    for (int x = 0; x < tb.color.width; ++x) {
      if (!(tb.normal.at(x, y).w > 0.0f)) continue;
      float& near = nearest[static_cast<std::size_t>(y + margin) * static_cast<std::size_t>(frame.width) +
                            static_cast<std::size_t>(x + margin)];
      const float distance = -tb.position.at(x, y).z;
      if (!(distance < near)) continue;
      near = distance;
      frame.at(x + margin, y + margin) = vec4(vec3(tb.color.at(x, y)), 1.0f);
    }
}

// Three.js's WebGPU order over `passes` (every object's back side, then every front side, each in draw
// order): `readCopy(copy)` before each half sets the colour copy its passes read (nullptr: the opaque scene,
// for the back sides; then the frame holding them, for the front sides), and `shade(pass)` gives a pass's
// colour from it; returns the composite.
template <class ReadCopy, class Shade>
Image compositeBackSidesFirst(std::vector<ObjectPass>& passes, const FrameSetup& setup, ReadCopy&& readCopy,
                              Shade&& shade) {
  Image frame = setup.fullColor;
  std::vector<float> nearest(frame.texels.size(), std::numeric_limits<float>::infinity());
  Image backSides;
  for (bool back : {true, false}) {
    readCopy(back ? nullptr : &(backSides = frame));
    for (ObjectPass& pass : passes)
      if (pass.backSide == back) drawOverNearer(frame, nearest, shade(pass), setup.margin);
  }
  return frame;
}

// The viewport's part of a buffer-sized frame.
Image viewportOf(const Image& frame, int margin, int width, int height) {
  Image out(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) out.at(x, y) = frame.at(x + margin, y + margin);
  return out;
}

// Row `index` on the GPU, object after object back to front: snell's rows read each object's scene layer with
// the objects drawn before it as this row drew them (an engine row reads its opaque colour copy); each pass's
// colour goes over `frame`, which starts as the whole opaque scene. `keep`: the buffers each object read.
std::vector<ObjectPass> renderObjects(GpuLab& gpu, std::size_t index, const LabRowSpec& row, const FrameSetup& setup,
                                      const SceneFrame& sceneFrame, Image& frame, std::vector<StaticBuffers>* keep) {
  std::vector<ObjectPass> passes;
  if (row.backSidesFirst) {
    for (bool back : {true, false})
      for (std::size_t o : setup.order) passes.push_back(ObjectPass{o, {}, {}, back});
    const Image* copy = nullptr;
    const auto readCopy = [&](const Image* c) {
      copy = c;
      gpu.setColorCopy(c);
    };
    frame = compositeBackSidesFirst(passes, setup, readCopy, [&](ObjectPass& pass) -> const TechniqueBuffers& {
      StaticBuffers sb = gpu.readStatic(pass.object);
      if (copy) sb.fullColor = *copy;  // what the C++ side shades from, as the GPU reads it
      gpu.renderTechnique(index, pass.object, pass.backSide);
      pass.cb = cpuBuffers(sb, setup.k[pass.object], sceneFrame);
      pass.tb = gpu.readTechnique();
      if (keep && !pass.backSide) keep->push_back(std::move(sb));
      return pass.tb;
    });
    gpu.setColorCopy(nullptr);
    return passes;
  }
  frame = setup.fullColor;
  const bool stepped = setup.stepped(row);
  const std::vector<bool> copies = stepStarts(setup.order.size(), row.steps);
  Image copy;
  for (std::size_t position = 0; position < setup.order.size(); ++position) {
    const std::size_t o = setup.order[position];
    if (setup.several() && row.engine == nullptr) gpu.renderLayer(o, drawnBefore(setup, position), &frame);
    if (stepped && copies[position]) {
      copy = frame;
      gpu.setColorCopy(&copy);
    }
    StaticBuffers sb = gpu.readStatic(o);
    if (stepped) sb.fullColor = copy;  // what the C++ side shades from, as the GPU reads it
    gpu.renderTechnique(index, o);  // also compiles the shader's JIT code: not timed
    ObjectPass pass{o, cpuBuffers(sb, setup.k[o], sceneFrame), gpu.readTechnique()};
    drawOver(frame, pass.tb.color, pass.tb.normal, setup.margin);
    if (keep) keep->push_back(std::move(sb));
    passes.push_back(std::move(pass));
  }
  gpu.setColorCopy(nullptr);
  return passes;
}

// Stage 4: one row on the GPU, the same in C++, compared; its image (the objects composited over the scene)
// for the pictures. `keepFront`: each object's front pass (draw order), as `keep` its buffers.
TechniqueRow runTechnique(GpuLab& gpu, std::size_t index, const LabRowSpec& spec, float engineParameter,
                          const FrameSetup& setup, const SceneFrame& sceneFrame, const References& refs, int threads,
                          Image& image, Image& finalFrame, std::vector<StaticBuffers>* keep,
                          std::vector<TechniqueBuffers>* keepFront = nullptr) {
  const std::vector<ObjectPass> passes = renderObjects(gpu, index, spec, setup, sceneFrame, finalFrame, keep);
  if (keepFront)
    for (const ObjectPass& pass : passes)
      if (!pass.backSide) keepFront->push_back(pass.tb);
  TechniqueRow row;
  row.name = spec.name();
  row.label = spec.label();
  row.engine = spec.engine;
  row.steps = spec.steps;
  CpuGpuTally tally, agreement;  // the object's pixels (front passes); CPU-GPU agreement over every pass
  const int W = sceneFrame.camera.width, H = sceneFrame.camera.height;
  Mask coveredAny(W, H);
  for (const ObjectPass& pass : passes) {
    const CpuShader shade{spec, engineParameter, pass.cb, setup.k[pass.object].params, setup.margin};
    Image cpuColor(W, H), cpuStats(W, H);
    shadeOnCpu(shade, pass.tb, threads, cpuColor, cpuStats);
    const CpuGpuTally own = compareCpuGpu(shade, pass.tb, cpuColor, cpuStats, refs.escapes);
    debugWorstPixel(shade, pass.tb, cpuColor, cpuStats, own);
    agreement += own;
    if (pass.backSide) continue;
    tally += own;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x)
        if (pass.tb.normal.at(x, y).w > 0.0f) coveredAny.set(x, y, true);
  }
  tally.into(row);
  agreement.agreementInto(row);
  // Coverage: the ray tracer's object pixels that no front pass shaded (near-plane clipping, silhouette
  // rasterization) hold the scene colour in the composite; say how many, and refuse to score a technique
  // that shaded none of them.
  const Mask& object = refs.full.mask;
  std::size_t unshaded = 0, overdrawn = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      unshaded += object.at(x, y) && !coveredAny.at(x, y);
      overdrawn += !object.at(x, y) && coveredAny.at(x, y);
    }
  const std::size_t objectPixels = object.count();
  if (unshaded == objectPixels)
    throw Error(ErrorKind::Render,
                "technique " + spec.name() + " shaded none of the " + std::to_string(objectPixels) +
                    " pixels where the ray tracer sees the object (does the near plane cut the object, or does the "
                    "camera sit inside it?); no error can be measured");
  row.unshadedShare = objectPixels ? static_cast<double>(unshaded) / static_cast<double>(objectPixels) : 0.0;
  row.overdrawnShare = objectPixels ? static_cast<double>(overdrawn) / static_cast<double>(objectPixels) : 0.0;
  image = viewportOf(finalFrame, setup.margin, W, H);
  row.mseFull = compareImages(refs.full.color, image, refs.full.mask).mse;
  row.mseTwo = compareImages(refs.two.color, image, refs.full.mask).mse;
  row.mseFullTir = compareImages(refs.full.color, image, refs.tir).mse;
  row.bounces = spec.bounces();
  row.modelEvents = 2 + row.bounces;
  row.mseModel = compareImages(refs.modelOf(row.bounces).color, image, refs.full.mask).mse;
  if (setup.several()) row.mseComposited = compareImages(refs.composited.color, image, refs.full.mask).mse;
  return row;
}

// Before an engine row runs: its free value, swept on the C++ build of every object's pass (an engine row's
// passes read the opaque copy, so the GPU's fragment inputs do not depend on the value).
EngineSweep sweepEngineRow(GpuLab& gpu, std::size_t index, const LabRowSpec& spec, const FrameSetup& setup,
                           const SceneFrame& sceneFrame, const References& refs, int threads) {
  Image frame;
  std::vector<ObjectPass> passes = renderObjects(gpu, index, spec, setup, sceneFrame, frame, nullptr);
  const bool stepped = setup.stepped(spec);
  const std::vector<bool> copies = stepStarts(passes.size(), spec.steps);
  float range = 0.0f;
  for (const ShadeConstants& k : setup.k) range = std::max(range, k.params.backRange);
  const int W = sceneFrame.camera.width, H = sceneFrame.camera.height;
  return sweepEngineParameter(spec, range, refs, [&](float value) {
    if (spec.backSidesFirst) {
      Image color(W, H), stats(W, H);
      TechniqueBuffers shaded;
      Texture2D copy;
      const auto readCopy = [&](const Image* c) { copy = Texture2D(c ? *c : setup.fullColor, Filter::Linear); };
      const Image f = compositeBackSidesFirst(passes, setup, readCopy, [&](ObjectPass& pass) -> const TechniqueBuffers& {
        pass.cb.fullColor = copy;
        shadeOnCpu(CpuShader{spec, value, pass.cb, setup.k[pass.object].params, setup.margin}, pass.tb, threads, color,
                   stats);
        shaded = pass.tb;
        shaded.color = color;
        return shaded;
      });
      return viewportOf(f, setup.margin, W, H);
    }
    Image f = setup.fullColor;
    Texture2D copy;
    for (std::size_t position = 0; position < passes.size(); ++position) {
      ObjectPass& pass = passes[position];
      // Bevy's steps: the objects of a group read the frame as it was when the group began.
      if (stepped && copies[position]) copy = Texture2D(f, Filter::Linear);
      if (stepped) pass.cb.fullColor = copy;
      Image color(W, H), stats(W, H);
      shadeOnCpu(CpuShader{spec, value, pass.cb, setup.k[pass.object].params, setup.margin}, pass.tb, threads, color,
                 stats);
      drawOver(f, color, pass.tb.normal, setup.margin);
    }
    return viewportOf(f, setup.margin, W, H);
  });
}

// Stage 5: all techniques interleaved, frame after frame; median per technique (the sum of its objects'
// passes), ratios to single sample (to the first row when single sample did not run). With several objects,
// snell's rows draw each object's scene layer first from the row's own final frame (untimed: the layer's
// content changes no cost), and every object is timed alone too (its layer without the others).
void timeTechniques(GpuLab& gpu, const std::vector<LabRowSpec>& techniques, const FrameSetup& setup,
                    const std::vector<Image>& finalFrames, int frames, LabResult& result) {
  const std::size_t n = setup.order.size();
  std::vector<std::vector<double>> times(techniques.size());
  std::vector<std::vector<std::vector<double>>> perObject(techniques.size(), std::vector<std::vector<double>>(n)),
      alone = perObject;
  std::vector<std::vector<double>> layerMs(n);  // each object's scene layer, over snell's rows and frames
  // The bound is a reference, not a contender: one timed frame is enough to show its cost.
  for (int f = 0; f < frames; ++f)
    for (std::size_t i = 0; i < techniques.size(); ++i) {
      if (f > 0 && techniques[i].reference()) continue;
      const bool layers = setup.several() && techniques[i].engine == nullptr;
      const std::vector<bool> copies = stepStarts(n, techniques[i].steps);
      // Three.js's WebGPU order: the back sides (timed with their objects), then the front sides' copy.
      const bool backSides = techniques[i].backSidesFirst;
      std::vector<double> backMs(n, 0.0);
      for (std::size_t position = 0; backSides && position < n; ++position)
        backMs[position] = gpu.renderTechnique(i, setup.order[position], true);
      if (backSides) gpu.setColorCopy(&finalFrames[i]);
      double total = 0.0;
      for (std::size_t position = 0; position < n; ++position) {
        const std::size_t o = setup.order[position];
        if (layers) layerMs[position].push_back(gpu.renderLayer(o, drawnBefore(setup, position), &finalFrames[i]));
        if (setup.stepped(techniques[i]) && copies[position]) gpu.setColorCopy(&finalFrames[i]);
        const double ms = backMs[position] + gpu.renderTechnique(i, o);
        perObject[i][position].push_back(ms);
        total += ms;
      }
      times[i].push_back(total);
      gpu.setColorCopy(nullptr);
      if (!setup.several()) continue;
      for (std::size_t position = 0; position < n; ++position) {
        const std::size_t o = setup.order[position];
        if (layers) gpu.renderLayer(o, {}, nullptr);
        const double back = backSides ? gpu.renderTechnique(i, o, true) : 0.0;
        alone[i][position].push_back(back + gpu.renderTechnique(i, o));
      }
    }
  double unit = 0.0;
  for (std::size_t i = 0; i < techniques.size(); ++i) {
    TechniqueRow& row = result.rows[i];
    row.medianMs = median(times[i]);
    if (setup.several()) {
      row.objectMs.clear();
      row.aloneMs = 0.0;
      for (std::size_t position = 0; position < n; ++position) {
        row.objectMs.push_back(median(perObject[i][position]));
        row.aloneMs += median(alone[i][position]);
      }
    }
    if (techniques[i].costUnit()) unit = row.medianMs;
  }
  if (unit <= 0.0 && !result.rows.empty()) unit = result.rows[0].medianMs;
  for (TechniqueRow& r : result.rows) r.costRatio = unit > 0.0 ? r.medianMs / unit : 0.0;
  for (std::size_t position = 0; position < n && position < result.objects.size(); ++position)
    result.objects[position].layerMs = median(layerMs[position]);
}

// The pixels where the ray tracer's primary ray meets each object first.
std::vector<std::size_t> pixelsPerObject(const References& refs, const SceneFrame& frame) {
  std::vector<std::size_t> count(frame.objects.size(), 0);
  const Mask& mask = refs.full.mask;
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x) {
      if (!mask.at(x, y)) continue;
      const std::vector<PathEvent> ev = refs.tracer->principalPath(primaryRay(frame.camera, x, y), 1, TirPolicy::Critical);
      if (!ev.empty() && ev[0].object >= 0) ++count[static_cast<std::size_t>(ev[0].object)];
    }
  return count;
}

}  // namespace

// The guard band in texels per side: the fraction asked for, grown until both buffer sides are multiples
// of 32 where that is possible: the depth pyramid's levels then halve exactly for five levels (odd sizes
// drop a texel row per level, which shifts the coarse levels the depth-based plane reads).
namespace {
std::string fmtGb(double bytes) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f GB", bytes / 1e9);
  return b;
}

int guardBandMargin(double fraction, int width, int height) {
  int margin = static_cast<int>(std::lround(fraction * std::max(width, height)));
  if (margin > 0)
    for (int m = margin; m < margin + 32; ++m)
      if ((width + 2 * m) % 32 == 0 && (height + 2 * m) % 32 == 0) return m;
  return margin;
}

// What a run holds at its peak, about: from the largest resident set measured at 256, 512 and 1024 pixels
// square (sphere_painting with 2 rows and with every row, panes with 3 objects): 1.3 KB per pixel for one
// object (its GPU and read-back buffers with the guard band, the references, the pictures), 0.85 KB more per
// further object (its own buffers), 40 bytes per row (its image on both sides), over about 300 MB (the
// driver, the tracer, the meshes).
double estimatedBytes(double pixels, std::size_t objects, std::size_t rows) {
  return 300e6 + pixels * (1300.0 + 850.0 * static_cast<double>(objects - 1) + 40.0 * static_cast<double>(rows));
}

// A frame the machine cannot hold is refused before anything is allocated, with the estimate, rather than
// left to swap or to the OOM killer: the budget is three quarters of the physical memory.
void checkMemoryBudget(int width, int height, std::size_t objects, std::size_t rows) {
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || pageSize <= 0) return;  // unknown: nothing to compare with
  const double memory = static_cast<double>(pages) * static_cast<double>(pageSize), budget = 0.75 * memory;
  const double need = estimatedBytes(static_cast<double>(width) * height, objects, rows);
  if (need <= budget) return;
  const double perPixel = (estimatedBytes(1.0, objects, rows) - estimatedBytes(0.0, objects, rows));
  const int side = std::max(0, static_cast<int>(std::sqrt(std::max(0.0, budget - estimatedBytes(0.0, objects, rows)) /
                                                          perPixel)) / 64 * 64);
  throw Error(ErrorKind::Usage,
              std::to_string(width) + "x" + std::to_string(height) + " with " + std::to_string(objects) +
                  (objects == 1 ? " object" : " objects") + " and " + std::to_string(rows) + " rows needs about " +
                  fmtGb(need) + " of memory, over the lab's budget of " + fmtGb(budget) + " (3/4 of this machine's " +
                  fmtGb(memory) + "); choose a smaller --size (" + std::to_string(side) + "x" + std::to_string(side) +
                  " fits) or fewer techniques (-t)");
}

// One program per row.
std::vector<LabShader> labShaders(const std::vector<LabRowSpec>& techniques) {
  std::vector<LabShader> shaders;
  for (const LabRowSpec& t : techniques) shaders.push_back({t.techniqueId(), t.reference(), t.engineModel()});
  return shaders;
}

// Every object's constants with the run's read modes, the draw order and the guard band (fullColor comes from
// the GPU's static passes).
FrameSetup frameSetup(const SceneFrame& frame, const LabOptions& options) {
  FrameSetup setup;
  setup.margin = guardBandMargin(options.guardBand, frame.camera.width, frame.camera.height);
  for (std::size_t i = 0; i < frame.objects.size(); ++i) {
    ShadeConstants k = shadeConstants(frame, i, setup.margin);
    k.normalFilter = options.normalFilter;
    k.params.depthFilter = options.depthFilter;
    k.params.reflectSource = options.reflectSource;
    k.sceneLayer = options.sceneLayer;
    if (options.insideScene >= 0) k.params.insideScene = options.insideScene;
    setup.k.push_back(k);
  }
  setup.order = drawOrder(setup.k);
  return setup;
}

}  // namespace

std::vector<Image> renderRowsAtFrame(const SceneFrame& frame, const std::vector<LabRowSpec>& techniques,
                                     const std::vector<float>& engineParameters, const LabOptions& options) {
  FrameSetup setup = frameSetup(frame, options);
  GpuLab gpu(options.backend, frame, wymanDn(frame, techniques, false), labShaders(techniques), options.dirs, setup.k);
  gpu.renderStatic();
  if (!setup.several()) gpu.renderLayer(0, {}, nullptr);
  setup.fullColor = gpu.readStatic(setup.order.front()).fullColor;
  std::vector<Image> images;
  for (std::size_t i = 0; i < techniques.size(); ++i) {
    if (techniques[i].engine) gpu.setEngineParameter(i, engineParameters.at(i));
    Image finalFrame;
    renderObjects(gpu, i, techniques[i], setup, frame, finalFrame, nullptr);
    images.push_back(viewportOf(finalFrame, setup.margin, frame.camera.width, frame.camera.height));
  }
  return images;
}

LabResult runLab(const LabOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<LabRowSpec> techniques = selectTechniques(options);

  Scene scene = loadScene(options.scenePath);
  for (const std::string& w : scene.warnings) std::fprintf(stderr, "snell-lab: warning: %s\n", w.c_str());
  // Before the ray trace: what the page cannot draw should not cost one.
  if (!options.webBundleDir.empty() && options.sceneLayer == SceneLayer::Peeled)
    throw Error(ErrorKind::Render, "--web-bundle: the three.js page draws the behind and full scene layers, not "
                                   "the peeled one (--scene-layer peeled)");
  for (const RefractiveObject& o : scene.objects)
    if (!options.webBundleDir.empty() && o.roughness > 0.0f)
      throw Error(ErrorKind::Render, "--web-bundle: " + o.field + " is rough (roughness " + std::to_string(o.roughness) +
                                         "); the three.js page draws smooth glass only (its scene colour has no mips)");
  if (scene.objects.size() < 2 && options.techniques.empty())
    techniques.erase(std::remove_if(techniques.begin(), techniques.end(), [](const LabRowSpec& t) { return t.multiObject(); }),
                     techniques.end());
  const bool rough = std::any_of(scene.objects.begin(), scene.objects.end(),
                                 [](const RefractiveObject& o) { return o.roughness > 0.0f; });
  if (!rough && options.techniques.empty())
    techniques.erase(std::remove_if(techniques.begin(), techniques.end(), [](const LabRowSpec& t) { return t.roughOnly(); }),
                     techniques.end());
  if (options.width > 0) scene.camera.width = options.width;
  if (options.height > 0) scene.camera.height = options.height;
  checkMemoryBudget(scene.camera.width, scene.camera.height, scene.objects.size(), techniques.size());
  // Before the ray trace: a run asked for frames the scene cannot give should not cost one.
  sequenceLength(scene, options);
  const SceneFrame frame = buildAnimationFrame(scene, 0);
  // A glTF asset's open glass was named when it was read; a scene file's meshes are built here.
  for (std::size_t i = 0; i < frame.objects.size(); ++i) {
    const MeshSpec& m = scene.objects[i].mesh;
    if (m.kind == MeshKind::Loaded) continue;
    if (const std::size_t open = openEdges(frame.objects[i].mesh))
      std::fprintf(stderr,
                   "snell-lab: warning: %s%s: the mesh is open (%zu edges with one triangle): rays through its holes "
                   "find no back face and fall back\n",
                   scene.objects[i].field.c_str(), m.kind == MeshKind::Obj ? (" (" + m.path + ")").c_str() : "", open);
  }

  LabResult result;
  result.scene = scene.name.empty() ? fs::path(options.scenePath).stem().string() : scene.name;
  result.width = frame.camera.width;
  result.height = frame.camera.height;
  result.frames = options.frames;

  References refs = traceReferences(frame, techniques, options, result);

  // Stage 3: the GPU passes that do not depend on the technique (scene, back faces, pyramids), once:
  // the frame is static. Their read-back buffers are what the C++ side shades from.
  const std::vector<LabShader> shaders = labShaders(techniques);
  FrameSetup setup = frameSetup(frame, options);
  const int margin = setup.margin;
  result.guardBand = margin;
  if (setup.several()) traceComposited(refs, frame, setup.order, setup.k, options, result);
  result.insideScene = std::any_of(setup.k.begin(), setup.k.end(), [](const ShadeConstants& k) { return k.params.insideScene != 0; });
  result.sceneLayer = options.sceneLayer;
  // The web page offers every technique, ISR's d_N included.
  const std::vector<std::vector<float>> dN = wymanDn(frame, techniques, !options.webBundleDir.empty());
  GpuLab gpu(options.backend, frame, dN, shaders, options.dirs, setup.k);
  result.gpu = gpu.description();
  result.staticPassMs = gpu.renderStatic();
  // One object reads the same scene layer in every row: drawn once, with the static passes.
  if (!setup.several()) result.staticPassMs += gpu.renderLayer(0, {}, nullptr);
  setup.fullColor = gpu.readStatic(setup.order.front()).fullColor;
  for (const ShadeConstants& k : setup.k) result.objectDiagonal = std::max(result.objectDiagonal, k.params.backRange);
  const std::vector<std::size_t> pixels = pixelsPerObject(refs, frame);
  for (std::size_t o : setup.order) {
    ObjectReport report;
    report.index = o;
    report.ior = frame.objects[o].ior;
    report.abbe = frame.objects[o].abbe;
    report.enclosing = setup.k[o].enclosing;
    report.insideScene = setup.k[o].params.insideScene != 0;
    report.pixels = pixels[o];
    report.bytes = gpu.objectBytes(o);
    result.objects.push_back(report);
  }
  result.sharedBytes = gpu.sharedBytes();

  std::vector<Image> images(techniques.size()), finalFrames(techniques.size());
  std::vector<StaticBuffers> boundBuffers;  // per object, in draw order: what the two-interface bound read
  std::size_t boundIndex = techniques.size();
  for (std::size_t i = 0; i < techniques.size(); ++i)
    if (techniques[i].reference() && techniques[i].bounces() == 0) boundIndex = i;
  // The web page's lab buffers: with several objects each scene layer holds the frame as one row drew it, so
  // they come from one row: the page's default technique, else the first of the table's that ran, else the bound.
  WebBundleLabBuffers webBuffers;
  std::size_t webIndex = techniques.size();
  if (!options.webBundleDir.empty()) {
    for (std::size_t i = 0; i < techniques.size() && webIndex == techniques.size(); ++i)
      if (techniques[i].name() == "plane-normal-2") webIndex = i;
    for (std::size_t i = 0; i < techniques.size() && webIndex == techniques.size(); ++i)
      if (techniques[i].technique && !techniques[i].reference()) webIndex = i;
    if (webIndex == techniques.size()) webIndex = boundIndex;
    if (webIndex < techniques.size()) webBuffers.row = techniques[webIndex].name();
  }
  for (std::size_t i = 0; i < techniques.size(); ++i) {
    EngineSweep sweep;
    if (techniques[i].engine) {
      sweep = sweepEngineRow(gpu, i, techniques[i], setup, frame, refs, options.threads);
      gpu.setEngineParameter(i, sweep.best);
    }
    TechniqueRow row = runTechnique(gpu, i, techniques[i], sweep.best, setup, frame, refs, options.threads, images[i],
                                    finalFrames[i], i == boundIndex ? &boundBuffers
                                                    : i == webIndex ? &webBuffers.objects
                                                                    : nullptr,
                                    i == webIndex ? &webBuffers.fronts : nullptr);
    if (i == webIndex && i == boundIndex) webBuffers.objects = boundBuffers;
    row.engineSweep = sweep.tried;
    row.engineParameter = sweep.best;
    result.rows.push_back(std::move(row));
    if (!setup.several()) finalFrames[i] = Image();  // the timing reads them only for several objects
  }
  if (!boundBuffers.empty())
    scoreAgainstTheBound(techniques, images, missingInformation(refs, frame, boundBuffers, setup.k, setup.order), refs,
                         result);

  timeTechniques(gpu, techniques, setup, finalFrames, options.frames, result);
  // A glTF asset: three.js's own renderer on the same file, camera and environment, scored as the rows.
  std::vector<Image> rendererImages;
  if (!scene.gltf.empty() && options.threejs) {
    const fs::path work = options.outDir.empty() ? fs::temp_directory_path() / ("snell-lab-threejs-" + result.scene)
                                                 : fs::path(options.outDir) / "threejs";
    ThreeJsRender three = renderWithThreeJs(scene.gltf, scene, frame, work);
    RendererRow row;
    row.name = "threejs-renderer";
    row.label = "three.js (its renderer)";
    row.renderer = three.renderer;
    row.msPerFrame = three.msPerFrame;
    row.mseFull = compareImages(refs.full.color, three.image, refs.full.mask).mse;
    row.mseTwo = compareImages(refs.two.color, three.image, refs.full.mask).mse;
    result.renderers.push_back(row);
    rendererImages.push_back(std::move(three.image));
  }
  // An animated run: the frames after this one, and each row's flicker (sequence.hpp).
  if (sequenceLength(scene, options) > 0) {
    result.sequence = runSequence(scene, techniques, result.rows, refs.full, images, options);
    gpu.makeCurrent();
  }
  result.markdown = markdownTable(result);
  result.targets = targetsText(result) + whichToPick(result);
  if (!options.outDir.empty())
    writeOutputs(options.outDir, refs, images, rendererImages, gpu.description(), result, start);
  if (!options.webBundleDir.empty()) {
    std::vector<WebBundleImage> ran;
    for (std::size_t i = 0; i < techniques.size(); ++i) ran.push_back({techniques[i], &images[i]});
    writeWebBundle(options.webBundleDir, result.scene, frame, dN, setup.k, setup.order, ran, refs.full.mask,
                   webBuffers, {scene.gltf, rendererImages.empty() ? nullptr : &rendererImages.front()});
  }
  result.totalSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace snell::lab

