/*
description: a depth-aware refraction mask (a modern variant of Sousa's alpha
  mask): the perturbed read is rejected when the opaque scene there lies in
  front of the refracting surface (an occluder would leak into the
  refraction); otherwise it is kept even outside the refractive object's
  screen area, so no mask has to be written into S's alpha.
use: bool ok = snellRefractionDepthAccept(sceneDepth, surfaceDepth, SNELL_DEPTH_GL);
     vec4 c = snellRefractionMaskedDepth(sceneColor, sceneDepthTex, uv,
                                         vec2(bump.x, bump.y), 0.05f,
                                         gl_FragCoord.z, SNELL_DEPTH_GL);
  sceneDepth     depth-buffer value of the opaque scene at the perturbed uv
  surfaceDepth   depth-buffer value of the refracting surface at this fragment
                 (gl_FragCoord.z)
  convention     depth convention of both values (camera/conventions.glsl):
                 GL, ZERO_ONE, INFINITE_GL store near -> 0; REVERSED,
                 INFINITE_REVERSED near -> 1
  sceneDepthTex  the opaque scene's depth buffer as a texture (depth in .x),
                 read with SNELL_SAMPLE_LOD at lod 0: use NEAREST filtering
                 (a filtered depth blends silhouettes)
  sceneColor, uv, bump, scale  as in snellPerturbSample (perturb.glsl)
options: -
contract:
  - snellRefractionDepthAccept is true exactly when sceneDepth is not in front
    of surfaceDepth: sceneDepth >= surfaceDepth (near -> 0 conventions) or
    sceneDepth <= surfaceDepth (reversed conventions); equal depths accept. It
    is false when either depth is NaN or the convention is unknown. Depths are
    compared as given (no range check: both come from the same buffer format).
  - snellRefractionMaskedDepth returns S at the perturbed uv when the scene
    depth read at that same uv is accepted, else S at the unperturbed uv; uvs
    as in snellRefractionMasked (clamped to [0,1]^2, NaN -> screen centre),
    lod 0. Colours are returned as read (alpha untouched).
source: T. Sousa, "Generic Refraction Simulation", GPU Gems 2, ch. 19 (2005),
  sec. 19.2 (the leakage problem and the alpha mask, Example 19-2), with the
  mask replaced by a depth comparison (snell's variant; the chapter notes
  that the alpha mask is inaccurate where refraction would show objects not
  directly behind the refractive one: those reads are kept here).
*/
#ifndef SNELL_SHADE_REFRACTION_MASK_DEPTH_GLSL
#define SNELL_SHADE_REFRACTION_MASK_DEPTH_GLSL
#include "../prelude.glsl"
#include "../camera/conventions.glsl"
#include "perturb.glsl"

SNELL_FN bool snellRefractionDepthAccept(float sceneDepth, float surfaceDepth, int convention) {
  if (isnan(sceneDepth) || isnan(surfaceDepth)) {
    return false;
  }
  if (convention == SNELL_DEPTH_GL || convention == SNELL_DEPTH_ZERO_ONE || convention == SNELL_DEPTH_INFINITE_GL) {
    return sceneDepth >= surfaceDepth;
  }
  if (convention == SNELL_DEPTH_REVERSED || convention == SNELL_DEPTH_INFINITE_REVERSED) {
    return sceneDepth <= surfaceDepth;
  }
  return false;
}

SNELL_FN vec4 snellRefractionMaskedDepth(SNELL_TEX2D sceneColor, SNELL_TEX2D sceneDepthTex, vec2 uv, vec2 bump,
                                         float scale, float surfaceDepth, int convention) {
  vec2 uvA = clamp(snellPerturbUv(uv, bump, scale), vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
  vec2 uvB = clamp(snellPerturbUv(uv, vec2(0.0f, 0.0f), 0.0f), vec2(0.0f, 0.0f), vec2(1.0f, 1.0f));
  float sceneDepth = SNELL_SAMPLE_LOD(sceneDepthTex, uvA, 0.0f).x;
  if (snellRefractionDepthAccept(sceneDepth, surfaceDepth, convention)) {
    return SNELL_SAMPLE_LOD(sceneColor, uvA, 0.0f);
  }
  return SNELL_SAMPLE_LOD(sceneColor, uvB, 0.0f);
}

#endif
