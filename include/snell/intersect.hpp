// intersect/: a view-space ray against a surface known only as a depth buffer,
// one strategy a file, all returning SnellHit. The GLSL bodies of
// glsl/snell/intersect/, compiled as C++.
#pragma once
#include "bridge.hpp"

namespace snell {
#include "snell/intersect.glsl"
}  // namespace snell
