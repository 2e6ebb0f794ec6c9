/*
description: the lab's per-pixel technique call (snell-lab, examples/lab): one
  function that the front-face fragment shader (lab_refract.frag) calls on the
  GPU and snell-lab calls per pixel in C++ on the read-back buffers, so the
  CPU image and the GPU image come from the same body. It picks a preset of
  shade/technique_presets.glsl by number, points the exit slot at the opaque
  scene's buffers (the paintings; the environment where the exit ray finds
  none) and runs snellTwoInterfaceRefraction; or, for an engine row, one of
  the engines' refraction models (shade/engine_models/) with the same
  reflection (labEngineShade).
use: LabParams p;  // the host fills every field (C++), or the uniform block LabUniforms holds it (GLSL)
     SnellTwoInterfaceResult r = labShade(SNELL_TECHNIQUE_PLANE_NORMAL_1, false, frontPosition, frontNormal,
         dN, backDepth, backNormal, backPyramid, frontLayerDepth, frontLayerNormal, sceneDepth, sceneNormal,
         scenePyramid, sceneColor, environment, p);
     SnellTwoInterfaceResult r = labShadeRow(technique, engineModel, engineParameter, reference, ...the same);
  technique   SNELL_TECHNIQUE_* (shade/technique_presets.glsl)
  engineModel SNELL_ENGINE_* (shade/engine_models/engine_models.glsl) or
              LAB_ENGINE_BEVY, or -1: the technique; engineParameter: the
              model's free value
  reference   the technique table's row is a Reference (the image-space
              bound): its exit slot marches over the whole scene
  frontPosition, frontNormal, dN: the front-face fragment (view space), Wyman's d_N
  back*       the back-face pass: depth (GL_GREATER, cleared to 0), view-space
              normals, its depth min/max pyramid
  front*      the front-face pass: depth (GL_LESS, cleared to 1), view-space
              normals (read by the techniques that bounce inside)
  scene*      the opaque scene without the object: depth (GL_LESS, cleared to
              1), view-space normals, pyramid, colour
  environment the equirectangular environment (world directions through
              envX/envY/envZ, the columns of world-from-view with the
              environment's rotation folded in)
contract: every technique's exit slot reads the scene's buffers
  (SNELL_SOURCE_BUFFERS) with SNELL_FALLBACK_ENVIRONMENT; the material has the
  critical-angle TIR policy, Fresnel reflection at the first interface,
  Beer-Lambert absorption along the found chord and, for a dispersive object,
  one path per colour channel (the engine rows: one, with p.ior); the reflect slot is the exit
  slot's intersector with p.reflectSource as its source (SNELL_SOURCE_BUFFERS
  resolves R against the opaque scene, as the ray-traced reference does;
  SNELL_SOURCE_ENVIRONMENT the environment only) and the environment as its
  fallback. The
  marches (linear, DDA, the image-space bound) in the back slot and the
  inside slot's march walk at most p.backRange (the object's bounding-box
  diagonal), a reference's exit slot
  p.exitRange (the diagonal of the box around the object and the opaque
  scene); p.depthFilter BILINEAR reads both depth buffers bilinearly in every
  slot of every technique (the bound always does); every other parameter is
  the preset's.
source: the composition of DESIGN.md sec. 2; the presets' own sources.
*/
#ifndef LAB_TECHNIQUE_GLSL
#define LAB_TECHNIQUE_GLSL
#include "snell/prelude.glsl"
#include "snell/camera/conventions.glsl"
#include "snell/intersect/depth_surface.glsl"
#include "snell/shade/technique_options.glsl"
#include "snell/shade/technique_presets.glsl"
#include "snell/shade/two_interface_shade.glsl"
#include "snell/shade/engine_models/engine_models.glsl"

/* The per-frame constants of every technique pass. The fields come in
   (vec3, float) pairs after the two matrices, so the C++ struct's bytes are the
   std140 layout of the uniform block LabUniforms (lab_refract.frag): the host
   uploads it as it is (examples/lab/app/gpu_lab.cpp checks the offsets). */
struct LabParams {
  mat4 clipFromView;  // how the techniques read the buffers (the guard band's projection)
  mat4 proxyFromView; // the engine rows' probe proxy (HDRP): the box around object and scene, as [-1,1]^3
  vec3 absorption;    // Beer-Lambert coefficients per unit length
  float zNear;
  vec3 envX;          // world-from-view with the environment's rotation folded in, by column
  float zFar;
  vec3 envY;
  float ior;
  vec3 envZ;
  float backRange;    // the object's bounding-box diagonal: the back slot's march range
  float exitRange;    // the box around object and scene: the image-space bound's exit range
  int depthFilter;    // SNELL_DEPTH_FILTER_*: how every slot reads both depth buffers
  int reflectSource;  // SNELL_SOURCE_*: the reflect slot's source
  int insideScene;    // 1: the opaque scene has surfaces inside the object (SnellTechnique.insideScene)
  vec3 iors;          // the IOR per colour channel (green is ior) where dispersion is 1
  int dispersion;     // 1: one path per colour channel with iors (SnellMaterial.dispersion 3); 0: one with ior
  float roughness;    // SnellMaterial.roughness (the scene's perceptual roughness; 0 smooth)
  int sceneColorLevels;   // SnellView's: the scene colour's mip levels (1 when smooth: no mips)
  int environmentLevels;  // ... the environment's
  int pad0;           // std140: the block's size a multiple of 16
};

