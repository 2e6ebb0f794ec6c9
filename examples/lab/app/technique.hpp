// The techniques snell-lab compares, and the per-pixel call shared with the
// GPU: examples/glsl/lab_technique.glsl compiled as C++ inside namespace
// snell (the same body lab_refract.frag runs on the GPU).
#pragma once
#include <snell/snell.hpp>

namespace snell {
#include "lab_technique.glsl"
}  // namespace snell

#include <string>
#include <vector>

namespace snell::lab {

struct TechniqueInfo {
  int id;                   // LAB_TECHNIQUE_*
  const char* name;         // command-line name
  const char* label;        // table / picture label
  const char* description;  // one line for --help and the README
};

// Every technique, in table order (single sample first: it is the cost unit).
const std::vector<TechniqueInfo>& allTechniques();

// The technique of that command-line name, or nullptr.
const TechniqueInfo* findTechnique(const std::string& name);

// "single, plane-normal-0, ..." for messages.
std::string techniqueNames();

}  // namespace snell::lab
