/* The two-interface refraction parity cases' shared part (glsl/snell/shade/environment*.glsl,
   technique_*.glsl, two_interface*.glsl; the cases themselves are described in
   tests/parity/technique_inputs.hpp and the *_technique_cases.cpp, shade_engine_cases.cpp): the textures, the ray cases' options, the options cases' packing and
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
uniform sampler2D techFrontDepth;
uniform sampler2D techFrontNormal;
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
Texture2D<float4> techFrontDepth;
Texture2D<float4> techFrontNormal;
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

SNELL_FN SnellDepthSurface techFrontSurface(vec4 c) {
  return snellDepthSurface(techMatrix(c), 0.5f, 40.0f, SNELL_DEPTH_GL, 1.0f);
}

/* The textures as the argument lists of SNELL_OBJECT_BUFFERS and SNELL_SCENE_BUFFERS, for projection entries c */
#define TECH_OBJECT_TEXTURES(c) techBackDepth, techBackNormal, techBackPyramid, techBackSurface(c), techFrontDepth, techFrontNormal, techFrontSurface(c)
#define TECH_SCENE_TEXTURES(c) techSceneDepth, techSceneNormal, techScenePyramid, techSceneColor, techSceneSurface(c), techEnv

/* The ray cases' technique: a row of the technique table (ids 0 .. SNELL_TECHNIQUE_COUNT - 1, as the lab runs
   them), or one of the variants past it that sweep a count or use what no row does: TECH_DIR_STEPS (DIR with
   `steps` CBS steps in the back slot), TECH_DIR_BOUNDS (the bounding-box range), TECH_PLANE_NORMAL_N and
   TECH_PLANE_DEPTH_N (`steps` iterations), TECH_BINARY (binary search / linear+binary search). */
