// Analytic depth scenes: depth (and normal) buffers computed in double from
// closed-form surfaces, an independent ground truth for the intersect/ tests.
//
// Every scene is a camera (symmetric perspective, fovy kFovy, aspect w/h, zNear
// kNear, zFar kFar) looking down -Z at one analytic surface. Texel (i, j) holds
// the window depth (for the scene's convention) of the first point of that
// surface on the ray from the eye through the pixel centre ((i+.5)/w, (j+.5)/h),
// computed in double and rounded once to float; where the ray misses the
// surface, or meets it outside [zNear, zFar], the texel holds emptyDepth.
//
//   emptyDepth: sphereBack models a back-face pass (glDepthFunc(GL_GREATER)
//   after clearing to the near-plane value), so it is the near-plane depth (0,
//   or 1 for the reversed conventions); the other scenes model an opaque scene
//   pass (GL_LESS after clearing to the far value): 1, or 0 for reversed ones.
//   normals: view-space unit normal in xyz, w = 1 where a surface is, all 0
//   where empty (so a box-filtered mip keeps the coverage in w). Orientation:
//   the surface's geometric outward normal (the sphere's points away from its
//   centre, i.e. away from the camera on the back hemisphere; planes face the
//   camera).
//
// surfaceZ(uv) is the continuous analytic surface (view z < 0) seen along the
// ray through uv (any uv, not only texel centres), NaN where empty.
// referenceHit(origin, dir) is the first point of the ray (t >= 0) that lies in
// the view frustum (on screen, zNear <= -z <= zFar) and is behind or on the
// continuous surface (z_ray <= surfaceZ(projection)): a dense double-precision
// march (16 max(w, h) steps, at least 4096, over the ray's part inside the
// frustum) followed by bisection to 1e-12 relative; nullopt if there is none.
// A surface feature thinner than one march step can be stepped over; the steps
// are below 1/8 pixel for rays that do not approach the camera.
//
// The same surfaces are implemented in GLSL (tests/support/depth_scenes.glsl)
// for rendering on the GPU; `kind` and `params` carry a scene to that shader.
#pragma once

#include <snell/camera.hpp>
#include <snell/intersect.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string>

namespace snell_test {

constexpr float kSceneFovy = 0.9f;  // radians, vertical
constexpr float kSceneNear = 0.5f;
constexpr float kSceneFar = 40.0f;

// The window depth of view distance v under `convention` (near n, far f), in
// double: the reference the tests build depth buffers from, written from the
// projection formulas rather than through snellDelinearizeDepth.
inline double windowDepth(double v, double n, double f, int convention) {
  switch (convention) {
    case SNELL_DEPTH_GL:
    case SNELL_DEPTH_ZERO_ONE: return f * (v - n) / (v * (f - n));
    case SNELL_DEPTH_REVERSED: return n * (f - v) / (v * (f - n));
    case SNELL_DEPTH_INFINITE_GL: return 1.0 - n / v;
    default: return n / v;  // INFINITE_REVERSED
  }
}

enum SceneKind { kScenePlane = 0, kSceneSphereBack = 1, kSceneStep = 2, kSceneAnnulus = 3, kSceneSpike = 4 };

// A surface point along the pixel ray q = (x, y, -1): point = s q, s the view
// distance. normal unit, valid false where the ray misses.
struct AnalyticSample {
  double s = 0.0;
  glm::dvec3 normal{0.0};
  bool valid = false;
};

namespace detail {
inline double nan() { return std::numeric_limits<double>::quiet_NaN(); }

// Plane through p with normal n: s with dot(s q - p, n) = 0.
inline AnalyticSample rayPlane(const glm::dvec3& q, const glm::dvec3& p, const glm::dvec3& n) {
  AnalyticSample r;
  const double den = glm::dot(q, n);
  if (den == 0.0) return r;
  const double s = glm::dot(p, n) / den;
  if (!(s > 0.0)) return r;
  r.s = s;
  r.normal = glm::normalize(n);
  if (r.normal.z < 0.0) r.normal = -r.normal;  // face the camera
  r.valid = true;
  return r;
}

// The farther intersection of the line s q with the sphere (back hemisphere).
inline AnalyticSample sphereBack(const glm::dvec3& q, const glm::dvec3& c, double radius) {
  AnalyticSample r;
  const double a = glm::dot(q, q), b = -2.0 * glm::dot(q, c), cc = glm::dot(c, c) - radius * radius;
  const double disc = b * b - 4.0 * a * cc;
  if (!(disc >= 0.0)) return r;
  const double s = (-b + std::sqrt(disc)) / (2.0 * a);
  if (!(s > 0.0)) return r;
  r.s = s;
  r.normal = (s * q - c) / radius;
  r.valid = true;
  return r;
}

// Ray-box (slab) entry point for a box in front of the eye.
inline AnalyticSample rayBox(const glm::dvec3& q, const glm::dvec3& lo, const glm::dvec3& hi) {
  AnalyticSample r;
  double tNear = 0.0, tFar = std::numeric_limits<double>::infinity();
  int axis = -1;
  double sign = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (q[k] == 0.0) {
      if (0.0 < lo[k] || 0.0 > hi[k]) return r;
      continue;
    }
    double t0 = lo[k] / q[k], t1 = hi[k] / q[k];
    double enterSign = -1.0;  // entering through the low face: normal -axis
    if (t0 > t1) {
      std::swap(t0, t1);
      enterSign = 1.0;
    }
    if (t0 > tNear) {
      tNear = t0;
      axis = k;
      sign = enterSign;
    }
    tFar = std::min(tFar, t1);
  }
  if (axis < 0 || tNear > tFar) return r;
  r.s = tNear;
  r.normal = glm::dvec3(0.0);
  r.normal[axis] = sign;
  r.valid = true;
  return r;
}
}  // namespace detail

