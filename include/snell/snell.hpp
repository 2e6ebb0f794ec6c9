// All of snell's C++ API: the same functions as glsl/snell/snell.glsl, which this
// header compiles inside namespace snell, plus the C++-only conveniences.
#pragma once
#include "bridge.hpp"

namespace snell {
#include "snell/snell.glsl"
}  // namespace snell

#include "color_pyramid.hpp"
#include "depth_pyramid.hpp"
