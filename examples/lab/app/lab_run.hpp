// One snell-lab run: load a scene, ray-trace the ground truth (full and
// two-interface), render every requested technique on the GL driver, shade the
// same pixels in C++ from the read-back buffers, time the refraction pass, and
// write the pictures and the table.
#pragma once
#include "gpu_lab.hpp"

#include <snell/engine_model_table.hpp>
#include <snell/technique_table.hpp>

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace snell::lab {

struct LabOptions {
  std::string scenePath;
  // Command-line names; empty: all. The image-space bound always runs, and the bound with bounces does
  // when a technique that bounces does.
  std::vector<std::string> techniques;
  int width = 0, height = 0;            // 0: the scene's resolution
  int frames = 15;                      // timed frames (median), all techniques interleaved
  std::string backend = "auto";         // auto | osmesa | egl
  std::string outDir = "lab-out";       // "" writes nothing
  bool quiet = false;                   // no progress bars, no table on stdout
  int threads = 0;                      // tracer and CPU shading threads (0: all cores)
  NormalFilter normalFilter = NormalFilter::Linear;  // how both sides read the normal buffers
  int depthFilter = SNELL_DEPTH_FILTER_NEAREST;      // how every technique reads the depth buffers
  int reflectSource = SNELL_SOURCE_BUFFERS;          // what the first surface reflects (the reflect slot's source)
  SceneLayer sceneLayer = SceneLayer::Behind;        // the opaque scene's layer snell's rows read
  // SnellTechnique.insideScene for snell's rows: -1 auto (on when a painting reaches inside the object), 0 off, 1 on.
  int insideScene = -1;
  std::string webBundleDir;  // "": none; else the three.js page's bundle (web_bundle.hpp) is written there
  bool threejs = true;  // a glTF scene: also render it with three.js's own renderer (threejs_renderer.hpp)
  double guardBand = 0.1;  // scene and back-face buffers wider than the viewport by this share of its size per side
  int truthSamples = 1024;  // the ray tracer's paths per pixel on a rough object (TraceOptions::samples)
  // An animated run (sequence.hpp): frames 0 .. sequenceFrames - 1 of the scene's animation for every row and
  // each row's flicker; -1: the scene's animation.frames; 0: frame 0 alone (no animated run).
  int sequenceFrames = 0;
  ShaderDirs dirs;
};

// A real renderer's own image of the scene (three.js's, on a glTF asset), scored against the same truth as
// the rows; the rows' other columns (CPU-GPU, fetches, the bound) do not apply to it.
struct RendererRow {
  std::string name, label;
  std::string renderer;     // its version and what it ran on
  double mseFull = 0.0;     // vs the full ray tracer, object pixels
  double mseTwo = 0.0;      // vs the two-interface reference
  double msPerFrame = 0.0;  // its own second frame (a software rasterizer's, not a GPU's)
};

struct TechniqueRow {
  std::string name, label;
  const SnellEngineModelInfo* engine = nullptr;  // an engine row's model (nullptr: a technique of the table)
  int steps = 1;                                 // an engine row's Bevy steps (LabRowSpec::steps)
  double mseFull = 0.0;        // vs the full ray tracer (Fresnel + TIR), object pixels
  double mseTwo = 0.0;         // vs the two-interface reference
  int bounces = 0;             // the preset's bounce count (0: a two-interface technique)
  int modelEvents = 2;         // the interface events of the model it follows: 2 + bounces
  double mseModel = 0.0;       // vs that model's reference: mseTwo, or the principal path of modelEvents
  double mseComposited = -1.0;  // several objects: vs the composited two-interface model (-1 with one)
  double mseBound = 0.0;       // vs its image-space bound's image (the bound with its bounces): its own error
  double boundRatio = 0.0;     // mseModel / its bound's mseModel (1 = as good as any image-space method)
  double unshadedShare = 0.0;  // object pixels (ray tracer's mask) the technique's front pass did not shade
  double invalidShare = 0.0;   // object pixels whose technique fell back (no back or exit hit, TIR)
  double backMissShare = 0.0;  // ... of them: no hit in the back-face buffer
  double exitMissShare = 0.0;  // ... no hit in the opaque scene's buffer (environment used instead)
  double fetchesPerPixel = 0.0;
  double medianMs = 0.0;       // refraction pass, glFinish + steady clock
  double costRatio = 0.0;      // medianMs / single sample's
  double cpuGpuMaxAbs = 0.0;   // largest |CPU - GPU| of any channel, [0, 1]-clamped linear
  double cpuGpuBeyond1 = 0.0;  // share of object pixels with a channel beyond 1/255
  double cpuGpuBeyond4 = 0.0;  // ... beyond 4/255
  int cpuGpuBeyond4Pixels = 0;  // the count of those pixels
  int cpuGpuBeyond4Ties = 0;    // of them, reproduced by the C++ build from inputs nudged by a few ulps
  int worstX = -1, worstY = -1;  // the pixel of cpuGpuMaxAbs
  double fetchMismatch = 0.0;  // share of object pixels whose CPU fetch count differs from the GPU's
  // Covered pixels whose transmitted colour comes from an opaque surface nearer the camera than the pixel's
  // front face (a foreground leaked into the refraction; CpuShader::leaks in cpu_mirror.hpp).
  int leakPixels = 0;
  // ... by the surface they come from (StaticBuffers::sceneSurface's ids: k + 1 painting k, -(o + 1) object o).
  std::vector<std::pair<int, int>> leakSurfaces;
  // Covered pixels where the ray tracer sees something else first (an opaque object in front of the glass),
  // as a share of the object pixels: the glass drawn over what hides it (silhouette rasterization adds a few).
  double overdrawnShare = 0.0;
  double mseFullTir = 0.0;     // vs the full ray tracer on the object pixels with TIR (LabResult::tirShare)
  // Several objects: the refraction pass's median ms per object (draw order; their sum is medianMs), and the
  // sum of each object's median drawn alone (its scene layer without the other objects; 0 with one object).
  std::vector<double> objectMs;
  double aloneMs = 0.0;
  // An engine row: the value of its free parameter it ran with, the best of the sweep (value, MSE vs the full
  // ray tracer) on this scene.
  float engineParameter = 0.0f;
  std::vector<std::pair<float, double>> engineSweep;
};

// The model part of the error for a longer principal path (TraceMode::Principal): what an image-space
// method that follows `events` interface events, bounces inside included, can reach at best.
struct ModelFloor {
  int events = 0;
  double mseFull = 0.0;     // vs the full ray tracer, object pixels
  double mseFullTir = 0.0;  // ... on the object pixels with TIR
};

// A refractive object of the scene, as the lab drew it.
struct ObjectReport {
  std::size_t index = 0;      // in the scene file's order
  float ior = 1.5f;           // its material's (at the d line)
  float abbe = 0.0f;          // its dispersion's Abbe number (0: none)
  int enclosing = -1;         // the object it lies in (-1: none)
  bool insideScene = false;   // its rows also search the scene along the refracted ray
  std::size_t pixels = 0;     // pixels where the ray tracer's primary ray meets it first
  double layerMs = 0.0;       // its scene layer (pass 1b: the scene behind it and the objects drawn before it)
  std::size_t bytes = 0;      // GPU memory of its own buffers (mesh, back and front faces, back-face pyramid)
};

// An animated run's measures (sequence.hpp; frames 0: none ran).
struct SequenceReport {
  int frames = 0;
  float timeStart = 0.0f, timeStep = 0.0f;  // frame f at timeStart + f * timeStep
  vec2 panPixels{0.0f};                     // the camera's move per frame (AnimationSpec::cameraPanPixels)
  std::vector<double> flicker;              // per row, in LabResult::rows' order (lab/flicker.hpp)
  double truthChange = 0.0;    // mean over the pairs of the truth's own mean |change| (FlickerPair::truthChange)
  double pixelsPerPair = 0.0;  // mean over the pairs of the pixels in both frames' masks
  // The flicker the truth's noise alone gives a row (rough glass; 0 when smooth): see sequenceNoiseFloor.
  double noiseFloor = 0.0;
  double noiseFloorIndependent = 0.0;  // ... were each frame's noise drawn afresh (0 when smooth)
  double seconds = 0.0;       // frames 1 .. frames - 1 and the noise floor's traces
  double traceSeconds = 0.0;  // ... of it, ray tracing
};

struct LabResult {
  std::string scene;
  int width = 0, height = 0;
  int guardBand = 0;  // texels the scene and back-face buffers extend beyond the viewport on every side
  SceneLayer sceneLayer = SceneLayer::Behind;  // the opaque scene's layer snell's rows read
  bool insideScene = false;  // snell's rows also searched the scene along the refracted ray (SnellTechnique.insideScene)
  std::size_t objectPixels = 0;
  std::vector<ObjectReport> objects;  // in draw order: back to front
  std::size_t sharedBytes = 0;        // GPU memory every object shares (scene layers, the pass's targets)
  double mseTwoVsFull = 0.0;  // the two-interface model's own error (model + TIR)
  // A rough object: the ray tracer's paths per pixel and the noise left in its full image (TraceResult::noise:
  // the expected MSE of the truth against its own mean, which every row's mseFull carries on top of its own
  // error). 0 and 0 when every object is smooth (one deterministic path per pixel).
  int truthSamples = 0;
  double truthNoise = 0.0;
  // Several objects: the composited two-interface model's (References::composited) error, the floor of
  // the rows (-1 with one object, where it is the two-interface model).
  double mseCompositedVsFull = -1.0;
  double mseTwoVsFullTir = 0.0;  // ... on the object pixels with TIR
  // Object pixels whose principal path meets total internal reflection at its second interface (where
  // every two-interface technique clamps to the critical angle), as a share of the object pixels.
  double tirShare = 0.0;
  std::vector<ModelFloor> modelFloors;  // principal paths of 3, 4 and 6 events
  // The image-space bound's error vs the two-interface reference, split by pixel: where the bound
  // found no exit in the buffers (off-screen or hidden: information the buffers lack) and the rest
  // (the buffers' resolution and depth discretization). Both are MSE contributions over the object
  // pixels, so they add up to the bound's mseTwo.
  double boundInformationMse = 0.0, boundInformationShare = 0.0, boundBufferMse = 0.0;
  // Of the information part, the pixels whose exit P2 is a back face in front of the farthest one at its
  // pixel (a middle layer of a concave object): an upper bound of what a second, depth-peeled back-face
  // buffer would buy the bound.
  double boundMiddleLayerMse = 0.0, boundMiddleLayerShare = 0.0;
  float objectDiagonal = 0.0f;  // the object's bounding-box diagonal (the engine rows' lengths are swept in it)
  double traceSeconds = 0.0, staticPassMs = 0.0, totalSeconds = 0.0;
  int frames = 0;
  std::string gpu;
  std::vector<RendererRow> renderers;  // a glTF scene's real renderers (three.js), after the rows
  std::vector<TechniqueRow> rows;
  SequenceReport sequence;  // an animated run (LabOptions::sequenceFrames)
  std::string markdown;  // the table (and notes) as printed
  std::string targets;   // the Mayer-Assarsson comparison and which row to pick, as printed

  const TechniqueRow* row(const std::string& name) const {
    for (const TechniqueRow& r : rows)
      if (r.name == name) return &r;
    return nullptr;
  }
  // The first row whose technique-table entry satisfies `pred` (a SnellTechniqueInfo predicate), or nullptr.
  template <class Pred>
  const TechniqueRow* rowWhere(Pred pred) const {
    for (const TechniqueRow& r : rows) {
      const SnellTechniqueInfo* info = snellFindTechnique(r.name);
      if (info != nullptr && pred(*info)) return &r;
    }
    return nullptr;
  }
  // The image-space bound of the two-interface techniques (bounces 0).
  const TechniqueRow* boundRow() const {
    return rowWhere([](const SnellTechniqueInfo& t) {
      return t.kind == SnellTechniqueKind::Reference && snellTechniqueBounces(t) == 0;
    });
  }
  const TechniqueRow* costUnitRow() const { return rowWhere([](const SnellTechniqueInfo& t) { return t.costUnit; }); }
  const TechniqueRow* posterRow() const { return rowWhere([](const SnellTechniqueInfo& t) { return t.posterRow; }); }
};

// Throws snell::lab::Error (scene and file errors) and snell::gpu::Error (GL).
LabResult runLab(const LabOptions& options);

}  // namespace snell::lab
