// optics/: refraction with TIR policies, approximate refraction, Fresnel terms,
// normal blending, absorption, distance interpolation, ray-plane intersection.
// The functions are the GLSL bodies in glsl/snell/optics/, compiled as C++.
#pragma once
#include "bridge.hpp"

namespace snell {
#include "snell/optics.glsl"
}  // namespace snell