SNELL_FN SnellTechnique labTechnique(int technique, bool reference, LabParams p) {
  SnellTechnique t = snellTechniquePreset(technique);
  t.back.intersect.marchMaxDistance = p.backRange;
  t.back.intersect.ddaMaxDistance = p.backRange;
  t.inside.intersect.marchMaxDistance = p.backRange;
  if (reference) {
    t.exit.intersect.marchMaxDistance = p.exitRange;
  }
  if (p.depthFilter == SNELL_DEPTH_FILTER_BILINEAR) {
    t.back.intersect.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
    t.exit.intersect.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  }
  t.exit.source = SNELL_SOURCE_BUFFERS;
  t.exit.fallback = SNELL_FALLBACK_ENVIRONMENT;
  t.reflect = t.exit;
  t.reflect.source = p.reflectSource;
  t.insideScene = p.insideScene != 0;
  return t;
}

SNELL_FN SnellMaterial labMaterial(LabParams p) {
  SnellMaterial m = snellMaterial();
  m.tirPolicy = SNELL_TIR_CRITICAL;
  m.ior = p.ior;
  m.iorOutside = 1.0f;
  m.iors = p.iors;
  m.dispersion = p.dispersion != 0 ? 3 : 1;
  m.absorption = p.absorption;
  m.roughness = p.roughness;
  m.reflection = true;
  return m;
}

SNELL_FN SnellView labView(LabParams p) {
  SnellView v = snellView();
  v.envX = p.envX;
  v.envY = p.envY;
  v.envZ = p.envZ;
  v.sceneColorLevels = p.sceneColorLevels;
  v.environmentLevels = p.environmentLevels;
  return v;
}

SNELL_FN SnellTwoInterfaceResult labShade(int technique, bool reference, vec3 frontPosition, vec3 frontNormal, float dN,
                                          SNELL_TEX2D backDepth, SNELL_TEX2D backNormal, SNELL_TEX2D backPyramid,
                                          SNELL_TEX2D frontLayerDepth, SNELL_TEX2D frontLayerNormal, SNELL_TEX2D sceneDepth, SNELL_TEX2D sceneNormal, SNELL_TEX2D scenePyramid,
                                          SNELL_TEX2D sceneColor, SNELL_ENVIRONMENT_TEX environment, LabParams p) {
  SnellDepthSurface back = snellDepthSurface(p.clipFromView, p.zNear, p.zFar, SNELL_DEPTH_GL, 0.0f);
  SnellDepthSurface frontLayer = snellDepthSurface(p.clipFromView, p.zNear, p.zFar, SNELL_DEPTH_GL, 1.0f);
  SnellDepthSurface scene = snellDepthSurface(p.clipFromView, p.zNear, p.zFar, SNELL_DEPTH_GL, 1.0f);
  scene.closed = false;  // where the scene buffer is empty, the environment shows
  return snellTwoInterfaceRefraction(frontPosition, frontNormal, dN, SNELL_OBJECT_BUFFER_ARGS, SNELL_SCENE_BUFFER_ARGS,
                                     labTechnique(technique, reference, p), labMaterial(p), labView(p));
}

/* The preset whose reflect slot the engine rows reflect with (the one the techniques' rows are most often
   compared with), so that an engine row differs from them only in the transmitted light. */
#define LAB_ENGINE_REFLECTION_TECHNIQUE SNELL_TECHNIQUE_PLANE_NORMAL_2

/* The lab's engine row that pairs three.js's point (SNELL_ENGINE_THREEJS, which Bevy shares) with Bevy's own
   blur (SNELL_ENGINE_BLUR_BEVY): one id past the engine models, so a row is still one int. */
#define LAB_ENGINE_BEVY SNELL_ENGINE_MODEL_COUNT
#define LAB_ENGINE_ROW_COUNT (SNELL_ENGINE_MODEL_COUNT + 1)

/* An engine's refraction model in place of the two-interface trace (the lab's engine rows): the scene colour
   where the model reads it, through the engine's rough read (snellEngineBlurRead: on smooth glass the one
   texel at lod 0 of the uv clamped to the edge, as the engines' samplers; on rough glass the engine's blur of
   the mipmapped colour), mixed with the environment along the model's direction by its scene weight, absorbed
   over the model's distance; the same Fresnel reflection at the first surface as labShade's rows, through
   LAB_ENGINE_REFLECTION_TECHNIQUE's reflect slot. model: SNELL_ENGINE_* or LAB_ENGINE_BEVY. fetches: the
   colour reads, the environment read where the weight is below 1, one depth read for the models that test
   depth (HDRP, Godot) and the reflect slot's. */
