// The options the lab's end-to-end tests start from (tests that run snell-lab's stages, linked with the app).
#pragma once
#include "lab_run.hpp"

#include "lab_test_util.hpp"

#include <string>

namespace labtest {

// `scene` (a bundled scene's file name without .json) at size x size: one timed frame, no files written, no
// progress output, the source tree's shaders.
inline snell::lab::LabOptions labRunOptions(const std::string& scene, int size) {
  snell::lab::LabOptions o;
  o.scenePath = scenesDir() + "/" + scene + ".json";
  o.width = o.height = size;
  o.frames = 1;
  o.outDir = "";
  o.quiet = true;
  o.dirs.labGlsl = SNELL_LAB_GLSL_DIR;
  o.dirs.snellGlsl = SNELL_GLSL_DIR;
  return o;
}

}  // namespace labtest
