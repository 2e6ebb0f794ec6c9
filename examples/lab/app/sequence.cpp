#include "sequence.hpp"

#include "references.hpp"
#include "report.hpp"

#include "lab/error.hpp"
#include "lab/flicker.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

namespace snell::lab {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The truth's noise is in every row's flicker: a row that were the exact mean of the truth would still read
// the noise's own change between the frames. With a second seed the run traces frames 0 and 1 again; the
// seed-1 truth scored as a row against the seed-0 truth reads the two noises' difference, which for
// independent noise of one kind (Gaussian) is sqrt(2) times one noise's change: the floor is that over
// sqrt(2). Both sequences keep their seed from frame to frame (TraceOptions::seed), as the run's truth does,
// so the floor carries the same frame-to-frame correlation as the run's truth.
// `independent`: the floor were each frame's noise drawn afresh, the mean |seed 1 - seed 0| of frame 0 itself
// (two independent draws of the noise, as two frames' would be); the floor below it is what the shared seed
// keeps out.
double noiseFloor(const Scene& scene, const TraceOptions& base, const TraceResult& truth0, const TraceResult& truth1,
                  double& independent, double& traceSeconds) {
  TraceOptions other = base;
  other.seed = base.seed + 1;
  TraceResult again[2];
  for (int f = 0; f < 2; ++f) {
    const SceneFrame frame = buildAnimationFrame(scene, f);
    again[f] = ReferenceTracer(frame).render(frame.camera, other);
    traceSeconds += again[f].stats.seconds;
  }
  independent =
      pairFlicker(truth0.color, again[0].color, truth0.mask, again[0].mask, truth0.color, truth0.color).flicker;
  return pairFlicker(truth0.color, truth1.color, truth0.mask, truth1.mask, again[0].color, again[1].color).flicker /
         std::sqrt(2.0);
}

}  // namespace

int sequenceLength(const Scene& scene, const LabOptions& options) {
  if (options.sequenceFrames == 0) return 0;
  const int n = options.sequenceFrames < 0 ? scene.animation.frames : options.sequenceFrames;
  if (n < 2)
    throw Error(ErrorKind::Usage,
                "--sequence: the scene's animation has " + std::to_string(scene.animation.frames) +
                    (scene.animation.frames == 1 ? " frame" : " frames") +
                    " (animation.frames); a flicker needs at least 2: give --sequence-frames N with N >= 2");
  return n;
}

SequenceReport runSequence(const Scene& scene, const std::vector<LabRowSpec>& techniques,
                           const std::vector<TechniqueRow>& rows, const TraceResult& truth0,
                           const std::vector<Image>& images0, const LabOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SequenceReport report;
  report.frames = sequenceLength(scene, options);
  report.timeStart = scene.frameTime(0);
  report.timeStep = scene.animation.timeStep;
  report.panPixels = scene.animation.cameraPanPixels;
  std::vector<float> engineParameters;
  for (const TechniqueRow& r : rows) engineParameters.push_back(r.engineParameter);
  // The full truth as frame 0's (the same options, seed included), so that a pair's difference holds the
  // scene's change and not a change of how the truth was made.
  const TraceOptions to = truthOptions(options);
  std::vector<std::vector<FlickerPair>> pairs(techniques.size());
  TraceResult before = truth0;
  std::vector<Image> imagesBefore = images0;
  double pixels = 0.0, truthChange = 0.0;
  for (int f = 1; f < report.frames; ++f) {
    if (!options.quiet) std::fprintf(stderr, "snell-lab: sequence frame %d of %d\n", f + 1, report.frames);
    const SceneFrame frame = buildAnimationFrame(scene, f);
    TraceResult truth = ReferenceTracer(frame).render(frame.camera, to);
    report.traceSeconds += truth.stats.seconds;
    std::vector<Image> images = renderRowsAtFrame(frame, techniques, engineParameters, options);
    for (std::size_t i = 0; i < techniques.size(); ++i)
      pairs[i].push_back(pairFlicker(before.color, truth.color, before.mask, truth.mask, imagesBefore[i], images[i]));
    if (!techniques.empty()) {
      pixels += static_cast<double>(pairs[0].back().pixels);
      truthChange += pairs[0].back().truthChange;
    }
    if (f == 1 && truth0.stats.sampledPixels > 0)
      report.noiseFloor = noiseFloor(scene, to, truth0, truth, report.noiseFloorIndependent, report.traceSeconds);
    before = std::move(truth);
    imagesBefore = std::move(images);
  }
  const double pairCount = static_cast<double>(report.frames - 1);
  report.pixelsPerPair = pixels / pairCount;
  report.truthChange = truthChange / pairCount;
  for (const std::vector<FlickerPair>& p : pairs) report.flicker.push_back(meanFlicker(p));
  report.seconds = secondsSince(start);
  return report;
}

