// What a rough read returns from a texture whose level k holds the value k everywhere: trilinear filtering
// makes a read at level l return l, so the two reads of shade/rough_cone.glsl's contract return their
// levels mixed. The contract's constants are written out here, not taken from the library's macros.
#pragma once

#include <algorithm>

namespace snell_test {

inline double roughReadOfLevelTexture(double lod, int levels) {
  const double top = double(std::max(levels - 1, 0));
  const double l = std::clamp(lod, 0.0, top);
  if (!(l > 0.0)) return 0.0;
  const double core = std::clamp(l - 0.52, 0.0, top), tail = std::clamp(l + 1.14, 0.0, top);
  return 0.66 * core + 0.34 * tail;
}

}  // namespace snell_test