struct DepthScene {
  std::string name;
  snell::Texture2D depth;    // window depth in .x; emptyDepth where no surface; NEAREST, one level
  snell::Texture2D normals;  // view-space unit normal xyz, w = 1; 0 where empty; NEAREST, one level
  glm::mat4 clipFromView{1.0f};
  float zNear = kSceneNear, zFar = kSceneFar;
  int convention = SNELL_DEPTH_GL;
  float emptyDepth = 1.0f;
  int width = 0, height = 0;
  double tanHalfX = 0.0, tanHalfY = 0.0;  // tan of the half field of view, horizontal / vertical
  // The analytic surface along the pixel ray q = (x, y, -1) (NOT clipped to [zNear, zFar]).
  std::function<AnalyticSample(glm::dvec3 q)> analytic;
  int kind = kScenePlane;
  glm::vec4 params[4] = {};  // the GLSL twin's parameters (depth_scenes.glsl)

  snell::SnellDepthSurface surface() const {
    return snell::snellDepthSurface(clipFromView, zNear, zFar, convention, emptyDepth);
  }

  // The pixel ray through uv, scaled to z = -1.
  glm::dvec3 pixelRay(glm::dvec2 uv) const {
    return glm::dvec3((2.0 * uv.x - 1.0) * tanHalfX, (2.0 * uv.y - 1.0) * tanHalfY, -1.0);
  }
  // uv of a view-space point (z < 0).
  glm::dvec2 project(glm::dvec3 p) const {
    return glm::dvec2(p.x / (-p.z) / tanHalfX * 0.5 + 0.5, p.y / (-p.z) / tanHalfY * 0.5 + 0.5);
  }
  // The surface sample seen through uv, clipped to [zNear, zFar].
  AnalyticSample sampleAt(glm::dvec2 uv) const {
    AnalyticSample a = analytic(pixelRay(uv));
    if (a.valid && (a.s < double(zNear) || a.s > double(zFar))) a.valid = false;
    return a;
  }

  std::function<double(glm::dvec2 uv)> surfaceZ = [this](glm::dvec2 uv) {
    const AnalyticSample a = sampleAt(uv);
    return a.valid ? -a.s : detail::nan();
  };

  // The window depth of view distance v (double) for this scene's convention.
  double windowDepth(double v) const { return snell_test::windowDepth(v, zNear, zFar, convention); }

