// Flicker: how much a row's picture changes from one frame of an animated run
// to the next beyond what the ray tracer's truth changes. A technique that is
// wrong by the same amount in every frame does not flicker; one whose error
// jumps between frames (a march that finds another texel, a mip level that
// switches) does, even at a low MSE.
//
// For a frame pair (t, t + 1), over the pixels where the truth sees the object
// in both frames (the intersection of the two object masks: a pixel the
// silhouette enters or leaves changes from background to glass in the truth
// and in every row, which would measure the rasterizer's coverage against the
// ray tracer's, not the refraction's steadiness), the mean over those pixels
// and the three colour channels of
//     |(row(t+1) - row(t)) - (truth(t+1) - truth(t))|,
// every channel clamped to [0, 1] first (linear RGB, as the MSE of
// metrics.hpp). A run's flicker is the mean over its pairs, each pair weighed
// alike. The unit is a linear channel value, not a square: 0.01 is 2.55/255.
#pragma once
#include "lab/mask.hpp"

#include <snell/bridge.hpp>

#include <cstddef>
#include <vector>

namespace snell::lab {

struct FlickerPair {
  double flicker = 0.0;      // the mean above (0 when no pixel is in both masks)
  double truthChange = 0.0;  // the mean |truth(t+1) - truth(t)| over the same pixels: how much there is to follow
  std::size_t pixels = 0;    // pixels in both masks
};

// Throws std::invalid_argument when the images' and masks' sizes differ.
FlickerPair pairFlicker(const Image& truthBefore, const Image& truthAfter, const Mask& maskBefore,
                        const Mask& maskAfter, const Image& rowBefore, const Image& rowAfter);

// The mean of the pairs' flicker (0 for none).
double meanFlicker(const std::vector<FlickerPair>& pairs);

}  // namespace snell::lab
