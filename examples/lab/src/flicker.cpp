#include "lab/flicker.hpp"

#include "lab/metrics.hpp"

#include <cmath>
#include <stdexcept>

namespace snell::lab {

namespace {
bool sameSize(const Image& a, const Image& b) { return a.width == b.width && a.height == b.height; }
bool sameSize(const Image& a, const Mask& m) { return a.width == m.width && a.height == m.height; }
}  // namespace

FlickerPair pairFlicker(const Image& truthBefore, const Image& truthAfter, const Mask& maskBefore,
                        const Mask& maskAfter, const Image& rowBefore, const Image& rowAfter) {
  if (!sameSize(truthBefore, truthAfter) || !sameSize(truthBefore, rowBefore) || !sameSize(truthBefore, rowAfter) ||
      !sameSize(truthBefore, maskBefore) || !sameSize(truthBefore, maskAfter))
    throw std::invalid_argument("pairFlicker: image and mask sizes differ");
  FlickerPair p;
  double sum = 0.0, truthSum = 0.0;
  for (int y = 0; y < truthBefore.height; ++y)
    for (int x = 0; x < truthBefore.width; ++x) {
      if (!maskBefore.at(x, y) || !maskAfter.at(x, y)) continue;
      for (int c = 0; c < 3; ++c) {
        const double truthStep = clampedChannel(truthAfter.at(x, y)[c]) - clampedChannel(truthBefore.at(x, y)[c]);
        const double rowStep = clampedChannel(rowAfter.at(x, y)[c]) - clampedChannel(rowBefore.at(x, y)[c]);
        sum += std::fabs(rowStep - truthStep);
        truthSum += std::fabs(truthStep);
      }
      ++p.pixels;
    }
  if (p.pixels > 0) {
    p.flicker = sum / (3.0 * static_cast<double>(p.pixels));
    p.truthChange = truthSum / (3.0 * static_cast<double>(p.pixels));
  }
  return p;
}

double meanFlicker(const std::vector<FlickerPair>& pairs) {
  if (pairs.empty()) return 0.0;
  double sum = 0.0;
  for (const FlickerPair& p : pairs) sum += p.flicker;
  return sum / static_cast<double>(pairs.size());
}

}  // namespace snell::lab
