// The glass sphere of technique_scene.hpp as the two layers a ray inside it is
// marched between (its front and back hemispheres, nearest reads), and the
// side of a point as the inside march's contract defines it, computed in
// double from the analytic surfaces at the texel a nearest read picks.
// Shared by the unit tests of snellInsideSide and snellInsideBracket.
#pragma once

#include <snell/snell.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

#include "support/depth_scenes.hpp"
#include "support/technique_scene.hpp"

namespace inside_test {

struct Layers {
  snell_test::DepthScene front, back;
  int size = 0;
};

inline Layers sphereLayers(int size) {
  Layers l;
  l.size = size;
  l.front = snell_test::detail::makeScene("sphereFront", size, size, SNELL_DEPTH_GL, false,
                                          snell_test::kSceneSphereBack, technique_test::sphereFront);
  l.back = snell_test::sphereBack(size, size, SNELL_DEPTH_GL);
  return l;
}

// The sphere with one layer empty everywhere (frontEmpty: the front one), as where one pass drew nothing.
inline Layers oneLayerEmpty(int size, bool frontEmpty) {
  Layers l = sphereLayers(size);
  const auto none = [](glm::dvec3) { return snell_test::AnalyticSample{}; };
  if (frontEmpty)
    l.front = snell_test::detail::makeScene("empty", size, size, SNELL_DEPTH_GL, false, snell_test::kScenePlane, none);
  else
    l.back = snell_test::detail::makeScene("empty", size, size, SNELL_DEPTH_GL, true, snell_test::kScenePlane, none);
  return l;
}

// The view z of each layer at a texel's centre (what its nearest read holds), valid false where empty.
struct TexelLayers {
  double frontZ = 0.0, backZ = 0.0;
  bool frontValid = false, backValid = false;
};

inline TexelLayers layersAt(const Layers& l, glm::ivec2 texel) {
  const glm::dvec2 centre((texel.x + 0.5) / l.size, (texel.y + 0.5) / l.size);
  const snell_test::AnalyticSample f = l.front.sampleAt(centre), b = l.back.sampleAt(centre);
  TexelLayers t;
  t.frontValid = f.valid;
  t.backValid = b.valid;
  t.frontZ = -f.s;
  t.backZ = -b.s;
  return t;
}

// 0 inside, 1 left through the back layer, 2 through the front; -1 where z lies within `margin` of a layer
// (float depths put such a point on either side). Both layers crossed: -2, a case the callers leave out.
inline int expectedSide(const TexelLayers& t, double z, double dirZ, double margin) {
  if ((t.backValid && std::abs(z - t.backZ) < margin) || (t.frontValid && std::abs(z - t.frontZ) < margin)) return -1;
  const bool behindBack = t.backValid && z < t.backZ;
  const bool beforeFront = t.frontValid && z > t.frontZ;
  if (behindBack && beforeFront) return -2;
  if (behindBack) return 1;
  if (beforeFront) return 2;
  if (!t.backValid && !t.frontValid) return dirZ > 0.0 ? 2 : 1;
  return 0;
}

// The texel a nearest read of uv picks, and whether uv lies within `margin` texels of a texel edge (where
// the float uv may pick the neighbour).
inline glm::ivec2 texelOf(const Layers& l, glm::dvec2 uv) {
  return glm::clamp(glm::ivec2(glm::floor(uv * double(l.size))), glm::ivec2(0), glm::ivec2(l.size - 1));
}
inline bool nearTexelEdge(const Layers& l, glm::dvec2 uv, double margin) {
  const glm::dvec2 x = uv * double(l.size);
  const glm::dvec2 f = x - glm::floor(x);
  return std::min(std::min(f.x, 1.0 - f.x), std::min(f.y, 1.0 - f.y)) < margin;
}

}  // namespace inside_test
