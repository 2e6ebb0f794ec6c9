// camera/: depth conventions, view <-> clip <-> uv <-> pixel, and the perspective
// texture-space ray parameterization of Oliveira & Brauwers 2007 (eqs. 3-9).
// The functions are the GLSL bodies in glsl/snell/camera/, compiled as C++.
#pragma once
#include "bridge.hpp"

namespace snell {
#include "snell/camera.glsl"
}  // namespace snell
