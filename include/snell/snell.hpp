// All of snell's C++ API: the same functions as glsl/snell/snell.glsl, which this
// header compiles inside namespace snell.
#pragma once
#include "bridge.hpp"

namespace snell {
#include "snell/snell.glsl"
}  // namespace snell
