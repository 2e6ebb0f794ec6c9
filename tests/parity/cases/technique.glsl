/* Parity cases for the two-interface refraction family (glsl/snell/shade/
   environment*.glsl, technique_*.glsl, two_interface*.glsl).
   Textures: the technique test scene (tests/support/technique_scene.hpp) at 96x96:
   back-face depth / normal mips / pyramid of a glass sphere, an opaque painting
   plane's depth / normal mips / pyramid / mipmapped colour, an equirectangular
   environment (256x128, trilinear).
   Ray cases: a = (P1, technique: techPreset), b = (N1, steps), c = the projection's entries
   (A, B, C, D as in plane.glsl), d = (ior, dN, mode bits, roughness); mode bits:
   1 exit to scene, 2 edge-fade fallback, 4 dispersion (3 traces), 8 no reflection,
   16 TIR policy ZERO, 32 REFLECT, 64 absorption. */
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

SNELL_FN bool techBit(float bits, int bit) {
  int v = int(bits);
  return ((v / bit) - 2 * (v / (2 * bit))) == 1;
}

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
SNELL_FN SnellTechniqueOptions techPreset(float preset, float steps) {
  int p = int(preset);
  int n = int(steps);
  if (p >= 0 && p < SNELL_TECHNIQUE_COUNT) {
    return snellTechniquePreset(p);
  }
  if (p == TECH_DIR_STEPS) {
    SnellTechniqueOptions o = snellPresetDir();
    o.back.cbsSteps = n;
    return o;
  }
  if (p == TECH_DIR_BOUNDS) {
    return snellPresetDirBounds(-3.8f, -8.3f);
  }
  if (p == TECH_PLANE_NORMAL_N) {
    return snellPresetPlaneNormal(n);
  }
  if (p == TECH_PLANE_DEPTH_N) {
    return snellPresetPlaneDepth(n);
  }
  SnellTechniqueOptions o = snellTechniqueOptions();
  o.back = snellIntersectOptions(SNELL_STRATEGY_BINARY);
  o.exit = snellIntersectOptions(SNELL_STRATEGY_LINEAR_BINARY);
  return o;
}

