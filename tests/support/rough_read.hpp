// The two reads of shade/rough_cone.glsl's contract, its constants written out here (not taken from the
// library's macros), and what a rough read returns from a texture whose level k holds the value k
// everywhere: trilinear filtering makes a read at level l return l, so the two reads return their levels
// mixed.
#pragma once

#include <algorithm>

namespace snell_test {

constexpr double kRoughCoreOffset = -0.52, kRoughTailOffset = 1.14, kRoughTailWeight = 0.34;

inline double roughReadOfLevelTexture(double lod, int levels) {
  const double top = double(std::max(levels - 1, 0));
  const double l = std::clamp(lod, 0.0, top);
  if (!(l > 0.0)) return 0.0;
  const double core = std::clamp(l + kRoughCoreOffset, 0.0, top), tail = std::clamp(l + kRoughTailOffset, 0.0, top);
  return (1.0 - kRoughTailWeight) * core + kRoughTailWeight * tail;
}

}  // namespace snell_test
