// Registrations of the parity cases of the intersect/ searches and marches
// (tests/parity/cases/search.glsl): 12,000 rays per function on two analytic
// scene buffers (sphereBack: refracted rays through the sphere against its back
// faces; silhouette: rays into an annulus with empty texels around and inside),
// with step counts, strides, thicknesses and distances varied per ray and
// hostile rays mixed in (NaN, towards the camera, Zmin == Zmax, zero direction).
//
// Discrete outputs compared exactly: valid, fetch count, and the hit texel
// (snellUvToPixel of the returned uv). Continuous ones (uv, position): 1e-5
// relative with a 1e-5 absolute floor.
#include <snell/intersect.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "parity_case.hpp"
#include "support/depth_scenes.hpp"
#include "support/search_rays.hpp"

namespace parity_search {
using namespace snell;
Texture2D searchTexSphere, searchTexSilhouette;
#include "cases/search.glsl"
}  // namespace parity_search

namespace {
using snell_parity::InputGen;
using snell_parity::ParityIO;
using snell_search_test::Ray;
using snell_test::DepthScene;

constexpr int kInputs = 12000;
constexpr int kSize = 256;

struct SceneData {
  DepthScene scene;
  std::pair<float, float> range;
  glm::vec4 matrix;  // (A, B, C, D)
  std::vector<Ray> rays;
};

glm::vec4 entries(const glm::mat4& m) { return glm::vec4(m[0][0], m[1][1], m[2][2], m[3][2]); }

const SceneData& sceneData(int which) {
  static const SceneData data[2] = {
      [] {
        SceneData s{snell_test::sphereBack(kSize, kSize), {}, {}, {}};
        s.range = snell_search_test::depthRange(s.scene);
        s.matrix = entries(s.scene.clipFromView);
        s.rays = snell_search_test::sphereRefractedRays(s.scene, kInputs, 31);
        return s;
      }(),
      [] {
        SceneData s{snell_test::silhouette(kSize, kSize), {}, {}, {}};
        s.range = snell_search_test::depthRange(s.scene);
        s.matrix = entries(s.scene.clipFromView);
        s.rays = snell_search_test::sceneRays(s.scene, kInputs, 32);
        return s;
      }()};
  return data[which];
}

void setupTextures() {
  for (int k = 0; k < 2; ++k) {
    const SceneData& s = sceneData(k);
    if (parity_search::searchParityMatrix(s.matrix) != s.scene.clipFromView || s.scene.zNear != SEARCH_PARITY_NEAR ||
        s.scene.zFar != SEARCH_PARITY_FAR || s.scene.convention != SNELL_DEPTH_GL ||
        s.scene.emptyDepth != (k == 1 ? 1.0f : 0.0f))
      throw std::logic_error("search parity: scene camera differs from what search.glsl rebuilds");
  }
  parity_search::searchTexSphere = sceneData(0).scene.depth;
  parity_search::searchTexSilhouette = sceneData(1).scene.depth;
}

std::vector<snell::gpu::ParityTexture> textures() {
  return {{"searchTexSphere", &parity_search::searchTexSphere},
          {"searchTexSilhouette", &parity_search::searchTexSilhouette}};
}

// Options per strategy: (option 1, option 2, option 3, thickness in c.x for the DDA).
enum class Kind { Segment, Search, LinearSearch, LinearMarch, Dda };

std::vector<ParityIO> rayInputs(Kind kind, std::uint32_t seed) {
  InputGen g(seed);
  std::vector<ParityIO> v;
  v.reserve(kInputs);
  for (int i = 0; i < kInputs; ++i) {
    const int scene = g.chance(0.6f) ? 0 : 1;
    const SceneData& s = sceneData(scene);
    Ray ray = s.rays[static_cast<std::size_t>(i)];
    float zn = s.range.first, zf = s.range.second;
    if (g.chance(0.06f)) {  // hostile
      switch (g.integer(0, 5)) {
        case 0: ray.dir.z = -ray.dir.z; break;               // towards the camera
        case 1: zf = zn; break;                               // Zmin == Zmax
        case 2: ray.dir = glm::vec3(0.0f); break;             // zero direction
        case 3: ray.origin = g.hostileVector(); break;
        case 4: ray.dir = g.hostileVector(); break;
        default: zn = g.hostile(); break;
      }
    }
    float o1 = 0.0f, o2 = 0.0f, o3 = 0.0f, thick = 0.0f;
    switch (kind) {
      case Kind::Segment: break;
      case Kind::Search: o1 = static_cast<float>(g.integer(0, 10)); break;
      case Kind::LinearSearch:
        o1 = static_cast<float>(g.integer(1, 24));
        o2 = static_cast<float>(g.integer(0, 6));
        break;
      case Kind::LinearMarch:
        o1 = static_cast<float>(g.integer(2, 96));
        o2 = static_cast<float>(g.integer(0, 6));
        o3 = g.uniform(2.0f, 16.0f);
        break;
      case Kind::Dda:
        o1 = static_cast<float>(g.integer(8, 600));
        o2 = g.chance(0.5f) ? 1.0f : g.uniform(0.5f, 8.0f);
        o3 = g.uniform(2.0f, 16.0f);
        thick = g.chance(0.5f) ? SNELL_FLT_MAX : g.uniform(0.0f, 2.0f);
        if (g.chance(0.02f)) thick = std::numeric_limits<float>::quiet_NaN();
        break;
    }
    if (kind != Kind::Segment && g.chance(0.05f)) o1 = -1.0f;  // the #define-default overload
    if (kind == Kind::Search && g.chance(0.02f)) o1 = 40.0f;   // clamped to the max
    ParityIO in{};
    in.v[0] = glm::vec4(ray.origin, o1);
    in.v[1] = glm::vec4(ray.dir, o2);
    in.v[2] = glm::vec4(kind == Kind::Dda ? thick : zn, zf, o3, float(scene));
    in.v[3] = s.matrix;
    v.push_back(in);
  }
  return v;
}

// Brackets: mostly sub-intervals of [0, 1] (the linear search's steps, the whole segment), some reversed,
// outside [0, 1] or NaN (clamped / returned as given).
std::vector<ParityIO> bisectInputs() {
  std::vector<ParityIO> v = rayInputs(Kind::Search, 47);
  InputGen g(48);
  for (ParityIO& in : v) {
    float lo = g.chance(0.3f) ? 0.0f : g.uniform(0.0f, 0.9f);
    float hi = g.chance(0.3f) ? 1.0f : g.uniform(lo, 1.0f);
    if (g.chance(0.05f)) std::swap(lo, hi);
    if (g.chance(0.03f)) lo = g.hostile();
    if (g.chance(0.03f)) hi = g.hostile();
    in.v[1].w = lo;
    in.v[2].z = hi;
    if (in.v[0].w < 0.0f) in.v[0].w = 3.0f;  // no #define-default overload here
  }
  return v;
}
}  // namespace

