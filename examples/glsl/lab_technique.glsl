/*
description: the lab's per-pixel technique call (snell-lab, examples/lab): one
  function that the front-face fragment shader (lab_refract.frag) calls on the
  GPU and snell-lab calls per pixel in C++ on the read-back buffers, so the
  CPU image and the GPU image come from the same body. It picks a preset of
  shade/technique_presets.glsl by number, points the exit slot at the opaque
  scene's buffers (the paintings; the environment where the exit ray finds
  none) and runs snellTwoInterfaceRefraction.
use: LabParams p;  // the host fills every field (C++), or the uniform block LabUniforms holds it (GLSL)
     SnellTwoInterfaceResult r = labShade(SNELL_TECHNIQUE_PLANE_NORMAL_1, false, frontPosition, frontNormal,
         dN, backDepth, backNormal, backPyramid, sceneDepth, sceneNormal, scenePyramid,
         sceneColor, environment, p);
  technique   SNELL_TECHNIQUE_* (shade/technique_presets.glsl)
  reference   the technique table's row is a Reference (the image-space
              bound): its exit slot marches over the whole scene
  frontPosition, frontNormal, dN: the front-face fragment (view space), Wyman's d_N
  back*       the back-face pass: depth (GL_GREATER, cleared to 0), view-space
              normals, its depth min/max pyramid
  scene*      the opaque scene without the object: depth (GL_LESS, cleared to
              1), view-space normals, pyramid, colour
  environment the equirectangular environment (world directions through
              envX/envY/envZ, the columns of world-from-view with the
              environment's rotation folded in)
contract: every technique uses SNELL_EXIT_SCENE with SNELL_FALLBACK_ENVIRONMENT,
  the critical-angle TIR policy, Fresnel reflection at the first interface
  (p.reflectionMode: SNELL_REFLECT_SCENE resolves R against the opaque scene
  with the exit slot's strategy and parameters, as the ray-traced reference
  does; SNELL_REFLECT_ENVIRONMENT the environment only) and Beer-Lambert
  absorption along the found chord. The
  marches (linear, DDA, the image-space bound) in the back slot walk at most
  p.backRange (the object's bounding-box diagonal), a reference's exit slot
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

/* The per-frame constants of every technique pass. The fields come in
   (vec3, float) pairs after the matrix, so the C++ struct's bytes are the
   std140 layout of the uniform block LabUniforms (lab_refract.frag): the host
   uploads it as it is (examples/lab/app/gpu_lab.cpp checks the offsets). */
struct LabParams {
  mat4 clipFromView;  // how the techniques read the buffers (the guard band's projection)
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
  int reflectionMode; // SNELL_REFLECT_*
};

SNELL_FN SnellTechniqueOptions labTechniqueOptions(int technique, bool reference, LabParams p) {
  SnellTechniqueOptions o = snellTechniquePreset(technique);
  o.back.marchMaxDistance = p.backRange;
  o.back.ddaMaxDistance = p.backRange;
  if (reference) {
    o.exit.marchMaxDistance = p.exitRange;
  }
  if (p.depthFilter == SNELL_DEPTH_FILTER_BILINEAR) {
    o.back.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
    o.exit.depthFilter = SNELL_DEPTH_FILTER_BILINEAR;
  }
  o.exitMode = SNELL_EXIT_SCENE;
  o.fallback = SNELL_FALLBACK_ENVIRONMENT;
  o.tirPolicy = SNELL_TIR_CRITICAL;
  o.ior = p.ior;
  o.iorOutside = 1.0f;
  o.iors = vec3(p.ior, p.ior, p.ior);
  o.absorption = p.absorption;
  o.reflection = true;
  o.reflectionMode = p.reflectionMode;
  o.reflect = o.exit;
  o.envX = p.envX;
  o.envY = p.envY;
  o.envZ = p.envZ;
  return o;
}

SNELL_FN SnellTwoInterfaceResult labShade(int technique, bool reference, vec3 frontPosition, vec3 frontNormal, float dN,
                                          SNELL_TEX2D backDepth, SNELL_TEX2D backNormal, SNELL_TEX2D backPyramid,
                                          SNELL_TEX2D sceneDepth, SNELL_TEX2D sceneNormal, SNELL_TEX2D scenePyramid,
                                          SNELL_TEX2D sceneColor, SNELL_ENVIRONMENT_TEX environment, LabParams p) {
  SnellDepthSurface back = snellDepthSurface(p.clipFromView, p.zNear, p.zFar, SNELL_DEPTH_GL, 0.0f);
  SnellDepthSurface scene = snellDepthSurface(p.clipFromView, p.zNear, p.zFar, SNELL_DEPTH_GL, 1.0f);
  scene.closed = false;  // where the scene buffer is empty, the environment shows
  SnellTechniqueOptions o = labTechniqueOptions(technique, reference, p);
  return snellTwoInterfaceRefraction(frontPosition, frontNormal, dN, backDepth, backNormal, backPyramid, back,
                                     sceneDepth, sceneNormal, scenePyramid, sceneColor, scene, environment, o);
}

#endif