#define TECH_DIR_STEPS (SNELL_TECHNIQUE_COUNT + 0)
#define TECH_DIR_BOUNDS (SNELL_TECHNIQUE_COUNT + 1)
#define TECH_PLANE_NORMAL_N (SNELL_TECHNIQUE_COUNT + 2)
#define TECH_PLANE_DEPTH_N (SNELL_TECHNIQUE_COUNT + 3)
#define TECH_BINARY (SNELL_TECHNIQUE_COUNT + 4)
SNELL_FN SnellTechnique techPreset(int preset, int steps) {
  if (preset >= 0 && preset < SNELL_TECHNIQUE_COUNT) {
    return snellTechniquePreset(preset);
  }
  if (preset == TECH_DIR_STEPS) {
    SnellTechnique t = snellPresetDir();
    t.back.intersect.cbsSteps = steps;
    return t;
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
  SnellTechnique t = snellTechnique();
  t.back.intersect = snellIntersectOptions(SNELL_STRATEGY_BINARY);
  t.exit.intersect = snellIntersectOptions(SNELL_STRATEGY_LINEAR_BINARY);
  return t;
}

/* The ray cases' technique, material and view: techPreset(preset, steps) with the given IOR and roughness;
   mode bits: 1 exit slot to the scene, 2 edge-fade fallback, 4 dispersion (3 traces), 8 no reflection, 16 TIR
   policy ZERO, 32 REFLECT, 64 absorption, 128 reflect slot to the scene (with the exit slot's intersector), 256
   the normal plane inside (steps planes after a 12-step march), 512 a hostile bounce count (steps < 4: steps - 2,
   so -2 .. 1; else steps * 250, far past SNELL_MAX_BOUNCES), 1024 insideScene (the refracted ray searched
   against the scene too). */
SNELL_FN SnellTechnique techTechnique(int preset, int steps, int modes) {
  SnellTechnique t = techPreset(preset, steps);
  t.exit.source = techBit(modes, 1) ? SNELL_SOURCE_BUFFERS : SNELL_SOURCE_ENVIRONMENT;
  t.exit.fallback = techBit(modes, 2) ? SNELL_FALLBACK_EDGE_FADE : SNELL_FALLBACK_ENVIRONMENT;
  if (techBit(modes, 128)) {
    t.reflect.source = SNELL_SOURCE_BUFFERS;
    t.reflect.intersect = t.exit.intersect;
  }
  if (techBit(modes, 256)) {
    t.inside.intersect.strategy = SNELL_STRATEGY_PLANE_NORMAL;
    t.inside.intersect.marchSteps = 12;
    t.inside.intersect.planeIterations = steps;
  }
  if (techBit(modes, 512)) {
    t.bounces = steps < 4 ? steps - 2 : steps * 250;
  }
  t.insideScene = techBit(modes, 1024);
  return t;
}

SNELL_FN SnellMaterial techMaterial(float ior, int modes, float roughness) {
  SnellMaterial m = snellMaterial();
  m.ior = ior;
  m.iors = vec3(ior * 0.98f, ior, ior * 1.02f);
  m.dispersion = techBit(modes, 4) ? 3 : 1;
  m.reflection = !techBit(modes, 8);
  m.tirPolicy = techBit(modes, 16) ? SNELL_TIR_ZERO : (techBit(modes, 32) ? SNELL_TIR_REFLECT : SNELL_TIR_CRITICAL);
  m.absorption = techBit(modes, 64) ? vec3(0.1f, 0.2f, 0.4f) : vec3(0.0f, 0.0f, 0.0f);
  m.roughness = roughness;
  return m;
}

SNELL_FN SnellView techView() {
  SnellView v = snellView();
  v.sceneColorLevels = 7;
  v.environmentLevels = 8;
  return v;
}

/* A slot's counts in one float each: plane iterations + 16 CBS steps + 256 binary steps (+ 4096 linear steps of
   the linear search), and march steps + 1024 bisections + 32768 DDA steps. */
SNELL_FN vec2 techPackCounts(SnellIntersectOptions o) {
  return vec2(float(o.planeIterations) + 16.0f * float(o.cbsSteps) + 256.0f * float(o.binarySteps) +
                  4096.0f * float(o.linearSteps),
              float(o.marchSteps) + 1024.0f * float(o.marchBisections) + 32768.0f * float(o.ddaSteps));
}

/* the back slot: rangeSource + 2 (source is WYMAN) + 4 explicit range valid + 8 (source is ENVIRONMENT) */
SNELL_FN float techBackFlags(SnellSlot s) {
  return float(s.intersect.rangeSource) + 2.0f * techFlag(s.source == SNELL_SOURCE_WYMAN) +
         4.0f * techFlag(s.intersect.range.valid) + 8.0f * techFlag(s.source == SNELL_SOURCE_ENVIRONMENT);
}

/* the exit slot: (source is BUFFERS) + 2 fallback + 4 (source is WYMAN) */
SNELL_FN float techExitFlags(SnellSlot s) {
  return techFlag(s.source == SNELL_SOURCE_BUFFERS) + 2.0f * float(s.fallback) +
         4.0f * techFlag(s.source == SNELL_SOURCE_WYMAN);
}

/* x: the given range alone (sums of inputs and constants let a compiler fold the constants first, which changes
   the last bit); the other sums hold only whole numbers or constants: y: thickness clamp + fallback distance +
   edge fade, z: stride + roughness + distances + normal lod, w: max lod, levels, environment axes, iors,
   absorption, depth filter. */
SNELL_FN vec4 techOptionSums(SnellTechnique t, SnellMaterial m, SnellView v) {
  return vec4(t.back.intersect.range.zNearest + t.back.intersect.range.zFarthest,
              min(t.back.intersect.ddaThickness, 1e6f) + t.exit.fallbackDistance + t.exit.edgeFadeWidth,
              t.back.intersect.ddaStride + m.roughness + t.back.intersect.marchMaxDistance +
                  t.back.intersect.ddaMaxDistance + t.back.intersect.planeNormalLod,
              float(t.back.intersect.planeMaxLod) + float(v.sceneColorLevels + v.environmentLevels) + v.envX.x +
                  v.envY.y + v.envZ.z + m.iorOutside + m.iors.y + m.absorption.x + float(t.back.intersect.depthFilter));
}

/* The options cases' outputs (TECH_OPTIONS_EXACT in technique_inputs.hpp) set from a technique `t`, material
   `m` and view `v`: the back and exit slots' strategy, counts and flags, the material's settings and the sums. */
#define TECH_SLOTS_OUT(t) backStrategy = t.back.intersect.strategy; backCounts = techPackCounts(t.back.intersect); backFlags = techBackFlags(t.back); exitStrategy = t.exit.intersect.strategy; exitCounts = techPackCounts(t.exit.intersect); exitFlags = techExitFlags(t.exit);
/* The bounce presets' outputs (TECH_BOUNCE_EXACT in shade_technique_cases.cpp). */
#define TECH_BOUNCE_OUT(t) bounces = t.bounces; insideSource = t.inside.source; insideStrategy = t.inside.intersect.strategy; insideCounts = vec2(float(t.inside.intersect.marchSteps), float(t.inside.intersect.marchBisections)); insideMaxDistance = t.inside.intersect.marchMaxDistance; backStrategy = t.back.intersect.strategy; backCounts = techPackCounts(t.back.intersect); exitStrategy = t.exit.intersect.strategy;
/* The engine model cases' outputs (TECH_ENGINE_OUTPUTS in shade_engine_cases.cpp) from a SnellEngineRefraction. */
#define TECH_ENGINE_OUT(e) uv = e.uv; weight = e.sceneWeight; valid = e.valid; direction = e.direction; distance = e.distance;
#define TECH_OPTIONS_OUT(t, m, v) TECH_SLOTS_OUT(t) tirPolicy = m.tirPolicy; ior = m.ior; dispersion = m.dispersion; reflection = m.reflection; sums = techOptionSums(t, m, v);


/* The full-frame test's techniques (tests/gpu/technique_image_test.cpp, which
   compiles one program per preset with the strategies its options call):
   0 DIR to the scene, 1 plane normal (2 iterations) to the scene, 2 ISR (d_N =
   2R) to the environment, 3 DIR + dispersion + absorption + edge-fade
   fallback; then, painting behind: 4 plane depth (3 iterations), 5 single
   sample, 6 linear march, 7 DDA, 8 DIR with the sphere's bounding box as its
   range (centre z -6, radius 2.2: tests/support/technique_scene.hpp). */
#define TECH_IMAGE_PRESETS 9
SNELL_FN SnellTechnique techImageTechnique(int preset) {
  SnellTechnique t = snellPresetDir();
  if (preset == 1) {
    t = snellPresetPlaneNormal(2);
  } else if (preset == 2) {
    t = snellPresetIsr();
  } else if (preset == 3) {
    t.exit.fallback = SNELL_FALLBACK_EDGE_FADE;
  } else if (preset == 4) {
    t = snellPresetPlaneDepth(3);
  } else if (preset == 5) {
    t = snellPresetSingleSample();
  } else if (preset == 6) {
    t = snellPresetLinearMarch();
  } else if (preset == 7) {
    t = snellPresetDdaMarch();
  } else if (preset >= 8) {
    t = snellPresetDirBounds(-3.8f, -8.2f);
  }
  if (preset != 2) {
    t.exit.source = SNELL_SOURCE_BUFFERS;
  }
  return t;
}

SNELL_FN SnellMaterial techImageMaterial(int preset) {
  SnellMaterial m = snellMaterial();
  if (preset == 3) {
    m.dispersion = 3;
    m.iors = snellDispersionIors(1.5168f, 30.0f);
    m.absorption = vec3(0.05f, 0.1f, 0.2f);
  }
  return m;
}

/* One pixel of a full frame: the front-face buffers give P1 and N1, the
   technique (techImageTechnique(preset), techImageMaterial(preset)) the colour; outside the object, the
   painting (or the environment where the painting is missing). */
SNELL_FN vec4 techImagePixel(ivec2 px, int preset, vec4 c) {
  SnellDepthSurface front = techFrontSurface(c);
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
  SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(
      p1.position, vec3(n1.x, n1.y, n1.z), 4.4f, TECH_OBJECT_TEXTURES(c), TECH_SCENE_TEXTURES(c),
      techImageTechnique(preset), techImageMaterial(preset), snellView());
  return vec4(r.color.x, r.color.y, r.color.z, r.fellBack ? 2.0f : 1.0f);
}

/* The engine model cases' probe proxy: a box centred at (0.3, -0.2, centreZ) with half extents
   halfX (1, 0.8, 1.2), as the affine proxyFromView (shade/engine_models/hdrp.glsl) */
SNELL_FN mat4 techProxy(float halfX, float centreZ) {
  float hx = halfX;
  float hy = 0.8f * halfX;
  float hz = 1.2f * halfX;
  return SNELL_CAMERA_MAT4_COLUMNS(vec4(1.0f / hx, 0.0f, 0.0f, 0.0f), vec4(0.0f, 1.0f / hy, 0.0f, 0.0f),
                                   vec4(0.0f, 0.0f, 1.0f / hz, 0.0f),
                                   vec4(-0.3f / hx, 0.2f / hy, -centreZ / hz, 1.0f));
}