namespace parity_search {
#define SNELL_PARITY_FILE "search.glsl"
using snell_parity::CaseExtras;

CaseExtras sampling() { return CaseExtras().sampling(textures(), setupTextures); }

// A ray case's inputs: the ray, three per-strategy options (option1 < 0 selects
// the overload with the #define defaults), the search range (zNearest is the
// DDA's thickness), the scene (false: sphereBack, true: silhouette) and the
// projection's four entries.
#define SEARCH_RAY_IN                                                                                          \
  (vec3, origin, 0)(float, option1, 3)(vec3, dir, 4)(float, option2, 7)(float, zNearest, 8)(float, zFarthest, 9) \
  (float, option3, 10)(bool, sceneB, 11)(vec4, entries, 12)
// A hit (SEARCH_PARITY_SET_HIT): valid, fetches and the level-0 texel exactly,
// uv and position within 1e-5 (relative, with a 1e-5 absolute floor).
#define SEARCH_HIT_OUT                                                                                         \
  (vec2, uv, 0, within(1e-5f, 1e-5f))(bool, valid, 2, exact)(int, fetches, 3, exact)                           \
  (vec3, position, 4, within(1e-5f, 1e-5f))(ivec2, texel, 7, exact)

SNELL_PARITY_CASE(snellSearchSegment, [] { return rayInputs(Kind::Segment, 41); },
                  SEARCH_RAY_IN,
                  (vec3, s, 0, within(1e-5f, 1e-5f))(bool, valid, 3, exact)(vec3, e, 4, within(1e-5f, 1e-5f))
                  (float, k1, 7, within(1e-5f, 1e-5f))(vec2, ts, 8, within(1e-5f, 1e-5f))
                  (vec2, dt, 10, within(1e-5f, 1e-5f))(float, k2, 12, within(1e-5f, 1e-5f)),
                  sampling(),
                  SnellTexRay r = snellSearchSegment(origin, dir, zNearest, zFarthest, searchParityMatrix(entries));
                  s = r.s;
                  valid = r.valid;
                  e = r.e;
                  k1 = r.k1;
                  ts = r.ts;
                  dt = r.dt;
                  k2 = r.k2;)
// option1 = steps.
SNELL_PARITY_CASE(snellConservativeBinarySearch, [] { return rayInputs(Kind::Search, 42); },
                  SEARCH_RAY_IN,
                  SEARCH_HIT_OUT,
                  sampling(),
                  SnellDepthSurface s = searchParitySurface(sceneB, entries);
                  SnellHit h;  // no ?: on structs: WebGL rejects it
                  if (sceneB) {
                    if (option1 < 0.0f) {
                      h = snellConservativeBinarySearch(origin, dir, searchTexSilhouette, s, zNearest, zFarthest);
                    } else {
                      h = snellConservativeBinarySearch(origin, dir, searchTexSilhouette, s, zNearest, zFarthest, int(option1));
                    }
                  } else {
                    if (option1 < 0.0f) {
                      h = snellConservativeBinarySearch(origin, dir, searchTexSphere, s, zNearest, zFarthest);
                    } else {
                      h = snellConservativeBinarySearch(origin, dir, searchTexSphere, s, zNearest, zFarthest, int(option1));
                    }
                  }
                  SEARCH_PARITY_SET_HIT(h);)
// option1 = steps.
SNELL_PARITY_CASE(snellBinarySearch, [] { return rayInputs(Kind::Search, 43); },
                  SEARCH_RAY_IN,
                  SEARCH_HIT_OUT,
                  sampling(),
                  SnellDepthSurface s = searchParitySurface(sceneB, entries);
                  SnellHit h;  // no ?: on structs: WebGL rejects it
                  if (sceneB) {
                    if (option1 < 0.0f) {
                      h = snellBinarySearch(origin, dir, searchTexSilhouette, s, zNearest, zFarthest);
                    } else {
                      h = snellBinarySearch(origin, dir, searchTexSilhouette, s, zNearest, zFarthest, int(option1));
                    }
                  } else {
                    if (option1 < 0.0f) {
                      h = snellBinarySearch(origin, dir, searchTexSphere, s, zNearest, zFarthest);
                    } else {
                      h = snellBinarySearch(origin, dir, searchTexSphere, s, zNearest, zFarthest, int(option1));
                    }
                  }
                  SEARCH_PARITY_SET_HIT(h);)
// option1 = steps, option2 = lo, option3 = hi; the hit so far is a miss (its uv
// and position mark "not moved").
SNELL_PARITY_CASE(snellBisectTexRay, bisectInputs,
                  SEARCH_RAY_IN,
                  SEARCH_HIT_OUT,
                  sampling(),
                  SnellDepthSurface s = searchParitySurface(sceneB, entries);
                  SnellTexRay r = snellSearchSegment(origin, dir, zNearest, zFarthest, s.clipFromView);
                  SnellHit h = snellHitMiss(0);
                  if (r.valid) {
                    if (sceneB) {
                      h = snellBisectTexRay(r, searchTexSilhouette, s, option2, option3, int(option1), h);
                    } else {
                      h = snellBisectTexRay(r, searchTexSphere, s, option2, option3, int(option1), h);
                    }
                  }
                  SEARCH_PARITY_SET_HIT(h);)
// option1 = linearSteps, option2 = binarySteps.
SNELL_PARITY_CASE(snellLinearBinarySearch, [] { return rayInputs(Kind::LinearSearch, 44); },
                  SEARCH_RAY_IN,
                  SEARCH_HIT_OUT,
                  sampling(),
                  SnellDepthSurface s = searchParitySurface(sceneB, entries);
                  SnellHit h;  // no ?: on structs: WebGL rejects it
                  if (sceneB) {
                    if (option1 < 0.0f) {
                      h = snellLinearBinarySearch(origin, dir, searchTexSilhouette, s, zNearest, zFarthest);
                    } else {
                      h = snellLinearBinarySearch(origin, dir, searchTexSilhouette, s, zNearest, zFarthest, int(option1), int(option2));
                    }
                  } else {
                    if (option1 < 0.0f) {
                      h = snellLinearBinarySearch(origin, dir, searchTexSphere, s, zNearest, zFarthest);
                    } else {
                      h = snellLinearBinarySearch(origin, dir, searchTexSphere, s, zNearest, zFarthest, int(option1), int(option2));
                    }
                  }
                  SEARCH_PARITY_SET_HIT(h);)
// option1 = steps, option2 = refineSteps, option3 = maxDistance.
SNELL_PARITY_CASE(snellLinearMarch, [] { return rayInputs(Kind::LinearMarch, 45); },
                  SEARCH_RAY_IN,
                  SEARCH_HIT_OUT,
                  sampling(),
                  SnellDepthSurface s = searchParitySurface(sceneB, entries);
                  SnellHit h;  // no ?: on structs: WebGL rejects it
                  if (sceneB) {
                    if (option1 < 0.0f) {
                      h = snellLinearMarch(origin, dir, searchTexSilhouette, s);
                    } else {
                      h = snellLinearMarch(origin, dir, searchTexSilhouette, s, option3, int(option1), int(option2));
                    }
                  } else {
                    if (option1 < 0.0f) {
                      h = snellLinearMarch(origin, dir, searchTexSphere, s);
                    } else {
                      h = snellLinearMarch(origin, dir, searchTexSphere, s, option3, int(option1), int(option2));
                    }
                  }
                  SEARCH_PARITY_SET_HIT(h);)
// option1 = steps, option2 = stride, option3 = maxDistance, zNearest = thickness.
SNELL_PARITY_CASE(snellDdaMarch, [] { return rayInputs(Kind::Dda, 46); },
                  SEARCH_RAY_IN,
                  SEARCH_HIT_OUT,
                  sampling(),
                  SnellDepthSurface s = searchParitySurface(sceneB, entries);
                  SnellHit h;  // no ?: on structs: WebGL rejects it
                  if (sceneB) {
                    if (option1 < 0.0f) {
                      h = snellDdaMarch(origin, dir, searchTexSilhouette, s);
                    } else {
                      h = snellDdaMarch(origin, dir, searchTexSilhouette, s, option3, zNearest, option2, int(option1));
                    }
                  } else {
                    if (option1 < 0.0f) {
                      h = snellDdaMarch(origin, dir, searchTexSphere, s);
                    } else {
                      h = snellDdaMarch(origin, dir, searchTexSphere, s, option3, zNearest, option2, int(option1));
                    }
                  }
                  SEARCH_PARITY_SET_HIT(h);)

}  // namespace parity_search
