// A convex glass prism for the bounce tests (tests/unit/technique_bounce_test.cpp,
// tests/lab/bounce_buffers_test.cpp): a convex polygon in the x-z plane
// extruded over y, its planes, a flat-shaded OBJ of it, and the analytic
// entry and exit of rays in double precision (ray-plane intersections,
// independent of snell).
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace snell_test {

using glm::dvec2;
using glm::dvec3;

// A convex polygon in the x-z plane extruded over y in [-h, h], in view space (the camera at the origin
// looking down -z; the lab's test puts its camera there, so world space is view space).
struct Prism {
  std::vector<dvec2> polygon;  // (x, z), convex, either orientation
  double h = 1.2;

  struct Plane {
    dvec3 n;  // outward
    double d; // inside where n.p <= d
  };
  std::vector<Plane> planes() const {
    dvec2 c(0.0);
    for (const dvec2& p : polygon) c += p / double(polygon.size());
    std::vector<Plane> out;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const dvec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
      dvec3 n = glm::normalize(dvec3(-(b.y - a.y), 0.0, b.x - a.x));
      if (glm::dot(n, dvec3(a.x - c.x, 0.0, a.y - c.y)) < 0.0) n = -n;
      out.push_back({n, glm::dot(n, dvec3(a.x, 0.0, a.y))});
    }
    out.push_back({dvec3(0, 1, 0), h});
    out.push_back({dvec3(0, -1, 0), h});
    return out;
  }

  // Flat-shaded OBJ: each face its own normal (the loader makes the winding outward).
  std::string obj() const {
    std::ostringstream s;
    s.precision(17);
    const std::size_t n = polygon.size();
    for (double y : {-h, h})
      for (const dvec2& p : polygon) s << "v " << p.x << " " << y << " " << p.y << "\n";
    const std::vector<Plane> pl = planes();
    for (const Plane& p : pl) s << "vn " << p.n.x << " " << p.n.y << " " << p.n.z << "\n";
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n, vn = i + 1;
      s << "f " << i + 1 << "//" << vn << " " << j + 1 << "//" << vn << " " << n + j + 1 << "//" << vn << " "
        << n + i + 1 << "//" << vn << "\n";
    }
    s << "f";
    for (std::size_t i = 0; i < n; ++i) s << " " << n + i + 1 << "//" << n + 1;
    s << "\nf";
    for (std::size_t i = 0; i < n; ++i) s << " " << i + 1 << "//" << n + 2;
    s << "\n";
    return s.str();
  }

  // The first face a ray from outside enters along s q (s > 0): (s, its normal), or nothing; with `far`, the
  // face it leaves through (the back layer at its pixel).
  std::optional<std::pair<double, dvec3>> entry(dvec3 q, bool far = false) const {
    double sNear = 0.0, sFar = 1e30;
    dvec3 nNear(0.0), nFar(0.0);
    for (const Plane& p : planes()) {
      const double denom = glm::dot(p.n, q);
      if (denom == 0.0) {
        if (p.d < 0.0) return std::nullopt;
        continue;
      }
      const double s = p.d / denom;
      if (denom < 0.0 && s > sNear) {
        sNear = s;
        nNear = p.n;
      } else if (denom > 0.0 && s < sFar) {
        sFar = s;
        nFar = p.n;
      }
    }
    if (!(sNear > 0.0 && sNear < sFar)) return std::nullopt;
    return far ? std::make_pair(sFar, nFar) : std::make_pair(sNear, nNear);
  }

  // Where a ray from inside leaves: (point, outward normal of that face).
  std::optional<std::pair<dvec3, dvec3>> exit(dvec3 o, dvec3 d) const {
    double best = 1e30;
    dvec3 n(0.0);
    for (const Plane& p : planes()) {
      const double denom = glm::dot(p.n, d);
      if (denom <= 0.0) continue;
      const double t = (p.d - glm::dot(p.n, o)) / denom;
      if (t > 1e-9 && t < best) {
        best = t;
        n = p.n;
      }
    }
    if (best >= 1e30) return std::nullopt;
    return std::make_pair(o + best * d, n);
  }
};

}  // namespace snell_test
