// Texels per view unit at a view-space point of a w x h buffer seen through a projection, found by
// projecting the point and the point moved a little along x and y (a finite difference, independent of
// the closed form the rough cone uses).
#pragma once

#include <glm/glm.hpp>

namespace snell_test {

inline double texelsPerUnit(const glm::mat4& clip, glm::dvec3 p, int w, int h) {
  auto texel = [&](glm::dvec3 q) {
    const glm::dvec4 c = glm::dmat4(clip) * glm::dvec4(q, 1.0);
    return glm::dvec2((c.x / c.w * 0.5 + 0.5) * w, (c.y / c.w * 0.5 + 0.5) * h);
  };
  const double e = 1e-5;
  return 0.5 * (glm::length(texel(p + glm::dvec3(e, 0, 0)) - texel(p)) +
                glm::length(texel(p + glm::dvec3(0, e, 0)) - texel(p))) / e;
}

}  // namespace snell_test
