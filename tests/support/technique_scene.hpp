// The two-interface refraction test scene (unit, GPU image, parity, benchmark):
// a glass sphere (centre (0.3, -0.2, -6), radius 2.2: sphereBack's sphere of
// tests/support/depth_scenes.hpp) in front of an opaque, slightly tilted
// "painting" plane, plus an analytic double refraction through the sphere in
// double precision (independent of snell: glm::refract and closed-form
// ray-sphere / ray-plane intersections).
//
// Buffers (all w x h, SNELL_DEPTH_GL, computed in double at pixel centres):
//   front   the sphere's front hemisphere: depth (GL_LESS, empty 1), outward normals (the
//           object's front layer)
//   back    sphereBack: depth (GL_GREATER, empty 0), outward normals, its pyramid,
//           trilinear normal mips
//   scene   the painting plane (empty 1 where missed), normals, pyramid, and a
//           smooth colour (bilinear): a colour pattern of the plane point
//   env     an equirectangular environment, 256 x 128, smooth, bilinear
#pragma once

#include <snell/depth_pyramid.hpp>
#include <snell/snell.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <optional>

#include "support/depth_scenes.hpp"

namespace technique_test {

inline const glm::dvec3 kCentre(0.3, -0.2, -6.0);
constexpr double kRadius = 2.2;
inline const glm::dvec3 kPlanePoint(0.0, 0.0, -11.0);
inline const glm::dvec3 kPlaneNormal = glm::normalize(glm::dvec3(0.12, 0.08, 1.0));

// Near (front) intersection of the line s q with the sphere.
inline snell_test::AnalyticSample sphereFront(const glm::dvec3& q) {
  snell_test::AnalyticSample r;
  const double a = glm::dot(q, q), b = -2.0 * glm::dot(q, kCentre), cc = glm::dot(kCentre, kCentre) - kRadius * kRadius;
  const double disc = b * b - 4.0 * a * cc;
  if (!(disc >= 0.0)) return r;
  const double s = (-b - std::sqrt(disc)) / (2.0 * a);
  if (!(s > 0.0)) return r;
  r.s = s;
  r.normal = (s * q - kCentre) / kRadius;
  r.valid = true;
  return r;
}

// A smooth colour for a point on the painting plane.
inline glm::vec3 paintingColor(const glm::dvec3& p) {
  return glm::vec3(float(0.5 + 0.45 * std::sin(1.3 * p.x)), float(0.5 + 0.45 * std::cos(1.1 * p.y)),
                   float(0.5 + 0.3 * std::sin(0.7 * (p.x + p.y))));
}
// A smooth colour for a world direction (equirect texel centres).
inline glm::vec3 envColor(const glm::dvec3& d) {
  return glm::vec3(float(0.4 + 0.3 * d.x), float(0.5 + 0.4 * d.y), float(0.6 - 0.3 * d.z));
}

struct Scene {
  int width = 0, height = 0;
  snell_test::DepthScene front, back, plane;
  snell::Texture2D backPyramid, backNormalMips, scenePyramid, sceneNormalMips, sceneColor, env;

