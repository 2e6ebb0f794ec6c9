// The plane-family intersect/ parity and property cases (see parity_case.hpp):
// hit, depth surface, surface point, single sample, the two plane strategies
// with refinement and the normal plane's far start, the depth pyramid reduction,
// and the foreground rule of the scene slots.
//
// Textures: two analytic scenes of tests/support/depth_scenes.hpp at 160x120
// (sphereBack, GL convention, a back-face buffer; silhouette, reversed Z, an
// opaque buffer with many empty texels), their normal mips and depth pyramids.
// Rays: >= 12,000 per case, most of them realistic (refracted rays from the
// sphere's front face into its back faces, rays from in front of the annulus),
// the rest off screen, towards the camera, from behind the camera, hostile.
//
// Comparison: valid flags, fetch counts and the hit's level-0 texel compare
// EXACTLY; uv and positions with the tolerance stated at each case. The pyramid
// reduction compares every output exactly (min/max select, the mean is a sum in
// fixed order and one division).
#include <snell/depth_pyramid.hpp>
#include <snell/intersect.hpp>

#include <cmath>
#include <limits>

#include "parity_case.hpp"
#include "support/depth_scenes.hpp"

namespace parity_plane {
using namespace snell;
Texture2D planeDepthA, planeNormalA, planePyramidA, planeDepthB, planeNormalB, planePyramidB;
#include "cases/plane.glsl"
}  // namespace parity_plane

