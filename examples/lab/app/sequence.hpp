// An animated run of the lab (`snell-lab --sequence`): frames 0 .. N - 1 of the scene's animation, every row
// drawn on the GPU and the ray tracer's truth traced per frame, and each row's flicker against the truth's own
// change (lab/flicker.hpp). runLab does frame 0 as always; runSequence does the frames after it.
#pragma once
#include "lab_run.hpp"
#include "technique.hpp"

#include "lab/scene.hpp"
#include "lab/tracer.hpp"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace snell::lab {

// The frames an animated run draws (0: none asked). Error(Usage) when fewer than 2: a flicker needs a pair.
int sequenceLength(const Scene& scene, const LabOptions& options);

// Frames 1 .. sequenceLength - 1 of `scene` (its camera at the run's size), each row of `techniques` as runLab
// drew frame 0 (an engine row keeps the value frame 0 chose: `rows[i].engineParameter`), against the truth traced
// per frame; `truth0` and `images0` are frame 0's truth and the rows' pictures.
SequenceReport runSequence(const Scene& scene, const std::vector<LabRowSpec>& techniques,
                           const std::vector<TechniqueRow>& rows, const TraceResult& truth0,
                           const std::vector<Image>& images0, const LabOptions& options);

// Frame `frame` of the scene on the GPU for every row, as runLab draws frame 0 (in lab_run.cpp, beside the stages
// it shares): the rows' pictures (the viewport), the engine rows with `engineParameters[i]`.
std::vector<Image> renderRowsAtFrame(const SceneFrame& frame, const std::vector<LabRowSpec>& techniques,
                                     const std::vector<float>& engineParameters, const LabOptions& options);

// The flicker table and its notes (Markdown; "" when no animated run), and its keys in table.json.
std::string sequenceMarkdown(const LabResult& r);
void addSequenceJson(nlohmann::json& table, const LabResult& r);

}  // namespace snell::lab
