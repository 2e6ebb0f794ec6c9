// The parity cases of shade/engine_models/ (technique_inputs.hpp): where three.js, Bevy, Filament, HDRP and
// Godot read their scene colour, on the technique test scene's sphere.
#include "technique_inputs.hpp"

namespace parity_technique {
#define SNELL_PARITY_FILE "technique.glsl"

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

// The engines' rough reads (shade/engine_models/engine_rough.glsl) of the sphere scene's mipmapped colour (96x96,
// 7 levels): colours 1e-4, lods 1e-4, fetch counts exact. Bevy's noise has jumps (a fract of a fract), so its
// pixels stay 1e-3 away from them, and the dispatcher's p projects to a pixel centre.
inline bool bevyNoiseTie(double x, double y) {
  const double t = 0.06711056 * x + 0.00583715 * y;
  const double f = t - std::floor(t);
  const double u = 52.9829189 * f;
  const double w = u - std::floor(u);
  return f < 1e-3 || f > 1.0 - 1e-3 || w < 1e-3 || w > 1.0 - 1e-3;
}

inline std::vector<ParityIO> blurInputs(std::uint32_t seed) {
  InputGen g(seed);
  std::vector<ParityIO> v;
  const glm::vec4 m = matrixEntries();
  for (int i = 0; i < kInputs; ++i) {
    const float px = std::floor(g.uniform(0.0f, 95.99f)) + 0.5f, py = std::floor(g.uniform(0.0f, 95.99f)) + 0.5f;
    if (bevyNoiseTie(px, kSize - py)) {
      --i;
      continue;
    }
    // p on the ray through that pixel's centre, at a depth in front of the camera.
    const float z = g.uniform(2.0f, 12.0f);
    const glm::vec3 p((px / kSize * 2.0f - 1.0f) * z / m.x, (py / kSize * 2.0f - 1.0f) * z / m.y, -z);
    float r = g.uniform(0.0f, 1.0f);
    if (g.chance(0.05f)) r = 0.0f;
    if (g.chance(0.03f)) r = g.chance(0.5f) ? -g.uniform(0.0f, 1.0f) : g.hostile();
    float ior = g.uniform(1.0f, 2.0f);
    if (g.chance(0.03f)) ior = g.hostile();
    glm::vec2 uv(g.uniform(-0.1f, 1.1f), g.uniform(-0.1f, 1.1f));
    if (g.chance(0.02f)) uv = glm::vec2(g.hostile(), g.hostile());
    float lod = g.uniform(-0.5f, 7.0f);
    if (g.chance(0.02f)) lod = g.hostile();
    ParityIO in{};
    in.v[0] = glm::vec4(uv, r, ior);
    in.v[1] = glm::vec4(p, float(g.integer(-1, SNELL_ENGINE_BLUR_COUNT)));
    in.v[2] = m;
    in.v[3] = glm::vec4(lod, px, kSize - py, float(4 << g.integer(0, 3)));
    v.push_back(in);
  }
  return v;
}

#define TECH_BLUR_INPUTS                                                                                        \
  (vec2, uv, 0)(float, roughness, 2)(float, ior, 3)(vec3, p, 4)(int, blur, 7)(vec4, projection, 8)              \
  (float, lod, 12)(vec2, pixel, 13)(int, taps, 15)
#define TECH_BLUR_OUTPUTS (vec3, color, 0, within(1e-4f, 1e-4f))(int, fetches, 3, exact)

SNELL_PARITY_CASE(snellEngineBlurLod, [] { return blurInputs(853); }, TECH_BLUR_INPUTS,
                  (float, level, 0, within(1e-4f, 1e-4f)), techExtras(),
                  level = snellEngineBlurLod(blur, roughness, ior, 7, vec2(96.0f, 96.0f), techMatrix(projection));)

SNELL_PARITY_CASE(snellEngineBicubicMips, [] { return blurInputs(854); }, TECH_BLUR_INPUTS, TECH_BLUR_OUTPUTS,
                  techExtras(),
                  SnellEngineBlurRead r = snellEngineBicubicMips(techSceneColor, uv, lod, 7);
                  color = r.color;
                  fetches = r.fetches;)

SNELL_PARITY_CASE(snellEngineBevyBlur, [] { return blurInputs(855); }, TECH_BLUR_INPUTS, TECH_BLUR_OUTPUTS,
                  techExtras(),
                  SnellEngineBlurRead r = snellEngineBevyBlur(techSceneColor, uv, roughness, ior, p.z, pixel, taps);
                  color = r.color;
                  fetches = r.fetches;)

SNELL_PARITY_CASE(snellEngineBlurRead, [] { return blurInputs(856); }, TECH_BLUR_INPUTS, TECH_BLUR_OUTPUTS,
                  techExtras(),
                  SnellEngineBlurRead r = snellEngineBlurRead(blur, techSceneColor, uv, roughness, ior, p,
                                                              techMatrix(projection), 7);
                  color = r.color;
                  fetches = r.fetches;)

SNELL_PARITY_CASE(snellEngineSmoothRead, [] { return blurInputs(857); }, TECH_BLUR_INPUTS, TECH_BLUR_OUTPUTS,
                  techExtras(),
                  SnellEngineBlurRead r = snellEngineSmoothRead(techSceneColor, uv);
                  color = r.color;
                  fetches = r.fetches;)

SNELL_PARITY_CASE(snellEngineBlurOf, [] { return smallIntInputs(858, -2, SNELL_ENGINE_MODEL_COUNT + 1); },
                  (int, model, 0), (int, blur, 0, exact), techExtras(),
                  blur = snellEngineBlurOf(model);)

}  // namespace parity_technique
