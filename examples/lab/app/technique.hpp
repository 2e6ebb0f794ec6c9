// The per-pixel call shared with the GPU: examples/glsl/lab_technique.glsl
// compiled as C++ inside namespace snell (the same body lab_refract.frag runs
// on the GPU). The techniques themselves are the library's table
// (snellTechniqueTable(), include/snell/technique_table.hpp).
#pragma once
#include <snell/snell.hpp>
#include <snell/technique_table.hpp>

namespace snell {
#include "lab_technique.glsl"
}  // namespace snell

#include <string>

namespace snell::lab {

// "single, plane-normal-0, ..." for messages.
std::string techniqueNames();

}  // namespace snell::lab