SNELL_FN SnellTwoInterfaceResult labEngineShade(int model, float parameter, vec3 frontPosition, vec3 frontNormal,
                                                SNELL_TEX2D sceneDepth, SNELL_TEX2D sceneNormal,
                                                SNELL_TEX2D scenePyramid, SNELL_TEX2D sceneColor,
                                                SNELL_ENVIRONMENT_TEX environment, LabParams p) {
  SnellDepthSurface scene = snellDepthSurface(p.clipFromView, p.zNear, p.zFar, SNELL_DEPTH_GL, 1.0f);
  scene.closed = false;
  SnellTechnique t = labTechnique(LAB_ENGINE_REFLECTION_TECHNIQUE, false, p);
  SnellMaterial m = labMaterial(p);
  SnellView v = labView(p);
  float eta = snellIorToEta(m.iorOutside, m.ior);
  int point = model == LAB_ENGINE_BEVY ? SNELL_ENGINE_THREEJS : model;
  int blur = model == LAB_ENGINE_BEVY ? SNELL_ENGINE_BLUR_BEVY : snellEngineBlurOf(model);
  SnellEngineRefraction e =
      snellEngineRefraction(point, frontPosition, frontNormal, eta, parameter, p.proxyFromView, sceneDepth, scene);
  SnellTwoInterfaceResult r;
  r.color = vec3(0.0f, 0.0f, 0.0f);
  r.exitPoint = frontPosition;
  r.exitDirection = e.direction;
  r.exitHit = snellHitMiss(0);
  r.reflectionHit = snellHitMiss(0);
  r.pathLength = e.distance;
  r.fresnel = 0.0f;
  r.fetches = 0;
  r.backHit = false;
  r.fellBack = !e.valid || e.sceneWeight < 1.0f;
  r.tir = false;
  r.bounces = 0;
  r.insideHit = false;
  vec3 transmitted = vec3(0.0f, 0.0f, 0.0f);
  if (e.valid) {
    SnellEngineBlurRead c = snellEngineBlurRead(blur, sceneColor, e.uv, m.roughness, m.ior, frontPosition,
                                                p.clipFromView, p.sceneColorLevels);
    transmitted = c.color;
    bool readsDepth = point == SNELL_ENGINE_HDRP_SPHERE || point == SNELL_ENGINE_HDRP_BOX || point == SNELL_ENGINE_GODOT;
    r.fetches = (readsDepth ? 1 : 0) + c.fetches;
    r.exitHit.valid = e.sceneWeight > 0.0f;
    r.exitHit.uv = e.uv;
    if (e.sceneWeight < 1.0f) {
      SnellSlot toEnvironment = t.exit;
      toEnvironment.source = SNELL_SOURCE_ENVIRONMENT;
      SnellTwoInterfaceExit env = snellTwoInterfaceExit(frontPosition, e.direction, sceneDepth, sceneNormal,
                                                        scenePyramid, sceneColor, scene, environment,
                                                        toEnvironment, m, v);
      r.fetches = r.fetches + env.fetches;
      transmitted = mix(env.color, transmitted, e.sceneWeight);
    }
    transmitted = transmitted * snellBeerLambert(m.absorption, e.distance);
  }
  r.color = transmitted;
  vec3 vv = snellSafeNormalize(frontPosition);
  vec3 n1 = snellSafeNormalize(frontNormal);
  if (dot(vv, vv) > 0.0f && dot(n1, n1) > 0.0f) {
    float f = snellFresnelDielectric(dot(vv, n1), eta);
    SnellTwoInterfaceExit re = snellTwoInterfaceExitRough(frontPosition, reflect(vv, n1),
                                                          snellRoughConeReflect(m.roughness), sceneDepth,
                                                          sceneNormal, scenePyramid, sceneColor, scene, environment,
                                                          t.reflect, v);
    r.reflectionHit = re.hit;
    r.fetches = r.fetches + re.fetches;
    r.fresnel = f;
    r.color = f * re.color + (1.0f - f) * transmitted;
  }
  return r;
}

/* One row of the lab: an engine model (engineModel >= 0, with its parameter) or a technique of the table */
SNELL_FN SnellTwoInterfaceResult labShadeRow(int technique, int engineModel, float engineParameter, bool reference,
                                             vec3 frontPosition, vec3 frontNormal, float dN, SNELL_TEX2D backDepth,
                                             SNELL_TEX2D backNormal, SNELL_TEX2D backPyramid,
                                             SNELL_TEX2D frontLayerDepth, SNELL_TEX2D frontLayerNormal,
                                             SNELL_TEX2D sceneDepth, SNELL_TEX2D sceneNormal, SNELL_TEX2D scenePyramid,
                                             SNELL_TEX2D sceneColor, SNELL_ENVIRONMENT_TEX environment, LabParams p) {
  if (engineModel >= 0) {
    return labEngineShade(engineModel, engineParameter, frontPosition, frontNormal, sceneDepth, sceneNormal,
                          scenePyramid, sceneColor, environment, p);
  }
  return labShade(technique, reference, frontPosition, frontNormal, dN, backDepth, backNormal, backPyramid,
                  frontLayerDepth, frontLayerNormal, sceneDepth, sceneNormal, scenePyramid, sceneColor, environment, p);
}

#endif
