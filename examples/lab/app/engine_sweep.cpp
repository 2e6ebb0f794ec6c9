#include "engine_sweep.hpp"

#include "lab/metrics.hpp"

#include <algorithm>

namespace snell::lab {

namespace {

// The sweep: a grid of 41 values (lengths 0 to the object's bounding-box diagonal d, uv scales 0 to 0.3; Godot's
// default is 0.05), on in steps of 1.25x while the grid's last value is the best (to 8 d, or Godot's clamp 1), then
// six halvings of the step on both sides of the best. Each value costs one C++ frame of the cheap model (about
// 20 ms at 512x512 on 2 cores).
std::vector<float> engineGrid(const SnellEngineModelInfo& m, float range) {
  const float top = m.kind == SnellEngineParameterKind::UvScale ? 0.3f : range;
  std::vector<float> v;
  for (int i = 0; i <= 40; ++i) v.push_back(top * static_cast<float>(i) / 40.0f);
  return v;
}

}  // namespace

EngineSweep sweepEngineParameter(const LabRowSpec& row, float range, const References& refs,
                                 const std::function<Image(float)>& imageFor) {
  EngineSweep sweep;
  double bestMse = 0.0;
  const auto tryValue = [&](float value) {
    const double mse = compareImages(refs.full.color, imageFor(value), refs.full.mask).mse;
    sweep.tried.emplace_back(value, mse);
    if (sweep.tried.size() == 1 || mse < bestMse) {
      bestMse = mse;
      sweep.best = value;
    }
  };
  std::vector<float> grid = engineGrid(*row.engine, range);
  for (float value : grid) tryValue(value);
  const bool uv = row.engine->kind == SnellEngineParameterKind::UvScale;
  const float cap = uv ? 1.0f : 8.0f * range;
  float step = grid[1] - grid[0];
  while (sweep.best == grid.back() && grid.back() > 0.0f && grid.back() < cap) {
    step = std::min(cap, 1.25f * grid.back()) - grid.back();
    grid.push_back(grid.back() + step);
    tryValue(grid.back());
  }
  for (int halving = 0; halving < 6; ++halving) {
    step *= 0.5f;
    const float best = sweep.best;
    if (best - step >= 0.0f) tryValue(best - step);
    if (best + step <= cap) tryValue(best + step);
  }
  return sweep;
}

}  // namespace snell::lab