SNELL_FN SnellTechniqueOptions techOptions(vec4 a, vec4 b, vec4 d) {
  SnellTechniqueOptions o = techPreset(a.w, b.w);
  o.ior = d.x;
  o.iors = vec3(d.x * 0.98f, d.x, d.x * 1.02f);
  o.exitMode = techBit(d.z, 1) ? SNELL_EXIT_SCENE : SNELL_EXIT_ENVIRONMENT;
  o.fallback = techBit(d.z, 2) ? SNELL_FALLBACK_EDGE_FADE : SNELL_FALLBACK_ENVIRONMENT;
  o.dispersion = techBit(d.z, 4) ? 3 : 1;
  o.reflection = !techBit(d.z, 8);
  o.tirPolicy = techBit(d.z, 16) ? SNELL_TIR_ZERO : (techBit(d.z, 32) ? SNELL_TIR_REFLECT : SNELL_TIR_CRITICAL);
  o.absorption = techBit(d.z, 64) ? vec3(0.1f, 0.2f, 0.4f) : vec3(0.0f, 0.0f, 0.0f);
  o.reflectionMode = techBit(d.z, 128) ? SNELL_REFLECT_SCENE : SNELL_REFLECT_ENVIRONMENT;
  if (techBit(d.z, 128)) {
    o.reflect = o.exit;
  }
  o.roughness = d.w;
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

/* Options packed: a = (back strategy, back counts, rangeSource + 2 backMethod + 4 explicit range valid),
   b = (exit strategy, exit counts, exitMode + 2 fallback), c = (tir, ior, dispersion, reflection), d = (explicit range, thickness clamp +
   fallback distance + edge fade, stride + roughness + distances + normal lod, max lod, levels, environment axes,
   iors, absorption, depth filter) */
SNELL_FN SnellParityOut techPackOptions(SnellTechniqueOptions o) {
  SnellParityOut r;
  vec2 back = techPackCounts(o.back);
  vec2 exit = techPackCounts(o.exit);
  r.a = vec4(float(o.back.strategy), back.x, back.y,
             float(o.back.rangeSource) + 2.0f * float(o.backMethod) + 4.0f * techFlag(o.back.range.valid));
  r.b = vec4(float(o.exit.strategy), exit.x, exit.y, float(o.exitMode) + 2.0f * float(o.fallback));
  r.c = vec4(float(o.tirPolicy), o.ior, float(o.dispersion), techFlag(o.reflection));
  // The given range alone in d.x (sums of inputs and constants let a compiler fold the constants first, which
  // changes the last bit); the other sums hold only whole numbers or constants.
  r.d = vec4(o.back.range.zNearest + o.back.range.zFarthest,
             min(o.back.ddaThickness, 1e6f) + o.fallbackDistance + o.edgeFadeWidth,
             o.back.ddaStride + o.roughness + o.back.marchMaxDistance + o.back.ddaMaxDistance + o.back.planeNormalLod,
             float(o.back.planeMaxLod) + float(o.sceneColorLevels + o.environmentLevels) + o.envX.x + o.envY.y +
                 o.envZ.z + o.iorOutside + o.iors.y + o.absorption.x + float(o.back.depthFilter));
  return r;
}

SNELL_FN SnellParityOut techPackHit(SnellHit h) {
  SnellParityOut o;
  o.a = vec4(h.uv.x, h.uv.y, techFlag(h.valid), float(h.fetches));
  o.b = vec4(h.position.x, h.position.y, h.position.z, 0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* a = (dir, -) */
SNELL_FN SnellParityOut caseSnellCubeFaceUv(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellCubeFace f = snellCubeFaceUv(vec3(a.x, a.y, a.z));
  SnellParityOut o;
  o.a = vec4(float(f.face), f.uv.x, f.uv.y, techFlag(f.valid));
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* a = (y, x) */
SNELL_FN SnellParityOut caseSnellAtan2(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  o.a = vec4(snellAtan2(a.x, a.y), 0.0f, 0.0f, 0.0f);
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

SNELL_FN SnellParityOut caseSnellEquirectUv(vec4 a, vec4 b, vec4 c, vec4 d) {
  vec2 uv = snellEquirectUv(vec3(a.x, a.y, a.z));
  SnellParityOut o;
  o.a = vec4(uv.x, uv.y, 0.0f, 0.0f);
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* a = (dir, lod) */
SNELL_FN SnellParityOut caseSnellSampleEquirect(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellParityOut o;
  o.a = snellSampleEquirect(techEnv, vec3(a.x, a.y, a.z), a.w);
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

SNELL_FN SnellParityOut caseSnellDepthRangeInvalid(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthRange r = snellDepthRangeInvalid();
  SnellParityOut o;
  o.a = vec4(r.zNearest, r.zFarthest, techFlag(r.valid), a.x);
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* a.x selects the texture */
SNELL_FN SnellParityOut caseSnellTextureTopLod(vec4 a, vec4 b, vec4 c, vec4 d) {
  int t = int(a.x);
  int lod = t == 0 ? snellTextureTopLod(techBackPyramid) : (t == 1 ? snellTextureTopLod(techEnv) : snellTextureTopLod(techSceneColor));
  SnellParityOut o;
  o.a = vec4(float(lod), 0.0f, 0.0f, 0.0f);
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

SNELL_FN SnellParityOut caseSnellDepthRangeFromPyramid(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellDepthRange r = a.x > 0.5f ? snellDepthRangeFromPyramid(techScenePyramid) : snellDepthRangeFromPyramid(techBackPyramid);
  SnellParityOut o;
  o.a = vec4(r.zNearest, r.zFarthest, techFlag(r.valid), 0.0f);
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

/* a = (translation, scale), b = boxMin, c = boxMax, d = (rotation angle parameters) */
SNELL_FN SnellParityOut caseSnellDepthRangeFromBox(vec4 a, vec4 b, vec4 c, vec4 d) {
  mat4 m = SNELL_CAMERA_MAT4_COLUMNS(vec4(a.w * d.x, a.w * d.y, 0.0f, 0.0f), vec4(-a.w * d.y, a.w * d.x, 0.0f, 0.0f),
                                     vec4(0.0f, 0.0f, a.w, 0.0f), vec4(a.x, a.y, a.z, 1.0f));
  SnellDepthRange r = snellDepthRangeFromBox(m, vec3(b.x, b.y, b.z), vec3(c.x, c.y, c.z));
  SnellParityOut o;
  o.a = vec4(r.zNearest, r.zFarthest, techFlag(r.valid), 0.0f);
  o.b = vec4(0.0f);
  o.c = vec4(0.0f);
  o.d = vec4(0.0f);
  return o;
}

SNELL_FN SnellParityOut caseSnellIntersectOptions(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellTechniqueOptions t = snellTechniqueOptions();
  t.back = snellIntersectOptions(int(a.x));
  return techPackOptions(t);
}

SNELL_FN SnellParityOut caseSnellTechniqueOptions(vec4 a, vec4 b, vec4 c, vec4 d) {
  return techPackOptions(snellTechniqueOptions());
}

SNELL_FN SnellParityOut caseSnellTechniquePresetSlots(vec4 a, vec4 b, vec4 c, vec4 d) {
  return techPackOptions(snellTechniquePresetSlots(int(a.x), int(a.y)));
}

SNELL_FN SnellParityOut caseSnellPresetDir(vec4 a, vec4 b, vec4 c, vec4 d) {
  return techPackOptions(snellPresetDir());
}

SNELL_FN SnellParityOut caseSnellPresetDirBounds(vec4 a, vec4 b, vec4 c, vec4 d) {
  return techPackOptions(snellPresetDirBounds(a.x, a.y));
}

SNELL_FN SnellParityOut caseSnellPresetIsr(vec4 a, vec4 b, vec4 c, vec4 d) {
  return techPackOptions(snellPresetIsr());
}

SNELL_FN SnellParityOut caseSnellPresetPlaneNormal(vec4 a, vec4 b, vec4 c, vec4 d) {
  return techPackOptions(snellPresetPlaneNormal(int(a.x)));
}

SNELL_FN SnellParityOut caseSnellPresetPlaneDepth(vec4 a, vec4 b, vec4 c, vec4 d) {
  return techPackOptions(snellPresetPlaneDepth(int(a.x)));
}

SNELL_FN SnellParityOut caseSnellPresetSingleSample(vec4 a, vec4 b, vec4 c, vec4 d) {
  return techPackOptions(snellPresetSingleSample());
}

SNELL_FN SnellParityOut caseSnellPresetLinearMarch(vec4 a, vec4 b, vec4 c, vec4 d) {
  return techPackOptions(snellPresetLinearMarch());
}

SNELL_FN SnellParityOut caseSnellPresetDdaMarch(vec4 a, vec4 b, vec4 c, vec4 d) {
  return techPackOptions(snellPresetDdaMarch());
}

SNELL_FN SnellParityOut caseSnellPresetImageSpaceBound(vec4 a, vec4 b, vec4 c, vec4 d) {
  return techPackOptions(snellPresetImageSpaceBound());
}

SNELL_FN SnellParityOut caseSnellTechniquePreset(vec4 a, vec4 b, vec4 c, vec4 d) {
  return techPackOptions(snellTechniquePreset(int(a.x)));
}

/* ray case: a = (origin, strategy), b = (dir, the strategy's main count: iterations, steps, linear steps),
   c = matrix, d = (scene?, explicit range?, -, -) */
SNELL_FN SnellParityOut caseSnellIntersectWith(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellIntersectOptions o = snellIntersectOptions(int(a.w));
  int n = int(b.w);
  o.planeIterations = n;
  o.cbsSteps = n;
  if (o.strategy == SNELL_STRATEGY_BINARY) {
    o.binarySteps = n;
  }
  o.linearSteps = n;
  o.marchSteps = n;
  o.ddaSteps = n;
  if (d.y > 0.5f) {
    o.rangeSource = SNELL_RANGE_EXPLICIT;
    o.range.zNearest = -3.8f;
    o.range.zFarthest = -12.0f;
    o.range.valid = true;
  }
  if (d.x > 0.5f) {
    return techPackHit(snellIntersectWith(vec3(a.x, a.y, a.z), vec3(b.x, b.y, b.z), techSceneDepth, techSceneNormal,
                                          techScenePyramid, techSceneSurface(c), o));
  }
  return techPackHit(snellIntersectWith(vec3(a.x, a.y, a.z), vec3(b.x, b.y, b.z), techBackDepth, techBackNormal,
                                        techBackPyramid, techBackSurface(c), o));
}

/* out a = (T2, fetches), b = (P2, pathLength), c = (N2, flags hit + 2 tir + 4 fellBack + 8 valid), d = (uv, T1.z) */
SNELL_FN SnellParityOut caseSnellTwoInterfaceTrace(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellTechniqueOptions o = techOptions(a, b, d);
  SnellTwoInterfacePath p = snellTwoInterfaceTrace(vec3(a.x, a.y, a.z), vec3(b.x, b.y, b.z),
                                                   snellIorToEta(1.0f, o.ior), d.y, techBackDepth, techBackNormal,
                                                   techBackPyramid, techBackSurface(c), o);
  SnellParityOut r;
  r.a = vec4(p.exitDirection.x, p.exitDirection.y, p.exitDirection.z, float(p.fetches));
  r.b = vec4(p.exitPoint.x, p.exitPoint.y, p.exitPoint.z, p.pathLength);
  r.c = vec4(p.exitNormal.x, p.exitNormal.y, p.exitNormal.z,
             techFlag(p.hit) + 2.0f * techFlag(p.tir) + 4.0f * techFlag(p.fellBack) + 8.0f * techFlag(p.valid));
  r.d = vec4(p.exitUv.x, p.exitUv.y, p.entryDirection.z, 0.0f);
  return r;
}

/* a = (origin, preset), b = (dir, steps); out a = (color, fetches), b = (hit uv, valid, fellBack), c = hit position */
SNELL_FN SnellParityOut caseSnellTwoInterfaceExit(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellTechniqueOptions o = techOptions(a, b, d);
  SnellTwoInterfaceExit e = snellTwoInterfaceExit(vec3(a.x, a.y, a.z), vec3(b.x, b.y, b.z), techSceneDepth,
                                                  techSceneNormal, techScenePyramid, techSceneColor,
                                                  techSceneSurface(c), techEnv, o);
  SnellParityOut r;
  r.a = vec4(e.color.x, e.color.y, e.color.z, float(e.fetches));
  r.b = vec4(e.hit.uv.x, e.hit.uv.y, techFlag(e.hit.valid), techFlag(e.fellBack));
  r.c = vec4(e.hit.position.x, e.hit.position.y, e.hit.position.z, 0.0f);
  r.d = vec4(0.0f);
  return r;
}

/* out a = (color, fetches), b = (T2, flags backHit + 2 fellBack + 4 tir + 8 exit hit valid),
   c = (P2, pathLength), d = (exit hit uv, fresnel, -) */
SNELL_FN SnellParityOut caseSnellTwoInterfaceRefraction(vec4 a, vec4 b, vec4 c, vec4 d) {
  SnellTechniqueOptions o = techOptions(a, b, d);
  SnellTwoInterfaceResult t = snellTwoInterfaceRefraction(
      vec3(a.x, a.y, a.z), vec3(b.x, b.y, b.z), d.y, techBackDepth, techBackNormal, techBackPyramid,
      techBackSurface(c), techSceneDepth, techSceneNormal, techScenePyramid, techSceneColor, techSceneSurface(c),
      techEnv, o);
  SnellParityOut r;
  r.a = vec4(t.color.x, t.color.y, t.color.z, float(t.fetches));
  r.b = vec4(t.exitDirection.x, t.exitDirection.y, t.exitDirection.z,
             techFlag(t.backHit) + 2.0f * techFlag(t.fellBack) + 4.0f * techFlag(t.tir) +
                 8.0f * techFlag(t.exitHit.valid));
  r.c = vec4(t.exitPoint.x, t.exitPoint.y, t.exitPoint.z, t.pathLength);
  r.d = vec4(t.exitHit.uv.x, t.exitHit.uv.y, t.fresnel, techFlag(t.reflectionHit.valid));
  return r;
}

#if defined(SNELL_LANG_GLSL)
uniform sampler2D techFrontDepth;
uniform sampler2D techFrontNormal;
#endif
#if defined(SNELL_LANG_HLSL)
Texture2D<float4> techFrontDepth;
Texture2D<float4> techFrontNormal;
#endif

/* One pixel of a full frame (tests/gpu/technique_image_test.cpp): the front-face
   buffers give P1 and N1, the technique the colour; outside the object, the
   painting (or the environment where the painting is missing). preset: 0 DIR to
   the scene, 1 plane normal (2 iterations) to the scene, 2 ISR (d_N = 2R) to the
   environment, 3 DIR + dispersion + absorption + edge-fade fallback. */
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
    // The other presets, painting behind: plane depth, single sample, linear march, DDA, DIR with the
    // sphere's bounding box as its range (centre z -6, radius 2.2: tests/support/technique_scene.hpp).
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
  SnellTwoInterfaceResult r = snellTwoInterfaceRefraction(
      p1.position, vec3(n1.x, n1.y, n1.z), 4.4f, techBackDepth, techBackNormal, techBackPyramid, techBackSurface(c),
      techSceneDepth, techSceneNormal, techScenePyramid, techSceneColor, techSceneSurface(c), techEnv, o);
  return vec4(r.color.x, r.color.y, r.color.z, r.fellBack ? 2.0f : 1.0f);
}
