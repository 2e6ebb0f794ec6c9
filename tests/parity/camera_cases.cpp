// Registrations of the camera/ parity cases (see parity_registry.hpp).
//
// Tolerances: 1e-5 relative (with a small absolute floor) unless stated. The
// GLSL may evaluate x/y as x * (1/y) (2.5 ulp allowed), tan() with its own
// polynomial, and contract a*b+c into fma; the CPU build does none of that.
// Where a formula cancels (a matrix row summing terms of opposite sign), the
// absolute floor is widened, with the reason next to the case.
#include <snell/camera.hpp>

#include <cmath>
#include <limits>

#include "parity_registry.hpp"

namespace parity_camera {
using namespace snell;
using snell::gpu::SnellParityOut;
// Every entry takes four vec4s; most use fewer, and the common subset has no
// way to mark a parameter unused.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include "cases/camera.glsl"
#pragma GCC diagnostic pop
}  // namespace parity_camera

namespace {
using snell_parity::InputGen;
using snell_parity::ParityIO;

constexpr int kInputs = 12000;

ParityIO run(snell::gpu::SnellParityOut (*entry)(glm::vec4, glm::vec4, glm::vec4, glm::vec4), const ParityIO& in) {
  return snell::gpu::toParityIO(entry(in.v[0], in.v[1], in.v[2], in.v[3]));
}

// A depth convention as an integral float: mostly valid, sometimes unknown.
float convention(InputGen& g) {
  if (g.chance(0.04f)) {
    static const float bad[] = {-1.0f, 5.0f, 9.0f, -100.0f};
    return bad[g.integer(0, 3)];
  }
  return static_cast<float>(g.integer(0, SNELL_DEPTH_CONVENTION_COUNT - 1));
}

// A finite hostile value (for inputs whose NaN/Inf would legitimately propagate).
float hostileFinite(InputGen& g) {
  static const float values[] = {0.0f, -0.0f, 1e-38f, 1e-44f, 1e30f, -1e30f, 1.0f, -1.0f};
  return values[g.integer(0, 7)];
}

// (fovy, aspect, zNear, zFar): realistic cameras, the edges of the valid range
// (fovy near 0 and pi, far barely above near, huge far/near) and hostile values.
glm::vec4 camera(InputGen& g) {
  float fovy = g.uniform(0.2f, 2.8f);
  float aspect = g.uniform(0.3f, 3.0f);
  float n = std::pow(10.0f, g.uniform(-2.0f, 1.0f));
  float f = n * std::pow(10.0f, g.uniform(0.3f, 4.0f));
  if (g.chance(0.03f)) fovy = g.chance(0.5f) ? 1e-3f : 3.1f;
  if (g.chance(0.03f)) f = n * 1.001f;
  if (g.chance(0.02f)) f = n;                  // far == near: invalid
  if (g.chance(0.02f)) f = n * 0.5f;           // far < near: invalid
  if (g.chance(0.03f)) fovy = g.hostile();
  if (g.chance(0.03f)) aspect = g.hostile();
  if (g.chance(0.03f)) n = g.hostile();
  if (g.chance(0.03f)) f = g.hostile();
  return glm::vec4(fovy, aspect, n, f);
}

// A camera without hostile values (for cases where the camera only builds the matrix).
glm::vec4 goodCamera(InputGen& g) {
  const float n = std::pow(10.0f, g.uniform(-2.0f, 0.5f));
  return glm::vec4(g.uniform(0.3f, 2.5f), g.uniform(0.5f, 2.0f), n, n * std::pow(10.0f, g.uniform(0.5f, 3.0f)));
}

// A view-space point for camera c: in the frustum, near the near plane, at or
// behind the eye, off screen, or hostile.
glm::vec3 viewPoint(InputGen& g, glm::vec4 c, bool allowNonFinite) {
  const float n = std::isfinite(c.z) && c.z > 0.0f ? c.z : 0.1f;
  const float f = std::isfinite(c.w) && c.w > n ? std::min(c.w, n * 1e4f) : n * 100.0f;
  const float v = n * std::pow(f / n, g.uniform(0.0f, 1.0f));
  const float t = std::tan(0.5f * (std::isfinite(c.x) ? std::min(std::max(c.x, 0.1f), 3.0f) : 1.0f));
  glm::vec3 p(g.uniform(-1.0f, 1.0f) * v * t * 1.5f, g.uniform(-1.0f, 1.0f) * v * t, -v);
  const float k = g.uniform(0.0f, 1.0f);
  if (k < 0.05f) p.z = -n;                          // on the near plane
  else if (k < 0.08f) p.z = -n * g.uniform(0.9f, 1.1f);
  else if (k < 0.11f) p.z = 0.0f;                   // in the eye's plane
  else if (k < 0.15f) p.z = g.uniform(0.0f, 10.0f); // behind the camera
  else if (k < 0.18f) p.x *= 20.0f;                 // far off screen
  if (g.chance(0.04f)) p = allowNonFinite ? g.hostileVector() : glm::vec3(hostileFinite(g), hostileFinite(g), hostileFinite(g));
  return p;
}

std::vector<ParityIO> linearizeInputs() {
  InputGen g(301);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    const glm::vec4 c = camera(g);
    float d = g.uniform(0.0f, 1.0f);
    const float k = g.uniform(0.0f, 1.0f);
    if (k < 0.05f) d = 0.0f;
    else if (k < 0.10f) d = 1.0f;
    else if (k < 0.15f) d = 1.0f - std::ldexp(1.0f, -g.integer(2, 24));  // just below the far plane
    else if (k < 0.18f) d = std::ldexp(1.0f, -g.integer(2, 40));         // just above 0
    else if (k < 0.22f) d = g.uniform(-0.5f, 1.5f);                      // out of range
    else if (k < 0.25f) d = g.hostile();
    ParityIO in{};
    in.v[0] = glm::vec4(d, c.z, c.w, convention(g));
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> delinearizeInputs() {
  InputGen g(302);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    const glm::vec4 c = camera(g);
    const float n = std::isfinite(c.z) && c.z > 0.0f ? c.z : 1.0f;
    float dist = n * std::pow(10.0f, g.uniform(-0.3f, 4.5f));
    const float k = g.uniform(0.0f, 1.0f);
    if (k < 0.05f) dist = c.z;              // on the near plane
    else if (k < 0.10f) dist = c.w;         // on the far plane
    else if (k < 0.13f) dist = 0.0f;        // at the eye
    else if (k < 0.16f) dist = -g.uniform(0.0f, 10.0f);  // behind
    else if (k < 0.20f) dist = g.hostile();
    ParityIO in{};
    in.v[0] = glm::vec4(dist, c.z, c.w, convention(g));
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> ndcInputs(std::uint32_t seed, float lo, float hi) {
  InputGen g(seed);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    float x = g.uniform(lo, hi);
    if (g.chance(0.05f)) x = static_cast<float>(g.integer(-1, 1));
    if (g.chance(0.05f)) x = g.hostile();
    ParityIO in{};
    in.v[0] = glm::vec4(x, convention(g), 0.0f, 0.0f);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> perspectiveInputs(std::uint32_t seed) {
  InputGen g(seed);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    ParityIO in{};
    in.v[0] = camera(g);
    in.v[1] = glm::vec4(convention(g), 0.0f, 0.0f, 0.0f);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> viewPointInputs(std::uint32_t seed, bool allowNonFinite) {
  InputGen g(seed);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    ParityIO in{};
    in.v[0] = g.chance(0.9f) ? goodCamera(g) : camera(g);
    in.v[1] = glm::vec4(convention(g), 0.0f, 0.0f, 0.0f);
    in.v[2] = glm::vec4(viewPoint(g, in.v[0], allowNonFinite), 0.0f);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> clipInputs() {
  InputGen g(306);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    glm::vec4 c(g.uniform(-10.0f, 10.0f), g.uniform(-10.0f, 10.0f), g.uniform(-10.0f, 10.0f), g.uniform(-1.0f, 10.0f));
    const float k = g.uniform(0.0f, 1.0f);
    if (k < 0.05f) c.w = 0.0f;
    else if (k < 0.08f) c.w = -0.0f;
    else if (k < 0.12f) c.w = std::ldexp(1.0f, -g.integer(10, 140));  // tiny (and denormal) w
    else if (k < 0.15f) c.w = -std::ldexp(1.0f, -g.integer(10, 140));
    if (g.chance(0.05f)) c[g.integer(0, 3)] = g.hostile();
    ParityIO in{};
    in.v[0] = c;
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> pixelToUvInputs() {
  InputGen g(307);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    int w = g.integer(1, 8192), h = g.integer(1, 8192);
    int x = g.integer(0, w - 1), y = g.integer(0, h - 1);
    if (g.chance(0.05f)) x = g.integer(-50, -1);
    if (g.chance(0.05f)) y = h + g.integer(0, 50);
    if (g.chance(0.03f)) w = g.integer(-5, 0);
    if (g.chance(0.03f)) h = 0;
    ParityIO in{};
    in.v[0] = glm::vec4(float(x), float(y), float(w), float(h));
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> uvToPixelInputs() {
  InputGen g(308);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    int w = g.integer(1, 8192), h = g.integer(1, 8192);
    glm::vec2 uv(g.uniform(0.0f, 1.0f), g.uniform(0.0f, 1.0f));
    const float k = g.uniform(0.0f, 1.0f);
    if (k < 0.10f) {
      // Pixel centres and (power-of-two sizes) exact pixel boundaries.
      w = 1 << g.integer(0, 13);
      h = 1 << g.integer(0, 13);
      uv = glm::vec2(float(g.integer(0, w)) / float(w), (float(g.integer(0, h - 1)) + 0.5f) / float(h));
    } else if (k < 0.15f) {
      uv = glm::vec2(g.uniform(-2.0f, 3.0f), g.uniform(-2.0f, 3.0f));
    } else if (k < 0.20f) {
      uv = glm::vec2(g.hostile(), g.hostile());
    } else if (k < 0.22f) {
      w = g.integer(-3, 0);
    }
    ParityIO in{};
    in.v[0] = glm::vec4(uv, float(w), float(h));
    v.push_back(in);
  }
  return v;
}

// uv, depth: the projections of frustum points (so depth is consistent), plus
// the planes (near, far, the infinite far plane), out-of-range and hostile depth.
std::vector<ParityIO> uvDepthInputs(std::uint32_t seed, bool linearDistance) {
  InputGen g(seed);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    glm::vec4 cam = g.chance(0.95f) ? goodCamera(g) : camera(g);
    if (!linearDistance) cam.w = std::min(cam.w, cam.z * 200.0f);  // see the tolerance note
    const float conv = convention(g);
    const int ci = static_cast<int>(conv);
    glm::vec2 uv(g.uniform(-0.1f, 1.1f), g.uniform(-0.1f, 1.1f));
    float value = 0.0f;
    const float n = std::isfinite(cam.z) && cam.z > 0.0f ? cam.z : 1.0f;
    const float f = std::isfinite(cam.w) && cam.w > n ? cam.w : n * 10.0f;
    const float dist = n * std::pow(f / n, g.uniform(0.0f, 1.0f));
    if (linearDistance) {
      value = dist;
      const float k = g.uniform(0.0f, 1.0f);
      if (k < 0.05f) value = 0.0f;
      else if (k < 0.08f) value = -1.0f;
      else if (k < 0.11f) value = n;
      else if (k < 0.15f) value = g.hostile();
    } else {
      value = snell::snellDelinearizeDepth(dist, n, f, ci);
      const float k = g.uniform(0.0f, 1.0f);
      if (k < 0.05f) value = 0.0f;
      else if (k < 0.10f) value = 1.0f;
      else if (k < 0.13f) value = g.uniform(-0.5f, 1.5f);
      else if (k < 0.17f) value = g.hostile();
    }
    if (g.chance(0.03f)) uv = glm::vec2(g.hostile(), g.hostile());
    ParityIO in{};
    in.v[0] = cam;
    in.v[1] = glm::vec4(conv, uv, value);
    v.push_back(in);
  }
  return v;
}

// Rays of the paper's setting: P1 on a front face in the frustum, T1 heading
// into the object, back-face planes behind P1; plus Zmin == Zmax, T1.z = 0
// (and denormal), rays towards the camera, planes at or behind the eye, hostile
// values. d.y = pz for the alpha / uv cases: on the segment, extrapolated,
// at the planes, at or behind the eye, hostile.
std::vector<ParityIO> texRayInputs(std::uint32_t seed) {
  InputGen g(seed);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    const glm::vec4 cam = g.chance(0.95f) ? goodCamera(g) : camera(g);
    const float n = std::isfinite(cam.z) && cam.z > 0.0f ? cam.z : 1.0f;
    const float d1 = n * g.uniform(1.5f, 30.0f);
    const float t = std::tan(0.5f * (std::isfinite(cam.x) ? std::min(std::max(cam.x, 0.1f), 3.0f) : 1.0f));
    glm::vec3 p1(g.uniform(-1.0f, 1.0f) * d1 * t, g.uniform(-1.0f, 1.0f) * d1 * t, -d1);
    glm::vec3 t1(g.uniform(-1.0f, 1.0f), g.uniform(-1.0f, 1.0f), -g.uniform(0.1f, 1.0f));
    float zNearest = p1.z - d1 * g.uniform(0.0f, 0.5f);
    float zFarthest = zNearest - d1 * g.uniform(0.0f, 2.0f);
    const float k = g.uniform(0.0f, 1.0f);
    if (k < 0.06f) zFarthest = zNearest;                     // Zmin == Zmax
    else if (k < 0.10f) t1.z = 0.0f;                         // parallel to the planes
    else if (k < 0.12f) t1.z = g.chance(0.5f) ? 1e-44f : -1e-40f;  // denormal: counts as 0
    else if (k < 0.16f) t1.z = g.uniform(0.1f, 1.0f);        // towards the camera
    else if (k < 0.19f) zNearest = g.chance(0.5f) ? 0.0f : g.uniform(0.0f, 2.0f);  // plane at/behind the eye
    else if (k < 0.21f) zFarthest = g.uniform(0.0f, 2.0f);
    else if (k < 0.24f) zNearest = zFarthest = -n;           // the near plane
    else if (k < 0.26f) zFarthest = zNearest - d1 * 1e-4f;   // very thin slab: large k2
    if (g.chance(0.03f)) p1 = g.hostileVector();
    if (g.chance(0.03f)) t1 = g.hostileVector();
    if (g.chance(0.02f)) zNearest = g.hostile();
    if (g.chance(0.02f)) zFarthest = g.hostile();
    // pz: mostly on or near the segment (eq. 5), then the special values.
    const float beta = g.uniform(-0.25f, 1.25f);
    float pz = (1.0f - beta) * zNearest + beta * zFarthest;
    const float kz = g.uniform(0.0f, 1.0f);
    if (kz < 0.05f) pz = zNearest;
    else if (kz < 0.10f) pz = zFarthest;
    else if (kz < 0.13f) pz = 0.0f;
    else if (kz < 0.16f) pz = g.uniform(0.0f, 5.0f);
    else if (kz < 0.18f) pz = -std::ldexp(1.0f, -g.integer(60, 149));  // tiny / denormal
    else if (kz < 0.21f) pz = g.hostile();
    ParityIO in{};
    in.v[0] = cam;
    in.v[1] = glm::vec4(p1, zNearest);
    in.v[2] = glm::vec4(t1, zFarthest);
    in.v[3] = glm::vec4(convention(g), pz, 0.0f, 0.0f);
    v.push_back(in);
  }
  return v;
}

}  // namespace

using parity_camera::caseSnellClipToNdc;
using parity_camera::caseSnellDelinearizeDepth;
using parity_camera::caseSnellDepthToNdcZ;
using parity_camera::caseSnellLinearizeDepth;
using parity_camera::caseSnellNdcZToDepth;
using parity_camera::caseSnellPerspective;
using parity_camera::caseSnellPerspectiveInverse;
using parity_camera::caseSnellPerspectiveWithDepth;
using parity_camera::caseSnellPixelToUv;
using parity_camera::caseSnellTexRayAlpha;
using parity_camera::caseSnellTexRaySetup;
using parity_camera::caseSnellTexRayUv;
using parity_camera::caseSnellUvDepthToView;
using parity_camera::caseSnellUvDistanceToView;
using parity_camera::caseSnellUvToPixel;
using parity_camera::caseSnellViewToClip;
using parity_camera::caseSnellViewToUv;

// Depth maps: every sum adds positive terms (no cancellation), a few ulp apart.
SNELL_PARITY_CASE({"snellLinearizeDepth", "camera.glsl", "caseSnellLinearizeDepth", linearizeInputs,
                   [](const ParityIO& in) { return run(caseSnellLinearizeDepth, in); }, 0, 1, {1e-6f, 1e-5f}});
SNELL_PARITY_CASE({"snellDelinearizeDepth", "camera.glsl", "caseSnellDelinearizeDepth", delinearizeInputs,
                   [](const ParityIO& in) { return run(caseSnellDelinearizeDepth, in); }, 0, 1, {1e-6f, 1e-5f}});
SNELL_PARITY_CASE({"snellDepthToNdcZ", "camera.glsl", "caseSnellDepthToNdcZ",
                   [] { return ndcInputs(303, -0.2f, 1.2f); },
                   [](const ParityIO& in) { return run(caseSnellDepthToNdcZ, in); }, 0, 1, {1e-6f, 1e-6f}});
SNELL_PARITY_CASE({"snellNdcZToDepth", "camera.glsl", "caseSnellNdcZToDepth",
                   [] { return ndcInputs(304, -1.2f, 1.2f); },
                   [](const ParityIO& in) { return run(caseSnellNdcZToDepth, in); }, 0, 1, {1e-6f, 1e-6f}});
// Matrices: tan() on the GPU is its own polynomial; 1e-5 relative covers it.
SNELL_PARITY_CASE({"snellPerspective", "camera.glsl", "caseSnellPerspective", [] { return perspectiveInputs(305); },
                   [](const ParityIO& in) { return run(caseSnellPerspective, in); }, 0, 16, {1e-6f, 1e-5f}});
SNELL_PARITY_CASE({"snellPerspectiveWithDepth", "camera.glsl", "caseSnellPerspectiveWithDepth",
                   [] { return perspectiveInputs(315); },
                   [](const ParityIO& in) { return run(caseSnellPerspectiveWithDepth, in); }, 0, 16, {1e-6f, 1e-5f}});
SNELL_PARITY_CASE({"snellPerspectiveInverse", "camera.glsl", "caseSnellPerspectiveInverse",
                   [] { return perspectiveInputs(325); },
                   [](const ParityIO& in) { return run(caseSnellPerspectiveInverse, in); }, 0, 16, {1e-6f, 1e-5f}});
// clip.z = C z + D sums terms of opposite sign (zero at z = -2fn/(f+n)); with fma
// contraction on the GPU the absolute error is an ulp of the terms (|D| <= ~60
// here: 4e-6), hence the 1e-5 floor. Hostile points are finite here: the
// function documents NaN/Inf propagation only.
SNELL_PARITY_CASE({"snellViewToClip", "camera.glsl", "caseSnellViewToClip", [] { return viewPointInputs(309, false); },
                   [](const ParityIO& in) { return run(caseSnellViewToClip, in); }, 0, 4, {1e-5f, 1e-5f}});
// Flags exact (bit 3); ndc of tiny w is clamped to +-FLT_MAX on both sides.
SNELL_PARITY_CASE({"snellClipToNdc", "camera.glsl", "caseSnellClipToNdc", clipInputs,
                   [](const ParityIO& in) { return run(caseSnellClipToNdc, in); }, 0x8, 4, {1e-6f, 1e-5f}});
// ndcZ inherits the C z + D cancellation (divided by w >= near): abs 1e-5.
SNELL_PARITY_CASE({"snellViewToUv", "camera.glsl", "caseSnellViewToUv", [] { return viewPointInputs(310, true); },
                   [](const ParityIO& in) { return run(caseSnellViewToUv, in); }, 0x8, 4, {1e-5f, 1e-5f}});
SNELL_PARITY_CASE({"snellPixelToUv", "camera.glsl", "caseSnellPixelToUv", pixelToUvInputs,
                   [](const ParityIO& in) { return run(caseSnellPixelToUv, in); }, 0, 2, {0.0f, 1e-6f}});
// Pixels are discrete: exact (uv * size is one correctly rounded product on both sides).
SNELL_PARITY_CASE({"snellUvToPixel", "camera.glsl", "caseSnellUvToPixel", uvToPixelInputs,
                   [](const ParityIO& in) { return run(caseSnellUvToPixel, in); }, 0x3, 2, {0.0f, 0.0f}});
// Reconstruction through viewFromClip computes w = (zc + C wc)/D, which cancels:
// the relative error is ~ulp(1) * distance/zNear (GPU fma contraction changes
// the rounding). Cameras here keep far/near <= 200, so 1e-4 relative covers it.
SNELL_PARITY_CASE({"snellUvDepthToView", "camera.glsl", "caseSnellUvDepthToView",
                   [] { return uvDepthInputs(311, false); },
                   [](const ParityIO& in) { return run(caseSnellUvDepthToView, in); }, 0x8, 4, {1e-5f, 1e-4f}});
SNELL_PARITY_CASE({"snellUvDistanceToView", "camera.glsl", "caseSnellUvDistanceToView",
                   [] { return uvDepthInputs(312, true); },
                   [](const ParityIO& in) { return run(caseSnellUvDistanceToView, in); }, 0x8, 4, {1e-5f, 1e-5f}});
// S, E = P1 + l T1 (eqs. 3-4) may be fma-contracted on the GPU: the absolute error
// is an ulp of |l T1| (<= ~100 here: 8e-6), and dt = t'e - t's cancels: abs 1e-4.
SNELL_PARITY_CASE({"snellTexRaySetup", "camera.glsl", "caseSnellTexRaySetup", [] { return texRayInputs(313); },
                   [](const ParityIO& in) { return run(caseSnellTexRaySetup, in); }, 0x8, 13, {1e-4f, 1e-5f}});
// alpha = ((S.z - pz)/pz) (k1 k2): no cancellation (S.z - pz is exact near S.z).
SNELL_PARITY_CASE({"snellTexRayAlpha", "camera.glsl", "caseSnellTexRayAlpha", [] { return texRayInputs(314); },
                   [](const ParityIO& in) { return run(caseSnellTexRayAlpha, in); }, 0x2, 2, {1e-5f, 1e-5f}});
// uv = t's + alpha dt inherits t's and dt of the setup: abs 1e-4 as there. For pz
// near the eye alpha is huge (1e17 for pz = -1e-30) and multiplies the rounding
// of dt = t'e - t's, a cancelling difference: relative 1e-4 (seen: 1.5e-5).
SNELL_PARITY_CASE({"snellTexRayUv", "camera.glsl", "caseSnellTexRayUv", [] { return texRayInputs(316); },
                   [](const ParityIO& in) { return run(caseSnellTexRayUv, in); }, 0x4, 3, {1e-4f, 1e-4f}});
