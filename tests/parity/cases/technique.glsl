/* The two-interface refraction parity cases' shared part (glsl/snell/shade/environment*.glsl,
   technique_*.glsl, two_interface*.glsl; the cases themselves are described in
   tests/parity/technique_cases.cpp): the textures, the ray cases' options, the options cases' packing and
   techImagePixel (tests/gpu/technique_image_test.cpp).
   Textures: the technique test scene (tests/support/technique_scene.hpp) at 96x96:
   back-face depth / normal mips / pyramid of a glass sphere, an opaque painting
   plane's depth / normal mips / pyramid / mipmapped colour, an equirectangular
   environment (256x128, trilinear). */
#include "snell/snell.glsl"

#if defined(SNELL_LANG_GLSL)
uniform sampler2D techBackDepth;
uniform sampler2D techBackNormal;
uniform sampler2D techBackPyramid;
uniform sampler2D techSceneDepth;
uniform sampler2D techSceneNormal;
uniform sampler2D techScenePyramid;
uniform sampler2D techSceneColor;
uniform sampler2D techEnv;
#endif
#if defined(SNELL_LANG_HLSL)
Texture2D<float4> techBackDepth;
Texture2D<float4> techBackNormal;
Texture2D<float4> techBackPyramid;
Texture2D<float4> techSceneDepth;
Texture2D<float4> techSceneNormal;
Texture2D<float4> techScenePyramid;
Texture2D<float4> techSceneColor;
Texture2D<float4> techEnv;
#endif

SNELL_FN float techFlag(bool b) {
  return b ? 1.0f : 0.0f;
}

SNELL_FN bool techBit(int bits, int bit) {
  return ((bits / bit) - 2 * (bits / (2 * bit))) == 1;
}

/* The projection from its entries (A, B, C, D as in plane.glsl) */
SNELL_FN mat4 techMatrix(vec4 c) {
  return SNELL_CAMERA_MAT4_COLUMNS(vec4(c.x, 0.0f, 0.0f, 0.0f), vec4(0.0f, c.y, 0.0f, 0.0f),
                                   vec4(0.0f, 0.0f, c.z, -1.0f), vec4(0.0f, 0.0f, c.w, 0.0f));
}

SNELL_FN SnellDepthSurface techBackSurface(vec4 c) {
  return snellDepthSurface(techMatrix(c), 0.5f, 40.0f, SNELL_DEPTH_GL, 0.0f);
}

SNELL_FN SnellDepthSurface techSceneSurface(vec4 c) {
  return snellDepthSurface(techMatrix(c), 0.5f, 40.0f, SNELL_DEPTH_GL, 1.0f);
}

/* The ray cases' technique: a row of the technique table (ids 0 .. SNELL_TECHNIQUE_COUNT - 1, as the lab runs
   them), or one of the variants past it that sweep a count or use what no row does: TECH_DIR_STEPS (DIR with
   `steps` CBS steps in the back slot), TECH_DIR_BOUNDS (the bounding-box range), TECH_PLANE_NORMAL_N and
   TECH_PLANE_DEPTH_N (`steps` iterations), TECH_BINARY (binary search / linear+binary search). */
#define TECH_DIR_STEPS (SNELL_TECHNIQUE_COUNT + 0)
#define TECH_DIR_BOUNDS (SNELL_TECHNIQUE_COUNT + 1)
#define TECH_PLANE_NORMAL_N (SNELL_TECHNIQUE_COUNT + 2)
#define TECH_PLANE_DEPTH_N (SNELL_TECHNIQUE_COUNT + 3)
#define TECH_BINARY (SNELL_TECHNIQUE_COUNT + 4)
SNELL_FN SnellTechniqueOptions techPreset(int preset, int steps) {
  if (preset >= 0 && preset < SNELL_TECHNIQUE_COUNT) {
    return snellTechniquePreset(preset);
  }
  if (preset == TECH_DIR_STEPS) {
    SnellTechniqueOptions o = snellPresetDir();
    o.back.cbsSteps = steps;
    return o;
  }
  if (preset == TECH_DIR_BOUNDS) {
    return snellPresetDirBounds(-3.8f, -8.3f);
  }
  if (preset == TECH_PLANE_NORMAL_N) {
    return snellPresetPlaneNormal(steps);
  }
  if (preset == TECH_PLANE_DEPTH_N) {
    return snellPresetPlaneDepth(steps);
  }
  SnellTechniqueOptions o = snellTechniqueOptions();
  o.back = snellIntersectOptions(SNELL_STRATEGY_BINARY);
  o.exit = snellIntersectOptions(SNELL_STRATEGY_LINEAR_BINARY);
  return o;
}