  // First point of origin + t dir (t >= 0) inside the frustum and behind or on the surface.
  std::optional<glm::dvec3> referenceHit(glm::dvec3 origin, glm::dvec3 dir) const {
    if (!std::isfinite(origin.x) || !std::isfinite(origin.y) || !std::isfinite(origin.z) || !std::isfinite(dir.x) ||
        !std::isfinite(dir.y) || !std::isfinite(dir.z) || glm::dot(dir, dir) == 0.0)
      return std::nullopt;
    // Clip the ray to the frustum (Cyrus-Beck): a.p <= b for six planes.
    const glm::dvec3 a[6] = {{0, 0, 1},          {0, 0, -1},         {1, 0, tanHalfX},
                             {-1, 0, tanHalfX}, {0, 1, tanHalfY}, {0, -1, tanHalfY}};
    const double b[6] = {-double(zNear), double(zFar), 0, 0, 0, 0};
    double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 6; ++k) {
      const double an = glm::dot(a[k], dir), ao = glm::dot(a[k], origin);
      if (an == 0.0) {
        if (ao > b[k]) return std::nullopt;
        continue;
      }
      const double t = (b[k] - ao) / an;
      if (an > 0.0) t1 = std::min(t1, t);
      else t0 = std::max(t0, t);
    }
    if (!(t0 <= t1) || !std::isfinite(t1)) return std::nullopt;
    auto behind = [&](double t) {
      const glm::dvec3 p = origin + t * dir;
      if (!(p.z < 0.0)) return false;
      const AnalyticSample s = sampleAt(project(p));
      return s.valid && -p.z >= s.s;
    };
    const int steps = std::max(4096, 16 * std::max(width, height));
    double prev = t0;
    if (behind(t0)) return origin + t0 * dir;
    for (int i = 1; i <= steps; ++i) {
      const double t = t0 + (t1 - t0) * double(i) / double(steps);
      if (behind(t)) {
        double lo = prev, hi = t;
        for (int k = 0; k < 200 && hi - lo > 1e-12 * std::max(1.0, hi); ++k) {
          const double mid = 0.5 * (lo + hi);
          if (behind(mid)) hi = mid;
          else lo = mid;
        }
        return origin + hi * dir;
      }
      prev = t;
    }
    return std::nullopt;
  }

  DepthScene() = default;
  // surfaceZ captures `this`: copies must not point at the source.
  DepthScene(const DepthScene& o) { *this = o; }
  DepthScene& operator=(const DepthScene& o) {
    name = o.name;
    depth = o.depth;
    normals = o.normals;
    clipFromView = o.clipFromView;
    zNear = o.zNear;
    zFar = o.zFar;
    convention = o.convention;
    emptyDepth = o.emptyDepth;
    width = o.width;
    height = o.height;
    tanHalfX = o.tanHalfX;
    tanHalfY = o.tanHalfY;
    analytic = o.analytic;
    kind = o.kind;
    for (int i = 0; i < 4; ++i) params[i] = o.params[i];
    return *this;
  }
};

namespace detail {
inline bool reversedConvention(int c) { return c == SNELL_DEPTH_REVERSED || c == SNELL_DEPTH_INFINITE_REVERSED; }

// Fills camera fields, then the buffers from `analytic`.
inline DepthScene makeScene(std::string name, int w, int h, int convention, bool backFaces, int kind,
                            std::function<AnalyticSample(glm::dvec3)> analytic) {
  DepthScene sc;
  sc.name = std::move(name);
  sc.width = w;
  sc.height = h;
  sc.convention = convention;
  sc.kind = kind;
  const float aspect = float(w) / float(h);
  sc.clipFromView = snell::snellPerspectiveWithDepth(kSceneFovy, aspect, kSceneNear, kSceneFar, convention);
  sc.tanHalfY = std::tan(0.5 * double(kSceneFovy));
  sc.tanHalfX = sc.tanHalfY * double(w) / double(h);
  const bool rev = reversedConvention(convention);
  sc.emptyDepth = backFaces ? (rev ? 1.0f : 0.0f) : (rev ? 0.0f : 1.0f);
  sc.analytic = std::move(analytic);
  snell::Image depth(w, h, glm::vec4(sc.emptyDepth, 0.0f, 0.0f, 0.0f)), normals(w, h, glm::vec4(0.0f));
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const glm::dvec2 uv((i + 0.5) / w, (j + 0.5) / h);
      const AnalyticSample a = sc.sampleAt(uv);
      if (!a.valid) continue;
      depth.at(i, j) = glm::vec4(float(sc.windowDepth(a.s)), 0.0f, 0.0f, 0.0f);
      normals.at(i, j) = glm::vec4(glm::vec3(a.normal), 1.0f);
    }
  sc.depth = snell::Texture2D(std::move(depth));
  sc.normals = snell::Texture2D(std::move(normals));
  return sc;
}
}  // namespace detail

// A plane covering the whole screen, tilted about x and y: point (0, 0, -6),
// normal (0.35, 0.45, 1) normalized. View distances ~3.6 .. ~12.
inline DepthScene slantedPlane(int w, int h, int convention = SNELL_DEPTH_GL) {
  const glm::dvec3 p(0.0, 0.0, -6.0), n = glm::normalize(glm::dvec3(0.35, 0.45, 1.0));
  DepthScene sc = detail::makeScene("slantedPlane", w, h, convention, false, kScenePlane,
                                    [p, n](glm::dvec3 q) { return detail::rayPlane(q, p, n); });
  sc.params[0] = glm::vec4(glm::vec3(p), 0.0f);
  sc.params[1] = glm::vec4(glm::vec3(n), 0.0f);
  return sc;
}

