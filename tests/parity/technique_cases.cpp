// Registrations of the two-interface refraction parity cases (cases/technique.glsl):
// environment helpers, depth ranges, options and presets, the strategy dispatcher,
// the path trace, the exit slot and the full shaded technique.
//
// Textures: the technique test scene (tests/support/technique_scene.hpp) at 96x96.
// Rays: >= 12,000 per case: front-face points and normals of random pixels of the
// glass sphere (exact, double, rounded to float) with random presets, steps, IOR,
// d_N, exit modes, fallbacks, dispersion, TIR policies and roughness; 3-10% hostile.
//
// Comparison: valid flags, fetch counts, path flags EXACTLY; colours within
// 1e-4 abs; positions / directions 1e-4 abs + 1e-4 rel (searches through depth
// buffers amplify ulp differences of the projection at grazing angles).
#include <snell/depth_pyramid.hpp>
#include <snell/snell.hpp>

#include <cmath>
#include <limits>

#include "parity_registry.hpp"
#include "support/technique_scene.hpp"

namespace parity_technique {
using namespace snell;
using snell::gpu::SnellParityOut;
Texture2D techBackDepth, techBackNormal, techBackPyramid, techSceneDepth, techSceneNormal, techScenePyramid, techFrontDepth,
    techFrontNormal,
    techSceneColor, techEnv;
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include "cases/technique.glsl"
#pragma GCC diagnostic pop
}  // namespace parity_technique

