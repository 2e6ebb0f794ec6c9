// A convex glass prism for the bounce tests (tests/unit/technique_bounce_test.cpp,
// tests/lab/bounce_buffers_test.cpp, and through bounce_shapes.hpp the tests of
// paths with several reflections): a convex polygon in the x-z plane extruded
// over y, its planes, a flat-shaded OBJ of it, and the analytic entry and exit
// of rays and the whole path inside in double precision (ray-plane
// intersections, glm::refract / glm::reflect, independent of snell).
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

  // Flat-shaded OBJ: each face its own normal, its vertices counter-clockwise seen from outside (a
  // loader that orients a mesh outward flips all faces or none: each must agree with the others).
  std::string obj() const {
    std::ostringstream s;
    s.precision(17);
    const std::size_t n = polygon.size();
    std::vector<dvec3> v;
    for (double y : {-h, h})
      for (const dvec2& p : polygon) v.push_back(dvec3(p.x, y, p.y));
    for (const dvec3& p : v) s << "v " << p.x << " " << p.y << " " << p.z << "\n";
    const std::vector<Plane> pl = planes();
    for (const Plane& p : pl) s << "vn " << p.n.x << " " << p.n.y << " " << p.n.z << "\n";
    // Faces as 0-based vertex lists, in planes()' order: the sides, then the caps y = h and y = -h.
    std::vector<std::vector<std::size_t>> faces;
    for (std::size_t i = 0; i < n; ++i) faces.push_back({i, (i + 1) % n, n + (i + 1) % n, n + i});
    std::vector<std::size_t> top, bottom;
    for (std::size_t i = 0; i < n; ++i) {
      top.push_back(n + i);
      bottom.push_back(i);
    }
    faces.push_back(top);
    faces.push_back(bottom);
    for (std::size_t f = 0; f < faces.size(); ++f) {
      std::vector<std::size_t> face = faces[f];
      const dvec3 winding = glm::cross(v[face[1]] - v[face[0]], v[face[2]] - v[face[0]]);
      if (glm::dot(winding, pl[f].n) < 0.0) std::reverse(face.begin(), face.end());
      s << "f";
      for (std::size_t i : face) s << " " << i + 1 << "//" << f + 1;
      s << "\n";
    }
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

  // The textbook path of a ray inside, from p along d (eta = n_outside / n_glass): each face it meets, in
  // order, with total internal reflection (glm::reflect) where glm::refract finds none, until it refracts
  // out or has met `maxFaces` faces. leaves: it refracted out at the last face, along `out`.
  struct Face {
    dvec3 point, normal;  // outward normal
    bool tir;
  };
  struct Path {
    std::vector<Face> faces;
    dvec3 out{0.0};
    bool leaves = false;
    int reflections() const { return int(faces.size()) - (leaves ? 1 : 0); }
  };
  Path inside(dvec3 p, dvec3 d, double eta, int maxFaces) const {
    Path path;
    for (int k = 0; k < maxFaces; ++k) {
      const auto hit = exit(p, d);
      if (!hit) break;
      const dvec3 t = glm::refract(d, -hit->second, 1.0 / eta);
      const bool tir = glm::dot(t, t) == 0.0;
      path.faces.push_back({hit->first, hit->second, tir});
      if (!tir) {
        path.out = t;
        path.leaves = true;
        break;
      }
      p = hit->first;
      d = glm::reflect(d, hit->second);
    }
    return path;
  }
};

}  // namespace snell_test
