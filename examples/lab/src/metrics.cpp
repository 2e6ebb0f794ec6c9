#include "lab/metrics.hpp"

#include <algorithm>
#include <stdexcept>

namespace snell::lab {

double clampedChannel(float v) { return v > 0.0f ? std::min(static_cast<double>(v), 1.0) : 0.0; }

double pixelSquaredError(const vec4& a, const vec4& b) {
  double s = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double d = clampedChannel(a[c]) - clampedChannel(b[c]);
    s += d * d;
  }
  return s / 3.0;
}

ErrorStats compareImages(const Image& reference, const Image& test, const Mask& mask) {
  if (reference.width != test.width || reference.height != test.height || mask.width != reference.width ||
      mask.height != reference.height)
    throw std::invalid_argument("compareImages: image and mask sizes differ");
  ErrorStats s;
  double sum = 0.0;
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x) {
      if (!mask.at(x, y)) continue;
      const double e = pixelSquaredError(reference.at(x, y), test.at(x, y));
      sum += e;
      s.maxSquared = std::max(s.maxSquared, e);
      ++s.pixels;
    }
  s.mse = s.pixels ? sum / static_cast<double>(s.pixels) : 0.0;
  return s;
}

}  // namespace snell::lab
