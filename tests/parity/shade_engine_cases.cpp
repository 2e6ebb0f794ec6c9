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

}  // namespace parity_technique
