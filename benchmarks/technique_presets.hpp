// The technique presets the benchmarks compare (technique_bench.cpp,
// threads_bench.cpp), each with the exit slot on the opaque scene.
#pragma once

#include <snell/shade.hpp>

namespace snell_bench {

constexpr int kPresetCount = 7;
constexpr const char* kPresetNames[kPresetCount] = {"DIR", "ISR", "PlaneN", "PlaneD", "Single", "March", "DDA"};

inline snell::SnellTechniqueOptions preset(int k) {
  snell::SnellTechniqueOptions o;
  switch (k) {
    case 0: o = snell::snellPresetDir(); break;
    case 1: o = snell::snellPresetIsr(); break;
    case 2: o = snell::snellPresetPlaneNormal(2); break;
    case 3: o = snell::snellPresetPlaneDepth(2); break;
    case 4: o = snell::snellPresetSingleSample(); break;
    case 5: o = snell::snellPresetLinearMarch(); break;
    default: o = snell::snellPresetDdaMarch(); break;
  }
  o.exitMode = SNELL_EXIT_SCENE;
  return o;
}

}  // namespace snell_bench