std::string sequenceMarkdown(const LabResult& r) {
  const SequenceReport& q = r.sequence;
  if (q.frames == 0) return "";
  const auto per255 = [](double v) { return fmt("%.3g", v) + " (" + fmt("%.2f", 255.0 * v) + "/255)"; };
  std::string s = "\nFlicker over frames 0 to " + std::to_string(q.frames - 1) + " (time " + fmt("%g", q.timeStart) +
                  " to " + fmt("%g", q.timeStart + static_cast<float>(q.frames - 1) * q.timeStep) + ", step " +
                  fmt("%g", q.timeStep) + "; the camera panned by (" + fmt("%g", q.panPixels.x) + ", " +
                  fmt("%g", q.panPixels.y) + ") pixels per frame):\n\n";
  s += "| row | flicker | x noise floor |\n|---|---:|---:|\n";
  for (std::size_t i = 0; i < r.rows.size() && i < q.flicker.size(); ++i)
    s += "| " + r.rows[i].label + " | " + per255(q.flicker[i]) + " | " +
         (q.noiseFloor > 0.0 ? fmt("%.2fx", q.flicker[i] / q.noiseFloor) : std::string("-")) + " |\n";
  s += "\nFlicker: per pair of consecutive frames, over the pixels where the ray tracer sees the object in both "
       "(" + fmt("%.0f", q.pixelsPerPair) + " per pair on average), the mean over pixels and RGB of |(row(t+1) - "
       "row(t)) - (truth(t+1) - truth(t))| in linear RGB clamped to [0, 1]; then the mean over the " +
       std::to_string(q.frames - 1) + " pairs. The truth itself changes by " + per255(q.truthChange) +
       " per pair there. Each engine row keeps the value frame 0's sweep chose.\n";
  if (q.noiseFloor > 0.0)
    s += "\nNoise floor: the truth's own noise (" + std::to_string(r.truthSamples) + " paths per pixel) reads as "
         "flicker too: " + per255(q.noiseFloor) + ", measured by tracing frames 0 and 1 again with another seed "
         "(the second truth's flicker against the first, over sqrt(2) as for independent Gaussian noise); a row "
         "near 1x the floor is as steady as this truth can tell. Were each frame's noise drawn afresh it would be " +
         per255(q.noiseFloorIndependent) + " (frame 0's two truths against each other): every frame draws the "
         "same random numbers at a pixel, which keeps " +
         fmt("%.0f %%", q.noiseFloorIndependent > 0.0 ? 100.0 * (1.0 - q.noiseFloor / q.noiseFloorIndependent) : 0.0) +
         " of it out.\n";
  else
    s += "\nNoise floor: 0 (smooth glass: the truth traces one deterministic path per pixel).\n";
  s += "Frames 1 to " + std::to_string(q.frames - 1) + " took " + fmt("%.1f", q.seconds) + " s (ray tracing " +
       fmt("%.1f", q.traceSeconds) + " s).\n";
  return s;
}

void addSequenceJson(nlohmann::json& table, const LabResult& r) {
  const SequenceReport& q = r.sequence;
  if (q.frames == 0) return;
  table["sequence"] = {{"frames", q.frames},
                       {"time_start", q.timeStart},
                       {"time_step", q.timeStep},
                       {"camera_pan_pixels", {q.panPixels.x, q.panPixels.y}},
                       {"truth_change", q.truthChange},
                       {"pixels_per_pair", q.pixelsPerPair},
                       {"noise_floor", q.noiseFloor},
                       {"noise_floor_independent_frames", q.noiseFloorIndependent},
                       {"seconds", q.seconds},
                       {"trace_seconds", q.traceSeconds}};
  nlohmann::json& rows = table["techniques"];
  for (std::size_t i = 0; i < rows.size() && i < q.flicker.size(); ++i) rows[i]["flicker"] = q.flicker[i];
}

}  // namespace snell::lab
