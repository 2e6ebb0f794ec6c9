// The parity cases of shade/'s two-interface technique (technique_inputs.hpp): the environment lookups,
// the technique's options and presets, the path trace, the exit slot and the full shaded technique.
#include "technique_inputs.hpp"

namespace parity_technique {
#define SNELL_PARITY_FILE "technique.glsl"

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
// A rough read of the technique's scene colour (7 levels) and environment: uv a little beyond [0, 1], the level
// 0 (smooth glass) or up to beyond the top.
inline std::vector<ParityIO> roughReadInputs() {
  InputGen g(829);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    ParityIO in{};
    in.v[0] = glm::vec4(g.uniform(-0.1f, 1.1f), g.uniform(-0.1f, 1.1f), g.chance(0.3f) ? 0.0f : g.uniform(0.0f, 9.0f),
                        float(g.integer(1, 9)));
    in.v[1] = glm::vec4(g.unitVector(), 0.0f);
    v.push_back(in);
  }
  return v;
}

// The colour pyramid's reduce of the technique's scene colour (96 x 96: even levels, then 3 -> 1) and of its
// environment: an output texel of level lod + 1 (at times beyond it: clamped).
inline std::vector<ParityIO> colorReduceInputs() {
  buildTextures();
  InputGen g(833);
  std::vector<ParityIO> v;
  for (int i = 0; i < kInputs; ++i) {
    const int which = g.chance(0.5f) ? 0 : 1;
    const Texture2D& t = which ? techEnv : techSceneColor;
    const int lod = g.integer(0, t.levelCount() - 2);
    const glm::ivec2 next = t.size(lod + 1);
    const int slack = g.chance(0.05f) ? 3 : 0;
    ParityIO in{};
    in.v[0] = glm::vec4(float(g.integer(-slack, next.x - 1 + slack)), float(g.integer(-slack, next.y - 1 + slack)),
                        float(lod), float(which));
    v.push_back(in);
  }
  return v;
}

SNELL_PARITY_CASE(snellColorPyramidReduce, colorReduceInputs,
                  (ivec2, px, 0)(int, lod, 2)(bool, environment, 3),
                  (vec4, texel, 0, within(1e-5f, 1e-5f)),
                  techExtras(),
                  if (environment) {
                    texel = snellColorPyramidReduce(techEnv, lod, px);
                  } else {
                    texel = snellColorPyramidReduce(techSceneColor, lod, px);
                  })

SNELL_PARITY_CASE(snellRoughConeSample, roughReadInputs,
                  (vec2, uv, 0)(float, lod, 2)(int, levels, 3),
                  (vec4, color, 0, within(1e-4f, 1e-4f)),
                  techExtras(),
                  color = snellRoughConeSample(techSceneColor, uv, snellRoughConeTaps(lod, levels));)

SNELL_PARITY_CASE(snellRoughConeSampleEnvironment, roughReadInputs,
                  (float, lod, 2)(int, levels, 3)(vec3, direction, 4),
                  (vec4, color, 0, within(1e-4f, 1e-4f)),
                  techExtras(),
                  color = snellRoughConeSampleEnvironment(techEnv, direction, snellRoughConeTaps(lod, levels));)

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

// Through a cone of the input's roughness, with d_N as the path inside and one bounce.
SNELL_PARITY_CASE(snellTwoInterfaceExitRough, [] { return exitInputs(824); },
                  TECH_RAY_INPUTS(origin, direction),
                  (vec3, color, 0, within(1e-4f, 1e-4f))(int, fetches, 3, exact)(vec2, hitUv, 4, within(1e-4f, 1e-4f))
                  (bool, hitValid, 6, exact)(bool, fellBack, 7, exact)(vec3, hitPosition, 8, within(1e-4f, 1e-4f)),
                  techExtras(),
                  SnellTechnique t = techTechnique(preset, steps, modes);
                  SnellRoughCone cone = snellRoughConeTransmit(roughness, snellIorToEta(1.0f, ior), dN, 1);
                  SnellTwoInterfaceExit e = snellTwoInterfaceExitRough(origin, direction, cone, techSceneDepth,
                                                                       techSceneNormal, techScenePyramid,
                                                                       techSceneColor, techSceneSurface(projection),
                                                                       techEnv, t.exit, techView());
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

}  // namespace parity_technique
