/* The shared part of the parity cases for the ray-vs-depth-buffer searches and
   marches of glsl/snell/intersect/ (described in tests/parity/intersect_search_cases.cpp:
   search_segment, conservative_binary_search, binary_search (and its
   bisection), linear_binary_search, linear_march, dda_march), run on the
   analytic scene buffers of tests/support/depth_scenes.hpp uploaded as
   textures: sphereBack (back-face buffer) and silhouette (opaque, empty
   texels); both GL convention, zNear/zFar as below, emptyDepth 0 / 1. The
   projection travels as its four non-zero entries (x scale, y scale, z row),
   so the matrix is bit-identical on both sides (no tan on the GPU). */
#include "snell/intersect.glsl"
#include "hit_outputs.glsl"

#define SEARCH_PARITY_NEAR 0.5f
#define SEARCH_PARITY_FAR 40.0f

#if defined(SNELL_LANG_GLSL)
uniform sampler2D searchTexSphere;      /* sphereBack 256x256, NEAREST */
uniform sampler2D searchTexSilhouette;  /* silhouette 256x256, NEAREST */
#endif
#if defined(SNELL_LANG_HLSL)
Texture2D<float4> searchTexSphere;
Texture2D<float4> searchTexSilhouette;
#endif

SNELL_FN mat4 searchParityMatrix(vec4 d) {
  return SNELL_CAMERA_MAT4_COLUMNS(vec4(d.x, 0.0f, 0.0f, 0.0f), vec4(0.0f, d.y, 0.0f, 0.0f),
                                   vec4(0.0f, 0.0f, d.z, -1.0f), vec4(0.0f, 0.0f, d.w, 0.0f));
}

SNELL_FN SnellDepthSurface searchParitySurface(bool sceneB, vec4 d) {
  return snellDepthSurface(searchParityMatrix(d), SEARCH_PARITY_NEAR, SEARCH_PARITY_FAR, SNELL_DEPTH_GL,
                           sceneB ? 1.0f : 0.0f);
}

/* Sets the hit outputs (SEARCH_HIT_OUT in intersect_search_cases.cpp) from a SnellHit. */
#define SEARCH_PARITY_SET_HIT(hit) CASE_SET_HIT(hit, ivec2(256, 256))