/* The ray cases' options: techPreset(preset, steps) with the given IOR and roughness; mode bits: 1 exit to
   scene, 2 edge-fade fallback, 4 dispersion (3 traces), 8 no reflection, 16 TIR policy ZERO, 32 REFLECT,
   64 absorption, 128 reflection from the scene (through the exit slot). */
SNELL_FN SnellTechniqueOptions techOptions(int preset, int steps, float ior, int modes, float roughness) {
  SnellTechniqueOptions o = techPreset(preset, steps);
  o.ior = ior;
  o.iors = vec3(ior * 0.98f, ior, ior * 1.02f);
  o.exitMode = techBit(modes, 1) ? SNELL_EXIT_SCENE : SNELL_EXIT_ENVIRONMENT;
  o.fallback = techBit(modes, 2) ? SNELL_FALLBACK_EDGE_FADE : SNELL_FALLBACK_ENVIRONMENT;
  o.dispersion = techBit(modes, 4) ? 3 : 1;
  o.reflection = !techBit(modes, 8);
  o.tirPolicy = techBit(modes, 16) ? SNELL_TIR_ZERO : (techBit(modes, 32) ? SNELL_TIR_REFLECT : SNELL_TIR_CRITICAL);
  o.absorption = techBit(modes, 64) ? vec3(0.1f, 0.2f, 0.4f) : vec3(0.0f, 0.0f, 0.0f);
  o.reflectionMode = techBit(modes, 128) ? SNELL_REFLECT_SCENE : SNELL_REFLECT_ENVIRONMENT;
  if (techBit(modes, 128)) {
    o.reflect = o.exit;
  }
  o.roughness = roughness;
  o.sceneColorLevels = 7;
  o.environmentLevels = 8;
  return o;
}

/* A slot's counts in one float each: plane iterations + 16 CBS steps + 256 binary steps (+ 4096 linear steps of
   the linear search), and march steps + 1024 bisections + 32768 DDA steps. */
SNELL_FN vec2 techPackCounts(SnellIntersectOptions o) {
  return vec2(float(o.planeIterations) + 16.0f * float(o.cbsSteps) + 256.0f * float(o.binarySteps) +
                  4096.0f * float(o.linearSteps),
              float(o.marchSteps) + 1024.0f * float(o.marchBisections) + 32768.0f * float(o.ddaSteps));
}

/* rangeSource + 2 backMethod + 4 explicit range valid */
SNELL_FN float techBackFlags(SnellTechniqueOptions o) {
  return float(o.back.rangeSource) + 2.0f * float(o.backMethod) + 4.0f * techFlag(o.back.range.valid);
}

/* exitMode + 2 fallback */
SNELL_FN float techExitFlags(SnellTechniqueOptions o) {
  return float(o.exitMode) + 2.0f * float(o.fallback);
}

/* x: the given range alone (sums of inputs and constants let a compiler fold the constants first, which changes
   the last bit); the other sums hold only whole numbers or constants: y: thickness clamp + fallback distance +
   edge fade, z: stride + roughness + distances + normal lod, w: max lod, levels, environment axes, iors,
   absorption, depth filter. */
SNELL_FN vec4 techOptionSums(SnellTechniqueOptions o) {
  return vec4(o.back.range.zNearest + o.back.range.zFarthest,
              min(o.back.ddaThickness, 1e6f) + o.fallbackDistance + o.edgeFadeWidth,
              o.back.ddaStride + o.roughness + o.back.marchMaxDistance + o.back.ddaMaxDistance + o.back.planeNormalLod,
              float(o.back.planeMaxLod) + float(o.sceneColorLevels + o.environmentLevels) + o.envX.x + o.envY.y +
                  o.envZ.z + o.iorOutside + o.iors.y + o.absorption.x + float(o.back.depthFilter));
}

/* The options cases' outputs (TECH_OPTIONS_OUTPUTS in technique_cases.cpp) set from the options `o`: each slot's
   strategy, counts and flags, the refraction settings and the sums. */
