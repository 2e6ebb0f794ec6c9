// The engine rows' free value (stage 4 of a run, before an engine row runs).
#pragma once
#include "cpu_mirror.hpp"
#include "gpu_lab.hpp"
#include "references.hpp"
#include "technique.hpp"

#include <functional>
#include <utility>
#include <vector>

namespace snell::lab {

// Stage 4, before an engine row runs: its free value (a material's thickness, Godot's uv scale) has no value in
// the scene, so it is swept on this scene and the best value by MSE against the full ray tracer is kept: the
// comparison is as fair to the engine as a user tuning it by eye could be at best. The C++ build of the same
// row shades the GPU front pass's inputs for every value; the GPU then runs the best.
struct EngineSweep {
  float best = 0.0f;
  std::vector<std::pair<float, double>> tried;  // (value, MSE vs the full ray tracer), in the order tried
};

// `imageFor(value)`: the row's picture with that value (the C++ build of every object's pass, composited);
// `range`: the largest object's bounding-box diagonal (lengths are swept in it).
EngineSweep sweepEngineParameter(const LabRowSpec& row, float range, const References& refs,
                                 const std::function<Image(float)>& imageFor);

}  // namespace snell::lab