namespace {
using snell_parity::InputGen;
using snell_parity::ParityIO;
using namespace parity_plane;

constexpr int kInputs = 12000;
constexpr int kW = 160, kH = 120;

const snell_test::DepthScene& sceneA() {
  static const snell_test::DepthScene s = snell_test::sphereBack(kW, kH, SNELL_DEPTH_GL);
  return s;
}
const snell_test::DepthScene& sceneB() {
  static const snell_test::DepthScene s = snell_test::silhouette(kW, kH, SNELL_DEPTH_REVERSED);
  return s;
}

void buildTextures() {
  static bool built = false;
  if (built) return;
  built = true;
  const snell_test::DepthScene& a = sceneA();
  const snell_test::DepthScene& b = sceneB();
  planeDepthA = a.depth;
  planeNormalA = snellBuildNormalMips(a.normals);
  planePyramidA = snellBuildDepthPyramid(a.depth, a.surface());
  planeDepthB = b.depth;
  planeNormalB = snellBuildNormalMips(b.normals);
  planePyramidB = snellBuildDepthPyramid(b.depth, b.surface());
}

std::vector<snell::gpu::ParityTexture> textures() {
  return {{"planeDepthA", &planeDepthA},   {"planeNormalA", &planeNormalA}, {"planePyramidA", &planePyramidA},
          {"planeDepthB", &planeDepthB},   {"planeNormalB", &planeNormalB}, {"planePyramidB", &planePyramidB}};
}

glm::vec4 matrixEntries(const snell_test::DepthScene& s) {
  return glm::vec4(s.clipFromView[0][0], s.clipFromView[1][1], s.clipFromView[2][2], s.clipFromView[3][2]);
}

// A ray for scene `which`: origin, dir.
struct Ray {
  glm::vec3 o, d;
};
Ray sceneRay(InputGen& g, int which) {
  const snell_test::DepthScene& sc = which ? sceneB() : sceneA();
  const float k = g.uniform(0.0f, 1.0f);
  if (which == 0 && k < 0.7f) {
    // Refracted ray from the sphere's front face (centre, radius of sphereBack).
    const glm::dvec3 c(0.3, -0.2, -6.0);
    const double r = 2.2;
    for (;;) {
      const glm::dvec2 uv(g.uniform(0.0f, 1.0f), g.uniform(0.0f, 1.0f));
      const glm::dvec3 q = sc.pixelRay(uv);
      const double a = glm::dot(q, q), b = -2.0 * glm::dot(q, c), cc = glm::dot(c, c) - r * r;
      const double disc = b * b - 4.0 * a * cc;
      if (disc < 0.0) continue;
      const glm::dvec3 w = (-b - std::sqrt(disc)) / (2.0 * a) * q;
      const glm::dvec3 n = (w - c) / r, i = glm::normalize(q);
      const double eta = 1.0 / double(g.uniform(1.05f, 2.4f)), ci = -glm::dot(i, n);
      const double kk = 1.0 - eta * eta * (1.0 - ci * ci);
      const glm::dvec3 t = eta * i + (eta * ci - std::sqrt(kk)) * n;
      return {glm::vec3(w), glm::vec3(t)};
    }
  }
  // A point in the frustum 1..6 in front of the camera, a direction mostly away from it.
  const float dist = g.uniform(1.0f, 6.0f);
  const glm::vec3 o(g.uniform(-1.0f, 1.0f) * dist * float(sc.tanHalfX), g.uniform(-1.0f, 1.0f) * dist * float(sc.tanHalfY),
                    -dist);
  glm::vec3 d = g.unitVector();
  if (g.chance(0.85f)) d.z = -std::fabs(d.z) - 0.3f;
  return {o, d};
}

void hostileRay(InputGen& g, Ray& r) {
  const float k = g.uniform(0.0f, 1.0f);
  if (k < 0.02f) r.o = g.hostileVector();
  else if (k < 0.04f) r.d = g.hostileVector();
  else if (k < 0.05f) r.d = glm::vec3(0.0f);
  else if (k < 0.06f) r.o.z = g.uniform(0.0f, 3.0f);  // at or behind the camera
  else if (k < 0.08f) r.o.x *= 4.0f;                   // off screen
  else if (k < 0.10f) r.d = -r.d;                      // towards the camera
}

std::vector<ParityIO> rayInputs(std::uint32_t seed, bool unitDir) {
  buildTextures();
  InputGen g(seed);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    const int which = g.chance(0.6f) ? 0 : 1;
    const snell_test::DepthScene& sc = which ? sceneB() : sceneA();
    Ray r = sceneRay(g, which);
    if (unitDir) r.d = glm::normalize(r.d);
    hostileRay(g, r);
    int iterations = g.integer(0, 4);
    if (g.chance(0.03f)) iterations = g.chance(0.5f) ? -1 : 20;  // clamped
    static const float lods[] = {0.0f, 0.0f, 0.5f, 1.0f, 2.3f};
    const float normalLod = lods[g.integer(0, 4)];
    const int levels = (which ? planePyramidB : planePyramidA).levelCount();
    const int maxLod = g.chance(0.8f) ? levels - 1 : g.integer(0, levels - 1);
    ParityIO in{};
    in.v[0] = glm::vec4(r.o, float(which));
    in.v[1] = glm::vec4(r.d, float(iterations));
    in.v[2] = matrixEntries(sc);
    // z: every other ray 1 (the plane normal's far start; no draw from g, so the inputs are as before)
    in.v[3] = glm::vec4(normalLod, float(maxLod), float(i % 2), 0.0f);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> uvInputs(std::uint32_t seed, bool withLod) {
  buildTextures();
  InputGen g(seed);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    const int which = g.chance(0.5f) ? 0 : 1;
    glm::vec2 uv(g.uniform(-0.1f, 1.1f), g.uniform(-0.1f, 1.1f));
    if (g.chance(0.1f)) uv = glm::vec2(float(g.integer(0, kW)) / kW, float(g.integer(0, kH)) / kH);  // texel edges
    if (g.chance(0.03f)) uv = glm::vec2(g.hostile(), g.hostile());
    const int levels = (which ? planePyramidB : planePyramidA).levelCount();
    ParityIO in{};
    in.v[0] = glm::vec4(uv, 0.0f, float(which));
    // z: the depth filter for the snellSampleSurface case (every other input bilinear; no draw from g,
    // so the other cases' inputs are unchanged).
    in.v[1] = glm::vec4(0.0f, 0.0f, float(i % 2), withLod && g.chance(0.5f) ? float(g.integer(1, levels - 1)) : 0.0f);
    in.v[2] = matrixEntries(which ? sceneB() : sceneA());
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> hitMissInputs() {
  InputGen g(601);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    ParityIO in{};
    in.v[0] = glm::vec4(float(g.integer(-5, 1000)), 0.0f, 0.0f, 0.0f);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> surfaceInputs() {
  InputGen g(602);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    ParityIO in{};
    in.v[2] = glm::vec4(g.uniform(0.1f, 5.0f), g.uniform(0.1f, 5.0f), g.uniform(-2.0f, 1.0f), g.uniform(-5.0f, 5.0f));
    in.v[3] = glm::vec4(g.uniform(0.01f, 2.0f), g.uniform(2.0f, 1000.0f), float(g.integer(-1, 5)),
                        g.chance(0.5f) ? float(g.integer(0, 1)) : g.uniform(0.0f, 1.0f));
    // Matrix entries stay finite: the case reads them back through products with 0,
    // which a GPU compiler may fold (NaN * 0).
    if (g.chance(0.05f)) in.v[3].x = g.hostile();
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> uvZInputs() {
  InputGen g(603);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    const float b = 1.0f / std::tan(0.5f * g.uniform(0.3f, 2.5f));
    ParityIO in{};
    in.v[0] = glm::vec4(g.uniform(-0.2f, 1.2f), g.uniform(-0.2f, 1.2f), -std::pow(10.0f, g.uniform(-2.0f, 3.0f)), 0.0f);
    in.v[1] = g.chance(0.3f) ? glm::vec4(g.uniform(-0.3f, 0.3f), g.uniform(-0.3f, 0.3f), 0.0f, 0.0f) : glm::vec4(0.0f);
    in.v[2] = glm::vec4(b / g.uniform(0.5f, 2.0f), b, -1.0f - g.uniform(0.0f, 0.1f), -g.uniform(0.01f, 2.0f));
    const float k = g.uniform(0.0f, 1.0f);
    if (k < 0.03f) in.v[0].z = g.uniform(0.0f, 5.0f);  // behind
    else if (k < 0.05f) in.v[0].z = 0.0f;
    else if (k < 0.08f) in.v[0].x = g.hostile();
    else if (k < 0.10f) in.v[0].z = g.hostile();
    else if (k < 0.12f) in.v[2].x = 0.0f;  // singular
    v.push_back(in);
  }
  return v;
}

// The surface's projection pair: perspective, off-centre and sheared (general)
// matrices, the flag cleared for a quarter, hostile coordinates and entries.
ParityIO surfaceShapeInput(InputGen& g) {
  const float b = 1.0f / std::tan(0.5f * g.uniform(0.3f, 2.5f));
  ParityIO in{};
  in.v[1] = glm::vec4(0.0f);
  if (g.chance(0.3f)) in.v[1] = glm::vec4(g.uniform(-0.3f, 0.3f), g.uniform(-0.3f, 0.3f), 0.0f, 0.0f);
  if (g.chance(0.2f)) in.v[1].z = g.uniform(-0.3f, 0.3f);
  in.v[2] = glm::vec4(b / g.uniform(0.5f, 2.0f), b, -1.0f - g.uniform(0.0f, 0.1f), -g.uniform(0.01f, 2.0f));
  if (g.chance(0.03f)) in.v[2].x = 0.0f;  // singular
  if (g.chance(0.03f)) in.v[2][g.integer(0, 3)] = g.hostile();
  in.v[0].w = g.chance(0.25f) ? 1.0f : 0.0f;
  return in;
}
// snellSurfaceLinearDepth: depths across [0,1] and its edges, every convention
// (and unknown ones), valid and invalid ranges.
std::vector<ParityIO> surfaceLinearDepthInputs() {
  InputGen g(615);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    float d = g.uniform(0.0f, 1.0f);
    const float k = g.uniform(0.0f, 1.0f);
    if (k < 0.05f) d = 0.0f;
    else if (k < 0.10f) d = 1.0f;
    else if (k < 0.15f) d = 1.0f - std::ldexp(1.0f, -g.integer(2, 24));  // just below the far plane
    else if (k < 0.18f) d = std::ldexp(1.0f, -g.integer(2, 40));         // just above 0, denormals
    else if (k < 0.22f) d = g.uniform(-0.5f, 1.5f);                      // out of range
    else if (k < 0.25f) d = g.hostile();
    float zNear = g.uniform(0.01f, 2.0f), zFar = g.uniform(2.0f, 1000.0f);
    if (g.chance(0.04f)) zNear = g.hostile();
    if (g.chance(0.04f)) zFar = g.hostile();
    if (g.chance(0.03f)) zFar = zNear;
    ParityIO in{};
    in.v[0] = glm::vec4(d, zNear, zFar, float(g.integer(-1, 5)));
    v.push_back(in);
  }
  return v;
}

// snellDepthSurfaceComplete: a surface filled in by hand whose derived fields
// disagree with its source fields (stale or hostile), read at uv, then
// completed and read again. Source fields: the scene's own projection (a shear
// m10 on a quarter: the perspective flag then disagrees with the matrix), its
// range and convention, or hostile ones.
std::vector<ParityIO> surfaceCompleteInputs() {
  buildTextures();
  InputGen g(616);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    const int which = g.chance(0.5f) ? 0 : 1;
    glm::vec2 uv(g.uniform(-0.1f, 1.1f), g.uniform(-0.1f, 1.1f));
    if (g.chance(0.03f)) uv = glm::vec2(g.hostile(), g.hostile());
    ParityIO in{};
    in.v[0] = glm::vec4(uv, 0.0f, float(which));
    float zNear = 0.5f, zFar = 40.0f;
    if (g.chance(0.1f)) zNear = g.chance(0.5f) ? -g.uniform(0.0f, 1.0f) : 0.0f;  // zero or negative ranges
    if (g.chance(0.1f)) zFar = g.uniform(0.0f, 0.6f);
    if (g.chance(0.05f)) zNear = g.hostile();
    in.v[1] = glm::vec4(zNear, zFar, float(which ? SNELL_DEPTH_REVERSED : SNELL_DEPTH_GL),
                        g.chance(0.25f) ? g.uniform(-0.3f, 0.3f) : 0.0f);
    in.v[2] = matrixEntries(which ? sceneB() : sceneA());
    // The derived fields as the hand filled them: a perspective flag (1/0),
    // a determinant, n / f and the far limit, right, stale or hostile.
    const glm::vec4& e = in.v[2];
    glm::vec4 derived(1.0f, e.x * e.y, zNear / zFar, zFar);
    for (int c = 0; c < 4; ++c) {
      if (!g.chance(0.3f)) continue;
      derived[c] = c == 0 ? float(g.integer(0, 1)) : (g.chance(0.5f) ? g.hostile() : g.uniform(-2.0f, 50.0f));
    }
    in.v[3] = derived;
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> surfaceViewToUvInputs() {
  InputGen g(613);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    ParityIO in = surfaceShapeInput(g);
    glm::vec3 p(g.uniform(-3.0f, 3.0f), g.uniform(-3.0f, 3.0f), -std::pow(10.0f, g.uniform(-2.0f, 3.0f)));
    const float k = g.uniform(0.0f, 1.0f);
    if (k < 0.03f) p.z = g.uniform(0.0f, 5.0f);  // behind
    else if (k < 0.05f) p.z = 0.0f;
    else if (k < 0.10f) p[g.integer(0, 2)] = g.hostile();
    else if (k < 0.12f) p.x = 0.0f;
    in.v[0] = glm::vec4(p, in.v[0].w);
    v.push_back(in);
  }
  return v;
}
std::vector<ParityIO> surfaceUvZInputs() {
  InputGen g(614);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    ParityIO in = surfaceShapeInput(g);
    glm::vec3 a(g.uniform(-0.2f, 1.2f), g.uniform(-0.2f, 1.2f), -std::pow(10.0f, g.uniform(-2.0f, 3.0f)));
    const float k = g.uniform(0.0f, 1.0f);
    if (k < 0.03f) a.z = g.uniform(0.0f, 5.0f);  // behind
    else if (k < 0.05f) a.z = 0.0f;
    else if (k < 0.10f) a[g.integer(0, 2)] = g.hostile();
    else if (k < 0.12f) a.x = 0.5f;  // the centre column
    in.v[0] = glm::vec4(a, in.v[0].w);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> hitOnSurfaceInputs() {
  InputGen g(604);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    const int which = g.chance(0.5f) ? 0 : 1;
    Ray r = sceneRay(g, which);
    glm::vec3 p = r.o + g.uniform(0.0f, 5.0f) * glm::normalize(r.d);
    if (g.chance(0.05f)) p = g.hostileVector();
    if (g.chance(0.03f)) p.z = g.uniform(0.0f, 1.0f);
    ParityIO in{};
    in.v[0] = glm::vec4(p, float(which));
    in.v[1] = glm::vec4(0.0f, 0.0f, 0.0f, float(g.integer(0, 20)));
    in.v[2] = matrixEntries(which ? sceneB() : sceneA());
    v.push_back(in);
  }
  return v;
}

// As hitOnSurfaceInputs, plus the held plane's texel uv (on and off the surface).
std::vector<ParityIO> planeHitInputs() {
  std::vector<ParityIO> v = hitOnSurfaceInputs();
  InputGen g(612);
  for (ParityIO& in : v) in.v[3] = glm::vec4(g.uniform(-0.1f, 1.1f), g.uniform(-0.1f, 1.1f), 0.0f, 0.0f);
  return v;
}

std::vector<ParityIO> pyramidBaseInputs() {
  InputGen g(605);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    const float n = std::pow(10.0f, g.uniform(-2.0f, 0.5f));
    float d = g.uniform(0.0f, 1.0f);
    const float empty = g.chance(0.5f) ? 0.0f : 1.0f;
    if (g.chance(0.15f)) d = empty;
    if (g.chance(0.05f)) d = g.hostile();
    ParityIO in{};
    in.v[0] = glm::vec4(d, n, n * std::pow(10.0f, g.uniform(0.3f, 4.0f)), float(g.integer(0, 4)));
    if (g.chance(0.03f)) in.v[0].y = g.hostile();
    in.v[1] = glm::vec4(empty, 0.0f, 0.0f, 0.0f);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> reduceInputs() {
  buildTextures();
  InputGen g(606);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    const int which = g.chance(0.5f) ? 0 : 1;
    const Texture2D& p = which ? planePyramidB : planePyramidA;
    const int lod = g.integer(0, p.levelCount() - 2);
    const glm::ivec2 next = p.size(lod + 1);
    ParityIO in{};
    in.v[0] = glm::vec4(float(g.integer(0, next.x - 1)), float(g.integer(0, next.y - 1)), float(lod), float(which));
    v.push_back(in);
  }
  return v;
}

// A strategy's hit (on the pixel ray of its uv, in front of and behind the surfaces) and a ray origin
// depth, for the foreground rule: both verdicts are common. Layout: (uv, origin z, scene), (position,
// valid), the projection's entries, (depth filter, fetches so far, tolerance).
std::vector<ParityIO> foregroundInputs() {
  InputGen g(617);
  std::vector<ParityIO> v;
  const float tolerances[] = {0.0f, 0.01f, 0.2f, 1.0f, -0.5f, 3.0f};
  for (int i = 0; i < kInputs; ++i) {
    const int which = g.chance(0.5f) ? 0 : 1;
    const snell_test::DepthScene& sc = which ? sceneB() : sceneA();
    glm::vec2 uv(g.uniform(-0.05f, 1.05f), g.uniform(-0.05f, 1.05f));
    glm::vec3 p = glm::vec3(sc.pixelRay(glm::dvec2(uv)) * double(g.uniform(1.0f, 15.0f)));
    float originZ = -g.uniform(1.0f, 15.0f);
    float tolerance = tolerances[g.integer(0, 5)];
    if (g.chance(0.03f)) uv[g.integer(0, 1)] = g.hostile();
    if (g.chance(0.03f)) p = g.hostileVector();
    if (g.chance(0.03f)) originZ = g.hostile();
    if (g.chance(0.03f)) tolerance = g.hostile();
    ParityIO in{};
    in.v[0] = glm::vec4(uv, originZ, float(which));
    in.v[1] = glm::vec4(p, g.chance(0.9f) ? 1.0f : 0.0f);
    in.v[2] = matrixEntries(sc);
    in.v[3] = glm::vec4(float(i % 2), float(g.integer(0, 20)), tolerance, 0.0f);
    v.push_back(in);
  }
  return v;
}

}  // namespace

namespace parity_plane {
#define SNELL_PARITY_FILE "plane.glsl"
using snell_parity::CaseExtras;

CaseExtras sampling() { return CaseExtras().sampling(textures(), buildTextures); }

// A hit (PLANE_PARITY_SET_HIT): uv and position with the case's tolerance; the
// valid flag, fetch count and level-0 texel exactly.
#define PLANE_HIT_OUT(check) \
  (vec2, uv, 0, check)(bool, valid, 2, exact)(int, fetches, 3, exact)(vec3, position, 4, check)(ivec2, texel, 8, exact)
// A ray case's inputs: origin and scene (false: A, true: B), direction and
// iteration count, the projection's four entries, normalLod, maxLod and
// farStart (the far start case: scene B's surface is open).
#define PLANE_RAY_IN                                                                                         \
  (vec3, origin, 0)(bool, sceneB, 3)(vec3, dir, 4)(int, iterations, 7)(vec4, entries, 8)(float, normalLod, 12) \
  (int, maxLod, 13)(bool, farStart, 14)

SNELL_PARITY_CASE(snellHitMiss, hitMissInputs,
                  (int, missFetches, 0),
                  PLANE_HIT_OUT(exact),
                  {},
                  PLANE_PARITY_SET_HIT(snellHitMiss(missFetches));)

SNELL_PARITY_CASE(snellDepthSurface, surfaceInputs,
                  (vec4, entries, 8)(float, zNear, 12)(float, zFar, 13)(int, convention, 14)(float, emptyDepth, 15),
                  (vec4, storedEntries, 0, exact)(float, storedNear, 4, exact)(float, storedFar, 5, exact)
                  (int, storedConvention, 6, exact)(float, storedEmpty, 7, exact)(int, lod, 8, exact)
                  (float, m23, 9, exact)(float, zeroSum0, 10, exact)(float, zeroSum1, 11, exact),
                  CaseExtras().passThrough({"entries", "zNear", "zFar", "convention", "emptyDepth"},
                                           {"storedEntries", "storedNear", "storedFar", "storedConvention",
                                            "storedEmpty", "lod", "m23", "zeroSum0", "zeroSum1"},
                                           "a plain constructor: the case packs back the matrix and (zNear, zFar, "
                                           "convention, emptyDepth) it stores"),
                  SnellDepthSurface s = snellDepthSurface(planeParityMatrix(entries), zNear, zFar, convention, emptyDepth);
                  vec4 c0 = SNELL_MUL(s.clipFromView, vec4(1.0f, 0.0f, 0.0f, 0.0f));
                  vec4 c1 = SNELL_MUL(s.clipFromView, vec4(0.0f, 1.0f, 0.0f, 0.0f));
                  vec4 c2 = SNELL_MUL(s.clipFromView, vec4(0.0f, 0.0f, 1.0f, 0.0f));
                  vec4 c3 = SNELL_MUL(s.clipFromView, vec4(0.0f, 0.0f, 0.0f, 1.0f));
                  storedEntries = vec4(c0.x, c1.y, c2.z, c3.z);
                  storedNear = s.zNear;
                  storedFar = s.zFar;
                  storedConvention = s.convention;
                  storedEmpty = s.emptyDepth;
                  lod = s.lod;
                  m23 = c2.w;
                  zeroSum0 = c0.y + c0.z + c0.w + c1.x + c1.z + c1.w;
                  zeroSum1 = c2.x + c2.y + c3.x + c3.y + c3.w;)

// The surface's linearization and the reference it equals, each against C++
// (one division each; the unit test DepthSurface.* compares the two bit for bit).
SNELL_PARITY_CASE(snellSurfaceLinearDepth, surfaceLinearDepthInputs,
                  (float, depthValue, 0)(float, zNear, 1)(float, zFar, 2)(int, convention, 3),
                  (float, distance, 0, within(1e-6f, 1e-5f))(float, reference, 1, within(1e-6f, 1e-5f)),
                  {},
                  SnellDepthSurface s = snellDepthSurface(planeParityMatrix(vec4(1.0f, 1.0f, -1.0f, -1.0f)), zNear,
                                                          zFar, convention, 0.0f);
                  distance = snellSurfaceLinearDepth(s, depthValue);
                  reference = snellLinearizeDepth(depthValue, zNear, zFar, convention);)

// A hand-filled, inconsistent surface read as it is (hand*), then completed.
SNELL_PARITY_CASE(snellDepthSurfaceComplete, surfaceCompleteInputs,
                  (vec2, uv, 0)(bool, sceneB, 3)(float, zNear, 4)(float, zFar, 5)(int, convention, 6)
                  (float, shear, 7)(vec4, entries, 8)(bool, handPerspective, 12)(float, handDet, 13)
                  (float, handNearOverFar, 14)(float, handFarLimit, 15),
                  (vec3, handPosition, 0, within(1e-5f, 1e-5f))(bool, handValid, 3, exact)
                  (vec3, position, 4, within(1e-5f, 1e-5f))(bool, valid, 7, exact)(bool, perspective, 8, exact)
                  (bool, linearizable, 9, exact)(float, det, 10, within(1e-6f, 1e-6f))
                  (float, nearOverFar, 11, within(1e-6f, 1e-6f))(float, farLimit, 12, exact),
                  sampling(),
                  SnellDepthSurface s = planeParitySurface(sceneB, vec4(1.0f, 1.0f, -1.0f, -1.0f));
                  s.clipFromView = SNELL_CAMERA_MAT4_COLUMNS(vec4(entries.x, 0.0f, 0.0f, 0.0f),
                                                             vec4(shear, entries.y, 0.0f, 0.0f),
                                                             vec4(0.0f, 0.0f, entries.z, -1.0f),
                                                             vec4(0.0f, 0.0f, entries.w, 0.0f));
                  s.zNear = zNear;
                  s.zFar = zFar;
                  s.convention = convention;
                  s.perspective = handPerspective;
                  s.perspectiveDet = handDet;
                  s.linearizable = true;
                  s.nearOverFar = handNearOverFar;
                  s.depthFarLimit = handFarLimit;
                  SnellSurfacePoint h;  // no ?: on structs: WebGL rejects it
                  if (sceneB) {
                    h = snellSurfacePoint(planeDepthB, uv, s);
                  } else {
                    h = snellSurfacePoint(planeDepthA, uv, s);
                  }
                  handPosition = h.position;
                  handValid = h.valid;
                  SnellDepthSurface c = snellDepthSurfaceComplete(s);
                  SnellSurfacePoint p;
                  if (sceneB) {
                    p = snellSurfacePoint(planeDepthB, uv, c);
                  } else {
                    p = snellSurfacePoint(planeDepthA, uv, c);
                  }
                  position = p.position;
                  valid = p.valid;
                  perspective = c.perspective;
                  linearizable = c.linearizable;
                  det = c.perspectiveDet;
                  nearOverFar = c.nearOverFar;
                  farLimit = c.depthFarLimit;)

// One fetch and a linearization (a division: GL may use x * (1/y), 2.5 ulp).
// lod > 0 reads the pyramid.
SNELL_PARITY_CASE(snellSampleSurface, [] { return uvInputs(607, true); },
                  (vec2, uv, 0)(bool, sceneB, 3)(int, depthFilter, 6)(int, lod, 7)(vec4, entries, 8),
                  (float, viewZ, 0, within(1e-5f, 1e-5f))(bool, valid, 1, exact),
                  sampling(),
                  SnellDepthSurface s = planeParitySurface(sceneB, entries);
                  s.lod = lod;
                  s.depthFilter = depthFilter;
                  SnellSurfaceSample x;  // no ?: on structs: WebGL rejects it
                  if (sceneB) {
                    if (s.lod > 0) {
                      x = snellSampleSurface(planePyramidB, uv, s);
                    } else {
                      x = snellSampleSurface(planeDepthB, uv, s);
                    }
                  } else {
                    if (s.lod > 0) {
                      x = snellSampleSurface(planePyramidA, uv, s);
                    } else {
                      x = snellSampleSurface(planeDepthA, uv, s);
                    }
                  }
                  viewZ = x.viewZ;
                  valid = x.valid;)

// Cramer's rule: a handful of products and two divisions. (m20, m21): the
// off-centre terms.
SNELL_PARITY_CASE(snellUvZToView, uvZInputs,
                  (vec2, uv, 0)(float, viewZ, 2)(vec2, offCentre, 4)(vec4, entries, 8),
                  (vec3, position, 0, within(1e-5f, 1e-5f))(bool, valid, 3, exact),
                  {},
                  mat4 m = SNELL_CAMERA_MAT4_COLUMNS(vec4(entries.x, 0.0f, 0.0f, 0.0f), vec4(0.0f, entries.y, 0.0f, 0.0f),
                                                     vec4(offCentre.x, offCentre.y, entries.z, -1.0f),
                                                     vec4(0.0f, 0.0f, entries.w, 0.0f));
                  SnellViewPoint p = snellUvZToView(m, uv, viewZ);
                  position = p.position;
                  valid = p.valid;)

// The surface's own projection (surface_projection.glsl): shape = (m20, m21)
// off-centre terms and m10, a shear that makes the matrix general; clearFlag
// clears the perspective flag snellDepthSurface set (output `perspective`).
SNELL_PARITY_CASE(snellSurfaceViewToUv, surfaceViewToUvInputs,
                  (vec3, pView, 0)(bool, clearFlag, 3)(vec3, shape, 4)(vec4, entries, 8),
                  (vec2, uv, 0, within(1e-5f, 1e-5f))(float, ndcZ, 2, within(1e-5f, 1e-5f))(bool, valid, 3, exact)
                  (bool, perspective, 4, exact),
                  {},
                  SnellDepthSurface s = planeParityShapedSurface(shape, entries);
                  perspective = s.perspective;
                  if (clearFlag) {
                    s.perspective = false;
                  }
                  SnellScreenPoint sp = snellSurfaceViewToUv(s, pView);
                  uv = sp.uv;
                  ndcZ = sp.ndcZ;
                  valid = sp.valid;)
SNELL_PARITY_CASE(snellSurfaceUvZToView, surfaceUvZInputs,
                  (vec2, uv, 0)(float, viewZ, 2)(bool, clearFlag, 3)(vec3, shape, 4)(vec4, entries, 8),
                  (vec3, position, 0, within(1e-5f, 1e-5f))(bool, valid, 3, exact)(bool, perspective, 4, exact),
                  {},
                  SnellDepthSurface s = planeParityShapedSurface(shape, entries);
                  perspective = s.perspective;
                  if (clearFlag) {
                    s.perspective = false;
                  }
                  SnellViewPoint p = snellSurfaceUvZToView(s, uv, viewZ);
                  position = p.position;
                  valid = p.valid;)

// The point's uv is its texel centre: exact.
SNELL_PARITY_CASE(snellSurfacePoint, [] { return uvInputs(608, false); },
                  (vec2, uv, 0)(bool, sceneB, 3)(vec4, entries, 8),
                  (vec3, position, 0, within(1e-5f, 1e-5f))(bool, valid, 3, exact)(vec2, texelUv, 4, exact),
                  sampling(),
                  SnellDepthSurface s = planeParitySurface(sceneB, entries);
                  SnellSurfacePoint p;
                  if (sceneB) {
                    p = snellSurfacePoint(planeDepthB, uv, s);
                  } else {
                    p = snellSurfacePoint(planeDepthA, uv, s);
                  }
                  position = p.position;
                  valid = p.valid;
                  texelUv = p.uv;)

// Positions: 1e-4 relative (plane intersections amplify ulp differences of the
// reconstruction by 1/cos of the ray-plane angle); the texel must be the same.
SNELL_PARITY_CASE(snellIntersectSingleSample, [] { return rayInputs(609, false); },
                  PLANE_RAY_IN,
                  PLANE_HIT_OUT(within(1e-4f, 1e-4f)),
                  sampling(),
                  SnellDepthSurface s = planeParitySurface(sceneB, entries);
                  if (sceneB) {
                    PLANE_PARITY_SET_HIT(snellIntersectSingleSample(origin, dir, planeDepthB, s));
                  } else {
                    PLANE_PARITY_SET_HIT(snellIntersectSingleSample(origin, dir, planeDepthA, s));
                  })
// The rule returns the hit it is given or a miss: uv and position exactly (a hit given with non-finite ones
// is returned as it is, the pass-through).
SNELL_PARITY_CASE(snellRejectForeground, foregroundInputs,
                  (vec2, hitUv, 0)(float, originZ, 2)(bool, sceneB, 3)(vec3, hitPosition, 4)(bool, hitValid, 7)
                  (vec4, entries, 8)(int, depthFilter, 12)(int, hitFetches, 13)(float, tolerance, 14),
                  PLANE_HIT_OUT(exact),
                  sampling().passThrough({"hitUv", "hitPosition"}, {"uv", "position"},
                                         "intersect/foreground.glsl: an invalid hit, or one kept, is returned as it "
                                         "was given"),
                  SnellDepthSurface s = planeParitySurface(sceneB, entries);
                  s.depthFilter = depthFilter;
                  SnellHit h;
                  h.uv = hitUv;
                  h.position = hitPosition;
                  h.valid = hitValid;
                  h.fetches = hitFetches;
                  if (sceneB) {
                    PLANE_PARITY_SET_HIT(snellRejectForeground(h, vec3(0.0f, 0.0f, originZ), planeDepthB, s, tolerance));
                  } else {
                    PLANE_PARITY_SET_HIT(snellRejectForeground(h, vec3(0.0f, 0.0f, originZ), planeDepthA, s, tolerance));
                  })
SNELL_PARITY_CASE(snellHitOnSurface, hitOnSurfaceInputs,
                  (vec3, p, 0)(bool, sceneB, 3)(int, fetchesSoFar, 7)(vec4, entries, 8),
                  PLANE_HIT_OUT(within(1e-5f, 1e-5f)),
                  sampling(),
                  SnellDepthSurface s = planeParitySurface(sceneB, entries);
                  if (sceneB) {
                    PLANE_PARITY_SET_HIT(snellHitOnSurface(p, planeDepthB, s, fetchesSoFar));
                  } else {
                    PLANE_PARITY_SET_HIT(snellHitOnSurface(p, planeDepthA, s, fetchesSoFar));
                  })
SNELL_PARITY_CASE(snellPlaneHit, planeHitInputs,
                  (vec3, p, 0)(bool, sceneB, 3)(int, fetchesSoFar, 7)(vec4, entries, 8)(vec2, planeUv, 12),
                  PLANE_HIT_OUT(within(1e-5f, 1e-5f)),
                  sampling(),
                  SnellDepthSurface s = planeParitySurface(sceneB, entries);
                  if (sceneB) {
                    PLANE_PARITY_SET_HIT(snellPlaneHit(p, planeUv, planeDepthB, s, fetchesSoFar));
                  } else {
                    PLANE_PARITY_SET_HIT(snellPlaneHit(p, planeUv, planeDepthA, s, fetchesSoFar));
                  })
// Two pyramid fetches chosen by comparisons of a projected point: the level and the texel
// compare exactly (fetches, valid), the plane hit with the single sample's tolerance.
// The origin's own projection is originUv; farStart on scene B makes its surface open.
SNELL_PARITY_CASE(snellPlaneFarStart, [] { return rayInputs(613, false); },
                  PLANE_RAY_IN,
                  (vec3, position, 0, within(1e-4f, 1e-4f))(bool, valid, 3, exact)(float, t, 4, within(1e-4f, 1e-4f))
                  (int, fetches, 5, exact),
                  sampling(),
                  SnellDepthSurface s = planeParitySurface(sceneB, entries);
                  vec2 originUv = snellSurfaceViewToUv(s, origin).uv;
                  SnellFarPlane f;
                  if (sceneB) {
                    s.closed = !farStart;
                    f = snellPlaneFarStart(origin, dir, originUv, planePyramidB, s);
                  } else {
                    f = snellPlaneFarStart(origin, dir, originUv, planePyramidA, s);
                  }
                  position = f.position;
                  valid = f.valid;
                  t = f.t;
                  fetches = f.fetches;)
SNELL_PARITY_CASE(snellIntersectPlaneNormal, [] { return rayInputs(610, false); },
                  PLANE_RAY_IN,
                  PLANE_HIT_OUT(within(1e-4f, 1e-4f)),
                  sampling(),
                  SnellDepthSurface s = planeParitySurface(sceneB, entries);
                  if (sceneB) {
                    PLANE_PARITY_SET_HIT(snellIntersectPlaneNormal(origin, dir, planeDepthB, planeNormalB, planePyramidB, s,
                                                                   normalLod, iterations, farStart));
                  } else {
                    PLANE_PARITY_SET_HIT(snellIntersectPlaneNormal(origin, dir, planeDepthA, planeNormalA, planePyramidA, s,
                                                                   normalLod, iterations, farStart));
                  })
// dir is a unit vector here.
SNELL_PARITY_CASE(snellDepthPlaneAt, [] { return rayInputs(611, true); },
                  PLANE_RAY_IN,
                  (vec3, position, 0, within(1e-4f, 1e-4f))(bool, valid, 3, exact)(vec3, normal, 4, within(1e-4f, 1e-4f))
                  (int, fetches, 7, exact),
                  sampling(),
                  SnellDepthSurface s = planeParitySurface(sceneB, entries);
                  SnellDepthPlane p;
                  if (sceneB) {
                    p = snellDepthPlaneAt(origin, dir, planePyramidB, s, maxLod);
                  } else {
                    p = snellDepthPlaneAt(origin, dir, planePyramidA, s, maxLod);
                  }
                  position = p.position;
                  valid = p.valid;
                  normal = p.normal;
                  fetches = p.fetches;)
SNELL_PARITY_CASE(snellIntersectPlaneDepth, [] { return rayInputs(612, false); },
                  PLANE_RAY_IN,
                  PLANE_HIT_OUT(within(1e-4f, 1e-4f)),
                  sampling(),
                  SnellDepthSurface s = planeParitySurface(sceneB, entries);
                  if (sceneB) {
                    PLANE_PARITY_SET_HIT(snellIntersectPlaneDepth(origin, dir, planePyramidB, s, maxLod, iterations, farStart));
                  } else {
                    PLANE_PARITY_SET_HIT(snellIntersectPlaneDepth(origin, dir, planePyramidA, s, maxLod, iterations, farStart));
                  })
// The texel's mean depth value and coverage exactly; nearest / farthest
// distances (a linearization) within 1e-5.
SNELL_PARITY_CASE(snellDepthPyramidBase, pyramidBaseInputs,
                  (float, depthValue, 0)(float, zNear, 1)(float, zFar, 2)(int, convention, 3)(float, emptyDepth, 4),
                  (float, meanDepth, 0, exact)(vec2, nearFar, 1, within(1e-5f, 1e-5f))(float, coverage, 3, exact),
                  CaseExtras().passThrough({"emptyDepth"}, {"meanDepth"},
                                           "intersect/depth_pyramid.glsl: an invalid texel is vec4(emptyDepth, 0, 0, "
                                           "0), the emptyDepth given"),
                  SnellDepthSurface s = snellDepthSurface(planeParityMatrix(vec4(1.0f, 1.0f, -1.0f, -1.0f)), zNear, zFar,
                                                          convention, emptyDepth);
                  vec4 texel = snellDepthPyramidBase(depthValue, s);
                  meanDepth = texel.x;
                  nearFar = vec2(texel.y, texel.z);
                  coverage = texel.w;)
// Min/max select, the mean a sum in fixed order and one division: exact.
SNELL_PARITY_CASE(snellDepthMinMaxReduce, reduceInputs,
                  (ivec2, px, 0)(int, lod, 2)(bool, sceneB, 3),
                  (vec4, texel, 0, exact),
                  sampling(),
                  if (sceneB) {
                    texel = snellDepthMinMaxReduce(planePyramidB, lod, px, 0.0f);
                  } else {
                    texel = snellDepthMinMaxReduce(planePyramidA, lod, px, 0.0f);
                  })

}  // namespace parity_plane
