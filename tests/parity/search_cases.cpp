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

#include "parity_registry.hpp"
#include "support/depth_scenes.hpp"
#include "support/search_rays.hpp"

namespace parity_search {
using namespace snell;
using snell::gpu::SnellParityOut;
Texture2D searchTexSphere, searchTexSilhouette;
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include "cases/search.glsl"
#pragma GCC diagnostic pop
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

ParityIO run(snell::gpu::SnellParityOut (*entry)(glm::vec4, glm::vec4, glm::vec4, glm::vec4), const ParityIO& in) {
  return snell::gpu::toParityIO(entry(in.v[0], in.v[1], in.v[2], in.v[3]));
}

// valid (2), fetches (3), texel x (7), texel y (8).
constexpr std::uint16_t kHitDiscrete = (1u << 2) | (1u << 3) | (1u << 7) | (1u << 8);
}  // namespace

SNELL_PARITY_CASE({"snellSearchSegment", "search.glsl", "caseSnellSearchSegment",
                   [] { return rayInputs(Kind::Segment, 41); },
                   [](const ParityIO& in) { return run(parity_search::caseSnellSearchSegment, in); }, 1u << 3, 13,
                   {1e-5f, 1e-5f}, textures(), setupTextures});
SNELL_PARITY_CASE({"snellConservativeBinarySearch", "search.glsl", "caseSnellConservativeBinarySearch",
                   [] { return rayInputs(Kind::Search, 42); },
                   [](const ParityIO& in) { return run(parity_search::caseSnellConservativeBinarySearch, in); },
                   kHitDiscrete, 9, {1e-5f, 1e-5f}, textures(), setupTextures});
SNELL_PARITY_CASE({"snellBinarySearch", "search.glsl", "caseSnellBinarySearch",
                   [] { return rayInputs(Kind::Search, 43); },
                   [](const ParityIO& in) { return run(parity_search::caseSnellBinarySearch, in); }, kHitDiscrete, 9,
                   {1e-5f, 1e-5f}, textures(), setupTextures});
// Brackets: mostly sub-intervals of [0, 1] (the linear search's steps, the whole segment), some reversed,
// outside [0, 1] or NaN (clamped / returned as given).
SNELL_PARITY_CASE({"snellBisectTexRay", "search.glsl", "caseSnellBisectTexRay",
                   [] {
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
                   },
                   [](const ParityIO& in) { return run(parity_search::caseSnellBisectTexRay, in); }, kHitDiscrete, 9,
                   {1e-5f, 1e-5f}, textures(), setupTextures});
SNELL_PARITY_CASE({"snellLinearBinarySearch", "search.glsl", "caseSnellLinearBinarySearch",
                   [] { return rayInputs(Kind::LinearSearch, 44); },
                   [](const ParityIO& in) { return run(parity_search::caseSnellLinearBinarySearch, in); },
                   kHitDiscrete, 9, {1e-5f, 1e-5f}, textures(), setupTextures});
SNELL_PARITY_CASE({"snellLinearMarch", "search.glsl", "caseSnellLinearMarch",
                   [] { return rayInputs(Kind::LinearMarch, 45); },
                   [](const ParityIO& in) { return run(parity_search::caseSnellLinearMarch, in); }, kHitDiscrete, 9,
                   {1e-5f, 1e-5f}, textures(), setupTextures});
SNELL_PARITY_CASE({"snellDdaMarch", "search.glsl", "caseSnellDdaMarch", [] { return rayInputs(Kind::Dda, 46); },
                   [](const ParityIO& in) { return run(parity_search::caseSnellDdaMarch, in); }, kHitDiscrete, 9,
                   {1e-5f, 1e-5f}, textures(), setupTextures});
