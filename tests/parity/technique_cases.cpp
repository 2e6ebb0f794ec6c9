// The two-interface refraction parity and property cases (see parity_case.hpp):
// environment helpers, depth ranges, options and presets, the strategy dispatcher,
// the path trace, the exit slot and the full shaded technique. cases/technique.glsl
// holds the textures, the ray cases' technique, material and view (techTechnique, techMaterial, techView), the options cases'
// packing (TECH_OPTIONS_OUT) and techImagePixel (tests/gpu/technique_image_test.cpp).
//
// Textures: the technique test scene (tests/support/technique_scene.hpp) at 96x96;
// every case binds them all.
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

#include "parity_case.hpp"
#include "support/technique_scene.hpp"

namespace parity_technique {
using namespace snell;
Texture2D techBackDepth, techBackNormal, techBackPyramid, techSceneDepth, techSceneNormal, techScenePyramid, techFrontDepth,
    techFrontNormal,
    techSceneColor, techEnv;
#include "cases/technique.glsl"
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
  techFrontDepth = s.front.depth;  // the object's front layer, and techImagePixel's front-face buffers
  techFrontNormal = s.front.normals;
}

std::vector<snell::gpu::ParityTexture> textures() {
  return {{"techBackDepth", &techBackDepth},       {"techBackNormal", &techBackNormal},
          {"techBackPyramid", &techBackPyramid},   {"techSceneDepth", &techSceneDepth},
          {"techSceneNormal", &techSceneNormal},   {"techScenePyramid", &techScenePyramid},
          {"techSceneColor", &techSceneColor},     {"techEnv", &techEnv},
          {"techFrontDepth", &techFrontDepth},     {"techFrontNormal", &techFrontNormal}};
}

// Every case: the scene's textures, built before the generator and the C++ build run.
snell_parity::CaseExtras techExtras() { return snell_parity::CaseExtras().sampling(textures(), buildTextures); }

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
    // Every row of the technique table but the image-space bounds (the linear march with 16x the steps: their
    // CPU-GPU agreement is the lab's whole-frame comparison), and techPreset's variants past the table.
    int preset = g.integer(0, SNELL_TECHNIQUE_COUNT + 4);
    if (preset == SNELL_TECHNIQUE_IMAGE_SPACE_BOUND || preset == SNELL_TECHNIQUE_IMAGE_SPACE_BOUND_BOUNCES)
      preset = SNELL_TECHNIQUE_COUNT + g.integer(0, 4);
    ParityIO in{};
    in.v[0] = glm::vec4(p, float(preset));
    in.v[1] = glm::vec4(n, float(g.integer(0, 8)));
    in.v[2] = matrixEntries();
    const float roughness = g.chance(0.7f) ? 0.0f : g.uniform(0.0f, 1.0f);
    in.v[3] = glm::vec4(ior, g.uniform(0.0f, 5.0f), float(g.integer(0, 2047)), roughness);
    v.push_back(in);
  }
  return v;
}

// The engine models' fragments: front-face samples of the sphere (a tenth with a tilted normal, a few hostile),
// every model and one outside the table, a thickness around the sphere's size (a few negative or hostile), the
// proxy box around sphere and painting, Godot's scale.
std::vector<ParityIO> engineInputs(std::uint32_t seed) {
  buildTextures();
  InputGen g(seed);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    const float ior = g.chance(0.1f) ? g.uniform(0.6f, 0.95f) : g.uniform(1.1f, 2.0f);
    const technique_test::Exact e = frontSample(g, double(std::max(ior, 1.01f)));
    glm::vec3 p(e.p1), n(e.n1);
    if (g.chance(0.1f)) n = glm::normalize(n + 0.3f * g.unitVector());
    // Within about 8 degrees of grazing, at the entry or (ior < 1) of TIR, the models divide by a cosine that
    // cancels: one rounding there moves the result by more than the tolerance. Those inputs are not compared.
    const float cosI = std::abs(glm::dot(glm::normalize(p), n));
    const float sin2T = (1.0f - cosI * cosI) / (ior * ior);
    if (cosI < 0.15f || (sin2T < 1.0f && 1.0f - sin2T < 0.0225f)) {
      --i;
      continue;
    }
    const float k = g.uniform(0.0f, 1.0f);
    if (k < 0.01f) p = g.hostileVector();
    else if (k < 0.02f) n = g.hostileVector();
    else if (k < 0.03f) n = glm::vec3(0.0f);
    float parameter = g.uniform(0.0f, 4.5f);
    if (g.chance(0.03f)) parameter = -g.uniform(0.0f, 1.0f);
    if (g.chance(0.02f)) parameter = g.hostile();
    float scale = g.uniform(-0.3f, 0.3f);
    if (g.chance(0.02f)) scale = g.hostile();
    ParityIO in{};
    in.v[0] = glm::vec4(p, float(g.integer(-1, SNELL_ENGINE_MODEL_COUNT)));
    in.v[1] = glm::vec4(n, parameter);
    in.v[2] = matrixEntries();
    in.v[3] = glm::vec4(ior, g.uniform(6.0f, 12.0f), g.uniform(-9.0f, -5.0f), scale);
    v.push_back(in);
  }
  return v;
}

