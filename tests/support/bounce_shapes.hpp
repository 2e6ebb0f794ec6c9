// Convex glass shapes inside which a ray entering the face towards the camera reflects totally
// before it leaves: two, three or four times (tests/unit/technique_bounce_paths_test.cpp in analytic
// buffers, tests/lab/bounce_paths_buffers_test.cpp in the lab's GL buffers), once (the wedge) or five
// to seven times (the tilted plate, in analytic buffers); and the textbook path through them in double
// precision (Prism::inside: glm::refract / glm::reflect and ray-plane intersections, independent of
// snell). All are convex, so every face point lies on the front layer or the back layer as the camera
// sees them: the two layers hold the whole path.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "support/convex_prism.hpp"

namespace snell_test {

struct BounceShape {
  std::string name;
  Prism prism;
  double ior;
  double extent;  // the diagonal of its bounding box: the longest segment inside
};

// A Porro prism: a right isosceles triangle (hypotenuse 2 wide at z = -3 facing the camera, the right
// angle at (0, -4)) extruded over y in [-1.2, 1.2], dense flint (IOR 1.7, critical angle 36 deg). A
// ray entering the hypotenuse within 15 deg of its normal (9 deg inside) meets each leg at 45 +- 9
// deg: total reflection at both, and back out through the hypotenuse (a front face). Two
// reflections, three or four where the ray also meets the caps y = +-1.2 (at a grazing angle: total
// reflection too); a ray entering farther off the normal leaves through a leg (not these tests').
inline const BounceShape& porroPrism() {
  static const BounceShape s{"Porro prism", Prism{{{-1.0, -3.0}, {1.0, -3.0}, {0.0, -4.0}}, 1.2}, 1.7,
                             std::sqrt(2.0 * 2.0 + 1.0 + 2.4 * 2.4)};
  return s;
}

// A light guide: a bar 1 x 1 wide along the view axis, its near end at z = -1.5 and its far end at
// z = -11.5, crown glass (IOR 1.5, critical angle 42 deg). A ray entering the near end (at most 25
// deg off its normal) runs down the bar within 17 deg of its axis, reflects totally at every side it
// meets (73 deg or more from the side's normal) and leaves through the far end (a back face) after
// up to six reflections, as many as the pixel's angle says.
inline const BounceShape& lightGuide() {
  static const BounceShape s{"light guide", Prism{{{-0.5, -1.5}, {0.5, -1.5}, {0.5, -11.5}, {-0.5, -11.5}}, 0.5},
                             1.5, std::sqrt(10.0 * 10.0 + 1.0 + 1.0)};
  return s;
}

// A wedge whose right face is steep enough (43 deg off the view axis, crown glass: critical angle 42
// deg) to reflect totally a ray entering the top face z = -3 left of its middle, which then runs left,
// nearly level, and leaves through the left face, turned towards the camera (a front face): one
// reflection and out through the front layer.
inline const BounceShape& frontExitWedge() {
  static const BounceShape s{"front-exit wedge", Prism{{{-1.0, -3.0}, {1.0, -3.0}, {-0.462, -4.364}, {-1.9, -3.9}}, 1.2},
                             1.5, std::sqrt(2.9 * 2.9 + 1.364 * 1.364 + 2.4 * 2.4)};
  return s;
}

// A plate 3 long and 0.4 thick, crown glass (IOR 1.5), its faces turned 30 deg from the camera (its near
// top corner at (0, -4), running down to the right), extruded over y in [-1.2, 1.2]. A ray entering its
// near end (the short face at the left, turned 60 deg from the camera) meets the back face and the
// front face in turn, now and then a cap, the first five of them 54 deg or more from their normals
// (critical angle 42 deg): five to seven total reflections before it leaves through the far end (a
// back face). More than SNELL_MAX_BOUNCES (4), each on a face the camera sees broadside, where the
// light guide's last ones lie on its sides near the far end, too foreshortened for the buffers to hold.
inline const BounceShape& tiltedPlate() {
  static const BounceShape s = [] {
    const double c = std::sqrt(3.0) / 2.0;  // cos 30 deg
    const dvec2 top(0.0, -4.0), along(c, -0.5), in(-0.5, -c);  // in: from the top face into the plate
    const dvec2 far = top + 3.0 * along;
    return BounceShape{"tilted plate", Prism{{top, far, far + 0.4 * in, top + 0.4 * in}, 1.2}, 1.5,
                       std::sqrt(2.8 * 2.8 + 1.85 * 1.85 + 2.4 * 2.4)};
  }();
  return s;
}

// Whether a face point lies on the front layer (its face turned towards the camera) or the back layer.
inline bool onFrontLayer(const Prism::Face& f) { return glm::dot(f.normal, f.point) < 0.0; }

// The path of the pixel ray along q (q.z = -1) through the shape: the entry (point, outward normal) and
// the inside path, or nothing where the ray misses the shape or does not leave it after 6 faces.
struct PixelPath {
  dvec3 entry, entryNormal, t1;
  Prism::Path inside;
};
inline std::optional<PixelPath> pixelPath(const BounceShape& shape, dvec3 q) {
  const auto f = shape.prism.entry(q);
  if (!f) return std::nullopt;
  PixelPath p;
  p.entry = f->first * q;
  p.entryNormal = f->second;
  p.t1 = glm::refract(glm::normalize(q), f->second, 1.0 / shape.ior);
  p.inside = shape.prism.inside(p.entry, p.t1, 1.0 / shape.ior, 6);
  if (!p.inside.leaves) return std::nullopt;
  return p;
}

// Whether the buffers hold every face of the path as the geometry has it: each face point's layer
// (`layerNormalAt(uv, front)`: the outward normal of the face that layer shows through uv, nothing
// where it is empty) shows its face at every texel within one texel of its uv (`uvOf`), `px` the
// texel size. Near an edge of a face a filtered read of the normals blends two faces, and a read
// beside the silhouette finds none: the buffers do not hold that path.
inline bool buffersHoldPath(const PixelPath& p, const std::function<glm::dvec2(dvec3)>& uvOf,
                            const std::function<std::optional<dvec3>(glm::dvec2, bool)>& layerNormalAt, double px) {
  for (const Prism::Face& f : p.inside.faces) {
    const glm::dvec2 uv = uvOf(f.point);
    if (!(uv.x > 2.0 * px && uv.x < 1.0 - 2.0 * px && uv.y > 2.0 * px && uv.y < 1.0 - 2.0 * px)) return false;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const std::optional<dvec3> n = layerNormalAt(uv + px * glm::dvec2(dx, dy), onFrontLayer(f));
        if (!n || glm::length(*n - f.normal) > 1e-9) return false;
      }
  }
  return true;
}

// The shortest segment of the path between two faces (after a reflection).
inline double shortestChord(const PixelPath& p) {
  double l = 1e30;
  for (std::size_t f = 1; f < p.inside.faces.size(); ++f)
    l = std::min(l, glm::length(p.inside.faces[f].point - p.inside.faces[f - 1].point));
  return l;
}

// The length of the path inside: entry to the first face, and face to face.
inline double insideLength(const PixelPath& p) {
  double l = 0.0;
  dvec3 from = p.entry;
  for (const Prism::Face& f : p.inside.faces) {
    l += glm::length(f.point - from);
    from = f.point;
  }
  return l;
}

}  // namespace snell_test
