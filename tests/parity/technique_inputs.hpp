// The technique test scene's textures and the input generators the parity cases of the two-interface
// technique share (intersect_technique_cases.cpp, shade_technique_cases.cpp, shade_engine_cases.cpp; see
// parity_case.hpp). cases/technique.glsl holds the textures, the ray cases' technique, material and view
// (techTechnique, techMaterial, techView), the options cases' packing (TECH_OPTIONS_OUT) and techImagePixel
// (tests/gpu/technique_image_test.cpp).
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
#pragma once

#include <snell/depth_pyramid.hpp>
#include <snell/snell.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "parity_case.hpp"
#include "support/technique_scene.hpp"

namespace parity_technique {
using namespace snell;
inline Texture2D techBackDepth, techBackNormal, techBackPyramid, techSceneDepth, techSceneNormal, techScenePyramid,
    techFrontDepth, techFrontNormal, techSceneColor, techEnv;
#include "cases/technique.glsl"

using snell_parity::InputGen;
using snell_parity::ParityIO;

inline constexpr int kInputs = 12000;
inline constexpr int kSize = 96;

inline const technique_test::Scene& scene() {
  static const technique_test::Scene s = technique_test::makeScene(kSize, kSize);
  return s;
}

inline void buildTextures() {
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

inline std::vector<snell::gpu::ParityTexture> textures() {
  return {{"techBackDepth", &techBackDepth},       {"techBackNormal", &techBackNormal},
          {"techBackPyramid", &techBackPyramid},   {"techSceneDepth", &techSceneDepth},
          {"techSceneNormal", &techSceneNormal},   {"techScenePyramid", &techScenePyramid},
          {"techSceneColor", &techSceneColor},     {"techEnv", &techEnv},
          {"techFrontDepth", &techFrontDepth},     {"techFrontNormal", &techFrontNormal}};
}

// Every case: the scene's textures, built before the generator and the C++ build run.
inline snell_parity::CaseExtras techExtras() { return snell_parity::CaseExtras().sampling(textures(), buildTextures); }

inline glm::vec4 matrixEntries() {
  const glm::mat4& m = scene().back.clipFromView;
  return glm::vec4(m[0][0], m[1][1], m[2][2], m[3][2]);
}

// Front-face sample of a random pixel (most hit the sphere; misses get a made-up point).
inline technique_test::Exact frontSample(InputGen& g, double ior) {
  for (int k = 0; k < 50; ++k) {
    const technique_test::Exact e =
        technique_test::exactTrace(scene().front, glm::dvec2(g.uniform(0.0f, 1.0f), g.uniform(0.0f, 1.0f)), ior);
    if (e.hitsSphere) return e;
  }
  return technique_test::exactTrace(scene().front, glm::dvec2(0.5, 0.45), ior);
}

inline std::vector<ParityIO> techniqueInputs(std::uint32_t seed) {
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
inline std::vector<ParityIO> engineInputs(std::uint32_t seed) {
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
inline std::vector<ParityIO> seePointInputs(std::uint32_t seed) {
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
inline std::vector<ParityIO> proxyInputs(std::uint32_t seed) {
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

inline std::vector<ParityIO> exitInputs(std::uint32_t seed) {
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
inline std::vector<ParityIO> insideInputs(std::uint32_t seed) {
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
inline std::vector<ParityIO> insideSideInputs(std::uint32_t seed) {
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

inline std::vector<ParityIO> dispatchInputs(std::uint32_t seed) {
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

inline std::vector<ParityIO> directionInputs(std::uint32_t seed, bool withLod) {
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

inline std::vector<ParityIO> atanInputs() {
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

inline std::vector<ParityIO> smallIntInputs(std::uint32_t seed, int lo, int hi) {
  InputGen g(seed);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    ParityIO in{};
    in.v[0] = glm::vec4(float(g.integer(lo, hi)), float(g.integer(lo, hi)), 0.0f, 0.0f);
    v.push_back(in);
  }
  return v;
}

inline std::vector<ParityIO> boundsInputs() {
  InputGen g(802);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    ParityIO in{};
    in.v[0] = glm::vec4(g.uniform(-1.0f, 0.0f), g.uniform(-20.0f, 0.0f), 0.0f, 0.0f);
    v.push_back(in);
  }
  return v;
}

inline std::vector<ParityIO> boxInputs() {
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

}  // namespace parity_technique
