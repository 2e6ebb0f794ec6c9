/* The shared part of the plane-family intersect/ parity cases (described in
   tests/parity/intersect_plane_cases.cpp: hit.glsl, depth_surface.glsl, surface_point.glsl,
   single_sample.glsl, plane_refine.glsl, plane_far_start.glsl, plane_normal.glsl,
   plane_depth.glsl, depth_pyramid.glsl, foreground.glsl). Two analytic scenes
   (tests/support/depth_scenes.hpp) as textures:
     A = sphereBack 160x120, SNELL_DEPTH_GL, emptyDepth 0 (a back-face buffer)
     B = silhouette 160x120, SNELL_DEPTH_REVERSED, emptyDepth 0 (an opaque buffer
         with many empty texels)
   A projection travels as its four entries (A, B, C, D: columns (A,0,0,0)
   (0,B,0,0) (0,0,C,-1) (0,0,D,0)), so both builds use the same floats (tan()
   differs between drivers). */
#include "snell/intersect.glsl"
#include "hit_outputs.glsl"

#if defined(SNELL_LANG_GLSL)
uniform sampler2D planeDepthA;    /* NEAREST, one level */
uniform sampler2D planeNormalA;   /* trilinear normal mips */
uniform sampler2D planePyramidA;  /* depth pyramid, NEAREST_MIPMAP_NEAREST */
uniform sampler2D planeDepthB;
uniform sampler2D planeNormalB;
uniform sampler2D planePyramidB;
#endif
#if defined(SNELL_LANG_HLSL)
Texture2D<float4> planeDepthA;
Texture2D<float4> planeNormalA;
Texture2D<float4> planePyramidA;
Texture2D<float4> planeDepthB;
Texture2D<float4> planeNormalB;
Texture2D<float4> planePyramidB;
#endif

SNELL_FN mat4 planeParityMatrix(vec4 c) {
  return SNELL_CAMERA_MAT4_COLUMNS(vec4(c.x, 0.0f, 0.0f, 0.0f), vec4(0.0f, c.y, 0.0f, 0.0f),
                                   vec4(0.0f, 0.0f, c.z, -1.0f), vec4(0.0f, 0.0f, c.w, 0.0f));
}

SNELL_FN SnellDepthSurface planeParitySurface(bool sceneB, vec4 c) {
  if (sceneB) {
    return snellDepthSurface(planeParityMatrix(c), 0.5f, 40.0f, SNELL_DEPTH_REVERSED, 0.0f);
  }
  return snellDepthSurface(planeParityMatrix(c), 0.5f, 40.0f, SNELL_DEPTH_GL, 0.0f);
}

/* A general projection: shape = (m20, m21) off-centre terms and m10, a shear. */
SNELL_FN SnellDepthSurface planeParityShapedSurface(vec3 b, vec4 c) {
  mat4 m = SNELL_CAMERA_MAT4_COLUMNS(vec4(c.x, 0.0f, 0.0f, 0.0f), vec4(b.z, c.y, 0.0f, 0.0f),
                                     vec4(b.x, b.y, c.z, -1.0f), vec4(0.0f, 0.0f, c.w, 0.0f));
  return snellDepthSurface(m, 0.5f, 40.0f, SNELL_DEPTH_GL, 0.0f);
}

/* Sets the hit outputs (PLANE_HIT_OUT in intersect_plane_cases.cpp) from a SnellHit. */
#define PLANE_PARITY_SET_HIT(hit) CASE_SET_HIT(hit, ivec2(160, 120))