// The back hemisphere of a sphere (centre (0.3, -0.2, -6), radius 2.2): what
// a back-face pass with GL_GREATER stores; empty outside its silhouette.
inline DepthScene sphereBack(int w, int h, int convention = SNELL_DEPTH_GL) {
  const glm::dvec3 c(0.3, -0.2, -6.0);
  const double r = 2.2;
  DepthScene sc = detail::makeScene("sphereBack", w, h, convention, true, kSceneSphereBack,
                                    [c, r](glm::dvec3 q) { return detail::sphereBack(q, c, r); });
  sc.params[0] = glm::vec4(glm::vec3(c), float(r));
  return sc;
}

// A depth step: a fronto-parallel half-plane z = -3 for view x <= 0.25 in front
// of a slightly tilted plane through (0, 0, -8); full coverage, one vertical edge.
inline DepthScene stepEdge(int w, int h, int convention = SNELL_DEPTH_GL) {
  const double zA = -3.0, xEdge = 0.25;
  const glm::dvec3 p(0.0, 0.0, -8.0), n = glm::normalize(glm::dvec3(-0.1, 0.2, 1.0));
  DepthScene sc = detail::makeScene("stepEdge", w, h, convention, false, kSceneStep, [=](glm::dvec3 q) {
    const double s = -zA;  // q.z = -1
    if (s * q.x <= xEdge) {
      AnalyticSample a;
      a.s = s;
      a.normal = glm::dvec3(0.0, 0.0, 1.0);
      a.valid = true;
      return a;
    }
    return detail::rayPlane(q, p, n);
  });
  sc.params[0] = glm::vec4(glm::vec3(p), 0.0f);
  sc.params[1] = glm::vec4(glm::vec3(n), 0.0f);
  sc.params[2] = glm::vec4(float(zA), float(xEdge), 0.0f, 0.0f);
  return sc;
}

// A disc with a hole (annulus, radii 0.9 .. 2.4, centre (-0.2, 0.1, -7)) seen
// at an angle (normal (0.2, 0.75, 0.6) normalized), nothing behind it: many
// invalid texels around and inside.
inline DepthScene silhouette(int w, int h, int convention = SNELL_DEPTH_GL) {
  const glm::dvec3 c(-0.2, 0.1, -7.0), n = glm::normalize(glm::dvec3(0.2, 0.75, 0.6));
  const double rIn = 0.9, rOut = 2.4;
  DepthScene sc = detail::makeScene("silhouette", w, h, convention, false, kSceneAnnulus, [=](glm::dvec3 q) {
    AnalyticSample a = detail::rayPlane(q, c, n);
    if (a.valid) {
      const double rr = glm::length(a.s * q - c);
      if (rr < rIn || rr > rOut) a.valid = false;
    }
    return a;
  });
  sc.params[0] = glm::vec4(glm::vec3(c), float(rIn));
  sc.params[1] = glm::vec4(glm::vec3(n), float(rOut));
  return sc;
}

// A thin box (0.05 wide in x, 2.4 tall, from z = -3.5 back through the
// background) in front of a tilted plane through (0, 0, -9): a spike a few
// pixels wide (about 2 px at 256 px height) that strides over it can miss.
inline DepthScene thinSpike(int w, int h, int convention = SNELL_DEPTH_GL) {
  const glm::dvec3 p(0.0, 0.0, -9.0), n = glm::normalize(glm::dvec3(0.15, -0.1, 1.0));
  const glm::dvec3 lo(0.1, -1.2, -12.0), hi(0.15, 1.2, -3.5);
  DepthScene sc = detail::makeScene("thinSpike", w, h, convention, false, kSceneSpike, [=](glm::dvec3 q) {
    const AnalyticSample bg = detail::rayPlane(q, p, n);
    const AnalyticSample box = detail::rayBox(q, lo, hi);
    if (box.valid && (!bg.valid || box.s < bg.s)) return box;
    return bg;
  });
  sc.params[0] = glm::vec4(glm::vec3(p), 0.0f);
  sc.params[1] = glm::vec4(glm::vec3(n), 0.0f);
  sc.params[2] = glm::vec4(glm::vec3(lo), 0.0f);
  sc.params[3] = glm::vec4(glm::vec3(hi), 0.0f);
  return sc;
}

}  // namespace snell_test
