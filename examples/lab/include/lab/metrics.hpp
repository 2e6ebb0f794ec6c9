// Image error, as DESIGN.md sec. 4 defines it: MSE on linear RGB clamped to
// [0, 1], averaged over the three channels and over the mask's pixels.
#pragma once
#include "lab/mask.hpp"

#include <snell/bridge.hpp>

#include <cstddef>

namespace snell::lab {

struct ErrorStats {
  double mse = 0.0;           // mean over masked pixels of mean over RGB of (a - b)^2
  double maxSquared = 0.0;    // largest per-pixel (channel-averaged) squared error
  std::size_t pixels = 0;     // pixels compared (mask count)
};

// A linear colour channel as every measure of the lab reads it: clamped to [0, 1] (NaN reads 0).
double clampedChannel(float v);

// Per-pixel channel-averaged squared error of two linear images, each clamped to [0, 1].
double pixelSquaredError(const vec4& a, const vec4& b);

// Throws std::invalid_argument when the sizes differ. An empty mask gives mse 0.
ErrorStats compareImages(const Image& reference, const Image& test, const Mask& mask);

}  // namespace snell::lab
