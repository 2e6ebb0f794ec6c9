// The lab's references (stages 2 and 4c of a run): the ray-traced ground truth and model references, the
// pixels whose path the buffers cannot show, and every row scored against the image-space bound.
#pragma once
#include "gpu_lab.hpp"
#include "lab_run.hpp"
#include "technique.hpp"

#include "lab/mask.hpp"
#include "lab/scene.hpp"
#include "lab/tracer.hpp"

#include <map>
#include <memory>
#include <vector>

namespace snell::lab {

// Stage 2: the ground truth, full paths and the two-interface reference.
struct References {
  std::unique_ptr<ReferenceTracer> tracer;
  TraceResult full, two;
  Mask tir;  // object pixels with TIR on the principal path (LabResult::tirShare)
  // Object pixels whose exact two-interface path leaves the object and meets nothing: the environment is the
  // right answer there, so a row that falls back to it after a found back face is not invalid.
  Mask escapes;
  // The principal path of 2 + B events for each bounce count B > 0 a row follows: the model reference
  // of those rows, as `two` is of the two-interface ones.
  std::map<int, TraceResult> principal;
  // Several objects: the composited two-interface model (ReferenceTracer::renderComposited), in the lab's
  // draw order with the relative indices its passes use: the floor of the rows.
  TraceResult composited;

  const TraceResult& modelOf(int bounces) const { return bounces > 0 ? principal.at(2 + bounces) : two; }
};

// How the lab traces a frame's full truth (mode Full, the run's threads, progress and truth samples, the
// default seed): every frame of a run traces it alike, so two frames differ by the scene alone.
TraceOptions truthOptions(const LabOptions& options);

References traceReferences(const SceneFrame& frame, const std::vector<LabRowSpec>& techniques,
                            const LabOptions& options, LabResult& result);

// Stage 2b, with several objects: refs.composited, and its error in the result.
void traceComposited(References& refs, const SceneFrame& frame, const std::vector<std::size_t>& order,
                     const std::vector<ShadeConstants>& k, const LabOptions& options, LabResult& result);

// Stage 3a: the object pixels whose two-interface path the buffers cannot show any image-space method:
// the exact exit point P2 (critical-angle TIR, as the techniques) off screen or not the farthest back
// face at its pixel (a middle layer of a concave object), or the exit ray's hit on the opaque scene off
// screen or behind a nearer surface. Rays that leave into the environment lack nothing.
struct MissingInformation {
  Mask any;
  // Of them, the pixels whose P2 is on screen but in front of the farthest back face there: a middle
  // layer of a concave object, what a second (depth-peeled) back-face buffer could hold.
  Mask middleLayer;
};

// With several objects, each pixel is classified with the buffers of the object its primary ray meets first:
// `buffers` in draw order (`order`, as the bound read them), `k` in the file's order. A path whose second event
// is on another object (a nested one) is not a two-interface path of its object and is left out; an exit ray
// that meets an object drawn after its own (not in the layer) lacks information.
MissingInformation missingInformation(const References& refs, const SceneFrame& frame,
                                      const std::vector<StaticBuffers>& buffers, const std::vector<ShadeConstants>& k,
                                      const std::vector<std::size_t>& order);

// Stage 4c: every row against the image-space bound, and the bound's own error split into the pixels
// whose path the buffers do not hold (missingInformation) and the rest.
void scoreAgainstTheBound(const std::vector<LabRowSpec>& techniques, const std::vector<Image>& images,
                          const MissingInformation& missing, const References& refs, LabResult& result);

}  // namespace snell::lab
