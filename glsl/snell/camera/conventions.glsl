/*
description: the conventions every glsl/snell/camera file shares: spaces, the
  depth-buffer conventions (integer #defines passed as `int convention`), and two
  helper macros. No function is defined here.
use: #include "snell/camera/conventions.glsl" (every camera file does).
options:
  SNELL_DEPTH_GL                 glm::perspective / glFrustum: NDC z in [-1,1],
                                 stored as window depth 0.5 z_ndc + 0.5
                                 (glDepthRange(0,1), the default); near -> 0, far -> 1
  SNELL_DEPTH_ZERO_ONE           D3D / Vulkan / glClipControl(GL_ZERO_TO_ONE),
                                 glm::perspectiveZO: NDC z in [0,1] stored as is;
                                 near -> 0, far -> 1
  SNELL_DEPTH_REVERSED           reversed Z: NDC z in [0,1], near -> 1, far -> 0
  SNELL_DEPTH_INFINITE_GL        glm::infinitePerspective: GL NDC, far plane at
                                 infinity: depth 1 is "infinitely far"
  SNELL_DEPTH_INFINITE_REVERSED  reversed Z with an infinite far plane:
                                 depth = zNear / distance, 0 is "infinitely far"
  SNELL_DEPTH_CONVENTION_COUNT   number of conventions (valid values 0 .. COUNT-1)
  (SNELL_FINITE and SNELL_FLT_MIN, used by every family, are in prelude.glsl)
  SNELL_CAMERA_MAT4_COLUMNS(c0, c1, c2, c3)  a mat4 from four column vec4s in
                                 every language (GLSL/GLM constructors take
                                 columns, HLSL's take rows)
  SNELL_CAMERA_MAT_COLUMN(m, i)  column i of a mat4 (its i-th basis image) in
                                 every language, without a matrix product
contract:
  - view space is right-handed; the camera sits at the origin and looks down -Z,
    so points in front of it have z < 0. "View distance" is -z_view (> 0 in front).
  - clip = clipFromView * vec4(p, 1); NDC = clip.xyz / clip.w, defined for w > 0.
  - uv is [0,1]^2 over the viewport, origin bottom-left (GL window space):
    uv = 0.5 NDC.xy + 0.5; pixel (i, j) covers uv [i, i+1]/W x [j, j+1]/H and its
    centre is ((i + 0.5)/W, (j + 0.5)/H).
  - "depth value" always means what the depth buffer stores (window-space depth
    in [0,1]), never NDC z. For SNELL_DEPTH_GL window depth is 0.5 z_ndc + 0.5;
    for the other conventions window depth equals NDC z. The GL and ZERO_ONE
    conventions therefore store the same value for the same point,
    d = zFar (v - zNear) / (v (zFar - zNear)), v the view distance; they differ in
    the projection matrix and in NDC z only.
source: OpenGL 4.5 core spec sec. 13.6 (coordinate transformations, glDepthRange),
  sec. 13.7 (glClipControl); GLM 0.9.9 ext/matrix_clip_space.inl.
*/
#ifndef SNELL_CAMERA_CONVENTIONS_GLSL
#define SNELL_CAMERA_CONVENTIONS_GLSL
#include "../prelude.glsl"

#define SNELL_DEPTH_GL 0
#define SNELL_DEPTH_ZERO_ONE 1
#define SNELL_DEPTH_REVERSED 2
#define SNELL_DEPTH_INFINITE_GL 3
#define SNELL_DEPTH_INFINITE_REVERSED 4
#define SNELL_DEPTH_CONVENTION_COUNT 5

/* isnan/isinf rather than comparison tricks: GPU compilers may rewrite !(a > b)
   into a <= b, which changes the NaN answer. */

#if defined(SNELL_LANG_HLSL)
#  define SNELL_CAMERA_MAT4_COLUMNS(c0, c1, c2, c3) transpose(float4x4(c0, c1, c2, c3))
#else
#  define SNELL_CAMERA_MAT4_COLUMNS(c0, c1, c2, c3) mat4(c0, c1, c2, c3)
#endif

/* GLSL and GLM index a matrix's columns, HLSL its rows. */
#if defined(SNELL_LANG_HLSL)
#  define SNELL_CAMERA_MAT_COLUMN(m, i) (transpose(m)[i])
#else
#  define SNELL_CAMERA_MAT_COLUMN(m, i) ((m)[i])
#endif

#endif