#define TECH_SLOTS_OUT(o) backStrategy = o.back.strategy; backCounts = techPackCounts(o.back); backFlags = techBackFlags(o); exitStrategy = o.exit.strategy; exitCounts = techPackCounts(o.exit); exitFlags = techExitFlags(o);
#define TECH_OPTIONS_OUT(o) TECH_SLOTS_OUT(o) tirPolicy = o.tirPolicy; ior = o.ior; dispersion = o.dispersion; reflection = o.reflection; sums = techOptionSums(o);

#if defined(SNELL_LANG_GLSL)
uniform sampler2D techFrontDepth;
uniform sampler2D techFrontNormal;
#endif
#if defined(SNELL_LANG_HLSL)
Texture2D<float4> techFrontDepth;
Texture2D<float4> techFrontNormal;
#endif

/* The full-frame test's techniques (tests/gpu/technique_image_test.cpp, which
   compiles one program per preset with the strategies its options call):
   0 DIR to the scene, 1 plane normal (2 iterations) to the scene, 2 ISR (d_N =
   2R) to the environment, 3 DIR + dispersion + absorption + edge-fade
   fallback; then, painting behind: 4 plane depth (3 iterations), 5 single
   sample, 6 linear march, 7 DDA, 8 DIR with the sphere's bounding box as its
   range (centre z -6, radius 2.2: tests/support/technique_scene.hpp). */
#define TECH_IMAGE_PRESETS 9
SNELL_FN SnellTechniqueOptions techImageOptions(int preset) {
  SnellTechniqueOptions o = snellPresetDir();
  o.exitMode = SNELL_EXIT_SCENE;
  if (preset == 1) {
    o = snellPresetPlaneNormal(2);
    o.exitMode = SNELL_EXIT_SCENE;
  } else if (preset == 2) {
    o = snellPresetIsr();
  } else if (preset == 3) {
    o.dispersion = 3;
    o.iors = snellDispersionIors(1.5168f, 30.0f);
    o.absorption = vec3(0.05f, 0.1f, 0.2f);
    o.fallback = SNELL_FALLBACK_EDGE_FADE;
  } else if (preset >= 4) {
    if (preset == 4) {
      o = snellPresetPlaneDepth(3);
    } else if (preset == 5) {
      o = snellPresetSingleSample();
    } else if (preset == 6) {
      o = snellPresetLinearMarch();
    } else if (preset == 7) {
      o = snellPresetDdaMarch();
    } else {
      o = snellPresetDirBounds(-3.8f, -8.2f);
    }
    o.exitMode = SNELL_EXIT_SCENE;
  }
  return o;
}

/* One pixel of a full frame: the front-face buffers give P1 and N1, the
   technique (techImageOptions(preset)) the colour; outside the object, the
   painting (or the environment where the painting is missing). */
SNELL_FN vec4 techImagePixel(ivec2 px, int preset, vec4 c) {
  SnellDepthSurface front = snellDepthSurface(techMatrix(c), 0.5f, 40.0f, SNELL_DEPTH_GL, 1.0f);
  ivec2 size = SNELL_TEXTURE_SIZE(techFrontDepth, 0);
  vec2 uv = snellPixelToUv(px, size);
  SnellSurfaceSample f = snellSampleSurface(techFrontDepth, uv, front);
  if (!f.valid) {
    SnellSurfaceSample s = snellSampleSurface(techSceneDepth, uv, techSceneSurface(c));
    if (s.valid) {
      return vec4(vec3(SNELL_SAMPLE_LOD(techSceneColor, uv, 0.0f).x, SNELL_SAMPLE_LOD(techSceneColor, uv, 0.0f).y,
                       SNELL_SAMPLE_LOD(techSceneColor, uv, 0.0f).z),
                  0.0f);
    }
    return vec4(0.0f, 0.0f, 0.0f, 0.0f);
  }
  SnellViewPoint p1 = snellUvZToView(techMatrix(c), uv, f.viewZ);
  vec4 n1 = SNELL_TEXEL_FETCH(techFrontNormal, px, 0);
  SnellTechniqueOptions o = techImageOptions(preset);
  SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(
      p1.position, vec3(n1.x, n1.y, n1.z), 4.4f, techBackDepth, techBackNormal, techBackPyramid, techBackSurface(c),
      techSceneDepth, techSceneNormal, techScenePyramid, techSceneColor, techSceneSurface(c), techEnv, o);
  return vec4(r.color.x, r.color.y, r.color.z, r.fellBack ? 2.0f : 1.0f);
}
