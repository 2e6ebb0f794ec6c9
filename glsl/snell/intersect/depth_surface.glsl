/*
description: how a depth texture describes a surface (the refractive object's
  back faces, or the opaque scene), and the one way every strategy reads it.
use: SnellDepthSurface s = snellDepthSurface(clipFromView, zNear, zFar, SNELL_DEPTH_GL, 0.0f);
     SnellSurfaceSample x = snellSampleSurface(depthTex, uv, s);   // x.viewZ < 0 when x.valid
  clipFromView  the projection the depth texture was rendered with
  zNear, zFar   its clip distances; convention: SNELL_DEPTH_* (camera/conventions.glsl)
  emptyDepth    the texel value meaning "no surface here": the clear value (0.0f for
                back faces drawn with glDepthFunc(GL_GREATER) after clearing to 0,
                1.0f for a scene drawn with GL_LESS after clearing to 1)
  lod           the mip level the searches read (0 = full resolution); set the field
contract (snellSampleSurface):
  - reads the texel containing uv (nearest, no filtering: filtering depth invents
    surfaces between foreground and background, Oliveira & Brauwers 2007 sec. 3.1)
    at level lod through SNELL_TEXEL_FETCH, red channel, and costs one fetch;
  - valid = false (viewZ = 0) when uv lies outside [0,1]^2 (off screen: no
    information, never clamped to the edge), when uv is NaN, when the texel equals
    emptyDepth, or when the depth does not linearize (NaN, bad zNear/zFar);
  - otherwise viewZ = -snellLinearizeDepth(texel) < 0, finite.
source: Oliveira & Brauwers 2007 sec. 3.1 and Algorithm 2 ("invalid texels have
  depth = 0"); depth conventions in camera/linearize_depth.glsl.
*/
#ifndef SNELL_INTERSECT_DEPTH_SURFACE_GLSL
#define SNELL_INTERSECT_DEPTH_SURFACE_GLSL
#include "../prelude.glsl"
#include "../camera/linearize_depth.glsl"
#include "../camera/pixel_to_uv.glsl"

struct SnellDepthSurface {
  mat4 clipFromView;
  float zNear;
  float zFar;
  int convention;
  float emptyDepth;
  int lod;
};

struct SnellSurfaceSample {
  float viewZ;
  bool valid;
};

SNELL_FN SnellDepthSurface snellDepthSurface(mat4 clipFromView, float zNear, float zFar, int convention,
                                             float emptyDepth) {
  SnellDepthSurface s;
  s.clipFromView = clipFromView;
  s.zNear = zNear;
  s.zFar = zFar;
  s.convention = convention;
  s.emptyDepth = emptyDepth;
  s.lod = 0;
  return s;
}

SNELL_FN SnellSurfaceSample snellSampleSurface(SNELL_TEX2D depthTex, vec2 uv, SnellDepthSurface s) {
  SnellSurfaceSample r;
  r.viewZ = 0.0f;
  r.valid = false;
  // Written so NaN fails: every comparison with NaN is false.
  if (!(uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f)) {
    return r;
  }
  ivec2 size = SNELL_TEXTURE_SIZE(depthTex, s.lod);
  if (size.x <= 0 || size.y <= 0) {
    return r;
  }
  float d = SNELL_TEXEL_FETCH(depthTex, snellUvToPixel(uv, size), s.lod).x;
  if (d == s.emptyDepth) {
    return r;
  }
  float v = snellLinearizeDepth(d, s.zNear, s.zFar, s.convention);
  if (!(v > 0.0f)) {
    return r;
  }
  r.viewZ = -v;
  r.valid = true;
  return r;
}

#endif