namespace {
using snell_parity::InputGen;
using snell_parity::ParityIO;
using namespace parity_technique;

constexpr int kInputs = 12000;
constexpr int kSize = 96;

const technique_test::Scene& scene() {
  static const technique_test::Scene s = technique_test::makeScene(kSize, kSize);
  return s;
}

void buildTextures() {
  static bool built = false;
  if (built) return;
  built = true;
  const technique_test::Scene& s = scene();
  techBackDepth = s.back.depth;
  techBackNormal = s.backNormalMips;
  techBackPyramid = s.backPyramid;
  techSceneDepth = s.plane.depth;
  techSceneNormal = s.sceneNormalMips;
  techScenePyramid = s.scenePyramid;
  techSceneColor = s.sceneColor;
  techEnv = s.env;
  techFrontDepth = s.front.depth;  // read only by techImagePixel (tests/gpu/technique_image_test.cpp)
  techFrontNormal = s.front.normals;
}

std::vector<snell::gpu::ParityTexture> textures() {
  return {{"techBackDepth", &techBackDepth},       {"techBackNormal", &techBackNormal},
          {"techBackPyramid", &techBackPyramid},   {"techSceneDepth", &techSceneDepth},
          {"techSceneNormal", &techSceneNormal},   {"techScenePyramid", &techScenePyramid},
          {"techSceneColor", &techSceneColor},     {"techEnv", &techEnv},
          {"techFrontDepth", &techFrontDepth},     {"techFrontNormal", &techFrontNormal}};
}

ParityIO run(SnellParityOut (*entry)(glm::vec4, glm::vec4, glm::vec4, glm::vec4), const ParityIO& in) {
  buildTextures();
  return snell::gpu::toParityIO(entry(in.v[0], in.v[1], in.v[2], in.v[3]));
}

glm::vec4 matrixEntries() {
  const glm::mat4& m = scene().back.clipFromView;
  return glm::vec4(m[0][0], m[1][1], m[2][2], m[3][2]);
}

// Front-face sample of a random pixel (most hit the sphere; misses get a made-up point).
technique_test::Exact frontSample(InputGen& g, double ior) {
  for (int k = 0; k < 50; ++k) {
    const technique_test::Exact e =
        technique_test::exactTrace(scene().front, glm::dvec2(g.uniform(0.0f, 1.0f), g.uniform(0.0f, 1.0f)), ior);
    if (e.hitsSphere) return e;
  }
  return technique_test::exactTrace(scene().front, glm::dvec2(0.5, 0.45), ior);
}

std::vector<ParityIO> techniqueInputs(std::uint32_t seed) {
  buildTextures();
  InputGen g(seed);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    const float ior = g.chance(0.1f) ? g.uniform(0.6f, 0.95f) : g.uniform(1.1f, 2.0f);
    const technique_test::Exact e = frontSample(g, double(std::max(ior, 1.01f)));
    glm::vec3 p(e.p1), n(e.n1);
    if (g.chance(0.2f)) n = glm::normalize(n + 0.2f * g.unitVector());
    const float k = g.uniform(0.0f, 1.0f);
    if (k < 0.01f) p = g.hostileVector();
    else if (k < 0.02f) n = g.hostileVector();
    else if (k < 0.03f) n = glm::vec3(0.0f);
    // Every row of the technique table but the image-space bound (the linear march with 16x the steps: its
    // CPU-GPU agreement is the lab's whole-frame comparison), and techPreset's variants past the table.
    int preset = g.integer(0, SNELL_TECHNIQUE_COUNT + 4);
    if (preset == SNELL_TECHNIQUE_IMAGE_SPACE_BOUND) preset = SNELL_TECHNIQUE_COUNT + g.integer(0, 4);
    ParityIO in{};
    in.v[0] = glm::vec4(p, float(preset));
    in.v[1] = glm::vec4(n, float(g.integer(0, 8)));
    in.v[2] = matrixEntries();
    const float roughness = g.chance(0.7f) ? 0.0f : g.uniform(0.0f, 1.0f);
    in.v[3] = glm::vec4(ior, g.uniform(0.0f, 5.0f), float(g.integer(0, 255)), roughness);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> exitInputs(std::uint32_t seed) {
  std::vector<ParityIO> v = techniqueInputs(seed);
  InputGen g(seed + 1);
  for (ParityIO& in : v) {
    // Exit rays: from a back-face point of the exact path, along its T2 (or perturbed).
    const technique_test::Exact e = frontSample(g, 1.5);
    glm::vec3 o = e.tir ? glm::vec3(e.p2) : glm::vec3(e.p2), d = e.tir ? glm::vec3(e.t1) : glm::vec3(e.t2);
    if (g.chance(0.3f)) d = glm::normalize(d + 0.5f * g.unitVector());
    if (g.chance(0.02f)) o = g.hostileVector();
    in.v[0] = glm::vec4(o, in.v[0].w);
    in.v[1] = glm::vec4(d, in.v[1].w);
  }
  return v;
}

std::vector<ParityIO> dispatchInputs(std::uint32_t seed) {
  buildTextures();
  InputGen g(seed);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    const technique_test::Exact e = frontSample(g, double(g.uniform(1.1f, 2.0f)));
    const bool toScene = g.chance(0.4f) && !e.tir;
    glm::vec3 o = toScene ? glm::vec3(e.p2) : glm::vec3(e.p1), d = toScene ? glm::vec3(e.t2) : glm::vec3(e.t1);
    if (g.chance(0.05f)) d = -d;
    if (g.chance(0.02f)) o = g.hostileVector();
    ParityIO in{};
    in.v[0] = glm::vec4(o, float(g.integer(0, 9)));
    in.v[1] = glm::vec4(d, float(g.integer(0, 12)));
    in.v[2] = matrixEntries();
    in.v[3] = glm::vec4(toScene ? 1.0f : 0.0f, g.chance(0.3f) ? 1.0f : 0.0f, 0.0f, 0.0f);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> directionInputs(std::uint32_t seed, bool withLod) {
  InputGen g(seed);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    glm::vec3 d = g.unitVector() * g.uniform(0.01f, 10.0f);
    const float k = g.uniform(0.0f, 1.0f);
    if (k < 0.05f) d = g.hostileVector();
    else if (k < 0.10f) d[g.integer(0, 2)] = 0.0f;
    else if (k < 0.15f) d = glm::vec3(float(g.integer(-1, 1)), float(g.integer(-1, 1)), float(g.integer(-1, 1)));
    ParityIO in{};
    in.v[0] = glm::vec4(d, withLod ? (g.chance(0.5f) ? 0.0f : g.uniform(0.0f, 8.0f)) : 0.0f);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> atanInputs() {
  InputGen g(801);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    ParityIO in{};
    in.v[0] = glm::vec4(g.uniform(-5.0f, 5.0f), g.uniform(-5.0f, 5.0f), 0.0f, 0.0f);
    if (g.chance(0.1f)) in.v[0].x = g.hostile();
    if (g.chance(0.1f)) in.v[0].y = g.hostile();
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> smallIntInputs(std::uint32_t seed, int lo, int hi) {
  InputGen g(seed);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    ParityIO in{};
    in.v[0] = glm::vec4(float(g.integer(lo, hi)), float(g.integer(lo, hi)), 0.0f, 0.0f);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> boundsInputs() {
  InputGen g(802);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    ParityIO in{};
    in.v[0] = glm::vec4(g.uniform(-1.0f, 0.0f), g.uniform(-20.0f, 0.0f), 0.0f, 0.0f);
    v.push_back(in);
  }
  return v;
}

std::vector<ParityIO> boxInputs() {
  InputGen g(803);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    const float ang = g.uniform(0.0f, 6.28f);
    const glm::vec3 lo(g.uniform(-3.0f, 0.0f), g.uniform(-3.0f, 0.0f), g.uniform(-3.0f, 0.0f));
    ParityIO in{};
    in.v[0] = glm::vec4(g.uniform(-2.0f, 2.0f), g.uniform(-2.0f, 2.0f), g.uniform(-15.0f, 2.0f), g.uniform(0.2f, 2.0f));
    in.v[1] = glm::vec4(lo, 0.0f);
    in.v[2] = glm::vec4(lo + glm::vec3(g.uniform(0.0f, 3.0f), g.uniform(0.0f, 3.0f), g.chance(0.1f) ? 0.0f : g.uniform(0.0f, 3.0f)), 0.0f);
    in.v[3] = glm::vec4(std::cos(ang), std::sin(ang), 0.0f, 0.0f);
    if (g.chance(0.03f)) in.v[0].z = g.hostile();
    v.push_back(in);
  }
  return v;
}

constexpr snell_parity::Tolerance kExact{0.0f, 0.0f};
constexpr snell_parity::Tolerance kColor{1e-4f, 1e-4f};
// Hit: 0-1 uv, 2 valid, 3 fetches, 4-6 position.
constexpr std::uint16_t kHitDiscrete = 0x000C;
}  // namespace

#define TECH_CASE(FN, ENTRY, GEN, DISCRETE, OUTPUTS, TOL)                                                     \
  SNELL_PARITY_CASE({#FN, "technique.glsl", "case" #ENTRY, GEN,                                                \
                     [](const ParityIO& in) { return run(case##ENTRY, in); }, DISCRETE, OUTPUTS, TOL, textures(), \
                     buildTextures})

// Pure arithmetic: the cube face and flags exact, coordinates to rounding.
TECH_CASE(snellCubeFaceUv, SnellCubeFaceUv, [] { return directionInputs(804, false); }, 0x0009, 4, (snell_parity::Tolerance{1e-6f, 1e-6f}));
TECH_CASE(snellAtan2, SnellAtan2, atanInputs, 0x0000, 1, (snell_parity::Tolerance{1e-6f, 1e-6f}));
TECH_CASE(snellEquirectUv, SnellEquirectUv, [] { return directionInputs(805, false); }, 0x0000, 2, (snell_parity::Tolerance{1e-6f, 1e-6f}));
TECH_CASE(snellSampleEquirect, SnellSampleEquirect, [] { return directionInputs(806, true); }, 0x0000, 4, kColor);
TECH_CASE(snellDepthRangeInvalid, SnellDepthRangeInvalid, [] { return smallIntInputs(807, 0, 5); }, 0x000F, 4, kExact);
TECH_CASE(snellTextureTopLod, SnellTextureTopLod, [] { return smallIntInputs(808, 0, 2); }, 0x0001, 1, kExact);
TECH_CASE(snellDepthRangeFromPyramid, SnellDepthRangeFromPyramid, [] { return smallIntInputs(809, 0, 1); }, 0x0004, 3, (snell_parity::Tolerance{1e-6f, 1e-6f}));
TECH_CASE(snellDepthRangeFromBox, SnellDepthRangeFromBox, boxInputs, 0x0004, 3, (snell_parity::Tolerance{1e-5f, 1e-5f}));
TECH_CASE(snellIntersectOptions, SnellIntersectOptions, [] { return smallIntInputs(810, -1, 10); }, 0xFFFF, 16, kExact);
TECH_CASE(snellTechniqueOptions, SnellTechniqueOptions, [] { return smallIntInputs(811, 0, 1); }, 0xFFFF, 16, kExact);
TECH_CASE(snellTechniquePresetSlots, SnellTechniquePresetSlots, [] { return smallIntInputs(812, -1, 10); }, 0xFFFF, 16, kExact);
TECH_CASE(snellPresetDir, SnellPresetDir, [] { return smallIntInputs(813, 0, 1); }, 0xFFFF, 16, kExact);
TECH_CASE(snellPresetDirBounds, SnellPresetDirBounds, boundsInputs, 0xF7FF, 16, (snell_parity::Tolerance{1e-5f, 1e-5f}));
TECH_CASE(snellPresetIsr, SnellPresetIsr, [] { return smallIntInputs(814, 0, 1); }, 0xFFFF, 16, kExact);
TECH_CASE(snellPresetPlaneNormal, SnellPresetPlaneNormal, [] { return smallIntInputs(815, -2, 12); }, 0xFFFF, 16, kExact);
TECH_CASE(snellPresetPlaneDepth, SnellPresetPlaneDepth, [] { return smallIntInputs(816, -2, 12); }, 0xFFFF, 16, kExact);
TECH_CASE(snellPresetSingleSample, SnellPresetSingleSample, [] { return smallIntInputs(817, 0, 1); }, 0xFFFF, 16, kExact);
TECH_CASE(snellPresetLinearMarch, SnellPresetLinearMarch, [] { return smallIntInputs(818, 0, 1); }, 0xFFFF, 16, kExact);
TECH_CASE(snellPresetDdaMarch, SnellPresetDdaMarch, [] { return smallIntInputs(819, 0, 1); }, 0xFFFF, 16, kExact);
TECH_CASE(snellPresetImageSpaceBound, SnellPresetImageSpaceBound, [] { return smallIntInputs(825, 0, 1); }, 0xFFFF, 16, kExact);
// Every id of the technique table and a few outside it.
TECH_CASE(snellTechniquePreset, SnellTechniquePreset, [] { return smallIntInputs(824, -2, SNELL_TECHNIQUE_COUNT + 2); }, 0xFFFF, 16, kExact);
// Searches and marches through the sphere's back faces and the painting plane.
TECH_CASE(snellIntersectWith, SnellIntersectWith, [] { return dispatchInputs(820); }, kHitDiscrete, 7, (snell_parity::Tolerance{1e-4f, 1e-4f}));
// Path flags (float 11) and fetches (3) exact.
TECH_CASE(snellTwoInterfaceTrace, SnellTwoInterfaceTrace, [] { return techniqueInputs(821); }, 0x0808, 15, (snell_parity::Tolerance{1e-4f, 1e-4f}));
// Fetches (3), hit valid (6), fellBack (7) exact; colours 1e-4.
TECH_CASE(snellTwoInterfaceExit, SnellTwoInterfaceExit, [] { return exitInputs(822); }, 0x00C8, 11, (snell_parity::Tolerance{1e-4f, 1e-4f}));
// Fetches (3), flags (7) and the reflection hit (15) exact; colour, directions, points, fresnel 1e-4.
TECH_CASE(snellTwoInterfaceRefraction, SnellTwoInterfaceRefraction, [] { return techniqueInputs(823); }, 0x8088, 16, (snell_parity::Tolerance{1e-4f, 1e-4f}));