// Points to project (some behind the camera, some hostile) with a direction and a distance.
std::vector<ParityIO> seePointInputs(std::uint32_t seed) {
  InputGen g(seed);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    glm::vec3 x(g.uniform(-6.0f, 6.0f), g.uniform(-6.0f, 6.0f), g.uniform(-30.0f, 2.0f));
    if (g.chance(0.03f)) x = g.hostileVector();
    glm::vec3 d = g.unitVector() * g.uniform(0.1f, 10.0f);
    if (g.chance(0.03f)) d = g.chance(0.5f) ? glm::vec3(0.0f) : g.hostileVector();
    ParityIO in{};
    in.v[0] = glm::vec4(x, g.uniform(0.0f, 5.0f));
    in.v[1] = glm::vec4(d, 0.0f);
    in.v[2] = matrixEntries();
    v.push_back(in);
  }
  return v;
}

// Proxy exits and lookups: an origin near the sphere (a few outside the box or hostile), any direction, the
// front point p the halo test compares with.
std::vector<ParityIO> proxyInputs(std::uint32_t seed) {
  std::vector<ParityIO> v = engineInputs(seed);
  InputGen g(seed + 1);
  for (ParityIO& in : v) {
    glm::vec3 o = glm::vec3(0.3f, -0.2f, -6.0f) + g.unitVector() * g.uniform(0.0f, 3.0f);
    if (g.chance(0.05f)) o = glm::vec3(g.uniform(-40.0f, 40.0f), g.uniform(-40.0f, 40.0f), g.uniform(-40.0f, 10.0f));
    if (g.chance(0.02f)) o = g.hostileVector();
    glm::vec3 d = g.unitVector() * g.uniform(0.5f, 2.0f);
    if (g.chance(0.03f)) d = g.chance(0.5f) ? glm::vec3(0.0f) : g.hostileVector();
    if (g.chance(0.05f)) d[g.integer(0, 2)] = 0.0f;
    in.v[0] = glm::vec4(o, g.uniform(0.0f, 3.0f));  // origin, distance
    in.v[1] = glm::vec4(d, 0.0f);
    in.v[3].w = g.uniform(0.5f, 1.0f);  // p = origin * this: a front point on the origin's view ray
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

// Rays inside the glass sphere (between its front and back layers), in every direction, with the march's
// counts and distance; 1-2 % hostile origins, directions, distances and counts.
std::vector<ParityIO> insideInputs(std::uint32_t seed) {
  buildTextures();
  InputGen g(seed);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    glm::vec3 o = glm::vec3(technique_test::kCentre) +
                  float(technique_test::kRadius) * g.uniform(0.0f, 0.97f) * g.unitVector();
    glm::vec3 d = g.unitVector();
    float maxDistance = g.uniform(0.5f, 6.0f);
    int steps = g.integer(1, 48);
    const int refine = g.integer(0, 10);
    const float k = g.uniform(0.0f, 1.0f);
    if (k < 0.01f) o = g.hostileVector();
    else if (k < 0.02f) d = g.hostileVector();
    else if (k < 0.03f) d = glm::vec3(0.0f);
    else if (k < 0.04f) maxDistance = g.hostile();
    else if (k < 0.05f) steps = g.integer(-3, 2000);
    ParityIO in{};
    in.v[0] = glm::vec4(o, maxDistance);
    in.v[1] = glm::vec4(d, float(steps));
    in.v[2] = glm::vec4(float(refine), 0.0f, 0.0f, 0.0f);
    in.v[3] = matrixEntries();
    v.push_back(in);
  }
  return v;
}

// Points in front of, inside and behind the sphere at random uv (the layers read there).
std::vector<ParityIO> insideSideInputs(std::uint32_t seed) {
  buildTextures();
  InputGen g(seed);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    ParityIO in{};
    glm::vec3 p(g.uniform(-3.0f, 3.0f), g.uniform(-3.0f, 3.0f), g.uniform(-10.0f, -2.0f));
    if (g.chance(0.02f)) p = g.hostileVector();
    in.v[0] = glm::vec4(p, g.uniform(-1.0f, 1.0f));
    in.v[1] = glm::vec4(g.uniform(-0.05f, 1.05f), g.uniform(-0.05f, 1.05f), 0.0f, 0.0f);
    in.v[3] = matrixEntries();
    v.push_back(in);
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
    in.v[0] = glm::vec4(o, float(g.integer(0, SNELL_STRATEGY_COUNT + 1)));  // every strategy and two ids past them
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
}  // namespace

namespace parity_technique {
#define SNELL_PARITY_FILE "technique.glsl"

// The options cases' 16 floats (TECH_OPTIONS_OUT in cases/technique.glsl): per slot the strategy, the counts
// (techPackCounts) and the flags, then tirPolicy, ior, dispersion, reflection and four sums (techOptionSums).
// All exact.
#define TECH_OPTIONS_EXACT                                                                                         \
  (int, backStrategy, 0, exact)(vec2, backCounts, 1, exact)(float, backFlags, 3, exact)                            \
  (int, exitStrategy, 4, exact)(vec2, exitCounts, 5, exact)(float, exitFlags, 7, exact)                            \
  (int, tirPolicy, 8, exact)(float, ior, 9, exact)(int, dispersion, 10, exact)(bool, reflection, 11, exact)        \
  (vec4, sums, 12, exact)

// The ray cases' inputs after the ray (floats 0-2, 4-6): the technique (techPreset), its steps, the
// projection's entries, the IOR, d_N, the mode bits (techTechnique, techMaterial) and the roughness.
#define TECH_RAY_INPUTS(ORIGIN, DIRECTION)                                                                           \
  (vec3, ORIGIN, 0)(int, preset, 3)(vec3, DIRECTION, 4)(int, steps, 7)(vec4, projection, 8)(float, ior, 12)         \
  (float, dN, 13)(int, modes, 14)(float, roughness, 15)

// Pure arithmetic: the cube face and flags exact, coordinates to rounding.
SNELL_PARITY_CASE(snellCubeFaceUv, [] { return directionInputs(804, false); },
                  (vec3, direction, 0),
                  (int, face, 0, exact)(vec2, uv, 1, within(1e-6f, 1e-6f))(bool, valid, 3, exact),
                  techExtras(),
                  SnellCubeFace f = snellCubeFaceUv(direction);
                  face = f.face;
                  uv = f.uv;
                  valid = f.valid;)

SNELL_PARITY_CASE(snellAtan2, atanInputs,
                  (float, y, 0)(float, x, 1),
                  (float, angle, 0, within(1e-6f, 1e-6f)),
                  techExtras(),
                  angle = snellAtan2(y, x);)

SNELL_PARITY_CASE(snellEquirectUv, [] { return directionInputs(805, false); },
                  (vec3, direction, 0),
                  (vec2, uv, 0, within(1e-6f, 1e-6f)),
                  techExtras(),
                  uv = snellEquirectUv(direction);)

SNELL_PARITY_CASE(snellSampleEquirect, [] { return directionInputs(806, true); },
                  (vec3, direction, 0)(float, lod, 3),
                  (vec4, color, 0, within(1e-4f, 1e-4f)),
                  techExtras(),
                  color = snellSampleEquirect(techEnv, direction, lod);)

// The function takes nothing; the case echoes its input a.x in output 3.
SNELL_PARITY_CASE(snellDepthRangeInvalid, [] { return smallIntInputs(807, 0, 5); },
                  (float, echoIn, 0),
                  (float, zNearest, 0, exact)(float, zFarthest, 1, exact)(bool, valid, 2, exact)
                  (float, echoOut, 3, exact),
                  techExtras().passThrough({"echoIn"}, {"echoOut"},
                                           "the case echoes its input a.x in output 3 (not the function's)"),
                  SnellDepthRange r = snellDepthRangeInvalid();
                  zNearest = r.zNearest;
                  zFarthest = r.zFarthest;
                  valid = r.valid;
                  echoOut = echoIn;)

// which: 0 the back pyramid, 1 the environment, 2 the scene colour.
SNELL_PARITY_CASE(snellTextureTopLod, [] { return smallIntInputs(808, 0, 2); },
                  (int, which, 0),
                  (int, lod, 0, exact),
                  techExtras(),
                  lod = which == 0 ? snellTextureTopLod(techBackPyramid)
                                   : (which == 1 ? snellTextureTopLod(techEnv) : snellTextureTopLod(techSceneColor));)

SNELL_PARITY_CASE(snellDepthRangeFromPyramid, [] { return smallIntInputs(809, 0, 1); },
                  (bool, toScene, 0),
                  (float, zNearest, 0, within(1e-6f, 1e-6f))(float, zFarthest, 1, within(1e-6f, 1e-6f))
                  (bool, valid, 2, exact),
                  techExtras(),
                  SnellDepthRange r;  // no ?: on structs: WebGL rejects it
                  if (toScene) {
                    r = snellDepthRangeFromPyramid(techScenePyramid);
                  } else {
                    r = snellDepthRangeFromPyramid(techBackPyramid);
                  }
                  zNearest = r.zNearest;
                  zFarthest = r.zFarthest;
                  valid = r.valid;)

// A box seen through a rotation about z by (cos, sin), a scale and a translation.
SNELL_PARITY_CASE(snellDepthRangeFromBox, boxInputs,
                  (vec3, translation, 0)(float, scale, 3)(vec3, boxMin, 4)(vec3, boxMax, 8)(vec2, rotation, 12),
                  (float, zNearest, 0, within(1e-5f, 1e-5f))(float, zFarthest, 1, within(1e-5f, 1e-5f))
                  (bool, valid, 2, exact),
                  techExtras(),
                  mat4 m = SNELL_CAMERA_MAT4_COLUMNS(vec4(scale * rotation.x, scale * rotation.y, 0.0f, 0.0f),
                                                     vec4(-scale * rotation.y, scale * rotation.x, 0.0f, 0.0f),
                                                     vec4(0.0f, 0.0f, scale, 0.0f),
                                                     vec4(translation.x, translation.y, translation.z, 1.0f));
                  SnellDepthRange r = snellDepthRangeFromBox(m, boxMin, boxMax);
                  zNearest = r.zNearest;
                  zFarthest = r.zFarthest;
                  valid = r.valid;)

// The options and presets, packed by TECH_OPTIONS_OUT: every count, flag and setting exact.
SNELL_PARITY_CASE(snellIntersectOptions, [] { return smallIntInputs(810, -1, 10); },
                  (int, strategy, 0),
                  TECH_OPTIONS_EXACT,
                  techExtras(),
                  SnellTechnique t = snellTechnique();
                  t.back.intersect = snellIntersectOptions(strategy);
                  TECH_OPTIONS_OUT(t, snellMaterial(), snellView()))

// The three defaults together: their outputs are the single options struct's before the split.
SNELL_PARITY_CASE(snellTechnique, [] { return smallIntInputs(811, 0, 1); },
                  /* no inputs */,
                  TECH_OPTIONS_EXACT,
                  techExtras(),
                  TECH_OPTIONS_OUT(snellTechnique(), snellMaterial(), snellView()))

SNELL_PARITY_CASE(snellMaterial, [] { return smallIntInputs(826, 0, 1); },
                  /* no inputs */,
                  TECH_OPTIONS_EXACT,
                  techExtras(),
                  SnellMaterial m = snellMaterial();
                  TECH_OPTIONS_OUT(snellTechnique(), m, snellView()))

SNELL_PARITY_CASE(snellView, [] { return smallIntInputs(827, 0, 1); },
                  /* no inputs */,
                  TECH_OPTIONS_EXACT,
                  techExtras(),
                  SnellView v = snellView();
                  TECH_OPTIONS_OUT(snellTechnique(), snellMaterial(), v))

// A slot from its source and strategy, in the exit slot (flags: source and fallback) and the back slot.
SNELL_PARITY_CASE(snellSlot, [] { return smallIntInputs(828, -1, 10); },
                  (int, source, 0)(int, strategy, 1),
                  TECH_OPTIONS_EXACT,
                  techExtras(),
                  SnellTechnique t = snellTechnique();
                  t.exit = snellSlot(source, strategy);
                  t.back = snellSlot(source, strategy);
                  TECH_OPTIONS_OUT(t, snellMaterial(), snellView()))

SNELL_PARITY_CASE(snellTechniquePresetSlots, [] { return smallIntInputs(812, -1, 10); },
                  (int, backSlot, 0)(int, exitSlot, 1),
                  TECH_OPTIONS_EXACT,
                  techExtras(),
                  SnellTechnique t = snellTechniquePresetSlots(backSlot, exitSlot);
                  TECH_OPTIONS_OUT(t, snellMaterial(), snellView()))

SNELL_PARITY_CASE(snellPresetDir, [] { return smallIntInputs(813, 0, 1); },
                  /* no inputs */,
                  TECH_OPTIONS_EXACT,
                  techExtras(),
                  SnellTechnique t = snellPresetDir();
                  TECH_OPTIONS_OUT(t, snellMaterial(), snellView()))

// Every float exact (the old mask compared the `reflection` flag, float 11, within 1e-5: a slip, a flag
// is 0 or 1).
SNELL_PARITY_CASE(snellPresetDirBounds, boundsInputs,
                  (float, zNearest, 0)(float, zFarthest, 1),
                  TECH_OPTIONS_EXACT,
                  techExtras().passThrough({"zNearest", "zFarthest"}, {"sums.x", "sums.y"},
                                           "a preset constructor: stores the bounds it is given (outputs 12-13)"),
                  SnellTechnique t = snellPresetDirBounds(zNearest, zFarthest);
                  TECH_OPTIONS_OUT(t, snellMaterial(), snellView()))

SNELL_PARITY_CASE(snellPresetIsr, [] { return smallIntInputs(814, 0, 1); },
                  /* no inputs */,
                  TECH_OPTIONS_EXACT,
                  techExtras(),
                  SnellTechnique t = snellPresetIsr();
                  TECH_OPTIONS_OUT(t, snellMaterial(), snellView()))

SNELL_PARITY_CASE(snellPresetPlaneNormal, [] { return smallIntInputs(815, -2, 12); },
                  (int, iterations, 0),
                  TECH_OPTIONS_EXACT,
                  techExtras(),
                  SnellTechnique t = snellPresetPlaneNormal(iterations);
                  TECH_OPTIONS_OUT(t, snellMaterial(), snellView()))

SNELL_PARITY_CASE(snellPresetPlaneDepth, [] { return smallIntInputs(816, -2, 12); },
                  (int, iterations, 0),
                  TECH_OPTIONS_EXACT,
                  techExtras(),
                  SnellTechnique t = snellPresetPlaneDepth(iterations);
                  TECH_OPTIONS_OUT(t, snellMaterial(), snellView()))

SNELL_PARITY_CASE(snellPresetSingleSample, [] { return smallIntInputs(817, 0, 1); },
                  /* no inputs */,
                  TECH_OPTIONS_EXACT,
                  techExtras(),
                  SnellTechnique t = snellPresetSingleSample();
                  TECH_OPTIONS_OUT(t, snellMaterial(), snellView()))

SNELL_PARITY_CASE(snellPresetLinearMarch, [] { return smallIntInputs(818, 0, 1); },
                  /* no inputs */,
                  TECH_OPTIONS_EXACT,
                  techExtras(),
                  SnellTechnique t = snellPresetLinearMarch();
                  TECH_OPTIONS_OUT(t, snellMaterial(), snellView()))

// The presets that bounce inside: the bounce count, the inside slot (source, strategy, counts, range) and the
// back and exit strategies, exact (TECH_BOUNCE_OUT in cases/technique.glsl).
#define TECH_BOUNCE_EXACT                                                                                          \
  (int, bounces, 0, exact)(int, insideSource, 1, exact)(int, insideStrategy, 2, exact)(vec2, insideCounts, 3, exact) \
  (float, insideMaxDistance, 5, exact)(int, backStrategy, 6, exact)(vec2, backCounts, 7, exact)                    \
  (int, exitStrategy, 9, exact)

SNELL_PARITY_CASE(snellPresetPlaneNormalBounces, [] { return smallIntInputs(831, -2, 12); },
                  (int, iterations, 0),
                  TECH_BOUNCE_EXACT,
                  techExtras(),
                  SnellTechnique t = snellPresetPlaneNormalBounces(iterations);
                  TECH_BOUNCE_OUT(t))

SNELL_PARITY_CASE(snellPresetLinearMarchBounces, [] { return smallIntInputs(832, 0, 1); },
                  /* no inputs */,
                  TECH_BOUNCE_EXACT,
                  techExtras(),
                  SnellTechnique t = snellPresetLinearMarchBounces();
                  TECH_BOUNCE_OUT(t))

SNELL_PARITY_CASE(snellPresetDdaMarch, [] { return smallIntInputs(819, 0, 1); },
                  /* no inputs */,
                  TECH_OPTIONS_EXACT,
                  techExtras(),
                  SnellTechnique t = snellPresetDdaMarch();
                  TECH_OPTIONS_OUT(t, snellMaterial(), snellView()))

SNELL_PARITY_CASE(snellPresetImageSpaceBound, [] { return smallIntInputs(825, 0, 1); },
                  /* no inputs */,
                  TECH_OPTIONS_EXACT,
                  techExtras(),
                  SnellTechnique t = snellPresetImageSpaceBound();
                  TECH_OPTIONS_OUT(t, snellMaterial(), snellView()))

SNELL_PARITY_CASE(snellPresetImageSpaceBoundBounces, [] { return smallIntInputs(835, 0, 1); },
                  /* no inputs */,
                  TECH_BOUNCE_EXACT,
                  techExtras(),
                  SnellTechnique t = snellPresetImageSpaceBoundBounces();
                  TECH_BOUNCE_OUT(t))

// Every id of the technique table and a few outside it.
SNELL_PARITY_CASE(snellTechniquePreset, [] { return smallIntInputs(824, -2, SNELL_TECHNIQUE_COUNT + 2); },
                  (int, id, 0),
                  TECH_OPTIONS_EXACT,
                  techExtras(),
                  SnellTechnique t = snellTechniquePreset(id);
                  TECH_OPTIONS_OUT(t, snellMaterial(), snellView()))

// Searches and marches through the sphere's back faces and the painting plane: the strategy, its main count
// (iterations, steps, linear steps), to the scene or the back faces, an explicit range or the pyramid's.
SNELL_PARITY_CASE(snellIntersectWith, [] { return dispatchInputs(820); },
                  (vec3, origin, 0)(int, strategy, 3)(vec3, direction, 4)(int, count, 7)(vec4, projection, 8)
                  (bool, toScene, 12)(bool, explicitRange, 13),
                  (vec2, uv, 0, within(1e-4f, 1e-4f))(bool, valid, 2, exact)(int, fetches, 3, exact)
                  (vec3, position, 4, within(1e-4f, 1e-4f)),
                  techExtras(),
                  SnellIntersectOptions o = snellIntersectOptions(strategy);
                  o.planeIterations = count;
                  o.cbsSteps = count;
                  if (o.strategy == SNELL_STRATEGY_BINARY) {
                    o.binarySteps = count;
                  }
                  o.linearSteps = count;
                  o.marchSteps = count;
                  o.ddaSteps = count;
                  if (explicitRange) {
                    o.rangeSource = SNELL_RANGE_EXPLICIT;
                    o.range.zNearest = -3.8f;
                    o.range.zFarthest = -12.0f;
                    o.range.valid = true;
                  }
                  SnellHit h;
                  if (toScene) {
                    h = snellIntersectWith(origin, direction, techSceneDepth, techSceneNormal, techScenePyramid,
                                           techSceneSurface(projection), o);
                  } else {
                    h = snellIntersectWith(origin, direction, techBackDepth, techBackNormal, techBackPyramid,
                                           techBackSurface(projection), o);
                  }
                  uv = h.uv;
                  valid = h.valid;
                  fetches = h.fetches;
                  position = h.position;)

// Path flags and fetches exact. flags: hit + 2 tir + 4 fellBack + 8 valid + 16 exitFront + 32 bounces.
SNELL_PARITY_CASE(snellTwoInterfaceTrace, [] { return techniqueInputs(821); },
                  TECH_RAY_INPUTS(entryPoint, entryNormal),
                  (vec3, exitDirection, 0, within(1e-4f, 1e-4f))(int, fetches, 3, exact)
                  (vec3, exitPoint, 4, within(1e-4f, 1e-4f))(float, pathLength, 7, within(1e-4f, 1e-4f))
                  (vec3, exitNormal, 8, within(1e-4f, 1e-4f))(float, flags, 11, exact)
                  (vec2, exitUv, 12, within(1e-4f, 1e-4f))(float, entryDirectionZ, 14, within(1e-4f, 1e-4f)),
                  techExtras(),
                  SnellTechnique t = techTechnique(preset, steps, modes);
                  SnellMaterial m = techMaterial(ior, modes, roughness);
                  SnellTwoInterfacePath p = snellTwoInterfaceTrace(entryPoint, entryNormal, snellIorToEta(1.0f, m.ior),
                                                                   dN, TECH_OBJECT_TEXTURES(projection), t, m.tirPolicy);
                  exitDirection = p.exitDirection;
                  fetches = p.fetches;
                  exitPoint = p.exitPoint;
                  pathLength = p.pathLength;
                  exitNormal = p.exitNormal;
                  flags = techFlag(p.hit) + 2.0f * techFlag(p.tir) + 4.0f * techFlag(p.fellBack) +
                          8.0f * techFlag(p.valid) + 16.0f * techFlag(p.exitFront) + 32.0f * float(p.bounces);
                  exitUv = p.exitUv;
                  entryDirectionZ = p.entryDirection.z;)

// Rays inside the object: the hit's flags and fetches exact, position and uv 1e-4 (the bisection's last step
// on a grazing ray moves with the GPU's rounding, as snellTwoInterfaceTrace's).
SNELL_PARITY_CASE(snellInsideMarch, [] { return insideInputs(829); },
                  (vec3, origin, 0)(float, maxDistance, 3)(vec3, dir, 4)(int, steps, 7)(int, refineSteps, 8)
                  (vec4, projection, 12),
                  (vec3, position, 0, within(1e-4f, 1e-4f))(int, fetches, 3, exact)(vec2, uv, 4, within(1e-4f, 1e-4f))
                  (bool, valid, 6, exact)(bool, front, 7, exact),
                  techExtras(),
                  SnellInsideHit h = snellInsideMarch(origin, dir, techBackDepth, techBackSurface(projection),
                                                      techFrontDepth, techFrontSurface(projection), maxDistance, steps,
                                                      refineSteps);
                  position = h.hit.position;
                  fetches = h.hit.fetches;
                  uv = h.hit.uv;
                  valid = h.hit.valid;
                  front = h.front;)

// The march alone: lo and hi are sample positions (i dt, or a halving's), exact but for rounding.
SNELL_PARITY_CASE(snellInsideBracket, [] { return insideInputs(833); },
                  (vec3, origin, 0)(float, maxDistance, 3)(vec3, dir, 4)(int, steps, 7)(vec4, projection, 12),
                  (float, lo, 0, within(1e-5f, 1e-5f))(float, hi, 1, within(1e-5f, 1e-5f))(int, side, 2, exact)
                  (int, fetches, 3, exact)(vec2, uv, 4, within(1e-5f, 1e-5f))(bool, valid, 6, exact)
                  (vec2, loUv, 8, within(1e-5f, 1e-5f)),
                  techExtras(),
                  SnellInsideBracket b = snellInsideBracket(origin, dir, techBackDepth, techBackSurface(projection),
                                                            techFrontDepth, techFrontSurface(projection), maxDistance,
                                                            steps);
                  lo = b.lo;
                  hi = b.hi;
                  side = b.side;
                  fetches = b.fetches;
                  uv = b.uv;
                  valid = b.valid;
                  loUv = b.loUv;)

// The normal plane after the march (iterations: the march case's refine count, past the clamp too).
SNELL_PARITY_CASE(snellInsidePlane, [] { return insideInputs(834); },
                  (vec3, origin, 0)(float, maxDistance, 3)(vec3, dir, 4)(int, steps, 7)(int, iterations, 8)
                  (vec4, projection, 12),
                  (vec3, position, 0, within(1e-4f, 1e-4f))(int, fetches, 3, exact)(vec2, uv, 4, within(1e-4f, 1e-4f))
                  (bool, valid, 6, exact)(bool, front, 7, exact),
                  techExtras(),
                  SnellInsideHit h = snellInsidePlane(origin, dir, techBackDepth, techBackNormal,
                                                      techBackSurface(projection), techFrontDepth, techFrontNormal,
                                                      techFrontSurface(projection), maxDistance, steps, iterations);
                  position = h.hit.position;
                  fetches = h.hit.fetches;
                  uv = h.hit.uv;
                  valid = h.hit.valid;
                  front = h.front;)

SNELL_PARITY_CASE(snellInsideSide, [] { return insideSideInputs(830); },
                  (vec3, at, 0)(float, dirZ, 3)(vec2, uv, 4)(vec4, projection, 12),
                  (int, side, 0, exact),
                  techExtras(),
                  side = snellInsideSide(at, uv, techBackDepth, techBackSurface(projection), techFrontDepth,
                                         techFrontSurface(projection), dirZ);)

// Exit rays from back-face points (d_N unused). Fetches, hit valid, fellBack exact; colours 1e-4.
SNELL_PARITY_CASE(snellTwoInterfaceExit, [] { return exitInputs(822); },
                  TECH_RAY_INPUTS(origin, direction),
                  (vec3, color, 0, within(1e-4f, 1e-4f))(int, fetches, 3, exact)(vec2, hitUv, 4, within(1e-4f, 1e-4f))
                  (bool, hitValid, 6, exact)(bool, fellBack, 7, exact)(vec3, hitPosition, 8, within(1e-4f, 1e-4f)),
                  techExtras(),
                  SnellTechnique t = techTechnique(preset, steps, modes);
                  SnellTwoInterfaceExit e = snellTwoInterfaceExit(origin, direction, techSceneDepth, techSceneNormal,
                                                                  techScenePyramid, techSceneColor,
                                                                  techSceneSurface(projection), techEnv, t.exit,
                                                                  techMaterial(ior, modes, roughness), techView());
                  color = e.color;
                  fetches = e.fetches;
                  hitUv = e.hit.uv;
                  hitValid = e.hit.valid;
                  fellBack = e.fellBack;
                  hitPosition = e.hit.position;)

// Fetches, flags and the reflection hit exact; colour, directions, points, fresnel 1e-4. flags: backHit +
// 2 fellBack + 4 tir + 8 exit hit valid.
SNELL_PARITY_CASE(snellTwoInterfaceRefraction, [] { return techniqueInputs(823); },
                  TECH_RAY_INPUTS(entryPoint, entryNormal),
                  (vec3, color, 0, within(1e-4f, 1e-4f))(int, fetches, 3, exact)
                  (vec3, exitDirection, 4, within(1e-4f, 1e-4f))(float, flags, 7, exact)
                  (vec3, exitPoint, 8, within(1e-4f, 1e-4f))(float, pathLength, 11, within(1e-4f, 1e-4f))
                  (vec2, exitUv, 12, within(1e-4f, 1e-4f))(float, fresnel, 14, within(1e-4f, 1e-4f))
                  (bool, reflectionHit, 15, exact),
                  techExtras(),
                  SnellTwoInterfaceResult t = snellTwoInterfaceRefraction(
                      entryPoint, entryNormal, dN, TECH_OBJECT_TEXTURES(projection), TECH_SCENE_TEXTURES(projection),
                      techTechnique(preset, steps, modes),
                      techMaterial(ior, modes, roughness), techView());
                  color = t.color;
                  fetches = t.fetches;
                  exitDirection = t.exitDirection;
                  flags = techFlag(t.backHit) + 2.0f * techFlag(t.fellBack) + 4.0f * techFlag(t.tir) +
                          8.0f * techFlag(t.exitHit.valid);
                  exitPoint = t.exitPoint;
                  pathLength = t.pathLength;
                  exitUv = t.exitHit.uv;
                  fresnel = t.fresnel;
                  reflectionHit = t.reflectionHit.valid;)


// The engines' models (shade/engine_models/): uv, weight, direction and distance 1e-4, valid exact. The textures
// are the sphere scene's: its painting's depth for HDRP's halo test and Godot's guard.
#define TECH_ENGINE_INPUTS                                                                                      \
  (vec3, p, 0)(int, model, 3)(vec3, n, 4)(float, parameter, 7)(vec4, projection, 8)(float, ior, 12)            \
  (float, proxyHalf, 13)(float, proxyZ, 14)(float, scale, 15)
#define TECH_ENGINE_OUTPUTS                                                                                     \
  (vec2, uv, 0, within(1e-4f, 1e-4f))(float, weight, 2, within(1e-4f, 1e-4f))(bool, valid, 3, exact)           \
  (vec3, direction, 4, within(1e-4f, 1e-4f))(float, distance, 7, within(1e-4f, 1e-4f))

SNELL_PARITY_CASE(snellEngineRefraction, [] { return engineInputs(840); }, TECH_ENGINE_INPUTS, TECH_ENGINE_OUTPUTS,
                  techExtras(),
                  SnellEngineRefraction e = snellEngineRefraction(model, p, n, 1.0f / ior,
                                                                  model == SNELL_ENGINE_GODOT ? scale : parameter,
                                                                  techProxy(proxyHalf, proxyZ), techSceneDepth,
                                                                  techSceneSurface(projection));
                  TECH_ENGINE_OUT(e))

SNELL_PARITY_CASE(snellEngineEntry, [] { return engineInputs(852); }, TECH_ENGINE_INPUTS,
                  (vec3, direction, 0, within(1e-4f, 1e-4f))(float, cosine, 3, within(1e-4f, 1e-4f))
                  (vec3, normal, 4, within(1e-5f, 1e-5f))(bool, tir, 7, exact)(bool, valid, 8, exact),
                  techExtras(),
                  SnellEngineEntry e = snellEngineEntry(p, n, 1.0f / ior);
                  direction = e.direction;
                  cosine = e.cosine;
                  normal = e.normal;
                  tir = e.tir;
                  valid = e.valid;)

SNELL_PARITY_CASE(snellEngineThreeJs, [] { return engineInputs(841); }, TECH_ENGINE_INPUTS, TECH_ENGINE_OUTPUTS,
                  techExtras(),
                  SnellEngineRefraction e = snellEngineThreeJs(p, n, 1.0f / ior, parameter, techMatrix(projection));
                  TECH_ENGINE_OUT(e))

SNELL_PARITY_CASE(snellEngineFilamentSolid, [] { return engineInputs(842); }, TECH_ENGINE_INPUTS,
                  TECH_ENGINE_OUTPUTS, techExtras(),
                  SnellEngineRefraction e = snellEngineFilamentSolid(p, n, 1.0f / ior, parameter,
                                                                     techMatrix(projection));
                  TECH_ENGINE_OUT(e))

SNELL_PARITY_CASE(snellEngineFilamentThin, [] { return engineInputs(843); }, TECH_ENGINE_INPUTS,
                  TECH_ENGINE_OUTPUTS, techExtras(),
                  SnellEngineRefraction e = snellEngineFilamentThin(p, n, 1.0f / ior, parameter * 0.2f,
                                                                    techMatrix(projection));
                  TECH_ENGINE_OUT(e))

SNELL_PARITY_CASE(snellEngineHdrpSphere, [] { return engineInputs(844); }, TECH_ENGINE_INPUTS, TECH_ENGINE_OUTPUTS,
                  techExtras(),
                  SnellEngineRefraction e = snellEngineHdrpSphere(p, n, 1.0f / ior, parameter,
                                                                  techProxy(proxyHalf, proxyZ), techSceneDepth,
                                                                  techSceneSurface(projection));
                  TECH_ENGINE_OUT(e))

SNELL_PARITY_CASE(snellEngineHdrpBox, [] { return engineInputs(845); }, TECH_ENGINE_INPUTS, TECH_ENGINE_OUTPUTS,
                  techExtras(),
                  SnellEngineRefraction e = snellEngineHdrpBox(p, n, 1.0f / ior, parameter,
                                                               techProxy(proxyHalf, proxyZ), techSceneDepth,
                                                               techSceneSurface(projection));
                  TECH_ENGINE_OUT(e))

SNELL_PARITY_CASE(snellEngineGodot, [] { return engineInputs(846); }, TECH_ENGINE_INPUTS, TECH_ENGINE_OUTPUTS,
                  techExtras(),
                  SnellEngineRefraction e = snellEngineGodot(p, n, scale, techSceneDepth, techSceneSurface(projection));
                  TECH_ENGINE_OUT(e))

SNELL_PARITY_CASE(snellEngineHdrpProxyLookup, [] { return proxyInputs(847); },
                  (vec3, origin, 0)(float, dist, 3)(vec3, dir, 4)(vec4, projection, 8)(float, proxyHalf, 13)
                  (float, proxyZ, 14)(float, front, 15),
                  TECH_ENGINE_OUTPUTS, techExtras(),
                  SnellEngineRefraction e = snellEngineHdrpProxyLookup(origin * front, origin, dir, dist,
                                                                       techProxy(proxyHalf, proxyZ), techSceneDepth,
                                                                       techSceneSurface(projection));
                  TECH_ENGINE_OUT(e))

SNELL_PARITY_CASE(snellEngineProxyExit, [] { return proxyInputs(848); },
                  (vec3, origin, 0)(vec3, dir, 4)(float, proxyHalf, 13)(float, proxyZ, 14),
                  (float, s, 0, within(1e-4f, 1e-4f)),
                  techExtras(),
                  s = snellEngineProxyExit(origin, dir, techProxy(proxyHalf, proxyZ));)

SNELL_PARITY_CASE(snellEngineSeePoint, [] { return seePointInputs(849); },
                  (vec3, x, 0)(float, dist, 3)(vec3, dir, 4)(vec4, projection, 8),
                  TECH_ENGINE_OUTPUTS, techExtras(),
                  SnellEngineRefraction e = snellEngineSeePoint(x, dir, dist, techMatrix(projection));
                  TECH_ENGINE_OUT(e))

SNELL_PARITY_CASE(snellEngineHdrpEdgeFade, [] { return seePointInputs(850); },
                  (vec2, uv, 0),
                  (float, fade, 0, within(1e-5f, 1e-5f)),
                  techExtras(),
                  fade = snellEngineHdrpEdgeFade(uv * 0.1f + vec2(0.5f, 0.5f));)

SNELL_PARITY_CASE(snellEngineInvalid, [] { return smallIntInputs(851, 0, 1); },
                  /* no inputs */,
                  TECH_ENGINE_OUTPUTS, techExtras(),
                  SnellEngineRefraction e = snellEngineInvalid();
                  TECH_ENGINE_OUT(e))

}  // namespace parity_technique
