// shade/: the composed techniques (two-interface refraction, screen-space
// perturbation, water, glass, ice, refractive texture mapping). The GLSL bodies
// of glsl/snell/shade/, compiled as C++.
#pragma once
#include "bridge.hpp"

namespace snell {
#include "snell/shade.glsl"
}  // namespace snell
