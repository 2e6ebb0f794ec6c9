// The camera/ parity and property cases (see parity_case.hpp).
//
// Tolerances: 1e-5 relative (with a small absolute floor) unless stated. The
// GLSL may evaluate x/y as x * (1/y) (2.5 ulp allowed), tan() with its own
// polynomial, and contract a*b+c into fma; the CPU build does none of that.
// Where a formula cancels (a matrix row summing terms of opposite sign), the
// absolute floor is widened, with the reason next to the case.
#include <snell/camera.hpp>

#include <cmath>
#include <limits>

#include "parity_case.hpp"

namespace {
using snell_parity::InputGen;
using snell_parity::ParityIO;

constexpr int kInputs = 12000;

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

namespace parity_camera {
using namespace snell;
using snell_parity::CaseExtras;
#include "cases/camera.glsl"
#define SNELL_PARITY_FILE "camera.glsl"

// A camera: (fovy, aspect, zNear, zFar) in one vec4, built into a matrix the
// same way on both sides. A matrix leaves as its four columns.
#define CAMERA_COLUMNS_OUT(check) \
  (vec4, column0, 0, check)(vec4, column1, 4, check)(vec4, column2, 8, check)(vec4, column3, 12, check)

// Depth maps: every sum adds positive terms (no cancellation), a few ulp apart.
SNELL_PARITY_CASE(snellLinearizeDepth, linearizeInputs,
                  (float, depthValue, 0)(float, zNear, 1)(float, zFar, 2)(int, convention, 3),
                  (float, distance, 0, within(1e-6f, 1e-5f)),
                  {},
                  distance = snellLinearizeDepth(depthValue, zNear, zFar, convention);)
SNELL_PARITY_CASE(snellDelinearizeDepth, delinearizeInputs,
                  (float, distance, 0)(float, zNear, 1)(float, zFar, 2)(int, convention, 3),
                  (float, depthValue, 0, within(1e-6f, 1e-5f)),
                  {},
                  depthValue = snellDelinearizeDepth(distance, zNear, zFar, convention);)
SNELL_PARITY_CASE(snellDepthToNdcZ, [] { return ndcInputs(303, -0.2f, 1.2f); },
                  (float, depthValue, 0)(int, convention, 1),
                  (float, ndcZ, 0, within(1e-6f, 1e-6f)),
                  {},
                  ndcZ = snellDepthToNdcZ(depthValue, convention);)
SNELL_PARITY_CASE(snellNdcZToDepth, [] { return ndcInputs(304, -1.2f, 1.2f); },
                  (float, ndcZ, 0)(int, convention, 1),
                  (float, depthValue, 0, within(1e-6f, 1e-6f)),
                  {},
                  depthValue = snellNdcZToDepth(ndcZ, convention);)

// Matrices: tan() on the GPU is its own polynomial; 1e-5 relative covers it.
SNELL_PARITY_CASE(snellPerspective, [] { return perspectiveInputs(305); },
                  (float, fovy, 0)(float, aspect, 1)(float, zNear, 2)(float, zFar, 3),
                  CAMERA_COLUMNS_OUT(within(1e-6f, 1e-5f)),
                  {},
                  CAMERA_PARITY_SET_COLUMNS(snellPerspective(fovy, aspect, zNear, zFar));)
SNELL_PARITY_CASE(snellPerspectiveWithDepth, [] { return perspectiveInputs(315); },
                  (float, fovy, 0)(float, aspect, 1)(float, zNear, 2)(float, zFar, 3)(int, convention, 4),
                  CAMERA_COLUMNS_OUT(within(1e-6f, 1e-5f)),
                  {},
                  CAMERA_PARITY_SET_COLUMNS(snellPerspectiveWithDepth(fovy, aspect, zNear, zFar, convention));)
SNELL_PARITY_CASE(snellPerspectiveInverse, [] { return perspectiveInputs(325); },
                  (float, fovy, 0)(float, aspect, 1)(float, zNear, 2)(float, zFar, 3)(int, convention, 4),
                  CAMERA_COLUMNS_OUT(within(1e-6f, 1e-5f)),
                  {},
                  CAMERA_PARITY_SET_COLUMNS(snellPerspectiveInverse(fovy, aspect, zNear, zFar, convention));)

// clip.z = C z + D sums terms of opposite sign (zero at z = -2fn/(f+n)); with fma
// contraction on the GPU the absolute error is an ulp of the terms (|D| <= ~60
// here: 4e-6), hence the 1e-5 floor. Hostile points are finite here: the
// function documents NaN/Inf propagation only.
SNELL_PARITY_CASE(snellViewToClip, [] { return viewPointInputs(309, false); },
                  (vec4, camera, 0)(int, convention, 4)(vec3, pView, 8),
                  (vec4, clip, 0, within(1e-5f, 1e-5f)),
                  CaseExtras().unchecked({"clip"}, "camera/view_to_clip.glsl: 'clipFromView * vec4(pView, 1), nothing "
                                                   "else: no check, NaN and Inf propagate as the matrix product makes "
                                                   "them' (snellClipToNdc is the checked step)"),
                  clip = snellViewToClip(cameraParityMatrix(camera, convention), pView);)
// ndc of tiny w is clamped to +-FLT_MAX on both sides.
SNELL_PARITY_CASE(snellClipToNdc, clipInputs,
                  (vec4, clip, 0),
                  (vec3, ndc, 0, within(1e-6f, 1e-5f))(bool, valid, 3, exact),
                  {},
                  SnellNdc n = snellClipToNdc(clip);
                  ndc = n.ndc;
                  valid = n.valid;)
// ndcZ inherits the C z + D cancellation (divided by w >= near): abs 1e-5.
SNELL_PARITY_CASE(snellViewToUv, [] { return viewPointInputs(310, true); },
                  (vec4, camera, 0)(int, convention, 4)(vec3, pView, 8),
                  (vec2, uv, 0, within(1e-5f, 1e-5f))(float, ndcZ, 2, within(1e-5f, 1e-5f))(bool, valid, 3, exact),
                  {},
                  SnellScreenPoint sp = snellViewToUv(cameraParityMatrix(camera, convention), pView);
                  uv = sp.uv;
                  ndcZ = sp.ndcZ;
                  valid = sp.valid;)
SNELL_PARITY_CASE(snellPixelToUv, pixelToUvInputs,
                  (ivec2, px, 0)(ivec2, size, 2),
                  (vec2, uv, 0, within(0.0f, 1e-6f)),
                  {},
                  uv = snellPixelToUv(px, size);)
// Pixels are discrete: exact (uv * size is one correctly rounded product on both sides).
SNELL_PARITY_CASE(snellUvToPixel, uvToPixelInputs,
                  (vec2, uv, 0)(ivec2, size, 2),
                  (ivec2, px, 0, exact),
                  {},
                  px = snellUvToPixel(uv, size);)
// Reconstruction through viewFromClip computes w = (zc + C wc)/D, which cancels:
// the relative error is ~ulp(1) * distance/zNear (GPU fma contraction changes
// the rounding). Cameras here keep far/near <= 200, so 1e-4 relative covers it.
SNELL_PARITY_CASE(snellUvDepthToView, [] { return uvDepthInputs(311, false); },
                  (vec4, camera, 0)(int, convention, 4)(vec2, uv, 5)(float, depthValue, 7),
                  (vec3, position, 0, within(1e-5f, 1e-4f))(bool, valid, 3, exact),
                  {},
                  mat4 inv = snellPerspectiveInverse(camera.x, camera.y, camera.z, camera.w, convention);
                  SnellViewPoint p = snellUvDepthToView(uv, depthValue, inv, convention);
                  position = p.position;
                  valid = p.valid;)
SNELL_PARITY_CASE(snellUvDistanceToView, [] { return uvDepthInputs(312, true); },
                  (vec4, camera, 0)(int, convention, 4)(vec2, uv, 5)(float, distance, 7),
                  (vec3, position, 0, within(1e-5f, 1e-5f))(bool, valid, 3, exact),
                  {},
                  mat4 inv = snellPerspectiveInverse(camera.x, camera.y, camera.z, camera.w, convention);
                  SnellViewPoint p = snellUvDistanceToView(uv, distance, inv);
                  position = p.position;
                  valid = p.valid;)

// The texture-space ray cases' inputs: a camera, the ray (P1, T1), the
// scene's nearest and farthest depths and a point's depth pz.
#define CAMERA_TEX_RAY_IN \
  (vec4, camera, 0)(vec3, p1, 4)(float, zNearest, 7)(vec3, t1, 8)(float, zFarthest, 11)(int, convention, 12)(float, pz, 13)

// S, E = P1 + l T1 (eqs. 3-4) may be fma-contracted on the GPU: the absolute error
// is an ulp of |l T1| (<= ~100 here: 8e-6), and dt = t'e - t's cancels: abs 1e-4.
SNELL_PARITY_CASE(snellTexRaySetup, [] { return texRayInputs(313); },
                  CAMERA_TEX_RAY_IN,
                  (vec3, s, 0, within(1e-4f, 1e-5f))(bool, valid, 3, exact)(vec3, e, 4, within(1e-4f, 1e-5f))
                  (float, k1, 7, within(1e-4f, 1e-5f))(vec2, ts, 8, within(1e-4f, 1e-5f))
                  (vec2, dt, 10, within(1e-4f, 1e-5f))(float, k2, 12, within(1e-4f, 1e-5f)),
                  {},
                  SnellTexRay r = cameraParityTexRay(camera, convention, p1, t1, zNearest, zFarthest);
                  s = r.s;
                  valid = r.valid;
                  e = r.e;
                  k1 = r.k1;
                  ts = r.ts;
                  dt = r.dt;
                  k2 = r.k2;)
// alpha = ((S.z - pz)/pz) (k1 k2): no cancellation (S.z - pz is exact near S.z).
SNELL_PARITY_CASE(snellTexRayAlpha, [] { return texRayInputs(314); },
                  CAMERA_TEX_RAY_IN,
                  (float, alpha, 0, within(1e-5f, 1e-5f))(bool, valid, 1, exact),
                  {},
                  SnellTexRay r = cameraParityTexRay(camera, convention, p1, t1, zNearest, zFarthest);
                  alpha = snellTexRayAlpha(r, pz);
                  valid = r.valid;)
// uv = t's + alpha dt inherits t's and dt of the setup: abs 1e-4 as there. For pz
// near the eye alpha is huge (1e17 for pz = -1e-30) and multiplies the rounding
// of dt = t'e - t's, a cancelling difference: relative 1e-4 (seen: 1.5e-5).
// Beyond that, measured on every runtime (the six give the same bits): 1 input of
// the 12,000 (#1132: fovy 1.62, a slab 1.2e-4 thick, pz = -3.8e-37, alpha ~3e38)
// is 2.0e31 off on uv.y = -1.03e34. Its camera's fovy / 2 is above pi/4, where
// snellPerspectiveWithDepth reduces tan's argument as (hi - x) - lo; every GPU
// compiler here folds that into (hi - lo) - x (runtime_floats_test.cpp), so A is
// an ulp off the C++ build's, and so are t's and t'e: dt cancels and alpha
// multiplies it. Hence, on a runtime that folds constants and only for such a
// camera (scaledWhere), plus 1.2e-7 |alpha| (|t's| + |t'e|) (`condition`,
// reported for it): an ulp of each end, 2x the 5.7e-8 that input needs. Elsewhere
// a wrong uv of a few ulps times alpha fails.
SNELL_PARITY_CASE(snellTexRayUv, [] { return texRayInputs(316); },
                  CAMERA_TEX_RAY_IN,
                  (vec2, uv, 0, within(1e-4f, 1e-4f, 1.2e-7f, 3))(bool, valid, 2, exact)
                  (vec2, condition, 3, within(1e-4f, 1e-3f)),
                  ::snell_parity::CaseExtras().scaledWhere(
                      [](const ::snell_parity::ParityIO& in) { return in.v[0].x / 2.0f > 0.78539818525f; }),
                  SnellTexRay r = cameraParityTexRay(camera, convention, p1, t1, zNearest, zFarthest);
                  uv = snellTexRayUv(r, pz);
                  valid = r.valid;
                  condition = min(abs(snellTexRayAlpha(r, pz)) * (abs(r.ts) + abs(r.ts + r.dt)),
                                  vec2(SNELL_FLT_MAX, SNELL_FLT_MAX));)

}  // namespace parity_camera