  snell::SnellDepthSurface backSurface() const { return back.surface(); }
  snell::SnellDepthSurface frontSurface() const { return front.surface(); }
  snell::SnellDepthSurface sceneSurface() const { return plane.surface(); }
};

// A Scene's buffers as the argument lists of SNELL_OBJECT_BUFFERS and SNELL_SCENE_BUFFERS
// (glsl/snell/shade/technique_buffers.glsl), in their order: a new layer is one edit here.
#define TECH_OBJECT_ARGS(s) \
  (s).back.depth, (s).backNormalMips, (s).backPyramid, (s).backSurface(), (s).front.depth, (s).front.normals, (s).frontSurface()
#define TECH_SCENE_ARGS(s) (s).plane.depth, (s).sceneNormalMips, (s).scenePyramid, (s).sceneColor, (s).sceneSurface(), (s).env

// planePoint, planeNormal: the painting plane (a plane through the sphere puts an opaque card inside it).
inline Scene makeScene(int w, int h, const glm::dvec3& planePoint = kPlanePoint,
                       const glm::dvec3& planeNormal = kPlaneNormal) {
  Scene s;
  s.width = w;
  s.height = h;
  s.front = snell_test::detail::makeScene("sphereFront", w, h, SNELL_DEPTH_GL, false, snell_test::kSceneSphereBack,
                                          sphereFront);
  s.back = snell_test::sphereBack(w, h, SNELL_DEPTH_GL);
  s.plane = snell_test::detail::makeScene("painting", w, h, SNELL_DEPTH_GL, false, snell_test::kScenePlane,
                                          [=](glm::dvec3 q) { return snell_test::detail::rayPlane(q, planePoint, planeNormal); });
  s.backPyramid = snell::snellBuildDepthPyramid(s.back.depth, s.back.surface());
  s.backNormalMips = snell::snellBuildNormalMips(s.back.normals);
  s.scenePyramid = snell::snellBuildDepthPyramid(s.plane.depth, s.plane.surface());
  s.sceneNormalMips = snell::snellBuildNormalMips(s.plane.normals);
  snell::Image color(w, h, glm::vec4(0.0f));
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const glm::dvec3 q = s.plane.pixelRay(glm::dvec2((i + 0.5) / w, (j + 0.5) / h));
      const snell_test::AnalyticSample a = snell_test::detail::rayPlane(q, planePoint, planeNormal);
      if (a.valid) color.at(i, j) = glm::vec4(paintingColor(a.s * q), 1.0f);
    }
  s.sceneColor = snell::Texture2D(color, snell::Filter::Linear, snell::MipFilter::Linear);
  s.sceneColor.generateMipmaps();
  const int ew = 256, eh = 128;
  snell::Image env(ew, eh, glm::vec4(0.0f));
  for (int j = 0; j < eh; ++j)
    for (int i = 0; i < ew; ++i) {
      const double u = (i + 0.5) / ew, v = (j + 0.5) / eh;
      const double phi = (u - 0.5) * 2.0 * M_PI, theta = (v - 0.5) * M_PI;  // longitude, latitude
      const glm::dvec3 d(std::cos(theta) * std::sin(phi), std::sin(theta), -std::cos(theta) * std::cos(phi));
      env.at(i, j) = glm::vec4(envColor(d), 1.0f);
    }
  s.env = snell::Texture2D(env, snell::Filter::Linear, snell::MipFilter::Linear);
  s.env.generateMipmaps();
  return s;
}

// Exact two-interface trace of the pixel ray through uv (double).
struct Exact {
  bool hitsSphere = false;
  bool tir = false;
  glm::dvec3 p1, n1, t1, p2, n2, t2;
  std::optional<glm::dvec3> planeHit;  // the exit ray on the painting plane
};

inline Exact exactTrace(const snell_test::DepthScene& cam, glm::dvec2 uv, double ior) {
  Exact e;
  const glm::dvec3 q = cam.pixelRay(uv);
  const snell_test::AnalyticSample f = sphereFront(q);
  if (!f.valid) return e;
  e.hitsSphere = true;
  e.p1 = f.s * q;
  e.n1 = f.normal;
  e.t1 = glm::normalize(glm::refract(glm::normalize(q), e.n1, 1.0 / ior));
  // Second intersection with the sphere: |p1 + t t1 - c|^2 = R^2, t > 0.
  const glm::dvec3 oc = e.p1 - kCentre;
  const double b = glm::dot(oc, e.t1), cc = glm::dot(oc, oc) - kRadius * kRadius;
  const double t = -b + std::sqrt(std::max(0.0, b * b - cc));
  e.p2 = e.p1 + t * e.t1;
  e.n2 = (e.p2 - kCentre) / kRadius;  // outward
  const glm::dvec3 t2 = glm::refract(e.t1, -e.n2, ior);
  if (glm::dot(t2, t2) == 0.0) {
    e.tir = true;
    return e;
  }
  e.t2 = glm::normalize(t2);
  const double den = glm::dot(e.t2, kPlaneNormal);
  if (den != 0.0) {
    const double s = glm::dot(kPlanePoint - e.p2, kPlaneNormal) / den;
    if (s > 0.0) e.planeHit = e.p2 + s * e.t2;
  }
  return e;
}

}  // namespace technique_test
